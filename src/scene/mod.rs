//! Declarative scenes (RON files) and the compute graph they drive.
//!
//! A scene says what is shown: the columns (one sample pattern each, with its seed), the
//! shared settings (N, signal, filter, reconstruction, spectrum), the visible panels and the
//! effects that are on. The [`graph`] turns a scene into the list of nodes that the visible
//! panels need; nothing else is computed.

pub mod compute;
pub mod cost;
pub mod figure;
pub mod graph;
pub mod import;
pub mod integration;
pub mod motion;
pub mod node;
pub mod panels;
pub mod ron_path;

pub use import::ImportedPoints;
pub use integration::IntegrationSettings;
pub use motion::Motion;

use crate::core::filter::Filter2D;
use crate::core::params::{fmt_num, ParamError, Params};
use crate::core::pattern::Pattern;
use crate::core::signal::theorem::{TheoremError, TheoremSettings};
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

/// Largest per-column elementary-interval exponent k (2^24 strata per axis).
pub const MAX_ELEMENTARY_K: u32 = 24;

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
        }
    }
}

impl Column {
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

/// Spectrum settings.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct SpectrumSettings {
    /// Frequencies per side (M×M integer frequencies, DC in the middle).
    pub size: usize,
    /// NUFFT tolerance (relative ℓ2); ignored when `exact`.
    pub tolerance: f64,
    /// Use the exact DFT instead of the NUFFT.
    pub exact: bool,
    /// Number of realizations averaged (seeds derived from the column's seed).
    pub realizations: usize,
    /// Hide the DC peak P(0) = N.
    pub mask_dc: bool,
}

impl Default for SpectrumSettings {
    fn default() -> Self {
        SpectrumSettings {
            size: 256,
            tolerance: 1e-6,
            exact: false,
            realizations: 1,
            mask_dc: true,
        }
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
    /// How samples are taken.
    pub mode: ReconMode,
    /// Output image size W (W×W pixels).
    pub size: usize,
}

impl Default for ReconSettings {
    fn default() -> Self {
        ReconSettings {
            mode: ReconMode::Scattered,
            size: 512,
        }
    }
}

/// Which panels are visible.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Panels {
    pub pattern: bool,
    pub spectrum: bool,
    pub zoneplate: bool,
    pub filter: bool,
    /// The cost view (every node's time and error, and the convergence plot).
    pub cost: bool,
    /// The 1D sampling-theorem view (signal, replicas, filter, pre-/post-aliasing).
    pub theorem: bool,
    /// The integration-error study: MSE of the Monte Carlo estimate against N, every column
    /// on one log–log plot.
    pub integration: bool,
    /// The points wrapped onto the sphere (the lecture's cylinder wrap and radial projection).
    pub sphere: bool,
}

impl Default for Panels {
    fn default() -> Self {
        Panels {
            pattern: true,
            spectrum: true,
            zoneplate: true,
            filter: true,
            cost: false,
            theorem: false,
            integration: false,
            sphere: false,
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
        }
    }
}

/// Why a scene could not be loaded.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SceneError {
    /// The RON text is malformed or names an unknown field; `line`/`column` are 1-based.
    #[error("{source_name}:{line}:{column}: {message}")]
    Parse {
        source_name: String,
        line: usize,
        column: usize,
        message: String,
    },
    /// The scene parsed but a value is out of range; `location` is where the field (or the
    /// innermost part of its path that is written) stands in the text, when known.
    #[error("{source_name}{location}: {field} = {value}: must be {allowed}")]
    Invalid {
        source_name: String,
        location: Location,
        field: String,
        value: String,
        allowed: String,
    },
    /// The file is not there (or is a directory), or is not a scene's text: not UTF-8, a
    /// NUL byte, too large. Bad input, as a malformed scene is.
    #[error("{path}: {message}")]
    File { path: String, message: String },
    /// An existing file could not be read (permissions, a device error): the environment.
    #[error("{path}: {message}")]
    Io { path: String, message: String },
    /// A column's point file could not be read or holds a bad point (the error names the line).
    #[error("{source_name}: columns[{column}].points: {path}: {error}")]
    Points {
        source_name: String,
        column: usize,
        path: String,
        error: crate::core::pointset::PointsFileError,
    },
}

