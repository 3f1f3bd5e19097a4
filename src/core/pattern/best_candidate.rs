//! Mitchell's best-candidate sampling on the unit torus, and tiling of a toroidal pattern.
//!
//! # Algorithm (Mitchell 1991)
//!
//! Point 0 is uniform in [0,1)². Point i ≥ 1 is chosen among c_i = m · i candidates drawn
//! uniformly in [0,1)²: the candidate q maximising the toroidal nearest-neighbour distance
//! D(q) = min_{j < i} d(q, x_j) is kept (the first such candidate wins a tie). It is a greedy
//! form of farthest-point sampling that approximates a Poisson-disk pattern, and it is
//! *progressive*: every prefix x_0 … x_{k−1} is itself a well-spread pattern of k points.
//! The lecture proposes it as the compromise to dart throwing: "compute pattern once, reuse it
//! by tiling the image plane (translating and scaling)", with a toroidal topology so the copies
//! join seamlessly ([`tile`]).
//!
//! # Random stream
//!
//! Everything comes from `Rng::new(seed)`: point 0 is two [`Rng::next_f64`] calls (x then y),
//! then every candidate of every point, in order, is two more (x then y). Distances are
//! [`torus::distance_squared`](crate::core::torus::distance_squared); candidate q replaces the current best when D(q)² > best D².
//!
//! # Acceleration
//!
//! [`best_candidate()`] settles each candidate q in up to three steps, with structures rebuilt
//! each time the point count reaches a power of two (sized for up to twice that many points):
//! 1. a coarse discrete Voronoi raster (pixels of half a point spacing, holding an f32 copy of
//!    a point near each pixel's centre) proposes one point x near q; if d(q, x) is below the
//!    best distance so far by more than the f32 rounding can move it, q cannot win — the
//!    verdict a scan of every point reaches, since it would meet x. About 97 % of the
//!    candidates stop here. The pixel comes from the random bits' top 32 by an integer
//!    multiply; the raster only proposes, so that choice changes no result.
//! 2. otherwise the proposals of the 8 pixels around q's are tried the same way; with them
//!    hardly more than the winning candidates reach step 3 (N = 16384: about 152 000 of
//!    134 M candidates, for 151 751 new best ones).
//! 3. D(q)² is found in a uniform grid of the points ([`CELLS_PER_POINT`] cells per
//!    point), searching rings of cells around q outwards, stopping as soon as a point at squared
//!    distance ≤ best D² is met (q cannot win), or when the nearest point found is closer than
//!    any cell not yet visited (then it is the exact minimum).
//!
//! A step of at least 8192 candidates is split in two runs of the random stream settled on
//! two threads: the second thread steps its copy of the generator over the first run's values
//! ([`Rng::skip`], ~1 ns a value) and each run keeps its first best candidate; the first run's
//! wins ties, so the chosen candidate is the serial one whatever the split.
//!
//! Every distance that decides is the same expression as the scan's (the toroidal squared
//! distance of [`torus::distance_squared`](crate::core::torus::distance_squared)), so
//! [`best_candidate()`] returns the same points as [`best_candidate_naive`], bit for bit; the
//! cost per candidate is O(1) expected instead of O(i). The total work stays Θ(m N²)
//! candidates, each costing two random numbers, which bounds the speed from below.
//!
//! # Reference
//! D. P. Mitchell, "Spectrally optimal sampling for distribution ray tracing", SIGGRAPH 1991.
use super::poisson::{TorusGrid, NONE};
use super::*;
use crate::core::rng::{unit_f64, Rng};
use crate::core::torus;

/// Grid cells per placed point used by the accelerated search (applied at each rebuild).
pub const CELLS_PER_POINT: f64 = 2.0;

/// Relative and absolute slack on the "no unvisited cell can hold a nearer point" bound, far
/// above the rounding of cell indices and squared distances (≈ 1e−16).
const STOP_REL: f64 = 1e-9;
const STOP_ABS: f64 = 1e-12;

pub(super) fn check_m(p: &BestCandidate) -> Result<u64, PatternError> {
    if p.m == 0 || p.m > 1000 {
        return Err(PatternError::InvalidParam {
            pattern: BestCandidate::NAME,
            field: "m",
            value: p.m.to_string(),
            allowed: "an integer in 1..=1000".into(),
        });
    }
    Ok(p.m as u64)
}

