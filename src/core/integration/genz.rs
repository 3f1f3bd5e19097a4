//! Genz's six test families on [0,1]^D (Genz 1984), each with its closed-form integral, and
//! their random instances as Genz's test package draws them (Genz 1987).
//!
//! | integrand | f(x) | ∫ f over [0,1]^D |
//! |---|---|---|
//! | `genz-oscillatory` | cos(2πu + Σ aᵢxᵢ) | cos(2πu + Σ aᵢ/2) · Π sin(aᵢ/2)/(aᵢ/2) |
//! | `genz-product-peak` | Π (aᵢ⁻² + (xᵢ − uᵢ)²)⁻¹ | Π aᵢ (atan(aᵢ(1 − uᵢ)) + atan(aᵢuᵢ)) |
//! | `genz-corner-peak` | (1 + Σ aᵢxᵢ)^(−(D+1)) | [`corner_peak_integral`] (stable; see there) |
//! | `genz-gaussian` | exp(−Σ aᵢ²(xᵢ − uᵢ)²) | Π (√π/(2aᵢ)) (erf(aᵢ(1 − uᵢ)) + erf(aᵢuᵢ)) |
//! | `genz-continuous` | exp(−Σ aᵢ\|xᵢ − uᵢ\|) | Π (2 − e^(−aᵢuᵢ) − e^(−aᵢ(1−uᵢ)))/aᵢ |
//! | `genz-discontinuous` | 0 if x₁ > u₁ or x₂ > u₂, else exp(Σ aᵢxᵢ) | Π_{i≤2} (e^(aᵢuᵢ) − 1)/aᵢ · Π_{i>2} (e^(aᵢ) − 1)/aᵢ |
//!
//! Each factor is evaluated without cancellation (`expm1`, a series for sin(a/2)/(a/2) near
//! 0), and an entry aᵢ = 0 takes the factor's limit (1, or uᵢ for the discontinuous family's
//! first two). The oscillatory family has one phase u (Genz's u₁); the corner peak has no u;
//! the discontinuous family reads u₁ and u₂ only. With D = 1 there is no x₂: the
//! discontinuous integrand is 0 if x₁ > u₁, else exp(a₁x₁).
//!
//! `a` and `u` are [`PerDim`] values: one number for every dimension or a list of D numbers;
//! [`Genz::new`] expands them for a dimension D and refuses a list of another length, and a set
//! whose peak value or integral leaves the range of f64 (Π aᵢ² of the product peak in many
//! dimensions, say), each with the field named.
//!
//! # Random instances
//!
//! [`GenzFamily::randomized`] draws an instance the way Genz's test driver MULTST (Genz 1987,
//! "A package for testing multiple integration subroutines"; TESTPACK) does: for each
//! dimension i in order, a′ᵢ and then uᵢ from [`Rng::next_f64`] (a′ᵢ = 1 − that draw, in
//! (0, 1], so that no aᵢ is 0), then aᵢ = a′ᵢ · h / (D^e · Σ a′) so that Σ aᵢ = h/D^e, with
//! MULTST's difficulties h and exponents e ([`DIFFICULTY`]): oscillatory 110 and 1.5,
//! product peak 600 and 2, corner peak 600 and 2, Gaussian 100 and 1, continuous 150 and 2,
//! discontinuous 100 and 2. The oscillatory phase is u₁.

use crate::core::filter::special::erf;
use crate::core::params::{declare_params, fmt_num, ParamError, PerDim};
use crate::core::rng::Rng;
use std::f64::consts::PI;

/// The largest aᵢ (Genz's normalised difficulties reach 600 in one dimension).
pub const MAX_A: f64 = 1000.0;

/// The largest aᵢ of the discontinuous family, whose peak exp(Σ aᵢ) must stay finite: at most
/// 300 keeps it finite in the GUI's 2D study (exp(600) < f64::MAX ≈ exp(709.78)); in more
/// dimensions the peak check refuses a sum that overflows.
pub const MAX_A_DISCONTINUOUS: f64 = 300.0;

/// The smallest edge u₁, u₂ of the discontinuous family: the region x₁ ≤ u₁, x₂ ≤ u₂ keeps an
/// area, so the integral is not 0.
pub const MIN_U_DISCONTINUOUS: f64 = 0.001;

