//! Poisson-disk patterns on the unit torus: dart throwing (the lecture's pseudo-code) and
//! Bridson's fast algorithm.
//!
//! # Conventions
//!
//! - Points live in [0,1)² and every distance is **toroidal**:
//!   d(a, b)² = Δx² + Δy² with Δ = min(|a − b|, 1 − |a − b|) per coordinate
//!   ([`torus::distance`](crate::core::torus::distance)). A pattern computed on the torus tiles the plane seamlessly.
//! - **Radius.** `radius` is the minimum toroidal distance between two points of the pattern.
//!   The lecture's pseudo-code rejects a dart when d² < (2 r_p)² (r_p is the radius of the disk
//!   drawn around each point, so disks may touch but not overlap); hence `radius = 2 r_p`, and a
//!   dart is accepted exactly when its squared distance to every accepted point is ≥ radius².
//! - **Packing bound.** N disks of diameter r fit on the unit torus only if their hexagonal
//!   packing density allows it: N · (√3/2) r² ≤ 1, i.e. r ≤ d_max(N) = √(2/(√3 N))
//!   ([`max_radius`]). A larger radius is rejected with [`PatternError::RadiusTooLarge`] before any
//!   work is done. The *relative radius* ρ = r / d_max(N) (Lagae & Dutré 2008) is reported in
//!   notes. Dart throwing saturates around ρ ≈ 0.75 (with the default miss bound); Bridson's
//!   maximal sets (k = 30) reach ρ ≈ 0.73 (measured: r = 0.65 d_max(n) gives M ≈ 1.26 n points).
//! - **Default radius.** `radius = 0` means [`default_radius`]`(n)` =
//!   [`DEFAULT_RADIUS_FRACTION`] · d_max(n) = 0.65 · d_max(n): close enough to saturation to look
//!   like a Poisson-disk pattern, loose enough that dart throwing places all n points and Bridson's
//!   maximal set holds at least n points.
//!
//! # References
//! - Lecture "Signals and Sampling", slide "Dart throwing" (pseudo-code).
//! - R. Bridson, "Fast Poisson disk sampling in arbitrary dimensions", SIGGRAPH 2007 sketches.
//! - A. Lagae, P. Dutré, "A comparison of methods for generating Poisson disk distributions",
//!   Computer Graphics Forum 27(1), 2008 (relative radius ρ).
use super::*;
use crate::core::params::fmt_num;
use crate::core::rng::Rng;
use crate::core::torus;

/// Fraction of the hexagonal packing distance used when `radius = 0`: r = 0.65 · d_max(n).
pub const DEFAULT_RADIUS_FRACTION: f64 = 0.65;

/// Safety margin (relative) between a grid cell size and the radius it must cover, so that
/// rounding in cell indices and in squared distances can never hide a point from a search.
pub(crate) const GRID_MARGIN: f64 = 1e-6;

/// Hexagonal packing distance on the unit torus: d_max(n) = √(2 / (√3 · n)).
///
/// n disks of diameter d cover at most the fraction π/(2√3) of the plane (hexagonal packing);
/// equivalently each point needs a hexagonal cell of area (√3/2) d², so n points with mutual
/// distance ≥ d fit in area 1 only if d ≤ d_max(n). Returns +∞ for n = 0.
pub fn max_radius(n: usize) -> f64 {
    if n == 0 {
        return f64::INFINITY;
    }
    (2.0 / (3f64.sqrt() * n as f64)).sqrt()
}

/// Radius used when the `radius` parameter is 0: [`DEFAULT_RADIUS_FRACTION`] · [`max_radius`]`(n)`.
pub fn default_radius(n: usize) -> f64 {
    DEFAULT_RADIUS_FRACTION * max_radius(n)
}

/// Resolves the `radius` parameter: 0 → [`default_radius`]; otherwise it must be finite, in
/// (0, 1] and at most [`max_radius`]`(n)`.
fn resolve_radius(pattern: &'static str, radius: f64, n: usize) -> Result<f64, PatternError> {
    if !radius.is_finite() || !(0.0..=1.0).contains(&radius) {
        return Err(PatternError::InvalidParam {
            pattern,
            field: "radius",
            value: fmt_num(radius),
            allowed: "a finite number in [0, 1] (0 = auto)".into(),
        });
    }
    if radius == 0.0 {
        return Ok(default_radius(n));
    }
    let max = max_radius(n);
    if radius > max {
        return Err(PatternError::RadiusTooLarge {
            pattern,
            radius,
            n,
            max,
        });
    }
    Ok(radius)
}

