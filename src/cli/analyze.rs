//! `samplescope analyze`: statistics, discrepancies, t-value, PSA's statistics (effective
//! Nyquist frequency, oscillations, bond-orientational order; `--rdf` its radial distribution
//! function) and spectrum of a point set, with the time and accuracy of every stage.

use super::outln;
use super::session::{check_outputs, write_output, Session};
use super::{parse_n, CliError};
use glam::DVec2;
use samplescope::core::budget;
use samplescope::core::metrics::{self, psa, MetricsError};
use samplescope::core::pattern::MAX_N;
use samplescope::core::pointset::{read_points_named, OutOfRange, PointsFileError};
use samplescope::core::rng::derive_seed;
use samplescope::core::spectrum::{
    average_periodogram, radial_average, SpectrumRequest, DEFAULT_ERROR_CHECK_BUDGET,
};
use samplescope::export::{flip_rows, png_bytes};
use samplescope::model::Colormap;
use samplescope::scene::SpectrumSettings;
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

fn io_err(path: &str) -> impl FnOnce(std::io::Error) -> CliError + '_ {
    move |source| CliError::Io {
        path: path.to_string(),
        source,
    }
}

/// A metric's error as a usage error (bad input), cancellation as cancellation.
fn metrics_err(e: MetricsError) -> CliError {
    match e {
        MetricsError::Cancelled => CliError::Cancelled,
        e => CliError::Usage(e.to_string()),
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
fn read_point_files(files: &[String], normalize: bool) -> Result<Vec<Vec<DVec2>>, CliError> {
    let mode = if normalize {
        OutOfRange::NormalizeToBoundingBox
    } else {
        OutOfRange::Reject
    };
    let mut sets: Vec<Vec<DVec2>> = Vec::with_capacity(files.len().min(1024));
    let mut total = 0usize;
    for path in files {
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

/// Runs `samplescope analyze`.
pub fn run(args: &AnalyzeArgs, session: &Session) -> Result<(), CliError> {
    let cancel = &session.cancel;
    let seed_arg = args.seed.unwrap_or(0);
    let mut timings: Vec<(String, f64)> = Vec::new();
    // Every output is checked before any work (and before a point file is read).
    check_outputs(&[
        ("--spectrum", args.spectrum.as_deref()),
        ("--spectrum-data", args.spectrum_data.as_deref()),
        ("--raps", args.raps.as_deref()),
        ("--rdf", args.rdf.as_deref()),
    ])?;
    let t0 = Instant::now();
    // Point files are read first (bounded and streamed): their size sets the estimates.
    let files = expand_points(&args.points)?;
    let (file_sets, generator) = if !files.is_empty() {
        if args.realizations != 1 {
            return Err(CliError::Usage(format!(
                "--realizations = {}: must be 1 with --points (each file is one realization)",
                args.realizations
            )));
        }
        (Some(read_point_files(&files, args.normalize)?), None)
    } else {
        let name = args.pattern.as_deref().unwrap_or_default();
        let n = args.n.unwrap_or(0);
        let pattern = super::pattern_from_args(name, &args.set)?;
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
    // Files averaged (K ≥ 2) or one set.
    let sets_k = file_sets.as_ref().map_or(1, |s| s.len());
    let averaged = sets_k > 1;
    // The scene's settings make the request; analyze shows DC and checks the error at the
    // core's default budget (its measured error is reported as before).
    let settings = SpectrumSettings {
        size: args.size,
        tolerance: args.tolerance.unwrap_or(DEFAULT_TOLERANCE),
        exact: args.exact,
        realizations: if file_sets.is_some() {
            sets_k
        } else {
            args.realizations
        },
        mask_dc: false,
    };
    let req = SpectrumRequest {
        error_check_budget: DEFAULT_ERROR_CHECK_BUDGET,
        ..settings.request(0, false)
    };
    req.validate().map_err(|e| CliError::Usage(e.to_string()))?;
    let n = match (&file_sets, &generator) {
        (Some(sets), _) => sets[0].len(),
        (None, Some((_, n))) => *n,
        (None, None) => 0,
    };
    let m = args.size;
    let mut plan = Vec::new();
    if let Some((pattern, n)) = &generator {
        plan.push(budget::pattern(pattern, *n));
    }
    // Per-set work runs once per file.
    let times = |mut e: budget::Estimate| {
        if sets_k > 1 {
            e.operation = format!("{} × {sets_k} files", e.operation);
            e.amount *= sets_k as f64;
            e.seconds *= sets_k as f64;
        }
        e
    };
    let first = plan.len();
    plan.push(times(budget::statistics(n)));
    plan.push(times(budget::psa_statistics(n)));
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
        plan.push(times(budget::rdf(n, rdf_bins)));
        plan.push(budget::text_rows("RDF CSV", rdf_bins));
    }
    if file_sets.is_some() {
        plan.push(times(budget::net_prefixes(n)));
    }
    let Some(progress) = session.admit(plan)? else {
        return Ok(());
    };
    progress.stage(0);
    let sets: Vec<Vec<DVec2>> = match (file_sets, &generator) {
        (Some(sets), _) => sets,
        (None, Some((pattern, n))) => {
            let g = pattern.generate_with(*n, seed_arg, cancel)?;
            vec![super::require_points(g, pattern, args.allow_fewer)?]
        }
        (None, None) => Vec::new(),
    };
    // A sampler may stop short of the n asked for (it says so in its note).
    let Some(n) = sets.first().map(|s| s.len()) else {
        return Err(CliError::Usage("no points to analyse".into()));
    };
    timings.push(("points".into(), t0.elapsed().as_secs_f64() * 1e3));

    progress.stage(first);
    let mut all_stats = Vec::with_capacity(sets.len());
    let mut stat_ms = Vec::new();
    for points in &sets {
        let stats =
            metrics::statistics(points, cancel).map_err(|e| CliError::Usage(e.to_string()))?;
        for (i, (name, d)) in stats.timings.iter().enumerate() {
            if stat_ms.len() <= i {
                stat_ms.push((name.to_string(), 0.0));
            }
            stat_ms[i].1 += d.as_secs_f64() * 1e3;
        }
        all_stats.push(stats);
    }
    timings.extend(stat_ms);

    progress.stage(first + 1);
    let (all_psa, psa_skipped) = if (psa::PSA_MIN_N..=psa::PSA_MAX_N).contains(&n) {
        let t0 = Instant::now();
        let mut v = Vec::with_capacity(sets.len());
        for points in &sets {
            v.push(metrics::psa_statistics(points, cancel).map_err(metrics_err)?);
        }
        timings.push(("PSA statistics".into(), t0.elapsed().as_secs_f64() * 1e3));
        (Some(v), None)
    } else {
        (
            None,
            Some(format!(
                "PSA statistics need {} ≤ n ≤ {} points (the RDF costs O(N²)), got n = {n}",
                psa::PSA_MIN_N,
                psa::PSA_MAX_N,
            )),
        )
    };

    progress.stage(first + 2);
    let first_seed = derive_seed(seed_arg, 0);
    let seed = seed_arg;
    // Realization r of the spectrum is file r (its seed is derive_seed(seed, r)); with a
    // pattern, realization 0 is the analysed point set and the others are fresh seeds.
    let file_seeds: Vec<u64> = (0..sets.len() as u64)
        .map(|r| derive_seed(seed, r))
        .collect();
    let sets_ref = &sets;
    let (spec, report) = average_periodogram(
        &req,
        seed,
        move |sd| match &generator {
            Some((pattern, n)) if sd != first_seed => pattern.generate(*n, sd),
            _ => {
                let r = file_seeds.iter().position(|&s| s == sd).unwrap_or(0);
                Ok(sets_ref[r].clone())
            }
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
    let mut outputs: Vec<(&String, Vec<u8>)> = Vec::new();
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
                    n, m, req.realizations, req.method, seed_arg
                ),
            ),
        ];
        let bytes = png_bytes(&values, m, m, lo, hi, Colormap::Viridis, &text)
            .map_err(|e| CliError::Usage(e.to_string()))?;
        outputs.push((path, bytes));
    }
    if let Some(path) = &args.spectrum_data {
        let mut s = String::from("kx,ky,power\n");
        for (kx, ky, p) in spec.to_csv_rows() {
            let _ = writeln!(s, "{kx},{ky},{p:?}");
        }
        outputs.push((path, s.into_bytes()));
    }
    if let Some(path) = &args.raps {
        let mut s = String::from("radius,power\n");
        for b in &bins {
            let _ = writeln!(s, "{:?},{:?}", b.radius, b.mean_power);
        }
        outputs.push((path, s.into_bytes()));
    }
    if let Some(path) = &args.rdf {
        let t0 = Instant::now();
        // The mean of the sets' g over the same bins (all sets hold N points).
        let mut mean: Vec<f64> = vec![0.0; rdf_bins];
        let mut dr = 0.0;
        for points in &sets {
            let g = metrics::rdf(points, rdf_bins, rdf_r_max, cancel).map_err(metrics_err)?;
            dr = g.bin_width();
            for (acc, v) in mean.iter_mut().zip(g.values()) {
                *acc += v;
            }
        }
        for v in &mut mean {
            *v /= sets.len() as f64;
        }
        timings.push(("RDF".into(), t0.elapsed().as_secs_f64() * 1e3));
        let d_hex = metrics::hex_distance(n);
        let mut s = String::from("r_min,r_max,r_mid_normalized,g\n");
        for (i, v) in mean.iter().enumerate() {
            let (lo, hi) = (i as f64 * dr, (i + 1) as f64 * dr);
            let _ = writeln!(s, "{lo:?},{hi:?},{:?},{v:?}", 0.5 * (lo + hi) / d_hex);
        }
        outputs.push((path, s.into_bytes()));
    }
    // For point files: the (0,k,2)-net check of every power-of-two prefix.
    let nets = if files.is_empty() {
        Vec::new()
    } else {
        let t0 = Instant::now();
        let mut v = Vec::with_capacity(sets.len());
        for points in &sets {
            v.push(metrics::net_prefixes(points, cancel).map_err(metrics_err)?);
        }
        timings.push(("net prefixes".into(), t0.elapsed().as_secs_f64() * 1e3));
        v
    };
    for (path, bytes) in outputs {
        write_output(Path::new(path), &bytes, cancel)?;
    }
    drop(progress);

    let error = report.error.map(|e| e.relative_l2);
    let spectrum_json = json!({
        "size": spec.m,
        "realizations": spec.realizations,
        "method": if args.exact { "exact" } else { "nufft" },
        "tolerance": report.tolerance,
        "measured_relative_l2_error": error,
    });
    let spectrum_line = format!(
        "spectrum               {}² · K = {} · {}",
        spec.m,
        spec.realizations,
        match (report.tolerance, error) {
            (Some(t), Some(e)) => format!("NUFFT, asked {t:.0e}, measured rel. ℓ2 error {e:.2e}"),
            (Some(t), None) => format!("NUFFT, asked {t:.0e} (exact check too expensive)"),
            (None, _) => "exact DFT".to_string(),
        }
    );
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
        );
    }
    let stats = &all_stats[0];
    let psa_stats = all_psa.as_ref().map(|v| v[0]);
    let md = stats.min_distance.as_ref();
    if args.json {
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
        outln!("{out}")?;
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
    all_stats: &[metrics::Statistics],
    all_psa: Option<&[metrics::PsaStatistics]>,
    psa_skipped: Option<String>,
    nets: &[metrics::NetPrefixes],
    spectrum_json: serde_json::Value,
    spectrum_line: &str,
    timings: &[(String, f64)],
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
    if args.json {
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
        outln!("{out}")?;
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
