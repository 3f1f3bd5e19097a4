//! `analyze --points F` for a file of other than two columns: the measures of a point set in
//! [0,1)^d (`core::metrics::cube`) — the five L2 discrepancies (scipy's conventions: L2-star
//! the root, CD, WD, MD and SD squared), the minimum toroidal distance, whether each 1D
//! projection is stratified, and the table of every 2D projection worst first — as text or
//! `--json`, inside the budget (each measure estimated first, progress while it runs,
//! cancellable). `--project i,j` instead takes the pair of columns into every 2D analysis
//! ([`plane`]).

use super::outln;
use super::session::Session;
use super::CliError;
use glam::DVec2;
use samplescope::core::budget;
use samplescope::core::cube::CubePoints;
use samplescope::core::metrics::cube::{self, CubeMeasure, Discrepancy};
use samplescope::core::metrics::MetricsError;
use samplescope::core::pointset::{read_cube_named, CubeRead, OutOfRange, PointsFileError};
use samplescope::core::progress::Progress as Report;
use serde_json::json;
use std::path::Path;

fn metrics_err(e: MetricsError) -> CliError {
    match e {
        MetricsError::Cancelled => CliError::Cancelled,
        e => CliError::Usage(e.to_string()),
    }
}

/// Reads one `--points` file with any number of columns.
pub fn read(path: &str, normalize: bool) -> Result<CubeRead, CliError> {
    let mode = if normalize {
        OutOfRange::NormalizeToBoundingBox
    } else {
        OutOfRange::Reject
    };
    let file = super::open_input(Path::new(path))?;
    let read = read_cube_named(file, Path::new(path), mode).map_err(|e| match e {
        PointsFileError::Io { message, .. } => CliError::Io {
            path: path.to_string(),
            source: std::io::Error::other(message),
        },
        e => CliError::Usage(format!("{path}: {e}")),
    })?;
    if read.on_closed_edge > 0 {
        eprintln!(
            "note: {path}: {} point(s) with a coordinate exactly 1, taken as 1 − 2⁻⁵³",
            read.on_closed_edge
        );
    }
    Ok(read)
}

/// The 2D set a file gives the 2D analyses: its pair `--project i,j` (checked against its
/// columns), or the file itself when it has two columns.
pub fn plane(
    path: &str,
    points: &CubePoints,
    project: Option<&str>,
) -> Result<Vec<DVec2>, CliError> {
    match project {
        Some(text) => {
            let (i, j) = super::points::parse_project(text, points.dims())
                .map_err(|e| CliError::Usage(format!("{path}: {e}")))?;
            Ok(points.project(i, j).map_err(|e| CliError::Usage(e.to_string()))?)
        }
        None => points.to_2d().ok_or_else(|| {
            CliError::Usage(format!(
                "{path}: {} columns: several files are averaged as 2D point sets; give one file, or --project i,j",
                points.dims()
            ))
        }),
    }
}

