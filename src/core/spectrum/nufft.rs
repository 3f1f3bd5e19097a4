//! A type-1 non-uniform FFT for periodograms, written on rustfft.
//!
//! F(k) = Σ_j exp(−2πi k·x_j) for all k on the M×M grid is computed in three stages
//! (Dutt & Rokhlin 1993; Greengard & Lee 2004; the kernel and parameters of Barnett,
//! Magland & af Klinteberg, "A parallel non-uniform fast Fourier transform library based on
//! an 'exponential of semicircle' kernel", SIAM J. Sci. Comput. 41(5), 2019):
//!
//! 1. **Spread** every point onto an upsampled periodic grid of n×n cells, n ≥ σM with σ = 2
//!    (n is the smallest even 2·3·5-smooth integer ≥ 2M, so σ is exactly 2 for the usual
//!    sizes), with the separable kernel ψ(x)ψ(y), ψ(x) = φ(x/α), α = w/(2n):
//!    b\[l\] = Σ_j ψ(l_x/n − x_j) ψ(l_y/n − y_j) (periodised). φ is the "exponential of
//!    semicircle" φ(z) = exp(β(√(1 − z²) − 1)) on |z| ≤ 1 ([`es_kernel`]); its support covers
//!    w grid cells per axis, so a point touches w² cells. The w values per axis are computed
//!    once per point (separable) from a per-tap Chebyshev interpolant of φ, accurate to the
//!    kernel's own truncation level e^{−β} (see `KernelTable`), instead of 2w `exp` calls.
//! 2. **FFT** the grid: B\[k\] = Σ_l b\[l\] exp(−2πi k·l/n). The grid is real, so grid lines are
//!    transformed along y two at a time as one complex FFT and split by Hermitian symmetry;
//!    only 0 ≤ ky ≤ ⌊M/2⌋ is kept and transformed along x (F(−k) = conj F(k) gives the rest).
//! 3. **Deconvolve**: the rectangle rule on the grid gives (1/n²) B\[k\] ≈ F(k) ψ̂(kx) ψ̂(ky), so
//!    F(k) ≈ B\[k\] / (n ψ̂(kx) · n ψ̂(ky)), with n ψ̂(k) = (w/2) ∫_{−1}^{1} φ(z) cos(π k w z / n) dz
//!    computed by Gauss–Legendre quadrature in θ = arcsin z ([`kernel_transform`]) once per plan.
//!    Then P(k) = |F(k)|²/N.
//!
//! # Tolerance → kernel rule
//! Barnett et al. give, for σ = 2, w = ⌈log10(1/ε)⌉ + 1 cells and β = 2.30·w for a relative
//! error ε of F at random points. The periodogram squares F, so its relative error is about
//! twice F's, and grid-aligned points (every point on a node of the upsampled grid) make the
//! aliasing errors add coherently, 2 to 5 times more. Measured worst relative ℓ2 error of P
//! (DC excluded) over the test cases (N = 1, 2, 100, 4096, 65 536 uniform, on 64² to 256²;
//! points at 0 and at 1 − 2⁻⁵³; duplicates; three grid-aligned lattices), β = 2.30·w:
//!
//! | w | 4 | 5 | 6 | 7 | 8 | 9 | 10 | 11 | 12 | 13 | 14 | 15 | 16 |
//! |---|---|---|---|---|---|---|---|---|---|---|---|---|---|
//! | worst | 1.0e-2 | 1.0e-3 | 7.2e-5 | 4.7e-6 | 5.3e-7 | 1.2e-7 | 2.0e-8 | 2.3e-9 | 2.0e-10 | 9.5e-12 | 5.3e-13 | 3.4e-13 | 1.2e-13 |
//! | uniform only | 1.9e-3 | 1.7e-4 | 1.9e-5 | 1.9e-6 | 2.4e-7 | 3.0e-8 | 3.4e-9 | 3.7e-10 | 3.8e-11 | 4.3e-12 | 4.7e-13 | 5.9e-14 | 2.6e-14 |
//!
//! (β/w = 2.1, 2.2, 2.4, 2.5 were worse or no better.) The rule used here is therefore the
//! nominal width plus 2:
//!
//!   w = ⌈log10(1/ε)⌉ + 3,  β = 2.30·w,
//!
//! i.e. w = 5, 6, 9, 12, 15 for ε = 1e-2, 1e-3, 1e-6, 1e-9, 1e-12, which leaves the worst case
//! at ≤ 0.34 ε for every ε in [1e-12, 1e-2]. The tests are the judge: they assert error ≤ ε on
//! those point sets, and `nominal_width_is_not_enough_for_the_periodogram` shows that the
//! nominal width is not.
//!
//! # Parallelism and determinism
//! Points are bucketed into slabs of x (a count that depends only on N and n, never on
//! the thread count); each slab spreads into its own strip (its rows plus a margin of
//! ⌊w/2⌋ + 1 rows and columns on each side), strips run in parallel, and the FFT stage folds
//! the strips into each grid row in slab order. FFTs of rows and of columns run in parallel.
//! Every sum therefore runs in a fixed order: the same input gives the same bits on any
//! number of threads. `cancel` is checked every 1024 points and every FFT batch.

