//! `samplescope converge`: the integration error of a pattern on an integrand with a known
//! integral over [0,1]^D (`--dims`, 2 by default), as N grows: MSE, its standard error,
//! variance and squared bias per N, and the log–log slope of the MSE.

use super::session::{check_outputs, write_output, Session};
use super::{from_args, outln, CliError};
use samplescope::core::budget;
use samplescope::core::integration::{
    check_request, estimate, run_study, Integrand, Study, StudyError, StudyRequest, MAX_STUDY_N,
};
use samplescope::core::params::params_json;
use std::path::Path;

/// Arguments of `samplescope converge`.
#[derive(clap::Args, Debug)]
pub struct ConvergeArgs {
    /// Sample pattern (see `points --list`).
    #[arg(long)]
    pub pattern: String,
    /// Pattern parameter `key=value`; repeatable.
    #[arg(long = "set", value_name = "KEY=VALUE")]
    pub set: Vec<String>,
    /// Integrand with an exact integral. On [0,1]²: disk (cx, cy, r), gaussian (cx, cy,
    /// sigma), heaviside (px, py, theta in degrees), bilinear (x·y), cosines (a, b). On
    /// [0,1]^D, Genz's families (a, u: one number for every dimension or a list of D):
    /// genz-oscillatory, genz-product-peak, genz-corner-peak, genz-gaussian, genz-continuous,
    /// genz-discontinuous.
    #[arg(long)]
    pub integrand: String,
    /// Integrand parameter `key=value`; repeatable (e.g. `--integrand-set r=0.2`).
    #[arg(long = "integrand-set", value_name = "KEY=VALUE")]
    pub integrand_set: Vec<String>,
    /// A new random instance of the integrand's family per realization (disk centre in
    /// [0.2,0.8]², r in [0.1,0.4]; gaussian centre in [0,1]², σ in [0.05,0.3]; heaviside p in
    /// [0,1]², θ in [0°,360°); cosines a, b in [0.5,8]; Genz's families as Genz's test
    /// package draws them: u uniform, a uniform normalised to Σa = h/D^e). Not with
    /// --integrand-set (the drawn instances replace the integrand's parameters) nor with
    /// bilinear (it has no family).
    #[arg(long, conflicts_with = "integrand_set")]
    pub randomize: bool,
    /// Sample counts, comma-separated (e.g. 16,64,256,1024), each in 1..=1048576, at most 64.
    #[arg(long = "n", value_name = "N,N,…")]
    pub n: String,
    /// Realizations per N, in 1..=4096.
    #[arg(long, value_name = "R")]
    pub realizations: String,
    /// Dimension D of the cube integrated over, in 1..=1024 [default: 2]. D ≠ 2 needs a Genz
    /// integrand and a pattern with a d-dimensional form (`points --list`), and N·D ≤ 2^25.
    #[arg(long, value_name = "D")]
    pub dims: Option<String>,
    /// Seed of the realizations' streams [default: 0].
    #[arg(long)]
    pub seed: Option<u64>,
    /// No Cranley–Patterson rotation of deterministic patterns (every realization the same);
    /// refused with a random pattern, which is never shifted.
    #[arg(long = "no-shift")]
    pub no_shift: bool,
    /// Print one JSON object.
    #[arg(long)]
    pub json: bool,
    /// Also write the rows as CSV (`n,mse,mse_stderr,variance,bias2`).
    #[arg(long, value_name = "OUT.csv")]
    pub csv: Option<String>,
}

/// Parses the comma-separated `--n` list (the range is checked with the request).
fn parse_ns(text: &str) -> Result<Vec<usize>, CliError> {
    text.split(',')
        .map(|t| {
            t.trim().parse::<usize>().map_err(|_| {
                CliError::Usage(format!(
                    "--n {}: must be a comma-separated list of integers, each in 1..={MAX_STUDY_N}",
                    samplescope::core::params::fmt_text(t)
                ))
            })
        })
        .collect()
}

fn study_error(e: StudyError) -> CliError {
    match e {
        StudyError::Cancelled => CliError::Cancelled,
        other => CliError::Usage(other.to_string()),
    }
}

