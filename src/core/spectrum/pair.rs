//! The radial distribution (pair correlation) function g(r) of a point set on the unit torus.
//!
//! Bin b covers toroidal pair distances d ∈ [b·Δ, (b+1)·Δ), b = 0 … B − 1 with
//! B = ⌊r_max/Δ⌋ (a ratio within 1e-9 of an integer counts as that integer). The distance
//! is d = √(dx² + dy²) with dx = min(|x_i − x_j|, 1 − |x_i − x_j|) (likewise dy). Each
//! unordered pair counts once, and
//!
//!   g_b = count_b / ( N(N−1)/2 · π((b+1)²Δ² − b²Δ²) ),
//!
//! the count divided by its expectation for N uniform i.i.d. points (a binomial process, the
//! finite-N Poisson process): a pair's displacement is uniform on the torus and the disc of
//! radius r ≤ ½ lies inside the unit cell, so P(d ∈ bin) is the annulus area exactly, which
//! is the 2π r dr of the continuous definition taken at the bin centre:
//! π(r₂² − r₁²) = 2π·((r₁ + r₂)/2)·Δ. Hence r_max ≤ ½.
//! Uniform random points give g ≈ 1; hard-disk or grid patterns give g = 0 below their
//! minimum distance.
//!
//! [`pair_correlation_naive`] tests all N(N−1)/2 pairs (allowed for N ≤ 16 384);
//! [`pair_correlation`] uses a cell list of ⌊1/r_max⌋² cells and tests only the 9 cells around
//! each point, about N²·9/(2C²) tests (it falls back to all pairs when C < 3). Counts are
//! integers, summed per thread and added: the result does not depend on the thread count.

use super::{check_points, SpectrumError};
use crate::core::cancel::Cancel;
use glam::DVec2;
use rayon::prelude::*;

/// Largest N for [`pair_correlation_naive`] (N(N−1)/2 ≈ 1.3·10⁸ pair tests).
pub const MAX_NAIVE_POINTS: usize = 16_384;
/// Largest number of pair tests [`pair_correlation`] accepts (2³²).
pub const MAX_PAIR_TESTS: f64 = 4_294_967_296.0;
/// Largest number of bins.
pub const MAX_BINS: usize = 1_000_000;

/// g(r) of a point set.
#[derive(Debug, Clone, PartialEq)]
pub struct PairCorrelation {
    /// Bin width Δ.
    pub bin_width: f64,
    /// Bin centres (b + ½)·Δ.
    pub radii: Vec<f64>,
    /// g_b (see the module docs).
    pub g: Vec<f64>,
    /// Unordered pairs per bin.
    pub counts: Vec<u64>,
    /// N.
    pub n_points: usize,
}

/// Validates the input; returns the number of bins.
fn validate(points: &[DVec2], bin_width: f64, r_max: f64) -> Result<usize, SpectrumError> {
    check_points(points)?;
    if points.len() < 2 {
        return Err(SpectrumError::InvalidParam {
            field: "n_points",
            value: points.len().to_string(),
            allowed: "at least 2 points (g(r) counts pairs)".into(),
        });
    }
    if !(r_max.is_finite() && r_max > 0.0 && r_max <= 0.5) {
        return Err(SpectrumError::InvalidParam {
            field: "r_max",
            value: crate::core::params::fmt_num(r_max),
            allowed: "a number in (0, 0.5] (larger discs leave the unit torus cell)".into(),
        });
    }
    if !(bin_width.is_finite() && bin_width > 0.0 && bin_width <= r_max * (1.0 + 1e-9)) {
        return Err(SpectrumError::InvalidParam {
            field: "bin_width",
            value: crate::core::params::fmt_num(bin_width),
            allowed: format!(
                "a number in (0, r_max = {}]",
                crate::core::params::fmt_num(r_max)
            ),
        });
    }
    let bins = (r_max / bin_width + 1e-9).floor();
    if bins > MAX_BINS as f64 {
        return Err(SpectrumError::InvalidParam {
            field: "bin_width",
            value: crate::core::params::fmt_num(bin_width),
            allowed: format!(
                "at least r_max/{MAX_BINS} = {}",
                crate::core::params::fmt_num(r_max / MAX_BINS as f64)
            ),
        });
    }
    Ok((bins as usize).max(1))
}

/// Bin of the toroidal distance between a and b, if below bins·Δ.
#[inline]
fn bin_of(a: DVec2, b: DVec2, inv_width: f64, r2_max: f64, bins: usize) -> Option<usize> {
    let dx = (a.x - b.x).abs();
    let dy = (a.y - b.y).abs();
    let dx = dx.min(1.0 - dx);
    let dy = dy.min(1.0 - dy);
    let d2 = dx * dx + dy * dy;
    if d2 >= r2_max {
        return None;
    }
    let b = (d2.sqrt() * inv_width) as usize;
    (b < bins).then_some(b)
}

fn finish(counts: Vec<u64>, n: usize, bin_width: f64) -> PairCorrelation {
    let pairs = n as f64 * (n as f64 - 1.0) / 2.0;
    let g = counts
        .iter()
        .enumerate()
        .map(|(b, &c)| {
            let (r1, r2) = (b as f64 * bin_width, (b + 1) as f64 * bin_width);
            c as f64 / (pairs * std::f64::consts::PI * (r2 * r2 - r1 * r1))
        })
        .collect();
    PairCorrelation {
        bin_width,
        radii: (0..counts.len())
            .map(|b| (b as f64 + 0.5) * bin_width)
            .collect(),
        g,
        counts,
        n_points: n,
    }
}

