//! Subcommands of the `samplescope` binary. Each returns a [`CliError`]: bad input exits with
//! status 2 and one line naming the field and what is allowed; I/O failures exit with 1.

pub mod analyze;
pub mod analyze_cube;
pub mod converge;
pub mod filter;
pub mod gui;
pub mod points;
pub mod recon;
pub mod render;
pub mod session;

use samplescope::core::family::Family;
use samplescope::core::filter::FilterError;
use samplescope::core::params::{ParamError, Params};
use samplescope::core::pattern::{Generated, Pattern, PatternError};

/// An error of a subcommand.
#[derive(Debug, thiserror::Error)]
pub enum CliError {
    /// Bad input from the user (exit status 2).
    #[error("{0}")]
    Usage(String),
    /// A pattern could not be generated from the given parameters (exit status 2).
    #[error("{0}")]
    Pattern(#[from] PatternError),
    /// A filter could not be built or evaluated from the given parameters (exit status 2).
    #[error("{0}")]
    Filter(#[from] FilterError),
    /// A `--set`, `--filter-set` or `--signal-set` value is unknown, malformed or out of range
    /// (exit status 2).
    #[error(transparent)]
    Param(#[from] ParamError),
    /// The work is estimated beyond the budget (exit status 2); the message names the
    /// operation, its estimate, the limit and the flag that raises it.
    #[error("{0}")]
    Budget(String),
    /// Ctrl-C stopped the command (exit status 130).
    #[error("interrupted")]
    Cancelled,
    /// The window could not be opened (exit status 1).
    #[cfg_attr(not(feature = "gui"), allow(dead_code))]
    #[error("cannot open the window: {0}")]
    Gui(String),
    /// Writing the results to standard output failed (exit status 1; a closed pipe ends the
    /// program quietly instead, see `main`).
    #[error("writing to standard output: {0}")]
    Output(#[source] std::io::Error),
    /// The environment failed us (exit status 1): an existing file could not be read.
    #[error("{0}")]
    Environment(String),
    /// Reading or writing a file failed (exit status 1).
    #[error("{path}: {source}")]
    Io {
        path: String,
        source: std::io::Error,
    },
}

/// `print!` to standard output that returns a [`CliError::Output`] instead of panicking
/// when the write fails (a closed pipe, a full disk).
macro_rules! out {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        write!(std::io::stdout().lock(), $($arg)*).map_err($crate::cli::CliError::Output)
    }};
}

/// `println!` to standard output that returns a [`CliError::Output`] instead of panicking.
macro_rules! outln {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        writeln!(std::io::stdout().lock(), $($arg)*).map_err($crate::cli::CliError::Output)
    }};
}
pub(crate) use {out, outln};

impl CliError {
    /// Whether this is a write to a closed pipe (`samplescope … | head -1`): the reader has
    /// all it wanted, so the program ends quietly with status 0, as coreutils and ripgrep do.
    pub fn is_broken_pipe(&self) -> bool {
        let io = match self {
            CliError::Output(e) => e,
            CliError::Io { source, .. } => source,
            _ => return false,
        };
        io.kind() == std::io::ErrorKind::BrokenPipe
    }

    /// The process exit status for this error.
    pub fn exit_code(&self) -> u8 {
        match self {
            CliError::Io { .. }
            | CliError::Environment(_)
            | CliError::Gui(_)
            | CliError::Output(_) => 1,
            CliError::Cancelled => 130,
            _ => 2,
        }
    }
}

/// A member of a family (a pattern, filter, signal or integrand) from its name and its
/// `key=value` settings: `name_flag` starts the message of an unknown name (empty for a name
/// given without a flag), `set_flag` is the settings' flag and `list_hint` the command that
/// lists the parameters.
pub fn from_args<F: Family>(
    name_flag: &str,
    name: &str,
    set_flag: &str,
    settings: &[String],
    list_hint: &str,
) -> Result<F, CliError> {
    let mut member = F::from_name(name).map_err(|e| {
        CliError::Usage(if name_flag.is_empty() {
            e.to_string()
        } else {
            format!("{name_flag} {e}")
        })
    })?;
    apply_settings(&mut member, set_flag, settings, list_hint)?;
    Ok(member)
}

