//! Exact periodograms: the naive double loop (reference for tests) and a fast exact path
//! built on separable phasor recurrences.
//!
//! Both compute F(k) = Σ_j exp(−2πi k·x_j) and P(k) = |F(k)|²/N on the grid of the module
//! docs; they differ only in how the phasors are produced.

use super::{check_points, check_size, k_min, Spectrum, SpectrumError};
use crate::core::cancel::Cancel;
use glam::DVec2;
use rayon::prelude::*;
use std::f64::consts::TAU;

/// Points per block of the fast exact path: the block's phasor tables (points × columns)
/// stay in cache while every output row accumulates them.
const BLOCK: usize = 128;
/// Every `ANCHOR`-th phasor of a recurrence is recomputed directly, so rounding errors of the
/// complex multiplications never accumulate over more than `ANCHOR` steps.
const ANCHOR: usize = 16;

/// exp(−2πi t) as `(re, im)`, with t first reduced to t − round(t) ∈ [−½, ½] (exact in
/// floating point), so the sine and cosine see a small argument whatever the size of t.
#[inline]
pub(crate) fn phasor(t: f64) -> (f64, f64) {
    let f = t - t.round();
    let (s, c) = (TAU * f).sin_cos();
    (c, -s)
}

/// The periodogram P(k) = |Σ_j exp(−2πi k·x_j)|²/N by the definition: one `sin_cos` per
/// point per frequency (phase k·x_j reduced modulo 1 first), N·M² in all.
///
/// This is the reference that the fast paths are tested against; it is far too slow for
/// interactive use (N = 4096 on 256² takes seconds). It takes no cancellation token on
/// purpose: keep it to tests and benchmarks.
///
/// # Errors
/// [`SpectrumError::InvalidSize`] unless 2 ≤ m ≤ 4096; [`SpectrumError::EmptyPointSet`];
/// [`SpectrumError::InvalidPoint`] for a coordinate outside [0, 1) or not finite.
pub fn periodogram_naive(points: &[DVec2], m: usize) -> Result<Spectrum, SpectrumError> {
    check_size(m)?;
    check_points(points)?;
    let k0 = k_min(m);
    let n = points.len() as f64;
    let mut power = vec![0.0; m * m];
    for iy in 0..m {
        let ky = (k0 + iy as i64) as f64;
        for ix in 0..m {
            let kx = (k0 + ix as i64) as f64;
            let (mut re, mut im) = (0.0, 0.0);
            for p in points {
                let (c, s) = phasor(kx * p.x + ky * p.y);
                re += c;
                im += s;
            }
            power[iy * m + ix] = (re * re + im * im) / n;
        }
    }
    Ok(Spectrum::from_power(m, power, points.len()))
}

/// The exact Fourier sums F(kx, ky) = Σ_j exp(−2πi (kx x_j + ky y_j)) for the rows
/// `ky ∈ rows` and the `ncols` consecutive columns kx = kx_lo, …, kx_lo + ncols − 1.
///
/// Separable: exp(−2πi k·x_j) = exp(−2πi kx x_j) · exp(−2πi ky y_j). For every point the
/// column phasors are produced by the recurrence e_{kx+1} = e_{kx} · exp(−2πi x_j) (one complex
/// multiplication each, re-anchored with a direct `sin_cos` every 16 steps so the rounding
/// error stays at a few ulps), the row phasor once per point and row, and each output row
/// accumulates row phasor × column phasors: N·rows·ncols complex multiply-adds in all.
/// Points are processed in blocks of 128; rows run in parallel (rayon); every output value is
/// summed in point order, so the bits do not depend on the number of threads.
///
/// Returns a row-major buffer of `rows.len()` rows, each `ncols` real parts followed by
/// `ncols` imaginary parts. Points are not validated here (callers do), any finite
/// coordinates work. Checks `cancel` once per block.
pub fn exact_field_rows(
    points: &[DVec2],
    kx_lo: i64,
    ncols: usize,
    rows: &[i64],
    cancel: &Cancel,
) -> Result<Vec<f64>, SpectrumError> {
    let nrows = rows.len();
    let mut out = vec![0.0; nrows * 2 * ncols];
    if nrows == 0 || ncols == 0 {
        return Ok(out);
    }
    let mut axr = vec![0.0; BLOCK * ncols];
    let mut axi = vec![0.0; BLOCK * ncols];
    let mut byr = vec![0.0; BLOCK * nrows];
    let mut byi = vec![0.0; BLOCK * nrows];
    for block in points.chunks(BLOCK) {
        cancel.check()?;
        // Column and row phasor tables of this block, one point per task.
        axr.par_chunks_mut(ncols)
            .zip(axi.par_chunks_mut(ncols))
            .zip(byr.par_chunks_mut(nrows))
            .zip(byi.par_chunks_mut(nrows))
            .zip(block.par_iter())
            .for_each(|((((xr, xi), yr), yi), p)| {
                let step = phasor(p.x);
                let mut cur = (0.0, 0.0);
                for c in 0..ncols {
                    cur = if c % ANCHOR == 0 {
                        phasor((kx_lo + c as i64) as f64 * p.x)
                    } else {
                        (
                            cur.0 * step.0 - cur.1 * step.1,
                            cur.0 * step.1 + cur.1 * step.0,
                        )
                    };
                    xr[c] = cur.0;
                    xi[c] = cur.1;
                }
                for (r, &ky) in rows.iter().enumerate() {
                    let (a, b) = phasor(ky as f64 * p.y);
                    yr[r] = a;
                    yi[r] = b;
                }
            });
        let (axr, axi, byr, byi) = (&axr, &axi, &byr, &byi);
        out.par_chunks_mut(2 * ncols)
            .enumerate()
            .for_each(|(r, acc)| {
                let (ar, ai) = acc.split_at_mut(ncols);
                for j in 0..block.len() {
                    let (cr, ci) = (byr[j * nrows + r], byi[j * nrows + r]);
                    let xr = &axr[j * ncols..(j + 1) * ncols];
                    let xi = &axi[j * ncols..(j + 1) * ncols];
                    for (((sr, si), &a), &b) in ar.iter_mut().zip(ai.iter_mut()).zip(xr).zip(xi) {
                        *sr += cr * a - ci * b;
                        *si += cr * b + ci * a;
                    }
                }
            });
    }
    Ok(out)
}

