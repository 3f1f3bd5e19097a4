//! `samplescope recon`: sample a test signal with a pattern, reconstruct it, and report the
//! error against the signal's reference image.

use super::outln;
use super::session::{check_outputs, write_output, Session};
use super::{from_args, parse_n, CliError};
use samplescope::core::budget;
use samplescope::core::filter::{Filter, Filter2D, Mode2D};
use samplescope::core::pattern::Pattern;
use samplescope::core::recon::{
    error_report, reconstruct_scattered, reference_image_with, sample_signal, supersample,
    PatternProvider, ReconError, ReferenceOptions, MAX_SPP, MAX_W,
};
use samplescope::core::signal::Signal;
use samplescope::export::{flip_rows, png_bytes};
use samplescope::model::Colormap;
use std::path::Path;
use std::time::Instant;

/// The reconstruction's estimator, as the JSON output names it (`core::recon` module docs).
const RULE: &str =
    "Σw·f/Σw where Σw ≥ c·Σ|w|, else (Σw·f + (c·Σ|w| − Σw)·P)/(c·Σ|w|) with P = Σ|w|·f/Σ|w|";

/// Arguments of `samplescope recon`.
#[derive(clap::Args, Debug)]
pub struct ReconArgs {
    /// Test signal: zone-plate (alias zoneplate), checkerboard, grating, step-edge, polygon.
    #[arg(long, default_value = "zone-plate")]
    pub signal: String,
    /// Signal parameter `key=value`; repeatable. Numbers as typed (`k=512`), enum values
    /// unquoted (`--signal polygon --signal-set shape=square`), booleans `true`/`false`, lists
    /// in brackets (`--signal sum-of-sines --signal-set amps=[0.5,0.25]`; missing entries are
    /// 0). Parameters: zone-plate k, cx, cy; checkerboard checks, height, horizon, tilt;
    /// grating frequency, angle, phase; step-edge angle, offset; polygon shape, angle, size;
    /// sum-of-sines freqs, amps; chirp f0, f1; square frequency; constant value.
    #[arg(long = "signal-set", value_name = "KEY=VALUE")]
    pub signal_set: Vec<String>,
    /// Sample pattern (see `points --list`).
    #[arg(long, default_value = "jitter")]
    pub pattern: String,
    /// Pattern parameter `key=value`; repeatable.
    #[arg(long = "set", value_name = "KEY=VALUE")]
    pub set: Vec<String>,
    /// Number of scattered samples over the whole image (without --spp).
    #[arg(short = 'n', value_parser = parse_n, conflicts_with = "spp")]
    pub n: Option<usize>,
    /// Samples per pixel: supersample with the pattern in every pixel instead.
    #[arg(long)]
    pub spp: Option<usize>,
    /// Seed [default: 0] (refused with a deterministic pattern, which has none).
    #[arg(long)]
    pub seed: Option<u64>,
    /// With -n: keep the samples placed when the pattern stops short of N (poisson-dart,
    /// poisson-bridson) instead of failing. Not with --spp: every pixel needs all its samples.
    #[arg(long, conflicts_with = "spp")]
    pub allow_fewer: bool,
    /// Reconstruction filter (see `filter --list`).
    #[arg(long, default_value = "gaussian")]
    pub filter: String,
    /// Filter parameter `key=value`; repeatable.
    #[arg(long = "filter-set", value_name = "KEY=VALUE")]
    pub filter_set: Vec<String>,
    /// 2D extension of the filter: separable or radial.
    #[arg(long, default_value = "separable")]
    pub mode: String,
    /// Output size W (W×W pixels).
    #[arg(long, default_value_t = 512)]
    pub size: usize,
    /// Output PNG of the reconstruction.
    #[arg(long, value_name = "IMG.png")]
    pub out: Option<String>,
    /// Print one JSON object.
    #[arg(long)]
    pub json: bool,
}

/// The 2D filter from its name, settings and mode.
pub fn filter_from_args(name: &str, settings: &[String], mode: &str) -> Result<Filter2D, CliError> {
    let f: Filter = from_args(
        "",
        name,
        "--filter-set",
        settings,
        "samplescope filter --list",
    )?;
    let mode = Mode2D::from_name(mode).map_err(|e| CliError::Usage(e.to_string()))?;
    Filter2D::new(f, mode).map_err(|e| CliError::Usage(e.to_string()))
}

