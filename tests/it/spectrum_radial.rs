//! RAPS and anisotropy against a naive loop and on synthetic spectra with known statistics.

use glam::DVec2;
use samplescope::core::cancel::Cancel;
use samplescope::core::rng::Rng;
use samplescope::core::spectrum::*;
use std::convert::Infallible;

fn spectrum(m: usize, power: Vec<f64>) -> Spectrum {
    Spectrum {
        m,
        power,
        n_points: 1,
        realizations: 1,
        dc: DcMode::Show,
    }
}

fn uniform(n: usize, seed: u64) -> Vec<DVec2> {
    let mut r = Rng::new(seed);
    (0..n)
        .map(|_| DVec2::new(r.next_f64(), r.next_f64()))
        .collect()
}

/// Naive reference: for every annulus, scan the grid for b − ½ ≤ |k| < b + ½ (hypot in f64),
/// then mean and population variance in one pass each.
fn naive(s: &Spectrum) -> Vec<(f64, f64, usize, f64)> {
    let m = s.m as i64;
    let lo = -(m / 2);
    let b_max = if m % 2 == 0 { m / 2 - 1 } else { (m - 1) / 2 };
    (1..=b_max)
        .map(|b| {
            let mut v = Vec::new();
            for ky in lo..lo + m {
                for kx in lo..lo + m {
                    let r = (kx as f64).hypot(ky as f64);
                    if r >= b as f64 - 0.5 && r < b as f64 + 0.5 {
                        v.push(s.at(kx, ky).unwrap());
                    }
                }
            }
            let mean = v.iter().sum::<f64>() / v.len() as f64;
            let var = v.iter().map(|p| (p - mean).powi(2)).sum::<f64>() / v.len() as f64;
            (
                b as f64,
                mean,
                v.len(),
                10.0 * (var / (mean * mean)).log10(),
            )
        })
        .collect()
}

fn exponential_spectrum(m: usize, k: usize, seed: u64) -> Spectrum {
    // Mean of k i.i.d. Exp(1) values per frequency: var/mean² = 1/k.
    let mut r = Rng::new(seed);
    let power = (0..m * m)
        .map(|_| (0..k).map(|_| -(1.0 - r.next_f64()).ln()).sum::<f64>() / k as f64)
        .collect();
    spectrum(m, power)
}

#[test]
fn raps_and_anisotropy_match_naive_loop_even_and_odd() {
    for (m, seed) in [(64usize, 1u64), (33, 2), (4, 3), (5, 4)] {
        let s = exponential_spectrum(m, 1, seed);
        let got = radial_average(&s).unwrap();
        let want = naive(&s);
        assert_eq!(got.len(), want.len(), "m {m}");
        for (g, w) in got.iter().zip(&want) {
            assert_eq!((g.radius, g.count), (w.0, w.2), "m {m}");
            assert!((g.mean_power - w.1).abs() <= 1e-12 * w.1, "m {m} b {}", w.0);
            assert!((g.anisotropy_db - w.3).abs() <= 1e-9, "m {m} b {}", w.0);
        }
    }
}

#[test]
fn only_complete_annuli_and_dc_excluded() {
    assert!(radial_average(&spectrum(2, vec![1.0; 4]))
        .unwrap()
        .is_empty());
    assert!(radial_average(&spectrum(3, vec![1.0; 9])).unwrap().len() == 1);
    let bins = radial_average(&spectrum(256, vec![1.0; 256 * 256])).unwrap();
    assert_eq!(bins.len(), 127);
    assert_eq!(bins.last().unwrap().radius, 127.0);
    // Annulus 1: |k|² ∈ {1, 2}: 4 + 4 frequencies.
    assert_eq!(bins[0].count, 8);
    // Total count = lattice points with ½ ≤ |k| < 127.5.
    let total: usize = bins.iter().map(|b| b.count).sum();
    let mut expect = 0;
    for ky in -128i64..128 {
        for kx in -128i64..128 {
            let r2 = (kx * kx + ky * ky) as f64;
            if (0.25..127.5 * 127.5).contains(&r2) {
                expect += 1;
            }
        }
    }
    assert_eq!(total, expect);
    // A huge DC changes nothing.
    let mut p = vec![2.0; 16 * 16];
    p[8 * 16 + 8] = 1e12;
    assert!(radial_average(&spectrum(16, p))
        .unwrap()
        .iter()
        .all(|b| b.mean_power == 2.0));
}

#[test]
fn constant_spectrum_has_minus_infinity_anisotropy() {
    let bins = radial_average(&spectrum(32, vec![3.0; 32 * 32])).unwrap();
    for b in bins {
        assert_eq!(b.mean_power, 3.0);
        assert_eq!(b.anisotropy_db, f64::NEG_INFINITY);
    }
}