use super::quadrature::gauss_legendre;
use super::{check_points, check_size, k_min, Spectrum, SpectrumError};
use crate::core::cancel::Cancel;
use glam::DVec2;
use rayon::prelude::*;
use rustfft::num_complex::Complex;
use rustfft::{Fft, FftPlanner};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// Smallest NUFFT tolerance accepted.
pub const MIN_TOLERANCE: f64 = 1e-12;
/// Largest NUFFT tolerance accepted.
pub const MAX_TOLERANCE: f64 = 1e-2;
/// Largest kernel width w (cells per axis).
pub const MAX_WIDTH: usize = 16;
/// β / w for the upsampling factor σ = 2 (Barnett et al. 2019, §3.1).
pub const BETA_PER_WIDTH: f64 = 2.30;
/// Points per parallel slab of the spreader (at most 16 slabs).
const POINTS_PER_SLAB: usize = 2048;
/// Points spread between two cancellation checks.
const CANCEL_EVERY: usize = 1024;

/// The spreading kernel: width w in grid cells per axis and shape parameter β.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KernelParams {
    /// Cells per axis covered by the kernel (w² per point in 2D).
    pub width: usize,
    /// Shape parameter β of φ(z) = exp(β(√(1 − z²) − 1)).
    pub beta: f64,
}

/// The kernel for a requested periodogram tolerance ε ∈ [1e-12, 1e-2]:
/// w = ⌈log10(1/ε)⌉ + 3, β = 2.30·w (the nominal width of Barnett et al. plus 2; see the
/// module docs for the measurements behind it).
///
/// # Errors
/// [`SpectrumError::InvalidTolerance`] for NaN or ε outside [1e-12, 1e-2].
pub fn kernel_params(tolerance: f64) -> Result<KernelParams, SpectrumError> {
    if tolerance.is_nan() || !(MIN_TOLERANCE..=MAX_TOLERANCE).contains(&tolerance) {
        return Err(SpectrumError::InvalidTolerance {
            value: tolerance,
            min: MIN_TOLERANCE,
            max: MAX_TOLERANCE,
        });
    }
    // The small slack keeps exact powers of ten (log10(1/1e-6) = 5.999…or 6.000…1) at their digit count.
    let width = ((1.0 / tolerance).log10() - 1e-9).ceil() as usize + 3;
    Ok(KernelParams {
        width,
        beta: BETA_PER_WIDTH * width as f64,
    })
}

/// The "exponential of semicircle" kernel φ(z) = exp(β(√(1 − z²) − 1)) for |z| ≤ 1, 0 outside
/// (Barnett, Magland & af Klinteberg 2019, eq. 1.8). φ(0) = 1, φ(±1) = e^{−β}.
#[inline]
pub fn es_kernel(z: f64, beta: f64) -> f64 {
    let s = 1.0 - z * z;
    if s < 0.0 {
        0.0
    } else {
        (beta * (s.sqrt() - 1.0)).exp()
    }
}

/// ∫_{−1}^{1} φ(z) cos(π s z) dz, the Fourier transform of the ES kernel at π s (s = k·w/n for
/// frequency k on a grid of n cells), by q-point Gauss–Legendre quadrature after the change of
/// variable z = sin θ:
///
///   ∫_{−π/2}^{π/2} exp(β(cos θ − 1)) cos(π s sin θ) cos θ dθ.
///
/// In z the integrand has a square-root singularity at z = ±1 (of size β e^{−β}), which slows
/// plain Gauss–Legendre to algebraic convergence; in θ it is analytic, so convergence is
/// exponential (2w + 24 nodes agree with 3× as many to 1e-13, rounding level).
pub fn kernel_transform(s: f64, beta: f64, q: usize) -> f64 {
    let (nodes, weights) = gauss_legendre(q);
    kernel_transform_with(s, beta, &nodes, &weights)
}

/// [`kernel_transform`] with precomputed Gauss–Legendre nodes and weights on [−1, 1].
fn kernel_transform_with(s: f64, beta: f64, nodes: &[f64], weights: &[f64]) -> f64 {
    let h = std::f64::consts::FRAC_PI_2;
    nodes
        .iter()
        .zip(weights)
        .map(|(&t, &wq)| {
            let theta = h * t;
            let (sin, cos) = theta.sin_cos();
            wq * h * (beta * (cos - 1.0)).exp() * (std::f64::consts::PI * s * sin).cos() * cos
        })
        .sum()
}

/// The smallest even integer ≥ x whose only prime factors are 2, 3 and 5 (fast FFT sizes).
pub fn upsampled_size(m: usize) -> usize {
    let mut n = (2 * m).max(2);
    loop {
        let mut r = n;
        for p in [2, 3, 5] {
            while r % p == 0 {
                r /= p;
            }
        }
        if r == 1 && n % 2 == 0 {
            return n;
        }
        n += 1;
    }
}

/// Wall time of each NUFFT stage.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct NufftTimes {
    /// Bucketing into slabs and spreading onto the upsampled grid.
    pub spread: Duration,
    /// Row FFTs (folding the strips in) and column FFTs.
    pub fft: Duration,
    /// Deconvolution by the kernel's transform and |F|²/N onto the output grid.
    pub deconvolve: Duration,
}

/// The kernel values of the w taps of one axis as polynomials of the point's offset:
/// for a point at upsampled coordinate u, with l₀ = ⌈u − w/2⌉ and s = l₀ − (u − w/2) ∈ [0, 1),
/// tap t (grid cell l₀ + t) has the value f_t(s) = φ((2(s + t) − w)/w). Each f_t is replaced
/// by its Chebyshev interpolant of degree d in x = 2s − 1 (Chebyshev points of the first
/// kind), evaluated by Clenshaw's recurrence for all w taps at once (one x per axis per point,
/// so the recurrence vectorises across taps). This replaces 2w `exp` and `sqrt` calls per
/// point by 2·w·d multiply-adds. The degree is the smallest whose maximum error,
/// measured on 64 offsets per tap, is ≤ max(e^{−β}, 1e-14), the kernel's own truncation level;
/// when no degree up to 2w + 12 reaches it (very large β) the spreader evaluates φ directly.
#[derive(Debug, Clone)]
struct KernelTable {
    degree: usize,
    /// `coef[k·w + t]`: coefficient of T_k for tap t.
    coef: Vec<f64>,
}

