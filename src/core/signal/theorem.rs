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

use crate::core::filter::special::{cos_pi, sin_pi, sinc};
use crate::core::filter::{quad, Filter, FilterError, Parity, ResponseEval};
use crate::core::params::{ParamError, ParamKind, ParamSpec, ParamValue, Params};
use crate::core::pattern::radical_inverse::{radical_inverse_table, RadicalInverseRow};
use rustfft::num_complex::Complex64;
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

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

/// A 1D test signal with a closed-form Fourier transform (see the module table).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "kebab-case")]
pub enum Signal1D {
    /// ½cos 2π(B/4)x + 0.3cos 2π(B/2)x + 0.2cos 2πBx: band-limited to B.
    Cosines { bandwidth: f64 },
    /// sinc(2Bx): F = 1/(2B) on |ω| < B.
    Sinc { bandwidth: f64 },
    /// sinc²(Bx): F = (1/B)(1 − |ω|/B)₊.
    SincSquared { bandwidth: f64 },
    /// The box of width w: F = w sinc(wω).
    Box { width: f64 },
    /// The tent of radius w: F = w sinc²(wω).
    Tent { radius: f64 },
    /// e^{−x²/2σ²}: F = σ√(2π)e^{−2π²σ²ω²}.
    Gaussian { sigma: f64 },
    /// Pulses of width d·p every p: Fourier series c_m = d sinc(md).
    PulseTrain { period: f64, duty: f64 },
}

fn param_spec(name: &'static str, doc: &'static str, default: f64, range: (f64, f64)) -> ParamSpec {
    ParamSpec {
        name,
        doc,
        kind: ParamKind::Float {
            default,
            min: range.0,
            max: range.1,
            min_exclusive: false,
            max_exclusive: false,
        },
    }
}

/// The theorem's 1D signals share the one parameter mechanism; errors start with `signal.`.
impl Params for Signal1D {
    fn owner(&self) -> &'static str {
        "signal"
    }

    fn specs(&self) -> Vec<ParamSpec> {
        let r = PARAM_RANGE;
        match self {
            Signal1D::Cosines { .. } | Signal1D::Sinc { .. } | Signal1D::SincSquared { .. } => {
                vec![param_spec(
                    "bandwidth",
                    "bandwidth B, cycles per unit",
                    1.5,
                    r,
                )]
            }
            Signal1D::Box { .. } => vec![param_spec("width", "width w, units", 1.0, r)],
            Signal1D::Tent { .. } => vec![param_spec("radius", "radius w, units", 1.0, r)],
            Signal1D::Gaussian { .. } => {
                vec![param_spec("sigma", "standard deviation σ, units", 0.3, r)]
            }
            Signal1D::PulseTrain { .. } => vec![
                param_spec("period", "period p, units", 2.0, r),
                param_spec("duty", "duty cycle d (pulse width d·p)", 0.5, (0.01, 0.99)),
            ],
        }
    }

    fn get(&self, key: &str) -> Option<ParamValue> {
        let v = match (*self, key) {
            (
                Signal1D::Cosines { bandwidth }
                | Signal1D::Sinc { bandwidth }
                | Signal1D::SincSquared { bandwidth },
                "bandwidth",
            ) => bandwidth,
            (Signal1D::Box { width }, "width") => width,
            (Signal1D::Tent { radius }, "radius") => radius,
            (Signal1D::Gaussian { sigma }, "sigma") => sigma,
            (Signal1D::PulseTrain { period, .. }, "period") => period,
            (Signal1D::PulseTrain { duty, .. }, "duty") => duty,
            _ => return None,
        };
        Some(ParamValue::Float(v))
    }

    fn put(&mut self, key: &str, value: ParamValue) {
        let ParamValue::Float(value) = value else {
            return;
        };
        match (self, key) {
            (
                Signal1D::Cosines { bandwidth }
                | Signal1D::Sinc { bandwidth }
                | Signal1D::SincSquared { bandwidth },
                "bandwidth",
            ) => *bandwidth = value,
            (Signal1D::Box { width }, "width") => *width = value,
            (Signal1D::Tent { radius }, "radius") => *radius = value,
            (Signal1D::Gaussian { sigma }, "sigma") => *sigma = value,
            (Signal1D::PulseTrain { period, .. }, "period") => *period = value,
            (Signal1D::PulseTrain { duty, .. }, "duty") => *duty = value,
            _ => {}
        }
    }
}

/// Amplitudes and frequency fractions (of B) of [`Signal1D::Cosines`].
pub const COSINES: [(f64, f64); 3] = [(0.5, 0.25), (0.3, 0.5), (0.2, 1.0)];

/// How a signal's spectrum is represented.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SpectrumKind {
    /// F is a function (finite-energy signal).
    Continuous,
    /// F is a sum of Dirac lines (periodic signal).
    Lines,
}

impl Default for Signal1D {
    fn default() -> Self {
        Signal1D::Tent { radius: 1.0 }
    }
}

