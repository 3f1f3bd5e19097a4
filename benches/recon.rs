//! Splatting vs per-pixel gathering of scattered samples; the zone plate's reference image.
//!
//! Target: 65 536 samples, 5×5 taps each (kernel radius 1.25 sample spacings = 2.5 px), onto a
//! 512×512 image in ≤ 5 ms on one core, i.e. ≤ 3 ns per tap. Both algorithms run on a
//! one-thread rayon pool so the ratio compares one core with one core. A summary table (best
//! of 15 runs, wall and on-CPU time) is printed after the criterion measurements.
//!
//! Group `reference`: the 512² zone plate reference (K = 256, `ZonePlate::default()`) by
//! separable Gauss–Legendre quadrature, against 8×8 + 16×16 jittered supersampling
//! (`reference_supersampled`, default options) in the same run, both on the global rayon pool
//! (all cores). A table of medians and the ratio (also at K = 64, the default scene's
//! `default.ron`, and K = 2000) follows, printed only when
//! the command line's filter selects the group (`cargo bench --bench recon -- reference`).

use criterion::{criterion_group, criterion_main, Criterion, SamplingMode};
use glam::DVec2;
use samplescope::core::cancel::Cancel;
#[path = "../tests/it/recon_kernels.rs"]
#[allow(dead_code)]
mod recon_kernels;
use recon_kernels::{GaussianKernel, NonSeparable, TentKernel};
use samplescope::core::filter::{Filter, Filter2D, Gaussian};
use samplescope::core::recon::{
    reconstruct_scattered, reconstruct_scattered_gather, reference_image, reference_supersampled,
    rmse, sample_signal, ExactFactors, ReconKernel, ReferenceOptions,
};
use samplescope::core::rng::Rng;
use samplescope::core::signal::{Signal, ZonePlate};
use std::hint::black_box;
use std::time::{Duration, Instant};

const N: usize = 65_536;
const W: usize = 512;
const RADIUS: f64 = 1.25;

fn setup() -> (Vec<DVec2>, Vec<f64>) {
    let mut rng = Rng::new(2024);
    let points: Vec<DVec2> = (0..N)
        .map(|_| DVec2::new(rng.next_f64(), rng.next_f64()))
        .collect();
    let values = sample_signal(
        &Signal::ZonePlate(ZonePlate::default()),
        &points,
        &Cancel::never(),
    )
    .expect("valid signal");
    (points, values)
}

/// Exact number of (sample, pixel) pairs with both offsets inside the support.
fn count_taps(points: &[DVec2]) -> u64 {
    let r_px = RADIUS * W as f64 / (N as f64).sqrt();
    let per_axis = |x: f64| {
        (0..W)
            .filter(|&i| ((i as f64 + 0.5) - x).abs() < r_px)
            .count() as u64
    };
    points
        .iter()
        .map(|p| per_axis(p.x * W as f64) * per_axis(p.y * W as f64))
        .sum()
}

fn pool() -> rayon::ThreadPool {
    rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .expect("one-thread pool")
}

/// On-CPU time of the calling thread in ns (`clock_gettime(CLOCK_THREAD_CPUTIME_ID)`), which
/// excludes the time spent waiting for a core on a shared machine; `None` off 64-bit Linux.
#[cfg(all(target_os = "linux", target_pointer_width = "64"))]
fn thread_cpu_ns() -> Option<u64> {
    #[repr(C)]
    struct Timespec {
        tv_sec: i64,
        tv_nsec: i64,
    }
    extern "C" {
        fn clock_gettime(clock: i32, ts: *mut Timespec) -> i32;
    }
    const CLOCK_THREAD_CPUTIME_ID: i32 = 3;
    let mut ts = Timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: `ts` is a valid, writable timespec (two 64-bit fields on 64-bit Linux).
    let rc = unsafe { clock_gettime(CLOCK_THREAD_CPUTIME_ID, &mut ts) };
    (rc == 0).then(|| ts.tv_sec as u64 * 1_000_000_000 + ts.tv_nsec as u64)
}

