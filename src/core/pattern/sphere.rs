//! Mapping of 2D patterns onto the unit sphere.
//!
//! The lecture ("Hammersley Sequences", sphere figure): *samples on the sphere are obtained by
//! wrapping the square into a cylinder and then doing a radial projection*. The square
//! (u, v) ∈ [0,1)² is wrapped around the unit cylinder of height 2 — angle φ = 2πu, height
//! z = 1 − 2v — and every cylinder point is projected horizontally (along the ray from the
//! z-axis) onto the sphere:
//!
//! (u, v) ↦ (r cos φ, r sin φ, z), φ = 2πu, z = 1 − 2v, r = √(1 − z²).
//!
//! By Archimedes' hat-box theorem this horizontal projection preserves area, so the map sends
//! uniform points of the square to uniform points of the sphere (area element
//! dA = dφ dz = 4π du dv) and a well-distributed pattern to a well-distributed one. u = 0 is the
//! +x meridian; v = 0 is the north pole (0, 0, 1).
use glam::{DVec2, DVec3};
use std::f64::consts::TAU;

/// The cylinder-wrap and radial projection of one point (see the module docs):
/// φ = 2πu, z = 1 − 2v, r = √(max(0, 1 − z²)), result (r cos φ, r sin φ, z).
///
/// r is evaluated as 2√(max(0, v(1 − v))), the same quantity (1 − z² = 4v(1 − v)) without the
/// cancellation of 1 − z² near the poles, so the result has unit length to within a few ulp.
/// Domain: v ∈ [0, 1] (pattern points); u may be any real (the map is 1-periodic in u). For
/// v outside [0, 1] the result is (0, 0, 1 − 2v), not a unit vector.
#[inline]
pub fn square_to_sphere(p: DVec2) -> DVec3 {
    let phi = TAU * p.x;
    let z = 1.0 - 2.0 * p.y;
    let r = 2.0 * (p.y * (1.0 - p.y)).max(0.0).sqrt();
    let (s, c) = phi.sin_cos();
    DVec3::new(r * c, r * s, z)
}

/// [`square_to_sphere`] applied to every point of a pattern, in order.
pub fn pattern_to_sphere(points: &[DVec2]) -> Vec<DVec3> {
    points.iter().map(|&p| square_to_sphere(p)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn landmarks_map_to_poles_and_axes() {
        let close = |a: DVec3, b: DVec3| (a - b).length() < 1e-15;
        assert!(close(square_to_sphere(DVec2::new(0.3, 0.0)), DVec3::Z));
        assert!(close(square_to_sphere(DVec2::new(0.7, 1.0)), -DVec3::Z));
        assert!(close(square_to_sphere(DVec2::new(0.0, 0.5)), DVec3::X));
        assert!(close(square_to_sphere(DVec2::new(0.25, 0.5)), DVec3::Y));
        assert!(close(square_to_sphere(DVec2::new(0.5, 0.5)), -DVec3::X));
    }

    #[test]
    fn near_pole_edge_has_unit_length() {
        // v a few ulps from 0 and 1, where 1 − z² would cancel.
        for v in [
            f64::MIN_POSITIVE,
            1e-300,
            1e-17,
            1e-9,
            1.0 - f64::EPSILON / 2.0,
        ] {
            let q = square_to_sphere(DVec2::new(0.1, v));
            assert!(
                (q.length() - 1.0).abs() < 1e-15,
                "v = {v}: |q| = {}",
                q.length()
            );
        }
    }
}