fn add(mut a: Vec<u64>, b: Vec<u64>) -> Vec<u64> {
    a.iter_mut().zip(b).for_each(|(x, y)| *x += y);
    a
}

/// All-pairs counts (no input checks). Cancellation is polled per point.
fn count_all_pairs(
    points: &[DVec2],
    bin_width: f64,
    bins: usize,
    cancel: &Cancel,
) -> Result<Vec<u64>, SpectrumError> {
    let inv = 1.0 / bin_width;
    let r2 = (bins as f64 * bin_width).powi(2);
    let counts = (0..points.len())
        .into_par_iter()
        .fold(
            || vec![0u64; bins],
            |mut h, i| {
                if !cancel.is_cancelled() {
                    let a = points[i];
                    for &b in &points[i + 1..] {
                        if let Some(k) = bin_of(a, b, inv, r2, bins) {
                            h[k] += 1;
                        }
                    }
                }
                h
            },
        )
        .reduce(|| vec![0u64; bins], add);
    cancel.check()?;
    Ok(counts)
}

/// g(r) by testing all N(N−1)/2 pairs (the reference). Bins of width `bin_width` up to
/// `r_max` ≤ ½ (see the module docs).
///
/// # Errors
/// [`SpectrumError::EmptyPointSet`], [`SpectrumError::InvalidPoint`];
/// [`SpectrumError::InvalidParam`] naming `n_points` (2..=16 384), `r_max` ((0, ½]) or
/// `bin_width` ((0, r_max], at most 10⁶ bins); [`SpectrumError::Cancelled`].
pub fn pair_correlation_naive(
    points: &[DVec2],
    bin_width: f64,
    r_max: f64,
    cancel: &Cancel,
) -> Result<PairCorrelation, SpectrumError> {
    let bins = validate(points, bin_width, r_max)?;
    if points.len() > MAX_NAIVE_POINTS {
        return Err(SpectrumError::InvalidParam {
            field: "n_points",
            value: points.len().to_string(),
            allowed: format!(
                "2..={MAX_NAIVE_POINTS} for the all-pairs count (use pair_correlation)"
            ),
        });
    }
    let counts = count_all_pairs(points, bin_width, bins, cancel)?;
    Ok(finish(counts, points.len(), bin_width))
}

/// g(r) with a cell list: cells of side 1/C ≥ r_max, C = ⌊1/r_max⌋, and each point tested
/// against the 9 cells around its own (all pairs when C < 3). Same result as
/// [`pair_correlation_naive`], bit for bit.
///
/// # Errors
/// As [`pair_correlation_naive`], except that the limit on N is on the pair tests:
/// N²·min(1, 9/C²)/2 ≤ 2³² (`n_points` named).
pub fn pair_correlation(
    points: &[DVec2],
    bin_width: f64,
    r_max: f64,
    cancel: &Cancel,
) -> Result<PairCorrelation, SpectrumError> {
    let bins = validate(points, bin_width, r_max)?;
    let n = points.len();
    let reach = bins as f64 * bin_width;
    let cells = ((1.0 / reach).floor() as usize).max(1);
    let tests = (n as f64).powi(2) * (9.0 / (cells * cells) as f64).min(1.0) / 2.0;
    if tests > MAX_PAIR_TESTS {
        let max = (2.0 * MAX_PAIR_TESTS / (9.0 / (cells * cells) as f64).min(1.0)).sqrt();
        return Err(SpectrumError::InvalidParam {
            field: "n_points",
            value: n.to_string(),
            allowed: format!(
                "at most {} points for r_max = {r_max} (pair tests N²·min(1, 9/C²)/2 ≤ 2³², C = {cells})",
                max.floor()
            ),
        });
    }
    if cells < 3 {
        let counts = count_all_pairs(points, bin_width, bins, cancel)?;
        return Ok(finish(counts, n, bin_width));
    }
    let cell_of = |p: DVec2| -> usize {
        let cx = ((p.x * cells as f64) as usize).min(cells - 1);
        let cy = ((p.y * cells as f64) as usize).min(cells - 1);
        cy * cells + cx
    };
    // Counting sort of the points by cell.
    let mut start = vec![0usize; cells * cells + 1];
    for &p in points {
        start[cell_of(p) + 1] += 1;
    }
    for c in 0..cells * cells {
        start[c + 1] += start[c];
    }
    let mut fill = start.clone();
    let mut sorted = vec![DVec2::ZERO; n];
    for &p in points {
        let c = cell_of(p);
        sorted[fill[c]] = p;
        fill[c] += 1;
    }
    let inv = 1.0 / bin_width;
    let r2 = reach * reach;
    let counts = (0..cells * cells)
        .into_par_iter()
        .fold(
            || vec![0u64; bins],
            |mut h, c| {
                if cancel.is_cancelled() {
                    return h;
                }
                let (cx, cy) = (c % cells, c / cells);
                for i in start[c]..start[c + 1] {
                    let a = sorted[i];
                    for dy in [cells - 1, 0, 1] {
                        for dx in [cells - 1, 0, 1] {
                            let nc = ((cy + dy) % cells) * cells + (cx + dx) % cells;
                            // Each unordered pair once: j after i in the sorted order.
                            let (lo, hi) = (start[nc].max(i + 1), start[nc + 1]);
                            if lo >= hi {
                                continue;
                            }
                            for &b in &sorted[lo..hi] {
                                if let Some(k) = bin_of(a, b, inv, r2, bins) {
                                    h[k] += 1;
                                }
                            }
                        }
                    }
                }
                h
            },
        )
        .reduce(|| vec![0u64; bins], add);
    cancel.check()?;
    Ok(finish(counts, n, bin_width))
}
