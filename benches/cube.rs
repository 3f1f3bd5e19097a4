//! d-dimensional generators against their naive references (same run, ratio printed):
//! - Sobol' 2²⁰ points × 32 dimensions: Gray-code stepping (one XOR per coordinate, parallel
//!   chunks) vs every point from its index through the 32 columns of the generator matrices;
//! - Halton 2¹⁶ points × 32 dimensions: the incremental exact radical inverses (parallel
//!   chunks) vs one `radical_inverse` per coordinate (digit extraction by division);
//! - the projection table of 4096 points × 32 dimensions (496 pairs: t-value, L2-star,
//!   minimum distance each): `projection_table` (pairs in parallel, the fast 2D statistics) vs
//!   `projection_table_naive` (pairs in turn, the O(N²) 2D references), the rows checked equal;
//! - the rates of `metrics::cube::cost`: each d-dimensional measure timed on one thread at
//!   N = 4096 and D = 4 and 32, the rates solved from the two; the pair table's parts (the
//!   projection, minimum distance, L2-star and t-value of its 496 rows) per their units; each
//!   measure's estimate beside the measured time.
//!
//! The fast paths are timed on one thread and on all threads (rayon), the references on one.
//!
//! Run: `cargo bench --bench cube -- --warm-up-time 1 --measurement-time 3`; `-- rates` runs
//! only the rates (no criterion group, no naive table).
mod common;
use common::selected;
use criterion::{black_box, Criterion};
use samplescope::core::budget;
use samplescope::core::cancel::Cancel;
use samplescope::core::cube::CubePoints;
use samplescope::core::metrics;
use samplescope::core::metrics::cube::{self as measures, CubeMeasure};
use samplescope::core::pattern::cube::{halton, sobol};
use samplescope::core::pattern::Pattern;
use samplescope::core::progress::no_progress;
use std::time::Instant;

const SOBOL_N: usize = 1 << 20;
const HALTON_N: usize = 1 << 16;
const DIMS: usize = 32;

fn fast(name: &str, n: usize) -> Vec<f64> {
    let p = Pattern::from_name(name).expect("a pattern");
    p.cube_coords(black_box(n), DIMS, 0, &Cancel::never())
        .expect("valid")
}

fn one_thread<T: Send>(f: impl FnOnce() -> T + Send) -> T {
    rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .expect("a pool")
        .install(f)
}

/// Median wall time of `reps` runs, in milliseconds.
fn median_ms<T>(reps: usize, f: impl Fn() -> T) -> f64 {
    let mut t: Vec<f64> = (0..reps)
        .map(|_| {
            let start = Instant::now();
            black_box(f());
            start.elapsed().as_secs_f64() * 1e3
        })
        .collect();
    t.sort_by(f64::total_cmp);
    t[reps / 2]
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("sobol_2^20x32");
    g.sample_size(10);
    g.bench_function("gray_code", |b| b.iter(|| fast("sobol", SOBOL_N)));
    g.bench_function("naive_matrices", |b| {
        b.iter(|| sobol::sobol_naive(0, black_box(SOBOL_N), DIMS))
    });
    g.finish();
    let mut g = c.benchmark_group("halton_2^16x32");
    g.sample_size(10);
    g.bench_function("incremental", |b| b.iter(|| fast("halton", HALTON_N)));
    g.bench_function("naive_radical_inverse", |b| {
        b.iter(|| halton::halton_naive(0, black_box(HALTON_N), DIMS))
    });
    g.finish();

    let rows = [
        (
            "sobol 2^20 x 32",
            median_ms(5, || one_thread(|| fast("sobol", SOBOL_N))),
            median_ms(5, || fast("sobol", SOBOL_N)),
            median_ms(3, || sobol::sobol_naive(0, SOBOL_N, DIMS)),
        ),
        (
            "halton 2^16 x 32",
            median_ms(9, || one_thread(|| fast("halton", HALTON_N))),
            median_ms(9, || fast("halton", HALTON_N)),
            median_ms(5, || halton::halton_naive(0, HALTON_N, DIMS)),
        ),
        pair_table(c),
    ];
    println!(
        "\n{:<20} {:>12} {:>12} {:>12} {:>10} {:>10}",
        "", "fast 1 thr", "fast all", "naive", "ratio 1", "ratio all"
    );
    for (name, one, all, naive) in rows {
        println!(
            "{name:<20} {one:>10.1}ms {all:>10.1}ms {naive:>10.1}ms {:>9.1}x {:>9.1}x",
            naive / one,
            naive / all
        );
    }
}

