//! Image-plane sampling: one pattern shared by all pixels instead of an independent copy per
//! pixel, the Z-order Sobol' sampler, and the low-frequency content of an error image.
//!
//! ## [`ImagePlaneProvider`]: one tiled pattern (lecture: "compute the pattern once, reuse it by
//! tiling the image plane, translating and scaling"; Mitchell 1991)
//!
//! A pattern of N = s·T² points is generated once in the unit square (T = `tile`), scaled by T
//! onto a toroidal tile of T×T pixels, and repeated across the image by translation: pixel
//! (i, j) reads tile cell (i mod T, j mod T). Every pixel must receive exactly s offsets, which
//! the points of stratified patterns already satisfy (jitter with T√s columns, Sobol' and other
//! (0,m,2)-nets for T a power of two, grids, multi-jitter, PMJ, …): then **nothing moves**. For
//! the others (random, best candidate, Poisson disk, Halton, …) the points are partitioned
//! among the T² cells by moving only the excess of overfull cells:
//!
//! 1. **Greedy transport.** Rounds of radius r = 1, 2, 4, … cells (toroidal Chebyshev), until
//!    the window covers the tile: the points still in an overfull cell are paired with their
//!    nearest cell holding fewer than s points within r (distance from the point to the cell,
//!    on the torus; ties by point index, then cell index) and the pairs are taken in increasing
//!    distance; a pair whose cell has filled is re-targeted, one whose source cell is no longer
//!    overfull is dropped. Each move fixes one unit of excess, so when the rounds finish the
//!    number of moved points is the minimum any exact partition needs, Σ max(0, count − s).
//! 2. **Fallback** (only when a round would test more than max(2²⁷, 32·N) cells, e.g. a van der
//!    Corput pattern on one line at a large T): the points of the cells still overfull and the
//!    remaining deficits go through a capacity k-d split. The tile is cut across its longer side
//!    after ⌊side/2⌋ cells; R₁ receives the cap(R₁) points first along the cut (ties by the other
//!    coordinate, then by index), recursively, until every cell holds exactly s.
//! 3. **Placement.** A point that stays keeps its offset. A moved point is placed in its new cell
//!    at one of its 4 mirror images (per axis its offset o or 1 − o, so each coordinate's values
//!    are kept): the one whose toroidal distance to the nearest point placed so far, capped at one
//!    cell, is largest, ties going to the smaller displacement. Moved points are placed in index
//!    order after all the points that stay. This keeps blue-noise patterns well spaced: best
//!    candidate with 1 spp keeps a minimum distance of 0.24–0.33 pixel over the image where
//!    independent per-pixel jitter has 0.05–0.08.
//!
//! [`ImagePlaneProvider::moved`] counts the points that changed cell. Within a pixel the offsets
//! are listed in generation order. T = 1 gives every pixel the same s-point pattern; T = W one
//! pattern over the whole image. Note that a blue-noise *pattern* at one point per pixel does not
//! give a blue-noise *error*: its offsets frac(p·W) fold its spectral peak (near W cycles per
//! image) down to low frequencies (see [`ZSobolProvider`] for a sampler built for that).
//!
//! Cost: the pattern's generation; nothing more for balanced patterns; otherwise the greedy rounds
//! (O((2r+1)²) cell tests per candidate, bounded as above; 7–8 s for 2²² random points and 29 s
//! for 2²⁴ in the optimised test profile on 2 cores), the k-d fallback O(N log T²), and about
//! 48 bytes per point at the peak (800 MB at N = 2²⁴, the limit [`MAX_SAMPLES`]).
//!
//! ## [`ZSobolProvider`]: Ahmed & Wonka 2020, as in pbrt-v4's `ZSobolSampler`
//!
//! A. G. M. Ahmed and P. Wonka, "Screen-space blue-noise diffusion of Monte Carlo sampling error
//! via hierarchical ordering of pixels", ACM TOG 39(6) (SIGGRAPH Asia 2020); M. Pharr, W. Jakob,
//! G. Humphreys, *Physically Based Rendering*, 4th ed., §8.7.7. One Sobol' (0,2)-sequence covers
//! the whole image: sample t of pixel (i, j) takes the sequence index
//!
//! ```text
//! a = π((morton(i, j) << log₂ s) | t),      morton(i, j) = …y₁x₁y₀x₀ (x in the even bits)
//! ```
//!
//! where π randomises the base-4 digits of the index from the most significant down: digit d at
//! level ℓ is replaced by σ(d), σ one of the 24 permutations of {0,1,2,3} chosen by
//! `derive_seed(derive_seed(derive_seed(seed, 2), ℓ), digits above ℓ)` (nested, so π is a
//! bijection that maps every Morton-aligned block of 4ᵏ indices onto an aligned block). For odd
//! log₂ s the digits sit at bit pairs (2ℓ−1, 2ℓ) so that they stay aligned with the pixel
//! quadtree, and bit 0 is flipped by a hash of the bits above it. The pixel's offset is the 2D
//! Sobol' point of index a, Owen-scrambled ([`owen_scramble`], seeds `derive_seed(seed, 0)` for
//! x and `derive_seed(seed, 1)` for y), used directly as the offset in [0,1)². Consequences
//! (tested exactly): each pixel's s offsets are a (0, log₂ s, 2)-net (for s = 4: one per 2×2
//! sub-pixel cell), and the offsets of the 4ᵏ pixels of a Morton-aligned 2ᵏ×2ᵏ block together
//! form a (0, 2k + log₂ s, 2)-net, so neighbouring pixels sample complementary parts of the pixel
//! and the error is pushed to high screen-space frequencies (blue noise).
//! spp must be a power of two (like pbrt, which warns and rounds down; here other counts are a
//! [`ReconError::ProviderSpp`] error). Indices have 2⌈log₂ W⌉ + log₂ s ≤ 38 bits: dimension 1
//! uses the direction numbers up to bit 63 (Pascal's matrix mod 2, truncated to the 32 output
//! digits); in dimension 0 index bits ≥ 32 only reach digits below 2⁻³² (32-bit output, as pbrt).
//! Cost: per sample, ⌈log₂ W⌉ + ⌈log₂ s / 2⌉ hashes, one 32-step Sobol' product and two scrambles.
//!
//! ## Error spectra
//!
//! [`error_periodogram`] is P(k) = |Σₓ e(x) exp(−2πi k·x/W)|² / W² of a W×W error image (2D FFT
//! with rustfft, rows in parallel; O(W² log W), 16·W² bytes, W ≤ 4096), laid out with DC in the
//! centre as the crate's spectra ([`crate::core::spectrum`]). [`low_frequency_energy`] is the
//! fraction of the error's energy (over k ≠ 0, which by Parseval is Σ(e − ē)²) at 0 < |k| ≤ r
//! cycles per image: ≈ (frequencies in the disc)/(W² − 1) for white noise, much less for blue
//! noise.

use super::supersample::SampleProvider;
use super::{check_cancel, check_size, ReconError, MAX_SAMPLES, MAX_SPP, MAX_W};
use crate::core::cancel::Cancel;
use crate::core::pattern::lowdisc::{owen_scramble, sobol_point_u32};
use crate::core::pattern::{clamp_unit, Pattern};
use crate::core::rng::derive_seed;
use crate::core::torus;
use glam::DVec2;
use rayon::prelude::*;
use rustfft::num_complex::Complex;
use rustfft::FftPlanner;
use std::cmp::{Ordering, Reverse};
use std::collections::BinaryHeap;

/// Work unit: k-d nodes with more points check the cancel token and split in parallel; the
/// greedy rounds check it every this many pairs.
const PAR_POINTS: usize = 1 << 14;

/// Largest W accepted by [`error_periodogram`] and [`low_frequency_energy`]
/// (= [`crate::core::spectrum::MAX_SIZE`]: a 4096² complex FFT buffer is 256 MiB).
pub const MAX_SPECTRUM_W: usize = crate::core::spectrum::MAX_SIZE;

/// A rectangle of tile cells [x0, x1) × [y0, y1).
#[derive(Debug, Clone, Copy)]
struct Rect {
    x0: usize,
    x1: usize,
    y0: usize,
    y1: usize,
}

impl Rect {
    fn cells(&self) -> usize {
        (self.x1 - self.x0) * (self.y1 - self.y0)
    }

    /// The cut of the k-d split: across the longer side after ⌊side/2⌋ cells; axis 0 = x.
    fn split(&self) -> (Rect, Rect, usize) {
        let (w, h) = (self.x1 - self.x0, self.y1 - self.y0);
        if w >= h {
            let xm = self.x0 + w / 2;
            (Rect { x1: xm, ..*self }, Rect { x0: xm, ..*self }, 0)
        } else {
            let ym = self.y0 + h / 2;
            (Rect { y1: ym, ..*self }, Rect { y0: ym, ..*self }, 1)
        }
    }
}

/// Capacities of the tile's cells with a summed-area table for the capacity of any rectangle.
struct Capacities {
    t: usize,
    /// `sat[y·(T+1) + x]` = Σ cap over cells [0, x) × [0, y).
    sat: Vec<u32>,
}

impl Capacities {
    fn new(cap: &[u32], t: usize) -> Self {
        let mut sat = vec![0u32; (t + 1) * (t + 1)];
        for y in 0..t {
            let mut row = 0u32;
            for x in 0..t {
                row += cap[y * t + x];
                sat[(y + 1) * (t + 1) + x + 1] = sat[y * (t + 1) + x + 1] + row;
            }
        }
        Capacities { t, sat }
    }

    fn of(&self, r: Rect) -> usize {
        let s = |x: usize, y: usize| self.sat[y * (self.t + 1) + x] as usize;
        s(r.x1, r.y1) + s(r.x0, r.y0) - s(r.x0, r.y1) - s(r.x1, r.y0)
    }
}

