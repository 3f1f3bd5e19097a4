//! `samplescope analyze`: statistics, discrepancies, t-value, PSA's statistics (effective
//! Nyquist frequency, oscillations, bond-orientational order; `--rdf` its radial distribution
//! function) and spectrum of a point set, with the time and accuracy of every stage.
//!
//! A front over a scene: [`read_input`] reads the points (files) or the pattern,
//! [`analyze_2d`] builds the scene ([`analysis_scene`]: one column of the pattern, or one
//! imported column per file), asks for the nodes it prints ([`asked_nodes`]), checks the
//! scene's estimate against the budget, evaluates it with the engine's `Evaluator` and prints
//! and writes what the nodes computed; `--spectrum` is the scene's spectrum figure published
//! through `export::publish`.

use super::outln;
use super::session::{check_outputs, write_output, Session};
use super::{parse_n, CliError};
use glam::DVec2;
use samplescope::core::budget::{self, Estimate};
use samplescope::core::cancel::Cancel;
use samplescope::core::metrics::{self, psa};
use samplescope::core::pattern::{Pattern, MAX_N};
use samplescope::core::pointset::{read_points_named, OutOfRange, PointsFileError};
use samplescope::core::spectrum::Spectrum;
use samplescope::engine::cache::DEFAULT_BUDGET;
use samplescope::engine::Evaluator;
use samplescope::export::figure::base_size;
use samplescope::model::{Accuracy, FigureKind, SpectrumData};
use samplescope::scene::graph::{self, NodeError, NodeKind, NodeResult, NodeValue};
use samplescope::scene::SpectrumSettings;
use samplescope::scene::{compute, cost, figure, Column, ImportedPoints, Panels, Scene};
use serde_json::json;
use std::collections::HashMap;
use std::fmt::Write as _;
use std::path::Path;
use std::sync::Arc;
use std::time::Instant;

/// The NUFFT tolerance without --tolerance.
const DEFAULT_TOLERANCE: f64 = 1e-6;

/// Parses `--tolerance`: a number in the NUFFT's range (NaN is refused).
fn parse_tolerance(text: &str) -> Result<f64, String> {
    use samplescope::core::spectrum::{MAX_TOLERANCE, MIN_TOLERANCE};
    text.trim()
        .parse::<f64>()
        .ok()
        .filter(|t| (MIN_TOLERANCE..=MAX_TOLERANCE).contains(t))
        .ok_or_else(|| {
            format!(
                "tolerance = {text}: must be a number in [{MIN_TOLERANCE:e}, {MAX_TOLERANCE:e}]"
            )
        })
}

/// Arguments of `samplescope analyze`.
#[derive(clap::Args, Debug)]
pub struct AnalyzeArgs {
    /// Pattern name (see `points --list`); or give --points.
    #[arg(required_unless_present = "points", conflicts_with = "points")]
    pub pattern: Option<String>,
    /// Number of points (with a pattern).
    #[arg(
        short = 'n',
        value_parser = parse_n,
        required_unless_present = "points",
        conflicts_with = "points"
    )]
    pub n: Option<usize>,
    /// Seed (with a random pattern) [default: 0].
    #[arg(long, conflicts_with = "points")]
    pub seed: Option<u64>,
    /// Keep the points placed when the pattern stops short of N (poisson-dart, poisson-bridson)
    /// instead of failing.
    #[arg(long, conflicts_with = "points")]
    pub allow_fewer: bool,
    /// Pattern parameter `key=value`; repeatable.
    #[arg(long = "set", value_name = "KEY=VALUE", conflicts_with = "points")]
    pub set: Vec<String>,
    /// Read the points from a file: CSV or `x y` text (optional header or count line),
    /// pmj-cpp's `(x, y),` rows, NumPy .npy or PSA .rps (see the README's formats). Several
    /// files (or a pattern such as 'runs/*.txt', expanded here when the shell did not) are
    /// realizations of one sampler: the spectrum, RAPS and RDF are averaged over them and every
    /// statistic is reported as mean ± sample standard deviation. They must hold the same N.
    #[arg(long, num_args = 1.., value_name = "FILE")]
    pub points: Vec<String>,
    /// Map the points' bounding box onto [0,1)² instead of rejecting points outside (with --points).
    #[arg(long, conflicts_with = "pattern")]
    pub normalize: bool,
    /// Analyse the 2D projection onto dimensions i and j (0-based), e.g. `--project 3,7`: of
    /// the files of --points (any number of columns), or of the pattern's points in --dims
    /// dimensions. Without it, a file of other than two columns gets the d-dimensional
    /// measures (see the README).
    #[arg(long, value_name = "I,J")]
    pub project: Option<String>,
    /// With a pattern: generate its points in D dimensions [default: 2] and analyse the
    /// projection --project i,j (each pattern's limit is in `points --list`).
    #[arg(long, value_name = "D", conflicts_with = "points")]
    pub dims: Option<usize>,
    /// Spectrum size M (M×M integer frequencies).
    #[arg(long, default_value_t = 256)]
    pub size: usize,
    /// Realizations K averaged (with a pattern; seeds derived from --seed). With --points, each
    /// file is one realization.
    #[arg(long, default_value_t = 1)]
    pub realizations: usize,
    /// NUFFT tolerance (relative ℓ2 error of P), 1e-12..=1e-2 [default: 1e-6]; not with --exact.
    #[arg(long, value_parser = parse_tolerance, conflicts_with = "exact")]
    pub tolerance: Option<f64>,
    /// Use the exact DFT instead of the NUFFT.
    #[arg(long)]
    pub exact: bool,
    /// Write the spectrum figure (the centred periodogram, log10 P, viridis, with its colour
    /// bar and the figures' metadata) as PNG.
    #[arg(long, value_name = "OUT.png")]
    pub spectrum: Option<String>,
    /// Write the averaged periodogram as CSV `kx,ky,power`.
    #[arg(long = "spectrum-data", value_name = "OUT.csv")]
    pub spectrum_data: Option<String>,
    /// Write the radially averaged power spectrum as CSV `radius,power`.
    #[arg(long, value_name = "OUT.csv")]
    pub raps: Option<String>,
    /// Write PSA's radial distribution function as CSV `r_min,r_max,r_mid_normalized,g`
    /// (N/8 bins up to 8 hexagonal spacings; r_mid_normalized = bin centre / d_hex).
    #[arg(long, value_name = "OUT.csv")]
    pub rdf: Option<String>,
    /// Print one JSON object instead of text.
    #[arg(long)]
    pub json: bool,
}