/// The measures of one point set of `dims ≠ 2` columns, printed as text or JSON. The 2D
/// outputs and averaging over files are refused (they need `--project i,j`).
pub fn run(
    args: &super::analyze::AnalyzeArgs,
    path: &str,
    points: &CubePoints,
    session: &Session,
    sink: super::analyze::Sink<'_>,
) -> Result<(), CliError> {
    use super::analyze::Sink;
    let (n, dims) = (points.n(), points.dims());
    let json_out = args.json || matches!(sink, Sink::Keep(_));
    if super::analyze::expand_points(&args.points)?.len() > 1 {
        plane(path, points, None)?;
    }
    for (flag, given) in [
        ("--spectrum", args.spectrum.is_some()),
        ("--spectrum-data", args.spectrum_data.is_some()),
        ("--raps", args.raps.is_some()),
        ("--rdf", args.rdf.is_some()),
    ] {
        if given {
            return Err(CliError::Usage(format!(
                "{flag}: {path} has {dims} columns: the 2D outputs need --project i,j"
            )));
        }
    }
    let measures: Vec<CubeMeasure> = CubeMeasure::ALL
        .into_iter()
        .filter(|m| m.skipped(n, dims).is_none())
        .collect();
    let plan = measures
        .iter()
        .map(|&m| budget::cube_measure(m, n, dims))
        .collect();
    let Some(progress) = session.admit(plan)? else {
        return Ok(());
    };
    let cancel = &session.cancel;
    let mut follow = |r: Report<'_, ()>| progress.follow(r);
    let mut disc = None;
    let mut md = None;
    let mut strata = Vec::new();
    let mut table = None;
    for (stage, &m) in measures.iter().enumerate() {
        progress.stage(stage);
        match m {
            CubeMeasure::Discrepancies => {
                disc = Some(cube::discrepancies(points, cancel, &mut follow).map_err(metrics_err)?)
            }
            CubeMeasure::MinDistance => {
                md = Some(
                    cube::min_distance_cube(points, cancel, &mut follow).map_err(metrics_err)?,
                )
            }
            CubeMeasure::Stratification => {
                strata = cube::stratification(points, cancel).map_err(metrics_err)?
            }
            CubeMeasure::Projections => {
                table =
                    Some(cube::projection_table(points, cancel, &mut follow).map_err(metrics_err)?)
            }
        }
    }
    drop(progress);
    let skipped: Vec<String> = CubeMeasure::ALL
        .into_iter()
        .filter_map(|m| m.skipped(n, dims))
        .collect();
    if json_out {
        let mut o = json!({
            "file": path,
            "n": n,
            "dims": dims,
            "min_distance": md.map(|m| m.min_distance),
            "min_distance_pair": md.map(|m| [m.pair.0, m.pair.1]),
            "stratified": strata.iter().map(|s| s.stratified).collect::<Vec<_>>(),
            "projections": table.as_ref().map(|t| t.iter().map(|r| json!({
                "dims": r.dims,
                "t_value": r.t_value,
                "l2_star_discrepancy": r.l2_star_discrepancy,
                "min_distance": r.min_distance,
            })).collect::<Vec<_>>()),
            "skipped": skipped,
        });
        for which in Discrepancy::ALL {
            o[which.key()] = json!(disc.map(|d| d.get(which)));
        }
        match sink {
            Sink::Keep(kept) => kept.json = o,
            Sink::Print => outln!(
                "{}",
                serde_json::to_string_pretty(&o).map_err(|e| CliError::Usage(e.to_string()))?
            )?,
        }
        return Ok(());
    }
    outln!("points: {path}: N = {n} in {dims} dimensions")?;
    if let Some(d) = disc {
        for which in Discrepancy::ALL {
            outln!("{}: {:.6e}", which.label(), d.get(which))?;
        }
    }
    if let Some(m) = md {
        outln!(
            "min toroidal distance: {:.6e} (points {} and {})",
            m.min_distance,
            m.pair.0,
            m.pair.1
        )?;
    }
    let good: Vec<String> = strata
        .iter()
        .filter(|s| s.stratified)
        .map(|s| s.dim.to_string())
        .collect();
    outln!(
        "1D stratified (every interval [k/N, (k+1)/N) holds one point): {} of {dims} dimensions{}",
        good.len(),
        if good.is_empty() {
            String::new()
        } else {
            format!(" ({})", good.join(", "))
        }
    )?;
    for s in strata.iter().filter(|s| !s.stratified) {
        let why = match (s.empty_interval, s.crowded_interval) {
            (Some(e), Some((c, k))) => format!("interval {e} empty, interval {c} holds {k}"),
            _ => String::new(),
        };
        outln!("  x{} not stratified: {why}", s.dim)?;
    }
    if let Some(t) = table {
        outln!("projections (worst first): dims  t  L2-star  min distance")?;
        for r in &t {
            outln!(
                "  {},{}  {}  {:.6e}  {}",
                r.dims[0],
                r.dims[1],
                r.t_value.map_or("-".to_string(), |t| t.to_string()),
                r.l2_star_discrepancy,
                r.min_distance
                    .map_or("-".to_string(), |m| format!("{m:.6e}"))
            )?;
        }
    }
    for s in skipped {
        outln!("{s}")?;
    }
    Ok(())
}
