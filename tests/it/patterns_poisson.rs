//! Blue-noise patterns: dart throwing, Bridson, best candidate, tiling.
//!
//! References used here: (1) literal transcriptions of the lecture's dart-throwing pseudo-code and
//! of Mitchell's best candidate written in this file (full scans, no acceleration, no early exit);
//! (2) the crate's own naive references `dart_naive` and `best_candidate_naive`; (3) brute-force
//! O(N²) toroidal minimum distances. All seeds are fixed.

use glam::DVec2;
use samplescope::core::cancel::Cancel;
use samplescope::core::pattern::best_candidate::{best_candidate, best_candidate_naive, tile};
use samplescope::core::pattern::poisson::{
    bridson, bridson_min_radius, dart, dart_naive, default_radius, max_radius,
    DEFAULT_RADIUS_FRACTION,
};
use samplescope::core::pattern::{
    BestCandidate, Generated, Pattern, PatternError, PoissonBridson, PoissonDart, MAX_N,
};
use samplescope::core::rng::Rng;
use samplescope::core::torus;
use std::time::{Duration, Instant};

fn never() -> Cancel {
    Cancel::never()
}

/// Brute-force toroidal minimum distance (∞ for fewer than two points).
fn min_distance(points: &[DVec2]) -> f64 {
    let mut d = f64::INFINITY;
    for i in 0..points.len() {
        for j in 0..i {
            d = d.min(torus::distance(points[i], points[j], 1.0));
        }
    }
    d
}

fn in_unit_square(points: &[DVec2]) -> bool {
    points
        .iter()
        .all(|p| (0.0..1.0).contains(&p.x) && (0.0..1.0).contains(&p.y))
}

fn bits(points: &[DVec2]) -> Vec<(u64, u64)> {
    points
        .iter()
        .map(|p| (p.x.to_bits(), p.y.to_bits()))
        .collect()
}

fn assert_same_bits(a: &Generated, b: &Generated, what: &str) {
    assert_eq!(bits(&a.points), bits(&b.points), "{what}: points differ");
    assert_eq!(a.requested, b.requested, "{what}");
    assert_eq!(a.note, b.note, "{what}: notes differ");
}

/// Squared toroidal distance written out independently of the crate.
fn torus_d2(a: DVec2, b: DVec2) -> f64 {
    let mut dx = (a.x - b.x).abs();
    let mut dy = (a.y - b.y).abs();
    dx = dx.min(1.0 - dx);
    dy = dy.min(1.0 - dy);
    dx * dx + dy * dy
}

/// The lecture's dart-throwing pseudo-code, literally (with toroidal d and r = 2 r_p):
/// x_i ← unit(); y_i ← unit(); reject if d < (2 r_p)² for some k < i; plus the miss bound.
#[allow(clippy::needless_range_loop)] // kept as the slide writes it: `for k ← 0 to i − 1`
fn lecture_dart(n: usize, r: f64, max_misses: u32, seed: u64) -> Vec<DVec2> {
    let mut rng = Rng::new(seed);
    let mut pts: Vec<DVec2> = Vec::new();
    let mut misses = 0;
    let mut i = 0;
    while i < n {
        let x = rng.next_f64();
        let y = rng.next_f64();
        let c = DVec2::new(x, y);
        let mut reject = false;
        for k in 0..i {
            let d = torus_d2(c, pts[k]);
            if d < r * r {
                reject = true;
                break;
            }
        }
        if !reject {
            pts.push(c);
            i += 1;
            misses = 0;
        } else {
            misses += 1;
            if misses >= max_misses {
                break;
            }
        }
    }
    pts
}

/// Mitchell's best candidate, literally: full nearest-neighbour scans, first maximum wins.
fn mitchell(n: usize, m: u64, seed: u64) -> Vec<DVec2> {
    let mut rng = Rng::new(seed);
    let mut pts = vec![DVec2::new(rng.next_f64(), rng.next_f64())];
    for i in 1..n {
        let mut best = DVec2::ZERO;
        let mut best_d = -1.0;
        for _ in 0..(m * i as u64).max(1) {
            let q = DVec2::new(rng.next_f64(), rng.next_f64());
            let d = pts
                .iter()
                .map(|&p| torus_d2(q, p))
                .fold(f64::INFINITY, f64::min);
            if d > best_d {
                best_d = d;
                best = q;
            }
        }
        pts.push(best);
    }
    pts
}

