//! Figures for slides: every panel of a column as a PNG, SVG, PDF or CSV, drawn on the CPU.
//!
//! Each figure is laid out once, with the `plotters` crate (axes, ticks, labels, colour bars),
//! into a vector drawing (`canvas.rs` records it, `drawing.rs` holds it); the PNG is that
//! drawing rasterised antialiased by tiny-skia, the SVG and the PDF (`pdf.rs`) are written from
//! the same shapes, so the three are one picture. Nothing here computes: every function takes the plain data the
//! compute graph already produced ([`ColumnData`], filled from a column's node results by
//! `scene::figure::column_data`) and a [`FigureContext`] naming the scene, pattern, N, seed,
//! signal and filter for titles, metadata and file names (`scene::figure::context`). This
//! module reads [`crate::model`] only, never the scene. The GUI calls these functions on a
//! background thread with data it already holds; `samplescope render` calls them headless (no
//! window, no GPU).
//!
//! - **One figure per file.** Each [`FigureKind`] has one [`Figure`] (`pattern.rs`,
//!   `spectrum.rs`, … `theorem_pair.rs`): its base size, title, data check, drawing, CSV and
//!   metadata. [`figure`] is expanded from the panel list. The frame around every figure (white
//!   page, title band) and the shared helpers (axes, text, legends, images with
//!   colour bars) are in `draw.rs`; the shared CSV writers in `csv.rs`.
//! - **Sizes.** Each figure has a base size ([`Figure::base_size`]); a figure at `scale` s is
//!   exactly s × base (text, lines, margins and markers scale too). `scale` must lie in
//!   [`SCALES`] (1..=4). Every figure is 510 pixels high so that figures sit side by side in
//!   a composite; image and pattern plots are square.
//! - **Antialiasing.** Curves, stems, markers and text are antialiased; one-pixel axis lines
//!   and ticks lie on pixel centres and stay crisp (see `canvas.rs`).
//! - **Text.** One font, Ubuntu Light (the font egui ships), from bytes: the same glyphs on
//!   every machine, no system font lookup. The PNG fills the glyph outlines, the SVG carries
//!   the same outlines (no viewer needs the font), the PDF embeds the font (searchable text).
//!   `f_s`, `F_r`, `Φ_p1`, `N^s`, `10^-3` are laid out as sub- and superscripts (smaller glyphs
//!   off the baseline; the rule in `drawing.rs` leaves words like `per_pixel` literal).
//! - **PNG.** The drawing is rasterised in bands of 64 rows on worker threads while the
//!   calling thread encodes the finished bands in order (Sub filter, fdeflate); markers drawn
//!   many times are composited from one antialiased coverage stamp per radius, colour and
//!   quarter-pixel phase.
//! - **Metadata.** PNGs carry tEXt chunks (iTXt for values that are not Latin-1), SVGs a
//!   `<title>` and `<desc>`, PDFs their document information (Title, Subject): the figure's
//!   title, scene, pattern and its parameters, N, seed, signal, filter, scale and
//!   `Software: samplescope <version>`. Never timings.
//! - **Determinism.** The same inputs give byte-identical PNG, SVG and PDF: no clocks, no
//!   hash ordering, nothing random.
//! - **The 1D sampling theorem.** The `theorem-*` kinds draw the column-independent
//!   [`TheoremView`](crate::model::TheoremView) (computed for column 0 only, when the scene
//!   shows the theorem panel): the signal with its samples and reconstruction, the spectrum
//!   with the replicas, the filter and the Nyquist lines, and the reconstructed spectrum. Their
//!   titles say what is plotted, a caption line under the plot gives the pre- and
//!   post-aliasing terms, and their metadata holds the 1D signal, rate, filter and every error
//!   term instead of the 2D pattern, N and seed (which do not apply to them; nor do their file
//!   names carry them).
//! - **Images.** Periodograms and zone-plate images are kept at the data's own resolution and
//!   shown nearest-neighbour over the plotting area: resampled into the PNG's pixels, embedded
//!   in the SVG as PNG (`<image>` with a data URI, pixelated rendering) and in the PDF as an
//!   uninterpolated image.
//!
//! **Adding a figure** for data a column already has: a file here implementing [`Figure`] with
//! its `mod` line below, and its entry in its panel's entry of the panel list
//! (`scene::panels::panel_list!`: its name, when it is shown, whether a composite holds it,
//! and this file's type), from which [`FigureKind`] and [`figure`] are expanded; a test checks
//! that every kind's figure says it is that kind.

