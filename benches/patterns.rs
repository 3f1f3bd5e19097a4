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

mod common;
use common::{both, median_ms, once_ms, selected, Timing};
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
