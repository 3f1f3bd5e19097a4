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

/// CPU time consumed so far by all threads of this process (Linux: the first field of
/// /proc/self/task/*/schedstat, in ns); `None` elsewhere.
fn cpu_time() -> Option<Duration> {
    let mut total = 0u64;
    for entry in std::fs::read_dir("/proc/self/task").ok()? {
        let path = entry.ok()?.path().join("schedstat");
        if let Ok(text) = std::fs::read_to_string(path) {
            total += text.split_whitespace().next()?.parse::<u64>().ok()?;
        }
    }
    Some(Duration::from_nanos(total))
}

/// Timing of `runs` calls (after one warm-up call): median wall time and mean CPU time of all
/// threads (on a machine shared with other jobs, the CPU time is the better estimate of the
/// uncontended cost; for a 1-thread pool it is the single-core time).
#[derive(Clone, Copy)]
struct Timing {
    wall: Duration,
    cpu: Option<Duration>,
}

fn measure<T>(runs: usize, mut f: impl FnMut() -> T) -> Timing {
    black_box(f());
    let c0 = cpu_time();
    let mut t: Vec<Duration> = (0..runs)
        .map(|_| {
            let s = Instant::now();
            black_box(f());
            s.elapsed()
        })
        .collect();
    let cpu = match (c0, cpu_time()) {
        (Some(a), Some(b)) => Some((b - a) / runs as u32),
        _ => None,
    };
    t.sort();
    Timing {
        wall: t[runs / 2],
        cpu,
    }
}

fn ms(d: Duration) -> f64 {
    d.as_secs_f64() * 1e3
}

fn cpu_ms(t: Timing) -> String {
    t.cpu.map_or("n/a".into(), |c| format!("{:.3}", ms(c)))
}

fn table() {
    let c = Cancel::never();
    let points = uniform(N, 1);
    let one = pool(1);
    println!();
    println!("periodogram of N = {N} uniform points on M = {M} (256² frequencies), 1 thread (rayon pool of 1)");
    println!("times in ms: wall = median wall clock, cpu = mean CPU time of all threads per call, stages = median wall clock");
    one.install(|| {
        let exact = periodogram_exact(&points, M, &c).expect("exact");
        let t_exact = measure(3, || periodogram_exact(&points, M, &c).expect("exact"));
        let t_naive_small = measure(1, || periodogram_naive(&points, M_NAIVE).expect("naive"));
        let scale = (M * M) as f64 / (M_NAIVE * M_NAIVE) as f64;
        let naive_wall = t_naive_small.wall.as_secs_f64() * scale;
        let naive_cpu = t_naive_small.cpu.map(|c| c.as_secs_f64() * scale);
        println!(
            "exact DFT, phasor recurrences (N·M²/2 multiply-adds): wall {:.1} cpu {}",
            ms(t_exact.wall),
            cpu_ms(t_exact)
        );
        println!(
            "naive DFT, sin/cos per point and frequency: wall {:.1} cpu {} on {M_NAIVE}², × {scale} (cost ∝ M²) = wall {:.0} cpu {} estimated for {M}²",
            ms(t_naive_small.wall),
            cpu_ms(t_naive_small),
            naive_wall * 1e3,
            naive_cpu.map_or("n/a".into(), |c| format!("{:.0}", c * 1e3)),
        );
        println!("| tolerance | w  | β    | rel. ℓ2 error (DC excl.) | error/tol | wall ms | cpu ms | spread | fft   | deconv | exact/nufft (cpu) | naive/nufft (cpu) |");
        println!("|-----------|----|------|--------------------------|-----------|---------|--------|--------|-------|--------|-------------------|-------------------|");
        for tol in TOLERANCES {
            let plan = NufftPlan::new(M, tol).expect("plan");
            let (s, _) = plan.periodogram_timed(&points, &c).expect("nufft");
            let err = relative_l2_error(&s, &exact, true);
            let mut stages: Vec<[Duration; 3]> = Vec::new();
            let runs = 41;
            let t = measure(runs, || {
                let (s, tm) = plan.periodogram_timed(&points, &c).expect("nufft");
                stages.push([tm.spread, tm.fft, tm.deconvolve]);
                s
            });
            // Median of each stage over the calls.
            let per = |i: usize| {
                let mut v: Vec<Duration> = stages.iter().map(|s| s[i]).collect();
                v.sort();
                ms(v[v.len() / 2])
            };
            let k = plan.kernel();
            let base = t.cpu.unwrap_or(t.wall).as_secs_f64();
            println!(
                "| {tol:9.0e} | {:2} | {:4.1} | {err:24.2e} | {:9.3} | {:7.3} | {:>6} | {:6.3} | {:5.3} | {:6.3} | {:17.0} | {:17.0} |",
                k.width,
                k.beta,
                err / tol,
                ms(t.wall),
                cpu_ms(t),
                per(0),
                per(1),
                per(2),
                t_exact.cpu.unwrap_or(t_exact.wall).as_secs_f64() / base,
                naive_cpu.unwrap_or(naive_wall) / base,
            );
        }
        let t_plan = measure(5, || NufftPlan::new(M, 1e-6).expect("plan"));
        println!(
            "plan construction (1e-6, 256²; once per request): wall {:.3} ms",
            ms(t_plan.wall)
        );
        let m_psa = psa_default_size(N);
        for tol in [1e-3, 1e-6] {
            let plan = NufftPlan::new(m_psa, tol).expect("plan");
            let t = measure(9, || plan.periodogram(&points, &c).expect("nufft"));
            println!(
                "PSA default grid M = {m_psa} for N = {N}, tolerance {tol:.0e}, 1 thread: wall {:.2} ms, cpu {} ms (target ≤ 20 ms)",
                ms(t.wall),
                cpu_ms(t)
            );
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
        let t = p.install(|| measure(9, || average_periodogram(&req, 7, gen, &c).expect("avg")));
        println!(
            "K = 16 realizations of N = {N} (generated + NUFFT 1e-6 on {M}² + averaged), {threads} thread(s): wall {:.2} ms, cpu {} ms (target ≤ 25 ms wall on 2)",
            ms(t.wall),
            cpu_ms(t)
        );
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
    let mut g = c.benchmark_group("spectrum_targets");
    let plan = NufftPlan::new(psa_default_size(N), 1e-6).expect("plan");
    g.bench_function("psa_640sq_1e-6_1thread", |b| {
        one.install(|| b.iter(|| plan.periodogram(&points, &cancel).expect("nufft")))
    });
    let two = pool(2);
    let req = SpectrumRequest {
        size: M,
        method: Method::Nufft { tolerance: 1e-6 },
        realizations: 16,
        dc: DcMode::Show,
        error_check_budget: 0,
    };
    let gen = |seed: u64| Ok::<_, std::convert::Infallible>(uniform(N, seed));
    g.bench_function("average_k16_256sq_1e-6_2threads", |b| {
        two.install(|| b.iter(|| average_periodogram(&req, 7, gen, &cancel).expect("avg")))
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
