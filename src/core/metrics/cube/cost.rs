//! What each measure of a point set in [0,1)^d costs (work, seconds, bytes): one arm per
//! [`CubeMeasure`] and no fallback, so a measure without a cost does not compile. Rates and
//! method: [`crate::core::budget`]. The rates here are first estimates from the operation
//! counts of the loops (not yet timed on the reference machine).

use super::CubeMeasure;
use crate::core::budget::{cpu, parallel, Estimate, Unit};
use crate::core::metrics::cost::{L2_NS, MIN_DISTANCE_NS, TVALUE_NS};

/// One factor h(x_ik, x_jk) of one discrepancy's double sum, multiplied into its product
/// (parallel; the double-double sum per pair is amortised over the d factors).
pub(crate) const DISCREPANCY_FACTOR_NS: f64 = 1.2;
/// The double-double addition of one pair's product.
pub(crate) const DISCREPANCY_PAIR_NS: f64 = 4.0;
/// One pair of the minimum distance: the coordinates visited before it is abandoned (a few)
/// and the comparison (parallel).
pub(crate) const DISTANCE_PAIR_NS: f64 = 3.0;
/// One coordinate visited past the first few (for sets whose close pairs are many).
pub(crate) const DISTANCE_DIM_NS: f64 = 0.1;
/// One coordinate's interval and count of the stratification check (serial).
pub(crate) const STRATUM_NS: f64 = 8.0;

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
        parallel(pairs * (d * DISCREPANCY_FACTOR_NS + DISCREPANCY_PAIR_NS)),
        8.0 * nf * d,
    )
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
                parallel(amount * (d * DISCREPANCY_FACTOR_NS + DISCREPANCY_PAIR_NS)),
                coords_bytes,
            )
        }
        CubeMeasure::MinDistance => {
            let pairs = nf * (nf - 1.0).max(0.0) / 2.0;
            Estimate::new(
                format!("minimum toroidal distance of {n} points in {dims} dimensions"),
                pairs,
                Unit::Pairs,
                parallel(pairs * (DISTANCE_PAIR_NS + d * DISTANCE_DIM_NS)),
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
            let per_pair = nf * MIN_DISTANCE_NS + nf * log * L2_NS + t * TVALUE_NS;
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
