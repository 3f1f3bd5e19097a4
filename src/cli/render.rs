//! `samplescope render`: every figure of a scene, headless (no window, no GPU).
//!
//! Loads the scene, evaluates its compute graph synchronously, and writes, for every column,
//! each figure its visible panels show (PNG, SVG, PDF, CSV; the figures of
//! [`samplescope::scene::panels`]' rule), the column composite, and the comparison of all
//! columns (laid out to fill a 16:9 frame, or `--aspect W:H`; in each picture format asked
//! for), printing one line per file. The 1D sampling-theorem figures
//! belong to column 0 only (the view does not depend on the column). The periodograms of all columns
//! share one colour range (the union of their automatic ranges), as locked scales do in
//! the GUI. Same scene → byte-identical files.
//!
//! `--format gif` writes the comparison of an animated scene (motion, or a prefix of columns
//! that play in order: `scene::animation`) as one looping GIF, `--frames` frames at `--fps`
//! (default: the scene's `animation`), through `engine::animation`; a scene that does not
//! animate is refused, and frames × width × height is checked against the GIF budget before
//! any work.

use super::outln;
use super::session::{write_output, Session};
use super::CliError;
use samplescope::core::cancel::Cancel;
use samplescope::engine::{ColumnResults, ColumnsError, Evaluator};
use samplescope::export::figure::{Aspect, FileFormat, MAX_COMPOSITE_PIXELS, SCALES};
use samplescope::export::publish::{publish, Format as PublishFormat, Target};
use samplescope::export::ExportError;
use samplescope::scene::graph::NodeKind;
use samplescope::scene::{figure, panels, Scene};
use std::path::PathBuf;
use std::sync::Arc;

/// Arguments of `samplescope render`.
#[derive(clap::Args, Debug)]
pub struct RenderArgs {
    /// Scene file (RON).
    pub scene: PathBuf,
    /// Output directory (created if missing).
    #[arg(long, value_name = "DIR")]
    pub out: PathBuf,
    /// Figure scale, 1..=4 [default: 1]: every figure is scale × its base size (text and lines
    /// too). Not with `--format csv` alone (data has no size).
    #[arg(long)]
    pub scale: Option<u32>,
    /// Formats to write, comma-separated: png, svg, pdf, csv (the composites in each of png,
    /// svg and pdf asked for), gif (the comparison of an animated scene as a looping GIF).
    #[arg(long, value_delimiter = ',', default_value = "png,svg,csv", value_enum)]
    pub format: Vec<Format>,
    /// Shape of the frame the composites are laid out to fill, W:H with W and H positive
    /// numbers and W/H in 0.1..=10 (e.g. 16:9, 4:3, 1:1, 9:16). The column and comparison
    /// composites take the grid of panels that covers the largest part of such a frame
    /// [default: 16:9]. Not with `--format csv` alone (no composite is drawn).
    #[arg(long, value_name = "W:H", value_parser = parse_aspect)]
    pub aspect: Option<Aspect>,
    /// Compute reference images even if the disk cache has them (and store nothing there).
    #[arg(long)]
    pub no_cache: bool,
    /// Frames of the GIF, 2..=1000 [default: the scene's animation.frames, 48]: a moving
    /// scene's frame i is t = i / motion.frame_rate; a prefix reaches all N points in the last.
    /// Only with `--format gif`.
    #[arg(long)]
    pub frames: Option<usize>,
    /// Frames per second the GIF plays at, 1..=50 [default: the scene's animation.fps, 24].
    /// Only with `--format gif`.
    #[arg(long)]
    pub fps: Option<f64>,
}

fn parse_aspect(text: &str) -> Result<Aspect, String> {
    text.parse()
        .map_err(|e: samplescope::export::figure::AspectError| e.to_string())
}

/// An output format.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    /// Antialiased bitmap figures.
    Png,
    /// Vector figures, the glyphs as outlines.
    Svg,
    /// Vector figures, one page each, the font embedded.
    Pdf,
    /// The figures' data.
    Csv,
    /// The comparison of an animated scene, as a looping animated GIF.
    Gif,
}

impl Format {
    /// The still format published (`None`: the animated GIF, made by `engine::animation`).
    fn publish(self) -> Option<PublishFormat> {
        match self {
            Format::Png => Some(PublishFormat::Picture(FileFormat::Png)),
            Format::Svg => Some(PublishFormat::Picture(FileFormat::Svg)),
            Format::Pdf => Some(PublishFormat::Picture(FileFormat::Pdf)),
            Format::Csv => Some(PublishFormat::Csv),
            Format::Gif => None,
        }
    }
}

