//! 2D filters: separable h(x)h(y) or radial h(|p|), their responses, response images and
//! metrics.
//!
//! Units as in 1D: p in sample spacings, ω = (ω_x, ω_y) in cycles per sample.
//! - **Separable**: h₂(p) = h(x)h(y) on the square |x|, |y| ≤ r; H₂(ω) = H(ω_x)H(ω_y).
//! - **Radial**: h₂(p) = h(|p|) on the disk |p| ≤ r; H₂ depends on ρ = |ω| only and is the
//!   Hankel transform H₂(ρ) = 2π∫₀^r h(s) J₀(2πρs) s ds, computed by adaptive Gauss–Legendre
//!   quadrature ([`Filter2D::radial_response`]) or, for many ρ, a precomputed rule
//!   ([`HankelRule`]). Note that h(|p|) of a 1D kernel is *not* the 2D filter with response
//!   H(|ω|) (e.g. sinc(|p|) is not the ideal circular low-pass, whose kernel is a jinc).
//!   Odd kernels (cosc) and kernels with a Dirac part (ideal high-pass) have no radial version.
//!
//! Metrics of a 2D filter are measured along the ω_x axis, i.e. on the edge response across an
//! edge parallel to y: for separable filters they equal the 1D metrics of h; for radial filters
//! smoothing and post-aliasing use the Hankel profile H₂(ρ) and ringing the step response of the
//! Abel projection m(x) = ∫h(√(x² + y²)) dy (whose 1D transform is H₂(ω_x, 0) by the
//! projection-slice theorem).

use super::metrics::{self, FilterMetrics, Gain};
use super::special::bessel_j0;
use super::{
    check_omega_max, quad, Filter, FilterError, Parity, ResponseCurve, ResponseEval,
    ResponseSample, MAX_CURVE_SAMPLES, REL_TOL,
};
use crate::core::cancel::Cancel;
use glam::DVec2;
use rustfft::num_complex::Complex64;
use serde::{Deserialize, Serialize};
use std::collections::HashMap;
use std::f64::consts::PI;

/// Largest response image side.
pub const MAX_IMAGE_SIZE: usize = 4096;

/// How a 1D kernel becomes a 2D filter.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Mode2D {
    /// h(x)·h(y).
    #[default]
    Separable,
    /// h(|p|).
    Radial,
}

impl Mode2D {
    /// Names as used by `--mode`.
    pub const NAMES: &'static [&'static str] = &["separable", "radial"];

    /// The mode's name.
    pub fn name(&self) -> &'static str {
        match self {
            Mode2D::Separable => "separable",
            Mode2D::Radial => "radial",
        }
    }

    /// The mode named `name` (case-insensitive).
    pub fn from_name(name: &str) -> Result<Mode2D, FilterError> {
        match name.trim().to_ascii_lowercase().as_str() {
            "separable" => Ok(Mode2D::Separable),
            "radial" => Ok(Mode2D::Radial),
            _ => Err(FilterError::InvalidArgument {
                field: "mode",
                value: name.to_string(),
                allowed: "one of separable, radial".into(),
            }),
        }
    }
}

/// A 2D reconstruction filter: a 1D kernel and how it is extended to 2D.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Filter2D {
    /// The 1D kernel.
    pub filter: Filter,
    /// Separable or radial.
    #[serde(default)]
    pub mode: Mode2D,
}

/// Gauss–Legendre nodes s_q ∈ \[0, r\] and weights W_q = 2π w_q h(s_q) s_q of a radial kernel,
/// with 16-point panels no wider than one period of J₀(2πρ_max s) (≈ 1/ρ_max), so that
/// H₂(ρ) = Σ W_q J₀(2πρ s_q) for every ρ ≤ ρ_max.
#[derive(Debug, Clone)]
pub struct HankelRule {
    nodes: Vec<f64>,
    weights: Vec<f64>,
    /// The largest ρ the rule resolves.
    pub rho_max: f64,
}

impl HankelRule {
    /// H₂(ρ) by the rule.
    pub fn eval(&self, rho: f64) -> f64 {
        let k = 2.0 * PI * rho;
        self.nodes
            .iter()
            .zip(&self.weights)
            .map(|(s, w)| w * bessel_j0(k * s))
            .sum()
    }
}

