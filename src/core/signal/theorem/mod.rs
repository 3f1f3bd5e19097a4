//! The 1D sampling theorem as plain data: the lecture's "General Process of Sampling and
//! Reconstruction" for signals whose Fourier transforms are known in closed form.
//!
//! ## Conventions
//! - x is in units (the signal's own length unit); frequencies ω are in **cycles per unit**;
//!   F(ω) = ∫ f(x) e^{−2πiωx} dx (the lecture's transform pair).
//! - Sampling at rate f_s (samples per unit, period T = 1/f_s) takes f(nT) for every integer n.
//!   The sampled signal Σ_n f(nT) δ(x − nT) has the spectrum
//!   F_s(ω) = Σ_n f(nT) e^{−2πiωnT} = f_s Σ_k F(ω − k f_s) (Poisson summation):
//!   replicas of F at every multiple of f_s. Plots and error terms use
//!   P(ω) = T·F_s(ω) = Σ_k F(ω − k f_s), in the units of F, and A(ω) = P(ω) − F(ω) =
//!   Σ_{k≠0} F(ω − k f_s), the replicas alone.
//! - Reconstruction with a kernel h of [`crate::core::filter`] (given in sample spacings)
//!   scaled to the sample spacing and **normalised to unit DC gain**:
//!   f_r(x) = Σ_n f(nT) h(x/T − n) / H(0), H(0) = ∫h. Its spectrum is
//!   F_r(ω) = T·H(ωT)/H(0)·F_s(ω) = G(ω)·P(ω) with the gain G(ω) = H(ωT)/H(0) (the ideal
//!   low-pass at cutoff ½ cycles per sample has G = 1 on |ω| < f_s/2, 0 beyond).
//!
//! ## Signals ([`Signal1D`])
//! | signal | f(x) | F(ω) | band-limited |
//! |---|---|---|---|
//! | `cosines` (bandwidth B) | ½cos 2π(B/4)x + 0.3 cos 2π(B/2)x + 0.2 cos 2πBx | lines ±B/4, ±B/2, ±B with ½ of each amplitude | to B |
//! | `sinc` (B) | sinc(2Bx) | 1/(2B) on \|ω\| < B (½ of it at \|ω\| = B) | to B |
//! | `sinc-squared` (B) | sinc²(Bx) | (1/B) max(0, 1 − \|ω\|/B) | to B |
//! | `box` (width w) | 1 on \|x\| < w/2, ½ at \|x\| = w/2 | w sinc(wω) | no |
//! | `tent` (radius w) | max(0, 1 − \|x\|/w) | w sinc²(wω) | no |
//! | `gaussian` (σ) | e^{−x²/2σ²} | σ√(2π) e^{−2π²σ²ω²} | no |
//! | `pulse-train` (period p, duty d) | 1 within d·p/2 of a multiple of p (½ on the edge) | lines c_m = d sinc(md) at m/p | no |
//!
//! with sinc(x) = sin(πx)/(πx). Cosines and the pulse train are periodic (power signals): their
//! spectra are lines and their error terms are **powers** (mean square per unit length,
//! Parseval for Fourier series: Σ|c|²); the others are finite-energy signals and their error
//! terms are **energies** (∫|·|² dω = ∫|·|² dx by Parseval).
//!
//! ## Error decomposition ([`AliasingErrors`], the lecture's "Summary: possible errors")
//! Over the band |ω| ≤ Ω = [`ERROR_BAND`]·f_s:
//! - **pre-aliasing** = ∫_{|ω|<f_s/2} |A(ω)|² dω: replica content folded into the Nyquist band
//!   by sampling, whatever the filter. It vanishes exactly when F = 0 for |ω| ≥ f_s/2 (a
//!   band-limited signal sampled above the Nyquist rate).
//! - **post-aliasing** = ∫_{|ω|>f_s/2} |G(ω)A(ω)|² dω: replica content the filter passes beyond
//!   Nyquist (it appears in f_r at frequencies the signal does not have).
//! - **smoothing** = ∫_{|ω|<f_s/2} |(1 − G(ω))F(ω)|² dω: pass-band attenuation.
//! - **lost** = ∫_{|ω|>f_s/2} |(1 − G(ω))F(ω)|² dω (signal content above Nyquist the
//!   reconstruction does not reproduce; beyond Ω counted as all of F's energy there).
//! - **total** = ∫ |F_r − F|² dω = ∫ |f_r − f|² dx.
//!
//! The terms are not additive in general (cross terms), but with the ideal low-pass total =
//! pre-aliasing + lost. Line spectra replace each integral by a sum over lines (lines on
//! |ω| = f_s/2 count as inside the Nyquist band, so a cosine at exactly f_s/2 pre-aliases).
//!
//! Integrals use the 16-point Gauss–Legendre rule ([`crate::core::filter::quad`]) on panels of
//! [0, Ω] (all spectra here are even) split at multiples of f_s/2, at the band edges and the
//! ideal cutoff, and no wider than half the shortest period of any integrand (1/support of f,
//! 1/σ, f_s/r of the filter); every term is summed in one pass over the same nodes. Tests
//! check the result against closed forms and against ∫|f_r − f|² dx computed in space.
//! [`AliasingErrors::tail_bound`] bounds what the band limit Ω leaves out.