// ---------------------------------------------------------------- dart throwing

#[test]
fn dart_min_distance_at_least_radius_over_20_seeds() {
    let n = 300;
    let d_max = max_radius(n);
    for fraction in [0.0, 0.3, 0.5, DEFAULT_RADIUS_FRACTION, 0.7] {
        let radius = fraction * d_max;
        let r = if fraction == 0.0 {
            default_radius(n)
        } else {
            radius
        };
        for seed in 0..20 {
            let p = PoissonDart {
                radius,
                max_misses: 100_000,
            };
            let g = dart(&p, n, seed, &never()).unwrap();
            assert!(in_unit_square(&g.points));
            assert!(g.points.len() <= n);
            let d = min_distance(&g.points);
            assert!(d >= r, "fraction {fraction}, seed {seed}: {d} < {r}");
            if fraction <= DEFAULT_RADIUS_FRACTION {
                assert_eq!(g.points.len(), n, "fraction {fraction}, seed {seed}");
                assert_eq!(g.note, None);
            }
        }
    }
}

#[test]
fn dart_grid_equals_naive_bit_for_bit_over_seeds_and_radii() {
    let n = 250;
    let d_max = max_radius(n);
    for fraction in [0.0, 0.05, 0.4, 0.65, 0.75, 0.9, 1.0] {
        for seed in 0..12 {
            let p = PoissonDart {
                radius: fraction * d_max,
                max_misses: 3000,
            };
            let fast = dart(&p, n, seed, &never()).unwrap();
            let naive = dart_naive(&p, n, seed, &never()).unwrap();
            assert_same_bits(&fast, &naive, &format!("fraction {fraction} seed {seed}"));
        }
    }
}

#[test]
fn dart_equals_the_lecture_pseudo_code() {
    for (n, fraction, misses, seed) in [
        (50usize, 0.5, 1000u32, 1u64),
        (200, 0.65, 100_000, 2),
        (200, 0.85, 500, 3),
    ] {
        let r = fraction * max_radius(n);
        let p = PoissonDart {
            radius: r,
            max_misses: misses,
        };
        let ours = dart(&p, n, seed, &never()).unwrap();
        assert_eq!(bits(&ours.points), bits(&lecture_dart(n, r, misses, seed)));
    }
}

#[test]
fn dart_grid_equals_naive_for_large_radii_and_tiny_grids() {
    // Radii ≥ 1/3 make grids of 1 or 2 cells per side: the neighbourhood wraps onto itself.
    for (n, radius) in [
        (1usize, 1.0),
        (2, 0.7),
        (3, 0.6),
        (4, 0.5),
        (6, 0.4),
        (9, 0.33),
    ] {
        assert!(radius <= max_radius(n));
        for seed in 0..10 {
            let p = PoissonDart {
                radius,
                max_misses: 200,
            };
            let fast = dart(&p, n, seed, &never()).unwrap();
            let naive = dart_naive(&p, n, seed, &never()).unwrap();
            assert_same_bits(&fast, &naive, &format!("n {n} r {radius} seed {seed}"));
            assert!(min_distance(&fast.points) >= radius);
        }
    }
}

#[test]
fn dart_near_the_packing_bound_terminates_with_a_note() {
    let n = 200;
    let r = 0.95 * max_radius(n);
    let p = PoissonDart {
        radius: r,
        max_misses: 2000,
    };
    let g = dart(&p, n, 7, &never()).unwrap();
    let placed = g.points.len();
    assert!(placed < n, "placed {placed}");
    assert_eq!(g.requested, n);
    let note = g.note.expect("a note when fewer points are placed");
    assert!(
        note.starts_with(&format!(
            "placed {placed} of {n} points; gave up after 2000 consecutive misses at radius {}",
            samplescope::core::params::fmt_num(r)
        )),
        "{note}"
    );
    assert!(note.contains("relative radius r/d_max = 0.9500"), "{note}");
    // The note names the parameters that would place the rest.
    assert!(
        note.ends_with("raise max_misses (now 2000) or lower radius"),
        "{note}"
    );
    assert!(min_distance(&g.points) >= r);
    // The dispatcher keeps the points and the note.
    let via = Pattern::PoissonDart(p)
        .generate_with(n, 7, &never())
        .unwrap();
    assert_eq!(via, dart(&p, n, 7, &never()).unwrap());
}

