//! Figures for slides: every panel of a column as a PNG, SVG or CSV, drawn on the CPU.
//!
//! The figures are drawn with the `plotters` crate (axes, ticks, labels, colour bars) on a
//! bitmap or into SVG text; nothing here computes: every function takes the plain data the
//! compute graph already produced ([`ColumnData`], filled from a column's node results) and a
//! [`FigureContext`] naming the scene, pattern, N, seed, signal and filter for titles,
//! metadata and file names. The GUI calls these functions on the UI thread with data it
//! already holds; `samplescope render` calls them headless (no window, no GPU).
//!
//! - **Sizes.** Each [`PanelKind`] has a base size ([`PanelKind::base_size`]); a figure at
//!   `scale` s is exactly s × base (text, lines, margins and markers scale too).
//!   `scale` must lie in [`SCALES`] (1..=4).
//! - **Text.** One font, Ubuntu Light (the font egui ships), registered with plotters from
//!   bytes: the same glyphs on every machine, no system font lookup.
//! - **Metadata.** PNGs carry tEXt chunks (iTXt for values that are not Latin-1) and SVGs a
//!   `<title>` and `<desc>`: the figure's title, scene, pattern and its parameters, N, seed,
//!   signal, filter, scale and `Software: samplescope <version>`. Never timings.
//! - **Determinism.** The same inputs give byte-identical PNG and SVG: no clocks, no hash
//!   ordering, nothing random.
//! - **The 1D sampling theorem.** The `theorem-*` kinds draw the column-independent
//!   [`TheoremView`] (computed for column 0 only, when the scene shows the theorem panel):
//!   the signal with its samples and reconstruction, the spectrum with the replicas, the
//!   filter and the Nyquist lines, and the reconstructed spectrum. Their titles say what is
//!   plotted, a caption line under the plot gives the pre- and post-aliasing terms, and their
//!   metadata holds the 1D signal, rate, filter and every error term instead of the 2D
//!   pattern, N and seed (which do not apply to them; nor do their file names carry them).
//! - **Images.** Periodograms and zone-plate images are drawn nearest-neighbour into the
//!   plotting area of the bitmap; in SVG they are embedded as PNG (`<image>` with a data URI,
//!   pixelated rendering), at the data's own resolution.

mod composite;
mod csv;
mod draw;
mod svg;
mod text;

use super::ExportError;
use crate::core::signal::theorem::TheoremView;
use crate::scene::graph::{
    ConvergencePoint, ErrorData, NodeKind, NodeResult, NodeValue, PointsData, ReconData,
    ReferenceData, ResponseData, SpectrumData,
};
use crate::scene::{ReconMode, Scene};
use std::collections::HashMap;
use std::sync::Arc;

pub use composite::{
    column_png, column_rgba, column_size, comparison_png, comparison_rgba, comparison_size,
};

/// The allowed figure scales (a figure at scale s is s × its base size).
pub const SCALES: std::ops::RangeInclusive<u32> = 1..=4;

/// Largest composite image, in pixels (a comparison of many columns at a high scale can ask
/// for more; it is refused with [`ExportError::TooLarge`] rather than allocated).
pub const MAX_COMPOSITE_PIXELS: u64 = 64 * 1024 * 1024;

/// One figure of a column.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum PanelKind {
    /// The points in the unit square.
    Pattern,
    /// The periodogram image (log10 P through a colour map) with a colour bar.
    Spectrum,
    /// The radially averaged power spectrum as a line plot.
    Raps,
    /// The reconstructed signal (grey, 0..1).
    Reconstruction,
    /// The reference image of the signal (grey, 0..1).
    Reference,
    /// |reconstruction − reference| (inferno, 0..max) with a colour bar.
    Error,
    /// The filter kernel h(x).
    Kernel,
    /// The filter's frequency response |H(ω)| with the Nyquist line and the ideal low-pass.
    Response,
    /// RMSE against samples per pixel (log–log).
    Convergence,
    /// The 1D sampling theorem: f(x), the samples f(nT) as stems and the reconstruction
    /// f_r(x).
    TheoremSignal,
    /// The 1D sampling theorem: |F(ω)|, the replicas F(ω − k f_s) (one colour per k), the
    /// filter's gain |G(ω)| and the Nyquist lines ±f_s/2, with a legend beside the plot.
    TheoremSpectrum,
    /// The 1D sampling theorem: the reconstructed spectrum |F_r(ω)| against |F(ω)|.
    TheoremReconstructed,
    /// The theorem panel's transform pair p(x) = g(a(x − s)) and its transform P(ω) side by
    /// side (|P|, Re P and Im P; the shah as impulses).
    TheoremPair,
}