/// Mitchell's best-candidate pattern of n points on the torus, grid accelerated.
///
/// Point 0 is uniform; point i ≥ 1 keeps, among m·i uniform candidates, the one whose toroidal
/// distance to the nearest of points 0 … i−1 is largest (first candidate wins ties). Every
/// prefix is usable (progressive). Same output as [`best_candidate_naive`], bit for bit; see the
/// module docs for the random stream and the search. `m` must be in 1..=1000. The cancel token
/// is checked every 4096 candidates.
///
/// Cost: m·N(N−1)/2 candidates, each O(1) expected.
pub fn best_candidate(
    p: &BestCandidate,
    n: usize,
    seed: u64,
    cancel: &Cancel,
) -> Result<Vec<DVec2>, PatternError> {
    generate(p, n, seed, cancel, true)
}

/// Reference best candidate: each candidate is compared with every previous point (stopping at
/// the first one that shows it cannot beat the current best). O(m N³) overall. Same stream and
/// output as [`best_candidate()`]; kept to test it.
pub fn best_candidate_naive(
    p: &BestCandidate,
    n: usize,
    seed: u64,
    cancel: &Cancel,
) -> Result<Vec<DVec2>, PatternError> {
    generate(p, n, seed, cancel, false)
}

/// Grid side for `count` points: about [`CELLS_PER_POINT`] cells per point.
fn grid_side(count: usize) -> usize {
    ((count as f64 * CELLS_PER_POINT).sqrt().round() as usize).max(1)
}

fn build_grid(points: &[DVec2], capacity: usize) -> TorusGrid {
    let mut grid = TorusGrid::new(grid_side(points.len()), capacity);
    for (i, &p) in points.iter().enumerate() {
        grid.insert(i, p);
    }
    grid
}

/// Raster pixels per point spacing (1/√(2c) for the 2c points a raster built at c points serves).
const RASTER_PER_SPACING: f64 = 2.0;
/// When a raster is built, every point claims the pixels up to this many point spacings (1/√c)
/// away (rounded to pixels: 1 each side): a pixel left with a far proposal is covered by its
/// neighbours' ([`NEIGHBOURS`]); wider windows (1 spacing, 4 pixels) cost 9× the claims for
/// 0.3 % fewer exact searches.
const BUILD_WINDOW_SPACINGS: f64 = 0.5;
/// A point inserted later claims the pixels up to this many point spacings away: it lands in
/// the largest empty disc, so the pixels it is nearest to lie within about half a spacing.
const INSERT_WINDOW_SPACINGS: f64 = 0.5;
/// Raster pixels around the candidate's whose proposals are tried when its own does not reject
/// it (the 4 sharing an edge, then the 4 corners): together they settle all but the winning
/// candidates (N = 16384: about 152 000 grid searches for 151 751 new best candidates, against
/// 3.1 M with the candidate's pixel alone).
const NEIGHBOURS: usize = 8;

/// Slack (in distance) of the raster's rejection test on the f32 copies of the points: above
/// the largest displacement of rounding a coordinate in [0, 1) to f32 (2⁻²⁵·√2 ≈ 4.3e-8) plus
/// the rounding of the squared distances (≈ 1e-15).
const F32_SLACK: f64 = 1e-7;

/// The raster's rejection threshold for a best squared distance `best_d2`: a candidate whose
/// squared distance to a proposal (computed from its f32 copy) is at most this has a point at
/// squared distance ≤ `best_d2` (as [`torus::distance_squared`] computes it), so it cannot win;
/// −1 (no rejection) when the best distance is too small for the slack to be safe.
#[inline]
fn reject_below(best_d2: f64) -> f64 {
    if best_d2 <= 0.0 {
        return -1.0;
    }
    let r = best_d2.sqrt() - F32_SLACK;
    if r >= 1e-6 {
        r * r
    } else {
        -1.0
    }
}

/// The raster pixel (one axis) of a coordinate made from 64 random bits (`unit_f64(bits)`):
/// ⌊(bits / 2⁶⁴) · h⌋ from the top 32 bits, an integer multiply instead of a float conversion.
/// It may differ from ⌊x · h⌋ by one at pixel edges, which only changes which point is proposed.
#[inline(always)]
fn pixel_of_bits(bits: u64, h: u64) -> u64 {
    ((bits >> 32) * h) >> 32
}

