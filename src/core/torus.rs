//! Geometry on the torus (the square of side `period` with opposite edges glued): the one
//! toroidal distance ([`distance_squared`], [`distance`]; its per-axis rule [`axis_gap`], and
//! [`distance_squared_cube`] on the unit torus [0,1)^d) and displacement ([`delta`]) that every
//! pattern, metric and tile uses, and the periodic Delaunay helpers shared by Lloyd
//! relaxation's exact Voronoi cells (`pattern::optimize`) and PSA's bond-orientational order
//! (`metrics::psa`): the points and
//! their periodic copies in a band of width w around the unit square, the circumcircle of a
//! triangle, and whether a circumdisc lies inside the band (where a triangle of the copies is
//! a triangle of the periodic triangulation), and [`delaunay`]: the Delaunay triangulation made
//! unique on cocircular points.
//!
//! ## Ties ([`delaunay`])
//!
//! Where four or more points are cocircular (every cell of a square grid), the Delaunay
//! triangulation is not unique, and `delaunator` splits each such quad by the order in which
//! its sweep met the points: on a grid the diagonals then point both ways (PSA's
//! bond-orientational order of a 32 × 32 grid came out 0.313 instead of 1/3). [`delaunay`]
//! takes `delaunator`'s triangulation and flips edges (Lawson's algorithm) until every edge is
//! locally Delaunay under exact predicates (`robust`, Shewchuk's adaptive orient2d and
//! incircle) with the *symbolic perturbation* used by CGAL's `Delaunay_triangulation_2`, which
//! PSA triangulates with (Devillers and Teillaud, "Perturbations for Delaunay and weighted
//! Delaunay 3D triangulations", CGTA 44(3), 2011): each point is lifted to the paraboloid
//! z = x² + y² plus an infinitesimal ε_i that is larger for points later in (x, y)
//! lexicographic order, each infinitely larger than the ones before it. In-circle tests that
//! are exactly 0 are decided by the largest perturbation whose coefficient is not zero: for a
//! counter-clockwise triangle abc and a query d, d is outside when d is the largest of the four,
//! and otherwise the sign is orient(d, b, c), orient(a, d, c) or orient(a, b, d) for the largest
//! being a, b or c (the derivatives of the lifted determinant). The perturbed lifting is in
//! general position, so the result is the one Delaunay triangulation of the perturbed points:
//! independent of the input order, and on a square grid every cell is split by the same
//! diagonal, from its lower-right to its upper-left corner.

use glam::DVec2;
use robust::{incircle, orient2d, Coord};

/// Squared distance on the torus of side `period` between points whose coordinates lie in
/// [0, period): Δx² + Δy² with Δ = min(|a − b|, period − |a − b|) per coordinate, the
/// distance to the nearest of b's periodic images. Branch-free and inlined: the hot path of
/// every Poisson-disk, best-candidate, pmj, optimisation, minimum-distance and RDF search (and
/// of their naive references, so their decisions agree bit for bit).
#[inline(always)]
pub fn distance_squared(a: DVec2, b: DVec2, period: f64) -> f64 {
    let dx = axis_gap(a.x, b.x, period);
    let dy = axis_gap(a.y, b.y, period);
    dx * dx + dy * dy
}

/// The toroidal gap along one axis of period `period`: min(|a − b|, period − |a − b|), for a, b
/// in [0, period). The one per-coordinate rule of [`distance_squared`] and
/// [`distance_squared_cube`].
#[inline(always)]
pub fn axis_gap(a: f64, b: f64, period: f64) -> f64 {
    let d = (a - b).abs();
    // `if d < p − d` rather than f64::min: the same value for every non-NaN d, one instruction.
    let e = period - d;
    if d < e {
        d
    } else {
        e
    }
}

