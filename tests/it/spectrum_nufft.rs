//! NUFFT periodograms against the exact DFT: the relative ℓ2 error of P (DC excluded, and
//! also with DC) must not exceed the requested tolerance, for every tolerance in the
//! allowed range, on the edge cases named in the test names. Fixed seeds.

use glam::DVec2;
use samplescope::core::cancel::Cancel;
use samplescope::core::rng::Rng;
use samplescope::core::spectrum::*;

const TOLERANCES: [f64; 7] = [1e-2, 3e-3, 1e-3, 1e-6, 1e-9, 1e-11, 1e-12];
const ONE_MINUS_ULP: f64 = 1.0 - f64::EPSILON / 2.0;

fn uniform(n: usize, seed: u64) -> Vec<DVec2> {
    let mut r = Rng::new(seed);
    (0..n)
        .map(|_| DVec2::new(r.next_f64(), r.next_f64()))
        .collect()
}

fn lattice(g: usize, offset: f64) -> Vec<DVec2> {
    (0..g * g)
        .map(|i| {
            DVec2::new(
                ((i % g) as f64 + offset) / g as f64,
                ((i / g) as f64 + offset) / g as f64,
            )
        })
        .collect()
}

/// Asserts error ≤ tolerance for every tolerance, against the exact periodogram.
fn check_all_tolerances(name: &str, points: &[DVec2], m: usize) {
    let c = Cancel::never();
    let exact = periodogram_exact(points, m, &c).unwrap();
    for tol in TOLERANCES {
        let s = periodogram_nufft(points, m, tol, &c).unwrap();
        let err = relative_l2_error(&s, &exact, true);
        let err_dc = relative_l2_error(&s, &exact, false);
        assert!(
            err <= tol,
            "{name}: m {m} tolerance {tol:e}: error {err:e} (DC excluded)"
        );
        assert!(
            err_dc <= tol,
            "{name}: m {m} tolerance {tol:e}: error {err_dc:e} (DC included)"
        );
        assert_eq!((s.m, s.n_points), (m, points.len()));
    }
}

#[test]
fn one_point_meets_tolerance() {
    check_all_tolerances("n=1", &uniform(1, 1), 64);
}

#[test]
fn two_points_meet_tolerance() {
    check_all_tolerances("n=2", &uniform(2, 2), 64);
}

#[test]
fn hundred_points_meet_tolerance() {
    check_all_tolerances("n=100", &uniform(100, 3), 128);
}

#[test]
fn n_4096_points_meet_tolerance() {
    check_all_tolerances("n=4096", &uniform(4096, 4), 64);
}

#[test]
fn n_65536_points_meet_tolerance_on_64_squared() {
    // Several slabs in parallel; the exact reference is 65 536 · 33 · 65 multiply-adds.
    let pts = uniform(65_536, 5);
    let c = Cancel::never();
    let exact = periodogram_exact(&pts, 64, &c).unwrap();
    for tol in [1e-2, 1e-6, 1e-12] {
        let s = periodogram_nufft(&pts, 64, tol, &c).unwrap();
        let err = relative_l2_error(&s, &exact, true);
        assert!(err <= tol, "tolerance {tol:e}: error {err:e}");
    }
}

#[test]
fn n_65536_points_meet_tolerance_on_rows_of_a_256_grid() {
    // Larger grid, exact reference on 6 rows only (subset of frequencies).
    let pts = uniform(65_536, 6);
    let c = Cancel::never();
    let m = 256;
    let k0 = -(m as i64) / 2;
    let rows = [-128i64, -77, -3, 1, 64, 127];
    let field = exact_field_rows(&pts, k0, m, &rows, &c).unwrap();
    for tol in [1e-3, 1e-9] {
        let s = periodogram_nufft(&pts, m, tol, &c).unwrap();
        let (mut num, mut den) = (0.0f64, 0.0f64);
        for (r, &ky) in rows.iter().enumerate() {
            for ix in 0..m {
                let (re, im) = (field[r * 2 * m + ix], field[r * 2 * m + m + ix]);
                let exact = (re * re + im * im) / pts.len() as f64;
                let d = s.at(k0 + ix as i64, ky).unwrap() - exact;
                num += d * d;
                den += exact * exact;
            }
        }
        let err = (num / den).sqrt();
        assert!(err <= tol, "tolerance {tol:e}: error {err:e}");
    }
}

