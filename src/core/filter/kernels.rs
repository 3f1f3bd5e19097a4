//! The 1D kernels: parameter structs, their spatial definition h(x), derivative h'(x), integral
//! and the closed forms of their Fourier transforms.
//!
//! Units: x in sample spacings, ω in cycles per sample; H(ω) = ∫ h(x) e^{−2πiωx} dx.
//! Every kernel is 0 for |x| > radius. At a jump discontinuity the kernel takes its inside value
//! (support closed, as in pbrt); at a kink [`Kernel::eval_derivative`] returns the mean of the
//! two one-sided derivatives. Jumps (box edges, truncated sinc and cosc, Kaiser window edges)
//! are *not* represented in the derivative as Dirac masses: `eval_derivative` is the derivative
//! of the smooth pieces.
//!
//! Closed forms used (T_r is the transform of sinc truncated to \[−r, r\], Si the sine integral):
//!
//! | kernel | H(ω) |
//! |---|---|
//! | box, radius r | 2r sinc(2rω) |
//! | tent 1 − \|x\|/r | r sinc²(rω) |
//! | Gaussian e^{−x²/2σ²} (untruncated) | σ√(2π) e^{−2π²σ²ω²} |
//! | sinc truncated to r | T_r(ω) = (Si(π(1+2ω)r) + Si(π(1−2ω)r))/π |
//! | cosc truncated to r | i(2πω T_r(ω) − 2 sinc(r) sin(2πωr)) (integration by parts) |
//! | sinc or cosc × Hann / Blackman window | Σ_m a_m K(ω − m/(2r)) (modulation: cos(πmx/r) shifts by ±m/(2r)) |
//! | ideal low-pass 2c sinc(2cx) truncated to R | T_{2cR}(ω/2c) |

use super::special::{
    bessel_i0, bessel_i1_over_x, cos_pi, cosc, erf, erfc, sin_pi, sinc, sinc_d2, sine_integral,
};
use crate::core::params::{
    declare_params, fmt_num, ParamError, ParamKind, ParamSpec, ParamValue, Params,
};
use rustfft::num_complex::Complex64;
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// Largest radius (in sample spacings) of any kernel.
pub const MAX_RADIUS: f64 = 64.0;
/// Smallest radius accepted by validation.
pub const MIN_RADIUS: f64 = 1e-3;
/// Largest absolute distance of a kernel's [`Kernel::eval_many`] from [`Kernel::eval`]
/// (4·2⁻⁵³): the Gaussian's one-exponential form; every other kernel's is 0.
pub const EVAL_MANY_ABS_ERROR: f64 = 4.0 * f64::EPSILON / 2.0;

/// Symmetry of a kernel.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Parity {
    /// h(−x) = h(x): H is real.
    Even,
    /// h(−x) = −h(x): H is imaginary.
    Odd,
}

/// A closed-form frequency response with a bound on its deviation from the transform of the
/// kernel as evaluated (0 when it is exact up to rounding).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ClosedForm {
    /// The closed-form value.
    pub value: Complex64,
    /// |value − ∫h(x)e^{−2πiωx}dx| ≤ error_bound (plus rounding, ~1e-15·∫|h|).
    pub error_bound: f64,
}

impl ClosedForm {
    fn exact(value: Complex64) -> Self {
        ClosedForm {
            value,
            error_bound: 0.0,
        }
    }
}

/// The uniform interface of a 1D kernel (pbrt-v4 `filters.h` style, plus frequency data).
pub trait Kernel {
    /// Radius r: h(x) = 0 for |x| > r (sample spacings). For the ideal filters, the documented
    /// truncation radius of their infinite spatial kernel.
    fn radius(&self) -> f64;
    /// h(x), finite for every finite x.
    fn eval(&self, x: f64) -> f64;
    /// h at each of `xs`, in place: what the reconstruction's splat calls for its separable
    /// factors (2(2r+1) a sample). The default is [`Kernel::eval`] on each; a kernel may
    /// override it with a cheaper form whose distance to `eval` it documents and tests (the
    /// Gaussian's, at most [`EVAL_MANY_ABS_ERROR`] absolute).
    fn eval_many(&self, xs: &mut [f64]) {
        for x in xs {
            *x = self.eval(*x);
        }
    }
    /// h'(x) of the smooth pieces (see the module docs for kinks and jumps).
    fn eval_derivative(&self, x: f64) -> f64;
    /// Even or odd.
    fn parity(&self) -> Parity {
        Parity::Even
    }
    /// Weight of a Dirac mass at x = 0 that `eval` cannot represent (the ideal high-pass).
    fn dirac_weight(&self) -> f64 {
        0.0
    }
    /// Points of (0, r), sorted, where h is not smooth or changes its length scale: every
    /// quadrature panel boundary.
    fn breakpoints(&self) -> Vec<f64> {
        Vec::new()
    }
    /// Shortest length over which h varies appreciably (quadrature panels are at most half of it).
    fn feature_scale(&self) -> f64;
    /// ∫h in closed form, where one exists.
    fn integral_closed_form(&self) -> Option<f64> {
        None
    }
    /// The Fourier transform of h as evaluated, in closed form, where one exists.
    fn response_closed_form(&self, omega: f64) -> Option<ClosedForm> {
        let _ = omega;
        None
    }
    /// For filters defined in the frequency domain: their exact (ideal) response.
    fn response_ideal(&self, omega: f64) -> Option<Complex64> {
        let _ = omega;
        None
    }
    /// Frequencies where the response is not smooth (ideal filters' edges).
    fn frequency_breakpoints(&self) -> Vec<f64> {
        Vec::new()
    }
    /// Whether the filter blocks DC by design (derivative, band-pass, high-pass).
    fn nominal_zero_dc(&self) -> bool {
        false
    }
    /// Whether the kernel approximates a derivative (ideal response 2πiω).
    fn is_derivative(&self) -> bool {
        false
    }
}

