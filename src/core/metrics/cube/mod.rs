//! Measures of point sets in [0,1)^d ([`CubePoints`]): the five L2 discrepancies (L2-star,
//! centred, wrap-around, mixture, symmetric; equal to `scipy.stats.qmc.discrepancy` where scipy
//! has them), the minimum toroidal distance, the stratification of every 1D projection, and
//! the table of every 2D projection (t-value, L2-star discrepancy, minimum distance, worst
//! first). What `analyze --points` prints for a file of more than two columns.
//!
//! | measure | fast | reference (tests, benches) |
//! |---|---|---|
//! | L2 discrepancies | [`discrepancy`], [`discrepancies`]: half the pairs, parallel rows, double-double sums, O(N²d) | [`discrepancy_naive`]: scipy's loops, f64; [`discrepancy_reference`]: all in double-double |
//! | min distance | [`min_distance_cube`]: parallel rows, pairs abandoned early, O(N²d) worst | [`min_distance_cube_naive`]: every pair in full |
//! | 1D stratification | [`stratification`]: counts per interval, O(Nd) | [`stratification_naive`]: per interval, on integers, O(N²d) |
//! | projection table | [`projection_table`]: pairs in parallel, the fast 2D statistics | [`projection_table_naive`]: pairs in turn, the O(N²) 2D references |
//!
//! Each measure is one [`CubeMeasure`]: its estimate is an arm of [`cost::cube_measure`] and
//! whether it applies to a set (and why not) is [`CubeMeasure::skipped`]. The long ones take
//! a [`Cancel`] token and report [`crate::core::progress::Progress`] (pairs done of all
//! pairs, no partial result) between batches, by the rules of `core::progress`.

pub mod cost;
pub mod discrepancy;
pub mod distance;
pub mod projections;
pub mod strata;

use std::ops::Range;

use crate::core::cube::CubePoints;
use crate::core::metrics::MetricsError;

pub use crate::core::cancel::Cancel;
pub use discrepancy::{
    discrepancies, discrepancy, discrepancy_naive, discrepancy_reference, Discrepancies,
    Discrepancy, DISCREPANCY_MAX_DIMS, DISCREPANCY_NAIVE_MAX_N,
};
pub use distance::{
    min_distance_cube, min_distance_cube_naive, CubeMinDistance, MIN_DISTANCE_CUBE_NAIVE_MAX_N,
};
pub use projections::{
    projection_rows, projection_table, projection_table_naive, sort_worst_first, ProjectionMeasure,
    ProjectionRow, PROJECTION_MAX_DIMS,
};
pub use strata::{stratification, stratification_naive, Stratification};

/// The measures of a point set in [0,1)^d, in the order `analyze` runs and prints them.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CubeMeasure {
    /// The five L2 discrepancies.
    Discrepancies,
    /// The minimum toroidal distance.
    MinDistance,
    /// Whether each 1D projection is stratified.
    Stratification,
    /// The table of the 2D projections.
    Projections,
}

impl CubeMeasure {
    /// All of them, in order.
    pub const ALL: [CubeMeasure; 4] = [
        CubeMeasure::Discrepancies,
        CubeMeasure::MinDistance,
        CubeMeasure::Stratification,
        CubeMeasure::Projections,
    ];

    /// Why the measure is not computed for `n` points in `dims` dimensions (`None`: it is).
    pub fn skipped(self, n: usize, dims: usize) -> Option<String> {
        match self {
            CubeMeasure::Discrepancies => (dims > DISCREPANCY_MAX_DIMS).then(|| {
                format!(
                    "discrepancies skipped: dims = {dims} > {DISCREPANCY_MAX_DIMS} (their terms 3^-d and 2^d leave the range of f64)"
                )
            }),
            CubeMeasure::MinDistance => (n < 2).then(|| {
                format!("a minimum distance needs at least 2 points, got n = {n}")
            }),
            CubeMeasure::Stratification => None,
            CubeMeasure::Projections => {
                if dims > PROJECTION_MAX_DIMS {
                    Some(format!(
                        "projection table skipped: dims = {dims} > {PROJECTION_MAX_DIMS} (it measures d(d-1)/2 pairs; use --project i,j for one pair)"
                    ))
                } else if dims < 2 {
                    Some(format!(
                        "projection table skipped: dims = {dims} has no pair of dimensions"
                    ))
                } else {
                    None
                }
            }
        }
    }
}

/// Checks that the set is not empty and every coordinate is finite and in [0, 1) (a
/// [`CubePoints`] made by [`CubePoints::from_2d`] is not checked when made).
pub(crate) fn check_cube(points: &CubePoints) -> Result<(), MetricsError> {
    if points.n() == 0 {
        return Err(MetricsError::Empty);
    }
    let d = points.dims();
    if let Some(k) = points.coords().iter().position(|v| !(0.0..1.0).contains(v)) {
        return Err(MetricsError::Cube(
            crate::core::cube::CubeError::OutsideCube {
                index: k / d,
                dim: k % d,
                value: points.coords()[k],
            },
        ));
    }
    Ok(())
}

/// Rows `0..n` in consecutive batches of about 1/32 of the `n(n+1)/2` pairs `(i, j ≥ i)`
/// each (row i holds n − i of them): the unit of work between two cancellation checks and
/// progress reports of the O(N²) measures.
pub(crate) fn pair_batches(n: usize) -> Vec<Range<usize>> {
    let total = n * (n + 1) / 2;
    let target = (total / 32).max(1);
    let mut out = Vec::new();
    let (mut start, mut pairs) = (0, 0);
    for i in 0..n {
        pairs += n - i;
        if pairs >= target {
            out.push(start..i + 1);
            start = i + 1;
            pairs = 0;
        }
    }
    if start < n {
        out.push(start..n);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn batches_cover_every_row_once_in_order() {
        for n in [0usize, 1, 2, 7, 100, 4097] {
            let b = pair_batches(n);
            let rows: Vec<usize> = b.iter().flat_map(|r| r.clone()).collect();
            assert_eq!(rows, (0..n).collect::<Vec<_>>());
            assert!(b.len() <= 33, "{n}: {}", b.len());
        }
    }
}