impl Signal1D {
    /// Every signal with its default parameters.
    pub fn all() -> Vec<Signal1D> {
        vec![
            Signal1D::Cosines { bandwidth: 1.5 },
            Signal1D::Sinc { bandwidth: 1.5 },
            Signal1D::SincSquared { bandwidth: 1.5 },
            Signal1D::Box { width: 1.0 },
            Signal1D::Tent { radius: 1.0 },
            Signal1D::Gaussian { sigma: 0.3 },
            Signal1D::PulseTrain {
                period: 2.0,
                duty: 0.5,
            },
        ]
    }

    /// Name in scene files.
    pub fn name(&self) -> &'static str {
        match self {
            Signal1D::Cosines { .. } => "cosines",
            Signal1D::Sinc { .. } => "sinc",
            Signal1D::SincSquared { .. } => "sinc-squared",
            Signal1D::Box { .. } => "box",
            Signal1D::Tent { .. } => "tent",
            Signal1D::Gaussian { .. } => "gaussian",
            Signal1D::PulseTrain { .. } => "pulse-train",
        }
    }

    /// Checks every parameter; the error names `signal.<param>`.
    pub fn validate(&self) -> Result<(), TheoremError> {
        Ok(self.check_params()?)
    }

    /// Continuous spectrum or lines.
    pub fn spectrum_kind(&self) -> SpectrumKind {
        match self {
            Signal1D::Cosines { .. } | Signal1D::PulseTrain { .. } => SpectrumKind::Lines,
            _ => SpectrumKind::Continuous,
        }
    }

    /// The highest frequency of F (cycles per unit), `None` if not band-limited.
    pub fn bandwidth(&self) -> Option<f64> {
        match *self {
            Signal1D::Cosines { bandwidth }
            | Signal1D::Sinc { bandwidth }
            | Signal1D::SincSquared { bandwidth } => Some(bandwidth),
            _ => None,
        }
    }

    /// f(x).
    pub fn eval(&self, x: f64) -> f64 {
        match *self {
            Signal1D::Cosines { bandwidth } => COSINES
                .iter()
                .map(|&(a, r)| a * cos_pi(2.0 * r * bandwidth * x))
                .sum(),
            Signal1D::Sinc { bandwidth } => sinc(2.0 * bandwidth * x),
            Signal1D::SincSquared { bandwidth } => {
                let s = sinc(bandwidth * x);
                s * s
            }
            Signal1D::Box { width } => edge_value(x.abs(), 0.5 * width),
            Signal1D::Tent { radius } => (1.0 - x.abs() / radius).max(0.0),
            Signal1D::Gaussian { sigma } => (-x * x / (2.0 * sigma * sigma)).exp(),
            Signal1D::PulseTrain { period, duty } => {
                let t = x / period;
                let d = (t - t.round()).abs();
                edge_value(d, 0.5 * duty)
            }
        }
    }

    /// F(ω) for continuous spectra (real: every signal here is even); 0 for line spectra.
    pub fn transform(&self, omega: f64) -> f64 {
        match *self {
            Signal1D::Sinc { bandwidth } => edge_value(omega.abs(), bandwidth) / (2.0 * bandwidth),
            Signal1D::SincSquared { bandwidth } => {
                (1.0 - omega.abs() / bandwidth).max(0.0) / bandwidth
            }
            Signal1D::Box { width } => width * sinc(width * omega),
            Signal1D::Tent { radius } => {
                let s = sinc(radius * omega);
                radius * s * s
            }
            Signal1D::Gaussian { sigma } => {
                sigma * (2.0 * PI).sqrt() * (-2.0 * PI * PI * sigma * sigma * omega * omega).exp()
            }
            Signal1D::Cosines { .. } | Signal1D::PulseTrain { .. } => 0.0,
        }
    }

    /// The spectral lines (ω, c) of a periodic signal (f = Σ c e^{2πiωx}; empty for continuous
    /// spectra) and a bound on the power of the lines left out (pulse train: |m| >
    /// [`PULSE_HARMONICS`]).
    pub fn lines(&self) -> (Vec<(f64, f64)>, f64) {
        match *self {
            Signal1D::Cosines { bandwidth } => {
                let mut v = Vec::new();
                for &(a, r) in &COSINES {
                    v.push((-r * bandwidth, 0.5 * a));
                    v.push((r * bandwidth, 0.5 * a));
                }
                (v, 0.0)
            }
            Signal1D::PulseTrain { period, duty } => {
                let v = (-PULSE_HARMONICS..=PULSE_HARMONICS)
                    .map(|m| (m as f64 / period, duty * sinc(m as f64 * duty)))
                    .collect();
                (v, 2.0 / (PI * PI * PULSE_HARMONICS as f64))
            }
            _ => (Vec::new(), 0.0),
        }
    }

    /// ∫|f|² dx (continuous spectra) or the mean power lim (1/2L)∫_{−L}^{L}|f|² dx (lines), in
    /// closed form: box w, tent 2w/3, Gaussian σ√π, sinc 1/(2B), sinc² 2/(3B), cosines Σa²/2,
    /// pulse train d.
    pub fn energy(&self) -> f64 {
        match *self {
            Signal1D::Cosines { .. } => COSINES.iter().map(|&(a, _)| 0.5 * a * a).sum(),
            Signal1D::Sinc { bandwidth } => 0.5 / bandwidth,
            Signal1D::SincSquared { bandwidth } => 2.0 / (3.0 * bandwidth),
            Signal1D::Box { width } => width,
            Signal1D::Tent { radius } => 2.0 * radius / 3.0,
            Signal1D::Gaussian { sigma } => sigma * PI.sqrt(),
            Signal1D::PulseTrain { duty, .. } => duty,
        }
    }

    /// Half-width of the support of f (`None` when unbounded).
    pub fn support(&self) -> Option<f64> {
        match *self {
            Signal1D::Box { width } => Some(0.5 * width),
            Signal1D::Tent { radius } => Some(radius),
            _ => None,
        }
    }

    /// The width that sets the error integrals' cost: 2·support (box, tent), 8σ (Gaussian).
    pub fn cost_width(&self) -> Option<f64> {
        match *self {
            Signal1D::Gaussian { sigma } => Some(8.0 * sigma),
            _ => self.support().map(|s| 2.0 * s),
        }
    }

    /// |F| beyond this frequency is below 10⁻²⁰·F(0) (Gaussian only).
    fn gaussian_cut(sigma: f64) -> f64 {
        (20.0 * std::f64::consts::LN_10 / (2.0 * PI * PI * sigma * sigma)).sqrt()
    }

    /// P(ω) = T·F_s(ω) = Σ_k F(ω − k f_s) and A(ω) = Σ_{k≠0} F(ω − k f_s), evaluated exactly:
    /// band-limited signals sum the finitely many replicas that reach ω; compactly supported
    /// signals use the finite sample sum T Σ_n f(nT) cos(2πωnT) (Poisson summation, with the
    /// mid-value ½ at the box's jumps); the Gaussian sums replicas until they fall below
    /// 10⁻²⁰·F(0) (F decreases in |ω| and F(c + jf_s)/F(c) ≤ q^j, q = e^{−2π²σ²f_s²}, so the
    /// rest is at most 2·10⁻²⁰·F(0)/(1 − q)).
    /// Continuous spectra only ((0, 0) for lines).
    pub fn periodized(&self, omega: f64, rate: f64) -> (f64, f64) {
        let replicas = |reach: f64| {
            let lo = ((omega - reach) / rate).ceil() as i64;
            let hi = ((omega + reach) / rate).floor() as i64;
            let mut a = 0.0;
            for k in lo..=hi {
                if k != 0 {
                    a += self.transform(omega - k as f64 * rate);
                }
            }
            let f = self.transform(omega);
            (f + a, a)
        };
        match *self {
            Signal1D::Sinc { bandwidth } | Signal1D::SincSquared { bandwidth } => {
                replicas(bandwidth)
            }
            Signal1D::Gaussian { sigma } => replicas(Self::gaussian_cut(sigma)),
            Signal1D::Box { .. } | Signal1D::Tent { .. } => {
                let t = 1.0 / rate;
                let n_max = (self.support().unwrap_or(0.0) * rate).floor() as i64;
                let mut p = self.eval(0.0);
                for n in 1..=n_max {
                    p += 2.0 * self.eval(n as f64 * t) * cos_pi(2.0 * omega * n as f64 * t);
                }
                p *= t;
                (p, p - self.transform(omega))
            }
            Signal1D::Cosines { .. } | Signal1D::PulseTrain { .. } => (0.0, 0.0),
        }
    }

    /// The replica k as plotted: F(ω − k f_s) (the k-th term of P = T·F_s).
    pub fn replica(&self, k: i64, omega: f64, rate: f64) -> f64 {
        self.transform(omega - k as f64 * rate)
    }

    /// An upper bound on |P(ω)| over all ω (continuous spectra).
    fn periodized_bound(&self, rate: f64) -> f64 {
        match *self {
            Signal1D::Sinc { bandwidth } | Signal1D::SincSquared { bandwidth } => {
                self.transform(0.0) * (2.0 * bandwidth / rate + 1.0)
            }
            Signal1D::Gaussian { .. } => {
                // F is even and decreasing in |ω|: on each side of the nearest replica the
                // terms are at most (1/f_s)∫F, so Σ_k F(ω − k f_s) ≤ 2F(0) + f(0)/f_s.
                2.0 * self.transform(0.0) + 1.0 / rate
            }
            _ => {
                let t = 1.0 / rate;
                let n_max = (self.support().unwrap_or(0.0) * rate).floor() as i64;
                t * (self.eval(0.0).abs()
                    + 2.0
                        * (1..=n_max)
                            .map(|n| self.eval(n as f64 * t).abs())
                            .sum::<f64>())
            }
        }
    }
}