fn io_err(path: &str) -> impl FnOnce(std::io::Error) -> CliError + '_ {
    move |source| CliError::Io {
        path: path.to_string(),
        source,
    }
}

/// Expands `--points` arguments: a path that exists is kept as it is; one that does not and
/// has `*` or `?` in its file name (the shell left it: quoted, or no match there) is matched
/// against the files of its directory (`*` any run of characters, `?` one; names starting with
/// `.` only when the pattern does), sorted by name. A pattern that matches nothing is an error.
pub fn expand_points(args: &[String]) -> Result<Vec<String>, CliError> {
    let mut out = Vec::new();
    for a in args {
        let path = Path::new(a);
        let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("");
        if path.exists() || !(name.contains('*') || name.contains('?')) {
            out.push(a.clone());
            continue;
        }
        let dir = match path.parent() {
            Some(d) if !d.as_os_str().is_empty() => d,
            _ => Path::new("."),
        };
        let dir_text = dir.to_string_lossy();
        if dir_text.contains('*') || dir_text.contains('?') {
            return Err(CliError::Usage(format!(
                "--points {a}: wildcards are expanded in the file name only, not in directories"
            )));
        }
        let entries = std::fs::read_dir(dir).map_err(io_err(&dir_text))?;
        let mut found: Vec<String> = Vec::new();
        for e in entries {
            let e = e.map_err(io_err(&dir_text))?;
            let file = e.file_name();
            let Some(file) = file.to_str() else { continue };
            if file.starts_with('.') && !name.starts_with('.') {
                continue;
            }
            if wildcard_match(name.as_bytes(), file.as_bytes())
                && e.file_type().map(|t| !t.is_dir()).unwrap_or(false)
            {
                found.push(
                    if path.parent().is_some_and(|d| !d.as_os_str().is_empty()) {
                        dir.join(file).to_string_lossy().into_owned()
                    } else {
                        file.to_string()
                    },
                );
            }
        }
        if found.is_empty() {
            return Err(CliError::Usage(format!(
                "--points {a}: no file matches the pattern"
            )));
        }
        found.sort();
        out.extend(found);
    }
    Ok(out)
}

/// Whether `name` matches the wildcard `pattern` (`*` any run, `?` one byte).
fn wildcard_match(pattern: &[u8], name: &[u8]) -> bool {
    // Iterative matching with one backtrack point for the last `*`: O(len²) at worst.
    let (mut p, mut n) = (0, 0);
    let mut star: Option<(usize, usize)> = None;
    while n < name.len() {
        if p < pattern.len() && (pattern[p] == b'?' || pattern[p] == name[n]) {
            p += 1;
            n += 1;
        } else if p < pattern.len() && pattern[p] == b'*' {
            star = Some((p, n));
            p += 1;
        } else if let Some((sp, sn)) = star {
            p = sp + 1;
            n = sn + 1;
            star = Some((sp, sn + 1));
        } else {
            return false;
        }
    }
    pattern[p..].iter().all(|&c| c == b'*')
}

/// Reads the point files of `--points` (one realization each): the same N in every file, at
/// most [`MAX_N`] points in all.
fn read_point_files(
    files: &[String],
    normalize: bool,
    project: Option<&str>,
) -> Result<Vec<Vec<DVec2>>, CliError> {
    let mode = if normalize {
        OutOfRange::NormalizeToBoundingBox
    } else {
        OutOfRange::Reject
    };
    let mut sets: Vec<Vec<DVec2>> = Vec::with_capacity(files.len().min(1024));
    let mut total = 0usize;
    for path in files {
        if project.is_some() {
            let cube = super::analyze_cube::read(path, normalize)?;
            sets.push(super::analyze_cube::plane(path, &cube.points, project)?);
            continue;
        }
        let file = super::open_input(Path::new(path))?;
        // Streamed with a size and line-length limit: a binary or endless file is refused
        // after at most one line.
        let read = read_points_named(file, Path::new(path), mode).map_err(|e| match e {
            PointsFileError::Io { message, .. } => CliError::Io {
                path: path.clone(),
                source: std::io::Error::other(message),
            },
            e => CliError::Usage(format!("{path}: {e}")),
        })?;
        if read.on_closed_edge > 0 {
            eprintln!(
                "note: {path}: {} point(s) on the closed edge x = 1 or y = 1, taken as 1 − 2⁻⁵³",
                read.on_closed_edge
            );
        }
        if let Some(first) = sets.first() {
            if first.len() != read.points.len() {
                return Err(CliError::Usage(format!(
                    "--points: {} holds {} points but {path} holds {}: averaging needs the same N in every file",
                    files[0],
                    first.len(),
                    read.points.len()
                )));
            }
        }
        total += read.points.len();
        if total > MAX_N {
            return Err(CliError::Usage(format!(
                "--points: the files hold more than {MAX_N} points in all (at most {MAX_N} are analysed together)"
            )));
        }
        sets.push(read.points);
    }
    Ok(sets)
}

/// The statistics of one point set that `analyze` reports, by their JSON names (`None` where
/// undefined or skipped).
fn scalar_statistics(
    stats: &metrics::Statistics,
    psa_stats: Option<&metrics::PsaStatistics>,
) -> Vec<(&'static str, Option<f64>)> {
    let md = stats.min_distance.as_ref();
    vec![
        ("min_distance", md.map(|m| m.min_distance)),
        (
            "min_distance_normalized",
            md.map(|m| m.normalized_min_distance),
        ),
        ("mean_nn_distance", md.map(|m| m.mean_nn_distance)),
        ("star_discrepancy", stats.star.as_ref().map(|s| s.value)),
        ("l2_star_discrepancy", Some(stats.l2_star)),
        ("t_value", stats.t_value.as_ref().map(|t| t.t as f64)),
        ("effective_nyquist", psa_stats.map(|p| p.effective_nyquist)),
        ("oscillations", psa_stats.map(|p| p.oscillations)),
        (
            "bond_orientational_order",
            psa_stats.map(|p| p.bond_orientational_order),
        ),
    ]
}