/// Applies `inner` inside the support, half of it at |x| = r, 0 outside (derivative convention).
#[inline]
fn inside_derivative(x: f64, r: f64, inner: impl Fn(f64) -> f64) -> f64 {
    let ax = x.abs();
    if ax < r {
        inner(x)
    } else if ax == r {
        0.5 * inner(x)
    } else {
        0.0
    }
}

/// T_r(ω) = ∫_{−r}^{r} sinc(x) e^{−2πiωx} dx = (Si(π(1+2ω)r) + Si(π(1−2ω)r))/π (real, even).
pub fn truncated_sinc_response(r: f64, omega: f64) -> f64 {
    (sine_integral(PI * (1.0 + 2.0 * omega) * r) + sine_integral(PI * (1.0 - 2.0 * omega) * r)) / PI
}

/// ∫_{−r}^{r} cosc(x) e^{−2πiωx} dx = i(2πω T_r(ω) − 2 sinc(r) sin(2πωr)) (imaginary, odd).
pub fn truncated_cosc_response(r: f64, omega: f64) -> Complex64 {
    let v = 2.0 * PI * omega * truncated_sinc_response(r, omega)
        - 2.0 * sinc(r) * sin_pi(2.0 * omega * r);
    Complex64::new(0.0, v)
}

/// The ideal response of a pass band lo < |ω| < hi: 1 inside, ½ on the edges, 0 outside.
fn ideal_band(omega: f64, lo: f64, hi: f64) -> f64 {
    let a = omega.abs();
    if omega.is_nan() {
        f64::NAN
    } else if a > lo && a < hi {
        1.0
    } else if (a == lo && lo > 0.0) || a == hi {
        0.5
    } else if a == 0.0 && lo == 0.0 {
        1.0
    } else {
        0.0
    }
}

declare_params! {
    /// Box: h(x) = 1 for |x| ≤ r (nearest neighbour at r = ½).
    BoxFilter = "box", "box h(x) = 1 on |x| ≤ r; H(ω) = 2r sinc(2rω)" {
        /// Radius r (sample spacings).
        radius: float(0.5, MIN_RADIUS, MAX_RADIUS, "radius r in sample spacings (h = 0 for |x| > r)"),
    }
}

impl Kernel for BoxFilter {
    fn radius(&self) -> f64 {
        self.radius
    }
    fn eval(&self, x: f64) -> f64 {
        if x.abs() <= self.radius {
            1.0
        } else {
            0.0
        }
    }
    fn eval_derivative(&self, _x: f64) -> f64 {
        0.0
    }
    fn feature_scale(&self) -> f64 {
        self.radius
    }
    fn integral_closed_form(&self) -> Option<f64> {
        Some(2.0 * self.radius)
    }
    fn response_closed_form(&self, omega: f64) -> Option<ClosedForm> {
        let r = self.radius;
        Some(ClosedForm::exact(Complex64::new(
            2.0 * r * sinc(2.0 * r * omega),
            0.0,
        )))
    }
}

declare_params! {
    /// Tent (triangle, linear interpolation at r = 1): h(x) = 1 − |x|/r.
    Tent = "tent", "tent h(x) = 1 − |x|/r (linear interpolation at r = 1); H(ω) = r sinc²(rω)" {
        /// Radius r (sample spacings).
        radius: float(1.0, MIN_RADIUS, MAX_RADIUS, "radius r in sample spacings (h = 0 for |x| > r)"),
    }
}

impl Kernel for Tent {
    fn radius(&self) -> f64 {
        self.radius
    }
    fn eval(&self, x: f64) -> f64 {
        (1.0 - x.abs() / self.radius).max(0.0)
    }
    fn eval_derivative(&self, x: f64) -> f64 {
        if x == 0.0 {
            return 0.0;
        }
        let r = self.radius;
        inside_derivative(x, r, |x| -x.signum() / r)
    }
    fn feature_scale(&self) -> f64 {
        self.radius
    }
    fn integral_closed_form(&self) -> Option<f64> {
        Some(self.radius)
    }
    fn response_closed_form(&self, omega: f64) -> Option<ClosedForm> {
        let r = self.radius;
        let s = sinc(r * omega);
        Some(ClosedForm::exact(Complex64::new(r * s * s, 0.0)))
    }
}

declare_params! {
    /// Gaussian g(x) = exp(−x²/(2σ²)) on |x| ≤ r, optionally minus g(r) (pbrt-v4) so that it
    /// reaches 0 continuously at the radius.
    Gaussian = "gaussian", "Gaussian e^(−x²/2σ²) on |x| ≤ r, minus its value at r if subtract_edge (pbrt-v4)" {
        /// Standard deviation σ (sample spacings).
        sigma: float(0.5, 1e-3, 1e3, "standard deviation σ in sample spacings"),
        /// Radius r (sample spacings).
        radius: float(1.5, MIN_RADIUS, MAX_RADIUS, "radius r in sample spacings (h = 0 for |x| > r)"),
        /// Subtract g(r) (pbrt-v4) so that h(±r) = 0.
        subtract_edge: flag(true, "subtract g(r) so that the kernel reaches 0 at the radius (pbrt-v4)"),
    }
}

impl Gaussian {
    /// ½(x/σ)², the exponent of g (computed as a ratio first so that σ² never under/overflows).
    #[inline]
    fn exponent(&self, x: f64) -> f64 {
        let t = x / self.sigma;
        0.5 * t * t
    }

    /// The untruncated Gaussian's transform σ√(2π) e^{−2π²σ²ω²}.
    pub fn response_untruncated(&self, omega: f64) -> f64 {
        let t = PI * self.sigma * omega;
        self.sigma * (2.0 * PI).sqrt() * (-2.0 * t * t).exp()
    }

