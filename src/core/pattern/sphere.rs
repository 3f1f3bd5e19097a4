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

/// An orthographic view of the unit sphere from the direction at azimuth `yaw` (about +z,
/// from +x towards +y) and elevation `pitch` (towards +z), in radians.
///
/// The camera looks along −d, d = (cos θ cos ψ, cos θ sin ψ, sin θ) (ψ = yaw, θ = pitch);
/// the screen's right is r = (−sin ψ, cos ψ, 0) and its up u = d × r =
/// (−sin θ cos ψ, −sin θ sin ψ, cos θ), so +z points up at θ = 0 and the frame stays
/// orthonormal at the poles. A point q is drawn at (q·r, q·u) ∈ [−1, 1]² (y up) and is on the
/// near hemisphere when its depth q·d ≥ 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OrthoView {
    pub yaw: f64,
    pub pitch: f64,
}

impl OrthoView {
    /// The figures' front view: azimuth 30°, elevation 20° (the north pole's cap in sight).
    pub const FRONT: OrthoView = OrthoView {
        yaw: std::f64::consts::PI / 6.0,
        pitch: std::f64::consts::PI / 9.0,
    };

    /// The view from the opposite direction (−d): its near hemisphere is this view's far one.
    pub fn opposite(self) -> OrthoView {
        OrthoView {
            yaw: self.yaw + std::f64::consts::PI,
            pitch: -self.pitch,
        }
    }

    /// The view turned by `dyaw` and `dpitch` radians, the elevation kept in [−π/2, π/2] and
    /// the azimuth in [0, 2π).
    pub fn turned(self, dyaw: f64, dpitch: f64) -> OrthoView {
        use std::f64::consts::FRAC_PI_2;
        OrthoView {
            yaw: (self.yaw + dyaw).rem_euclid(TAU),
            pitch: (self.pitch + dpitch).clamp(-FRAC_PI_2, FRAC_PI_2),
        }
    }

    /// (d, r, u): the direction towards the camera and the screen's right and up.
    pub fn basis(self) -> (DVec3, DVec3, DVec3) {
        let (sy, cy) = self.yaw.sin_cos();
        let (sp, cp) = self.pitch.sin_cos();
        (
            DVec3::new(cp * cy, cp * sy, sp),
            DVec3::new(-sy, cy, 0.0),
            DVec3::new(-sp * cy, -sp * sy, cp),
        )
    }

    /// The screen position (q·r, q·u) of `q` (y up) and its depth q·d (≥ 0: near side).
    pub fn project(self, q: DVec3) -> (DVec2, f64) {
        let (d, r, u) = self.basis();
        (DVec2::new(q.dot(r), q.dot(u)), q.dot(d))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::FRAC_PI_2;

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
    fn ortho_view_basis_is_orthonormal_and_right_handed_even_at_the_poles() {
        for (yaw, pitch) in [
            (0.0, 0.0),
            (0.5, 0.3),
            (2.0, -1.2),
            (1.0, FRAC_PI_2),
            (4.0, -FRAC_PI_2),
        ] {
            let (d, r, u) = OrthoView { yaw, pitch }.basis();
            for (a, b) in [(d, r), (r, u), (u, d)] {
                assert!(a.dot(b).abs() < 1e-15, "{yaw} {pitch}");
            }
            for v in [d, r, u] {
                assert!((v.length() - 1.0).abs() < 1e-15);
            }
            // r × u = d: the camera looks at the screen's front.
            assert!((r.cross(u) - d).length() < 1e-15);
        }
    }

    #[test]
    fn ortho_view_projects_landmarks_in_closed_form() {
        // Seen from +x (yaw 0, pitch 0): +y is to the right, +z up, +x at the centre, nearest.
        let v = OrthoView {
            yaw: 0.0,
            pitch: 0.0,
        };
        let close = |a: DVec2, b: DVec2| (a - b).length() < 1e-15;
        let (s, depth) = v.project(DVec3::X);
        assert!(close(s, DVec2::ZERO) && (depth - 1.0).abs() < 1e-15);
        assert!(close(v.project(DVec3::Y).0, DVec2::X));
        assert!(close(v.project(DVec3::Z).0, DVec2::Y));
        assert!(v.project(-DVec3::X).1 < 0.0);
        // Any view: the screen position is the point less its depth along d, and the
        // opposite view sees the other hemisphere, mirrored left to right.
        let w = OrthoView::FRONT;
        let (d, _, _) = w.basis();
        let q = square_to_sphere(DVec2::new(0.37, 0.21));
        let (s, depth) = w.project(q);
        assert!((s.length_squared() + depth * depth - 1.0).abs() < 1e-14);
        assert!((depth - q.dot(d)).abs() < 1e-15);
        let (s2, depth2) = w.opposite().project(q);
        assert!((depth2 + depth).abs() < 1e-15);
        assert!((s2.x + s.x).abs() < 1e-14 && (s2.y - s.y).abs() < 1e-14);
    }

    #[test]
    fn turning_keeps_the_elevation_within_the_poles() {
        let v = OrthoView::FRONT.turned(10.0, 5.0);
        assert_eq!(v.pitch, FRAC_PI_2);
        assert!((0.0..TAU).contains(&v.yaw));
        assert_eq!(OrthoView::FRONT.turned(0.0, -9.0).pitch, -FRAC_PI_2);
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