impl PanelKind {
    /// Every kind, in the order `render` writes them.
    pub const ALL: [PanelKind; 13] = [
        PanelKind::Pattern,
        PanelKind::Spectrum,
        PanelKind::Raps,
        PanelKind::Reconstruction,
        PanelKind::Reference,
        PanelKind::Error,
        PanelKind::Kernel,
        PanelKind::Response,
        PanelKind::Convergence,
        PanelKind::TheoremSignal,
        PanelKind::TheoremSpectrum,
        PanelKind::TheoremReconstructed,
        PanelKind::TheoremPair,
    ];

    /// The figures of the 1D sampling-theorem panel.
    pub const THEOREM: [PanelKind; 4] = [
        PanelKind::TheoremSignal,
        PanelKind::TheoremSpectrum,
        PanelKind::TheoremReconstructed,
        PanelKind::TheoremPair,
    ];

    /// Whether this is a figure of the 1D sampling-theorem panel: its data does not depend
    /// on the column and exists for column 0 only.
    pub fn is_theorem(self) -> bool {
        PanelKind::THEOREM.contains(&self)
    }

    /// Name used in file names and metadata.
    pub fn name(self) -> &'static str {
        match self {
            PanelKind::Pattern => "pattern",
            PanelKind::Spectrum => "spectrum",
            PanelKind::Raps => "raps",
            PanelKind::Reconstruction => "reconstruction",
            PanelKind::Reference => "reference",
            PanelKind::Error => "error",
            PanelKind::Kernel => "kernel",
            PanelKind::Response => "response",
            PanelKind::Convergence => "convergence",
            PanelKind::TheoremSignal => "theorem-signal",
            PanelKind::TheoremSpectrum => "theorem-spectrum",
            PanelKind::TheoremReconstructed => "theorem-reconstructed",
            PanelKind::TheoremPair => "theorem-pair",
        }
    }

    /// Size at scale 1, in pixels (width, height). Every kind is 510 pixels high so that
    /// figures sit side by side in a composite; image and pattern plots are square. The
    /// theorem's spectrum is wider by its legend column.
    pub fn base_size(self) -> (u32, u32) {
        match self {
            PanelKind::Pattern | PanelKind::Reconstruction | PanelKind::Reference => (480, 510),
            PanelKind::Spectrum | PanelKind::Error => (590, 510),
            PanelKind::Raps
            | PanelKind::Kernel
            | PanelKind::Response
            | PanelKind::Convergence
            | PanelKind::TheoremSignal
            | PanelKind::TheoremReconstructed => (640, 510),
            PanelKind::TheoremSpectrum => (820, 510),
            PanelKind::TheoremPair => (1000, 510),
        }
    }

    /// The figures a scene computes, in [`PanelKind::ALL`] order (the theorem figures when
    /// the scene shows the theorem panel; they exist for column 0 only, see
    /// [`PanelKind::available_in`]).
    pub fn available(scene: &Scene) -> Vec<PanelKind> {
        let p = scene.panels;
        let fx = scene.effects;
        let recon = p.zoneplate && fx.reconstruction;
        PanelKind::ALL
            .into_iter()
            .filter(|k| match k {
                PanelKind::Pattern => p.pattern,
                PanelKind::Spectrum | PanelKind::Raps => p.spectrum,
                PanelKind::Reconstruction => recon,
                PanelKind::Reference | PanelKind::Error => recon && fx.error,
                PanelKind::Kernel | PanelKind::Response => p.filter,
                PanelKind::Convergence => p.cost && fx.convergence,
                PanelKind::TheoremSignal
                | PanelKind::TheoremSpectrum
                | PanelKind::TheoremReconstructed
                | PanelKind::TheoremPair => p.theorem,
            })
            .collect()
    }

    /// The figures column `column` of `scene` has: [`PanelKind::available`] without the
    /// theorem figures for every column but the first. What `render` writes for the column.
    pub fn available_in(scene: &Scene, column: usize) -> Vec<PanelKind> {
        let mut kinds = PanelKind::available(scene);
        kinds.retain(|k| column == 0 || !k.is_theorem());
        kinds
    }

    /// The figures of a column composite: one per visible panel as the GUI first shows it
    /// (pattern, periodogram, reconstruction, kernel and response), then the theorem's
    /// signal, spectrum and reconstructed spectrum (not the transform pair; column 0 only: see
    /// [`PanelKind::composite_in`]).
    pub fn composite(scene: &Scene) -> Vec<PanelKind> {
        let p = scene.panels;
        let mut out = Vec::new();
        if p.pattern {
            out.push(PanelKind::Pattern);
        }
        if p.spectrum {
            out.push(PanelKind::Spectrum);
        }
        if p.zoneplate && scene.effects.reconstruction {
            out.push(PanelKind::Reconstruction);
        }
        if p.filter {
            out.push(PanelKind::Kernel);
            out.push(PanelKind::Response);
        }
        if p.theorem {
            out.extend([
                PanelKind::TheoremSignal,
                PanelKind::TheoremSpectrum,
                PanelKind::TheoremReconstructed,
            ]);
        }
        out
    }

    /// The composite of column `column`: [`PanelKind::composite`] without the theorem
    /// figures for every column but the first.
    pub fn composite_in(scene: &Scene, column: usize) -> Vec<PanelKind> {
        let mut kinds = PanelKind::composite(scene);
        kinds.retain(|k| column == 0 || !k.is_theorem());
        kinds
    }

    /// The figures of the comparison (every column one row, the same figures in each): the
    /// composite figures every column has, so the theorem figures only when the scene has a
    /// single column.
    pub fn comparison(scene: &Scene) -> Vec<PanelKind> {
        let mut kinds = PanelKind::composite(scene);
        kinds.retain(|k| scene.columns.len() == 1 || !k.is_theorem());
        kinds
    }
}