/// A uniform grid of g × g cells over the unit torus, each cell holding a singly linked list
/// of point indices (`head[cell]` → `next[i]` → …). Shared by dart throwing, Bridson and best
/// candidate.
#[derive(Debug, Clone)]
pub(crate) struct TorusGrid {
    /// Cells per side.
    pub g: usize,
    gf: f64,
    head: Vec<u32>,
    next: Vec<u32>,
}

pub(crate) const NONE: u32 = u32::MAX;

impl TorusGrid {
    /// An empty g × g grid (g ≥ 1) expecting about `capacity` points.
    pub fn new(g: usize, capacity: usize) -> Self {
        let g = g.max(1);
        TorusGrid {
            g,
            gf: g as f64,
            head: vec![NONE; g * g],
            next: Vec::with_capacity(capacity),
        }
    }

    /// Cell side 1/g.
    #[inline]
    pub fn cell_size(&self) -> f64 {
        1.0 / self.gf
    }

    /// Cell coordinates of p ∈ [0,1)² and the position inside the cell in cell units (in [0,1]).
    #[inline(always)]
    pub fn locate(&self, p: DVec2) -> (usize, usize, f64, f64) {
        let sx = p.x * self.gf;
        let sy = p.y * self.gf;
        let cx = (sx as usize).min(self.g - 1);
        let cy = (sy as usize).min(self.g - 1);
        (cx, cy, sx - cx as f64, sy - cy as f64)
    }

    /// Adds point number `index` (indices must be inserted as 0, 1, 2, …) at p.
    #[inline]
    pub fn insert(&mut self, index: usize, p: DVec2) {
        debug_assert_eq!(index, self.next.len());
        let (cx, cy, _, _) = self.locate(p);
        let c = cy * self.g + cx;
        self.next.push(self.head[c]);
        self.head[c] = index as u32;
    }

    /// First point index of cell (cx, cy), or [`NONE`].
    #[inline(always)]
    pub fn first(&self, cx: usize, cy: usize) -> u32 {
        self.head[cy * self.g + cx]
    }

    /// The point index following `i` in its cell, or [`NONE`].
    #[inline(always)]
    pub fn after(&self, i: u32) -> u32 {
        self.next[i as usize]
    }

    /// Whether some point of `points` (all inserted) lies at squared toroidal distance < r2 from
    /// q, searching the cells within `k` cells of q's cell (all cells when 2k + 1 ≥ g).
    ///
    /// Exact (same answer as a scan of every point) whenever k ≥ ⌈r·(1 + margin)·g⌉.
    #[inline]
    pub fn any_within(&self, points: &[DVec2], q: DVec2, r2: f64, k: usize) -> bool {
        let g = self.g;
        let (cx, cy, _, _) = self.locate(q);
        let scan = |x: usize, y: usize| {
            let mut i = self.first(x, y);
            while i != NONE {
                if torus::distance_squared(q, points[i as usize], 1.0) < r2 {
                    return true;
                }
                i = self.after(i);
            }
            false
        };
        if 2 * k + 1 >= g {
            for y in 0..g {
                for x in 0..g {
                    if scan(x, y) {
                        return true;
                    }
                }
            }
            return false;
        }
        // Rows cy − k … cy + k, columns cx − k … cx + k, wrapped (2k + 1 < g: one wrap each).
        let x0 = if cx >= k { cx - k } else { cx + g - k };
        let y0 = if cy >= k { cy - k } else { cy + g - k };
        for dy in 0..=2 * k {
            let mut y = y0 + dy;
            if y >= g {
                y -= g;
            }
            for dx in 0..=2 * k {
                let mut x = x0 + dx;
                if x >= g {
                    x -= g;
                }
                if scan(x, y) {
                    return true;
                }
            }
        }
        false
    }
}

/// Bridson's background grid: g × g cells of side ≤ r/√2 (so at most one point per cell), padded
/// with `k` ghost cells on every side that mirror the cells across the torus seam. A cell holds
/// the index of its point in `points`, where index 0 is a sentinel point with NaN coordinates
/// (any comparison with it is false), so the (2k+1)² neighbourhood is read without wrapping
/// and without testing for empty cells.
#[derive(Debug, Clone)]
struct PaddedGrid {
    g: usize,
    gf: f64,
    k: usize,
    /// Padded row length g + 2k.
    w: usize,
    cells: Vec<u32>,
    /// Offsets of the (2k+1)² neighbourhood from its top-left padded cell, nearest cells first.
    offsets: Vec<usize>,
}

