//! t-value of nets: known (0,m,2)-nets, hand-checked sets, boundaries, and an independent
//! reference that tests every elementary interval with exact integer arithmetic.

use crate::metrics_common;

use glam::DVec2;
use metrics_common::{hammersley2, random, sobol};
use samplescope::core::cancel::Cancel;
use samplescope::core::metrics::{t_value, MetricsError};
use samplescope::core::rng::Rng;

const TWO53: f64 = 9_007_199_254_740_992.0;

/// Reference t-value: for t = 0, 1, …, enumerate every shape (kx, ky), kx + ky = m − t, and
/// every cell (i, j), and count the points with i/b^kx ≤ x < (i+1)/b^kx (same for y) by exact
/// integer comparisons `i·2⁵³ ≤ X·b^kx < (i+1)·2⁵³` with `X = x·2⁵³` (inputs must be
/// multiples of 2⁻⁵³). Cost O(N²·m²); for small sets only.
fn t_value_reference(points: &[DVec2], b: u64) -> u32 {
    let n = points.len() as u64;
    let mut m = 0u32;
    while b.pow(m) < n {
        m += 1;
    }
    assert_eq!(b.pow(m), n);
    let int = |v: f64| {
        let x = v * TWO53;
        assert_eq!(x, x.floor(), "reference needs multiples of 2^-53");
        x as u128
    };
    let ints: Vec<(u128, u128)> = points.iter().map(|p| (int(p.x), int(p.y))).collect();
    let two53 = 1u128 << 53;
    let inside = |x: u128, k: u32, i: u64| {
        let s = (b as u128).pow(k);
        (i as u128) * two53 <= x * s && x * s < (i as u128 + 1) * two53
    };
    'next_t: for t in 0..=m {
        for kx in 0..=(m - t) {
            let ky = m - t - kx;
            for i in 0..b.pow(kx) {
                for j in 0..b.pow(ky) {
                    let c = ints
                        .iter()
                        .filter(|&&(x, y)| inside(x, kx, i) && inside(y, ky, j))
                        .count() as u64;
                    if c != b.pow(t) {
                        continue 'next_t;
                    }
                }
            }
        }
        return t;
    }
    unreachable!("t = m always holds")
}

/// Radical inverse digits of i in base b over m digits, as an integer in [0, b^m).
fn reverse_digits(mut i: u64, b: u64, m: u32) -> u64 {
    let mut r = 0;
    for _ in 0..m {
        r = r * b + i % b;
        i /= b;
    }
    r
}

/// Rounds down to a multiple of 2⁻⁵³.
fn q53(v: f64) -> f64 {
    (v * TWO53).floor() / TWO53
}

/// Hammersley net in base b with cell-centred coordinates: ((i+½)/b^m, (rev(i)+½)/b^m),
/// a (0,m,2)-net in base b; the ½ keeps every point strictly inside its finest cell, so the
/// rounding of non-dyadic values cannot move it across a boundary.
fn hammersley_centred(b: u64, m: u32) -> Vec<DVec2> {
    let n = b.pow(m);
    (0..n)
        .map(|i| {
            DVec2::new(
                q53((i as f64 + 0.5) / n as f64),
                q53((reverse_digits(i, b, m) as f64 + 0.5) / n as f64),
            )
        })
        .collect()
}

#[test]
fn hammersley_base2_is_a_0_m_2_net() {
    for m in 0..=12u32 {
        let t = t_value(&hammersley2(1 << m), 2, &Cancel::never()).unwrap();
        assert_eq!((t.m, t.t, t.violation), (m, 0, None), "m = {m}");
    }
}

#[test]
fn sobol_prefixes_are_0_m_2_nets() {
    for m in 0..=12u32 {
        let t = t_value(&sobol(1 << m), 2, &Cancel::never()).unwrap();
        assert_eq!(t.t, 0, "m = {m}");
    }
}

#[test]
fn hammersley_in_bases_3_4_5_are_nets() {
    for (b, mmax) in [(3u64, 5u32), (4, 5), (5, 4)] {
        for m in 0..=mmax {
            let pts = hammersley_centred(b, m);
            let t = t_value(&pts, b as u32, &Cancel::never()).unwrap();
            assert_eq!(t.t, 0, "base {b}, m = {m}");
        }
    }
}

#[test]
fn grid_2x2_at_cell_centres_has_t_1() {
    // Points (¼,¼), (¾,¼), (¼,¾), (¾,¾); N = 4 = 2², m = 2.
    // t = 0 needs one point in every interval of area ¼. The strips 1 × ¼ fail: y = ¼ lies on
    // a boundary and belongs to the upper strip [¼,½), so [0,¼) holds 0 points and [¼,½) two.
    // t = 1 (area ½): the halves [0,½)×[0,1), [½,1)×[0,1) and [0,1)×[0,½), [0,1)×[½,1) each
    // hold 2 = 2¹ points. Hence t = 1.
    let pts = metrics_common::grid(2);
    let t = t_value(&pts, 2, &Cancel::never()).unwrap();
    assert_eq!((t.m, t.t), (2, 1));
    let v = t.violation.expect("t > 0 has a witness");
    assert_eq!(
        (v.t, v.kx, v.ky, v.cell, v.count, v.expected),
        (0, 0, 2, (0, 0), 0, 1)
    );
    assert_eq!(t_value_reference(&pts, 2), 1);
}

