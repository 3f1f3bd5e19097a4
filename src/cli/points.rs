//! `samplescope points`: generate a pattern and write CSV: `x,y` in 2D (and `x,y,z` on the
//! sphere), `x0,…,x{D−1}` in D dimensions, `x,y` for a projection `--project i,j`.

use super::out;
use super::session::{check_outputs, write_output, Session};
use super::{check_allow_fewer, check_seed, parse_n, pattern_from_args, require_points, CliError};
use samplescope::core::budget;
use samplescope::core::family::Family;
use samplescope::core::pattern::{sphere, Pattern};
use std::io::Write;
use std::path::Path;

/// Arguments of `samplescope points`.
#[derive(clap::Args, Debug)]
pub struct PointsArgs {
    /// Pattern name (see --list).
    #[arg(required_unless_present = "list")]
    pub pattern: Option<String>,
    /// Number of points.
    #[arg(short = 'n', value_parser = parse_n, required_unless_present = "list")]
    pub n: Option<usize>,
    /// Seed of the random stream [default: 0] (refused with a deterministic pattern, which has
    /// none).
    #[arg(long)]
    pub seed: Option<u64>,
    /// Pattern parameter, `key=value`; repeatable.
    #[arg(long = "set", value_name = "KEY=VALUE")]
    pub set: Vec<String>,
    /// Output file (default: standard output).
    #[arg(long)]
    pub out: Option<String>,
    /// Map the points onto the unit sphere (cylinder wrap + radial projection) and write `x,y,z`.
    #[arg(long)]
    pub sphere: bool,
    /// Keep the points placed when a pattern stops short of N (dart throwing's `max_misses`,
    /// Bridson's `radius`) instead of failing; a note on standard error says how many.
    #[arg(long)]
    pub allow_fewer: bool,
    /// Dimensions of each point [default: 2]: 2 writes `x,y` as always; any other D writes
    /// `x0,…,x{D−1}` (each pattern's limit is in --list; 2D-only patterns take 2).
    #[arg(long, value_name = "D")]
    pub dims: Option<usize>,
    /// Write the 2D projection onto dimensions i and j (0-based, `x,y`), e.g. `--project 3,7`.
    #[arg(long, value_name = "I,J")]
    pub project: Option<String>,
    /// List every pattern with its parameters, defaults and allowed ranges.
    #[arg(
        long,
        conflicts_with_all = ["pattern", "n", "seed", "set", "out", "sphere", "allow_fewer", "dims", "project"]
    )]
    pub list: bool,
}

/// Runs `samplescope points`.
pub fn run(args: &PointsArgs, session: &Session) -> Result<(), CliError> {
    if args.list {
        session.refuse_budget_flags("--list")?;
        out!("{}{}", Pattern::list_text(), dims_text())?;
        return Ok(());
    }
    let (Some(name), Some(n)) = (&args.pattern, args.n) else {
        return Err(CliError::Usage(
            "points: a pattern and -n are required".into(),
        ));
    };
    let pattern = pattern_from_args(name, &args.set)?;
    check_seed(&pattern, args.seed, "--seed")?;
    check_allow_fewer(&pattern, args.allow_fewer)?;
    let dims = args.dims.unwrap_or(2);
    let project = args
        .project
        .as_deref()
        .map(|p| parse_project(p, dims))
        .transpose()?;
    if dims != 2 || project.is_some() {
        return run_cube(args, &pattern, n, dims, project, session);
    }
    pattern.validate(n)?;
    check_outputs(&[("--out", args.out.as_deref())])?;
    let plan = vec![budget::pattern(&pattern, n), budget::csv(n, args.sphere)];
    let Some(progress) = session.admit(plan)? else {
        return Ok(());
    };
    let cancel = &session.cancel;
    progress.stage(0);
    let generated = pattern.generate_observed(n, args.seed.unwrap_or(0), cancel, &mut |p| {
        progress.follow(p)
    })?;
    let points = require_points(generated, &pattern, args.allow_fewer)?;
    progress.stage(1);
    let text = points_text(&points, args.sphere, cancel)?;
    drop(progress);
    write_text(args, &text, cancel)
}

/// The `--list` section on dimensions: each pattern's `--dims` range.
pub fn dims_text() -> String {
    let mut s = String::from(
        "dimensions (--dims D, default 2; D = 2 is always the 2D pattern; n·D ≤ 2^25)\n",
    );
    for p in Pattern::all() {
        let range = match p.max_dims() {
            2 => "2 only".to_string(),
            max => format!("1..={max}"),
        };
        s.push_str(&format!("    {:<20} {range}\n", p.name()));
    }
    s
}