    /// Bound on the error of the untruncated closed form: the tail mass
    /// ∫_{|x|>r} g = σ√(2π) erfc(r/(σ√2)), since |∫_{|x|>r} g e^{−2πiωx}| ≤ ∫_{|x|>r} g.
    pub fn truncation_error_bound(&self) -> f64 {
        let z = self.radius / (self.sigma * std::f64::consts::SQRT_2);
        self.sigma * (2.0 * PI).sqrt() * erfc(z)
    }
}

impl Kernel for Gaussian {
    fn radius(&self) -> f64 {
        self.radius
    }
    fn eval(&self, x: f64) -> f64 {
        if x.abs() > self.radius || x.is_nan() {
            return 0.0;
        }
        let a = self.exponent(x);
        if !a.is_finite() {
            return 0.0;
        }
        if self.subtract_edge {
            // e^{−a} − e^{−b} = −e^{−a}·expm1(a − b), exact even when σ ≫ r.
            let b = self.exponent(self.radius);
            if !b.is_finite() {
                return (-a).exp();
            }
            (-(-a).exp() * (a - b).exp_m1()).max(0.0)
        } else {
            (-a).exp()
        }
    }
    /// With the edge subtracted and g(r) ≤ e⁻¹ (r ≥ √2·σ: every kernel whose cancellation
    /// is harmless), h = e^{−a} − g(r) with g(r) computed once: one `exp` a tap instead of
    /// an `exp` and an `expm1` (the splat's largest cost). Each term is within ½ ulp of ≤ 1 and
    /// the difference is rounded once, so |h − eval| ≤ [`EVAL_MANY_ABS_ERROR`] (4·2⁻⁵³)
    /// absolute against a peak 1 − g(r) ≥ 0.63 (tested). Otherwise (σ ≳ r, where the
    /// difference of two near-1 values would lose digits, or no subtraction) [`Kernel::eval`].
    fn eval_many(&self, xs: &mut [f64]) {
        let b = self.exponent(self.radius);
        if !(self.subtract_edge && b.is_finite() && b >= 1.0) {
            for x in xs {
                *x = self.eval(*x);
            }
            return;
        }
        let g_r = (-b).exp();
        for x in xs {
            let v = *x;
            *x = if v.abs() > self.radius || v.is_nan() {
                0.0
            } else {
                ((-self.exponent(v)).exp() - g_r).max(0.0)
            };
        }
    }
    fn eval_derivative(&self, x: f64) -> f64 {
        let s = self.sigma;
        inside_derivative(x, self.radius, |x| {
            let a = self.exponent(x);
            let g = (-a).exp();
            if g == 0.0 {
                0.0
            } else {
                -(x / s) * g / s
            }
        })
    }
    fn breakpoints(&self) -> Vec<f64> {
        [1.0, 2.0, 4.0, 8.0]
            .iter()
            .map(|k| k * self.sigma)
            .filter(|&b| b < self.radius)
            .collect()
    }
    fn feature_scale(&self) -> f64 {
        self.sigma.min(self.radius)
    }
    /// σ√(2π) erf(r/(σ√2)) [− 2r e^{−r²/2σ²} if `subtract_edge`]. When subtracting with
    /// t = r²/(2σ²) < 1 the two terms nearly cancel, so the difference is summed as the series
    /// 4r Σ_{n≥1} (−1)^{n+1} tⁿ/((n−1)!(2n+1)) (termwise integration of e^{−x²/2σ²} − e^{−t}),
    /// whose terms decrease from the first.
    fn integral_closed_form(&self) -> Option<f64> {
        let z = self.radius / (self.sigma * std::f64::consts::SQRT_2);
        if self.subtract_edge && z * z < 1.0 {
            let t = z * z;
            let mut p = t; // tⁿ/(n−1)! for n = 1
            let mut sum = 0.0;
            for n in 1..60 {
                let nf = n as f64;
                let term = p / (2.0 * nf + 1.0);
                let next = if n % 2 == 1 { sum + term } else { sum - term };
                if next == sum {
                    break;
                }
                sum = next;
                p *= t / nf;
            }
            return Some(4.0 * self.radius * sum);
        }
        let full = self.sigma * (2.0 * PI).sqrt() * erf(z);
        let edge = if self.subtract_edge {
            2.0 * self.radius * (-self.exponent(self.radius)).exp()
        } else {
            0.0
        };
        Some(full - edge)
    }
    /// The untruncated Gaussian transform (minus the transform of the subtracted box
    /// g(r)·2r sinc(2rω) when `subtract_edge`), with the tail mass as error bound.
    fn response_closed_form(&self, omega: f64) -> Option<ClosedForm> {
        let mut v = self.response_untruncated(omega);
        if self.subtract_edge {
            let r = self.radius;
            v -= (-self.exponent(r)).exp() * 2.0 * r * sinc(2.0 * r * omega);
        }
        Some(ClosedForm {
            value: Complex64::new(v, 0.0),
            error_bound: self.truncation_error_bound(),
        })
    }
}

declare_params! {
    /// Mitchell–Netravali cubic k_{B,C} (support \[−2, 2\]) stretched to radius r: h(x) = k(2x/r).
    Mitchell = "mitchell", "Mitchell–Netravali cubic (B, C) stretched to radius r: h(x) = k(2x/r); catmull-rom = (0, ½), b-spline = (1, 0)" {
        /// B (blurring).
        b: float(1.0 / 3.0, 0.0, 1.0, "B: 1 = cubic B-spline (blurry), 0 = interpolating"),
        /// C (ringing).
        c: float(1.0 / 3.0, 0.0, 1.0, "C: larger = sharper, more ringing (Catmull–Rom: ½)"),
        /// Radius r (sample spacings); 2 is the classic kernel.
        radius: float(2.0, MIN_RADIUS, MAX_RADIUS, "radius r in sample spacings; 2 = the classic kernel (partition of unity needs r = 2)"),
    }
}

