//! The measures of point sets in [0,1)^d (`core::metrics::cube`): the five L2 discrepancies
//! against scipy.stats.qmc.discrepancy and a 50-digit evaluation of the same formulas
//! (`tests/data/scipy/discrepancy`, written by `scripts/reference-scipy-discrepancy.py`), the
//! fast paths against their references, D in {1, 2, 3, 8, 32}, and the errors.
//!
//! **Tolerances.** The formulas end in `A − t₁ + t₂`, three terms up to κ = (|A| + t₁ + t₂) /
//! |value| times the result (κ up to ~10⁶ for the 2D Sobol' set). Even the exact terms,
//! rounded once to f64, would leave an error of one ulp of their scale S = |A| + t₁ + t₂
//! after the cancellation; our fast path rounds each pair's product of d factors in f64 (errors
//! of both signs that average out) and sums in double-double, so it must be within
//! **1e-12 relative plus ε·S** of the 50-digit value (on the squares for the L2-star
//! discrepancy, whose S is that of T²): 1e-12 relative where κ is small, the one-ulp-of-the-terms
//! limit where it is large (observed errors are ~1% of that). scipy sums N² terms in plain f64
//! and is itself far from the 50-digit value (CD of the 1D set: 2·10⁻¹⁰ relative, ~20 ε·S), so
//! against scipy the test asks that ours be at least as close to the exact value as scipy is,
//! plus 1e-12: `|ours − scipy| ≤ |scipy − exact| + 1e-12·|exact|`. The naive path (scipy's
//! loops, literally) must reproduce scipy's own value to 1e-15 of the terms' scale (the order
//! of operations is scipy's; only `pow` and `x**2` may round differently).

use samplescope::core::cancel::Cancel;
use samplescope::core::cube::CubePoints;
use samplescope::core::metrics::cube::{
    discrepancies, discrepancy, discrepancy_naive, discrepancy_reference, min_distance_cube,
    min_distance_cube_naive, projection_table, projection_table_naive, stratification,
    stratification_naive, CubeMeasure, Discrepancy, DISCREPANCY_MAX_DIMS, PROJECTION_MAX_DIMS,
};
use samplescope::core::metrics::{self, MetricsError};
use samplescope::core::progress::{no_progress, Progress};
use samplescope::core::rng::Rng;
use serde_json::Value;
use std::path::Path;

fn data_dir() -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/scipy/discrepancy")
}

/// The points of one reference set (header x0,…, comma-separated, 17 significant digits).
fn read_set(name: &str) -> CubePoints {
    let text = std::fs::read_to_string(data_dir().join(format!("{name}.csv"))).unwrap();
    let (header, rows) = crate::parse_csv(&text);
    CubePoints::new(header.split(',').count(), rows.concat()).unwrap()
}

/// Whether `ours` is within 1e-12 relative of `exact` plus one ulp of the terms' scale (for
/// the L2-star discrepancy, on the squares, the terms being those of T²): as close as the
/// exact terms rounded once and cancelled would be.
fn close(which: Discrepancy, ours: f64, exact: f64, scale: f64) -> bool {
    let (o, e) = if which == Discrepancy::L2Star {
        (ours * ours, exact * exact)
    } else {
        (ours, exact)
    };
    (o - e).abs() <= 1e-12 * e.abs() + f64::EPSILON * scale
}

fn method(which: Discrepancy) -> &'static str {
    which.scipy_method().unwrap_or("SD")
}

fn never() -> Cancel {
    Cancel::never()
}

fn fast(points: &CubePoints, which: Discrepancy) -> f64 {
    discrepancy(points, which, &never(), &mut no_progress).unwrap()
}

