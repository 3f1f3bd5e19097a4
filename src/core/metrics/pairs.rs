//! The histogram of toroidal pair distances below a radius, by a cell grid: the pair counts
//! behind PSA's radial distribution function ([`super::psa::rdf`]), in O(N·k) for k points
//! within the radius instead of over all N(N−1)/2 pairs.
//!
//! The points are sorted into a G × G grid of cells of side 1/G; each pair closer than the
//! radius R lies in two cells whose offset (a, b) has |a|, |b| ≤ reach = ⌈R·G⌉ and whose
//! closest corners are closer than R. A half stencil (b > 0, or b = 0 and a > 0, plus pairs
//! within a cell) visits every unordered pair of cells once when G ≥ 2·reach + 1 (no offset
//! wraps onto another); otherwise every pair is visited ([`all_pairs`]). Each pair's distance
//! is [`torus::distance_squared`] of the original coordinates and its bin ⌊√d²/Δr⌋, the same
//! arithmetic as the all-pairs loop, so the counts are equal bin for bin.

use glam::DVec2;
use rayon::prelude::*;

use super::{Cancel, MetricsError};
use crate::core::torus;

/// The bin ⌊d/Δr⌋ of distance `d`, if below `bins` (the one binning rule of every pair loop,
/// so that their counts agree exactly).
#[inline]
pub(crate) fn bin_of(d: f64, dr: f64, bins: usize) -> Option<usize> {
    // ⌊q⌋ < bins ⟺ q < bins for an integer bins, and `as` truncates a q ≥ 0 to ⌊q⌋ (no call
    // to floor, which is a library call without SSE4.1); NaN gives no bin.
    let q = d / dr;
    (q < bins as f64).then_some(q as usize)
}

/// The chunks the pair loops split their work into: a fixed number (4 per thread), each
/// with its own histogram.
fn chunk_count(items: usize) -> usize {
    (rayon::current_num_threads() * 4).clamp(1, items.max(1))
}

/// Sums per-chunk histograms.
fn merge(partial: Vec<Vec<u64>>, bins: usize) -> Vec<u64> {
    let mut counts = vec![0u64; bins];
    for h in &partial {
        for (c, v) in counts.iter_mut().zip(h) {
            *c += v;
        }
    }
    counts
}

/// Counts of the pairs of `points` in bins [iΔr, (i+1)Δr), i < `bins`, over all N(N−1)/2
/// pairs (parallel over interleaved rows; the counts do not depend on the threads).
pub(crate) fn all_pairs(
    points: &[DVec2],
    bins: usize,
    dr: f64,
    cancel: &Cancel,
) -> Result<Vec<u64>, MetricsError> {
    let n = points.len();
    // Rows interleaved over a fixed number of chunks: balanced (row i has N − 1 − i pairs).
    let chunks = chunk_count(n);
    let partial: Vec<Vec<u64>> = (0..chunks)
        .into_par_iter()
        .map(|c| {
            let mut h = vec![0u64; bins];
            for i in (c..n).step_by(chunks) {
                cancel.check()?;
                let p = points[i];
                for q in &points[i + 1..] {
                    if let Some(b) = bin_of(torus::distance_squared(p, *q, 1.0).sqrt(), dr, bins) {
                        h[b] += 1;
                    }
                }
            }
            Ok(h)
        })
        .collect::<Result<_, MetricsError>>()?;
    Ok(merge(partial, bins))
}

/// The grid's cells per side for N points and radius R: about two points per cell, at most
/// 1024 per side.
fn grid_side(n: usize, radius: f64) -> Option<(usize, usize)> {
    let g = ((n as f64 / 2.0).sqrt().floor() as usize).clamp(1, 1024);
    let reach = (radius * g as f64).ceil() as usize;
    (g > 2 * reach).then_some((g, reach))
}

/// The pairs [`pair_counts`] visits for N uniformly spread points and bins up to `radius`:
/// N(N−1)/2 times the share of the cells its stencil covers (all pairs without a grid). The
/// budget's count.
pub(crate) fn visited_pairs(n: usize, radius: f64) -> f64 {
    let nf = n as f64;
    let all = nf * (nf - 1.0).max(0.0) / 2.0;
    let Some((g, reach)) = grid_side(n, radius * (1.0 + 1e-9)) else {
        return all;
    };
    let cells: usize = stencil(g, reach, radius * (1.0 + 1e-9))
        .iter()
        .map(|&(b, a)| if b == 0 { a } else { 2 * a + 1 })
        .sum();
    all * ((2 * cells + 1) as f64 / (g * g) as f64).min(1.0)
}

