//! Speed of the integration-error study ([`run_study`]) against its naive serial loop
//! ([`run_study_naive`]) in the same run. Criterion measures the fast path; a table printed at
//! the end gives medians of wall time (`Instant`) and process CPU time (all threads), the
//! budget's estimate, the target and the ratios.
//!
//! ```text
//! cargo bench --bench converge -- --warm-up-time 1 --measurement-time 3
//! cargo bench --bench converge -- study_jitter     # one sampler (substring filter)
//! cargo bench --bench converge -- eval_            # the per-evaluation rates only
//! ```
//!
//! | benchmark | fast path | reference | target |
//! |---|---|---|---|
//! | `study_<sampler>` | `run_study`: disk, N = 16, 32, …, 4096 (9 values), 256 realizations, seed 1; samplers random, jitter, sobol (Owen), halton, pmj02, best-candidate, kronecker, rank1 | `run_study_naive`, the same study (same bits checked) | all eight studies ≤ 2 s in all (wall, 2 cores) |
//! | `d32_<sampler>` | `run_study` in 32 dimensions (`--dims 32`): Genz's Gaussian, a random instance per realization (Genz's normalisation), N = 16, 32, …, 4096 (9 values), 64 realizations; samplers random, lhs, sobol (Owen), halton (Owen), sobol (unscrambled, Cranley–Patterson rotated) | `run_study_naive`, the same study, single-threaded (same bits checked) | the ratio naive/fast |
//! | `eval_<integrand>` | `run_study` on 4096 Cranley–Patterson rotations of one Kronecker set of 2^14 points (in cache): integrand evaluations only | — | the per-evaluation CPU ns behind `integration::study`'s cost estimate |
//!
//! Hammersley is not progressive and is left out, as in the lecture's convergence plots.

mod common;
use common::{median_ms_with, process_cpu_ms, selected, Timing};
use criterion::Criterion;
use samplescope::core::budget;
use samplescope::core::cancel::Cancel;
use samplescope::core::integration::{
    estimate, run_study, run_study_naive, Integrand, Study, StudyRequest,
};
use samplescope::core::params::Params;
use samplescope::core::pattern::Pattern;
use samplescope::core::progress::no_progress;
use std::hint::black_box;
use std::sync::Mutex;
use std::time::Instant;

const REALIZATIONS: usize = 256;
const SEED: u64 = 1;
/// Target for the eight studies together, in ms of wall time.
const TARGET_MS: f64 = 2000.0;

/// One line of the printed table.
struct Row {
    what: String,
    ms: Timing,
    estimate_s: f64,
    versus: String,
}

static ROWS: Mutex<Vec<Row>> = Mutex::new(Vec::new());

fn push(row: Row) {
    if let Ok(mut rows) = ROWS.lock() {
        rows.push(row);
    }
}

/// "w ms wall / c ms cpu".
fn both(t: Timing) -> String {
    format!("{:.1} ms wall / {:.1} ms cpu", t.wall, t.cpu)
}

/// The eight samplers: (benchmark id, pattern).
fn samplers() -> Vec<(&'static str, Pattern)> {
    let named = |name: &str, settings: &[(&str, &str)]| {
        let mut p = Pattern::from_name(name).expect("a known pattern");
        for (k, v) in settings {
            p.set(k, v).expect("a valid setting");
        }
        p
    };
    vec![
        ("random", named("random", &[])),
        ("jitter", named("jitter", &[])),
        ("sobol_owen", named("sobol", &[("scramble", "owen")])),
        ("halton", named("halton", &[])),
        ("pmj02", named("pmj02", &[])),
        ("best_candidate", named("best-candidate", &[])),
        ("kronecker", named("kronecker", &[])),
        ("rank1", named("rank1", &[])),
    ]
}

fn request(pattern: Pattern) -> StudyRequest {
    StudyRequest {
        pattern,
        integrand: Integrand::from_name("disk").expect("disk"),
        ns: (4..=12).map(|m| 1usize << m).collect(),
        realizations: REALIZATIONS,
        seed: SEED,
        shift: true,
        randomize: false,
        dims: 2,
    }
}