/// The order of a cut along `axis`: the coordinate, then the other one, then the index (a
/// strict total order, so the set each side receives is unique).
#[inline]
fn key_cmp(pts: &[DVec2], axis: usize, a: u32, b: u32) -> Ordering {
    let (p, q) = (pts[a as usize], pts[b as usize]);
    let (pa, pb, sa, sb) = if axis == 0 {
        (p.x, q.x, p.y, q.y)
    } else {
        (p.y, q.y, p.x, q.x)
    };
    pa.total_cmp(&pb).then(sa.total_cmp(&sb)).then(a.cmp(&b))
}

/// The tile cell (cx, cy) a unit-square point falls in (clamped: x·T may round up to T).
#[inline]
fn cell_of(p: DVec2, t: usize) -> (usize, usize) {
    let tf = t as f64;
    (
        ((p.x * tf) as usize).min(t - 1),
        ((p.y * tf) as usize).min(t - 1),
    )
}

/// The point's offset inside its own cell, in [0, 1)².
#[inline]
fn own_offset(p: DVec2, t: usize) -> DVec2 {
    let (cx, cy) = cell_of(p, t);
    let tf = t as f64;
    DVec2::new(
        clamp_unit(p.x * tf - cx as f64),
        clamp_unit(p.y * tf - cy as f64),
    )
}

/// The placed offsets of the tile, cell-major (cell c = cy·T + cx owns slots c·s ..< (c+1)·s,
/// the first `filled[c]` of them used), with the pattern index of each.
struct Placement {
    t: usize,
    s: usize,
    offsets: Vec<DVec2>,
    sources: Vec<u32>,
    filled: Vec<u32>,
}

impl Placement {
    fn push(&mut self, c: usize, q: usize, u: DVec2) {
        let slot = c * self.s + self.filled[c] as usize;
        self.offsets[slot] = u;
        self.sources[slot] = q as u32;
        self.filled[c] += 1;
    }

    /// For each of the 4 images `at[k]` in cell (bx, by): the squared toroidal distance (tile
    /// units) to the nearest point placed so far, capped at 1 (one cell). Points outside the
    /// 3×3 cells around (bx, by) are at least one cell away, so the capped value is exact.
    fn nearest_d2(&self, at: &[DVec2; 4], bx: usize, by: usize) -> [f64; 4] {
        let (t, tf) = (self.t, self.t as f64);
        let mut best = [1.0f64; 4];
        for cy in window(by, 1, t) {
            for cx in window(bx, 1, t) {
                let c = cy * t + cx;
                let corner = DVec2::new(cx as f64, cy as f64);
                let used = c * self.s..c * self.s + self.filled[c] as usize;
                for &u in &self.offsets[used] {
                    let p = corner + u;
                    for (b, a) in best.iter_mut().zip(at) {
                        *b = b.min(torus::distance_squared(*a, p, tf));
                    }
                }
            }
        }
        best
    }
}

/// Places every point q in its assigned cell `cell[q]` (module docs): unmoved points keep their
/// offset; a moved point takes, per axis, its offset o or its mirror 1 − o, choosing among
/// those 4 images in the receiving cell the one whose toroidal distance to the nearest point
/// placed so far, capped at one cell, is largest; ties go to the smaller displacement. Unmoved points
/// are placed first, then the moved ones in index order; each cell's offsets are finally put in
/// generation order. Returns (offsets, sources, moved), cell-major.
fn relocate(
    pts: &[DVec2],
    cell: &[u32],
    t: usize,
    s: usize,
    cancel: &Cancel,
) -> Result<(Vec<DVec2>, Vec<u32>, usize), ReconError> {
    let tf = t as f64;
    let own = |q: usize| {
        let (cx, cy) = cell_of(pts[q], t);
        cy * t + cx
    };
    let mut pl = Placement {
        t,
        s,
        offsets: vec![DVec2::ZERO; pts.len()],
        sources: vec![0; pts.len()],
        filled: vec![0; t * t],
    };
    for (q, &c) in cell.iter().enumerate() {
        if c as usize == own(q) {
            pl.push(c as usize, q, own_offset(pts[q], t));
        }
    }
    let mut moved = 0;
    for q in (0..pts.len()).filter(|&q| cell[q] as usize != own(q)) {
        if moved % 4096 == 0 {
            check_cancel(cancel)?;
        }
        moved += 1;
        let b = cell[q] as usize;
        let (bx, by) = (b % t, b / t);
        let o = own_offset(pts[q], t);
        let origin = pts[q] * tf;
        let (mx, my) = (clamp_unit(1.0 - o.x), clamp_unit(1.0 - o.y));
        let images = [
            DVec2::new(o.x, o.y),
            DVec2::new(mx, o.y),
            DVec2::new(o.x, my),
            DVec2::new(mx, my),
        ];
        let corner = DVec2::new(bx as f64, by as f64);
        let at = images.map(|u| corner + u);
        let score = pl.nearest_d2(&at, bx, by);
        let mut best: Option<(f64, f64, DVec2)> = None; // (score, −displacement², offset)
        for k in 0..4 {
            let cand = (
                score[k],
                -torus::distance_squared(at[k], origin, tf),
                images[k],
            );
            if best.is_none_or(|(s0, d0, _)| (cand.0, cand.1) > (s0, d0)) {
                best = Some(cand);
            }
        }
        pl.push(b, q, best.map_or(o, |b| b.2));
    }
    if s > 1 {
        let mut pairs = Vec::with_capacity(s);
        for c in 0..t * t {
            let r = c * s..(c + 1) * s;
            pairs.clear();
            let (src, off) = (&pl.sources[r.clone()], &pl.offsets[r.clone()]);
            pairs.extend(src.iter().copied().zip(off.iter().copied()));
            pairs.sort_unstable_by_key(|&(q, _)| q);
            for (k, &(q, u)) in pairs.iter().enumerate() {
                pl.sources[c * s + k] = q;
                pl.offsets[c * s + k] = u;
            }
        }
    }
    Ok((pl.offsets, pl.sources, moved))
}

/// Cells a greedy round may test before the k-d split takes over (bounds its time): the larger
/// of this and 32 per point.
const GREEDY_WORK: usize = 1 << 27;

/// Distance (cell units) along one axis from a point at offset f ∈ [0, 1) in cell a to cell b
/// of a ring of T cells, the shorter way round the torus; 0 when a = b.
#[inline]
fn axis_gap(f: f64, a: usize, b: usize, t: usize) -> f64 {
    if a == b {
        return 0.0;
    }
    let da = (b + t - a) % t; // 1 ..< T steps upwards from a to b
    let up = da as f64 - f; // to b's lower edge, going up
    let down = (t - da) as f64 - 1.0 + f; // to b's upper edge, going down
    up.min(down)
}

/// The cells of a toroidal window of radius r around a (each once), without allocating.
#[inline]
fn window(a: usize, r: usize, t: usize) -> impl ExactSizeIterator<Item = usize> {
    let (start, len) = if 2 * r + 1 >= t {
        (0, t)
    } else {
        ((a + t - r) % t, 2 * r + 1)
    };
    (0..len).map(move |k| (start + k) % t)
}

/// The nearest deficit cell to point `q` within radius r: (squared gap bits, q, cell), the
/// smallest tuple winning ties.
fn best_target(
    q: u32,
    pts: &[DVec2],
    t: usize,
    s: usize,
    r: usize,
    count: &[u32],
) -> Option<(u64, u32, u32)> {
    let p = pts[q as usize];
    let (ax, ay) = cell_of(p, t);
    let o = own_offset(p, t);
    // The window's columns with their gaps, on the stack up to r = 16.
    let mut stack = [(0usize, 0.0f64); 33];
    let mut heap_cols = Vec::new();
    let cols: &[(usize, f64)] = if window(ax, r, t).len() <= stack.len() {
        let mut n = 0;
        for bx in window(ax, r, t) {
            stack[n] = (bx, axis_gap(o.x, ax, bx, t));
            n += 1;
        }
        &stack[..n]
    } else {
        heap_cols.extend(window(ax, r, t).map(|bx| (bx, axis_gap(o.x, ax, bx, t))));
        &heap_cols
    };
    let mut best: Option<(u64, u32, u32)> = None;
    for by in window(ay, r, t) {
        let gy = axis_gap(o.y, ay, by, t);
        let row = &count[by * t..(by + 1) * t];
        for &(bx, gx) in cols {
            if row[bx] as usize >= s {
                continue;
            }
            // Non-negative f64: its bits order like its value.
            let key = ((gx * gx + gy * gy).to_bits(), q, (by * t + bx) as u32);
            if best.is_none_or(|k| key < k) {
                best = Some(key);
            }
        }
    }
    best
}

/// The points of each cell's own geometric set, CSR: cell c's are `list[start[c]..start[c+1]]`.
struct ByCell {
    start: Vec<u32>,
    list: Vec<u32>,
}

impl ByCell {
    fn new(cell: &[u32], cells: usize) -> Self {
        let mut start = vec![0u32; cells + 1];
        for &c in cell {
            start[c as usize + 1] += 1;
        }
        for c in 0..cells {
            start[c + 1] += start[c];
        }
        let mut fill = start.clone();
        let mut list = vec![0u32; cell.len()];
        for (q, &c) in cell.iter().enumerate() {
            list[fill[c as usize] as usize] = q as u32;
            fill[c as usize] += 1;
        }
        ByCell { start, list }
    }

    /// The points still in their own cell, for cells holding more than s points.
    fn overfull_home(&self, cell: &[u32], count: &[u32], s: usize) -> Vec<u32> {
        let mut out = Vec::new();
        for (c, &n) in count.iter().enumerate() {
            if n as usize > s {
                let own = &self.list[self.start[c] as usize..self.start[c + 1] as usize];
                out.extend(own.iter().filter(|&&q| cell[q as usize] as usize == c));
            }
        }
        out
    }
}

/// The points of a tile of T×T cells that must hold s points each.
struct Tile<'a> {
    pts: &'a [DVec2],
    t: usize,
    s: usize,
}

/// The cell of every point and the number of points of every cell, during the partition.
struct Assignment {
    cell: Vec<u32>,
    count: Vec<u32>,
}

