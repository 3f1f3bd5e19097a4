//! Toroidal minimum distance and mean nearest-neighbour distance.
//!
//! For points `x_1 … x_N` on the unit torus, with the toroidal distance
//! `d(p,q)² = Σ_k min(|p_k−q_k|, 1−|p_k−q_k|)²`:
//!
//! - minimum distance `d_min = min_{i≠j} d(x_i, x_j)`, and the pair `(i, j)`, `i < j`, that
//!   attains it (the lexicographically smallest pair when several do, so the fast and the
//!   naive algorithm return the same pair);
//! - mean nearest-neighbour distance `d̄_NN = (1/N) Σ_i min_{j≠i} d(x_i, x_j)`;
//! - both divided by the hexagonal packing distance `d_hex(N) = √(2/(√3·N))` (the
//!   nearest-neighbour distance of the densest packing of N discs on the unit torus). PSA
//!   reports distances multiplied by `√(√3·N/2) = 1/d_hex(N)`, i.e. exactly these values.
//!
//! Duplicate points give `d_min = 0` (a valid answer, not an error).

use crate::core::torus;
use glam::DVec2;
use serde::Serialize;

use super::{validate, Cancel, MetricsError, CANCEL_STRIDE};

/// [`min_distance_naive`] accepts at most this many points (it costs N²/2 distance evaluations).
pub const MIN_DISTANCE_NAIVE_MAX_N: usize = 1 << 16;

/// Result of [`min_distance`].
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct MinDistance {
    /// Toroidal minimum distance between two distinct points (0 for duplicates), in units of
    /// the unit square.
    pub min_distance: f64,
    /// Indices `(i, j)`, `i < j`, of the pair at the minimum distance (lexicographically
    /// smallest among ties) — e.g. to draw two discs of radius `min_distance / 2`.
    pub pair: (usize, usize),
    /// Mean over all points of the toroidal distance to the nearest other point.
    pub mean_nn_distance: f64,
    /// `d_hex(N) = √(2/(√3·N))`, the hexagonal packing distance used to normalise.
    pub hex_distance: f64,
    /// `min_distance / d_hex(N)` (PSA's normalised minimum distance; 1 = hexagonal packing).
    pub normalized_min_distance: f64,
    /// `mean_nn_distance / d_hex(N)`.
    pub normalized_mean_nn_distance: f64,
}

/// The hexagonal packing distance `d_hex(N) = √(2/(√3·N))` for N ≥ 1: the nearest-neighbour
/// distance of N points on a hexagonal lattice covering the unit area (each point owns a
/// hexagon of area 1/N = (√3/2)·d²). PSA's normalisation factor `√(√3·N/2)` is `1/d_hex(N)`.
pub fn hex_distance(n: usize) -> f64 {
    (2.0 / (3f64.sqrt() * n as f64)).sqrt()
}

/// Per-point nearest neighbour: (squared distance, index), ties broken by the smaller index.
#[derive(Clone, Copy)]
struct Nn {
    d2: f64,
    j: usize,
}

impl Nn {
    const NONE: Nn = Nn {
        d2: f64::INFINITY,
        j: usize::MAX,
    };
    #[inline]
    fn offer(&mut self, d2: f64, j: usize) {
        if d2 < self.d2 || (d2 == self.d2 && j < self.j) {
            self.d2 = d2;
            self.j = j;
        }
    }
}

/// Builds the result from per-point nearest neighbours (shared by the fast and naive paths,
/// so both sum in the same order and return bit-identical results).
fn assemble(nn: &[Nn]) -> MinDistance {
    let n = nn.len();
    let mut best = (f64::INFINITY, (usize::MAX, usize::MAX));
    let mut sum = 0.0;
    for (i, q) in nn.iter().enumerate() {
        sum += q.d2.sqrt();
        let pair = (i.min(q.j), i.max(q.j));
        if q.d2 < best.0 || (q.d2 == best.0 && pair < best.1) {
            best = (q.d2, pair);
        }
    }
    let min_distance = best.0.sqrt();
    let mean_nn_distance = sum / n as f64;
    let hex = hex_distance(n);
    MinDistance {
        min_distance,
        pair: best.1,
        mean_nn_distance,
        hex_distance: hex,
        normalized_min_distance: min_distance / hex,
        normalized_mean_nn_distance: mean_nn_distance / hex,
    }
}

fn check_two(points: &[DVec2]) -> Result<(), MetricsError> {
    validate(points)?;
    if points.len() < 2 {
        return Err(MetricsError::TooFewPoints {
            what: "a minimum distance",
            n: points.len(),
            min: 2,
        });
    }
    Ok(())
}

