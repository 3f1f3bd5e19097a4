//! Reconstruction filters in the spatial and the frequency domain.
//!
//! ## Conventions
//! - A kernel h(x) is a function of x **in units of the sample spacing**, with a radius r:
//!   h(x) = 0 for |x| > r. Its support is closed (h(±r) takes the inside value, as in pbrt).
//! - Frequencies ω are in **cycles per sample**: the Nyquist frequency of unit-spaced samples is
//!   ½. The frequency response is H(ω) = ∫ h(x) e^{−2πiωx} dx (so a box of radius ½ has
//!   H = sinc(ω) and the ideal low-pass with cutoff ½ is sinc(x)).
//! - Kernels are not normalised to ∫h = 1 (box and tent have peak 1, pbrt style);
//!   [`Filter::integral`] gives ∫h, and displayed responses are divided by H(0) wherever H(0) ≠ 0
//!   ([`Filter::response_curve`]).
//! - 2D filters ([`Filter2D`]) are separable h(x)h(y) or radial h(|p|); their responses are
//!   H(ω_x)H(ω_y) or the Hankel transform 2π∫₀^r h(s) J₀(2π|ω|s) s ds.
//!
//! ## The filters
//! One small `Copy` parameter struct per kernel, dispatched by the [`Filter`] enum (serde-tagged
//! by `kind`, like [`crate::core::pattern::Pattern`]). Each has the uniform interface of
//! [`Kernel`] (pbrt-v4 `filters.h` style): `radius`, `eval`, `eval_derivative`, `integral`,
//! `response`.
//!
//! | name | h(x) on \|x\| ≤ r | H(ω) |
//! |---|---|---|
//! | `box` | 1 | 2r sinc(2rω) (closed form) |
//! | `tent` | 1 − \|x\|/r | r sinc²(rω) (closed form) |
//! | `gaussian` | e^{−x²/2σ²} (− e^{−r²/2σ²} if `subtract_edge`) | numeric; closed form σ√(2π)e^{−2π²σ²ω²} of the untruncated kernel with error ≤ tail mass σ√(2π) erfc(r/σ√2) |
//! | `mitchell` | Mitchell–Netravali k_{B,C}(2x/r) | numeric |
//! | `sinc` | sinc(x) | (Si(π(1+2ω)r) + Si(π(1−2ω)r))/π (closed form) |
//! | `windowed-sinc` | sinc(x) w(x/r), w ∈ rect, Lanczos, Hann, Blackman, Kaiser(β) | closed form for rect/Hann/Blackman (modulation), numeric for Lanczos/Kaiser |
//! | `cosc` | cosc(x) w(x/r) (derivative kernel; w = rect: truncated) | closed form for rect/Hann/Blackman, numeric otherwise; ideal 2πiω on \|ω\| < ½ |
//! | `low-pass` | 2c sinc(2cx), truncated to `radius` | exact ideal: 1 on \|ω\| < c |
//! | `band-pass` | 2h sinc(2hx) − 2l sinc(2lx), truncated | exact ideal: 1 on l < \|ω\| < h |
//! | `high-pass` | δ(x) − 2c sinc(2cx), sinc part truncated | exact ideal: 1 on \|ω\| > c |
//!
//! Ideal filters are *defined* in the frequency domain: [`Filter::response`] is their exact
//! ideal response (½ exactly on a band edge); their spatial kernels have infinite support and
//! are truncated at the documented `radius` parameter (default [`kernels::IDEAL_RADIUS`] = 16
//! sample spacings) for spatial evaluation, ringing and 2D weights.
//!
//! ## Numeric responses
//! [`Filter::response_numeric`] integrates h(x)e^{−2πiωx} over \[−r, r\] with adaptive
//! Gauss–Legendre quadrature ([`quad`]), using the kernel's symmetry (even: 2∫₀^r h cos,
//! odd: −2i∫₀^r h sin), panels split at every kink of h, no wider than half its feature scale
//! and one period of the exponential, refined until the estimated error is below
//! 10⁻¹³·∫|h|. Tests check it against every closed form to 10⁻⁹ (relative to ∫|h|).
//!
//! ## Quality metrics ([`FilterMetrics`], the lecture's "possible errors")
//! With A(ω) = |H(ω)|/|H(0)| the normalised magnitude (for the derivative kernel `cosc`:
//! A(ω) = |H(ω)|/(2π|ω|·D), D = |∫x h(x) dx| its derivative gain; when H(0) vanishes —
//! band-pass, high-pass — A = |H|/max|H|):
//! - **smoothing** = 1 − (1/0.5)∫₀^{0.5} A(ω) dω: the mean pass-band loss below Nyquist
//!   (0 for the ideal low-pass at ½, 1 − 2c for a low-pass at c < ½; negative if the filter
//!   amplifies).
//! - **post_aliasing** = ∫_{0.5}^{ω_max} |H|² dω / ∫₀^{ω_max} |H|² dω: the fraction of the
//!   response energy above Nyquist, which replicas of the sampled spectrum leak into the
//!   reconstruction. ω_max = [`metrics::OMEGA_MAX`] = 4 cycles per sample.
//! - **ringing**: the step response S(x) = ∫_{−r}^x h / ∫h overshoots: `overshoot` =
//!   max S − 1, `undershoot` = −min S, `ringing` = the larger of the two (symmetric kernels have
//!   both equal). For kernels with zero DC (cosc, band-, high-pass) S is normalised by its
//!   largest excursion and ringing is the largest excursion of the opposite sign.
//! - **anisotropy** of the 2D response: max over radii 0 < ρ < 0.5 of
//!   (max − min)/mean over angles of |H₂(ρ cos θ, ρ sin θ)|; 0 for radial filters (by symmetry).
//!
//! See [`metrics`] for the discretisation and its accuracy.

