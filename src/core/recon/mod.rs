//! Sampling a signal and reconstructing it onto a W×W image; reference images and errors.
//!
//! ## Conventions
//! - **Image.** A W×W image stores pixel (i, j) at `pixels[j·W + i]`; it covers
//!   [i/W, (i+1)/W) × [j/W, (j+1)/W) of the unit square and its centre is ((i+½)/W, (j+½)/W).
//!   Row 0 is y ∈ [0, 1/W), drawn at the top. W is in 1..=[`MAX_W`].
//! - **Reconstruction** is the normalised weighted sum
//!
//!   ```text
//!   I(p) = Σⱼ wⱼ f(xⱼ) / Σⱼ wⱼ,      wⱼ = w((p − xⱼ)/h)      (where Σw ≥ c·Σ|w|: see below)
//!   ```
//!
//!   evaluated at every pixel centre p, with a [`ReconKernel`] w given in filter units and a
//!   scale h: the mean sample spacing h = 1/√N for N scattered samples over the image
//!   ([`scattered`], and [`grid`] where N = G²), the output pixel h = 1/W for supersampling
//!   ([`supersample`](mod@supersample)). A kernel with support r covers |d| < r sample spacings (or pixels).
//! - **Cancelling weights: the floor.** A kernel with negative lobes (Mitchell, Catmull–Rom,
//!   Lanczos, sinc, …) has weights that cancel, and where scattered samples are sparse Σw can
//!   come close to 0 or cross it: Σw·f/Σw then explodes (RMSE 19 and errors of 9·10³ for
//!   Catmull–Rom on 4096 jittered samples). So the normaliser has a floor: with A = Σⱼ|wⱼ|,
//!   P = Σⱼ|wⱼ| f(xⱼ) / A (the mean under the absolute weights, a convex combination of the
//!   samples) and c = [`FLOOR_FACTOR`]·ρ, where ρ = ∫∫w / ∫∫|w| ∈ (0, 1] is the kernel's own
//!   ratio ([`ReconKernel::dc_fraction`]: 1 without negative lobes, 0.73 for Catmull–Rom, 0.54
//!   for Lanczos-3, 0.30 for the sinc of radius 4),
//!
//!   ```text
//!   I(p) = (Σw·f + (c·A − Σw)·P) / (c·A)   where Σw < c·A   ("floored")
//!        = t·(Σw·f/Σw) + (1 − t)·P,         t = Σw/(c·A) < 1.
//!   ```
//!
//!   The missing weight c·A − Σw is lent to P: a pixel whose weights cancel more than half
//!   as much as the continuous kernel's do is pulled towards the |w|-weighted mean in
//!   proportion. Properties (the tests check each):
//!   - **Bounded**: in both branches I − P = Σw(f − P)/max(Σw, c·A), so
//!     |I(p) − P| ≤ (max f − min f)/c over the samples that reach p, for every kernel and
//!     pattern (P itself lies between their min and max).
//!   - **Unchanged where samples are regular or dense**: where Σw ≥ c·A — every pixel of a
//!     grid, whose local ratio stays near ρ, and most pixels of well-spread patterns — the
//!     estimate is the plain Σw·f/Σw, bit for bit, with the kernel's sharpness.
//!     [`Reconstruction::floored`] counts the other pixels.
//!   - **Constants exact, no seams**: f ≡ k gives P = k and I = k in both branches (a plain
//!     floor max(Σw, c·A) would darken floored pixels); at Σw = c·A both branches agree.
//!
//!   Kernels that cannot reconstruct (ρ ≤ [`MIN_DC_FRACTION`]: band-pass, high-pass,
//!   derivative kernels, a radial sinc cut at an even radius) are refused with
//!   [`ReconError::NoDcGain`]. Alternatives measured on the zone plate (N = 4096, W = 128,
//!   every kernel × grid, random, jitter, Poisson disk, Sobol'): dividing by max(Σw, c·A)
//!   alone (shrinking towards 0) doubles the error of sinc on random samples (RMSE 0.72
//!   against 0.50 here) and breaks constants; dividing by A alone biases every pixel, the
//!   grid's included (a constant comes out ρ-dependent); dividing by the expected weight
//!   N·∫∫w (density compensation) turns the local density of irregular patterns into noise
//!   (RMSE 0.38–0.67 where the positive Gaussian has 0.25); a floor at c = ρ instead of ρ/2 is
//!   slightly better on irregular patterns but changes the grid.
//! - **Borders are open** (not toroidal): the signals are not periodic, so a sample only
//!   contributes to pixels inside the image, distances are plain Euclidean, and pixels near the
//!   border are normalised by the smaller weight they receive. This keeps the normalised sum
//!   exact for constants and unbiased at the border.
//! - **Zero total weight.** A pixel that no sample reaches with a non-zero weight
//!   (Σ|w| = 0) is never divided: it is set to [`ZERO_WEIGHT_FILL`] (½, mid grey), flagged in
//!   [`Reconstruction::mask`] and counted in [`Reconstruction::zero_weight`]. No output is
//!   ever NaN.
//! - **Reference images** ([`reference`](mod@reference)) are box-prefiltered: the mean of the signal over each
//!   pixel square, exact where a closed form exists (area coverage, integrals), by separable
//!   Gauss–Legendre quadrature with an error bound for the zone plate and the chirp, and
//!   estimated by stratified supersampling, with an error estimate, otherwise.
//! - **Errors** ([`ErrorReport`]) are measured over every pixel (zero-weight pixels count with
//!   their fill value): RMSE = √(mean (I − R)²) and PSNR = 10 log₁₀(1/MSE) dB (peak 1).
//! - **Cost and cancellation.** Every routine checks a [`Cancel`] token once per output row (or
//!   every 4096 samples) and refuses work above [`MAX_WORK`] kernel taps or signal evaluations.
//!   Results are deterministic: the same inputs and seeds give the same bits, whatever the
//!   number of threads (parallel loops write disjoint pixels; splatting is serial).