impl Mitchell {
    /// Catmull–Rom: B = 0, C = ½ (interpolating, partition of unity).
    pub fn catmull_rom() -> Self {
        Mitchell {
            b: 0.0,
            c: 0.5,
            radius: 2.0,
        }
    }
    /// Cubic B-spline: B = 1, C = 0 (non-negative, blurry).
    pub fn b_spline() -> Self {
        Mitchell {
            b: 1.0,
            c: 0.0,
            radius: 2.0,
        }
    }
    /// The recommended Mitchell–Netravali filter: B = C = ⅓.
    #[allow(clippy::self_named_constructors)]
    pub fn mitchell() -> Self {
        Mitchell::default()
    }

    /// The cubic k(u) on \[−2, 2\] (Mitchell & Netravali 1988, eq. 8).
    pub fn cubic(&self, u: f64) -> f64 {
        let (b, c) = (self.b, self.c);
        let u = u.abs();
        if u < 1.0 {
            ((12.0 - 9.0 * b - 6.0 * c) * u * u * u
                + (-18.0 + 12.0 * b + 6.0 * c) * u * u
                + (6.0 - 2.0 * b))
                / 6.0
        } else if u < 2.0 {
            ((-b - 6.0 * c) * u * u * u
                + (6.0 * b + 30.0 * c) * u * u
                + (-12.0 * b - 48.0 * c) * u
                + (8.0 * b + 24.0 * c))
                / 6.0
        } else {
            0.0
        }
    }

    /// k'(u) (C¹ everywhere: continuous at |u| = 1 and 0 at |u| = 2).
    pub fn cubic_derivative(&self, u: f64) -> f64 {
        let (b, c) = (self.b, self.c);
        let s = u.signum();
        let u = u.abs();
        let d = if u < 1.0 {
            (3.0 * (12.0 - 9.0 * b - 6.0 * c) * u * u + 2.0 * (-18.0 + 12.0 * b + 6.0 * c) * u)
                / 6.0
        } else if u < 2.0 {
            (3.0 * (-b - 6.0 * c) * u * u + 2.0 * (6.0 * b + 30.0 * c) * u + (-12.0 * b - 48.0 * c))
                / 6.0
        } else {
            0.0
        };
        if u == 0.0 {
            0.0
        } else {
            s * d
        }
    }
}

impl Kernel for Mitchell {
    fn radius(&self) -> f64 {
        self.radius
    }
    fn eval(&self, x: f64) -> f64 {
        if x.abs() > self.radius || x.is_nan() {
            return 0.0;
        }
        self.cubic(2.0 * x / self.radius)
    }
    fn eval_derivative(&self, x: f64) -> f64 {
        if x.abs() > self.radius || x.is_nan() {
            return 0.0;
        }
        self.cubic_derivative(2.0 * x / self.radius) * 2.0 / self.radius
    }
    fn breakpoints(&self) -> Vec<f64> {
        vec![0.5 * self.radius]
    }
    fn feature_scale(&self) -> f64 {
        0.5 * self.radius
    }
    /// ∫k = 1 for every (B, C), so ∫h = r/2.
    fn integral_closed_form(&self) -> Option<f64> {
        Some(0.5 * self.radius)
    }
}

declare_params! {
    /// Sinc truncated to \[−r, r\] (no window): h(x) = sinc(x).
    Sinc = "sinc", "sinc(x) = sin(πx)/(πx) truncated to |x| ≤ r (no window: strong ringing)" {
        /// Truncation radius r (sample spacings).
        radius: float(4.0, MIN_RADIUS, MAX_RADIUS, "truncation radius r in sample spacings"),
    }
}

impl Kernel for Sinc {
    fn radius(&self) -> f64 {
        self.radius
    }
    fn eval(&self, x: f64) -> f64 {
        if x.abs() > self.radius || x.is_nan() {
            0.0
        } else {
            sinc(x)
        }
    }
    fn eval_derivative(&self, x: f64) -> f64 {
        inside_derivative(x, self.radius, cosc)
    }
    fn feature_scale(&self) -> f64 {
        self.radius.min(1.0)
    }
    fn integral_closed_form(&self) -> Option<f64> {
        Some(2.0 / PI * sine_integral(PI * self.radius))
    }
    fn response_closed_form(&self, omega: f64) -> Option<ClosedForm> {
        Some(ClosedForm::exact(Complex64::new(
            truncated_sinc_response(self.radius, omega),
            0.0,
        )))
    }
}

/// A window w(t) on |t| ≤ 1 (t = x/r) that tapers a sinc or cosc kernel.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "kebab-case")]
pub enum Window {
    /// w = 1 (plain truncation).
    Rect,
    /// Lanczos: w(t) = sinc(t).
    Lanczos,
    /// Hann: w(t) = ½(1 + cos πt).
    Hann,
    /// Blackman: w(t) = 0.42 + 0.5 cos πt + 0.08 cos 2πt.
    Blackman,
    /// Kaiser: w(t) = I₀(β√(1 − t²))/I₀(β) (β = 0 is the rectangle).
    Kaiser {
        /// Shape β ≥ 0: larger = narrower window, lower side lobes.
        beta: f64,
    },
}

/// Names of the windows, as used by `--set window=…`.
pub const WINDOW_NAMES: &[&str] = &["rect", "lanczos", "hann", "blackman", "kaiser"];
/// Default Kaiser β when the window is switched to Kaiser.
pub const DEFAULT_KAISER_BETA: f64 = 4.0;
/// Largest Kaiser β accepted.
pub const MAX_KAISER_BETA: f64 = 50.0;

