//! Everything the sampling-theorem view draws ([`TheoremView`]), computed from its settings.

use super::{
    aliasing_errors, merged_lines, pair_plots, samples, AliasingErrors, PairPlots, Reconstructor,
    SpectrumKind, TheoremError, TheoremSettings, CURVE_POINTS, DISPLAY_REPLICAS, ERROR_BAND,
    SPECTRUM_POINTS,
};
use crate::core::pattern::radical_inverse::{radical_inverse_table, RadicalInverseRow};
use serde::Serialize;

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
