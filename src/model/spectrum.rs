//! Periodograms ready to display.

use super::ImageData;

/// A periodogram ready to display.
#[derive(Debug, Clone)]
pub struct SpectrumData {
    /// log10 P, row 0 = highest ky.
    pub image: ImageData,
    /// A display range from the data (2nd and 99.8th percentile of log10 P).
    pub auto_range: (f32, f32),
    /// Radially averaged power spectrum: (|k|, P).
    pub raps: Vec<[f64; 2]>,
    /// Anisotropy in dB: (|k|, A).
    pub anisotropy: Vec<[f64; 2]>,
    /// Wall time per stage (ms).
    pub stages: Vec<(String, f64)>,
}
