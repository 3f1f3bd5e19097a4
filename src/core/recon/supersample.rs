//! Supersampling: s samples per pixel, filtered by a pixel filter scaled to the output pixel.
//!
//! Pixel (i, j) of a W×W image receives s sample offsets uₖ ∈ [0,1)² from a
//! [`SampleProvider`] (jitter, N-rooks, Halton/Sobol with per-pixel scrambling, …); its samples
//! sit at ((i + uₖ.x)/W, (j + uₖ.y)/W). Every pixel's value is the lecture's
//! Pixel = Σₖ wₖ·Sampleₖ / Σₖ wₖ, with wₖ = w(d) for the pixel filter w in **pixel units**
//! (d = offset of the sample from the pixel centre, times W), its denominator floored at
//! c·Σₖ |wₖ| as every reconstruction's (module docs of [`super`]): a pixel filter with
//! negative lobes (Lanczos, Mitchell) over a few random samples per pixel would otherwise
//! divide by a Σw near 0.
//!
//! **Samples are shared with neighbouring pixels**: a pixel gathers every sample (of any pixel)
//! within the filter support, so a filter wider than ½ pixel (tent of radius 1, Gaussian,
//! windowed sinc) blends neighbouring pixels' samples, as a film plane with splatting does.
//! With a box of radius ½ every sample reaches only its own pixel and the result is the plain
//! mean of the pixel's samples, which converges to the box-prefiltered [`super::reference`].
//! Borders are open: samples are only taken inside the image.
//!
//! Implementation: pixels are evaluated in parallel (tasks of ~2¹⁴ samples, each checking the
//! cancel token) in batches of at most 2²¹ samples (offsets and signal values, ~50 MB), then
//! splatted serially in row-major pixel order, so the result does not depend on the number of
//! threads.

use super::accum::{splat_work, Accum};
use super::{
    check_cancel, check_size, check_support, check_work, ReconError, ReconKernel, Reconstruction,
    MAX_SPP, MAX_W,
};
use crate::core::cancel::Cancel;
use crate::core::pattern::{clamp_unit, divisor_near_sqrt, Pattern};
use crate::core::rng::{derive_seed, Rng};
use crate::core::signal::Signal;
use glam::DVec2;
use rayon::prelude::*;
use std::time::Instant;

/// Gives the sample offsets of each pixel.
///
/// `offsets(pixel, spp, out)` appends exactly `spp` offsets in [0,1)² (relative to the pixel's
/// corner, in pixel units) for pixel index `pixel = j·W + i` to `out` (which the caller clears).
/// It must be a pure function of `(pixel, spp)` for results to be deterministic. Closures
/// `Fn(u64, usize, &mut Vec<DVec2>) -> Result<(), ReconError>` are providers too.
pub trait SampleProvider: Sync {
    /// Appends `spp` offsets for `pixel`.
    fn offsets(&self, pixel: u64, spp: usize, out: &mut Vec<DVec2>) -> Result<(), ReconError>;
}

impl<F> SampleProvider for F
where
    F: Fn(u64, usize, &mut Vec<DVec2>) -> Result<(), ReconError> + Sync,
{
    fn offsets(&self, pixel: u64, spp: usize, out: &mut Vec<DVec2>) -> Result<(), ReconError> {
        self(pixel, spp, out)
    }
}

/// Jittered (stratified) offsets: spp = c·r strata (c = the divisor of spp nearest √spp, not
/// above it), one uniform point per stratum, per-pixel stream `Rng::new(derive_seed(seed, pixel))`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Jittered {
    /// Seed of the jitter.
    pub seed: u64,
}

impl SampleProvider for Jittered {
    fn offsets(&self, pixel: u64, spp: usize, out: &mut Vec<DVec2>) -> Result<(), ReconError> {
        let cols = divisor_near_sqrt(spp);
        let rows = spp / cols;
        let mut rng = Rng::new(derive_seed(self.seed, pixel));
        for b in 0..rows {
            for a in 0..cols {
                let x = (a as f64 + rng.next_f64()) / cols as f64;
                let y = (b as f64 + rng.next_f64()) / rows as f64;
                out.push(DVec2::new(clamp_unit(x), clamp_unit(y)));
            }
        }
        Ok(())
    }
}

/// Uniform supersampling: the k×k sub-pixel centres ((a+½)/k, (b+½)/k); spp must be k².
/// spp = 1 is point sampling at the pixel centre.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct UniformGrid;

impl SampleProvider for UniformGrid {
    fn offsets(&self, _pixel: u64, spp: usize, out: &mut Vec<DVec2>) -> Result<(), ReconError> {
        let k = (spp as f64).sqrt().round() as usize;
        if k * k != spp {
            return Err(ReconError::ProviderSpp {
                provider: "uniform grid",
                spp,
                allowed: "a perfect square k² (1, 4, 9, 16, …)".into(),
            });
        }
        for b in 0..k {
            for a in 0..k {
                out.push(DVec2::new(
                    (a as f64 + 0.5) / k as f64,
                    (b as f64 + 0.5) / k as f64,
                ));
            }
        }
        Ok(())
    }
}