/// A number for JSON: `null` when absent or not finite.
fn num(v: Option<f64>) -> serde_json::Value {
    v.filter(|x| x.is_finite())
        .map_or(serde_json::Value::Null, serde_json::Value::from)
}

fn ms(d: std::time::Duration) -> f64 {
    d.as_secs_f64() * 1e3
}

/// The rows as CSV, numbers in shortest round-trip form, an absent standard error empty.
pub fn csv_text(study: &Study) -> String {
    let mut s = String::from("n,mse,mse_stderr,variance,bias2\n");
    for r in &study.rows {
        let se = r.mse_stderr.map(|v| format!("{v:?}")).unwrap_or_default();
        s.push_str(&format!(
            "{},{:?},{se},{:?},{:?}\n",
            r.n, r.mse, r.variance, r.bias2
        ));
    }
    s
}

/// Runs `samplescope converge`.
pub fn run(args: &ConvergeArgs, session: &Session) -> Result<(), CliError> {
    let Some((req, study)) = study(args, session)? else {
        return Ok(());
    };
    let t = &study.timings;
    if args.json {
        outln!("{}", study_json(&req, &study))?;
        return Ok(());
    }
    print_text(&req, &study, t)
}

/// The object `converge --json` prints.
pub fn study_json(req: &StudyRequest, study: &Study) -> serde_json::Value {
    let t = &study.timings;
    let rows: Vec<serde_json::Value> = study
        .rows
        .iter()
        .map(|r| {
            serde_json::json!({
                "n": r.n,
                "mse": num(Some(r.mse)),
                "mse_stderr": num(r.mse_stderr),
                "variance": num(Some(r.variance)),
                "bias2": num(Some(r.bias2)),
            })
        })
        .collect();
    serde_json::json!({
        "pattern": req.pattern.name(),
        "pattern_params": params_json(&req.pattern),
        "integrand": req.integrand.name(),
        "integrand_params": params_json(&req.integrand),
        "randomize": req.randomize,
        "dims": req.dims,
        "shift": req.applies_shift(),
        "seed": req.seed,
        "realizations": req.realizations,
        "reference": study.reference,
        "rows": rows,
        "slope": num(study.slope),
        "slope_stderr": num(study.slope_stderr),
        "timings_ms": {
            "points": ms(t.points),
            "evaluation": ms(t.evaluation),
            "statistics": ms(t.statistics),
            "total": ms(t.total),
        },
    })
}

