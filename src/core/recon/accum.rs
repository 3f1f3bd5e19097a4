//! The splatting engine shared by scattered, grid and supersampled reconstruction.
//!
//! Positions are in **pixel units** (pixel i covers [i, i+1), its centre is i + ½). A sample at
//! x with value v adds w(d)·v, w(d), |w(d)| and |w(d)|·v to every pixel whose centre c satisfies
//! |c − x| < r_px (per axis), where d = (c − x)·inv_scale is the offset in filter units and
//! r_px = support / inv_scale the support in pixels. The range of pixels is padded by
//! [`PAD`] pixel so that rounding never drops a tap inside the support; taps outside it have
//! weight 0 by the [`ReconKernel`] contract.

use super::{check_floor, ReconError, ReconKernel, Reconstruction, ZERO_WEIGHT_FILL};
use glam::DVec2;
use std::time::Duration;

/// Padding of the splat range, in pixels (rounding errors are ~10⁻¹² px).
pub(crate) const PAD: f64 = 1e-7;

/// The offset in filter units of pixel centre `k + ½` from position `x` (pixel units). Splat
/// and gather both call this, so they hand the kernel bit-identical arguments.
#[inline(always)]
pub(crate) fn offset(k: usize, x: f64, inv_scale: f64) -> f64 {
    ((k as f64 + 0.5) - x) * inv_scale
}

/// The inclusive pixel range [lo, hi] whose centres lie within `r_px` (+ pad) of `x`, clipped
/// to [0, w − 1]; `None` when empty.
///
/// Written with truncating casts instead of `ceil`/`floor`, which are library calls on
/// baseline x86-64; positions are finite and |x| + r_px < 2⁶² (checked by the callers).
#[inline(always)]
pub(crate) fn pixel_range(x: f64, r_px: f64, w: usize) -> Option<(usize, usize)> {
    let a = x - 0.5 - r_px - PAD;
    let b = x - 0.5 + r_px + PAD;
    // b < 0 (or NaN): every centre is to the right of the support.
    if b.is_nan() || b < 0.0 {
        return None;
    }
    let lo = if a > 0.0 {
        let t = a as u64; // ⌊a⌋ for a ≥ 0
        if (t as f64) < a {
            t + 1
        } else {
            t
        }
    } else {
        0
    };
    let hi = (b as u64).min(w as u64 - 1); // ⌊b⌋ for b ≥ 0
    if hi < lo {
        None
    } else {
        Some((lo as usize, hi as usize))
    }
}

/// The samples (positions scaled to pixel units, values) sorted stably by 64×64-pixel tile,
/// row-major, so that consecutive splats touch memory that is already in cache. A counting
/// sort: one sequential pass to count, one to scatter the pairs into place (so the splat
/// loop then reads them sequentially).
pub(crate) fn tile_sorted(points: &[DVec2], values: &[f64], w: usize) -> Vec<(DVec2, f64)> {
    const TILE: f64 = 64.0;
    let wf = w as f64;
    let tiles = w.div_ceil(64).max(1);
    let key = |p: DVec2| {
        let tx = ((p.x.max(0.0) / TILE) as usize).min(tiles - 1);
        let ty = ((p.y.max(0.0) / TILE) as usize).min(tiles - 1);
        ty * tiles + tx
    };
    let keys: Vec<u32> = points.iter().map(|p| key(*p * wf) as u32).collect();
    let mut start = vec![0usize; tiles * tiles + 1];
    for &k in &keys {
        start[k as usize + 1] += 1;
    }
    for k in 0..tiles * tiles {
        start[k + 1] += start[k];
    }
    let mut out = vec![(DVec2::ZERO, 0.0); points.len()];
    for ((p, &v), &k) in points.iter().zip(values).zip(&keys) {
        let slot = &mut start[k as usize];
        out[*slot] = (*p * wf, v);
        *slot += 1;
    }
    out
}