mod canvas;
mod composite;
mod convergence;
mod csv;
mod draw;
mod drawing;
mod error;
mod integration;
mod kernel;
mod matrix;
mod pattern;
mod pdf;
mod raps;
mod reconstruction;
mod reference;
mod response;
mod spectrum;
mod sphere;
mod theorem;
mod theorem_pair;
mod theorem_reconstructed;
mod theorem_signal;
mod theorem_spectrum;

use super::ExportError;
use crate::model::{sanitize, ColumnData, FigureContext, FigureKind};

pub use canvas::{Area, Canvas, CanvasError};
pub use composite::{
    column_file, column_layout, column_png, column_rgba, column_size, comparison_file,
    comparison_layout, comparison_png, comparison_rgba, comparison_size, comparison_title_lines,
    fill, text_width, wrap, Aspect, AspectError, Layout,
};
pub use draw::Frame;
pub use integration::legend_label as integration_legend;
pub use pdf::PT_PER_PX;
pub use theorem::theorem_caption;

/// The allowed figure scales (a figure at scale s is s × its base size).
pub const SCALES: std::ops::RangeInclusive<u32> = 1..=4;

/// Largest composite image, in pixels (a comparison of many columns at a high scale can ask
/// for more; it is refused with [`ExportError::TooLarge`] rather than allocated).
pub const MAX_COMPOSITE_PIXELS: u64 = 64 * 1024 * 1024;

/// One figure: everything that differs between the panels' figures. The frame around it
/// (page, title band, scale, the PNG/SVG/PDF writers, metadata header, file names) is common.
pub trait Figure: Sync {
    /// The panel it draws.
    fn kind(&self) -> FigureKind;

    /// Size at scale 1, in pixels (width, height).
    fn base_size(&self) -> (u32, u32);

    /// The title (also the `Title` metadata).
    fn title(&self, ctx: &FigureContext, data: &ColumnData) -> String;

    /// The title as a panel of a composite, whose block caption already names the column (or
    /// the theorem's setup): what the figure plots, without repeating the caption. By default
    /// the title.
    fn panel_title(&self, ctx: &FigureContext, data: &ColumnData) -> String {
        self.title(ctx, data)
    }

    /// Whether the data it draws was computed (it may still be empty: see [`Figure::check`]).
    fn has_data(&self, data: &ColumnData) -> bool;

    /// Refuses missing or empty data before anything is drawn.
    fn check(&self, data: &ColumnData) -> Result<(), ExportError>;

    /// Draws everything under the title band into `body`; [`Figure::check`] has passed.
    fn draw(&self, frame: &mut Frame<'_, '_>, body: &Area<'_>) -> Result<(), ExportError>;

    /// The data it draws as CSV (see [`panel_csv`] for the columns of each figure).
    fn csv(&self, data: &ColumnData) -> Result<String, ExportError>;

    /// Its metadata after `Title`, `Software` and `figure` and before `scale`: by default the
    /// scene, column, pattern, N, seed, signal, filter and reconstruction of the context.
    fn metadata(&self, ctx: &FigureContext, _data: &ColumnData) -> Vec<(String, String)> {
        context_metadata(ctx)
    }
}

/// Expands the panel list into [`figure`]: each kind's drawing type, named by the list
/// relative to this module (its file is `figure/<module>.rs`, declared above).
macro_rules! figure_registry {
    (
        figures: $figures:tt
        draw: [$($kind:ident $module:ident :: $ty:ident;)*]
        $($rest:tt)*
    ) => {
        /// The figure of `kind` (its `draw` type in the panel list).
        pub fn figure(kind: FigureKind) -> &'static dyn Figure {
            match kind {
                $(FigureKind::$kind => &$module::$ty,)*
            }
        }
    };
}

crate::scene::panels::panel_list!(figure_registry);