#[test]
fn dart_with_max_misses_one_stops_at_the_first_rejection() {
    let n = 100;
    let p = PoissonDart {
        radius: 0.65 * max_radius(n),
        max_misses: 1,
    };
    let g = dart(&p, n, 3, &never()).unwrap();
    assert!(g.points.len() < n);
    assert_eq!(bits(&g.points), bits(&lecture_dart(n, p.radius, 1, 3)));
    assert!(g
        .note
        .unwrap()
        .contains("gave up after 1 consecutive misses"));
}

// ---------------------------------------------------------------- Bridson

#[test]
fn bridson_min_distance_at_least_radius_over_20_seeds() {
    let n = 300;
    let d_max = max_radius(n);
    for fraction in [0.0, 0.3, 0.5, DEFAULT_RADIUS_FRACTION, 0.8] {
        let r = if fraction == 0.0 {
            default_radius(n)
        } else {
            fraction * d_max
        };
        for seed in 0..20 {
            let p = PoissonBridson {
                radius: fraction * d_max,
                k: 30,
            };
            let g = bridson(&p, n, seed, &never()).unwrap();
            assert!(in_unit_square(&g.points));
            let d = min_distance(&g.points);
            assert!(d >= r, "fraction {fraction}, seed {seed}: {d} < {r}");
            if fraction <= DEFAULT_RADIUS_FRACTION {
                assert_eq!(g.points.len(), n, "fraction {fraction} seed {seed}");
                assert_eq!(g.note, None);
            }
        }
    }
}

#[test]
fn bridson_returns_exactly_n_points_at_the_default_radius() {
    for n in [1usize, 2, 100, 4096] {
        let seeds = if n == 4096 { 0..3 } else { 0..20 };
        for seed in seeds {
            let g = bridson(&PoissonBridson::default(), n, seed, &never()).unwrap();
            assert_eq!(g.points.len(), n, "n {n} seed {seed}");
            assert_eq!(g.note, None);
            assert!(in_unit_square(&g.points));
            if n <= 100 {
                assert!(min_distance(&g.points) >= default_radius(n));
            }
        }
    }
}

#[test]
fn bridson_maximal_set_leaves_little_room_for_another_disk() {
    // At radius 0.9 d_max(n) the maximal set has fewer than n points and is returned whole.
    // Bridson's set is maximal up to its k-sample test: random darts should almost never fit.
    let n = 400;
    let r = 0.9 * max_radius(n);
    let p = PoissonBridson { radius: r, k: 30 };
    let g = bridson(&p, n, 5, &never()).unwrap();
    let m = g.points.len();
    assert!(m < n);
    let note = g.note.unwrap();
    assert!(
        note.starts_with(&format!("placed {m} of {n} points")),
        "{note}"
    );
    // The achieved relative radius r/d_max(M) of Bridson's maximal sets (k = 30) is ≈ 0.73
    // (measured over n = 10 … 65 536); random sequential adsorption saturates near 0.75.
    let rho = r / max_radius(m);
    assert!((0.68..0.78).contains(&rho), "relative radius {rho}");
    let mut rng = Rng::new(99);
    let darts = 20_000;
    let fits = (0..darts)
        .filter(|_| {
            let q = DVec2::new(rng.next_f64(), rng.next_f64());
            g.points.iter().all(|&x| torus::distance(q, x, 1.0) >= r)
        })
        .count();
    assert!(
        (fits as f64) < 0.01 * darts as f64,
        "{fits} of {darts} darts fit"
    );
}

#[test]
fn bridson_small_radius_is_a_subset_with_min_distance_kept() {
    // r = 0.3 d_max: the maximal set has ≈ 5× more points; a random subset of n is returned.
    let n = 200;
    let r = 0.3 * max_radius(n);
    let g = bridson(&PoissonBridson { radius: r, k: 30 }, n, 4, &never()).unwrap();
    assert_eq!(g.points.len(), n);
    assert!(min_distance(&g.points) >= r);
}