/// The half stencil, row by row: for row offset b, the largest column offset a_b whose cells
/// can hold a pair closer than `radius` (columns −a_b … a_b for b > 0, 1 … a_b for b = 0).
fn stencil(g: usize, reach: usize, radius: f64) -> Vec<(usize, usize)> {
    let s = 1.0 / g as f64;
    let r2 = radius * radius;
    let near = |a: usize, b: usize| {
        let gx = a.saturating_sub(1) as f64 * s;
        let gy = b.saturating_sub(1) as f64 * s;
        gx * gx + gy * gy < r2
    };
    (0..=reach)
        .filter_map(|b| {
            let a = (0..=reach).take_while(|&a| near(a, b)).last()?;
            (b > 0 || a > 0).then_some((b, a))
        })
        .collect()
}

/// Counts of the pairs of `points` in bins [iΔr, (i+1)Δr), i < `bins`: equal to
/// [`all_pairs`] bin for bin; by the cell grid (module docs) when the radius `bins`·Δr is
/// small enough for one, else over all pairs.
pub(crate) fn pair_counts(
    points: &[DVec2],
    bins: usize,
    dr: f64,
    cancel: &Cancel,
) -> Result<Vec<u64>, MetricsError> {
    grid_pair_counts(points, bins, dr, cancel, true)
}

/// [`pair_counts`], with the AVX2 forms where the CPU has them (`simd`) or the scalar forms.
fn grid_pair_counts(
    points: &[DVec2],
    bins: usize,
    dr: f64,
    cancel: &Cancel,
    simd: bool,
) -> Result<Vec<u64>, MetricsError> {
    let n = points.len();
    // Every counted distance is below `radius` (a margin over bins·Δr for the rounding of
    // d/Δr; the bin decides).
    let radius = bins as f64 * dr * (1.0 + 1e-9);
    let Some((g, reach)) = grid_side(n, radius) else {
        return all_pairs(points, bins, dr, cancel);
    };
    let r2 = radius * radius;
    // Sort the points by cell (row-major), coordinates as structure of arrays.
    let cell_of = |p: DVec2| {
        let cx = ((p.x * g as f64) as usize).min(g - 1);
        let cy = ((p.y * g as f64) as usize).min(g - 1);
        cy * g + cx
    };
    let mut start = vec![0usize; g * g + 1];
    for p in points {
        start[cell_of(*p) + 1] += 1;
    }
    for c in 0..g * g {
        start[c + 1] += start[c];
    }
    let mut fill = start.clone();
    let mut xs = vec![0.0; n];
    let mut ys = vec![0.0; n];
    for p in points {
        let c = cell_of(*p);
        xs[fill[c]] = p.x;
        ys[fill[c]] = p.y;
        fill[c] += 1;
    }
    let rows = stencil(g, reach, radius);
    let chunks = chunk_count(g);
    let grid = Grid {
        g,
        start: &start,
        xs: &xs,
        ys: &ys,
        rows: &rows,
        r2,
        dr,
        bins,
    };
    let partial: Vec<Vec<u64>> = (0..chunks)
        .into_par_iter()
        .map(|chunk| {
            if simd {
                grid.chunk_dispatch(chunk, chunks, cancel)
            } else {
                grid.chunk::<false>(chunk, chunks, cancel)
            }
        })
        .collect::<Result<_, MetricsError>>()?;
    Ok(merge(partial, bins))
}

/// The sorted points and the stencil of [`pair_counts`], and its binning.
struct Grid<'a> {
    g: usize,
    /// Cell c's points are `start[c] .. start[c + 1]` of `xs`, `ys` (cells row-major).
    start: &'a [usize],
    xs: &'a [f64],
    ys: &'a [f64],
    rows: &'a [(usize, usize)],
    r2: f64,
    dr: f64,
    bins: usize,
}

/// Candidates whose distances are computed together before they are binned.
const LANES: usize = 4;
/// Histograms each chunk counts into (see [`Grid::chunk`]).
const SUBS: usize = 4;
/// The most memory a chunk's sub-histograms take: beyond it (bins > 8191) each chunk counts
/// into one histogram, as the pairs then spread over many bins anyway (at N = 2^20 four would
/// have held 32 MiB over the 8 chunks).
const SUB_BYTES: usize = 256 << 10;

