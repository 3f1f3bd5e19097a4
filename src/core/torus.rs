//! Periodic (toroidal) Delaunay helpers shared by Lloyd relaxation's exact Voronoi cells
//! (`pattern::optimize`) and PSA's bond-orientational order (`metrics::psa`): the points and
//! their periodic copies in a band of width w around the unit square, the circumcircle of a
//! triangle, and whether a circumdisc lies inside the band (where a triangle of the copies is
//! a triangle of the periodic triangulation).

use glam::DVec2;

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

#[cfg(test)]
mod tests {
    use super::*;

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
