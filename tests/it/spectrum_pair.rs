//! Pair correlation g(r): uniform points, lattices, the naive reference against the cell list,
//! a hand-computed toroidal pair, and input errors.

use glam::DVec2;
use samplescope::core::cancel::Cancel;
use samplescope::core::rng::Rng;
use samplescope::core::spectrum::*;
use std::f64::consts::PI;

fn uniform(n: usize, seed: u64) -> Vec<DVec2> {
    let mut r = Rng::new(seed);
    (0..n)
        .map(|_| DVec2::new(r.next_f64(), r.next_f64()))
        .collect()
}

#[test]
fn uniform_points_give_g_near_one() {
    // N = 2000, Δ = 0.01 up to 0.25: expected pairs per bin E_b = N(N−1)/2 · π(r₂² − r₁²)
    // (628 in the first bin, ~30 000 in the last); the count is nearly Poisson: |g − 1| ≤ 5/√E_b.
    let n = 2000;
    let g = pair_correlation(&uniform(n, 1), 0.01, 0.25, &Cancel::never()).unwrap();
    assert_eq!(g.g.len(), 25);
    for (b, &v) in g.g.iter().enumerate() {
        let (r1, r2) = (b as f64 * 0.01, (b + 1) as f64 * 0.01);
        let e = (n * (n - 1) / 2) as f64 * PI * (r2 * r2 - r1 * r1);
        assert!((v - 1.0).abs() <= 5.0 / e.sqrt(), "bin {b}: g = {v}");
        assert!((g.radii[b] - (b as f64 + 0.5) * 0.01).abs() < 1e-15);
    }
}

#[test]
fn lattice_gives_zero_below_its_spacing_and_four_neighbours_at_it() {
    // 32×32 lattice at cell centres: spacing 1/32 = 0.03125, bins of 0.005.
    let pts: Vec<DVec2> = (0..1024)
        .map(|i| {
            DVec2::new(
                ((i % 32) as f64 + 0.5) / 32.0,
                ((i / 32) as f64 + 0.5) / 32.0,
            )
        })
        .collect();
    for f in [pair_correlation, pair_correlation_naive] {
        let g = f(&pts, 0.005, 0.1, &Cancel::never()).unwrap();
        assert!(g.g[..6].iter().all(|&v| v == 0.0), "{:?}", &g.g[..7]);
        // Bin 6 = [0.030, 0.035) holds the 4 nearest neighbours of every point: 2N pairs.
        assert_eq!(g.counts[6], 2048);
        // Next shell √2/32 = 0.0442 (bin 8): 4 diagonal neighbours: 2N pairs.
        assert_eq!(g.counts[8], 2048);
        assert_eq!(g.counts[7], 0);
    }
}

#[test]
fn cell_list_matches_all_pairs_exactly() {
    let pts = uniform(3000, 2);
    let c = Cancel::never();
    for (width, r_max) in [
        (0.002, 0.05),
        (0.01, 0.2),
        (0.02, 0.34),
        (0.05, 0.5),
        (0.003, 0.0333),
    ] {
        let fast = pair_correlation(&pts, width, r_max, &c).unwrap();
        let naive = pair_correlation_naive(&pts, width, r_max, &c).unwrap();
        assert_eq!(fast, naive, "width {width} r_max {r_max}");
    }
}

#[test]
fn toroidal_pair_across_the_boundary() {
    // (0.05, 0.5) and (0.95, 0.5) are 0.1 apart through the boundary: bin ⌊0.1/0.03⌋ = 3,
    // g₃ = 1 / (1 · π(0.12² − 0.09²)).
    let pts = [DVec2::new(0.05, 0.5), DVec2::new(0.95, 0.5)];
    let g = pair_correlation_naive(&pts, 0.03, 0.5, &Cancel::never()).unwrap();
    assert_eq!(g.counts.len(), 16);
    assert_eq!(g.counts.iter().sum::<u64>(), 1);
    assert_eq!(g.counts[3], 1);
    assert!((g.g[3] - 1.0 / (PI * (0.12f64.powi(2) - 0.09f64.powi(2)))).abs() < 1e-12);
    // Duplicated points are at distance 0 (first bin).
    let dup = [DVec2::new(0.3, 0.3); 3];
    let g = pair_correlation(&dup, 0.01, 0.1, &Cancel::never()).unwrap();
    assert_eq!(g.counts[0], 3);
}

#[test]
fn bad_inputs_are_typed_errors_naming_the_field() {
    let c = Cancel::never();
    let pts = uniform(10, 3);
    let field = |r: Result<PairCorrelation, SpectrumError>| match r {
        Err(SpectrumError::InvalidParam { field, .. }) => field,
        other => panic!("expected InvalidParam, got {other:?}"),
    };
    assert_eq!(
        field(pair_correlation(&pts[..1], 0.01, 0.1, &c)),
        "n_points"
    );
    for r_max in [0.0, -0.1, 0.51, f64::NAN, f64::INFINITY] {
        assert_eq!(field(pair_correlation(&pts, 0.01, r_max, &c)), "r_max");
    }
    for w in [0.0, -0.01, 0.2, f64::NAN] {
        assert_eq!(field(pair_correlation(&pts, w, 0.1, &c)), "bin_width");
    }
    assert_eq!(field(pair_correlation(&pts, 1e-8, 0.5, &c)), "bin_width");
    let big = uniform(16_385, 4);
    assert_eq!(
        field(pair_correlation_naive(&big, 0.01, 0.1, &c)),
        "n_points"
    );
    // The cell list accepts it (few pair tests for a small r_max).
    assert!(pair_correlation(&big, 0.001, 0.01, &c).is_ok());
    // …but not all pairs of 200 000 points.
    let huge = uniform(200_000, 5);
    let e = pair_correlation(&huge, 0.01, 0.5, &c).unwrap_err();
    assert!(
        e.to_string().contains("n_points") && e.to_string().contains("r_max"),
        "{e}"
    );
    assert!(matches!(
        pair_correlation(&[], 0.01, 0.1, &c),
        Err(SpectrumError::EmptyPointSet)
    ));
    assert!(matches!(
        pair_correlation(&[DVec2::ZERO, DVec2::new(0.5, 1.5)], 0.01, 0.1, &c),
        Err(SpectrumError::InvalidPoint { index: 1, .. })
    ));
}

#[test]
fn cancelled_pair_correlation_stops() {
    let c = Cancel::new();
    c.cancel();
    let pts = uniform(2000, 6);
    assert!(matches!(
        pair_correlation(&pts, 0.01, 0.1, &c),
        Err(SpectrumError::Cancelled)
    ));
    assert!(matches!(
        pair_correlation_naive(&pts, 0.01, 0.1, &c),
        Err(SpectrumError::Cancelled)
    ));
}