#[cfg(not(all(target_os = "linux", target_pointer_width = "64")))]
fn thread_cpu_ns() -> Option<u64> {
    None
}

/// Best of `runs` (wall time, on-CPU time) of `f`, run on the one-thread pool.
fn best_of<F: Fn() + Sync>(
    one: &rayon::ThreadPool,
    runs: usize,
    f: F,
) -> (Duration, Option<Duration>) {
    let mut wall = Duration::MAX;
    let mut cpu: Option<Duration> = None;
    for _ in 0..runs {
        let (w, c) = one.install(|| {
            let c0 = thread_cpu_ns();
            let t = Instant::now();
            f();
            let w = t.elapsed();
            let c = match (c0, thread_cpu_ns()) {
                (Some(a), Some(b)) => Some(Duration::from_nanos(b.saturating_sub(a))),
                _ => None,
            };
            (w, c)
        });
        wall = wall.min(w);
        cpu = match (cpu, c) {
            (Some(a), Some(b)) => Some(a.min(b)),
            (None, b) => b,
            (a, None) => a,
        };
    }
    (wall, cpu)
}

type Timing = (Duration, Option<Duration>);

/// Best-of-15 splat and gather times for one kernel (statically dispatched).
fn time_pair<K: ReconKernel + ?Sized>(k: &K, points: &[DVec2], values: &[f64]) -> (Timing, Timing) {
    let cancel = Cancel::never();
    let one = pool();
    let s = best_of(&one, 15, || {
        black_box(reconstruct_scattered(points, values, W, k, &cancel).expect("ok"));
    });
    let g = best_of(&one, 15, || {
        black_box(reconstruct_scattered_gather(points, values, W, k, &cancel).expect("ok"));
    });
    (s, g)
}

fn bench_kernel<K: ReconKernel>(
    c: &mut Criterion,
    name: &str,
    k: &K,
    points: &[DVec2],
    values: &[f64],
) {
    let cancel = Cancel::never();
    let one = pool();
    let mut group = c.benchmark_group("recon_scattered_65536_to_512");
    group.sample_size(20);
    group.bench_function(format!("splat {name}"), |b| {
        b.iter(|| {
            one.install(|| {
                black_box(reconstruct_scattered(points, values, W, k, &cancel).expect("ok"))
            })
        })
    });
    group.bench_function(format!("gather {name}"), |b| {
        b.iter(|| {
            one.install(|| {
                black_box(reconstruct_scattered_gather(points, values, W, k, &cancel).expect("ok"))
            })
        })
    });
    group.finish();
}

fn bench(c: &mut Criterion) {
    let (points, values) = setup();
    let tent = TentKernel { radius: RADIUS };
    let gauss = GaussianKernel {
        sigma: 0.5,
        radius: RADIUS,
    };
    let tent2d = NonSeparable(tent);
    bench_kernel(c, "tent (separable)", &tent, &points, &values);
    bench_kernel(c, "gaussian (separable)", &gauss, &points, &values);
    bench_kernel(c, "tent (2D path)", &tent2d, &points, &values);

    let rows = [
        ("tent (separable)", time_pair(&tent, &points, &values)),
        ("gaussian (separable)", time_pair(&gauss, &points, &values)),
        ("tent (2D path)", time_pair(&tent2d, &points, &values)),
        (
            "tent (dyn, separable)",
            time_pair(&tent as &dyn ReconKernel, &points, &values),
        ),
    ];
    let taps = count_taps(&points);
    println!();
    println!(
        "scattered reconstruction: N = {N}, W = {W}, radius {RADIUS} spacings, {taps} taps ({:.2} per sample), one core, best of 15",
        taps as f64 / N as f64
    );
    println!(
        "{:<22} {:>9} {:>9} {:>8} {:>10} {:>10} {:>8} {:>13}",
        "kernel", "splat ms", "cpu ms", "ns/tap", "gather ms", "cpu ms", "ns/tap", "gather/splat"
    );
    let ms = |d: Duration| d.as_secs_f64() * 1e3;
    for (name, ((sw, sc), (gw, gc))) in rows {
        // ns per tap and the ratio from the on-CPU time when available, else the wall time.
        let s = sc.unwrap_or(sw);
        let g = gc.unwrap_or(gw);
        println!(
            "{:<22} {:>9.3} {:>9.3} {:>8.3} {:>10.3} {:>10.3} {:>8.3} {:>13.2}",
            name,
            ms(sw),
            ms(s),
            s.as_secs_f64() * 1e9 / taps as f64,
            ms(gw),
            ms(g),
            g.as_secs_f64() * 1e9 / taps as f64,
            g.as_secs_f64() / s.as_secs_f64()
        );
    }
    println!("target: splat ≤ 5 ms (≤ 3 ns per tap) for the separable tent");
}

