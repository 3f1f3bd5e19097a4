//! Exact periodograms: the fast phasor-recurrence path against the naive sin/cos reference and
//! against closed forms (one point, two points, a lattice, white-noise expectations).

use glam::DVec2;
use samplescope::core::cancel::Cancel;
use samplescope::core::rng::Rng;
use samplescope::core::spectrum::*;
use std::f64::consts::TAU;

fn uniform(n: usize, seed: u64) -> Vec<DVec2> {
    let mut r = Rng::new(seed);
    (0..n)
        .map(|_| DVec2::new(r.next_f64(), r.next_f64()))
        .collect()
}

/// Largest |a − b| over the grid, relative to the largest |b|.
fn max_rel(a: &Spectrum, b: &Spectrum) -> f64 {
    let scale = b.power.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    a.power
        .iter()
        .zip(&b.power)
        .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()))
        / scale
}

#[test]
fn exact_matches_naive_to_1e_10_relative_even_odd_and_tiny_sizes() {
    let c = Cancel::never();
    for (n, m, seed) in [
        (200usize, 32usize, 1u64),
        (150, 31, 2),
        (7, 2, 3),
        (300, 3, 4),
        (64, 48, 5),
    ] {
        let pts = uniform(n, seed);
        let naive = periodogram_naive(&pts, m).unwrap();
        let fast = periodogram_exact(&pts, m, &c).unwrap();
        let l2 = relative_l2_error(&fast, &naive, false);
        let l2_no_dc = relative_l2_error(&fast, &naive, true);
        assert!(
            l2 <= 1e-10 && l2_no_dc <= 1e-10,
            "n {n} m {m}: {l2:e} {l2_no_dc:e}"
        );
        assert!(max_rel(&fast, &naive) <= 1e-10, "n {n} m {m}");
        assert_eq!((fast.m, fast.n_points, fast.power.len()), (m, n, m * m));
    }
}

#[test]
fn exact_matches_naive_at_the_largest_frequencies() {
    // Long recurrences (M = 512: 513 columns re-anchored every 16 steps) stay accurate.
    let pts = uniform(5, 9);
    let c = Cancel::never();
    let fast = periodogram_exact(&pts, 512, &c).unwrap();
    let naive = periodogram_naive(&pts, 512).unwrap();
    assert!(relative_l2_error(&fast, &naive, true) <= 1e-10);
    assert!(max_rel(&fast, &naive) <= 1e-10);
}

#[test]
fn single_point_has_flat_unit_spectrum() {
    // |e^{−2πi k·x}|² / 1 = 1 for every k.
    let c = Cancel::never();
    for p in [
        DVec2::ZERO,
        DVec2::new(0.123, 0.987),
        DVec2::splat(1.0 - f64::EPSILON / 2.0),
    ] {
        let s = periodogram_exact(&[p], 16, &c).unwrap();
        assert!(s.power.iter().all(|&v| (v - 1.0).abs() < 1e-13), "{p}");
    }
}

#[test]
fn two_points_match_closed_form() {
    // P(k) = |1 + e^{−2πi k·d}|² / 2 = 1 + cos(2π k·d), d = x₁ − x₂.
    let pts = [DVec2::new(0.1, 0.25), DVec2::new(0.7, 0.05)];
    let d = pts[0] - pts[1];
    let s = periodogram_exact(&pts, 20, &Cancel::never()).unwrap();
    for iy in 0..20 {
        for ix in 0..20 {
            let (kx, ky) = (s.frequency(ix) as f64, s.frequency(iy) as f64);
            let expect = 1.0 + (TAU * (kx * d.x + ky * d.y)).cos();
            assert!((s.power[iy * 20 + ix] - expect).abs() < 1e-12);
        }
    }
}

