//! Filter quality metrics: the lecture's "possible errors" (smoothing, post-aliasing, ringing,
//! anisotropy), defined in the [module docs of `filter`](super) and computed here.
//!
//! Discretisation (accuracy ≈ 10⁻⁷ absolute, limited by the kinks of |H| at its zeros):
//! - smoothing: ∫₀^{0.5} A(ω) dω with 8-point Gauss–Legendre on panels of width 1/64 split at the
//!   response's breakpoints (ideal filters' edges).
//! - post-aliasing: ∫|H|² on \[0, 0.5\] and \[0.5, ω_max\], panels of width 1/32 (GL8).
//! - ringing: the step response S is accumulated piece by piece (GL8 on pieces of width
//!   ≤ feature/4, split at the kernel's breakpoints, at most 16384 pieces); its extrema lie
//!   at zeros of h, which are located by bisection in every piece where h changes sign, so the
//!   extrema are exact up to quadrature error.
//! - anisotropy (separable filters): |H(ρ cos θ) H(ρ sin θ)| on radii ρ_k = (k − ½)/32,
//!   k = 1..16 (0 < ρ < 0.5, avoiding the band edge of the ideal filter at exactly ½) and 17 angles θ ∈ \[0, π/4\] (the magnitude is symmetric under x ↔ y and sign
//!   flips, so this octant covers the circle); radii whose mean is below 10⁻⁹ of the peak are
//!   skipped. Radial filters have exactly radially symmetric responses: anisotropy 0.

use super::quad::{gl8, panels};
use crate::core::cancel::{Cancel, Cancelled};
use rustfft::num_complex::Complex64;
use serde::Serialize;
use std::f64::consts::PI;

/// Upper end ω_max of the post-aliasing energy integrals, in cycles per sample.
pub const OMEGA_MAX: f64 = 4.0;
/// Number of radii 0 < ρ ≤ ½ of the anisotropy measure.
pub const ANISOTROPY_RADII: usize = 16;
/// Number of angles in \[0, π/4\] of the anisotropy measure.
pub const ANISOTROPY_ANGLES: usize = 17;
/// Most pieces of the step-response accumulation.
const MAX_STEP_PIECES: usize = 16_384;

/// The four quality metrics of a (2D) filter, plus the parts of the ringing measure.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FilterMetrics {
    /// Pass-band loss below Nyquist: 1 − 2∫₀^{½} A(ω) dω.
    pub smoothing: f64,
    /// Fraction of ∫₀^{ω_max}|H|² above Nyquist.
    pub post_aliasing: f64,
    /// max(overshoot, undershoot) of the step response.
    pub ringing: f64,
    /// max S − 1 of the normalised step response S.
    pub overshoot: f64,
    /// −min S of the normalised step response.
    pub undershoot: f64,
    /// max over 0 < ρ ≤ ½ of (max − min)/mean of |H₂| over angles.
    pub anisotropy: f64,
    /// The ω_max of the post-aliasing integrals (cycles per sample).
    pub omega_max: f64,
}

/// How the magnitude is normalised for the smoothing measure.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Gain {
    /// A = |H|/|H(0)|, or |H|/max|H| when |H(0)| < 10⁻³ max|H| (zero-DC filters).
    Dc,
    /// A = |H(ω)|/(2π|ω| D) for a derivative kernel with derivative gain D = |∫x h(x) dx|.
    Derivative(f64),
}