/// Colour map of the periodogram figure.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum FigureColormap {
    /// matplotlib's viridis (perceptually uniform).
    #[default]
    Viridis,
    /// matplotlib's inferno (perceptually uniform, high contrast).
    Inferno,
    /// Grey ramp.
    Greys,
}

impl FigureColormap {
    /// The sRGB colour at t ∈ [0, 1] (clamped; NaN maps to 0).
    pub fn eval(self, t: f64) -> [u8; 3] {
        let t = if t.is_nan() { 0.0 } else { t.clamp(0.0, 1.0) };
        let c = match self {
            FigureColormap::Viridis => colorous::VIRIDIS.eval_continuous(t),
            FigureColormap::Inferno => colorous::INFERNO.eval_continuous(t),
            FigureColormap::Greys => {
                let g = (t * 255.0).round() as u8;
                colorous::Color { r: g, g, b: g }
            }
        };
        [c.r, c.g, c.b]
    }
}

/// What a figure says about where its data came from: titles, metadata and file names.
/// Build it with [`FigureContext::new`]; the display choices (`spectrum_range`,
/// `spectrum_colormap`, `response_db`) default to what the GUI first shows.
#[derive(Debug, Clone, PartialEq)]
pub struct FigureContext {
    /// The scene's title.
    pub scene_title: String,
    /// Short name of the scene for file names (e.g. its file stem `zone-plate-128-to-512`).
    pub scene_name: String,
    /// Index of the column in the scene.
    pub column: usize,
    /// The column's label (its pattern's name when it has none).
    pub column_title: String,
    /// File-name part naming the column: the pattern's name, then the label when it differs
    /// (sanitised), made unique within the scene.
    pub column_slug: String,
    /// The pattern's name (`imported` for a column showing points from a file).
    pub pattern: String,
    /// The pattern's parameters, `key=value` separated by spaces (for imported points the file
    /// name and whether the points were normalised).
    pub pattern_params: String,
    /// Number of points.
    pub n: usize,
    /// The column's seed.
    pub seed: u64,
    /// The test signal and its parameters (RON).
    pub signal: String,
    /// The reconstruction filter with its parameters and 2D mode (RON).
    pub filter: String,
    /// How the signal is sampled and the output size, e.g. `scattered, 512²`.
    pub recon: String,
    /// The periodogram's colour range in log10 P; `None` uses the data's own `auto_range`.
    pub spectrum_range: Option<(f32, f32)>,
    /// The periodogram's colour map.
    pub spectrum_colormap: FigureColormap,
    /// Plot |H| in dB instead of linear.
    pub response_db: bool,
    /// Draw the elementary intervals 2^k × 2^(m−k) (N = 2^m) under the points of the pattern
    /// figure with this k (the column's `elementary_k`; nothing is drawn when N is not a
    /// power of two; k above m is taken as m).
    pub elementary_k: Option<u32>,
}

