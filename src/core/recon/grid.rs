//! Uniform grid sampling and resampling: "sampled at 128×128 and reconstructed to 512×512
//! using windowed sinc" (the lecture's zone plate slide).
//!
//! The signal is sampled at the G×G cell centres xₐ_b = ((a+½)/G, (b+½)/G) and reconstructed on
//! a W×W image by the normalised weighted sum with a (typically separable) kernel scaled to the
//! grid spacing 1/G, which is the mean spacing 1/√N of N = G² samples: this is
//! [`reconstruct_scattered`] on grid points. Normalising makes a windowed sinc, whose weights
//! do not sum exactly to 1, reproduce constants exactly and keeps the open border unbiased.
//! The grid has Nyquist G/2 cycles per unit: a zone plate with constant K aliases beyond
//! ρ = G/(2K) whatever the output size W.

use super::scattered::reconstruct_scattered;
use super::{check_size, ReconError, ReconKernel, Reconstruction};
use crate::core::cancel::Cancel;
use crate::core::signal::Signal;
use glam::DVec2;
use std::time::Instant;

/// Largest grid size G (G² ≤ 2²⁴ samples).
pub const MAX_G: usize = 4096;

/// The G×G cell-centre grid, row-major, and the signal's values there.
pub fn sample_grid(
    signal: &Signal,
    g: usize,
    cancel: &Cancel,
) -> Result<(Vec<DVec2>, Vec<f64>), ReconError> {
    signal.validate()?;
    check_size("g", g, 1, MAX_G)?;
    let gf = g as f64;
    let points: Vec<DVec2> = (0..g * g)
        .map(|k| DVec2::new(((k % g) as f64 + 0.5) / gf, ((k / g) as f64 + 0.5) / gf))
        .collect();
    let values = super::scattered::sample_signal(signal, &points, cancel)?;
    Ok((points, values))
}

/// Samples `signal` on a G×G grid and reconstructs it on W×W with `kernel` scaled to 1/G.
///
/// The wall time includes the sampling.
pub fn resample_grid<K: ReconKernel + ?Sized>(
    signal: &Signal,
    g: usize,
    w: usize,
    kernel: &K,
    cancel: &Cancel,
) -> Result<Reconstruction, ReconError> {
    let start = Instant::now();
    check_size("w", w, 1, super::MAX_W)?;
    let (points, values) = sample_grid(signal, g, cancel)?;
    let mut r = reconstruct_scattered(&points, &values, w, kernel, cancel)?;
    r.wall_time = start.elapsed();
    Ok(r)
}
