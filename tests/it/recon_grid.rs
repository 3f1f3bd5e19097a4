//! Uniform grid sampling and resampling: nearest neighbour and bilinear as closed forms, a
//! band-limited grating through Lanczos, and the lecture's zone plate whose outer rings alias.

use crate::recon_kernels::{BoxKernel, LanczosKernel, TentKernel};
use glam::DVec2;
use samplescope::core::cancel::Cancel;
use samplescope::core::recon::{resample_grid, sample_grid, ReconError, Reconstruction};
use samplescope::core::signal::{Grating, Signal, ZonePlate};

fn centre(i: usize, j: usize, w: usize) -> DVec2 {
    DVec2::new((i as f64 + 0.5) / w as f64, (j as f64 + 0.5) / w as f64)
}

#[test]
fn grid_box_half_spacing_is_nearest_neighbour() {
    let sig = Signal::ZonePlate(ZonePlate {
        k: 40.0,
        ..Default::default()
    });
    let (g, w) = (8, 32);
    let c = Cancel::never();
    let (_, values) = sample_grid(&sig, g, &c).unwrap();
    let r = resample_grid(&sig, g, w, &BoxKernel { radius: 0.5 }, &c).unwrap();
    for j in 0..w {
        for i in 0..w {
            // Pixel (i, j) lies in grid cell (i/4, j/4): its value is replicated exactly.
            assert_eq!(r.pixels[j * w + i], values[(j / 4) * g + i / 4]);
        }
    }
}

#[test]
fn grid_tent_is_bilinear_interpolation_inside() {
    let sig = Signal::ZonePlate(ZonePlate {
        k: 30.0,
        ..Default::default()
    });
    let (g, w) = (10, 40);
    let c = Cancel::never();
    let (_, v) = sample_grid(&sig, g, &c).unwrap();
    let r = resample_grid(&sig, g, w, &TentKernel { radius: 1.0 }, &c).unwrap();
    let gf = g as f64;
    for j in 0..w {
        for i in 0..w {
            let p = centre(i, j, w) * gf - DVec2::splat(0.5); // grid coordinates
            if p.x < 0.0 || p.y < 0.0 || p.x >= gf - 1.0 || p.y >= gf - 1.0 {
                continue; // border: only one side of samples, normalised differently
            }
            let (a, b) = (p.x.floor() as usize, p.y.floor() as usize);
            let (fx, fy) = (p.x - a as f64, p.y - b as f64);
            let at = |x: usize, y: usize| v[y * g + x];
            let bilinear = (1.0 - fy) * ((1.0 - fx) * at(a, b) + fx * at(a + 1, b))
                + fy * ((1.0 - fx) * at(a, b + 1) + fx * at(a + 1, b + 1));
            assert!(
                (r.pixels[j * w + i] - bilinear).abs() < 1e-14,
                "pixel ({i},{j})"
            );
        }
    }
}

#[test]
fn band_limited_grating_survives_lanczos_resampling() {
    // 5 cycles/unit on a 32-grid (Nyquist 16): Lanczos-3 passes it with small error away from
    // the border (4 grid spacings); measured 3.0e-3 RMS, tolerance 1e-2.
    let sig = Signal::Grating(Grating {
        frequency: 5.0,
        angle: 20.0,
        phase: 0.0,
    });
    let (g, w) = (32, 128);
    let r = resample_grid(&sig, g, w, &LanczosKernel { a: 3.0 }, &Cancel::never()).unwrap();
    let margin = 4 * w / g;
    let mut sum = 0.0;
    let mut n = 0;
    for j in margin..w - margin {
        for i in margin..w - margin {
            let d = r.pixels[j * w + i] - sig.eval(centre(i, j, w));
            sum += d * d;
            n += 1;
        }
    }
    let e = (sum / n as f64).sqrt();
    eprintln!("lanczos grating rms {e:e}");
    assert!(e < 1e-2, "rms {e:e}");
}

#[test]
fn lecture_zone_plate_outer_rings_alias() {
    // "Sampled at 128×128 and reconstructed to 512×512 using windowed sinc", scaled down by 2:
    // G = 64, W = 256, K = 128 → Nyquist 32 is reached at ρ = G/(2K) = ¼. Inside ρ < 0.12 the
    // rings are "part of the signal" (small error); for 0.3 < ρ < 0.45 they are aliases.
    // Measured: inner RMS 6.4e-3, outer 0.45.
    let sig = Signal::ZonePlate(ZonePlate {
        k: 128.0,
        ..Default::default()
    });
    let (g, w) = (64, 256);
    let r = resample_grid(&sig, g, w, &LanczosKernel { a: 3.0 }, &Cancel::never()).unwrap();
    let (mut inner, mut ni, mut outer, mut no) = (0.0, 0, 0.0, 0);
    for j in 0..w {
        for i in 0..w {
            let p = centre(i, j, w);
            let rho = (p - DVec2::splat(0.5)).length();
            let d = r.pixels[j * w + i] - sig.eval(p);
            if rho < 0.12 {
                inner += d * d;
                ni += 1;
            } else if (0.3..0.45).contains(&rho) {
                outer += d * d;
                no += 1;
            }
        }
    }
    let (inner, outer) = ((inner / ni as f64).sqrt(), (outer / no as f64).sqrt());
    eprintln!("zone plate: inner rms {inner:e}, outer rms {outer:e}");
    assert!(inner < 0.05 && outer > 0.2, "inner {inner}, outer {outer}");
}

#[test]
fn grid_rejects_bad_sizes() {
    let sig = Signal::default();
    let c = Cancel::never();
    let k = TentKernel { radius: 1.0 };
    let e = |r: Result<Reconstruction, ReconError>| match r {
        Err(e) => e.to_string(),
        Ok(_) => panic!("accepted"),
    };
    assert!(
        e(resample_grid(&sig, 0, 16, &k, &c)).starts_with("g = 0: must be an integer in 1..=4096")
    );
    assert!(e(resample_grid(&sig, 4097, 16, &k, &c)).starts_with("g = 4097"));
    assert!(e(resample_grid(&sig, 8, 0, &k, &c)).starts_with("w = 0"));
}