impl Window {
    /// The window's name.
    pub fn name(&self) -> &'static str {
        match self {
            Window::Rect => "rect",
            Window::Lanczos => "lanczos",
            Window::Hann => "hann",
            Window::Blackman => "blackman",
            Window::Kaiser { .. } => "kaiser",
        }
    }

    /// The window named `name` (Kaiser with `beta`).
    pub fn from_name(name: &str, beta: f64) -> Option<Window> {
        match name.to_ascii_lowercase().as_str() {
            "rect" => Some(Window::Rect),
            "lanczos" => Some(Window::Lanczos),
            "hann" => Some(Window::Hann),
            "blackman" => Some(Window::Blackman),
            "kaiser" => Some(Window::Kaiser { beta }),
            _ => None,
        }
    }

    /// w(t) for |t| ≤ 1 (callers ensure the range).
    pub fn eval(&self, t: f64) -> f64 {
        match *self {
            Window::Rect => 1.0,
            Window::Lanczos => sinc(t),
            Window::Hann => 0.5 * (1.0 + cos_pi(t)),
            Window::Blackman => 0.42 + 0.5 * cos_pi(t) + 0.08 * cos_pi(2.0 * t),
            Window::Kaiser { beta } => {
                let s = (1.0 - t * t).max(0.0).sqrt();
                bessel_i0(beta * s) / bessel_i0(beta)
            }
        }
    }

    /// w'(t) for |t| ≤ 1.
    pub fn derivative(&self, t: f64) -> f64 {
        match *self {
            Window::Rect => 0.0,
            Window::Lanczos => cosc(t),
            Window::Hann => -0.5 * PI * sin_pi(t),
            Window::Blackman => -0.5 * PI * sin_pi(t) - 0.16 * PI * sin_pi(2.0 * t),
            Window::Kaiser { beta } => {
                let s = (1.0 - t * t).max(0.0).sqrt();
                // d/dt I₀(β s) = I₁(β s)·β·(−t/s) = −β² t · I₁(βs)/(βs).
                -beta * beta * t * bessel_i1_over_x(beta * s) / bessel_i0(beta)
            }
        }
    }

    /// Cosine-series coefficients (a_m for m = 0, 1, 2) of windows w(t) = Σ a_m cos(mπt), whose
    /// modulation makes the windowed transform a sum of shifted truncated transforms.
    fn cosine_series(&self) -> Option<[f64; 3]> {
        match self {
            Window::Rect => Some([1.0, 0.0, 0.0]),
            Window::Hann => Some([0.5, 0.5, 0.0]),
            Window::Blackman => Some([0.42, 0.5, 0.08]),
            _ => None,
        }
    }

    /// Σ_m a_m (K(ω − m/(2r)) + K(ω + m/(2r)))/2 for m ≥ 1, plus a₀K(ω).
    fn modulated(&self, r: f64, omega: f64, k: impl Fn(f64) -> Complex64) -> Option<Complex64> {
        let a = self.cosine_series()?;
        let shift = 1.0 / (2.0 * r);
        let mut v = k(omega) * a[0];
        for (m, am) in a.iter().enumerate().skip(1) {
            if *am != 0.0 {
                let d = m as f64 * shift;
                v += (k(omega - d) + k(omega + d)) * (0.5 * am);
            }
        }
        Some(v)
    }
}

fn float_spec(
    name: &'static str,
    doc: &'static str,
    default: f64,
    min: f64,
    max: f64,
) -> ParamSpec {
    ParamSpec {
        name,
        doc,
        kind: ParamKind::Float {
            default,
            min,
            max,
            min_exclusive: false,
            max_exclusive: false,
        },
    }
}

fn window_specs(
    radius_default: f64,
    window: &Window,
    window_default: &'static str,
) -> Vec<ParamSpec> {
    let mut v = vec![
        float_spec("radius", "radius r in sample spacings (window support)", radius_default, MIN_RADIUS, MAX_RADIUS),
        ParamSpec {
            name: "window",
            doc: "taper w(x/r): rect (plain truncation) | lanczos sinc(t) | hann ½(1+cos πt) | blackman | kaiser I0(β√(1−t²))/I0(β)",
            kind: ParamKind::Choice {
                default: window_default,
                options: WINDOW_NAMES,
            },
        },
    ];
    if matches!(window, Window::Kaiser { .. }) {
        v.push(float_spec(
            "beta",
            "Kaiser shape β (window = kaiser only): larger = lower side lobes, wider main lobe",
            DEFAULT_KAISER_BETA,
            0.0,
            MAX_KAISER_BETA,
        ));
    }
    v
}

fn window_get(radius: f64, window: &Window, key: &str) -> Option<ParamValue> {
    match key {
        "radius" => Some(ParamValue::Float(radius)),
        "window" => Some(ParamValue::Choice(window.name())),
        "beta" => match window {
            Window::Kaiser { beta } => Some(ParamValue::Float(*beta)),
            _ => None,
        },
        _ => None,
    }
}

fn window_put(radius: &mut f64, window: &mut Window, key: &str, value: ParamValue) {
    match (key, value) {
        ("radius", ParamValue::Float(v)) => *radius = v,
        ("window", ParamValue::Choice(name)) => {
            let beta = match window {
                Window::Kaiser { beta } => *beta,
                _ => DEFAULT_KAISER_BETA,
            };
            if let Some(w) = Window::from_name(name, beta) {
                *window = w;
            }
        }
        ("beta", ParamValue::Float(v)) => {
            if let Window::Kaiser { beta } = window {
                *beta = v;
            }
        }
        _ => {}
    }
}

const BETA_INACTIVE: (&str, &str) = (
    "beta",
    "used only with window=kaiser (set window=kaiser before beta)",
);

/// Sinc multiplied by a window: h(x) = sinc(x)·w(x/r) on |x| ≤ r.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct WindowedSinc {
    /// Radius r (sample spacings) = window half-width.
    pub radius: f64,
    /// The taper.
    pub window: Window,
}

impl Default for WindowedSinc {
    fn default() -> Self {
        WindowedSinc {
            radius: 3.0,
            window: Window::Lanczos,
        }
    }
}

