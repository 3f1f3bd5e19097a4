//! The theorem's 1D test signals ([`Signal1D`]): f(x), F(ω), lines, energy and their parameters.

use super::{TheoremError, PARAM_RANGE, PULSE_HARMONICS};
use crate::core::family::family;
use crate::core::filter::special::{cos_pi, sinc};
use crate::core::params::{declare_params, Params};
use std::f64::consts::PI;

declare_params! {
    /// ½cos 2π(B/4)x + 0.3cos 2π(B/2)x + 0.2cos 2πBx: band-limited to B.
    Cosines1D = "cosines" in "signal", "½cos 2π(B/4)x + 0.3cos 2π(B/2)x + 0.2cos 2πBx: lines at ±B/4, ±B/2, ±B (band-limited to B)" {
        bandwidth: float(1.5, PARAM_RANGE.0, PARAM_RANGE.1, "bandwidth B, cycles per unit"),
    }
}
declare_params! {
    /// sinc(2Bx): F = 1/(2B) on |ω| < B.
    Sinc1D = "sinc" in "signal", "sinc(2Bx): F = 1/(2B) on |ω| < B (band-limited to B)" {
        bandwidth: float(1.5, PARAM_RANGE.0, PARAM_RANGE.1, "bandwidth B, cycles per unit"),
    }
}
declare_params! {
    /// sinc²(Bx): F = (1/B)(1 − |ω|/B)₊.
    SincSquared1D = "sinc-squared" in "signal", "sinc²(Bx): F = (1/B)(1 − |ω|/B)₊ (band-limited to B)" {
        bandwidth: float(1.5, PARAM_RANGE.0, PARAM_RANGE.1, "bandwidth B, cycles per unit"),
    }
}
declare_params! {
    /// The box of width w: F = w sinc(wω).
    Box1D = "box" in "signal", "the box of width w: F = w sinc(wω)" {
        width: float(1.0, PARAM_RANGE.0, PARAM_RANGE.1, "width w, units"),
    }
}
declare_params! {
    /// The tent of radius w: F = w sinc²(wω).
    Tent1D = "tent" in "signal", "the tent of radius w: F = w sinc²(wω)" {
        radius: float(1.0, PARAM_RANGE.0, PARAM_RANGE.1, "radius w, units"),
    }
}
declare_params! {
    /// e^{−x²/2σ²}: F = σ√(2π)e^{−2π²σ²ω²}.
    Gaussian1D = "gaussian" in "signal", "e^(−x²/2σ²): F = σ√(2π)e^(−2π²σ²ω²)" {
        sigma: float(0.3, PARAM_RANGE.0, PARAM_RANGE.1, "standard deviation σ, units"),
    }
}
declare_params! {
    /// Pulses of width d·p every p: Fourier series c_m = d sinc(md).
    PulseTrain1D = "pulse-train" in "signal", "pulses of width d·p every p: lines c_m = d sinc(md) at m/p" {
        period: float(2.0, PARAM_RANGE.0, PARAM_RANGE.1, "period p, units"),
        duty: float(0.5, 0.01, 0.99, "duty cycle d (pulse width d·p)"),
    }
}

family! {
    /// A 1D test signal with a closed-form Fourier transform (see the module table). Errors
    /// name `signal.<parameter>`.
    Signal1D = "signal", "signals" {
        /// ½cos 2π(B/4)x + 0.3cos 2π(B/2)x + 0.2cos 2πBx: band-limited to B.
        Cosines(Cosines1D) = "cosines",
        /// sinc(2Bx): F = 1/(2B) on |ω| < B.
        Sinc(Sinc1D) = "sinc",
        /// sinc²(Bx): F = (1/B)(1 − |ω|/B)₊.
        SincSquared(SincSquared1D) = "sinc-squared",
        /// The box of width w: F = w sinc(wω).
        Box(Box1D) = "box",
        /// The tent of radius w: F = w sinc²(wω).
        Tent(Tent1D) = "tent",
        /// e^{−x²/2σ²}: F = σ√(2π)e^{−2π²σ²ω²}.
        Gaussian(Gaussian1D) = "gaussian",
        /// Pulses of width d·p every p: Fourier series c_m = d sinc(md).
        PulseTrain(PulseTrain1D) = "pulse-train",
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
        Signal1D::Tent(Tent1D::default())
    }
}