impl FigureContext {
    /// The context of column `column` of `scene`; `scene_name` names the scene in file names
    /// (its file stem; the title is used when empty).
    pub fn new(scene: &Scene, column: usize, scene_name: &str) -> Result<Self, ExportError> {
        let col = scene
            .columns
            .get(column)
            .ok_or_else(|| ExportError::OutOfRange {
                field: "column",
                value: column as i64,
                min: 0,
                max: scene.columns.len() as i64 - 1,
            })?;
        let slugs = column_slugs(scene);
        let (pattern, pattern_params) = match &col.points {
            Some(p) => (
                IMPORTED.to_string(),
                format!("file={} normalize={}", p.label(), p.normalize),
            ),
            None => (
                col.pattern.name().to_string(),
                col.pattern
                    .specs()
                    .iter()
                    .filter_map(|s| col.pattern.get(s.name).map(|v| format!("{}={v}", s.name)))
                    .collect::<Vec<_>>()
                    .join(" "),
            ),
        };
        let recon = match scene.recon.mode {
            ReconMode::Scattered => "scattered".to_string(),
            ReconMode::Supersample { spp } => format!("supersample {spp} spp"),
            ReconMode::Resample { grid } => format!("resample {grid}² grid"),
        };
        let name = if scene_name.trim().is_empty() {
            &scene.title
        } else {
            scene_name
        };
        Ok(FigureContext {
            scene_title: scene.title.clone(),
            scene_name: sanitize(name),
            column,
            column_title: col.title(),
            column_slug: slugs[column].clone(),
            pattern,
            pattern_params,
            n: scene.n,
            seed: col.seed,
            signal: ron::to_string(&scene.signal).unwrap_or_else(|_| scene.signal.name().into()),
            filter: ron::to_string(&scene.filter)
                .unwrap_or_else(|_| scene.filter.filter.name().into()),
            recon: format!("{recon}, {}²", scene.recon.size),
            spectrum_range: None,
            spectrum_colormap: FigureColormap::Viridis,
            response_db: false,
            elementary_k: col.elementary_k,
        })
    }

    /// "label, N = n, seed s": the column as the titles name it.
    pub fn column_caption(&self) -> String {
        format!("{}, N = {}, seed {}", self.column_title, self.n, self.seed)
    }
}

/// What names the "pattern" of a column whose points were imported from a file.
const IMPORTED: &str = "imported";

/// Unique file-name parts for the columns of a scene.
fn column_slugs(scene: &Scene) -> Vec<String> {
    let base: Vec<String> = scene
        .columns
        .iter()
        .map(|c| {
            let name = sanitize(if c.points.is_some() {
                IMPORTED
            } else {
                c.pattern.name()
            });
            let label = sanitize(&c.title());
            if label == name {
                name
            } else {
                format!("{name}-{label}")
            }
        })
        .collect();
    base.iter()
        .enumerate()
        .map(|(i, s)| {
            if base.iter().filter(|t| *t == s).count() > 1 {
                format!("{s}-c{}", i + 1)
            } else {
                s.clone()
            }
        })
        .collect()
}

/// Lower-case ASCII letters and digits; every other run of characters becomes one `-`;
/// at most 48 characters; never empty.
pub fn sanitize(text: &str) -> String {
    let mut out = String::new();
    for c in text.chars() {
        if c.is_ascii_alphanumeric() {
            out.push(c.to_ascii_lowercase());
        } else if !out.ends_with('-') {
            out.push('-');
        }
    }
    let mut s = out.trim_matches('-').to_string();
    if s.len() > 48 {
        s.truncate(48);
        s = s.trim_end_matches('-').to_string();
    }
    if s.is_empty() {
        "untitled".into()
    } else {
        s
    }
}

/// The data of one column, as the compute graph produced it; `None` where a node was not
/// computed (hidden panel, effect off, still running or failed).
#[derive(Debug, Clone, Default)]
pub struct ColumnData {
    /// The points (pattern figure).
    pub points: Option<Arc<PointsData>>,
    /// The periodogram and its radial average (spectrum and RAPS figures).
    pub spectrum: Option<Arc<SpectrumData>>,
    /// The reconstructed signal.
    pub reconstruction: Option<Arc<ReconData>>,
    /// The signal's reference image.
    pub reference: Option<Arc<ReferenceData>>,
    /// |reconstruction − reference| with RMSE and PSNR.
    pub error: Option<Arc<ErrorData>>,
    /// The filter's kernel and frequency response.
    pub response: Option<Arc<ResponseData>>,
    /// RMSE against samples per pixel (its timings are never drawn).
    pub convergence: Option<Arc<Vec<ConvergencePoint>>>,
    /// The 1D sampling-theorem view (column 0 only, when the scene shows the theorem panel).
    pub theorem: Option<Arc<TheoremView>>,
}

impl ColumnData {
    /// Picks the successful node values out of a column's results (the GUI's
    /// `ColumnResults`, or what `Evaluator::evaluate` sent for the column).
    pub fn from_results<R: AsRef<NodeResult>>(results: &HashMap<NodeKind, R>) -> Self {
        let mut d = ColumnData::default();
        for r in results.values() {
            match &r.as_ref().value {
                Ok(NodeValue::Points(v)) => d.points = Some(v.clone()),
                Ok(NodeValue::Spectrum(v)) => d.spectrum = Some(v.clone()),
                Ok(NodeValue::Reconstruction(v)) => d.reconstruction = Some(v.clone()),
                Ok(NodeValue::Reference(v)) => d.reference = Some(v.clone()),
                Ok(NodeValue::Error(v)) => d.error = Some(v.clone()),
                Ok(NodeValue::Response(v)) => d.response = Some(v.clone()),
                Ok(NodeValue::Convergence(v)) => d.convergence = Some(v.clone()),
                Ok(NodeValue::Theorem(v)) => d.theorem = Some(v.clone()),
                // Values no figure draws (statistics, samples, …) and failed nodes.
                _ => {}
            }
        }
        d
    }