pub mod cost;
pub mod kernels;
pub mod metrics;
pub mod quad;
pub mod special;
pub mod two_d;

pub use kernels::{
    BandPass, BoxFilter, ClosedForm, Cosc, Gaussian, HighPass, Kernel, LowPass, Mitchell, Parity,
    Sinc, Tent, Window, WindowedSinc, MAX_RADIUS,
};
pub use metrics::FilterMetrics;
pub use two_d::{Filter2D, Mode2D};

use crate::core::cancel::Cancelled;
use crate::core::family::{family, UnknownName};
use crate::core::params::{ParamError, Params};
use rustfft::num_complex::Complex64;

use special::{cos_pi, sin_pi};

/// Relative tolerance (times ∫|integrand|) of the numeric responses and integrals.
pub const REL_TOL: f64 = 1e-13;

/// Why a filter could not be built or evaluated. Every variant names the field and what is
/// allowed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum FilterError {
    /// A parameter is out of range, not finite, or malformed.
    #[error("{filter}.{field} = {value}: must be {allowed}")]
    InvalidParam {
        filter: &'static str,
        field: &'static str,
        value: String,
        allowed: String,
    },
    /// The filter name is not known.
    #[error(transparent)]
    UnknownFilter(#[from] UnknownName),
    /// The parameter key is not known for this filter.
    #[error("{filter}: unknown parameter '{key}': allowed parameters are [{allowed}]")]
    UnknownParam {
        filter: &'static str,
        key: String,
        allowed: String,
    },
    /// An argument of a computation (image size, frequency range, …) is out of range.
    #[error("{field} = {value}: must be {allowed}")]
    InvalidArgument {
        field: &'static str,
        value: String,
        allowed: String,
    },
    /// The filter has no radial 2D version.
    #[error("{filter}: mode = radial is not available: {why}")]
    RadialUnsupported {
        filter: &'static str,
        why: &'static str,
    },
    /// The computation was cancelled.
    #[error("cancelled")]
    Cancelled,
}

impl From<ParamError> for FilterError {
    fn from(e: ParamError) -> Self {
        match e {
            ParamError::Unknown {
                owner,
                key,
                allowed,
            } => FilterError::UnknownParam {
                filter: owner,
                key,
                allowed,
            },
            ParamError::Invalid {
                owner,
                field,
                value,
                allowed,
            } => FilterError::InvalidParam {
                filter: owner,
                field,
                value,
                allowed,
            },
        }
    }
}

impl From<Cancelled> for FilterError {
    fn from(_: Cancelled) -> Self {
        FilterError::Cancelled
    }
}