fn same_bits(a: &Study, b: &Study) -> bool {
    a.rows.len() == b.rows.len()
        && a.rows.iter().zip(&b.rows).all(|(x, y)| {
            x.mse.to_bits() == y.mse.to_bits()
                && x.variance.to_bits() == y.variance.to_bits()
                && x.bias2.to_bits() == y.bias2.to_bits()
                && x.mse_stderr.map(f64::to_bits) == y.mse_stderr.map(f64::to_bits)
        })
        && a.slope.map(f64::to_bits) == b.slope.map(f64::to_bits)
}

const ZERO: Timing = Timing {
    wall: 0.0,
    cpu: 0.0,
};

/// Sums in ms for the total rows: (fast medians, naive times) of every study, and of every
/// study but best candidate's (whose sampler alone is beyond the target).
static TOTALS: Mutex<[(Timing, Timing); 2]> = Mutex::new([(ZERO, ZERO); 2]);

fn studies(c: &mut Criterion) {
    let never = Cancel::never();
    for (id, pattern) in samplers() {
        let bench_id = format!("study_{id}");
        if !selected(&bench_id) {
            continue;
        }
        let req = request(pattern);
        let run = || run_study(&req, &never, &mut no_progress).expect("study");
        let mut group = c.benchmark_group(&bench_id);
        group.sample_size(10);
        group.bench_function("fast", |b| b.iter(|| black_box(run())));
        group.finish();
        let fast = median_ms_with(process_cpu_ms, 5, || {
            black_box(run());
        });
        // The naive loop: one timed run (seconds for best candidate), checked equal.
        let (c0, t0) = (process_cpu_ms(), Instant::now());
        let naive_study = run_study_naive(&req, &never, &mut no_progress).expect("naive");
        let naive = Timing {
            wall: t0.elapsed().as_secs_f64() * 1e3,
            cpu: process_cpu_ms() - c0,
        };
        let fast_study = run();
        let same = same_bits(&fast_study, &naive_study);
        if let Ok(mut totals) = TOTALS.lock() {
            let n = if id == "best_candidate" { 1 } else { 2 };
            for t in totals.iter_mut().take(n) {
                t.0.wall += fast.wall;
                t.0.cpu += fast.cpu;
                t.1.wall += naive.wall;
                t.1.cpu += naive.cpu;
            }
        }
        push(Row {
            what: format!(
                "{} (slope {:.2})",
                pattern.name(),
                fast_study.slope.unwrap_or(f64::NAN)
            ),
            ms: fast,
            estimate_s: budget::total_seconds(&estimate(&req)),
            versus: format!(
                "naive serial (1 run): {}; naive/fast {:.1}× wall; same bits: {same}",
                both(naive),
                naive.wall / fast.wall
            ),
        });
    }
}

/// The five d-dimensional samplers of the 32-dimensional study: (benchmark id, pattern).
fn cube_samplers() -> Vec<(&'static str, Pattern)> {
    let named = |name: &str, settings: &[(&str, &str)]| {
        let mut p = Pattern::from_name(name).expect("a known pattern");
        for (k, v) in settings {
            p.set(k, v).expect("a valid setting");
        }
        p
    };
    vec![
        ("random", named("random", &[])),
        ("lhs", named("lhs", &[])),
        ("sobol_owen", named("sobol", &[("scramble", "owen")])),
        ("halton_owen", named("halton", &[("scramble", "owen")])),
        ("sobol_shifted", named("sobol", &[])),
    ]
}