/// Squared distance on the unit torus [0,1)^d between two points of d coordinates each
/// (`a.len() == b.len()`): Σ_k [`axis_gap`]², summed in coordinate order, so that at d = 2 it
/// is [`distance_squared`] bit for bit.
#[inline(always)]
pub fn distance_squared_cube(a: &[f64], b: &[f64]) -> f64 {
    let mut s = 0.0;
    for (&x, &y) in a.iter().zip(b) {
        let g = axis_gap(x, y, 1.0);
        s += g * g;
    }
    s
}

/// Distance on the torus of side `period` between any two points (each coordinate difference
/// reduced modulo the period first): √[`distance_squared`], at most period·√2 / 2.
pub fn distance(a: DVec2, b: DVec2, period: f64) -> f64 {
    let d = (a - b).abs();
    let d = DVec2::new(d.x % period, d.y % period);
    distance_squared(d, DVec2::ZERO, period).sqrt()
}

/// The displacement a − b to the nearest periodic image, in [−period/2, period/2] per
/// coordinate (a, b with coordinates in [0, period)).
#[inline]
pub fn delta(a: DVec2, b: DVec2, period: f64) -> DVec2 {
    let half = 0.5 * period;
    let wrap = |d: f64| {
        if d > half {
            d - period
        } else if d < -half {
            d + period
        } else {
            d
        }
    };
    DVec2::new(wrap(a.x - b.x), wrap(a.y - b.y))
}

/// `points` (first, in order) and their periodic copies p + (a, b), a, b ∈ {−2 … 2}, whose
/// coordinates lie in [−w, 1 + w] (`closed`) or [−w, 1 + w) (not `closed`); copies two
/// periods away only when w > 1.
pub(crate) fn with_periodic_copies(
    points: &[DVec2],
    w: f64,
    closed: bool,
) -> Vec<delaunator::Point> {
    let reach: i32 = if w > 1.0 { 2 } else { 1 };
    let mut all: Vec<delaunator::Point> = points
        .iter()
        .map(|p| delaunator::Point { x: p.x, y: p.y })
        .collect();
    let inside = |v: f64| v >= -w && if closed { v <= 1.0 + w } else { v < 1.0 + w };
    for p in points {
        for b in -reach..=reach {
            let y = p.y + b as f64;
            if !inside(y) {
                continue;
            }
            for a in -reach..=reach {
                let x = p.x + a as f64;
                if (a != 0 || b != 0) && inside(x) {
                    all.push(delaunator::Point { x, y });
                }
            }
        }
    }
    all
}

/// The circumcentre of triangle abc and its squared radius (non-finite for a degenerate
/// triangle).
pub(crate) fn circumcircle(a: DVec2, b: DVec2, c: DVec2) -> (DVec2, f64) {
    let (d, e) = (b - a, c - a);
    let (dd, ee) = (d.length_squared(), e.length_squared());
    let den = 2.0 * (d.x * e.y - d.y * e.x);
    let u = DVec2::new((e.y * dd - d.y * ee) / den, (d.x * ee - e.x * dd) / den);
    (a + u, u.length_squared())
}

/// Whether the disc of centre `c` and squared radius `r2` (widened by a relative 10⁻⁹ and an
/// absolute 10⁻¹²) lies in the band [−w, 1 + w]²; false for non-finite values.
pub(crate) fn circumdisc_in_band(c: DVec2, r2: f64, w: f64) -> bool {
    let r = r2.sqrt() * (1.0 + 1e-9) + 1e-12;
    c.is_finite()
        && r.is_finite()
        && c.x - r >= -w
        && c.x + r <= 1.0 + w
        && c.y - r >= -w
        && c.y + r <= 1.0 + w
}

fn coord(p: &delaunator::Point) -> Coord<f64> {
    Coord { x: p.x, y: p.y }
}

/// (x, y) lexicographic order: the order of the symbolic perturbation (module docs).
fn lex_less(a: &delaunator::Point, b: &delaunator::Point) -> bool {
    a.x < b.x || (a.x == b.x && a.y < b.y)
}