/// Mean and sample standard deviation (denominator K − 1) of values over K ≥ 2 sets; `None`
/// when any set has no value.
fn mean_and_sd(values: &[Option<f64>]) -> Option<(f64, f64)> {
    let v: Option<Vec<f64>> = values.iter().copied().collect();
    let v = v?;
    let k = v.len() as f64;
    let mean = v.iter().sum::<f64>() / k;
    let var = v.iter().map(|x| (x - mean) * (x - mean)).sum::<f64>() / (k - 1.0).max(1.0);
    Some((mean, var.sqrt()))
}

/// The JSON of a prefix check (see [`metrics::net_prefixes`]).
fn net_prefixes_json(p: &metrics::NetPrefixes) -> serde_json::Value {
    json!({
        "base": 2,
        "prefixes": p.prefixes.iter().map(|c| json!({"n": c.n, "k": c.k, "net": c.is_net})).collect::<Vec<_>>(),
        "first_failure": p.first_failure.as_ref().map(|(c, v)| {
            let (w, h) = (0.5f64.powi(v.kx as i32), 0.5f64.powi(v.ky as i32));
            json!({
                "n": c.n,
                "k": c.k,
                "kx": v.kx,
                "ky": v.ky,
                "cell": [v.cell.0, v.cell.1],
                "interval": [[v.cell.0 as f64 * w, (v.cell.0 + 1) as f64 * w], [v.cell.1 as f64 * h, (v.cell.1 + 1) as f64 * h]],
                "count": v.count,
                "expected": v.expected,
            })
        }),
    })
}

/// The text line of a prefix check.
fn net_prefixes_text(p: &metrics::NetPrefixes) -> String {
    let list = |net: bool| -> Vec<String> {
        p.prefixes
            .iter()
            .filter(|c| c.is_net == net)
            .map(|c| c.n.to_string())
            .collect()
    };
    match &p.first_failure {
        None => format!(
            "all {} prefixes N = 1, 2, 4, …, {} are (0,k,2)-nets (base 2)",
            p.prefixes.len(),
            p.prefixes.last().map_or(1, |c| c.n)
        ),
        Some((c, v)) => {
            let (w, h) = (1u64 << v.kx, 1u64 << v.ky);
            let plural =
                |n: u64, what: &str| format!("{n} {what}{}", if n == 1 { "" } else { "s" });
            format!(
                "nets: N = {}; not nets: N = {}; first failure N = {} (k = {}): the 2^-{} × 2^-{} intervals ({} × {}), cell (column {}, row {}) = [{}/{w}, {}/{w}) × [{}/{h}, {}/{h}) holds {} point(s), expected {}",
                if list(true).is_empty() { "none".to_string() } else { list(true).join(", ") },
                list(false).join(", "),
                c.n,
                c.k,
                v.kx,
                v.ky,
                plural(w, "column"),
                plural(h, "row"),
                v.cell.0,
                v.cell.1,
                v.cell.0,
                v.cell.0 + 1,
                v.cell.1,
                v.cell.1 + 1,
                v.count,
                v.expected
            )
        }
    }
}

/// What `analyze` analyses, as read from its arguments.
pub enum Input {
    /// Point files, one realization each (the same N in every file): their names and points.
    Files {
        files: Vec<String>,
        sets: Vec<Vec<DVec2>>,
    },
    /// N points of a pattern (its realizations from seeds derived from `--seed`).
    Pattern { pattern: Pattern, n: usize },
    /// The 2D projection onto dimensions `pair` of N points of a pattern in `dims` dimensions
    /// (`--dims D --project i,j`): generated once the budget admits it, then analysed as the
    /// points of a file of that projection would be.
    Projection {
        pattern: Pattern,
        n: usize,
        dims: usize,
        pair: (usize, usize),
    },
}

impl Input {
    /// The name the points of a projection are shown under (figure label and metadata).
    fn projection_label(pattern: &Pattern, dims: usize, pair: (usize, usize)) -> String {
        format!("{} dims {},{} of {dims}", pattern.name(), pair.0, pair.1)
    }
}

/// Runs `samplescope analyze`: checks the outputs, reads the input ([`read_input`]) and
/// analyses it ([`analyze_2d`]).
pub fn run(args: &AnalyzeArgs, session: &Session) -> Result<(), CliError> {
    // Every output is checked before any work (and before a point file is read).
    check_outputs(&[
        ("--spectrum", args.spectrum.as_deref()),
        ("--spectrum-data", args.spectrum_data.as_deref()),
        ("--raps", args.raps.as_deref()),
        ("--rdf", args.rdf.as_deref()),
    ])?;
    // A file of other than two columns (without --project): the d-dimensional measures.
    if let (Some(first), None) = (args.points.first(), &args.project) {
        let files = expand_points(std::slice::from_ref(first))?;
        let cube = super::analyze_cube::read(&files[0], args.normalize)?;
        if cube.points.dims() != 2 {
            return super::analyze_cube::run(args, &files[0], &cube.points, session, Sink::Print);
        }
    }
    let t0 = Instant::now();
    let input = read_input(args)?;
    let read_ms = t0.elapsed().as_secs_f64() * 1e3;
    analyze_2d(args, input, read_ms, session, Sink::Print)
}

/// Where `analyze`'s result goes: printed (the command), or kept for a caller (the Python
/// module) as the object `--json` prints together with the arrays behind it.
pub enum Sink<'a> {
    /// Printed as text, or as JSON with `--json`.
    Print,
    /// Kept: the JSON object (whatever `--json` says), the spectrum and the RDF.
    Keep(&'a mut Kept),
}

/// What [`Sink::Keep`] keeps of one analysis.
#[derive(Default)]
pub struct Kept {
    /// The object `analyze --json` prints.
    pub json: serde_json::Value,
    /// The spectrum node's data: the periodogram, its RAPS and anisotropy (2D input only).
    pub spectrum: Option<Arc<SpectrumData>>,
    /// The RDF rows `r_min, r_max, r_mid_normalized, g` that `--rdf` writes (2D input only).
    pub rdf: Option<Vec<[f64; 4]>>,
}