/// The separable factors of the pixels `k0, k0 + 1, …` (one per slot of `out`) for a sample
/// at `x` (pixel units): each pixel centre's [`offset`], then the kernel's
/// [`ReconKernel::factors`] on them all (the serial and the parallel splat both call this, so
/// they add the same bits).
#[inline]
fn factors_at<K: ReconKernel + ?Sized>(
    kernel: &K,
    x: f64,
    k0: usize,
    inv_scale: f64,
    out: &mut [f64],
) {
    for (a, h) in out.iter_mut().enumerate() {
        *h = offset(k0 + a, x, inv_scale);
    }
    kernel.factors(out);
}

/// Largest per-axis tap count handled with stack buffers.
const SMALL: usize = 16;

/// Adds the separable weights wt = hx[a]·hy[b] to the pixels (i0 + a, j0 + b): the four sums
/// [wt·v, wt, |wt|, |wt|·v] (or the two of [`TwoSums`]).
#[inline(always)]
fn splat_rows<C: Sums>(
    cells: &mut [C],
    w: usize,
    i0: usize,
    j0: usize,
    hx: &[f64],
    hy: &[f64],
    v: f64,
) {
    let nx = hx.len();
    for (b, &wy) in hy.iter().enumerate() {
        if wy == 0.0 {
            continue;
        }
        let base = (j0 + b) * w + i0;
        let row = &mut cells[base..base + nx];
        // [wy·v, wy] scaled by wx: one packed multiply-add per tap, and the absolute pair.
        let wyv = wy * v;
        for (cell, &wx) in row.iter_mut().zip(hx) {
            cell.add(wx * wy, wx * wyv, v);
        }
    }
}

/// Adds one tap of weight `wt` (and `wtv` = wt·v) to a pixel's sums [Σw·v, Σw, Σ|w|, Σ|w|·v].
#[inline(always)]
fn add(cell: &mut [f64; 4], wt: f64, wtv: f64, v: f64) {
    let a = wt.abs();
    cell[0] += wtv;
    cell[1] += wt;
    cell[2] += a;
    cell[3] += a * v;
}

/// A pixel's running sums: the four [Σw·v, Σw, Σ|w|, Σ|w|·v] ([`FourSums`]), or the two
/// [Σw·v, Σw] that decide the pixel when no weight is negative ([`TwoSums`]).
pub(crate) trait Sums: Copy + Default + Send + Sync {
    /// Whether this is the two-sum layout (usable only under its conditions).
    const TWO: bool;
    /// Adds one tap of weight `wt` (and `wtv` = wt·v) for a sample of value `v`.
    fn add(&mut self, wt: f64, wtv: f64, v: f64);
    /// The four sums the estimator reads ([`finish_sums`]).
    fn four(&self) -> [f64; 4];
}

/// The four sums of every kernel.
pub(crate) type FourSums = [f64; 4];

impl Sums for FourSums {
    const TWO: bool = false;
    #[inline(always)]
    fn add(&mut self, wt: f64, wtv: f64, v: f64) {
        add(self, wt, wtv, v)
    }
    #[inline(always)]
    fn four(&self) -> [f64; 4] {
        *self
    }
}

/// [Σw·v, Σw] for weights that are all ≥ 0 (or −0), at most [`FACTOR_BOUND`]² in size, with
/// values at most [`VALUE_BOUND`] in size. Then Σ|w| is Σw bit for bit (the same terms added
/// in the same order), so the estimator never floors (Σw ≥ c·Σ|w| for c ≤ ½), and Σ|w|·v,
/// which only the floored branch reads, is finite like Σw·v (no sum can overflow under the
/// bounds): [`Sums::four`] gives [Σw·v, Σw, Σw, Σw·v] and the estimator's every output bit
/// and flag are those of the four sums. Half the memory traffic and adds per tap.
pub(crate) type TwoSums = [f64; 2];