/// A 1-based line and column in a scene's text (displayed as `:line:column`, or nothing when
/// unknown, e.g. for a scene built in code).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Location(pub Option<(usize, usize)>);

impl std::fmt::Display for Location {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.0 {
            Some((line, column)) => write!(f, ":{line}:{column}"),
            None => Ok(()),
        }
    }
}

impl SceneError {
    /// Whether the environment is at fault (exit status 1: an existing file could not be
    /// read), rather than the input (status 2: a file that is not there, not text, malformed
    /// or out of range). A column's point file follows the same rule.
    pub fn is_environment(&self) -> bool {
        match self {
            SceneError::Io { .. } => true,
            SceneError::Points {
                error: crate::core::pointset::PointsFileError::Io { path, .. },
                ..
            } => std::fs::metadata(path).is_ok_and(|m| m.is_file()),
            _ => false,
        }
    }

    /// The error with the location of its field in `text` (for [`SceneError::Invalid`]).
    pub fn located_in(mut self, text: &str) -> Self {
        if let SceneError::Invalid {
            location, field, ..
        } = &mut self
        {
            *location = Location(ron_path::locate(text, field));
        }
        self
    }
}

/// The deepest nesting RON reads (its default recursion limit): deeper text is refused with
/// one line at the place it goes too deep.
pub const RON_NESTING: usize = 128;

/// The largest scene file read (inline points included): 256 MiB.
pub const MAX_SCENE_BYTES: u64 = 256 << 20;

/// Why [`read_text_limited`] failed.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum ReadTextError {
    /// Reading failed (the environment's fault).
    Io(String),
    /// The bytes are not a text file of the allowed size (the input's fault).
    NotText(String),
}

/// Reads UTF-8 text of at most `max` bytes from `reader`, block by block: the first block
/// holding a NUL byte or bytes that are not UTF-8 ends the read with the byte offset.
pub(crate) fn read_text_limited(
    mut reader: impl std::io::Read,
    max: u64,
) -> Result<String, ReadTextError> {
    use ReadTextError::{Io, NotText};
    let mut bytes: Vec<u8> = Vec::new();
    let mut block = vec![0u8; 64 * 1024];
    // Bytes before `checked` are known to be UTF-8 (a character may span two blocks).
    let mut checked = 0usize;
    loop {
        let n = match reader.read(&mut block) {
            Ok(0) => break,
            Ok(n) => n,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(Io(e.to_string())),
        };
        if bytes.len() as u64 + n as u64 > max {
            return Err(NotText(format!(
                "larger than {max} bytes: scene files are read up to that size"
            )));
        }
        if let Some(i) = block[..n].iter().position(|&b| b == 0) {
            return Err(NotText(format!(
                "byte {} is a NUL byte: not a scene file (RON text)",
                bytes.len() + i
            )));
        }
        bytes.extend_from_slice(&block[..n]);
        match std::str::from_utf8(&bytes[checked..]) {
            Ok(_) => checked = bytes.len(),
            Err(e) if e.error_len().is_none() => checked += e.valid_up_to(),
            Err(e) => {
                return Err(NotText(format!(
                    "byte {} is not UTF-8 text: not a scene file (RON text)",
                    checked + e.valid_up_to()
                )))
            }
        }
    }
    String::from_utf8(bytes).map_err(|e| {
        NotText(format!(
            "byte {} is not UTF-8 text: the file ends inside a character",
            e.utf8_error().valid_up_to()
        ))
    })
}