/// Reads what `analyze` analyses: the point files of `--points` (read first, bounded and
/// streamed: their size sets the estimates), or the pattern and N, with everything the
/// generator would refuse refused before the estimate and the budget.
pub fn read_input(args: &AnalyzeArgs) -> Result<Input, CliError> {
    let files = expand_points(&args.points)?;
    if !files.is_empty() {
        if args.realizations != 1 {
            return Err(CliError::Usage(format!(
                "--realizations = {}: must be 1 with --points (each file is one realization)",
                args.realizations
            )));
        }
        let sets = read_point_files(&files, args.normalize, args.project.as_deref())?;
        return Ok(Input::Files { files, sets });
    }
    let name = args.pattern.as_deref().unwrap_or_default();
    let n = args.n.unwrap_or(0);
    let pattern = super::pattern_from_args(name, &args.set)?;
    super::check_seed(&pattern, args.seed, "--seed")?;
    super::check_allow_fewer(&pattern, args.allow_fewer)?;
    if let (Some(dims), None) = (args.dims, &args.project) {
        return Err(CliError::Usage(format!(
            "--dims {dims}: analyze takes a pattern's 2D projection: add --project i,j (i ≠ j \
             in 0..={}); for the d-dimensional measures write the points with `points --dims \
             {dims} --out F.csv` and give F.csv to --points",
            dims.saturating_sub(1)
        )));
    }
    if let Some(text) = &args.project {
        let dims = args.dims.unwrap_or(2);
        pattern.validate_cube(n, dims)?;
        let pair = super::points::parse_project(text, dims)?;
        if args.allow_fewer {
            return Err(CliError::Usage(
                "--allow-fewer: applies to 2D patterns only (no --project)".into(),
            ));
        }
        if args.realizations != 1 {
            return Err(CliError::Usage(format!(
                "--realizations = {}: must be 1 with --project (the projection is one point \
                 set; to average several, write them with `points --dims {dims} --project \
                 {text} --seed S` and give the files to --points)",
                args.realizations
            )));
        }
        return Ok(Input::Projection {
            pattern,
            n,
            dims,
            pair,
        });
    }
    if args.realizations > 1 && !pattern.is_random() {
        return Err(CliError::Usage(format!(
            "--realizations {}: {} with these parameters is deterministic, so every \
             realization is the same point set and averaging them has no effect; leave it out",
            args.realizations,
            pattern.name()
        )));
    }
    pattern.validate(n)?;
    Ok(Input::Pattern { pattern, n })
}

/// The scene `analyze` evaluates: one column of imported points per file, or one column of
/// the pattern (N points, seed `seed`); the spectrum panel alone, with `spectrum`'s settings.
/// The statistics it prints are asked for by name ([`asked_nodes`]).
pub fn analysis_scene(
    input: &Input,
    spectrum: SpectrumSettings,
    seed: u64,
    normalize: bool,
) -> Scene {
    let (columns, n) = match input {
        Input::Files { files, sets } => (
            files
                .iter()
                .zip(sets)
                .map(|(file, points)| Column {
                    seed,
                    points: Some(ImportedPoints {
                        path: String::new(),
                        normalize,
                        points: points.iter().map(|p| [p.x, p.y]).collect(),
                        source: file.clone(),
                    }),
                    ..Column::default()
                })
                .collect(),
            sets.first().map_or(0, Vec::len),
        ),
        Input::Pattern { pattern, n } => (
            vec![Column {
                pattern: *pattern,
                seed,
                ..Column::default()
            }],
            *n,
        ),
        // Imported points standing for the projection (filled once generated, `analyze_2d`).
        Input::Projection {
            pattern,
            n,
            dims,
            pair,
        } => (
            vec![Column {
                pattern: *pattern,
                seed,
                points: Some(ImportedPoints {
                    points: vec![[0.0, 0.0]; *n],
                    source: Input::projection_label(pattern, *dims, *pair),
                    ..Default::default()
                }),
                ..Column::default()
            }],
            *n,
        ),
    };
    let mut scene = Scene {
        title: "analyze".into(),
        columns,
        n,
        spectrum,
        ..Scene::default()
    };
    scene.panels = Panels {
        spectrum: true,
        ..Panels::none()
    };
    scene.effects.reconstruction = false;
    scene.effects.error = false;
    scene.effects.convergence = false;
    scene.effects.statistics = false;
    scene
}

/// The nodes `analyze` reads besides the spectrum its scene shows: the statistics and PSA's,
/// the RDF with `--rdf`, the prefixes' net check for point files.
pub fn asked_nodes(args: &AnalyzeArgs, files: bool, keep: bool) -> Vec<NodeKind> {
    let mut v = vec![NodeKind::Statistics, NodeKind::Psa, NodeKind::Spectrum];
    if args.rdf.is_some() || keep {
        v.push(NodeKind::Rdf);
    }
    if files {
        v.push(NodeKind::NetPrefixes);
    }
    v
}

/// The node results of every column of an evaluated scene.
pub type Results = Vec<HashMap<NodeKind, Arc<NodeResult>>>;

/// Runs `plan` of `scene` with the engine's evaluator (no disk cache): the results of every
/// column, or the first node that failed by itself (later ones fail through their inputs).
pub fn evaluate(scene: &Scene, plan: graph::Plan, cancel: &Cancel) -> Result<Results, CliError> {
    evaluate_shared(Arc::new(scene.clone()), plan, cancel, &mut |_, _| {})
}

/// [`evaluate`] of a scene already shared (not copied), calling `on_final` with each node's
/// column and kind as its final result arrives.
pub fn evaluate_shared(
    scene: Arc<Scene>,
    plan: graph::Plan,
    cancel: &Cancel,
    on_final: &mut dyn FnMut(usize, NodeKind),
) -> Result<Results, CliError> {
    let mut results: Results = vec![HashMap::new(); scene.columns.len()];
    Evaluator::new(DEFAULT_BUDGET, None).evaluate_shared(
        scene,
        Arc::new(plan),
        cancel,
        &mut |c, kind, r| {
            on_final(c, kind);
            results[c].insert(kind, r);
        },
    );
    if cancel.is_cancelled() {
        return Err(CliError::Cancelled);
    }
    for kind in [
        NodeKind::Points,
        NodeKind::Statistics,
        NodeKind::Psa,
        NodeKind::Spectrum,
        NodeKind::Rdf,
        NodeKind::NetPrefixes,
    ] {
        for r in &results {
            match r.get(&kind).map(|r| &r.value) {
                Some(Err(NodeError::Input { .. })) | Some(Ok(_)) | None => {}
                Some(Err(e)) => return Err(super::node_error(e)),
            }
        }
    }
    Ok(results)
}