#[test]
fn the_five_discrepancies_equal_scipy_and_the_50_digit_formula() {
    let meta: Value =
        serde_json::from_str(&std::fs::read_to_string(data_dir().join("values.json")).unwrap())
            .unwrap();
    let sets = meta["sets"].as_array().unwrap();
    let mut dims_seen: Vec<u64> = sets.iter().map(|s| s["dims"].as_u64().unwrap()).collect();
    dims_seen.dedup();
    assert_eq!(dims_seen, vec![1, 2, 3, 8, 32]);
    for set in sets {
        let name = set["name"].as_str().unwrap();
        let points = read_set(name);
        assert_eq!(points.n() as u64, set["n"].as_u64().unwrap(), "{name}");
        assert_eq!(
            points.dims() as u64,
            set["dims"].as_u64().unwrap(),
            "{name}"
        );
        let all = discrepancies(&points, &never(), &mut no_progress).unwrap();
        for which in Discrepancy::ALL {
            let v = &set["values"][method(which)];
            let exact: f64 = v["reference"].as_str().unwrap().parse().unwrap();
            let scale = v["terms"].as_f64().unwrap();
            let ours = fast(&points, which);
            assert_eq!(ours.to_bits(), all.get(which).to_bits(), "{name} {which:?}");
            assert!(
                close(which, ours, exact, scale),
                "{name} {which:?}: {ours:e} vs exact {exact:e} (rel {:e}, terms {scale:e})",
                (ours - exact).abs() / exact.abs()
            );
            // The double-double reference is exact to the last bits here.
            let dd = discrepancy_reference(&points, which, &never()).unwrap();
            assert!(
                (dd - exact).abs() <= 4.0 * f64::EPSILON * exact.abs(),
                "{name} {which:?}: double-double {dd:e} vs exact {exact:e}"
            );
            let naive = discrepancy_naive(&points, which, &never()).unwrap();
            match v["scipy"].as_f64() {
                Some(scipy) => {
                    assert!(
                        (ours - scipy).abs() <= (scipy - exact).abs() + 1e-12 * exact.abs(),
                        "{name} {which:?}: ours {ours:e}, scipy {scipy:e}, exact {exact:e}"
                    );
                    // scipy's loops, literally: scipy's value up to pow's last bit. (For the
                    // root, relative to the value; otherwise to the terms' scale.)
                    let tol = if which == Discrepancy::L2Star {
                        1e-15 * scale / scipy
                    } else {
                        1e-15 * scale
                    };
                    assert!(
                        (naive - scipy).abs() <= tol,
                        "{name} {which:?}: naive {naive:e} vs scipy {scipy:e}"
                    );
                }
                None => {
                    // No scipy value: the naive path within the classical bound of a plain
                    // running sum of N² terms.
                    assert_eq!(which, Discrepancy::Symmetric);
                    let n = points.n() as f64;
                    let bound = n * n * f64::EPSILON * scale;
                    assert!(
                        (naive - exact).abs() <= bound,
                        "{name} SD naive {naive:e} vs {exact:e}"
                    );
                }
            }
        }
    }
}

/// N random points in [0,1)^d.
fn random(n: usize, d: usize, seed: u64) -> CubePoints {
    let mut r = Rng::new(seed);
    CubePoints::new(d, (0..n * d).map(|_| r.next_f64()).collect()).unwrap()
}

/// A Korobov rank-1 lattice with generator a (x_ik = {i·a^k / N}): low discrepancy, so the
/// terms cancel deeply.
fn korobov(n: usize, d: usize, a: usize) -> CubePoints {
    let mut g = vec![1usize; d];
    for k in 1..d {
        g[k] = g[k - 1] * a % n;
    }
    let coords = (0..n)
        .flat_map(|i| {
            g.iter()
                .map(move |&gk| (i * gk % n) as f64 / n as f64)
                .collect::<Vec<_>>()
        })
        .collect();
    CubePoints::new(d, coords).unwrap()
}

#[test]
fn at_larger_n_the_fast_path_stays_as_close_to_double_double() {
    for points in [
        random(1024, 8, 5),
        korobov(1021, 8, 76),
        korobov(2048, 3, 1173),
    ] {
        let d = points.dims() as i32;
        for which in Discrepancy::ALL {
            let f = fast(&points, which);
            let r = discrepancy_reference(&points, which, &never()).unwrap();
            // The three terms are each about |A(d)| (a lower bound of their scale).
            let a = match which {
                Discrepancy::L2Star => 3f64.powi(-d),
                Discrepancy::Centered => (13.0f64 / 12.0).powi(d),
                Discrepancy::WrapAround | Discrepancy::Symmetric => (4.0f64 / 3.0).powi(d),
                Discrepancy::Mixture => (19.0f64 / 12.0).powi(d),
            };
            assert!(
                close(which, f, r, a),
                "n = {} {which:?}: {f:e} vs {r:e}",
                points.n()
            );
        }
    }
}

#[test]
fn in_two_dimensions_the_l2_star_discrepancy_is_the_2d_one() {
    for seed in 0..3 {
        let p = random(500, 2, seed);
        let two = metrics::l2_star_discrepancy(&p.to_2d().unwrap(), &never()).unwrap();
        let d = fast(&p, Discrepancy::L2Star);
        assert!((d - two).abs() <= 1e-13 * two, "{d:e} vs {two:e}");
    }
}

#[test]
fn results_do_not_depend_on_the_number_of_threads() {
    let p = random(700, 5, 9);
    let run = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| {
            let d = discrepancies(&p, &never(), &mut no_progress).unwrap();
            let m = min_distance_cube(&p, &never(), &mut no_progress).unwrap();
            let t = projection_table(&p, &never(), &mut no_progress).unwrap();
            (
                Discrepancy::ALL.map(|w| d.get(w).to_bits()),
                m.min_distance.to_bits(),
                m.pair,
                format!("{t:?}"),
            )
        })
    };
    assert_eq!(run(1), run(3));
}