/// 1 below the edge e, ½ on it, 0 beyond (the mid-value at a jump, as Fourier inversion gives).
fn edge_value(d: f64, e: f64) -> f64 {
    if d < e {
        1.0
    } else if d == e {
        0.5
    } else {
        0.0
    }
}

/// A reconstruction filter prepared for one sampling rate: f_r(x) = Σ_n f(nT) h(x/T − n)/H(0)
/// and G(ω) = H(ωT)/H(0).
#[derive(Debug, Clone)]
pub struct Reconstructor {
    filter: Filter,
    rate: f64,
    h0: f64,
    eval: ResponseEval,
}

impl Reconstructor {
    /// Checks the filter (valid parameters, even, passes DC: not `cosc`, band- or high-pass) and
    /// the rate; `omega_max` (cycles per unit) is the largest |ω| at which G will be evaluated.
    pub fn new(filter: Filter, rate: f64, omega_max: f64) -> Result<Self, TheoremError> {
        check("rate", rate, MIN_RATE, MAX_RATE)?;
        filter.validate()?;
        let h0 = match filter.dc_normaliser() {
            Some(h0) if filter.parity() == Parity::Even && !filter.is_derivative() => h0.re,
            _ => {
                return Err(TheoremError::InvalidParam {
                    field: "filter",
                    value: filter.name().to_string(),
                    allowed: "an even filter that passes DC (not cosc, band-pass or high-pass)"
                        .into(),
                })
            }
        };
        let omega_samples = (omega_max / rate).clamp(1e-3, crate::core::filter::MAX_OMEGA);
        Ok(Reconstructor {
            filter,
            rate,
            h0,
            eval: filter.response_eval(omega_samples),
        })
    }

