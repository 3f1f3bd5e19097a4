//! Scattered reconstruction: splatting against the per-pixel gather and a brute-force O(W²N)
//! sum, constants, zero-weight pixels and input errors.

use crate::recon_kernels::{
    BoxKernel, ConeKernel, GaussianKernel, LanczosKernel, NonSeparable, TentKernel,
};
use glam::DVec2;
use samplescope::core::cancel::Cancel;
use samplescope::core::recon::{
    reconstruct_scattered, reconstruct_scattered_gather, reconstruct_scattered_serial,
    sample_signal, ReconError, ReconKernel, Reconstruction, FLOOR_FACTOR, ZERO_WEIGHT_FILL,
};
use samplescope::core::rng::Rng;
use samplescope::core::signal::{Signal, ZonePlate};

fn random_points(n: usize, seed: u64) -> Vec<DVec2> {
    let mut rng = Rng::new(seed);
    (0..n)
        .map(|_| DVec2::new(rng.next_f64(), rng.next_f64()))
        .collect()
}

/// The definition, summed over every sample for every pixel (no range, no buckets): Σw·f/Σw,
/// floored where Σw < c·Σ|w| (c = FLOOR_FACTOR·ρ) towards P = Σ|w|·f/Σ|w| as `core::recon`
/// documents.
fn brute_force<K: ReconKernel>(points: &[DVec2], values: &[f64], w: usize, k: &K) -> Vec<f64> {
    let inv_scale = (points.len() as f64).sqrt() / w as f64;
    let c = FLOOR_FACTOR * k.dc_fraction();
    let mut out = vec![f64::NAN; w * w];
    for j in 0..w {
        for i in 0..w {
            let (mut num, mut den, mut abs, mut num_abs) = (0.0, 0.0, 0.0, 0.0);
            for (p, v) in points.iter().zip(values) {
                let x = *p * w as f64;
                let d = DVec2::new(
                    ((i as f64 + 0.5) - x.x) * inv_scale,
                    ((j as f64 + 0.5) - x.y) * inv_scale,
                );
                let wt = k.weight(d);
                num += wt * v;
                den += wt;
                abs += wt.abs();
                num_abs += wt.abs() * v;
            }
            out[j * w + i] = if abs == 0.0 {
                ZERO_WEIGHT_FILL
            } else if den < c * abs {
                let p = num_abs / abs;
                p + (num - den * p) / (c * abs)
            } else {
                num / den
            };
        }
    }
    out
}