/// The `T` value of node `kind` in every column (an internal error if one has none).
pub fn values<'a, T>(
    results: &'a Results,
    kind: NodeKind,
    pick: impl Fn(&'a NodeValue) -> Option<&'a Arc<T>>,
) -> Result<Vec<&'a Arc<T>>, CliError> {
    results
        .iter()
        .map(|r| {
            r.get(&kind)
                .and_then(|r| r.value.as_ref().ok())
                .and_then(&pick)
                .ok_or_else(|| {
                    CliError::Environment(format!(
                        "analyze: the {} node did not finish",
                        kind.name()
                    ))
                })
        })
        .collect()
}

/// The sum of node `kind`'s wall times over the columns, in ms.
fn wall_ms(results: &Results, kind: NodeKind) -> f64 {
    results
        .iter()
        .filter_map(|r| r.get(&kind))
        .map(|r| r.wall.as_secs_f64() * 1e3)
        .sum()
}

/// The tolerance asked for and the error measured, from a spectrum node's accuracy.
fn spectrum_accuracy(a: Option<&Accuracy>) -> (Option<f64>, Option<f64>) {
    match a {
        Some(Accuracy::SpectrumMeasured {
            relative_l2, asked, ..
        }) => (Some(*asked), Some(*relative_l2)),
        Some(Accuracy::SpectrumAsked { tolerance }) => (Some(*tolerance), None),
        Some(Accuracy::ImportedOneRealization { spectrum, .. }) => {
            spectrum_accuracy(Some(spectrum))
        }
        _ => (None, None),
    }
}

/// The mean of the columns' periodograms (the spectrum of K ≥ 2 files: each file is one
/// realization), summed in column order and scaled by 1/K as the core averages
/// realizations; its display data as the spectrum node makes it, with the columns' stage
/// times summed (the mean's own time in `average`).
pub fn mean_spectrum(spectra: &[&Arc<SpectrumData>]) -> Result<SpectrumData, CliError> {
    let t = Instant::now();
    let first = &spectra[0].power;
    let mut power = vec![0.0; first.power.len()];
    for s in spectra {
        for (a, p) in power.iter_mut().zip(&s.power.power) {
            *a += p;
        }
    }
    let k = spectra.len();
    if k > 1 {
        let inv = 1.0 / k as f64;
        power.iter_mut().for_each(|a| *a *= inv);
    }
    let mean = Spectrum {
        m: first.m,
        power,
        n_points: spectra.iter().map(|s| s.power.n_points).min().unwrap_or(0),
        realizations: k,
        dc: first.dc,
    };
    let average_ms = t.elapsed().as_secs_f64() * 1e3;
    let mut stages: Vec<(String, f64)> = spectra[0].stages.clone();
    for s in &spectra[1..] {
        for ((_, total), (_, v)) in stages.iter_mut().zip(&s.stages) {
            *total += v;
        }
    }
    if let Some((_, v)) = stages.iter_mut().find(|(name, _)| name == "average") {
        *v += average_ms;
    }
    compute::spectrum_data(Arc::new(mean), stages).map_err(|e| CliError::Usage(e.to_string()))
}

/// The `--spectrum` PNG: the scene's spectrum figure of column 0, published through
/// `export::publish` as `render` publishes it (its title, colour bar and metadata); over K ≥ 2
/// files the figure of `spectrum`, their mean, labelled with the files.
fn spectrum_figure(
    scene: &Scene,
    results: &Results,
    spectrum: &Arc<SpectrumData>,
    averaged: bool,
    input: &Input,
    cancel: &Cancel,
) -> Result<Vec<u8>, CliError> {
    let usage = |e: &dyn std::fmt::Display| CliError::Usage(e.to_string());
    let (one, columns) = if averaged {
        // One column standing for the K files, drawing their mean.
        let mut one = scene.clone();
        let k = one.columns.len();
        one.columns.truncate(1);
        let names: Vec<String> = scene
            .columns
            .iter()
            .filter_map(|c| c.points.as_ref().map(|p| p.label()))
            .collect();
        one.columns[0].label = format!("mean of {k} files ({} points each)", scene.n);
        let mut columns =
            figure::figure_columns(&one, &results[..1], "analyze").map_err(|e| usage(&e))?;
        let (ctx, data) = &mut columns[0];
        ctx.pattern_params = format!("files={}", names.join(","));
        data.spectrum = spectrum.clone().into();
        ctx.spectrum_range = samplescope::model::shared_spectrum_range(&[spectrum.auto_range]);
        (one, columns)
    } else {
        let mut columns =
            figure::figure_columns(scene, results, "analyze").map_err(|e| usage(&e))?;
        // A projection's metadata names the pattern, its parameters and the pair.
        if let Input::Projection {
            pattern,
            dims,
            pair,
            ..
        } = input
        {
            let ctx = &mut columns[0].0;
            ctx.pattern = pattern.name().to_string();
            ctx.pattern_params = format!(
                "{} dims={dims} project={},{}",
                samplescope::core::params::Params::params_text(pattern),
                pair.0,
                pair.1
            )
            .trim_start()
            .to_string();
        }
        (scene.clone(), columns)
    };
    super::figure_png(&one, columns, "analyze", FigureKind::Spectrum, cancel)
}

/// The spectrum settings of `analyze`'s scene for `input`, the request they make (averaged
/// over the files) checked with the core's messages; DC masked in the figure only (the
/// numbers hold it).
pub fn spectrum_settings(args: &AnalyzeArgs, input: &Input) -> Result<SpectrumSettings, CliError> {
    let settings = SpectrumSettings {
        size: args.size,
        tolerance: args.tolerance.unwrap_or(DEFAULT_TOLERANCE),
        exact: args.exact,
        realizations: args.realizations,
        mask_dc: true,
    };
    let (k, n) = match input {
        Input::Files { sets, .. } => (sets.len(), sets[0].len()),
        Input::Pattern { n, .. } => (args.realizations, *n),
        Input::Projection { n, .. } => (1, *n),
    };
    SpectrumSettings {
        realizations: k,
        ..settings
    }
    .request(n, false)
    .validate()
    .map_err(|e| CliError::Usage(e.to_string()))?;
    Ok(settings)
}