impl Sums for TwoSums {
    const TWO: bool = true;
    #[inline(always)]
    fn add(&mut self, wt: f64, wtv: f64, _v: f64) {
        self[0] += wtv;
        self[1] += wt;
    }
    #[inline(always)]
    fn four(&self) -> [f64; 4] {
        [self[0], self[1], self[1], self[0]]
    }
}

/// Largest separable factor |h| for which [`TwoSums`] is used (|w| ≤ 10¹⁰⁰).
const FACTOR_BOUND: f64 = 1e50;
/// Largest sample value |v| for which [`TwoSums`] is used (|w·v| ≤ 10²⁵⁰, and sums of up to
/// 2⁶⁴ such terms stay below 10²⁷⁰: finite).
const VALUE_BOUND: f64 = 1e150;

/// Most factors held at once by [`splat_separable`] (16 MiB); more samples are splatted in
/// blocks.
const FACTOR_BUDGET: usize = 1 << 21;

/// The separable factors of a block of samples, evaluated once each (in parallel) and read by
/// every band of output rows the sample reaches.
struct FactorTable {
    /// Per sample, its pixel range (i0, i1, j0, j1), `None` when it reaches no pixel.
    ranges: Vec<Option<(usize, usize, usize, usize)>>,
    /// Per sample, `stride` slots: its factors along x from i0, then along y from j0 at
    /// `cap`.
    h: Vec<f64>,
    cap: usize,
    /// Whether every factor lies in [0, FACTOR_BOUND] ([`TwoSums`] may be used).
    two_sums: bool,
}

impl FactorTable {
    fn new<K: ReconKernel + ?Sized>(
        samples: &[(DVec2, f64)],
        kernel: &K,
        inv_scale: f64,
        r_px: f64,
        w: usize,
    ) -> Self {
        use rayon::prelude::*;
        let ranges: Vec<_> = samples
            .iter()
            .map(|&(x, _)| {
                let (j0, j1) = pixel_range(x.y, r_px, w)?;
                let (i0, i1) = pixel_range(x.x, r_px, w)?;
                Some((i0, i1, j0, j1))
            })
            .collect();
        let cap = ranges
            .iter()
            .flatten()
            .map(|&(i0, i1, j0, j1)| (i1 - i0).max(j1 - j0) + 1)
            .max()
            .unwrap_or(0);
        let mut h = vec![0.0; samples.len() * 2 * cap];
        let two_sums = cap == 0
            || h.par_chunks_mut(2 * cap)
                .zip(samples.par_iter().zip(ranges.par_iter()))
                .with_min_len(64)
                .map(|(slots, (&(x, _), range))| {
                    let Some((i0, i1, j0, j1)) = *range else {
                        return true;
                    };
                    let (hx, hy) = slots.split_at_mut(cap);
                    let (hx, hy) = (&mut hx[..=i1 - i0], &mut hy[..=j1 - j0]);
                    factors_at(kernel, x.x, i0, inv_scale, hx);
                    factors_at(kernel, x.y, j0, inv_scale, hy);
                    hx.iter()
                        .chain(hy.iter())
                        .all(|h| (0.0..=FACTOR_BOUND).contains(h))
                })
                .reduce(|| true, |a, b| a && b);
        FactorTable {
            ranges,
            h,
            cap,
            two_sums,
        }
    }
}