/// One greedy round: the nearest (point, deficit cell) pairs within radius r first, lazily
/// re-targeted when a deficit fills; only points of overfull cells move, and each cell keeps s.
/// Returns false when the round was skipped or stopped for its cost: more than `limit` cells
/// tested, initial targets and re-targets together.
fn greedy_round(
    tile: &Tile,
    r: usize,
    state: &mut Assignment,
    home: &ByCell,
    limit: usize,
    cancel: &Cancel,
) -> Result<bool, ReconError> {
    let (pts, t, s) = (tile.pts, tile.t, tile.s);
    let (cell, count) = (&mut state.cell[..], &mut state.count[..]);
    let candidates = home.overfull_home(cell, count, s);
    let per = window(0, r, t).len().pow(2);
    let mut work = candidates.len().saturating_mul(per);
    if work > limit {
        return Ok(false);
    }
    check_cancel(cancel)?;
    // The initial targets sorted once (unique keys: a unique order), the re-targets in a
    // heap; each step takes the smaller of the two heads, i.e. the smallest pending pair.
    let mut first: Vec<(u64, u32, u32)> = candidates
        .par_iter()
        .filter_map(|&q| best_target(q, pts, t, s, r, count))
        .collect();
    first.par_sort_unstable();
    let mut heap: BinaryHeap<Reverse<(u64, u32, u32)>> = BinaryHeap::new();
    let mut next_first = 0;
    let mut pops = 0usize;
    loop {
        let take_first = match (first.get(next_first), heap.peek()) {
            (Some(a), Some(Reverse(b))) => a < b,
            (Some(_), None) => true,
            (None, Some(_)) => false,
            (None, None) => break,
        };
        let (_, q, b) = if take_first {
            next_first += 1;
            first[next_first - 1]
        } else {
            heap.pop().map(|Reverse(k)| k).unwrap_or_default()
        };
        pops += 1;
        if pops % PAR_POINTS == 0 {
            check_cancel(cancel)?;
        }
        let a = cell[q as usize] as usize;
        if count[a] as usize <= s {
            continue; // its cell is no longer overfull: q stays
        }
        if count[b as usize] as usize >= s {
            work += per;
            if work > limit {
                return Ok(false); // the state stays consistent: the k-d split finishes it
            }
            if let Some(next) = best_target(q, pts, t, s, r, count) {
                heap.push(Reverse(next));
            }
            continue;
        }
        count[a] -= 1;
        count[b as usize] += 1;
        cell[q as usize] = b;
    }
    Ok(true)
}

/// The capacity k-d split: distributes `idx` over the cells of `rect` so that every cell gets
/// exactly its capacity. At each cut, R₁ receives the cap(R₁) points first along the cut axis.
fn kd_split(
    idx: &mut [u32],
    pts: &[DVec2],
    caps: &Capacities,
    rect: Rect,
    cancel: &Cancel,
) -> Result<(), ReconError> {
    if rect.cells() == 1 || idx.is_empty() {
        return Ok(());
    }
    if idx.len() >= PAR_POINTS {
        check_cancel(cancel)?;
    }
    let (r1, r2, axis) = rect.split();
    let k = caps.of(r1);
    if k > 0 && k < idx.len() {
        idx.select_nth_unstable_by(k, |&a, &b| key_cmp(pts, axis, a, b));
    }
    let big = idx.len() >= PAR_POINTS;
    let (lo, hi) = idx.split_at_mut(k);
    if big {
        let (a, b) = rayon::join(
            || kd_split(lo, pts, caps, r1, cancel),
            || kd_split(hi, pts, caps, r2, cancel),
        );
        a.and(b)
    } else {
        kd_split(lo, pts, caps, r1, cancel)?;
        kd_split(hi, pts, caps, r2, cancel)
    }
}

/// The cells of positive capacity in [`kd_split`]'s leaf order, with their capacities.
fn leaf_cells(rect: Rect, caps: &Capacities, out: &mut Vec<(usize, usize)>) {
    let c = caps.of(rect);
    if c == 0 {
        return;
    }
    if rect.cells() == 1 {
        out.push((rect.y0 * caps.t + rect.x0, c));
        return;
    }
    let (r1, r2, _) = rect.split();
    leaf_cells(r1, caps, out);
    leaf_cells(r2, caps, out);
}

/// Assigns the points `participants` to cells with capacities `cap` (Σ cap = their number)
/// by the capacity k-d split; writes `cell[q]`.
fn kd_assign(
    participants: Vec<u32>,
    cap: &[u32],
    pts: &[DVec2],
    t: usize,
    cell: &mut [u32],
    cancel: &Cancel,
) -> Result<(), ReconError> {
    let rect = Rect {
        x0: 0,
        x1: t,
        y0: 0,
        y1: t,
    };
    let caps = Capacities::new(cap, t);
    debug_assert_eq!(caps.of(rect), participants.len());
    let mut idx = participants;
    kd_split(&mut idx, pts, &caps, rect, cancel)?;
    let mut leaves = Vec::new();
    leaf_cells(rect, &caps, &mut leaves);
    let mut at = 0;
    for (c, k) in leaves {
        for &q in &idx[at..at + k] {
            cell[q as usize] = c as u32;
        }
        at += k;
    }
    Ok(())
}

/// The partition of the module docs: the cell (cy·T + cx) of every point, s points per cell.
fn partition(pts: &[DVec2], t: usize, s: usize, cancel: &Cancel) -> Result<Vec<u32>, ReconError> {
    partition_with(pts, t, s, GREEDY_WORK.max(32 * pts.len()), cancel)
}

/// [`partition`] with the greedy rounds' work limit as a parameter (tests force the k-d
/// fallback with small limits).
fn partition_with(
    pts: &[DVec2],
    t: usize,
    s: usize,
    limit: usize,
    cancel: &Cancel,
) -> Result<Vec<u32>, ReconError> {
    let cell: Vec<u32> = pts
        .iter()
        .map(|p| {
            let (cx, cy) = cell_of(*p, t);
            (cy * t + cx) as u32
        })
        .collect();
    let mut count = vec![0u32; t * t];
    for &c in &cell {
        count[c as usize] += 1;
    }
    let balanced = |count: &[u32]| count.iter().all(|&c| c as usize == s);
    if balanced(&count) {
        return Ok(cell);
    }
    let home = ByCell::new(&cell, t * t);
    let tile = Tile { pts, t, s };
    let mut state = Assignment { cell, count };
    // Greedy rounds of radius 1, 2, 4, … cells until the window covers the torus (2r + 1 ≥ T).
    let mut r = 1;
    loop {
        if !greedy_round(&tile, r, &mut state, &home, limit, cancel)? {
            break;
        }
        if balanced(&state.count) {
            return Ok(state.cell);
        }
        if 2 * r + 1 >= t {
            break;
        }
        r *= 2;
    }
    let Assignment { mut cell, count } = state;
    // Fallback: the points of the cells still overfull (which keep capacity s) and the
    // remaining deficits, by the capacity k-d split.
    let participants = home.overfull_home(&cell, &count, s);
    let cap: Vec<u32> = count
        .iter()
        .map(|&c| {
            if c as usize > s {
                s as u32
            } else {
                s as u32 - c
            }
        })
        .collect();
    kd_assign(participants, &cap, pts, t, &mut cell, cancel)?;
    Ok(cell)
}

/// Sample offsets from one pattern of s·T² points tiled over the image (see the module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct ImagePlaneProvider {
    w: usize,
    spp: usize,
    tile: usize,
    /// Cell-major: cell c = cy·T + cx holds `offsets[c·s .. (c+1)·s]`.
    offsets: Vec<DVec2>,
    /// The pattern index of each offset (same layout).
    sources: Vec<u32>,
    moved: usize,
}

impl ImagePlaneProvider {
    /// Generates `pattern` once with s·T² points (`pattern.generate_with(spp·T², seed, cancel)`)
    /// and partitions it among the T×T cells of the tile, T = `tile` (0 = W).
    ///
    /// Errors: `w` outside 1..=8192, `spp` outside 1..=4096, `tile` outside 0..=W
    /// ([`ReconError::OutOfRange`]); s·T² > 2²⁴ (`tile` with the largest allowed T); the
    /// pattern's own errors; a pattern that placed fewer than s·T² points
    /// ([`ReconError::LengthMismatch`]); cancellation.
    pub fn new(
        pattern: &Pattern,
        w: usize,
        spp: usize,
        seed: u64,
        tile: usize,
        cancel: &Cancel,
    ) -> Result<Self, ReconError> {
        check_size("w", w, 1, MAX_W)?;
        check_size("spp", spp, 1, MAX_SPP)?;
        check_size("tile", tile, 0, w)?;
        let t = if tile == 0 { w } else { tile };
        // The largest T with s·T² ≤ 2²⁴ (integer square root, settled exactly), at most W.
        let mut max_t = ((MAX_SAMPLES / spp) as f64).sqrt() as usize;
        while max_t * max_t * spp > MAX_SAMPLES {
            max_t -= 1;
        }
        while (max_t + 1) * (max_t + 1) * spp <= MAX_SAMPLES {
            max_t += 1;
        }
        let max_t = max_t.min(w);
        if t * t * spp > MAX_SAMPLES {
            return Err(ReconError::OutOfRange {
                field: "tile",
                value: t,
                min: 1,
                max: max_t,
            });
        }
        let n = spp * t * t;
        let generated = pattern.generate_with(n, seed, cancel)?;
        let pts = generated.points;
        if pts.len() != n {
            return Err(ReconError::LengthMismatch {
                field: "pattern points",
                got: pts.len(),
                expected: n,
                per: "sample of the tile, spp·tile²",
            });
        }
        for (index, p) in pts.iter().enumerate() {
            if !((0.0..1.0).contains(&p.x) && (0.0..1.0).contains(&p.y)) {
                return Err(ReconError::OutOfDomain {
                    index,
                    x: p.x,
                    y: p.y,
                });
            }
        }
        check_cancel(cancel)?;
        let cell = partition(&pts, t, spp, cancel)?;
        check_cancel(cancel)?;
        let (offsets, sources, moved) = relocate(&pts, &cell, t, spp, cancel)?;
        drop(pts);
        Ok(ImagePlaneProvider {
            w,
            spp,
            tile: t,
            offsets,
            sources,
            moved,
        })
    }