/// A coarse discrete Voronoi diagram: for each pixel, an f32 copy of a point near its centre
/// (the nearest among those that claimed it; before any claim, a copy of point 0).
///
/// It only *proposes* a neighbour: a candidate q whose proposed point x is closer than the
/// best distance by more than the f32 rounding ([`reject_below`]) cannot win, the same verdict
/// a scan of every point reaches; otherwise the exact grid search decides. Most candidates of a
/// best-candidate step lose, so most are settled by one pixel read and one distance. f32 copies
/// halve the raster (8 bytes a pixel), which keeps it in cache longer as N grows.
#[derive(Debug, Clone)]
struct NearRaster {
    h: usize,
    hf: f64,
    /// Claim windows (pixels each side) when building and when inserting later.
    build_window: usize,
    insert_window: usize,
    near: Vec<[f32; 2]>,
    dist: Vec<f32>,
}

impl NearRaster {
    /// A raster sized for `count` points (and up to twice as many), every pixel proposing
    /// `fill` (which must be one of the points) until a point claims it.
    fn new(count: usize, fill: DVec2) -> Self {
        let count = count.max(1) as f64;
        let h = ((RASTER_PER_SPACING * (2.0 * count).sqrt()).ceil() as usize).max(1);
        let per_spacing = h as f64 / count.sqrt();
        NearRaster {
            h,
            hf: h as f64,
            build_window: (BUILD_WINDOW_SPACINGS * per_spacing).round() as usize,
            insert_window: (INSERT_WINDOW_SPACINGS * per_spacing).round() as usize,
            near: vec![[fill.x as f32, fill.y as f32]; h * h],
            dist: vec![f32::INFINITY; h * h],
        }
    }

    #[inline(always)]
    fn pixel(&self, p: DVec2) -> (usize, usize) {
        let x = ((p.x * self.hf) as usize).min(self.h - 1);
        let y = ((p.y * self.hf) as usize).min(self.h - 1);
        (x, y)
    }

    /// Squared distance from q to the proposal of pixel (x, y) (its f32 copy).
    #[inline(always)]
    fn near_d2(&self, q: DVec2, x: usize, y: usize) -> f64 {
        let [nx, ny] = self.near[y * self.h + x];
        let dx = torus::axis_gap(q.x, f64::from(nx), 1.0);
        let dy = torus::axis_gap(q.y, f64::from(ny), 1.0);
        dx * dx + dy * dy
    }

    /// Whether the proposal of one of the [`NEIGHBOURS`] pixels around (px, py) (on the torus)
    /// is within squared distance `reject` of q.
    #[inline]
    fn neighbours_reject(&self, q: DVec2, px: usize, py: usize, reject: f64) -> bool {
        let h = self.h;
        let (l, r) = (
            if px == 0 { h - 1 } else { px - 1 },
            if px + 1 == h { 0 } else { px + 1 },
        );
        let (d, u) = (
            if py == 0 { h - 1 } else { py - 1 },
            if py + 1 == h { 0 } else { py + 1 },
        );
        [
            (l, py),
            (r, py),
            (px, d),
            (px, u),
            (l, d),
            (r, d),
            (l, u),
            (r, u),
        ][..NEIGHBOURS]
            .iter()
            .any(|&(x, y)| self.near_d2(q, x, y) <= reject)
    }

    /// Point p claims the pixels within `w` pixels whose centres it is nearest to.
    fn claim(&mut self, p: DVec2, w: usize) {
        let h = self.h;
        let inv = 1.0 / self.hf;
        let (px, py) = self.pixel(p);
        let copy = [p.x as f32, p.y as f32];
        let (dist, near) = (&mut self.dist, &mut self.near);
        let mut claim = |x: usize, y: usize| {
            let c = DVec2::new((x as f64 + 0.5) * inv, (y as f64 + 0.5) * inv);
            let d = torus::distance_squared(c, p, 1.0) as f32;
            let k = y * h + x;
            if d < dist[k] {
                dist[k] = d;
                near[k] = copy;
            }
        };
        if 2 * w + 1 >= h {
            for y in 0..h {
                for x in 0..h {
                    claim(x, y);
                }
            }
            return;
        }
        let x0 = if px >= w { px - w } else { px + h - w };
        let y0 = if py >= w { py - w } else { py + h - w };
        for dy in 0..=2 * w {
            let mut y = y0 + dy;
            if y >= h {
                y -= h;
            }
            for dx in 0..=2 * w {
                let mut x = x0 + dx;
                if x >= h {
                    x -= h;
                }
                claim(x, y);
            }
        }
    }
}

