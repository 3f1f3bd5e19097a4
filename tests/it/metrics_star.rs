//! Exact star discrepancy (2D sweep and brute force) and the lecture's 1D closed form.

use crate::metrics_common;

use glam::DVec2;
use metrics_common::{hammersley2, jittered, random, sobol};
use samplescope::core::cancel::Cancel;
use samplescope::core::metrics::{
    star_discrepancy, star_discrepancy_1d, star_discrepancy_1d_brute_force,
    star_discrepancy_brute_force, MetricsError, StarDiscrepancy,
};
use samplescope::core::rng::Rng;

/// Agreement required between the O(N²) sweep and the O(N³) brute force.
const TOL: f64 = 1e-12;

/// Recounts the reported worst box and checks it reproduces the reported value.
fn check_box(points: &[DVec2], s: &StarDiscrepancy) {
    let (a, b) = s.worst_box;
    let count = points
        .iter()
        .filter(|p| {
            if s.closed {
                p.x <= a && p.y <= b
            } else {
                p.x < a && p.y < b
            }
        })
        .count();
    assert_eq!(count, s.points_inside, "{s:?}");
    let n = points.len() as f64;
    let v = if s.closed {
        count as f64 / n - a * b
    } else {
        a * b - count as f64 / n
    };
    assert!((v - s.value).abs() <= 1e-15, "box value {v} vs {s:?}");
}

fn compare(points: &[DVec2]) -> f64 {
    let c = Cancel::never();
    let fast = star_discrepancy(points, &c).unwrap();
    let brute = star_discrepancy_brute_force(points, &c).unwrap();
    assert!(
        (fast.value - brute.value).abs() <= TOL,
        "n = {}: sweep {fast:?} vs brute force {brute:?}",
        points.len()
    );
    check_box(points, &fast);
    check_box(points, &brute);
    fast.value
}

#[test]
fn sweep_matches_brute_force_on_random_sets() {
    for n in [1usize, 2, 3, 4, 5, 7, 8, 13, 16, 31, 32, 33, 64] {
        for seed in 0..5 {
            compare(&random(n, 1000 * n as u64 + seed));
        }
    }
}

#[test]
fn sweep_matches_brute_force_on_structured_sets() {
    for m in 0..=6 {
        compare(&hammersley2(1 << m));
        compare(&sobol(1 << m));
    }
    for k in [1usize, 2, 3, 5, 8] {
        compare(&jittered(k, 7));
        compare(&metrics_common::grid(k));
    }
}

#[test]
fn sweep_matches_brute_force_with_ties_and_duplicates() {
    // Coordinates on a 1/8 lattice: many shared x, shared y and duplicate points.
    let mut r = Rng::new(42);
    for n in [2usize, 5, 17, 40, 64] {
        for _ in 0..4 {
            let pts: Vec<DVec2> = (0..n)
                .map(|_| DVec2::new(r.below(8) as f64 / 8.0, r.below(8) as f64 / 8.0))
                .collect();
            compare(&pts);
        }
    }
    // All points identical.
    compare(&[DVec2::new(0.3, 0.6); 10]);
}

#[test]
fn sweep_matches_brute_force_at_n_200() {
    compare(&random(200, 99));
}

#[test]
fn single_point_at_centre_is_three_quarters() {
    // By hand: open boxes [0,½)×[0,1) and [0,1)×[0,½) hold no point: ½. The closed box
    // [0,½]×[0,½] holds the point with volume ¼: 1 − ¼ = ¾, the maximum.
    let s = star_discrepancy(&[DVec2::new(0.5, 0.5)], &Cancel::never()).unwrap();
    assert_eq!(s.value, 0.75);
    assert_eq!(s.worst_box, (0.5, 0.5));
    assert!(s.closed);
    assert_eq!(s.points_inside, 1);
}

#[test]
fn point_at_origin_gives_one() {
    // The closed box [0,0]×[0,0] has volume 0 and holds every point.
    let s = star_discrepancy(&[DVec2::ZERO; 3], &Cancel::never()).unwrap();
    assert_eq!(s.value, 1.0);
    assert!(s.closed);
    assert_eq!(s.points_inside, 3);
}

