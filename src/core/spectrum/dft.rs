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

/// Table steps per turn of [`phasor_table`].
const TURN_STEPS: usize = 1024;

/// exp(−2πi j/1024) for j = −512 … 512 (index j + 512), each by `sin_cos`.
fn turn_table() -> &'static [(f64, f64)] {
    static TABLE: std::sync::OnceLock<Vec<(f64, f64)>> = std::sync::OnceLock::new();
    TABLE.get_or_init(|| {
        (0..=TURN_STEPS)
            .map(|i| phasor((i as f64 - (TURN_STEPS / 2) as f64) / TURN_STEPS as f64))
            .collect()
    })
}

/// exp(−2πi t) as [`phasor`] gives it, without a library call: t − round(t) = j/1024 + r
/// (both steps exact), the table's exp(−2πi j/1024) times exp(−2πi r) by its Taylor series to
/// the 6th power (|2πr| ≤ π/1024: the first term left out is below 10⁻²¹). Within a few ulps
/// of [`phasor`] (tested); the anchors of [`exact_field_few_rows`].
#[inline]
fn phasor_table(table: &[(f64, f64)], t: f64) -> (f64, f64) {
    let f = t - t.round();
    let j = (f * TURN_STEPS as f64).round();
    let theta = TAU * (f - j / TURN_STEPS as f64);
    let t2 = theta * theta;
    let sin = theta * (1.0 - t2 / 6.0 * (1.0 - t2 / 20.0));
    let cos = 1.0 - t2 / 2.0 * (1.0 - t2 / 12.0 * (1.0 - t2 / 30.0));
    let (c, s) = table[(j as i64 + (TURN_STEPS / 2) as i64) as usize];
    // (c + i s)·(cos − i sin)
    (c * cos + s * sin, s * cos - c * sin)
}

/// Points summed side by side in vector lanes by [`exact_field_few_rows`].
const LANES: usize = 4;
/// Points per task of [`exact_field_few_rows`]: a fixed partition, so that the order of the
/// sums does not depend on the number of threads.
const TASK_POINTS: usize = 256;
/// Tasks of [`exact_field_few_rows`] run (and partial sums held) at a time.
const TASKS_IN_FLIGHT: usize = 64;

/// [`exact_field_rows`] for a few rows (the error check's): the same sums by the same
/// recurrence e_{kx+1} = e_{kx} · exp(−2πi x_j), re-anchored every 16 steps (the anchors from
/// a table and a short series, [`phasor_table`], within a few ulps of `sin_cos`), but without
/// the phasor tables: LANES points are advanced side by side
/// (one vector lane each, AVX2 where the CPU has it) and every row accumulates them in lane
/// sums, added up at the end. For R rows it costs N·ncols complex multiplications (the
/// recurrence) and N·R·ncols multiply-adds, with every intermediate in registers or the
/// R·ncols lane sums (L2-resident); the table path writes and reads N·ncols phasors from
/// memory, which for R = 2 costs more than the sums. Tasks of 256 points run in parallel and
/// their partial sums are added in point order: the bits do not depend on the threads (they
/// differ from [`exact_field_rows`]' by the order of the additions only). Same output layout.
pub fn exact_field_few_rows(
    points: &[DVec2],
    kx_lo: i64,
    ncols: usize,
    rows: &[i64],
    cancel: &Cancel,
) -> Result<Vec<f64>, SpectrumError> {
    let mut out = vec![0.0; rows.len() * 2 * ncols];
    if rows.is_empty() || ncols == 0 {
        return Ok(out);
    }
    // TASKS_IN_FLIGHT tasks at a time, so that the partial sums held stay bounded (at
    // N = 2^20 all 4096 at once would hold 32 MiB); added in task order either way.
    for group in points.chunks(TASK_POINTS * TASKS_IN_FLIGHT) {
        let partial: Vec<Vec<f64>> = group
            .par_chunks(TASK_POINTS)
            .map(|task| {
                cancel.check()?;
                Ok(few_rows(task, kx_lo, ncols, rows))
            })
            .collect::<Result<_, SpectrumError>>()?;
        for p in &partial {
            for (o, v) in out.iter_mut().zip(p) {
                *o += v;
            }
        }
    }
    Ok(out)
}

