//! The projection table: every pair of dimensions i < j of a point set in [0,1)^d taken to the
//! 2D set `(x_i, x_j)` ([`CubePoints::project`]) and measured by the 2D statistics: the t-value
//! in base 2 (N a power of two; [`crate::core::metrics::t_value`]), the L2-star discrepancy
//! ([`crate::core::metrics::l2_star_discrepancy`]) and the toroidal minimum distance
//! ([`crate::core::metrics::min_distance`]). Up to [`PROJECTION_MAX_DIMS`] dimensions
//! (d(d−1)/2 pairs: 496 at d = 32).
//!
//! **Worst first.** Rows are sorted by the t-value, largest first (a row without one after
//! those with one), then by the L2-star discrepancy, largest first, then by the minimum
//! distance, smallest first, then by (i, j): the defective projections (Halton's correlated
//! high bases, a Sobol' pair with a poor (t, m, 2) structure) come first.
//!
//! **Cost.** Each pair costs the 2D statistics of N points (O(N log N) for the L2-star
//! discrepancy, O(N) expected for the minimum distance, O(N m log m) for the t-value): the
//! pairs run in parallel on rayon's pool, in batches, cancel checked and progress reported
//! between batches; the rows do not depend on the number of threads.
//! [`projection_table_naive`], the reference (and the bench's baseline), runs the pairs one
//! after the other with the O(N²) references of the L2-star discrepancy and the minimum
//! distance.

use rayon::prelude::*;
use serde::Serialize;

use super::check_cube;
use crate::core::cube::CubePoints;
use crate::core::metrics::{
    l2_star_discrepancy, l2_star_discrepancy_naive, min_distance, min_distance_naive, t_value,
    Cancel, MetricsError,
};
use crate::core::progress::{OnProgress, Progress};

/// The most dimensions the projection table takes (496 pairs at 32).
pub const PROJECTION_MAX_DIMS: usize = 32;

/// One pair of dimensions, measured as a 2D point set.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ProjectionRow {
    /// The dimensions `[i, j]`, i < j.
    pub dims: [usize; 2],
    /// The t-value in base 2 of the projection; `None` when N is not a power of two.
    pub t_value: Option<u32>,
    /// Its L2-star discrepancy (Warnock's T_N).
    pub l2_star_discrepancy: f64,
    /// Its toroidal minimum distance; `None` for a single point.
    pub min_distance: Option<f64>,
}

/// A measure of one projection, as the projection matrix tints its cells by it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum ProjectionMeasure {
    /// The t-value in base 2 (N a power of two): 0 is a (0, m, 2)-net; larger is worse.
    #[default]
    TValue,
    /// The L2-star discrepancy: larger is worse.
    L2Star,
    /// The toroidal minimum distance: smaller is worse.
    MinDistance,
}

impl crate::core::params::ChoiceParam for ProjectionMeasure {
    const OPTIONS: &'static [&'static str] = &["t-value", "l2-star", "min-distance"];
    fn index(self) -> usize {
        self as usize
    }
    fn from_index(index: usize) -> Self {
        [
            ProjectionMeasure::TValue,
            ProjectionMeasure::L2Star,
            ProjectionMeasure::MinDistance,
        ][index]
    }
}

impl ProjectionMeasure {
    /// Every measure.
    pub const ALL: [ProjectionMeasure; 3] = [
        ProjectionMeasure::TValue,
        ProjectionMeasure::L2Star,
        ProjectionMeasure::MinDistance,
    ];

    /// The measure's name in text (its colour bar, its hover text).
    pub fn label(self) -> &'static str {
        match self {
            ProjectionMeasure::TValue => "t-value (base 2)",
            ProjectionMeasure::L2Star => "L2-star discrepancy",
            ProjectionMeasure::MinDistance => "min. toroidal distance",
        }
    }
}

impl ProjectionRow {
    /// The row's value of `measure` (`None`: no t-value when N is not a power of two, no
    /// distance for one point).
    pub fn value(&self, measure: ProjectionMeasure) -> Option<f64> {
        match measure {
            ProjectionMeasure::TValue => self.t_value.map(f64::from),
            ProjectionMeasure::L2Star => Some(self.l2_star_discrepancy),
            ProjectionMeasure::MinDistance => self.min_distance,
        }
    }
}

/// Every pair i < j of `dims` dimensions, in order.
pub fn pairs(dims: usize) -> Vec<[usize; 2]> {
    (0..dims)
        .flat_map(|i| (i + 1..dims).map(move |j| [i, j]))
        .collect()
}

fn check(points: &CubePoints) -> Result<(), MetricsError> {
    check_cube(points)?;
    if points.dims() > PROJECTION_MAX_DIMS {
        return Err(MetricsError::TooManyDims {
            what: "the projection table",
            dims: points.dims(),
            max: PROJECTION_MAX_DIMS,
            why: "d(d-1)/2 pairs of 2D statistics",
        });
    }
    if points.dims() < 2 {
        return Err(MetricsError::TooFewDims {
            what: "the projection table",
            dims: points.dims(),
            min: 2,
        });
    }
    Ok(())
}

