//! Periodogram benchmarks: NUFFT at several tolerances against the exact DFT (fast exact path
//! and the naive sin/cos reference) in the same run, on one core (a 1-thread rayon pool) unless
//! a line says otherwise. Prints a table with the measured error and the speed ratios, then
//! runs criterion on the main cases.
//!
//! Run: `cargo bench --bench spectrum -- --warm-up-time 1 --measurement-time 3`

use criterion::{criterion_group, criterion_main, Criterion};
use glam::DVec2;
use samplescope::core::cancel::Cancel;
use samplescope::core::rng::Rng;
use samplescope::core::spectrum::{
    average_periodogram, periodogram_exact, periodogram_naive, psa_default_size, relative_l2_error,
    DcMode, Method, NufftPlan, SpectrumRequest,
};
use std::hint::black_box;
use std::time::{Duration, Instant};

const N: usize = 4096;
const M: usize = 256;
/// The naive DFT runs on M_NAIVE² frequencies and is scaled by (M/M_NAIVE)²: its cost is
/// exactly N sin/cos per frequency, so the scaling is linear in the number of frequencies.
const M_NAIVE: usize = 64;
const TOLERANCES: [f64; 5] = [1e-2, 1e-3, 1e-6, 1e-9, 1e-12];

fn uniform(n: usize, seed: u64) -> Vec<DVec2> {
    let mut r = Rng::new(seed);
    (0..n)
        .map(|_| DVec2::new(r.next_f64(), r.next_f64()))
        .collect()
}

fn pool(threads: usize) -> rayon::ThreadPool {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("thread pool")
}

/// Median wall time of `runs` calls (after one warm-up call).
fn median<T>(runs: usize, mut f: impl FnMut() -> T) -> Duration {
    black_box(f());
    let mut t: Vec<Duration> = (0..runs)
        .map(|_| {
            let s = Instant::now();
            black_box(f());
            s.elapsed()
        })
        .collect();
    t.sort();
    t[runs / 2]
}

fn ms(d: Duration) -> f64 {
    d.as_secs_f64() * 1e3
}

fn table() {
    let c = Cancel::never();
    let points = uniform(N, 1);
    let one = pool(1);
    one.install(|| {
        let exact = periodogram_exact(&points, M, &c).expect("exact");
        let t_exact = median(3, || periodogram_exact(&points, M, &c).expect("exact"));
        let t_naive_small = median(1, || periodogram_naive(&points, M_NAIVE).expect("naive"));
        let scale = (M * M) as f64 / (M_NAIVE * M_NAIVE) as f64;
        let t_naive = t_naive_small.mul_f64(scale);
        println!();
        println!("periodogram, N = {N} uniform points, M = {M} (256² frequencies), 1 thread");
        println!(
            "exact (phasor recurrences): {:9.2} ms | naive sin/cos: {:9.2} ms on {M_NAIVE}² × {scale} = {:9.1} ms (est. for {M}²)",
            ms(t_exact),
            ms(t_naive_small),
            ms(t_naive)
        );
        println!("| tolerance | w  | β     | rel. ℓ2 error (DC excl.) | error/tol | time (ms) | spread | fft | deconv | × faster than exact | × faster than naive |");
        for tol in TOLERANCES {
            let plan = NufftPlan::new(M, tol).expect("plan");
            let (s, _) = plan.periodogram_timed(&points, &c).expect("nufft");
            let err = relative_l2_error(&s, &exact, true);
            let mut stage = [Duration::ZERO; 3];
            let t = median(15, || {
                let (s, tm) = plan.periodogram_timed(&points, &c).expect("nufft");
                stage = [tm.spread, tm.fft, tm.deconvolve];
                s
            });
            let k = plan.kernel();
            println!(
                "| {tol:9.0e} | {:2} | {:5.1} | {err:24.2e} | {:9.2} | {:9.3} | {:6.3} | {:5.3} | {:6.3} | {:19.0} | {:19.0} |",
                k.width,
                k.beta,
                err / tol,
                ms(t),
                ms(stage[0]),
                ms(stage[1]),
                ms(stage[2]),
                t_exact.as_secs_f64() / t.as_secs_f64(),
                t_naive.as_secs_f64() / t.as_secs_f64(),
            );
        }
        let plan_once = median(5, || NufftPlan::new(M, 1e-6).expect("plan"));
        println!("plan construction (1e-6, 256): {:.3} ms (once per request, not per realization)", ms(plan_once));
        let m_psa = psa_default_size(N);
        for tol in [1e-3, 1e-6] {
            let plan = NufftPlan::new(m_psa, tol).expect("plan");
            let t = median(7, || plan.periodogram(&points, &c).expect("nufft"));
            println!("PSA default grid M = {m_psa} (N = {N}), tolerance {tol:.0e}, 1 thread: {:.2} ms (target ≤ 20 ms)", ms(t));
        }
    });
    for threads in [1, 2] {
        let p = pool(threads);
        let req = SpectrumRequest {
            size: M,
            method: Method::Nufft { tolerance: 1e-6 },
            realizations: 16,
            dc: DcMode::Show,
            error_check_budget: 0,
        };
        let gen = |seed: u64| Ok::<_, std::convert::Infallible>(uniform(N, seed));
        let t = p.install(|| median(7, || average_periodogram(&req, 7, gen, &c).expect("avg")));
        println!("K = 16 realizations of N = {N} averaged on {M}², tolerance 1e-6, {threads} thread(s): {:.2} ms (target ≤ 25 ms on 2)", ms(t));
    }
    println!();
}

fn bench(c: &mut Criterion) {
    table();
    let cancel = Cancel::never();
    let points = uniform(N, 1);
    let one = pool(1);
    let mut g = c.benchmark_group("periodogram_4096pts_256sq_1thread");
    for tol in [1e-3, 1e-6, 1e-12] {
        let plan = NufftPlan::new(M, tol).expect("plan");
        g.bench_function(format!("nufft_{tol:.0e}"), |b| {
            one.install(|| b.iter(|| plan.periodogram(&points, &cancel).expect("nufft")))
        });
    }
    g.sample_size(10);
    g.bench_function("exact", |b| {
        one.install(|| b.iter(|| periodogram_exact(&points, M, &cancel).expect("exact")))
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