/// Size of figure `kind` at scale 1, in pixels (width, height).
pub fn base_size(kind: FigureKind) -> (u32, u32) {
    figure(kind).base_size()
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
pub fn figure_title(kind: FigureKind, ctx: &FigureContext, data: &ColumnData) -> String {
    figure(kind).title(ctx, data)
}

/// The metadata of a figure, in a fixed order: (keyword, value).
pub fn metadata(
    kind: FigureKind,
    ctx: &FigureContext,
    data: &ColumnData,
    scale: u32,
) -> Vec<(String, String)> {
    let f = figure(kind);
    let mut m = vec![
        ("Title".to_string(), f.title(ctx, data)),
        (
            "Software".to_string(),
            format!("samplescope {}", env!("CARGO_PKG_VERSION")),
        ),
        ("figure".to_string(), kind.name().to_string()),
    ];
    m.extend(f.metadata(ctx, data));
    m.push(("scale".into(), scale.to_string()));
    m
}

/// The scene, column, pattern, N, seed, signal and filter of a context as metadata.
fn context_metadata(ctx: &FigureContext) -> Vec<(String, String)> {
    let mut m = vec![
        ("scene".into(), ctx.scene_title.clone()),
        ("column".into(), ctx.column_title.clone()),
        ("pattern".into(), ctx.pattern.clone()),
        ("pattern parameters".into(), ctx.pattern_params.clone()),
        ("N".into(), ctx.n.to_string()),
        ("seed".into(), ctx.seed.to_string()),
        ("signal".into(), ctx.signal.clone()),
        ("filter".into(), ctx.filter.clone()),
        ("reconstruction".into(), ctx.recon.clone()),
    ];
    if let Some((i, j, d)) = ctx.projection {
        m.insert(
            5,
            (
                "projection".into(),
                format!("x{i} × x{j} of {d} dimensions"),
            ),
        );
    }
    m
}

/// A file format of the figures.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum FileFormat {
    /// 8-bit RGB PNG with text chunks.
    Png,
    /// SVG 1.1 text, glyphs as outlines, images as embedded PNG.
    Svg,
    /// PDF 1.7, one page, the font embedded.
    Pdf,
}

impl FileFormat {
    /// The file name extension (also the format's name on the command line).
    pub fn ext(self) -> &'static str {
        match self {
            FileFormat::Png => "png",
            FileFormat::Svg => "svg",
            FileFormat::Pdf => "pdf",
        }
    }
}

/// Lays out `kind` at its base size × `scale` into its vector drawing.
fn panel_drawing(
    kind: FigureKind,
    ctx: &FigureContext,
    data: &ColumnData,
    scale: u32,
) -> Result<drawing::Drawing, ExportError> {
    check_scale(scale)?;
    draw::render_drawing(figure(kind), ctx, data, scale, draw::Role::Alone)
}

/// A drawing in `format`, with `meta` as its metadata.
fn encode(
    d: &drawing::Drawing,
    format: FileFormat,
    meta: &[(String, String)],
) -> Result<Vec<u8>, ExportError> {
    match format {
        FileFormat::Png => d.png(meta),
        FileFormat::Svg => Ok(d.svg(meta)?.into_bytes()),
        FileFormat::Pdf => pdf::write(d, meta),
    }
}

/// The figure `kind` (its base size × `scale`) as a file in `format`, with the [`metadata`]:
/// PNG text chunks, SVG `<title>` and `<desc>`, PDF document information.
pub fn panel_file(
    kind: FigureKind,
    ctx: &FigureContext,
    data: &ColumnData,
    scale: u32,
    format: FileFormat,
) -> Result<Vec<u8>, ExportError> {
    let d = panel_drawing(kind, ctx, data, scale)?;
    encode(&d, format, &metadata(kind, ctx, data, scale))
}

/// The figure `kind` as PNG bytes (8-bit RGB, its base size × `scale`), with the
/// [`metadata`] as text chunks.
pub fn panel_png(
    kind: FigureKind,
    ctx: &FigureContext,
    data: &ColumnData,
    scale: u32,
) -> Result<Vec<u8>, ExportError> {
    panel_file(kind, ctx, data, scale, FileFormat::Png)
}

