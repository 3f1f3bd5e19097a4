//! What each measure of a point set in [0,1)^d costs (work, seconds, bytes): one arm per
//! [`CubeMeasure`] and no fallback, so a measure without a cost does not compile. Rates and
//! method: [`crate::core::budget`]. The rates here are CPU ns on one thread of the reference
//! machine, measured by `benches/cube.rs` (4096 unscrambled Sobol' points at D = 4 and 32; its
//! output prints each measure's rates beside these constants, BENCHMARKS.md records them).

use super::CubeMeasure;
use crate::core::budget::{cpu, parallel, Estimate, Unit};

/// One factor h(x_ik, x_jk) of one discrepancy's double sum, multiplied into its product
/// (parallel; measured 0.899 ns).
pub(crate) const DISCREPANCY_FACTOR_NS: f64 = 0.9;
/// The double-double addition of one pair's product (measured 3.09 ns).
pub(crate) const DISCREPANCY_PAIR_NS: f64 = 3.1;
/// One coordinate of one pair of the minimum distance (parallel). A pair is abandoned once its
/// partial sum passes the best distance so far, but in d dimensions the nearest neighbour is
/// far, so most pairs are summed nearly in full: the time is linear in d (measured 3.16 ns per
/// pair at D = 4, 31.5 at D = 32: 1.01 ns per coordinate, nothing per pair).
pub(crate) const DISTANCE_DIM_NS: f64 = 1.0;
/// One coordinate's interval and count of the stratification check (serial; measured 6.98 ns).
pub(crate) const STRATUM_NS: f64 = 7.0;
/// One row of the projection table, per point of its 2D projection: copying the pair's
/// coordinates out, the minimum distance (cell grid), the L2-star discrepancy (per point and
/// log₂ N: its sort and sweep) and the t-value (per N·log₂ N·log₂ log₂ N), parallel over
/// pairs. `benches/cube.rs` times each part over the table's 496 rows (4096 × 32); the parts'
/// shares of a loaded run (8.2, 588, 46.4 and 9.8 ns: 1720 ns a point in all) scaled to the
/// table's quiet-machine time (1014 ms on one thread, 499 ns a point).
pub(crate) const PROJECT_NS: f64 = 2.4;
/// See [`PROJECT_NS`].
pub(crate) const PROJECTION_MIN_DISTANCE_NS: f64 = 170.0;
/// See [`PROJECT_NS`].
pub(crate) const PROJECTION_L2_NS: f64 = 13.5;
/// See [`PROJECT_NS`].
pub(crate) const PROJECTION_TVALUE_NS: f64 = 2.8;

/// The estimate of one of the five discrepancies of `n` points in `dims` dimensions (a fifth
/// of [`CubeMeasure::Discrepancies`]' work: what `discrepancy(points, method)` of the Python
/// module computes).
pub fn cube_discrepancy(which: super::Discrepancy, n: usize, dims: usize) -> Estimate {
    let (nf, d) = (n as f64, dims as f64);
    let pairs = nf * (nf + 1.0) / 2.0;
    Estimate::new(
        format!("{} of {n} points in {dims} dimensions", which.label()),
        pairs,
        Unit::Pairs,
        parallel(pairs * discrepancy_pair_ns(d)),
        8.0 * nf * d,
    )
}

/// One pair (i ≤ j) of one discrepancy's double sum in `d` dimensions: d factors and the sum.
fn discrepancy_pair_ns(d: f64) -> f64 {
    d * DISCREPANCY_FACTOR_NS + DISCREPANCY_PAIR_NS
}

/// The estimate of one measure of `n` points in `dims` dimensions.
pub fn cube_measure(measure: CubeMeasure, n: usize, dims: usize) -> Estimate {
    let nf = n as f64;
    let d = dims as f64;
    let coords_bytes = 8.0 * nf * d;
    match measure {
        CubeMeasure::Discrepancies => {
            let pairs = nf * (nf + 1.0) / 2.0;
            let amount = 5.0 * pairs;
            Estimate::new(
                format!("5 L2 discrepancies of {n} points in {dims} dimensions"),
                amount,
                Unit::Pairs,
                parallel(amount * discrepancy_pair_ns(d)),
                coords_bytes,
            )
        }
        CubeMeasure::MinDistance => {
            let pairs = nf * (nf - 1.0).max(0.0) / 2.0;
            Estimate::new(
                format!("minimum toroidal distance of {n} points in {dims} dimensions"),
                pairs,
                Unit::Pairs,
                parallel(pairs * d * DISTANCE_DIM_NS),
                coords_bytes,
            )
        }
        CubeMeasure::Stratification => Estimate::new(
            format!("1D stratification of {n} points in {dims} dimensions"),
            nf * d,
            Unit::Points,
            cpu(nf * d * STRATUM_NS),
            coords_bytes + 4.0 * nf,
        ),
        CubeMeasure::Projections => {
            let pairs = d * (d - 1.0) / 2.0;
            let log = nf.max(2.0).log2();
            let t = if n.is_power_of_two() && n > 1 {
                nf * log * log.log2().max(1.0)
            } else {
                0.0
            };
            let per_pair = nf * (PROJECT_NS + PROJECTION_MIN_DISTANCE_NS)
                + nf * log * PROJECTION_L2_NS
                + t * PROJECTION_TVALUE_NS;
            // Each worker holds one projection and its statistics' buffers (~80 bytes a point).
            let bytes = coords_bytes + 80.0 * nf * crate::core::budget::REFERENCE_CORES;
            Estimate::new(
                format!("projection table of {n} points: {pairs} pairs of dimensions"),
                pairs * nf,
                Unit::Points,
                parallel(pairs * per_pair),
                bytes,
            )
        }
    }
}