/// The sentinel point of [`PaddedGrid`]: every distance to it is NaN.
const NAN_POINT: DVec2 = DVec2::new(f64::NAN, f64::NAN);

impl PaddedGrid {
    fn new(g: usize, k: usize) -> Self {
        let g = g.max(1);
        let w = g + 2 * k;
        let side = 2 * k + 1;
        let mut rel: Vec<(usize, usize, usize)> = (0..side * side)
            .map(|i| {
                let (dx, dy) = (i % side, i / side);
                let dist = dx.abs_diff(k).pow(2) + dy.abs_diff(k).pow(2);
                (dist, i, dy * w + dx)
            })
            .collect();
        rel.sort_unstable();
        PaddedGrid {
            g,
            gf: g as f64,
            k,
            w,
            cells: vec![0; w * w],
            offsets: rel.into_iter().map(|(_, _, o)| o).collect(),
        }
    }

    #[inline(always)]
    fn cell(&self, p: DVec2) -> (usize, usize) {
        let cx = ((p.x * self.gf) as usize).min(self.g - 1);
        let cy = ((p.y * self.gf) as usize).min(self.g - 1);
        (cx, cy)
    }

    /// Stores point `index` (≥ 1) at p in its cell and in every ghost copy of that cell.
    fn insert(&mut self, index: u32, p: DVec2) {
        let (cx, cy) = self.cell(p);
        debug_assert_eq!(self.cells[(cy + self.k) * self.w + cx + self.k], 0);
        let mut py = (cy + self.k) % self.g;
        while py < self.w {
            let mut px = (cx + self.k) % self.g;
            while px < self.w {
                self.cells[py * self.w + px] = index;
                px += self.g;
            }
            py += self.g;
        }
    }

    /// Whether a point lies at squared toroidal distance < r2 from q (exact when
    /// k ≥ ⌈r(1 + margin) g⌉), nearest cells first with an early exit.
    #[inline(always)]
    fn any_within(&self, points: &[DVec2], q: DVec2, r2: f64) -> bool {
        let (cx, cy) = self.cell(q);
        // Padded (cx + k − k, cy + k − k): the top-left cell of q's neighbourhood.
        let corner = &self.cells[cy * self.w + cx..];
        // The 3 × 3 block without branches (most conflicts are there), then the rest.
        let (near, far) = self.offsets.split_at(self.offsets.len().min(9));
        let hit = near.iter().fold(false, |acc, &o| {
            acc | (torus::distance_squared(q, points[corner[o] as usize], 1.0) < r2)
        });
        hit || far
            .iter()
            .any(|&o| torus::distance_squared(q, points[corner[o] as usize], 1.0) < r2)
    }
}

/// Neighbourhood reach in cells so that every point at distance < r is searched: ⌈r(1+margin)g⌉ ≥ 1.
fn reach(r: f64, g: usize) -> usize {
    ((r * (1.0 + GRID_MARGIN) * g as f64).ceil() as usize).max(1)
}

/// Dart-throwing grid: cells of side ≥ r(1 + margin), so a 3 × 3 neighbourhood is exact; at
/// most about 2n cells (tiny radii would otherwise ask for huge grids).
fn dart_grid(r: f64, n: usize) -> TorusGrid {
    let by_radius = (1.0 / (r * (1.0 + GRID_MARGIN))).floor();
    let by_count = (2.0 * n as f64).sqrt().ceil().max(1.0);
    let g = by_radius.min(by_count).max(1.0) as usize;
    TorusGrid::new(g, n)
}

fn dart_note(placed: usize, n: usize, misses: u32, r: f64) -> String {
    format!(
        "placed {placed} of {n} points; gave up after {misses} consecutive misses at radius {} \
         (relative radius r/d_max = {:.4}): raise max_misses (now {misses}) or lower radius",
        fmt_num(r),
        r / max_radius(n)
    )
}