impl Filter2D {
    /// A validated 2D filter.
    pub fn new(filter: Filter, mode: Mode2D) -> Result<Filter2D, FilterError> {
        let f = Filter2D { filter, mode };
        f.validate()?;
        Ok(f)
    }

    /// The separable version of `filter` (not validated).
    pub fn separable(filter: Filter) -> Filter2D {
        Filter2D {
            filter,
            mode: Mode2D::Separable,
        }
    }

    /// The radial version of `filter` (not validated).
    pub fn radial(filter: Filter) -> Filter2D {
        Filter2D {
            filter,
            mode: Mode2D::Radial,
        }
    }

    /// Checks the kernel's parameters and that the mode applies to it.
    pub fn validate(&self) -> Result<(), FilterError> {
        self.filter.validate()?;
        if self.mode == Mode2D::Radial {
            if self.filter.parity() == Parity::Odd {
                return Err(FilterError::RadialUnsupported {
                    filter: self.filter.name(),
                    why: "an odd (derivative) kernel has no radial version; use mode = separable",
                });
            }
            if self.filter.dirac_weight() != 0.0 {
                return Err(FilterError::RadialUnsupported {
                    filter: self.filter.name(),
                    why: "its Dirac part δ(x) has no radial profile; use mode = separable",
                });
            }
        }
        Ok(())
    }

    /// The support radius in sample spacings: the weight is 0 where |d.x| > r or |d.y| > r
    /// (separable) or |d| > r (radial).
    pub fn support(&self) -> f64 {
        self.filter.radius()
    }

    /// h₂(p): h(x)h(y) or h(|p|), p in sample spacings. Dirac parts are not represented.
    pub fn eval2(&self, p: DVec2) -> f64 {
        match self.mode {
            Mode2D::Separable => self.filter.eval(p.x) * self.filter.eval(p.y),
            Mode2D::Radial => self.filter.eval(p.length()),
        }
    }

    /// The reconstruction weight w(d) of a sample at offset d (in units of the filter scale,
    /// i.e. sample spacings): [`Filter2D::eval2`]`(d)`.
    pub fn weight(&self, d: DVec2) -> f64 {
        self.eval2(d)
    }

    /// ∫∫ h₂: (∫h)² (separable) or 2π∫₀^r h(s) s ds (radial, adaptive quadrature).
    pub fn integral2(&self) -> f64 {
        match self.mode {
            Mode2D::Separable => {
                let i = self.filter.integral();
                i * i
            }
            Mode2D::Radial => {
                let f = self.filter;
                let v = quad::adaptive(
                    &mut |s| f.eval(s) * s,
                    &f.quad_breaks(),
                    0.5 * f.kernel().feature_scale(),
                    REL_TOL,
                    1e-300,
                );
                2.0 * PI * v.value
            }
        }
    }

    /// H₂ at radius ρ = |ω| of a radial filter by adaptive quadrature of the Hankel transform
    /// 2π∫₀^r h(s) J₀(2πρs) s ds (≈ 10⁻¹³ relative to ∫|h(s)| s ds). For a separable filter,
    /// H(ρ)H(0) (the profile along the ω_x axis).
    pub fn radial_response(&self, rho: f64) -> f64 {
        match self.mode {
            Mode2D::Separable => (self.filter.response(rho) * self.filter.response(0.0)).re,
            Mode2D::Radial => {
                if !rho.is_finite() {
                    return f64::NAN;
                }
                let f = self.filter;
                let mut width = 0.5 * f.kernel().feature_scale();
                if rho != 0.0 {
                    width = width.min(1.0 / rho.abs());
                }
                let k = 2.0 * PI * rho;
                let v = quad::adaptive(
                    &mut |s| f.eval(s) * s * bessel_j0(k * s),
                    &f.quad_breaks(),
                    width,
                    REL_TOL,
                    1e-300,
                );
                2.0 * PI * v.value
            }
        }
    }

    /// The 2D response H₂(ω), ω in cycles per sample.
    pub fn response2(&self, omega: DVec2) -> Complex64 {
        match self.mode {
            Mode2D::Separable => self.filter.response(omega.x) * self.filter.response(omega.y),
            Mode2D::Radial => Complex64::new(self.radial_response(omega.length()), 0.0),
        }
    }