/// Splats `samples` (pixel units, in the order given) with a separable kernel: the factors of
/// each block of samples are evaluated once, in parallel ([`FactorTable`]), then added in
/// parallel over bands of output rows, each band visiting the samples in order and adding to
/// its own rows only. Every pixel receives the same terms, with the same bits, in the same
/// order as [`Accum::splat`] on each sample in turn, so the image is that of the serial splat
/// bit for bit (a test checks it, kernel by kernel). When no factor is negative and the values
/// are bounded it keeps two sums per pixel instead of four ([`TwoSums`], same bits); a kernel
/// whose factors turn out negative in a later block is splatted again with four.
/// Cancellable every 4096 samples per band.
fn splat_separable<K: ReconKernel + ?Sized>(
    acc: Accum<'_, K>,
    samples: &[(DVec2, f64)],
    n: usize,
    start: std::time::Instant,
    cancel: &crate::core::cancel::Cancel,
) -> Result<Reconstruction, ReconError> {
    debug_assert!(acc.separable);
    let mut first = None;
    if samples.iter().all(|s| s.1.abs() <= VALUE_BOUND) {
        if let Some(cells) = splat_blocks::<K, TwoSums>(&acc, samples, &mut first, cancel)? {
            return finish_sums(acc.w, &cells, acc.floor, n, start.elapsed());
        }
    }
    match splat_blocks::<K, FourSums>(&acc, samples, &mut first, cancel)? {
        Some(cells) => finish_sums(acc.w, &cells, acc.floor, n, start.elapsed()),
        None => unreachable!("four sums take every factor"),
    }
}

/// The sums of every pixel, block of samples after block; `None` when `C` is [`TwoSums`] and a
/// block has a factor outside [0, FACTOR_BOUND] (the first block's table is left in `first`
/// for the next try).
fn splat_blocks<K: ReconKernel + ?Sized, C: Sums>(
    acc: &Accum<'_, K>,
    samples: &[(DVec2, f64)],
    first: &mut Option<FactorTable>,
    cancel: &crate::core::cancel::Cancel,
) -> Result<Option<Vec<C>>, ReconError> {
    use rayon::prelude::*;
    let w = acc.w;
    let per_sample = 2 * (2.0 * acc.r_px + 3.0).min(w as f64 + 1.0) as usize;
    let block = (FACTOR_BUDGET / per_sample.max(1)).max(1);
    let mut cells = vec![C::default(); w * w];
    // Several bands per thread balance uneven sample densities.
    let bands = (4 * rayon::current_num_threads()).clamp(1, 64).min(w);
    let rows = w.div_ceil(bands);
    for (b, chunk) in samples.chunks(block).enumerate() {
        if cancel.is_cancelled() {
            return Err(ReconError::Cancelled);
        }
        let table = match first.take().filter(|_| b == 0) {
            Some(t) => t,
            None => FactorTable::new(chunk, acc.kernel, acc.inv_scale, acc.r_px, w),
        };
        if C::TWO && !table.two_sums {
            if b == 0 {
                *first = Some(table);
            }
            return Ok(None);
        }
        let (cap, stride) = (table.cap, 2 * table.cap);
        cells
            .par_chunks_mut(rows * w)
            .enumerate()
            .try_for_each(|(band_index, band)| {
                let (row0, row1) = (band_index * rows, band_index * rows + band.len() / w);
                for (k, &(_, v)) in chunk.iter().enumerate() {
                    if k % 4096 == 0 && cancel.is_cancelled() {
                        return Err(ReconError::Cancelled);
                    }
                    let Some((i0, i1, j0, j1)) = table.ranges[k] else {
                        continue;
                    };
                    let (jc0, jc1) = (j0.max(row0), j1.min(row1 - 1));
                    if jc1 < jc0 {
                        continue;
                    }
                    let slots = &table.h[k * stride..(k + 1) * stride];
                    let hx = &slots[..i1 - i0 + 1];
                    let hy = &slots[cap + (jc0 - j0)..cap + (jc1 - j0) + 1];
                    splat_rows(band, w, i0, jc0 - row0, hx, hy, v);
                }
                Ok(())
            })?;
    }
    Ok(Some(cells))
}

/// Running sums Σ w·v, Σ w, Σ |w| and Σ |w|·v per pixel (interleaved for locality).
pub(crate) struct Accum<'k, K: ReconKernel + ?Sized> {
    w: usize,
    cells: Vec<[f64; 4]>,
    floor: f64,
    kernel: &'k K,
    separable: bool,
    inv_scale: f64,
    r_px: f64,
    hx: Vec<f64>,
    hy: Vec<f64>,
}