#[test]
fn lattice_spectrum_is_spikes_at_multiples_of_its_size() {
    // N = g² points (i/g, j/g): F(k) = N when g divides kx and ky, else 0; P = N or 0.
    let g = 8;
    let pts: Vec<DVec2> = (0..g * g)
        .map(|i| DVec2::new((i % g) as f64 / g as f64, (i / g) as f64 / g as f64))
        .collect();
    let s = periodogram_exact(&pts, 32, &Cancel::never()).unwrap();
    let n = (g * g) as f64;
    for iy in 0..32 {
        for ix in 0..32 {
            let (kx, ky) = (s.frequency(ix), s.frequency(iy));
            let expect = if kx % g as i64 == 0 && ky % g as i64 == 0 {
                n
            } else {
                0.0
            };
            assert!(
                (s.power[iy * 32 + ix] - expect).abs() < 1e-9,
                "k ({kx}, {ky})"
            );
        }
    }
}

#[test]
fn white_noise_has_unit_mean_and_dc_equal_to_n() {
    // E[P(k)] = 1 for k ≠ 0, Var[P(k)] = 1 − 1/N. Mean over 200 realizations × 255 frequencies
    // (pairs ±k equal: ≈ 25 500 independent values): σ ≈ 0.0063; allow 5σ.
    let c = Cancel::never();
    let (n, m, k) = (64usize, 16usize, 200u64);
    let mut sum = 0.0;
    let mut sum_sq = 0.0;
    let mut count = 0.0;
    for r in 0..k {
        let s = periodogram_exact(&uniform(n, 1000 + r), m, &c).unwrap();
        assert!((s.power[s.dc_index()] - n as f64).abs() < 1e-9);
        for (i, &p) in s.power.iter().enumerate() {
            if i != s.dc_index() {
                sum += p;
                sum_sq += p * p;
                count += 1.0;
            }
        }
    }
    let mean = sum / count;
    let var = sum_sq / count - mean * mean;
    assert!((mean - 1.0).abs() < 0.032, "mean {mean}");
    // Var = 1 − 1/N = 0.984; the sample variance of exponential-like data is noisier: ±0.1.
    assert!((var - (1.0 - 1.0 / n as f64)).abs() < 0.1, "var {var}");
}

#[test]
fn spectrum_is_symmetric_under_k_to_minus_k() {
    let s = periodogram_exact(&uniform(50, 3), 10, &Cancel::never()).unwrap();
    for ky in -4i64..=4 {
        for kx in -4i64..=4 {
            assert_eq!(
                s.at(kx, ky).unwrap().to_bits(),
                s.at(-kx, -ky).unwrap().to_bits()
            );
        }
    }
}

#[test]
fn invalid_size_points_and_empty_set_are_typed_errors() {
    let c = Cancel::never();
    let pts = uniform(4, 1);
    for m in [0usize, 1, 4097] {
        let e = periodogram_exact(&pts, m, &c).unwrap_err();
        assert!(matches!(e, SpectrumError::InvalidSize { .. }));
        assert!(e.to_string().contains("size m") && e.to_string().contains("2..=4096"));
        assert!(matches!(
            periodogram_naive(&pts, m),
            Err(SpectrumError::InvalidSize { .. })
        ));
    }
    assert!(matches!(
        periodogram_exact(&[], 8, &c),
        Err(SpectrumError::EmptyPointSet)
    ));
    for (bad, index) in [
        (
            vec![DVec2::new(0.5, 0.5), DVec2::new(f64::NAN, 0.1)],
            1usize,
        ),
        (vec![DVec2::new(1.0, 0.5)], 0),
        (
            vec![
                DVec2::new(0.2, 0.2),
                DVec2::new(0.2, 0.2),
                DVec2::new(0.3, f64::INFINITY),
            ],
            2,
        ),
        (vec![DVec2::new(-0.25, 0.5)], 0),
    ] {
        let e = periodogram_exact(&bad, 8, &c).unwrap_err();
        assert!(
            matches!(e, SpectrumError::InvalidPoint { index: i, .. } if i == index),
            "{e}"
        );
        assert!(e.to_string().contains(&format!("point {index}")));
    }
}

#[test]
fn cancelled_exact_path_stops() {
    let c = Cancel::new();
    c.cancel();
    assert!(matches!(
        periodogram_exact(&uniform(1000, 1), 64, &c),
        Err(SpectrumError::Cancelled)
    ));
}
