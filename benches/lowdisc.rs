//! Low-discrepancy generators against their naive references.
//!
//! Target (task brief): 65 536 Owen-scrambled Sobol' points in ≤ 1.5 ms, release, one core.
//! Each fast path is timed next to its reference in the same run and the ratio is printed:
//! - `sobol owen`  vs the definition-level Owen scramble (one hashed coin per tree node, 32 per
//!   coordinate) applied to matrix-product Sobol' points;
//! - `sobol none`  vs the matrix-vector product per point ([`sobol_point_u32`]);
//! - `halton 2,3`  vs digit-by-digit f64 summation of Φ_b;
//! - `halton-zaremba 2,3` vs digit-by-digit f64 summation of the folded series (64 digits).
//!
//! Run: `cargo bench --bench lowdisc -- --warm-up-time 1 --measurement-time 3`.
use criterion::{black_box, criterion_group, criterion_main, Criterion};
use glam::DVec2;
use samplescope::core::pattern::lowdisc::{self, owen_scramble_reference, sobol_point_u32};
use samplescope::core::pattern::{Halton, HaltonZaremba, Scramble, Sobol};
use samplescope::core::rng::derive_seed;
use std::time::Instant;

const N: usize = 65_536;

fn sobol_fast(scramble: Scramble) -> Vec<DVec2> {
    lowdisc::sobol(&Sobol { scramble, skip: 0 }, N, black_box(7)).expect("valid parameters")
}

/// Per point: matrix-vector product, then (optionally) the per-node-hash Owen scramble.
fn sobol_reference(owen: bool) -> Vec<DVec2> {
    let (sx, sy) = (derive_seed(7, 0), derive_seed(7, 1));
    (0..N as u32)
        .map(|i| {
            let [mut x, mut y] = sobol_point_u32(black_box(i ^ (i >> 1)));
            if owen {
                x = owen_scramble_reference(x, sx);
                y = owen_scramble_reference(y, sy);
            }
            DVec2::new(x as f64 / 4_294_967_296.0, y as f64 / 4_294_967_296.0)
        })
        .collect()
}

fn halton_fast() -> Vec<DVec2> {
    lowdisc::halton(&Halton::default(), black_box(N)).expect("valid parameters")
}

/// Φ_b(i) by summing a_k b^{−k} in f64, digit by digit.
fn halton_reference() -> Vec<DVec2> {
    let phi = |mut i: u64, b: u64| {
        let (mut sum, mut w) = (0.0, 1.0 / b as f64);
        while i > 0 {
            sum += (i % b) as f64 * w;
            w /= b as f64;
            i /= b;
        }
        sum
    };
    (0..N as u64)
        .map(|i| DVec2::new(phi(black_box(i), 2), phi(i, 3)))
        .collect()
}

fn zaremba_fast() -> Vec<DVec2> {
    lowdisc::halton_zaremba(&HaltonZaremba::default(), black_box(N)).expect("valid parameters")
}

/// Φ⁺_b(i) by summing ((a_k + k − 1) mod b) b^{−k} in f64 over 64 digits (past double precision
/// for b ≥ 2: the omitted tail is < 2⁻⁶⁴).
fn zaremba_reference() -> Vec<DVec2> {
    let phi = |mut i: u64, b: u64| {
        let (mut sum, mut w) = (0.0, 1.0 / b as f64);
        for k in 0..64 {
            sum += ((i % b + k) % b) as f64 * w;
            w /= b as f64;
            i /= b;
        }
        sum
    };
    (0..N as u64)
        .map(|i| DVec2::new(phi(black_box(i), 2), phi(i, 3)))
        .collect()
}

/// Median wall time of `reps` runs, in milliseconds.
fn median_ms(reps: usize, f: impl Fn() -> Vec<DVec2>) -> f64 {
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
    let mut g = c.benchmark_group("sobol_65536");
    g.bench_function("owen_fast", |b| b.iter(|| sobol_fast(Scramble::Owen)));
    g.bench_function("owen_reference", |b| b.iter(|| sobol_reference(true)));
    g.bench_function("none_gray", |b| b.iter(|| sobol_fast(Scramble::None)));
    g.bench_function("none_matrix", |b| b.iter(|| sobol_reference(false)));
    g.finish();
    let mut g = c.benchmark_group("halton_65536");
    g.bench_function("fast", |b| b.iter(halton_fast));
    g.bench_function("reference", |b| b.iter(halton_reference));
    g.finish();
    let mut g = c.benchmark_group("halton_zaremba_65536");
    g.bench_function("fast", |b| b.iter(zaremba_fast));
    g.bench_function("reference", |b| b.iter(zaremba_reference));
    g.finish();

    // The ratio table (same process, same machine state).
    let rows = [
        (
            "sobol owen (target ≤ 1.5 ms)",
            median_ms(51, || sobol_fast(Scramble::Owen)),
            median_ms(11, || sobol_reference(true)),
        ),
        (
            "sobol none",
            median_ms(51, || sobol_fast(Scramble::None)),
            median_ms(51, || sobol_reference(false)),
        ),
        (
            "halton 2,3",
            median_ms(21, halton_fast),
            median_ms(21, halton_reference),
        ),
        (
            "halton-zaremba 2,3",
            median_ms(21, zaremba_fast),
            median_ms(5, zaremba_reference),
        ),
    ];
    println!(
        "\n{:<30} {:>10} {:>14} {:>8}",
        "65 536 points", "fast ms", "reference ms", "speedup"
    );
    for (name, fast, reference) in rows {
        println!(
            "{name:<30} {fast:>10.3} {reference:>14.3} {:>7.1}x",
            reference / fast
        );
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
