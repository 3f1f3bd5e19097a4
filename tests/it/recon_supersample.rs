//! Supersampling: convergence with spp, the box filter as the plain pixel mean, sharing samples
//! with neighbouring pixels, constants, providers and input errors.

use crate::recon_kernels::{BoxKernel, LanczosKernel, TentKernel};
use glam::DVec2;
use samplescope::core::cancel::Cancel;
use samplescope::core::recon::{
    convergence_curve, supersample, Jittered, ReconError, ReconKernel, Reconstruction,
    SampleProvider, UniformGrid,
};
use samplescope::core::rng::{derive_seed, Rng};
use samplescope::core::signal::{Constant, Polygon, Signal, ZonePlate};

/// An inline jitter provider (independent of the library's): per-pixel stream, k×k strata.
fn inline_jitter(
    seed: u64,
) -> impl Fn(u64, usize, &mut Vec<DVec2>) -> Result<(), ReconError> + Sync {
    move |pixel, spp, out| {
        let k = (spp as f64).sqrt() as usize;
        assert_eq!(k * k, spp, "inline jitter wants square spp");
        let mut rng = Rng::new(derive_seed(seed, pixel));
        for b in 0..k {
            for a in 0..k {
                out.push(DVec2::new(
                    (a as f64 + rng.next_f64()) / k as f64,
                    (b as f64 + rng.next_f64()) / k as f64,
                ));
            }
        }
        Ok(())
    }
}

#[test]
fn jittered_supersampling_error_decreases_with_spp() {
    // Slanted square (exact area reference), box pixel filter: jittered error ∝ spp^(−3/4) at
    // edges (factor 0.35 per ×4). Fixed seed; require a drop of at least 30% per step.
    let sig = Signal::Polygon(Polygon::default());
    let c = Cancel::never();
    let k = BoxKernel { radius: 0.5 };
    for provider in [
        &inline_jitter(1) as &dyn SampleProvider,
        &Jittered { seed: 1 },
    ] {
        let curve = convergence_curve(&sig, provider, &[1, 4, 16, 64], 32, &k, &c).unwrap();
        assert_eq!(curve.reference_error, None);
        let e: Vec<f64> = curve.points.iter().map(|p| p.rmse).collect();
        eprintln!("rmse over spp 1, 4, 16, 64: {e:?}");
        for w in e.windows(2) {
            assert!(w[1] < 0.7 * w[0], "not decreasing: {e:?}");
        }
        // Log–log slope over 1 → 64 between −1 and −0.5 (theory −0.75).
        let slope = (e[3] / e[0]).ln() / 64f64.ln();
        assert!((-1.0..-0.5).contains(&slope), "slope {slope}, {e:?}");
        for p in &curve.points {
            assert!((p.psnr + 20.0 * p.rmse.log10()).abs() < 1e-9);
        }
    }
}

#[test]
fn box_half_pixel_is_the_plain_mean_of_the_pixel_samples() {
    let sig = Signal::ZonePlate(ZonePlate {
        k: 150.0,
        ..Default::default()
    });
    let (w, spp) = (20, 9);
    let prov = inline_jitter(5);
    let r = supersample(
        &sig,
        w,
        spp,
        &prov,
        &BoxKernel { radius: 0.5 },
        &Cancel::never(),
    )
    .unwrap();
    let mut buf = Vec::new();
    for j in 0..w {
        for i in 0..w {
            buf.clear();
            prov((j * w + i) as u64, spp, &mut buf).unwrap();
            let mean = buf
                .iter()
                .map(|u| {
                    sig.eval(DVec2::new(
                        (i as f64 + u.x) / w as f64,
                        (j as f64 + u.y) / w as f64,
                    ))
                })
                .sum::<f64>()
                / spp as f64;
            assert!(
                (r.pixels[j * w + i] - mean).abs() < 1e-14,
                "pixel ({i},{j})"
            );
        }
    }
}