/// Scenes shipped with the app: (file name, RON text).
pub const BUILTIN: &[(&str, &str)] = &[
    (
        "default.ron",
        include_str!("../../assets/scenes/default.ron"),
    ),
    (
        "two-columns.ron",
        include_str!("../../assets/scenes/two-columns.ron"),
    ),
    (
        "frontier-blue-noise.ron",
        include_str!("../../assets/scenes/frontier-blue-noise.ron"),
    ),
    (
        "lattices-and-sequences.ron",
        include_str!("../../assets/scenes/lattices-and-sequences.ron"),
    ),
    (
        "image-plane-samplers.ron",
        include_str!("../../assets/scenes/image-plane-samplers.ron"),
    ),
    (
        "image-plane-samplers-4spp.ron",
        include_str!("../../assets/scenes/image-plane-samplers-4spp.ron"),
    ),
    (
        "integration-error-disk.ron",
        include_str!("../../assets/scenes/integration-error-disk.ron"),
    ),
    (
        "integration-error-gaussian.ron",
        include_str!("../../assets/scenes/integration-error-gaussian.ron"),
    ),
    (
        "sampling-theorem.ron",
        include_str!("../../assets/scenes/sampling-theorem.ron"),
    ),
    (
        "pre-aliasing-vs-post-aliasing.ron",
        include_str!("../../assets/scenes/pre-aliasing-vs-post-aliasing.ron"),
    ),
    (
        "best-candidate.ron",
        include_str!("../../assets/scenes/best-candidate.ron"),
    ),
    (
        "halton-vs-hammersley.ron",
        include_str!("../../assets/scenes/halton-vs-hammersley.ron"),
    ),
    (
        "hammersley-p1.ron",
        include_str!("../../assets/scenes/hammersley-p1.ron"),
    ),
    (
        "random-jitter-poisson.ron",
        include_str!("../../assets/scenes/random-jitter-poisson.ron"),
    ),
    (
        "ringing-at-a-step.ron",
        include_str!("../../assets/scenes/ringing-at-a-step.ron"),
    ),
    (
        "sobol-net.ron",
        include_str!("../../assets/scenes/sobol-net.ron"),
    ),
    (
        "uniform-vs-jittered-40x40.ron",
        include_str!("../../assets/scenes/uniform-vs-jittered-40x40.ron"),
    ),
    (
        "zone-plate-128-to-512.ron",
        include_str!("../../assets/scenes/zone-plate-128-to-512.ron"),
    ),
    (
        "motion-zone-plate-drift.ron",
        include_str!("../../assets/scenes/motion-zone-plate-drift.ron"),
    ),
    (
        "motion-zone-plate-rotate.ron",
        include_str!("../../assets/scenes/motion-zone-plate-rotate.ron"),
    ),
    (
        "motion-grating-strobe.ron",
        include_str!("../../assets/scenes/motion-grating-strobe.ron"),
    ),
    (
        "checkerboard-point-sampled.ron",
        include_str!("../../assets/scenes/checkerboard-point-sampled.ron"),
    ),
    (
        "checkerboard-supersampled-4x4.ron",
        include_str!("../../assets/scenes/checkerboard-supersampled-4x4.ron"),
    ),
    (
        "texture-1spp.ron",
        include_str!("../../assets/scenes/texture-1spp.ron"),
    ),
    (
        "texture-4spp.ron",
        include_str!("../../assets/scenes/texture-4spp.ron"),
    ),
    (
        "texture-256spp.ron",
        include_str!("../../assets/scenes/texture-256spp.ron"),
    ),
    (
        "random-vs-jittered.ron",
        include_str!("../../assets/scenes/random-vs-jittered.ron"),
    ),
    (
        "net-0-4-2-elementary-intervals.ron",
        include_str!("../../assets/scenes/net-0-4-2-elementary-intervals.ron"),
    ),
    (
        "nrooks-and-lhs.ron",
        include_str!("../../assets/scenes/nrooks-and-lhs.ron"),
    ),
    (
        "dart-throwing-step-by-step.ron",
        include_str!("../../assets/scenes/dart-throwing-step-by-step.ron"),
    ),
    (
        "kernel-box.ron",
        include_str!("../../assets/scenes/kernel-box.ron"),
    ),
    (
        "kernel-tent.ron",
        include_str!("../../assets/scenes/kernel-tent.ron"),
    ),
    (
        "kernel-gaussian.ron",
        include_str!("../../assets/scenes/kernel-gaussian.ron"),
    ),
    (
        "kernel-mitchell.ron",
        include_str!("../../assets/scenes/kernel-mitchell.ron"),
    ),
    (
        "kernel-lanczos.ron",
        include_str!("../../assets/scenes/kernel-lanczos.ron"),
    ),
    (
        "low-pass.ron",
        include_str!("../../assets/scenes/low-pass.ron"),
    ),
    (
        "band-pass.ron",
        include_str!("../../assets/scenes/band-pass.ron"),
    ),
    (
        "high-pass.ron",
        include_str!("../../assets/scenes/high-pass.ron"),
    ),
    (
        "derivative-cosc.ron",
        include_str!("../../assets/scenes/derivative-cosc.ron"),
    ),
    (
        "pre-aliasing.ron",
        include_str!("../../assets/scenes/pre-aliasing.ron"),
    ),
    (
        "post-aliasing.ron",
        include_str!("../../assets/scenes/post-aliasing.ron"),
    ),
];