/// `--frames` and `--fps` into the scene's animation, each checked against its descriptor (the
/// error names the flag and the range).
fn animation_flags(args: &RenderArgs, scene: &mut Scene) -> Result<(), CliError> {
    use samplescope::core::params::{ParamKind, ParamValue, Params};
    let mut set = |flag: &str, key: &str, value: ParamValue, shown: String| {
        let spec = scene.animation.specs().into_iter().find(|s| s.name == key);
        scene.animation.set_value(key, &value).map_err(|_| {
            let allowed = match spec.map(|s| s.kind) {
                Some(ParamKind::Int { min, max, .. }) => format!("an integer in {min}..={max}"),
                Some(ParamKind::Float { min, max, .. }) => format!("a number in {min}..={max}"),
                _ => "a value the scene's animation allows".into(),
            };
            CliError::Usage(format!("{flag} = {shown}: must be {allowed}"))
        })
    };
    if let Some(f) = args.frames {
        let v = ParamValue::Int(i64::try_from(f).unwrap_or(i64::MAX));
        set("--frames", "frames", v, f.to_string())?;
    }
    if let Some(r) = args.fps {
        set("--fps", "fps", ParamValue::Float(r), r.to_string())?;
    }
    Ok(())
}

/// The formats asked for, each once, in the order given.
fn formats(list: &[Format]) -> Vec<Format> {
    let mut out = Vec::new();
    for f in list {
        if !out.contains(f) {
            out.push(*f);
        }
    }
    out
}

fn export_err(e: ExportError) -> CliError {
    match e {
        ExportError::Io { path, source } => CliError::Io { path, source },
        ExportError::Cancelled => CliError::Cancelled,
        other => CliError::Usage(other.to_string()),
    }
}

/// The evaluator of a render: the memory cache's default budget, the disk cache of reference
/// images unless `no_cache`.
fn evaluator(no_cache: bool) -> Evaluator {
    let disk = if no_cache {
        None
    } else {
        samplescope::engine::default_disk_cache()
    };
    Evaluator::new(samplescope::engine::cache::DEFAULT_BUDGET, disk)
}

/// Evaluates every node the scene needs; the first failed node of any column is an error
/// naming the column and the node ([`Evaluator::evaluate_columns`]).
fn evaluate(
    scene: &Scene,
    plan: Arc<samplescope::scene::graph::Plan>,
    source: &str,
    no_cache: bool,
    cancel: &Cancel,
) -> Result<ColumnResults, CliError> {
    evaluator(no_cache)
        .evaluate_columns(scene, plan, cancel)
        .map_err(|e| match e {
            ColumnsError::Cancelled => CliError::Cancelled,
            ColumnsError::Failed(e) => CliError::Usage(format!("{source}: {e}")),
        })
}

/// Runs `samplescope render`.
pub fn run(args: &RenderArgs, session: &Session) -> Result<(), CliError> {
    render(args, None, session, &mut |path| {
        outln!("{}", path.display())
    })
}