/// The pattern named by a command's positional name or `--pattern` and its `--set` settings,
/// the way every command that samples reads it (errors point at `samplescope points --list`).
pub fn pattern_from_args(name: &str, settings: &[String]) -> Result<Pattern, CliError> {
    from_args("", name, "--set", settings, "samplescope points --list")
}

/// Applies `key=value` settings (from `flag`, e.g. `--set`) to any parameter set through its
/// descriptors: enum values unquoted (`shape=square`), booleans `true`/`false`, lists
/// `amps=[0.5,0.25]`. Enum settings go first, so that a parameter that exists only for one
/// option (`beta` with `window=kaiser`) may be given in any order. Each value is checked
/// against its own range as it is applied; the constraints between fields (a band-pass's
/// `low < high`) are checked once, after every setting, so the order of the settings never
/// matters. A key given twice is refused (the first would have no effect). Errors name the
/// owner, the field and the allowed range; a field the user did not set is marked
/// `(default)`.
pub fn apply_settings(
    params: &mut impl Params,
    flag: &str,
    settings: &[String],
    list_hint: &str,
) -> Result<(), CliError> {
    let mut pairs: Vec<(&str, &str)> = Vec::with_capacity(settings.len());
    for s in settings {
        let (k, v) = s.split_once('=').ok_or_else(|| {
            CliError::Usage(format!(
                "{flag} {}: expected key=value (see `{list_hint}`)",
                samplescope::core::params::fmt_text(s)
            ))
        })?;
        let k = k.trim();
        if let Some((_, first)) = pairs.iter().find(|(key, _)| *key == k) {
            return Err(CliError::Usage(format!(
                "{flag} {k}: given twice ({k}={} and {k}={}): give each key once",
                samplescope::core::params::fmt_text(first),
                samplescope::core::params::fmt_text(v)
            )));
        }
        pairs.push((k, v));
    }
    params.set_all(&pairs)?;
    Ok(())
}

/// Refuses a seed given explicitly (`flag`) for a deterministic pattern: it would have no
/// effect (the pattern draws no random numbers).
pub fn check_seed(pattern: &Pattern, seed: Option<u64>, flag: &str) -> Result<(), CliError> {
    match seed.and_then(|s| pattern.seed_refusal(s, flag)) {
        Some(message) => Err(CliError::Usage(message)),
        None => Ok(()),
    }
}

/// Refuses `--allow-fewer` for a pattern that always places exactly N points (or refuses N).
pub fn check_allow_fewer(pattern: &Pattern, allow_fewer: bool) -> Result<(), CliError> {
    if allow_fewer && !pattern.may_place_fewer() {
        return Err(CliError::Usage(format!(
            "--allow-fewer: {} always places exactly N points, so --allow-fewer would have no \
             effect (only poisson-dart and poisson-bridson can stop short)",
            pattern.name()
        )));
    }
    Ok(())
}

/// The points of a generation: all N of them; or, with `--allow-fewer`, those placed (a note
/// on standard error says how many); otherwise a pattern that stopped short is bad input,
/// naming the parameter that stopped it.
pub fn require_points(
    generated: Generated,
    pattern: &Pattern,
    allow_fewer: bool,
) -> Result<Vec<glam::DVec2>, CliError> {
    if allow_fewer {
        if let Some(note) = &generated.note {
            eprintln!("note: {note}");
        }
        return Ok(generated.points);
    }
    generated.require_all(pattern.name()).map_err(|e| match e {
        e @ PatternError::TooFew { .. } => CliError::Usage(format!(
            "{e}; or pass --allow-fewer to keep the points placed"
        )),
        e => CliError::Pattern(e),
    })
}

