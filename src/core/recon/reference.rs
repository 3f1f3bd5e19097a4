//! Reference images: the box-prefiltered signal, R(i, j) = W² ∫∫_pixel f(p) dp.
//!
//! This is the image a perfect box-filtered renderer would produce; reconstruction errors are
//! measured against it. Per signal:
//!
//! | signal | method | how |
//! |---|---|---|
//! | step edge, polygon | [`ReferenceMethod::ExactArea`] | area coverage: the pixel square clipped against the shape's half-planes (Sutherland–Hodgman), shoelace area ([`super::coverage`]) |
//! | grating | [`ReferenceMethod::ExactIntegral`] | mean of sin(2πf n·p) over a box = sin(2πf n·m)·sinc(f nₓ/W)·sinc(f n_y/W), m the pixel centre, sinc(x) = sin πx/(πx) |
//! | sum of sines | [`ReferenceMethod::ExactIntegral`] | the same, 1D: sin(2πf mₓ)·sinc(f/W) per term |
//! | square wave | [`ReferenceMethod::ExactIntegral`] | difference of the antiderivative F(x) = (⌊fx⌋/2 + min(frac(fx), ½))/f |
//! | constant | [`ReferenceMethod::ExactIntegral`] | the value |
//! | zone plate | [`ReferenceMethod::SeparableQuadrature`] | sin(πK(u² + v²)) = sin(πKu²)cos(πKv²) + cos(πKu²)sin(πKv²): products of 1D pixel means, each by composite Gauss–Legendre quadrature, with an error bound (below) |
//! | chirp | [`ReferenceMethod::SeparableQuadrature`] | the 1D pixel mean of the chirp per column, by the same quadrature |
//! | checkerboard | [`ReferenceMethod::Supersampled`] | stratified jittered supersampling with an error estimate (below) |
//!
//! Exact methods have `error_estimate = None`: their error is rounding only (≲ 10⁻¹³).
//!
//! ## Quadrature references (zone plate, chirp)
//!
//! **Separation.** With u = x − cₓ, v = y − c_y and φ(t) = πKt², the zone plate's pixel mean
//! over [i/W, (i+1)/W] × [j/W, (j+1)/W] is exactly
//!
//! ```text
//! R(i, j) = ½(1 + σˣᵢ γʸⱼ + γˣᵢ σʸⱼ),   σˣᵢ = W ∫ sin φ(x − cₓ) dx,  γˣᵢ = W ∫ cos φ(x − cₓ) dx
//! ```
//!
//! over pixel column i (σʸⱼ, γʸⱼ likewise with c_y over pixel row j): 4W one-dimensional means
//! instead of W² two-dimensional integrals (2W when cₓ = c_y: the two axes are then the same).
//! The chirp is ½(1 + σᵢ) with σᵢ the mean of sin(2π(f₀x + (f₁ − f₀)x²/2)) over column i, the
//! same for every row. The phase is formed as the signals form it (double-double, reduced
//! exactly by [`rem2`], then [`sin_pi`] / [`cos_pi`](crate::core::signal::exact::cos_pi)); the
//! nodes are placed in double-double pixel coordinates, so the pixel edges i/W are exact even
//! when W is not a power of two.
//!
//! **Quadrature.** Each pixel interval is cut into m equal subintervals, m = ⌈F/q⌉ with F the
//! largest local frequency on the interval in cycles per pixel (K·|u|/W for the zone plate,
//! (f₀ + (f₁ − f₀)x)/W for the chirp; linear in x, so largest at an end) and q = 1.25 cycles:
//! near u = 0 one subinterval suffices, far out m grows like K|u|/W. Every subinterval gets the
//! n = 20-point Gauss–Legendre rule (the returned means) and the 16-point rule (a check). Cost:
//! 36 evaluations of (sin, cos) per subinterval: the default 512² plate (K = 256, at most ¼
//! cycle per pixel) needs 512 subintervals, 18 432 evaluations for both axes, plus W² products,
//! against 8.4·10⁷ signal evaluations for 8×8 + 16×16 supersampling.
//!
//! **Error bound.** On a subinterval mapped to t ∈ [−1, 1] the integrand is e^{iψ(t)} with
//! ψ(t) = θ + αt + βt² and max|ψ'| = |α| + 2|β| ≤ πq (at most q cycles over the subinterval,
//! i.e. 2πq radians over a length 2). It is entire and bounded on the Bernstein ellipse E_ρ (semi-axes
//! a = (ρ + 1/ρ)/2, b = (ρ − 1/ρ)/2) by M = exp(πq·ab), so the n-point rule's error for the mean
//! over the subinterval is at most (32/15)·M·ρ^(2−2n)/(ρ² − 1) (Chebyshev coefficients
//! |a_k| ≤ 2Mρ^(−k), Trefethen 2008, "Is Gauss quadrature better than Clenshaw–Curtis?",
//! Thm. 4.5): with n = 20, q = 1.25 and ρ = 4.5 this is T = 6.9·10⁻¹⁸ (the 16-point check rule:
//! 7.7·10⁻¹³ by the same bound, ≈ 10⁻¹⁶ measured). Per pixel interval the returned mean σᵢ (and
//! γᵢ) therefore errs by at most
//!
//! ```text
//! eᵢ = δᵢ + T + ρᵢ,   δᵢ = max(|σᵢ − σᵢ^(16)|, |γᵢ − γᵢ^(16)|),
//! ρᵢ = 3·10⁻¹⁶ + π(2⁻⁵¹ + 4q·2⁻⁵³ + 2⁻¹⁰⁰·Pᵢ) + (n + 4)·2⁻⁵³ + mᵢ·2⁻¹⁰⁴
//! ```
//!
//! where δᵢ is the a-posteriori fine–coarse difference (the measured error of the coarse rule,
//! a safety margin over T that would also expose a wrong frequency model) and ρᵢ bounds
//! the rounding: the error of `sin_pi`/`cos_pi`, of [`rem2`] (2⁻⁵¹, in units of π), of the node
//! positions (≤ 2⁻⁵³/m pixels, moving the phase/π by ≤ 2F·2⁻⁵³/m ≤ 2q·2⁻⁵³), of the
//! double-double phase (Pᵢ the largest |phase/π| on the interval), of the n-term sums and the
//! weights, and of the double-double sum over the subintervals. With e = maxᵢ eᵢ over both axes
//! and the true means σ̄, γ̄ (so |σ − σ̄|, |γ − γ̄| ≤ e):
//!
//! ```text
//! |σˣγʸ − σ̄ˣγ̄ʸ| ≤ |σˣ − σ̄ˣ||γʸ| + |σ̄ˣ||γʸ − γ̄ʸ| ≤ e|γʸ| + e(|σˣ| + e),
//! |R̂ − R| ≤ ½e(Mₓ + M_y + 2e) + 5·2⁻⁵³,   M = maxᵢ(|σᵢ| + |γᵢ|) ≤ √2,
//! ```
//!
//! the last term for forming ½(1 + σγ + γσ). For the chirp |R̂ − R| ≤ ½e + 2·2⁻⁵³. That bound
//! is the reported `error_estimate`: a bound on the **largest** pixel error (so also on the
//! RMS error), typically ≈ 10⁻¹⁴. Clamping to [0, 1] (the true means lie there) only lowers
//! the error.
//!
//! **Work cap.** The number of evaluations is computed before any is made and refused above
//! [`MAX_WORK`](super::MAX_WORK) with [`ReconError::TooMuchWork`]: Σm ≈ W + |K|·∫₀¹|x − c|dx/q
//! per axis, i.e. about 7|K| evaluations for the centred plate (cₓ = c_y = ½, one axis) and up
//! to 86|K| for c = (2, −1), so |K| above 2·10⁹ (centred) down to 2·10⁸ (far off-centre) is
//! refused; a chirp (f ≤ 10⁶, at most 3·10⁷ evaluations) never is. There is no fallback to
//! supersampling: at such K a pixel holds 10⁴ cycles and more even at W = 8192, and 16×16
//! jittered samples would return noise around ½ (with an estimate saying so), not a reference.
//!
//! ## Supersampled references (checkerboard; any signal via [`reference_supersampled`])
//!
//! **Supersampled references** use s×s jittered strata per pixel (one uniform point per
//! stratum, per-pixel streams `derive_seed(seed, pixel)`), twice: I_s with s×s and I_2s with
//! 2s×2s strata, independent seeds. The returned pixels are I_2s and the error estimate is
//! ε = RMS(I_s − I_2s) = √(mean over pixels of (I_s − I_2s)²). Since the two are independent
//! and the finer one has the smaller error, ε² ≈ E_s² + E_2s² ≥ E_s², i.e. ε estimates the RMS
//! error of the coarser I_s; jittered sampling's error falls by at least 2^(3/2) ≈ 2.8 when s
//! doubles (Mitchell 1996: N^(−3/4) at edges, faster on smooth regions), so ε over-estimates
//! the error of the returned I_2s about threefold: a conservative estimate. Cost: 5s² signal
//! evaluations per pixel. When the signal is not resolved even at 2s strata per pixel (a zone
//! plate with K·ρ ≫ 2sW) the two differ, and ε says so.
//!
//! **Progressive.** [`reference_image_progressive`] hands out I_s (method
//! [`ReferenceMethod::Jittered`]) as soon as it is done, pass 1 of 2, then computes I_2s and
//! returns exactly what [`reference_image_with`] returns (which is the progressive function
//! with [`no_progress`]). I_s's own estimate is the per-pixel standard error
//! √(mean over pixels of s²ₚ/N), N = s² and s²ₚ the sample variance of pixel p's N values: with one uniform point per stratum,
//! E\[s²ₚ\] = N/(N − 1)·(σₚ² − Var(Īₚ)) ≥ σₚ² ≥ N·Var(Īₚ) (σₚ² the variance of f over the pixel;
//! stratification gives Var(Īₚ) ≤ σₚ²/N, often much less), so the estimate is conservative in
//! expectation, by the stratification gain; `None` when s = 1.