/// Analyses 2D points (`input`, read in `read_ms`): the scene of [`analysis_scene`] checked
/// against the budget with the scene's estimate (`scene::cost`) and the outputs', evaluated
/// by the engine's `Evaluator`; over K ≥ 2 files the spectrum and RDF are the means of the
/// columns'. `--spectrum` is the scene's spectrum figure, published through
/// `export::publish`. With [`Sink::Keep`] the RDF is computed too and the result is kept, not
/// printed.
pub fn analyze_2d(
    args: &AnalyzeArgs,
    mut input: Input,
    read_ms: f64,
    session: &Session,
    mut sink: Sink<'_>,
) -> Result<(), CliError> {
    let cancel = &session.cancel;
    let seed = args.seed.unwrap_or(0);
    let files: Vec<String> = match &input {
        Input::Files { files, .. } => files.clone(),
        Input::Pattern { .. } | Input::Projection { .. } => Vec::new(),
    };
    let is_files = !files.is_empty();
    // A projection is analysed as a file of it would be (the prefixes' net check included).
    let is_points = is_files || matches!(input, Input::Projection { .. });
    // Files averaged (K ≥ 2) or one set.
    let sets_k = match &input {
        Input::Files { sets, .. } => sets.len(),
        Input::Pattern { .. } | Input::Projection { .. } => 1,
    };
    let averaged = sets_k > 1;
    let settings = spectrum_settings(args, &input)?;
    let n = match &input {
        Input::Files { sets, .. } => sets[0].len(),
        Input::Pattern { n, .. } | Input::Projection { n, .. } => *n,
    };
    let mut scene = analysis_scene(&input, settings, seed, args.normalize);
    // The scene holds its own copy of the files' points: the ones read are not needed again.
    if let Input::Files { sets, .. } = &mut input {
        sets.iter_mut().for_each(|s| *s = Vec::new());
    }
    let asked = asked_nodes(args, is_points, matches!(sink, Sink::Keep(_)));
    let mut plan = graph::plan_asking(&scene, &asked);
    // The engine runs the scene's nodes at the same time, while the scene holds its imported
    // points (a projection's are filled in below): their memory adds up.
    let mut estimates: Vec<Estimate> = Vec::new();
    if let Input::Projection {
        pattern, n, dims, ..
    } = &input
    {
        // The d-dimensional points the projection is taken from.
        estimates.push(budget::pattern_cube(pattern, *n, *dims));
    }
    let nodes_from = estimates.len();
    if is_points {
        estimates.push(budget::points_held(n * sets_k).concurrent());
    }
    estimates.extend(
        cost::estimate_plan(&scene, &plan)
            .into_iter()
            .map(Estimate::concurrent),
    );
    let nodes = nodes_from..estimates.len();
    let m = args.size;
    if args.spectrum.is_some() {
        // The spectrum figure's PNG, at its base size.
        let (fw, fh) = base_size(FigureKind::Spectrum);
        estimates.push(budget::png(fw as usize, fh as usize));
    }
    if args.spectrum_data.is_some() {
        estimates.push(budget::text_rows("spectrum CSV", m * m));
    }
    if args.rdf.is_some() {
        estimates.push(budget::text_rows("RDF CSV", psa::psa_rdf_range(n).0));
    }
    let Some(progress) = session.admit(estimates)? else {
        return Ok(());
    };
    progress.stage(0);
    // A pattern that may stop short with --allow-fewer: its points are generated here (as the
    // scene's points node would); a short set is shown as imported points.
    let t0 = Instant::now();
    if let (true, Input::Pattern { pattern, n }) = (args.allow_fewer, &input) {
        let g = pattern.generate_with(*n, seed, cancel)?;
        let points = super::require_points(g, pattern, true)?;
        if points.len() < *n {
            if args.realizations > 1 {
                return Err(CliError::Usage(format!(
                    "--realizations {}: {} placed {} of {n} points, and the other realizations \
                     need all of them; leave --realizations out to analyse the points placed",
                    args.realizations,
                    pattern.name(),
                    points.len()
                )));
            }
            scene.n = points.len();
            scene.columns[0].points = Some(ImportedPoints {
                points: points.iter().map(|p| [p.x, p.y]).collect(),
                source: pattern.name().into(),
                ..Default::default()
            });
            plan = graph::plan_asking(&scene, &asked);
        }
    }
    if let Input::Projection {
        pattern,
        n,
        dims,
        pair,
    } = &input
    {
        let cube = pattern.generate_cube(*n, *dims, seed, cancel)?;
        let points = cube
            .project(pair.0, pair.1)
            .map_err(|e| CliError::Usage(format!("--project {e}")))?;
        scene.columns[0].points = Some(ImportedPoints {
            points: points.iter().map(|p| [p.x, p.y]).collect(),
            source: Input::projection_label(pattern, *dims, *pair),
            ..Default::default()
        });
        plan = graph::plan_asking(&scene, &asked);
    }
    let generated_ms = t0.elapsed().as_secs_f64() * 1e3;
    progress.concurrent(nodes.clone());
    let scene = Arc::new(scene);
    let results = evaluate_shared(scene.clone(), plan, cancel, &mut |c, kind| {
        let estimate = cost::node_estimate(&scene, c, kind);
        progress.finished(estimate.iter().map(|e| e.seconds).sum());
    })?;
    progress.stage(nodes.end);
    let points = values(&results, NodeKind::Points, |v| match v {
        NodeValue::Points(p) => Some(p),
        _ => None,
    })?;
    // A sampler may stop short of the n asked for (it says so in its note).
    let n = points[0].points.len();
    let stats = values(&results, NodeKind::Statistics, |v| match v {
        NodeValue::Statistics(s) => Some(s),
        _ => None,
    })?;
    let all_stats: Vec<&metrics::Statistics> = stats.iter().map(|s| &s.full).collect();
    let psa = values(&results, NodeKind::Psa, |v| match v {
        NodeValue::Psa(p) => Some(p),
        _ => None,
    })?;
    let psa_skipped = psa[0].skipped.clone();
    let all_psa: Option<Vec<metrics::PsaStatistics>> = psa.iter().map(|p| p.statistics).collect();
    let spectra = values(&results, NodeKind::Spectrum, |v| match v {
        NodeValue::Spectrum(s) => Some(s),
        _ => None,
    })?;
    let spectrum: Arc<SpectrumData> = if averaged {
        Arc::new(mean_spectrum(&spectra)?)
    } else {
        spectra[0].clone()
    };
    let (tolerance, error) = spectrum_accuracy(
        results[0]
            .get(&NodeKind::Spectrum)
            .and_then(|r| r.accuracy.as_ref()),
    );

    // Timings, in the order of the stages: points, statistics, PSA, spectrum, RDF, nets.
    let mut timings: Vec<(String, f64)> = vec![(
        "points".into(),
        read_ms + generated_ms + wall_ms(&results, NodeKind::Points),
    )];
    let mut stat_ms: Vec<(String, f64)> = Vec::new();
    for s in &all_stats {
        for (i, (name, d)) in s.timings.iter().enumerate() {
            if stat_ms.len() <= i {
                stat_ms.push((name.to_string(), 0.0));
            }
            stat_ms[i].1 += d.as_secs_f64() * 1e3;
        }
    }
    timings.extend(stat_ms);
    if all_psa.is_some() {
        timings.push(("PSA statistics".into(), wall_ms(&results, NodeKind::Psa)));
    }
    for (name, ms) in &spectrum.stages {
        timings.push((format!("spectrum {name}"), *ms));
    }

    // Every output is made before any is written: a failure leaves none of them.
    let mut outputs: Vec<(&String, Vec<u8>)> = Vec::new();
    if let Some(path) = &args.spectrum {
        outputs.push((
            path,
            spectrum_figure(&scene, &results, &spectrum, averaged, &input, cancel)?,
        ));
    }
    if let Some(path) = &args.spectrum_data {
        let mut s = String::from("kx,ky,power\n");
        for (kx, ky, p) in spectrum.power.to_csv_rows() {
            let _ = writeln!(s, "{kx},{ky},{p:?}");
        }
        outputs.push((path, s.into_bytes()));
    }
    if let Some(path) = &args.raps {
        let mut s = String::from("radius,power\n");
        for [radius, power] in &spectrum.raps {
            let _ = writeln!(s, "{radius:?},{power:?}");
        }
        outputs.push((path, s.into_bytes()));
    }
    if args.rdf.is_some() || matches!(sink, Sink::Keep(_)) {
        let rdfs = values(&results, NodeKind::Rdf, |v| match v {
            NodeValue::Rdf(g) => Some(g),
            _ => None,
        })?;
        // The mean of the sets' g over the same bins (all sets hold N points).
        let t0 = Instant::now();
        let mut mean: Vec<f64> = vec![0.0; rdfs[0].values().len()];
        for g in &rdfs {
            for (acc, v) in mean.iter_mut().zip(g.values()) {
                *acc += v;
            }
        }
        for v in &mut mean {
            *v /= rdfs.len() as f64;
        }
        let dr = rdfs[rdfs.len() - 1].bin_width();
        timings.push((
            "RDF".into(),
            wall_ms(&results, NodeKind::Rdf) + t0.elapsed().as_secs_f64() * 1e3,
        ));
        let d_hex = metrics::hex_distance(n);
        let rows: Vec<[f64; 4]> = mean
            .iter()
            .enumerate()
            .map(|(i, &v)| {
                let (lo, hi) = (i as f64 * dr, (i + 1) as f64 * dr);
                [lo, hi, 0.5 * (lo + hi) / d_hex, v]
            })
            .collect();
        if let Some(path) = &args.rdf {
            let mut s = String::from("r_min,r_max,r_mid_normalized,g\n");
            for [lo, hi, mid, v] in &rows {
                let _ = writeln!(s, "{lo:?},{hi:?},{mid:?},{v:?}");
            }
            outputs.push((path, s.into_bytes()));
        }
        if let Sink::Keep(kept) = &mut sink {
            kept.rdf = Some(rows);
        }
    }
    // For point files and projections: the (0,k,2)-net check of every power-of-two prefix.
    let nets: Vec<metrics::NetPrefixes> = if is_points {
        timings.push((
            "net prefixes".into(),
            wall_ms(&results, NodeKind::NetPrefixes),
        ));
        values(&results, NodeKind::NetPrefixes, |v| match v {
            NodeValue::NetPrefixes(p) => Some(p),
            _ => None,
        })?
        .into_iter()
        .map(|p| (**p).clone())
        .collect()
    } else {
        Vec::new()
    };
    for (path, bytes) in outputs {
        write_output(Path::new(path), &bytes, cancel)?;
    }
    drop(progress);

    let spectrum_json = json!({
        "size": spectrum.power.m,
        "realizations": spectrum.power.realizations,
        "method": if args.exact { "exact" } else { "nufft" },
        "tolerance": tolerance,
        "measured_relative_l2_error": error,
    });
    let spectrum_line = format!(
        "spectrum               {}² · K = {} · {}",
        spectrum.power.m,
        spectrum.power.realizations,
        match (tolerance, error) {
            (Some(t), Some(e)) => format!("NUFFT, asked {t:.0e}, measured rel. ℓ2 error {e:.2e}"),
            (Some(t), None) => format!("NUFFT, asked {t:.0e} (exact check too expensive)"),
            (None, _) => "exact DFT".to_string(),
        }
    );
    if let Sink::Keep(kept) = &mut sink {
        kept.spectrum = Some(spectrum.clone());
    }
    if averaged {
        return print_averaged(
            args,
            &files,
            n,
            &all_stats,
            all_psa.as_deref(),
            psa_skipped,
            &nets,
            spectrum_json,
            &spectrum_line,
            &timings,
            sink,
        );
    }
    let stats = all_stats[0];
    let psa_stats = all_psa.as_ref().map(|v| v[0]);
    let md = stats.min_distance.as_ref();
    if args.json || matches!(sink, Sink::Keep(_)) {
        let timings_obj: serde_json::Map<String, serde_json::Value> =
            timings.iter().map(|(k, v)| (k.clone(), json!(v))).collect();
        let mut out = json!({
            "n": n,
            "min_distance": md.map(|m| m.min_distance),
            "min_distance_normalized": md.map(|m| m.normalized_min_distance),
            "mean_nn_distance": md.map(|m| m.mean_nn_distance),
            "star_discrepancy": stats.star.as_ref().map(|s| s.value),
            "star_discrepancy_box": stats.star.as_ref().map(|s| [s.worst_box.0, s.worst_box.1]),
            "l2_star_discrepancy": stats.l2_star,
            "t_value": stats.t_value.as_ref().map(|t| t.t),
            "effective_nyquist": psa_stats.map(|p| p.effective_nyquist),
            "oscillations": psa_stats.map(|p| p.oscillations),
            "bond_orientational_order": psa_stats.map(|p| p.bond_orientational_order),
            "psa_skipped": psa_skipped,
            "spectrum": spectrum_json,
            "timings_ms": timings_obj,
        });
        if let Some(p) = nets.first() {
            out["net_prefixes"] = net_prefixes_json(p);
        }
        match sink {
            Sink::Keep(kept) => kept.json = out,
            Sink::Print => outln!("{out}")?,
        }
    } else {
        outln!("n                      {n}")?;
        if let Some(m) = md {
            outln!(
                "min distance           {:.6}  ({:.4} × hexagonal packing distance)",
                m.min_distance,
                m.normalized_min_distance
            )?;
            outln!("mean NN distance       {:.6}", m.mean_nn_distance)?;
        }
        match &stats.star {
            Some(s) => outln!(
                "star discrepancy D*    {:.6e}  (worst anchored box [0,{:.6})×[0,{:.6}))",
                s.value,
                s.worst_box.0,
                s.worst_box.1
            )?,
            None => outln!(
                "star discrepancy D*    skipped: {}",
                stats.star_skipped.clone().unwrap_or_default()
            )?,
        }
        outln!("L2-star discrepancy    {:.6e}", stats.l2_star)?;
        match &stats.t_value {
            Some(t) => outln!(
                "t-value (base 2)       {}  ((t, m, 2)-net with m = {})",
                t.t,
                t.m
            )?,
            None => outln!(
                "t-value (base 2)       undefined: {}",
                stats.t_value_skipped.clone().unwrap_or_default()
            )?,
        }
        if let Some(p) = nets.first() {
            outln!("(0,k,2)-net prefixes   {}", net_prefixes_text(p))?;
        }
        match &psa_stats {
            Some(p) => {
                outln!(
                    "effective Nyquist      {:.6}  (PSA: × the Nyquist frequency √N/2 of a grid)",
                    p.effective_nyquist
                )?;
                outln!("oscillations           {:.6}  (PSA)", p.oscillations)?;
                outln!(
                    "bond-orient. order     {:.6}  (PSA: mean |ψ₆|, 1 = hexagonal)",
                    p.bond_orientational_order
                )?;
            }
            None => outln!(
                "PSA statistics         skipped: {}",
                psa_skipped.clone().unwrap_or_default()
            )?,
        }
        outln!("{spectrum_line}")?;
        outln!("timings (ms)")?;
        for (k, v) in &timings {
            outln!("  {k:<22} {v:.3}")?;
        }
    }
    Ok(())
}