    /// Image size W.
    pub fn w(&self) -> usize {
        self.w
    }

    /// Samples per pixel s.
    pub fn spp(&self) -> usize {
        self.spp
    }

    /// Tile size T in pixels (W when built with `tile = 0`).
    pub fn tile(&self) -> usize {
        self.tile
    }

    /// Points of the pattern, s·T².
    pub fn len(&self) -> usize {
        self.offsets.len()
    }

    /// Never true (a tile has at least one point); for clippy's `len` convention.
    pub fn is_empty(&self) -> bool {
        self.offsets.is_empty()
    }

    /// How many points the partition moved to a cell they do not lie in (0 for patterns with
    /// exactly s points per cell).
    pub fn moved(&self) -> usize {
        self.moved
    }

    /// The s offsets of tile cell (cx, cy), cx, cy < T, in generation order.
    pub fn cell_offsets(&self, cx: usize, cy: usize) -> &[DVec2] {
        let c = (cy % self.tile) * self.tile + cx % self.tile;
        &self.offsets[c * self.spp..(c + 1) * self.spp]
    }

    /// The tile's sample positions after the partition, in tile units [0,1)²
    /// ((cx + u)/T, (cy + v)/T), cell-major: for display.
    pub fn positions(&self) -> Vec<DVec2> {
        let (t, tf) = (self.tile, self.tile as f64);
        self.offsets
            .iter()
            .enumerate()
            .map(|(slot, u)| {
                let c = slot / self.spp;
                DVec2::new(((c % t) as f64 + u.x) / tf, ((c / t) as f64 + u.y) / tf)
            })
            .collect()
    }
}

impl SampleProvider for ImagePlaneProvider {
    /// The offsets of tile cell (i mod T, j mod T) for pixel = j·W + i. Errors: `spp` other
    /// than the one the provider was built with, `pixel` ≥ W².
    fn offsets(&self, pixel: u64, spp: usize, out: &mut Vec<DVec2>) -> Result<(), ReconError> {
        if spp != self.spp {
            return Err(ReconError::ProviderSpp {
                provider: "image plane",
                spp,
                allowed: format!("{} (the spp the provider was built with)", self.spp),
            });
        }
        let pixels = (self.w * self.w) as u64;
        if pixel >= pixels {
            return Err(ReconError::OutOfRange {
                field: "pixel",
                value: pixel.min(usize::MAX as u64) as usize,
                min: 0,
                max: (pixels - 1) as usize,
            });
        }
        let (i, j) = (
            (pixel % self.w as u64) as usize,
            (pixel / self.w as u64) as usize,
        );
        out.extend_from_slice(self.cell_offsets(i, j));
        Ok(())
    }
}

/// Direction numbers of Sobol' dimension 1 for index bits 32..64 (V_33 … V_64), truncated to
/// the 32 output digits: ⌊m_k · 2^(32−k)⌋ = m_k ≫ (k − 32), m_k = row k−1 of Pascal's triangle
/// mod 2 read as a binary number (m_1 = 1, m_k = m_{k−1} ⊕ 2m_{k−1}).
const SOBOL_Y_HIGH: [u32; 32] = sobol_y_high();

const fn sobol_y_high() -> [u32; 32] {
    let mut out = [0u32; 32];
    let mut m: u64 = 1;
    let mut k = 1;
    while k <= 64 {
        if k > 32 {
            out[k - 33] = (m >> (k - 32)) as u32;
        }
        m ^= m << 1;
        k += 1;
    }
    out
}

/// The unscrambled 32-bit 2D Sobol' point of a 64-bit natural index: [`sobol_point_u32`] of
/// the low 32 bits, plus the high bits' columns in dimension 1 (see [`SOBOL_Y_HIGH`]).
fn sobol_point_u64(a: u64) -> [u32; 2] {
    let [x, mut y] = sobol_point_u32(a as u32);
    let mut hi = a >> 32;
    let mut k = 0;
    while hi != 0 {
        if hi & 1 == 1 {
            y ^= SOBOL_Y_HIGH[k];
        }
        hi >>= 1;
        k += 1;
    }
    [x, y]
}

/// Interleaves the bits of x (even positions) and y (odd): the Morton (Z-order) code.
#[inline]
fn morton2(x: u32, y: u32) -> u64 {
    fn spread(v: u32) -> u64 {
        let mut x = u64::from(v);
        x = (x | (x << 16)) & 0x0000_FFFF_0000_FFFF;
        x = (x | (x << 8)) & 0x00FF_00FF_00FF_00FF;
        x = (x | (x << 4)) & 0x0F0F_0F0F_0F0F_0F0F;
        x = (x | (x << 2)) & 0x3333_3333_3333_3333;
        (x | (x << 1)) & 0x5555_5555_5555_5555
    }
    spread(x) | (spread(y) << 1)
}

/// The 24 permutations of {0, 1, 2, 3} in lexicographic order.
const PERMUTATIONS_4: [[u8; 4]; 24] = permutations_4();

const fn permutations_4() -> [[u8; 4]; 24] {
    let mut out = [[0u8; 4]; 24];
    let mut n = 0;
    let mut a = 0;
    while a < 4 {
        let mut b = 0;
        while b < 4 {
            let mut c = 0;
            while c < 4 {
                if a != b && a != c && b != c {
                    out[n] = [a, b, c, (6 - a - b - c)];
                    n += 1;
                }
                c += 1;
            }
            b += 1;
        }
        a += 1;
    }
    out
}

/// Uniform choice in 0..24 from 64 hashed bits (multiply-high, bias ≤ 24/2⁶⁴).
#[inline]
fn below_24(h: u64) -> usize {
    ((u128::from(h) * 24) >> 64) as usize
}

/// Z-order Sobol' sampling (Ahmed & Wonka 2020; pbrt-v4's `ZSobolSampler`): see the module docs.
///
/// `pixel = j·W + i`; spp must be a power of two in 1..=4096.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ZSobolProvider {
    /// Seed of the index permutation and of the Owen scrambling.
    pub seed: u64,
    /// Image size W (the Morton codes need it to locate pixel j·W + i).
    pub w: usize,
}

impl ZSobolProvider {
    /// Base-4 digits of the permuted index: ⌈log₂ W⌉ + ⌈log₂ s / 2⌉.
    fn digits(&self, log2_spp: u32) -> u32 {
        let res_log2 = self.w.next_power_of_two().trailing_zeros();
        res_log2 + log2_spp.div_ceil(2)
    }

    /// The permuted sequence index π(m) of the Morton sample index m (module docs).
    fn sample_index(&self, m: u64, log2_spp: u32) -> u64 {
        let odd = log2_spp & 1 == 1;
        let perm_seed = derive_seed(self.seed, 2);
        let mut a = 0u64;
        let digits = self.digits(log2_spp);
        let last = u32::from(odd);
        for level in (last..digits).rev() {
            let shift = 2 * level - last;
            let digit = ((m >> shift) & 3) as usize;
            let higher = m >> (shift + 2);
            let p = below_24(derive_seed(
                derive_seed(perm_seed, u64::from(level)),
                higher,
            ));
            a |= u64::from(PERMUTATIONS_4[p][digit]) << shift;
        }
        if odd {
            let flip = derive_seed(derive_seed(self.seed, 3), m >> 1) & 1;
            a |= (m & 1) ^ flip;
        }
        a
    }
}

impl SampleProvider for ZSobolProvider {
    fn offsets(&self, pixel: u64, spp: usize, out: &mut Vec<DVec2>) -> Result<(), ReconError> {
        check_size("w", self.w, 1, MAX_W)?;
        if !spp.is_power_of_two() || spp > MAX_SPP {
            return Err(ReconError::ProviderSpp {
                provider: "zsobol",
                spp,
                allowed: format!("a power of two in 1..={MAX_SPP}"),
            });
        }
        let pixels = (self.w * self.w) as u64;
        if pixel >= pixels {
            return Err(ReconError::OutOfRange {
                field: "pixel",
                value: pixel.min(usize::MAX as u64) as usize,
                min: 0,
                max: (pixels - 1) as usize,
            });
        }
        let (i, j) = (
            (pixel % self.w as u64) as u32,
            (pixel / self.w as u64) as u32,
        );
        let log2_spp = spp.trailing_zeros();
        let base = morton2(i, j) << log2_spp;
        let (sx, sy) = (derive_seed(self.seed, 0), derive_seed(self.seed, 1));
        const TWO_POW_M32: f64 = 1.0 / 4_294_967_296.0;
        for t in 0..spp as u64 {
            let [x, y] = sobol_point_u64(self.sample_index(base | t, log2_spp));
            out.push(DVec2::new(
                f64::from(owen_scramble(x, sx)) * TWO_POW_M32,
                f64::from(owen_scramble(y, sy)) * TWO_POW_M32,
            ));
        }
        Ok(())
    }
}

/// Checks a W×W error image for the spectrum functions.
fn check_error_image(error: &[f64], w: usize) -> Result<(), ReconError> {
    check_size("w", w, 1, MAX_SPECTRUM_W)?;
    if error.len() != w * w {
        return Err(ReconError::LengthMismatch {
            field: "error",
            got: error.len(),
            expected: w * w,
            per: "pixel of the W×W image",
        });
    }
    if let Some((index, &value)) = error.iter().enumerate().find(|(_, v)| !v.is_finite()) {
        return Err(ReconError::NonFinite {
            field: "error",
            index,
            value,
        });
    }
    Ok(())
}