#[test]
fn wide_pixel_filter_gathers_neighbouring_pixels_samples() {
    // Brute force: every sample of every pixel, weighted by the kernel at (sample − centre)·W.
    let sig = Signal::ZonePlate(ZonePlate {
        k: 90.0,
        ..Default::default()
    });
    let (w, spp) = (14, 4);
    let prov = Jittered { seed: 9 };
    let c = Cancel::never();
    for k in [
        &TentKernel { radius: 1.5 } as &dyn ReconKernel,
        &LanczosKernel { a: 2.0 },
    ] {
        let r = supersample(&sig, w, spp, &prov, k, &c).unwrap();
        let mut samples = Vec::new();
        let mut buf = Vec::new();
        for p in 0..w * w {
            buf.clear();
            prov.offsets(p as u64, spp, &mut buf).unwrap();
            for u in &buf {
                let x = DVec2::new((p % w) as f64 + u.x, (p / w) as f64 + u.y);
                samples.push((x, sig.eval(x / w as f64)));
            }
        }
        for j in 0..w {
            for i in 0..w {
                let ctr = DVec2::new(i as f64 + 0.5, j as f64 + 0.5);
                let (mut num, mut den) = (0.0, 0.0);
                for (x, v) in &samples {
                    let wt = k.weight(ctr - *x);
                    num += wt * v;
                    den += wt;
                }
                let got = r.pixels[j * w + i];
                assert!(
                    (got - num / den).abs() < 1e-12,
                    "pixel ({i},{j}): {got} vs {}",
                    num / den
                );
            }
        }
    }
}

#[test]
fn constant_signal_supersamples_exactly() {
    let sig = Signal::Constant(Constant { value: 0.37 });
    let c = Cancel::never();
    for k in [
        &BoxKernel { radius: 0.5 } as &dyn ReconKernel,
        &TentKernel { radius: 2.0 },
    ] {
        let r = supersample(&sig, 16, 16, &Jittered { seed: 2 }, k, &c).unwrap();
        assert_eq!(r.zero_weight, 0);
        let d = r
            .pixels
            .iter()
            .map(|p| (p - 0.37).abs())
            .fold(0.0, f64::max);
        assert!(d < 1e-15, "max deviation {d:e}");
    }
}

#[test]
fn uniform_grid_spp1_is_point_sampling_at_centres() {
    let sig = Signal::ZonePlate(ZonePlate::default());
    let w = 24;
    let r = supersample(
        &sig,
        w,
        1,
        &UniformGrid,
        &BoxKernel { radius: 0.5 },
        &Cancel::never(),
    )
    .unwrap();
    for j in 0..w {
        for i in 0..w {
            let c = DVec2::new((i as f64 + 0.5) / w as f64, (j as f64 + 0.5) / w as f64);
            assert_eq!(r.pixels[j * w + i], sig.eval(c));
        }
    }
    assert_eq!(r.samples, w * w);
}

#[test]
fn supersample_deterministic_and_thread_count_independent() {
    let sig = Signal::ZonePlate(ZonePlate::default());
    let k = TentKernel { radius: 1.0 };
    let c = Cancel::never();
    let run = || supersample(&sig, 32, 4, &Jittered { seed: 11 }, &k, &c).unwrap();
    let a = run();
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap();
    let b = pool.install(run);
    assert!(a
        .pixels
        .iter()
        .zip(&b.pixels)
        .all(|(x, y)| x.to_bits() == y.to_bits()));
}

fn err(r: Result<Reconstruction, ReconError>) -> ReconError {
    match r {
        Err(e) => e,
        Ok(_) => panic!("accepted"),
    }
}

#[test]
fn supersample_rejects_bad_input_and_bad_providers() {
    let sig = Signal::default();
    let k = BoxKernel { radius: 0.5 };
    let c = Cancel::never();
    let j = Jittered { seed: 0 };
    assert!(err(supersample(&sig, 0, 4, &j, &k, &c))
        .to_string()
        .starts_with("w = 0: must be an integer in 1..=8192"));
    assert!(err(supersample(&sig, 8, 0, &j, &k, &c))
        .to_string()
        .starts_with("spp = 0: must be an integer in 1..=4096"));
    assert!(err(supersample(&sig, 8, 4097, &j, &k, &c))
        .to_string()
        .starts_with("spp = 4097"));
    let e = err(supersample(&sig, 8, 3, &UniformGrid, &k, &c));
    assert!(matches!(e, ReconError::ProviderSpp { spp: 3, .. }), "{e}");
    let short = |_: u64, _: usize, out: &mut Vec<DVec2>| {
        out.push(DVec2::splat(0.5));
        Ok(())
    };
    let e = err(supersample(&sig, 8, 2, &short, &k, &c));
    assert!(
        matches!(e, ReconError::ProviderCount { got: 1, spp: 2, .. }),
        "{e}"
    );
    let outside = |_: u64, spp: usize, out: &mut Vec<DVec2>| {
        out.extend(std::iter::repeat_n(DVec2::new(1.0, 0.5), spp));
        Ok(())
    };
    let e = err(supersample(&sig, 8, 2, &outside, &k, &c));
    assert!(e.to_string().contains("must lie in [0,1)²"), "{e}");
    let bad = Signal::ZonePlate(ZonePlate {
        cx: f64::NAN,
        ..Default::default()
    });
    assert!(err(supersample(&bad, 8, 1, &j, &k, &c))
        .to_string()
        .starts_with("zone-plate.cx = NaN"));
    let cancelled = Cancel::new();
    cancelled.cancel();
    assert_eq!(
        err(supersample(&sig, 8, 1, &j, &k, &cancelled)),
        ReconError::Cancelled
    );
    // 8192² pixels × 4096 spp is far beyond the work limit.
    let e = err(supersample(&sig, 8192, 4096, &j, &k, &c));
    assert!(matches!(e, ReconError::TooMuchWork { .. }), "{e}");
}