family! {
    /// Every reconstruction filter, as a small parameter struct per variant.
    Filter = "filter", "filters" {
        Box(BoxFilter) = "box",
        Tent(Tent) = "tent",
        Gaussian(Gaussian) = "gaussian",
        Mitchell(Mitchell) = "mitchell",
        Sinc(Sinc) = "sinc",
        WindowedSinc(WindowedSinc) = "windowed-sinc",
        Cosc(Cosc) = "cosc",
        LowPass(LowPass) = "low-pass",
        BandPass(BandPass) = "band-pass",
        HighPass(HighPass) = "high-pass",
    }
    dyn Kernel => kernel;
    impl {
        /// Named presets: catmull-rom, b-spline, lanczos, kaiser.
        fn presets() -> Vec<(&'static str, &'static str, Filter)> {
            vec![
                (
                    "catmull-rom",
                    "Mitchell B = 0, C = ½ (interpolating cubic)",
                    Filter::Mitchell(Mitchell::catmull_rom()),
                ),
                (
                    "b-spline",
                    "Mitchell B = 1, C = 0 (cubic B-spline, no ringing)",
                    Filter::Mitchell(Mitchell::b_spline()),
                ),
                (
                    "lanczos",
                    "windowed sinc, Lanczos window, radius 3",
                    Filter::WindowedSinc(WindowedSinc {
                        radius: 3.0,
                        window: Window::Lanczos,
                    }),
                ),
                (
                    "kaiser",
                    "windowed sinc, Kaiser window β = 4, radius 4",
                    Filter::WindowedSinc(WindowedSinc {
                        radius: 4.0,
                        window: Window::Kaiser { beta: 4.0 },
                    }),
                ),
            ]
        }

        /// The parameters that apply now, and the Kaiser window's `beta` of a windowed sinc
        /// or cosc whose window is another one.
        fn listed_specs(&self) -> Vec<crate::core::params::ParamSpec> {
            let mut kaiser = *self;
            if let Filter::WindowedSinc(_) | Filter::Cosc(_) = self {
                // Show the Kaiser-only parameter too.
                let _ = kaiser.set("window", "kaiser");
            }
            kaiser.specs()
        }
    }
}

impl Filter {
    /// Checks every parameter (finite, in range, cross-field constraints).
    pub fn validate(&self) -> Result<(), FilterError> {
        Ok(self.check_params()?)
    }
}

impl Default for Filter {
    fn default() -> Self {
        Filter::Mitchell(Mitchell::default())
    }
}

/// A response sample: ω (cycles per sample), the (normalised) complex response, its magnitude
/// and its phase in radians in (−π, π].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ResponseSample {
    /// Frequency in cycles per sample.
    pub omega: f64,
    /// The response value (divided by H(0) when the curve is normalised).
    pub value: Complex64,
    /// |value|.
    pub magnitude: f64,
    /// arg(value) in (−π, π] (0 for a zero value).
    pub phase: f64,
}

impl ResponseSample {
    /// A sample from its value; a −0 imaginary part counts as +0 so real negatives have phase π.
    pub fn new(omega: f64, value: Complex64) -> Self {
        let im = if value.im == 0.0 { 0.0 } else { value.im };
        let re = if value.re == 0.0 { 0.0 } else { value.re };
        ResponseSample {
            omega,
            value,
            magnitude: value.norm(),
            phase: im.atan2(re),
        }
    }
}

/// A response curve: samples from ω = 0 to ω_max and whether they were divided by H(0).
#[derive(Debug, Clone, PartialEq)]
pub struct ResponseCurve {
    /// The samples, ω increasing.
    pub samples: Vec<ResponseSample>,
    /// `Some(H(0))` when every value was divided by it; `None` for zero-DC filters (raw H).
    pub normalised_by: Option<Complex64>,
}

/// The most samples a response curve may have.
pub const MAX_CURVE_SAMPLES: usize = 1 << 20;

/// Largest ω_max accepted by curves, images and metrics (cycles per sample).
pub const MAX_OMEGA: f64 = 64.0;

/// Checks `0 < omega_max ≤ MAX_OMEGA`.
pub fn check_omega_max(omega_max: f64) -> Result<(), FilterError> {
    if !omega_max.is_finite() || omega_max <= 0.0 || omega_max > MAX_OMEGA {
        return Err(FilterError::InvalidArgument {
            field: "omega_max",
            value: crate::core::params::fmt_num(omega_max),
            allowed: format!("a finite number in (0, {MAX_OMEGA}] (cycles per sample)"),
        });
    }
    Ok(())
}

/// A response evaluator for many frequencies up to a bound: the ideal response, an exact closed
/// form, or a precomputed quadrature rule ([`ResponseRule`]).
#[derive(Debug, Clone)]
pub enum ResponseEval {
    /// Evaluate `Filter::response` directly (ideal or exact closed form: cheap).
    Direct(Filter),
    /// A fixed quadrature rule for a kernel without a closed form.
    Rule(ResponseRule),
}

