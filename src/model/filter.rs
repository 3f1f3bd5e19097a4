//! A filter's curves, its 2D response and its quality metrics, and the dB scale they are
//! shown on.

use super::ImageData;

/// A filter's curves, 2D response and quality metrics.
#[derive(Debug, Clone)]
pub struct ResponseData {
    pub kernel: Vec<[f64; 2]>,
    /// (ω, |H(ω)|/|H(0)|) for ω ∈ [0, omega_max]; (ω, |H(ω)|) when `normalised` is false.
    pub magnitude: Vec<[f64; 2]>,
    /// Whether `magnitude` was divided by |H(0)|: false for filters that block DC by design
    /// (band-pass, high-pass, the derivative cosc), whose H(0) is zero.
    pub normalised: bool,
    pub omega_max: f64,
    /// |H(ωx, ωy)| over [−omega_max, omega_max]².
    pub image: ImageData,
    pub metrics: ResponseMetrics,
}

/// The quality measures shown under a filter (see [`crate::core::filter::metrics`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ResponseMetrics {
    /// Pass-band loss below Nyquist.
    pub smoothing: f64,
    /// Fraction of the energy above Nyquist.
    pub post_aliasing: f64,
    /// max(overshoot, undershoot) of the step response.
    pub ringing: f64,
    /// Angular variation of |H₂|.
    pub anisotropy: f64,
}

impl ResponseMetrics {
    /// (label, value) in display order: smoothing, post-aliasing, ringing, anisotropy.
    pub fn iter(&self) -> impl Iterator<Item = (&'static str, f64)> {
        [
            ("smoothing", self.smoothing),
            ("post-aliasing", self.post_aliasing),
            ("ringing", self.ringing),
            ("anisotropy", self.anisotropy),
        ]
        .into_iter()
    }
}

/// The bottom of the dB scale of magnitude plots (the ideal low-pass is drawn down to it).
pub const DB_FLOOR: f64 = -120.0;

/// 20·log₁₀|m| in dB, never below [`DB_FLOOR`] (|m| is taken as at least 10⁻¹² before the
/// logarithm, so that 0 gives the floor rather than −∞).
pub fn amplitude_db(m: f64) -> f64 {
    (20.0 * m.abs().max(1e-12).log10()).max(DB_FLOOR)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn amplitude_db_is_20_log10_and_floored() {
        assert_eq!(amplitude_db(1.0), 0.0);
        assert!((amplitude_db(0.1) + 20.0).abs() < 1e-12);
        assert_eq!(amplitude_db(-0.1), amplitude_db(0.1));
        assert_eq!(amplitude_db(0.0), DB_FLOOR);
        assert_eq!(amplitude_db(1e-9), DB_FLOOR);
    }
}