/// Dart throwing with a background grid: the lecture's pseudo-code, accelerated, on the torus.
///
/// Darts (x, y) are drawn as two consecutive [`Rng::next_f64`] calls (x first) from
/// `Rng::new(seed)`. A dart is accepted when its squared toroidal distance to every accepted
/// point is ≥ r² (the lecture rejects d² < (2 r_p)², and r = 2 r_p), otherwise rejected. The
/// search only visits the 3 × 3 grid cells around the dart (cells of side ≥ r), which finds the
/// same conflicts as scanning every point: the output equals [`dart_naive`]'s bit for bit.
///
/// `radius` = 0 uses [`default_radius`]`(n)`; a radius above [`max_radius`]`(n)` is
/// [`PatternError::RadiusTooLarge`] (checked before any allocation). The loop stops after
/// `max_misses` consecutive rejected darts and returns the points placed so far, with a note
/// "placed K of N points; gave up after M consecutive misses at radius r (relative radius …)".
/// The cancel token is checked every 1024 darts.
///
/// Cost: O(1) expected per dart instead of O(i).
pub fn dart(
    p: &PoissonDart,
    n: usize,
    seed: u64,
    cancel: &Cancel,
) -> Result<Generated, PatternError> {
    dart_impl(p, n, seed, cancel, true)
}

/// Reference dart throwing, a literal transcription of the lecture's pseudo-code: every dart is
/// compared with every accepted point (O(N²) overall). Same parameters, RNG stream, stopping rule
/// and note as [`dart`]; kept to test it.
pub fn dart_naive(
    p: &PoissonDart,
    n: usize,
    seed: u64,
    cancel: &Cancel,
) -> Result<Generated, PatternError> {
    dart_impl(p, n, seed, cancel, false)
}

/// The checks of [`dart`]: `n`, `radius` (against `n`) and `max_misses`; the radius in use.
pub(super) fn check_dart(p: &PoissonDart, n: usize) -> Result<f64, PatternError> {
    const NAME: &str = PoissonDart::NAME;
    check_n(n, MAX_N)?;
    let r = resolve_radius(NAME, p.radius, n)?;
    if p.max_misses == 0 {
        return Err(PatternError::InvalidParam {
            pattern: NAME,
            field: "max_misses",
            value: "0".into(),
            allowed: "an integer in 1..=100000000".into(),
        });
    }
    Ok(r)
}

fn dart_impl(
    p: &PoissonDart,
    n: usize,
    seed: u64,
    cancel: &Cancel,
    use_grid: bool,
) -> Result<Generated, PatternError> {
    let r = check_dart(p, n)?;
    cancel.check()?;
    let r2 = r * r;
    let mut rng = Rng::new(seed);
    let mut points: Vec<DVec2> = Vec::with_capacity(n);
    let mut grid = if use_grid {
        Some(dart_grid(r, n))
    } else {
        None
    };
    let k = grid.as_ref().map_or(1, |g| reach(r, g.g));
    let mut misses: u32 = 0;
    let mut darts: u64 = 0;
    while points.len() < n {
        if darts % 1024 == 0 {
            cancel.check()?;
        }
        darts += 1;
        let x = rng.next_f64();
        let y = rng.next_f64();
        let c = DVec2::new(x, y);
        let reject = match &grid {
            Some(g) => g.any_within(&points, c, r2, k),
            None => points
                .iter()
                .any(|&q| torus::distance_squared(c, q, 1.0) < r2),
        };
        if reject {
            misses += 1;
            if misses >= p.max_misses {
                let note = dart_note(points.len(), n, misses, r);
                return Ok(Generated {
                    points,
                    requested: n,
                    note: Some(note),
                });
            }
        } else {
            if let Some(g) = grid.as_mut() {
                g.insert(points.len(), c);
            }
            points.push(c);
            misses = 0;
        }
    }
    Ok(Generated::complete(points))
}

/// Smallest radius Bridson accepts: a maximal Poisson-disk set of radius r covers the torus
/// with disks of radius r, so it holds at least 1/(π r²) points; this keeps that ≤ [`MAX_N`].
pub fn bridson_min_radius() -> f64 {
    1.0 / (std::f64::consts::PI * MAX_N as f64).sqrt()
}

/// The checks of [`bridson`]: `n`, `radius` (against `n` and the largest set built) and `k`;
/// the radius in use.
pub(super) fn check_bridson(p: &PoissonBridson, n: usize) -> Result<f64, PatternError> {
    const NAME: &str = PoissonBridson::NAME;
    check_n(n, MAX_N)?;
    let r = resolve_radius(NAME, p.radius, n)?;
    let r_min = bridson_min_radius();
    if r < r_min {
        return Err(PatternError::InvalidParam {
            pattern: NAME,
            field: "radius",
            value: fmt_num(p.radius),
            allowed: format!(
                "0 (auto) or in [{}, {}]: a maximal set of radius r holds at least \
                 1/(π r²) points and at most {MAX_N} are built",
                fmt_num(r_min),
                fmt_num(max_radius(n).min(1.0))
            ),
        });
    }
    if p.k == 0 || p.k > 1000 {
        return Err(PatternError::InvalidParam {
            pattern: NAME,
            field: "k",
            value: p.k.to_string(),
            allowed: "an integer in 1..=1000".into(),
        });
    }
    Ok(r)
}