#[test]
fn checkerboard_point_sampling_aliases_towards_the_horizon() {
    // Duff's checkerboard: point sampling is fine near the viewer and aliases (moiré) towards
    // the horizon; 16 jittered samples per pixel reduce the horizon error.
    use samplescope::core::recon::{reference_image, ReferenceMethod};
    use samplescope::core::signal::Checkerboard;
    let sig = Signal::Checkerboard(Checkerboard::default());
    let w = 64;
    let reference = reference_image(&sig, w).unwrap();
    assert!(matches!(
        reference.method,
        ReferenceMethod::Supersampled { .. }
    ));
    let est = reference
        .error_estimate
        .expect("supersampled reference has an estimate");
    let c = Cancel::never();
    let k = BoxKernel { radius: 0.5 };
    let band_rms = |img: &[f64], y0: f64, y1: f64| {
        let (mut s, mut n) = (0.0, 0);
        for j in 0..w {
            let y = (j as f64 + 0.5) / w as f64;
            if (y0..y1).contains(&y) {
                for i in 0..w {
                    let d = img[j * w + i] - reference.pixels[j * w + i];
                    s += d * d;
                    n += 1;
                }
            }
        }
        (s / n as f64).sqrt()
    };
    let point = supersample(&sig, w, 1, &UniformGrid, &k, &c).unwrap();
    let near_horizon = band_rms(&point.pixels, 0.27, 0.4);
    let near_viewer = band_rms(&point.pixels, 0.8, 1.0);
    let jit = supersample(&sig, w, 16, &Jittered { seed: 3 }, &k, &c).unwrap();
    let jit_horizon = band_rms(&jit.pixels, 0.27, 0.4);
    eprintln!(
        "checkerboard: reference estimate {est:e}; point sampling rms near horizon {near_horizon:.3}, near viewer {near_viewer:.3}; 16 jittered near horizon {jit_horizon:.3}"
    );
    assert!(near_horizon > 2.0 * near_viewer);
    assert!(jit_horizon < 0.5 * near_horizon);
    // Measured: estimate 0.026, point 0.485 / 0.140, jittered 0.120: the reference is good
    // enough to judge both.
    assert!(est < 0.5 * jit_horizon);
}

#[test]
fn supersample_stops_when_cancelled_mid_flight() {
    // The provider cancels the token at pixel 100 of 256×256: the computation must stop with
    // Cancelled instead of finishing (checks happen every ~2¹⁴ samples).
    let token = Cancel::new();
    let t = token.clone();
    let calls = std::sync::atomic::AtomicUsize::new(0);
    let prov = |pixel: u64, spp: usize, out: &mut Vec<DVec2>| {
        calls.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        if pixel == 100 {
            t.cancel();
        }
        out.extend(std::iter::repeat_n(DVec2::splat(0.5), spp));
        Ok(())
    };
    let sig = Signal::default();
    let r = supersample(&sig, 256, 16, &prov, &BoxKernel { radius: 0.5 }, &token);
    assert_eq!(err(r), ReconError::Cancelled);
    let n = calls.load(std::sync::atomic::Ordering::Relaxed);
    assert!(n < 256 * 256, "provider called for every pixel ({n})");
}