    /// A Hankel quadrature rule valid for ρ ≤ `rho_max` (see [`HankelRule`]).
    pub fn hankel_rule(&self, rho_max: f64) -> HankelRule {
        let f = self.filter;
        let mut width = 0.5 * f.kernel().feature_scale();
        if rho_max.is_finite() && rho_max > 0.0 {
            width = width.min(1.0 / rho_max);
        }
        let rule = quad::adaptive_rule(
            &mut |s| f.eval(s) * s,
            &f.quad_breaks(),
            width,
            REL_TOL,
            1e-300,
        );
        let (nodes, weights) = rule
            .into_iter()
            .map(|(s, w)| (s, 2.0 * PI * w * f.eval(s) * s))
            .unzip();
        HankelRule {
            nodes,
            weights,
            rho_max,
        }
    }

    /// Why this filter cannot reconstruct a signal, as one line; `None` when it can. A
    /// normalised reconstruction Σw·f/Σw needs H₂(0) ≠ 0 ([`Filter2D::dc_normaliser`]) and a
    /// kernel that is not a derivative: band-pass, high-pass and cosc are refused, and so is
    /// any setting that makes H₂(0) vanish (a radial sinc cut at an even radius).
    pub fn reconstruction_refusal(&self) -> Option<String> {
        let name = self.filter.name();
        if self.filter.is_derivative() {
            return Some(format!(
                "{name} cannot reconstruct: it is a derivative kernel (H(0) = 0); use box, tent, gaussian, mitchell, sinc, windowed-sinc or low-pass"
            ));
        }
        match self.dc_normaliser() {
            Some(h0) if h0 > 0.0 => None,
            _ => {
                let how = match self.mode {
                    Mode2D::Separable => "",
                    Mode2D::Radial => " (radial)",
                };
                Some(format!(
                    "{name}{how} cannot reconstruct: H(0) = 0 with these settings (it blocks constants); use box, tent, gaussian, mitchell, sinc, windowed-sinc or low-pass"
                ))
            }
        }
    }

    /// ∫∫|h₂|, the scale against which a vanishing DC gain is judged.
    pub fn abs_integral2(&self) -> f64 {
        let f = self.filter;
        let k = f.kernel();
        let (g, w) = (|s: f64| k.eval(s).abs(), 0.5 * k.feature_scale());
        match self.mode {
            Mode2D::Separable => {
                let a = 2.0
                    * quad::adaptive(&mut |s| g(s), &f.quad_breaks(), w, 1e-8, 1e-300).value
                    + k.dirac_weight().abs();
                a * a
            }
            Mode2D::Radial => {
                2.0 * PI
                    * quad::adaptive(&mut |s| g(s) * s, &f.quad_breaks(), w, 1e-8, 1e-300).value
            }
        }
    }

    /// `Some(H₂(0))` when the 2D response can be normalised to 1 at DC: the kernel does not block
    /// DC by design and |H₂(0)| > 10⁻⁶ ∫∫|h₂| (a radial sinc truncated at an even radius, for
    /// example, has H₂(0) = 0).
    pub fn dc_normaliser(&self) -> Option<f64> {
        if self.filter.nominal_zero_dc() {
            return None;
        }
        let h0 = match self.mode {
            Mode2D::Separable => self.response2(DVec2::ZERO).re,
            Mode2D::Radial => self.integral2(),
        };
        (h0.is_finite() && h0.abs() > 1e-6 * self.abs_integral2()).then_some(h0)
    }

    /// The magnitude response |H₂(ω)| as a `size × size` image, row-major, divided by |H₂(0)|
    /// where [`Filter2D::dc_normaliser`] allows it.
    ///
    /// Pixel (i, j) (column i, row j) shows ω = ((i − ⌊size/2⌋)Δ, (j − ⌊size/2⌋)Δ) with
    /// Δ = 2ω_max/size: DC sits at pixel (⌊size/2⌋, ⌊size/2⌋) as in the centred periodogram, and
    /// the image covers \[−ω_max, ω_max) on each axis (row j = 0 is the most negative ω_y).
    /// Radial filters are evaluated once per distinct |ω|² (no interpolation) with a
    /// [`HankelRule`]: the cost is (number of distinct radii, ≈ size²/10) × (rule nodes, ≈ 16·r·ω_max√2
    /// for sinc-like kernels) Bessel evaluations; cancel through
    /// [`Filter2D::response_image_with`] (checked once per row).
    pub fn response_image(&self, size: usize, omega_max: f64) -> Result<Vec<f64>, FilterError> {
        self.response_image_with(size, omega_max, &Cancel::never())
    }

