//! What a scene holds: its columns, shared settings and effects (serde types and defaults);
//! its visible panels ([`Panels`]) live with the panel table in `panels.rs`.

use super::{AnimationSettings, ImportedPoints, IntegrationSettings, Motion, Panels};
use crate::core::filter::Filter2D;
use crate::core::params::{declare_params, ParamKind, ParamSpec, ParamValue, Params};
use crate::core::pattern::Pattern;
use crate::core::signal::theorem::TheoremSettings;
use crate::core::signal::Signal;
use serde::{Deserialize, Serialize};

/// One column of a comparison: a pattern and its seed.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Column {
    /// The sample pattern with its parameters.
    pub pattern: Pattern,
    /// The seed of its random stream.
    pub seed: u64,
    /// Optional label shown above the column (default: the pattern's name).
    pub label: String,
    /// Points imported from a file (or inline) used instead of the pattern; see [`import`].
    pub points: Option<ImportedPoints>,
    /// Draw this column's elementary intervals b^k × b^(m−k) (base 2, N = 2^m) with this k,
    /// whatever the shared overlay setting; lets a scene show several interval shapes side by
    /// side. At most [`MAX_ELEMENTARY_K`].
    pub elementary_k: Option<u32>,
    /// Draw this column's strata (the grid its pattern stratifies: jitter's cells, N-rooks'
    /// and Latin hypercubes' N rows and columns) under its points in the pattern figure; only
    /// for stratified patterns (see `Pattern::strata`).
    pub strata: bool,
    /// How supersampling gives the pixels their samples (only with `recon.mode: Supersample`).
    pub pixels: PixelSampling,
    /// The dimension D of the column's points, in 2..=the pattern's `max_dims` (2 for the
    /// patterns defined in 2D only); the points are `Pattern::generate_cube`'s in [0,1)^D and
    /// every 2D panel shows their projection [`Column::project`]. Default 2 (left out when
    /// written): the 2D pattern, bit for bit.
    #[serde(skip_serializing_if = "is_default_dims")]
    pub dims: usize,
    /// The pair of dimensions (i, j), i ≠ j, both below `dims`, that the 2D panels show:
    /// point k is drawn at (x_i, x_j). Default (0, 1) (left out when written).
    #[serde(skip_serializing_if = "is_default_project")]
    pub project: (usize, usize),
}

/// A column's default dimension (the 2D pattern).
pub const DEFAULT_DIMS: usize = 2;
/// A column's default projection (the first two dimensions).
pub const DEFAULT_PROJECT: (usize, usize) = (0, 1);

fn is_default_dims(d: &usize) -> bool {
    *d == DEFAULT_DIMS
}

fn is_default_project(p: &(usize, usize)) -> bool {
    *p == DEFAULT_PROJECT
}

/// How a supersampling column draws each pixel's s samples.
///
/// In scene files: `pixels: per_pixel`, `pixels: image_plane(tile: 0)`, `pixels: zsobol`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum PixelSampling {
    /// Every pixel draws its own, independent copy of the pattern (seed derived from the pixel).
    #[default]
    PerPixel,
    /// One pattern of s·T² points over a toroidal tile of T×T pixels (T = 0: the whole image),
    /// repeated across the image; each pixel takes the points that fall in it (excess points of
    /// unstratified patterns move to the nearest underfull pixel; see
    /// [`crate::core::recon::image_plane`]).
    ImagePlane { tile: usize },
    /// Ahmed & Wonka's ZSobol (pbrt-v4): one Owen-scrambled Sobol' sequence over the pixels in
    /// Morton order with base-4 digit randomisation; the column's pattern is not used. spp must
    /// be a power of two.
    #[serde(rename = "zsobol")]
    ZSobol,
}

impl PixelSampling {
    /// Name shown in the GUI and in figure labels.
    pub fn name(self) -> &'static str {
        match self {
            PixelSampling::PerPixel => "per-pixel",
            PixelSampling::ImagePlane { .. } => "image-plane",
            PixelSampling::ZSobol => "zsobol",
        }
    }
}

impl Default for Column {
    fn default() -> Self {
        Column {
            pattern: Pattern::default(),
            seed: 1,
            label: String::new(),
            points: None,
            elementary_k: None,
            strata: false,
            pixels: PixelSampling::PerPixel,
            dims: DEFAULT_DIMS,
            project: DEFAULT_PROJECT,
        }
    }
}

impl Column {
    /// Whether the column shows the 2D pattern itself (dims 2, projection (0, 1)): its nodes
    /// are keyed and computed exactly as before dimensions existed.
    pub fn is_plain_2d(&self) -> bool {
        self.dims == DEFAULT_DIMS && self.project == DEFAULT_PROJECT
    }