    /// G(ω) = H(ω/f_s)/H(0), ω in cycles per unit (real: the filter is even).
    pub fn gain(&self, omega: f64) -> f64 {
        self.eval.eval(omega / self.rate).re / self.h0
    }

    /// f_r(x) = Σ_n f(nT) h(x/T − n)/H(0) over the n with |x/T − n| ≤ r.
    pub fn reconstruct(&self, signal: &Signal1D, x: f64) -> f64 {
        let u = x * self.rate;
        let r = self.filter.radius();
        let lo = (u - r).ceil() as i64;
        let hi = (u + r).floor() as i64;
        let t = 1.0 / self.rate;
        let mut s = 0.0;
        for n in lo..=hi {
            s += signal.eval(n as f64 * t) * self.filter.eval(u - n as f64);
        }
        s / self.h0
    }

    /// ∫_{|ω|>Ω} |G(ω)|² dω: 0 for ideal filters whose cutoff lies below Ω; otherwise
    /// (Parseval) f_s∫h²/H(0)² − ∫_{|ω|<Ω}|G|², with `inside` = ∫_{|ω|<Ω}|G|² (clamped at 0).
    fn gain_tail(&self, omega_band: f64, inside: f64) -> f64 {
        if let Some(v) = self.filter.response_ideal(omega_band / self.rate) {
            if v.norm() == 0.0 {
                return 0.0;
            }
        }
        let f = self.filter;
        let h2 = quad::adaptive(
            &mut |x| {
                let v = f.eval(x);
                v * v
            },
            &f.quad_breaks(),
            0.5,
            1e-12,
            1e-300,
        )
        .value
            * 2.0;
        (self.rate * h2 / (self.h0 * self.h0) - inside).max(0.0)
    }
}

/// The lecture's error terms for one signal, rate and filter (see the module docs). Energies
/// (∫|·|² dω) for continuous spectra, powers (Σ|c|²) for line spectra.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct AliasingErrors {
    /// ∫|f|² (or the mean power of a periodic signal).
    pub signal_energy: f64,
    /// Replica content folded into |ω| < f_s/2.
    pub pre_aliasing: f64,
    /// Replica content passed by the filter beyond f_s/2.
    pub post_aliasing: f64,
    /// Pass-band attenuation ∫_{|ω|<f_s/2}|(1 − G)F|².
    pub smoothing: f64,
    /// Signal content above f_s/2 not reproduced: ∫_{|ω|>f_s/2}|(1 − G)F|².
    pub lost: f64,
    /// ∫|F_r − F|² = ∫|f_r − f|².
    pub total: f64,
    /// The band Ω (cycles per unit) of the integrals.
    pub band: f64,
    /// Whether the terms are powers (line spectra) rather than energies.
    pub periodic: bool,
    /// Bound on what the band limit leaves out of `post_aliasing` and `total` (continuous
    /// spectra: sup|A|²·∫_{|ω|>Ω}|G|², resp. sup|P|²∫_{|ω|>Ω}|G|² + 2sup|P|(∫_{|ω|>Ω}|G|²
    /// ∫_{|ω|>Ω}|F|²)^½, the larger of the two), or on the power of the harmonics left out
    /// (pulse train).
    pub tail_bound: f64,
}

impl AliasingErrors {
    /// A term relative to the signal's energy (power).
    pub fn relative(&self, term: f64) -> f64 {
        term / self.signal_energy
    }
}

