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

use super::outln;
use super::session::{write_output, Session};
use super::CliError;
use samplescope::core::cancel::Cancel;
use samplescope::engine::Evaluator;
use samplescope::export::figure::{Aspect, FileFormat, MAX_COMPOSITE_PIXELS, SCALES};
use samplescope::export::publish::{publish, Format as PublishFormat, Target};
use samplescope::export::ExportError;
use samplescope::scene::graph::{NodeKind, NodeResult};
use samplescope::scene::{figure, panels, Scene};
use std::collections::HashMap;
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
    /// svg and pdf asked for).
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
}

impl Format {
    /// The format published.
    fn publish(self) -> PublishFormat {
        match self {
            Format::Png => PublishFormat::Picture(FileFormat::Png),
            Format::Svg => PublishFormat::Picture(FileFormat::Svg),
            Format::Pdf => PublishFormat::Picture(FileFormat::Pdf),
            Format::Csv => PublishFormat::Csv,
        }
    }
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

/// Evaluates every node the scene needs; the first failed node (in evaluation order) of any
/// column is an error naming the column and the node.
fn evaluate(
    scene: &Scene,
    plan: Arc<samplescope::scene::graph::Plan>,
    source: &str,
    no_cache: bool,
    cancel: &Cancel,
) -> Result<Vec<HashMap<NodeKind, Arc<NodeResult>>>, CliError> {
    let mut results: Vec<HashMap<NodeKind, Arc<NodeResult>>> =
        vec![HashMap::new(); scene.columns.len()];
    let disk = if no_cache {
        None
    } else {
        samplescope::engine::default_disk_cache()
    };
    let eval = Evaluator::new(samplescope::engine::cache::DEFAULT_BUDGET, disk);
    eval.evaluate_planned(scene, plan, cancel, &mut |c, kind, r| {
        if let Some(col) = results.get_mut(c) {
            col.insert(kind, r);
        }
    });
    if cancel.is_cancelled() {
        return Err(CliError::Cancelled);
    }
    for (c, col) in results.iter().enumerate() {
        for kind in NodeKind::ALL {
            if let Some(Err(e)) = col.get(&kind).map(|r| &r.value) {
                return Err(CliError::Usage(format!(
                    "{source}: column {} ({}): {} node failed: {e}",
                    c + 1,
                    scene.columns[c].title(),
                    kind.name()
                )));
            }
        }
    }
    Ok(results)
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
    let scene = match text {
        Some(text) => Scene::from_ron(text, &source),
        None => Scene::load(&args.scene),
    }
    .map_err(super::scene_error)?;
    // What a column's points node would refuse is refused before the estimate and the budget,
    // with the words of that node's failure.
    for (c, col) in scene.columns.iter().enumerate() {
        if col.points.is_none() {
            if let Err(e) = col.pattern.validate(scene.n) {
                return Err(CliError::Usage(format!(
                    "{source}: column {} ({}): {} node failed: {e}",
                    c + 1,
                    col.title(),
                    NodeKind::Points.name()
                )));
            }
        }
    }
    let stem = args
        .scene
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    // The scene is planned once: its nodes are estimated and checked before any is evaluated,
    // and the engine runs that plan.
    let planned = Arc::new(samplescope::scene::graph::plan(&scene));
    let plan = samplescope::scene::cost::estimate_plan(&scene, &planned);
    let Some(progress) = session.admit(plan).map_err(|e| match e {
        CliError::Budget(m) => CliError::Budget(format!("{source}: {m}")),
        other => other,
    })?
    else {
        return Ok(());
    };
    progress.stage(0);
    let cancel = &session.cancel;
    let results = evaluate(&scene, planned, &source, args.no_cache, cancel)?;
    drop(progress);

    let columns = figure::figure_columns(&scene, &results, &stem)
        .map_err(|e| CliError::Usage(e.to_string()))?;
    let count = columns.len();
    let publication = figure::publication(&scene, columns, &stem);

    if panels::available(&scene).is_empty() {
        eprintln!(
            "warning: {source} shows none of the panels render draws (pattern, spectrum, zone \
             plate, filter, cost view with convergence, sampling theorem); nothing written"
        );
    }
    let formats: Vec<PublishFormat> = formats.iter().map(|f| f.publish()).collect();
    let made =
        publish(&publication, Target::All, &formats, scale, aspect, cancel).map_err(export_err)?;
    if let Some((cw, ch)) = made.comparison_too_large {
        eprintln!(
            "warning: comparison skipped: {count} columns at --scale {scale} would be {cw}×{ch} \
             pixels, more than {MAX_COMPOSITE_PIXELS}; use a smaller --scale"
        );
    }
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
