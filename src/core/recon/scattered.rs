//! Reconstruction from N scattered samples over the whole image.
//!
//! N samples xⱼ ∈ \[0,1\]² with values f(xⱼ) are reconstructed on a W×W grid by the normalised
//! weighted sum I(p) = Σⱼ wⱼ f(xⱼ) / Σⱼ wⱼ, wⱼ = w((p − xⱼ)/h), at every pixel centre p (where
//! the weights cancel, Σw below c·Σ|w|, the floored estimator of the module docs of
//! [`super`]), with
//! the kernel scaled to the mean sample spacing h = 1/√N: a kernel of support r reaches r mean
//! sample spacings, r·W/√N pixels. Borders are open (see the module docs of [`super`]).
//!
//! Two algorithms compute the same sums:
//! - [`reconstruct_scattered`] **splats**: each sample adds w·f and w to the pixels within its
//!   support (serial, O(N·(2rW/√N)²) taps, separable kernels evaluate 2(2rW/√N) factors per
//!   sample);
//! - [`reconstruct_scattered_gather`] **gathers**: each pixel sums over the samples near it,
//!   found through a uniform bucket grid whose cells are at least the support wide (parallel
//!   over rows). It is the reference the splat is tested against (to 1e-12; only the order of
//!   the additions differs).

use super::accum::{finish_sums, offset, splat_work, tile_sorted, Accum, PAD};
use super::{
    check_cancel, check_floor, check_size, check_support, check_work, ReconError, ReconKernel,
    Reconstruction, MAX_SAMPLES, MAX_W,
};
use crate::core::cancel::Cancel;
use crate::core::signal::Signal;
use glam::DVec2;
use rayon::prelude::*;
use std::time::Instant;

/// Samples `signal` at `points`: f(xⱼ) for every j (parallel, cancellable).
pub fn sample_signal(
    signal: &Signal,
    points: &[DVec2],
    cancel: &Cancel,
) -> Result<Vec<f64>, ReconError> {
    signal.validate()?;
    check_size("n", points.len(), 1, MAX_SAMPLES)?;
    check_points(points)?;
    let mut values = vec![0.0; points.len()];
    let signal = signal.prepare();
    values
        .par_chunks_mut(4096)
        .zip(points.par_chunks(4096))
        .try_for_each(|(out, pts)| {
            check_cancel(cancel)?;
            for (o, p) in out.iter_mut().zip(pts) {
                *o = signal.eval(*p);
            }
            Ok::<(), ReconError>(())
        })?;
    Ok(values)
}

/// Checks every point is finite and inside \[0,1\]².
fn check_points(points: &[DVec2]) -> Result<(), ReconError> {
    for (index, p) in points.iter().enumerate() {
        if !(p.x.is_finite() && p.y.is_finite()) {
            return Err(ReconError::NonFinite {
                field: "points",
                index,
                value: if p.x.is_finite() { p.y } else { p.x },
            });
        }
        if !((0.0..=1.0).contains(&p.x) && (0.0..=1.0).contains(&p.y)) {
            return Err(ReconError::OutOfDomain {
                index,
                x: p.x,
                y: p.y,
            });
        }
    }
    Ok(())
}

/// Validates the common inputs; returns (support, pixels per filter unit W/√N).
fn check_inputs<K: ReconKernel + ?Sized>(
    points: &[DVec2],
    values: &[f64],
    w: usize,
    kernel: &K,
) -> Result<(f64, f64), ReconError> {
    check_size("w", w, 1, MAX_W)?;
    check_size("n", points.len(), 1, MAX_SAMPLES)?;
    if values.len() != points.len() {
        return Err(ReconError::LengthMismatch {
            field: "values",
            got: values.len(),
            expected: points.len(),
            per: "point",
        });
    }
    check_points(points)?;
    for (index, &value) in values.iter().enumerate() {
        if !value.is_finite() {
            return Err(ReconError::NonFinite {
                field: "values",
                index,
                value,
            });
        }
    }
    let support = check_support(kernel)?;
    let scale_px = w as f64 / (points.len() as f64).sqrt();
    Ok((support, scale_px))
}

/// Splats N scattered samples onto a W×W image (kernel scaled to 1/√N; see the module docs).
///
/// `points[j]` ∈ \[0,1\]² and `values[j]` = f(points\[j\]). Samples are splatted in
/// 64×64-pixel tile order (a stable counting sort) for cache locality, in parallel over bands
/// of output rows; every pixel gets its terms in that fixed order, so the bits do not depend
/// on the number of threads. Cancellable every 4096 samples. Cost: about
/// N·(2rW/√N + 1)² kernel taps, i.e. ≈ 4r²W² for any N.
pub fn reconstruct_scattered<K: ReconKernel + ?Sized>(
    points: &[DVec2],
    values: &[f64],
    w: usize,
    kernel: &K,
    cancel: &Cancel,
) -> Result<Reconstruction, ReconError> {
    splat_scattered(points, values, w, kernel, cancel, true)
}

/// [`reconstruct_scattered`] with the serial splat loop, one sample after the other: the
/// reference of the banded parallel splat (same bits expected).
pub fn reconstruct_scattered_serial<K: ReconKernel + ?Sized>(
    points: &[DVec2],
    values: &[f64],
    w: usize,
    kernel: &K,
    cancel: &Cancel,
) -> Result<Reconstruction, ReconError> {
    splat_scattered(points, values, w, kernel, cancel, false)
}