impl<'k, K: ReconKernel + ?Sized> Accum<'k, K> {
    /// An empty W×W accumulator for `kernel` at `scale_px` pixels per filter unit; refuses a
    /// kernel that cannot reconstruct ([`check_floor`]).
    pub(crate) fn new(
        w: usize,
        kernel: &'k K,
        support: f64,
        scale_px: f64,
    ) -> Result<Self, ReconError> {
        let floor = check_floor(kernel)?;
        Ok(Accum {
            w,
            cells: vec![[0.0; 4]; w * w],
            floor,
            kernel,
            separable: kernel.factor(0.0).is_some(),
            inv_scale: 1.0 / scale_px,
            r_px: support * scale_px,
            hx: Vec::new(),
            hy: Vec::new(),
        })
    }

    /// Support in pixels.
    pub(crate) fn r_px(&self) -> f64 {
        self.r_px
    }

    /// Adds one sample at `x` (pixel units) with value `v`.
    #[inline]
    pub(crate) fn splat(&mut self, x: DVec2, v: f64) {
        let Some((i0, i1)) = pixel_range(x.x, self.r_px, self.w) else {
            return;
        };
        let Some((j0, j1)) = pixel_range(x.y, self.r_px, self.w) else {
            return;
        };
        let (nx, ny) = (i1 - i0 + 1, j1 - j0 + 1);
        let w = self.w;
        let s = self.inv_scale;
        let kernel = self.kernel;
        if self.separable {
            if nx <= SMALL && ny <= SMALL {
                // Common case (supports up to 7 px): factors on the stack.
                let mut hx = [0.0; SMALL];
                let mut hy = [0.0; SMALL];
                factors_at(kernel, x.x, i0, s, &mut hx[..nx]);
                factors_at(kernel, x.y, j0, s, &mut hy[..ny]);
                splat_rows(&mut self.cells, w, i0, j0, &hx[..nx], &hy[..ny], v);
            } else {
                self.hx.resize(nx, 0.0);
                self.hy.resize(ny, 0.0);
                factors_at(kernel, x.x, i0, s, &mut self.hx[..nx]);
                factors_at(kernel, x.y, j0, s, &mut self.hy[..ny]);
                splat_rows(&mut self.cells, w, i0, j0, &self.hx, &self.hy, v);
            }
        } else {
            for j in j0..j0 + ny {
                let dy = offset(j, x.y, s);
                let base = j * w + i0;
                let row = &mut self.cells[base..base + nx];
                for (a, cell) in row.iter_mut().enumerate() {
                    let wt = kernel.weight(DVec2::new(offset(i0 + a, x.x, s), dy));
                    add(cell, wt, wt * v, v);
                }
            }
        }
    }

    /// Splats every sample of `samples` (pixel units, in the order given) in parallel and
    /// normalises: [`splat_separable`] for a separable kernel, else bands of output rows
    /// ([`Self::splat_all_radial`]). The image is bit for bit that of [`Self::splat`] called on
    /// each sample in turn, whatever the number of threads (a test checks it). `n` is the
    /// number of samples reported, `start` when the reconstruction began.
    pub(crate) fn splat_all(
        mut self,
        samples: &[(DVec2, f64)],
        n: usize,
        start: std::time::Instant,
        cancel: &crate::core::cancel::Cancel,
    ) -> Result<Reconstruction, ReconError> {
        if self.separable {
            return splat_separable(self, samples, n, start, cancel);
        }
        self.splat_all_radial(samples, cancel)?;
        self.finish(n, start.elapsed())
    }