/// Computes [`AliasingErrors`] for `signal` sampled at `rate` and reconstructed with `filter`.
pub fn aliasing_errors(
    signal: &Signal1D,
    rate: f64,
    filter: Filter,
) -> Result<AliasingErrors, TheoremError> {
    signal.validate()?;
    check("rate", rate, MIN_RATE, MAX_RATE)?;
    check_width_samples(signal, rate)?;
    let band = ERROR_BAND * rate;
    let rec = Reconstructor::new(filter, rate, band)?;
    match signal.spectrum_kind() {
        SpectrumKind::Continuous => Ok(continuous_errors(signal, rate, &rec, band)),
        SpectrumKind::Lines => Ok(line_errors(signal, rate, &rec, band)),
    }
}

/// Checks rate × [`Signal1D::cost_width`] ≤ [`MAX_WIDTH_SAMPLES`].
fn check_width_samples(signal: &Signal1D, rate: f64) -> Result<(), TheoremError> {
    if let Some(w) = signal.cost_width() {
        if w * rate > MAX_WIDTH_SAMPLES {
            return Err(TheoremError::InvalidParam {
                field: "rate",
                value: crate::core::params::fmt_num(rate),
                allowed: format!(
                    "at most {MAX_WIDTH_SAMPLES} samples across the {} ({} units wide): rate ≤ {}",
                    signal.name(),
                    crate::core::params::fmt_num(w),
                    crate::core::params::fmt_num(MAX_WIDTH_SAMPLES / w)
                ),
            });
        }
    }
    Ok(())
}

fn continuous_errors(
    signal: &Signal1D,
    rate: f64,
    rec: &Reconstructor,
    band: f64,
) -> AliasingErrors {
    let nyq = 0.5 * rate;
    // Kinks and jumps: multiples of f_s/2 (replica edges of band-limited spectra are
    // B + k f_s, added below), the band edge, the filter's cutoff for ideal filters.
    let mut breaks: Vec<f64> = (0..=(2.0 * ERROR_BAND) as usize)
        .map(|i| i as f64 * nyq)
        .collect();
    if let Some(b) = signal.bandwidth() {
        let kmax = (band / rate).ceil() as i64 + 1;
        for k in -kmax..=kmax {
            let e = (b + k as f64 * rate).abs();
            if e < band {
                breaks.push(e);
            }
        }
    }
    if let Filter::LowPass(l) = rec.filter {
        if l.cutoff * rate < band {
            breaks.push(l.cutoff * rate);
        }
    }
    breaks.sort_by(|a, b| a.total_cmp(b));
    breaks.dedup_by(|a, b| (*a - *b).abs() <= 1e-12 * band);
    // Panels no wider than half the shortest period of the integrands: of F and of the sample
    // sum (1/support), of G (f_s/r), of the Gaussian's F (1/σ), and f_s/4. The 16-point rule
    // integrates a period of a cosine to ≈ 10⁻²⁹ of the panel width (see `quad`).
    let mut width = rate / 4.0;
    if let Some(s) = signal.support() {
        width = width.min(0.5 / s);
    }
    if let Signal1D::Gaussian { sigma } = *signal {
        width = width.min(0.5 / sigma);
    }
    width = width.min(0.5 * rate / rec.filter.radius().max(1e-3));
    let rule = quad::gl16();
    // One pass: every integrand at every node. Sums over [0, Ω]; spectra are even (× 2 below).
    let (mut pre, mut post, mut smoothing, mut lost, mut total, mut f2, mut g2) =
        (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    for (a, b) in quad::panels(&breaks, width) {
        let c = 0.5 * (a + b);
        let h = 0.5 * (b - a);
        let inside = c < nyq;
        for (x, w) in rule.nodes.iter().zip(&rule.weights) {
            let omega = c + h * x;
            let wt = w * h;
            let (p, al) = signal.periodized(omega, rate);
            let f = signal.transform(omega);
            let g = rec.gain(omega);
            let s = (1.0 - g) * f;
            if inside {
                pre += wt * al * al;
                smoothing += wt * s * s;
            } else {
                post += wt * g * al * g * al;
                lost += wt * s * s;
            }
            let e = g * p - f;
            total += wt * e * e;
            f2 += wt * f * f;
            g2 += wt * g * g;
        }
    }
    let energy = signal.energy();
    let beyond = (energy - 2.0 * f2).max(0.0);
    let sup_a = signal.periodized_bound(rate) + signal.transform(0.0).abs();
    let g_tail = rec.gain_tail(band, 2.0 * g2);
    // Left out beyond Ω: post-aliasing ∫|GA|² ≤ sup|A|²·∫|G|²; the total's ∫(|GP − F|² − |F|²)
    // ≤ sup|P|²∫|G|² + 2 sup|P|·(∫|G|²·∫|F|²)^½ (Cauchy–Schwarz).
    let sup_p = signal.periodized_bound(rate);
    let tail_bound = (sup_a * sup_a * g_tail)
        .max(sup_p * sup_p * g_tail + 2.0 * sup_p * (g_tail * beyond).sqrt());
    AliasingErrors {
        signal_energy: energy,
        pre_aliasing: 2.0 * pre,
        post_aliasing: 2.0 * post,
        smoothing: 2.0 * smoothing,
        lost: 2.0 * lost + beyond,
        total: 2.0 * total + beyond,
        band,
        periodic: false,
        tail_bound,
    }
}

/// A line of the sampled spectrum P = T·F_s after merging coincident replicas: frequency, the
/// sum `total` of every replica's amplitude there, and the original's share `original` (k = 0).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct MergedLine {
    pub omega: f64,
    pub total: f64,
    pub original: f64,
}