/// Candidates of one step (m·i) from which the step is split between two threads.
const PAR_CANDIDATES: u64 = 8192;
/// Share of a split step's candidates the first thread takes: the second one also steps the
/// random stream over the first share (~2 ns a candidate against ~5 ns to settle one), so
/// equal times need a larger first share.
const PAR_FIRST_SHARE: f64 = 0.6;

/// The accelerated search structures, rebuilt whenever the point count reaches a power of two.
struct Accel {
    grid: TorusGrid,
    raster: NearRaster,
}

impl Accel {
    fn build(points: &[DVec2], capacity: usize) -> Self {
        let mut raster = NearRaster::new(points.len(), points[0]);
        let w = raster.build_window;
        for &p in points {
            raster.claim(p, w);
        }
        Accel {
            grid: build_grid(points, capacity),
            raster,
        }
    }

    fn insert(&mut self, index: usize, p: DVec2) {
        self.grid.insert(index, p);
        let w = self.raster.insert_window;
        self.raster.claim(p, w);
    }

    /// One step's `count` candidates drawn from `rng` (x then y each): the first candidate
    /// with the largest nearest-point distance, and that squared distance. The cancel token is
    /// checked whenever `work` reaches a multiple of 4096.
    #[inline]
    fn step(
        &self,
        points: &[DVec2],
        rng: &mut Rng,
        count: u64,
        work: &mut u64,
        cancel: &Cancel,
    ) -> Result<(DVec2, f64), PatternError> {
        let raster = &self.raster;
        let h = raster.h as u64;
        let mut r = rng.clone();
        let mut w = *work;
        let mut best = DVec2::ZERO;
        let mut best_d2 = -1.0;
        let mut reject = -1.0;
        let mut left = count;
        while left > 0 {
            let run = left.min(4096 - w % 4096);
            for _ in 0..run {
                let (u, v) = (r.next_u64(), r.next_u64());
                let q = DVec2::new(unit_f64(u), unit_f64(v));
                let (px, py) = (pixel_of_bits(u, h) as usize, pixel_of_bits(v, h) as usize);
                if raster.near_d2(q, px, py) <= reject
                    || (reject > 0.0 && raster.neighbours_reject(q, px, py, reject))
                {
                    continue;
                }
                if let Some(d2) = nearest_beyond(&self.grid, points, q, best_d2) {
                    best = q;
                    best_d2 = d2;
                    reject = reject_below(d2);
                }
            }
            left -= run;
            w += run;
            if w % 4096 == 0 {
                cancel.check()?;
            }
        }
        *rng = r;
        *work = w;
        Ok((best, best_d2))
    }

    /// [`Accel::step`] with the candidates split in two consecutive runs settled on two
    /// threads: the first run from `rng` as it is, the second from `rng` stepped over the first
    /// run's values. The first candidate of the larger distance wins, the first run's on a tie:
    /// the same candidate as one serial run, whatever the split. `rng` ends after the second.
    fn step_split(
        &self,
        points: &[DVec2],
        rng: &mut Rng,
        count: u64,
        cancel: &Cancel,
    ) -> Result<(DVec2, f64), PatternError> {
        let first = ((count as f64 * PAR_FIRST_SHARE) as u64).clamp(1, count - 1);
        let mut second_rng = rng.clone();
        let (a, b) = rayon::join(
            || self.step(points, rng, first, &mut 0, cancel),
            || {
                second_rng.skip(2 * first);
                self.step(points, &mut second_rng, count - first, &mut 0, cancel)
            },
        );
        let (a, b) = (a?, b?);
        *rng = second_rng;
        Ok(if b.1 > a.1 { b } else { a })
    }
}

fn generate(
    p: &BestCandidate,
    n: usize,
    seed: u64,
    cancel: &Cancel,
    use_grid: bool,
) -> Result<Vec<DVec2>, PatternError> {
    check_n(n, MAX_N)?;
    let m = check_m(p)?;
    cancel.check()?;
    if !use_grid {
        return generate_naive(m, n, seed, cancel);
    }
    let split = if rayon::current_num_threads() > 1 {
        PAR_CANDIDATES
    } else {
        u64::MAX
    };
    generate_accelerated(m, n, seed, cancel, split)
}

