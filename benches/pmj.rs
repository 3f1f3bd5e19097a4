//! Speed of the progressive multi-jittered (0,2) sequences against their naive references and
//! white noise, in the same run. Criterion measures the fast paths; a table printed at the end
//! gives medians of wall time (`Instant`) and thread CPU time, the target and the ratios.
//!
//! ```text
//! cargo bench --bench pmj -- --warm-up-time 1 --measurement-time 3
//! cargo bench --bench pmj -- pmj02_4096          # one benchmark (substring filter)
//! cargo bench --bench pmj -- pmj02bn_4096
//! ```
//!
//! | benchmark | fast path | references | target |
//! |---|---|---|---|
//! | `pmj02_4096` | `pmj02`, N = 4096 | `pmj02_naive` (N = 4096, timed once: it takes a second or more), white noise (2N `next_f64`) | ≤ 1 ms, one core |
//! | `pmj02bn_4096` | `pmj02bn`, N = 4096, 16 candidates | `pmj02bn_naive` (N = 4096, timed once), `pmj02` | ≤ 10 ms, one core |
//! | `pmj02_65536` | `pmj02`, N = 65 536 | white noise of the same size | — (scaling) |

mod common;
use common::{both, median_ms, once_ms, selected, Timing};
use criterion::Criterion;
use glam::DVec2;
use samplescope::core::cancel::Cancel;
use samplescope::core::pattern::pmj::{pmj02, pmj02_naive, pmj02bn, pmj02bn_naive};
use samplescope::core::rng::Rng;
use std::hint::black_box;
use std::sync::Mutex;

const N: usize = 4096;
const SEED: u64 = 1;
/// Candidates per point for pmj02bn in these benchmarks.
const CANDIDATES: u32 = 16;

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
    format!("{:.1}× wall, {:.1}× cpu", a.wall / b.wall, a.cpu / b.cpu)
}

/// 2m uniform `next_f64` into a Vec of m points.
fn white(m: usize) -> Vec<DVec2> {
    let mut rng = Rng::new(SEED);
    (0..m)
        .map(|_| DVec2::new(rng.next_f64(), rng.next_f64()))
        .collect()
}

fn target(t: Timing, ms: f64) -> String {
    format!(
        "≤ {ms} ms: {:.2}× (wall), {:.2}× (cpu)",
        t.wall / ms,
        t.cpu / ms
    )
}

fn pmj02_4096(c: &mut Criterion) {
    if !selected("pmj02_4096") {
        return;
    }
    let never = Cancel::never();
    c.bench_function("pmj02_4096", |b| {
        b.iter(|| pmj02(black_box(N), SEED, &never))
    });
    let fast = median_ms(101, || {
        black_box(pmj02(N, SEED, &never).ok());
    });
    let noise = median_ms(101, || {
        black_box(white(N));
    });
    let mut naive_points = None;
    let naive = once_ms(|| naive_points = pmj02_naive(N, SEED, &never).ok());
    let same = naive_points.is_some() && naive_points == pmj02(N, SEED, &never).ok();
    push(Row {
        what: format!("pmj02 N = {N}"),
        ms: fast,
        points: N,
        target: target(fast, 1.0),
        versus: format!(
            "naive (1 run, N = {N}): {}; naive/fast {}; same points: {same}; \
             white noise (2N next_f64): {}; pmj02/white {}",
            both(naive),
            ratio(naive, fast),
            both(noise),
            ratio(fast, noise)
        ),
    });
}

fn pmj02bn_4096(c: &mut Criterion) {
    if !selected("pmj02bn_4096") {
        return;
    }
    let never = Cancel::never();
    let mut group = c.benchmark_group("pmj02bn_4096");
    group.sample_size(20);
    group.bench_function("grid", |b| {
        b.iter(|| pmj02bn(black_box(N), SEED, CANDIDATES, &never))
    });
    group.finish();
    let fast = median_ms(21, || {
        black_box(pmj02bn(N, SEED, CANDIDATES, &never).ok());
    });
    let plain = median_ms(101, || {
        black_box(pmj02(N, SEED, &never).ok());
    });
    let mut naive_points = None;
    let naive = once_ms(|| naive_points = pmj02bn_naive(N, SEED, CANDIDATES, &never).ok());
    let same = naive_points.is_some() && naive_points == pmj02bn(N, SEED, CANDIDATES, &never).ok();
    push(Row {
        what: format!("pmj02bn N = {N}, {CANDIDATES} candidates"),
        ms: fast,
        points: N,
        target: target(fast, 10.0),
        versus: format!(
            "naive (1 run, N = {N}): {}; naive/fast {}; same points: {same}; pmj02: {}; \
             bn/pmj02 {}",
            both(naive),
            ratio(naive, fast),
            both(plain),
            ratio(fast, plain)
        ),
    });
}

fn pmj02_65536(c: &mut Criterion) {
    if !selected("pmj02_65536") {
        return;
    }
    const M: usize = 65_536;
    let never = Cancel::never();
    c.bench_function("pmj02_65536", |b| {
        b.iter(|| pmj02(black_box(M), SEED, &never))
    });
    let fast = median_ms(21, || {
        black_box(pmj02(M, SEED, &never).ok());
    });
    let noise = median_ms(21, || {
        black_box(white(M));
    });
    push(Row {
        what: format!("pmj02 N = {M}"),
        ms: fast,
        points: M,
        target: "— (scaling)".into(),
        versus: format!(
            "white noise (2N next_f64): {}; pmj02/white {}",
            both(noise),
            ratio(fast, noise)
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
        "{:<34} {:>10} {:>10} {:>10}  {:<34} reference",
        "benchmark", "wall ms", "cpu ms", "cpu ns/pt", "target (measured/target)"
    );
    for r in rows.iter() {
        println!(
            "{:<34} {:>10.3} {:>10.3} {:>10.0}  {:<34} {}",
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
    pmj02_4096(&mut c);
    pmj02bn_4096(&mut c);
    pmj02_65536(&mut c);
    c.final_summary();
    print_table();
}
