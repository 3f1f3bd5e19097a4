//! The zone plate z(p) = ½(1 + sin(π K |p − c|²)).
//!
//! Local frequency: the phase φ(ρ) = π K ρ² has derivative 2π K ρ, i.e. K·ρ cycles per unit at
//! radius ρ = |p − c|. A W×W grid (Nyquist W/2 cycles per unit) therefore aliases beyond
//! ρ = W/(2K): with K = 256 and the lecture's 128×128 grid, beyond ρ = ¼.
//!
//! ## Phase stability
//! The phase is never formed in `f32`, nor as a rounded `f64` product. With t = K|p − c|² in
//! units of π:
//! 1. d = p − c is formed exactly as a double-double per axis ([`DoubleDouble::diff`]);
//! 2. |d|² = dₓ² + d_y² in double-double (relative error ≲ 10·2⁻¹⁰⁶);
//! 3. t = K·|d|² in double-double (relative error ≲ 13·2⁻¹⁰⁶ ≈ 1.6·10⁻³¹ in all);
//! 4. t is reduced modulo 2 exactly ([`rem2`], one final rounding ≤ 2⁻⁵¹) and
//!    sin(π t) is evaluated by [`sin_pi`] (absolute error ≤ 3·10⁻¹⁶).
//!
//! **Bound.** For exactly representable p and c (e.g. grid points i/W with W a power of two
//! and c = (½, ½)) the returned value differs from the exact ½(1 + sin(πK|p − c|²)) by at most
//! ½(π·1.6·10⁻³¹·K|p − c|² + π·2⁻⁵¹ + 3·10⁻¹⁶) ≤ 2·10⁻¹⁵ for K|p − c|² ≤ 10¹⁵ (K is limited to
//! |K| ≤ [`ZonePlate::MAX_K`] = 10¹², so on the unit square K|p − c|² ≤ 2·10¹² and the bound
//! holds everywhere). A naive `0.5 * (1.0 + (PI * k * d2).sin())` errs by up to
//! K|p − c|²·π·2⁻⁵² ≈ 7·10⁻⁸ at K|p − c|² = 10⁸. When p is not exactly representable (i/W with
//! W not a power of two) the input's own rounding (≤ 2⁻⁵³|p|) moves the phase by up to
//! 2πK|p − c|·2⁻⁵³·|p|√2; that is a property of the input, not of the evaluation.

use super::exact::{rem2, sin_pi, DoubleDouble};
use super::SignalError;
use crate::core::params::{declare_params, Params};
use glam::DVec2;

declare_params! {
    /// Zone plate parameters: z(p) = ½(1 + sin(π K |p − c|²)), c = (cx, cy).
    ZonePlate = "zone-plate", "zone plate ½(1 + sin(πK|p − c|²)): local frequency K·ρ at radius ρ" {
        /// K: the local frequency at radius ρ is K·ρ cycles per unit. |K| ≤ 10¹².
        k: float(256.0, -1e12, 1e12, "K: local frequency K·ρ cycles per unit at radius ρ"),
        /// Centre x (default ½), in [−1, 2].
        cx: float(0.5, -1.0, 2.0, "centre x"),
        /// Centre y (default ½), in [−1, 2].
        cy: float(0.5, -1.0, 2.0, "centre y (downwards)"),
    }
}

impl ZonePlate {
    /// Largest |K| accepted.
    pub const MAX_K: f64 = 1e12;

    /// Checks every parameter against its descriptor (see [`Params::check_params`]).
    pub fn validate(&self) -> Result<(), SignalError> {
        Ok(self.check_params()?)
    }

    /// The phase in units of π, reduced modulo 2 into [−1, 1]: K|p − c|² mod 2.
    #[inline]
    pub fn phase_over_pi(&self, p: DVec2) -> f64 {
        let dx = DoubleDouble::diff(p.x, self.cx);
        let dy = DoubleDouble::diff(p.y, self.cy);
        let d2 = dx * dx + dy * dy;
        rem2(d2.mul_f64(self.k))
    }

    /// z(p) = ½(1 + sin(π K |p − c|²)) ∈ [0, 1], phase reduced exactly (see module docs).
    #[inline]
    pub fn eval(&self, p: DVec2) -> f64 {
        (0.5 * (1.0 + sin_pi(self.phase_over_pi(p)))).clamp(0.0, 1.0)
    }

    /// Local frequency K·ρ (cycles per unit) at p, ρ = |p − c|.
    pub fn local_frequency(&self, p: DVec2) -> f64 {
        self.k.abs() * (p - DVec2::new(self.cx, self.cy)).length()
    }
}
