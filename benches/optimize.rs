//! Speed of the iterative blue-noise samplers (Lloyd, sliced optimal transport, Gaussian blue
//! noise), each against references measured in the same run. Criterion measures the fast paths;
//! a table printed at the end gives medians of wall time measured here with `Instant` (and the
//! thread's CPU time), the target and the ratios.
//!
//! ```text
//! cargo bench --bench optimize -- --warm-up-time 1 --measurement-time 3
//! cargo bench --bench optimize -- lloyd_1024        # one benchmark (substring filter)
//! cargo bench --bench optimize -- sot_1024
//! cargo bench --bench optimize -- gbn_1024
//! ```
//!
//! | benchmark | fast path | references | target |
//! |---|---|---|---|
//! | `lloyd_1024` | `lloyd`, N = 1024, 50 iterations | `lloyd_naive` (512² raster), 1 iteration; the same run on 1 thread; white noise | ≤ 100 ms |
//! | `sot_1024` | `sot`, N = 1024, 1024 iterations × 64 directions (the converged defaults) | the same run on 1 thread; `sot_naive` (comparison sort, same bits) on 1 thread (CPU ratio) | ≤ 500 ms |
//! | `gbn_1024` | `gbn`, N = 1024, default iterations and σ (vectorised cell-block kernel) | the same run on 1 thread; `gbn_naive` (libm `exp`, per-pair wrap) on 1 thread (CPU ratio); white noise | ≤ 500 ms |
//!
//! The CPU column is the calling thread's CPU time: for the multi-threaded runs it misses the
//! work of rayon's other threads, so compare their wall times.

mod common;
use common::{both, median_ms, selected, Timing};
use criterion::Criterion;
use samplescope::core::cancel::Cancel;
use samplescope::core::pattern::optimize::{
    gbn, gbn_naive, lloyd, lloyd_naive, sot, sot_naive, GBN_DEFAULT_ITERATIONS,
    LLOYD_DEFAULT_ITERATIONS, SOT_DEFAULT_DIRECTIONS, SOT_DEFAULT_ITERATIONS,
};
use samplescope::core::progress::no_progress;
use samplescope::core::rng::Rng;
use std::hint::black_box;
use std::sync::Mutex;

const N: usize = 1024;
const SEED: u64 = 1;

/// One line of the printed table.
struct Row {
    what: String,
    ms: Timing,
    target: String,
    versus: String,
}

static ROWS: Mutex<Vec<Row>> = Mutex::new(Vec::new());

fn push(row: Row) {
    if let Ok(mut rows) = ROWS.lock() {
        rows.push(row);
    }
}

/// `f` inside a one-thread rayon pool (the single-threaded reference).
fn single_thread<T: Send>(f: impl FnOnce() -> T + Send) -> T {
    match rayon::ThreadPoolBuilder::new().num_threads(1).build() {
        Ok(pool) => pool.install(f),
        Err(_) => f(),
    }
}

/// White noise of N points (the common start of the three samplers), median of 21 runs.
fn white_noise_ms() -> Timing {
    median_ms(21, || {
        let mut rng = Rng::new(SEED);
        let v: Vec<(f64, f64)> = (0..N).map(|_| (rng.next_f64(), rng.next_f64())).collect();
        black_box(v);
    })
}

fn target(t: Timing, ms: f64) -> String {
    format!("≤ {ms} ms: {:.2}× (wall)", t.wall / ms)
}

fn lloyd_1024(c: &mut Criterion) {
    if !selected("lloyd_1024") {
        return;
    }
    let never = Cancel::never();
    let it = LLOYD_DEFAULT_ITERATIONS;
    let mut group = c.benchmark_group("lloyd_1024");
    group.sample_size(20);
    group.bench_function("exact", |b| {
        b.iter(|| lloyd(black_box(N), it, SEED, &never, &mut no_progress))
    });
    group.finish();
    let fast = median_ms(11, || {
        black_box(lloyd(N, it, SEED, &never, &mut no_progress).ok());
    });
    let one = single_thread(|| {
        median_ms(11, || {
            black_box(lloyd(N, it, SEED, &never, &mut no_progress).ok());
        })
    });
    let naive = median_ms(3, || {
        black_box(lloyd_naive(N, 1, SEED, &never, &mut no_progress).ok());
    });
    let white = white_noise_ms();
    push(Row {
        what: format!("Lloyd N = {N}, {it} iterations"),
        ms: fast,
        target: target(fast, 100.0),
        versus: format!(
            "1 thread: {}; lloyd_naive (512² raster) 1 iteration: {} (= {:.1}× a whole exact \
             run of {it}); white noise: {}",
            both(one),
            both(naive),
            naive.wall / fast.wall,
            both(white)
        ),
    });
}