/// Runs `samplescope recon`.
pub fn run(args: &ReconArgs, session: &Session) -> Result<(), CliError> {
    let cancel = &session.cancel;
    let signal: Signal = from_args(
        "--signal",
        &args.signal,
        "--signal-set",
        &args.signal_set,
        "samplescope recon --help",
    )?;
    let pattern: Pattern = from_args(
        "",
        &args.pattern,
        "--set",
        &args.set,
        "samplescope points --list",
    )?;
    let filter = filter_from_args(&args.filter, &args.filter_set, &args.mode)?;
    if let Some(why) = filter.reconstruction_refusal() {
        return Err(CliError::Usage(format!("--filter: {why}")));
    }
    super::check_seed(&pattern, args.seed, "--seed")?;
    super::check_allow_fewer(&pattern, args.allow_fewer)?;
    let seed = args.seed.unwrap_or(0);
    let usage = |e: &dyn std::fmt::Display| CliError::Usage(e.to_string());
    // The sizes the estimates take are checked first (the same errors the core gives).
    let range = |field: &'static str, value: usize, max: usize| {
        if (1..=max).contains(&value) {
            Ok(())
        } else {
            Err(usage(&ReconError::OutOfRange {
                field,
                value,
                min: 1,
                max,
            }))
        }
    };
    range("--size", args.size, MAX_W)?;
    let w = args.size;
    // Ok(spp): supersampling; Err(n): n scattered samples.
    let sampling = match (args.spp, args.n) {
        (Some(spp), _) => Ok(spp),
        (None, Some(n)) => Err(n),
        (None, None) => {
            return Err(CliError::Usage(
                "recon: give -n N (scattered samples) or --spp S (samples per pixel)".into(),
            ))
        }
    };
    let mut plan = match sampling {
        Ok(spp) => {
            range("--spp", spp, MAX_SPP)?;
            pattern.validate(spp)?;
            vec![budget::supersampling(&signal, w, spp, &pattern, &filter)]
        }
        Err(n) => {
            pattern.validate(n)?;
            vec![
                budget::pattern(&pattern, n),
                budget::sampling(&signal, n),
                budget::scattered(n, w, &filter),
            ]
        }
    };
    let after = plan.len();
    plan.push(budget::reference(&signal, w));
    plan.push(budget::error_image(w));
    if args.out.is_some() {
        plan.push(budget::png(w, w));
    }
    check_outputs(&[("--out", args.out.as_deref())])?;
    let Some(progress) = session.admit(plan)? else {
        return Ok(());
    };
    progress.stage(0);
    let t0 = Instant::now();
    let recon = match sampling {
        Ok(spp) => {
            let provider = PatternProvider { pattern, seed };
            supersample(&signal, w, spp, &provider, &filter, cancel).map_err(|e| usage(&e))?
        }
        Err(n) => {
            let g = pattern.generate_with(n, seed, cancel)?;
            let points = super::require_points(g, &pattern, args.allow_fewer)?;
            progress.stage(1);
            let values = sample_signal(&signal, &points, cancel).map_err(|e| usage(&e))?;
            progress.stage(2);
            reconstruct_scattered(&points, &values, w, &filter, cancel).map_err(|e| usage(&e))?
        }
    };
    let recon_ms = t0.elapsed().as_secs_f64() * 1e3;
    let t1 = Instant::now();
    progress.stage(after);
    let reference = reference_image_with(&signal, args.size, &ReferenceOptions::default(), cancel)
        .map_err(|e| usage(&e))?;
    let reference_ms = t1.elapsed().as_secs_f64() * 1e3;
    progress.stage(after + 1);
    let report = error_report(&recon, &reference.pixels).map_err(|e| usage(&e))?;
    if let Some(path) = &args.out {
        progress.stage(after + 2);
        let w = args.size;
        let values = flip_rows(&recon.pixels, w);
        let text = [
            ("Software", "samplescope".to_string()),
            (
                "Parameters",
                format!(
                    "signal={signal:?} pattern={pattern:?} n={:?} spp={:?} seed={} filter={filter:?} size={w}",
                    args.n, args.spp, seed
                ),
            ),
        ];
        let bytes =
            png_bytes(&values, w, w, 0.0, 1.0, Colormap::Greys, &text).map_err(|e| usage(&e))?;
        write_output(Path::new(path), &bytes, cancel)?;
    }
    drop(progress);
    if args.json {
        outln!(
            "{}",
            serde_json::json!({
                "rmse": report.rmse,
                "psnr": report.psnr,
                "max_abs_error": report.max_abs,
                "zero_weight_pixels": recon.zero_weight,
                "normaliser": {
                    "rule": RULE,
                    "c": recon.floor,
                    "floored_pixels": recon.floored,
                },
                "reference_error_estimate": reference.error_estimate,
                "reference_method": reference.method.label(),
                "timings_ms": { "reconstruction": recon_ms, "reference": reference_ms },
            })
        )?;
    } else {
        outln!("RMSE   {:.6}", report.rmse)?;
        outln!("PSNR   {:.3} dB", report.psnr)?;
        outln!("time   {recon_ms:.2} ms (reconstruction, sampling included); reference {reference_ms:.2} ms")?;
        outln!(
            "norm   Σw·f/Σw, floored where Σw < c·Σ|w| (c = {:.3}): {} pixels floored",
            recon.floor,
            recon.floored
        )?;
        if recon.zero_weight > 0 {
            outln!(
                "note   {} pixels had zero total filter weight",
                recon.zero_weight
            )?;
        }
        if let Some(e) = reference.error_estimate {
            if reference.method.estimate_is_bound() {
                outln!("reference's own error ≤ {e:.2e} (any pixel)")?;
            } else {
                outln!("reference's own RMS error ≈ {e:.2e}")?;
            }
        }
    }
    Ok(())
}
