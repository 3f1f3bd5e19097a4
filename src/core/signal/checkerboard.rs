//! The lecture's "Checkerboard sequence by Tom Duff": an infinite checkerboard on a ground plane
//! seen in perspective, receding to the horizon.
//!
//! ## Projection (exact definition)
//! World axes: X to the right, Y forward (away from the viewer), Z up; the ground is Z = 0.
//! A pinhole camera sits at (0, 0, `height`) and looks along +Y; its image plane is vertical
//! (no pitch) at distance 1, and the image is 1 unit wide, so the horizontal field of view is
//! 2·atan(½) ≈ 53.13°. The horizon is shifted (a lens shift, which keeps verticals vertical)
//! to the image row y = `horizon`.
//!
//! An image point p = (x, y) ∈ [0,1)², with x to the right and y **downwards** (row 0 at the
//! top, as images are stored), has u = x − ½ and v = y − `horizon`. For v > 0 its ray meets
//! the ground at
//!
//! ```text
//!     X = u·height / v,   Y = height / v.
//! ```
//!
//! The board is rotated about the vertical axis by `tilt` degrees:
//! X' = X cos t + Y sin t, Y' = −X sin t + Y cos t, and with s = `checks` (checks per world
//! unit) the value is 1 (white) where ⌊s X'⌋ + ⌊s Y'⌋ is even and 0 (black) where it is odd.
//!
//! The sky (v ≤ 0, on or above the horizon) is ½, the mean of the board, so that the correctly
//! prefiltered image fades continuously into it; ground points farther than 2⁴⁰ checks (beyond
//! any sampling rate, where `f64` can no longer tell the checks apart) are also ½. Near the
//! horizon the check frequency grows without bound: every finite sampling rate aliases there.

use super::exact::{cos_pi, sin_pi};
use super::SignalError;
use crate::core::params::{declare_params, Params};
use glam::DVec2;

declare_params! {
    /// Perspective checkerboard parameters (see the module docs for the exact projection).
    Checkerboard = "checkerboard", "Duff's perspective checkerboard: moiré towards the horizon" {
        /// Checks per world unit on the ground, in (0, 1000].
        checks: positive(4.0, 1000.0, "checks per world unit on the ground"),
        /// Camera height above the ground in world units, in (0, 1000].
        height: positive(1.0, 1000.0, "camera height above the ground, world units"),
        /// Image row of the horizon, as a fraction of the image height from the top, in [0, 1].
        horizon: float(0.25, 0.0, 1.0, "image row of the horizon, fraction of the height from the top"),
        /// Rotation of the board about the vertical axis, degrees, in [−360, 360].
        tilt: float(20.0, -360.0, 360.0, "rotation of the board about the vertical axis, degrees"),
    }
}

/// Beyond this many checks from the origin the board is replaced by its mean ½.
const FAR_CHECKS: f64 = 1_099_511_627_776.0; // 2^40

impl Checkerboard {
    /// The value of the sky and of the unresolvable far field: the mean of the board.
    pub const SKY: f64 = 0.5;

    /// Checks every parameter against its descriptor (see [`Params::check_params`]).
    pub fn validate(&self) -> Result<(), SignalError> {
        Ok(self.check_params()?)
    }

    /// The ground point (X', Y') in check units (already rotated by `tilt` and scaled by
    /// `checks`) seen at image point p, or `None` for the sky (v ≤ 0).
    pub fn ground_checks(&self, p: DVec2) -> Option<DVec2> {
        self.prepare().ground_checks(p)
    }

    /// The board's value at image point p: 1 (white), 0 (black) or ½ (sky / far field).
    #[inline]
    pub fn eval(&self, p: DVec2) -> f64 {
        self.prepare().eval(p)
    }

    /// The board with sin and cos of its tilt computed once, for evaluating many points:
    /// [`PreparedCheckerboard::eval`] gives exactly the bits of [`Checkerboard::eval`].
    #[inline]
    pub fn prepare(&self) -> PreparedCheckerboard {
        let a = self.tilt / 180.0;
        PreparedCheckerboard {
            board: *self,
            sin: sin_pi(a),
            cos: cos_pi(a),
        }
    }
}