impl Scene {
    /// Parses and validates a scene from RON text; `source_name` appears in errors. Point
    /// files named by columns are read relative to the current directory.
    pub fn from_ron(text: &str, source_name: &str) -> Result<Scene, SceneError> {
        Scene::from_ron_in(text, source_name, None)
    }

    /// As [`Scene::from_ron`], reading the columns' point files relative to `base_dir`.
    pub fn from_ron_in(
        text: &str,
        source_name: &str,
        base_dir: Option<&std::path::Path>,
    ) -> Result<Scene, SceneError> {
        // A byte-order mark (as some Windows editors write) is not part of the text.
        let text = text.strip_prefix('\u{feff}').unwrap_or(text);
        let mut scene: Scene = ron::from_str(text).map_err(|e| SceneError::Parse {
            source_name: source_name.to_string(),
            line: e.span.start.line,
            column: e.span.start.col,
            message: match e.code {
                ron::Error::ExceededRecursionLimit => format!(
                    "nested more than {RON_NESTING} levels deep: a scene nests a few levels \
                     (scene, columns, pattern); look for brackets that are never closed"
                ),
                // RON writes names with dashes as raw identifiers (`r#n-rooks`); show them as
                // they are written in a scene.
                code => code.to_string().replace("`r#", "`"),
            },
        })?;
        for (ci, col) in scene.columns.iter().enumerate() {
            if let Some(imp) = col.points.as_ref().filter(|p| !p.path.is_empty()) {
                if !imp.points.is_empty() {
                    let err = SceneError::Invalid {
                        source_name: source_name.to_string(),
                        location: Location::default(),
                        field: format!("columns[{ci}].points"),
                        value: format!(
                            "path {:?} and {} inline points",
                            imp.path,
                            imp.points.len()
                        ),
                        allowed:
                            "either a `path` (read when the scene loads) or inline `points` (with \
                                  `source` naming where they came from), not both"
                                .into(),
                    };
                    return Err(err.located_in(text));
                }
            }
        }
        scene.resolve_points(source_name, base_dir)?;
        scene
            .validate(source_name)
            .map_err(|e| e.located_in(text))?;
        Ok(scene)
    }

    /// Reads every column's point file that is not loaded yet (see [`ImportedPoints::resolve`]).
    pub fn resolve_points(
        &mut self,
        source_name: &str,
        base_dir: Option<&std::path::Path>,
    ) -> Result<(), SceneError> {
        for (ci, col) in self.columns.iter_mut().enumerate() {
            if let Some(imp) = &mut col.points {
                imp.resolve(base_dir).map_err(|error| SceneError::Points {
                    source_name: source_name.to_string(),
                    column: ci,
                    path: imp.path.clone(),
                    error,
                })?;
            }
        }
        Ok(())
    }