    /// Splats every sample with a kernel that is not separable, in parallel over bands of
    /// output rows: each band visits the samples in the given order and adds only to its own
    /// rows, so every pixel receives the same terms in the same order as [`Self::splat`]
    /// called on each sample in turn. Cancellable every 4096 samples per band.
    fn splat_all_radial(
        &mut self,
        samples: &[(DVec2, f64)],
        cancel: &crate::core::cancel::Cancel,
    ) -> Result<(), ReconError> {
        use rayon::prelude::*;
        let w = self.w;
        // Several bands per thread balance uneven sample densities.
        let bands = (4 * rayon::current_num_threads()).clamp(1, 64).min(w);
        let rows = w.div_ceil(bands);
        let (kernel, s, r_px) = (self.kernel, self.inv_scale, self.r_px);
        self.cells
            .par_chunks_mut(rows * w)
            .enumerate()
            .try_for_each(|(b, band)| {
                let (row0, row1) = (b * rows, b * rows + band.len() / w);
                for (k, &(x, v)) in samples.iter().enumerate() {
                    if k % 4096 == 0 && cancel.is_cancelled() {
                        return Err(ReconError::Cancelled);
                    }
                    let Some((j0, j1)) = pixel_range(x.y, r_px, w) else {
                        continue;
                    };
                    let (j0, j1) = (j0.max(row0), j1.min(row1 - 1));
                    if j1 < j0 {
                        continue;
                    }
                    let Some((i0, i1)) = pixel_range(x.x, r_px, w) else {
                        continue;
                    };
                    let nx = i1 - i0 + 1;
                    for j in j0..=j1 {
                        let dy = offset(j, x.y, s);
                        let base = (j - row0) * w + i0;
                        let row = &mut band[base..base + nx];
                        for (a, cell) in row.iter_mut().enumerate() {
                            let wt = kernel.weight(DVec2::new(offset(i0 + a, x.x, s), dy));
                            add(cell, wt, wt * v, v);
                        }
                    }
                }
                Ok(())
            })
    }

    /// Normalises every pixel (module docs of [`super`]); zero-weight pixels get the fill
    /// value and are flagged.
    pub(crate) fn finish(
        self,
        samples: usize,
        wall_time: Duration,
    ) -> Result<Reconstruction, ReconError> {
        finish_sums(self.w, &self.cells, self.floor, samples, wall_time)
    }
}

/// Turns per-pixel sums [Σw·v, Σw, Σ|w|, Σ|w|·v] into a [`Reconstruction`] (the estimator of
/// the module docs of [`super`]): with A = Σ|w| and P = Σ|w|·v / A,
///
/// ```text
/// I = Σw·v / Σw                               where Σw ≥ c·A,
/// I = (Σw·v + (c·A − Σw)·P) / (c·A)           where Σw < c·A (floored),
/// ```
///
/// and the fill value where A = 0.
pub(crate) fn finish_sums<C: Sums>(
    w: usize,
    cells: &[C],
    floor: f64,
    samples: usize,
    wall_time: Duration,
) -> Result<Reconstruction, ReconError> {
    let n = cells.len();
    let mut pixels = vec![0.0; n];
    let mut mask = vec![false; n];
    let mut zero_weight = 0usize;
    let mut floored = 0usize;
    // One pass. x·0 is NaN exactly when x is not finite, and a finite sum over a tiny
    // non-zero weight can still overflow: both make `bad` true.
    let mut bad = false;
    for ((c, p), m) in cells.iter().zip(pixels.iter_mut()).zip(mask.iter_mut()) {
        let [num, den, abs, num_abs] = c.four();
        let zero = abs == 0.0;
        let least = floor * abs;
        let low = den < least;
        let v = if zero {
            ZERO_WEIGHT_FILL
        } else if low {
            (num + (least - den) * (num_abs / abs)) / least
        } else {
            num / den
        };
        bad |= ((num + den + abs + num_abs) * 0.0 != 0.0) | !v.is_finite();
        *p = v;
        *m = zero;
        zero_weight += zero as usize;
        floored += (low && !zero) as usize;
    }
    if bad {
        let pixel = cells
            .iter()
            .zip(&pixels)
            .position(|(c, v)| !(c.four().iter().all(|x| x.is_finite()) && v.is_finite()))
            .unwrap_or(0);
        return Err(ReconError::NonFiniteWeight { pixel });
    }
    Ok(Reconstruction {
        w,
        pixels,
        zero_weight,
        floored,
        floor,
        mask,
        fill: ZERO_WEIGHT_FILL,
        samples,
        wall_time,
    })
}

