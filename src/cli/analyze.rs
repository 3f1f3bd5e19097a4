//! `samplescope analyze`: statistics, discrepancies, t-value, PSA's statistics (effective
//! Nyquist frequency, oscillations, bond-orientational order; `--rdf` its radial distribution
//! function) and spectrum of a point set, with the time and accuracy of every stage.

use super::outln;
use super::session::{check_outputs, write_output, Session};
use super::{parse_n, pattern_from_args, CliError};
use samplescope::core::budget;
use samplescope::core::metrics::{self, psa, MetricsError};
use samplescope::core::pointset::{read_points, OutOfRange, PointsFileError};
use samplescope::core::rng::derive_seed;
use samplescope::core::spectrum::{
    average_periodogram, radial_average, DcMode, Method, SpectrumRequest,
};
use samplescope::export::{flip_rows, png_bytes};
use samplescope::model::Colormap;
use serde_json::json;
use std::fmt::Write as _;
use std::path::Path;
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
    /// Read the points from a file (CSV `x,y` as written by `points`, or PSA-style text).
    #[arg(long)]
    pub points: Option<String>,
    /// Map the points' bounding box onto [0,1)² instead of rejecting points outside (with --points).
    #[arg(long, conflicts_with = "pattern")]
    pub normalize: bool,
    /// Spectrum size M (M×M integer frequencies).
    #[arg(long, default_value_t = 256)]
    pub size: usize,
    /// Realizations K averaged (with a pattern; seeds derived from --seed).
    #[arg(long, default_value_t = 1)]
    pub realizations: usize,
    /// NUFFT tolerance (relative ℓ2 error of P), 1e-12..=1e-2 [default: 1e-6]; not with --exact.
    #[arg(long, value_parser = parse_tolerance, conflicts_with = "exact")]
    pub tolerance: Option<f64>,
    /// Use the exact DFT instead of the NUFFT.
    #[arg(long)]
    pub exact: bool,
    /// Write the centred periodogram (log10 scale, viridis) as PNG.
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

/// A metric's error as a usage error (bad input), cancellation as cancellation.
fn metrics_err(e: MetricsError) -> CliError {
    match e {
        MetricsError::Cancelled => CliError::Cancelled,
        e => CliError::Usage(e.to_string()),
    }
}

