//! Reconstructions, reference images, their error, and convergence curves.

use super::ImageData;
use crate::core::recon::{Reconstruction, ReferenceMethod};
use std::sync::Arc;

/// A reconstructed image.
#[derive(Debug, Clone)]
pub struct ReconData {
    /// The reconstruction for display (f32, row 0 at the top).
    pub image: ImageData,
    /// Pixels with zero total filter weight (shown at the fill value).
    pub zero_weight: usize,
    /// The reconstruction as computed (f64 pixels, row 0 at the bottom): what its error
    /// against the reference is measured on.
    pub exact: Arc<Reconstruction>,
}

impl ReconData {
    /// A reconstruction with its display image: rows flipped (the pixels' row j lies at
    /// y = (j + ½)/W, y up; the image's row 0 is the top), values as f32.
    pub fn new(r: Reconstruction) -> Self {
        let w = r.w;
        ReconData {
            image: ImageData::from_y_up(w, w, |i| r.pixels[i] as f32),
            zero_weight: r.zero_weight,
            exact: Arc::new(r),
        }
    }
}

/// A reference image.
#[derive(Debug, Clone)]
pub struct ReferenceData {
    /// The reference for display (f32, row 0 at the top).
    pub image: ImageData,
    /// The pixel means as computed (f64, row-major, row 0 at the bottom): what errors are
    /// measured against.
    pub pixels: Arc<Vec<f64>>,
    /// The image's own error, where known (a bound or an estimate: see [`Self::method`]).
    pub error_estimate: Option<f64>,
    /// How the pixels were computed.
    pub method: ReferenceMethod,
}

impl ReferenceData {
    /// A W×W reference from its pixel means (row-major, row 0 at the bottom), with its
    /// display image made as [`ReconData::new`] makes a reconstruction's.
    pub fn new(
        w: usize,
        pixels: Vec<f64>,
        error_estimate: Option<f64>,
        method: ReferenceMethod,
    ) -> Self {
        ReferenceData {
            image: ImageData::from_y_up(w, w, |i| pixels[i] as f32),
            pixels: Arc::new(pixels),
            error_estimate,
            method,
        }
    }
}

/// Error of a reconstruction against its reference.
#[derive(Debug, Clone)]
pub struct ErrorData {
    /// √(mean of (I − R)²) over the f64 pixels ([`crate::core::recon::error_report`]): the
    /// number `samplescope recon` prints for the same scene.
    pub rmse: f64,
    /// 10·log₁₀(1/MSE) dB (peak 1).
    pub psnr: f64,
    /// The largest |reconstruction − reference| over the f64 pixels (the report's).
    pub max_abs: f64,
    /// |reconstruction − reference| of the display images (f32).
    pub image: ImageData,
    /// The largest value of [`Self::image`] (the top of its colour range).
    pub max_error: f32,
    /// The share of the error's energy at low frequencies: its periodogram summed over
    /// 0 < |k| ≤ W/8 cycles per image, over the total for k ≠ 0 (white noise ≈ π/64 ≈ 4.9 %;
    /// blue-noise error, e.g. ZSobol's, much less). `None` for a constant error.
    pub low_frequency: Option<f64>,
    /// The error's periodogram (centred, DC in the middle), as log₁₀ P, with its display range
    /// (lo, hi); `None` when it was not computed (non-square or over 4096²).
    pub spectrum: Option<(ImageData, f32, f32)>,
}

/// One point of a convergence curve.
#[derive(Debug, Clone, Copy)]
pub struct ConvergencePoint {
    pub spp: usize,
    pub rmse: f64,
    pub millis: f64,
}