    /// The scene at time `t` seconds: the signal moved by [`Scene::motion`] (see [`motion`]),
    /// everything else unchanged (the points and their spectrum do not depend on the signal,
    /// so the compute graph reuses them). A scene without motion, or t = 0, is returned as is.
    pub fn at_time(&self, t: f64) -> Result<Scene, SceneError> {
        let mut out = self.clone();
        if let Some(m) = &self.motion {
            out.signal = motion::signal_at(&self.signal, m, t).map_err(|e| {
                let (field, value, allowed) = match &e {
                    motion::MotionError::InvalidParam {
                        field,
                        value,
                        allowed,
                    } => (field.to_string(), value.to_string(), allowed.clone()),
                    motion::MotionError::Unsupported { signal } => (
                        "motion".to_string(),
                        signal.to_string(),
                        "used with a zone-plate, grating or step-edge signal".to_string(),
                    ),
                };
                SceneError::Invalid {
                    source_name: self.title.clone(),
                    location: Location::default(),
                    field,
                    value,
                    allowed,
                }
            })?;
        }
        Ok(out)
    }

    /// Reads a scene file: at most [`MAX_SCENE_BYTES`], UTF-8 text without NUL bytes, checked
    /// as it is read, so a binary or endless file (`/dev/zero`, `/dev/urandom`) is refused
    /// after its first block.
    pub fn load(path: &std::path::Path) -> Result<Scene, SceneError> {
        let io = |message: String| SceneError::Io {
            path: path.display().to_string(),
            message,
        };
        let bad = |message: String| SceneError::File {
            path: path.display().to_string(),
            message,
        };
        let file = std::fs::File::open(path).map_err(|e| {
            use std::io::ErrorKind as K;
            match e.kind() {
                K::NotFound | K::NotADirectory | K::IsADirectory | K::InvalidFilename => {
                    bad(e.to_string())
                }
                _ => io(e.to_string()),
            }
        })?;
        if file.metadata().is_ok_and(|m| m.is_dir()) {
            return Err(bad("is a directory, not a scene file".into()));
        }
        let text = read_text_limited(file, MAX_SCENE_BYTES).map_err(|e| match e {
            ReadTextError::Io(m) => io(m),
            ReadTextError::NotText(m) => bad(m),
        })?;
        Scene::from_ron_in(&text, &path.display().to_string(), path.parent())
    }

    /// The built-in default scene.
    pub fn builtin_default() -> Scene {
        Scene::from_ron(BUILTIN[0].1, BUILTIN[0].0).unwrap_or_default()
    }

    /// The scene as RON text.
    /// Imported points are written inline (with their file as `source`), so the saved scene
    /// does not depend on the point file and loads as it was.
    pub fn to_ron(&self) -> String {
        let mut scene = self.clone();
        for col in &mut scene.columns {
            if let Some(imp) = &mut col.points {
                *imp = imp.inline();
            }
        }
        ron::ser::to_string_pretty(&scene, ron::ser::PrettyConfig::default()).unwrap_or_default()
    }

