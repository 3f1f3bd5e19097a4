//! `samplescope points`: generate a pattern and write CSV.

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
    /// List every pattern with its parameters, defaults and allowed ranges.
    #[arg(
        long,
        conflicts_with_all = ["pattern", "n", "seed", "set", "out", "sphere", "allow_fewer"]
    )]
    pub list: bool,
}

/// Runs `samplescope points`.
pub fn run(args: &PointsArgs, session: &Session) -> Result<(), CliError> {
    if args.list {
        session.refuse_budget_flags("--list")?;
        out!("{}", Pattern::list_text())?;
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
    let mut text = String::with_capacity(points.len() * 44);
    if args.sphere {
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
    drop(progress);
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