impl KernelTable {
    fn build(kernel: KernelParams) -> Option<Self> {
        let w = kernel.width;
        let wf = w as f64;
        let f = |t: usize, s: f64| es_kernel((2.0 * (s + t as f64) - wf) / wf, kernel.beta);
        let target = (-kernel.beta).exp().max(1e-14);
        for degree in 2..=2 * w + 12 {
            let q = degree + 1;
            let nodes: Vec<f64> = (0..q)
                .map(|j| (std::f64::consts::PI * (j as f64 + 0.5) / q as f64).cos())
                .collect();
            let mut coef = vec![0.0; q * w];
            for t in 0..w {
                let values: Vec<f64> = nodes.iter().map(|&x| f(t, 0.5 * (x + 1.0))).collect();
                for k in 0..q {
                    let sum: f64 = nodes
                        .iter()
                        .zip(&values)
                        .map(|(&x, &v)| v * (k as f64 * x.acos()).cos())
                        .sum();
                    let scale = if k == 0 { 1.0 } else { 2.0 };
                    coef[k * w + t] = scale * sum / q as f64;
                }
            }
            let table = KernelTable { degree, coef };
            let mut worst = 0.0f64;
            let mut out = [0.0; MAX_WIDTH];
            for i in 0..64 {
                let s = (i as f64 + 0.37) / 64.0;
                table.eval_dyn(w, s, &mut out);
                for (t, &o) in out[..w].iter().enumerate() {
                    worst = worst.max((o - f(t, s)).abs());
                }
            }
            if worst <= target {
                return Some(table);
            }
        }
        None
    }

    /// Clenshaw for all taps (width known at run time; used to build and test the table).
    fn eval_dyn(&self, w: usize, s: f64, out: &mut [f64]) {
        let x = 2.0 * s - 1.0;
        let mut b1 = [0.0; MAX_WIDTH];
        let mut b2 = [0.0; MAX_WIDTH];
        for k in (1..=self.degree).rev() {
            for t in 0..w {
                let b0 = self.coef[k * w + t] + 2.0 * x * b1[t] - b2[t];
                b2[t] = b1[t];
                b1[t] = b0;
            }
        }
        for t in 0..w {
            out[t] = self.coef[t] + x * b1[t] - b2[t];
        }
    }

    /// Clenshaw for all W taps at once.
    #[inline(always)]
    fn eval<const W: usize>(&self, s: f64) -> [f64; W] {
        let x = 2.0 * s - 1.0;
        let x2 = 2.0 * x;
        let mut b1 = [0.0; W];
        let mut b2 = [0.0; W];
        let mut chunks = self.coef.chunks_exact(W);
        let c0 = chunks.next();
        for c in chunks.rev() {
            for t in 0..W {
                let b0 = c[t] + x2 * b1[t] - b2[t];
                b2[t] = b1[t];
                b1[t] = b0;
            }
        }
        let mut out = [0.0; W];
        if let Some(c0) = c0 {
            for t in 0..W {
                out[t] = c0[t] + x * b1[t] - b2[t];
            }
        }
        out
    }
}

/// The kernel values of the W taps for offset s (see [`KernelTable`]).
#[inline(always)]
fn taps<const W: usize>(table: Option<&KernelTable>, beta: f64, s: f64) -> [f64; W] {
    match table {
        Some(t) => t.eval::<W>(s),
        None => {
            let wf = W as f64;
            std::array::from_fn(|t| es_kernel((2.0 * (s + t as f64) - wf) / wf, beta))
        }
    }
}

/// Buffers reused between calls of one plan (fresh multi-megabyte buffers cost page faults).
#[derive(Default)]
struct Workspace {
    order: Vec<u32>,
    /// Every strip, one after another (one buffer: in a one-shot command a fresh buffer of
    /// several MiB is mapped with huge pages, a strip of under 2 MiB page by page).
    strips: Vec<f64>,
    /// Strip s is `strips[strip_starts[s]..strip_starts[s + 1]]`.
    strip_starts: Vec<usize>,
    /// For grid row g, the (strip, strip row) pairs folding onto it: `sources[starts[g]..starts[g+1]]`.
    source_starts: Vec<usize>,
    sources: Vec<(usize, usize)>,
    cols: Vec<Complex<f64>>,
}

/// Where each strip sits: global row of its first row (may be negative, rows wrap modulo n)
/// and its height.
#[derive(Clone, Copy)]
struct StripPlace {
    row0: isize,
    height: usize,
}

/// A reusable NUFFT periodogram plan for one size M and one kernel: the FFT plan of the
/// upsampled length, the deconvolution factors, the kernel's polynomial table, and a pool of
/// work buffers. Build once, use for many point sets (e.g. the K realizations of an average,
/// concurrently: it is `Send + Sync`).
pub struct NufftPlan {
    m: usize,
    n: usize,
    kernel: KernelParams,
    tolerance: Option<f64>,
    /// 1/(n ψ̂(k))² for k = 0..=⌊M/2⌋.
    deconv2: Vec<f64>,
    table: Option<KernelTable>,
    fft: Arc<dyn Fft<f64>>,
    pool: Mutex<Vec<Workspace>>,
}