    /// Checks every value against its documented range ([`limits`]) and every parameter of
    /// every pattern, signal and filter against its descriptor; the error names the field path
    /// (`columns[1].pattern.cols`, `signal.k`, `filter.filter.sigma`, `recon.mode.spp`).
    pub fn validate(&self, source_name: &str) -> Result<(), SceneError> {
        let invalid = |field: &str, value: String, allowed: &str| SceneError::Invalid {
            source_name: source_name.to_string(),
            location: Location::default(),
            field: field.to_string(),
            value,
            allowed: allowed.to_string(),
        };
        let param = |prefix: &str, e: ParamError| match e {
            ParamError::Invalid {
                field,
                value,
                allowed,
                ..
            } => invalid(&format!("{prefix}.{field}"), value, &allowed),
            ParamError::Unknown { key, allowed, .. } => invalid(
                &format!("{prefix}.{key}"),
                "(set)".into(),
                &format!("one of the parameters [{allowed}]"),
            ),
        };
        fn int_range<T: PartialOrd + std::fmt::Display + Copy>(
            v: T,
            r: &std::ops::RangeInclusive<T>,
        ) -> Option<String> {
            (!r.contains(&v)).then(|| format!("an integer in {}..={}", r.start(), r.end()))
        }
        // Free text first: its length bounds the work of laying it out and the metadata of
        // every figure that carries it.
        let text_len = |field: &str, text: &str, max: usize| {
            let len = text.chars().count();
            if len > max {
                Err(invalid(
                    field,
                    format!("{len} characters"),
                    &format!("at most {max} characters"),
                ))
            } else {
                Ok(())
            }
        };
        text_len("title", &self.title, limits::TITLE_CHARS)?;
        text_len("notes", &self.notes, limits::NOTES_CHARS)?;
        for (i, c) in self.columns.iter().enumerate() {
            text_len(
                &format!("columns[{i}].label"),
                &c.label,
                limits::LABEL_CHARS,
            )?;
            if let Some(imp) = &c.points {
                text_len(
                    &format!("columns[{i}].points.path"),
                    &imp.path,
                    limits::PATH_CHARS,
                )?;
                text_len(
                    &format!("columns[{i}].points.source"),
                    &imp.source,
                    limits::PATH_CHARS,
                )?;
            }
        }
        let ncols = self.columns.len();
        if !limits::COLUMNS.contains(&ncols) {
            return Err(invalid(
                "columns",
                format!("{ncols} columns"),
                &format!(
                    "{}..={} columns",
                    limits::COLUMNS.start(),
                    limits::COLUMNS.end()
                ),
            ));
        }
        if let Some(allowed) = int_range(self.n, &limits::N) {
            return Err(invalid("n", self.n.to_string(), &allowed));
        }
        for (i, c) in self.columns.iter().enumerate() {
            if c.points.is_none() {
                c.pattern
                    .check_params()
                    .map_err(|e| param(&format!("columns[{i}].pattern"), e))?;
            }
            if c.strata && (c.points.is_some() || c.pattern.strata(self.n).is_none()) {
                return Err(invalid(
                    &format!("columns[{i}].strata"),
                    "true".into(),
                    &format!(
                        "false: {} has no strata for N = {} (stratified patterns: grid, jitter, \
                         multijitter, cmj with a column count dividing N; nrooks; lhs)",
                        if c.points.is_some() {
                            "imported points"
                        } else {
                            c.pattern.name()
                        },
                        self.n
                    ),
                ));
            }
            if let Some(k) = c.elementary_k {
                let field = format!("columns[{i}].elementary_k");
                if let Some(allowed) = int_range(k, &limits::ELEMENTARY_K) {
                    return Err(invalid(&field, format!("Some({k})"), &allowed));
                }
                let n = c.points.as_ref().map_or(self.n, |p| p.points.len());
                if c.points.as_ref().is_none_or(|p| !p.points.is_empty()) {
                    if !n.is_power_of_two() {
                        return Err(invalid(
                            &field,
                            format!("Some({k})"),
                            &format!("None: elementary intervals need N = 2^m points, and N = {n}"),
                        ));
                    }
                    let m = n.trailing_zeros();
                    if k > m {
                        return Err(invalid(
                            &field,
                            format!("Some({k})"),
                            &format!("an integer in 0..={m} (N = {n} = 2^{m})"),
                        ));
                    }
                }
            }
        }
        for (i, c) in self.columns.iter().enumerate() {
            let field = format!("columns[{i}].pixels");
            match (c.pixels, self.recon.mode) {
                (PixelSampling::PerPixel, _) => {}
                (_, ReconMode::Scattered | ReconMode::Resample { .. }) => {
                    return Err(invalid(
                        &field,
                        c.pixels.name().into(),
                        "per-pixel: image-plane and zsobol apply only to recon.mode: Supersample",
                    ))
                }
                (PixelSampling::ImagePlane { tile }, ReconMode::Supersample { spp }) => {
                    if tile > self.recon.size {
                        return Err(invalid(
                            &format!("{field}.tile"),
                            tile.to_string(),
                            &format!(
                                "0 (the whole image) or a tile side in 1..={}",
                                self.recon.size
                            ),
                        ));
                    }
                    let t = if tile == 0 { self.recon.size } else { tile };
                    if spp.saturating_mul(t * t) > crate::core::pattern::MAX_N {
                        return Err(invalid(
                            &format!("{field}.tile"),
                            tile.to_string(),
                            &format!(
                                "a tile with spp·T² ≤ {} points (spp = {spp})",
                                crate::core::pattern::MAX_N
                            ),
                        ));
                    }
                }
                (PixelSampling::ZSobol, ReconMode::Supersample { spp }) => {
                    if !spp.is_power_of_two() {
                        return Err(invalid(
                            "recon.mode.spp",
                            spp.to_string(),
                            &format!("a power of two with columns[{i}].pixels: zsobol"),
                        ));
                    }
                }
            }
        }
        self.signal.check_params().map_err(|e| param("signal", e))?;
        self.filter
            .filter
            .check_params()
            .map_err(|e| param("filter.filter", e))?;
        if let Err(e) = self.filter.validate() {
            return Err(invalid(
                "filter.mode",
                format!("{:?}", self.filter.mode).to_lowercase(),
                &e.to_string(),
            ));
        }
        let reconstructs = (self.panels.zoneplate && self.effects.reconstruction)
            || (self.panels.cost && self.effects.convergence);
        if reconstructs && self.filter.reconstruction_refusal().is_some() {
            return Err(invalid(
                "filter.filter",
                self.filter.filter.name().to_string(),
                "a filter that passes constants (H(0) ≠ 0: not band-pass, high-pass or cosc, nor a setting that makes H(0) vanish) while effects.reconstruction or effects.convergence is on; turn those off to show the kernel alone",
            ));
        }
        let s = &self.spectrum;
        if let Some(allowed) = int_range(s.size, &limits::SPECTRUM_SIZE) {
            return Err(invalid("spectrum.size", s.size.to_string(), &allowed));
        }
        if !limits::TOLERANCE.contains(&s.tolerance) {
            return Err(invalid(
                "spectrum.tolerance",
                fmt_num(s.tolerance),
                &format!(
                    "a number in [{}, {}]",
                    fmt_num(*limits::TOLERANCE.start()),
                    fmt_num(*limits::TOLERANCE.end())
                ),
            ));
        }
        if let Some(allowed) = int_range(s.realizations, &limits::REALIZATIONS) {
            return Err(invalid(
                "spectrum.realizations",
                s.realizations.to_string(),
                &allowed,
            ));
        }
        if let Some(allowed) = int_range(self.recon.size, &limits::RECON_SIZE) {
            return Err(invalid("recon.size", self.recon.size.to_string(), &allowed));
        }
        if let ReconMode::Resample { grid } = self.recon.mode {
            if let Some(allowed) = int_range(grid, &limits::GRID) {
                return Err(invalid("recon.mode.grid", grid.to_string(), &allowed));
            }
        }
        if let ReconMode::Supersample { spp } = self.recon.mode {
            if let Some(allowed) = int_range(spp, &limits::SPP) {
                return Err(invalid("recon.mode.spp", spp.to_string(), &allowed));
            }
        }
        self.theorem
            .signal
            .check_params()
            .map_err(|e| param("theorem.signal", e))?;
        self.theorem
            .filter
            .check_params()
            .map_err(|e| param("theorem.filter", e))?;
        match self.theorem.validate() {
            Err(TheoremError::InvalidParam {
                field,
                value,
                allowed,
            }) => return Err(invalid(&format!("theorem.{field}"), value, &allowed)),
            Err(TheoremError::Param(e)) => return Err(param("theorem", e)),
            Err(TheoremError::Filter(e)) => {
                return Err(invalid(
                    "theorem.filter",
                    self.theorem.filter.name().to_string(),
                    &e.to_string(),
                ))
            }
            Ok(()) => {}
        }
        self.integration
            .integrand
            .check_params()
            .map_err(|e| param("integration.integrand", e))?;
        if let Some((field, value, allowed)) = self.integration.check() {
            return Err(invalid(&format!("integration.{field}"), value, &allowed));
        }
        if let Some(m) = &self.motion {
            match m.validate() {
                Err(motion::MotionError::InvalidParam {
                    field,
                    value,
                    allowed,
                }) => return Err(invalid(field, value.to_string(), &allowed)),
                Err(motion::MotionError::Unsupported { signal }) => {
                    return Err(invalid(
                        "motion",
                        signal.to_string(),
                        "used with a zone-plate, grating or step-edge signal",
                    ))
                }
                Ok(()) => {}
            }
            if let Err(motion::MotionError::Unsupported { signal }) =
                Motion::check_signal(&self.signal)
            {
                return Err(invalid(
                    "motion",
                    format!("Some(..) with a {signal} signal"),
                    "None, or a zone-plate, grating or step-edge signal",
                ));
            }
        }
        for (ci, col) in self.columns.iter().enumerate() {
            if let Some(imp) = &col.points {
                let field = format!("columns[{ci}].points.points");
                if imp.points.is_empty() {
                    return Err(invalid(
                        &field,
                        "no points".into(),
                        "at least one point (or a `path` to a point file)",
                    ));
                }
                if imp.points.len() > MAX_SCENE_N {
                    return Err(invalid(
                        &field,
                        format!("{} points", imp.points.len()),
                        &format!("at most {MAX_SCENE_N} points"),
                    ));
                }
                if let Some(j) = imp.first_outside() {
                    let [x, y] = imp.points[j];
                    return Err(invalid(
                        &format!("{field}[{j}]"),
                        format!("({x}, {y})"),
                        "inside [0,1)² (or set `normalize: true`)",
                    ));
                }
            }
        }
        Ok(())
    }
}