fn splat_scattered<K: ReconKernel + ?Sized>(
    points: &[DVec2],
    values: &[f64],
    w: usize,
    kernel: &K,
    cancel: &Cancel,
    parallel: bool,
) -> Result<Reconstruction, ReconError> {
    let start = Instant::now();
    let (support, scale_px) = check_inputs(points, values, w, kernel)?;
    let mut acc = Accum::new(w, kernel, support, scale_px)?;
    check_work(
        "scattered splatting",
        splat_work(points.len(), acc.r_px(), w),
    )?;
    // Splat tile by tile (a stable counting sort of the samples): the same sums, added in an
    // order that keeps the W×W accumulator's working set in cache.
    let sorted = tile_sorted(points, values, w);
    if parallel {
        check_cancel(cancel)?;
        return acc.splat_all(&sorted, points.len(), start, cancel);
    }
    for (k, &(x, v)) in sorted.iter().enumerate() {
        if k % 4096 == 0 {
            check_cancel(cancel)?;
        }
        acc.splat(x, v);
    }
    acc.finish(points.len(), start.elapsed())
}

/// Samples bucketed into a C×C grid of cells (compressed rows, stable within a cell).
struct Buckets {
    c: usize,
    start: Vec<u32>,
    index: Vec<u32>,
}

impl Buckets {
    /// The number of cells C per axis so that cells are at least `min_cell` pixels wide
    /// (C ≤ 1024).
    fn cells_for(w: usize, min_cell: f64) -> usize {
        ((w as f64 / min_cell).floor() as usize).clamp(1, 1024)
    }

    /// C×C cells over positions in pixel units [0, W].
    fn new(pos: &[DVec2], w: usize, c: usize) -> Self {
        let mut count = vec![0u32; c * c + 1];
        let cells: Vec<usize> = pos.iter().map(|p| Self::cell_of(*p, w, c)).collect();
        for &cell in &cells {
            count[cell + 1] += 1;
        }
        for k in 0..c * c {
            count[k + 1] += count[k];
        }
        let mut fill = count.clone();
        let mut index = vec![0u32; pos.len()];
        for (j, &cell) in cells.iter().enumerate() {
            index[fill[cell] as usize] = j as u32;
            fill[cell] += 1;
        }
        Buckets {
            c,
            start: count,
            index,
        }
    }

    #[inline]
    fn coord(x: f64, w: usize, c: usize) -> usize {
        ((x * c as f64 / w as f64).floor().max(0.0) as usize).min(c - 1)
    }

    #[inline]
    fn cell_of(p: DVec2, w: usize, c: usize) -> usize {
        Self::coord(p.y, w, c) * c + Self::coord(p.x, w, c)
    }

    #[inline]
    fn cell(&self, cx: usize, cy: usize) -> &[u32] {
        let k = cy * self.c + cx;
        &self.index[self.start[k] as usize..self.start[k + 1] as usize]
    }
}

/// The per-pixel gather reference for [`reconstruct_scattered`]: same sums, computed pixel by
/// pixel over the samples in the neighbouring bucket cells (parallel over rows, cancellable
/// every row). Uses only `kernel.weight`, never the separable factor.
pub fn reconstruct_scattered_gather<K: ReconKernel + ?Sized>(
    points: &[DVec2],
    values: &[f64],
    w: usize,
    kernel: &K,
    cancel: &Cancel,
) -> Result<Reconstruction, ReconError> {
    let start = Instant::now();
    let (support, scale_px) = check_inputs(points, values, w, kernel)?;
    let floor = check_floor(kernel)?;
    let r_px = support * scale_px;
    let inv_scale = 1.0 / scale_px;
    // A sample within r_px (+ pad) of a pixel centre lies in the centre's cell or a neighbour.
    let c = Buckets::cells_for(w, r_px + 2.0 * PAD);
    let per_pixel = 9 * (points.len() as u128 / (c * c) as u128 + 1);
    check_work("scattered gathering", (w * w) as u128 * per_pixel)?;
    let wf = w as f64;
    let pos: Vec<DVec2> = points.iter().map(|p| *p * wf).collect();
    let buckets = Buckets::new(&pos, w, c);
    let mut cells = vec![[0.0f64; 4]; w * w];
    cells
        .par_chunks_mut(w)
        .enumerate()
        .try_for_each(|(j, row)| {
            check_cancel(cancel)?;
            let cy = Buckets::coord(j as f64 + 0.5, w, c);
            for (i, cell) in row.iter_mut().enumerate() {
                let cx = Buckets::coord(i as f64 + 0.5, w, c);
                let mut sums = [0.0; 4];
                for by in cy.saturating_sub(1)..=(cy + 1).min(c - 1) {
                    for bx in cx.saturating_sub(1)..=(cx + 1).min(c - 1) {
                        for &k in buckets.cell(bx, by) {
                            let x = pos[k as usize];
                            let d =
                                DVec2::new(offset(i, x.x, inv_scale), offset(j, x.y, inv_scale));
                            let wt = kernel.weight(d);
                            if wt != 0.0 {
                                let v = values[k as usize];
                                sums[0] += wt * v;
                                sums[1] += wt;
                                sums[2] += wt.abs();
                                sums[3] += wt.abs() * v;
                            }
                        }
                    }
                }
                *cell = sums;
            }
            Ok::<(), ReconError>(())
        })?;
    finish_sums(w, &cells, floor, points.len(), start.elapsed())
}