use super::coverage::{half_planes, pixel_coverage};
use super::{check_cancel, check_size, check_work, ReconError, MAX_W};
use crate::core::cancel::Cancel;
use crate::core::progress::{no_progress, OnProgress, Progress};
use crate::core::rng::{derive_seed, Rng};
use crate::core::signal::exact::{rem2, sin_pi, DoubleDouble};
use crate::core::signal::{sinc_pi, Chirp, Signal, ZonePlate};
use glam::DVec2;
use quadrature::{axis_means, plan, QuadraticPhase, FINE_NODES, U};
use rayon::prelude::*;
use std::time::{Duration, Instant};

mod quadrature;

/// How a reference image was computed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum ReferenceMethod {
    /// Exact area coverage of each pixel by the shape.
    ExactArea,
    /// A closed-form integral of the signal over each pixel.
    ExactIntegral,
    /// Separable composite Gauss–Legendre quadrature (zone plate, chirp): products of 1D pixel
    /// means, `nodes` Gauss–Legendre points per subinterval; `error_estimate` is a bound on
    /// the largest pixel error (see the module docs).
    SeparableQuadrature {
        /// n, the nodes per subinterval of the returned rule.
        nodes: usize,
    },
    /// Jittered supersampling with `strata`×`strata` and 2·`strata`×2·`strata` samples per
    /// pixel (the finer image is returned).
    Supersampled {
        /// s, the strata per axis of the coarser pass.
        strata: usize,
    },
    /// One pass of `strata`×`strata` jittered samples per pixel: the intermediate image of a
    /// progressive supersampled reference ([`reference_image_progressive`]).
    Jittered {
        /// s, the strata per axis.
        strata: usize,
    },
}

