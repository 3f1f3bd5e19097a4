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
//! [`best_candidate()`] settles each candidate q in two steps, with structures rebuilt each time
//! the point count reaches a power of two (sized for up to twice that many points):
//! 1. a coarse discrete Voronoi raster (pixels of half a point spacing) proposes one point x near
//!    q; if d(q, x)² ≤ best D², q cannot win — the verdict a scan of every point reaches, since it
//!    would meet x. About 97 % of the candidates stop here (N = 4096, m = 1).
//! 2. otherwise D(q)² is found in a uniform grid of the points ([`CELLS_PER_POINT`] cells per
//!    point), searching rings of cells around q outwards, stopping as soon as a point at squared
//!    distance ≤ best D² is met (q cannot win), or when the nearest point found is closer than
//!    any cell not yet visited (then it is the exact minimum).
//!
//! Every distance is the same expression as the scan's (the toroidal squared distance of
//! [`torus::distance_squared`](crate::core::torus::distance_squared)), so [`best_candidate()`] returns
//! the same points as [`best_candidate_naive`], bit for bit; the cost per candidate is O(1)
//! expected instead of O(i). The total work stays Θ(m N²) candidates, each costing two random
//! numbers, which bounds the speed from below.
//!
//! # Reference
//! D. P. Mitchell, "Spectrally optimal sampling for distribution ray tracing", SIGGRAPH 1991.
use super::poisson::{TorusGrid, NONE};
use super::*;
use crate::core::rng::Rng;
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
/// A new point claims raster pixels up to this many point spacings (1/√c) away.
const RASTER_WINDOW_SPACINGS: f64 = 1.0;

/// A coarse discrete Voronoi diagram: for each pixel, a copy of a point near its centre (the
/// nearest among those inserted within the claim window; before any claim, a copy of point 0).
///
/// It only *proposes* a neighbour: a candidate q whose proposed point x satisfies
/// d(q, x)² ≤ best D² (computed exactly as the scan computes it) cannot win, the same verdict a
/// scan of every point reaches; otherwise the exact grid search decides. Most candidates of a
/// best-candidate step lose, so most are settled by one pixel read and one distance.
#[derive(Debug, Clone)]
struct NearRaster {
    h: usize,
    hf: f64,
    window: usize,
    near: Vec<DVec2>,
    dist: Vec<f64>,
}

impl NearRaster {
    /// A raster sized for `count` points (and up to twice as many), every pixel proposing
    /// `fill` (which must be one of the points) until a point claims it.
    fn new(count: usize, fill: DVec2) -> Self {
        let count = count.max(1) as f64;
        let h = ((RASTER_PER_SPACING * (2.0 * count).sqrt()).ceil() as usize).max(1);
        let window = (RASTER_WINDOW_SPACINGS * h as f64 / count.sqrt()).ceil() as usize + 1;
        NearRaster {
            h,
            hf: h as f64,
            window,
            near: vec![fill; h * h],
            dist: vec![f64::INFINITY; h * h],
        }
    }

    #[inline(always)]
    fn pixel(&self, p: DVec2) -> (usize, usize) {
        let x = ((p.x * self.hf) as usize).min(self.h - 1);
        let y = ((p.y * self.hf) as usize).min(self.h - 1);
        (x, y)
    }

    /// The proposed neighbour of q (a copy of one of the points).
    #[inline(always)]
    fn proposal(&self, q: DVec2) -> DVec2 {
        let (x, y) = self.pixel(q);
        self.near[y * self.h + x]
    }

    /// Point p claims the pixels of its window whose centres it is nearest to.
    fn insert(&mut self, p: DVec2) {
        let h = self.h;
        let inv = 1.0 / self.hf;
        let (px, py) = self.pixel(p);
        let w = self.window;
        let (dist, near) = (&mut self.dist, &mut self.near);
        let mut claim = |x: usize, y: usize| {
            let c = DVec2::new((x as f64 + 0.5) * inv, (y as f64 + 0.5) * inv);
            let d = torus::distance_squared(c, p, 1.0);
            let k = y * h + x;
            if d < dist[k] {
                dist[k] = d;
                near[k] = p;
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

/// The accelerated search structures, rebuilt whenever the point count reaches a power of two.
struct Accel {
    grid: TorusGrid,
    raster: NearRaster,
}

impl Accel {
    fn build(points: &[DVec2], capacity: usize) -> Self {
        let mut raster = NearRaster::new(points.len(), points[0]);
        for &p in points {
            raster.insert(p);
        }
        Accel {
            grid: build_grid(points, capacity),
            raster,
        }
    }

    fn insert(&mut self, index: usize, p: DVec2) {
        self.grid.insert(index, p);
        self.raster.insert(p);
    }

    /// Same value as [`nearest_beyond_naive`].
    #[inline(always)]
    fn nearest_beyond(&self, points: &[DVec2], q: DVec2, best_d2: f64) -> Option<f64> {
        if torus::distance_squared(q, self.raster.proposal(q), 1.0) <= best_d2 {
            return None;
        }
        nearest_beyond(&self.grid, points, q, best_d2)
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
    let mut rng = Rng::new(seed);
    let mut points: Vec<DVec2> = Vec::with_capacity(n);
    points.push(DVec2::new(rng.next_f64(), rng.next_f64()));
    let mut accel = if use_grid {
        Some(Accel::build(&points, n))
    } else {
        None
    };
    let mut next_rebuild = 2usize;
    let mut work: u64 = 0;
    for i in 1..n {
        if let Some(a) = accel.as_mut() {
            if points.len() == next_rebuild {
                *a = Accel::build(&points, n);
                next_rebuild *= 2;
            }
        }
        let candidates = m * i as u64;
        let mut best = DVec2::ZERO;
        let mut best_d2 = -1.0;
        for _ in 0..candidates {
            work += 1;
            if work % 4096 == 0 {
                cancel.check()?;
            }
            let q = DVec2::new(rng.next_f64(), rng.next_f64());
            let beyond = match &accel {
                Some(a) => a.nearest_beyond(&points, q, best_d2),
                None => nearest_beyond_naive(&points, q, best_d2),
            };
            if let Some(d2) = beyond {
                best = q;
                best_d2 = d2;
            }
        }
        if let Some(a) = accel.as_mut() {
            a.insert(i, best);
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

    #[test]
    fn m_zero_is_invalid_param() {
        let err = best_candidate(&BestCandidate { m: 0 }, 10, 1, &Cancel::never()).unwrap_err();
        assert!(matches!(err, PatternError::InvalidParam { field: "m", .. }));
        let err = best_candidate(&BestCandidate { m: 1001 }, 10, 1, &Cancel::never()).unwrap_err();
        assert!(matches!(err, PatternError::InvalidParam { field: "m", .. }));
    }
}