/// A node's failure as the fronts over a scene (`recon`, `analyze`) report it: a pattern's
/// error as a pattern error (a pattern that stopped short with the `--allow-fewer` hint),
/// cancellation as cancellation, any other as bad input with the node's message.
pub fn node_error(e: &samplescope::scene::node::NodeError) -> CliError {
    use samplescope::core::metrics::MetricsError;
    use samplescope::scene::node::NodeError;
    match e {
        NodeError::Pattern(e @ PatternError::TooFew { .. }) => CliError::Usage(format!(
            "{e}; or pass --allow-fewer to keep the points placed"
        )),
        NodeError::Pattern(e) => CliError::Pattern(e.clone()),
        NodeError::Cancelled | NodeError::Metrics(MetricsError::Cancelled) => CliError::Cancelled,
        e => CliError::Usage(e.to_string()),
    }
}

/// The PNG of figure `kind` of column 0 of `scene` (its columns' contexts and data in
/// `columns`, `name` its file-name stem), published through `export::publish` as `render`
/// publishes it: the one image output of the fronts over a scene (`recon --out`,
/// `analyze --spectrum`).
pub fn figure_png(
    scene: &samplescope::scene::Scene,
    columns: Vec<(
        samplescope::model::FigureContext,
        samplescope::model::ColumnData,
    )>,
    name: &str,
    kind: samplescope::model::FigureKind,
    cancel: &samplescope::core::cancel::Cancel,
) -> Result<Vec<u8>, CliError> {
    use samplescope::export::figure::{Aspect, FileFormat};
    use samplescope::export::publish::{publish, Format, Target};
    use samplescope::export::ExportError;
    let publication = samplescope::scene::figure::publication(scene, columns, name);
    let target = Target::Panel { column: 0, kind };
    let png = [Format::Picture(FileFormat::Png)];
    let made =
        publish(&publication, target, &png, 1, Aspect::SLIDE, cancel).map_err(|e| match e {
            ExportError::Cancelled => CliError::Cancelled,
            e => CliError::Usage(e.to_string()),
        })?;
    made.files
        .into_iter()
        .next()
        .map(|(_, bytes)| bytes)
        .ok_or_else(|| {
            CliError::Environment(format!("{name}: the {} figure was not made", kind.name()))
        })
}

/// Opens a file the user named for reading. A path that does not exist, is a directory or
/// goes through something that is not a directory is bad input (status 2); any other failure
/// (permissions, a device error) is the environment's (status 1). See the README's "Exit
/// status".
pub fn open_input(path: &std::path::Path) -> Result<std::fs::File, CliError> {
    let file = std::fs::File::open(path).map_err(|e| input_error(path, e))?;
    if file.metadata().is_ok_and(|m| m.is_dir()) {
        return Err(CliError::Usage(format!(
            "{}: is a directory, not a file",
            path.display()
        )));
    }
    Ok(file)
}

/// The [`CliError`] for a failure to open the input file `path`: bad input (2) when the file
/// is not there, the environment's (1) otherwise.
pub fn input_error(path: &std::path::Path, e: std::io::Error) -> CliError {
    use std::io::ErrorKind as K;
    match e.kind() {
        K::NotFound | K::IsADirectory | K::NotADirectory | K::InvalidFilename => {
            CliError::Usage(format!("{}: {e}", path.display()))
        }
        _ => CliError::Io {
            path: path.display().to_string(),
            source: e,
        },
    }
}

/// The [`CliError`] of a scene that cannot be loaded: bad input (status 2) unless reading an
/// existing file failed ([`SceneError::is_environment`]).
pub fn scene_error(e: samplescope::scene::SceneError) -> CliError {
    if e.is_environment() {
        CliError::Environment(e.to_string())
    } else {
        CliError::Usage(e.to_string())
    }
}

/// Parses `-n`, accepting only a positive integer that fits in memory.
pub fn parse_n(text: &str) -> Result<usize, String> {
    let max = samplescope::core::pattern::MAX_N;
    text.trim()
        .parse::<usize>()
        .ok()
        .filter(|&n| (1..=max).contains(&n))
        .ok_or_else(|| format!("n = {text}: must be an integer in 1..={max}"))
}