/// One row, by the fast 2D statistics (or their naive references).
fn row(
    points: &CubePoints,
    [i, j]: [usize; 2],
    naive: bool,
    cancel: &Cancel,
) -> Result<ProjectionRow, MetricsError> {
    let p = points.project(i, j)?;
    let n = p.len();
    let t = if n.is_power_of_two() {
        Some(t_value(&p, 2, cancel)?.t)
    } else {
        None
    };
    let (l2, md) = if naive {
        (
            l2_star_discrepancy_naive(&p, cancel)?,
            (n >= 2)
                .then(|| min_distance_naive(&p, cancel))
                .transpose()?,
        )
    } else {
        (
            l2_star_discrepancy(&p, cancel)?,
            (n >= 2).then(|| min_distance(&p, cancel)).transpose()?,
        )
    };
    Ok(ProjectionRow {
        dims: [i, j],
        t_value: t,
        l2_star_discrepancy: l2,
        min_distance: md.map(|m| m.min_distance),
    })
}

/// Sorts worst first (see the module docs).
pub fn sort_worst_first(rows: &mut [ProjectionRow]) {
    rows.sort_by(|a, b| {
        // Some(t) before None, larger t first.
        let t = |r: &ProjectionRow| r.t_value.map_or(-1i64, i64::from);
        let md = |r: &ProjectionRow| r.min_distance.unwrap_or(f64::INFINITY);
        t(b).cmp(&t(a))
            .then(b.l2_star_discrepancy.total_cmp(&a.l2_star_discrepancy))
            .then(md(a).total_cmp(&md(b)))
            .then(a.dims.cmp(&b.dims))
    });
}

/// Pairs per batch between two cancellation checks and progress reports.
const PAIR_BATCH: usize = 16;

/// The projection table, worst first: the pairs in parallel (batches of [`PAIR_BATCH`],
/// progress (`done` of `total` pairs) between them). N = 4096 in 32 dimensions (496 pairs): about
/// a second on 2 cores.
///
/// Errors: empty or invalid points, fewer than 2 or more than [`PROJECTION_MAX_DIMS`]
/// dimensions, cancellation.
pub fn projection_table(
    points: &CubePoints,
    cancel: &Cancel,
    progress: &mut OnProgress<'_, ()>,
) -> Result<Vec<ProjectionRow>, MetricsError> {
    check(points)?;
    let all = pairs(points.dims());
    let mut rows = projection_rows(points, &all, cancel, &mut |p| {
        progress(Progress::at(p.done, p.total))
    })?;
    sort_worst_first(&mut rows);
    Ok(rows)
}

/// The rows of the pairs `pairs`, in their order (not sorted): the work of
/// [`projection_table`], whose partial result is the rows measured so far (the projection
/// matrix shows its cells tinted as they come in). Batches of [`PAIR_BATCH`] pairs in
/// parallel, cancel checked and progress reported between them.
///
/// Errors: empty or invalid points, more than [`PROJECTION_MAX_DIMS`] dimensions, a pair that
/// is not two different dimensions of the set, cancellation.
pub fn projection_rows(
    points: &CubePoints,
    pairs: &[[usize; 2]],
    cancel: &Cancel,
    progress: &mut OnProgress<'_, [ProjectionRow]>,
) -> Result<Vec<ProjectionRow>, MetricsError> {
    check(points)?;
    let mut rows = Vec::with_capacity(pairs.len());
    for batch in pairs.chunks(PAIR_BATCH) {
        cancel.check()?;
        let done: Result<Vec<ProjectionRow>, MetricsError> = batch
            .par_iter()
            .map(|&ij| row(points, ij, false, cancel))
            .collect();
        rows.extend(done?);
        progress(Progress::with(rows.len(), pairs.len(), &rows));
    }
    if pairs.is_empty() {
        progress(Progress::with(0, 0, &rows));
    }
    Ok(rows)
}

/// The reference of [`projection_table`]: the pairs one after the other, each with the O(N²)
/// references of the L2-star discrepancy and the minimum distance (the same t-value). Equal
/// rows, in the same order.
///
/// Errors: as [`projection_table`], and more than 2^16 points (the 2D references' limit).
pub fn projection_table_naive(
    points: &CubePoints,
    cancel: &Cancel,
) -> Result<Vec<ProjectionRow>, MetricsError> {
    check(points)?;
    let mut rows = pairs(points.dims())
        .into_iter()
        .map(|ij| row(points, ij, true, cancel))
        .collect::<Result<Vec<_>, _>>()?;
    sort_worst_first(&mut rows);
    Ok(rows)
}