/// Bridson's fast Poisson-disk sampling (SIGGRAPH 2007) on the torus, thinned to exactly n points.
///
/// Algorithm (toroidal variant): a first point uniform in [0,1)² starts the active list. While the
/// list is not empty, pick a uniformly random active point p and draw up to k candidates uniformly
/// in the annulus r ≤ |c − p| ≤ 2r (rejection sampling from the square [−2r, 2r]², accepting
/// r² ≤ |c − p|² ≤ 4r²), each wrapped onto the torus. The first candidate whose squared toroidal
/// distance to every point is ≥ r² becomes a point and joins the active list; when all k fail, p
/// leaves the list. Conflicts are found in a background grid of cells of side ≤ r/√2 (at most one
/// point per cell, padded with ghost cells across the seam), searching the 5 × 5 cells around the
/// candidate, nearest first.
///
/// The result is a *maximal* set (no more disk fits near any point) of M points with toroidal
/// minimum distance ≥ r. To return exactly n points:
/// - if M > n, a uniformly random subset of n points is kept (partial Fisher–Yates with the same
///   RNG, in random order); a subset of a Poisson-disk set keeps its minimum distance ≥ r, but has a
///   lower density than the radius suggests (its relative radius is r / d_max(n));
/// - if M < n, the M points are returned with a note, as for dart throwing.
///
/// `radius` = 0 uses [`default_radius`]`(n)` (0.65 d_max(n); Bridson's maximal sets reach about
/// r ≈ 0.73 d_max(M) at k = 30, so M ≈ 1.26 n at the default); radii above [`max_radius`]`(n)` are [`PatternError::RadiusTooLarge`],
/// radii below [`bridson_min_radius`] (sets of more than [`MAX_N`] points) are
/// [`PatternError::InvalidParam`]; both are checked before any work. The cancel token is checked
/// every 4096 candidates.
pub fn bridson(
    p: &PoissonBridson,
    n: usize,
    seed: u64,
    cancel: &Cancel,
) -> Result<Generated, PatternError> {
    let r = check_bridson(p, n)?;
    cancel.check()?;
    let r2 = r * r;
    let four_r2 = 4.0 * r2;
    let two_r = 2.0 * r;
    let g = (std::f64::consts::SQRT_2 * (1.0 + GRID_MARGIN) / r)
        .ceil()
        .max(1.0) as usize;
    // Packing bound on M, capped: the vectors grow if needed.
    let expected = ((2.0 / (3f64.sqrt() * r2)) as usize).clamp(1, 2 * n + 64) + 1;
    let mut grid = PaddedGrid::new(g, reach(r, g));
    // points[0] is the grid's NaN sentinel; the pattern is points[1..].
    let mut points: Vec<DVec2> = Vec::with_capacity(expected);
    points.push(NAN_POINT);
    let mut active: Vec<u32> = Vec::with_capacity(expected);
    let mut rng = Rng::new(seed);

    let first = DVec2::new(rng.next_f64(), rng.next_f64());
    grid.insert(1, first);
    points.push(first);
    active.push(1);
    let mut tries: u64 = 0;
    while !active.is_empty() {
        let a = rng.below(active.len() as u64) as usize;
        let centre = points[active[a] as usize];
        let mut found = false;
        for _ in 0..p.k {
            tries += 1;
            if tries % 4096 == 0 {
                cancel.check()?;
            }
            // Uniform in the annulus r ≤ |d| ≤ 2r by rejection from the square [−2r, 2r]²
            // (acceptance 3π/16 ≈ 0.59); one 64-bit draw per try gives both coordinates
            // (32 bits each: a resolution of 4r·2⁻³², far below any distance that matters).
            let d = loop {
                let u = rng.next_u64();
                let d = DVec2::new(
                    ((u >> 32) as f64 * U32_SCALE - 1.0) * two_r,
                    ((u & 0xFFFF_FFFF) as f64 * U32_SCALE - 1.0) * two_r,
                );
                let l2 = d.length_squared();
                if (r2..=four_r2).contains(&l2) {
                    break d;
                }
            };
            let c = DVec2::new(wrap_unit(centre.x + d.x), wrap_unit(centre.y + d.y));
            if !grid.any_within(&points, c, r2) {
                let index = points.len() as u32;
                grid.insert(index, c);
                points.push(c);
                active.push(index);
                found = true;
                break;
            }
        }
        if !found {
            active.swap_remove(a);
        }
    }
    drop(grid);
    points.remove(0);
    cancel.check()?;
    let m = points.len();
    if m >= n {
        for i in 0..n {
            let j = i + rng.below((m - i) as u64) as usize;
            points.swap(i, j);
        }
        points.truncate(n);
        Ok(Generated::complete(points))
    } else {
        let note = format!(
            "placed {m} of {n} points: Bridson's maximal set at radius {} (relative radius \
             r/d_max = {:.4}) holds only {m} points: lower radius",
            fmt_num(r),
            r / max_radius(n)
        );
        Ok(Generated {
            points,
            requested: n,
            note: Some(note),
        })
    }
}