impl Signal1D {
    /// Checks every parameter; the error names `signal.<param>`.
    pub fn validate(&self) -> Result<(), TheoremError> {
        Ok(self.check_params()?)
    }

    /// Continuous spectrum or lines.
    pub fn spectrum_kind(&self) -> SpectrumKind {
        match self {
            Signal1D::Cosines(Cosines1D { .. }) | Signal1D::PulseTrain(PulseTrain1D { .. }) => {
                SpectrumKind::Lines
            }
            _ => SpectrumKind::Continuous,
        }
    }

    /// The highest frequency of F (cycles per unit), `None` if not band-limited.
    pub fn bandwidth(&self) -> Option<f64> {
        match *self {
            Signal1D::Cosines(Cosines1D { bandwidth })
            | Signal1D::Sinc(Sinc1D { bandwidth })
            | Signal1D::SincSquared(SincSquared1D { bandwidth }) => Some(bandwidth),
            _ => None,
        }
    }

    /// f(x).
    pub fn eval(&self, x: f64) -> f64 {
        match *self {
            Signal1D::Cosines(Cosines1D { bandwidth }) => COSINES
                .iter()
                .map(|&(a, r)| a * cos_pi(2.0 * r * bandwidth * x))
                .sum(),
            Signal1D::Sinc(Sinc1D { bandwidth }) => sinc(2.0 * bandwidth * x),
            Signal1D::SincSquared(SincSquared1D { bandwidth }) => {
                let s = sinc(bandwidth * x);
                s * s
            }
            Signal1D::Box(Box1D { width }) => edge_value(x.abs(), 0.5 * width),
            Signal1D::Tent(Tent1D { radius }) => (1.0 - x.abs() / radius).max(0.0),
            Signal1D::Gaussian(Gaussian1D { sigma }) => (-x * x / (2.0 * sigma * sigma)).exp(),
            Signal1D::PulseTrain(PulseTrain1D { period, duty }) => {
                let t = x / period;
                let d = (t - t.round()).abs();
                edge_value(d, 0.5 * duty)
            }
        }
    }

    /// F(ω) for continuous spectra (real: every signal here is even); 0 for line spectra.
    pub fn transform(&self, omega: f64) -> f64 {
        match *self {
            Signal1D::Sinc(Sinc1D { bandwidth }) => {
                edge_value(omega.abs(), bandwidth) / (2.0 * bandwidth)
            }
            Signal1D::SincSquared(SincSquared1D { bandwidth }) => {
                (1.0 - omega.abs() / bandwidth).max(0.0) / bandwidth
            }
            Signal1D::Box(Box1D { width }) => width * sinc(width * omega),
            Signal1D::Tent(Tent1D { radius }) => {
                let s = sinc(radius * omega);
                radius * s * s
            }
            Signal1D::Gaussian(Gaussian1D { sigma }) => {
                sigma * (2.0 * PI).sqrt() * (-2.0 * PI * PI * sigma * sigma * omega * omega).exp()
            }
            Signal1D::Cosines(Cosines1D { .. }) | Signal1D::PulseTrain(PulseTrain1D { .. }) => 0.0,
        }
    }