/// The study `converge` runs (`None` after `--estimate`), its CSV written with `--csv`.
pub fn study(
    args: &ConvergeArgs,
    session: &Session,
) -> Result<Option<(StudyRequest, Study)>, CliError> {
    let pattern = super::pattern_from_args(&args.pattern, &args.set)?;
    let integrand: Integrand = from_args(
        "--integrand",
        &args.integrand,
        "--integrand-set",
        &args.integrand_set,
        "samplescope converge --help",
    )?;
    let ns = parse_ns(&args.n)?;
    let realizations = args.realizations.trim().parse::<usize>().map_err(|_| {
        CliError::Usage(format!(
            "--realizations {}: must be an integer in 1..={}",
            samplescope::core::params::fmt_text(&args.realizations),
            samplescope::core::integration::MAX_REALIZATIONS
        ))
    })?;
    if args.randomize && matches!(integrand, Integrand::Bilinear(_)) {
        return Err(CliError::Usage(
            "--randomize: bilinear has no parameters, so there is no family to draw instances \
             from and --randomize would have no effect; leave it out"
                .into(),
        ));
    }
    if args.no_shift && pattern.is_random() {
        return Err(CliError::Usage(format!(
            "--no-shift: {} (with these parameters) is a random pattern, and random patterns are \
             never shifted (each realization draws new points), so --no-shift would have no \
             effect; leave it out",
            pattern.name()
        )));
    }
    if let (Some(seed), false, true, false) = (
        args.seed,
        pattern.is_random(),
        args.no_shift,
        args.randomize,
    ) {
        return Err(CliError::Usage(format!(
            "--seed {seed}: {} is deterministic and with --no-shift and without --randomize \
             nothing is drawn at random, so --seed would have no effect; leave it out",
            pattern.name()
        )));
    }
    let dims = match &args.dims {
        None => 2,
        Some(text) => text.trim().parse::<usize>().map_err(|_| {
            CliError::Usage(format!(
                "--dims {}: must be an integer in 1..={}",
                samplescope::core::params::fmt_text(text),
                samplescope::core::cube::MAX_DIMS
            ))
        })?,
    };
    let req = StudyRequest {
        pattern,
        integrand,
        ns,
        realizations,
        seed: args.seed.unwrap_or(0),
        shift: !args.no_shift,
        randomize: args.randomize,
        dims,
    };
    check_request(&req).map_err(study_error)?;
    let mut plan = estimate(&req);
    let stages = plan.len();
    // The share of the work before the evaluation stage, to move the bar between stages.
    let first = plan[0].seconds / budget::total_seconds(&plan).max(f64::MIN_POSITIVE);
    if args.csv.is_some() {
        plan.push(budget::text_rows("CSV", req.ns.len()));
    }
    check_outputs(&[("--csv", args.csv.as_deref())])?;
    let Some(progress) = session.admit(plan)? else {
        return Ok(None);
    };
    progress.stage(0);
    let mut stage = 0;
    let study = run_study(&req, &session.cancel, &mut |p| {
        if stage == 0 && p.done as f64 >= first * p.total as f64 && stages > 1 {
            stage = 1;
            progress.stage(1);
        }
    })
    .map_err(study_error)?;
    if let Some(path) = &args.csv {
        progress.stage(stages);
        write_output(
            Path::new(path),
            csv_text(&study).as_bytes(),
            &session.cancel,
        )?;
    }
    drop(progress);
    Ok(Some((req, study)))
}

/// The text `converge` prints without `--json`.
fn print_text(
    req: &StudyRequest,
    study: &Study,
    t: &samplescope::core::integration::StudyTimings,
) -> Result<(), CliError> {
    let shift = if req.pattern.is_random() {
        "none (random pattern)"
    } else if req.shift {
        "Cranley–Patterson rotation per realization"
    } else {
        "none (every realization the same)"
    };
    outln!(
        "{} on {}{}{}: reference {}, {} realizations, seed {}, shift: {shift}",
        req.pattern.name(),
        req.integrand.name(),
        if req.dims == 2 {
            String::new()
        } else {
            format!(" in {} dimensions", req.dims)
        },
        if req.randomize { " (randomized)" } else { "" },
        // Genz's integrals span many decades (Π aᵢ² in 32 dimensions): in scientific form.
        if req.integrand.is_planar() {
            format!("{:.12}", study.reference)
        } else {
            format!("{:.12e}", study.reference)
        },
        req.realizations,
        req.seed
    )?;
    outln!(
        "{:>8}  {:>12}  {:>12}  {:>12}  {:>12}",
        "N",
        "MSE",
        "± stderr",
        "variance",
        "bias²"
    )?;
    for r in &study.rows {
        let se = r
            .mse_stderr
            .map_or_else(|| "—".to_string(), |v| format!("{v:.5e}"));
        outln!(
            "{:>8}  {:>12.5e}  {:>12}  {:>12.5e}  {:>12.5e}",
            r.n,
            r.mse,
            se,
            r.variance,
            r.bias2
        )?;
    }
    match (study.slope, study.slope_stderr) {
        (Some(b), Some(se)) => outln!("slope  {b:.4} ± {se:.4} (least squares of ln MSE on ln N)")?,
        (Some(b), None) => outln!("slope  {b:.4} (two values of N: no standard error)")?,
        _ => outln!("slope  — (fewer than two values of N with MSE > 0)")?,
    }
    outln!(
        "time   {:.2} ms (points {:.2} ms, evaluation {:.2} ms, summed over threads)",
        ms(t.total),
        ms(t.points),
        ms(t.evaluation)
    )?;
    Ok(())
}