impl Clone for NufftPlan {
    /// A plan sharing the FFT plan, with an empty buffer pool.
    fn clone(&self) -> Self {
        NufftPlan {
            m: self.m,
            n: self.n,
            kernel: self.kernel,
            tolerance: self.tolerance,
            deconv2: self.deconv2.clone(),
            table: self.table.clone(),
            fft: Arc::clone(&self.fft),
            pool: Mutex::new(Vec::new()),
        }
    }
}

impl std::fmt::Debug for NufftPlan {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("NufftPlan")
            .field("m", &self.m)
            .field("n", &self.n)
            .field("kernel", &self.kernel)
            .field("tolerance", &self.tolerance)
            .field("chebyshev_degree", &self.table.as_ref().map(|t| t.degree))
            .finish()
    }
}

/// Calls `$f::<W>(args)` for the run-time width `$w` (2..=16).
macro_rules! with_width {
    ($w:expr, $f:ident ( $($arg:expr),* )) => {
        match $w {
            2 => $f::<2>($($arg),*),
            3 => $f::<3>($($arg),*),
            4 => $f::<4>($($arg),*),
            5 => $f::<5>($($arg),*),
            6 => $f::<6>($($arg),*),
            7 => $f::<7>($($arg),*),
            8 => $f::<8>($($arg),*),
            9 => $f::<9>($($arg),*),
            10 => $f::<10>($($arg),*),
            11 => $f::<11>($($arg),*),
            12 => $f::<12>($($arg),*),
            13 => $f::<13>($($arg),*),
            14 => $f::<14>($($arg),*),
            15 => $f::<15>($($arg),*),
            16 => $f::<16>($($arg),*),
            w => Err(SpectrumError::InvalidParam {
                field: "kernel.width",
                value: w.to_string(),
                allowed: format!("an integer in 2..={MAX_WIDTH}"),
            }),
        }
    };
}

/// What one slab spreads: its points (indices into `points`, in point order) and its strip.
struct SlabJob<'a> {
    points: &'a [DVec2],
    order: &'a [u32],
    data: &'a mut [f64],
    width: usize,
    place: StripPlace,
    pad: usize,
    n: usize,
    beta: f64,
    table: Option<&'a KernelTable>,
}

/// Spreads one slab's points into its strip with the W×W separable kernel.
fn spread_slab<const W: usize>(job: SlabJob<'_>, cancel: &Cancel) -> Result<(), SpectrumError> {
    let nf = job.n as f64;
    let half_w = W as f64 / 2.0;
    let pad = job.pad as isize;
    for (c, &i) in job.order.iter().enumerate() {
        if c % CANCEL_EVERY == 0 {
            cancel.check()?;
        }
        let p = job.points[i as usize];
        // Grid rows follow x and columns follow y (see `NufftPlan::spread`).
        let vr = p.x * nf - half_w;
        let vc = p.y * nf - half_w;
        let (lr0, lc0) = (vr.ceil(), vc.ceil());
        let kr: [f64; W] = taps::<W>(job.table, job.beta, lr0 - vr);
        let kc: [f64; W] = taps::<W>(job.table, job.beta, lc0 - vc);
        let c0 = (lc0 as isize + pad) as usize;
        let r0 = (lr0 as isize - job.place.row0) as usize;
        for (tr, &wr) in kr.iter().enumerate() {
            let start = (r0 + tr) * job.width + c0;
            let row: &mut [f64] = &mut job.data[start..start + W];
            for (g, &wc) in row.iter_mut().zip(kc.iter()) {
                *g += wr * wc;
            }
        }
    }
    Ok(())
}

impl NufftPlan {
    /// A plan for size `m` and periodogram tolerance ε, with the kernel of [`kernel_params`].
    ///
    /// # Errors
    /// [`SpectrumError::InvalidSize`] unless 2 ≤ m ≤ 4096; [`SpectrumError::InvalidTolerance`]
    /// unless ε ∈ [1e-12, 1e-2].
    pub fn new(m: usize, tolerance: f64) -> Result<Self, SpectrumError> {
        let kernel = kernel_params(tolerance)?;
        let mut plan = Self::with_kernel(m, kernel)?;
        plan.tolerance = Some(tolerance);
        Ok(plan)
    }

    /// A plan with an explicit kernel (for experiments and tests of the tolerance rule);
    /// no tolerance is promised.
    ///
    /// # Errors
    /// [`SpectrumError::InvalidSize`]; [`SpectrumError::InvalidParam`] naming `kernel.width`
    /// (2..=16) or `kernel.beta` (finite, > 0).
    pub fn with_kernel(m: usize, kernel: KernelParams) -> Result<Self, SpectrumError> {
        check_size(m)?;
        if !(2..=MAX_WIDTH).contains(&kernel.width) {
            return Err(SpectrumError::InvalidParam {
                field: "kernel.width",
                value: kernel.width.to_string(),
                allowed: format!("an integer in 2..={MAX_WIDTH}"),
            });
        }
        if !(kernel.beta.is_finite() && kernel.beta > 0.0) {
            return Err(SpectrumError::InvalidParam {
                field: "kernel.beta",
                value: crate::core::params::fmt_num(kernel.beta),
                allowed: "a finite number > 0".into(),
            });
        }
        let n = upsampled_size(m);
        let half = (-k_min(m)) as usize;
        let w = kernel.width as f64;
        let (nodes, weights) = gauss_legendre(2 * kernel.width + 24);
        let deconv2 = (0..=half)
            .map(|k| {
                let s = k as f64 * w / n as f64;
                let nhat = 0.5 * w * kernel_transform_with(s, kernel.beta, &nodes, &weights);
                1.0 / (nhat * nhat)
            })
            .collect();
        let fft = FftPlanner::new().plan_fft_forward(n);
        Ok(NufftPlan {
            m,
            n,
            kernel,
            tolerance: None,
            deconv2,
            table: KernelTable::build(kernel),
            fft,
            pool: Mutex::new(Vec::new()),
        })
    }