/// Whether `d` lies strictly inside the circle through a, b, c (any orientation, not
/// collinear) under the symbolic perturbation of the module docs: exact, and never a tie for
/// four distinct points.
fn in_circle_perturbed(pts: &[delaunator::Point], a: usize, b: usize, c: usize, d: usize) -> bool {
    let (mut a, mut b) = (a, b);
    if orient2d(coord(&pts[a]), coord(&pts[b]), coord(&pts[c])) < 0.0 {
        std::mem::swap(&mut a, &mut b);
    }
    // Shewchuk's incircle: positive when d is inside the circle of the counter-clockwise abc.
    let det = incircle(
        coord(&pts[a]),
        coord(&pts[b]),
        coord(&pts[c]),
        coord(&pts[d]),
    );
    if det != 0.0 {
        return det > 0.0;
    }
    let mut order = [a, b, c, d];
    order.sort_by(|&u, &v| {
        if lex_less(&pts[u], &pts[v]) {
            std::cmp::Ordering::Less
        } else if lex_less(&pts[v], &pts[u]) {
            std::cmp::Ordering::Greater
        } else {
            std::cmp::Ordering::Equal
        }
    });
    let o = |p: usize, q: usize, r: usize| orient2d(coord(&pts[p]), coord(&pts[q]), coord(&pts[r]));
    for &k in order.iter().rev() {
        let sign = if k == d {
            return false;
        } else if k == a {
            o(d, b, c)
        } else if k == b {
            o(a, d, c)
        } else {
            o(a, b, d)
        };
        if sign != 0.0 {
            return sign > 0.0;
        }
    }
    false
}