/// The 2D DFT F[ky·W + kx] = Σ e(x, y) exp(−2πi(kx·x + ky·y)/W), FFT index order.
fn fft2(error: &[f64], w: usize) -> Vec<Complex<f64>> {
    let fft = FftPlanner::<f64>::new().plan_fft_forward(w);
    let scratch_len = fft.get_inplace_scratch_len();
    let mut buf: Vec<Complex<f64>> = error.iter().map(|&e| Complex::new(e, 0.0)).collect();
    let rows = |buf: &mut Vec<Complex<f64>>| {
        buf.par_chunks_mut(w).for_each_init(
            || vec![Complex::new(0.0, 0.0); scratch_len],
            |scratch, row| fft.process_with_scratch(row, scratch),
        );
    };
    let transpose = |buf: &mut Vec<Complex<f64>>| {
        for r in 0..w {
            for c in r + 1..w {
                buf.swap(r * w + c, c * w + r);
            }
        }
    };
    rows(&mut buf);
    transpose(&mut buf);
    rows(&mut buf);
    transpose(&mut buf);
    buf
}

/// The periodogram P(k) = |F(k)|²/W² of a W×W error image (`error[j·W + i]`), centred: entry
/// `[iy·W + ix]` is kx = ix − ⌊W/2⌋, ky = iy − ⌊W/2⌋, DC at (⌊W/2⌋, ⌊W/2⌋) (the layout of
/// [`crate::core::spectrum`]). Σ P = Σ e² (Parseval).
///
/// Errors: W outside 1..=4096, `error.len() ≠ W²`, a non-finite entry.
pub fn error_periodogram(error: &[f64], w: usize) -> Result<Vec<f64>, ReconError> {
    check_error_image(error, w)?;
    let f = fft2(error, w);
    let norm = 1.0 / (w * w) as f64;
    let half = w / 2;
    let mut out = vec![0.0; w * w];
    for iy in 0..w {
        let fy = (iy + w - half) % w;
        for ix in 0..w {
            let fx = (ix + w - half) % w;
            out[iy * w + ix] = f[fy * w + fx].norm_sqr() * norm;
        }
    }
    Ok(out)
}

/// The fraction of the error's energy at low frequencies: Σ P(k) over 0 < |k| ≤ `radius`
/// (k in cycles per image, each component in −⌊W/2⌋ ..< W − ⌊W/2⌋) divided by Σ P(k) over all
/// k ≠ 0. White noise gives about (frequencies in the disc)/(W² − 1); blue noise much less.
/// 0 when the error has no energy off DC (a constant image) or the disc is empty (radius < 1).
///
/// Errors: as [`error_periodogram`]; a NaN or infinite `radius`.
pub fn low_frequency_energy(error: &[f64], w: usize, radius: f64) -> Result<f64, ReconError> {
    check_error_image(error, w)?;
    if !radius.is_finite() {
        return Err(ReconError::NonFinite {
            field: "radius",
            index: 0,
            value: radius,
        });
    }
    Ok(periodogram_low_frequency_share(
        &error_periodogram(error, w)?,
        w,
        radius,
    ))
}