/// The accelerated generation; steps of at least `split` candidates are settled on two threads
/// ([`Accel::step_split`]: the same points, whatever `split`). Not wrapped in a pool job: a
/// pool worker waiting in another node's loop could take the whole generation, so only its
/// split steps (each well under a millisecond) enter the pool.
fn generate_accelerated(
    m: u64,
    n: usize,
    seed: u64,
    cancel: &Cancel,
    split: u64,
) -> Result<Vec<DVec2>, PatternError> {
    let mut rng = Rng::new(seed);
    let mut points: Vec<DVec2> = Vec::with_capacity(n);
    points.push(DVec2::new(rng.next_f64(), rng.next_f64()));
    let mut accel = Accel::build(&points, n);
    let mut next_rebuild = 2usize;
    let mut work: u64 = 0;
    for i in 1..n {
        if points.len() == next_rebuild {
            accel = Accel::build(&points, n);
            next_rebuild *= 2;
        }
        let count = m * i as u64;
        let (best, _) = if count >= split {
            accel.step_split(&points, &mut rng, count, cancel)?
        } else {
            accel.step(&points, &mut rng, count, &mut work, cancel)?
        };
        accel.insert(i, best);
        points.push(best);
    }
    Ok(points)
}

/// The reference: every candidate against every point ([`nearest_beyond_naive`]).
fn generate_naive(
    m: u64,
    n: usize,
    seed: u64,
    cancel: &Cancel,
) -> Result<Vec<DVec2>, PatternError> {
    let mut rng = Rng::new(seed);
    let mut points: Vec<DVec2> = Vec::with_capacity(n);
    points.push(DVec2::new(rng.next_f64(), rng.next_f64()));
    let mut work: u64 = 0;
    for i in 1..n {
        let candidates = m * i as u64;
        let mut best = DVec2::ZERO;
        let mut best_d2 = -1.0;
        for _ in 0..candidates {
            work += 1;
            if work % 4096 == 0 {
                cancel.check()?;
            }
            let q = DVec2::new(rng.next_f64(), rng.next_f64());
            if let Some(d2) = nearest_beyond_naive(&points, q, best_d2) {
                best = q;
                best_d2 = d2;
            }
        }
        points.push(best);
    }
    Ok(points)
}

/// min_j d(q, x_j)² if it exceeds `best_d2`, else `None`; a scan of every point.
fn nearest_beyond_naive(points: &[DVec2], q: DVec2, best_d2: f64) -> Option<f64> {
    let mut dmin = f64::INFINITY;
    for &x in points {
        let d2 = torus::distance_squared(q, x, 1.0);
        if d2 <= best_d2 {
            return None;
        }
        if d2 < dmin {
            dmin = d2;
        }
    }
    Some(dmin)
}

/// As [`nearest_beyond_naive`], searching rings of grid cells around q outwards.
///
/// After the rings 0 … k (the (2k+1)² block of cells centred on q's cell), every unvisited point
/// lies at toroidal distance ≥ (k + e)·s from q, where s is the cell side and e·s the distance
/// from q to the nearest side of its own cell. Once the nearest point found is strictly closer
/// than that (with a safety slack), it is the exact minimum.
#[inline]
fn nearest_beyond(grid: &TorusGrid, points: &[DVec2], q: DVec2, best_d2: f64) -> Option<f64> {
    let g = grid.g;
    let (cx, cy, fx, fy) = grid.locate(q);
    let s = grid.cell_size();
    let e = fx.min(1.0 - fx).min(fy).min(1.0 - fy).max(0.0);
    let mut dmin = f64::INFINITY;

    // Scans one cell; false when a point at squared distance ≤ best_d2 shows q cannot win.
    macro_rules! scan {
        ($x:expr, $y:expr) => {{
            let mut i = grid.first($x, $y);
            while i != NONE {
                let d2 = torus::distance_squared(q, points[i as usize], 1.0);
                if d2 <= best_d2 {
                    return None;
                }
                if d2 < dmin {
                    dmin = d2;
                }
                i = grid.after(i);
            }
        }};
    }

    let mut k = 0usize;
    loop {
        if 2 * k + 1 >= g {
            // The block covers the whole torus: visit every cell (revisits are harmless).
            for y in 0..g {
                for x in 0..g {
                    scan!(x, y);
                }
            }
            return Some(dmin);
        }
        if k == 0 {
            scan!(cx, cy);
        } else {
            let wrap = |v: usize| if v >= g { v - g } else { v };
            // x0, y0 < g and 2k + 1 < g, so one wrap suffices below.
            let x0 = wrap(cx + g - k);
            let y0 = wrap(cy + g - k);
            let y_lo = wrap(y0);
            let y_hi = wrap(cy + k);
            for dx in 0..=2 * k {
                let x = wrap(x0 + dx);
                scan!(x, y_lo);
                scan!(x, y_hi);
            }
            let x_lo = x0;
            let x_hi = wrap(cx + k);
            for dy in 1..2 * k {
                let y = wrap(y0 + dy);
                scan!(x_lo, y);
                scan!(x_hi, y);
            }
        }
        let bound = (k as f64 + e) * s * (1.0 - STOP_REL) - STOP_ABS;
        if bound > 0.0 && dmin < bound * bound {
            return Some(dmin);
        }
        k += 1;
    }
}