#[test]
fn points_at_exactly_zero_meet_tolerance() {
    let mut pts = vec![DVec2::ZERO, DVec2::new(0.0, 0.4), DVec2::new(0.6, 0.0)];
    pts.extend(uniform(20, 7));
    check_all_tolerances("zero", &pts, 64);
    check_all_tolerances("only zero", &[DVec2::ZERO], 32);
}

#[test]
fn points_at_one_minus_ulp_meet_tolerance() {
    let mut pts = vec![
        DVec2::splat(ONE_MINUS_ULP),
        DVec2::new(ONE_MINUS_ULP, 0.3),
        DVec2::new(0.0, ONE_MINUS_ULP),
    ];
    pts.extend(uniform(20, 8));
    check_all_tolerances("one minus ulp", &pts, 64);
    // Odd size, upsampled grid not a power of two.
    check_all_tolerances("one minus ulp, m 45", &pts, 45);
}

#[test]
fn duplicated_points_meet_tolerance() {
    let base = uniform(50, 9);
    let mut pts = base.clone();
    pts.extend(base.iter().copied());
    pts.extend(base);
    check_all_tolerances("each point three times", &pts, 64);
    check_all_tolerances("one point seven times", &[DVec2::new(0.3, 0.6); 7], 64);
}

#[test]
fn grid_aligned_points_meet_tolerance() {
    // (i/64, j/64) on 128²: the upsampled grid has 256 cells, so every point sits exactly on a
    // grid node (the kernel's first tap at z = −1). The worst case of the tolerance rule.
    check_all_tolerances("lattice on nodes", &lattice(64, 0.0), 128);
    check_all_tolerances("lattice at cell centres", &lattice(32, 0.5), 64);
    check_all_tolerances("lattice 30", &lattice(30, 0.25), 60);
}

#[test]
fn tiny_sizes_meet_tolerance() {
    // m = 2 → n = 4 and m = 3 → n = 6 cells: the kernel (up to 15 cells) wraps several times.
    let pts = uniform(10, 10);
    check_all_tolerances("m 2", &pts, 2);
    check_all_tolerances("m 3", &pts, 3);
    check_all_tolerances("m 5", &pts, 5);
}

#[test]
fn nominal_width_is_not_enough_for_the_periodogram() {
    // Barnett et al.'s w = ⌈log10(1/ε)⌉ + 1 (here 7 for 1e-6) bounds F's error, not that of
    // P = |F|²/N on grid-aligned points: this is why kernel_params adds 2.
    let pts = lattice(64, 0.0);
    let c = Cancel::never();
    let exact = periodogram_exact(&pts, 128, &c).unwrap();
    let nominal = NufftPlan::with_kernel(
        128,
        KernelParams {
            width: 7,
            beta: 2.30 * 7.0,
        },
    )
    .unwrap();
    let err = relative_l2_error(&nominal.periodogram(&pts, &c).unwrap(), &exact, true);
    assert!(err > 1e-6, "nominal width already meets 1e-6: {err:e}");
    let rule = NufftPlan::new(128, 1e-6).unwrap();
    assert_eq!(rule.kernel().width, 9);
    assert!(relative_l2_error(&rule.periodogram(&pts, &c).unwrap(), &exact, true) <= 1e-6);
}