pub mod convergence;
pub mod cost;
pub mod coverage;
pub mod filter_kernel;
pub mod grid;
pub mod image_plane;
pub mod reference;
pub mod scattered;
pub mod supersample;

mod accum;

pub use convergence::{
    convergence_curve, convergence_curve_progressive, ConvergenceCurve, ConvergencePoint,
    DEFAULT_SPP_LIST,
};
pub use filter_kernel::ExactFactors;
pub use grid::{resample_grid, sample_grid};
pub use reference::{
    reference_image, reference_image_progressive, reference_image_with, reference_supersampled,
    reference_work, ReferenceImage, ReferenceMethod, ReferenceOptions,
};
pub use scattered::{
    reconstruct_scattered, reconstruct_scattered_gather, reconstruct_scattered_serial,
    sample_signal,
};
pub use supersample::{supersample, Jittered, PatternProvider, SampleProvider, UniformGrid};

use crate::core::cancel::{Cancel, Cancelled};
use crate::core::pattern::PatternError;
use crate::core::signal::SignalError;
use glam::DVec2;
use std::time::Duration;

/// Largest output size W (the image is W×W).
pub const MAX_W: usize = 8192;
/// Largest number of samples per pixel.
pub const MAX_SPP: usize = 4096;
/// Largest number of scattered samples N (the pattern limit).
pub const MAX_SAMPLES: usize = crate::core::pattern::MAX_N;
/// Largest kernel support, in filter units (sample spacings or pixels).
pub const MAX_SUPPORT: f64 = 64.0;
/// Largest amount of work accepted: kernel taps plus signal evaluations (2³⁴ ≈ 1.7·10¹⁰,
/// about a minute on one core).
pub const MAX_WORK: u128 = 1 << 34;
/// The value of a pixel whose total weight is zero: mid grey.
pub const ZERO_WEIGHT_FILL: f64 = 0.5;
/// The normaliser's floor as a fraction of the kernel's own ratio ρ = ∫∫w/∫∫|w|: pixels with
/// Σw < c·Σ|w|, c = `FLOOR_FACTOR`·ρ, are floored (module docs).
pub const FLOOR_FACTOR: f64 = 0.5;
/// The smallest ratio ρ = ∫∫w/∫∫|w| of a kernel that may reconstruct: below it the kernel
/// (nearly) blocks constants and a normalised sum is meaningless.
pub const MIN_DC_FRACTION: f64 = 1e-6;