#[test]
fn bridson_radius_below_its_minimum_is_invalid_param() {
    let r = 0.5 * bridson_min_radius();
    let err = bridson(&PoissonBridson { radius: r, k: 30 }, 10, 1, &never()).unwrap_err();
    assert!(
        matches!(
            err,
            PatternError::InvalidParam {
                field: "radius",
                ..
            }
        ),
        "{err}"
    );
    // The default radius at MAX_N points is allowed.
    assert!(default_radius(MAX_N) >= bridson_min_radius());
}

// ---------------------------------------------------------------- validation

#[test]
fn radius_above_the_packing_bound_is_rejected_before_any_work() {
    let n = 16_000_000;
    let radius = 0.01;
    assert!(radius > max_radius(n));
    let start = Instant::now();
    let e1 = dart(
        &PoissonDart {
            radius,
            max_misses: 100_000,
        },
        n,
        1,
        &never(),
    )
    .unwrap_err();
    let e2 = dart_naive(
        &PoissonDart {
            radius,
            max_misses: 100_000,
        },
        n,
        1,
        &never(),
    )
    .unwrap_err();
    let e3 = bridson(&PoissonBridson { radius, k: 30 }, n, 1, &never()).unwrap_err();
    // Placing 16 M points would take many seconds: the errors come without any work.
    assert!(start.elapsed() < Duration::from_millis(500));
    for (e, name) in [
        (e1, "poisson-dart"),
        (e2, "poisson-dart"),
        (e3, "poisson-bridson"),
    ] {
        assert_eq!(
            e,
            PatternError::RadiusTooLarge {
                pattern: name,
                radius,
                n,
                max: max_radius(n)
            }
        );
    }
}

#[test]
fn bad_parameters_are_typed_errors() {
    for radius in [f64::NAN, -0.1, 1.5, f64::INFINITY] {
        let e = dart(
            &PoissonDart {
                radius,
                max_misses: 10,
            },
            10,
            1,
            &never(),
        )
        .unwrap_err();
        assert!(
            matches!(
                e,
                PatternError::InvalidParam {
                    field: "radius",
                    ..
                }
            ),
            "{e}"
        );
        let e = bridson(&PoissonBridson { radius, k: 30 }, 10, 1, &never()).unwrap_err();
        assert!(
            matches!(
                e,
                PatternError::InvalidParam {
                    field: "radius",
                    ..
                }
            ),
            "{e}"
        );
    }
    let e = dart(
        &PoissonDart {
            radius: 0.0,
            max_misses: 0,
        },
        10,
        1,
        &never(),
    )
    .unwrap_err();
    assert!(matches!(
        e,
        PatternError::InvalidParam {
            field: "max_misses",
            ..
        }
    ));
    for k in [0, 1001] {
        let e = bridson(&PoissonBridson { radius: 0.0, k }, 10, 1, &never()).unwrap_err();
        assert!(matches!(e, PatternError::InvalidParam { field: "k", .. }));
    }
    for n in [0, MAX_N + 1] {
        assert!(matches!(
            dart(&PoissonDart::default(), n, 1, &never()),
            Err(PatternError::InvalidN { .. })
        ));
        assert!(matches!(
            bridson(&PoissonBridson::default(), n, 1, &never()),
            Err(PatternError::InvalidN { .. })
        ));
        assert!(matches!(
            best_candidate(&BestCandidate::default(), n, 1, &never()),
            Err(PatternError::InvalidN { .. })
        ));
    }
}