/// Whether the criterion filter on the command line (`cargo bench --bench recon -- FILTER`)
/// selects one of `ids` (a substring match, as for plain-word filters; no filter selects all).
/// The values of criterion's value-taking flags are not filters.
fn selected(ids: &[&str]) -> bool {
    const WITH_VALUE: [&str; 16] = [
        "--save-baseline",
        "-s",
        "--baseline",
        "-b",
        "--load-baseline",
        "--sample-size",
        "--warm-up-time",
        "--measurement-time",
        "--nresamples",
        "--noise-threshold",
        "--confidence-level",
        "--significance-level",
        "--plotting-backend",
        "--output-format",
        "--profile-time",
        "--color",
    ];
    let mut args = std::env::args().skip(1);
    let mut filters = Vec::new();
    while let Some(a) = args.next() {
        if WITH_VALUE.contains(&a.as_str()) {
            args.next();
        } else if !a.starts_with('-') {
            filters.push(a);
        }
    }
    filters.is_empty()
        || filters
            .iter()
            .any(|f| ids.iter().any(|id| id.contains(f.as_str())))
}

/// Median wall time of `reps` ≥ 1 runs of `f` in ms, and the last run's result.
fn median_ms<T>(reps: usize, f: impl Fn() -> T) -> (f64, T) {
    let mut t = Vec::with_capacity(reps);
    let mut last = None;
    for _ in 0..reps {
        let s = Instant::now();
        let r = black_box(f());
        t.push(s.elapsed().as_secs_f64() * 1e3);
        last = Some(r);
    }
    t.sort_by(f64::total_cmp);
    (t[reps / 2], last.expect("reps ≥ 1"))
}

fn bench_reference(c: &mut Criterion) {
    let cancel = Cancel::never();
    let opts = ReferenceOptions::default();
    let plate = |k: f64| {
        Signal::ZonePlate(ZonePlate {
            k,
            ..ZonePlate::default()
        })
    };
    // The signal's default zone plate: K = 256, centre (½, ½).
    let z = Signal::ZonePlate(ZonePlate::default());
    let ids = [
        "reference/zone plate 512 K=256 quadrature",
        "reference/zone plate 512 K=256 supersampled",
    ];
    let mut group = c.benchmark_group("reference");
    group.sample_size(10);
    // One iteration per sample: the supersampled reference takes seconds.
    group.sampling_mode(SamplingMode::Flat);
    group.bench_function("zone plate 512 K=256 quadrature", |b| {
        b.iter(|| black_box(reference_image(&z, W).expect("ok")))
    });
    group.bench_function("zone plate 512 K=256 supersampled", |b| {
        b.iter(|| black_box(reference_supersampled(&z, W, &opts, &cancel).expect("ok")))
    });
    group.finish();
    if !selected(&ids) {
        return;
    }
    println!();
    println!(
        "zone plate reference, {W}², {} threads: separable 20-point Gauss–Legendre vs 8×8 + 16×16 \
         jittered supersampling (medians of 21 and 3 runs)",
        rayon::current_num_threads()
    );
    println!(
        "{:<8} {:>14} {:>16} {:>10} {:>12} {:>12} {:>16}",
        "K", "quadrature ms", "supersampled ms", "speedup", "bound", "ss estimate", "RMS(q − ss)"
    );
    for k in [64.0, 256.0, 2000.0] {
        let sig = plate(k);
        let (fast, q) = median_ms(21, || reference_image(&sig, W).expect("ok"));
        let (slow, ss) = median_ms(3, || {
            reference_supersampled(&sig, W, &opts, &cancel).expect("ok")
        });
        println!(
            "{:<8} {:>14.3} {:>16.1} {:>9.0}x {:>12.1e} {:>12.2e} {:>16.2e}",
            k,
            fast,
            slow,
            slow / fast,
            q.error_estimate.expect("bound"),
            ss.error_estimate.expect("estimate"),
            rmse(&q.pixels, &ss.pixels).expect("same size")
        );
    }
}