/// A [`Checkerboard`] with the sine and cosine of its tilt precomputed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PreparedCheckerboard {
    board: Checkerboard,
    sin: f64,
    cos: f64,
}

impl PreparedCheckerboard {
    /// See [`Checkerboard::ground_checks`].
    #[inline]
    pub fn ground_checks(&self, p: DVec2) -> Option<DVec2> {
        let b = &self.board;
        let v = p.y - b.horizon;
        if v.is_nan() || v <= 0.0 {
            return None;
        }
        let u = p.x - 0.5;
        let t = b.height / v;
        let x = u * t;
        let y = t;
        let (s, c) = (self.sin, self.cos);
        Some(DVec2::new(
            b.checks * (x * c + y * s),
            b.checks * (-x * s + y * c),
        ))
    }

    /// See [`Checkerboard::eval`].
    #[inline]
    pub fn eval(&self, p: DVec2) -> f64 {
        match self.ground_checks(p) {
            None => Checkerboard::SKY,
            Some(g) => {
                if !(g.x.abs() < FAR_CHECKS && g.y.abs() < FAR_CHECKS) {
                    return Checkerboard::SKY;
                }
                // Both floors are exact integers below 2^40 in magnitude.
                let parity = (g.x.floor() as i64 + g.y.floor() as i64).rem_euclid(2);
                if parity == 0 {
                    1.0
                } else {
                    0.0
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn prepared_board_gives_the_plain_boards_bits() {
        // Reference: the plain eval (sin/cos of the tilt per point), on a fixed grid of
        // points incl. the horizon row, the sky and the far field, for several boards.
        for (checks, height, horizon, tilt) in [
            (4.0, 1.0, 0.25, 20.0),
            (0.3, 7.0, 0.0, -135.0),
            (1000.0, 0.01, 0.9, 360.0),
        ] {
            let b = Checkerboard {
                checks,
                height,
                horizon,
                tilt,
            };
            let p = b.prepare();
            for j in 0..=200 {
                for i in 0..=50 {
                    let q = DVec2::new(i as f64 / 50.0, j as f64 / 200.0 + 1e-9 * i as f64);
                    assert_eq!(p.eval(q).to_bits(), b.eval(q).to_bits(), "{q:?}");
                    assert_eq!(p.ground_checks(q), b.ground_checks(q));
                }
            }
        }
    }

    #[test]
    fn sky_above_horizon_is_mean() {
        let c = Checkerboard::default();
        assert_eq!(c.eval(DVec2::new(0.3, 0.1)), 0.5);
        assert_eq!(c.eval(DVec2::new(0.3, c.horizon)), 0.5);
    }

    #[test]
    fn ground_point_matches_pinhole_projection() {
        // Project a known ground point back into the image and read it again.
        let c = Checkerboard {
            checks: 1.0,
            height: 2.0,
            horizon: 0.3,
            tilt: 0.0,
        };
        // Ground point (X, Y) = (1, 4): v = height/Y = 0.5, u = X·v/height = 0.25.
        let p = DVec2::new(0.5 + 0.25, 0.3 + 0.5);
        let g = c.ground_checks(p).unwrap();
        assert!(
            (g.x - 1.0).abs() < 1e-15 && (g.y - 4.0).abs() < 1e-15,
            "{g}"
        );
    }

    #[test]
    fn adjacent_checks_alternate() {
        let c = Checkerboard {
            checks: 1.0,
            height: 1.0,
            horizon: 0.0,
            tilt: 0.0,
        };
        // Along the row y = 0.5 (Y = 2), X = 2u; checks X ∈ [0,1) and [−1,0) differ.
        let a = c.eval(DVec2::new(0.5 + 0.25, 0.5)); // X = 0.5 → ⌊0.5⌋ + ⌊2⌋ = 2, white
        let b = c.eval(DVec2::new(0.5 - 0.25, 0.5)); // X = −0.5 → −1 + 2 = 1, black
        assert_eq!((a, b), (1.0, 0.0));
    }
}