/// One group of [`LANES`] points of [`exact_field_few_rows`]: their x, the recurrence's step
/// exp(−2πi x) and every row's phasor exp(−2πi ky y), lane by lane. A short last group's empty
/// lanes have x = 0 and row phasors 0: they add zeros.
struct Group {
    /// [`turn_table`], for the anchors.
    table: &'static [(f64, f64)],
    x: [f64; LANES],
    wr: [f64; LANES],
    wi: [f64; LANES],
    row_re: Vec<[f64; LANES]>,
    row_im: Vec<[f64; LANES]>,
}

/// Lane sums of one row and column: real parts, imaginary parts.
type LaneSums = [[f64; LANES]; 2];

/// Adds columns `c0 .. end` (one anchor segment) of a group into `acc` (row r, column c at
/// r·ncols + c): the phasors of column c0 directly, then by the recurrence. The scalar form;
/// [`segment_avx2`] runs the same operations in the same order on 4 lanes at once.
fn segment(g: &Group, kx_lo: i64, (c0, end): (usize, usize), ncols: usize, acc: &mut [LaneSums]) {
    let (mut zr, mut zi) = ([0.0f64; LANES], [0.0f64; LANES]);
    for l in 0..LANES {
        (zr[l], zi[l]) = phasor_table(g.table, (kx_lo + c0 as i64) as f64 * g.x[l]);
    }
    for c in c0..end {
        if c > c0 {
            for l in 0..LANES {
                let (a, b) = (
                    zr[l] * g.wr[l] - zi[l] * g.wi[l],
                    zr[l] * g.wi[l] + zi[l] * g.wr[l],
                );
                zr[l] = a;
                zi[l] = b;
            }
        }
        for ((sum, cr), ci) in acc[c..]
            .iter_mut()
            .step_by(ncols)
            .zip(&g.row_re)
            .zip(&g.row_im)
        {
            for l in 0..LANES {
                sum[0][l] += cr[l] * zr[l] - ci[l] * zi[l];
                sum[1][l] += cr[l] * zi[l] + ci[l] * zr[l];
            }
        }
    }
}

/// [`segment`] with AVX2 intrinsics: the same IEEE operations in the same order, lane for
/// lane (no FMA), hence the same bits.
///
/// # Safety
/// The CPU must have AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn segment_avx2(
    g: &Group,
    kx_lo: i64,
    (c0, end): (usize, usize),
    ncols: usize,
    acc: &mut [LaneSums],
) {
    use std::arch::x86_64::*;
    let (mut ar, mut ai) = ([0.0f64; LANES], [0.0f64; LANES]);
    for l in 0..LANES {
        (ar[l], ai[l]) = phasor_table(g.table, (kx_lo + c0 as i64) as f64 * g.x[l]);
    }
    // SAFETY: every load and store is of 4 f64 from a [f64; 4] (unaligned forms).
    unsafe {
        let (wr, wi) = (
            _mm256_loadu_pd(g.wr.as_ptr()),
            _mm256_loadu_pd(g.wi.as_ptr()),
        );
        let (mut zr, mut zi) = (_mm256_loadu_pd(ar.as_ptr()), _mm256_loadu_pd(ai.as_ptr()));
        for c in c0..end {
            if c > c0 {
                let a = _mm256_sub_pd(_mm256_mul_pd(zr, wr), _mm256_mul_pd(zi, wi));
                let b = _mm256_add_pd(_mm256_mul_pd(zr, wi), _mm256_mul_pd(zi, wr));
                zr = a;
                zi = b;
            }
            for ((sum, cr), ci) in acc[c..]
                .iter_mut()
                .step_by(ncols)
                .zip(&g.row_re)
                .zip(&g.row_im)
            {
                let (cr, ci) = (_mm256_loadu_pd(cr.as_ptr()), _mm256_loadu_pd(ci.as_ptr()));
                let re = _mm256_sub_pd(_mm256_mul_pd(cr, zr), _mm256_mul_pd(ci, zi));
                let im = _mm256_add_pd(_mm256_mul_pd(cr, zi), _mm256_mul_pd(ci, zr));
                _mm256_storeu_pd(
                    sum[0].as_mut_ptr(),
                    _mm256_add_pd(_mm256_loadu_pd(sum[0].as_ptr()), re),
                );
                _mm256_storeu_pd(
                    sum[1].as_mut_ptr(),
                    _mm256_add_pd(_mm256_loadu_pd(sum[1].as_ptr()), im),
                );
            }
        }
    }
}