    /// The output size M.
    pub fn size(&self) -> usize {
        self.m
    }

    /// The upsampled grid size n (≥ 2M).
    pub fn upsampled(&self) -> usize {
        self.n
    }

    /// The spreading kernel.
    pub fn kernel(&self) -> KernelParams {
        self.kernel
    }

    /// The tolerance the plan was built for (`None` for [`NufftPlan::with_kernel`]).
    pub fn tolerance(&self) -> Option<f64> {
        self.tolerance
    }

    /// The degree of the Chebyshev kernel table, or `None` when φ is evaluated directly.
    pub fn chebyshev_degree(&self) -> Option<usize> {
        self.table.as_ref().map(|t| t.degree)
    }

    /// The w kernel values used for a point at offset s ∈ [0, 1) (see the module docs):
    /// tap t approximates φ((2(s + t) − w)/w). For tests of the kernel table.
    pub fn kernel_taps(&self, s: f64) -> Vec<f64> {
        let w = self.kernel.width;
        match &self.table {
            Some(t) => {
                let mut out = [0.0; MAX_WIDTH];
                t.eval_dyn(w, s, &mut out);
                out[..w].to_vec()
            }
            None => (0..w)
                .map(|t| {
                    es_kernel(
                        (2.0 * (s + t as f64) - w as f64) / w as f64,
                        self.kernel.beta,
                    )
                })
                .collect(),
        }
    }

    /// 1/(n ψ̂(k))², the squared deconvolution factor, for k = 0..=⌊M/2⌋ (for tests).
    pub fn deconvolution_squared(&self) -> &[f64] {
        &self.deconv2
    }

    /// The periodogram P(k) = |Σ_j exp(−2πi k·x_j)|²/N of `points` on this plan's grid.
    ///
    /// # Errors
    /// [`SpectrumError::EmptyPointSet`], [`SpectrumError::InvalidPoint`],
    /// [`SpectrumError::Cancelled`].
    pub fn periodogram(
        &self,
        points: &[DVec2],
        cancel: &Cancel,
    ) -> Result<Spectrum, SpectrumError> {
        self.periodogram_timed(points, cancel).map(|(s, _)| s)
    }

    /// [`NufftPlan::periodogram`] with the wall time of each stage.
    pub fn periodogram_timed(
        &self,
        points: &[DVec2],
        cancel: &Cancel,
    ) -> Result<(Spectrum, NufftTimes), SpectrumError> {
        let mut power = Vec::new();
        let times = self.periodogram_into(points, &mut power, cancel)?;
        Ok((Spectrum::from_power(self.m, power, points.len()), times))
    }

    /// [`NufftPlan::periodogram_timed`] writing P into `power` (resized to M², row-major as in
    /// [`Spectrum::power`]), so that a caller can reuse the buffer.
    ///
    /// # Errors
    /// As [`NufftPlan::periodogram`], plus [`SpectrumError::InvalidParam`] naming `n_points`
    /// beyond 2³² − 1 points.
    pub fn periodogram_into(
        &self,
        points: &[DVec2],
        power: &mut Vec<f64>,
        cancel: &Cancel,
    ) -> Result<NufftTimes, SpectrumError> {
        check_points(points)?;
        if points.len() > u32::MAX as usize {
            return Err(SpectrumError::InvalidParam {
                field: "n_points",
                value: points.len().to_string(),
                allowed: format!("at most {} points (32-bit point indices)", u32::MAX),
            });
        }
        let mut ws = self
            .pool
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .pop()
            .unwrap_or_default();
        let result = self.run(points, power, &mut ws, cancel);
        self.pool.lock().unwrap_or_else(|e| e.into_inner()).push(ws);
        result
    }

    fn run(
        &self,
        points: &[DVec2],
        power: &mut Vec<f64>,
        ws: &mut Workspace,
        cancel: &Cancel,
    ) -> Result<NufftTimes, SpectrumError> {
        let t0 = Instant::now();
        let pad = self.kernel.width / 2 + 1;
        let places = self.spread(points, pad, ws, cancel)?;
        let t1 = Instant::now();
        self.fft_stage(&places, pad, ws, cancel)?;
        let t2 = Instant::now();
        self.deconvolve(&ws.cols, points.len(), power);
        let t3 = Instant::now();
        Ok(NufftTimes {
            spread: t1 - t0,
            fft: t2 - t1,
            deconvolve: t3 - t2,
        })
    }