    /// As [`Filter2D::response_image`], cancellable.
    pub fn response_image_with(
        &self,
        size: usize,
        omega_max: f64,
        cancel: &Cancel,
    ) -> Result<Vec<f64>, FilterError> {
        self.validate()?;
        check_omega_max(omega_max)?;
        if size == 0 || size > MAX_IMAGE_SIZE {
            return Err(FilterError::InvalidArgument {
                field: "size",
                value: size.to_string(),
                allowed: format!("an integer in 1..={MAX_IMAGE_SIZE}"),
            });
        }
        let c = (size / 2) as i64;
        let delta = 2.0 * omega_max / size as f64;
        // Normalise by the DC value of the same evaluator, so that the DC pixel is exactly 1.
        let normalise = self.dc_normaliser().is_some();
        let mut out = vec![0.0; size * size];
        match self.mode {
            Mode2D::Separable => {
                let eval = self.filter.response_eval(omega_max);
                let half = c.max(size as i64 - 1 - c) as usize;
                let mut m = Vec::with_capacity(half + 1);
                for k in 0..=half {
                    if k % 256 == 0 {
                        cancel.check()?;
                    }
                    m.push(eval.eval(k as f64 * delta).norm());
                }
                let n1 = if normalise && m[0] > 0.0 { m[0] } else { 1.0 };
                for j in 0..size {
                    let mj = m[(j as i64 - c).unsigned_abs() as usize] / n1;
                    for i in 0..size {
                        out[j * size + i] = m[(i as i64 - c).unsigned_abs() as usize] / n1 * mj;
                    }
                }
            }
            Mode2D::Radial => {
                let rule = self.hankel_rule(omega_max * std::f64::consts::SQRT_2);
                let h0 = rule.eval(0.0).abs();
                let norm = if normalise && h0 > 0.0 { h0 } else { 1.0 };
                let mut values: HashMap<u64, f64> = HashMap::new();
                for j in 0..size {
                    cancel.check()?;
                    let dj = (j as i64 - c).unsigned_abs();
                    for i in 0..size {
                        let di = (i as i64 - c).unsigned_abs();
                        let key = di * di + dj * dj;
                        let v = *values
                            .entry(key)
                            .or_insert_with(|| rule.eval((key as f64).sqrt() * delta).abs() / norm);
                        out[j * size + i] = v;
                    }
                }
            }
        }
        Ok(out)
    }

    /// The response profile along the ω_x axis, `steps + 1` samples on \[0, ω_max\]: for separable
    /// filters the 1D curve H(ω)/H(0) ([`Filter::response_curve`]; raw H for zero-DC kernels);
    /// for radial filters H₂(ρ)/H₂(0) (raw where H₂(0) vanishes).
    pub fn response_profile(
        &self,
        omega_max: f64,
        steps: usize,
    ) -> Result<ResponseCurve, FilterError> {
        self.validate()?;
        match self.mode {
            Mode2D::Separable => self.filter.response_curve(omega_max, steps),
            Mode2D::Radial => {
                check_omega_max(omega_max)?;
                if steps == 0 || steps >= MAX_CURVE_SAMPLES {
                    return Err(FilterError::InvalidArgument {
                        field: "steps",
                        value: steps.to_string(),
                        allowed: format!("an integer in 1..{MAX_CURVE_SAMPLES}"),
                    });
                }
                let rule = self.hankel_rule(omega_max);
                let norm = self.dc_normaliser();
                let samples = (0..=steps)
                    .map(|i| {
                        let omega = omega_max * i as f64 / steps as f64;
                        let v = rule.eval(omega) / norm.unwrap_or(1.0);
                        ResponseSample::new(omega, Complex64::new(v, 0.0))
                    })
                    .collect();
                Ok(ResponseCurve {
                    samples,
                    normalised_by: norm.map(|v| Complex64::new(v, 0.0)),
                })
            }
        }
    }

    /// The four quality metrics with ω_max = [`metrics::OMEGA_MAX`].
    pub fn metrics(&self) -> Result<FilterMetrics, FilterError> {
        self.metrics_with(metrics::OMEGA_MAX, &Cancel::never())
    }

