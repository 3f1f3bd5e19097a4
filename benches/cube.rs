//! d-dimensional generators against their naive references (same run, ratio printed):
//! - Sobol' 2²⁰ points × 32 dimensions: Gray-code stepping (one XOR per coordinate, parallel
//!   chunks) vs every point from its index through the 32 columns of the generator matrices;
//! - Halton 2¹⁶ points × 32 dimensions: the incremental exact radical inverses (parallel
//!   chunks) vs one `radical_inverse` per coordinate (digit extraction by division).
//!
//! The fast paths are timed on one thread and on all threads (rayon), the references on one.
//!
//! Run: `cargo bench --bench cube -- --warm-up-time 1 --measurement-time 3`.
use criterion::{black_box, criterion_group, criterion_main, Criterion};
use samplescope::core::cancel::Cancel;
use samplescope::core::pattern::cube::{halton, sobol};
use samplescope::core::pattern::Pattern;
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
fn median_ms(reps: usize, f: impl Fn() -> Vec<f64>) -> f64 {
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

criterion_group!(benches, bench);
criterion_main!(benches);