    /// Stage 1: bucket points into slabs by x and spread each slab into its own strip.
    ///
    /// The grid is stored transposed, b[l_x][l_y] (rows follow x, columns follow y), so that
    /// the row FFTs run along y and the column FFTs along x, and the final spectrum comes out
    /// as rows of constant ky with contiguous kx: the deconvolution then reads and writes
    /// memory in order.
    fn spread(
        &self,
        points: &[DVec2],
        pad: usize,
        ws: &mut Workspace,
        cancel: &Cancel,
    ) -> Result<Vec<StripPlace>, SpectrumError> {
        let n = self.n;
        let slabs = (points.len() / POINTS_PER_SLAB)
            .clamp(1, 16)
            .min((n / (4 * pad)).max(1));
        let row_of = |y: f64| (((y * n as f64) as usize).min(n - 1) * slabs) / n;
        // Counting sort of point indices by slab (stable: point order kept within a slab).
        let mut starts = vec![0usize; slabs + 1];
        for p in points {
            starts[row_of(p.x) + 1] += 1;
        }
        for s in 0..slabs {
            starts[s + 1] += starts[s];
        }
        let mut fill = starts.clone();
        ws.order.clear();
        ws.order.resize(points.len(), 0);
        for (i, p) in points.iter().enumerate() {
            let s = row_of(p.x);
            ws.order[fill[s]] = i as u32;
            fill[s] += 1;
        }
        let width = n + 2 * pad;
        // Slab s owns rows ⌈s·n/S⌉ .. ⌈(s+1)·n/S⌉, exactly the rows r with ⌊r·S/n⌋ = s.
        let places: Vec<StripPlace> = (0..slabs)
            .map(|s| {
                let lo = (s * n).div_ceil(slabs);
                let hi = ((s + 1) * n).div_ceil(slabs);
                StripPlace {
                    row0: lo as isize - pad as isize,
                    height: hi - lo + 2 * pad,
                }
            })
            .collect();
        ws.strip_starts.clear();
        ws.strip_starts.push(0);
        for place in &places {
            let end = ws.strip_starts[ws.strip_starts.len() - 1] + place.height * width;
            ws.strip_starts.push(end);
        }
        ws.strips.clear();
        ws.strips.resize(ws.strip_starts[slabs], 0.0);
        // The strips as disjoint slices, one per slab.
        let mut data: Vec<&mut [f64]> = Vec::with_capacity(slabs);
        let mut rest: &mut [f64] = &mut ws.strips;
        for s in 0..slabs {
            let (strip, tail) = rest.split_at_mut(ws.strip_starts[s + 1] - ws.strip_starts[s]);
            data.push(strip);
            rest = tail;
        }
        let order = &ws.order;
        let table = self.table.as_ref();
        let beta = self.kernel.beta;
        let w = self.kernel.width;
        data.into_par_iter().enumerate().try_for_each(|(s, data)| {
            let place = places[s];
            let job = SlabJob {
                points,
                order: &order[starts[s]..starts[s + 1]],
                data,
                width,
                place,
                pad,
                n,
                beta,
                table,
            };
            with_width!(w, spread_slab(job, cancel))
        })?;
        Ok(places)
    }

    /// Stage 2: fold strips into grid rows (constant l_x), FFT rows in pairs along y, keep
    /// ky ∈ [0, ⌊M/2⌋] (written column-major), FFT those columns along x. Leaves
    /// `(⌊M/2⌋ + 1) × n` complex values in `ws.cols`: ky at `ky·n`, kx at offset `kx mod n`.
    fn fft_stage(
        &self,
        places: &[StripPlace],
        pad: usize,
        ws: &mut Workspace,
        cancel: &Cancel,
    ) -> Result<(), SpectrumError> {
        let n = self.n;
        let keep = (-k_min(self.m)) as usize + 1;
        let width = n + 2 * pad;
        // For every grid row, the (strip, strip row) pairs that fold onto it, in strip order.
        ws.source_starts.clear();
        ws.source_starts.resize(n + 1, 0);
        let row_of = |place: &StripPlace, r: usize| {
            (place.row0 + r as isize).rem_euclid(n as isize) as usize
        };
        for place in places {
            for r in 0..place.height {
                ws.source_starts[row_of(place, r) + 1] += 1;
            }
        }
        for g in 0..n {
            ws.source_starts[g + 1] += ws.source_starts[g];
        }
        ws.sources.clear();
        ws.sources.resize(ws.source_starts[n], (0, 0));
        let mut fill = ws.source_starts.clone();
        for (s, place) in places.iter().enumerate() {
            for r in 0..place.height {
                let g = row_of(place, r);
                ws.sources[fill[g]] = (s, r);
                fill[g] += 1;
            }
        }
        let (strips, strip_starts) = (&ws.strips, &ws.strip_starts);
        let (starts, sources) = (&ws.source_starts, &ws.sources);
        // Adds grid row g into the real (part 0) or imaginary (part 1) parts of `buf`.
        let gather = |g: usize, part: usize, buf: &mut [Complex<f64>]| {
            let add = |b: &mut Complex<f64>, v: f64| {
                if part == 0 {
                    b.re += v
                } else {
                    b.im += v
                }
            };
            for &(s, r) in &sources[starts[g]..starts[g + 1]] {
                let row = &strips[strip_starts[s] + r * width..][..width];
                if pad <= n {
                    for (b, &v) in buf.iter_mut().zip(&row[pad..pad + n]) {
                        add(b, v);
                    }
                    for i in 0..pad {
                        add(&mut buf[n - pad + i], row[i]);
                        add(&mut buf[i], row[n + pad + i]);
                    }
                } else {
                    for (c, &v) in row.iter().enumerate() {
                        add(
                            &mut buf[(c as isize - pad as isize).rem_euclid(n as isize) as usize],
                            v,
                        );
                    }
                }
            }
        };
        let fft = &self.fft;
        let scratch_len = fft.get_inplace_scratch_len();
        // Row stage: rows 2p and 2p+1 as the real and imaginary parts of one complex FFT. The
        // kept values go straight into column-major order: every column is split into blocks
        // of ROWS rows, and task b owns block b of every column (disjoint slices, no transpose).
        const ROWS: usize = 32;
        ws.cols.resize(keep * n, Complex::new(0.0, 0.0));
        let mut blocks: Vec<Vec<&mut [Complex<f64>]>> = (0..n.div_ceil(ROWS))
            .map(|_| Vec::with_capacity(keep))
            .collect();
        for col in ws.cols.chunks_mut(n) {
            for (b, chunk) in col.chunks_mut(ROWS).enumerate() {
                blocks[b].push(chunk);
            }
        }
        blocks.into_par_iter().enumerate().try_for_each_init(
            || {
                (
                    vec![Complex::new(0.0, 0.0); n],
                    vec![Complex::new(0.0, 0.0); scratch_len],
                    vec![Complex::new(0.0, 0.0); ROWS * keep],
                )
            },
            |(buf, scratch, tile), (b, mut slices)| {
                cancel.check()?;
                let rows_here = slices.first().map_or(0, |s| s.len());
                for p in 0..rows_here / 2 {
                    let g = b * ROWS + 2 * p;
                    buf.fill(Complex::new(0.0, 0.0));
                    gather(g, 0, buf);
                    gather(g + 1, 1, buf);
                    fft.process_with_scratch(buf, scratch);
                    for k in 0..keep {
                        let z = buf[k];
                        let zc = buf[(n - k) % n].conj();
                        // A[k] = (Z[k] + conj Z[n−k]) / 2, B[k] = (Z[k] − conj Z[n−k]) / (2i).
                        tile[k * ROWS + 2 * p] = (z + zc) * 0.5;
                        tile[k * ROWS + 2 * p + 1] = (z - zc) * Complex::new(0.0, -0.5);
                    }
                }
                for (k, slice) in slices.iter_mut().enumerate() {
                    slice.copy_from_slice(&tile[k * ROWS..k * ROWS + rows_here]);
                }
                Ok::<(), SpectrumError>(())
            },
        )?;
        // Column FFTs.
        let batch = (4096 / n).max(1);
        ws.cols.par_chunks_mut(n * batch).try_for_each_init(
            || vec![Complex::new(0.0, 0.0); scratch_len],
            |scratch, chunk| {
                cancel.check()?;
                fft.process_with_scratch(chunk, scratch);
                Ok::<(), SpectrumError>(())
            },
        )?;
        Ok(())
    }