impl WindowedSinc {
    /// Name used on the command line and in scene files.
    pub const NAME: &'static str = "windowed-sinc";
    /// One-line description.
    pub const SUMMARY: &'static str =
        "sinc(x)·w(x/r) on |x| ≤ r with a Lanczos, Hann, Blackman, Kaiser or rect window";
}

impl Params for WindowedSinc {
    fn owner(&self) -> &'static str {
        Self::NAME
    }
    fn specs(&self) -> Vec<ParamSpec> {
        window_specs(3.0, &self.window, "lanczos")
    }
    fn get(&self, key: &str) -> Option<ParamValue> {
        window_get(self.radius, &self.window, key)
    }
    fn put(&mut self, key: &str, value: ParamValue) {
        window_put(&mut self.radius, &mut self.window, key, value)
    }
    fn inactive_reason(&self, key: &str) -> Option<(&'static str, &'static str)> {
        (key == "beta").then_some(BETA_INACTIVE)
    }
}

impl Kernel for WindowedSinc {
    fn radius(&self) -> f64 {
        self.radius
    }
    fn eval(&self, x: f64) -> f64 {
        if x.abs() > self.radius || x.is_nan() {
            0.0
        } else {
            sinc(x) * self.window.eval(x / self.radius)
        }
    }
    fn eval_derivative(&self, x: f64) -> f64 {
        let r = self.radius;
        inside_derivative(x, r, |x| {
            let t = x / r;
            cosc(x) * self.window.eval(t) + sinc(x) * self.window.derivative(t) / r
        })
    }
    fn feature_scale(&self) -> f64 {
        self.radius.min(1.0)
    }
    fn integral_closed_form(&self) -> Option<f64> {
        self.response_closed_form(0.0).map(|c| c.value.re)
    }
    fn response_closed_form(&self, omega: f64) -> Option<ClosedForm> {
        let r = self.radius;
        self.window
            .modulated(r, omega, |w| {
                Complex64::new(truncated_sinc_response(r, w), 0.0)
            })
            .map(ClosedForm::exact)
    }
}

/// The derivative kernel: cosc(x) = d/dx sinc(x), multiplied by a window w(x/r) on |x| ≤ r
/// (`window = rect`, the default, is plain truncation). Its ideal (untruncated) response is
/// 2πiω on |ω| < ½: convolving samples with it reconstructs the derivative of the
/// band-limited signal (the lecture's "Example: Derivatives").
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Cosc {
    /// Radius r (sample spacings).
    pub radius: f64,
    /// The taper (rect = truncation).
    pub window: Window,
}

impl Default for Cosc {
    fn default() -> Self {
        Cosc {
            radius: 4.0,
            window: Window::Rect,
        }
    }
}

impl Cosc {
    /// Name used on the command line and in scene files.
    pub const NAME: &'static str = "cosc";
    /// One-line description.
    pub const SUMMARY: &'static str =
        "derivative kernel cosc(x) = d/dx sinc(x), truncated (window = rect) or windowed on |x| ≤ r";
}

impl Params for Cosc {
    fn owner(&self) -> &'static str {
        Self::NAME
    }
    fn specs(&self) -> Vec<ParamSpec> {
        window_specs(4.0, &self.window, "rect")
    }
    fn get(&self, key: &str) -> Option<ParamValue> {
        window_get(self.radius, &self.window, key)
    }
    fn put(&mut self, key: &str, value: ParamValue) {
        window_put(&mut self.radius, &mut self.window, key, value)
    }
    fn inactive_reason(&self, key: &str) -> Option<(&'static str, &'static str)> {
        (key == "beta").then_some(BETA_INACTIVE)
    }
}

impl Kernel for Cosc {
    fn radius(&self) -> f64 {
        self.radius
    }
    fn eval(&self, x: f64) -> f64 {
        if x.abs() > self.radius || x.is_nan() {
            0.0
        } else {
            cosc(x) * self.window.eval(x / self.radius)
        }
    }
    fn eval_derivative(&self, x: f64) -> f64 {
        let r = self.radius;
        inside_derivative(x, r, |x| {
            let t = x / r;
            sinc_d2(x) * self.window.eval(t) + cosc(x) * self.window.derivative(t) / r
        })
    }
    fn parity(&self) -> Parity {
        Parity::Odd
    }
    fn feature_scale(&self) -> f64 {
        self.radius.min(1.0)
    }
    fn integral_closed_form(&self) -> Option<f64> {
        Some(0.0)
    }
    fn response_closed_form(&self, omega: f64) -> Option<ClosedForm> {
        let r = self.radius;
        self.window
            .modulated(r, omega, |w| truncated_cosc_response(r, w))
            .map(ClosedForm::exact)
    }
    fn nominal_zero_dc(&self) -> bool {
        true
    }
    fn is_derivative(&self) -> bool {
        true
    }
}

/// Default truncation radius of the ideal filters' spatial kernels.
pub const IDEAL_RADIUS: f64 = 16.0;

declare_params! {
    /// Ideal low-pass: H(ω) = 1 for |ω| < c (½ at |ω| = c), 0 above. Spatial kernel
    /// h(x) = 2c sinc(2cx), truncated to |x| ≤ radius for spatial evaluation.
    LowPass = "low-pass", "ideal low-pass H = 1 for |ω| < cutoff; spatial 2c sinc(2cx) truncated to radius" {
        /// Cutoff c (cycles per sample; ½ = Nyquist).
        cutoff: float(0.5, 1e-3, 4.0, "cutoff c in cycles per sample (Nyquist = 0.5)"),
        /// Truncation radius of the spatial kernel (sample spacings).
        radius: float(IDEAL_RADIUS, MIN_RADIUS, MAX_RADIUS, "truncation radius of the spatial kernel (sinc combination) in sample spacings; the response is the exact ideal one"),
    }
}