impl ReferenceMethod {
    /// A human-readable name, e.g. "separable Gauss–Legendre quadrature (20-point)".
    pub fn label(&self) -> String {
        match *self {
            ReferenceMethod::ExactArea => "exact area coverage".to_string(),
            ReferenceMethod::ExactIntegral => "exact pixel integral".to_string(),
            ReferenceMethod::SeparableQuadrature { nodes } => {
                format!("separable Gauss–Legendre quadrature ({nodes}-point)")
            }
            ReferenceMethod::Supersampled { strata } => {
                format!("{0}×{0} jittered supersampling", 2 * strata)
            }
            ReferenceMethod::Jittered { strata } => {
                format!("{strata}×{strata} jittered supersampling (first pass)")
            }
        }
    }

    /// Whether `error_estimate` is a bound on the largest pixel error (quadrature) rather than
    /// an estimate of the RMS error (supersampling).
    pub fn estimate_is_bound(&self) -> bool {
        matches!(self, ReferenceMethod::SeparableQuadrature { .. })
    }
}

impl std::fmt::Display for ReferenceMethod {
    /// The [`label`](ReferenceMethod::label).
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.label())
    }
}

/// A box-prefiltered W×W reference image.
#[derive(Debug, Clone, PartialEq)]
pub struct ReferenceImage {
    /// Size W.
    pub w: usize,
    /// Pixel means, row-major (`pixels[j·W + i]`).
    pub pixels: Vec<f64>,
    /// The image's own error (see the module docs): for supersampling an estimated RMS error
    /// (an over-estimate); for quadrature a bound on the largest pixel error; `None` when
    /// exact.
    pub error_estimate: Option<f64>,
    /// How the pixels were computed.
    pub method: ReferenceMethod,
    /// Wall-clock time.
    pub wall_time: Duration,
}

