//! Point sets and their statistics.

use glam::DVec2;
use std::sync::Arc;

/// The points of a column.
#[derive(Debug, Clone)]
pub struct PointsData {
    pub points: Vec<DVec2>,
    /// The same points as f32, for the GPU.
    pub gpu: Arc<Vec<[f32; 2]>>,
    pub version: u64,
    /// Why fewer points than asked were placed, if so.
    pub note: Option<String>,
}

/// A column's full run of N points (the sequence node's data): the points node of a scene
/// with a prefix shows its first k, so moving k slices it instead of generating again.
#[derive(Debug, Clone)]
pub struct SequenceData(pub PointsData);

/// Point-set statistics for the overlays.
#[derive(Debug, Clone)]
pub struct StatsData {
    pub min_distance: f64,
    pub normalized_min_distance: f64,
    pub mean_nn: f64,
    /// Star discrepancy and the worst anchored box (a, b).
    pub star: Option<(f64, (f64, f64))>,
    pub l2_star: f64,
    pub t_value: Option<u32>,
    /// PSA's effective Nyquist frequency, oscillations and bond-orientational order, for
    /// N ≤ [`STATS_PSA_MAX_N`] (their RDF is O(N²)).
    pub psa: Option<crate::core::metrics::PsaStatistics>,
    /// The core's whole result: why a statistic was skipped, the t-value's m, the time of
    /// each stage (what `samplescope analyze` prints).
    pub full: crate::core::metrics::Statistics,
}

/// PSA's statistics of a column's points (the `Psa` node): computed for
/// [`crate::core::metrics::PSA_MIN_N`] ≤ N ≤ [`crate::core::metrics::PSA_MAX_N`] (their RDF
/// is O(N²)), otherwise the reason they were skipped.
#[derive(Debug, Clone)]
pub struct PsaData {
    /// The statistics, when N is in range.
    pub statistics: Option<crate::core::metrics::PsaStatistics>,
    /// Why they were skipped, when N is not.
    pub skipped: Option<String>,
}

/// Largest N whose statistics include PSA's measures (about 0.25 s at 4096 on 2 cores).
pub const STATS_PSA_MAX_N: usize = 8192;

/// Most strata per axis a pattern panel or figure draws (beyond, the lines merge into grey).
pub const MAX_STRATA_LINES: usize = 256;

/// The strata grid (columns, rows) a pattern panel or figure draws for a pattern whose strata
/// are `strata`: all of them, or none when either axis has more than [`MAX_STRATA_LINES`]
/// (a coarser grid would not be the pattern's strata).
pub fn drawn_strata(strata: Option<(usize, usize)>) -> Option<(usize, usize)> {
    strata.filter(|&(c, r)| c <= MAX_STRATA_LINES && r <= MAX_STRATA_LINES)
}

/// The elementary-interval grid (columns, rows) = (2^k, 2^(m−k)) drawn under `n` = 2^m
/// points for `k` (k above m taken as m); `None` without a k or when `n` is not a power of
/// two. The pattern panel's overlay and the pattern figure both draw this grid.
pub fn elementary_grid(k: Option<u32>, n: usize) -> Option<(usize, usize)> {
    let k = k?;
    if !n.is_power_of_two() {
        return None;
    }
    let m = n.trailing_zeros();
    let k = k.min(m);
    Some((1usize << k, 1usize << (m - k)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn elementary_grid_splits_2_to_the_m_into_2_to_the_k_columns() {
        assert_eq!(elementary_grid(Some(1), 16), Some((2, 8)));
        assert_eq!(elementary_grid(Some(0), 16), Some((1, 16)));
        // k above m is taken as m.
        assert_eq!(elementary_grid(Some(9), 16), Some((16, 1)));
        assert_eq!(elementary_grid(Some(1), 12), None);
        assert_eq!(elementary_grid(None, 16), None);
    }
}
