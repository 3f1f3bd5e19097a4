//! Speed of the point-set metrics against their naive references, in the same run.
//!
//! Targets: exact star discrepancy N = 4096 ≤ 50 ms and N = 16 384 ≤ 1 s; L2-star N = 4096
//! ≤ 10 ms; PSA's statistics of 4096 jittered points ≤ 20 ms. References: the O(N³)
//! brute-force star discrepancy (timed at N = 256 and extrapolated by (N/256)³, since at
//! N = 4096 it would take minutes), the O(N²) literal Warnock sum (timed at the same N), the
//! O(N²) brute-force minimum distance, and PSA's statistics by the all-pairs RDF and the
//! direct O(m²) transform (the same triangulation).
//!
//! Run: `cargo bench --bench metrics -- --warm-up-time 1 --measurement-time 3`.
//! After criterion's report a table of medians (own timing, `Instant`) and ratios is printed.

use std::hint::black_box;
use std::time::{Duration, Instant};

use criterion::Criterion;
use glam::DVec2;
use samplescope::core::cancel::Cancel;
use samplescope::core::metrics::psa::{
    bond_orientational_order, effective_nyquist, oscillations, psa_statistics, radial_power,
    radial_power_direct, PsaStatistics,
};
use samplescope::core::metrics::{
    l2_star_discrepancy, l2_star_discrepancy_naive, min_distance, min_distance_naive,
    star_discrepancy, star_discrepancy_brute_force,
};
use samplescope::core::rng::Rng;

const SEED: u64 = 0x5EED_2024;

fn random_points(n: usize) -> Vec<DVec2> {
    let mut r = Rng::new(SEED);
    (0..n)
        .map(|_| DVec2::new(r.next_f64(), r.next_f64()))
        .collect()
}

/// Jittered points, one per cell of a k × k grid (PSA's kind of input).
fn jittered_points(k: usize) -> Vec<DVec2> {
    let mut r = Rng::new(SEED);
    let s = 1.0 / k as f64;
    (0..k * k)
        .map(|i| {
            let x = ((i % k) as f64 + r.next_f64()) * s;
            DVec2::new(x, ((i / k) as f64 + r.next_f64()) * s)
        })
        .collect()
}

/// PSA's statistics by the references: the all-pairs RDF and the direct transform.
fn psa_statistics_reference(points: &[DVec2], cancel: &Cancel) -> PsaStatistics {
    let rp = radial_power_direct(points, cancel).unwrap();
    PsaStatistics {
        effective_nyquist: effective_nyquist(&rp),
        oscillations: oscillations(&rp),
        bond_orientational_order: bond_orientational_order(points, cancel).unwrap(),
    }
}

/// `f` on one thread (so that the calling thread's CPU time is all of its work).
fn serial<T: Send>(f: impl FnOnce() -> T + Send) -> T {
    rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .expect("a one-thread pool")
        .install(f)
}

/// CPU time of the calling thread, in ns, from Linux's `/proc/thread-self/schedstat` (first
/// field: time spent on a CPU). `None` elsewhere.
fn thread_cpu_ns() -> Option<u64> {
    let s = std::fs::read_to_string("/proc/thread-self/schedstat").ok()?;
    s.split_whitespace().next()?.parse().ok()
}

/// Median over `reps` samples (after one warm-up run) of the time per call: wall time and,
/// on Linux, thread CPU time. Each sample runs `f` enough times to last ≥ 30 ms, because the
/// thread CPU clock of this kind of VM advances in scheduler ticks. The CPU time is what to
/// compare on a shared, loaded machine, where the wall time also counts waiting for a core.
fn median<T>(reps: usize, mut f: impl FnMut() -> T) -> (Duration, Option<Duration>) {
    let t = Instant::now();
    black_box(f());
    let once = t.elapsed().as_secs_f64().max(1e-7);
    let batch = ((0.03 / once).ceil() as u32).max(1);
    let mut wall = Vec::with_capacity(reps);
    let mut cpu = Vec::with_capacity(reps);
    for _ in 0..reps {
        let c0 = thread_cpu_ns();
        let t = Instant::now();
        for _ in 0..batch {
            black_box(f());
        }
        wall.push(t.elapsed() / batch);
        if let (Some(c0), Some(c1)) = (c0, thread_cpu_ns()) {
            cpu.push(Duration::from_nanos(c1 - c0) / batch);
        }
    }
    wall.sort();
    cpu.sort();
    (wall[reps / 2], cpu.get(reps / 2).copied())
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
    g.sample_size(10);
    let pts = random_points(4096);
    g.bench_function("fenwick/4096", |b| {
        b.iter(|| l2_star_discrepancy(black_box(&pts), &never).unwrap())
    });
    g.bench_function("naive/4096", |b| {
        b.iter(|| l2_star_discrepancy_naive(black_box(&pts), &never).unwrap())
    });
    g.finish();

    let mut g = c.benchmark_group("min_distance");
    g.sample_size(10);
    g.bench_function("grid/4096", |b| {
        b.iter(|| min_distance(black_box(&pts), &never).unwrap())
    });
    g.bench_function("naive/4096", |b| {
        b.iter(|| min_distance_naive(black_box(&pts), &never).unwrap())
    });
    g.finish();

    let mut g = c.benchmark_group("psa_statistics");
    g.sample_size(10);
    let jit = jittered_points(64);
    g.bench_function("fast/4096", |b| {
        b.iter(|| psa_statistics(black_box(&jit), &never).unwrap())
    });
    g.bench_function("all_pairs_rdf_direct_transform/4096", |b| {
        b.iter(|| psa_statistics_reference(black_box(&jit), &never))
    });
    g.finish();
}