/// The Delaunay triangulation of `pts` (`delaunator`'s layout: `triangles`, `halfedges`,
/// `hull`), unique on cocircular points by the symbolic perturbation of the module docs.
///
/// `delaunator` triangulates first; then every interior edge is tested with exact predicates
/// and flipped while it is not locally Delaunay (a queue of edges, Lawson's algorithm). On
/// points in general position nothing flips (each edge costs one exact in-circle test, a few
/// floating-point operations when the filter of `robust` decides); on a grid every cell whose
/// diagonal points the other way flips once.
pub(crate) fn delaunay(pts: &[delaunator::Point]) -> delaunator::Triangulation {
    use delaunator::{next_halfedge, prev_halfedge, EMPTY};
    let mut t = delaunator::triangulate(pts);
    let mut queue: Vec<usize> = (0..t.halfedges.len())
        .filter(|&e| t.halfedges[e] != EMPTY && e < t.halfedges[e])
        .collect();
    // Each flip strictly lowers the perturbed lifted surface, so the loop ends; the bound only
    // guards against a fault of the predicates.
    let mut budget = 64 * t.halfedges.len() + 64;
    while let Some(e) = queue.pop() {
        let f = t.halfedges[e];
        if f == EMPTY || budget == 0 {
            continue;
        }
        let (e1, e2) = (next_halfedge(e), prev_halfedge(e));
        let (f1, f2) = (next_halfedge(f), prev_halfedge(f));
        // e: p → q in triangle (p, q, r); f: q → p in triangle (q, p, s).
        let (p, q, r, s) = (
            t.triangles[e],
            t.triangles[e1],
            t.triangles[e2],
            t.triangles[f2],
        );
        if !in_circle_perturbed(pts, p, q, r, s) {
            continue;
        }
        // Flip only a strictly convex quad (always so for a Delaunay-illegal edge).
        let side = |u: usize| orient2d(coord(&pts[r]), coord(&pts[s]), coord(&pts[u]));
        if side(p) * side(q) >= 0.0 {
            continue;
        }
        budget -= 1;
        let (h_qr, h_rp, h_ps, h_sq) = (
            t.halfedges[e1],
            t.halfedges[e2],
            t.halfedges[f1],
            t.halfedges[f2],
        );
        // (p, q, r) + (q, p, s) → (r, s, q) + (s, r, p): same orientation, diagonal r–s.
        t.triangles[e] = r;
        t.triangles[e1] = s;
        t.triangles[e2] = q;
        t.triangles[f] = s;
        t.triangles[f1] = r;
        t.triangles[f2] = p;
        let mut link = |a: usize, b: usize| {
            t.halfedges[a] = b;
            if b != EMPTY {
                t.halfedges[b] = a;
            }
        };
        link(e, f);
        link(e1, h_sq);
        link(e2, h_qr);
        link(f1, h_rp);
        link(f2, h_ps);
        queue.extend([e1, e2, f1, f2]);
    }
    t
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::rng::Rng;

    /// The distance to the nearest of b's 9 images b + (i, j)·period, i, j ∈ {−1, 0, 1}.
    fn naive_d2(a: DVec2, b: DVec2, period: f64) -> f64 {
        let mut best = f64::INFINITY;
        for i in -1..=1 {
            for j in -1..=1 {
                let image = b + DVec2::new(f64::from(i), f64::from(j)) * period;
                best = best.min(a.distance_squared(image));
            }
        }
        best
    }

    #[test]
    fn the_cube_distance_is_the_2d_one_at_d_2_and_the_nearest_image_in_d() {
        let mut rng = Rng::new(25);
        for _ in 0..10_000 {
            let a = DVec2::new(rng.next_f64(), rng.next_f64());
            let b = DVec2::new(rng.next_f64(), rng.next_f64());
            let cube = distance_squared_cube(&[a.x, a.y], &[b.x, b.y]);
            assert_eq!(cube.to_bits(), distance_squared(a, b, 1.0).to_bits());
        }
        // d = 3: the nearest of the 27 images, each coordinate wrapped independently.
        for _ in 0..2000 {
            let a: Vec<f64> = (0..3).map(|_| rng.next_f64()).collect();
            let b: Vec<f64> = (0..3).map(|_| rng.next_f64()).collect();
            let mut best = f64::INFINITY;
            for s in 0..27 {
                let shift = [s % 3, s / 3 % 3, s / 9].map(|t| t as f64 - 1.0);
                let d2: f64 = (0..3).map(|k| (a[k] - b[k] - shift[k]).powi(2)).sum();
                best = best.min(d2);
            }
            assert!((distance_squared_cube(&a, &b) - best).abs() <= 1e-15);
        }
    }

    #[test]
    fn torus_distance_is_the_nearest_of_nine_images() {
        let mut rng = Rng::new(24);
        for period in [1.0, 0.25, 3.0, 17.0] {
            for _ in 0..20_000 {
                let a = DVec2::new(rng.next_f64(), rng.next_f64()) * period;
                let b = DVec2::new(rng.next_f64(), rng.next_f64()) * period;
                let (fast, naive) = (distance_squared(a, b, period), naive_d2(a, b, period));
                assert!(
                    (fast - naive).abs() <= 1e-12 * period * period,
                    "{a} {b} {period}"
                );
                assert!((distance(a, b, period) - naive.sqrt()).abs() <= 1e-12 * period);
                let d = delta(a, b, period);
                assert!(d.x.abs() <= 0.5 * period && d.y.abs() <= 0.5 * period);
                assert!((d.length_squared() - naive).abs() <= 1e-12 * period * period);
            }
        }
        // Any points: reduced modulo the period; at most half the diagonal.
        assert!((distance(DVec2::new(2.25, 0.0), DVec2::ZERO, 1.0) - 0.25).abs() < 1e-15);
        assert!((distance(DVec2::new(-7.5, 0.5), DVec2::ZERO, 1.0) - 0.5f64.sqrt()).abs() < 1e-15);
        let across = distance(DVec2::new(0.05, 0.5), DVec2::new(0.95, 0.5), 1.0);
        assert!((across - 0.1).abs() < 1e-15);
    }

    #[test]
    fn incircle_sign_and_the_perturbed_tie_break() {
        let p = |x: f64, y: f64| delaunator::Point { x, y };
        // Counter-clockwise unit right triangle; its circle has centre (½, ½).
        let pts = [
            p(0.0, 0.0),
            p(1.0, 0.0),
            p(0.0, 1.0),
            p(0.2, 0.2),
            p(1.0, 1.0),
            p(2.0, 2.0),
        ];
        assert!(in_circle_perturbed(&pts, 0, 1, 2, 3));
        assert!(
            in_circle_perturbed(&pts, 0, 2, 1, 3),
            "orientation must not matter"
        );
        assert!(!in_circle_perturbed(&pts, 0, 1, 2, 5));
        // (1, 1) is on the circle and the lexicographically largest of the four: outside.
        assert!(!in_circle_perturbed(&pts, 0, 1, 2, 4));
        // The other split of the same square: (0, 1) is then inside the circle of (0,0),
        // (1,0), (1,1) (the largest, (1,1), is a vertex; orient(a, b, d) decides).
        assert!(in_circle_perturbed(&pts, 0, 1, 4, 2));
    }

    #[test]
    fn grid_cells_are_all_split_by_the_same_diagonal_whatever_the_input_order() {
        let k = 9;
        let mut pts: Vec<delaunator::Point> = (0..k * k)
            .map(|i| delaunator::Point {
                x: (i % k) as f64 / k as f64,
                y: (i / k) as f64 / k as f64,
            })
            .collect();
        for round in 0..3 {
            let t = delaunay(&pts);
            assert_eq!(t.triangles.len(), 3 * 2 * (k - 1) * (k - 1));
            for tri in t.triangles.chunks(3) {
                // Each triangle has one edge that is a diagonal: from lower right to upper left.
                for i in 0..3 {
                    let (a, b) = (&pts[tri[i]], &pts[tri[(i + 1) % 3]]);
                    let (dx, dy) = (b.x - a.x, b.y - a.y);
                    if dx != 0.0 && dy != 0.0 {
                        assert!(dx * dy < 0.0, "round {round}: diagonal {dx} {dy}");
                    }
                }
            }
            // Another input order gives the same triangles.
            pts.reverse();
            if round == 1 {
                pts.rotate_left(k * k / 3);
            }
        }
    }

    #[test]
    fn copies_cover_the_band_and_the_circumcircle_is_equidistant() {
        let pts = [DVec2::new(0.05, 0.5), DVec2::new(0.5, 0.97)];
        let all = with_periodic_copies(&pts, 0.1, false);
        // Each point keeps its place first; (0.05, 0.5) gains x + 1 = 1.05, (0.5, 0.97) gains
        // y − 1 = −0.03.
        assert_eq!((all[0].x, all[0].y), (0.05, 0.5));
        assert_eq!(all.len(), 4);
        assert!(all.iter().any(|p| p.x == 1.05 && p.y == 0.5));
        assert!(all.iter().any(|p| p.x == 0.5 && (p.y + 0.03).abs() < 1e-15));
        // Closed band: a copy landing exactly on 1 + w is kept.
        let edge = [DVec2::new(0.25, 0.5)];
        assert_eq!(with_periodic_copies(&edge, 0.25, false).len(), 1);
        assert_eq!(with_periodic_copies(&edge, 0.25, true).len(), 2);
        let (a, b, c) = (
            DVec2::new(0.1, 0.2),
            DVec2::new(0.7, 0.3),
            DVec2::new(0.4, 0.9),
        );
        let (o, r2) = circumcircle(a, b, c);
        for p in [a, b, c] {
            assert!(((p - o).length_squared() - r2).abs() < 1e-14);
        }
        assert!(circumdisc_in_band(o, r2, 0.5));
        assert!(!circumdisc_in_band(o, r2, 0.0));
        assert!(!circumdisc_in_band(DVec2::NAN, 0.0, 1.0));
    }
}