/// The lines of P = T·F_s within |ω| ≤ `band`: every (ν + k f_s, c) for the signal's lines
/// (ν, c), coincident ones (|Δω| ≤ 10⁻⁹·f_s) merged, sorted by ω.
pub fn merged_lines(signal: &Signal1D, rate: f64, band: f64) -> Vec<MergedLine> {
    let (lines, _) = signal.lines();
    let mut all: Vec<(f64, f64, bool)> = Vec::new();
    for &(nu, c) in &lines {
        let lo = ((-band - nu) / rate).ceil() as i64;
        let hi = ((band - nu) / rate).floor() as i64;
        for k in lo..=hi {
            all.push((nu + k as f64 * rate, c, k == 0));
        }
    }
    all.sort_by(|a, b| a.0.total_cmp(&b.0));
    let tol = 1e-9 * rate;
    let mut out: Vec<MergedLine> = Vec::new();
    for (w, c, orig) in all {
        match out.last_mut() {
            Some(m) if (w - m.omega).abs() <= tol => {
                m.total += c;
                if orig {
                    m.original += c;
                }
            }
            _ => out.push(MergedLine {
                omega: w,
                total: c,
                original: if orig { c } else { 0.0 },
            }),
        }
    }
    out
}

fn line_errors(signal: &Signal1D, rate: f64, rec: &Reconstructor, band: f64) -> AliasingErrors {
    let nyq = 0.5 * rate;
    let (lines, dropped) = signal.lines();
    let merged = merged_lines(signal, rate, band);
    let (mut pre, mut post, mut smoothing, mut lost, mut total) = (0.0, 0.0, 0.0, 0.0, 0.0);
    for m in &merged {
        let g = rec.gain(m.omega);
        let a = m.total - m.original;
        let s = (1.0 - g) * m.original;
        let inside = m.omega.abs() <= nyq * (1.0 + 1e-12);
        if inside {
            pre += a * a;
            smoothing += s * s;
        } else {
            post += g * a * g * a;
            lost += s * s;
        }
        let e = g * m.total - m.original;
        total += e * e;
    }
    // Original lines beyond the band: not reproduced (their replicas inside are counted).
    for &(nu, c) in &lines {
        if nu.abs() > band {
            lost += c * c;
            total += c * c;
        }
    }
    AliasingErrors {
        signal_energy: signal.energy(),
        pre_aliasing: pre,
        post_aliasing: post,
        smoothing,
        lost,
        total,
        band,
        periodic: true,
        tail_bound: dropped,
    }
}

/// The samples (nT, f(nT)) for |nT| ≤ `extent`.
pub fn samples(signal: &Signal1D, rate: f64, extent: f64) -> Result<Vec<[f64; 2]>, TheoremError> {
    signal.validate()?;
    check("rate", rate, MIN_RATE, MAX_RATE)?;
    check("extent", extent, EXTENT_RANGE.0, EXTENT_RANGE.1)?;
    let n = (extent * rate).floor();
    if 2.0 * n + 1.0 > MAX_SAMPLES as f64 {
        return Err(TheoremError::InvalidParam {
            field: "rate",
            value: crate::core::params::fmt_num(rate),
            allowed: format!(
                "at most {MAX_SAMPLES} samples in the window: 2·extent·rate + 1 ≤ {MAX_SAMPLES} (extent = {})",
                crate::core::params::fmt_num(extent)
            ),
        });
    }
    let n = n as i64;
    let t = 1.0 / rate;
    Ok((-n..=n)
        .map(|i| {
            let x = i as f64 * t;
            [x, signal.eval(x)]
        })
        .collect())
}

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
    /// The scale a ≠ 0 (|a| in [0.05, 20]).
    pub scale: f64,
    /// The shift s (units).
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