/// One task of [`exact_field_few_rows`]: the sums over `points`, in its output layout.
fn few_rows(points: &[DVec2], kx_lo: i64, ncols: usize, rows: &[i64]) -> Vec<f64> {
    #[cfg(target_arch = "x86_64")]
    let avx2 = std::arch::is_x86_feature_detected!("avx2");
    let nrows = rows.len();
    let mut acc: Vec<LaneSums> = vec![[[0.0; LANES]; 2]; nrows * ncols];
    let mut g = Group {
        table: turn_table(),
        x: [0.0; LANES],
        wr: [1.0; LANES],
        wi: [0.0; LANES],
        row_re: vec![[0.0; LANES]; nrows],
        row_im: vec![[0.0; LANES]; nrows],
    };
    for group in points.chunks(LANES) {
        g.x = [0.0; LANES];
        (g.wr, g.wi) = ([1.0; LANES], [0.0; LANES]);
        for (l, p) in group.iter().enumerate() {
            g.x[l] = p.x;
            (g.wr[l], g.wi[l]) = phasor(p.x);
        }
        for (r, &ky) in rows.iter().enumerate() {
            g.row_re[r] = [0.0; LANES];
            g.row_im[r] = [0.0; LANES];
            for (l, p) in group.iter().enumerate() {
                (g.row_re[r][l], g.row_im[r][l]) = phasor(ky as f64 * p.y);
            }
        }
        for c0 in (0..ncols).step_by(ANCHOR) {
            let cols = (c0, (c0 + ANCHOR).min(ncols));
            #[cfg(target_arch = "x86_64")]
            if avx2 {
                // SAFETY: the CPU was checked to have AVX2.
                unsafe { segment_avx2(&g, kx_lo, cols, ncols, &mut acc) };
                continue;
            }
            segment(&g, kx_lo, cols, ncols, &mut acc);
        }
    }
    let mut out = vec![0.0; nrows * 2 * ncols];
    for (r, sums) in acc.chunks(ncols).enumerate() {
        for (c, sum) in sums.iter().enumerate() {
            out[r * 2 * ncols + c] = sum[0].iter().sum();
            out[r * 2 * ncols + ncols + c] = sum[1].iter().sum();
        }
    }
    out
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

    /// The table phasor is within 10⁻¹⁵ (4.5 ulps of 1) of `phasor` over 10⁶ arguments (fixed
    /// seed), including exact table steps, ±½ and large arguments; `phasor` itself rounds 2π·f
    /// (up to 4·10⁻¹⁶ of angle).
    #[test]
    fn table_phasor_is_within_a_few_ulps_of_sin_cos() {
        let table = turn_table();
        let mut rng = crate::core::rng::Rng::new(5);
        let special = [
            0.0,
            0.5,
            -0.5,
            1.0 / 1024.0,
            0.25,
            1e6 + 0.125,
            -2047.3,
            0.49951171875,
        ];
        let args = special
            .into_iter()
            .chain((0..1_000_000).map(|_| (rng.next_f64() - 0.5) * 4096.0));
        for t in args {
            let (a, b) = (phasor(t), phasor_table(table, t));
            let err = (a.0 - b.0).abs().max((a.1 - b.1).abs());
            assert!(err < 1e-15, "t {t}: {a:?} vs {b:?}");
        }
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

    /// The few-rows path against a direct sum of `cos`/`sin` per term: 1000 points (the last
    /// group of 4 full, then one of 2 with 1002), 3 rows, 131 columns from −70 (anchors
    /// mid-way and a short last segment), within 1e-13 + 1e-14·N absolute (the recurrence's
    /// and N additions' rounding), and within 1e-12 of the table path.
    #[test]
    fn exact_field_few_rows_matches_direct_sum_and_the_table_path() {
        let mut rng = crate::core::rng::Rng::new(7);
        for n in [1000usize, 1002, 1] {
            let pts: Vec<DVec2> = (0..n)
                .map(|_| DVec2::new(rng.next_f64(), rng.next_f64()))
                .collect();
            let rows = [-5i64, 0, 12];
            let (lo, nc) = (-70i64, 131usize);
            let few = exact_field_few_rows(&pts, lo, nc, &rows, &Cancel::never()).unwrap();
            let table = exact_field_rows(&pts, lo, nc, &rows, &Cancel::never()).unwrap();
            // Both sums round N additions of terms of modulus 1 (1e-14·N), and a phasor after
            // up to 15 steps of the recurrence is a few times 1e-15 off (1e-13).
            let tol = 1e-13 + 1e-14 * n as f64;
            for (r, &ky) in rows.iter().enumerate() {
                for c in 0..nc {
                    let kx = lo + c as i64;
                    // One cos and sin per term of the phase reduced modulo 1 (no recurrence).
                    let (mut re, mut im) = (0.0, 0.0);
                    for p in &pts {
                        let t = kx as f64 * p.x + ky as f64 * p.y;
                        let a = -TAU * (t - t.round());
                        re += a.cos();
                        im += a.sin();
                    }
                    let (i, j) = (r * 2 * nc + c, r * 2 * nc + nc + c);
                    assert!((few[i] - re).abs() < tol, "n {n} row {ky} kx {kx}");
                    assert!((few[j] - im).abs() < tol, "n {n} row {ky} kx {kx}");
                    assert!((few[i] - table[i]).abs() < 1e-12 && (few[j] - table[j]).abs() < 1e-12);
                }
            }
        }
        // No rows or columns: an empty or zero result, no work.
        assert!(
            exact_field_few_rows(&[DVec2::ZERO], 0, 4, &[], &Cancel::never())
                .unwrap()
                .is_empty()
        );
    }

    /// The AVX2 segment gives the scalar one's bits (where the CPU has AVX2).
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn avx2_segment_equals_the_scalar_one_bit_for_bit() {
        if !std::arch::is_x86_feature_detected!("avx2") {
            return;
        }
        let (x, y) = ([0.12, 0.77, 0.5, 0.999], [0.3, 0.01, 0.62, 0.4]);
        let rows = [-9i64, 4];
        let mut g = Group {
            table: turn_table(),
            x,
            wr: [0.0; LANES],
            wi: [0.0; LANES],
            row_re: vec![[0.0; LANES]; 2],
            row_im: vec![[0.0; LANES]; 2],
        };
        for l in 0..LANES {
            (g.wr[l], g.wi[l]) = phasor(x[l]);
            for (r, &ky) in rows.iter().enumerate() {
                (g.row_re[r][l], g.row_im[r][l]) = phasor(ky as f64 * y[l]);
            }
        }
        let ncols = 40;
        let (mut a, mut b) = (
            vec![[[0.5; LANES]; 2]; 2 * ncols],
            vec![[[0.5; LANES]; 2]; 2 * ncols],
        );
        for cols in [(0, 16), (16, 32), (32, 40)] {
            segment(&g, -20, cols, ncols, &mut a);
            // SAFETY: AVX2 was checked above.
            unsafe { segment_avx2(&g, -20, cols, ncols, &mut b) };
        }
        let bits = |v: &[LaneSums]| -> Vec<u64> {
            v.iter().flatten().flatten().map(|f| f.to_bits()).collect()
        };
        assert_eq!(bits(&a), bits(&b));
    }

    #[test]
    fn cancelled_exact_returns_cancelled() {
        let c = Cancel::new();
        c.cancel();
        let r = periodogram_exact(&[DVec2::splat(0.5)], 8, &c);
        assert!(matches!(r, Err(SpectrumError::Cancelled)));
    }
}
