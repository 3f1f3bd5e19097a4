//! Float images for display.

use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;

static VERSION: AtomicU64 = AtomicU64::new(1);

/// A fresh version number for display uploads.
pub fn next_version() -> u64 {
    VERSION.fetch_add(1, Ordering::Relaxed)
}

/// A float image for display, row 0 at the top.
#[derive(Debug, Clone)]
pub struct ImageData {
    pub width: usize,
    pub height: usize,
    pub values: Arc<Vec<f32>>,
    /// Changes whenever the values change (GPU uploads happen only then).
    pub version: u64,
}

impl ImageData {
    /// An image from row-major values (row 0 at the top).
    pub fn new(width: usize, height: usize, values: Vec<f32>) -> Self {
        ImageData {
            width,
            height,
            values: Arc::new(values),
            version: next_version(),
        }
    }

    /// From an image stored with row 0 at the bottom (y up), flipping rows.
    pub fn from_y_up(width: usize, height: usize, values: impl Fn(usize) -> f32) -> Self {
        let mut v = Vec::with_capacity(width * height);
        for row in (0..height).rev() {
            for col in 0..width {
                v.push(values(row * width + col));
            }
        }
        ImageData::new(width, height, v)
    }
}