/// Options of supersampled references.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ReferenceOptions {
    /// s: strata per axis of the coarser pass (the returned pass has 2s), in 1..=64.
    pub strata: usize,
    /// Seed of the jitter.
    pub seed: u64,
}

impl Default for ReferenceOptions {
    fn default() -> Self {
        ReferenceOptions {
            strata: 8,
            seed: 0x5eed_2ef0,
        }
    }
}

/// Largest `strata`.
pub const MAX_STRATA: usize = 64;

/// The box-prefiltered reference with default options (exact or quadrature where possible,
/// else 8×8 and 16×16 jittered supersampling).
pub fn reference_image(signal: &Signal, w: usize) -> Result<ReferenceImage, ReconError> {
    reference_image_with(signal, w, &ReferenceOptions::default(), &Cancel::never())
}

/// The box-prefiltered reference: exact where a closed form exists, by separable quadrature
/// for the zone plate and the chirp, supersampled otherwise (see the module docs). `options`
/// are used (and checked) only by supersampled references.
pub fn reference_image_with(
    signal: &Signal,
    w: usize,
    options: &ReferenceOptions,
    cancel: &Cancel,
) -> Result<ReferenceImage, ReconError> {
    reference_image_progressive(signal, w, options, cancel, &mut no_progress)
}

/// [`reference_image_with`], handing out intermediate images: `progress`
/// ([`crate::core::progress`]) gets pass k of n after each pass, with its image (after the
/// last: the returned image). A supersampled reference has two passes, the s×s pass I_s
/// ([`ReferenceMethod::Jittered`], its estimate described in the module docs) and I_2s, which
/// it returns; exact and quadrature references have one pass. The result is bit for bit that
/// of [`reference_image_with`] (which calls this with [`no_progress`]): the first pass is
/// computed once and reused.
pub fn reference_image_progressive(
    signal: &Signal,
    w: usize,
    options: &ReferenceOptions,
    cancel: &Cancel,
    progress: &mut OnProgress<'_, ReferenceImage>,
) -> Result<ReferenceImage, ReconError> {
    signal.validate()?;
    check_size("w", w, 1, MAX_W)?;
    let start = Instant::now();
    let (method, pixels, error_estimate) = match signal {
        Signal::StepEdge(s) => {
            let (n, b) = s.half_plane();
            (
                ReferenceMethod::ExactArea,
                area_image(&[(n, b)], w, cancel)?,
                None,
            )
        }
        Signal::Polygon(p) => {
            let planes = half_planes(&p.vertices());
            (
                ReferenceMethod::ExactArea,
                area_image(&planes, w, cancel)?,
                None,
            )
        }
        Signal::Grating(_) | Signal::SumOfSines(_) | Signal::Square(_) | Signal::Constant(_) => (
            ReferenceMethod::ExactIntegral,
            per_pixel(w, cancel, |i, j| box_integral(signal, i, j, w))?,
            None,
        ),
        Signal::ZonePlate(z) => {
            let (pixels, bound) = zone_plate_quadrature(z, w, cancel)?;
            (
                ReferenceMethod::SeparableQuadrature { nodes: FINE_NODES },
                pixels,
                Some(bound),
            )
        }
        Signal::Chirp(c) => {
            let (pixels, bound) = chirp_quadrature(c, w, cancel)?;
            (
                ReferenceMethod::SeparableQuadrature { nodes: FINE_NODES },
                pixels,
                Some(bound),
            )
        }
        Signal::Checkerboard(_) => {
            return supersampled(signal, w, options, cancel, progress);
        }
    };
    let image = ReferenceImage {
        w,
        pixels,
        error_estimate,
        method,
        wall_time: start.elapsed(),
    };
    progress(Progress::with(1, 1, &image));
    Ok(image)
}