declare_params! {
    /// Genz's oscillatory family.
    GenzOscillatory = "genz-oscillatory", "Genz oscillatory cos(2πu + Σ aᵢxᵢ) on [0,1]^D (smooth; a sets the frequency along each axis)" {
        a: per_dim(1.0, 0.0, MAX_A, "aᵢ, radians per unit along axis i: one number (every axis) or one per axis"),
        u: float(0.5, 0.0, 1.0, "phase u (Genz's u₁), in turns"),
    }
}
declare_params! {
    /// Genz's product-peak family.
    GenzProductPeak = "genz-product-peak", "Genz product peak Π (aᵢ⁻² + (xᵢ − uᵢ)²)⁻¹ on [0,1]^D (a peak of height Π aᵢ² at u)" {
        a: per_dim(5.0, 0.0, MAX_A, "aᵢ > 0, the peak's sharpness along axis i: one number (every axis) or one per axis"),
        u: per_dim(0.5, 0.0, 1.0, "uᵢ, the peak's position: one number (every axis) or one per axis"),
    }
    check(p) {
        if p.a.as_slice().contains(&0.0) {
            return Err(ParamError::Invalid {
                owner: "genz-product-peak",
                field: "a",
                value: p.a.value().short(),
                allowed: format!("each entry in (0, {}] (a = 0 makes f ≡ 0)", fmt_num(MAX_A)),
            });
        }
        Ok(())
    }
}
declare_params! {
    /// Genz's corner-peak family.
    GenzCornerPeak = "genz-corner-peak", "Genz corner peak (1 + Σ aᵢxᵢ)^(−(D+1)) on [0,1]^D (a peak at the origin)" {
        a: per_dim(1.0, 0.0, MAX_A, "aᵢ, the peak's sharpness along axis i: one number (every axis) or one per axis"),
    }
}
declare_params! {
    /// Genz's Gaussian family.
    GenzGaussian = "genz-gaussian", "Genz Gaussian exp(−Σ aᵢ²(xᵢ − uᵢ)²) on [0,1]^D (a bump at u)" {
        a: per_dim(5.0, 0.0, MAX_A, "aᵢ, the inverse width along axis i: one number (every axis) or one per axis"),
        u: per_dim(0.5, 0.0, 1.0, "uᵢ, the centre: one number (every axis) or one per axis"),
    }
}
declare_params! {
    /// Genz's continuous (C⁰) family.
    GenzContinuous = "genz-continuous", "Genz continuous exp(−Σ aᵢ|xᵢ − uᵢ|) on [0,1]^D (a kink at u along every axis)" {
        a: per_dim(5.0, 0.0, MAX_A, "aᵢ, the decay along axis i: one number (every axis) or one per axis"),
        u: per_dim(0.5, 0.0, 1.0, "uᵢ, the kink: one number (every axis) or one per axis"),
    }
}
declare_params! {
    /// Genz's discontinuous family.
    GenzDiscontinuous = "genz-discontinuous", "Genz discontinuous: 0 if x₁ > u₁ or x₂ > u₂, else exp(Σ aᵢxᵢ), on [0,1]^D (with D = 1: 0 if x₁ > u₁)" {
        a: per_dim(1.0, 0.0, MAX_A_DISCONTINUOUS, "aᵢ, the growth along axis i: one number (every axis) or one per axis"),
        u: per_dim(0.5, MIN_U_DISCONTINUOUS, 1.0, "uᵢ: the edges x₁ = u₁ and x₂ = u₂ (entries past the second are not used; at least 0.001, so the region x₁ ≤ u₁, x₂ ≤ u₂ has an area and the integral is not 0): one number or one per axis"),
    }
}

/// Which of Genz's six families.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum GenzKind {
    Oscillatory,
    ProductPeak,
    CornerPeak,
    Gaussian,
    Continuous,
    Discontinuous,
}

/// Genz 1987's difficulty h and exponent e per family (MULTST's `difclt` and `expnts`), in
/// the order of [`GenzKind`]: a random instance has Σ aᵢ = h / D^e.
pub const DIFFICULTY: [(f64, f64); 6] = [
    (110.0, 1.5),
    (600.0, 2.0),
    (600.0, 2.0),
    (100.0, 1.0),
    (150.0, 2.0),
    (100.0, 2.0),
];

impl GenzKind {
    /// The family's name (the integrand's).
    pub fn name(self) -> &'static str {
        match self {
            GenzKind::Oscillatory => GenzOscillatory::NAME,
            GenzKind::ProductPeak => GenzProductPeak::NAME,
            GenzKind::CornerPeak => GenzCornerPeak::NAME,
            GenzKind::Gaussian => GenzGaussian::NAME,
            GenzKind::Continuous => GenzContinuous::NAME,
            GenzKind::Discontinuous => GenzDiscontinuous::NAME,
        }
    }

    /// Genz's difficulty (h, e) of [`DIFFICULTY`].
    pub fn difficulty(self) -> (f64, f64) {
        DIFFICULTY[self as usize]
    }
}

/// The parameters of one Genz integrand, whatever its family: `u` is the one phase of the
/// oscillatory family and unused by the corner peak.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GenzFamily {
    pub kind: GenzKind,
    pub a: PerDim,
    pub u: PerDim,
}

impl GenzFamily {
    /// A random instance in `dims` dimensions, drawn as the module docs say.
    pub fn randomized(kind: GenzKind, dims: usize, rng: &mut Rng) -> GenzFamily {
        let dims = dims.max(1);
        let mut a = Vec::with_capacity(dims);
        let mut u = Vec::with_capacity(dims);
        for _ in 0..dims {
            a.push(1.0 - rng.next_f64());
            u.push(rng.next_f64());
        }
        let (h, e) = kind.difficulty();
        let target = h / (dims as f64).powf(e);
        let total: f64 = a.iter().sum();
        for x in &mut a {
            *x *= target / total;
        }
        let per = |v: &[f64]| PerDim::list(v).unwrap_or(PerDim::all(v[0]));
        let u = match kind {
            GenzKind::Oscillatory => PerDim::all(u[0]),
            // The edges keep the region x₁ ≤ u₁, x₂ ≤ u₂ an area (u ≥ MIN_U_DISCONTINUOUS, the
            // descriptor's minimum): u = MIN + (1 − MIN)·U, the same draws.
            GenzKind::Discontinuous => per(&u
                .iter()
                .map(|v| MIN_U_DISCONTINUOUS + (1.0 - MIN_U_DISCONTINUOUS) * v)
                .collect::<Vec<_>>()),
            _ => per(&u),
        };
        GenzFamily {
            kind,
            a: per(&a),
            u,
        }
    }
}