/// Tiles a toroidal pattern: `tiles_x × tiles_y` copies of `tile`, each scaled by
/// (1/tiles_x, 1/tiles_y) and translated to its cell of the unit square:
/// x' = ((t_x + x)/tiles_x, (t_y + y)/tiles_y), copies in row-major order of (t_y, t_x).
///
/// This is the lecture's "compute pattern once, reuse it by tiling the image plane (translating
/// and scaling)". When the tile was computed with toroidal distances (best candidate, Poisson
/// disk), the copies join seamlessly: the toroidal minimum distance of the result is the tile's
/// toroidal minimum distance scaled by 1/tiles (for tiles_x = tiles_y), across tile borders
/// too, and the result is again toroidal.
///
/// Errors: `tiles_x` or `tiles_y` = 0, an empty tile, a point outside [0,1)² (or not finite),
/// or more than [`MAX_N`] points in total.
pub fn tile(tile: &[DVec2], tiles_x: usize, tiles_y: usize) -> Result<Vec<DVec2>, PatternError> {
    const NAME: &str = "tile";
    for (field, v) in [("tiles_x", tiles_x), ("tiles_y", tiles_y)] {
        if v == 0 {
            return Err(PatternError::InvalidParam {
                pattern: NAME,
                field,
                value: "0".into(),
                allowed: format!("an integer in 1..={MAX_N}"),
            });
        }
    }
    if tile.is_empty() {
        return Err(PatternError::InvalidParam {
            pattern: NAME,
            field: "tile",
            value: "[] (no points)".into(),
            allowed: "a non-empty point set".into(),
        });
    }
    if let Some(p) = tile
        .iter()
        .find(|p| !((0.0..1.0).contains(&p.x) && (0.0..1.0).contains(&p.y)))
    {
        return Err(PatternError::InvalidParam {
            pattern: NAME,
            field: "tile",
            value: format!("a point at ({}, {})", p.x, p.y),
            allowed: "points in [0,1)²".into(),
        });
    }
    let total = tile
        .len()
        .checked_mul(tiles_x)
        .and_then(|v| v.checked_mul(tiles_y));
    let total = match total {
        Some(t) if t <= MAX_N => t,
        other => {
            return Err(PatternError::InvalidN {
                n: other.unwrap_or(usize::MAX),
                max: MAX_N,
                why: format!(
                    "; the tiling has tile.len() × tiles_x × tiles_y = {} × {tiles_x} × {tiles_y} points",
                    tile.len()
                ),
            })
        }
    };
    let (fx, fy) = (tiles_x as f64, tiles_y as f64);
    let mut out = Vec::with_capacity(total);
    for ty in 0..tiles_y {
        for tx in 0..tiles_x {
            let (ox, oy) = (tx as f64, ty as f64);
            out.extend(
                tile.iter()
                    .map(|p| DVec2::new(clamp_unit((ox + p.x) / fx), clamp_unit((oy + p.y) / fy))),
            );
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn naive_nearest(points: &[DVec2], q: DVec2) -> f64 {
        points
            .iter()
            .map(|&x| torus::distance_squared(q, x, 1.0))
            .fold(f64::INFINITY, f64::min)
    }

    #[test]
    fn grid_nearest_equals_full_scan_for_many_grid_sizes() {
        let mut rng = Rng::new(11);
        for count in [1usize, 2, 3, 7, 40, 300] {
            let pts: Vec<DVec2> = (0..count)
                .map(|_| DVec2::new(rng.next_f64(), rng.next_f64()))
                .collect();
            let grid = build_grid(&pts, count);
            for _ in 0..3000 {
                let q = DVec2::new(rng.next_f64(), rng.next_f64());
                let exact = naive_nearest(&pts, q);
                // With best = −1 the search must return the exact minimum.
                assert_eq!(
                    nearest_beyond(&grid, &pts, q, -1.0),
                    Some(exact),
                    "count {count}"
                );
                // With a threshold, it must agree with the scan on win/lose.
                let best = 0.5 * exact + 0.25 * rng.next_f64() * exact;
                assert_eq!(
                    nearest_beyond(&grid, &pts, q, best),
                    Some(exact),
                    "count {count}"
                );
                assert_eq!(nearest_beyond(&grid, &pts, q, exact), None);
                assert_eq!(nearest_beyond_naive(&pts, q, exact), None);
            }
        }
    }

    fn bits(p: &[DVec2]) -> Vec<(u64, u64)> {
        p.iter().map(|q| (q.x.to_bits(), q.y.to_bits())).collect()
    }

    #[test]
    fn split_steps_choose_the_serial_points_whatever_the_split() {
        // Steps split from 8, 37 and 1000 candidates on (m = 3: steps of up to 1197), against
        // the serial path and the scan of every point.
        let never = Cancel::never();
        for (m, n, seed) in [(1u64, 300usize, 5u64), (3, 400, 9)] {
            let serial = generate_accelerated(m, n, seed, &never, u64::MAX).unwrap();
            let naive = generate_naive(m, n, seed, &never).unwrap();
            assert_eq!(bits(&serial), bits(&naive), "m {m}");
            for split in [8u64, 37, 1000] {
                let two = generate_accelerated(m, n, seed, &never, split).unwrap();
                assert_eq!(bits(&two), bits(&serial), "m {m} split {split}");
            }
        }
    }

    #[test]
    fn the_f32_rejection_threshold_only_rejects_what_the_exact_distance_rejects() {
        // A proposal stored as f32 at squared distance ≤ reject_below(b) from q is, exactly,
        // at squared distance ≤ b; points placed just inside and outside the threshold.
        let mut rng = Rng::new(3);
        for _ in 0..20000 {
            let q = DVec2::new(rng.next_f64(), rng.next_f64());
            let b = rng.next_f64() * 1e-3 + 1e-10;
            let t = reject_below(b);
            let angle = rng.next_f64() * std::f64::consts::TAU;
            for r in [t.max(0.0).sqrt(), b.sqrt()] {
                let x = DVec2::new(
                    (q.x + r * angle.cos()).rem_euclid(1.0),
                    (q.y + r * angle.sin()).rem_euclid(1.0),
                );
                let x = DVec2::new(x.x.min(ONE_MINUS_EPSILON), x.y.min(ONE_MINUS_EPSILON));
                let copy = [x.x as f32, x.y as f32];
                let dx = torus::axis_gap(q.x, f64::from(copy[0]), 1.0);
                let dy = torus::axis_gap(q.y, f64::from(copy[1]), 1.0);
                if dx * dx + dy * dy <= t {
                    assert!(torus::distance_squared(q, x, 1.0) <= b, "q {q} x {x} b {b}");
                }
            }
        }
        assert_eq!(reject_below(-1.0), -1.0);
        assert_eq!(reject_below(1e-13), -1.0);
    }

    #[test]
    fn the_pixel_of_the_random_bits_is_in_the_raster() {
        for h in [1u64, 2, 7, 46, 256, 1 << 20] {
            for bits in [0u64, 1, u64::MAX, u64::MAX >> 1, 0x8000_0000_0000_0000] {
                assert!(pixel_of_bits(bits, h) < h, "h {h} bits {bits:#x}");
            }
        }
        assert_eq!(pixel_of_bits(u64::MAX, 46), 45);
        assert_eq!(pixel_of_bits(1 << 63, 46), 23);
    }

    #[test]
    fn m_zero_is_invalid_param() {
        let err = best_candidate(&BestCandidate { m: 0 }, 10, 1, &Cancel::never()).unwrap_err();
        assert!(matches!(err, PatternError::InvalidParam { field: "m", .. }));
        let err = best_candidate(&BestCandidate { m: 1001 }, 10, 1, &Cancel::never()).unwrap_err();
        assert!(matches!(err, PatternError::InvalidParam { field: "m", .. }));
    }
}