/// Points of the pair table and the rates: unscrambled Sobol' (t-values defined, N = 2^12).
fn sobol_points(n: usize, dims: usize) -> CubePoints {
    Pattern::from_name("sobol")
        .expect("sobol")
        .generate_cube(n, dims, 0, &Cancel::never())
        .expect("valid")
}

const TABLE_N: usize = 4096;

/// The pair table at N = 4096, D = 32: fast on one and all threads, the naive reference once
/// (it takes tens of seconds), the rows checked equal.
fn pair_table(c: &mut Criterion) -> (&'static str, f64, f64, f64) {
    let pts = sobol_points(TABLE_N, DIMS);
    let never = Cancel::never();
    let fast = || measures::projection_table(&pts, &never, &mut no_progress).expect("table");
    let mut g = c.benchmark_group("pair_table_4096x32");
    g.sample_size(10);
    g.bench_function("fast", |b| b.iter(|| black_box(fast())));
    g.finish();
    let one = median_ms(5, || one_thread(fast));
    let all = median_ms(5, fast);
    let start = Instant::now();
    let naive = measures::projection_table_naive(&pts, &never).expect("naive table");
    let naive_ms = start.elapsed().as_secs_f64() * 1e3;
    assert_eq!(fast(), naive, "the fast table is the naive one");
    let est = budget::cube_measure(CubeMeasure::Projections, TABLE_N, DIMS);
    println!(
        "pair table 4096 x 32: {} pairs, estimate {:.3} s (2 cores), fast {all:.0} ms, naive {naive_ms:.0} ms",
        DIMS * (DIMS - 1) / 2,
        est.seconds
    );
    ("pair table 4096x32", one, all, naive_ms)
}