/// Runs `samplescope analyze`.
pub fn run(args: &AnalyzeArgs, session: &Session) -> Result<(), CliError> {
    let cancel = &session.cancel;
    let seed_arg = args.seed.unwrap_or(0);
    let mut timings: Vec<(String, f64)> = Vec::new();
    let req = SpectrumRequest {
        size: args.size,
        method: if args.exact {
            Method::Exact
        } else {
            Method::Nufft {
                tolerance: args.tolerance.unwrap_or(DEFAULT_TOLERANCE),
            }
        },
        realizations: args.realizations,
        dc: DcMode::Show,
        ..SpectrumRequest::default()
    };
    // Every output is checked before any work (and before a point file is read).
    check_outputs(&[
        ("--spectrum", args.spectrum.as_deref()),
        ("--spectrum-data", args.spectrum_data.as_deref()),
        ("--raps", args.raps.as_deref()),
        ("--rdf", args.rdf.as_deref()),
    ])?;
    let t0 = Instant::now();
    // A point file is read first (bounded and streamed): its size sets the estimates.
    let (file_points, generator) = if let Some(path) = &args.points {
        if args.realizations != 1 {
            return Err(CliError::Usage(format!(
                "--realizations = {}: must be 1 with --points (a file is one realization)",
                args.realizations
            )));
        }
        let file = super::open_input(Path::new(path))?;
        let mode = if args.normalize {
            OutOfRange::NormalizeToBoundingBox
        } else {
            OutOfRange::Reject
        };
        // Streamed with a size and line-length limit: a binary or endless file is refused
        // after at most one line.
        let pts = read_points(file, mode).map_err(|e| match e {
            PointsFileError::Io { message, .. } => CliError::Io {
                path: path.clone(),
                source: std::io::Error::other(message),
            },
            e => CliError::Usage(format!("{path}: {e}")),
        })?;
        (Some(pts), None)
    } else {
        let name = args.pattern.as_deref().unwrap_or_default();
        let n = args.n.unwrap_or(0);
        let pattern = pattern_from_args(name, &args.set)?;
        super::check_seed(&pattern, args.seed, "--seed")?;
        super::check_allow_fewer(&pattern, args.allow_fewer)?;
        if args.realizations > 1 && !pattern.is_random() {
            return Err(CliError::Usage(format!(
                "--realizations {}: {} with these parameters is deterministic, so every \
                 realization is the same point set and averaging them has no effect; leave it out",
                args.realizations,
                pattern.name()
            )));
        }
        // Everything the generator would refuse is refused before the estimate and the budget.
        pattern.validate(n)?;
        (None, Some((pattern, n)))
    };
    req.validate().map_err(|e| CliError::Usage(e.to_string()))?;
    let n = match (&file_points, &generator) {
        (Some(pts), _) => pts.len(),
        (None, Some((_, n))) => *n,
        (None, None) => 0,
    };
    let m = args.size;
    let mut plan = Vec::new();
    if let Some((pattern, n)) = &generator {
        plan.push(budget::pattern(pattern, *n));
    }
    let first = plan.len();
    plan.push(budget::statistics(n));
    plan.push(budget::psa_statistics(n));
    plan.push(budget::spectrum(
        &req,
        n,
        generator.as_ref().map(|(p, _)| p),
    ));
    if args.spectrum.is_some() {
        plan.push(budget::spectrum_image(m));
    }
    if args.spectrum_data.is_some() {
        plan.push(budget::text_rows("spectrum CSV", m * m));
    }
    let (rdf_bins, rdf_r_max) = psa::psa_rdf_range(n);
    if args.rdf.is_some() {
        plan.push(budget::rdf(n, rdf_bins));
        plan.push(budget::text_rows("RDF CSV", rdf_bins));
    }
    let Some(progress) = session.admit(plan)? else {
        return Ok(());
    };
    progress.stage(0);
    let points = match (file_points, &generator) {
        (Some(pts), _) => pts,
        (None, Some((pattern, n))) => {
            let g = pattern.generate_with(*n, seed_arg, cancel)?;
            super::require_points(g, pattern, args.allow_fewer)?
        }
        (None, None) => Vec::new(),
    };
    timings.push(("points".into(), t0.elapsed().as_secs_f64() * 1e3));

    progress.stage(first);
    let stats = metrics::statistics(&points, cancel).map_err(|e| CliError::Usage(e.to_string()))?;
    for (name, d) in &stats.timings {
        timings.push((name.to_string(), d.as_secs_f64() * 1e3));
    }

    progress.stage(first + 1);
    let (psa_stats, psa_skipped) = if (psa::PSA_MIN_N..=psa::PSA_MAX_N).contains(&points.len()) {
        let t0 = Instant::now();
        let s = metrics::psa_statistics(&points, cancel).map_err(metrics_err)?;
        timings.push(("PSA statistics".into(), t0.elapsed().as_secs_f64() * 1e3));
        (Some(s), None)
    } else {
        (
            None,
            Some(format!(
                "PSA statistics need {} ≤ n ≤ {} points (the RDF costs O(N²)), got n = {}",
                psa::PSA_MIN_N,
                psa::PSA_MAX_N,
                points.len()
            )),
        )
    };

    progress.stage(first + 2);
    let first_seed = derive_seed(seed_arg, 0);
    let seed = seed_arg;
    let pts = points.clone();
    let (spec, report) = average_periodogram(
        &req,
        seed,
        move |sd| match &generator {
            // Realization 0 is the analysed point set; others are fresh seeds.
            Some((pattern, n)) if sd != first_seed => pattern.generate(*n, sd),
            _ => Ok(pts.clone()),
        },
        cancel,
    )
    .map_err(|e| CliError::Usage(e.to_string()))?;
    for (name, d) in &report.stages {
        timings.push((format!("spectrum {name}"), d.as_secs_f64() * 1e3));
    }
    progress.stage(first + 3);
    let bins = radial_average(&spec).map_err(|e| CliError::Usage(e.to_string()))?;

    // Every output is made before any is written: a failure leaves none of them.
    let mut files: Vec<(&String, Vec<u8>)> = Vec::new();
    if let Some(path) = &args.spectrum {
        let m = spec.m;
        let log = spec.to_log_image(true);
        // Row 0 of the PNG is the highest ky.
        let values: Vec<f64> = flip_rows(&log, m).into_iter().map(f64::from).collect();
        let mut sorted: Vec<f64> = values.clone();
        sorted.sort_by(|a, b| a.total_cmp(b));
        let lo = sorted[(sorted.len() - 1) * 2 / 100];
        let hi = sorted[(sorted.len() - 1) * 998 / 1000].max(lo + 1e-3);
        let text = [
            ("Software", "samplescope".to_string()),
            (
                "Description",
                format!("centred periodogram, log10 P in [{lo:.3}, {hi:.3}], DC masked"),
            ),
            (
                "Parameters",
                format!(
                    "n={} size={} realizations={} method={:?} seed={}",
                    points.len(),
                    m,
                    args.realizations,
                    req.method,
                    seed_arg
                ),
            ),
        ];
        let bytes = png_bytes(&values, m, m, lo, hi, Colormap::Viridis, &text)
            .map_err(|e| CliError::Usage(e.to_string()))?;
        files.push((path, bytes));
    }
    if let Some(path) = &args.spectrum_data {
        let mut s = String::from("kx,ky,power\n");
        for (kx, ky, p) in spec.to_csv_rows() {
            let _ = writeln!(s, "{kx},{ky},{p:?}");
        }
        files.push((path, s.into_bytes()));
    }
    if let Some(path) = &args.raps {
        let mut s = String::from("radius,power\n");
        for b in &bins {
            let _ = writeln!(s, "{:?},{:?}", b.radius, b.mean_power);
        }
        files.push((path, s.into_bytes()));
    }
    if let Some(path) = &args.rdf {
        let t0 = Instant::now();
        let g = metrics::rdf(&points, rdf_bins, rdf_r_max, cancel).map_err(metrics_err)?;
        timings.push(("RDF".into(), t0.elapsed().as_secs_f64() * 1e3));
        let dr = g.bin_width();
        let d_hex = metrics::hex_distance(points.len());
        let mut s = String::from("r_min,r_max,r_mid_normalized,g\n");
        for (i, v) in g.values().iter().enumerate() {
            let (lo, hi) = (i as f64 * dr, (i + 1) as f64 * dr);
            let _ = writeln!(s, "{lo:?},{hi:?},{:?},{v:?}", 0.5 * (lo + hi) / d_hex);
        }
        files.push((path, s.into_bytes()));
    }
    for (path, bytes) in files {
        write_output(Path::new(path), &bytes, cancel)?;
    }
    drop(progress);

    let md = stats.min_distance.as_ref();
    let error = report.error.map(|e| e.relative_l2);
    if args.json {
        let timings_obj: serde_json::Map<String, serde_json::Value> =
            timings.iter().map(|(k, v)| (k.clone(), json!(v))).collect();
        let out = json!({
            "n": points.len(),
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
            "spectrum": {
                "size": spec.m,
                "realizations": spec.realizations,
                "method": if args.exact { "exact" } else { "nufft" },
                "tolerance": report.tolerance,
                "measured_relative_l2_error": error,
            },
            "timings_ms": timings_obj,
        });
        outln!("{out}")?;
    } else {
        outln!("n                      {}", points.len())?;
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
        outln!(
            "spectrum               {}² · K = {} · {}",
            spec.m,
            spec.realizations,
            match (report.tolerance, error) {
                (Some(t), Some(e)) =>
                    format!("NUFFT, asked {t:.0e}, measured rel. ℓ2 error {e:.2e}"),
                (Some(t), None) => format!("NUFFT, asked {t:.0e} (exact check too expensive)"),
                (None, _) => "exact DFT".to_string(),
            }
        )?;
        outln!("timings (ms)")?;
        for (k, v) in &timings {
            outln!("  {k:<22} {v:.3}")?;
        }
    }
    Ok(())
}