/// The study in 32 dimensions, fast against the naive single-threaded loop in the same run.
fn studies_d32(c: &mut Criterion) {
    let never = Cancel::never();
    for (id, pattern) in cube_samplers() {
        let bench_id = format!("d32_{id}");
        if !selected(&bench_id) {
            continue;
        }
        let req = StudyRequest {
            pattern,
            integrand: Integrand::from_name("genz-gaussian").expect("genz-gaussian"),
            ns: (4..=12).map(|m| 1usize << m).collect(),
            realizations: 64,
            seed: SEED,
            shift: true,
            randomize: true,
            dims: 32,
        };
        let run = || run_study(&req, &never, &mut no_progress).expect("study");
        let mut group = c.benchmark_group(&bench_id);
        group.sample_size(10);
        group.bench_function("fast", |b| b.iter(|| black_box(run())));
        group.finish();
        let fast = median_ms_with(process_cpu_ms, 5, || {
            black_box(run());
        });
        let (c0, t0) = (process_cpu_ms(), Instant::now());
        let naive_study = run_study_naive(&req, &never, &mut no_progress).expect("naive");
        let naive = Timing {
            wall: t0.elapsed().as_secs_f64() * 1e3,
            cpu: process_cpu_ms() - c0,
        };
        let fast_study = run();
        push(Row {
            what: format!(
                "D = 32 {} (slope {:.2})",
                id,
                fast_study.slope.unwrap_or(f64::NAN)
            ),
            ms: fast,
            estimate_s: budget::total_seconds(&estimate(&req)),
            versus: format!(
                "naive single-threaded (1 run): {}; naive/fast {:.1}× wall; same bits: {}",
                both(naive),
                naive.wall / fast.wall,
                same_bits(&fast_study, &naive_study)
            ),
        });
    }
}

fn evaluations(c: &mut Criterion) {
    let never = Cancel::never();
    // 2^14 points (256 KiB) stay in cache: the rate of the loop itself, not of memory.
    const POINTS: usize = 1 << 14;
    const ROTATIONS: usize = 4096;
    for integrand in Integrand::all() {
        let bench_id = format!("eval_{}", integrand.name());
        if !selected(&bench_id) {
            continue;
        }
        // A deterministic progressive set is generated once and shared: the rest is the
        // evaluation loop (rotation, f, the sum).
        let req = StudyRequest {
            pattern: Pattern::from_name("kronecker").expect("kronecker"),
            integrand,
            ns: vec![POINTS],
            realizations: ROTATIONS,
            seed: SEED,
            shift: true,
            randomize: false,
            dims: 2,
        };
        let run = || run_study(&req, &never, &mut no_progress).expect("study");
        let mut group = c.benchmark_group(&bench_id);
        group.sample_size(10);
        group.bench_function("fast", |b| b.iter(|| black_box(run())));
        group.finish();
        let mut eval_cpu = Vec::new();
        let t = median_ms_with(process_cpu_ms, 5, || {
            eval_cpu.push(run().timings.evaluation.as_secs_f64() * 1e3);
        });
        eval_cpu.sort_by(f64::total_cmp);
        let per = eval_cpu[eval_cpu.len() / 2] * 1e6 / (POINTS * ROTATIONS) as f64;
        push(Row {
            what: format!("{} evaluations ({ROTATIONS} × 2^14)", integrand.name()),
            ms: t,
            estimate_s: budget::total_seconds(&estimate(&req)),
            versus: format!("{per:.2} ns per evaluation (summed over threads)"),
        });
    }
}

fn print_table() {
    let Ok(rows) = ROWS.lock() else { return };
    if rows.is_empty() {
        return;
    }
    println!();
    println!(
        "medians of repeated runs in this process: wall time (Instant) and process CPU time \
         (all threads); {} threads",
        rayon::current_num_threads()
    );
    println!(
        "{:<44} {:>10} {:>10} {:>11}  reference",
        "benchmark", "wall ms", "cpu ms", "estimate s"
    );
    for r in rows.iter() {
        println!(
            "{:<44} {:>10.1} {:>10.1} {:>11.3}  {}",
            r.what, r.ms.wall, r.ms.cpu, r.estimate_s, r.versus
        );
    }
    if let Ok(totals) = TOTALS.lock() {
        for (what, t) in ["all studies", "all studies but best-candidate"]
            .iter()
            .zip(totals.iter())
        {
            if t.0.wall > 0.0 {
                println!(
                    "{:<44} {:>10.1} {:>10.1} {:>11}  target ≤ {TARGET_MS} ms wall: {:.2}× the \
                     target; naive serial in all {}; naive/fast {:.1}× wall",
                    what,
                    t.0.wall,
                    t.0.cpu,
                    "",
                    t.0.wall / TARGET_MS,
                    both(t.1),
                    t.1.wall / t.0.wall
                );
            }
        }
    }
}

fn main() {
    let mut c = Criterion::default().configure_from_args();
    studies(&mut c);
    studies_d32(&mut c);
    evaluations(&mut c);
    c.final_summary();
    print_table();
}