    /// Whether the data for `kind` is present.
    pub fn has(&self, kind: PanelKind) -> bool {
        match kind {
            PanelKind::Pattern => self.points.is_some(),
            PanelKind::Spectrum | PanelKind::Raps => self.spectrum.is_some(),
            PanelKind::Reconstruction => self.reconstruction.is_some(),
            PanelKind::Reference => self.reference.is_some(),
            PanelKind::Error => self.error.is_some(),
            PanelKind::Kernel | PanelKind::Response => self.response.is_some(),
            PanelKind::Convergence => self.convergence.is_some(),
            PanelKind::TheoremSignal
            | PanelKind::TheoremSpectrum
            | PanelKind::TheoremReconstructed
            | PanelKind::TheoremPair => self.theorem.is_some(),
        }
    }
}

/// Checks a figure scale against [`SCALES`].
pub fn check_scale(scale: u32) -> Result<(), ExportError> {
    if SCALES.contains(&scale) {
        Ok(())
    } else {
        Err(ExportError::OutOfRange {
            field: "scale",
            value: scale as i64,
            min: *SCALES.start() as i64,
            max: *SCALES.end() as i64,
        })
    }
}

/// An 8-bit RGB image, row 0 at the top.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Rgb {
    pub width: u32,
    pub height: u32,
    pub data: Vec<u8>,
}

/// The figure's title (also its `Title` metadata).
pub fn figure_title(kind: PanelKind, ctx: &FigureContext, data: &ColumnData) -> String {
    let cap = ctx.column_caption();
    match kind {
        PanelKind::Pattern => cap,
        PanelKind::Spectrum => format!("periodogram, {cap}"),
        PanelKind::Raps => format!("RAPS, {cap}"),
        PanelKind::Reconstruction => format!("reconstruction, {cap}"),
        PanelKind::Reference => "reference".to_string(),
        PanelKind::Error => match &data.error {
            Some(e) => format!("error, RMSE {:.4}, PSNR {:.2} dB", e.rmse, e.psnr),
            None => "error".to_string(),
        },
        PanelKind::Kernel => "kernel h(x)".to_string(),
        PanelKind::Response => "frequency response |H(ω)|".to_string(),
        PanelKind::Convergence => format!("RMSE vs samples per pixel, {}", ctx.column_title),
        PanelKind::TheoremPair => match &data.theorem {
            Some(v) => {
                let p = &v.settings.pair;
                format!(
                    "transform pair {}, scale a = {}, shift s = {}",
                    p.kind.name(),
                    p.scale,
                    p.shift
                )
            }
            None => "transform pair".to_string(),
        },
        PanelKind::TheoremSignal | PanelKind::TheoremSpectrum | PanelKind::TheoremReconstructed => {
            let what = match kind {
                PanelKind::TheoremSignal => "f(x), samples f(nT), reconstruction f_r(x)",
                PanelKind::TheoremSpectrum => "|F(ω)|, replicas F(ω − k·f_s), filter |G(ω)|",
                _ => "reconstructed spectrum |F_r(ω)| vs |F(ω)|",
            };
            match &data.theorem {
                Some(v) => format!("{what}: {}", theorem_setup(v)),
                None => what.to_string(),
            }
        }
    }
}

/// "signal (params), f_s = …, filter": the theorem view's settings in words.
fn theorem_setup(v: &TheoremView) -> String {
    let s = &v.settings;
    let params = s
        .signal
        .params()
        .iter()
        .map(|(n, x, _)| format!("{n} {x}"))
        .collect::<Vec<_>>()
        .join(", ");
    format!(
        "{} ({params}), f_s = {}, {} filter",
        s.signal.name(),
        s.rate,
        s.filter.name()
    )
}

/// The caption line under the theorem figures: the pre- and post-aliasing terms, absolute
/// and relative to the signal's energy (power, for periodic signals).
pub fn theorem_caption(v: &TheoremView) -> String {
    let e = &v.errors;
    let unit = if e.periodic { "power" } else { "energy" };
    format!(
        "pre-aliasing {:.3e} ({:.3} % of {unit}) · post-aliasing {:.3e} ({:.3} %) · Nyquist f_s/2 = {}",
        e.pre_aliasing,
        100.0 * e.relative(e.pre_aliasing),
        e.post_aliasing,
        100.0 * e.relative(e.post_aliasing),
        0.5 * v.settings.rate
    )
}

