//! Speed of the blue-noise patterns (and of Owen-scrambled Sobol'), each against its reference
//! in the same run. Criterion measures the fast paths; a table printed at the end gives medians
//! of wall time measured here with `Instant`, the target and the ratios.
//!
//! ```text
//! cargo bench --bench patterns -- --warm-up-time 1 --measurement-time 3
//! cargo bench --bench patterns -- bridson_4096          # one benchmark (substring filter)
//! cargo bench --bench patterns -- best_candidate_4096
//! cargo bench --bench patterns -- dart_4096
//! cargo bench --bench patterns -- sobol_owen_65536
//! ```
//!
//! | benchmark | fast path | reference | target |
//! |---|---|---|---|
//! | `bridson_4096` | Bridson, N = 4096, default radius | dart throwing (grid) at the same radius | ≤ 1 µs per point |
//! | `best_candidate_4096` | grid + raster best candidate, N = 4096, m = 1 | `best_candidate_naive` (timed once: seconds) and the random stream alone | ≤ 5 ms |
//! | `dart_4096` | grid dart throwing, N = 4096, default radius | `dart_naive` | — (ratio) |
//! | `sobol_owen_65536` | `Pattern::Sobol(owen)`, 65 536 points | 131 072 `next_f64` (white noise of the same size) | ≤ 1.5 ms |

use criterion::Criterion;
use samplescope::core::cancel::Cancel;
use samplescope::core::pattern::best_candidate::{best_candidate, best_candidate_naive};
use samplescope::core::pattern::poisson::{bridson, dart, dart_naive, default_radius};
use samplescope::core::pattern::{
    BestCandidate, Pattern, PoissonBridson, PoissonDart, Scramble, Sobol,
};
use samplescope::core::rng::Rng;
use std::hint::black_box;
use std::sync::Mutex;
use std::time::Instant;

const N: usize = 4096;
const SEED: u64 = 1;

/// One line of the printed table.
struct Row {
    what: String,
    ms: Timing,
    points: usize,
    target: String,
    versus: String,
}

static ROWS: Mutex<Vec<Row>> = Mutex::new(Vec::new());

fn push(row: Row) {
    if let Ok(mut rows) = ROWS.lock() {
        rows.push(row);
    }
}

/// Medians in ms of `reps` runs: wall time and this thread's CPU time.
#[derive(Clone, Copy)]
struct Timing {
    wall: f64,
    cpu: f64,
}

/// CPU time of the calling thread in ms (`clock_gettime(CLOCK_THREAD_CPUTIME_ID)`), NaN where
/// unavailable. On a shared machine it excludes the time the thread waited for a core.
#[cfg(target_os = "linux")]
fn thread_cpu_ms() -> f64 {
    #[repr(C)]
    struct Timespec {
        tv_sec: i64,
        tv_nsec: i64,
    }
    extern "C" {
        fn clock_gettime(clock: i32, tp: *mut Timespec) -> i32;
    }
    const CLOCK_THREAD_CPUTIME_ID: i32 = 3;
    let mut t = Timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: `t` is a valid, writable timespec; the clock id is Linux's thread CPU clock.
    let rc = unsafe { clock_gettime(CLOCK_THREAD_CPUTIME_ID, &mut t) };
    if rc != 0 {
        return f64::NAN;
    }
    t.tv_sec as f64 * 1e3 + t.tv_nsec as f64 * 1e-6
}

#[cfg(not(target_os = "linux"))]
fn thread_cpu_ms() -> f64 {
    f64::NAN
}

/// Wall and CPU time in ms of one run (for references that take seconds).
fn once_ms(f: impl FnOnce()) -> Timing {
    let (c0, start) = (thread_cpu_ms(), Instant::now());
    f();
    Timing {
        wall: start.elapsed().as_secs_f64() * 1e3,
        cpu: thread_cpu_ms() - c0,
    }
}