/// The work [`reference_image_with`] does for `signal` at size `w`, counted from the same
/// parameters its loops use and without allocating: the method it will use and the count of
/// its inner-loop steps. Exact methods count pixels (one area coverage or closed-form
/// integral each); quadrature counts integrand evaluations (Σᵢ mᵢ subintervals times the 36
/// nodes of the two rules, per distinct axis; the loop of the quadrature itself); supersampling
/// counts signal evaluations (5s² per pixel: the s×s and 2s×2s passes). `w` and
/// `options.strata` are not checked here; the reference itself refuses them.
pub fn reference_work(
    signal: &Signal,
    w: usize,
    options: &ReferenceOptions,
) -> (ReferenceMethod, u128) {
    let pixels = (w as u128) * (w as u128);
    let axis = |phase: &QuadraticPhase| -> u128 {
        (0..w).map(|i| phase.subintervals(i) as u128).sum::<u128>()
            * quadrature::EVALS_PER_SUBINTERVAL
    };
    match signal {
        Signal::StepEdge(_) | Signal::Polygon(_) => (ReferenceMethod::ExactArea, pixels),
        Signal::Grating(_) | Signal::SumOfSines(_) | Signal::Square(_) | Signal::Constant(_) => {
            (ReferenceMethod::ExactIntegral, pixels)
        }
        Signal::ZonePlate(z) => {
            let px = QuadraticPhase::zone_plate_axis(z.k, z.cx, w);
            let py = QuadraticPhase::zone_plate_axis(z.k, z.cy, w);
            let work = if px == py {
                axis(&px)
            } else {
                axis(&px) + axis(&py)
            };
            (
                ReferenceMethod::SeparableQuadrature { nodes: FINE_NODES },
                work,
            )
        }
        Signal::Chirp(c) => (
            ReferenceMethod::SeparableQuadrature { nodes: FINE_NODES },
            axis(&QuadraticPhase::chirp(c.f0, c.f1, w)),
        ),
        Signal::Checkerboard(_) => {
            let s = options.strata as u128;
            (
                ReferenceMethod::Supersampled {
                    strata: options.strata,
                },
                pixels * 5 * s * s,
            )
        }
    }
}

/// Name of the quadrature references in [`ReconError::TooMuchWork`].
const QUADRATURE_WORK: &str = "separable quadrature reference (its cost grows with |K|)";

/// The zone plate's separable quadrature (module docs): pixels and the error bound.
fn zone_plate_quadrature(
    z: &ZonePlate,
    w: usize,
    cancel: &Cancel,
) -> Result<(Vec<f64>, f64), ReconError> {
    let px = QuadraticPhase::zone_plate_axis(z.k, z.cx, w);
    let py = QuadraticPhase::zone_plate_axis(z.k, z.cy, w);
    let same = px == py;
    let (mx, wx) = plan(&px, w);
    let (my, wy) = if same { (Vec::new(), 0) } else { plan(&py, w) };
    check_work(QUADRATURE_WORK, wx + wy)?;
    let x = axis_means(&px, &mx, cancel)?;
    let y_own;
    let y = if same {
        &x
    } else {
        y_own = axis_means(&py, &my, cancel)?;
        &y_own
    };
    let e = x.err.max(y.err);
    let bound = 0.5 * e * (x.mag + y.mag + 2.0 * e) + 5.0 * U;
    let pixels = per_pixel(w, cancel, |i, j| {
        (0.5 * (1.0 + (x.sin[i] * y.cos[j] + x.cos[i] * y.sin[j]))).clamp(0.0, 1.0)
    })?;
    Ok((pixels, bound))
}

/// The chirp's quadrature (module docs): one row of 1D means, copied to every row.
fn chirp_quadrature(c: &Chirp, w: usize, cancel: &Cancel) -> Result<(Vec<f64>, f64), ReconError> {
    let p = QuadraticPhase::chirp(c.f0, c.f1, w);
    let (m, work) = plan(&p, w);
    check_work(QUADRATURE_WORK, work)?;
    let x = axis_means(&p, &m, cancel)?;
    let row: Vec<f64> = x
        .sin
        .iter()
        .map(|s| (0.5 * (1.0 + s)).clamp(0.0, 1.0))
        .collect();
    let pixels = per_pixel(w, cancel, |i, _| row[i])?;
    Ok((pixels, 0.5 * x.err + 2.0 * U))
}