#[test]
fn random_points_have_positive_t() {
    for (m, seed) in [(4u32, 1u64), (6, 2), (8, 3), (10, 4)] {
        let t = t_value(&random(1 << m, seed), 2, &Cancel::never()).unwrap();
        assert!(t.t > 0, "m = {m}: {t:?}");
        let v = t.violation.unwrap();
        assert_ne!(v.count, v.expected);
        assert_eq!(v.kx + v.ky + v.t, m);
    }
}

#[test]
fn matches_reference_on_random_and_lattice_sets() {
    let mut r = Rng::new(21);
    for m in 0..=6u32 {
        let n = 1usize << m;
        for seed in 0..3 {
            let pts = random(n, 100 * m as u64 + seed);
            let t = t_value(&pts, 2, &Cancel::never()).unwrap().t;
            assert_eq!(t, t_value_reference(&pts, 2), "random m = {m}");
        }
        // Coordinates on the 1/8 lattice: many points exactly on interval boundaries.
        let pts: Vec<DVec2> = (0..n)
            .map(|_| DVec2::new(r.below(8) as f64 / 8.0, r.below(8) as f64 / 8.0))
            .collect();
        let t = t_value(&pts, 2, &Cancel::never()).unwrap().t;
        assert_eq!(t, t_value_reference(&pts, 2), "lattice m = {m}");
    }
    for m in 0..=3u32 {
        let n = 3usize.pow(m);
        let pts = random(n, 7 + m as u64);
        let t = t_value(&pts, 3, &Cancel::never()).unwrap().t;
        assert_eq!(t, t_value_reference(&pts, 3), "base 3 random m = {m}");
        let pts = hammersley_centred(3, m);
        assert_eq!(t_value_reference(&pts, 3), 0);
    }
}

#[test]
fn boundary_point_belongs_to_upper_interval() {
    // (0, ½) and (½, 0): x = ½ and y = ½ lie in the upper halves, so each half holds one
    // point: a (0,1,2)-net.
    let pts = [DVec2::new(0.0, 0.5), DVec2::new(0.5, 0.0)];
    assert_eq!(t_value(&pts, 2, &Cancel::never()).unwrap().t, 0);
    // Just below ½ is the lower half: both points in [0,½)×[0,1), so t = 1.
    let below = 0.5 - f64::EPSILON / 4.0;
    let pts = [DVec2::new(0.25, 0.5), DVec2::new(below, 0.0)];
    assert_eq!(t_value(&pts, 2, &Cancel::never()).unwrap().t, 1);
}

#[test]
fn boundary_one_third_is_not_representable() {
    // fl(1/3) < 1/3, so the "regular" base-3 points x = 0, fl(1/3), fl(2/3) put two points in
    // [0, 1/3) (fl(2/3) < 2/3 too, lands in [1/3, 2/3)): not a (0,1,2)-net; t = 1.
    let pts: Vec<DVec2> = (0..3)
        .map(|i| DVec2::new(i as f64 / 3.0, (i as f64 + 0.5) / 3.0))
        .collect();
    let t = t_value(&pts, 3, &Cancel::never()).unwrap();
    assert_eq!(t.t, 1);
    let v = t.violation.unwrap();
    assert_eq!((v.kx, v.ky, v.cell, v.count), (1, 0, (0, 0), 2));
}

#[test]
fn single_point_is_a_0_0_2_net() {
    let t = t_value(&[DVec2::new(0.3, 0.7)], 5, &Cancel::never()).unwrap();
    assert_eq!((t.m, t.t, t.violation), (0, 0, None));
}

#[test]
fn n_not_power_of_base_and_bad_base_are_errors() {
    let c = Cancel::never();
    assert_eq!(
        t_value(&random(12, 1), 2, &c),
        Err(MetricsError::NotPowerOfBase { n: 12, base: 2 })
    );
    assert_eq!(
        t_value(&random(8, 1), 3, &c),
        Err(MetricsError::NotPowerOfBase { n: 8, base: 3 })
    );
    assert_eq!(
        t_value(&random(8, 1), 1, &c),
        Err(MetricsError::InvalidBase { base: 1 })
    );
    assert_eq!(
        t_value(&random(8, 1), 0, &c),
        Err(MetricsError::InvalidBase { base: 0 })
    );
    assert_eq!(
        t_value(&random(4, 1), u32::MAX, &c),
        Err(MetricsError::NotPowerOfBase {
            n: 4,
            base: u32::MAX
        })
    );
    assert_eq!(t_value(&[], 2, &c), Err(MetricsError::Empty));
    let mut pts = random(4, 1);
    pts[2].x = f64::NAN;
    assert!(matches!(
        t_value(&pts, 2, &c),
        Err(MetricsError::NonFinite { index: 2, .. })
    ));
    let cancelled = Cancel::new();
    cancelled.cancel();
    assert_eq!(
        t_value(&random(64, 1), 2, &cancelled),
        Err(MetricsError::Cancelled)
    );
}