/// The CPU ns per unit of each measure of `metrics::cube::cost`, timed on one thread (so wall
/// time is CPU time): the discrepancies and the minimum distance at D = 4 and D = 32 (their
/// per-pair and per-dimension parts solved from the two), the stratification per coordinate,
/// the projection table against its estimate from the 2D rates.
fn rates() {
    let never = Cancel::never();
    let n = TABLE_N;
    let nf = n as f64;
    let (d1, d2) = (4usize, 32usize);
    let (p1, p2) = (sobol_points(n, d1), sobol_points(n, d2));
    // Median ns of one thread.
    let time = |f: &(dyn Fn() + Sync)| one_thread(|| median_ms(5, f)) * 1e6;
    // Discrepancies: 5 · N(N+1)/2 pairs · (d · factor + pair).
    let pairs = 5.0 * nf * (nf + 1.0) / 2.0;
    let disc = |p: &CubePoints| {
        time(&|| {
            black_box(measures::discrepancies(p, &never, &mut no_progress).expect("ok"));
        }) / pairs
    };
    let (y1, y2) = (disc(&p1), disc(&p2));
    let factor = (y2 - y1) / (d2 - d1) as f64;
    let pair = y1 - d1 as f64 * factor;
    println!(
        "discrepancies: {y1:.2} ns per pair at D = {d1}, {y2:.2} at D = {d2}: factor {factor:.3} ns, pair {pair:.3} ns"
    );
    // Minimum distance: N(N−1)/2 pairs · (pair + d · dim).
    let pairs = nf * (nf - 1.0) / 2.0;
    let dist = |p: &CubePoints| {
        time(&|| {
            black_box(measures::min_distance_cube(p, &never, &mut no_progress).expect("ok"));
        }) / pairs
    };
    let (y1, y2) = (dist(&p1), dist(&p2));
    let dim = (y2 - y1) / (d2 - d1) as f64;
    let pair = y1 - d1 as f64 * dim;
    println!(
        "min distance: {y1:.2} ns per pair at D = {d1}, {y2:.2} at D = {d2}: pair {pair:.3} ns, dim {dim:.3} ns"
    );
    // Stratification: N · d coordinates.
    let per = time(&|| {
        black_box(measures::stratification(&p2, &never).expect("ok"));
    }) / (nf * d2 as f64);
    println!("stratification: {per:.2} ns per coordinate (D = {d2})");
    // Projections: each part of a row, summed over the 496 pairs, per its unit: the
    // projection per point, the minimum distance per point, the L2-star per point and log₂ N,
    // the t-value per N·log₂ N·log₂ log₂ N (the units of `cost.rs`).
    let pairs: Vec<(usize, usize)> = (0..d2)
        .flat_map(|i| (i + 1..d2).map(move |j| (i, j)))
        .collect();
    let projections: Vec<Vec<glam::DVec2>> = pairs
        .iter()
        .map(|&(i, j)| p2.project(i, j).expect("a pair"))
        .collect();
    let per_pair = |f: &(dyn Fn(&[glam::DVec2]) + Sync)| {
        time(&|| projections.iter().for_each(|p| f(p))) / pairs.len() as f64
    };
    let log = nf.log2();
    let project = time(&|| {
        for &(i, j) in &pairs {
            black_box(p2.project(i, j).expect("a pair"));
        }
    }) / pairs.len() as f64
        / nf;
    let md = per_pair(&|p| {
        black_box(metrics::min_distance(p, &never).expect("ok"));
    }) / nf;
    let l2 = per_pair(&|p| {
        black_box(metrics::l2_star_discrepancy(p, &never).expect("ok"));
    }) / (nf * log);
    let t = per_pair(&|p| {
        black_box(metrics::t_value(p, 2, &never).expect("ok"));
    }) / (nf * log * log.log2());
    println!(
        "pair table rows: projection {project:.2} ns per point, min distance {md:.1} ns per point, \
         L2-star {l2:.2} ns per point and log2 N, t-value {t:.2} ns per N log2 N log2 log2 N"
    );
    // Projections: measured against the estimate's CPU time (2 cores × its seconds).
    let measured = time(&|| {
        black_box(measures::projection_table(&p2, &never, &mut no_progress).expect("ok"));
    }) * 1e-9;
    for (what, m) in [
        (CubeMeasure::Discrepancies, None),
        (CubeMeasure::MinDistance, None),
        (CubeMeasure::Stratification, None),
        (CubeMeasure::Projections, Some(measured)),
    ] {
        let e = budget::cube_measure(what, n, d2);
        match m {
            Some(m) => println!(
                "{}: estimate {:.3} s on {} cores, measured {m:.3} s on one thread ({:.2}× the estimate's CPU)",
                e.operation,
                e.seconds,
                budget::REFERENCE_CORES,
                m / (e.seconds * budget::REFERENCE_CORES)
            ),
            None => println!("{}: estimate {:.3} s", e.operation, e.seconds),
        }
    }
}

fn main() {
    let mut c = Criterion::default().configure_from_args();
    // A filter picks the constructions and the pair table (their group names), or `rates`.
    if ["sobol_2^20x32", "halton_2^16x32", "pair_table_4096x32"]
        .iter()
        .any(|id| selected(id))
    {
        bench(&mut c);
    }
    if selected("rates") {
        rates();
    }
    c.final_summary();
}
