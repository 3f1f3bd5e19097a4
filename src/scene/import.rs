//! Points imported from other tools, shown in a column instead of a generated pattern.
//!
//! A column with `points: Some(…)` takes its points from a file (any format
//! [`crate::core::pointset`] reads: CSV or whitespace-separated text with an optional header
//! or count line, pmj-cpp's `(x, y),` rows, NumPy `.npy`, PSA's `.rps`) or from the scene itself (inline). The file is read once, when
//! the scene is loaded ([`ImportedPoints::resolve`]); from then on the points are part of the
//! scene, so the compute graph never touches the file system and a saved scene keeps them.
//!
//! ## What an imported column computes
//! - **Points**: exactly the imported points (their count replaces the scene's N); the node's
//!   key is a hash of the points' bits, so equal files share one evaluation.
//! - **Spectrum**: the imported set is a single realization, so the periodogram of that column
//!   is computed with K = 1 whatever the scene's K (other columns keep theirs), and the panel's
//!   accuracy line says so. We chose this over an error because K is a scene-wide setting and a
//!   comparison of a file against averaged patterns is a normal thing to want.
//! - **Scattered reconstruction**: uses the points like any pattern's.
//! - **Supersampling** and the **convergence curve** need a pattern that generates new samples
//!   for every pixel and every spp: those nodes fail with a message naming the column.

use crate::core::pattern::ONE_MINUS_EPSILON;
use crate::core::pointset::{
    normalize_to_bounding_box, read_points_file, OutOfRange, PointsFileError,
};
use glam::DVec2;
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};

/// Points for a column, read from `path` or given inline.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct ImportedPoints {
    /// The point file; a relative path is relative to the scene file's directory. Empty for
    /// inline points (then only `points` counts).
    pub path: String,
    /// Map the set's bounding box onto [0,1)² (aspect kept) instead of rejecting points outside.
    pub normalize: bool,
    /// The points (x, y) in [0,1)²: filled from `path` when the scene is loaded, or inline.
    /// A scene file gives either `path` or inline `points`, never both.
    pub points: Vec<[f64; 2]>,
    /// Where inline points came from (a file name), shown as the column's label; never read.
    /// A scene saved from the GUI keeps its imported points inline, with their file here.
    pub source: String,
}

impl ImportedPoints {
    /// Reads `path` (a point file) into an import, normalising when asked.
    pub fn from_file(path: &Path, normalize: bool) -> Result<ImportedPoints, PointsFileError> {
        let mode = if normalize {
            OutOfRange::NormalizeToBoundingBox
        } else {
            OutOfRange::Reject
        };
        let pts = read_points_file(path, mode)?;
        Ok(ImportedPoints {
            path: path.display().to_string(),
            normalize,
            points: pts.iter().map(|p| [p.x, p.y]).collect(),
            source: String::new(),
        })
    }

    /// Fills `points` from `path` when they are not there yet (a hand-written scene names only
    /// the file), resolving a relative path against `base_dir`; then, for inline points with
    /// `normalize`, maps them into [0,1)². Points already present are kept as they are.
    pub fn resolve(&mut self, base_dir: Option<&Path>) -> Result<(), PointsFileError> {
        if self.points.is_empty() && !self.path.is_empty() {
            let p = PathBuf::from(&self.path);
            let full = match base_dir {
                Some(dir) if p.is_relative() => dir.join(&p),
                _ => p,
            };
            let loaded = ImportedPoints::from_file(&full, self.normalize)?;
            self.points = loaded.points;
        } else if self.normalize && self.first_outside().is_some() {
            let raw: Vec<DVec2> = self.to_dvec();
            if raw.iter().all(|p| p.is_finite()) {
                self.points = normalize_to_bounding_box(&raw)?
                    .iter()
                    .map(|p| [p.x, p.y])
                    .collect();
            }
        }
        Ok(())
    }

    /// The index of the first point outside [0,1)² (or not finite), if any.
    pub fn first_outside(&self) -> Option<usize> {
        self.points.iter().position(|&[x, y]| {
            !((0.0..=ONE_MINUS_EPSILON).contains(&x) && (0.0..=ONE_MINUS_EPSILON).contains(&y))
        })
    }

    /// The points as `DVec2`.
    pub fn to_dvec(&self) -> Vec<DVec2> {
        self.points.iter().map(|&[x, y]| DVec2::new(x, y)).collect()
    }

    /// BLAKE3 digest of the points' count and bits, as 64 hex digits (the key of the points
    /// node: stable across runs and platforms).
    pub fn content_digest(&self) -> String {
        let mut h = blake3::Hasher::new();
        h.update(&(self.points.len() as u64).to_le_bytes());
        for &[x, y] in &self.points {
            h.update(&x.to_bits().to_le_bytes());
            h.update(&y.to_bits().to_le_bytes());
        }
        h.finalize().to_hex().to_string()
    }

    /// The import as a scene file holds it: inline points, their file (if any) as `source`.
    pub fn inline(&self) -> ImportedPoints {
        let mut out = self.clone();
        if !out.path.is_empty() {
            out.source = std::mem::take(&mut out.path);
        }
        out
    }

    /// A short label: the file name (of `path`, else of `source`), or "inline points".
    pub fn label(&self) -> String {
        let file = if self.path.is_empty() {
            &self.source
        } else {
            &self.path
        };
        Path::new(file)
            .file_name()
            .map(|f| f.to_string_lossy().into_owned())
            .unwrap_or_else(|| "inline points".into())
    }
}
