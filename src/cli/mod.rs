//! Subcommands of the `samplescope` binary. Each returns a [`CliError`]: bad input exits with
//! status 2 and one line naming the field and what is allowed; I/O failures exit with 1.

pub mod analyze;
pub mod converge;
pub mod filter;
pub mod points;
pub mod recon;
pub mod render;
pub mod session;

use samplescope::core::filter::FilterError;
use samplescope::core::params::{ParamError, ParamKind, ParamSpec, Params};
use samplescope::core::pattern::{Pattern, PatternError};

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
    #[error("cannot open the window: {0}")]
    Gui(String),
    /// Writing the results to standard output failed (exit status 1; a closed pipe ends the
    /// program quietly instead, see `main`).
    #[error("writing to standard output: {0}")]
    Output(#[source] std::io::Error),
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
            CliError::Io { .. } | CliError::Gui(_) | CliError::Output(_) => 1,
            CliError::Cancelled => 130,
            _ => 2,
        }
    }
}

/// Builds a pattern from its name and `key=value` settings.
pub fn pattern_from_args(name: &str, settings: &[String]) -> Result<Pattern, CliError> {
    let mut pattern = Pattern::from_name(name)?;
    apply_settings(&mut pattern, "--set", settings, "samplescope points --list")?;
    Ok(pattern)
}

/// Applies `key=value` settings (from `flag`, e.g. `--set`) to any parameter set through its
/// descriptors: enum values unquoted (`shape=square`), booleans `true`/`false`, lists
/// `amps=[0.5,0.25]`. Enum settings go first, so that a parameter that exists only for one
/// option (`beta` with `window=kaiser`) may be given in any order. Every value is checked;
/// the error names the owner, the field and the allowed range.
pub fn apply_settings(
    params: &mut impl Params,
    flag: &str,
    settings: &[String],
    list_hint: &str,
) -> Result<(), CliError> {
    let mut pairs = Vec::with_capacity(settings.len());
    for s in settings {
        let (k, v) = s.split_once('=').ok_or_else(|| {
            CliError::Usage(format!(
                "{flag} {s}: expected key=value (see `{list_hint}`)"
            ))
        })?;
        pairs.push((k.trim(), v));
    }
    let is_choice = |p: &dyn Fn(&str) -> Option<ParamSpec>, k: &str| {
        matches!(p(k).map(|s| s.kind), Some(ParamKind::Choice { .. }))
    };
    let snapshot = params.clone();
    pairs.sort_by_key(|(k, _)| !is_choice(&|key| snapshot.spec(key), k));
    for (k, v) in pairs {
        params.set(k, v)?;
    }
    Ok(())
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