/// Each parameter struct as a [`GenzFamily`].
macro_rules! family_of {
    ($($ty:ident => $kind:ident, |$g:ident| $u:expr;)*) => {
        $(impl $ty {
            /// The family and parameters, for [`Genz::new`].
            pub fn family(&self) -> GenzFamily {
                let $g = self;
                GenzFamily { kind: GenzKind::$kind, a: $g.a, u: $u }
            }
        })*
    };
}
family_of! {
    GenzOscillatory => Oscillatory, |g| PerDim::all(g.u);
    GenzProductPeak => ProductPeak, |g| g.u;
    GenzCornerPeak => CornerPeak, |_g| PerDim::all(0.0);
    GenzGaussian => Gaussian, |g| g.u;
    GenzContinuous => Continuous, |g| g.u;
    GenzDiscontinuous => Discontinuous, |g| g.u;
}

/// A Genz integrand made ready for `dims` dimensions: its per-dimension parameters expanded,
/// the constants of the evaluation computed once, and its closed-form integral.
#[derive(Debug, Clone, PartialEq)]
pub struct Genz {
    kind: GenzKind,
    dims: usize,
    /// aᵢ (for the product peak aᵢ⁻²; for the Gaussian aᵢ²).
    c: Vec<f64>,
    /// uᵢ (the oscillatory family: its phase 2πu in c₀'s place is `phase`).
    u: Vec<f64>,
    phase: f64,
    integral: f64,
}

impl Genz {
    /// The family's instance in `dims` ≥ 1 dimensions. Errors name the field: a list whose
    /// length is neither 1 nor `dims`, or a set whose peak value or integral is not a finite
    /// number in f64 (nor, for the families whose integral is positive, a normal one).
    pub fn new(f: &GenzFamily, dims: usize) -> Result<Genz, ParamError> {
        let owner = f.kind.name();
        let expand = |field: &'static str, v: &PerDim| {
            v.expand(dims).map_err(|len| ParamError::Invalid {
                owner,
                field,
                value: format!("{} ({len} numbers)", v.value().short()),
                allowed: format!(
                    "one number (every dimension) or a list of {dims}, one per dimension (dims = {dims})"
                ),
            })
        };
        let a = expand("a", &f.a)?;
        let u = match f.kind {
            GenzKind::Oscillatory | GenzKind::CornerPeak => vec![f.u.as_slice()[0]; dims],
            _ => expand("u", &f.u)?,
        };
        let range = |what: String, value: f64| {
            ParamError::Invalid {
            owner,
            field: "a",
            value: f.a.value().short(),
            allowed: format!(
                "a set whose {what} is a finite, normal f64 in {dims} dimensions (here {}): smaller a or fewer dimensions",
                fmt_num(value)
            ),
        }
        };
        // The largest value of f: Π aᵢ² (product peak) and exp(Σ aᵢ·(uᵢ or 1)) (discontinuous).
        match f.kind {
            GenzKind::ProductPeak => {
                let log_peak: f64 = a.iter().map(|x| 2.0 * x.ln()).sum();
                if log_peak >= f64::MAX.ln() {
                    return Err(range("peak value Π aᵢ²".into(), log_peak.exp()));
                }
            }
            GenzKind::Discontinuous => {
                let s: f64 = a
                    .iter()
                    .zip(&u)
                    .enumerate()
                    .map(|(i, (x, ui))| if i < 2 { x * ui } else { *x })
                    .sum();
                if s >= f64::MAX.ln() {
                    return Err(range("peak value exp(Σ aᵢ)".into(), s.exp()));
                }
            }
            _ => {}
        }
        let integral = integral(f.kind, &a, &u);
        let positive = !matches!(f.kind, GenzKind::Oscillatory);
        if !integral.is_finite() || (positive && !integral.is_normal()) {
            return Err(range("integral".into(), integral));
        }
        let c = match f.kind {
            GenzKind::ProductPeak => a.iter().map(|x| 1.0 / (x * x)).collect(),
            GenzKind::Gaussian => a.iter().map(|x| x * x).collect(),
            _ => a,
        };
        Ok(Genz {
            kind: f.kind,
            dims,
            c,
            phase: 2.0 * PI * u[0],
            u,
            integral,
        })
    }

    /// The number of dimensions.
    pub fn dims(&self) -> usize {
        self.dims
    }

    /// The exact integral over [0,1]^D.
    pub fn integral(&self) -> f64 {
        self.integral
    }

    /// f(x) for x of `dims` coordinates.
    pub fn eval(&self, x: &[f64]) -> f64 {
        self.eval_shifted(x, None)
    }

    /// f((x + s) mod 1) for x and s in [0,1)^D (a Cranley–Patterson rotation by s), or f(x).
    #[inline]
    pub fn eval_shifted(&self, x: &[f64], shift: Option<&[f64]>) -> f64 {
        match shift {
            Some(s) => self.eval_with(x, |i, v| {
                let w = v + s[i];
                if w >= 1.0 {
                    w - 1.0
                } else {
                    w
                }
            }),
            None => self.eval_with(x, |_, v| v),
        }
    }

    #[inline]
    fn eval_with(&self, x: &[f64], at: impl Fn(usize, f64) -> f64) -> f64 {
        let (c, u) = (&self.c[..], &self.u[..]);
        let x = &x[..self.dims];
        match self.kind {
            GenzKind::Oscillatory => {
                let mut s = self.phase;
                for (i, (&xi, &ci)) in x.iter().zip(c).enumerate() {
                    s += ci * at(i, xi);
                }
                s.cos()
            }
            GenzKind::ProductPeak => {
                let mut p = 1.0;
                for (i, ((&xi, &ci), &ui)) in x.iter().zip(c).zip(u).enumerate() {
                    let d = at(i, xi) - ui;
                    p /= ci + d * d;
                }
                p
            }
            GenzKind::CornerPeak => {
                let mut s = 1.0;
                for (i, (&xi, &ci)) in x.iter().zip(c).enumerate() {
                    s += ci * at(i, xi);
                }
                s.powi(-(self.dims as i32 + 1))
            }
            GenzKind::Gaussian => {
                let mut s = 0.0;
                for (i, ((&xi, &ci), &ui)) in x.iter().zip(c).zip(u).enumerate() {
                    let d = at(i, xi) - ui;
                    s += ci * d * d;
                }
                (-s).exp()
            }
            GenzKind::Continuous => {
                let mut s = 0.0;
                for (i, ((&xi, &ci), &ui)) in x.iter().zip(c).zip(u).enumerate() {
                    s += ci * (at(i, xi) - ui).abs();
                }
                (-s).exp()
            }
            GenzKind::Discontinuous => {
                let mut s = 0.0;
                for (i, (&xi, &ci)) in x.iter().zip(c).enumerate() {
                    let v = at(i, xi);
                    if i < 2 && v > u[i] {
                        return 0.0;
                    }
                    s += ci * v;
                }
                s.exp()
            }
        }
    }
}