/// The supersampled reference for any signal (see the module docs): I_2s with the estimate
/// RMS(I_s − I_2s).
pub fn reference_supersampled(
    signal: &Signal,
    w: usize,
    options: &ReferenceOptions,
    cancel: &Cancel,
) -> Result<ReferenceImage, ReconError> {
    supersampled(signal, w, options, cancel, &mut no_progress)
}

/// [`reference_supersampled`], reporting I_s as pass 1 of 2 before computing I_2s, then I_2s.
fn supersampled(
    signal: &Signal,
    w: usize,
    options: &ReferenceOptions,
    cancel: &Cancel,
    progress: &mut OnProgress<'_, ReferenceImage>,
) -> Result<ReferenceImage, ReconError> {
    signal.validate()?;
    check_size("w", w, 1, MAX_W)?;
    check_size("strata", options.strata, 1, MAX_STRATA)?;
    let s = options.strata;
    check_work(
        "supersampled reference",
        (w * w) as u128 * 5 * (s * s) as u128,
    )?;
    let start = Instant::now();
    let (coarse, variance) = jittered_image(signal, w, s, derive_seed(options.seed, 0), cancel)?;
    // Mean over pixels of s²ₚ/N (module docs); undefined for one sample per pixel.
    let coarse_estimate = (s > 1).then(|| {
        let n = (s * s) as f64;
        (variance.iter().sum::<f64>() / n / (w * w) as f64).sqrt()
    });
    let coarse = ReferenceImage {
        w,
        pixels: coarse,
        error_estimate: coarse_estimate,
        method: ReferenceMethod::Jittered { strata: s },
        wall_time: start.elapsed(),
    };
    progress(Progress::with(1, 2, &coarse));
    let (fine, _) = jittered_image(signal, w, 2 * s, derive_seed(options.seed, 1), cancel)?;
    let mse = coarse
        .pixels
        .iter()
        .zip(&fine)
        .map(|(a, b)| (a - b) * (a - b))
        .sum::<f64>()
        / (w * w) as f64;
    let image = ReferenceImage {
        w,
        pixels: fine,
        error_estimate: Some(mse.sqrt()),
        method: ReferenceMethod::Supersampled { strata: s },
        wall_time: start.elapsed(),
    };
    progress(Progress::with(2, 2, &image));
    Ok(image)
}

/// Mean of `s×s` jittered samples per pixel, and each pixel's sample variance
/// (Σ(v − mean)²/(N − 1), N = s²; 0 when N = 1); pixel k uses `Rng::new(derive_seed(seed, k))`.
fn jittered_image(
    signal: &Signal,
    w: usize,
    s: usize,
    seed: u64,
    cancel: &Cancel,
) -> Result<(Vec<f64>, Vec<f64>), ReconError> {
    let sw = (s * w) as f64;
    let inv = 1.0 / (s * s) as f64;
    let signal = signal.prepare();
    let both = per_pixel(w, cancel, |i, j| {
        let mut rng = Rng::new(derive_seed(seed, (j * w + i) as u64));
        let (mut sum, mut sum2) = (0.0, 0.0);
        for b in 0..s {
            for a in 0..s {
                let x = ((i * s + a) as f64 + rng.next_f64()) / sw;
                let y = ((j * s + b) as f64 + rng.next_f64()) / sw;
                let v = signal.eval(DVec2::new(x, y));
                sum += v;
                sum2 += v * v;
            }
        }
        let mean = sum * inv;
        let variance = if s > 1 {
            ((sum2 - sum * mean) / (s * s - 1) as f64).max(0.0)
        } else {
            0.0
        };
        (mean, variance)
    })?;
    Ok(both.into_iter().unzip())
}

/// Fills a W×W image with `f(i, j)`, parallel over rows, cancellable every row.
fn per_pixel<T, F>(w: usize, cancel: &Cancel, f: F) -> Result<Vec<T>, ReconError>
where
    T: Copy + Default + Send,
    F: Fn(usize, usize) -> T + Sync,
{
    let mut pixels = vec![T::default(); w * w];
    pixels
        .par_chunks_mut(w)
        .enumerate()
        .try_for_each(|(j, row)| {
            check_cancel(cancel)?;
            for (i, v) in row.iter_mut().enumerate() {
                *v = f(i, j);
            }
            Ok::<(), ReconError>(())
        })?;
    Ok(pixels)
}