/// Estimated kernel taps of splatting `n` samples with support `r_px` pixels onto W×W.
pub(crate) fn splat_work(n: usize, r_px: f64, w: usize) -> u128 {
    let per_axis = (2.0 * r_px + 2.0).min(w as f64 + 1.0);
    let per_axis = if per_axis.is_finite() {
        per_axis as u128
    } else {
        w as u128 + 1
    };
    n as u128 * per_axis * per_axis
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The definition: every k in 0..w with |k + ½ − x| < r (pixel centres inside the support).
    fn naive_range(x: f64, r: f64, w: usize) -> Option<(usize, usize)> {
        let ks: Vec<usize> = (0..w)
            .filter(|&k| ((k as f64 + 0.5) - x).abs() < r)
            .collect();
        ks.first().map(|&lo| (lo, *ks.last().unwrap_or(&lo)))
    }

    #[test]
    fn pixel_range_matches_definition_at_borders_and_outside() {
        let w = 10;
        for &x in &[
            0.0, 0.2, 0.5, 0.51, 1.0, 3.3, 9.49, 9.5, 9.99, 10.0, -0.7, -3.0, 10.4, 14.0,
        ] {
            for &r in &[0.3, 0.5, 1.0, 1.25, 2.5, 20.0] {
                let got = pixel_range(x, r, w);
                let want = naive_range(x, r, w);
                // The padded range may include a centre at distance exactly r (weight 0).
                match (got, want) {
                    (Some((a, b)), Some((c, d))) => {
                        assert!(a <= c && b >= d && c - a <= 1 && b - d <= 1, "x {x} r {r}")
                    }
                    (None, None) => {}
                    (Some((a, b)), None) => {
                        // Only a boundary tap (|k + ½ − x| = r within the pad) may appear.
                        for k in a..=b {
                            let dist = ((k as f64 + 0.5) - x).abs();
                            assert!((dist - r).abs() <= PAD, "x {x} r {r} k {k}");
                        }
                    }
                    (None, Some(_)) => panic!("x {x} r {r}: range dropped"),
                }
            }
        }
    }

    #[test]
    fn pixel_range_exact_support_boundary_is_padded() {
        // Centre 2.5 is exactly r = 1 away from x = 1.5: included (the kernel gives it 0).
        assert_eq!(pixel_range(1.5, 1.0, 8), Some((0, 2)));
        // Nothing when the support ends left of the first centre.
        assert_eq!(pixel_range(-1.0, 1.0, 8), None);
        assert_eq!(pixel_range(f64::NAN, 1.0, 8), None);
    }

    #[test]
    fn tile_sort_is_a_stable_permutation_grouped_by_tile() {
        // W = 128: tiles of 64 px are 2×2; positions given in unit coordinates.
        let pos = [
            DVec2::new(100.0, 3.0),
            DVec2::new(1.0, 1.0),
            DVec2::new(70.0, 2.0),
            DVec2::new(2.0, 90.0),
            DVec2::new(3.0, 2.0),
        ];
        let unit: Vec<DVec2> = pos.iter().map(|p| *p / 128.0).collect();
        let values = [0.0, 1.0, 2.0, 3.0, 4.0];
        let sorted = tile_sorted(&unit, &values, 128);
        // Tile (0,0) holds 1, 4; (1,0) holds 0, 2; (0,1) holds 3.
        let order: Vec<f64> = sorted.iter().map(|s| s.1).collect();
        assert_eq!(order, vec![1.0, 4.0, 0.0, 2.0, 3.0]);
        assert_eq!(sorted[2].0, pos[0]);
    }
}
