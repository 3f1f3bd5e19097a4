//! L2-star discrepancy: the O(N log N) Warnock evaluation against the literal O(N²) formula
//! and against direct numerical integration of the squared local discrepancy.

use crate::metrics_common;

use glam::DVec2;
use metrics_common::{hammersley2, random, sobol};
use samplescope::core::cancel::Cancel;
use samplescope::core::metrics::{l2_star_discrepancy, l2_star_discrepancy_naive, MetricsError};
use samplescope::core::rng::Rng;

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs().max(f64::MIN_POSITIVE)
}

fn compare(points: &[DVec2]) -> f64 {
    let c = Cancel::never();
    let fast = l2_star_discrepancy(points, &c).unwrap();
    let naive = l2_star_discrepancy_naive(points, &c).unwrap();
    assert!(
        rel(fast, naive) <= 1e-12,
        "n = {}: fast {fast:e} vs naive {naive:e} (rel {:e})",
        points.len(),
        rel(fast, naive)
    );
    fast
}

#[test]
fn fast_matches_naive_on_random_sets() {
    for n in [1usize, 2, 3, 10, 100, 1000] {
        for seed in 0..3 {
            compare(&random(n, seed * 31 + n as u64));
        }
    }
}

#[test]
fn fast_matches_naive_on_low_discrepancy_sets_despite_cancellation() {
    // T² ≈ 1e-6 while the terms of Warnock's formula are ≈ 0.1: six digits cancel.
    for m in [4u32, 8, 10] {
        compare(&sobol(1 << m));
        compare(&hammersley2(1 << m));
    }
}

#[test]
fn fast_matches_naive_with_ties_and_duplicates() {
    let mut r = Rng::new(9);
    for n in [2usize, 7, 50, 300] {
        let pts: Vec<DVec2> = (0..n)
            .map(|_| DVec2::new(r.below(6) as f64 / 6.0, r.below(4) as f64 / 4.0))
            .collect();
        compare(&pts);
    }
    compare(&[DVec2::new(0.25, 0.75); 20]);
}

#[test]
fn single_point_at_origin_by_hand() {
    // ∫∫ (1 − ab)² = 1 − 2·¼ + 1/9 = 11/18.
    let t = l2_star_discrepancy(&[DVec2::ZERO], &Cancel::never()).unwrap();
    assert!(rel(t, (11.0f64 / 18.0).sqrt()) < 1e-15, "{t}");
}

/// ∫∫ (A(a,b)/N − ab)² da db, cell by cell. The cells are cut by the point coordinates, so
/// A is constant on each and the integrand (c − ab)² is a polynomial of degree 2 in a and in
/// b; 2-point Gauss–Legendre per axis integrates it exactly. Independent of Warnock's algebra.
fn integrate_gauss(points: &[DVec2]) -> f64 {
    let n = points.len() as f64;
    let cuts = |f: fn(&DVec2) -> f64| {
        let mut v: Vec<f64> = points.iter().map(f).chain([0.0, 1.0]).collect();
        v.sort_by(f64::total_cmp);
        v.dedup();
        v
    };
    let xs = cuts(|p| p.x);
    let ys = cuts(|p| p.y);
    let g = 0.5 / 3f64.sqrt();
    let mut total = 0.0;
    for wx in xs.windows(2) {
        for wy in ys.windows(2) {
            let (ha, hb) = (wx[1] - wx[0], wy[1] - wy[0]);
            let (ma, mb) = ((wx[0] + wx[1]) / 2.0, (wy[0] + wy[1]) / 2.0);
            // A on the open cell: points with x ≤ left edge and y ≤ bottom edge.
            let c = points
                .iter()
                .filter(|p| p.x <= wx[0] && p.y <= wy[0])
                .count() as f64
                / n;
            let mut cell = 0.0;
            for sa in [-g, g] {
                for sb in [-g, g] {
                    let (a, b) = (ma + sa * ha, mb + sb * hb);
                    cell += (c - a * b).powi(2);
                }
            }
            total += cell * ha * hb / 4.0;
        }
    }
    total
}

/// Midpoint rule on an M×M grid, counting the points of [0,a)×[0,b) at each midpoint.
fn integrate_midpoint(points: &[DVec2], m: usize) -> f64 {
    let n = points.len() as f64;
    let h = 1.0 / m as f64;
    let mut total = 0.0;
    for i in 0..m {
        let a = (i as f64 + 0.5) * h;
        for j in 0..m {
            let b = (j as f64 + 0.5) * h;
            let c = points.iter().filter(|p| p.x < a && p.y < b).count() as f64 / n;
            total += (c - a * b).powi(2);
        }
    }
    total * h * h
}