impl Grid<'_> {
    /// The sub-histograms per chunk (a power of two): [`SUBS`] while they fit [`SUB_BYTES`].
    fn subs(&self) -> usize {
        if SUBS * (self.bins + 1) * 8 <= SUB_BYTES {
            SUBS
        } else {
            1
        }
    }

    /// [`Grid::chunk`] compiled for AVX2 when the CPU has it (4 f64 lanes for the root and
    /// the division instead of SSE2's 2). Both run the same IEEE operations in the same
    /// order, so the counts are identical.
    fn chunk_dispatch(
        &self,
        chunk: usize,
        chunks: usize,
        cancel: &Cancel,
    ) -> Result<Vec<u64>, MetricsError> {
        #[cfg(target_arch = "x86_64")]
        {
            if std::arch::is_x86_feature_detected!("avx2") {
                // SAFETY: `chunk_avx2` only requires AVX2, which the CPU was just checked to have.
                return unsafe { self.chunk_avx2(chunk, chunks, cancel) };
            }
        }
        self.chunk::<false>(chunk, chunks, cancel)
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    unsafe fn chunk_avx2(
        &self,
        chunk: usize,
        chunks: usize,
        cancel: &Cancel,
    ) -> Result<Vec<u64>, MetricsError> {
        self.chunk::<true>(chunk, chunks, cancel)
    }

    /// The histogram of the pairs whose first point lies in the cell rows `chunk`,
    /// `chunk + chunks`, …: each point against the rest of its cell and the cells of the half
    /// stencil.
    #[inline(always)]
    fn chunk<const AVX2: bool>(
        &self,
        chunk: usize,
        chunks: usize,
        cancel: &Cancel,
    ) -> Result<Vec<u64>, MetricsError> {
        let (g, start) = (self.g, self.start);
        // SUBS histograms (one for many bins: `subs`) of bins + 1 counts (the last one takes
        // the pairs out of range), lane l counting into histogram l mod SUBS: no branch per
        // pair, and consecutive pairs at
        // the same distance do not wait on each other's increment. Added up at the end.
        let mut h = vec![0u64; self.subs() * (self.bins + 1)];
        for cy in (chunk..g).step_by(chunks) {
            cancel.check()?;
            for cx in 0..g {
                let c = cy * g + cx;
                for i in start[c]..start[c + 1] {
                    let (px, py) = (self.xs[i], self.ys[i]);
                    // Pairs within the cell.
                    self.count::<AVX2>(px, py, i + 1, start[c + 1], &mut h);
                    for &(b, a) in self.rows {
                        let row = ((cy + b) % g) * g;
                        // Columns cx + lo … cx + a (mod g): at most two runs of cells.
                        let (lo, hi) = if b == 0 {
                            (cx + 1, cx + a)
                        } else {
                            (cx + g - a, cx + g + a)
                        };
                        let (first, last) = (lo % g, hi % g);
                        if first <= last {
                            self.count::<AVX2>(
                                px,
                                py,
                                start[row + first],
                                start[row + last + 1],
                                &mut h,
                            );
                        } else {
                            self.count::<AVX2>(px, py, start[row + first], start[row + g], &mut h);
                            self.count::<AVX2>(px, py, start[row], start[row + last + 1], &mut h);
                        }
                    }
                }
            }
        }
        let mut counts = vec![0u64; self.bins];
        for sub in h.chunks(self.bins + 1) {
            for (c, v) in counts.iter_mut().zip(sub) {
                *c += v;
            }
        }
        Ok(counts)
    }

    /// Counts the pairs of (px, py) with the points `lo .. hi` in `h`: d² by
    /// [`torus::distance_squared`] and the bin by [`bin_of`] (of d² < r² only), as the
    /// all-pairs loop does. The d² and √d²/Δr of `LANES` candidates are computed first, read
    /// straight from the sorted coordinates with no branch, so that the root and the division
    /// run in vector lanes; the last `< LANES` candidates one by one.
    #[inline(always)]
    fn count<const AVX2: bool>(&self, px: f64, py: f64, lo: usize, hi: usize, h: &mut [u64]) {
        let p = DVec2::new(px, py);
        let (bins, stride) = (self.bins as f64, self.bins + 1);
        let sub_mask = self.subs() - 1;
        // bin_of(√d², Δr, bins): ⌊q⌋ for q < bins (and d² < r²), else the spare count.
        let bin = |d2: f64, q: f64| {
            if d2 < self.r2 && q < bins {
                q as usize
            } else {
                self.bins
            }
        };
        let (xs, ys) = (&self.xs[lo..hi], &self.ys[lo..hi]);
        let (mut cx, mut cy) = (xs.chunks_exact(LANES), ys.chunks_exact(LANES));
        #[cfg(target_arch = "x86_64")]
        if AVX2 {
            for (qx, qy) in (&mut cx).zip(&mut cy) {
                // SAFETY: AVX2 is checked by the caller (`chunk_dispatch`).
                let b = unsafe { self.bins_avx2(px, py, qx, qy) };
                for (l, &b) in b.iter().enumerate() {
                    h[(l & sub_mask) * stride + b as usize] += 1;
                }
            }
        }
        for (qx, qy) in (&mut cx).zip(&mut cy) {
            let (mut d2, mut q) = ([0.0f64; LANES], [0.0f64; LANES]);
            for l in 0..LANES {
                d2[l] = torus::distance_squared(p, DVec2::new(qx[l], qy[l]), 1.0);
                q[l] = d2[l].sqrt() / self.dr;
            }
            for l in 0..LANES {
                h[(l & sub_mask) * stride + bin(d2[l], q[l])] += 1;
            }
        }
        for (&qx, &qy) in cx.remainder().iter().zip(cy.remainder()) {
            let d2 = torus::distance_squared(p, DVec2::new(qx, qy), 1.0);
            h[bin(d2, d2.sqrt() / self.dr)] += 1;
        }
    }

    /// The bins of four candidates (`bins` for one out of range) by AVX2: the same IEEE
    /// operations as [`torus::distance_squared`] and [`bin_of`] (|a − b|, the smaller of it and
    /// 1 − it, dx² + dy², √, ÷ Δr, truncation), lane by lane, so the same bins.
    ///
    /// # Safety
    /// The CPU must have AVX2; `qx` and `qy` hold `LANES` = 4 values.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    unsafe fn bins_avx2(&self, px: f64, py: f64, qx: &[f64], qy: &[f64]) -> [i32; LANES] {
        use std::arch::x86_64::*;
        debug_assert!(qx.len() == LANES && qy.len() == LANES);
        let gap = |a: __m256d, b: __m256d| {
            // |a − b| by clearing the sign bit, then d < 1 − d ? d : 1 − d (min_pd returns
            // its first operand exactly when it is the smaller).
            let d = _mm256_andnot_pd(_mm256_set1_pd(-0.0), _mm256_sub_pd(a, b));
            _mm256_min_pd(d, _mm256_sub_pd(_mm256_set1_pd(1.0), d))
        };
        // SAFETY: 4 f64 are read from each slice (checked by the caller's chunks_exact).
        let (x, y) = unsafe { (_mm256_loadu_pd(qx.as_ptr()), _mm256_loadu_pd(qy.as_ptr())) };
        let (dx, dy) = (gap(_mm256_set1_pd(px), x), gap(_mm256_set1_pd(py), y));
        let d2 = _mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy));
        let q = _mm256_div_pd(_mm256_sqrt_pd(d2), _mm256_set1_pd(self.dr));
        let inside = _mm256_and_pd(
            _mm256_cmp_pd::<_CMP_LT_OQ>(d2, _mm256_set1_pd(self.r2)),
            _mm256_cmp_pd::<_CMP_LT_OQ>(q, _mm256_set1_pd(self.bins as f64)),
        );
        // Out of range: the spare count's index (q itself may not fit an i32 there).
        let q = _mm256_blendv_pd(_mm256_set1_pd(self.bins as f64), q, inside);
        let mut out = [0i32; LANES];
        // SAFETY: 4 i32 are written to a [i32; 4].
        unsafe {
            _mm_storeu_si128(out.as_mut_ptr().cast(), _mm256_cvttpd_epi32(q));
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The grid's counts, by the AVX2 forms (where the CPU has them) and the scalar ones, equal
    /// the all-pairs loop's bin for bin: uniform points, a lattice (many equal distances, on
    /// bin edges too) and duplicates, with bins up to ¼ (a large stencil) and a short radius,
    /// few bins (four sub-histograms) and many (one).
    #[test]
    fn grid_counts_equal_all_pairs_in_both_forms() {
        let mut rng = crate::core::rng::Rng::new(11);
        let uniform: Vec<DVec2> = (0..3000)
            .map(|_| DVec2::new(rng.next_f64(), rng.next_f64()))
            .collect();
        let lattice: Vec<DVec2> = (0..40 * 40)
            .map(|i| DVec2::new((i % 40) as f64 / 40.0, (i / 40) as f64 / 40.0))
            .collect();
        let mut dupes = uniform[..500].to_vec();
        dupes.extend_from_slice(&uniform[..500]);
        let never = Cancel::never();
        for points in [&uniform, &lattice, &dupes] {
            for (bins, dr) in [
                (1000, 0.25 / 1000.0),
                (37, 0.05 / 37.0),
                (64, 1.0 / 160.0),
                // Over 8191 bins: one histogram per chunk.
                (10_000, 0.25 / 10_000.0),
            ] {
                let reference = all_pairs(points, bins, dr, &never).unwrap();
                for simd in [true, false] {
                    let got = grid_pair_counts(points, bins, dr, &never, simd).unwrap();
                    assert_eq!(got, reference, "n {} bins {bins} simd {simd}", points.len());
                }
            }
        }
    }
}