    /// Stage 3: P(k) = |B\[k\]|² / (n ψ̂(kx) n ψ̂(ky))² / N on the output grid. `cols` holds the
    /// rows ky = 0..=⌊M/2⌋; rows ky < 0, and the left half of row 0, use
    /// P(kx, ky) = P(−kx, −ky) (so that symmetry holds bit for bit).
    fn deconvolve(&self, cols: &[Complex<f64>], n_points: usize, power: &mut Vec<f64>) {
        let (m, n) = (self.m, self.n);
        let k0 = k_min(m);
        let inv_n = 1.0 / n_points as f64;
        // Every element is overwritten below: no need to clear a reused buffer.
        power.resize(m * m, 0.0);
        let deconv2 = &self.deconv2;
        power.par_chunks_mut(m).enumerate().for_each(|(iy, out)| {
            let ky = k0 + iy as i64;
            let row = &cols[ky.unsigned_abs() as usize * n..][..n];
            let dy = deconv2[ky.unsigned_abs() as usize] * inv_n;
            for (ix, o) in out.iter_mut().enumerate() {
                let kx = k0 + ix as i64;
                // The frequency read: (kx, ky) itself for ky > 0 and for ky = 0, kx ≥ 0, else
                // its mirror (−kx, −ky).
                let kr = if ky > 0 || (ky == 0 && kx >= 0) {
                    kx
                } else {
                    -kx
                };
                let v = row[if kr >= 0 {
                    kr as usize
                } else {
                    (kr + n as i64) as usize
                }];
                *o = v.norm_sqr() * dy * deconv2[kx.unsigned_abs() as usize];
            }
        });
    }
}