/// sin(a/2)/(a/2), 1 at a = 0.
fn half_sinc(a: f64) -> f64 {
    let h = 0.5 * a;
    if h.abs() < 1e-4 {
        1.0 - h * h / 6.0
    } else {
        h.sin() / h
    }
}

/// (e^t − 1)/a for t = a·w, w at a = 0.
fn expm1_over(a: f64, w: f64) -> f64 {
    if a == 0.0 {
        w
    } else {
        (a * w).exp_m1() / a
    }
}

/// The closed-form integral over [0,1]^D (module table), a and u of D entries.
pub fn integral(kind: GenzKind, a: &[f64], u: &[f64]) -> f64 {
    let pairs = a.iter().copied().zip(u.iter().copied());
    match kind {
        GenzKind::Oscillatory => {
            let phase = 2.0 * PI * u[0] + 0.5 * a.iter().sum::<f64>();
            phase.cos() * a.iter().map(|&x| half_sinc(x)).product::<f64>()
        }
        GenzKind::ProductPeak => pairs
            .map(|(x, ui)| x * ((x * (1.0 - ui)).atan() + (x * ui).atan()))
            .product(),
        GenzKind::CornerPeak => corner_peak_integral(a),
        GenzKind::Gaussian => pairs
            .map(|(x, ui)| {
                if x == 0.0 {
                    1.0
                } else {
                    PI.sqrt() / (2.0 * x) * (erf(x * (1.0 - ui)) + erf(x * ui))
                }
            })
            .product(),
        GenzKind::Continuous => pairs
            .map(|(x, ui)| {
                if x == 0.0 {
                    1.0
                } else {
                    (-(-x * ui).exp_m1() - (-x * (1.0 - ui)).exp_m1()) / x
                }
            })
            .product(),
        GenzKind::Discontinuous => pairs
            .enumerate()
            .map(|(i, (x, ui))| expm1_over(x, if i < 2 { ui } else { 1.0 }))
            .product(),
    }
}