/// A reconstruction kernel w(d), d in units of the filter scale (sample spacing or pixel).
///
/// Contract: `weight(d) = 0` whenever |d.x| ≥ `support()` or |d.y| ≥ `support()`; weights are
/// finite and may be negative (windowed sinc). The reconstruction visits only the taps inside
/// the support, so a kernel that breaks the contract is silently truncated.
pub trait ReconKernel: Sync {
    /// The support radius r (filter units): w vanishes outside the square |dₓ|, |d_y| < r.
    fn support(&self) -> f64;
    /// The weight w(d).
    fn weight(&self, d: DVec2) -> f64;
    /// For a separable kernel, the 1D factor h with `weight(d) = h(d.x)·h(d.y)`; `None` (the
    /// default) for other kernels. Splatting uses it to evaluate 2(2r+1) factors per sample
    /// instead of (2r+1)² weights.
    fn factor(&self, x: f64) -> Option<f64> {
        let _ = x;
        None
    }
    /// A separable kernel's factors at each of `xs`, in place (0 where `factor` gives none):
    /// what the splat evaluates, 2(2r+1) a sample. The default is `factor` on each; a kernel
    /// may use a cheaper form within its documented distance of `factor` (the filters':
    /// [`crate::core::filter::Kernel::eval_many`]).
    fn factors(&self, xs: &mut [f64]) {
        for x in xs {
            *x = self.factor(*x).unwrap_or(0.0);
        }
    }
    /// The kernel's ratio ρ = ∫∫w / ∫∫|w| over its support: 1 for kernels without negative
    /// lobes, less for those with (the normaliser's floor is [`FLOOR_FACTOR`]·ρ; module docs).
    /// The default integrates by the midpoint rule: 8192 nodes per axis on the separable
    /// factor when there is one, else 512 × 512 nodes on the support square (relative error
    /// about 10⁻⁴ for kernels with jumps, far less for smooth ones, which is all a floor needs).
    fn dc_fraction(&self) -> f64 {
        let r = self.support();
        if self.factor(0.0).is_some() {
            let m = 8192;
            let (mut s, mut a) = (0.0, 0.0);
            for k in 0..m {
                let x = -r + (k as f64 + 0.5) * 2.0 * r / m as f64;
                let h = self.factor(x).unwrap_or(0.0);
                s += h;
                a += h.abs();
            }
            // NaN when a weight is not finite (the reconstruction then names the pixel).
            if a == 0.0 {
                0.0
            } else {
                let q = s / a;
                q * q
            }
        } else {
            let m = 512;
            let (mut s, mut a) = (0.0, 0.0);
            for j in 0..m {
                let y = -r + (j as f64 + 0.5) * 2.0 * r / m as f64;
                for i in 0..m {
                    let x = -r + (i as f64 + 0.5) * 2.0 * r / m as f64;
                    let h = self.weight(DVec2::new(x, y));
                    s += h;
                    a += h.abs();
                }
            }
            if a == 0.0 {
                0.0
            } else {
                s / a
            }
        }
    }
}

impl<K: ReconKernel + ?Sized> ReconKernel for &K {
    fn support(&self) -> f64 {
        (**self).support()
    }
    fn weight(&self, d: DVec2) -> f64 {
        (**self).weight(d)
    }
    fn factor(&self, x: f64) -> Option<f64> {
        (**self).factor(x)
    }
    fn factors(&self, xs: &mut [f64]) {
        (**self).factors(xs)
    }
    fn dc_fraction(&self) -> f64 {
        (**self).dc_fraction()
    }
}