#[test]
fn the_minimum_distance_is_the_naive_one_bit_for_bit() {
    for (n, d) in [
        (2usize, 1usize),
        (300, 1),
        (400, 2),
        (300, 3),
        (200, 8),
        (120, 32),
    ] {
        let p = random(n, d, (n * d) as u64);
        let f = min_distance_cube(&p, &never(), &mut no_progress).unwrap();
        let naive = min_distance_cube_naive(&p, &never()).unwrap();
        assert_eq!(
            f.min_distance.to_bits(),
            naive.min_distance.to_bits(),
            "{n} {d}"
        );
        assert_eq!(f.pair, naive.pair);
        assert!(f.pair.0 < f.pair.1);
        if d == 2 {
            let two = metrics::min_distance(&p.to_2d().unwrap(), &never()).unwrap();
            assert_eq!(two.min_distance.to_bits(), f.min_distance.to_bits());
            assert_eq!(two.pair, f.pair);
        }
    }
    // Duplicates: distance 0, the first pair; across the seam: the wrapped distance.
    let p = CubePoints::new(
        3,
        vec![0.5, 0.5, 0.5, 0.1, 0.2, 0.3, 0.1, 0.2, 0.3, 0.1, 0.2, 0.3],
    )
    .unwrap();
    let m = min_distance_cube(&p, &never(), &mut no_progress).unwrap();
    assert_eq!((m.min_distance, m.pair), (0.0, (1, 2)));
    let p = CubePoints::new(3, vec![0.0, 0.5, 0.5, 0.75, 0.5, 0.5, 0.375, 0.0, 0.0]).unwrap();
    let m = min_distance_cube(&p, &never(), &mut no_progress).unwrap();
    assert_eq!((m.min_distance, m.pair), (0.25, (0, 1)));
}

/// A Latin hypercube: each dimension a random permutation of the N strata, jittered.
fn latin(n: usize, d: usize, seed: u64) -> CubePoints {
    let mut r = Rng::new(seed);
    let mut coords = vec![0.0; n * d];
    for k in 0..d {
        let mut perm: Vec<usize> = (0..n).collect();
        for i in (1..n).rev() {
            perm.swap(i, (r.next_u64() % (i as u64 + 1)) as usize);
        }
        for i in 0..n {
            coords[i * d + k] = (perm[i] as f64 + r.next_f64()) / n as f64;
        }
    }
    CubePoints::new(d, coords).unwrap()
}

#[test]
fn stratification_finds_latin_hypercubes_and_the_defect_of_a_random_set() {
    for (n, d) in [(1usize, 1usize), (64, 3), (100, 8), (37, 32)] {
        let p = latin(n, d, 3);
        let s = stratification(&p, &never()).unwrap();
        assert!(s.iter().all(|s| s.stratified), "{n} {d}");
        assert_eq!(stratification_naive(&p).unwrap(), vec![true; d]);
    }
    let p = random(100, 8, 1);
    let s = stratification(&p, &never()).unwrap();
    assert_eq!(
        s.iter().map(|s| s.stratified).collect::<Vec<_>>(),
        stratification_naive(&p).unwrap()
    );
    assert!(s.iter().all(|s| !s.stratified));
    let s0 = s[0];
    assert!(s0.empty_interval.is_some() && s0.crowded_interval.unwrap().1 >= 2);
    // Boundaries belong to the upper interval, exactly, also for N not a power of two: with
    // N = 3, fl(1/3) < 1/3 lies in interval 0, so {0, fl(1/3), fl(2/3)} is not stratified.
    let third = CubePoints::new(1, vec![0.0, 1.0 / 3.0, 2.0 / 3.0]).unwrap();
    assert!(!stratification(&third, &never()).unwrap()[0].stratified);
    assert_eq!(stratification_naive(&third).unwrap(), vec![false]);
    let fifths = CubePoints::new(1, vec![0.0, 0.25, 0.5, 0.75]).unwrap();
    assert!(stratification(&fifths, &never()).unwrap()[0].stratified);
}