/// (smoothing, post_aliasing) of a response `resp` (ω in cycles per sample), with `breaks`
/// the frequencies where the response is not smooth.
pub fn spectral_metrics(
    resp: &dyn Fn(f64) -> Complex64,
    omega_max: f64,
    breaks: &[f64],
    gain: Gain,
    cancel: &Cancel,
) -> Result<(f64, f64), Cancelled> {
    let rule = gl8();
    let mut eb: Vec<f64> = vec![0.0, 0.5, omega_max];
    eb.extend(breaks.iter().copied().filter(|&b| b > 0.0 && b < omega_max));
    eb.sort_by(f64::total_cmp);
    eb.dedup();
    let mut e_low = 0.0;
    let mut e_high = 0.0;
    let mut peak: f64 = 0.0;
    for (i, (a, b)) in panels(&eb, 1.0 / 32.0).into_iter().enumerate() {
        if i % 64 == 0 {
            cancel.check()?;
        }
        let e = rule.integrate(
            &mut |w| {
                let m = resp(w).norm();
                peak = peak.max(m);
                m * m
            },
            a,
            b,
        );
        if b <= 0.5 {
            e_low += e;
        } else {
            e_high += e;
        }
    }
    let h0 = resp(0.0).norm();
    peak = peak.max(h0);
    let total = e_low + e_high;
    let post = if total > 0.0 { e_high / total } else { 0.0 };
    // The normaliser: Some(D) for a derivative kernel, otherwise the DC gain (or the peak).
    let derivative = match gain {
        Gain::Derivative(d) if d > 0.0 && d.is_finite() => Some(d),
        _ => None,
    };
    let g = if h0 >= 1e-3 * peak { h0 } else { peak };
    if derivative.is_none() && (g <= 0.0 || !g.is_finite()) {
        return Ok((1.0, post));
    }
    let a_of = |w: f64| match derivative {
        Some(d) => resp(w).norm() / (2.0 * PI * w.abs() * d),
        None => resp(w).norm() / g,
    };
    let mut sb: Vec<f64> = vec![0.0, 0.5];
    sb.extend(breaks.iter().copied().filter(|&b| b > 0.0 && b < 0.5));
    sb.sort_by(f64::total_cmp);
    sb.dedup();
    let mut pass = 0.0;
    for (a, b) in panels(&sb, 1.0 / 64.0) {
        pass += rule.integrate(&mut |w| a_of(w), a, b);
    }
    Ok((1.0 - 2.0 * pass, post))
}

/// (overshoot, undershoot) of the step response S(x) = ∫_{−r}^{x} h of a kernel h on
/// \[−r, r\] with a Dirac mass `dirac` at 0, normalised by S(r) = ∫h (or, for zero-DC kernels —
/// `zero_dc` or |∫h| < 10⁻⁶ ∫|h| — by its largest excursion, reporting the largest excursion of
/// the opposite sign as undershoot and 0 as overshoot).
///
/// `pos_breaks` are the kernel's breakpoints in (0, r) (mirrored to the negative side);
/// `feature` its feature scale.
#[allow(clippy::too_many_arguments)]
pub fn step_extremes(
    h: &dyn Fn(f64) -> f64,
    r: f64,
    pos_breaks: &[f64],
    dirac: f64,
    zero_dc: bool,
    feature: f64,
    cancel: &Cancel,
) -> Result<(f64, f64), Cancelled> {
    let rule = gl8();
    let mut breaks: Vec<f64> = vec![-r, 0.0, r];
    for &b in pos_breaks {
        if b > 0.0 && b < r {
            breaks.push(b);
            breaks.push(-b);
        }
    }
    breaks.sort_by(f64::total_cmp);
    breaks.dedup();
    // Pieces of a quarter of the feature scale: at most one zero of h per piece for the
    // oscillating kernels (sinc-like half periods are ≥ the feature scale).
    let mut width = 0.25 * feature;
    if width.is_nan() || width <= 0.0 || 2.0 * r / width > MAX_STEP_PIECES as f64 {
        width = 2.0 * r / MAX_STEP_PIECES as f64;
    }
    let mut s = 0.0;
    let mut abs_total = dirac.abs();
    let mut candidates = vec![0.0];
    let mut dirac_done = dirac == 0.0;
    for (i, (a, b)) in panels(&breaks, width).into_iter().enumerate() {
        if i % 64 == 0 {
            cancel.check()?;
        }
        if !dirac_done && a >= 0.0 {
            candidates.push(s);
            s += dirac;
            candidates.push(s);
            dirac_done = true;
        }
        let eps = 1e-9 * (b - a);
        let (lo, hi) = (a + eps, b - eps);
        let (ha, hb) = (h(lo), h(hi));
        if ha * hb < 0.0 {
            let root = sign_change(h, lo, hi, ha, hb);
            candidates.push(s + rule.integrate(&mut |x| h(x), a, root));
        }
        // One pass over the nodes for ∫h and ∫|h|.
        let (c, hw) = (0.5 * (a + b), 0.5 * (b - a));
        let (mut piece, mut piece_abs) = (0.0, 0.0);
        for (x, w) in rule.nodes.iter().zip(&rule.weights) {
            let v = h(c + hw * x);
            piece += w * v;
            piece_abs += w * v.abs();
        }
        s += piece * hw;
        abs_total += piece_abs * hw;
        candidates.push(s);
    }
    let total = s;
    if !zero_dc && total.abs() >= 1e-6 * abs_total && total != 0.0 {
        let (mut mx, mut mn) = (f64::NEG_INFINITY, f64::INFINITY);
        for c in &candidates {
            let v = c / total;
            mx = mx.max(v);
            mn = mn.min(v);
        }
        Ok(((mx - 1.0).max(0.0), (-mn).max(0.0)))
    } else {
        let peak = candidates
            .iter()
            .copied()
            .fold(0.0_f64, |p, c| if c.abs() > p.abs() { c } else { p });
        if peak == 0.0 {
            return Ok((0.0, 0.0));
        }
        let mn = candidates
            .iter()
            .map(|c| c / peak)
            .fold(f64::INFINITY, f64::min);
        Ok((0.0, (-mn).max(0.0)))
    }
}