/// One row of the table: times in ms (CPU time where available, else wall time).
struct Row {
    what: &'static str,
    n: usize,
    fast: (Duration, Option<Duration>),
    target: &'static str,
    reference: String,
    /// Reference time, already extrapolated to `n` where it was timed at a smaller N.
    reference_ms: (f64, Option<f64>),
}

fn ratio_table() {
    let never = Cancel::never();
    let ms = |d: Duration| d.as_secs_f64() * 1e3;
    let mut rows = Vec::new();

    let brute_n = 256usize;
    let brute_pts = random_points(brute_n);
    let brute = median(3, || {
        star_discrepancy_brute_force(&brute_pts, &never).unwrap()
    });
    for (n, target) in [(4096usize, "≤ 50 ms"), (16_384, "≤ 1000 ms")] {
        let pts = random_points(n);
        let fast = median(if n > 5000 { 3 } else { 9 }, || {
            star_discrepancy(&pts, &never).unwrap()
        });
        let scale = (n as f64 / brute_n as f64).powi(3);
        rows.push(Row {
            what: "star discrepancy, exact",
            n,
            fast,
            target,
            reference: format!("O(N³) brute force at N={brute_n}, ×(N/{brute_n})³"),
            reference_ms: (ms(brute.0) * scale, brute.1.map(|d| ms(d) * scale)),
        });
    }

    let pts = random_points(4096);
    let fast = median(9, || l2_star_discrepancy(&pts, &never).unwrap());
    let naive = median(5, || l2_star_discrepancy_naive(&pts, &never).unwrap());
    rows.push(Row {
        what: "L2-star, Warnock+Fenwick",
        n: 4096,
        fast,
        target: "≤ 10 ms",
        reference: "literal O(N²) Warnock double sum, same N".into(),
        reference_ms: (ms(naive.0), naive.1.map(ms)),
    });

    let fast = median(9, || min_distance(&pts, &never).unwrap());
    let naive = median(5, || min_distance_naive(&pts, &never).unwrap());
    rows.push(Row {
        what: "min distance, grid",
        n: 4096,
        fast,
        target: "-",
        reference: "all pairs O(N²), same N".into(),
        reference_ms: (ms(naive.0), naive.1.map(ms)),
    });

    // PSA's statistics: wall time on the whole pool; CPU time on one thread (the calling
    // thread's CPU time would miss the pool's other threads).
    let jit = jittered_points(64);
    let fast_wall = median(9, || psa_statistics(&jit, &never).unwrap()).0;
    let fast_cpu = serial(|| median(9, || psa_statistics(&jit, &never).unwrap()).1);
    let ref_wall = median(3, || psa_statistics_reference(&jit, &never)).0;
    let ref_cpu = serial(|| median(3, || psa_statistics_reference(&jit, &never)).1);
    let (a, b) = (
        psa_statistics(&jit, &never).unwrap(),
        psa_statistics_reference(&jit, &never),
    );
    assert!(
        (a.oscillations - b.oscillations).abs() < 1e-9
            && a.effective_nyquist == b.effective_nyquist
    );
    // The same stages one after the other (as `psa_statistics` ran them before the
    // triangulation went beside the RDF and its transform): the wall time the overlap saves.
    let sequential = || {
        let rp = radial_power(&jit, &never).unwrap();
        let boo = bond_orientational_order(&jit, &never).unwrap();
        (effective_nyquist(&rp), oscillations(&rp), boo)
    };
    let mut overlap = (Vec::new(), Vec::new());
    for _ in 0..3 {
        overlap
            .0
            .push(median(5, || psa_statistics(&jit, &never).unwrap()).0);
        overlap.1.push(median(5, sequential).0);
    }
    overlap.0.sort();
    overlap.1.sort();
    let psa_overlap = (ms(overlap.0[1]), ms(overlap.1[1]));
    rows.push(Row {
        what: "PSA statistics, jittered",
        n: 4096,
        fast: (fast_wall, fast_cpu),
        target: "≤ 20 ms",
        reference: "all-pairs RDF + direct O(m²) transform".into(),
        reference_ms: (ms(ref_wall), ref_cpu.map(ms)),
    });

    println!();
    println!(
        "metrics: fast vs reference (median; random points, PSA's jittered, Rng seed {SEED:#x}; \
         cpu = thread CPU time, PSA's on a one-thread pool; wall = wall clock)"
    );
    println!(
        "{:<26} {:>6} {:>10} {:>10} {:>10} {:<44} {:>12} {:>12} {:>8}",
        "computation",
        "N",
        "cpu [ms]",
        "wall [ms]",
        "target",
        "reference",
        "ref cpu",
        "ref wall",
        "ratio"
    );
    println!(
        "PSA statistics wall (3 interleaved rounds, median): triangulation beside the RDF \
         {:.1} ms, after it {:.1} ms ({:.2}x)",
        psa_overlap.0,
        psa_overlap.1,
        psa_overlap.1 / psa_overlap.0
    );
    for r in rows {
        let fast_cpu = r.fast.1.map(ms);
        let ratio = match (fast_cpu, r.reference_ms.1) {
            (Some(f), Some(g)) => g / f,
            _ => r.reference_ms.0 / ms(r.fast.0),
        };
        let opt = |v: Option<f64>| v.map_or("n/a".to_string(), |v| format!("{v:.3}"));
        println!(
            "{:<26} {:>6} {:>10} {:>10.3} {:>10} {:<44} {:>12} {:>12.1} {:>8.0}",
            r.what,
            r.n,
            opt(fast_cpu),
            ms(r.fast.0),
            r.target,
            r.reference,
            opt(r.reference_ms.1),
            r.reference_ms.0,
            ratio
        );
    }
}

fn main() {
    let mut c = Criterion::default().configure_from_args();
    criterion_benches(&mut c);
    c.final_summary();
    ratio_table();
}