#[test]
fn same_bits_on_one_and_two_threads_and_on_reuse() {
    // 8192 points → 4 slabs spread in parallel; results must not depend on the thread count.
    let pts = uniform(8192, 11);
    let c = Cancel::never();
    let plan = NufftPlan::new(96, 1e-9).unwrap();
    let one = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap();
    let two = rayon::ThreadPoolBuilder::new()
        .num_threads(2)
        .build()
        .unwrap();
    let a = one.install(|| plan.periodogram(&pts, &c).unwrap());
    let b = two.install(|| plan.periodogram(&pts, &c).unwrap());
    let again = plan.periodogram(&pts, &c).unwrap();
    let fresh = periodogram_nufft(&pts, 96, 1e-9, &c).unwrap();
    for s in [&b, &again, &fresh] {
        assert!(a
            .power
            .iter()
            .zip(&s.power)
            .all(|(x, y)| x.to_bits() == y.to_bits()));
    }
}

#[test]
fn spectrum_is_symmetric_bit_for_bit() {
    let s = periodogram_nufft(&uniform(300, 12), 33, 1e-6, &Cancel::never()).unwrap();
    for ky in -16i64..=16 {
        for kx in -16i64..=16 {
            assert_eq!(
                s.at(kx, ky).unwrap().to_bits(),
                s.at(-kx, -ky).unwrap().to_bits()
            );
        }
    }
    let e = periodogram_nufft(&uniform(300, 12), 32, 1e-6, &Cancel::never()).unwrap();
    for kx in -15i64..=15 {
        for ky in [-7i64, 0, 7] {
            assert_eq!(
                e.at(kx, ky).unwrap().to_bits(),
                e.at(-kx, -ky).unwrap().to_bits()
            );
        }
    }
}

#[test]
fn dc_equals_number_of_points() {
    let s = periodogram_nufft(&uniform(1000, 13), 64, 1e-9, &Cancel::never()).unwrap();
    assert!((s.power[s.dc_index()] - 1000.0).abs() < 1e-9 * 1000.0);
}

#[test]
fn tolerance_out_of_range_or_nan_is_a_typed_error_naming_tolerance() {
    let pts = uniform(3, 1);
    let c = Cancel::never();
    for bad in [
        f64::NAN,
        0.0,
        1e-13,
        0.0101,
        0.5,
        -1e-6,
        f64::INFINITY,
        f64::NEG_INFINITY,
    ] {
        let e = periodogram_nufft(&pts, 16, bad, &c).unwrap_err();
        assert!(matches!(e, SpectrumError::InvalidTolerance { .. }), "{bad}");
        let msg = e.to_string();
        assert!(
            msg.contains("tolerance") && msg.contains("[1e-12, 1e-2]"),
            "{msg}"
        );
    }
    assert!(periodogram_nufft(&pts, 16, 1e-12, &c).is_ok());
    assert!(periodogram_nufft(&pts, 16, 1e-2, &c).is_ok());
}

#[test]
fn invalid_points_size_and_empty_set_are_typed_errors() {
    let c = Cancel::never();
    assert!(matches!(
        periodogram_nufft(&[], 16, 1e-3, &c),
        Err(SpectrumError::EmptyPointSet)
    ));
    assert!(matches!(
        periodogram_nufft(&[DVec2::new(0.5, 1.0)], 16, 1e-3, &c),
        Err(SpectrumError::InvalidPoint { index: 0, .. })
    ));
    assert!(matches!(
        periodogram_nufft(&[DVec2::ZERO], 1, 1e-3, &c),
        Err(SpectrumError::InvalidSize { m: 1, .. })
    ));
}

#[test]
fn cancelled_nufft_stops() {
    let c = Cancel::new();
    c.cancel();
    assert!(matches!(
        periodogram_nufft(&uniform(5000, 1), 64, 1e-6, &c),
        Err(SpectrumError::Cancelled)
    ));
    // The plan stays usable after a cancelled call.
    let plan = NufftPlan::new(32, 1e-6).unwrap();
    assert!(plan.periodogram(&uniform(5000, 1), &c).is_err());
    let ok = plan.periodogram(&uniform(50, 2), &Cancel::never()).unwrap();
    let exact = periodogram_exact(&uniform(50, 2), 32, &Cancel::never()).unwrap();
    assert!(relative_l2_error(&ok, &exact, true) <= 1e-6);
}