#[test]
fn value_bounds_every_random_box_and_is_approached() {
    let pts = random(500, 5);
    let s = star_discrepancy(&pts, &Cancel::never()).unwrap();
    check_box(&pts, &s);
    let n = pts.len() as f64;
    let local = |a: f64, b: f64| {
        let c = pts.iter().filter(|p| p.x < a && p.y < b).count() as f64;
        (c / n - a * b).abs()
    };
    let mut r = Rng::new(6);
    for _ in 0..2000 {
        let (a, b) = (r.next_f64(), r.next_f64());
        assert!(local(a, b) <= s.value + 1e-15);
    }
    // Half-open boxes approach the supremum: exactly for an open worst box, in the limit
    // a ↓ x, b ↓ y for a closed one (the volume error is ε(a + b + ε)).
    let (a, b) = s.worst_box;
    let eps = 1e-12;
    let approx = if s.closed {
        local(a + eps, b + eps)
    } else {
        local(a, b)
    };
    assert!(approx >= s.value - 3e-12, "{approx} vs {s:?}");
}

#[test]
fn projections_bound_the_2d_discrepancy_from_below() {
    // Boxes with b = 1 (resp. a = 1) are 1D intervals of the x (resp. y) projection, so
    // D*(P) ≥ D*_1D(x) and D*(P) ≥ D*_1D(y).
    for seed in 0..5 {
        let pts = random(300, seed);
        let d2 = star_discrepancy(&pts, &Cancel::never()).unwrap().value;
        let xs: Vec<f64> = pts.iter().map(|p| p.x).collect();
        let ys: Vec<f64> = pts.iter().map(|p| p.y).collect();
        assert!(d2 >= star_discrepancy_1d(&xs).unwrap() - 1e-15);
        assert!(d2 >= star_discrepancy_1d(&ys).unwrap() - 1e-15);
    }
}

/// D* of the degenerate "row" set {(x_i, c)} (all points at height c ∈ [0,1)).
///
/// Proof. A(a,b) = F(a)·[b > c] with F(a) = #{x_i < a}. For b ≤ c the box is empty and
/// |δ| = ab ≤ c, with c attained at (a,b) = (1,c). For b > c, δ = F(a)/N − ab is linear in b,
/// so sup over b ∈ (c,1] of |δ| is reached at an end: b ↓ c gives F(a)/N − ac, b = 1 gives
/// F(a)/N − a. The sup over a of |F(a)/N − a| is the 1D star discrepancy D1(x). For
/// F(a)/N − ac: its negative part ac − F/N ≤ a − F/N ≤ D1; its positive part is maximal as
/// a ↓ x_(i) (F is left-constant, −ac decreasing), giving G(c) = max_i (i/N − c·x_(i)).
/// Hence D*_2D = max(c, D1(x), G(c)).
///
/// This is why no row reduces to the 1D discrepancy for every x: G(c) ≥ 1 − c (take i = N)
/// and the c term make D*_2D ≥ max(c, 1 − c) ≥ ½. In particular all y_i = 0 gives D* = 1
/// (the closed box [0, x_max]×[0,0] holds every point and has volume 0), not the 1D value.
/// The 1D term dominates when D1(x) > ½, e.g. when the x are bunched near 0.9.
fn row_set_formula(xs: &[f64], c: f64) -> f64 {
    let mut s = xs.to_vec();
    s.sort_by(f64::total_cmp);
    let n = s.len() as f64;
    let g = s
        .iter()
        .enumerate()
        .map(|(k, &x)| (k + 1) as f64 / n - c * x)
        .fold(0.0, f64::max);
    c.max(star_discrepancy_1d(xs).unwrap()).max(g)
}

#[test]
fn row_set_matches_degenerate_reduction_formula() {
    let mut r = Rng::new(77);
    for n in [1usize, 2, 5, 20, 100] {
        for c in [0.0, 0.1, 0.5, 0.9, 0.999] {
            let xs: Vec<f64> = (0..n).map(|_| r.next_f64()).collect();
            let pts: Vec<DVec2> = xs.iter().map(|&x| DVec2::new(x, c)).collect();
            let d2 = star_discrepancy(&pts, &Cancel::never()).unwrap().value;
            let expect = row_set_formula(&xs, c);
            assert!((d2 - expect).abs() <= TOL, "n={n} c={c}: {d2} vs {expect}");
        }
    }
}

#[test]
fn row_set_with_bunched_x_equals_lecture_1d_formula() {
    // x_i ∈ [0.9, 0.95), c = ½: D1(x) ≈ 0.9 beats c = ½ and G(½) ≤ 1 − ½·0.9 = 0.55, so the
    // 2D exact value must equal the lecture's 1D closed form exactly (to rounding).
    let mut r = Rng::new(3);
    for n in [1usize, 3, 10, 64, 257] {
        let xs: Vec<f64> = (0..n).map(|_| 0.9 + 0.05 * r.next_f64()).collect();
        let pts: Vec<DVec2> = xs.iter().map(|&x| DVec2::new(x, 0.5)).collect();
        let d2 = star_discrepancy(&pts, &Cancel::never()).unwrap();
        let d1 = star_discrepancy_1d(&xs).unwrap();
        assert!((d2.value - d1).abs() <= TOL, "n={n}: 2D {d2:?} vs 1D {d1}");
        assert!(d1 > 0.9 - 1e-12);
    }
}

