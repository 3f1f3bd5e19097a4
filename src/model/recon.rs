//! Reconstructions, reference images, their error, and convergence curves.

use super::ImageData;
use crate::core::recon::ReferenceMethod;

/// A reconstructed image.
#[derive(Debug, Clone)]
pub struct ReconData {
    /// The reconstruction for display (f32, row 0 at the top).
    pub image: ImageData,
    /// Pixels with zero total filter weight (shown at the fill value).
    pub zero_weight: usize,
}

/// A reference image.
#[derive(Debug, Clone)]
pub struct ReferenceData {
    /// The reference for display (f32, row 0 at the top).
    pub image: ImageData,
    /// The image's own error, where known (a bound or an estimate: see [`Self::method`]).
    pub error_estimate: Option<f64>,
    /// How the pixels were computed.
    pub method: ReferenceMethod,
}

/// Error of a reconstruction against its reference.
#[derive(Debug, Clone)]
pub struct ErrorData {
    /// √(mean of (I − R)²).
    pub rmse: f64,
    /// 10·log₁₀(1/MSE) dB (peak 1).
    pub psnr: f64,
    /// |reconstruction − reference| of the display images (f32).
    pub image: ImageData,
    /// The largest value of [`Self::image`] (the top of its colour range).
    pub max_error: f32,
}

/// One point of a convergence curve.
#[derive(Debug, Clone, Copy)]
pub struct ConvergencePoint {
    pub spp: usize,
    pub rmse: f64,
    pub millis: f64,
}