    /// The spectral lines (ω, c) of a periodic signal (f = Σ c e^{2πiωx}; empty for continuous
    /// spectra) and a bound on the power of the lines left out (pulse train: |m| >
    /// [`PULSE_HARMONICS`]).
    pub fn lines(&self) -> (Vec<(f64, f64)>, f64) {
        match *self {
            Signal1D::Cosines(Cosines1D { bandwidth }) => {
                let mut v = Vec::new();
                for &(a, r) in &COSINES {
                    v.push((-r * bandwidth, 0.5 * a));
                    v.push((r * bandwidth, 0.5 * a));
                }
                (v, 0.0)
            }
            Signal1D::PulseTrain(PulseTrain1D { period, duty }) => {
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
            Signal1D::Cosines(Cosines1D { .. }) => COSINES.iter().map(|&(a, _)| 0.5 * a * a).sum(),
            Signal1D::Sinc(Sinc1D { bandwidth }) => 0.5 / bandwidth,
            Signal1D::SincSquared(SincSquared1D { bandwidth }) => 2.0 / (3.0 * bandwidth),
            Signal1D::Box(Box1D { width }) => width,
            Signal1D::Tent(Tent1D { radius }) => 2.0 * radius / 3.0,
            Signal1D::Gaussian(Gaussian1D { sigma }) => sigma * PI.sqrt(),
            Signal1D::PulseTrain(PulseTrain1D { duty, .. }) => duty,
        }
    }

    /// Half-width of the support of f (`None` when unbounded).
    pub fn support(&self) -> Option<f64> {
        match *self {
            Signal1D::Box(Box1D { width }) => Some(0.5 * width),
            Signal1D::Tent(Tent1D { radius }) => Some(radius),
            _ => None,
        }
    }

    /// The width that sets the error integrals' cost: 2·support (box, tent), 8σ (Gaussian).
    pub fn cost_width(&self) -> Option<f64> {
        match *self {
            Signal1D::Gaussian(Gaussian1D { sigma }) => Some(8.0 * sigma),
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
            Signal1D::Sinc(Sinc1D { bandwidth })
            | Signal1D::SincSquared(SincSquared1D { bandwidth }) => replicas(bandwidth),
            Signal1D::Gaussian(Gaussian1D { sigma }) => replicas(Self::gaussian_cut(sigma)),
            Signal1D::Box(Box1D { .. }) | Signal1D::Tent(Tent1D { .. }) => {
                let t = 1.0 / rate;
                let n_max = (self.support().unwrap_or(0.0) * rate).floor() as i64;
                let mut p = self.eval(0.0);
                for n in 1..=n_max {
                    p += 2.0 * self.eval(n as f64 * t) * cos_pi(2.0 * omega * n as f64 * t);
                }
                p *= t;
                (p, p - self.transform(omega))
            }
            Signal1D::Cosines(Cosines1D { .. }) | Signal1D::PulseTrain(PulseTrain1D { .. }) => {
                (0.0, 0.0)
            }
        }
    }

    /// The replica k as plotted: F(ω − k f_s) (the k-th term of P = T·F_s).
    pub fn replica(&self, k: i64, omega: f64, rate: f64) -> f64 {
        self.transform(omega - k as f64 * rate)
    }

    /// An upper bound on |P(ω)| over all ω (continuous spectra).
    pub(super) fn periodized_bound(&self, rate: f64) -> f64 {
        match *self {
            Signal1D::Sinc(Sinc1D { bandwidth })
            | Signal1D::SincSquared(SincSquared1D { bandwidth }) => {
                self.transform(0.0) * (2.0 * bandwidth / rate + 1.0)
            }
            Signal1D::Gaussian(Gaussian1D { .. }) => {
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
pub(super) fn edge_value(d: f64, e: f64) -> f64 {
    if d < e {
        1.0
    } else if d == e {
        0.5
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn edge_values_are_mid_values_at_jumps() {
        assert_eq!(Signal1D::Box(Box1D { width: 1.0 }).eval(0.5), 0.5);
        assert_eq!(Signal1D::Box(Box1D { width: 1.0 }).eval(0.49), 1.0);
        assert_eq!(
            Signal1D::PulseTrain(PulseTrain1D {
                period: 2.0,
                duty: 0.5
            })
            .eval(2.5),
            0.5
        );
        assert_eq!(
            Signal1D::Sinc(Sinc1D { bandwidth: 2.0 }).transform(2.0),
            0.125
        );
    }
}