/// Most columns a scene may have.
pub const MAX_COLUMNS: usize = 8;
/// Most points per column in a scene (interactive use).
pub const MAX_SCENE_N: usize = 1 << 20;

/// The documented range of every scene value that is not a pattern, signal or filter
/// parameter (those have their own descriptors). [`Scene::validate`] enforces them and the
/// GUI's widgets span exactly them, so no widget can clamp a value a scene file may hold.
pub mod limits {
    use std::ops::RangeInclusive;

    /// Points per column (`n`).
    pub const N: RangeInclusive<usize> = 1..=super::MAX_SCENE_N;
    /// Number of columns.
    pub const COLUMNS: RangeInclusive<usize> = 1..=super::MAX_COLUMNS;
    /// A column's elementary-interval exponent k (further bounded by N = 2^m: k ≤ m).
    pub const ELEMENTARY_K: RangeInclusive<u32> = 0..=super::MAX_ELEMENTARY_K;
    /// Side of the spectrum image (`spectrum.size`).
    pub const SPECTRUM_SIZE: RangeInclusive<usize> = 8..=2048;
    /// Relative tolerance of the fast spectrum (`spectrum.tolerance`).
    pub const TOLERANCE: RangeInclusive<f64> = 1e-12..=1e-2;
    /// Pattern realizations averaged into the spectrum (`spectrum.realizations`).
    pub const REALIZATIONS: RangeInclusive<usize> = 1..=256;
    /// Side of the reconstruction (`recon.size`).
    pub const RECON_SIZE: RangeInclusive<usize> = 16..=2048;
    /// Resampling grid (`recon.mode: Resample(grid: …)`).
    pub const GRID: RangeInclusive<usize> = 2..=4096;
    /// Samples per pixel (`recon.mode: Supersample(spp: …)`).
    pub const SPP: RangeInclusive<usize> = 1..=1024;
    /// Characters of the scene's `title` (drawn above the comparison, in every figure's
    /// metadata).
    pub const TITLE_CHARS: usize = 256;
    /// Characters of the scene's `notes`.
    pub const NOTES_CHARS: usize = 4096;
    /// Characters of a column's `label`.
    pub const LABEL_CHARS: usize = 128;
    /// Characters of an imported point file's `path` and `source`.
    pub const PATH_CHARS: usize = 4096;
}
