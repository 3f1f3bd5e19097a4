//! Gratings, step edges and slanted polygons: the signals of moiré, ringing and jaggies.
//!
//! Angles are in **degrees**, measured from the +x axis towards +y (y points down the image, so
//! positive angles turn clockwise on screen). The direction is n(θ) = (cos θ, sin θ), computed
//! with [`cos_pi`]/[`sin_pi`] of θ/180, so axis-aligned angles give exact 0 and ±1.

use super::exact::{cos_pi, rem2, sin_pi, DoubleDouble};
use super::SignalError;
use crate::core::params::{declare_params, Params};
use glam::DVec2;
use serde::{Deserialize, Serialize};

/// The image centre (½, ½), the pivot of step edges and polygons.
pub const CENTRE: DVec2 = DVec2::new(0.5, 0.5);

/// The unit direction n(θ) = (cos θ, sin θ) for θ in degrees.
#[inline]
pub fn direction(angle_deg: f64) -> DVec2 {
    let a = angle_deg / 180.0;
    DVec2::new(cos_pi(a), sin_pi(a))
}

declare_params! {
    /// A sinusoidal grating g(p) = ½(1 + sin(2π (f (n·p) + φ))), n = (cos θ, sin θ), phase φ in cycles.
    ///
    /// Its spectrum is a pair of impulses at ±f·n (cycles per unit): it aliases on a W×W grid as
    /// soon as f·max(|nₓ|, |n_y|) > W/2. n·p is formed in double-double and the phase is reduced
    /// exactly (as for the zone plate), so the phase error is ≤ 10⁻¹⁵ for every allowed f.
    Grating = "grating", "grating ½(1 + sin(2π(f n·p + φ))): a single frequency" {
        /// Frequency f in cycles per unit, in [0, 10⁶].
        frequency: float(16.0, 0.0, 1e6, "frequency f, cycles per unit"),
        /// Direction θ of the wave vector, degrees, in [−360, 360].
        angle: float(30.0, -360.0, 360.0, "direction θ of the wave vector, degrees"),
        /// Phase φ in cycles, in [−1, 1]: g(p) = ½(1 + sin(2π(f (n·p) + φ))). Default 0; a moving
        /// grating (scene motion) drifts through it.
        phase: float(0.0, -1.0, 1.0, "phase φ in cycles"),
    }
}

impl Grating {
    /// Largest frequency accepted (cycles per unit).
    pub const MAX_FREQUENCY: f64 = 1e6;

    /// Checks every parameter against its descriptor (see [`Params::check_params`]).
    pub fn validate(&self) -> Result<(), SignalError> {
        Ok(self.check_params()?)
    }

    /// 2 (f (n·p) + φ) modulo 2, in [−1, 1]: the phase in units of π (2φ is exact, and the sum
    /// is formed in double-double before the exact reduction).
    #[inline]
    pub fn phase_over_pi(&self, p: DVec2) -> f64 {
        let n = direction(self.angle);
        let proj = DoubleDouble::prod(p.x, n.x) + DoubleDouble::prod(p.y, n.y);
        rem2(proj.mul_f64(2.0 * self.frequency) + DoubleDouble::from_f64(2.0 * self.phase))
    }

    /// g(p) = ½(1 + sin(2π (f (n·p) + φ))) ∈ [0, 1].
    #[inline]
    pub fn eval(&self, p: DVec2) -> f64 {
        (0.5 * (1.0 + sin_pi(self.phase_over_pi(p)))).clamp(0.0, 1.0)
    }
}

declare_params! {
    /// A step edge: 1 on the side of the line n·(p − c) = offset that n points to, 0 on the other.
    ///
    /// s(p) = 1 if n·(p − (½,½)) ≥ offset, else 0, with n = (cos θ, sin θ). A slightly slanted edge
    /// (θ a few degrees off an axis) shows jaggies under point sampling and ringing under sinc-like
    /// reconstruction; its exact box-filtered image is the area coverage of each pixel
    /// (see `recon::reference`).
    StepEdge = "step-edge", "step edge: 1 where n·(p − c) ≥ offset: jaggies and ringing" {
        /// Direction θ of the edge normal, degrees, in [−360, 360].
        angle: float(10.0, -360.0, 360.0, "direction θ of the edge normal, degrees"),
        /// Signed distance of the edge from the image centre (½, ½) along n, in [−1, 1].
        offset: float(0.0, -1.0, 1.0, "signed distance of the edge from the image centre along n"),
    }
}