/// A zero of h in \[x0, x1\] where h(x0) = h0 and h(x1) = h1 have opposite signs, by the
/// Illinois variant of regula falsi, to |x1 − x0| ≤ 10⁻¹² (1 + |x|). An error δ in the zero
/// changes the step-response extremum only by h'·δ²/2.
fn sign_change(h: &dyn Fn(f64) -> f64, x0: f64, x1: f64, h0: f64, h1: f64) -> f64 {
    let (mut a, mut b, mut fa, mut fb) = (x0, x1, h0, h1);
    let mut side = 0;
    for _ in 0..100 {
        let c = (a * fb - b * fa) / (fb - fa);
        let c = if c > a && c < b { c } else { 0.5 * (a + b) };
        if (b - a) <= 1e-12 * (1.0 + c.abs()) {
            return c;
        }
        let fc = h(c);
        if fc == 0.0 {
            return c;
        }
        if fc * fb > 0.0 {
            b = c;
            fb = fc;
            if side == -1 {
                fa *= 0.5;
            }
            side = -1;
        } else {
            a = c;
            fa = fc;
            if side == 1 {
                fb *= 0.5;
            }
            side = 1;
        }
    }
    0.5 * (a + b)
}

/// Anisotropy of a separable filter's magnitude |H(ω_x) H(ω_y)| (see the module docs).
pub fn separable_anisotropy(resp: &dyn Fn(f64) -> Complex64) -> f64 {
    let k_n = ANISOTROPY_RADII;
    let j_n = ANISOTROPY_ANGLES;
    let mut rows = Vec::with_capacity(k_n);
    let mut peak: f64 = 0.0;
    for k in 1..=k_n {
        let rho = 0.5 * (k as f64 - 0.5) / k_n as f64;
        let row: Vec<f64> = (0..j_n)
            .map(|j| {
                let th = 0.25 * PI * j as f64 / (j_n - 1) as f64;
                let (s, c) = th.sin_cos();
                resp(rho * c).norm() * resp(rho * s).norm()
            })
            .collect();
        peak = row.iter().copied().fold(peak, f64::max);
        rows.push(row);
    }
    let mut aniso: f64 = 0.0;
    for row in rows {
        let mean = row.iter().sum::<f64>() / row.len() as f64;
        if mean <= 1e-9 * peak || mean <= 0.0 {
            continue;
        }
        let mx = row.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        let mn = row.iter().copied().fold(f64::INFINITY, f64::min);
        aniso = aniso.max((mx - mn) / mean);
    }
    aniso
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spectral_metrics_of_an_ideal_box_response() {
        // H = 1 on |ω| < 0.25: smoothing 1 − 2·0.25 = 0.5, post-aliasing 0.
        let resp = |w: f64| Complex64::new(if w.abs() < 0.25 { 1.0 } else { 0.0 }, 0.0);
        let (s, p) = spectral_metrics(&resp, 4.0, &[0.25], Gain::Dc, &Cancel::never()).unwrap();
        assert!((s - 0.5).abs() < 1e-14);
        assert_eq!(p, 0.0);
        // H = 1 everywhere: smoothing 0, post-aliasing (4 − 0.5)/4.
        let flat = |_: f64| Complex64::new(1.0, 0.0);
        let (s, p) = spectral_metrics(&flat, 4.0, &[], Gain::Dc, &Cancel::never()).unwrap();
        assert!(s.abs() < 1e-14);
        assert!((p - 3.5 / 4.0).abs() < 1e-14);
    }

    #[test]
    fn step_extremes_of_a_positive_kernel_are_zero() {
        let h = |x: f64| if x.abs() <= 1.0 { 1.0 - x.abs() } else { 0.0 };
        let (o, u) = step_extremes(&h, 1.0, &[], 0.0, false, 1.0, &Cancel::never()).unwrap();
        assert!(o < 1e-15 && u < 1e-15, "{o} {u}");
    }

    #[test]
    fn cancelled_metrics_return_cancelled() {
        let c = Cancel::new();
        c.cancel();
        let flat = |_: f64| Complex64::new(1.0, 0.0);
        assert_eq!(
            spectral_metrics(&flat, 4.0, &[], Gain::Dc, &c),
            Err(Cancelled)
        );
    }
}