/// Toroidal minimum distance, its pair, and mean nearest-neighbour distance, by brute force:
/// every pair is measured (N(N−1)/2 distances). The reference for [`min_distance`].
///
/// Errors: fewer than 2 points, invalid points, more than [`MIN_DISTANCE_NAIVE_MAX_N`] points,
/// cancellation.
pub fn min_distance_naive(points: &[DVec2], cancel: &Cancel) -> Result<MinDistance, MetricsError> {
    check_two(points)?;
    let n = points.len();
    if n > MIN_DISTANCE_NAIVE_MAX_N {
        return Err(MetricsError::TooManyPoints {
            what: "min_distance_naive",
            n,
            max: MIN_DISTANCE_NAIVE_MAX_N,
            cost: "O(N²)",
        });
    }
    let mut nn = vec![Nn::NONE; n];
    for i in 0..n {
        if i % 256 == 0 {
            cancel.check()?;
        }
        for j in i + 1..n {
            let d2 = torus::distance_squared(points[i], points[j], 1.0);
            nn[i].offer(d2, j);
            nn[j].offer(d2, i);
        }
    }
    Ok(assemble(&nn))
}

/// Toroidal minimum distance, the pair attaining it, and the mean nearest-neighbour distance,
/// with a uniform grid: G×G cells, `G = ⌊√(N/2)⌋` (about two points per cell). Each point
/// searches rings of cells around its own (wrapping around the torus) until the distance to
/// the unsearched region exceeds its best candidate, so the expected cost is O(N) for point
/// sets of bounded density (all samplers of this crate). Heavily clustered sets degrade
/// towards O(N²); the loop checks `cancel`. Same results, bit for bit, as
/// [`min_distance_naive`].
///
/// Errors: fewer than 2 points, invalid points, cancellation.
pub fn min_distance(points: &[DVec2], cancel: &Cancel) -> Result<MinDistance, MetricsError> {
    check_two(points)?;
    let n = points.len();
    // Below a 3×3 grid the rings wrap onto themselves: brute force is cheaper anyway.
    let g = ((n / 2) as f64).sqrt().floor() as usize;
    if g < 3 {
        return min_distance_naive(points, cancel);
    }
    let h = 1.0 / g as f64;
    let cell_of = |v: f64| ((v * g as f64) as usize).min(g - 1);

    // Counting sort of the points into cells.
    let mut start = vec![0u32; g * g + 1];
    let cells: Vec<usize> = points
        .iter()
        .map(|p| cell_of(p.y) * g + cell_of(p.x))
        .collect();
    for &c in &cells {
        start[c + 1] += 1;
    }
    for c in 0..g * g {
        start[c + 1] += start[c];
    }
    let mut fill = start.clone();
    let mut sorted: Vec<(DVec2, u32)> = vec![(DVec2::ZERO, 0); n];
    for (i, &c) in cells.iter().enumerate() {
        sorted[fill[c] as usize] = (points[i], i as u32);
        fill[c] += 1;
    }

    let mut nn = vec![Nn::NONE; n];
    for (i, &p) in points.iter().enumerate() {
        if i % CANCEL_STRIDE == 0 {
            cancel.check()?;
        }
        let (cx, cy) = (cell_of(p.x), cell_of(p.y));
        let mut best = Nn::NONE;
        let visit = |ix: isize, iy: isize, best: &mut Nn| {
            let x = ix.rem_euclid(g as isize) as usize;
            let y = iy.rem_euclid(g as isize) as usize;
            let c = y * g + x;
            for &(q, j) in &sorted[start[c] as usize..start[c + 1] as usize] {
                let j = j as usize;
                if j != i {
                    best.offer(torus::distance_squared(p, q, 1.0), j);
                }
            }
        };
        let (cxi, cyi) = (cx as isize, cy as isize);
        let mut r = 0isize;
        loop {
            if 2 * r + 1 > g as isize {
                // The ring would wrap onto cells already searched: finish by brute force.
                for (j, &q) in points.iter().enumerate() {
                    if j != i {
                        best.offer(torus::distance_squared(p, q, 1.0), j);
                    }
                }
                break;
            }
            if r == 0 {
                visit(cxi, cyi, &mut best);
            } else {
                for dx in -r..=r {
                    visit(cxi + dx, cyi - r, &mut best);
                    visit(cxi + dx, cyi + r, &mut best);
                }
                for dy in -r + 1..r {
                    visit(cxi - r, cyi + dy, &mut best);
                    visit(cxi + r, cyi + dy, &mut best);
                }
            }
            // Every point outside the searched (2r+1)² block is at least `bound` away.
            let rf = r as f64;
            let bound = (p.x - (cx as f64 - rf) * h)
                .min((cx as f64 + rf + 1.0) * h - p.x)
                .min(p.y - (cy as f64 - rf) * h)
                .min((cy as f64 + rf + 1.0) * h - p.y)
                .max(0.0);
            // Strict, with a relative margin against rounding, so that ties at exactly the
            // bound are still resolved by index exactly as the brute force does.
            if best.d2 < bound * bound * (1.0 - 1e-9) {
                break;
            }
            r += 1;
        }
        nn[i] = best;
    }
    Ok(assemble(&nn))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hex_distance_matches_psa_factor() {
        for n in [1usize, 7, 1024, 100_000] {
            let psa = (3f64.sqrt() * n as f64 / 2.0).sqrt();
            assert!((hex_distance(n) * psa - 1.0).abs() < 1e-15);
        }
    }

    #[test]
    fn wrap_around_distance() {
        let d2 = torus::distance_squared(DVec2::new(0.01, 0.5), DVec2::new(0.99, 0.5), 1.0);
        assert!((d2.sqrt() - 0.02).abs() < 1e-15);
    }
}