/// Why a sampling, reconstruction or reference computation was refused or stopped.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ReconError {
    /// An integer size (`w`, `n`, `spp`, `g`, `strata`) is outside its range.
    #[error("{field} = {value}: must be an integer in {min}..={max}")]
    OutOfRange {
        field: &'static str,
        value: usize,
        min: usize,
        max: usize,
    },
    /// Two inputs that must have the same length do not.
    #[error("{field} has {got} entries but must have {expected} (one per {per})")]
    LengthMismatch {
        field: &'static str,
        got: usize,
        expected: usize,
        per: &'static str,
    },
    /// An input value is NaN or infinite.
    #[error("{field}[{index}] = {}: must be finite", crate::core::params::fmt_num(*.value))]
    NonFinite {
        field: &'static str,
        index: usize,
        value: f64,
    },
    /// A sample position lies outside the unit square.
    #[error("points[{index}] = ({x}, {y}): must lie in [0,1]²")]
    OutOfDomain { index: usize, x: f64, y: f64 },
    /// The kernel's support is unusable.
    #[error("kernel support = {support}: must be a finite number in (0, {max}]")]
    InvalidSupport { support: f64, max: f64 },
    /// The kernel (nearly) blocks constants, so it cannot reconstruct a signal.
    #[error("the kernel's weights sum to {} of their absolute sum (∫∫w / ∫∫|w|): a reconstruction kernel must pass constants (H(0) > 0; band-pass, high-pass and derivative kernels cannot reconstruct)", crate::core::params::fmt_num(*.ratio))]
    NoDcGain { ratio: f64 },
    /// The kernel produced a non-finite weight (first affected pixel given).
    #[error(
        "kernel weights at pixel {pixel} are not finite: the kernel must return finite weights"
    )]
    NonFiniteWeight { pixel: usize },
    /// The signal's parameters are invalid.
    #[error(transparent)]
    Signal(#[from] SignalError),
    /// A sample provider rejected `spp` (e.g. a grid needs a perfect square).
    #[error("{provider}: spp = {spp}: must be {allowed}")]
    ProviderSpp {
        provider: &'static str,
        spp: usize,
        allowed: String,
    },
    /// A sample provider returned the wrong number of offsets.
    #[error("sample provider returned {got} offsets for pixel {pixel}; spp = {spp} expected")]
    ProviderCount { pixel: u64, got: usize, spp: usize },
    /// A sample provider returned an offset outside [0,1)².
    #[error("sample provider offset ({x}, {y}) for pixel {pixel}: must lie in [0,1)²")]
    ProviderOffset { pixel: u64, x: f64, y: f64 },
    /// The pattern behind a sample provider failed.
    #[error("sample pattern: {0}")]
    Pattern(#[from] PatternError),
    /// The request would exceed [`MAX_WORK`].
    #[error("{what} needs about {work} kernel taps and signal evaluations; the limit is {max}: lower w, n, spp or the kernel support")]
    TooMuchWork {
        what: &'static str,
        work: u128,
        max: u128,
    },
    /// The computation was cancelled.
    #[error("cancelled")]
    Cancelled,
}

impl From<Cancelled> for ReconError {
    fn from(_: Cancelled) -> Self {
        ReconError::Cancelled
    }
}

/// Checks `min ≤ value ≤ max` for an integer size.
pub(crate) fn check_size(
    field: &'static str,
    value: usize,
    min: usize,
    max: usize,
) -> Result<(), ReconError> {
    if value < min || value > max {
        return Err(ReconError::OutOfRange {
            field,
            value,
            min,
            max,
        });
    }
    Ok(())
}

/// Checks the kernel support and returns it.
pub(crate) fn check_support<K: ReconKernel + ?Sized>(kernel: &K) -> Result<f64, ReconError> {
    let r = kernel.support();
    if !(r.is_finite() && r > 0.0 && r <= MAX_SUPPORT) {
        return Err(ReconError::InvalidSupport {
            support: r,
            max: MAX_SUPPORT,
        });
    }
    Ok(r)
}

/// The normaliser's floor c = [`FLOOR_FACTOR`]·ρ of a kernel (module docs); refuses a kernel
/// whose ratio ρ = ∫∫w/∫∫|w| is not above [`MIN_DC_FRACTION`].
pub(crate) fn check_floor<K: ReconKernel + ?Sized>(kernel: &K) -> Result<f64, ReconError> {
    let ratio = kernel.dc_fraction();
    if ratio.is_nan() {
        // Non-finite weights: the reconstruction reports the first pixel they reach.
        return Ok(FLOOR_FACTOR);
    }
    if ratio <= MIN_DC_FRACTION {
        return Err(ReconError::NoDcGain { ratio });
    }
    Ok(FLOOR_FACTOR * ratio.min(1.0))
}

/// Checks an amount of work against [`MAX_WORK`].
pub(crate) fn check_work(what: &'static str, work: u128) -> Result<(), ReconError> {
    if work > MAX_WORK {
        return Err(ReconError::TooMuchWork {
            what,
            work,
            max: MAX_WORK,
        });
    }
    Ok(())
}

/// A reconstructed W×W image.
#[derive(Debug, Clone, PartialEq)]
pub struct Reconstruction {
    /// Size W (the image is W×W).
    pub w: usize,
    /// Pixel values, row-major (`pixels[j·W + i]`); zero-weight pixels hold [`Self::fill`].
    pub pixels: Vec<f64>,
    /// How many pixels had zero total weight (Σ|w| = 0).
    pub zero_weight: usize,
    /// How many pixels had Σw < c·Σ|w| and took the floored estimate (module docs).
    pub floored: usize,
    /// The floor's fraction c = [`FLOOR_FACTOR`]·ρ of the kernel.
    pub floor: f64,
    /// `true` where the total weight was zero (row-major, like `pixels`).
    pub mask: Vec<bool>,
    /// The value given to zero-weight pixels ([`ZERO_WEIGHT_FILL`]).
    pub fill: f64,
    /// How many samples of the signal were used.
    pub samples: usize,
    /// Wall-clock time of the reconstruction (sampling included where the routine samples).
    pub wall_time: Duration,
}

/// Error of a reconstruction against a reference image.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ErrorReport {
    /// √(mean over all W² pixels of (I − R)²).
    pub rmse: f64,
    /// 10·log₁₀(1/MSE) dB for peak value 1 (+∞ when the images are identical).
    pub psnr: f64,
    /// max |I − R|.
    pub max_abs: f64,
    /// Zero-weight pixels in the reconstruction (they count with their fill value).
    pub zero_weight: usize,
    /// Pixels divided by the normaliser's floor (copied from the reconstruction).
    pub floored: usize,
    /// Wall-clock time of the reconstruction being judged (copied from it).
    pub wall_time: Duration,
}