    /// The 2D points the column's panels show for `n` points and `seed`: the pattern's 2D
    /// points when [`Column::is_plain_2d`], else [`Pattern::generate_projected`] (the
    /// projection `project` of its points in [0,1)^dims). Imported points are not generated.
    pub fn generate_2d(
        &self,
        n: usize,
        seed: u64,
        cancel: &crate::core::cancel::Cancel,
    ) -> Result<Vec<glam::DVec2>, crate::core::pattern::PatternError> {
        if self.is_plain_2d() {
            return self
                .pattern
                .generate_with(n, seed, cancel)?
                .require_all(self.pattern.name());
        }
        self.pattern
            .generate_projected(n, self.dims, self.project, seed, cancel)
    }

    /// The label shown above the column.
    pub fn title(&self) -> String {
        if self.label.is_empty() {
            match &self.points {
                Some(p) => format!("{} ({} points)", p.label(), p.points.len()),
                None => self.pattern.name().to_string(),
            }
        } else {
            self.label.clone()
        }
    }
}

/// How the signal is sampled and reconstructed.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum ReconMode {
    /// The column's N points sample the signal over the whole image; a filter scaled to the
    /// mean sample spacing 1/√N reconstructs it on the output grid.
    Scattered,
    /// `spp` samples per output pixel from the column's pattern, combined by the pixel filter.
    Supersample { spp: usize },
    /// The signal sampled on a uniform `grid`×`grid` lattice (the columns' patterns are not
    /// used) and resampled to the output size with the filter scaled to the grid spacing — the
    /// lecture's "sampled at 128×128 and reconstructed to 512×512 using windowed sinc".
    Resample { grid: usize },
}

/// The samples per pixel a new supersampling mode starts with (`spp`'s default).
pub const DEFAULT_SPP: usize = 16;
/// The resampling grid's default side (the lecture's 128×128).
pub const DEFAULT_GRID: usize = 128;

/// `recon.mode`'s parameters, declared once: `spp` of `Supersample`, `grid` of `Resample`
/// (`Scattered` has none). `Scene::validate` checks them and the GUI's control spans them.
const MODE_SPECS: [ParamSpec; 2] = [
    ParamSpec {
        name: "spp",
        doc: "samples per output pixel, each pixel's from the column's pattern",
        kind: ParamKind::Int {
            default: DEFAULT_SPP as i64,
            min: 1,
            max: 1024,
        },
    },
    ParamSpec {
        name: "grid",
        doc: "side of the uniform grid the signal is sampled on before resampling",
        kind: ParamKind::Int {
            default: DEFAULT_GRID as i64,
            min: 2,
            max: 4096,
        },
    },
];

impl Params for ReconMode {
    fn owner(&self) -> &'static str {
        "recon.mode"
    }

    fn specs(&self) -> Vec<ParamSpec> {
        let key = match self {
            ReconMode::Scattered => return Vec::new(),
            ReconMode::Supersample { .. } => "spp",
            ReconMode::Resample { .. } => "grid",
        };
        MODE_SPECS
            .iter()
            .filter(|s| s.name == key)
            .cloned()
            .collect()
    }

    fn get(&self, key: &str) -> Option<ParamValue> {
        match (self, key) {
            (ReconMode::Supersample { spp: v }, "spp")
            | (ReconMode::Resample { grid: v }, "grid") => {
                Some(ParamValue::Int(i64::try_from(*v).unwrap_or(i64::MAX)))
            }
            _ => None,
        }
    }

    fn put(&mut self, key: &str, value: ParamValue) {
        if let ParamValue::Int(x) = value {
            match (self, key) {
                (ReconMode::Supersample { spp: v }, "spp")
                | (ReconMode::Resample { grid: v }, "grid") => *v = x as usize,
                _ => {}
            }
        }
    }
}

declare_params! {
    /// Spectrum settings: every field is a parameter (descriptor: range, default, doc), so
    /// `Scene::validate` and the GUI's controls come from the declaration.
    SpectrumSettings = "spectrum", "the power spectrum of every column's points" {
        size: count(256, 8, 2048, "frequencies per side (M×M integer frequencies, DC in the middle)"),
        tolerance: float(1e-6, 1e-12, 1e-2, "NUFFT tolerance (relative ℓ2); ignored when exact"),
        exact: flag(false, "use the exact DFT instead of the NUFFT"),
        realizations: count(1, 1, 256, "number of realizations averaged (seeds derived from the column's seed)"),
        mask_dc: flag(true, "hide the DC peak P(0) = N"),
    }
}

/// The most dimensions the projection matrix shows (120 cells).
pub const MATRIX_MAX_DIMS: usize = 16;

declare_params! {
    /// The projection matrix's settings (used only while `panels.matrix` is on): every field
    /// is a parameter, so `Scene::validate` and the panel's controls come from the declaration.
    MatrixSettings = "matrix", "the projection matrix of every column" {
        dims: count(8, 2, MATRIX_MAX_DIMS, "K: the first K dimensions of each column, one cell per pair (at most the column's dims)"),
        measure: choice(crate::core::metrics::cube::ProjectionMeasure, "what tints each cell: t-value (base 2, N a power of two) | l2-star (discrepancy) | min-distance (toroidal)"),
    }
}

impl MatrixSettings {
    /// K for a column of `dims` dimensions: the setting, at most `dims`.
    pub fn shown(&self, dims: usize) -> usize {
        self.dims.min(dims)
    }

