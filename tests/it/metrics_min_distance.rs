//! Toroidal minimum distance and mean nearest-neighbour distance: grid search against the
//! O(N²) brute force (bit-identical results), hand values and edge cases.

use crate::metrics_common;

use glam::DVec2;
use metrics_common::{jittered, random};
use samplescope::core::cancel::Cancel;
use samplescope::core::metrics::{hex_distance, min_distance, min_distance_naive, MetricsError};
use samplescope::core::rng::Rng;

fn compare(points: &[DVec2]) {
    let c = Cancel::never();
    let fast = min_distance(points, &c).unwrap();
    let naive = min_distance_naive(points, &c).unwrap();
    // Same distances, same summation order, same tie-breaking: equal to the bit.
    assert_eq!(fast, naive, "n = {}", points.len());
    let (i, j) = fast.pair;
    assert!(i < j && j < points.len());
}

#[test]
fn grid_matches_naive_on_random_sets() {
    for n in [2usize, 3, 10, 17, 18, 50, 100, 1000, 3000] {
        for seed in 0..3 {
            compare(&random(n, seed + 17 * n as u64));
        }
    }
}

#[test]
fn grid_matches_naive_on_jittered_and_clustered_sets() {
    for k in [2usize, 5, 20, 40] {
        compare(&jittered(k, 3));
    }
    // A dense cluster plus a few far points: the far points search many rings, and the
    // cluster's cells are crowded.
    let mut r = Rng::new(5);
    let mut pts: Vec<DVec2> = (0..500)
        .map(|_| DVec2::new(0.3 + 0.01 * r.next_f64(), 0.6 + 0.01 * r.next_f64()))
        .collect();
    pts.extend([
        DVec2::new(0.9, 0.1),
        DVec2::new(0.95, 0.05),
        DVec2::new(0.0, 0.0),
    ]);
    compare(&pts);
}

#[test]
fn grid_matches_naive_with_ties_on_a_lattice() {
    // Regular grid: every point has 4 neighbours at exactly 1/k; many tied pairs, resolved
    // to the lexicographically smallest pair in both algorithms.
    for k in [3usize, 8, 16, 33] {
        let pts = metrics_common::grid(k);
        compare(&pts);
        let md = min_distance(&pts, &Cancel::never()).unwrap();
        assert!((md.min_distance - 1.0 / k as f64).abs() < 1e-15);
        assert!((md.mean_nn_distance - 1.0 / k as f64).abs() < 1e-15);
        // Which tied pair is smallest depends on the rounding of the coordinates (e.g. the
        // seam pair (0, 2) of a 3×3 grid comes out an ulp shorter than (0, 1)); the pair must
        // attain the minimum.
        let (i, j) = md.pair;
        let mut dx = (pts[i].x - pts[j].x).abs();
        let mut dy = (pts[i].y - pts[j].y).abs();
        dx = dx.min(1.0 - dx);
        dy = dy.min(1.0 - dy);
        assert_eq!((dx * dx + dy * dy).sqrt(), md.min_distance);
        // Square grid normalised by the hexagonal packing distance: √(√3/2) ≈ 0.9306.
        let expect = (3f64.sqrt() / 2.0).sqrt();
        assert!((md.normalized_min_distance - expect).abs() < 1e-12);
    }
}

#[test]
fn wrap_around_pair_is_found() {
    // The closest pair is across the x = 0 ≡ 1 seam, at toroidal distance 0.003.
    let mut pts = metrics_common::grid(10);
    pts.push(DVec2::new(0.001, 0.33));
    pts.push(DVec2::new(0.998, 0.33));
    compare(&pts);
    let md = min_distance(&pts, &Cancel::never()).unwrap();
    assert!((md.min_distance - 0.003).abs() < 1e-12, "{md:?}");
    assert_eq!(md.pair, (100, 101));
}

#[test]
fn duplicate_points_give_zero() {
    let mut pts = random(200, 8);
    pts[150] = pts[42];
    pts[199] = pts[42];
    compare(&pts);
    let md = min_distance(&pts, &Cancel::never()).unwrap();
    assert_eq!(md.min_distance, 0.0);
    assert_eq!(md.pair, (42, 150));
    // All points identical.
    let same = vec![DVec2::new(0.5, 0.5); 100];
    compare(&same);
    let md = min_distance(&same, &Cancel::never()).unwrap();
    assert_eq!(
        (md.min_distance, md.mean_nn_distance, md.pair),
        (0.0, 0.0, (0, 1))
    );
}

#[test]
fn two_points_by_hand() {
    let pts = [DVec2::new(0.1, 0.1), DVec2::new(0.4, 0.5)];
    let md = min_distance(&pts, &Cancel::never()).unwrap();
    assert!((md.min_distance - 0.5).abs() < 1e-15); // (0.3, 0.4) → 0.5
    assert_eq!(md.mean_nn_distance, md.min_distance);
    let hex = (2.0 / (3f64.sqrt() * 2.0)).sqrt();
    assert!((md.hex_distance - hex).abs() < 1e-15);
    // PSA's normalisation: d · √(√3·N/2).
    let psa = md.min_distance * (3f64.sqrt() * 2.0 / 2.0).sqrt();
    assert!((md.normalized_min_distance - psa).abs() < 1e-15);
    assert_eq!(hex_distance(2), md.hex_distance);
}

#[test]
fn random_mean_nn_matches_poisson_expectation() {
    // For a Poisson process of intensity N, E[d_NN] = 1/(2√N) (edge-free on the torus).
    // N = 20 000: relative standard error ≈ 0.52/√N ≈ 0.4%; tolerance 3%.
    let n = 20_000;
    let md = min_distance(&random(n, 77), &Cancel::never()).unwrap();
    let expect = 0.5 / (n as f64).sqrt();
    assert!((md.mean_nn_distance / expect - 1.0).abs() < 0.03, "{md:?}");
}

#[test]
fn too_few_points_bad_input_and_cancel() {
    let c = Cancel::never();
    assert!(matches!(
        min_distance(&[DVec2::new(0.5, 0.5)], &c),
        Err(MetricsError::TooFewPoints { n: 1, min: 2, .. })
    ));
    assert_eq!(min_distance(&[], &c), Err(MetricsError::Empty));
    let mut pts = random(50, 1);
    pts[7].x = -1e-300;
    assert!(matches!(
        min_distance(&pts, &c),
        Err(MetricsError::OutOfRange { index: 7, .. })
    ));
    let cancelled = Cancel::new();
    cancelled.cancel();
    assert_eq!(
        min_distance(&random(100, 1), &cancelled),
        Err(MetricsError::Cancelled)
    );
    assert_eq!(
        min_distance_naive(&random(100, 1), &cancelled),
        Err(MetricsError::Cancelled)
    );
}