impl ResponseEval {
    /// H(ω).
    pub fn eval(&self, omega: f64) -> Complex64 {
        match self {
            ResponseEval::Direct(f) => f.response(omega),
            ResponseEval::Rule(r) => r.eval(omega),
        }
    }
}

/// Gauss–Legendre nodes x_q ∈ \[0, r\] and weights W_q = 2 w_q h(x_q) of a kernel, chosen
/// adaptively for h with 16-point panels no wider than one period at ω_max, so that
/// H(ω) = δ + Σ W_q cos(2πωx_q) (even) or −i Σ W_q sin(2πωx_q) (odd) for every |ω| ≤ ω_max at the
/// accuracy of [`Filter::response_numeric`], at the cost of one sum per ω.
#[derive(Debug, Clone)]
pub struct ResponseRule {
    nodes: Vec<f64>,
    weights: Vec<f64>,
    parity: Parity,
    dirac: f64,
    /// The largest |ω| the rule resolves.
    pub omega_max: f64,
}

impl ResponseRule {
    /// H(ω) by the rule.
    pub fn eval(&self, omega: f64) -> Complex64 {
        let mut s = 0.0;
        match self.parity {
            Parity::Even => {
                for (x, w) in self.nodes.iter().zip(&self.weights) {
                    s += w * cos_pi(2.0 * omega * x);
                }
                Complex64::new(s + self.dirac, 0.0)
            }
            Parity::Odd => {
                for (x, w) in self.nodes.iter().zip(&self.weights) {
                    s += w * sin_pi(2.0 * omega * x);
                }
                Complex64::new(0.0, -s)
            }
        }
    }

    /// Number of nodes.
    pub fn len(&self) -> usize {
        self.nodes.len()
    }

    /// Whether the rule has no nodes.
    pub fn is_empty(&self) -> bool {
        self.nodes.is_empty()
    }
}

impl Filter {
    /// Radius r in sample spacings (h = 0 for |x| > r).
    pub fn radius(&self) -> f64 {
        self.kernel().radius()
    }

    /// h(x), x in sample spacings.
    pub fn eval(&self, x: f64) -> f64 {
        self.kernel().eval(x)
    }

    /// h'(x) (derivative of the smooth pieces; mean of one-sided values at kinks).
    pub fn eval_derivative(&self, x: f64) -> f64 {
        self.kernel().eval_derivative(x)
    }

    /// Even or odd kernel.
    pub fn parity(&self) -> Parity {
        self.kernel().parity()
    }

    /// The weight of a Dirac mass at 0 (1 for the ideal high-pass, 0 otherwise).
    pub fn dirac_weight(&self) -> f64 {
        self.kernel().dirac_weight()
    }

    /// Whether the kernel approximates a derivative (cosc).
    pub fn is_derivative(&self) -> bool {
        self.kernel().is_derivative()
    }

    /// Whether the filter blocks DC by design (cosc, high-pass, band-pass with low > 0).
    pub fn nominal_zero_dc(&self) -> bool {
        self.kernel().nominal_zero_dc()
    }

    /// Quadrature breakpoints on \[0, r\]: 0, the kernel's interior breakpoints, r.
    pub fn quad_breaks(&self) -> Vec<f64> {
        let k = self.kernel();
        let r = k.radius();
        let mut v = vec![0.0];
        v.extend(k.breakpoints().into_iter().filter(|&b| b > 0.0 && b < r));
        v.push(r);
        v
    }

    /// Largest quadrature panel for the kernel alone: half its feature scale.
    fn panel_width(&self) -> f64 {
        0.5 * self.kernel().feature_scale()
    }

    /// ∫h over \[−r, r\] (including a Dirac mass): closed form where one exists, otherwise
    /// adaptive quadrature ([`Filter::integral_numeric`]).
    pub fn integral(&self) -> f64 {
        self.kernel()
            .integral_closed_form()
            .unwrap_or_else(|| self.integral_numeric())
    }

    /// ∫h by adaptive Gauss–Legendre quadrature (relative accuracy ≈ 10⁻¹³ of ∫|h|).
    pub fn integral_numeric(&self) -> f64 {
        match self.parity() {
            Parity::Odd => 0.0,
            Parity::Even => {
                let k = self.kernel();
                let v = quad::adaptive(
                    &mut |x| k.eval(x),
                    &self.quad_breaks(),
                    self.panel_width(),
                    REL_TOL,
                    1e-300,
                );
                2.0 * v.value + k.dirac_weight()
            }
        }
    }