/// 2 / 2³²: maps a 32-bit integer onto [0, 2).
const U32_SCALE: f64 = 2.0 / 4_294_967_296.0;

/// Wraps x (within a few units of [0,1)) onto [0, 1 − 2⁻⁵³].
#[inline(always)]
fn wrap_unit(mut x: f64) -> f64 {
    while x < 0.0 {
        x += 1.0;
    }
    while x >= 1.0 {
        x -= 1.0;
    }
    clamp_unit(x)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn max_radius_matches_hexagonal_cell_area() {
        // (√3/2) d_max² · n = 1 exactly (up to rounding).
        for n in [1usize, 2, 3, 100, 4096, MAX_N] {
            let d = max_radius(n);
            let area = 3f64.sqrt() / 2.0 * d * d * n as f64;
            assert!((area - 1.0).abs() < 1e-14, "n = {n}: {area}");
        }
        assert_eq!(default_radius(100), 0.65 * max_radius(100));
        assert_eq!(max_radius(0), f64::INFINITY);
    }

    #[test]
    fn padded_grid_any_within_equals_scan_of_every_point() {
        let mut rng = Rng::new(8);
        for &r in &[0.011, 0.05, 0.3, 0.6, 1.0] {
            let g = (std::f64::consts::SQRT_2 * (1.0 + GRID_MARGIN) / r).ceil() as usize;
            let mut grid = PaddedGrid::new(g, reach(r, g));
            // A Poisson-disk set built by naive dart throwing (one point per cell holds).
            let mut pts = vec![NAN_POINT];
            for _ in 0..3000 {
                let q = DVec2::new(rng.next_f64(), rng.next_f64());
                if pts[1..]
                    .iter()
                    .all(|&p| torus::distance_squared(q, p, 1.0) >= r * r)
                {
                    grid.insert(pts.len() as u32, q);
                    pts.push(q);
                }
            }
            for _ in 0..3000 {
                let q = DVec2::new(rng.next_f64(), rng.next_f64());
                let scan = pts[1..]
                    .iter()
                    .any(|&p| torus::distance_squared(q, p, 1.0) < r * r);
                assert_eq!(grid.any_within(&pts, q, r * r), scan, "r = {r}, q = {q}");
            }
        }
    }

    #[test]
    fn grid_any_within_equals_scan_of_every_point() {
        let mut rng = Rng::new(5);
        let pts: Vec<DVec2> = (0..500)
            .map(|_| DVec2::new(rng.next_f64(), rng.next_f64()))
            .collect();
        for &r in &[0.013, 0.05, 0.2, 0.45, 0.9] {
            let mut grid = dart_grid(r, pts.len());
            for (i, &p) in pts.iter().enumerate() {
                grid.insert(i, p);
            }
            let k = reach(r, grid.g);
            for _ in 0..2000 {
                let q = DVec2::new(rng.next_f64(), rng.next_f64());
                let scan = pts
                    .iter()
                    .any(|&p| torus::distance_squared(q, p, 1.0) < r * r);
                assert_eq!(grid.any_within(&pts, q, r * r, k), scan, "r = {r}, q = {q}");
            }
        }
    }

    #[test]
    fn wrap_unit_never_returns_one() {
        // −1e−17 + 1 rounds to 1.0 ≡ 0 on the torus; never 1.0 itself.
        assert_eq!(wrap_unit(-1e-17), 0.0);
        assert_eq!(wrap_unit(1.0), 0.0);
        assert_eq!(wrap_unit(1.25), 0.25);
        assert_eq!(wrap_unit(-0.25), 0.75);
        assert_eq!(wrap_unit(-2.5), 0.5);
    }
}