    fn is_default(&self) -> bool {
        *self == MatrixSettings::default()
    }
}

impl SpectrumSettings {
    /// The spectrum request these settings make for `n` points: the exact DFT or the NUFFT at
    /// `tolerance`, DC masked or shown, one realization for imported points (a file is one
    /// set), and an error check of two rows of the exact DFT (~2·N·M multiply-adds). The one
    /// place a [`SpectrumRequest`](crate::core::spectrum::SpectrumRequest) is made from
    /// settings: the spectrum node, its estimate and `analyze` use it.
    pub fn request(&self, n: usize, imported: bool) -> crate::core::spectrum::SpectrumRequest {
        use crate::core::spectrum::{DcMode, Method, SpectrumRequest};
        SpectrumRequest {
            size: self.size,
            method: if self.exact {
                Method::Exact
            } else {
                Method::Nufft {
                    tolerance: self.tolerance,
                }
            },
            realizations: if imported { 1 } else { self.realizations },
            dc: if self.mask_dc {
                DcMode::Mask
            } else {
                DcMode::Show
            },
            error_check_budget: 2 * (n as u64) * (self.size as u64),
        }
    }
}

/// Reconstruction settings.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct ReconSettings {
    /// How samples are taken (its `spp` and `grid` have descriptors, [`ReconMode`]'s
    /// [`Params`]).
    pub mode: ReconMode,
    /// Output image size W (W×W pixels); descriptor below.
    pub size: usize,
}

declare_params! {
    impl ReconSettings = "recon" {
        size: count(512, 16, 2048, "output image size W (W×W pixels)"),
    }
}

impl Default for ReconSettings {
    fn default() -> Self {
        ReconSettings {
            mode: ReconMode::Scattered,
            size: 512,
        }
    }
}

/// Which effects are simulated. An effect that is off costs nothing.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Effects {
    /// Sample the signal and reconstruct it (the zone plate panel's image).
    pub reconstruction: bool,
    /// Compute the reference image and the error against it.
    pub error: bool,
    /// Compute the convergence curve (RMSE vs samples per pixel) for the cost view.
    pub convergence: bool,
    /// Point-set statistics (minimum distance, discrepancy) for the pattern overlays.
    pub statistics: bool,
}

impl Default for Effects {
    fn default() -> Self {
        Effects {
            reconstruction: true,
            error: true,
            convergence: false,
            statistics: false,
        }
    }
}

/// A scene: what is shown and how it is computed.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Scene {
    pub title: String,
    /// What to look at (shown under the title).
    pub notes: String,
    pub columns: Vec<Column>,
    /// Number of points per column.
    pub n: usize,
    pub signal: Signal,
    pub filter: Filter2D,
    pub recon: ReconSettings,
    pub spectrum: SpectrumSettings,
    pub panels: Panels,
    pub effects: Effects,
    /// How the signal moves over time; `None` (the default) computes nothing per frame.
    pub motion: Option<Motion>,
    /// The 1D sampling-theorem view's settings (used only while `panels.theorem` is on).
    pub theorem: TheoremSettings,
    /// The integration-error study (used only while `panels.integration` is on).
    pub integration: IntegrationSettings,
    /// Show only the first k of every column's points (`Some(k)`, 1 ≤ k ≤ N; only when every
    /// column's points come in order): see `scene::animation`.
    pub prefix: Option<usize>,
    /// How the scene animates (motion or prefix): frames and rate of its player and GIF.
    pub animation: AnimationSettings,
    /// The projection matrix (used only while `panels.matrix` is on; left out when written
    /// as the default).
    #[serde(skip_serializing_if = "MatrixSettings::is_default")]
    pub matrix: MatrixSettings,
}

impl Default for Scene {
    fn default() -> Self {
        Scene {
            title: "untitled".into(),
            notes: String::new(),
            columns: vec![Column::default()],
            n: 4096,
            signal: Signal::default(),
            filter: Filter2D::default(),
            recon: ReconSettings::default(),
            spectrum: SpectrumSettings::default(),
            panels: Panels::default(),
            effects: Effects::default(),
            motion: None,
            theorem: TheoremSettings::default(),
            integration: IntegrationSettings::default(),
            prefix: None,
            animation: AnimationSettings::default(),
            matrix: MatrixSettings::default(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::params::Params;

    /// A setting's `Default` and its descriptors' defaults agree, and the defaults are valid.
    fn defaults_agree(p: &impl Params) {
        for spec in p.specs() {
            assert_eq!(
                p.get(spec.name),
                Some(spec.default_value()),
                "{}",
                spec.name
            );
        }
        p.check_params().unwrap();
    }

    #[test]
    fn every_setting_s_default_is_its_descriptors_default() {
        defaults_agree(&SpectrumSettings::default());
        defaults_agree(&ReconSettings::default());
        defaults_agree(&crate::scene::IntegrationSettings::default());
        defaults_agree(&TheoremSettings::default());
        defaults_agree(&MatrixSettings::default());
    }
}