/// Renders the scene of `args.scene` (or of the RON `text`, named `args.scene` in errors and
/// file names, its point files read relative to the current directory) into `args.out`,
/// calling `wrote` with each file once it is written.
pub fn render(
    args: &RenderArgs,
    text: Option<&str>,
    session: &Session,
    wrote: &mut dyn FnMut(&std::path::Path) -> Result<(), CliError>,
) -> Result<(), CliError> {
    let scale = args.scale.unwrap_or(1);
    if !SCALES.contains(&scale) {
        return Err(CliError::Usage(format!(
            "--scale = {}: must be an integer in {}..={}",
            scale,
            SCALES.start(),
            SCALES.end()
        )));
    }
    let formats = formats(&args.format);
    let gif = formats.contains(&Format::Gif);
    if !gif {
        let given = [args.frames.map(|_| "--frames"), args.fps.map(|_| "--fps")];
        if let Some(flag) = given.into_iter().flatten().next() {
            return Err(CliError::Usage(format!(
                "{flag} is only for --format gif (the frames of an animated GIF); add gif to \
                 --format or leave {flag} out"
            )));
        }
    }
    if formats.iter().all(|f| *f == Format::Csv) {
        // CSV only: nothing is drawn, so the drawing's size and shape have no effect.
        let given = [
            args.scale.map(|s| format!("--scale {s}")),
            args.aspect.map(|_| "--aspect".to_string()),
        ];
        if let Some(flag) = given.into_iter().flatten().next() {
            return Err(CliError::Usage(format!(
                "{flag} cannot be used with --format csv: CSV files hold the figures' data, \
                 not pictures, so {flag} would have no effect; add png, svg or pdf to --format \
                 or leave it out"
            )));
        }
    }
    let aspect = args.aspect.unwrap_or(Aspect::SLIDE);
    // The output directory is checked before any work: an existing file there is bad input.
    if args.out.exists() && !args.out.is_dir() {
        return Err(CliError::Usage(format!(
            "--out {}: exists and is not a directory (render writes its figures into a directory)",
            args.out.display()
        )));
    }
    samplescope::core::output::check_output_dir("--out", &args.out)?;
    let source = args.scene.display().to_string();
    let mut scene = match text {
        Some(text) => Scene::from_ron(text, &source),
        None => Scene::load(&args.scene),
    }
    .map_err(super::scene_error)?;
    animation_flags(args, &mut scene)?;
    // What a column's points node would refuse is refused before the estimate and the budget,
    // with the words of that node's failure.
    for (c, col) in scene.columns.iter().enumerate() {
        if col.points.is_none() {
            if let Err(e) = col.pattern.validate(scene.n) {
                let e = ColumnsError::failed(&scene, c, NodeKind::Points, &e);
                return Err(CliError::Usage(format!("{source}: {e}")));
            }
        }
    }
    let stem = args
        .scene
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    let stills: Vec<PublishFormat> = formats.iter().filter_map(|f| f.publish()).collect();
    // The animation is checked (the scene animates, its frames fit the GIF budget) and
    // planned before any work.
    let animation = if gif {
        let field = if args.frames.is_some() {
            "--frames"
        } else {
            "animation.frames"
        };
        let prepared = samplescope::engine::animation::prepare(&scene, &stem, scale, aspect, field)
            .map_err(|e| CliError::Usage(format!("{source}: --format gif: {e}")))?;
        Some(prepared)
    } else {
        None
    };
    // The scene is planned once: its nodes are estimated and checked before any is evaluated,
    // and the engine runs that plan.
    let planned = Arc::new(samplescope::scene::graph::plan(&scene));
    let mut plan = if stills.is_empty() {
        Vec::new()
    } else {
        samplescope::scene::cost::estimate_plan(&scene, &planned)
    };
    if let Some(a) = &animation {
        plan.extend(a.estimates.iter().cloned());
    }
    let Some(progress) = session.admit(plan).map_err(|e| match e {
        CliError::Budget(m) => CliError::Budget(format!("{source}: {m}")),
        other => other,
    })?
    else {
        return Ok(());
    };
    progress.stage(0);
    let cancel = &session.cancel;
    let mut made = samplescope::export::publish::Published::default();
    if !stills.is_empty() {
        let results = evaluate(&scene, planned, &source, args.no_cache, cancel)?;
        let columns = figure::figure_columns(&scene, &results, &stem)
            .map_err(|e| CliError::Usage(e.to_string()))?;
        let count = columns.len();
        let publication = figure::publication(&scene, columns, &stem);

        if panels::available(&scene).is_empty() {
            eprintln!(
                "warning: {source} shows none of the panels render draws (pattern, spectrum, \
                 zone plate, filter, cost view with convergence, sampling theorem); nothing \
                 written"
            );
        }
        made = publish(&publication, Target::All, &stills, scale, aspect, cancel)
            .map_err(export_err)?;
        if let Some((cw, ch)) = made.comparison_too_large {
            eprintln!(
                "warning: comparison skipped: {count} columns at --scale {scale} would be \
                 {cw}×{ch} pixels, more than {MAX_COMPOSITE_PIXELS}; use a smaller --scale"
            );
        }
    }
    if let Some(a) = &animation {
        use samplescope::engine::animation::{render_gif, AnimationError};
        let eval = evaluator(args.no_cache);
        let bytes = render_gif(a, &eval, cancel, &mut |_| {}).map_err(|e| match e {
            AnimationError::Cancelled => CliError::Cancelled,
            other => CliError::Usage(format!("{source}: --format gif: {other}")),
        })?;
        made.files.push((a.name.clone(), bytes));
    }
    drop(progress);
    std::fs::create_dir_all(&args.out).map_err(|source_err| CliError::Io {
        path: args.out.display().to_string(),
        source: source_err,
    })?;
    // Every file was made before any is written: a failure while making one leaves none.
    for (name, bytes) in made.files {
        let path = args.out.join(name);
        write_output(&path, &bytes, cancel)?;
        wrote(&path)?;
    }
    Ok(())
}