/// The theorem view's settings and error terms as metadata.
fn theorem_metadata(v: &TheoremView) -> Vec<(String, String)> {
    let s = &v.settings;
    let e = &v.errors;
    let unit = if e.periodic { "power" } else { "energy" };
    let term = |name: &str, x: f64| {
        (
            name.to_string(),
            format!("{x:e} ({} % of the signal's {unit})", 100.0 * e.relative(x)),
        )
    };
    vec![
        (
            "signal".into(),
            ron::to_string(&s.signal).unwrap_or_else(|_| s.signal.name().into()),
        ),
        (
            "sampling rate".into(),
            format!("{} samples per unit", s.rate),
        ),
        (
            "filter".into(),
            ron::to_string(&s.filter).unwrap_or_else(|_| s.filter.name().into()),
        ),
        ("extent".into(), format!("x in [-{0}, {0}]", s.extent)),
        (
            "transform pair".into(),
            format!(
                "{}, a = {}, s = {}",
                s.pair.kind.name(),
                s.pair.scale,
                s.pair.shift
            ),
        ),
        (format!("signal {unit}"), format!("{:e}", e.signal_energy)),
        term("pre-aliasing", e.pre_aliasing),
        term("post-aliasing", e.post_aliasing),
        term("smoothing", e.smoothing),
        term("lost above Nyquist", e.lost),
        term("total error", e.total),
        (
            "error band".into(),
            format!("|omega| <= {}, tail <= {:e}", e.band, e.tail_bound),
        ),
    ]
}

/// The metadata of a figure, in a fixed order: (keyword, value).
pub fn metadata(
    kind: PanelKind,
    ctx: &FigureContext,
    data: &ColumnData,
    scale: u32,
) -> Vec<(String, String)> {
    let mut m = vec![
        ("Title".to_string(), figure_title(kind, ctx, data)),
        (
            "Software".to_string(),
            format!("samplescope {}", env!("CARGO_PKG_VERSION")),
        ),
        ("figure".to_string(), kind.name().to_string()),
    ];
    if kind.is_theorem() {
        m.push(("scene".into(), ctx.scene_title.clone()));
        if let Some(v) = &data.theorem {
            m.extend(theorem_metadata(v));
        }
        m.push(("scale".into(), scale.to_string()));
        return m;
    }
    m.extend(context_metadata(ctx));
    if kind == PanelKind::Pattern {
        if let Some(grid) = data
            .points
            .as_ref()
            .and_then(|p| elementary_grid(ctx.elementary_k, p.points.len()))
        {
            m.push((
                "elementary intervals".into(),
                format!(
                    "k = {}: {}×{} boxes of 2^-{} × 2^-{}",
                    grid.0.trailing_zeros(),
                    grid.0,
                    grid.1,
                    grid.0.trailing_zeros(),
                    grid.1.trailing_zeros()
                ),
            ));
        }
    }
    if kind == PanelKind::Spectrum {
        if let Some(s) = &data.spectrum {
            let (lo, hi) = ctx.spectrum_range.unwrap_or(s.auto_range);
            m.push(("colour range".into(), format!("log10 P in [{lo}, {hi}]")));
        }
    }
    m.push(("scale".into(), scale.to_string()));
    m
}

/// The elementary-interval grid (columns, rows) = (2^k, 2^(m−k)) for `k` and `n` = 2^m
/// points (k above m taken as m); `None` without a k or when `n` is not a power of two.
pub(crate) fn elementary_grid(k: Option<u32>, n: usize) -> Option<(usize, usize)> {
    let k = k?;
    if !n.is_power_of_two() {
        return None;
    }
    let m = n.trailing_zeros();
    let k = k.min(m);
    Some((1usize << k, 1usize << (m - k)))
}

/// The scene, column, pattern, N, seed, signal and filter of a context as metadata.
fn context_metadata(ctx: &FigureContext) -> Vec<(String, String)> {
    vec![
        ("scene".into(), ctx.scene_title.clone()),
        ("column".into(), ctx.column_title.clone()),
        ("pattern".into(), ctx.pattern.clone()),
        ("pattern parameters".into(), ctx.pattern_params.clone()),
        ("N".into(), ctx.n.to_string()),
        ("seed".into(), ctx.seed.to_string()),
        ("signal".into(), ctx.signal.clone()),
        ("filter".into(), ctx.filter.clone()),
        ("reconstruction".into(), ctx.recon.clone()),
    ]
}

/// Draws `kind` into an RGB bitmap of exactly [`PanelKind::base_size`] × `scale`.
pub(crate) fn panel_rgb(
    kind: PanelKind,
    ctx: &FigureContext,
    data: &ColumnData,
    scale: u32,
) -> Result<Rgb, ExportError> {
    check_scale(scale)?;
    draw::render_bitmap(kind, ctx, data, scale)
}