#[test]
fn cancelled_token_before_the_call_returns_cancelled() {
    let c = Cancel::new();
    c.cancel();
    assert_eq!(
        dart(&PoissonDart::default(), 1000, 1, &c),
        Err(PatternError::Cancelled)
    );
    assert_eq!(
        dart_naive(&PoissonDart::default(), 1000, 1, &c),
        Err(PatternError::Cancelled)
    );
    assert_eq!(
        bridson(&PoissonBridson::default(), 1000, 1, &c),
        Err(PatternError::Cancelled)
    );
    assert_eq!(
        best_candidate(&BestCandidate::default(), 1000, 1, &c),
        Err(PatternError::Cancelled)
    );
    assert_eq!(
        best_candidate_naive(&BestCandidate::default(), 1000, 1, &c),
        Err(PatternError::Cancelled)
    );
    for pattern in [
        Pattern::PoissonDart(PoissonDart::default()),
        Pattern::PoissonBridson(PoissonBridson::default()),
        Pattern::BestCandidate(BestCandidate::default()),
    ] {
        assert_eq!(
            pattern.generate_with(1000, 1, &c),
            Err(PatternError::Cancelled)
        );
    }
}

#[test]
fn cancel_from_another_thread_stops_a_long_best_candidate() {
    // 20 000 points with m = 50 is 10¹⁰ candidates (minutes); cancelling must stop it promptly.
    let c = Cancel::new();
    let c2 = c.clone();
    let handle =
        std::thread::spawn(move || best_candidate(&BestCandidate { m: 50 }, 20_000, 1, &c2));
    std::thread::sleep(Duration::from_millis(50));
    c.cancel();
    assert_eq!(handle.join().unwrap(), Err(PatternError::Cancelled));
}

#[test]
fn cancel_from_another_thread_stops_long_dart_and_bridson_runs() {
    // Millions of points take seconds; a cancel after 20 ms must end both with Cancelled.
    let c = Cancel::new();
    let (c1, c2) = (c.clone(), c.clone());
    let d = std::thread::spawn(move || dart(&PoissonDart::default(), 4_000_000, 1, &c1));
    let b = std::thread::spawn(move || bridson(&PoissonBridson::default(), 4_000_000, 1, &c2));
    std::thread::sleep(Duration::from_millis(20));
    c.cancel();
    assert_eq!(d.join().unwrap(), Err(PatternError::Cancelled));
    assert_eq!(b.join().unwrap(), Err(PatternError::Cancelled));
}

// ---------------------------------------------------------------- best candidate

#[test]
fn best_candidate_grid_equals_naive_bit_for_bit() {
    for m in [1u32, 2, 5] {
        for seed in 0..8 {
            let n = if m == 1 { 300 } else { 150 };
            let p = BestCandidate { m };
            let fast = best_candidate(&p, n, seed, &never()).unwrap();
            let naive = best_candidate_naive(&p, n, seed, &never()).unwrap();
            assert_eq!(bits(&fast), bits(&naive), "m {m} seed {seed}");
        }
    }
    // One larger run crossing several grid rebuilds (powers of two up to 1024).
    let p = BestCandidate { m: 1 };
    let fast = best_candidate(&p, 1100, 42, &never()).unwrap();
    let naive = best_candidate_naive(&p, 1100, 42, &never()).unwrap();
    assert_eq!(bits(&fast), bits(&naive));
}

#[test]
fn best_candidate_equals_mitchell_full_scan() {
    for (n, m, seed) in [(120usize, 1u32, 3u64), (60, 4, 8)] {
        let ours = best_candidate(&BestCandidate { m }, n, seed, &never()).unwrap();
        assert_eq!(bits(&ours), bits(&mitchell(n, m as u64, seed)));
    }
}

#[test]
fn best_candidate_is_progressive_and_well_spread() {
    let n = 1024;
    let pts = best_candidate(&BestCandidate::default(), n, 9, &never()).unwrap();
    assert_eq!(pts.len(), n);
    assert!(in_unit_square(&pts));
    // Prefix property: the first k points are exactly the k-point pattern.
    let prefix = best_candidate(&BestCandidate::default(), 100, 9, &never()).unwrap();
    assert_eq!(bits(&pts[..100]), bits(&prefix));
    // Much better spread than white noise: relative min distance well above random's (≈ 0.05 at
    // this n); Mitchell's patterns typically reach 0.4–0.6 of the packing distance.
    for k in [64usize, 256, 1024] {
        let rho = min_distance(&pts[..k]) / max_radius(k);
        assert!(rho > 0.3, "k {k}: relative min distance {rho}");
    }
}