#[test]
fn all_y_zero_gives_one_not_the_1d_value() {
    let pts: Vec<DVec2> = (0..8)
        .map(|i| DVec2::new((i as f64 + 0.5) / 8.0, 0.0))
        .collect();
    let s = star_discrepancy(&pts, &Cancel::never()).unwrap();
    assert_eq!(s.value, 1.0);
    assert!(s.closed);
    assert_eq!(s.worst_box.1, 0.0);
}

#[test]
fn one_d_closed_form_matches_brute_force() {
    let mut r = Rng::new(8);
    for n in 1..=50 {
        let xs: Vec<f64> = (0..n).map(|_| r.next_f64()).collect();
        let a = star_discrepancy_1d(&xs).unwrap();
        let b = star_discrepancy_1d_brute_force(&xs).unwrap();
        assert!((a - b).abs() <= 1e-15, "n={n}: {a} vs {b}");
        // With duplicates and the closed end 1.
        let ys: Vec<f64> = (0..n).map(|_| r.below(5) as f64 / 4.0).collect();
        let a = star_discrepancy_1d(&ys).unwrap();
        let b = star_discrepancy_1d_brute_force(&ys).unwrap();
        assert!((a - b).abs() <= 1e-15, "n={n}: {a} vs {b} on {ys:?}");
    }
}

#[test]
fn lecture_examples_regular_and_centred() {
    for n in [1usize, 2, 3, 7, 10, 100, 1000] {
        let nf = n as f64;
        // Lecture: x_i = i/N (1-based) ⇒ 1/N.
        let xs: Vec<f64> = (1..=n).map(|i| i as f64 / nf).collect();
        assert!((star_discrepancy_1d(&xs).unwrap() - 1.0 / nf).abs() <= 1e-15);
        assert!((star_discrepancy_1d_brute_force(&xs).unwrap() - 1.0 / nf).abs() <= 1e-15);
        // Its [0,1) shift x_i = (i−1)/N also has 1/N.
        let xs: Vec<f64> = (0..n).map(|i| i as f64 / nf).collect();
        assert!((star_discrepancy_1d(&xs).unwrap() - 1.0 / nf).abs() <= 1e-15);
        // Lecture: x_i = (i − ½)/N ⇒ 1/(2N), the optimum.
        let xs: Vec<f64> = (1..=n).map(|i| (i as f64 - 0.5) / nf).collect();
        assert!((star_discrepancy_1d(&xs).unwrap() - 0.5 / nf).abs() <= 1e-15);
        assert!((star_discrepancy_1d_brute_force(&xs).unwrap() - 0.5 / nf).abs() <= 1e-15);
    }
}

#[test]
fn cancelled_token_stops_star() {
    let c = Cancel::new();
    c.cancel();
    let pts = random(100, 1);
    assert_eq!(star_discrepancy(&pts, &c), Err(MetricsError::Cancelled));
    assert_eq!(
        star_discrepancy_brute_force(&pts, &c),
        Err(MetricsError::Cancelled)
    );
}

#[test]
fn empty_nan_out_of_range_and_too_many_are_errors() {
    let c = Cancel::never();
    assert_eq!(star_discrepancy(&[], &c), Err(MetricsError::Empty));
    let mut pts = random(10, 2);
    pts[3].y = f64::NAN;
    assert!(matches!(
        star_discrepancy(&pts, &c),
        Err(MetricsError::NonFinite { index: 3, .. })
    ));
    pts[3].y = 1.0; // 1 is outside [0, 1)
    assert!(matches!(
        star_discrepancy(&pts, &c),
        Err(MetricsError::OutOfRange { index: 3, .. })
    ));
    pts[3].y = -0.25;
    assert!(matches!(
        star_discrepancy_brute_force(&pts, &c),
        Err(MetricsError::OutOfRange { index: 3, .. })
    ));
    assert!(matches!(
        star_discrepancy_brute_force(&random(2000, 1), &c),
        Err(MetricsError::TooManyPoints { n: 2000, .. })
    ));
    assert_eq!(star_discrepancy_1d(&[]), Err(MetricsError::Empty));
    assert!(matches!(
        star_discrepancy_1d(&[0.5, 1.5]),
        Err(MetricsError::ValueOutOfRange { index: 1, .. })
    ));
    assert!(matches!(
        star_discrepancy_1d_brute_force(&[f64::NAN]),
        Err(MetricsError::ValueOutOfRange { index: 0, .. })
    ));
}