/// The figure `kind` as PNG bytes (8-bit RGB, [`PanelKind::base_size`] × `scale`), with the
/// [`metadata`] as text chunks.
pub fn panel_png(
    kind: PanelKind,
    ctx: &FigureContext,
    data: &ColumnData,
    scale: u32,
) -> Result<Vec<u8>, ExportError> {
    let img = panel_rgb(kind, ctx, data, scale)?;
    encode_png(&img, &metadata(kind, ctx, data, scale))
}

/// The figure `kind` as (width, height, RGBA8 bytes, row 0 at the top), for the clipboard.
pub fn panel_rgba(
    kind: PanelKind,
    ctx: &FigureContext,
    data: &ColumnData,
    scale: u32,
) -> Result<(u32, u32, Vec<u8>), ExportError> {
    let img = panel_rgb(kind, ctx, data, scale)?;
    Ok((img.width, img.height, rgb_to_rgba(&img.data)))
}

/// The figure `kind` as SVG text ([`PanelKind::base_size`] × `scale` user units), with the
/// [`metadata`] as `<title>` and `<desc>`; images are embedded as PNG.
pub fn panel_svg(
    kind: PanelKind,
    ctx: &FigureContext,
    data: &ColumnData,
    scale: u32,
) -> Result<String, ExportError> {
    check_scale(scale)?;
    let (text, images) = draw::render_svg(kind, ctx, data, scale)?;
    svg::finish(text, &images, &metadata(kind, ctx, data, scale))
}

/// The data drawn by figure `kind` as CSV (round-trip precision):
///
/// | kind | columns |
/// |---|---|
/// | pattern | `x,y` |
/// | spectrum | `kx,ky,log10_power` (the displayed image: ky ascending, then kx; a masked DC holds the mean of its 8 neighbours) |
/// | raps | `radius,power` |
/// | reconstruction, reference, error | one image row per line, top row first, no header |
/// | kernel | `x,h` |
/// | response | `omega,magnitude` (|H(ω)|/|H(0)|, linear) |
/// | convergence | `spp,rmse` |
/// | theorem-signal | `series,x,value`: series `f` (the signal), `sample` (f(nT) at x = nT), `f_r` (the reconstruction) |
/// | theorem-spectrum | `series,omega,magnitude`: `F` (\|F\|), `replica_k` (\|F(ω − k f_s)\|, k = −3..3, k ≠ 0), `G` (\|G\|); line spectra: `line_k` (the lines of replica k, k = 0 the signal's) and `G` |
/// | theorem-reconstructed | `series,omega,magnitude`: `F` and `F_r`; line spectra: `F_line` and `F_r_line` |
/// | theorem-pair | `series,position,value`: `p` (x, p(x)), `abs_P`, `re_P`, `im_P` (ω, …); the shah: `impulse_x` (x, weight), `impulse_re`, `impulse_im` (ω, Re and Im of the weight) |
pub fn panel_csv(
    kind: PanelKind,
    _ctx: &FigureContext,
    data: &ColumnData,
) -> Result<String, ExportError> {
    csv::panel_csv(kind, data)
}

/// The file name of figure `kind` of a column:
/// `{scene}_{column}_n{N}_seed{S}_{kind}[@{scale}x][.{ext}]`, every part sanitised
/// (`scale` is given for PNG and SVG, `None` for CSV; an empty `ext` gives no extension).
/// The theorem figures, which depend on no column, are `{scene}_{kind}[@{scale}x][.{ext}]`.
pub fn panel_file_name(
    kind: PanelKind,
    ctx: &FigureContext,
    scale: Option<u32>,
    ext: &str,
) -> String {
    let s = scale.map(|s| format!("@{s}x")).unwrap_or_default();
    let ext = if ext.trim().is_empty() {
        String::new()
    } else {
        format!(".{}", sanitize(ext))
    };
    if kind.is_theorem() {
        return format!("{}_{}{s}{ext}", ctx.scene_name, kind.name());
    }
    format!(
        "{}_{}_n{}_seed{}_{}{s}{ext}",
        ctx.scene_name,
        ctx.column_slug,
        ctx.n,
        ctx.seed,
        kind.name(),
    )
}

/// The file name of a column composite: `{scene}_{column}_n{N}_seed{S}_column@{scale}x.png`.
pub fn column_file_name(ctx: &FigureContext, scale: u32) -> String {
    format!(
        "{}_{}_n{}_seed{}_column@{scale}x.png",
        ctx.scene_name, ctx.column_slug, ctx.n, ctx.seed
    )
}