/// Median wall and CPU times in ms of `reps` runs (after one warm-up run).
fn median_ms(reps: usize, mut f: impl FnMut()) -> Timing {
    f();
    let mut wall = Vec::with_capacity(reps);
    let mut cpu = Vec::with_capacity(reps);
    for _ in 0..reps {
        let (c0, start) = (thread_cpu_ms(), Instant::now());
        f();
        wall.push(start.elapsed().as_secs_f64() * 1e3);
        cpu.push(thread_cpu_ms() - c0);
    }
    wall.sort_by(f64::total_cmp);
    cpu.sort_by(f64::total_cmp);
    Timing {
        wall: wall[reps / 2],
        cpu: cpu[reps / 2],
    }
}

/// The benchmark filter given on the command line (criterion's first positional argument), if any.
fn filter() -> Option<String> {
    const WITH_VALUE: &[&str] = &[
        "--warm-up-time",
        "--measurement-time",
        "--sample-size",
        "--save-baseline",
        "-s",
        "--baseline",
        "-b",
        "--baseline-lenient",
        "--load-baseline",
        "--output-format",
        "--plotting-backend",
        "--color",
        "-c",
        "--significance-level",
        "--confidence-level",
        "--nresamples",
        "--noise-threshold",
        "--profile-time",
        "--format",
    ];
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        if WITH_VALUE.contains(&a.as_str()) {
            args.next();
        } else if !a.starts_with('-') {
            return Some(a);
        }
    }
    None
}

fn selected(id: &str) -> bool {
    filter().is_none_or(|f| id.contains(&f))
}

/// "w ms wall / c ms cpu".
fn both(t: Timing) -> String {
    format!("{:.3} ms wall / {:.3} ms cpu", t.wall, t.cpu)
}

/// Ratio a/b on wall and on CPU time.
fn ratio(a: Timing, b: Timing) -> String {
    format!("{:.2}× wall, {:.2}× cpu", a.wall / b.wall, a.cpu / b.cpu)
}

fn bridson_4096(c: &mut Criterion) {
    if !selected("bridson_4096") {
        return;
    }
    let never = Cancel::never();
    let p = PoissonBridson::default();
    c.bench_function("bridson_4096", |b| {
        b.iter(|| bridson(&p, black_box(N), SEED, &never))
    });
    let fast = median_ms(21, || {
        black_box(bridson(&p, N, SEED, &never).ok());
    });
    let reference = median_ms(21, || {
        black_box(dart(&PoissonDart::default(), N, SEED, &never).ok());
    });
    let target_ms = 1e-3 * N as f64;
    push(Row {
        what: format!("Bridson N = {N}, r = {:.5} (default)", default_radius(N)),
        ms: fast,
        points: N,
        target: format!(
            "≤ 1 µs/pt: {:.2}× (wall), {:.2}× (cpu)",
            fast.wall / target_ms,
            fast.cpu / target_ms
        ),
        versus: format!(
            "dart throwing (grid) at the same r: {}; Bridson/dart {}",
            both(reference),
            ratio(fast, reference)
        ),
    });
}

fn best_candidate_4096(c: &mut Criterion) {
    if !selected("best_candidate_4096") {
        return;
    }
    let never = Cancel::never();
    let p = BestCandidate::default();
    let mut group = c.benchmark_group("best_candidate_4096");
    group.sample_size(10);
    group.bench_function("grid", |b| {
        b.iter(|| best_candidate(&p, black_box(N), SEED, &never))
    });
    group.finish();
    let fast = median_ms(5, || {
        black_box(best_candidate(&p, N, SEED, &never).ok());
    });
    // The naive reference takes seconds: one timed run, checked equal to the fast output.
    let mut naive_points = None;
    let naive = once_ms(|| {
        naive_points = best_candidate_naive(&p, N, SEED, &never).ok();
    });
    let same = naive_points.is_some() && naive_points == best_candidate(&p, N, SEED, &never).ok();
    // Lower bound of any implementation with this random stream: 2 next_f64 per candidate.
    let candidates = (N * (N - 1) / 2) as u64;
    let stream = median_ms(3, || {
        let mut rng = Rng::new(SEED);
        let mut acc = 0.0;
        for _ in 0..candidates {
            acc += rng.next_f64();
            acc += rng.next_f64();
        }
        black_box(acc);
    });
    push(Row {
        what: format!("best candidate N = {N}, m = 1 ({candidates} candidates)"),
        ms: fast,
        points: N,
        target: format!(
            "≤ 5 ms: {:.1}× (wall), {:.1}× (cpu)",
            fast.wall / 5.0,
            fast.cpu / 5.0
        ),
        versus: format!(
            "naive (1 run): {}; naive/grid {}; same points: {same}; \
             random stream alone (2 next_f64 per candidate): {}",
            both(naive),
            ratio(naive, fast),
            both(stream)
        ),
    });
}

