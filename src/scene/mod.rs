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
pub mod motion;
pub mod node;
pub mod panels;

pub use import::ImportedPoints;
pub use motion::Motion;

use crate::core::filter::Filter2D;
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
    /// The scene parsed but a value is out of range.
    #[error("{source_name}: {field} = {value}: must be {allowed}")]
    Invalid {
        source_name: String,
        field: String,
        value: String,
        allowed: String,
    },
    /// The file could not be read.
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

/// The largest scene file read (inline points included): 256 MiB.
pub const MAX_SCENE_BYTES: u64 = 256 << 20;

/// Reads UTF-8 text of at most `max` bytes from `reader`, block by block: the first block
/// holding a NUL byte or bytes that are not UTF-8 ends the read with the byte offset.
pub(crate) fn read_text_limited(
    mut reader: impl std::io::Read,
    max: u64,
) -> Result<String, String> {
    let mut bytes: Vec<u8> = Vec::new();
    let mut block = vec![0u8; 64 * 1024];
    // Bytes before `checked` are known to be UTF-8 (a character may span two blocks).
    let mut checked = 0usize;
    loop {
        let n = match reader.read(&mut block) {
            Ok(0) => break,
            Ok(n) => n,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(e.to_string()),
        };
        if bytes.len() as u64 + n as u64 > max {
            return Err(format!(
                "larger than {max} bytes: scene files are read up to that size"
            ));
        }
        if let Some(i) = block[..n].iter().position(|&b| b == 0) {
            return Err(format!(
                "byte {} is a NUL byte: not a scene file (RON text)",
                bytes.len() + i
            ));
        }
        bytes.extend_from_slice(&block[..n]);
        match std::str::from_utf8(&bytes[checked..]) {
            Ok(_) => checked = bytes.len(),
            Err(e) if e.error_len().is_none() => checked += e.valid_up_to(),
            Err(e) => {
                return Err(format!(
                    "byte {} is not UTF-8 text: not a scene file (RON text)",
                    checked + e.valid_up_to()
                ))
            }
        }
    }
    String::from_utf8(bytes).map_err(|e| {
        format!(
            "byte {} is not UTF-8 text: the file ends inside a character",
            e.utf8_error().valid_up_to()
        )
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
        let mut scene: Scene = ron::from_str(text).map_err(|e| SceneError::Parse {
            source_name: source_name.to_string(),
            line: e.span.start.line,
            column: e.span.start.col,
            message: e.code.to_string(),
        })?;
        scene.resolve_points(source_name, base_dir)?;
        scene.validate(source_name)?;
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
        let file = std::fs::File::open(path).map_err(|e| io(e.to_string()))?;
        let text = read_text_limited(file, MAX_SCENE_BYTES).map_err(io)?;
        Scene::from_ron_in(&text, &path.display().to_string(), path.parent())
    }

    /// The built-in default scene.
    pub fn builtin_default() -> Scene {
        Scene::from_ron(BUILTIN[0].1, BUILTIN[0].0).unwrap_or_default()
    }

    /// The scene as RON text.
    pub fn to_ron(&self) -> String {
        ron::ser::to_string_pretty(self, ron::ser::PrettyConfig::default()).unwrap_or_default()
    }

    /// Checks ranges that the types alone cannot express.
    pub fn validate(&self, source_name: &str) -> Result<(), SceneError> {
        let invalid = |field: &str, value: String, allowed: &str| SceneError::Invalid {
            source_name: source_name.to_string(),
            field: field.to_string(),
            value,
            allowed: allowed.to_string(),
        };
        if self.columns.is_empty() || self.columns.len() > MAX_COLUMNS {
            return Err(invalid(
                "columns",
                format!("{} columns", self.columns.len()),
                &format!("1..={MAX_COLUMNS} columns"),
            ));
        }
        for (i, c) in self.columns.iter().enumerate() {
            if let Some(k) = c.elementary_k {
                if k > MAX_ELEMENTARY_K {
                    return Err(invalid(
                        &format!("columns[{i}].elementary_k"),
                        k.to_string(),
                        &format!("an integer in 0..={MAX_ELEMENTARY_K}"),
                    ));
                }
            }
        }
        if self.n == 0 || self.n > MAX_SCENE_N {
            return Err(invalid(
                "n",
                self.n.to_string(),
                &format!("an integer in 1..={MAX_SCENE_N}"),
            ));
        }
        let s = &self.spectrum;
        if !(8..=2048).contains(&s.size) {
            return Err(invalid(
                "spectrum.size",
                s.size.to_string(),
                "an integer in 8..=2048",
            ));
        }
        if !(s.tolerance >= 1e-12 && s.tolerance <= 1e-2) {
            return Err(invalid(
                "spectrum.tolerance",
                format!("{:e}", s.tolerance),
                "a number in [1e-12, 1e-2]",
            ));
        }
        if !(1..=256).contains(&s.realizations) {
            return Err(invalid(
                "spectrum.realizations",
                s.realizations.to_string(),
                "an integer in 1..=256",
            ));
        }
        if !(16..=2048).contains(&self.recon.size) {
            return Err(invalid(
                "recon.size",
                self.recon.size.to_string(),
                "an integer in 16..=2048",
            ));
        }
        if let ReconMode::Resample { grid } = self.recon.mode {
            if !(2..=4096).contains(&grid) {
                return Err(invalid(
                    "recon.mode.grid",
                    grid.to_string(),
                    "an integer in 2..=4096",
                ));
            }
        }
        if let ReconMode::Supersample { spp } = self.recon.mode {
            if !(1..=1024).contains(&spp) {
                return Err(invalid(
                    "recon.mode.spp",
                    spp.to_string(),
                    "an integer in 1..=1024",
                ));
            }
        }
        match self.theorem.validate() {
            Err(TheoremError::InvalidParam {
                field,
                value,
                allowed,
            }) => return Err(invalid(&format!("theorem.{field}"), value, &allowed)),
            Err(TheoremError::Filter(e)) => {
                return Err(invalid(
                    "theorem.filter",
                    self.theorem.filter.name().to_string(),
                    &e.to_string(),
                ))
            }
            Ok(()) => {}
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