#[test]
fn best_candidate_n_one_and_two() {
    let one = best_candidate(&BestCandidate::default(), 1, 5, &never()).unwrap();
    let mut rng = Rng::new(5);
    assert_eq!(
        bits(&one),
        bits(&[DVec2::new(rng.next_f64(), rng.next_f64())])
    );
    let two = best_candidate(&BestCandidate::default(), 2, 5, &never()).unwrap();
    // Point 1 is the single candidate drawn after point 0 (m·1 = 1 candidate).
    assert_eq!(
        bits(&two[1..]),
        bits(&[DVec2::new(rng.next_f64(), rng.next_f64())])
    );
}

// ---------------------------------------------------------------- determinism

#[test]
fn same_seed_same_bits_and_different_seeds_differ() {
    let n = 500;
    let patterns = [
        Pattern::PoissonDart(PoissonDart::default()),
        Pattern::PoissonBridson(PoissonBridson::default()),
        Pattern::BestCandidate(BestCandidate::default()),
    ];
    for pattern in patterns {
        let a = pattern.generate(n, 17).unwrap();
        let b = pattern.generate(n, 17).unwrap();
        let c = pattern.generate(n, 18).unwrap();
        assert_eq!(a.len(), n, "{}", pattern.name());
        assert_eq!(bits(&a), bits(&b), "{}", pattern.name());
        assert_ne!(bits(&a), bits(&c), "{}", pattern.name());
        assert!(in_unit_square(&a));
    }
}

// ---------------------------------------------------------------- tiling

#[test]
fn tile_is_seamless_and_counts_right() {
    let base = best_candidate(&BestCandidate::default(), 64, 3, &never()).unwrap();
    let inside = min_distance(&base);
    for t in [1usize, 2, 3] {
        let tiled = tile(&base, t, t).unwrap();
        assert_eq!(tiled.len(), base.len() * t * t);
        assert!(in_unit_square(&tiled));
        // Toroidal minimum distance of the tiled set = the tile's toroidal one, scaled by 1/t.
        let whole = min_distance(&tiled);
        let expected = inside / t as f64;
        assert!(
            (whole - expected).abs() <= 1e-12 * expected,
            "t {t}: {whole} vs {expected}"
        );
        // Pairs in different copies (across tile borders) are never closer than that.
        let tile_of = |i: usize| i / base.len();
        let mut across = f64::INFINITY;
        for i in 0..tiled.len() {
            for j in 0..i {
                if tile_of(i) != tile_of(j) {
                    across = across.min(torus::distance(tiled[i], tiled[j], 1.0));
                }
            }
        }
        if t > 1 {
            assert!(
                across >= expected * (1.0 - 1e-12),
                "t {t}: {across} < {expected}"
            );
        }
    }
    // Copy (t_x, t_y) = (1, 0) of point 0 is ((1 + x)/2, y/2).
    let two = tile(&base, 2, 3).unwrap();
    assert_eq!(two.len(), 64 * 6);
    assert_eq!(
        two[64],
        DVec2::new((1.0 + base[0].x) / 2.0, base[0].y / 3.0)
    );
}

#[test]
fn tile_rejects_zero_empty_out_of_range_and_overflow() {
    let p = [DVec2::new(0.25, 0.5), DVec2::new(0.75, 0.1)];
    assert!(matches!(
        tile(&p, 0, 2),
        Err(PatternError::InvalidParam {
            field: "tiles_x",
            ..
        })
    ));
    assert!(matches!(
        tile(&p, 2, 0),
        Err(PatternError::InvalidParam {
            field: "tiles_y",
            ..
        })
    ));
    assert!(matches!(
        tile(&[], 2, 2),
        Err(PatternError::InvalidParam { field: "tile", .. })
    ));
    for bad in [
        DVec2::new(1.0, 0.5),
        DVec2::new(-0.1, 0.5),
        DVec2::new(f64::NAN, 0.5),
    ] {
        assert!(matches!(
            tile(&[bad], 2, 2),
            Err(PatternError::InvalidParam { field: "tile", .. })
        ));
    }
    assert!(matches!(
        tile(&p, usize::MAX, 2),
        Err(PatternError::InvalidN { n: usize::MAX, .. })
    ));
    assert!(matches!(
        tile(&p, 4096, 4096),
        Err(PatternError::InvalidN { n: 33_554_432, .. })
    ));
}
