//! The lecture's error terms ([`AliasingErrors`]): pre-aliasing, post-aliasing, smoothing, lost, total.

use super::{
    check, Gaussian1D, Reconstructor, Signal1D, SpectrumKind, TheoremError, ERROR_BAND, MAX_RATE,
    MAX_WIDTH_SAMPLES, MIN_RATE,
};
use crate::core::filter::{quad, Filter};
use serde::Serialize;

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
pub(super) fn check_width_samples(signal: &Signal1D, rate: f64) -> Result<(), TheoremError> {
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
    if let Signal1D::Gaussian(Gaussian1D { sigma }) = *signal {
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