/// `x,y` lines of 2D points (`x,y,z` on the sphere), checking `cancel` every 4096 points.
fn points_text(
    points: &[glam::DVec2],
    sphere: bool,
    cancel: &samplescope::core::cancel::Cancel,
) -> Result<String, CliError> {
    let mut text = String::with_capacity(points.len() * 44);
    if sphere {
        text.push_str("x,y,z\n");
        for (i, p) in points.iter().enumerate() {
            if i % 4096 == 0 {
                cancel.check().map_err(|_| CliError::Cancelled)?;
            }
            let v = sphere::square_to_sphere(*p);
            text.push_str(&format!("{:?},{:?},{:?}\n", v.x, v.y, v.z));
        }
    } else {
        text.push_str("x,y\n");
        for (i, p) in points.iter().enumerate() {
            if i % 4096 == 0 {
                cancel.check().map_err(|_| CliError::Cancelled)?;
            }
            // `{:?}` prints the shortest string that parses back to the same f64.
            text.push_str(&format!("{:?},{:?}\n", p.x, p.y));
        }
    }
    Ok(text)
}

/// `--project i,j`: two different dimensions below `dims`, else one line naming the range.
pub(super) fn parse_project(text: &str, dims: usize) -> Result<(usize, usize), CliError> {
    let bad = || {
        CliError::Usage(format!(
            "--project {}: must be two different dimensions i,j in 0..={} (dims = {dims})",
            samplescope::core::params::fmt_text(text),
            dims.saturating_sub(1)
        ))
    };
    let (i, j) = text.split_once(',').ok_or_else(bad)?;
    let (i, j) = (
        i.trim().parse::<usize>().map_err(|_| bad())?,
        j.trim().parse::<usize>().map_err(|_| bad())?,
    );
    if i == j || i >= dims || j >= dims {
        return Err(bad());
    }
    Ok((i, j))
}

/// `points --dims D` (D ≠ 2) or `--project i,j`: the pattern's d-dimensional points, written
/// as `x0,…,x{D−1}` or as the 2D projection `x,y`.
fn run_cube(
    args: &PointsArgs,
    pattern: &Pattern,
    n: usize,
    dims: usize,
    project: Option<(usize, usize)>,
    session: &Session,
) -> Result<(), CliError> {
    pattern.validate_cube(n, dims)?;
    if args.allow_fewer {
        return Err(CliError::Usage(
            "--allow-fewer: applies to 2D patterns only (dims = 2, no --project)".into(),
        ));
    }
    if args.sphere && project.is_none() {
        return Err(CliError::Usage(format!(
            "--sphere: maps 2D points; with --dims {dims} add --project i,j"
        )));
    }
    check_outputs(&[("--out", args.out.as_deref())])?;
    let out = if project.is_some() {
        budget::csv(n, args.sphere)
    } else {
        budget::csv_dims(n, dims)
    };
    let plan = vec![budget::pattern_cube(pattern, n, dims), out];
    let Some(progress) = session.admit(plan)? else {
        return Ok(());
    };
    let cancel = &session.cancel;
    progress.stage(0);
    let points = pattern.generate_cube(n, dims, args.seed.unwrap_or(0), cancel)?;
    progress.stage(1);
    let text = match project {
        Some((i, j)) => {
            let pts = points
                .project(i, j)
                .map_err(|e| CliError::Usage(format!("--project {e}")))?;
            points_text(&pts, args.sphere, cancel)?
        }
        None => {
            let mut text = String::with_capacity(n * dims * 22);
            let header: Vec<String> = (0..dims).map(|d| format!("x{d}")).collect();
            text.push_str(&header.join(","));
            text.push('\n');
            for (i, row) in points.rows().enumerate() {
                if i % 4096 == 0 {
                    cancel.check().map_err(|_| CliError::Cancelled)?;
                }
                for (d, v) in row.iter().enumerate() {
                    if d > 0 {
                        text.push(',');
                    }
                    text.push_str(&format!("{v:?}"));
                }
                text.push('\n');
            }
            text
        }
    };
    drop(progress);
    write_text(args, &text, cancel)
}

/// Writes the CSV text to `--out` or standard output.
fn write_text(
    args: &PointsArgs,
    text: &str,
    cancel: &samplescope::core::cancel::Cancel,
) -> Result<(), CliError> {
    match &args.out {
        Some(path) => write_output(Path::new(path), text.as_bytes(), cancel),
        None => {
            let stdout = std::io::stdout();
            let mut lock = stdout.lock();
            lock.write_all(text.as_bytes())
                .map_err(|source| CliError::Io {
                    path: "<stdout>".into(),
                    source,
                })
        }
    }
}