    /// The four quality metrics (definitions in the [module docs of `filter`](super)), with the
    /// post-aliasing energy integrated up to `omega_max`; cancellable.
    pub fn metrics_with(
        &self,
        omega_max: f64,
        cancel: &Cancel,
    ) -> Result<FilterMetrics, FilterError> {
        self.validate()?;
        check_omega_max(omega_max)?;
        let f = self.filter;
        let k = f.kernel();
        let r = f.radius();
        let ((smoothing, post_aliasing), (overshoot, undershoot), anisotropy) = match self.mode {
            Mode2D::Separable => {
                let eval: ResponseEval = f.response_eval(omega_max);
                let resp = |w: f64| eval.eval(w);
                let gain = if f.is_derivative() {
                    Gain::Derivative(derivative_gain(&f))
                } else {
                    Gain::Dc
                };
                let spectral = metrics::spectral_metrics(
                    &resp,
                    omega_max,
                    &k.frequency_breakpoints(),
                    gain,
                    cancel,
                )?;
                let step = metrics::step_extremes(
                    &|x| k.eval(x),
                    r,
                    &k.breakpoints(),
                    k.dirac_weight(),
                    k.nominal_zero_dc(),
                    k.feature_scale(),
                    cancel,
                )?;
                cancel.check()?;
                (spectral, step, metrics::separable_anisotropy(&resp))
            }
            Mode2D::Radial => {
                let rule = self.hankel_rule(omega_max);
                let resp = |w: f64| Complex64::new(rule.eval(w), 0.0);
                let spectral = metrics::spectral_metrics(&resp, omega_max, &[], Gain::Dc, cancel)?;
                let breaks = k.breakpoints();
                // Absolute floor of the projections' quadrature: 1e-12 of ∫₀^r |h| (near |x| = r
                // the projection is tiny and its relative accuracy irrelevant to the extrema).
                let floor = 1e-12
                    * quad::adaptive(
                        &mut |s| k.eval(s).abs(),
                        &f.quad_breaks(),
                        0.5 * k.feature_scale(),
                        1e-8,
                        1e-300,
                    )
                    .value;
                let proj = |x: f64| abel_projection(&f, &breaks, x, floor);
                let step = metrics::step_extremes(
                    &proj,
                    r,
                    &breaks,
                    0.0,
                    k.nominal_zero_dc(),
                    k.feature_scale(),
                    cancel,
                )?;
                (spectral, step, 0.0)
            }
        };
        Ok(FilterMetrics {
            smoothing,
            post_aliasing,
            ringing: overshoot.max(undershoot),
            overshoot,
            undershoot,
            anisotropy,
            omega_max,
        })
    }
}

/// D = |∫ x h(x) dx| = |H'(0)|/(2π): the gain of a derivative kernel (1 for the untruncated cosc).
pub fn derivative_gain(f: &Filter) -> f64 {
    let k = f.kernel();
    let v = quad::adaptive(
        &mut |x| x * k.eval(x),
        &f.quad_breaks(),
        0.5 * k.feature_scale(),
        REL_TOL,
        1e-300,
    );
    match k.parity() {
        Parity::Odd => (2.0 * v.value).abs(),
        Parity::Even => 0.0,
    }
}

/// The Abel projection m(x) = ∫ h(√(x² + y²)) dy = 2∫₀^{√(r²−x²)} h(√(x²+y²)) dy of a radial
/// kernel (the line-spread function across an edge parallel to y), by adaptive quadrature to
/// relative 10⁻¹⁰ or absolute `abs_floor`, whichever is larger. `breaks` are the kernel's
/// breakpoints in (0, r).
pub fn abel_projection(f: &Filter, breaks: &[f64], x: f64, abs_floor: f64) -> f64 {
    let r = f.radius();
    let ax = x.abs();
    if ax >= r {
        return 0.0;
    }
    let ymax = (r * r - ax * ax).sqrt();
    let mut yb = vec![0.0];
    for &b in breaks {
        if b > ax && b < r {
            yb.push((b * b - ax * ax).sqrt());
        }
    }
    yb.push(ymax);
    yb.sort_by(f64::total_cmp);
    yb.dedup();
    // In y the kernel varies no faster than in s = √(x² + y²) (ds/dy ≤ 1): panels of one
    // feature scale (≤ half an oscillation) suffice for the 16-point rule.
    let width = f.kernel().feature_scale();
    let v = quad::adaptive(
        &mut |y| f.eval((ax * ax + y * y).sqrt()),
        &yb,
        width,
        1e-10,
        abs_floor,
    );
    2.0 * v.value
}
