//! Whether each 1D projection of a point set is stratified: for dimension k, every one of the
//! N intervals `[m/N, (m+1)/N)` holds exactly one coordinate `x_ik` (a Latin hypercube; for
//! N = 2^m, a (0, m, 1)-net in base 2 in that dimension). Membership is exact for the f64 values
//! given (`⌊x·N⌋` with the t-value's exact floor), a value on a boundary belonging to the upper
//! interval.

use serde::Serialize;

use super::check_cube;
use crate::core::cube::CubePoints;
use crate::core::metrics::tvalue::exact_floor_scaled;
use crate::core::metrics::{Cancel, MetricsError};

/// The stratification of one dimension.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct Stratification {
    /// The dimension k.
    pub dim: usize,
    /// Whether every interval `[m/N, (m+1)/N)` holds exactly one of the N coordinates.
    pub stratified: bool,
    /// When not: the first interval m (from 0) holding no coordinate…
    pub empty_interval: Option<usize>,
    /// …and the first interval holding more than one, with its count.
    pub crowded_interval: Option<(usize, usize)>,
}

/// Counts the coordinates of dimension `k` per interval; `counts` is reused.
fn check_dim(points: &CubePoints, k: usize, counts: &mut [u32]) -> Stratification {
    let n = points.n();
    let s = n as f64;
    let pow2 = n.is_power_of_two();
    counts.fill(0);
    for x in points.column(k) {
        // x < 1, so ⌊x·N⌋ ≤ N − 1.
        let m = exact_floor_scaled(x, s, pow2) as usize;
        counts[m.min(n - 1)] += 1;
    }
    let empty_interval = counts.iter().position(|&c| c == 0);
    let crowded_interval = counts
        .iter()
        .position(|&c| c > 1)
        .map(|m| (m, counts[m] as usize));
    Stratification {
        dim: k,
        stratified: empty_interval.is_none(),
        empty_interval,
        crowded_interval,
    }
}

/// The stratification of every dimension, in order. O(N·d) time, O(N) memory.
///
/// Errors: empty or invalid points, cancellation.
pub fn stratification(
    points: &CubePoints,
    cancel: &Cancel,
) -> Result<Vec<Stratification>, MetricsError> {
    check_cube(points)?;
    let mut counts = vec![0u32; points.n()];
    (0..points.dims())
        .map(|k| {
            cancel.check()?;
            Ok(check_dim(points, k, &mut counts))
        })
        .collect()
}

/// The reference of [`stratification`]: for every dimension and every interval
/// `[m/N, (m+1)/N)`, the coordinates inside it counted one interval at a time, each interval
/// `⌊x·N⌋` computed on integers (`x = mant·2^−sh` exactly, so `⌊x·N⌋ = (mant·N) >> sh`).
/// O(N²·d): small sets only (tests).
pub fn stratification_naive(points: &CubePoints) -> Result<Vec<bool>, MetricsError> {
    check_cube(points)?;
    let n = points.n() as u128;
    // x = mant · 2^−sh exactly; for sh ≥ 120, x < 2^−67 and x·N < 1 for every N here.
    let interval_of = |x: f64| -> u128 {
        if x == 0.0 {
            return 0;
        }
        let bits = x.to_bits();
        let exp = ((bits >> 52) & 0x7ff) as i64;
        let (mant, e) = if exp == 0 {
            (bits & ((1 << 52) - 1), -1074)
        } else {
            ((bits & ((1 << 52) - 1)) | (1 << 52), exp - 1075)
        };
        let sh = -e; // x = mant / 2^sh, sh > 0 since x < 1
        if sh >= 120 {
            return 0;
        }
        (mant as u128 * n) >> sh
    };
    Ok((0..points.dims())
        .map(|k| (0..n).all(|m| points.column(k).filter(|&x| interval_of(x) == m).count() == 1))
        .collect())
}
