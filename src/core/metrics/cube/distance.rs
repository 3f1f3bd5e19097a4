//! The minimum toroidal distance of a point set in [0,1)^d: `min_{i<j} d(x_i, x_j)` with the
//! one d-dimensional toroidal distance [`crate::core::torus::distance_squared_cube`] (at d = 2
//! the same bits as [`crate::core::metrics::min_distance`]'s distance), and the pair attaining
//! it (the lexicographically smallest among ties, so both paths return the same pair).

use std::sync::atomic::{AtomicU64, Ordering};

use rayon::prelude::*;
use serde::Serialize;

use super::{check_cube, pair_batches};
use crate::core::cube::CubePoints;
use crate::core::metrics::{Cancel, MetricsError};
use crate::core::progress::{OnProgress, Progress};
use crate::core::torus::{axis_gap, distance_squared_cube};

/// [`min_distance_cube_naive`] accepts at most this many points.
pub const MIN_DISTANCE_CUBE_NAIVE_MAX_N: usize = 1 << 14;

/// The closest pair of a point set in [0,1)^d on the torus.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct CubeMinDistance {
    /// The toroidal distance of the closest pair (0 for duplicates).
    pub min_distance: f64,
    /// Its indices `(i, j)`, `i < j`, the lexicographically smallest among ties.
    pub pair: (usize, usize),
}

fn check_two(points: &CubePoints) -> Result<(), MetricsError> {
    check_cube(points)?;
    if points.n() < 2 {
        return Err(MetricsError::TooFewPoints {
            what: "a minimum distance",
            n: points.n(),
            min: 2,
        });
    }
    Ok(())
}

/// Every pair measured in full, serially: the reference of [`min_distance_cube`].
///
/// Errors: fewer than 2 points, invalid points, more than [`MIN_DISTANCE_CUBE_NAIVE_MAX_N`]
/// points, cancellation.
pub fn min_distance_cube_naive(
    points: &CubePoints,
    cancel: &Cancel,
) -> Result<CubeMinDistance, MetricsError> {
    check_two(points)?;
    let n = points.n();
    if n > MIN_DISTANCE_CUBE_NAIVE_MAX_N {
        return Err(MetricsError::TooManyPoints {
            what: "min_distance_cube_naive",
            n,
            max: MIN_DISTANCE_CUBE_NAIVE_MAX_N,
            cost: "O(N²·d)",
        });
    }
    let mut best = (f64::INFINITY, (usize::MAX, usize::MAX));
    for i in 0..n {
        if i % 64 == 0 {
            cancel.check()?;
        }
        for j in i + 1..n {
            let d2 = distance_squared_cube(points.point(i), points.point(j));
            if d2 < best.0 {
                best = (d2, (i, j));
            }
        }
    }
    Ok(CubeMinDistance {
        min_distance: best.0.sqrt(),
        pair: best.1,
    })
}

/// The closest pair of row `i` among `j > i`, skipping a pair as soon as its partial sum
/// exceeds the best distance found so far by any row (`shared`, the bits of a non-negative
/// f64, which order as the values do). Sums run in coordinate order, so a pair measured in full
/// has the bits of [`distance_squared_cube`]; ties (never skipped: the test is strict) keep the
/// smallest j.
fn row_best(coords: &[f64], d: usize, i: usize, shared: &AtomicU64) -> (f64, usize) {
    let p = &coords[i * d..(i + 1) * d];
    let mut best = (f64::INFINITY, usize::MAX);
    for (off, q) in coords[(i + 1) * d..].chunks_exact(d).enumerate() {
        let bound = f64::from_bits(shared.load(Ordering::Relaxed)).min(best.0);
        let mut s = 0.0;
        let mut k = 0;
        while k < d {
            let g = axis_gap(p[k], q[k], 1.0);
            s += g * g;
            if s > bound {
                break;
            }
            k += 1;
        }
        if k == d && s < best.0 {
            best = (s, i + 1 + off);
            shared.fetch_min(s.to_bits(), Ordering::Relaxed);
        }
    }
    best
}

/// The minimum toroidal distance and its pair: every pair, rows in parallel on rayon's pool,
/// a pair abandoned once its partial sum exceeds the best distance found so far (usually after
/// a few coordinates), cancel checked and progress (`done` of `total` pairs) reported between
/// batches of rows. The same result, bit for bit, as [`min_distance_cube_naive`], whatever the
/// number of threads (the minimum over rows is taken in row order).
///
/// Errors: fewer than 2 points, invalid points, cancellation.
pub fn min_distance_cube(
    points: &CubePoints,
    cancel: &Cancel,
    progress: &mut OnProgress<'_, ()>,
) -> Result<CubeMinDistance, MetricsError> {
    check_two(points)?;
    let (n, d) = (points.n(), points.dims());
    let coords = points.coords();
    let shared = AtomicU64::new(f64::INFINITY.to_bits());
    let mut best = (f64::INFINITY, (usize::MAX, usize::MAX));
    let total = n * (n - 1) / 2;
    let mut done = 0;
    for rows in pair_batches(n) {
        cancel.check()?;
        let found: Vec<(f64, usize)> = rows
            .clone()
            .into_par_iter()
            .map(|i| row_best(coords, d, i, &shared))
            .collect();
        for (i, (d2, j)) in rows.clone().zip(found) {
            if d2 < best.0 {
                best = (d2, (i, j));
            }
        }
        done += rows.map(|i| n - 1 - i).sum::<usize>();
        progress(Progress::at(done, total));
    }
    Ok(CubeMinDistance {
        min_distance: best.0.sqrt(),
        pair: best.1,
    })
}