/// [`low_frequency_energy`] of a centred W×W periodogram already computed
/// ([`error_periodogram`]'s layout: kx = ix − ⌊W/2⌋): Σ P over 0 < |k| ≤ `radius` divided by
/// Σ P over k ≠ 0; 0 when there is no energy off DC.
pub fn periodogram_low_frequency_share(p: &[f64], w: usize, radius: f64) -> f64 {
    let half = (w / 2) as f64;
    let r2 = radius * radius;
    let (mut low, mut total) = (0.0, 0.0);
    for iy in 0..w {
        let ky = iy as f64 - half;
        for ix in 0..w {
            let kx = ix as f64 - half;
            if kx == 0.0 && ky == 0.0 {
                continue;
            }
            let v = p[iy * w + ix];
            total += v;
            if radius >= 0.0 && kx * kx + ky * ky <= r2 {
                low += v;
            }
        }
    }
    if total > 0.0 {
        low / total
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::pattern::{
        BestCandidate, Grid, Jitter, Random, Scramble, Sobol, ONE_MINUS_EPSILON,
    };
    use crate::core::recon::reference::reference_image;
    use crate::core::recon::supersample::{supersample, PatternProvider};
    use crate::core::recon::ReconKernel;
    use crate::core::rng::Rng;
    use crate::core::signal::{Grating, Signal};

    fn never() -> Cancel {
        Cancel::never()
    }

    /// All offsets of every pixel of the W×W image through the provider interface.
    fn all_offsets<P: SampleProvider>(p: &P, w: usize, spp: usize) -> Vec<Vec<DVec2>> {
        (0..w * w)
            .map(|px| {
                let mut out = Vec::new();
                p.offsets(px as u64, spp, &mut out).unwrap();
                out
            })
            .collect()
    }

    fn in_unit(u: DVec2) -> bool {
        (0.0..1.0).contains(&u.x) && (0.0..1.0).contains(&u.y)
    }

    /// Whether `pts` (2^m of them, in [0,1)²) is a (0,m,2)-net: exactly one point in every
    /// elementary interval of 2^a × 2^(m−a) cells, a = 0..=m.
    fn is_02_net(pts: &[DVec2]) -> bool {
        let n = pts.len();
        assert!(n.is_power_of_two());
        let m = n.trailing_zeros();
        (0..=m).all(|a| {
            let (cx, cy) = (1usize << a, 1usize << (m - a));
            let mut seen = vec![false; n];
            pts.iter().all(|p| {
                let c = ((p.y * cy as f64) as usize) * cx + (p.x * cx as f64) as usize;
                !std::mem::replace(&mut seen[c], true)
            })
        })
    }

    const CONFIGS: [(usize, usize, usize); 3] = [(20, 8, 2), (16, 0, 1), (12, 6, 3)];

    #[test]
    fn every_pixel_gets_spp_offsets_for_every_pattern() {
        for pattern in Pattern::all() {
            for (w, tile, s) in CONFIGS {
                let tn = if tile == 0 { w } else { tile };
                let prov = match ImagePlaneProvider::new(&pattern, w, s, 11, tile, &never()) {
                    Ok(p) => p,
                    // Patterns with their own point counts (e.g. Fibonacci numbers) may refuse
                    // s·T²; then the pattern itself must refuse it too.
                    Err(ReconError::Pattern(e)) => {
                        assert!(pattern.generate(s * tn * tn, 11).is_err());
                        eprintln!("{:>18} refuses n = {}: {e}", pattern.name(), s * tn * tn);
                        continue;
                    }
                    Err(e) => panic!("{} {w} {tile} {s}: {e}", pattern.name()),
                };
                let t = prov.tile();
                assert_eq!(t, if tile == 0 { w } else { tile });
                let n = s * t * t;
                assert_eq!(prov.len(), n);
                // Every pixel: exactly s offsets in [0,1)², those of tile cell (i mod T, j mod T).
                let offs = all_offsets(&prov, w, s);
                for (px, o) in offs.iter().enumerate() {
                    let (i, j) = (px % w, px / w);
                    assert_eq!(o.len(), s);
                    assert!(o.iter().all(|&u| in_unit(u)), "{}", pattern.name());
                    assert_eq!(o.as_slice(), prov.cell_offsets(i % t, j % t));
                }
                // The cells hold every pattern point once; check each against the regenerated
                // pattern: unmoved points keep their offset exactly, moved ones are reflected
                // (mirrored offset on axes with an odd cell displacement, same offset on even).
                let pts = pattern.generate(n, 11).unwrap();
                let mut seen = vec![false; n];
                let mut moved = 0;
                for (slot, &q) in prov.sources.iter().enumerate() {
                    assert!(!std::mem::replace(&mut seen[q as usize], true));
                    let c = slot / s;
                    let (cx, cy) = ((c % t) as i64, (c / t) as i64);
                    let p = pts[q as usize] * t as f64;
                    let (gx, gy) = (
                        (p.x.floor() as i64).min(t as i64 - 1),
                        (p.y.floor() as i64).min(t as i64 - 1),
                    );
                    let u = prov.offsets[slot];
                    let orig = DVec2::new(
                        (p.x - gx as f64).min(ONE_MINUS_EPSILON),
                        (p.y - gy as f64).min(ONE_MINUS_EPSILON),
                    );
                    moved += usize::from((gx, gy) != (cx, cy));
                    // Unmoved points keep their offset exactly; a moved one takes, per axis,
                    // its offset or its mirror.
                    for (ui, oi) in [(u.x, orig.x), (u.y, orig.y)] {
                        if (gx, gy) == (cx, cy) {
                            assert_eq!(ui, oi, "{}", pattern.name());
                        } else {
                            let ok = ui == oi || ui == (1.0 - oi).min(ONE_MINUS_EPSILON);
                            assert!(ok, "{}: {ui} from {oi}", pattern.name());
                        }
                    }
                }
                assert_eq!(moved, prov.moved());
                eprintln!(
                    "{:>18} W={w:>2} T={t:>2} s={s}: moved {moved:>3} of {n}",
                    pattern.name()
                );
            }
        }
    }

    #[test]
    fn stratified_patterns_move_nothing() {
        let owen = Pattern::Sobol(Sobol {
            scramble: Scramble::Owen,
            skip: 0,
        });
        let cases = [
            (Pattern::Jitter(Jitter::default()), 16, 1),
            (Pattern::Jitter(Jitter::default()), 8, 2),
            (Pattern::Jitter(Jitter::default()), 8, 4),
            (Pattern::Grid(Grid::default()), 8, 4),
            (owen, 16, 1),
            (owen, 8, 2),
            (owen, 4, 8),
        ];
        for (p, t, s) in cases {
            let prov = ImagePlaneProvider::new(&p, 32, s, 5, t, &never()).unwrap();
            assert_eq!(prov.moved(), 0, "{} T={t} s={s}", p.name());
            // The capacity k-d split alone (capacity s everywhere) is the identity on them too.
            let pts = p.generate(s * t * t, 5).unwrap();
            let mut cell = vec![u32::MAX; pts.len()];
            let all = (0..pts.len() as u32).collect();
            kd_assign(all, &vec![s as u32; t * t], &pts, t, &mut cell, &never()).unwrap();
            for (q, &c) in cell.iter().enumerate() {
                let (cx, cy) = cell_of(pts[q], t);
                assert_eq!(c as usize, cy * t + cx);
            }
        }
        // Not stratified at pixel resolution: random and best candidate must move points.
        for p in [
            Pattern::Random(Random {}),
            Pattern::BestCandidate(BestCandidate::default()),
        ] {
            let prov = ImagePlaneProvider::new(&p, 32, 1, 5, 16, &never()).unwrap();
            assert!(prov.moved() > 0, "{}", p.name());
        }
    }

    #[test]
    fn jitter_at_one_spp_is_one_jittered_pattern_over_the_image() {
        let w = 32;
        let jit = Pattern::Jitter(Jitter::default());
        let prov = ImagePlaneProvider::new(&jit, w, 1, 7, 0, &never()).unwrap();
        assert_eq!(prov.moved(), 0);
        let pts = jit.generate(w * w, 7).unwrap();
        let offs = all_offsets(&prov, w, 1);
        for j in 0..w {
            for i in 0..w {
                // Jitter lists its strata row-major: point j·W + i lies in stratum (i, j).
                let p = pts[j * w + i];
                let u = offs[j * w + i][0];
                assert_eq!(u.x, p.x * w as f64 - i as f64);
                assert_eq!(u.y, p.y * w as f64 - j as f64);
                let back = DVec2::new((i as f64 + u.x) / w as f64, (j as f64 + u.y) / w as f64);
                assert!((back - p).abs().max_element() < 1e-15);
            }
        }
        // With T = 8 the 8×8 jittered tile repeats by translation.
        let prov = ImagePlaneProvider::new(&jit, w, 1, 7, 8, &never()).unwrap();
        let tile = jit.generate(64, 7).unwrap();
        for (px, o) in all_offsets(&prov, w, 1).iter().enumerate() {
            let (ci, cj) = ((px % w) % 8, (px / w) % 8);
            let p = tile[cj * 8 + ci];
            assert_eq!(
                o[0],
                DVec2::new(p.x * 8.0 - ci as f64, p.y * 8.0 - cj as f64)
            );
        }
    }

    /// Smallest Euclidean distance between two positions (pixel units), all pairs.
    fn min_distance(pts: &[DVec2]) -> f64 {
        let mut best = f64::INFINITY;
        for a in 0..pts.len() {
            for b in a + 1..pts.len() {
                best = best.min(pts[a].distance_squared(pts[b]));
            }
        }
        best.sqrt()
    }

    fn image_positions<P: SampleProvider>(p: &P, w: usize) -> Vec<DVec2> {
        all_offsets(p, w, 1)
            .iter()
            .enumerate()
            .map(|(px, o)| DVec2::new((px % w) as f64, (px / w) as f64) + o[0])
            .collect()
    }

    #[test]
    fn best_candidate_tiling_keeps_points_apart_unlike_per_pixel_jitter() {
        // W = 64, 1 spp, a 32×32 best-candidate tile repeated 2×2, against one jittered point
        // per pixel (independent per pixel); min distance over all 4096 positions, pixel units.
        let w = 64;
        let bc = Pattern::BestCandidate(BestCandidate::default());
        let jit = Pattern::Jitter(Jitter::default());
        let mut rows = Vec::new();
        for seed in [1u64, 2, 3] {
            let prov = ImagePlaneProvider::new(&bc, w, 1, seed, 32, &never()).unwrap();
            let d_bc = min_distance(&image_positions(&prov, w));
            let d_jit = min_distance(&image_positions(&PatternProvider { pattern: jit, seed }, w));
            let d_tile = min_distance(
                &bc.generate(32 * 32, seed)
                    .unwrap()
                    .iter()
                    .map(|p| *p * 32.0)
                    .collect::<Vec<_>>(),
            );
            eprintln!(
                "seed {seed}: best-candidate tile min dist {d_tile:.3} px before the partition, \
                 {d_bc:.3} px over the image ({} of 1024 moved); per-pixel jitter {d_jit:.4} px",
                prov.moved()
            );
            rows.push((d_bc, d_jit));
        }
        for &(d_bc, d_jit) in &rows {
            assert!(d_bc > 0.2, "best candidate {d_bc}");
            assert!(
                d_bc > 2.5 * d_jit,
                "best candidate {d_bc} vs jitter {d_jit}"
            );
        }
        let mean = |f: fn(&(f64, f64)) -> f64| rows.iter().map(f).sum::<f64>() / 3.0;
        let ratio = mean(|r| r.0) / mean(|r| r.1);
        eprintln!("mean min distance ratio best candidate / jitter: {ratio:.2}");
        assert!(ratio > 3.5, "{ratio}");
    }

    #[test]
    fn partition_moves_only_the_excess_of_random_points() {
        for (w, s_pp) in [(64usize, 1usize), (32, 4)] {
            let n = w * w * s_pp;
            let p = Pattern::Random(Random {});
            let prov = ImagePlaneProvider::new(&p, w, s_pp, 9, 0, &never()).unwrap();
            let pts = p.generate(n, 9).unwrap();
            // The fewest moves any exact partition needs: the excess of the overfull cells.
            let mut count = vec![0usize; w * w];
            for q in &pts {
                let (cx, cy) = cell_of(*q, w);
                count[cy * w + cx] += 1;
            }
            let excess: usize = count.iter().map(|&c| c.saturating_sub(s_pp)).sum();
            // Toroidal Chebyshev displacement in cells: 1, 2, 3–4, 5–8, > 8.
            let mut hist = [0usize; 5];
            let ring = |a: usize, b: usize| {
                let d = a.abs_diff(b);
                d.min(w - d)
            };
            for (slot, &q) in prov.sources.iter().enumerate() {
                let c = slot / s_pp;
                let (gx, gy) = cell_of(pts[q as usize], w);
                let d = ring(gx, c % w).max(ring(gy, c / w));
                if d > 0 {
                    hist[match d {
                        1 => 0,
                        2 => 1,
                        3..=4 => 2,
                        5..=8 => 3,
                        _ => 4,
                    }] += 1;
                }
            }
            let moved: usize = hist.iter().sum();
            eprintln!(
                "random, {w}², {s_pp} spp: moved {moved} of {n} (excess {excess}), \
                 by 1/2/3–4/5–8/>8 cells: {hist:?}"
            );
            assert_eq!(moved, prov.moved());
            assert_eq!(moved, excess);
            assert!(hist[0] as f64 > 0.6 * moved as f64, "{hist:?}");
        }
    }

    #[test]
    fn k_d_fallback_balances_what_the_greedy_rounds_leave() {
        // Limit 0: no greedy round runs, the k-d split does everything; small limits stop a
        // round midway. Every cell must still get exactly s points, each point one cell.
        for (p, t, s_pp) in [
            (Pattern::Random(Random {}), 24usize, 2usize),
            (Pattern::BestCandidate(BestCandidate::default()), 16, 1),
            (Pattern::from_name("van-der-corput").unwrap(), 16, 1),
        ] {
            let pts = p.generate(s_pp * t * t, 2).unwrap();
            for limit in [
                0usize,
                200,
                1000,
                2000,
                3000,
                4000,
                6000,
                10_000,
                30_000,
                GREEDY_WORK,
            ] {
                let cell = partition_with(&pts, t, s_pp, limit, &never()).unwrap();
                let mut got = vec![0usize; t * t];
                for &c in &cell {
                    got[c as usize] += 1;
                }
                assert!(got.iter().all(|&c| c == s_pp), "{} limit {limit}", p.name());
                let moved = (0..pts.len())
                    .filter(|&q| {
                        let (cx, cy) = cell_of(pts[q], t);
                        cell[q] as usize != cy * t + cx
                    })
                    .count();
                eprintln!(
                    "{:>15} T={t} s={s_pp} limit {limit:>9}: moved {moved}",
                    p.name()
                );
            }
        }
    }

    #[test]
    fn axis_gap_is_the_toroidal_distance_to_the_cell() {
        // Reference: distance from x = a + f to the union of [b + kT, b + kT + 1), k = −1, 0, 1.
        let mut rng = Rng::new(12);
        for _ in 0..20_000 {
            let t = 1 + rng.below(20) as usize;
            let (a, b) = (rng.below(t as u64) as usize, rng.below(t as u64) as usize);
            let f = rng.next_f64();
            let x = a as f64 + f;
            let want = [-1.0, 0.0, 1.0]
                .iter()
                .map(|k| {
                    let lo = b as f64 + k * t as f64;
                    (lo - x).max(x - (lo + 1.0)).max(0.0)
                })
                .fold(f64::INFINITY, f64::min);
            let got = axis_gap(f, a, b, t);
            assert!(
                (got - want).abs() < 1e-12,
                "t {t} a {a} b {b} f {f}: {got} vs {want}"
            );
        }
    }

    #[test]
    fn capacity_kd_split_fills_every_cell_to_its_capacity() {
        // 13×13 cells, random capacities (zeros included) summing to the number of points.
        let t = 13;
        let mut rng = Rng::new(6);
        let cap: Vec<u32> = (0..t * t).map(|_| rng.below(4) as u32).collect();
        let n: usize = cap.iter().map(|&c| c as usize).sum();
        let pts = Pattern::Random(Random {}).generate(n, 6).unwrap();
        let mut cell = vec![u32::MAX; n];
        kd_assign((0..n as u32).collect(), &cap, &pts, t, &mut cell, &never()).unwrap();
        let mut got = vec![0u32; t * t];
        for &c in &cell {
            got[c as usize] += 1;
        }
        assert_eq!(got, cap);
    }

    #[test]
    fn image_plane_is_deterministic_for_any_thread_count() {
        // 2^16 points: the greedy targets and the k-d split run their parallel branches.
        let pts = Pattern::Random(Random {}).generate(1 << 16, 4).unwrap();
        let kd = |threads: usize| {
            rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap()
                .install(|| {
                    let mut cell = vec![0u32; pts.len()];
                    let all = (0..pts.len() as u32).collect();
                    kd_assign(all, &vec![1; 1 << 16], &pts, 256, &mut cell, &never()).unwrap();
                    cell
                })
        };
        assert_eq!(kd(1), kd(4));
        let build = |threads: usize| {
            rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap()
                .install(|| {
                    ImagePlaneProvider::new(&Pattern::Random(Random {}), 256, 1, 4, 0, &never())
                        .unwrap()
                })
        };
        let (a, b) = (build(1), build(4));
        assert!(a.moved() > 0);
        assert_eq!(a.sources, b.sources);
        let bits = |p: &ImagePlaneProvider| {
            p.offsets
                .iter()
                .flat_map(|u| [u.x.to_bits(), u.y.to_bits()])
                .collect::<Vec<_>>()
        };
        assert_eq!(bits(&a), bits(&b));
        let c =
            ImagePlaneProvider::new(&Pattern::Random(Random {}), 256, 1, 5, 0, &never()).unwrap();
        assert_ne!(bits(&a), bits(&c));
    }

    #[test]
    fn image_plane_rejects_bad_input() {
        let p = Pattern::Random(Random {});
        let c = never();
        let out_of_range = |r: Result<ImagePlaneProvider, ReconError>| match r {
            Err(ReconError::OutOfRange {
                field, min, max, ..
            }) => (field, min, max),
            other => panic!("{other:?}"),
        };
        assert_eq!(
            out_of_range(ImagePlaneProvider::new(&p, 0, 1, 0, 0, &c)),
            ("w", 1, MAX_W)
        );
        assert_eq!(
            out_of_range(ImagePlaneProvider::new(&p, 8, 0, 0, 0, &c)),
            ("spp", 1, MAX_SPP)
        );
        assert_eq!(
            out_of_range(ImagePlaneProvider::new(&p, 8, 1, 0, 9, &c)),
            ("tile", 0, 8)
        );
        // 1 spp at T = 8192 is 2^26 points; the largest allowed tile is 4096.
        assert_eq!(
            out_of_range(ImagePlaneProvider::new(&p, 8192, 1, 0, 0, &c)),
            ("tile", 1, 4096)
        );
        assert_eq!(
            out_of_range(ImagePlaneProvider::new(&p, 2048, 16, 0, 0, &c)),
            ("tile", 1, 1024)
        );
        assert_eq!(
            out_of_range(ImagePlaneProvider::new(&p, 4096, 3, 0, 0, &c)),
            ("tile", 1, 2364)
        );
        // The pattern's own errors pass through (a grid with 3 columns cannot hold 64 points).
        let grid = Pattern::Grid(Grid { cols: 3 });
        assert!(matches!(
            ImagePlaneProvider::new(&grid, 8, 1, 0, 0, &c),
            Err(ReconError::Pattern(_))
        ));
        let cancelled = Cancel::new();
        cancelled.cancel();
        assert_eq!(
            ImagePlaneProvider::new(&p, 8, 1, 0, 0, &cancelled),
            Err(ReconError::Cancelled)
        );
        let prov = ImagePlaneProvider::new(&p, 8, 2, 0, 4, &c).unwrap();
        let mut out = Vec::new();
        assert!(matches!(
            prov.offsets(0, 3, &mut out),
            Err(ReconError::ProviderSpp { spp: 3, .. })
        ));
        assert!(matches!(
            prov.offsets(64, 2, &mut out),
            Err(ReconError::OutOfRange {
                field: "pixel",
                max: 63,
                ..
            })
        ));
        assert!(out.is_empty());
    }

    #[test]
    fn sobol_high_direction_numbers_follow_lucas_and_keep_nets() {
        // Bit b of the truncated V_k is bit b + k − 32 of m_k, and bit j of m_k is C(k−1, j)
        // mod 2 = [j & (k−1) == j] (Lucas' theorem).
        for k in 33..=64usize {
            let mut v = 0u32;
            for b in 0..32 {
                let j = b + k - 32;
                if j < k && j & (k - 1) == j {
                    v |= 1 << b;
                }
            }
            assert_eq!(SOBOL_Y_HIGH[k - 33], v, "k = {k}");
        }
        let mut rng = Rng::new(8);
        for _ in 0..1000 {
            let a = rng.next_u32();
            assert_eq!(sobol_point_u64(u64::from(a)), sobol_point_u32(a));
        }
        // Aligned blocks beyond 2^32 are still (0,m,2)-nets; without the high columns the
        // block at 5·2^33 would repeat the first block, and its y would equal its low part's.
        for (base, m) in [
            (5u64 << 33, 10u32),
            ((3u64 << 40) + (7 << 20), 12),
            (1 << 37, 8),
        ] {
            let pts: Vec<DVec2> = (0..1u64 << m)
                .map(|t| {
                    let [x, y] = sobol_point_u64(base + t);
                    DVec2::new(f64::from(x), f64::from(y)) / 4_294_967_296.0
                })
                .collect();
            assert!(is_02_net(&pts), "base {base:#x}");
        }
        assert_ne!(sobol_point_u64(5 << 33), sobol_point_u32(0));
    }

    #[test]
    fn morton_code_interleaves_bits() {
        let mut rng = Rng::new(1);
        for _ in 0..1000 {
            let (x, y) = (rng.next_u32(), rng.next_u32());
            let mut want = 0u64;
            for b in 0..32 {
                want |= u64::from((x >> b) & 1) << (2 * b);
                want |= u64::from((y >> b) & 1) << (2 * b + 1);
            }
            assert_eq!(morton2(x, y), want);
        }
        let mut p: Vec<[u8; 4]> = PERMUTATIONS_4.to_vec();
        p.dedup();
        assert_eq!(p.len(), 24);
        assert!(PERMUTATIONS_4.iter().all(|q| {
            let mut s = *q;
            s.sort_unstable();
            s == [0, 1, 2, 3]
        }));
    }

    #[test]
    fn zsobol_index_permutation_is_a_seeded_bijection() {
        for spp in [1usize, 2, 4, 8] {
            let log2 = spp.trailing_zeros();
            let w = 16u32;
            let index = |seed: u64| -> Vec<u64> {
                let z = ZSobolProvider { seed, w: 16 };
                let mut v = Vec::new();
                for j in 0..w {
                    for i in 0..w {
                        for t in 0..spp as u64 {
                            v.push(z.sample_index((morton2(i, j) << log2) | t, log2));
                        }
                    }
                }
                v
            };
            let a = index(1);
            let mut sorted = a.clone();
            sorted.sort_unstable();
            assert!(
                sorted.iter().enumerate().all(|(k, &v)| v == k as u64),
                "spp {spp}"
            );
            let identity: Vec<u64> = {
                let mut v = Vec::new();
                for j in 0..w {
                    for i in 0..w {
                        for t in 0..spp as u64 {
                            v.push((morton2(i, j) << log2) | t);
                        }
                    }
                }
                v
            };
            assert_ne!(a, identity);
            assert_ne!(a, index(2));
            // The samples of one pixel stay one aligned block of spp indices.
            for block in a.chunks(spp) {
                let b0 = block[0] / spp as u64;
                assert!(block.iter().all(|&v| v / spp as u64 == b0));
            }
        }
    }

    #[test]
    fn zsobol_pixels_and_morton_blocks_are_nets() {
        for w in [16usize, 13] {
            for spp in [1usize, 2, 4, 8, 16, 32] {
                let z = ZSobolProvider { seed: 3, w };
                let offs = all_offsets(&z, w, spp);
                for o in &offs {
                    assert_eq!(o.len(), spp);
                    assert!(o.iter().all(|&u| in_unit(u)));
                    // For spp = 4: one offset in each 2×2 sub-pixel cell (and each 4×1, 1×4).
                    assert!(is_02_net(o), "w {w} spp {spp}");
                }
                // Morton-aligned 2^k × 2^k pixel blocks: their offsets together form a
                // (0, 2k + log2 spp, 2)-net.
                for k in 1..=3usize {
                    let b = 1 << k;
                    if spp * b * b > 1024 {
                        continue;
                    }
                    for by in 0..w / b {
                        for bx in 0..w / b {
                            let mut block = Vec::new();
                            for j in by * b..(by + 1) * b {
                                for i in bx * b..(bx + 1) * b {
                                    block.extend_from_slice(&offs[j * w + i]);
                                }
                            }
                            assert!(is_02_net(&block), "w {w} spp {spp} k {k} ({bx},{by})");
                        }
                    }
                }
            }
        }
        // The property is specific to aligned blocks: 2×2 blocks shifted by one pixel are not
        // all nets (this is what makes the check able to fail).
        let w = 16;
        let offs = all_offsets(&ZSobolProvider { seed: 3, w }, w, 1);
        let shifted_nets = (0..7)
            .flat_map(|by| (0..7).map(move |bx| (bx, by)))
            .filter(|&(bx, by)| {
                let (i, j) = (2 * bx + 1, 2 * by + 1);
                let block: Vec<DVec2> = [(i, j), (i + 1, j), (i, j + 1), (i + 1, j + 1)]
                    .iter()
                    .map(|&(x, y)| offs[y * w + x][0])
                    .collect();
                is_02_net(&block)
            })
            .count();
        assert!(shifted_nets < 49, "{shifted_nets}");
    }

    #[test]
    fn zsobol_is_deterministic_seeded_and_checks_input() {
        let z = ZSobolProvider { seed: 9, w: 40 };
        let a = all_offsets(&z, 40, 4);
        assert_eq!(a, all_offsets(&z, 40, 4));
        assert_ne!(a, all_offsets(&ZSobolProvider { seed: 10, w: 40 }, 40, 4));
        // The largest image: 2·13 + 6 = 32 index bits at 64 spp … and 38 at 4096.
        for spp in [64usize, 4096] {
            let big = ZSobolProvider { seed: 1, w: 8192 };
            let mut out = Vec::new();
            big.offsets(8192 * 8192 - 1, spp, &mut out).unwrap();
            assert_eq!(out.len(), spp);
            assert!(out.iter().all(|&u| in_unit(u)));
            assert!(is_02_net(&out));
        }
        let mut out = Vec::new();
        for spp in [0usize, 3, 12, 8192] {
            assert!(matches!(
                z.offsets(0, spp, &mut out),
                Err(ReconError::ProviderSpp {
                    provider: "zsobol",
                    ..
                })
            ));
        }
        assert!(matches!(
            z.offsets(1600, 1, &mut out),
            Err(ReconError::OutOfRange {
                field: "pixel",
                max: 1599,
                ..
            })
        ));
        assert!(matches!(
            ZSobolProvider { seed: 0, w: 0 }.offsets(0, 1, &mut out),
            Err(ReconError::OutOfRange { field: "w", .. })
        ));
        assert!(out.is_empty());
    }

    /// Direct O(W⁴) periodogram in the centred layout.
    fn periodogram_direct(e: &[f64], w: usize) -> Vec<f64> {
        let half = (w / 2) as i64;
        let mut out = vec![0.0; w * w];
        for iy in 0..w {
            for ix in 0..w {
                let (kx, ky) = (ix as i64 - half, iy as i64 - half);
                let (mut re, mut im) = (0.0, 0.0);
                for y in 0..w {
                    for x in 0..w {
                        let ph =
                            -2.0 * std::f64::consts::PI * (kx * x as i64 + ky * y as i64) as f64
                                / w as f64;
                        re += e[y * w + x] * ph.cos();
                        im += e[y * w + x] * ph.sin();
                    }
                }
                out[iy * w + ix] = (re * re + im * im) / (w * w) as f64;
            }
        }
        out
    }

    fn noise(w: usize, seed: u64) -> Vec<f64> {
        let mut rng = Rng::new(seed);
        (0..w * w).map(|_| rng.next_f64() - 0.5).collect()
    }

    #[test]
    fn periodogram_matches_the_direct_dft() {
        for w in [8usize, 7, 1, 2] {
            let e = noise(w, 21 + w as u64);
            let got = error_periodogram(&e, w).unwrap();
            let want = periodogram_direct(&e, w);
            let scale = want.iter().cloned().fold(0.0, f64::max);
            let err = got
                .iter()
                .zip(&want)
                .map(|(a, b)| (a - b).abs())
                .fold(0.0, f64::max);
            assert!(err <= 1e-12 * scale, "w {w}: {err} vs {scale}");
        }
    }

    #[test]
    fn periodogram_obeys_parseval_and_puts_dc_in_the_centre() {
        for w in [48usize, 45] {
            let e = noise(w, 3);
            let p = error_periodogram(&e, w).unwrap();
            let sum_p: f64 = p.iter().sum();
            let sum_e2: f64 = e.iter().map(|v| v * v).sum();
            assert!((sum_p - sum_e2).abs() <= 1e-12 * sum_e2, "{sum_p} {sum_e2}");
            // DC: (Σ e)²/W² at the centre.
            let mean_sum: f64 = e.iter().sum();
            let dc = p[(w / 2) * w + w / 2];
            assert!((dc - mean_sum * mean_sum / (w * w) as f64).abs() < 1e-12 * sum_e2);
        }
        // cos(2π(3x + 5y)/W): W²/4 at k = ±(3, 5), zero elsewhere.
        let w = 32;
        let e: Vec<f64> = (0..w * w)
            .map(|px| {
                let (x, y) = ((px % w) as f64, (px / w) as f64);
                (2.0 * std::f64::consts::PI * (3.0 * x + 5.0 * y) / w as f64).cos()
            })
            .collect();
        let p = error_periodogram(&e, w).unwrap();
        let at = |kx: i64, ky: i64| p[(ky + 16) as usize * w + (kx + 16) as usize];
        let peak = (w * w) as f64 / 4.0;
        assert!((at(3, 5) - peak).abs() < 1e-9 * peak);
        assert!((at(-3, -5) - peak).abs() < 1e-9 * peak);
        let rest: f64 = p.iter().sum::<f64>() - at(3, 5) - at(-3, -5);
        assert!(rest.abs() < 1e-9 * peak, "{rest}");
        // All of its energy sits at |k| = √34 ≈ 5.83.
        assert!(low_frequency_energy(&e, w, 5.8).unwrap() < 1e-12);
        assert!((low_frequency_energy(&e, w, 5.9).unwrap() - 1.0).abs() < 1e-12);
    }

    #[test]
    fn white_noise_low_frequency_share_is_the_disc_share() {
        // E[P(k)] is the same for every k ≠ 0, so the expected fraction is the share of the
        // disc's frequencies. Each realization's low sum has ≈ 400 independent terms (P(k) =
        // P(−k)), relative σ ≈ 5 %; the mean of 8 has σ ≈ 1.8 %: tolerance 8 % (4.5σ).
        let (w, r) = (128usize, 16.0);
        let mut disc = 0usize;
        for ky in -64i64..64 {
            for kx in -64i64..64 {
                let d2 = (kx * kx + ky * ky) as f64;
                if d2 > 0.0 && d2 <= r * r {
                    disc += 1;
                }
            }
        }
        let expected = disc as f64 / (w * w - 1) as f64;
        let fracs: Vec<f64> = (0..8)
            .map(|s| low_frequency_energy(&noise(w, 100 + s), w, r).unwrap())
            .collect();
        let mean = fracs.iter().sum::<f64>() / 8.0;
        eprintln!("white noise: fraction {mean:.5}, disc share {expected:.5} ({disc} freqs)");
        assert!((mean / expected - 1.0).abs() < 0.08, "{mean} vs {expected}");
    }

    #[test]
    fn spectrum_functions_check_input() {
        let e = vec![0.25; 16];
        assert_eq!(low_frequency_energy(&e, 4, 2.0), Ok(0.0)); // no energy off DC
        let n = noise(4, 1);
        assert_eq!(low_frequency_energy(&n, 4, 0.5), Ok(0.0)); // empty disc
        assert_eq!(low_frequency_energy(&n, 4, -1.0), Ok(0.0));
        assert!((low_frequency_energy(&n, 4, 10.0).unwrap() - 1.0).abs() < 1e-15);
        assert!(matches!(
            low_frequency_energy(&n, 4, f64::NAN),
            Err(ReconError::NonFinite {
                field: "radius",
                ..
            })
        ));
        assert!(matches!(
            error_periodogram(&n, 5),
            Err(ReconError::LengthMismatch {
                field: "error",
                got: 16,
                expected: 25,
                ..
            })
        ));
        let mut bad = n.clone();
        bad[7] = f64::INFINITY;
        assert!(matches!(
            error_periodogram(&bad, 4),
            Err(ReconError::NonFinite {
                field: "error",
                index: 7,
                ..
            })
        ));
        for w in [0usize, MAX_SPECTRUM_W + 1] {
            assert!(matches!(
                low_frequency_energy(&[], w, 1.0),
                Err(ReconError::OutOfRange { field: "w", .. })
            ));
        }
    }

    /// The box of radius ½ pixel: every sample reaches its own pixel only.
    struct HalfBox;

    impl ReconKernel for HalfBox {
        fn support(&self) -> f64 {
            0.5
        }
        fn weight(&self, d: DVec2) -> f64 {
            if d.x.abs() < 0.5 && d.y.abs() < 0.5 {
                1.0
            } else {
                0.0
            }
        }
    }

    #[test]
    fn zsobol_error_has_less_low_frequency_energy_than_random() {
        // W = 64, 1 spp, a smooth grating (3 cycles per image) against its exact box-filtered
        // reference; fraction of the error energy at 0 < |k| ≤ W/8 = 8, mean of 4 seeds.
        let w = 64;
        let sig = Signal::Grating(Grating {
            frequency: 3.0,
            angle: 30.0,
            phase: 0.0,
        });
        let reference = reference_image(&sig, w).unwrap();
        assert_eq!(reference.error_estimate, None);
        let c = never();
        let fraction = |provider: &dyn SampleProvider| {
            let r = supersample(&sig, w, 1, provider, &HalfBox, &c).unwrap();
            assert_eq!(r.zero_weight, 0);
            let e: Vec<f64> = r
                .pixels
                .iter()
                .zip(&reference.pixels)
                .map(|(a, b)| a - b)
                .collect();
            low_frequency_energy(&e, w, w as f64 / 8.0).unwrap()
        };
        let mean = |f: &dyn Fn(u64) -> f64| (0..4).map(f).sum::<f64>() / 4.0;
        let zsobol = mean(&|s| fraction(&ZSobolProvider { seed: s, w }));
        let random = mean(&|s| {
            fraction(&PatternProvider {
                pattern: Pattern::Random(Random {}),
                seed: s,
            })
        });
        let bc_plane = mean(&|s| {
            let bc = Pattern::BestCandidate(BestCandidate::default());
            fraction(&ImagePlaneProvider::new(&bc, w, 1, s, 0, &c).unwrap())
        });
        let disc = (1..=8i64)
            .flat_map(|y| (-8..=8i64).map(move |x| (x, y)))
            .filter(|&(x, y)| x * x + y * y <= 64)
            .count()
            * 2
            + 16; // the ky = 0 row without DC
        let white = disc as f64 / (w * w - 1) as f64;
        eprintln!(
            "low-frequency error energy (|k| ≤ 8): zsobol {zsobol:.4}, per-pixel random \
             {random:.4}, image-plane best candidate {bc_plane:.4}; white-noise share {white:.4}"
        );
        assert!(
            (random / white - 1.0).abs() < 0.5,
            "random {random} vs {white}"
        );
        assert!(zsobol < 0.5 * random, "zsobol {zsobol} vs random {random}");
        // Not asserted: a blue-noise pattern at one point per pixel does not give blue-noise
        // error. Its offsets frac(p·W) fold the pattern's spectral peak (near W cycles per
        // image) down to low frequencies; measured 0.073, above white noise.
        let _ = bc_plane;
    }
}