/// Root-mean-square difference √(Σ (aᵢ − bᵢ)²/n) of two equally long images.
pub fn rmse(a: &[f64], b: &[f64]) -> Result<f64, ReconError> {
    if a.len() != b.len() {
        return Err(ReconError::LengthMismatch {
            field: "reference",
            got: b.len(),
            expected: a.len(),
            per: "pixel",
        });
    }
    if a.is_empty() {
        return Err(ReconError::OutOfRange {
            field: "pixels",
            value: 0,
            min: 1,
            max: MAX_W * MAX_W,
        });
    }
    let sum: f64 = a.iter().zip(b).map(|(x, y)| (x - y) * (x - y)).sum();
    Ok((sum / a.len() as f64).sqrt())
}

/// PSNR for peak value 1: 10·log₁₀(1/rmse²) = −20·log₁₀(rmse) dB; +∞ for rmse = 0.
pub fn psnr(rmse: f64) -> f64 {
    if rmse == 0.0 {
        f64::INFINITY
    } else {
        -20.0 * rmse.log10()
    }
}

/// The error of `recon` against the reference pixels (same W×W layout).
pub fn error_report(recon: &Reconstruction, reference: &[f64]) -> Result<ErrorReport, ReconError> {
    for (index, &value) in reference.iter().enumerate() {
        if !value.is_finite() {
            return Err(ReconError::NonFinite {
                field: "reference",
                index,
                value,
            });
        }
    }
    let e = rmse(&recon.pixels, reference)?;
    let max_abs = recon
        .pixels
        .iter()
        .zip(reference)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    Ok(ErrorReport {
        rmse: e,
        psnr: psnr(e),
        max_abs,
        zero_weight: recon.zero_weight,
        floored: recon.floored,
        wall_time: recon.wall_time,
    })
}

/// The centre ((i+½)/W, (j+½)/W) of pixel (i, j).
#[inline]
pub fn pixel_centre(i: usize, j: usize, w: usize) -> DVec2 {
    DVec2::new((i as f64 + 0.5) / w as f64, (j as f64 + 0.5) / w as f64)
}

/// Helper: a cancellation check that converts to [`ReconError`].
#[inline]
pub(crate) fn check_cancel(cancel: &Cancel) -> Result<(), ReconError> {
    cancel.check().map_err(ReconError::from)
}