#[test]
fn the_projection_table_is_the_naive_one_worst_first() {
    // Dimension 3 repeats dimension 0: the pair (0, 3) lies on the diagonal, t = m.
    let base = korobov(256, 4, 93);
    let mut coords = base.coords().to_vec();
    for i in 0..256 {
        coords[i * 4 + 3] = coords[i * 4];
    }
    let p = CubePoints::new(4, coords).unwrap();
    let mut seen = Vec::new();
    let t = projection_table(&p, &never(), &mut |q: Progress<'_, ()>| {
        seen.push((q.done, q.total))
    })
    .unwrap();
    assert_eq!(seen.last(), Some(&(6, 6)));
    assert_eq!(t.len(), 6);
    assert_eq!(t[0].dims, [0, 3]);
    // On the diagonal every half holds half the points, no quadrant split does: t = m − 1.
    assert_eq!(t[0].t_value, Some(7));
    assert_eq!(t[0].min_distance, Some(std::f64::consts::SQRT_2 / 256.0));
    for w in t.windows(2) {
        let (a, b) = (&w[0], &w[1]);
        assert!(
            a.t_value > b.t_value
                || (a.t_value == b.t_value && a.l2_star_discrepancy >= b.l2_star_discrepancy)
        );
    }
    let naive = projection_table_naive(&p, &never()).unwrap();
    for (f, r) in t.iter().zip(&naive) {
        assert_eq!(
            (f.dims, f.t_value, f.min_distance),
            (r.dims, r.t_value, r.min_distance)
        );
        assert!(
            (f.l2_star_discrepancy - r.l2_star_discrepancy).abs() <= 1e-12 * r.l2_star_discrepancy
        );
    }
    // Each row is the 2D statistics of the projection.
    let two = p.project(1, 2).unwrap();
    let row = t.iter().find(|r| r.dims == [1, 2]).unwrap();
    assert_eq!(
        row.l2_star_discrepancy,
        metrics::l2_star_discrepancy(&two, &never()).unwrap()
    );
    assert_eq!(
        row.t_value,
        Some(metrics::t_value(&two, 2, &never()).unwrap().t)
    );
    // N not a power of two: no t-value, rows ordered by the discrepancy.
    let t = projection_table(&random(100, 3, 2), &never(), &mut no_progress).unwrap();
    assert!(t.iter().all(|r| r.t_value.is_none()));
    assert!(t[0].l2_star_discrepancy >= t[1].l2_star_discrepancy);
}

#[test]
fn limits_cancellation_and_progress() {
    let c = never();
    let wide = random(2, DISCREPANCY_MAX_DIMS + 1, 1);
    assert_eq!(
        discrepancy(&wide, Discrepancy::Centered, &c, &mut no_progress)
            .unwrap_err()
            .to_string(),
        "the L2 discrepancies accepts at most 512 dimensions (their terms 3^-d and 2^d leave \
         the range of f64), got dims = 513"
    );
    let p33 = random(4, PROJECTION_MAX_DIMS + 1, 1);
    assert!(matches!(
        projection_table(&p33, &c, &mut no_progress),
        Err(MetricsError::TooManyDims {
            dims: 33,
            max: 32,
            ..
        })
    ));
    assert!(CubeMeasure::Projections
        .skipped(4, 33)
        .unwrap()
        .contains("dims = 33 > 32"));
    assert!(CubeMeasure::Projections.skipped(4, 32).is_none());
    assert!(matches!(
        projection_table(&random(4, 1, 1), &c, &mut no_progress),
        Err(MetricsError::TooFewDims { dims: 1, .. })
    ));
    assert!(matches!(
        min_distance_cube(&random(1, 3, 1), &c, &mut no_progress),
        Err(MetricsError::TooFewPoints { n: 1, .. })
    ));
    // A point set made without checks (from 2D points) is checked by the measures.
    let outside = CubePoints::from_2d(&[glam::DVec2::new(0.5, 1.5)]);
    assert_eq!(
        discrepancy(&outside, Discrepancy::L2Star, &c, &mut no_progress)
            .unwrap_err()
            .to_string(),
        "point 0, x1 = 1.5: must be a number in [0, 1)"
    );
    let cancelled = Cancel::new();
    cancelled.cancel();
    let p = random(300, 4, 1);
    assert_eq!(
        discrepancies(&p, &cancelled, &mut no_progress),
        Err(MetricsError::Cancelled)
    );
    assert_eq!(
        min_distance_cube(&p, &cancelled, &mut no_progress),
        Err(MetricsError::Cancelled)
    );
    assert_eq!(
        projection_table(&p, &cancelled, &mut no_progress),
        Err(MetricsError::Cancelled)
    );
    // Progress counts up to the total.
    let mut last = (0, 0);
    discrepancies(&p, &c, &mut |q: Progress<'_, ()>| {
        assert!(q.done >= last.0 && q.done <= q.total);
        last = (q.done, q.total);
    })
    .unwrap();
    assert_eq!(last, (5 * 300 * 301 / 2, 5 * 300 * 301 / 2));
    let mut last = (0, 0);
    min_distance_cube(&p, &c, &mut |q: Progress<'_, ()>| last = (q.done, q.total)).unwrap();
    assert_eq!(last, (300 * 299 / 2, 300 * 299 / 2));
}