fn max_diff(a: &[f64], b: &[f64]) -> f64 {
    assert_eq!(a.len(), b.len());
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

fn zone_values(points: &[DVec2]) -> Vec<f64> {
    let s = Signal::ZonePlate(ZonePlate {
        k: 60.0,
        ..Default::default()
    });
    sample_signal(&s, points, &Cancel::never()).unwrap()
}

fn check_splat_equals_gather<K: ReconKernel>(kernel: &K, n: usize, w: usize, seed: u64) {
    let points = random_points(n, seed);
    let values = zone_values(&points);
    let c = Cancel::never();
    let splat = reconstruct_scattered(&points, &values, w, kernel, &c).unwrap();
    let gather = reconstruct_scattered_gather(&points, &values, w, kernel, &c).unwrap();
    let brute = brute_force(&points, &values, w, kernel);
    assert_eq!(splat.mask, gather.mask);
    assert_eq!(splat.zero_weight, gather.zero_weight);
    let d = max_diff(&splat.pixels, &gather.pixels);
    assert!(d < 1e-12, "splat vs gather: {d:e}");
    let d = max_diff(&gather.pixels, &brute);
    assert!(d < 1e-12, "gather vs brute force: {d:e}");
    assert!(splat.pixels.iter().all(|v| v.is_finite()));
}

#[test]
fn splat_equals_gather_tent_separable() {
    check_splat_equals_gather(&TentKernel { radius: 1.25 }, 1000, 48, 1);
}

#[test]
fn splat_equals_gather_gaussian_and_lanczos() {
    check_splat_equals_gather(
        &GaussianKernel {
            sigma: 0.5,
            radius: 1.5,
        },
        700,
        40,
        2,
    );
    check_splat_equals_gather(&LanczosKernel { a: 2.0 }, 900, 40, 3);
}

#[test]
fn splat_equals_gather_non_separable_cone() {
    check_splat_equals_gather(&ConeKernel { radius: 1.7 }, 800, 40, 4);
}

#[test]
fn splat_equals_gather_box_with_empty_pixels() {
    // Small box: many pixels receive nothing; masks must agree too.
    check_splat_equals_gather(&BoxKernel { radius: 0.3 }, 200, 50, 5);
}

#[test]
fn splat_equals_gather_wide_support_few_samples() {
    // N = 3: one filter covers most of the image (bucket grid of a single cell).
    check_splat_equals_gather(&TentKernel { radius: 0.9 }, 3, 32, 6);
}

#[test]
fn separable_fast_path_equals_general_path() {
    let points = random_points(600, 7);
    let values = zone_values(&points);
    let c = Cancel::never();
    let k = GaussianKernel {
        sigma: 0.6,
        radius: 2.0,
    };
    let a = reconstruct_scattered(&points, &values, 37, &k, &c).unwrap();
    let b = reconstruct_scattered(&points, &values, 37, &NonSeparable(k), &c).unwrap();
    assert!(max_diff(&a.pixels, &b.pixels) < 1e-15);
}

#[test]
fn splat_on_grid_aligned_samples_at_support_boundary() {
    // Samples on a 16×16 grid, W = 32, box radius ½: every sample is exactly half a pixel from
    // two pixel centres, at distance ½·(32/16)/2 … the open box must treat splat and gather alike.
    let g = 16;
    let points: Vec<DVec2> = (0..g * g)
        .map(|k| DVec2::new((k % g) as f64 / g as f64, (k / g) as f64 / g as f64))
        .collect();
    let values: Vec<f64> = (0..g * g).map(|k| (k % 7) as f64 / 7.0).collect();
    let c = Cancel::never();
    for radius in [0.25, 0.5, 0.75, 1.0] {
        let k = BoxKernel { radius };
        let s = reconstruct_scattered(&points, &values, 32, &k, &c).unwrap();
        let t = reconstruct_scattered_gather(&points, &values, 32, &k, &c).unwrap();
        let b = brute_force(&points, &values, 32, &k);
        assert_eq!(s.mask, t.mask, "radius {radius}");
        assert!(max_diff(&s.pixels, &t.pixels) < 1e-12, "radius {radius}");
        assert!(max_diff(&s.pixels, &b) < 1e-12, "radius {radius}");
    }
}

#[test]
fn constant_signal_reconstructs_exactly() {
    let points = random_points(5000, 8);
    let c = Cancel::never();
    for v in [0.0, 0.3, 1.0] {
        let values = vec![v; points.len()];
        // Supports of 3 spacings: ≥ 28 samples expected under every kernel, so no empty pixel.
        // Σw·v/Σw = v up to the rounding of the two sums, i.e. a few ulps times Σ|w|/|Σw|:
        // 1e-14 for non-negative kernels; the Lanczos lobes cancel (Σ|w|/|Σw| up to ~10³ on
        // random points), hence 1e-11.
        for (k, tol) in [
            (&TentKernel { radius: 3.0 } as &dyn ReconKernel, 1e-14),
            (&LanczosKernel { a: 3.0 }, 1e-11),
            (&ConeKernel { radius: 3.0 }, 1e-14),
        ] {
            let r = reconstruct_scattered(&points, &values, 64, k, &c).unwrap();
            assert_eq!(r.zero_weight, 0);
            let d = r.pixels.iter().map(|p| (p - v).abs()).fold(0.0, f64::max);
            assert!(d < tol, "v = {v}: max deviation {d:e}");
        }
    }
}

fn expected_zero_mask(points: &[DVec2], w: usize, r_px: f64) -> Vec<bool> {
    let mut mask = vec![true; w * w];
    for j in 0..w {
        for i in 0..w {
            let c = DVec2::new(i as f64 + 0.5, j as f64 + 0.5);
            if points.iter().any(|p| {
                let d = c - *p * w as f64;
                d.x.abs() < r_px && d.y.abs() < r_px
            }) {
                mask[j * w + i] = false;
            }
        }
    }
    mask
}

#[test]
fn zero_weight_pixels_reported_when_n_tiny_and_support_small() {
    // N = 4 → spacing ½; box radius 0.1 spacings = 0.05 units = 3.2 px at W = 64.
    let points = vec![
        DVec2::new(0.1, 0.1),
        DVec2::new(0.7, 0.2),
        DVec2::new(0.4, 0.6),
        DVec2::new(0.9, 0.95),
    ];
    let values = vec![0.9, 0.1, 0.7, 0.2];
    let w = 64;
    let k = BoxKernel { radius: 0.1 };
    let c = Cancel::never();
    let expected = expected_zero_mask(&points, w, 0.1 * 0.5 * w as f64);
    let count = expected.iter().filter(|&&m| m).count();
    assert!(count > 3000, "test setup: {count} empty pixels");
    for r in [
        reconstruct_scattered(&points, &values, w, &k, &c).unwrap(),
        reconstruct_scattered_gather(&points, &values, w, &k, &c).unwrap(),
    ] {
        assert_eq!(r.zero_weight, count);
        assert_eq!(r.mask, expected);
        assert!(r.pixels.iter().all(|v| v.is_finite()));
        for (p, m) in r.pixels.iter().zip(&r.mask) {
            if *m {
                assert_eq!(*p, ZERO_WEIGHT_FILL);
            }
        }
    }
}

#[test]
fn scattered_is_deterministic() {
    let points = random_points(2000, 9);
    let values = zone_values(&points);
    let c = Cancel::never();
    let k = TentKernel { radius: 1.0 };
    let a: Reconstruction = reconstruct_scattered(&points, &values, 50, &k, &c).unwrap();
    let b = reconstruct_scattered(&points, &values, 50, &k, &c).unwrap();
    assert!(a
        .pixels
        .iter()
        .zip(&b.pixels)
        .all(|(x, y)| x.to_bits() == y.to_bits()));
    let a = reconstruct_scattered_gather(&points, &values, 50, &k, &c).unwrap();
    let b = reconstruct_scattered_gather(&points, &values, 50, &k, &c).unwrap();
    assert!(a
        .pixels
        .iter()
        .zip(&b.pixels)
        .all(|(x, y)| x.to_bits() == y.to_bits()));
}

#[test]
fn scattered_rejects_bad_input_naming_the_field() {
    let c = Cancel::never();
    let k = TentKernel { radius: 1.0 };
    let pts = random_points(10, 10);
    let vals = vec![0.5; 10];
    let msg = |r: Result<Reconstruction, ReconError>| r.unwrap_err().to_string();
    assert!(msg(reconstruct_scattered(&pts, &vals, 0, &k, &c))
        .starts_with("w = 0: must be an integer in 1..=8192"));
    assert!(msg(reconstruct_scattered(&pts, &vals, 8193, &k, &c)).starts_with("w = 8193"));
    assert!(msg(reconstruct_scattered(&[], &[], 8, &k, &c))
        .starts_with("n = 0: must be an integer in 1..="));
    assert!(msg(reconstruct_scattered(&pts, &vals[..9], 8, &k, &c))
        .starts_with("values has 9 entries but must have 10"));
    let mut bad = vals.clone();
    bad[3] = f64::NAN;
    assert!(msg(reconstruct_scattered(&pts, &bad, 8, &k, &c))
        .starts_with("values[3] = NaN: must be finite"));
    let mut badp = pts.clone();
    badp[2] = DVec2::new(1.5, 0.2);
    assert!(msg(reconstruct_scattered(&badp, &vals, 8, &k, &c))
        .starts_with("points[2] = (1.5, 0.2): must lie in [0,1]²"));
    badp[2] = DVec2::new(f64::INFINITY, 0.2);
    assert!(msg(reconstruct_scattered_gather(&badp, &vals, 8, &k, &c))
        .starts_with("points[2] = inf: must be finite"));
    for radius in [0.0, -1.0, f64::NAN, 65.0] {
        let e = msg(reconstruct_scattered(
            &pts,
            &vals,
            8,
            &TentKernel { radius },
            &c,
        ));
        assert!(e.starts_with("kernel support"), "{e}");
    }
}

#[test]
fn scattered_cancelled_returns_error() {
    let c = Cancel::new();
    c.cancel();
    let pts = random_points(100, 11);
    let vals = vec![0.5; 100];
    let k = TentKernel { radius: 1.0 };
    assert_eq!(
        reconstruct_scattered(&pts, &vals, 16, &k, &c).unwrap_err(),
        ReconError::Cancelled
    );
    assert_eq!(
        reconstruct_scattered_gather(&pts, &vals, 16, &k, &c).unwrap_err(),
        ReconError::Cancelled
    );
    assert_eq!(
        sample_signal(&Signal::default(), &pts, &c).unwrap_err(),
        ReconError::Cancelled
    );
}

#[test]
fn scattered_refuses_too_much_work() {
    // N = 2²⁰, support 64 spacings at W = 8192: 512 px radius, ≈ 2²⁰·1026² ≈ 10¹² taps > 2³⁴.
    let n = 1 << 20;
    let pts = random_points(n, 12);
    let vals = vec![0.5; n];
    let k = TentKernel { radius: 64.0 };
    match reconstruct_scattered(&pts, &vals, 8192, &k, &Cancel::never()) {
        Err(ReconError::TooMuchWork { work, max, .. }) => assert!(work > max),
        Err(e) => panic!("unexpected error {e}"),
        Ok(r) => panic!("accepted {} pixels of work", r.pixels.len()),
    }
}

/// A kernel that returns a fixed (possibly non-finite or huge) weight inside its support.
struct FixedKernel(f64);

impl ReconKernel for FixedKernel {
    fn support(&self) -> f64 {
        1.0
    }
    fn weight(&self, d: DVec2) -> f64 {
        if d.x.abs() < 1.0 && d.y.abs() < 1.0 {
            self.0
        } else {
            0.0
        }
    }
}

#[test]
fn non_finite_kernel_weights_are_reported_not_propagated() {
    let pts = random_points(64, 13);
    let vals = vec![0.5; 64];
    let c = Cancel::never();
    for k in [
        FixedKernel(f64::NAN),
        FixedKernel(f64::INFINITY),
        FixedKernel(1e308),
    ] {
        for r in [
            reconstruct_scattered(&pts, &vals, 16, &k, &c),
            reconstruct_scattered_gather(&pts, &vals, 16, &k, &c),
        ] {
            match r {
                Err(ReconError::NonFiniteWeight { pixel }) => assert!(pixel < 256),
                Err(e) => panic!("unexpected error {e}"),
                Ok(_) => panic!("weight {} accepted", k.0),
            }
        }
    }
}

#[test]
fn banded_parallel_splat_gives_the_serial_loops_bits() {
    // Reference: the serial splat loop (one sample after the other). Every pixel must get
    // the same terms in the same order: identical bits, separable and not, at W not a
    // multiple of the band count, with supports crossing band edges, on 1 and 3 threads.
    let c = Cancel::never();
    for (n, w, seed) in [(4096usize, 512usize, 1u64), (600, 37, 2), (5, 9, 3)] {
        let points = random_points(n, seed);
        let values = zone_values(&points);
        let g = GaussianKernel {
            sigma: 0.6,
            radius: 2.0,
        };
        let serial = reconstruct_scattered_serial(&points, &values, w, &g, &c).unwrap();
        for threads in [1, 3] {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            let par = pool.install(|| reconstruct_scattered(&points, &values, w, &g, &c).unwrap());
            assert!(
                par.pixels
                    .iter()
                    .zip(&serial.pixels)
                    .all(|(a, b)| a.to_bits() == b.to_bits()),
                "separable, n {n}, w {w}, {threads} threads"
            );
            assert_eq!(par.mask, serial.mask);
            let cone = ConeKernel { radius: 1.7 };
            let a = pool.install(|| reconstruct_scattered(&points, &values, w, &cone, &c).unwrap());
            let b = reconstruct_scattered_serial(&points, &values, w, &cone, &c).unwrap();
            assert!(a
                .pixels
                .iter()
                .zip(&b.pixels)
                .all(|(x, y)| x.to_bits() == y.to_bits()));
        }
    }
}

#[test]
fn every_library_filter_splats_in_parallel_with_the_serial_loops_bits() {
    // The parallel separable splat evaluates each sample's factors once and keeps two sums
    // per pixel when no factor is negative (four otherwise): the image, the zero-weight mask
    // and the floored count must be the serial loop's bit for bit, for every filter of the
    // library (with and without negative lobes), several N, W and seeds, and values beyond
    // the two-sum bound (which take the four-sum path).
    use samplescope::core::filter::{Filter, Filter2D};
    let c = Cancel::never();
    let cases = [
        (4096usize, 512usize, 1u64, 1.0),
        (1000, 203, 7, 1.0),
        (64, 96, 3, 1.0),
        (3, 17, 4, 1.0),
        (700, 64, 5, 1e200),
    ];
    for filter in Filter::all() {
        let f = Filter2D::separable(filter);
        for &(n, w, seed, scale) in &cases {
            let points = random_points(n, seed);
            let values: Vec<f64> = zone_values(&points).iter().map(|v| v * scale).collect();
            let serial = reconstruct_scattered_serial(&points, &values, w, &f, &c);
            let par = reconstruct_scattered(&points, &values, w, &f, &c);
            let name = filter.name();
            match (serial, par) {
                (Ok(s), Ok(p)) => {
                    assert!(
                        p.pixels
                            .iter()
                            .zip(&s.pixels)
                            .all(|(a, b)| a.to_bits() == b.to_bits()),
                        "{name}: n {n}, w {w}, values × {scale:e}"
                    );
                    assert_eq!(p.mask, s.mask, "{name}");
                    assert_eq!(
                        (p.zero_weight, p.floored, p.floor),
                        (s.zero_weight, s.floored, s.floor),
                        "{name}"
                    );
                }
                (Err(a), Err(b)) => assert_eq!(a.to_string(), b.to_string(), "{name}"),
                (a, b) => panic!(
                    "{name}: serial {:?} vs parallel {:?}",
                    a.err().map(|e| e.to_string()),
                    b.err().map(|e| e.to_string())
                ),
            }
        }
    }
}