    /// The frequency response H(ω), ω in cycles per sample.
    ///
    /// Ideal filters: their exact ideal response. Kernels with an exact closed form (box, tent,
    /// sinc, rect/Hann/Blackman-windowed sinc and cosc): the closed form. Others (Gaussian,
    /// Mitchell, Lanczos, Kaiser): [`Filter::response_numeric`] — the exact transform of the
    /// kernel as evaluated (the truncated Gaussian, not the untruncated closed form).
    pub fn response(&self, omega: f64) -> Complex64 {
        let k = self.kernel();
        if let Some(v) = k.response_ideal(omega) {
            return v;
        }
        match k.response_closed_form(omega) {
            Some(c) if c.error_bound == 0.0 => c.value,
            _ => self.response_numeric(omega),
        }
    }

    /// (|H(ω)|, arg H(ω)) with the phase in radians in (−π, π] (unnormalised).
    pub fn response_polar(&self, omega: f64) -> (f64, f64) {
        let s = ResponseSample::new(omega, self.response(omega));
        (s.magnitude, s.phase)
    }

    /// The closed form of the transform of the spatial kernel as evaluated, with its error bound
    /// (for the ideal filters: the transform of the *truncated* sinc combination).
    pub fn response_closed_form(&self, omega: f64) -> Option<ClosedForm> {
        self.kernel().response_closed_form(omega)
    }

    /// The ideal response of a frequency-domain filter (`None` for spatial kernels).
    pub fn response_ideal(&self, omega: f64) -> Option<Complex64> {
        self.kernel().response_ideal(omega)
    }

    /// ∫_{−r}^{r} h(x) e^{−2πiωx} dx (+ Dirac weight) by adaptive Gauss–Legendre quadrature, to
    /// ≈ 10⁻¹³·∫|h| (see the module docs). NaN for non-finite ω.
    pub fn response_numeric(&self, omega: f64) -> Complex64 {
        if !omega.is_finite() {
            return Complex64::new(f64::NAN, f64::NAN);
        }
        let k = self.kernel();
        let mut width = self.panel_width();
        if omega != 0.0 {
            // One period of the exponential per panel (see `quad::adaptive_rule` for the error).
            width = width.min(1.0 / omega.abs());
        }
        let breaks = self.quad_breaks();
        match k.parity() {
            Parity::Even => {
                let v = quad::adaptive(
                    &mut |x| k.eval(x) * cos_pi(2.0 * omega * x),
                    &breaks,
                    width,
                    REL_TOL,
                    1e-300,
                );
                Complex64::new(2.0 * v.value + k.dirac_weight(), 0.0)
            }
            Parity::Odd => {
                let v = quad::adaptive(
                    &mut |x| k.eval(x) * sin_pi(2.0 * omega * x),
                    &breaks,
                    width,
                    REL_TOL,
                    1e-300,
                );
                Complex64::new(0.0, -2.0 * v.value)
            }
        }
    }

    /// A quadrature rule valid for |ω| ≤ `omega_max` (see [`ResponseRule`]).
    pub fn response_rule(&self, omega_max: f64) -> ResponseRule {
        let k = self.kernel();
        let mut width = self.panel_width();
        if omega_max.is_finite() && omega_max > 0.0 {
            // At most one period of e^{−2πiωx} per 16-point panel for |ω| ≤ ω_max.
            width = width.min(1.0 / omega_max);
        }
        let rule = quad::adaptive_rule(
            &mut |x| k.eval(x),
            &self.quad_breaks(),
            width,
            REL_TOL,
            1e-300,
        );
        let mut nodes = Vec::with_capacity(rule.len());
        let mut weights = Vec::with_capacity(rule.len());
        for (x, w) in rule {
            nodes.push(x);
            weights.push(2.0 * w * k.eval(x));
        }
        ResponseRule {
            nodes,
            weights,
            parity: k.parity(),
            dirac: k.dirac_weight(),
            omega_max,
        }
    }

    /// The cheapest accurate evaluator of H for |ω| ≤ `omega_max`: direct when H is ideal or in
    /// exact closed form, otherwise a [`ResponseRule`].
    pub fn response_eval(&self, omega_max: f64) -> ResponseEval {
        let k = self.kernel();
        let direct = k.response_ideal(0.0).is_some()
            || matches!(k.response_closed_form(0.0), Some(c) if c.error_bound == 0.0);
        if direct {
            ResponseEval::Direct(*self)
        } else {
            ResponseEval::Rule(self.response_rule(omega_max))
        }
    }