impl Kernel for LowPass {
    fn radius(&self) -> f64 {
        self.radius
    }
    fn eval(&self, x: f64) -> f64 {
        if x.abs() > self.radius || x.is_nan() {
            0.0
        } else {
            let c = self.cutoff;
            2.0 * c * sinc(2.0 * c * x)
        }
    }
    fn eval_derivative(&self, x: f64) -> f64 {
        let c = self.cutoff;
        inside_derivative(x, self.radius, |x| 4.0 * c * c * cosc(2.0 * c * x))
    }
    fn feature_scale(&self) -> f64 {
        (0.5 / self.cutoff).min(self.radius)
    }
    fn integral_closed_form(&self) -> Option<f64> {
        Some(2.0 / PI * sine_integral(2.0 * PI * self.cutoff * self.radius))
    }
    fn response_closed_form(&self, omega: f64) -> Option<ClosedForm> {
        let c = self.cutoff;
        Some(ClosedForm::exact(Complex64::new(
            truncated_sinc_response(2.0 * c * self.radius, omega / (2.0 * c)),
            0.0,
        )))
    }
    fn response_ideal(&self, omega: f64) -> Option<Complex64> {
        Some(Complex64::new(ideal_band(omega, 0.0, self.cutoff), 0.0))
    }
    fn frequency_breakpoints(&self) -> Vec<f64> {
        vec![self.cutoff]
    }
}

declare_params! {
    /// Ideal band-pass: H(ω) = 1 for low < |ω| < high (½ on the edges), 0 elsewhere. Spatial
    /// kernel 2·high·sinc(2·high·x) − 2·low·sinc(2·low·x), truncated to |x| ≤ radius.
    BandPass = "band-pass", "ideal band-pass H = 1 for low < |ω| < high; spatial 2h sinc(2hx) − 2l sinc(2lx) truncated to radius" {
        /// Lower edge (cycles per sample).
        low: float(0.125, 0.0, 4.0, "lower edge in cycles per sample (< high); 0 = low-pass"),
        /// Upper edge (cycles per sample).
        high: float(0.375, 1e-3, 4.0, "upper edge in cycles per sample (> low)"),
        /// Truncation radius of the spatial kernel (sample spacings).
        radius: float(IDEAL_RADIUS, MIN_RADIUS, MAX_RADIUS, "truncation radius of the spatial kernel (sinc combination) in sample spacings; the response is the exact ideal one"),
    }
    check(p) {
        if p.low < p.high {
            Ok(())
        } else {
            Err(ParamError::Invalid {
                owner: "band-pass",
                field: "low",
                value: fmt_num(p.low),
                allowed: format!("a number in [0, high = {}) (low must be below high)", fmt_num(p.high)),
            })
        }
    }
}

impl Kernel for BandPass {
    fn radius(&self) -> f64 {
        self.radius
    }
    fn eval(&self, x: f64) -> f64 {
        if x.abs() > self.radius || x.is_nan() {
            0.0
        } else {
            let (l, h) = (self.low, self.high);
            2.0 * h * sinc(2.0 * h * x) - 2.0 * l * sinc(2.0 * l * x)
        }
    }
    fn eval_derivative(&self, x: f64) -> f64 {
        let (l, h) = (self.low, self.high);
        inside_derivative(x, self.radius, |x| {
            4.0 * h * h * cosc(2.0 * h * x) - 4.0 * l * l * cosc(2.0 * l * x)
        })
    }
    fn feature_scale(&self) -> f64 {
        (0.5 / self.high).min(self.radius)
    }
    fn integral_closed_form(&self) -> Option<f64> {
        let r = self.radius;
        Some(
            2.0 / PI
                * (sine_integral(2.0 * PI * self.high * r)
                    - sine_integral(2.0 * PI * self.low * r)),
        )
    }
    fn response_closed_form(&self, omega: f64) -> Option<ClosedForm> {
        let (l, h, r) = (self.low, self.high, self.radius);
        let mut v = truncated_sinc_response(2.0 * h * r, omega / (2.0 * h));
        if l > 0.0 {
            v -= truncated_sinc_response(2.0 * l * r, omega / (2.0 * l));
        }
        Some(ClosedForm::exact(Complex64::new(v, 0.0)))
    }
    fn response_ideal(&self, omega: f64) -> Option<Complex64> {
        Some(Complex64::new(ideal_band(omega, self.low, self.high), 0.0))
    }
    fn frequency_breakpoints(&self) -> Vec<f64> {
        if self.low > 0.0 {
            vec![self.low, self.high]
        } else {
            vec![self.high]
        }
    }
    fn nominal_zero_dc(&self) -> bool {
        self.low > 0.0
    }
}

declare_params! {
    /// Ideal high-pass: H(ω) = 0 for |ω| < c (½ at |ω| = c), 1 above (at every frequency). Its
    /// spatial kernel is δ(x) − 2c sinc(2cx): `eval` returns the regular part −2c sinc(2cx)
    /// truncated to |x| ≤ radius, and the Dirac mass (weight 1) is reported by `dirac_weight`.
    HighPass = "high-pass", "ideal high-pass H = 1 for |ω| > cutoff; spatial δ(x) − 2c sinc(2cx) (sinc part truncated to radius)" {
        /// Cutoff c (cycles per sample).
        cutoff: float(0.25, 1e-3, 4.0, "cutoff c in cycles per sample (Nyquist = 0.5)"),
        /// Truncation radius of the spatial kernel's sinc part (sample spacings).
        radius: float(IDEAL_RADIUS, MIN_RADIUS, MAX_RADIUS, "truncation radius of the spatial kernel (sinc combination) in sample spacings; the response is the exact ideal one"),
    }
}

