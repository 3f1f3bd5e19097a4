//! The lecture's transform pairs ([`TransformPair`]) and their plots.

use super::signal1d::edge_value;
use super::{TheoremError, CURVE_POINTS, PAIR_SCALE_RANGE, PAIR_SHIFT_RANGE};
use crate::core::filter::special::{cos_pi, sin_pi, sinc};
use crate::core::params::{declare_params, Params};
use rustfft::num_complex::Complex64;
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// The lecture's transform pairs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum PairKind {
    /// Box of width 1 ↔ sinc(ω).
    Box,
    /// Tent of radius 1 ↔ sinc²(ω).
    Tent,
    /// e^{−πx²} ↔ e^{−πω²} (its own transform).
    Gaussian,
    /// Ш(x) = Σ_n δ(x − n) ↔ Ш(ω).
    Shah,
}

impl PairKind {
    /// Every pair.
    pub const ALL: [PairKind; 4] = [
        PairKind::Box,
        PairKind::Tent,
        PairKind::Gaussian,
        PairKind::Shah,
    ];

    /// Display name.
    pub fn name(self) -> &'static str {
        match self {
            PairKind::Box => "box <-> sinc",
            PairKind::Tent => "tent <-> sinc²",
            PairKind::Gaussian => "Gaussian <-> Gaussian",
            PairKind::Shah => "shah <-> shah",
        }
    }
}

/// A transform pair with scale a and shift s: p(x) = g(a(x − s)) ↔
/// P(ω) = e^{−2πiωs}·G(ω/a)/|a| (the lecture's expansion and delay properties).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct TransformPair {
    pub kind: PairKind,
    /// The scale a ≠ 0 (|a| in [0.05, 20]); this and `shift` have descriptors (below).
    pub scale: f64,
    /// The shift s (units), in [−10, 10].
    pub shift: f64,
}

impl Default for TransformPair {
    fn default() -> Self {
        TransformPair {
            kind: PairKind::Box,
            scale: 1.0,
            shift: 0.0,
        }
    }
}

declare_params! {
    impl TransformPair = "pair" {
        scale: scale(1.0, PAIR_SCALE_RANGE.0, PAIR_SCALE_RANGE.1, "scale a of p(x) = g(a(x − s)); a < 0 mirrors"),
        shift: float(0.0, PAIR_SHIFT_RANGE.0, PAIR_SHIFT_RANGE.1, "shift s of p(x) = g(a(x − s)) (units)"),
    }
}

impl TransformPair {
    /// Checks |a| ∈ [0.05, 20] and s ∈ [−10, 10] (the descriptors); the error names
    /// `pair.scale` or `pair.shift`.
    pub fn validate(&self) -> Result<(), TheoremError> {
        Ok(self.check_params()?)
    }

    /// g(x) of the unscaled pair (0 for the shah: see [`TransformPair::impulses`]).
    pub fn base(kind: PairKind, x: f64) -> f64 {
        match kind {
            PairKind::Box => edge_value(x.abs(), 0.5),
            PairKind::Tent => (1.0 - x.abs()).max(0.0),
            PairKind::Gaussian => (-PI * x * x).exp(),
            PairKind::Shah => 0.0,
        }
    }

    /// G(ω) of the unscaled pair (real and even).
    pub fn base_transform(kind: PairKind, omega: f64) -> f64 {
        match kind {
            PairKind::Box => sinc(omega),
            PairKind::Tent => {
                let s = sinc(omega);
                s * s
            }
            PairKind::Gaussian => (-PI * omega * omega).exp(),
            PairKind::Shah => 0.0,
        }
    }

    /// p(x) = g(a(x − s)).
    pub fn eval(&self, x: f64) -> f64 {
        Self::base(self.kind, self.scale * (x - self.shift))
    }

    /// P(ω) = e^{−2πiωs} G(ω/a)/|a|.
    pub fn transform(&self, omega: f64) -> Complex64 {
        let g = Self::base_transform(self.kind, omega / self.scale) / self.scale.abs();
        let phase = 2.0 * omega * self.shift;
        Complex64::new(cos_pi(phase), -sin_pi(phase)) * g
    }

    /// The shah's impulses in both domains within |x| ≤ `x_max`, |ω| ≤ `omega_max`:
    /// Ш(a(x − s)) = Σ_n δ(x − s − n/|a|)/|a| (positions, weights 1/|a|) and its transform
    /// e^{−2πiωs}Ш(ω/a)/|a| = Σ_m e^{−2πi m|a| s} δ(ω − m|a|) (positions, complex weights).
    pub fn impulses(&self, x_max: f64, omega_max: f64) -> (Vec<[f64; 2]>, Vec<(f64, Complex64)>) {
        let a = self.scale.abs();
        let s = self.shift;
        let lo = ((-x_max - s) * a).ceil() as i64;
        let hi = ((x_max - s) * a).floor() as i64;
        let spatial = (lo..=hi).map(|n| [s + n as f64 / a, 1.0 / a]).collect();
        let m_max = (omega_max / a).floor() as i64;
        let freq = (-m_max..=m_max)
            .map(|m| {
                let w = m as f64 * a;
                let phase = 2.0 * w * s;
                (w, Complex64::new(cos_pi(phase), -sin_pi(phase)))
            })
            .collect();
        (spatial, freq)
    }
}

/// The transform-pair plots.
#[derive(Debug, Clone, Default, Serialize)]
pub struct PairPlots {
    /// (x, p(x)) (empty for the shah).
    pub spatial: Vec<[f64; 2]>,
    /// (ω, Re P), (ω, Im P), (ω, |P|) (empty for the shah).
    pub re: Vec<[f64; 2]>,
    pub im: Vec<[f64; 2]>,
    pub magnitude: Vec<[f64; 2]>,
    /// Shah only: impulse positions and weights in x.
    pub impulses_x: Vec<[f64; 2]>,
    /// Shah only: impulse positions and complex weights in ω, as (ω, Re, Im).
    pub impulses_omega: Vec<[f64; 3]>,
    /// Plotted half-widths in x and ω.
    pub x_max: f64,
    pub omega_max: f64,
}

/// The transform-pair plots over x ∈ [−4, 4] and ω ∈ [−4, 4] (wider for wide or narrow pairs).
pub fn pair_plots(p: &TransformPair) -> PairPlots {
    let a = p.scale.abs();
    let x_max = (p.shift.abs() + 3.0 / a).clamp(2.0, 30.0);
    let omega_max = (3.0 * a).clamp(2.0, 60.0);
    let n = CURVE_POINTS;
    let mut out = PairPlots {
        x_max,
        omega_max,
        ..Default::default()
    };
    if p.kind == PairKind::Shah {
        let (ix, iw) = p.impulses(x_max, omega_max);
        out.impulses_x = ix;
        out.impulses_omega = iw.iter().map(|(w, c)| [*w, c.re, c.im]).collect();
        return out;
    }
    for i in 0..n {
        let x = -x_max + 2.0 * x_max * i as f64 / (n - 1) as f64;
        out.spatial.push([x, p.eval(x)]);
        let w = -omega_max + 2.0 * omega_max * i as f64 / (n - 1) as f64;
        let v = p.transform(w);
        out.re.push([w, v.re]);
        out.im.push([w, v.im]);
        out.magnitude.push([w, v.norm()]);
    }
    out
}