/// The figure `kind` as SVG text (its base size × `scale` user units), with the [`metadata`]
/// as `<title>` and `<desc>`; images are embedded as PNG.
pub fn panel_svg(
    kind: FigureKind,
    ctx: &FigureContext,
    data: &ColumnData,
    scale: u32,
) -> Result<String, ExportError> {
    let d = panel_drawing(kind, ctx, data, scale)?;
    d.svg(&metadata(kind, ctx, data, scale))
}

/// The figure `kind` as a one-page PDF (its base size × `scale` pixels at [`PT_PER_PX`]),
/// with the [`metadata`] as document information.
pub fn panel_pdf(
    kind: FigureKind,
    ctx: &FigureContext,
    data: &ColumnData,
    scale: u32,
) -> Result<Vec<u8>, ExportError> {
    panel_file(kind, ctx, data, scale, FileFormat::Pdf)
}

/// The figure `kind` as (width, height, RGBA8 bytes, row 0 at the top), for the clipboard.
pub fn panel_rgba(
    kind: FigureKind,
    ctx: &FigureContext,
    data: &ColumnData,
    scale: u32,
) -> Result<(u32, u32, Vec<u8>), ExportError> {
    let img = panel_drawing(kind, ctx, data, scale)?.raster()?;
    Ok((img.width, img.height, rgb_to_rgba(&img.data)))
}

/// The data drawn by figure `kind` as CSV (round-trip precision):
///
/// | kind | columns |
/// |---|---|
/// | pattern | `x,y` |
/// | sphere | `x,y,z` (the points on the unit sphere, as `points --sphere` writes them) |
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
/// | matrix | `i,j,t_value,l2_star_discrepancy,min_distance` (the pair table of the first K dimensions, pairs in order; empty where a value is missing) |
pub fn panel_csv(
    kind: FigureKind,
    _ctx: &FigureContext,
    data: &ColumnData,
) -> Result<String, ExportError> {
    figure(kind).csv(data)
}

/// The file name of figure `kind` of a column:
/// `{scene}_{column}_n{N}_seed{S}_{kind}[@{scale}x][.{ext}]`, every part sanitised
/// (`scale` is given for PNG, SVG and PDF, `None` for CSV; an empty `ext` gives no extension).
/// The theorem figures, which depend on no column, are `{scene}_{kind}[@{scale}x][.{ext}]`.
pub fn panel_file_name(
    kind: FigureKind,
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

/// The file name of a column composite:
/// `{scene}_{column}_n{N}_seed{S}_column@{scale}x.{ext}`.
pub fn column_file_name(ctx: &FigureContext, scale: u32, format: FileFormat) -> String {
    format!(
        "{}_{}_n{}_seed{}_column@{scale}x.{}",
        ctx.scene_name,
        ctx.column_slug,
        ctx.n,
        ctx.seed,
        format.ext()
    )
}

/// The file name of the comparison of every column:
/// `{scene}_n{N}_comparison@{scale}x.{ext}`.
pub fn comparison_file_name(scene_name: &str, n: usize, scale: u32, format: FileFormat) -> String {
    format!(
        "{}_n{n}_comparison@{scale}x.{}",
        sanitize(scene_name),
        format.ext()
    )
}

fn rgb_to_rgba(rgb: &[u8]) -> Vec<u8> {
    let mut out = Vec::with_capacity(rgb.len() / 3 * 4);
    for p in rgb.chunks_exact(3) {
        out.extend_from_slice(&[p[0], p[1], p[2], 255]);
    }
    out
}

/// Encodes an RGB image as PNG with `text` as tEXt chunks (iTXt for values that are not
/// Latin-1).
fn encode_png(img: &Rgb, text: &[(String, String)]) -> Result<Vec<u8>, ExportError> {
    super::encode::png_rgb(img.width, img.height, &img.data, text)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scale_outside_the_range_names_the_field() {
        assert!(check_scale(1).is_ok() && check_scale(4).is_ok());
        let e = check_scale(0).unwrap_err().to_string();
        assert!(e.contains("scale = 0") && e.contains("1..=4"), "{e}");
        assert!(check_scale(9).is_err());
    }

    #[test]
    fn every_kind_has_its_own_figure() {
        for kind in FigureKind::ALL {
            assert_eq!(figure(kind).kind(), kind);
            let (_, h) = base_size(kind);
            assert_eq!(h, 510, "{kind:?}: figures sit side by side in a composite");
        }
    }
}