impl StepEdge {
    /// Checks every parameter against its descriptor (see [`Params::check_params`]).
    pub fn validate(&self) -> Result<(), SignalError> {
        Ok(self.check_params()?)
    }

    /// The half-plane {p : a·p ≥ b} as (a = n, b = offset + n·(½,½)).
    pub fn half_plane(&self) -> (DVec2, f64) {
        let n = direction(self.angle);
        (n, self.offset + n.dot(CENTRE))
    }

    /// s(p) ∈ {0, 1}.
    #[inline]
    pub fn eval(&self, p: DVec2) -> f64 {
        let (n, b) = self.half_plane();
        if n.dot(p) >= b {
            1.0
        } else {
            0.0
        }
    }
}

/// The canonical shapes of [`Polygon`] (convex, counter-clockwise in the canonical frame).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum PolygonShape {
    /// The square (±½, ±½): a rotated square shows jaggies on all four edges.
    #[default]
    Square,
    /// The sliver (−½, −1/16), (½, 0), (−½, 1/16): a thin slanted triangle whose tip breaks up
    /// into disconnected dots under point sampling.
    ThinTriangle,
}

impl crate::core::params::ChoiceParam for PolygonShape {
    const OPTIONS: &'static [&'static str] = &["square", "thin-triangle"];
    fn index(self) -> usize {
        self as usize
    }
    fn from_index(index: usize) -> Self {
        [PolygonShape::Square, PolygonShape::ThinTriangle][index]
    }
}

impl PolygonShape {
    /// Vertices in the canonical frame, counter-clockwise (in a y-up frame).
    pub fn canonical_vertices(self) -> &'static [DVec2] {
        const SQUARE: [DVec2; 4] = [
            DVec2::new(-0.5, -0.5),
            DVec2::new(0.5, -0.5),
            DVec2::new(0.5, 0.5),
            DVec2::new(-0.5, 0.5),
        ];
        const THIN: [DVec2; 3] = [
            DVec2::new(-0.5, -0.0625),
            DVec2::new(0.5, 0.0),
            DVec2::new(-0.5, 0.0625),
        ];
        match self {
            PolygonShape::Square => &SQUARE,
            PolygonShape::ThinTriangle => &THIN,
        }
    }
}

declare_params! {
    /// A filled convex polygon with slanted edges: 1 inside (boundary included), 0 outside.
    ///
    /// Vertices vₖ = (½,½) + size·R(θ)·qₖ where qₖ are the [`PolygonShape::canonical_vertices`] and
    /// R(θ) the rotation by θ degrees. Its exact box-filtered image is computed by clipping each
    /// pixel square against the polygon (Sutherland–Hodgman) and taking the shoelace area.
    Polygon = "polygon", "filled convex polygon with slanted edges: jaggies, thin features breaking up" {
        /// Which canonical shape.
        shape: choice(PolygonShape, "square | thin-triangle"),
        /// Rotation θ, degrees, in [−360, 360].
        angle: float(20.0, -360.0, 360.0, "rotation θ, degrees"),
        /// Scale of the canonical shape (the square's side), in (0, 2].
        size: positive(0.6, 2.0, "scale of the canonical shape (the square's side)"),
    }
}

impl Polygon {
    /// Checks every parameter against its descriptor (see [`Params::check_params`]).
    pub fn validate(&self) -> Result<(), SignalError> {
        Ok(self.check_params()?)
    }

    /// The vertices vₖ = (½,½) + size·R(θ)·qₖ in image coordinates (at most 4).
    pub fn vertices(&self) -> Vec<DVec2> {
        let r = direction(self.angle);
        self.shape
            .canonical_vertices()
            .iter()
            .map(|q| CENTRE + self.size * DVec2::new(r.x * q.x - r.y * q.y, r.y * q.x + r.x * q.y))
            .collect()
    }

    /// 1 if p lies inside or on the polygon, else 0: p is inside a counter-clockwise convex
    /// polygon iff (vₖ₊₁ − vₖ) × (p − vₖ) ≥ 0 for every edge.
    #[inline]
    pub fn eval(&self, p: DVec2) -> f64 {
        let r = direction(self.angle);
        let q = self.shape.canonical_vertices();
        let v = |k: usize| {
            let q = q[k % q.len()];
            CENTRE + self.size * DVec2::new(r.x * q.x - r.y * q.y, r.y * q.x + r.x * q.y)
        };
        let inside = (0..q.len()).all(|k| {
            let (a, b) = (v(k), v(k + 1));
            (b - a).perp_dot(p - a) >= 0.0
        });
        if inside {
            1.0
        } else {
            0.0
        }
    }
}
