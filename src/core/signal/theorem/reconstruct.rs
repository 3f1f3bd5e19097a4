//! The reconstruction filter prepared for one sampling rate ([`Reconstructor`]) and the samples f(nT).

use super::{check, Signal1D, TheoremError, EXTENT_RANGE, MAX_RATE, MAX_SAMPLES, MIN_RATE};
use crate::core::filter::{quad, Filter, Parity, ResponseEval};

/// A reconstruction filter prepared for one sampling rate: f_r(x) = Σ_n f(nT) h(x/T − n)/H(0)
/// and G(ω) = H(ωT)/H(0).
#[derive(Debug, Clone)]
pub struct Reconstructor {
    pub(super) filter: Filter,
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
    pub(super) fn gain_tail(&self, omega_band: f64, inside: f64) -> f64 {
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