/// Area coverage of every pixel by the intersection of half-planes {p : a·p ≥ b}.
fn area_image(planes: &[(DVec2, f64)], w: usize, cancel: &Cancel) -> Result<Vec<f64>, ReconError> {
    per_pixel(w, cancel, |i, j| pixel_coverage(planes, i, j, w))
}

/// (⌊t⌋, frac t) of a double-double t, exact.
fn floor_frac(t: DoubleDouble) -> (f64, f64) {
    let mut fl = t.hi.floor();
    let mut r = (t.hi - fl) + t.lo;
    if r < 0.0 {
        fl -= 1.0;
        r += 1.0;
    } else if r >= 1.0 {
        fl += 1.0;
        r -= 1.0;
    }
    (fl, r)
}

/// Closed-form pixel mean of the signals that have one (see the module table).
fn box_integral(signal: &Signal, i: usize, j: usize, w: usize) -> f64 {
    let wf = w as f64;
    let h = 1.0 / wf;
    let m = DVec2::new((i as f64 + 0.5) / wf, (j as f64 + 0.5) / wf);
    let v = match signal {
        Signal::Grating(g) => {
            let n = crate::core::signal::shapes::direction(g.angle);
            let s = sin_pi(g.phase_over_pi(m));
            0.5 * (1.0 + s * sinc_pi(g.frequency * n.x * h) * sinc_pi(g.frequency * n.y * h))
        }
        Signal::SumOfSines(s) => {
            let mut acc = 0.0;
            for (&f, &a) in s.freqs.iter().zip(&s.amps) {
                if a != 0.0 {
                    acc += a * sin_pi(rem2(DoubleDouble::prod(2.0 * f, m.x))) * sinc_pi(f * h);
                }
            }
            0.5 * (1.0 + acc)
        }
        Signal::Square(sq) => {
            // ∫₀ˣ sq = (⌊fx⌋·½ + min(frac(fx), ½))/f; the pixel mean is W·(F(x₁) − F(x₀)).
            let f = sq.frequency;
            let (n0, r0) = floor_frac(DoubleDouble::prod(f, i as f64 / wf));
            let (n1, r1) = floor_frac(DoubleDouble::prod(f, (i + 1) as f64 / wf));
            let integral = ((n1 - n0) * 0.5 + r1.min(0.5) - r0.min(0.5)) / f;
            integral * wf
        }
        Signal::Constant(c) => c.value,
        // Not reached: the caller only asks for signals with a closed form.
        other => other.eval(m),
    };
    v.clamp(0.0, 1.0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::signal::Checkerboard;

    #[test]
    fn reference_work_is_what_the_quadrature_plans() {
        // The plan the quadrature loops run (and check against MAX_WORK), per distinct axis.
        let w = 300;
        for z in [
            ZonePlate::default(),
            ZonePlate {
                k: 4000.0,
                cx: 0.1,
                cy: 0.8,
            },
        ] {
            let px = QuadraticPhase::zone_plate_axis(z.k, z.cx, w);
            let py = QuadraticPhase::zone_plate_axis(z.k, z.cy, w);
            let planned = plan(&px, w).1 + if px == py { 0 } else { plan(&py, w).1 };
            let (method, work) =
                reference_work(&Signal::ZonePlate(z), w, &ReferenceOptions::default());
            assert_eq!(work, planned);
            assert!(matches!(
                method,
                ReferenceMethod::SeparableQuadrature { .. }
            ));
        }
        let c = Chirp::default();
        let (_, work) = reference_work(&Signal::Chirp(c), w, &ReferenceOptions::default());
        assert_eq!(work, plan(&QuadraticPhase::chirp(c.f0, c.f1, w), w).1);
        // Supersampled: the s×s and 2s×2s passes, 5s² evaluations per pixel.
        let options = ReferenceOptions {
            strata: 3,
            ..ReferenceOptions::default()
        };
        let (method, work) =
            reference_work(&Signal::Checkerboard(Checkerboard::default()), 10, &options);
        assert_eq!(work, 100 * (9 + 36));
        assert_eq!(method, ReferenceMethod::Supersampled { strata: 3 });
    }
}
