//! What sampling, reconstruction, supersampling, reference images, error images and the
//! convergence curve cost (work, seconds, bytes). Rates and method: [`crate::core::budget`].

use crate::core::budget::{
    cpu, largest_bytes, parallel, total_seconds, touch, Estimate, Unit, REFERENCE_CORES,
};
use crate::core::filter::{Filter2D, Mode2D};
use crate::core::format::significant;
use crate::core::pattern::cost::{pattern_cost, POINT_NS};
use crate::core::pattern::Pattern;
use crate::core::recon::{self, ReferenceMethod, ReferenceOptions};
use crate::core::signal::Signal;

/// Bytes of a reconstruction's accumulator and output per pixel: the sums
/// [Σw·v, Σw, Σ|w|, Σ|w|·v] (32), the pixel (8) and its zero-weight flag (1).
pub const ACCUM_PIXEL_BYTES: f64 = 41.0;

/// One signal evaluation: the zone plate (double-double phase), the others.
pub(crate) const EVAL_ZONE_PLATE_NS: f64 = 60.0;
pub(crate) const EVAL_NS: f64 = 40.0;
/// One kernel tap of a separable splat (a packed multiply-add), of a radial one (a filter
/// evaluation at |d|).
pub(crate) const TAP_NS: f64 = 2.0;
pub(crate) const RADIAL_TAP_NS: f64 = 50.0;
/// One 1D filter factor of a separable splat (2·taps per axis per sample).
pub(crate) const FACTOR_NS: f64 = 40.0;
/// Per sample of a scattered splat: its range in each of the
/// [`SPLAT_BANDS`] bands of rows, the tile sort.
pub(crate) const SPLAT_SAMPLE_NS: f64 = 30.0;
pub(crate) const SPLAT_BAND_NS: f64 = 3.0;
/// Bands of output rows of the parallel splat on the reference machine (4 per thread).
pub(crate) const SPLAT_BANDS: f64 = 8.0;
/// Per sample of the serial supersampling splat (range, bookkeeping, the batch buffer).
pub(crate) const SUPERSAMPLE_SAMPLE_NS: f64 = 80.0;
/// Per output pixel of an image (normalising, the mask, copying out).
pub(crate) const PIXEL_NS: f64 = 15.0;

/// One pixel of an exact area-coverage reference (clipping the pixel square).
pub(crate) const AREA_PIXEL_NS: f64 = 90.0;
/// One pixel of a closed-form reference (sin_pi and sincs in double-double).
pub(crate) const INTEGRAL_PIXEL_NS: f64 = 300.0;
/// One integrand evaluation of the quadrature reference (sin_pi and cos_pi of a double-double).
pub(crate) const QUADRATURE_EVAL_NS: f64 = 40.0;

/// One evaluation of `signal` (one arm per signal, no fallback).
pub(crate) fn eval_ns(signal: &Signal) -> f64 {
    match signal {
        Signal::ZonePlate(_) => EVAL_ZONE_PLATE_NS,
        Signal::Checkerboard(_)
        | Signal::Grating(_)
        | Signal::StepEdge(_)
        | Signal::Polygon(_)
        | Signal::SumOfSines(_)
        | Signal::Chirp(_)
        | Signal::Square(_)
        | Signal::Constant(_) => EVAL_NS,
    }
}

/// Sampling `signal` at `n` points ([`recon::sample_signal`], parallel).
pub fn sampling(signal: &Signal, n: usize) -> Estimate {
    let nf = n as f64;
    let bytes = 24.0 * nf;
    Estimate::new(
        format!("sampling the {} at {n} points", signal.name()),
        nf,
        Unit::Evaluations,
        nf * parallel(eval_ns(signal)) + touch(8.0 * nf),
        bytes,
    )
}

/// Expected pixel centres per axis within r pixels of a sample uniform on [0, W]: the mean
/// length of [x − r, x + r] ∩ [0, W], i.e. 2r − r²/W for r ≤ W, W beyond.
pub fn taps_per_axis(r_px: f64, w: usize) -> f64 {
    let wf = w as f64;
    if !(r_px.is_finite() && r_px > 0.0) {
        return 0.0;
    }
    if r_px >= wf {
        wf
    } else {
        2.0 * r_px - r_px * r_px / wf
    }
}

/// Taps, serial-free CPU seconds of one splat of `n` samples with support `r_px` pixels.
pub(crate) fn splat_cost(n: f64, r_px: f64, w: usize, filter: &Filter2D) -> (f64, f64) {
    let e = taps_per_axis(r_px, w);
    let taps = n * e * e;
    let ns = match filter.mode {
        Mode2D::Separable => taps * TAP_NS + n * 2.0 * e * FACTOR_NS,
        Mode2D::Radial => taps * RADIAL_TAP_NS,
    };
    (taps, ns)
}