/// ∫ over [0,1]^D of (1 + Σ aᵢxᵢ)^(−(D+1)), aᵢ ≥ 0, to about 1e−13 relative.
///
/// The textbook closed form (1/(D!·Π aᵢ)) Σ over the 2^D vertices v of (−1)^|v|/(1 + a·v)
/// cancels catastrophically (for D = 32, a = 1/64 its terms are 10¹⁸ times the result). This
/// evaluates instead the Laplace form: with (1 + s)^(−(D+1)) = (1/D!) ∫₀^∞ t^D e^(−(1+s)t) dt
/// the integral over the cube factorises,
///
/// I = (1/D!) ∫₀^∞ t^D e^(−t) Π φ(aᵢt) dt,  φ(z) = (1 − e^(−z))/z = ∫₀¹ e^(−zx) dx,
///
/// a sum of positive terms. With t = e^y the integrand is e^(L(y)),
/// L(y) = (D+1)y − e^y − ln D! + Σ ln φ(aᵢe^y), which is strictly concave (ln φ(e^w) is
/// concave: its derivative z/(e^z − 1) − 1 decreases), smooth and analytic in a strip, so the
/// trapezoidal rule in y converges exponentially: the step is halved from about a quarter of
/// the peak's width until two results agree to 1e−15, and the nodes run out from the peak
/// until L has fallen 50 below its maximum (concavity bounds the rest by far less than the
/// result's rounding). Sums are taken relative to the maximum, so nothing overflows; the
/// result underflows to 0 only where the integral is below f64's range.
pub fn corner_peak_integral(a: &[f64]) -> f64 {
    let d = a.len();
    let df = d as f64;
    let ln_fact: f64 = (2..=d).map(|k| (k as f64).ln()).sum();
    // ln φ(z) and d/dy ln φ(a e^y) = z/(e^z − 1) − 1 at z = a e^y.
    let ln_phi = |z: f64| {
        if z == 0.0 {
            0.0
        } else {
            (-(-z).exp_m1() / z).ln()
        }
    };
    let dln_phi = |z: f64| {
        if z == 0.0 {
            0.0
        } else {
            z / z.exp_m1() - 1.0
        }
    };
    let l = |y: f64| {
        let t = y.exp();
        (df + 1.0) * y - t - ln_fact + a.iter().map(|&x| ln_phi(x * t)).sum::<f64>()
    };
    let dl = |y: f64| {
        let t = y.exp();
        (df + 1.0) - t + a.iter().map(|&x| dln_phi(x * t)).sum::<f64>()
    };
    // L' decreases from D+1; z/(e^z−1) − 1 ≥ −z/2 brackets its root.
    let sum_a: f64 = a.iter().sum();
    let mut lo = ((df + 1.0) / (2.0 * (1.0 + 0.5 * sum_a))).ln();
    let mut hi = (df + 1.0).ln();
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if dl(mid) > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
        if hi - lo < 1e-13 {
            break;
        }
    }
    let peak = 0.5 * (lo + hi);
    let top = l(peak);
    // Width of the peak from L'' (central difference of L').
    let delta = 1e-4;
    let curvature = ((dl(peak - delta) - dl(peak + delta)) / (2.0 * delta)).max(1e-12);
    let mut h = 0.25 / curvature.sqrt();
    // Trapezoid over the nodes peak + k·h until L − top < −50 on both sides.
    let trapezoid = |h: f64, offset: f64, step: usize| {
        let mut s = 0.0;
        for dir in [1.0, -1.0] {
            let mut k = if dir > 0.0 { 0usize } else { 1 };
            loop {
                let y = peak + offset + dir * (k as f64) * h * step as f64;
                let v = l(y) - top;
                s += v.exp();
                if v < -50.0 || k > 1 << 20 {
                    break;
                }
                k += 1;
            }
        }
        s
    };
    let mut sum = trapezoid(h, 0.0, 1);
    let mut estimate = sum * h;
    for _ in 0..30 {
        // Halving the step adds the midpoints.
        let mid = trapezoid(h, 0.5 * h, 1);
        sum += mid;
        h *= 0.5;
        let next = sum * h;
        let done = (next - estimate).abs() <= 1e-15 * next;
        estimate = next;
        if done {
            break;
        }
    }
    (top + estimate.ln()).exp()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn family(kind: GenzKind, a: &[f64], u: &[f64]) -> GenzFamily {
        GenzFamily {
            kind,
            a: PerDim::list(a).unwrap(),
            u: PerDim::list(u).unwrap(),
        }
    }

    const KINDS: [GenzKind; 6] = [
        GenzKind::Oscillatory,
        GenzKind::ProductPeak,
        GenzKind::CornerPeak,
        GenzKind::Gaussian,
        GenzKind::Continuous,
        GenzKind::Discontinuous,
    ];

    /// ∫ over [0,1]^D by a tensor product of composite Gauss–Legendre rules: `panels` equal
    /// panels per axis with every uᵢ also a panel boundary (the kinks and steps), 20 nodes each.
    fn tensor_gauss(g: &Genz, u: &[f64], panels: usize) -> f64 {
        let rule = crate::core::filter::quad::GaussLegendre::new(20);
        let axis = |ui: f64| {
            let mut cuts: Vec<f64> = (0..=panels).map(|k| k as f64 / panels as f64).collect();
            if ui > 0.0 && ui < 1.0 {
                cuts.push(ui);
            }
            cuts.sort_by(f64::total_cmp);
            cuts.dedup();
            let mut nodes = Vec::new();
            for w in cuts.windows(2) {
                let (lo, hi) = (w[0], w[1]);
                for (x, wt) in rule.nodes.iter().zip(&rule.weights) {
                    nodes.push((lo + (hi - lo) * 0.5 * (x + 1.0), wt * 0.5 * (hi - lo)));
                }
            }
            nodes
        };
        let axes: Vec<Vec<(f64, f64)>> = u.iter().map(|&ui| axis(ui)).collect();
        let d = axes.len();
        let mut idx = vec![0usize; d];
        let mut x = vec![0.0; d];
        let mut total = 0.0;
        loop {
            let mut w = 1.0;
            for i in 0..d {
                x[i] = axes[i][idx[i]].0;
                w *= axes[i][idx[i]].1;
            }
            total += w * g.eval(&x);
            let mut i = 0;
            loop {
                if i == d {
                    return total;
                }
                idx[i] += 1;
                if idx[i] < axes[i].len() {
                    break;
                }
                idx[i] = 0;
                i += 1;
            }
        }
    }

    #[test]
    fn closed_forms_match_tensor_gauss_legendre_in_one_two_and_three_dimensions() {
        // Moderate parameters (the rule resolves the peaks), edges and kinks on panel
        // boundaries: |closed form − quadrature| ≤ 1e−10 · max(1, |I|).
        let cases: [(&[f64], &[f64]); 3] = [
            (&[3.0], &[0.3]),
            (&[2.5, 0.0], &[0.7, 0.2]),
            (&[1.5, 4.0, 0.5], &[0.25, 0.6, 0.9]),
        ];
        for kind in KINDS {
            for (a, u) in cases {
                if kind == GenzKind::ProductPeak && a.contains(&0.0) {
                    continue; // f ≡ 0, refused (bad_sets_… below)
                }
                let g = Genz::new(&family(kind, a, u), a.len()).unwrap();
                let (exact, quad) = (g.integral(), tensor_gauss(&g, u, 4));
                assert!(
                    (exact - quad).abs() <= 1e-10 * exact.abs().max(1.0),
                    "{kind:?} a = {a:?} u = {u:?}: closed form {exact}, quadrature {quad}"
                );
            }
        }
    }

    #[test]
    fn corner_peak_matches_the_vertex_sum_where_it_does_not_cancel() {
        // Few dimensions, large a: the alternating sum has little cancellation; relative 1e−12.
        let vertex_sum = |a: &[f64]| {
            let d = a.len();
            let mut s = 0.0;
            for mask in 0u32..(1 << d) {
                let dot: f64 = (0..d).filter(|i| mask >> i & 1 == 1).map(|i| a[i]).sum();
                let sign = if mask.count_ones() % 2 == 0 {
                    1.0
                } else {
                    -1.0
                };
                s += sign / (1.0 + dot);
            }
            let fact: f64 = (1..=d).map(|k| k as f64).product();
            s / (fact * a.iter().product::<f64>())
        };
        for a in [
            &[2.0][..],
            &[600.0],
            &[3.0, 5.0],
            &[10.0, 20.0, 30.0],
            &[4.0, 8.0, 1.0, 9.0],
        ] {
            let (ours, sum) = (corner_peak_integral(a), vertex_sum(a));
            assert!((ours / sum - 1.0).abs() < 1e-12, "{a:?}: {ours} vs {sum}");
        }
        assert!((corner_peak_integral(&[2.0]) - 1.0 / 3.0).abs() < 1e-15);
        // a = 0 everywhere: f ≡ 1.
        assert!((corner_peak_integral(&[0.0; 7]) - 1.0).abs() < 1e-13);
    }

    /// Non-negative big integers, little-endian base 2³², for the exact rational reference.
    #[derive(Clone, Debug, PartialEq)]
    struct Big(Vec<u32>);

    impl Big {
        fn one() -> Big {
            Big(vec![1])
        }
        fn mul(&mut self, m: u64) {
            let mut carry: u128 = 0;
            for limb in &mut self.0 {
                let v = *limb as u128 * m as u128 + carry;
                *limb = v as u32;
                carry = v >> 32;
            }
            while carry > 0 {
                self.0.push(carry as u32);
                carry >>= 32;
            }
        }
        fn add(&mut self, o: &Big) {
            let mut carry = 0u64;
            for i in 0..o.0.len().max(self.0.len()) {
                if i == self.0.len() {
                    self.0.push(0);
                }
                let v = self.0[i] as u64 + *o.0.get(i).unwrap_or(&0) as u64 + carry;
                self.0[i] = v as u32;
                carry = v >> 32;
            }
            if carry > 0 {
                self.0.push(carry as u32);
            }
        }
        /// self − o, for self ≥ o.
        fn sub(&mut self, o: &Big) {
            let mut borrow = 0i64;
            for i in 0..self.0.len() {
                let v = self.0[i] as i64 - *o.0.get(i).unwrap_or(&0) as i64 - borrow;
                borrow = (v < 0) as i64;
                self.0[i] = v.rem_euclid(1 << 32) as u32;
            }
            assert_eq!(borrow, 0, "negative");
        }
        fn ge(&self, o: &Big) -> bool {
            let trim = |v: &[u32]| v.iter().rposition(|&x| x != 0).map_or(0, |p| p + 1);
            let (a, b) = (&self.0[..trim(&self.0)], &o.0[..trim(&o.0)]);
            if a.len() != b.len() {
                return a.len() > b.len();
            }
            a.iter().rev().cmp(b.iter().rev()) != std::cmp::Ordering::Less
        }
        /// (m, e) with the value ≈ m·2^e, m from the top 96 bits.
        fn to_f64_exp(&self) -> (f64, i64) {
            let n = self.0.iter().rposition(|&x| x != 0).map_or(0, |p| p + 1);
            let mut m = 0.0;
            let lo = n.saturating_sub(3);
            for i in (lo..n).rev() {
                m = m * 4294967296.0 + self.0[i] as f64;
            }
            (m, 32 * lo as i64)
        }
    }

    /// The corner peak's integral for D = Σ counts dimensions, `counts[j]` of them with
    /// aᵢ = nums[j]/den, exactly: the vertex sum grouped by 1 + a·v = m/den, summed over a
    /// common denominator in big integers, divided once at the end.
    fn corner_peak_exact(nums: &[u64], counts: &[u32], den: u64) -> f64 {
        let d: u32 = counts.iter().sum();
        let binom = |n: u32, k: u32| (0..k).fold(1u64, |c, i| c * (n - i) as u64 / (i + 1) as u64);
        // Coefficient of 1/m in Σ_v (−1)^|v| / (1 + a·v), with 1 + a·v = m/den.
        let mut coef: std::collections::BTreeMap<u64, i128> = Default::default();
        let mut ks = vec![0u32; counts.len()];
        loop {
            let m = den
                + ks.iter()
                    .zip(nums)
                    .map(|(&k, &p)| k as u64 * p)
                    .sum::<u64>();
            let sign = if ks.iter().sum::<u32>() % 2 == 0 {
                1
            } else {
                -1
            };
            let c: i128 = ks
                .iter()
                .zip(counts)
                .map(|(&k, &n)| binom(n, k) as i128)
                .product();
            *coef.entry(m).or_default() += sign * c;
            let mut j = 0;
            loop {
                if j == ks.len() {
                    break;
                }
                ks[j] += 1;
                if ks[j] <= counts[j] {
                    break;
                }
                ks[j] = 0;
                j += 1;
            }
            if j == ks.len() {
                break;
            }
        }
        // Σ c_m·den/m = den·Σ c_m·(Π_{m'≠m} m')/Π m'.
        let ms: Vec<u64> = coef.keys().copied().collect();
        let (mut pos, mut neg) = (Big(vec![0]), Big(vec![0]));
        for (i, (_, &c)) in coef.iter().enumerate() {
            let mut t = Big::one();
            for (j, &m2) in ms.iter().enumerate() {
                if j != i {
                    t.mul(m2);
                }
            }
            t.mul(c.unsigned_abs() as u64);
            if c > 0 {
                pos.add(&t);
            } else {
                neg.add(&t);
            }
        }
        assert!(pos.ge(&neg));
        pos.sub(&neg);
        // I = den^(D+1)·(pos − neg) / (Π m · D! · Π nums^counts).
        let mut num = pos;
        for _ in 0..=d {
            num.mul(den);
        }
        let mut denom = Big::one();
        for &m in &ms {
            denom.mul(m);
        }
        for k in 2..=d as u64 {
            denom.mul(k);
        }
        for (&p, &n) in nums.iter().zip(counts) {
            for _ in 0..n {
                denom.mul(p);
            }
        }
        let ((mn, en), (md, ed)) = (num.to_f64_exp(), denom.to_f64_exp());
        mn / md * 2f64.powi((en - ed) as i32)
    }

    #[test]
    fn corner_peak_in_32_dimensions_matches_exact_rational_arithmetic() {
        // Relative 1e−12 against the vertex sum evaluated exactly (big integers), where the
        // floating-point vertex sum has no correct digit left: a = 1/64 (Genz's normalised
        // difficulty 600/32² ≈ 0.59 spread over 32 axes), a = 1/4, and half 1/2, half 3/4.
        let cases: [(&[u64], &[u32], u64); 4] = [
            (&[1], &[32], 64),
            (&[1], &[32], 4),
            (&[2, 3], &[16, 16], 4),
            (&[1, 5, 40], &[10, 12, 10], 8),
        ];
        for (nums, counts, den) in cases {
            let a: Vec<f64> = nums
                .iter()
                .zip(counts)
                .flat_map(|(&p, &n)| vec![p as f64 / den as f64; n as usize])
                .collect();
            let exact = corner_peak_exact(nums, counts, den);
            let ours = corner_peak_integral(&a);
            assert!(
                (ours / exact - 1.0).abs() < 1e-12,
                "a = {nums:?}/{den} × {counts:?}: {ours:e} vs exact {exact:e}"
            );
        }
        // The exact reference itself agrees with the closed form in one dimension.
        assert!((corner_peak_exact(&[3], &[1], 4) - 1.0 / (1.0 + 0.75)).abs() < 1e-16);
    }

    #[test]
    fn closed_forms_match_monte_carlo_in_8_and_32_dimensions() {
        // 2^18 uniform points per case: |mean − I| ≤ 5 standard errors (s/√N); a correct
        // closed form fails this with probability below 1e−6 (the seed is fixed).
        let mut rng = Rng::new(42);
        for dims in [8usize, 32] {
            for kind in KINDS {
                let f = GenzFamily::randomized(kind, dims, &mut rng);
                let g = Genz::new(&f, dims).unwrap();
                let n = 1 << 18;
                let (mut s, mut s2) = (0.0, 0.0);
                let mut x = vec![0.0; dims];
                for _ in 0..n {
                    for v in &mut x {
                        *v = rng.next_f64();
                    }
                    let y = g.eval(&x);
                    s += y;
                    s2 += y * y;
                }
                let mean = s / n as f64;
                let se = ((s2 / n as f64 - mean * mean).max(0.0) / n as f64).sqrt();
                let err = (mean - g.integral()).abs();
                assert!(
                    err <= 5.0 * se + 1e-14 * g.integral().abs(),
                    "{kind:?} D = {dims}: mean {mean:e}, closed form {:e}, s.e. {se:e}",
                    g.integral()
                );
            }
        }
    }

    #[test]
    fn random_instances_follow_genz_s_normalisation() {
        let mut rng = Rng::new(7);
        for kind in KINDS {
            for dims in [1usize, 2, 3, 8, 32] {
                let f = GenzFamily::randomized(kind, dims, &mut rng);
                let (h, e) = kind.difficulty();
                let a = f.a.expand(dims).unwrap();
                let sum: f64 = a.iter().sum();
                assert!((sum / (h / (dims as f64).powf(e)) - 1.0).abs() < 1e-12);
                assert!(a.iter().all(|&x| x > 0.0 && x <= MAX_A));
                let u = f.u.expand(dims).unwrap();
                assert!(u.iter().all(|x| (0.0..1.0).contains(x)));
                Genz::new(&f, dims).unwrap();
            }
        }
        // The draws, in order: a′₁, u₁, a′₂, u₂.
        let f = GenzFamily::randomized(GenzKind::Gaussian, 2, &mut Rng::new(3));
        let mut r = Rng::new(3);
        let (a1, u1, a2, u2) = (
            1.0 - r.next_f64(),
            r.next_f64(),
            1.0 - r.next_f64(),
            r.next_f64(),
        );
        assert_eq!(f.u.as_slice(), &[u1, u2]);
        let scale = 100.0 / 2.0 / (a1 + a2);
        assert_eq!(f.a.as_slice(), &[a1 * scale, a2 * scale]);
    }

    #[test]
    fn the_definitions_at_a_point() {
        let x = [0.2, 0.9, 0.4];
        let (a, u) = ([1.5, 2.0, 0.5], [0.3, 0.5, 0.8]);
        let g = |kind| Genz::new(&family(kind, &a, &u), 3).unwrap().eval(&x);
        let close = |v: f64, w: f64| (v - w).abs() <= 1e-15 * w.abs().max(1.0);
        assert!(close(
            g(GenzKind::Oscillatory),
            (2.0 * PI * 0.3 + 0.3 + 1.8 + 0.2f64).cos()
        ));
        let pp: f64 = (0..3)
            .map(|i| 1.0 / (a[i].powi(-2) + (x[i] - u[i]).powi(2)))
            .product();
        assert!(close(g(GenzKind::ProductPeak), pp));
        assert!(close(
            g(GenzKind::CornerPeak),
            (1.0 + 0.3 + 1.8 + 0.2f64).powi(-4)
        ));
        let gs: f64 = (0..3).map(|i| (a[i] * (x[i] - u[i])).powi(2)).sum();
        assert!(close(g(GenzKind::Gaussian), (-gs).exp()));
        let cs: f64 = (0..3).map(|i| a[i] * (x[i] - u[i]).abs()).sum();
        assert!(close(g(GenzKind::Continuous), (-cs).exp()));
        // x₂ = 0.9 > u₂ = 0.5: zero; inside, exp(a·x); the third u is not used.
        assert_eq!(g(GenzKind::Discontinuous), 0.0);
        let d = Genz::new(&family(GenzKind::Discontinuous, &a, &u), 3).unwrap();
        assert!(close(
            d.eval(&[0.2, 0.4, 0.95]),
            (0.3 + 0.8 + 0.475f64).exp()
        ));
        // One dimension: only x₁ > u₁ cuts.
        let d1 = Genz::new(&family(GenzKind::Discontinuous, &[2.0], &[0.5]), 1).unwrap();
        assert_eq!(d1.eval(&[0.6]), 0.0);
        assert!(close(d1.eval(&[0.4]), 0.8f64.exp()));
        assert!(close(d1.integral(), (1f64.exp() - 1.0) / 2.0));
        // A rotation: f((x + s) mod 1).
        let s = [0.9, 0.05, 0.7];
        let shifted = [0.1f64, 0.95, 0.1];
        let gg = Genz::new(&family(GenzKind::Gaussian, &a, &u), 3).unwrap();
        let want = gg.eval(&shifted);
        assert!((gg.eval_shifted(&x, Some(&s)) - want).abs() < 1e-15);
    }

    #[test]
    fn bad_sets_name_the_field_and_the_range() {
        let msg = |f: &GenzFamily, dims| Genz::new(f, dims).unwrap_err().to_string();
        let f = family(GenzKind::Gaussian, &[1.0, 2.0, 3.0], &[0.5]);
        assert_eq!(
            msg(&f, 8),
            "genz-gaussian.a = [1,2,3] (3 numbers): must be one number (every dimension) or a \
             list of 8, one per dimension (dims = 8)"
        );
        let f = family(GenzKind::Continuous, &[1.0], &[0.5, 0.5]);
        assert!(msg(&f, 3).starts_with("genz-continuous.u = [0.5,0.5] (2 numbers)"));
        // Π aᵢ² overflows: 1000² ^ 64 = 1e384.
        let f = family(GenzKind::ProductPeak, &[1000.0], &[0.5]);
        assert!(Genz::new(&f, 51).is_ok());
        let e = msg(&f, 64);
        assert!(
            e.starts_with("genz-product-peak.a = 1000: must be a set whose peak value"),
            "{e}"
        );
        // The discontinuous peak exp(Σ aᵢ) overflows past 709.
        let f = family(GenzKind::Discontinuous, &[100.0], &[0.5]);
        assert!(msg(&f, 9).starts_with("genz-discontinuous.a = 100"));
        // The integral underflows: the Gaussian with a = 1000 in 200 dimensions (≈ 8.9e−4^200).
        let f = family(GenzKind::Gaussian, &[1000.0], &[0.5]);
        assert!(Genz::new(&f, 100).is_ok());
        assert!(msg(&f, 200).contains("integral"));
        // The product peak with an entry 0 is f ≡ 0: its integral is refused.
        let f = family(GenzKind::ProductPeak, &[2.0, 0.0], &[0.5]);
        assert!(msg(&f, 2).contains("integral"));
        // The oscillatory family's integral may be 0 or negative.
        let f = family(GenzKind::Oscillatory, &[PI], &[0.25]);
        let g = Genz::new(&f, 2).unwrap();
        assert!(g.integral().abs() < 1e-15, "{}", g.integral());
    }
}