    /// `Some(H(0))` when the response can be normalised to H(0) = 1: the filter does not block
    /// DC by design and |H(0)| > 10⁻⁹·∫|h|.
    pub fn dc_normaliser(&self) -> Option<Complex64> {
        if self.nominal_zero_dc() {
            return None;
        }
        let h0 = self.response(0.0);
        let k = self.kernel();
        let abs_int = quad::adaptive(
            &mut |x| k.eval(x).abs(),
            &self.quad_breaks(),
            self.panel_width(),
            1e-8,
            1e-300,
        )
        .value
            * 2.0
            + k.dirac_weight().abs();
        (h0.norm() > 1e-9 * abs_int && h0.norm().is_finite()).then_some(h0)
    }

    /// `steps + 1` samples of H from ω = 0 to `omega_max` (step omega_max/steps), divided by
    /// H(0) where [`Filter::dc_normaliser`] allows it.
    pub fn response_curve(
        &self,
        omega_max: f64,
        steps: usize,
    ) -> Result<ResponseCurve, FilterError> {
        self.validate()?;
        check_omega_max(omega_max)?;
        if steps == 0 || steps >= MAX_CURVE_SAMPLES {
            return Err(FilterError::InvalidArgument {
                field: "steps",
                value: steps.to_string(),
                allowed: format!("an integer in 1..{MAX_CURVE_SAMPLES}"),
            });
        }
        let eval = self.response_eval(omega_max);
        let norm = self.dc_normaliser();
        let samples = (0..=steps)
            .map(|i| {
                let omega = omega_max * i as f64 / steps as f64;
                let mut v = eval.eval(omega);
                if let Some(h0) = norm {
                    v /= h0;
                }
                ResponseSample::new(omega, v)
            })
            .collect();
        Ok(ResponseCurve {
            samples,
            normalised_by: norm,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip_and_are_unique() {
        let all = Filter::all();
        for f in &all {
            assert_eq!(Filter::from_name(f.name()).map(|g| g.name()), Ok(f.name()));
            assert!(f.validate().is_ok(), "{} defaults invalid", f.name());
        }
        let mut names: Vec<_> = all.iter().map(|f| f.name()).collect();
        names.sort();
        names.dedup();
        assert_eq!(names.len(), all.len());
        assert!(matches!(Filter::from_name("nope"), Err(UnknownName { .. })));
        assert_eq!(
            Filter::from_name("Catmull-Rom"),
            Ok(Filter::Mitchell(Mitchell::catmull_rom()))
        );
    }

    #[test]
    fn serde_round_trip_every_filter() {
        let mut all = Filter::all();
        all.extend(Filter::presets().into_iter().map(|(_, _, f)| f));
        for f in all {
            let s = serde_json::to_string(&f).expect("serialise");
            let back: Filter = serde_json::from_str(&s).expect("deserialise");
            assert_eq!(back, f, "{s}");
        }
        let k: Filter = serde_json::from_str(
            r#"{"kind":"windowed-sinc","radius":2,"window":{"kind":"kaiser","beta":6}}"#,
        )
        .expect("parse");
        assert_eq!(
            k,
            Filter::WindowedSinc(WindowedSinc {
                radius: 2.0,
                window: Window::Kaiser { beta: 6.0 }
            })
        );
    }

    #[test]
    fn response_polar_of_the_tent_is_sinc_squared_with_zero_phase() {
        let t = Filter::Tent(Tent { radius: 2.0 });
        let (m, p) = t.response_polar(0.3);
        let s = special::sinc(0.6);
        assert!((m - 2.0 * s * s).abs() < 1e-15);
        assert_eq!(p, 0.0);
        let (_, p) = Filter::Cosc(Cosc::default()).response_polar(0.2);
        assert!(
            (p + std::f64::consts::FRAC_PI_2).abs() < 1e-15
                || (p - std::f64::consts::FRAC_PI_2).abs() < 1e-15
        );
    }

    #[test]
    fn response_sample_phase_of_negative_real_is_pi() {
        let s = ResponseSample::new(0.7, Complex64::new(-0.2, -0.0));
        assert_eq!(s.phase, std::f64::consts::PI);
        assert_eq!(s.magnitude, 0.2);
    }
}