/// Reconstructing `n` scattered samples onto a W×W image with `filter` scaled to the mean
/// sample spacing 1/√n ([`recon::reconstruct_scattered`]): about n·(2r − r²/W)² taps for a
/// support of r = support·W/√n pixels, in parallel over bands of rows.
pub fn scattered(n: usize, w: usize, filter: &Filter2D) -> Estimate {
    let (nf, wf) = (n as f64, w as f64);
    let r_px = filter.support() * wf / nf.max(1.0).sqrt();
    let (taps, ns) = splat_cost(nf, r_px, w, filter);
    let pixels = wf * wf;
    // Accumulator [Σwv, Σw, Σ|w|, Σ|w|v] per pixel, the pixels and mask out; the tile-sorted
    // samples and the points and values they came from.
    let bytes = ACCUM_PIXEL_BYTES * pixels + 52.0 * nf;
    let secs = parallel(ns + nf * SPLAT_BANDS * SPLAT_BAND_NS)
        + cpu(nf * SPLAT_SAMPLE_NS + pixels * PIXEL_NS)
        + touch(bytes);
    Estimate::new(
        format!(
            "scattered reconstruction of {n} samples on {w}×{w} ({} px support)",
            significant(r_px, 3)
        ),
        taps,
        Unit::Taps,
        secs,
        bytes,
    )
}

/// Sampling `signal` on a g×g grid and resampling it to W×W ([`recon::resample_grid`]).
pub fn resample(signal: &Signal, g: usize, w: usize, filter: &Filter2D) -> Estimate {
    let n = g * g;
    let s = sampling(signal, n);
    let r = scattered(n, w, filter);
    Estimate::new(
        format!("grid resampling {g}×{g} to {w}×{w}"),
        r.amount,
        Unit::Taps,
        s.seconds + r.seconds + cpu(n as f64 * POINT_NS),
        r.bytes,
    )
}

/// Supersampling `signal` on W×W with `spp` samples per pixel from `pattern` (one pattern per
/// pixel) and `filter` in pixel units ([`recon::supersample`]): the offsets and signal values
/// in parallel, the splat serial.
pub fn supersampling(
    signal: &Signal,
    w: usize,
    spp: usize,
    pattern: &Pattern,
    filter: &Filter2D,
) -> Estimate {
    let wf = w as f64;
    let pixels = wf * wf;
    let samples = pixels * spp as f64;
    let (_, _, per_pixel, _) = pattern_cost(pattern, spp);
    let (_, splat_ns) = splat_cost(samples, filter.support(), w, filter);
    // Batches of at most 2²¹ samples (positions and values, 24 bytes) beside the accumulator
    // and the output.
    let batch = (samples.min((1u64 << 21) as f64)) * 24.0;
    let bytes = ACCUM_PIXEL_BYTES * pixels + batch;
    let secs = pixels * per_pixel / REFERENCE_CORES
        + samples * parallel(eval_ns(signal))
        + cpu(splat_ns + samples * SUPERSAMPLE_SAMPLE_NS + pixels * PIXEL_NS)
        + touch(bytes);
    Estimate::new(
        format!(
            "supersampling {w}×{w} at {spp} spp ({} per pixel)",
            pattern.name()
        ),
        samples,
        Unit::Samples,
        secs,
        bytes,
    )
}

/// The box-prefiltered reference image of `signal` at W×W with default options
/// ([`recon::reference_image_with`]): counts from [`recon::reference_work`].
pub fn reference(signal: &Signal, w: usize) -> Estimate {
    let options = ReferenceOptions::default();
    let (method, work) = recon::reference_work(signal, w, &options);
    let pixels = (w as f64) * (w as f64);
    let work = work as f64;
    let (unit, ns, bytes) = match method {
        ReferenceMethod::ExactArea => (Unit::Pixels, work * AREA_PIXEL_NS, 8.0 * pixels),
        ReferenceMethod::ExactIntegral => (Unit::Pixels, work * INTEGRAL_PIXEL_NS, 8.0 * pixels),
        ReferenceMethod::SeparableQuadrature { .. } => (
            Unit::Evaluations,
            work * QUADRATURE_EVAL_NS + pixels * PIXEL_NS,
            8.0 * pixels,
        ),
        // Both passes' (mean, variance) pairs and the coarse image.
        ReferenceMethod::Supersampled { .. } | ReferenceMethod::Jittered { .. } => {
            (Unit::Evaluations, work * eval_ns(signal), 40.0 * pixels)
        }
    };
    Estimate::new(
        format!("reference image {w}×{w} ({})", method.label()),
        work,
        unit,
        parallel(ns) + touch(bytes),
        bytes,
    )
}

/// The error of a W×W reconstruction against its reference (RMSE, the difference image).
pub fn error_image(w: usize) -> Estimate {
    let pixels = (w as f64) * (w as f64);
    Estimate::new(
        format!("error image {w}×{w}"),
        pixels,
        Unit::Pixels,
        cpu(pixels * PIXEL_NS) + touch(4.0 * pixels),
        12.0 * pixels,
    )
}

/// The convergence curve: the reference at W×W, then supersampling at every spp of `spps`.
pub fn convergence(
    signal: &Signal,
    pattern: &Pattern,
    spps: &[usize],
    w: usize,
    filter: &Filter2D,
) -> Estimate {
    let r = reference(signal, w);
    let runs: Vec<Estimate> = spps
        .iter()
        .map(|&s| supersampling(signal, w, s, pattern, filter))
        .collect();
    let samples: f64 = runs.iter().map(|e| e.amount).sum();
    Estimate::new(
        format!(
            "convergence curve {w}×{w} at {} spp levels ({} per pixel)",
            spps.len(),
            pattern.name()
        ),
        samples,
        Unit::Samples,
        r.seconds + total_seconds(&runs),
        r.bytes.max(largest_bytes(&runs)),
    )
}