#[test]
fn warnock_matches_exact_cellwise_quadrature() {
    // Gauss–Legendre is exact per cell: agreement to rounding (1e-12 relative on T).
    for n in [1usize, 2, 3, 5, 8] {
        for seed in 0..4 {
            let pts = random(n, 500 + seed);
            let t = l2_star_discrepancy(&pts, &Cancel::never()).unwrap();
            let q = integrate_gauss(&pts).sqrt();
            assert!(rel(t, q) <= 1e-12, "n={n}: warnock {t} vs quadrature {q}");
        }
    }
}

#[test]
fn warnock_matches_midpoint_integration_of_tiny_sets() {
    // Error bound of the midpoint rule for f = (A/N − ab)² ∈ [0,1], h = 1/M:
    // - cells not cut by a discontinuity of A: |error| ≤ h⁴/24 · (|f_aa| + |f_bb|) ≤ h⁴/6
    //   (f_aa = 2b², f_bb = 2a²), so ≤ h²/6 in all;
    // - cells cut by one of the 2N rays {a = x_i, b > y_i}, {b = y_i, a > x_i}: at most 2NM
    //   cells, each off by at most h²·(max f − min f) ≤ h², so ≤ 2N·h in all.
    let c = Cancel::never();
    // (1) Coordinates on the 1/16 lattice and M = 256: no cell is cut; tolerance h²/6.
    let mut r = Rng::new(4);
    let pts: Vec<DVec2> = (0..4)
        .map(|_| DVec2::new(r.below(16) as f64 / 16.0, r.below(16) as f64 / 16.0))
        .collect();
    let m = 256;
    let tol = 1.0 / (6.0 * (m * m) as f64);
    let t2 = l2_star_discrepancy(&pts, &c).unwrap().powi(2);
    let mid = integrate_midpoint(&pts, m);
    assert!(
        (t2 - mid).abs() <= tol,
        "lattice: {t2} vs {mid} (tol {tol:e})"
    );
    // (2) Random coordinates, M = 1024: tolerance 2N/M + h²/6 ≈ 7.8e-3 for N = 4.
    let pts = random(4, 12);
    let m = 1024;
    let tol = 2.0 * 4.0 / m as f64 + 1.0 / (6.0 * (m * m) as f64);
    let t2 = l2_star_discrepancy(&pts, &c).unwrap().powi(2);
    let mid = integrate_midpoint(&pts, m);
    assert!(
        (t2 - mid).abs() <= tol,
        "random: {t2} vs {mid} (tol {tol:e})"
    );
}

#[test]
fn random_sets_follow_the_expected_mean() {
    // E[T²] = (1/N)(1/4 − 1/9) for i.i.d. uniform points in 2D. Mean over 200 sets of
    // N = 64: the standard error of the mean is ≈ 7% of E[T²] here; 25% tolerance.
    let n = 64;
    let k = 200;
    let mean: f64 = (0..k)
        .map(|s| {
            l2_star_discrepancy(&random(n, 10_000 + s), &Cancel::never())
                .unwrap()
                .powi(2)
        })
        .sum::<f64>()
        / k as f64;
    let expect = (0.25 - 1.0 / 9.0) / n as f64;
    assert!(rel(mean, expect) < 0.25, "{mean} vs {expect}");
}

#[test]
fn cancelled_and_bad_input() {
    let c = Cancel::new();
    c.cancel();
    let pts = random(10, 1);
    assert_eq!(l2_star_discrepancy(&pts, &c), Err(MetricsError::Cancelled));
    assert_eq!(
        l2_star_discrepancy_naive(&pts, &c),
        Err(MetricsError::Cancelled)
    );
    let never = Cancel::never();
    assert_eq!(l2_star_discrepancy(&[], &never), Err(MetricsError::Empty));
    assert!(matches!(
        l2_star_discrepancy(&[DVec2::new(0.5, f64::INFINITY)], &never),
        Err(MetricsError::NonFinite { index: 0, .. })
    ));
    assert!(matches!(
        l2_star_discrepancy_naive(&[DVec2::new(0.5, 0.5), DVec2::new(1.0, 0.5)], &never),
        Err(MetricsError::OutOfRange { index: 1, .. })
    ));
}
