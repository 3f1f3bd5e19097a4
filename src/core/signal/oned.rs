//! 1D signals for the sampling-theorem view: sums of sines, a linear chirp, a square wave; and
//! the constant field.
//!
//! Each is a function f(x) of x ∈ [0, 1) with values in [0, 1]; as a 2D image it is constant
//! along y (f(p) = f(p.x)). Frequencies are in cycles per unit: sampling with N points per unit
//! has Nyquist N/2. Phases are formed in double-double and reduced exactly, as for the zone plate.

use super::exact::{rem2, sin_pi, DoubleDouble};
use super::SignalError;
use crate::core::params::{declare_params, fmt_num, ParamError, Params};

/// Number of terms of [`SumOfSines`].
pub const MAX_TERMS: usize = 4;

/// Largest frequency accepted by the 1D signals (cycles per unit).
pub const MAX_FREQUENCY_1D: f64 = 1e6;

declare_params! {
    /// f(x) = ½(1 + Σₖ aₖ sin(2π fₖ x)), with Σ|aₖ| ≤ 1 so that f ∈ [0, 1].
    ///
    /// A band-limited signal when every fₖ < N/2: sampled at N points per unit it is recovered
    /// exactly by sinc interpolation (Shannon 1949); unused terms have aₖ = 0.
    SumOfSines = "sum-of-sines", "1D: ½(1 + Σ aₖ sin(2π fₖ x)), band-limited" {
        /// Frequencies fₖ in cycles per unit, each in [0, 10⁶].
        freqs: list(4, [2.0, 5.0, 11.0, 0.0], 0.0, MAX_FREQUENCY_1D, "frequencies fₖ, cycles per unit"),
        /// Amplitudes aₖ, with Σ|aₖ| ≤ 1.
        amps: list(4, [0.5, 0.3, 0.2, 0.0], -1.0, 1.0, "amplitudes aₖ, Σ|aₖ| ≤ 1"),
    }
    check(p) {
        let total: f64 = p.amps.iter().map(|a| a.abs()).sum();
        if total > 1.0 {
            return Err(ParamError::Invalid {
                owner: "sum-of-sines",
                field: "amps",
                value: fmt_num(total),
                allowed: "amplitudes with Σ|aₖ| ≤ 1 (value shown is Σ|aₖ|)".into(),
            });
        }
        Ok(())
    }
}

impl SumOfSines {
    /// Checks every parameter against its descriptor (see [`Params::check_params`]).
    pub fn validate(&self) -> Result<(), SignalError> {
        Ok(self.check_params()?)
    }

    /// f(x) ∈ [0, 1].
    #[inline]
    pub fn eval1(&self, x: f64) -> f64 {
        let mut s = 0.0;
        for (&f, &a) in self.freqs.iter().zip(&self.amps) {
            if a != 0.0 {
                s += a * sin_pi(rem2(DoubleDouble::prod(2.0 * f, x)));
            }
        }
        (0.5 * (1.0 + s)).clamp(0.0, 1.0)
    }
}

declare_params! {
    /// A linear chirp f(x) = ½(1 + sin(2π(f₀x + (f₁ − f₀)x²/2))): instantaneous frequency
    /// f₀ + (f₁ − f₀)x cycles per unit, sweeping from f₀ at x = 0 to f₁ at x = 1.
    Chirp = "chirp", "1D: linear chirp from f₀ at x = 0 to f₁ at x = 1" {
        /// Start frequency f₀ (cycles per unit) at x = 0, in [0, 10⁶].
        f0: float(1.0, 0.0, MAX_FREQUENCY_1D, "start frequency f₀ at x = 0, cycles per unit"),
        /// End frequency f₁ (cycles per unit) at x = 1, in [0, 10⁶].
        f1: float(64.0, 0.0, MAX_FREQUENCY_1D, "end frequency f₁ at x = 1, cycles per unit"),
    }
}

impl Chirp {
    /// Checks every parameter against its descriptor (see [`Params::check_params`]).
    pub fn validate(&self) -> Result<(), SignalError> {
        Ok(self.check_params()?)
    }

    /// Instantaneous frequency f₀ + (f₁ − f₀)x (cycles per unit).
    pub fn frequency_at(&self, x: f64) -> f64 {
        self.f0 + (self.f1 - self.f0) * x
    }