/// The periodogram by NUFFT with tolerance ε (relative ℓ2 error of P, DC excluded, ≤ ε):
/// a one-shot [`NufftPlan::new`] + [`NufftPlan::periodogram`]. Reuse a plan for repeated calls.
///
/// # Errors
/// As [`NufftPlan::new`] and [`NufftPlan::periodogram`].
pub fn periodogram_nufft(
    points: &[DVec2],
    m: usize,
    tolerance: f64,
    cancel: &Cancel,
) -> Result<Spectrum, SpectrumError> {
    NufftPlan::new(m, tolerance)?.periodogram(points, cancel)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn kernel_width_rule_and_tolerance_range() {
        let widths: Vec<usize> = [1e-2, 1e-3, 1e-6, 1e-9, 1e-12]
            .iter()
            .map(|&e| kernel_params(e).unwrap().width)
            .collect();
        assert_eq!(widths, vec![5, 6, 9, 12, 15]);
        assert_eq!(kernel_params(2e-3).unwrap().width, 6);
        assert_eq!(kernel_params(9.9e-7).unwrap().width, 10);
        assert_eq!(kernel_params(1e-6).unwrap().beta, 2.30 * 9.0);
        for bad in [f64::NAN, 0.0, 1e-13, 0.011, -1e-3, f64::INFINITY] {
            let e = kernel_params(bad).unwrap_err();
            assert!(matches!(e, SpectrumError::InvalidTolerance { .. }));
            let msg = e.to_string();
            assert!(
                msg.contains("tolerance") && msg.contains("1e-12") && msg.contains("1e-2"),
                "{msg}"
            );
        }
    }

    #[test]
    fn es_kernel_values() {
        assert_eq!(es_kernel(0.0, 10.0), 1.0);
        assert!((es_kernel(1.0, 10.0) - (-10.0f64).exp()).abs() < 1e-18);
        assert_eq!(es_kernel(1.0001, 10.0), 0.0);
        // φ(0.6) = exp(β(0.8 − 1)).
        assert!((es_kernel(0.6, 5.0) - (-1.0f64).exp()).abs() < 1e-15);
    }

    #[test]
    fn upsampled_sizes_are_even_and_smooth() {
        assert_eq!(upsampled_size(256), 512);
        assert_eq!(upsampled_size(640), 1280);
        assert_eq!(upsampled_size(3), 6);
        assert_eq!(upsampled_size(4094), 8192);
        assert_eq!(upsampled_size(4093), 8192);
        // 2002 = 2·7·11·13; 2025 is odd; 2048 = 2¹¹.
        assert_eq!(upsampled_size(1001), 2048);
    }

    #[test]
    fn deconvolution_quadrature_is_converged() {
        // The factors of a plan agree with a plain Gauss–Legendre rule in z (no change of
        // variable) of 4000 nodes, whose algebraic error (√ singularity of size β e^{−β} at
        // z = ±1) is below 1e-11 relative for these β; and with 3× as many θ-nodes to 1e-13 (rounding).
        for tol in [1e-2, 1e-6, 1e-12] {
            let plan = NufftPlan::new(64, tol).unwrap();
            let k = plan.kernel();
            let (z, wq) = gauss_legendre(4000);
            for (kk, &d2) in plan.deconvolution_squared().iter().enumerate() {
                let s = kk as f64 * k.width as f64 / plan.upsampled() as f64;
                let a = std::f64::consts::PI * s;
                let integral: f64 = z
                    .iter()
                    .zip(&wq)
                    .map(|(&x, &w)| w * es_kernel(x, k.beta) * (a * x).cos())
                    .sum();
                let nhat = 0.5 * k.width as f64 * integral;
                let reference = 1.0 / (nhat * nhat);
                assert!(
                    ((d2 - reference) / reference).abs() < 1e-11,
                    "tol {tol} k {kk}: {d2} vs {reference}"
                );
                let fine = kernel_transform(s, k.beta, 6 * k.width + 72);
                let nhat_fine = 0.5 * k.width as f64 * fine;
                let reference = 1.0 / (nhat_fine * nhat_fine);
                assert!(
                    ((d2 - reference) / reference).abs() < 1e-13,
                    "tol {tol} k {kk}: {d2} vs {reference}"
                );
            }
        }
    }

    #[test]
    fn plan_rejects_bad_kernels() {
        let bad_w = NufftPlan::with_kernel(
            8,
            KernelParams {
                width: 17,
                beta: 30.0,
            },
        );
        assert!(matches!(
            bad_w,
            Err(SpectrumError::InvalidParam {
                field: "kernel.width",
                ..
            })
        ));
        let bad_b = NufftPlan::with_kernel(
            8,
            KernelParams {
                width: 6,
                beta: f64::NAN,
            },
        );
        assert!(matches!(
            bad_b,
            Err(SpectrumError::InvalidParam {
                field: "kernel.beta",
                ..
            })
        ));
        assert!(matches!(
            NufftPlan::new(4097, 1e-6),
            Err(SpectrumError::InvalidSize { .. })
        ));
    }
}

#[cfg(test)]
mod table_tests {
    use super::*;
    use crate::core::rng::Rng;

    #[test]
    fn chebyshev_kernel_table_matches_es_kernel_for_every_width() {
        let mut rng = Rng::new(11);
        for w in 2..=MAX_WIDTH {
            let kernel = KernelParams {
                width: w,
                beta: BETA_PER_WIDTH * w as f64,
            };
            let plan = NufftPlan::with_kernel(8, kernel).unwrap();
            let degree = plan.chebyshev_degree();
            assert!(degree.is_some(), "w {w}: no Chebyshev table");
            let target = (-kernel.beta).exp().max(1e-14);
            let mut samples: Vec<f64> = (0..500).map(|_| rng.next_f64()).collect();
            samples.extend([0.0, 0.5, 1.0 - f64::EPSILON / 2.0]);
            for s in samples {
                let taps = plan.kernel_taps(s);
                for (t, v) in taps.iter().enumerate() {
                    let z = (2.0 * (s + t as f64) - w as f64) / w as f64;
                    let e = es_kernel(z, kernel.beta);
                    assert!(
                        (v - e).abs() <= 4.0 * target,
                        "w {w} degree {degree:?} s {s} tap {t}: {v} vs {e}"
                    );
                }
            }
        }
    }

    #[test]
    fn very_large_beta_falls_back_to_direct_kernel() {
        let plan = NufftPlan::with_kernel(
            8,
            KernelParams {
                width: 4,
                beta: 700.0,
            },
        )
        .unwrap();
        assert_eq!(plan.chebyshev_degree(), None);
        let taps = plan.kernel_taps(0.25);
        assert_eq!(taps[2], es_kernel((2.0 * 2.25 - 4.0) / 4.0, 700.0));
    }
}