pub mod cost;
mod errors;
mod pairs;
mod reconstruct;
mod settings;
mod signal1d;
mod view;

pub use errors::{aliasing_errors, merged_lines, AliasingErrors, MergedLine};
pub use pairs::{pair_plots, PairKind, PairPlots, TransformPair};
pub use reconstruct::{samples, Reconstructor};
pub use settings::TheoremSettings;
pub use signal1d::{
    Box1D, Cosines1D, Gaussian1D, PulseTrain1D, Signal1D, Sinc1D, SincSquared1D, SpectrumKind,
    Tent1D, COSINES,
};
pub use view::{compute_view, SpectrumPlots, TheoremView};

use crate::core::filter::FilterError;
use crate::core::params::ParamError;

/// Smallest accepted sampling rate (samples per unit).
pub const MIN_RATE: f64 = 0.05;
/// Largest accepted sampling rate (samples per unit).
pub const MAX_RATE: f64 = 1000.0;
/// Range of every signal parameter (bandwidths in cycles per unit, widths in units).
pub const PARAM_RANGE: (f64, f64) = (0.01, 100.0);
/// Range of the spatial half-window of the plots (units).
pub const EXTENT_RANGE: (f64, f64) = (0.1, 1000.0);
/// Most samples in the plotted window (2·extent·rate + 1).
pub const MAX_SAMPLES: usize = 1 << 16;
/// Most samples across the signal's width (2·support·rate for box and tent, 8σ·rate for the
/// Gaussian): bounds the cost of the error integrals (panels ∝ rate·width, sample-sum terms ∝
/// rate·width).
pub const MAX_WIDTH_SAMPLES: f64 = 256.0;
/// The error terms integrate over |ω| ≤ ERROR_BAND·f_s.
pub const ERROR_BAND: f64 = 8.0;
/// Harmonics |m| ≤ PULSE_HARMONICS of the pulse train are kept; the power of the rest is at
/// most 2/(π²·PULSE_HARMONICS) (|c_m| ≤ 1/(π|m|)).
pub const PULSE_HARMONICS: i64 = 1024;
/// Points of the spatial curves.
pub const CURVE_POINTS: usize = 1001;
/// Points of the spectrum curves.
pub const SPECTRUM_POINTS: usize = 1601;
/// Replicas k = −DISPLAY_REPLICAS..=DISPLAY_REPLICAS are returned for plotting.
pub const DISPLAY_REPLICAS: i64 = 3;
/// Most rows of the van der Corput table.
pub const MAX_VDC_ROWS: usize = 1024;
/// Range of |a| of the transform pairs.
pub const PAIR_SCALE_RANGE: (f64, f64) = (0.05, 20.0);
/// Range of the shift s of the transform pairs (units).
pub const PAIR_SHIFT_RANGE: (f64, f64) = (-10.0, 10.0);

/// Why a sampling-theorem computation was refused. Every variant names the field and what is
/// allowed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum TheoremError {
    /// A parameter is out of range or not finite.
    #[error("theorem.{field} = {value}: must be {allowed}")]
    InvalidParam {
        field: &'static str,
        value: String,
        allowed: String,
    },
    /// A parameter of the signal is out of range.
    #[error("theorem.{0}")]
    Param(#[from] ParamError),
    /// The reconstruction filter is invalid.
    #[error("theorem.filter: {0}")]
    Filter(#[from] FilterError),
}

fn check(field: &'static str, value: f64, lo: f64, hi: f64) -> Result<(), TheoremError> {
    if !(value.is_finite() && value >= lo && value <= hi) {
        return Err(TheoremError::InvalidParam {
            field,
            value: crate::core::params::fmt_num(value),
            allowed: format!(
                "a finite number in [{}, {}]",
                crate::core::params::fmt_num(lo),
                crate::core::params::fmt_num(hi)
            ),
        });
    }
    Ok(())
}