#[test]
fn zero_annulus_has_nan_anisotropy() {
    // P = 0 exactly on annulus 3 (|k| ∈ [2.5, 3.5)), 1 elsewhere: mean 0, 0/0 → NaN.
    let m = 16i64;
    let power = (0..m * m)
        .map(|i| {
            let (kx, ky) = (i % m - 8, i / m - 8);
            let r = ((kx * kx + ky * ky) as f64).sqrt();
            if (2.5..3.5).contains(&r) {
                0.0
            } else {
                1.0
            }
        })
        .collect();
    let bins = radial_average(&spectrum(16, power)).unwrap();
    assert_eq!(bins[2].mean_power, 0.0);
    assert!(bins[2].anisotropy_db.is_nan());
    assert_eq!(bins[1].anisotropy_db, f64::NEG_INFINITY);
}

#[test]
fn lattice_spikes_land_in_their_annulus() {
    // 8×8 lattice on 32²: P = 64 at multiples of 8, 0 (to rounding) elsewhere. Annulus 8 holds
    // the four spikes (±8, 0), (0, ±8); annulus 11 holds (±8, ±8) (|k| = 11.3).
    let pts: Vec<DVec2> = (0..64)
        .map(|i| DVec2::new((i % 8) as f64 / 8.0, (i / 8) as f64 / 8.0))
        .collect();
    let s = periodogram_exact(&pts, 32, &Cancel::never()).unwrap();
    let bins = radial_average(&s).unwrap();
    for b in [7usize, 10] {
        assert!(
            (bins[b].mean_power - 4.0 * 64.0 / bins[b].count as f64).abs() < 1e-9,
            "annulus {}",
            b + 1
        );
        // Four spikes of 64 among `count` values: var/mean² = count/4 − 1.
        let expect = 10.0 * (bins[b].count as f64 / 4.0 - 1.0).log10();
        assert!((bins[b].anisotropy_db - expect).abs() < 1e-6);
    }
    assert!(bins[2].mean_power < 1e-20);
}

#[test]
fn exponential_spectrum_anisotropy_is_zero_db_and_minus_10_log_k_for_k_averages() {
    // Var/mean² of Exp(1) is 1 (0 dB); of the mean of K values 1/K (−10·log10 K dB).
    // Averaged over annuli 20..=120 (≈ 100 annuli of ≥ 125 values, each ±1 dB): ±0.3 dB.
    for (k, expect) in [(1usize, 0.0f64), (16, -10.0 * 16f64.log10())] {
        let s = exponential_spectrum(256, k, 7);
        let bins = radial_average(&s).unwrap();
        let sel: Vec<&RadialBin> = bins
            .iter()
            .filter(|b| b.radius >= 20.0 && b.radius <= 120.0)
            .collect();
        let mean_db = sel.iter().map(|b| b.anisotropy_db).sum::<f64>() / sel.len() as f64;
        assert!(
            (mean_db - expect).abs() < 0.3,
            "K {k}: {mean_db} dB vs {expect} dB"
        );
        let mean_p = sel.iter().map(|b| b.mean_power).sum::<f64>() / sel.len() as f64;
        assert!((mean_p - 1.0).abs() < 0.02);
    }
}

#[test]
fn white_noise_periodogram_raps_is_one_and_anisotropy_matches_k() {
    // K = 16 realizations of 1024 uniform points on 128²: RAPS ≈ 1, anisotropy ≈ −12 dB.
    // P(k) = P(−k) duplicates every value, halving the effective count: ±0.5 dB on average.
    let req = SpectrumRequest {
        size: 128,
        method: Method::Nufft { tolerance: 1e-3 },
        realizations: 16,
        dc: DcMode::Show,
        error_check_budget: 0,
    };
    let (s, _) = average_periodogram(
        &req,
        11,
        |seed| Ok::<_, Infallible>(uniform(1024, seed)),
        &Cancel::never(),
    )
    .unwrap();
    let bins = radial_average(&s).unwrap();
    let sel: Vec<&RadialBin> = bins.iter().filter(|b| b.radius >= 10.0).collect();
    let mean_p = sel.iter().map(|b| b.mean_power).sum::<f64>() / sel.len() as f64;
    let mean_db = sel.iter().map(|b| b.anisotropy_db).sum::<f64>() / sel.len() as f64;
    assert!((mean_p - 1.0).abs() < 0.03, "RAPS {mean_p}");
    assert!(
        (mean_db + 10.0 * 16f64.log10()).abs() < 0.5,
        "anisotropy {mean_db} dB"
    );
}

#[test]
fn inconsistent_hand_built_spectrum_is_a_typed_error() {
    let e = radial_average(&spectrum(8, vec![1.0; 63])).unwrap_err();
    assert!(matches!(
        e,
        SpectrumError::InvalidParam { field: "power", .. }
    ));
    assert!(matches!(
        radial_average(&spectrum(1, vec![1.0])),
        Err(SpectrumError::InvalidSize { .. })
    ));
}