fn dart_4096(c: &mut Criterion) {
    if !selected("dart_4096") {
        return;
    }
    let never = Cancel::never();
    let p = PoissonDart::default();
    let mut group = c.benchmark_group("dart_4096");
    group.bench_function("grid", |b| b.iter(|| dart(&p, black_box(N), SEED, &never)));
    group.sample_size(10);
    group.bench_function("naive", |b| {
        b.iter(|| dart_naive(&p, black_box(N), SEED, &never))
    });
    group.finish();
    let fast = median_ms(21, || {
        black_box(dart(&p, N, SEED, &never).ok());
    });
    let naive = median_ms(5, || {
        black_box(dart_naive(&p, N, SEED, &never).ok());
    });
    push(Row {
        what: format!(
            "dart throwing N = {N}, r = {:.5} (default)",
            default_radius(N)
        ),
        ms: fast,
        points: N,
        target: "— (ratio only)".into(),
        versus: format!(
            "dart_naive: {}; naive/grid {}",
            both(naive),
            ratio(naive, fast)
        ),
    });
}

fn sobol_owen_65536(c: &mut Criterion) {
    if !selected("sobol_owen_65536") {
        return;
    }
    const M: usize = 65_536;
    let pattern = Pattern::Sobol(Sobol {
        scramble: Scramble::Owen,
        skip: 0,
    });
    // The Sobol' generator lives in another module; report instead of aborting if it panics.
    if std::panic::catch_unwind(|| pattern.generate(M, 1)).is_err() {
        println!("sobol_owen_65536: not measured, Pattern::Sobol panicked in this build");
        return;
    }
    c.bench_function("sobol_owen_65536", |b| {
        b.iter(|| pattern.generate(black_box(M), 1))
    });
    let fast = median_ms(21, || {
        black_box(pattern.generate(M, 1).ok());
    });
    let white = median_ms(21, || {
        let mut rng = Rng::new(1);
        let v: Vec<(f64, f64)> = (0..M).map(|_| (rng.next_f64(), rng.next_f64())).collect();
        black_box(v);
    });
    push(Row {
        what: format!("Sobol' Owen-scrambled {M} points"),
        ms: fast,
        points: M,
        target: format!(
            "≤ 1.5 ms: {:.2}× (wall), {:.2}× (cpu)",
            fast.wall / 1.5,
            fast.cpu / 1.5
        ),
        versus: format!(
            "white noise (2·{M} next_f64 into a Vec): {}; Sobol/white {}",
            both(white),
            ratio(fast, white)
        ),
    });
}

fn print_table() {
    let Ok(rows) = ROWS.lock() else { return };
    if rows.is_empty() {
        return;
    }
    println!();
    println!("medians of repeated runs in this process: wall time (Instant) and thread CPU time");
    println!(
        "{:<50} {:>10} {:>10} {:>12}  {:<34} reference",
        "benchmark", "wall ms", "cpu ms", "cpu ns/pt", "target (measured/target)"
    );
    for r in rows.iter() {
        println!(
            "{:<50} {:>10.3} {:>10.3} {:>12.0}  {:<34} {}",
            r.what,
            r.ms.wall,
            r.ms.cpu,
            r.ms.cpu * 1e6 / r.points as f64,
            r.target,
            r.versus
        );
    }
}

fn main() {
    let mut c = Criterion::default().configure_from_args();
    bridson_4096(&mut c);
    best_candidate_4096(&mut c);
    dart_4096(&mut c);
    sobol_owen_65536(&mut c);
    c.final_summary();
    print_table();
}