/// The file name of the comparison of every column: `{scene}_n{N}_comparison@{scale}x.png`.
pub fn comparison_file_name(scene_name: &str, n: usize, scale: u32) -> String {
    format!("{}_n{n}_comparison@{scale}x.png", sanitize(scene_name))
}

fn rgb_to_rgba(rgb: &[u8]) -> Vec<u8> {
    let mut out = Vec::with_capacity(rgb.len() / 3 * 4);
    for p in rgb.chunks_exact(3) {
        out.extend_from_slice(&[p[0], p[1], p[2], 255]);
    }
    out
}

/// Whether `text` can be stored in a tEXt chunk (Latin-1, no NUL).
fn is_latin1(text: &str) -> bool {
    text.chars().all(|c| (c as u32) < 256 && c != '\0')
}

/// Encodes an RGB image as PNG with `text` as tEXt chunks (iTXt, UTF-8, for values that are
/// not Latin-1).
pub(crate) fn encode_png(img: &Rgb, text: &[(String, String)]) -> Result<Vec<u8>, ExportError> {
    let png_err = |e: &dyn std::fmt::Display| ExportError::Png {
        path: String::new(),
        message: e.to_string(),
    };
    let mut out = Vec::new();
    {
        let mut enc = png::Encoder::new(&mut out, img.width, img.height);
        enc.set_color(png::ColorType::Rgb);
        enc.set_depth(png::BitDepth::Eight);
        for (k, v) in text {
            if is_latin1(v) {
                enc.add_text_chunk(k.clone(), v.clone())
                    .map_err(|e| png_err(&e))?;
            } else {
                enc.add_itxt_chunk(k.clone(), v.clone())
                    .map_err(|e| png_err(&e))?;
            }
        }
        let mut w = enc.write_header().map_err(|e| png_err(&e))?;
        w.write_image_data(&img.data).map_err(|e| png_err(&e))?;
        w.finish().map_err(|e| png_err(&e))?;
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sanitize_keeps_ascii_alnum_and_collapses_the_rest() {
        assert_eq!(
            sanitize("Zone plate sampled at 128² → 512²"),
            "zone-plate-sampled-at-128-512"
        );
        assert_eq!(sanitize("  p1 = 11 "), "p1-11");
        assert_eq!(sanitize("²²"), "untitled");
        assert_eq!(sanitize(&"a".repeat(80)).len(), 48);
    }

    #[test]
    fn column_slugs_are_unique_within_a_scene() {
        let mut scene = Scene {
            columns: vec![Default::default(), Default::default()],
            ..Default::default()
        };
        scene.columns[1].label = "jitter".into();
        assert_eq!(column_slugs(&scene), vec!["jitter-c1", "jitter-c2"]);
        scene.columns[1].label = "p1 = 3".into();
        assert_eq!(column_slugs(&scene), vec!["jitter", "jitter-p1-3"]);
    }

    #[test]
    fn imported_columns_are_named_by_their_file() {
        let text = r#"(title: "x", n: 2, columns: [
            (points: Some((path: "", points: [(0.5, 0.5), (0.25, 0.75)]))),
            (pattern: (kind: "random")),
        ])"#;
        let scene = Scene::from_ron(text, "imported.ron").unwrap();
        let ctx = FigureContext::new(&scene, 0, "imp").unwrap();
        assert_eq!(ctx.pattern, "imported");
        assert_eq!(ctx.pattern_params, "file=inline points normalize=false");
        assert!(
            ctx.column_slug.starts_with("imported"),
            "{}",
            ctx.column_slug
        );
        assert_eq!(
            FigureContext::new(&scene, 1, "imp").unwrap().pattern,
            "random"
        );
    }

    #[test]
    fn scale_outside_the_range_names_the_field() {
        assert!(check_scale(1).is_ok() && check_scale(4).is_ok());
        let e = check_scale(0).unwrap_err().to_string();
        assert!(e.contains("scale = 0") && e.contains("1..=4"), "{e}");
        assert!(check_scale(9).is_err());
    }

    #[test]
    fn latin1_values_use_text_and_others_itxt() {
        assert!(is_latin1("128² points, seed 1"));
        assert!(!is_latin1("ω in cycles"));
        let img = Rgb {
            width: 1,
            height: 1,
            data: vec![1, 2, 3],
        };
        let bytes =
            encode_png(&img, &[("a".into(), "x²".into()), ("b".into(), "ω".into())]).unwrap();
        let reader = png::Decoder::new(std::io::Cursor::new(bytes))
            .read_info()
            .unwrap();
        let info = reader.info();
        assert!(info
            .uncompressed_latin1_text
            .iter()
            .any(|t| t.keyword == "a" && t.text == "x²"));
        assert!(info
            .utf8_text
            .iter()
            .any(|t| t.keyword == "b" && t.get_text().unwrap() == "ω"));
    }
}