impl TransformPair {
    /// Checks |a| ∈ [0.05, 20] and s ∈ [−10, 10].
    pub fn validate(&self) -> Result<(), TheoremError> {
        let (lo, hi) = PAIR_SCALE_RANGE;
        if !(self.scale.is_finite() && self.scale.abs() >= lo && self.scale.abs() <= hi) {
            return Err(TheoremError::InvalidParam {
                field: "pair.scale",
                value: format!("{}", self.scale),
                allowed: format!("a finite number with |a| in [{lo}, {hi}]"),
            });
        }
        check(
            "pair.shift",
            self.shift,
            PAIR_SHIFT_RANGE.0,
            PAIR_SHIFT_RANGE.1,
        )
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

/// Everything the sampling-theorem view shows (part of a scene).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct TheoremSettings {
    /// The signal.
    pub signal: Signal1D,
    /// Sampling rate f_s (samples per unit), in [0.05, 1000].
    pub rate: f64,
    /// The reconstruction filter (sample-spacing units, scaled to T = 1/f_s).
    pub filter: Filter,
    /// Half-width of the spatial plots (units), in [0.1, 1000].
    pub extent: f64,
    /// The transform-pair sub-view.
    pub pair: TransformPair,
    /// Rows i = 0..vdc_rows of the van der Corput table (base 2), in 1..=1024.
    pub vdc_rows: usize,
}

impl Default for TheoremSettings {
    fn default() -> Self {
        TheoremSettings {
            signal: Signal1D::default(),
            rate: 4.0,
            filter: Filter::Tent(crate::core::filter::Tent { radius: 1.0 }),
            extent: 3.0,
            pair: TransformPair::default(),
            vdc_rows: 8,
        }
    }
}

impl TheoremSettings {
    /// Checks every field; the error names it (`theorem.rate`, `theorem.signal.width`, …).
    pub fn validate(&self) -> Result<(), TheoremError> {
        self.signal.validate()?;
        check("rate", self.rate, MIN_RATE, MAX_RATE)?;
        check_width_samples(&self.signal, self.rate)?;
        check("extent", self.extent, EXTENT_RANGE.0, EXTENT_RANGE.1)?;
        Reconstructor::new(self.filter, self.rate, ERROR_BAND * self.rate)?;
        self.pair.validate()?;
        if self.vdc_rows == 0 || self.vdc_rows > MAX_VDC_ROWS {
            return Err(TheoremError::InvalidParam {
                field: "vdc_rows",
                value: self.vdc_rows.to_string(),
                allowed: format!("an integer in 1..={MAX_VDC_ROWS}"),
            });
        }
        if 2.0 * (self.extent * self.rate).floor() + 1.0 > MAX_SAMPLES as f64 {
            return Err(TheoremError::InvalidParam {
                field: "rate",
                value: format!("{}", self.rate),
                allowed: format!(
                    "at most {MAX_SAMPLES} samples in the window: 2·extent·rate + 1 ≤ {MAX_SAMPLES} (extent = {})",
                    self.extent
                ),
            });
        }
        Ok(())
    }
}

/// The spectrum plots: ω ∈ [−omega_max, omega_max], magnitudes in the units of F.
#[derive(Debug, Clone, Default, Serialize)]
pub struct SpectrumPlots {
    /// Half-width of the plotted band (cycles per unit): 2.5 f_s.
    pub omega_max: f64,
    /// (ω, |F(ω)|) (continuous spectra; empty for lines).
    pub original: Vec<[f64; 2]>,
    /// (k, (ω, |F(ω − k f_s)|)) for k = −3..=3, k ≠ 0 (continuous spectra).
    pub replicas: Vec<(i64, Vec<[f64; 2]>)>,
    /// (ω, |P(ω)|), P = T·F_s (continuous spectra).
    pub sampled: Vec<[f64; 2]>,
    /// (ω, |G(ω)|): the filter's gain.
    pub gain: Vec<[f64; 2]>,
    /// (ω, |G(ω)P(ω)|) = |F_r(ω)| (continuous spectra).
    pub reconstructed: Vec<[f64; 2]>,
    /// Line spectra: (k, (ν + k f_s, |c|)) for each line of each displayed replica k.
    pub lines: Vec<(i64, Vec<[f64; 2]>)>,
    /// Line spectra: (ω, |G(ω)·Σ c|) of the merged lines (the reconstruction's lines).
    pub reconstructed_lines: Vec<[f64; 2]>,
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

/// Everything the sampling-theorem panel draws.
#[derive(Debug, Clone)]
pub struct TheoremView {
    pub settings: TheoremSettings,
    /// (x, f(x)) over [−extent, extent].
    pub signal: Vec<[f64; 2]>,
    /// The samples (nT, f(nT)).
    pub samples: Vec<[f64; 2]>,
    /// (x, f_r(x)).
    pub reconstruction: Vec<[f64; 2]>,
    pub spectrum: SpectrumPlots,
    pub errors: AliasingErrors,
    pub pair: PairPlots,
    /// The van der Corput table, base 2, i = 0..vdc_rows.
    pub vdc: Vec<RadicalInverseRow>,
}

impl TheoremView {
    /// Approximate heap bytes of the view's curves (for cache budgets).
    pub fn approx_bytes(&self) -> usize {
        let v = |c: &Vec<[f64; 2]>| c.len() * 16;
        let sp = &self.spectrum;
        let nested = |c: &Vec<(i64, Vec<[f64; 2]>)>| c.iter().map(|(_, x)| 8 + v(x)).sum::<usize>();
        let p = &self.pair;
        std::mem::size_of::<Self>()
            + v(&self.signal)
            + v(&self.samples)
            + v(&self.reconstruction)
            + v(&sp.original)
            + nested(&sp.replicas)
            + v(&sp.sampled)
            + v(&sp.gain)
            + v(&sp.reconstructed)
            + nested(&sp.lines)
            + v(&sp.reconstructed_lines)
            + v(&p.spatial)
            + v(&p.re)
            + v(&p.im)
            + v(&p.magnitude)
            + v(&p.impulses_x)
            + p.impulses_omega.len() * 24
            + self.vdc.len() * std::mem::size_of::<RadicalInverseRow>()
    }
}

/// Computes the whole view from validated settings.
pub fn compute_view(s: &TheoremSettings) -> Result<TheoremView, TheoremError> {
    s.validate()?;
    let rate = s.rate;
    let signal = s.signal;
    let omega_max = 2.5 * rate;
    let rec = Reconstructor::new(s.filter, rate, (ERROR_BAND * rate).max(omega_max))?;
    let xs = |lo: f64, hi: f64, n: usize| {
        (0..n).map(move |i| lo + (hi - lo) * i as f64 / (n - 1) as f64)
    };
    let ext = s.extent;
    let curve: Vec<[f64; 2]> = xs(-ext, ext, CURVE_POINTS)
        .map(|x| [x, signal.eval(x)])
        .collect();
    let recon: Vec<[f64; 2]> = xs(-ext, ext, CURVE_POINTS)
        .map(|x| [x, rec.reconstruct(&signal, x)])
        .collect();
    let omegas: Vec<f64> = xs(-omega_max, omega_max, SPECTRUM_POINTS).collect();
    let mut sp = SpectrumPlots {
        omega_max,
        gain: omegas.iter().map(|&w| [w, rec.gain(w).abs()]).collect(),
        ..Default::default()
    };
    match signal.spectrum_kind() {
        SpectrumKind::Continuous => {
            sp.original = omegas
                .iter()
                .map(|&w| [w, signal.transform(w).abs()])
                .collect();
            for k in -DISPLAY_REPLICAS..=DISPLAY_REPLICAS {
                if k != 0 {
                    let c = omegas
                        .iter()
                        .map(|&w| [w, signal.replica(k, w, rate).abs()])
                        .collect();
                    sp.replicas.push((k, c));
                }
            }
            for &w in &omegas {
                let (p, _) = signal.periodized(w, rate);
                sp.sampled.push([w, p.abs()]);
                sp.reconstructed.push([w, (rec.gain(w) * p).abs()]);
            }
        }
        SpectrumKind::Lines => {
            let (lines, _) = signal.lines();
            for k in -DISPLAY_REPLICAS..=DISPLAY_REPLICAS {
                let v: Vec<[f64; 2]> = lines
                    .iter()
                    .map(|&(nu, c)| [nu + k as f64 * rate, c.abs()])
                    .filter(|p| p[0].abs() <= omega_max && p[1] > 0.0)
                    .collect();
                sp.lines.push((k, v));
            }
            sp.reconstructed_lines = merged_lines(&signal, rate, omega_max)
                .iter()
                .map(|m| [m.omega, (rec.gain(m.omega) * m.total).abs()])
                .filter(|p| p[1] > 0.0)
                .collect();
        }
    }
    let errors = aliasing_errors(&signal, rate, s.filter)?;
    let pair = pair_plots(&s.pair);
    let vdc = radical_inverse_table(2, s.vdc_rows).map_err(|e| TheoremError::InvalidParam {
        field: "vdc_rows",
        value: s.vdc_rows.to_string(),
        allowed: e.to_string(),
    })?;
    Ok(TheoremView {
        settings: *s,
        signal: curve,
        samples: samples(&signal, rate, ext)?,
        reconstruction: recon,
        spectrum: sp,
        errors,
        pair,
        vdc,
    })
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn edge_values_are_mid_values_at_jumps() {
        assert_eq!(Signal1D::Box { width: 1.0 }.eval(0.5), 0.5);
        assert_eq!(Signal1D::Box { width: 1.0 }.eval(0.49), 1.0);
        assert_eq!(
            Signal1D::PulseTrain {
                period: 2.0,
                duty: 0.5
            }
            .eval(2.5),
            0.5
        );
        assert_eq!(Signal1D::Sinc { bandwidth: 2.0 }.transform(2.0), 0.125);
    }

    #[test]
    fn serde_round_trip_of_settings() {
        let s = TheoremSettings::default();
        let text = ron::to_string(&s).unwrap();
        let back: TheoremSettings = ron::from_str(&text).unwrap();
        assert_eq!(back, s);
        for sig in Signal1D::all() {
            let t = ron::to_string(&sig).unwrap();
            assert_eq!(ron::from_str::<Signal1D>(&t).unwrap(), sig, "{t}");
            sig.validate().unwrap();
        }
    }
}
