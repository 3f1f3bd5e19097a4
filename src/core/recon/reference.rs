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
//! | zone plate, checkerboard, chirp | [`ReferenceMethod::Supersampled`] | stratified jittered supersampling with an error estimate (below) |
//!
//! Exact methods have `error_estimate = None`: their error is rounding only (≲ 10⁻¹³).
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

use super::coverage::{half_planes, pixel_coverage};
use super::{check_cancel, check_size, check_work, ReconError, MAX_W};
use crate::core::cancel::Cancel;
use crate::core::rng::{derive_seed, Rng};
use crate::core::signal::exact::{rem2, sin_pi, DoubleDouble};
use crate::core::signal::{sinc_pi, Signal};
use glam::DVec2;
use rayon::prelude::*;
use std::time::{Duration, Instant};

/// How a reference image was computed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ReferenceMethod {
    /// Exact area coverage of each pixel by the shape.
    ExactArea,
    /// A closed-form integral of the signal over each pixel.
    ExactIntegral,
    /// Jittered supersampling with `strata`×`strata` and 2·`strata`×2·`strata` samples per
    /// pixel (the finer image is returned).
    Supersampled {
        /// s, the strata per axis of the coarser pass.
        strata: usize,
    },
}

/// A box-prefiltered W×W reference image.
#[derive(Debug, Clone, PartialEq)]
pub struct ReferenceImage {
    /// Size W.
    pub w: usize,
    /// Pixel means, row-major (`pixels[j·W + i]`).
    pub pixels: Vec<f64>,
    /// Estimated RMS error of `pixels` (over-estimate, see the module docs); `None` when exact.
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

/// The box-prefiltered reference with default options (exact where possible, else 8×8 and
/// 16×16 jittered supersampling).
pub fn reference_image(signal: &Signal, w: usize) -> Result<ReferenceImage, ReconError> {
    reference_image_with(signal, w, &ReferenceOptions::default(), &Cancel::never())
}

/// The box-prefiltered reference: exact where a closed form exists, supersampled otherwise
/// (see the module docs for the method per signal).
pub fn reference_image_with(
    signal: &Signal,
    w: usize,
    options: &ReferenceOptions,
    cancel: &Cancel,
) -> Result<ReferenceImage, ReconError> {
    signal.validate()?;
    check_size("w", w, 1, MAX_W)?;
    let start = Instant::now();
    let exact = match signal {
        Signal::StepEdge(s) => {
            let (n, b) = s.half_plane();
            Some((
                ReferenceMethod::ExactArea,
                area_image(&[(n, b)], w, cancel)?,
            ))
        }
        Signal::Polygon(p) => {
            let planes = half_planes(&p.vertices());
            Some((ReferenceMethod::ExactArea, area_image(&planes, w, cancel)?))
        }
        Signal::Grating(_) | Signal::SumOfSines(_) | Signal::Square(_) | Signal::Constant(_) => {
            Some((
                ReferenceMethod::ExactIntegral,
                per_pixel(w, cancel, |i, j| box_integral(signal, i, j, w))?,
            ))
        }
        Signal::ZonePlate(_) | Signal::Checkerboard(_) | Signal::Chirp(_) => None,
    };
    match exact {
        Some((method, pixels)) => Ok(ReferenceImage {
            w,
            pixels,
            error_estimate: None,
            method,
            wall_time: start.elapsed(),
        }),
        None => reference_supersampled(signal, w, options, cancel),
    }
}

/// The supersampled reference for any signal (see the module docs): I_2s with the estimate
/// RMS(I_s − I_2s).
pub fn reference_supersampled(
    signal: &Signal,
    w: usize,
    options: &ReferenceOptions,
    cancel: &Cancel,
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
    let coarse = jittered_image(signal, w, s, derive_seed(options.seed, 0), cancel)?;
    let fine = jittered_image(signal, w, 2 * s, derive_seed(options.seed, 1), cancel)?;
    let mse = coarse
        .iter()
        .zip(&fine)
        .map(|(a, b)| (a - b) * (a - b))
        .sum::<f64>()
        / (w * w) as f64;
    Ok(ReferenceImage {
        w,
        pixels: fine,
        error_estimate: Some(mse.sqrt()),
        method: ReferenceMethod::Supersampled { strata: s },
        wall_time: start.elapsed(),
    })
}

/// Mean of `s×s` jittered samples per pixel; pixel k uses `Rng::new(derive_seed(seed, k))`.
fn jittered_image(
    signal: &Signal,
    w: usize,
    s: usize,
    seed: u64,
    cancel: &Cancel,
) -> Result<Vec<f64>, ReconError> {
    let sw = (s * w) as f64;
    let inv = 1.0 / (s * s) as f64;
    per_pixel(w, cancel, |i, j| {
        let mut rng = Rng::new(derive_seed(seed, (j * w + i) as u64));
        let mut sum = 0.0;
        for b in 0..s {
            for a in 0..s {
                let x = ((i * s + a) as f64 + rng.next_f64()) / sw;
                let y = ((j * s + b) as f64 + rng.next_f64()) / sw;
                sum += signal.eval(DVec2::new(x, y));
            }
        }
        sum * inv
    })
}

/// Fills a W×W image with `f(i, j)`, parallel over rows, cancellable every row.
fn per_pixel<F>(w: usize, cancel: &Cancel, f: F) -> Result<Vec<f64>, ReconError>
where
    F: Fn(usize, usize) -> f64 + Sync,
{
    let mut pixels = vec![0.0; w * w];
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