/// Prints the result over K ≥ 2 files: every statistic as mean ± sample standard deviation
/// (denominator K − 1) with its per-file values; the spectrum, RAPS and RDF written above are
/// the means over the files.
#[allow(clippy::too_many_arguments)]
fn print_averaged(
    args: &AnalyzeArgs,
    files: &[String],
    n: usize,
    all_stats: &[&metrics::Statistics],
    all_psa: Option<&[metrics::PsaStatistics]>,
    psa_skipped: Option<String>,
    nets: &[metrics::NetPrefixes],
    spectrum_json: serde_json::Value,
    spectrum_line: &str,
    timings: &[(String, f64)],
    sink: Sink<'_>,
) -> Result<(), CliError> {
    let k = all_stats.len();
    // Per statistic, the values of every file.
    let per_file: Vec<Vec<(&'static str, Option<f64>)>> = all_stats
        .iter()
        .enumerate()
        .map(|(i, s)| scalar_statistics(s, all_psa.map(|p| &p[i])))
        .collect();
    let names: Vec<&'static str> = per_file[0].iter().map(|(name, _)| *name).collect();
    let column = |j: usize| -> Vec<Option<f64>> { per_file.iter().map(|f| f[j].1).collect() };
    if args.json || matches!(sink, Sink::Keep(_)) {
        let timings_obj: serde_json::Map<String, serde_json::Value> =
            timings.iter().map(|(k, v)| (k.clone(), json!(v))).collect();
        let mut out = json!({
            "files": files,
            "n": n,
            "spread": "sample standard deviation over the files (denominator K - 1)",
        });
        for (j, name) in names.iter().enumerate() {
            let values = column(j);
            let ms = mean_and_sd(&values);
            out[*name] = json!({
                "mean": ms.map(|m| m.0),
                "std_dev": ms.map(|m| m.1),
                "per_file": values,
            });
        }
        out["star_discrepancy_box"] = json!(all_stats
            .iter()
            .map(|s| s.star.as_ref().map(|s| [s.worst_box.0, s.worst_box.1]))
            .collect::<Vec<_>>());
        out["psa_skipped"] = json!(psa_skipped);
        out["net_prefixes"] = json!(nets.iter().map(net_prefixes_json).collect::<Vec<_>>());
        out["spectrum"] = spectrum_json;
        out["timings_ms"] = json!(timings_obj);
        match sink {
            Sink::Keep(kept) => kept.json = out,
            Sink::Print => outln!("{out}")?,
        }
        return Ok(());
    }
    outln!(
        "files                  {k}, each n = {n}; mean ± sample standard deviation over the files"
    )?;
    let labels = [
        "min distance",
        "min distance / d_hex",
        "mean NN distance",
        "star discrepancy D*",
        "L2-star discrepancy",
        "t-value (base 2)",
        "effective Nyquist",
        "oscillations",
        "bond-orient. order",
    ];
    for (j, label) in labels.iter().enumerate() {
        let values = column(j);
        match mean_and_sd(&values) {
            Some((mean, sd)) => outln!("{label:<22} {mean:.6e} ± {sd:.6e}")?,
            None if j >= 6 => {}
            None => outln!("{label:<22} undefined for at least one file")?,
        }
    }
    if let Some(s) = &psa_skipped {
        outln!("PSA statistics         skipped: {s}")?;
    }
    for (f, p) in files.iter().zip(nets) {
        outln!("(0,k,2)-net prefixes   {f}: {}", net_prefixes_text(p))?;
    }
    outln!("{spectrum_line}")?;
    outln!("timings (ms)")?;
    for (k, v) in timings {
        outln!("  {k:<22} {v:.3}")?;
    }
    Ok(())
}