impl Kernel for HighPass {
    fn radius(&self) -> f64 {
        self.radius
    }
    fn eval(&self, x: f64) -> f64 {
        if x.abs() > self.radius || x.is_nan() {
            0.0
        } else {
            let c = self.cutoff;
            -2.0 * c * sinc(2.0 * c * x)
        }
    }
    fn eval_derivative(&self, x: f64) -> f64 {
        let c = self.cutoff;
        inside_derivative(x, self.radius, |x| -4.0 * c * c * cosc(2.0 * c * x))
    }
    fn dirac_weight(&self) -> f64 {
        1.0
    }
    fn feature_scale(&self) -> f64 {
        (0.5 / self.cutoff).min(self.radius)
    }
    fn integral_closed_form(&self) -> Option<f64> {
        Some(1.0 - 2.0 / PI * sine_integral(2.0 * PI * self.cutoff * self.radius))
    }
    fn response_closed_form(&self, omega: f64) -> Option<ClosedForm> {
        let c = self.cutoff;
        Some(ClosedForm::exact(Complex64::new(
            1.0 - truncated_sinc_response(2.0 * c * self.radius, omega / (2.0 * c)),
            0.0,
        )))
    }
    fn response_ideal(&self, omega: f64) -> Option<Complex64> {
        Some(Complex64::new(
            ideal_band(omega, self.cutoff, f64::INFINITY),
            0.0,
        ))
    }
    fn frequency_breakpoints(&self) -> Vec<f64> {
        vec![self.cutoff]
    }
    fn nominal_zero_dc(&self) -> bool {
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ideal_band_edges_take_half() {
        assert_eq!(ideal_band(0.5, 0.0, 0.5), 0.5);
        assert_eq!(ideal_band(0.0, 0.0, 0.5), 1.0);
        assert_eq!(ideal_band(-0.25, 0.0, 0.5), 1.0);
        assert_eq!(ideal_band(0.6, 0.0, 0.5), 0.0);
        assert_eq!(ideal_band(0.1, 0.1, 0.3), 0.5);
        assert_eq!(ideal_band(0.05, 0.1, 0.3), 0.0);
        assert_eq!(ideal_band(100.0, 0.25, f64::INFINITY), 1.0);
    }

    /// The Gaussian's one-exponential `eval_many` against the `expm1` form of `eval`, at
    /// 20 001 points across [−r − 0.1, r + 0.1] (the edge, the centre and outside included)
    /// for σ/r from small to the √2 limit and beyond (where it must equal `eval` bit for
    /// bit), with and without the subtracted edge.
    #[test]
    fn gaussian_eval_many_is_within_its_bound_of_eval() {
        let mut worst: f64 = 0.0;
        for &(sigma, radius) in &[
            (0.5, 2.0),
            (0.5, 1.5),
            (0.1, 3.0),
            (1e-3, 64.0),
            (1.0, 1.0f64.max(2f64.sqrt())),
            (2.0, 64.0),
            (0.7, 1.0),
            (5.0, 2.0),
            (1e3, 1.5),
        ] {
            for subtract_edge in [true, false] {
                let g = Gaussian {
                    sigma,
                    radius,
                    subtract_edge,
                };
                let xs: Vec<f64> = (0..=20_000)
                    .map(|k| -(radius + 0.1) + (2.0 * radius + 0.2) * k as f64 / 20_000.0)
                    .chain([radius, -radius, 0.0, f64::NAN, f64::INFINITY])
                    .collect();
                let mut fast = xs.clone();
                g.eval_many(&mut fast);
                let fast_path = subtract_edge && g.exponent(radius) >= 1.0;
                for (&x, &f) in xs.iter().zip(&fast) {
                    let e = g.eval(x);
                    if fast_path {
                        assert!(
                            (f - e).abs() <= EVAL_MANY_ABS_ERROR && f >= 0.0,
                            "σ = {sigma}, r = {radius}, x = {x}: {f} vs {e}"
                        );
                        worst = worst.max((f - e).abs());
                    } else {
                        assert_eq!(
                            f.to_bits(),
                            e.to_bits(),
                            "σ = {sigma}, r = {radius}, x = {x}"
                        );
                    }
                }
            }
        }
        // The bound is not vacuous: the forms do differ.
        assert!(worst > 0.0);
    }

    #[test]
    fn mitchell_cubic_is_c1_at_the_joins() {
        for m in [
            Mitchell::mitchell(),
            Mitchell::catmull_rom(),
            Mitchell::b_spline(),
        ] {
            for u in [1.0, 2.0] {
                let e = 1e-9;
                assert!((m.cubic(u - e) - m.cubic(u + e)).abs() < 1e-8);
                assert!((m.cubic_derivative(u - e) - m.cubic_derivative(u + e)).abs() < 1e-8);
            }
            assert_eq!(m.cubic(2.0), 0.0);
        }
        // Catmull–Rom interpolates: k(0) = 1, k(1) = 0.
        let cr = Mitchell::catmull_rom();
        assert_eq!(cr.cubic(0.0), 1.0);
        assert_eq!(cr.cubic(1.0), 0.0);
    }

    #[test]
    fn window_values_at_centre_and_edge() {
        for w in [
            Window::Rect,
            Window::Lanczos,
            Window::Hann,
            Window::Blackman,
            Window::Kaiser { beta: 5.0 },
        ] {
            assert!((w.eval(0.0) - 1.0).abs() < 1e-15, "{w:?}");
        }
        assert!(Window::Hann.eval(1.0).abs() < 1e-16);
        assert!(Window::Blackman.eval(1.0).abs() < 1e-16);
        assert!(Window::Lanczos.eval(1.0).abs() < 1e-16);
        assert!((Window::Kaiser { beta: 5.0 }.eval(1.0) - 1.0 / bessel_i0(5.0)).abs() < 1e-16);
        assert_eq!(Window::Kaiser { beta: 0.0 }.eval(0.7), 1.0);
    }
}