/// The exact periodogram P(k) = |Σ_j exp(−2πi k·x_j)|²/N, computed fast with
/// [`exact_field_rows`] (separable phasor recurrences, rayon over rows, `f64`).
///
/// Only the half plane ky ≤ 0 is summed (with the columns kx ∈ [k_min, −k_min], one more than
/// the grid for even M); the rows ky > 0 follow from P(−k) = P(k), which holds for real
/// points. Cost N·(⌊M/2⌋ + 1)·(2⌊M/2⌋ + 1) complex multiply-adds: about N·M²/2. Agrees with
/// [`periodogram_naive`] to 1e-10 relative (tested).
///
/// # Errors
/// As [`periodogram_naive`], plus [`SpectrumError::Cancelled`] (checked every 128 points).
pub fn periodogram_exact(
    points: &[DVec2],
    m: usize,
    cancel: &Cancel,
) -> Result<Spectrum, SpectrumError> {
    check_size(m)?;
    check_points(points)?;
    let k0 = k_min(m);
    let rows: Vec<i64> = (k0..=0).collect();
    let ncols = (-2 * k0 + 1) as usize;
    let field = exact_field_rows(points, k0, ncols, &rows, cancel)?;
    let n = points.len() as f64;
    let mut power = vec![0.0; m * m];
    power.par_chunks_mut(m).enumerate().for_each(|(iy, out)| {
        let ky = k0 + iy as i64;
        for (ix, o) in out.iter_mut().enumerate() {
            let kx = k0 + ix as i64;
            // P(kx, ky) = P(−kx, −ky): read the half plane ky < 0 plus (kx ≤ 0, ky = 0), so
            // that the symmetry holds bit for bit.
            let (kx, ky) = if ky < 0 || (ky == 0 && kx <= 0) {
                (kx, ky)
            } else {
                (-kx, -ky)
            };
            let r = (ky - k0) as usize;
            let c = (kx - k0) as usize;
            let re = field[r * 2 * ncols + c];
            let im = field[r * 2 * ncols + ncols + c];
            *o = (re * re + im * im) / n;
        }
    });
    Ok(Spectrum::from_power(m, power, points.len()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn phasor_reduces_large_arguments() {
        let (c, s) = phasor(1e6 + 0.25);
        assert!(c.abs() < 1e-9 && (s + 1.0).abs() < 1e-12);
        let (c, s) = phasor(0.0);
        assert_eq!((c, s), (1.0, -0.0));
    }

    #[test]
    fn single_point_at_origin_is_flat_one() {
        let p = periodogram_exact(&[DVec2::ZERO], 6, &Cancel::never()).unwrap();
        assert!(p.power.iter().all(|&v| (v - 1.0).abs() < 1e-15));
    }

    #[test]
    fn exact_field_rows_matches_direct_sum() {
        let pts = [
            DVec2::new(0.1, 0.7),
            DVec2::new(0.33, 0.05),
            DVec2::new(0.9, 0.5),
        ];
        let rows = [-7i64, 0, 3];
        let (lo, nc) = (-40i64, 81usize);
        let f = exact_field_rows(&pts, lo, nc, &rows, &Cancel::never()).unwrap();
        for (r, &ky) in rows.iter().enumerate() {
            for c in 0..nc {
                let kx = lo + c as i64;
                let (mut re, mut im) = (0.0, 0.0);
                for p in &pts {
                    let a = -TAU * (kx as f64 * p.x + ky as f64 * p.y);
                    re += a.cos();
                    im += a.sin();
                }
                assert!((f[r * 2 * nc + c] - re).abs() < 1e-12);
                assert!((f[r * 2 * nc + nc + c] - im).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn cancelled_exact_returns_cancelled() {
        let c = Cancel::new();
        c.cancel();
        let r = periodogram_exact(&[DVec2::splat(0.5)], 8, &c);
        assert!(matches!(r, Err(SpectrumError::Cancelled)));
    }
}