/// The default scene's reconstruction, the one a slider change waits for: 4096 jittered
/// samples of the default zone plate onto 512², the library's Gaussian (σ = ½, r = 2, edge
/// subtracted), splatted with the Gaussian's one-exponential factors against the exact splat
/// ([`ExactFactors`]: `exp` and `expm1` a factor) in the same run, on one thread (CPU time)
/// and on the global pool (wall), with the largest difference between the two images.
fn bench_slider(c: &mut Criterion) {
    let ids = [
        "slider_recon_4096_to_512/fast factors",
        "slider_recon_4096_to_512/exact factors",
    ];
    let cancel = Cancel::never();
    let mut rng = Rng::new(1);
    let points: Vec<DVec2> = (0..4096)
        .map(|k| {
            let (i, j) = ((k % 64) as f64, (k / 64) as f64);
            DVec2::new((i + rng.next_f64()) / 64.0, (j + rng.next_f64()) / 64.0)
        })
        .collect();
    let values = sample_signal(&Signal::ZonePlate(ZonePlate::default()), &points, &cancel)
        .expect("valid signal");
    let gauss = Filter2D::separable(Filter::Gaussian(Gaussian {
        sigma: 0.5,
        radius: 2.0,
        subtract_edge: true,
    }));
    let exact = ExactFactors(gauss);
    let mut group = c.benchmark_group("slider_recon_4096_to_512");
    group.sample_size(20);
    group.bench_function("fast factors", |b| {
        b.iter(|| black_box(reconstruct_scattered(&points, &values, W, &gauss, &cancel)))
    });
    group.bench_function("exact factors", |b| {
        b.iter(|| black_box(reconstruct_scattered(&points, &values, W, &exact, &cancel)))
    });
    group.finish();
    if !selected(&ids) {
        return;
    }
    let one = pool();
    let (fw, fc) = best_of(&one, 15, || {
        black_box(reconstruct_scattered(&points, &values, W, &gauss, &cancel).expect("ok"));
    });
    let (ew, ec) = best_of(&one, 15, || {
        black_box(reconstruct_scattered(&points, &values, W, &exact, &cancel).expect("ok"));
    });
    let (fp, a) = median_ms(15, || {
        reconstruct_scattered(&points, &values, W, &gauss, &cancel).expect("ok")
    });
    let (ep, b) = median_ms(15, || {
        reconstruct_scattered(&points, &values, W, &exact, &cancel).expect("ok")
    });
    let worst = a
        .pixels
        .iter()
        .zip(&b.pixels)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max);
    let ms = |d: Duration| d.as_secs_f64() * 1e3;
    let cpu = |c: Option<Duration>, w: Duration| ms(c.unwrap_or(w));
    println!();
    println!(
        "slider reconstruction (default scene: 4096 jittered samples, {W}², Gaussian σ ½ r 2): \
         fast factors vs exact, one thread best of 15 (CPU) and {} threads median of 15 (wall)",
        rayon::current_num_threads()
    );
    println!(
        "one thread: fast {:.2} ms CPU, exact {:.2} ms CPU, exact/fast {:.2}x; pool: fast {fp:.2} ms, \
         exact {ep:.2} ms, exact/fast {:.2}x; largest pixel difference {worst:.1e} (bound 1e-13)",
        cpu(fc, fw),
        cpu(ec, ew),
        cpu(ec, ew) / cpu(fc, fw),
        ep / fp
    );
}

criterion_group!(benches, bench, bench_reference, bench_slider);
criterion_main!(benches);