fn sot_1024(c: &mut Criterion) {
    if !selected("sot_1024") {
        return;
    }
    let never = Cancel::never();
    let (it, dirs) = (SOT_DEFAULT_ITERATIONS, SOT_DEFAULT_DIRECTIONS);
    let mut group = c.benchmark_group("sot_1024");
    group.sample_size(10);
    group.bench_function("defaults", |b| {
        b.iter(|| sot(black_box(N), it, dirs, SEED, &never, &mut no_progress))
    });
    group.finish();
    let fast = median_ms(5, || {
        black_box(sot(N, it, dirs, SEED, &never, &mut no_progress).ok());
    });
    // Both on one thread, so that the calling thread's CPU time is the whole run's.
    let naive = single_thread(|| {
        median_ms(3, || {
            black_box(sot_naive(N, it, dirs, SEED, &never, &mut no_progress).ok());
        })
    });
    let one = single_thread(|| {
        median_ms(3, || {
            black_box(sot(N, it, dirs, SEED, &never, &mut no_progress).ok());
        })
    });
    let slices = (it * dirs) as f64 * N as f64;
    push(Row {
        what: format!("SOT N = {N}, {it} iterations × {dirs} directions"),
        ms: fast,
        target: target(fast, 500.0),
        versus: format!(
            "1 thread: {} ({:.1} ns CPU per point-slice); sot_naive (comparison sort, same \
             bits), 1 thread: {} → {:.2}× (CPU); threads/1 thread {:.2}× wall",
            both(one),
            one.cpu * 1e6 / slices,
            both(naive),
            naive.cpu / one.cpu,
            fast.wall / one.wall,
        ),
    });
}

fn gbn_1024(c: &mut Criterion) {
    if !selected("gbn_1024") {
        return;
    }
    let never = Cancel::never();
    let it = GBN_DEFAULT_ITERATIONS;
    let mut group = c.benchmark_group("gbn_1024");
    group.sample_size(10);
    group.bench_function("defaults", |b| {
        b.iter(|| gbn(black_box(N), it, 0.0, SEED, &never, &mut no_progress))
    });
    group.finish();
    let fast = median_ms(5, || {
        black_box(gbn(N, it, 0.0, SEED, &never, &mut no_progress).ok());
    });
    let fast_target = target(fast, 500.0);
    // Both on one thread, so that the calling thread's CPU time is the whole run's.
    let naive = single_thread(|| {
        median_ms(3, || {
            black_box(gbn_naive(N, it, 0.0, SEED, &never, &mut no_progress).ok());
        })
    });
    let one = single_thread(|| {
        median_ms(5, || {
            black_box(gbn(N, it, 0.0, SEED, &never, &mut no_progress).ok());
        })
    });
    let white = white_noise_ms();
    push(Row {
        what: format!("GBN N = {N}, {it} iterations, σ = 1 spacing"),
        ms: fast,
        target: fast_target,
        versus: format!(
            "1 thread: {} ({:.0} ns CPU per point-step); gbn_naive (libm exp), 1 thread: {} \
             → {:.2}× (CPU); threads/1 thread {:.2}× wall; white noise: {}",
            both(one),
            one.cpu * 1e6 / (it as f64 * N as f64),
            both(naive),
            naive.cpu / one.cpu,
            fast.wall / one.wall,
            both(white)
        ),
    });
}

fn print_table() {
    let Ok(rows) = ROWS.lock() else { return };
    if rows.is_empty() {
        return;
    }
    println!();
    println!(
        "medians of repeated runs in this process: wall time (Instant) and calling-thread CPU time \
         ({} rayon threads)",
        rayon::current_num_threads()
    );
    println!(
        "{:<48} {:>10} {:>10}  {:<24} reference",
        "benchmark", "wall ms", "cpu ms", "target (measured/target)"
    );
    for r in rows.iter() {
        println!(
            "{:<48} {:>10.3} {:>10.3}  {:<24} {}",
            r.what, r.ms.wall, r.ms.cpu, r.target, r.versus
        );
    }
}

fn main() {
    let mut c = Criterion::default().configure_from_args();
    lloyd_1024(&mut c);
    sot_1024(&mut c);
    gbn_1024(&mut c);
    c.final_summary();
    print_table();
}