/// Offsets from a sample [`Pattern`]: pixel p uses `pattern.generate(spp, derive_seed(seed, p))`,
/// so randomised patterns (jitter, N-rooks, scrambled Sobol', …) decorrelate across pixels.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PatternProvider {
    /// The pattern.
    pub pattern: Pattern,
    /// Base seed.
    pub seed: u64,
}

impl Default for PatternProvider {
    /// The default pattern (full jitter) with seed 0.
    fn default() -> Self {
        PatternProvider {
            pattern: Pattern::default(),
            seed: 0,
        }
    }
}

impl SampleProvider for PatternProvider {
    fn offsets(&self, pixel: u64, spp: usize, out: &mut Vec<DVec2>) -> Result<(), ReconError> {
        out.extend(self.pattern.generate(spp, derive_seed(self.seed, pixel))?);
        Ok(())
    }
}

/// Samples per evaluation batch (bounds the memory to ~50 MB).
const BATCH_SAMPLES: usize = 1 << 21;
/// Samples per parallel task (and per cancellation check).
const TASK_SAMPLES: usize = 1 << 14;

/// Supersamples `signal` on a W×W image with `spp` samples per pixel from `provider`, filtered
/// by `kernel` in pixel units (see the module docs).
///
/// Checks: W in 1..=8192, spp in 1..=4096, the kernel support, the provider's offsets (count
/// and range), and the total work. Cancellable every ~2¹⁴ samples.
pub fn supersample<K, P>(
    signal: &Signal,
    w: usize,
    spp: usize,
    provider: &P,
    kernel: &K,
    cancel: &Cancel,
) -> Result<Reconstruction, ReconError>
where
    K: ReconKernel + ?Sized,
    P: SampleProvider + ?Sized,
{
    let start = Instant::now();
    signal.validate()?;
    check_size("w", w, 1, MAX_W)?;
    check_size("spp", spp, 1, MAX_SPP)?;
    let support = check_support(kernel)?;
    let mut acc = Accum::new(w, kernel, support, 1.0)?;
    let n = w * w * spp;
    check_work("supersampling", splat_work(n, acc.r_px(), w) + n as u128)?;
    let wf = w as f64;
    let pixels = w * w;
    // Batches of at most BATCH_SAMPLES samples (at least one pixel), evaluated in parallel
    // in tasks of about TASK_SAMPLES samples, then splatted serially in pixel order.
    let per_batch = (BATCH_SAMPLES / spp).max(1);
    let per_task = (TASK_SAMPLES / spp).max(1);
    let mut p0 = 0;
    while p0 < pixels {
        let p1 = (p0 + per_batch).min(pixels);
        let tasks: Vec<usize> = (p0..p1).step_by(per_task).collect();
        let parts: Vec<Vec<(DVec2, f64)>> = tasks
            .into_par_iter()
            .map(|q0| {
                let q1 = (q0 + per_task).min(p1);
                sample_pixels(signal, w, wf, q0..q1, spp, provider, cancel)
            })
            .collect::<Result<_, _>>()?;
        for part in parts {
            check_cancel(cancel)?;
            for (x, v) in part {
                acc.splat(x, v);
            }
        }
        p0 = p1;
    }
    acc.finish(n, start.elapsed())
}

/// The samples of pixels `range` (row-major indices): positions in pixel units and values.
fn sample_pixels<P: SampleProvider + ?Sized>(
    signal: &Signal,
    w: usize,
    wf: f64,
    range: std::ops::Range<usize>,
    spp: usize,
    provider: &P,
    cancel: &Cancel,
) -> Result<Vec<(DVec2, f64)>, ReconError> {
    check_cancel(cancel)?;
    let mut out = Vec::with_capacity(range.len() * spp);
    let mut buf = Vec::with_capacity(spp);
    let signal = signal.prepare();
    for p in range {
        let (i, j) = (p % w, p / w);
        let pixel = p as u64;
        buf.clear();
        provider.offsets(pixel, spp, &mut buf)?;
        if buf.len() != spp {
            return Err(ReconError::ProviderCount {
                pixel,
                got: buf.len(),
                spp,
            });
        }
        for u in &buf {
            if !((0.0..1.0).contains(&u.x) && (0.0..1.0).contains(&u.y)) {
                return Err(ReconError::ProviderOffset {
                    pixel,
                    x: u.x,
                    y: u.y,
                });
            }
            let x = DVec2::new(i as f64 + u.x, j as f64 + u.y);
            out.push((x, signal.eval(x / wf)));
        }
    }
    Ok(out)
}
