//! Speed of the point-set metrics against their naive references, in the same run.
//!
//! Targets: exact star discrepancy N = 4096 ≤ 50 ms and N = 16 384 ≤ 1 s; L2-star N = 4096
//! ≤ 10 ms. References: the O(N³) brute-force star discrepancy (timed at N = 256 and
//! extrapolated by (N/256)³, since at N = 4096 it would take minutes), the O(N²) literal
//! Warnock sum (timed at the same N), and the O(N²) brute-force minimum distance.
//!
//! Run: `cargo bench --bench metrics -- --warm-up-time 1 --measurement-time 3`.
//! After criterion's report a table of medians (own timing, `Instant`) and ratios is printed.

use std::hint::black_box;
use std::time::{Duration, Instant};

use criterion::Criterion;
use glam::DVec2;
use samplescope::core::cancel::Cancel;
use samplescope::core::metrics::{
    l2_star_discrepancy, l2_star_discrepancy_naive, min_distance, min_distance_naive,
    star_discrepancy, star_discrepancy_brute_force,
};
use samplescope::core::rng::Rng;

const SEED: u64 = 0x5EED_2024;

fn random_points(n: usize) -> Vec<DVec2> {
    let mut r = Rng::new(SEED);
    (0..n).map(|_| DVec2::new(r.next_f64(), r.next_f64())).collect()
}

/// Median wall time of `reps` runs (after one warm-up run).
fn median<T>(reps: usize, mut f: impl FnMut() -> T) -> Duration {
    black_box(f());
    let mut v: Vec<Duration> = (0..reps)
        .map(|_| {
            let t = Instant::now();
            black_box(f());
            t.elapsed()
        })
        .collect();
    v.sort();
    v[reps / 2]
}

fn criterion_benches(c: &mut Criterion) {
    let never = Cancel::never();
    let mut g = c.benchmark_group("star_discrepancy");
    g.sample_size(10);
    for n in [4096usize, 16_384] {
        let pts = random_points(n);
        g.bench_function(format!("sweep/{n}"), |b| {
            b.iter(|| star_discrepancy(black_box(&pts), &never).unwrap())
        });
    }
    let pts = random_points(256);
    g.bench_function("brute_force/256", |b| {
        b.iter(|| star_discrepancy_brute_force(black_box(&pts), &never).unwrap())
    });
    g.finish();

    let mut g = c.benchmark_group("l2_star_discrepancy");
    g.sample_size(20);
    let pts = random_points(4096);
    g.bench_function("fenwick/4096", |b| {
        b.iter(|| l2_star_discrepancy(black_box(&pts), &never).unwrap())
    });
    g.bench_function("naive/4096", |b| {
        b.iter(|| l2_star_discrepancy_naive(black_box(&pts), &never).unwrap())
    });
    g.finish();

    let mut g = c.benchmark_group("min_distance");
    g.sample_size(20);
    g.bench_function("grid/4096", |b| {
        b.iter(|| min_distance(black_box(&pts), &never).unwrap())
    });
    g.bench_function("naive/4096", |b| {
        b.iter(|| min_distance_naive(black_box(&pts), &never).unwrap())
    });
    g.finish();
}

fn ratio_table() {
    let never = Cancel::never();
    let ms = |d: Duration| d.as_secs_f64() * 1e3;
    println!();
    println!("metrics: fast vs reference (median wall time, random points, seed {SEED:#x})");
    println!(
        "{:<28} {:>7} {:>12} {:>10} {:<40} {:>12} {:>10}",
        "computation", "N", "fast [ms]", "target", "reference", "ref [ms]", "ratio"
    );

    let brute_n = 256usize;
    let brute_pts = random_points(brute_n);
    let brute = median(3, || star_discrepancy_brute_force(&brute_pts, &never).unwrap());
    for (n, target) in [(4096usize, "≤ 50 ms"), (16_384, "≤ 1000 ms")] {
        let pts = random_points(n);
        let fast = median(if n > 5000 { 3 } else { 7 }, || {
            star_discrepancy(&pts, &never).unwrap()
        });
        let scale = (n as f64 / brute_n as f64).powi(3);
        let extrapolated = brute.as_secs_f64() * 1e3 * scale;
        println!(
            "{:<28} {:>7} {:>12.3} {:>10} {:<40} {:>12.1} {:>10.0}",
            "star discrepancy (exact)",
            n,
            ms(fast),
            target,
            format!("brute force O(N³): {:.2} ms at N={brute_n} ×{scale:.0}", ms(brute)),
            extrapolated,
            extrapolated / ms(fast)
        );
    }

    let pts = random_points(4096);
    let fast = median(21, || l2_star_discrepancy(&pts, &never).unwrap());
    let naive = median(5, || l2_star_discrepancy_naive(&pts, &never).unwrap());
    println!(
        "{:<28} {:>7} {:>12.3} {:>10} {:<40} {:>12.1} {:>10.0}",
        "L2-star (Warnock, Fenwick)",
        4096,
        ms(fast),
        "≤ 10 ms",
        "literal O(N²) double sum, same N",
        ms(naive),
        ms(naive) / ms(fast)
    );

    let fast = median(21, || min_distance(&pts, &never).unwrap());
    let naive = median(5, || min_distance_naive(&pts, &never).unwrap());
    println!(
        "{:<28} {:>7} {:>12.3} {:>10} {:<40} {:>12.1} {:>10.0}",
        "min distance (grid)",
        4096,
        ms(fast),
        "-",
        "all pairs O(N²), same N",
        ms(naive),
        ms(naive) / ms(fast)
    );
}

fn main() {
    let mut c = Criterion::default().configure_from_args();
    criterion_benches(&mut c);
    c.final_summary();
    ratio_table();
}