    /// f(x) ∈ [0, 1]; phase/π = 2f₀x + (f₁ − f₀)x², in double-double, reduced exactly.
    #[inline]
    pub fn eval1(&self, x: f64) -> f64 {
        let lin = DoubleDouble::prod(2.0 * self.f0, x);
        let quad = DoubleDouble::diff(self.f1, self.f0).mul_f64(x).mul_f64(x);
        (0.5 * (1.0 + sin_pi(rem2(lin + quad)))).clamp(0.0, 1.0)
    }
}

declare_params! {
    /// A square wave: f(x) = 1 where frac(f·x) < ½, else 0 (high on the first half period).
    ///
    /// Its Fourier series has odd harmonics (2k+1)f with amplitudes 2/(π(2k+1)): never band-limited.
    Square = "square", "1D: square wave, high on the first half period" {
        /// Frequency f (periods per unit), in (0, 10⁶].
        frequency: positive(4.0, MAX_FREQUENCY_1D, "frequency f, periods per unit"),
    }
}

impl Square {
    /// Checks every parameter against its descriptor (see [`Params::check_params`]).
    pub fn validate(&self) -> Result<(), SignalError> {
        Ok(self.check_params()?)
    }

    /// frac(f·x) ∈ [0, 1), with f·x formed exactly.
    #[inline]
    pub fn phase(&self, x: f64) -> f64 {
        let t = DoubleDouble::prod(self.frequency, x);
        let mut r = (t.hi % 1.0) + (t.lo % 1.0);
        r %= 1.0;
        if r < 0.0 {
            r += 1.0;
        }
        if r >= 1.0 {
            r -= 1.0;
        }
        r
    }

    /// f(x) ∈ {0, 1}.
    #[inline]
    pub fn eval1(&self, x: f64) -> f64 {
        if self.phase(x) < 0.5 {
            1.0
        } else {
            0.0
        }
    }
}

declare_params! {
    /// The constant field f(p) = value: reconstruction must return it exactly.
    Constant = "constant", "the constant field: reconstruction must reproduce it exactly" {
        /// The value, in [0, 1].
        value: float(0.5, 0.0, 1.0, "the value"),
    }
}

impl Constant {
    /// Checks every parameter against its descriptor (see [`Params::check_params`]).
    pub fn validate(&self) -> Result<(), SignalError> {
        Ok(self.check_params()?)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sum_of_sines_matches_naive_formula() {
        let s = SumOfSines::default();
        for i in 0..1000 {
            let x = i as f64 / 1000.0;
            let naive = 0.5
                * (1.0
                    + s.freqs
                        .iter()
                        .zip(&s.amps)
                        .map(|(f, a)| a * (2.0 * std::f64::consts::PI * f * x).sin())
                        .sum::<f64>());
            assert!((s.eval1(x) - naive).abs() < 1e-13, "x = {x}");
        }
    }

    #[test]
    fn chirp_matches_naive_formula_at_low_frequency() {
        let c = Chirp { f0: 3.0, f1: 40.0 };
        for i in 0..1000 {
            let x = i as f64 / 1000.0;
            let ph = 2.0 * std::f64::consts::PI * (c.f0 * x + (c.f1 - c.f0) * x * x / 2.0);
            let naive = 0.5 * (1.0 + ph.sin());
            assert!((c.eval1(x) - naive).abs() < 1e-13, "x = {x}");
        }
    }

    #[test]
    fn square_wave_levels_and_transitions() {
        let s = Square { frequency: 4.0 };
        assert_eq!(s.eval1(0.0), 1.0);
        assert_eq!(s.eval1(0.1), 1.0); // phase 0.4
        assert_eq!(s.eval1(0.125), 0.0); // phase exactly ½
        assert_eq!(s.eval1(0.2), 0.0); // phase 0.8
        assert_eq!(s.eval1(0.25), 1.0); // next period
    }

    #[test]
    fn sum_of_sines_rejects_amplitude_sum_above_one() {
        let s = SumOfSines {
            freqs: [1.0, 2.0, 0.0, 0.0],
            amps: [0.6, -0.5, 0.0, 0.0],
        };
        let e = s.validate().unwrap_err();
        assert!(e.to_string().contains("amps"), "{e}");
    }
}
