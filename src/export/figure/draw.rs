//! Drawing of each figure with plotters, onto a bitmap or into SVG text.
//!
//! Layout at scale 1 (every length is multiplied by the scale): a title band of
//! [`TITLE_H`] pixels, then a chart with [`MARGIN`] on every side, [`Y_LABEL`] pixels for the
//! y tick labels and description and [`X_LABEL`] pixels for the x ones. With the base sizes of
//! [`PanelKind::base_size`] the plotting area of the pattern and image figures is a
//! 400 × 400 square and that of the line plots 560 × 400. The theorem figures keep a
//! [`CAPTION_LINE`] band under the chart for the aliasing numbers, and the theorem's spectrum
//! a [`LEGEND_PART`] column right of it for its legend (nine entries would hide the curves).

use super::text::CrispText;
use super::{
    elementary_grid, figure_title, theorem_caption, ColumnData, FigureColormap, FigureContext,
    PanelKind, Rgb,
};
use crate::core::signal::theorem::TheoremView;
use crate::export::ExportError;
use crate::scene::graph::ImageData;
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use std::ops::Range;
use std::sync::OnceLock;

/// The font family every text uses (registered from bytes, see [`ensure_font`]).
const FONT: &str = "sans-serif";
/// Height of the title band.
const TITLE_H: u32 = 40;
/// Margin around a chart.
const MARGIN: u32 = 10;
/// Width of the y label area.
const Y_LABEL: u32 = 60;
/// Height of the x label area.
const X_LABEL: u32 = 50;
/// Width of the colour-bar part of the periodogram and error figures.
const BAR_PART: u32 = 110;
/// Title, tick-label and axis-description font sizes.
const TITLE_PX: f64 = 17.0;
const TICK_PX: f64 = 13.0;
const DESC_PX: f64 = 15.0;

/// Line colour of the data (matplotlib's first colour).
const DATA: RGBColor = RGBColor(31, 119, 180);
/// Reference lines (white noise, ideal low-pass, zero).
const GUIDE: RGBColor = RGBColor(150, 150, 150);
/// The Nyquist line.
const NYQUIST: RGBColor = RGBColor(200, 60, 60);
/// The points of a pattern.
const INK: RGBColor = RGBColor(20, 20, 30);
/// The elementary-interval grid under the points (the GUI's overlay colour).
const INTERVALS: RGBColor = RGBColor(120, 160, 220);
/// The reconstruction f_r and its spectrum (the theorem panel's colour).
const RECON: RGBColor = RGBColor(230, 120, 20);
/// The replicas k = −3..=3 of the theorem's spectrum (k = 0, the signal, is drawn in [`INK`]);
/// the theorem panel's colours.
const REPLICA_COLOURS: [RGBColor; 7] = [
    RGBColor(148, 103, 189),
    RGBColor(44, 160, 44),
    RGBColor(255, 127, 14),
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(23, 190, 207),
    RGBColor(188, 189, 34),
];
/// Height of the caption line under the theorem figures' charts.
const CAPTION_LINE: u32 = 26;
/// Width of the legend column of the theorem's spectrum figure.
const LEGEND_PART: u32 = 180;
/// Sample markers are drawn up to this many samples (beyond, the stems alone: the markers
/// would merge into a band).
const MAX_MARKERS: usize = 400;

/// An image placed in an SVG figure: `image` shown over the pixel rectangle (x, y, w, h).
pub(crate) struct SvgImage {
    pub x: i32,
    pub y: i32,
    pub width: u32,
    pub height: u32,
    pub image: Rgb,
}

/// Where images go: blitted into the bitmap, or collected for embedding in the SVG.
enum Sink {
    Bitmap,
    Svg(Vec<SvgImage>),
}

/// Registers the built-in font with plotters once.
pub(super) fn ensure_font() -> Result<(), ExportError> {
    static REGISTERED: OnceLock<bool> = OnceLock::new();
    let ok = *REGISTERED.get_or_init(|| {
        plotters::style::register_font(FONT, FontStyle::Normal, epaint_default_fonts::UBUNTU_LIGHT)
            .is_ok()
    });
    if ok {
        Ok(())
    } else {
        Err(ExportError::Draw {
            figure: "font",
            message: "the built-in font could not be parsed".into(),
        })
    }
}

/// A bitmap backend over an RGB buffer whose text is drawn by [`CrispText`].
pub(super) fn crisp_bitmap(
    buf: &mut [u8],
    size: (u32, u32),
) -> Result<CrispText<BitMapBackend<'_>>, ExportError> {
    CrispText::new(
        BitMapBackend::with_buffer(buf, size),
        epaint_default_fonts::UBUNTU_LIGHT,
    )
    .ok_or_else(|| ExportError::Draw {
        figure: "font",
        message: "the built-in font could not be parsed".into(),
    })
}

/// Scaled lengths and styles.
#[derive(Clone, Copy)]
struct Look {
    s: u32,
}

impl Look {
    fn u(self, v: u32) -> u32 {
        v * self.s
    }
    fn i(self, v: u32) -> i32 {
        (v * self.s) as i32
    }
    fn text(self, px: f64) -> TextStyle<'static> {
        (FONT, px * self.s as f64).into_font().color(&BLACK)
    }
    fn line(self, color: RGBColor, width: u32) -> ShapeStyle {
        color.stroke_width(width * self.s)
    }
}

fn draw_err(kind: PanelKind, e: impl std::fmt::Display) -> ExportError {
    ExportError::Draw {
        figure: kind.name(),
        message: e.to_string(),
    }
}

fn missing(kind: PanelKind) -> ExportError {
    ExportError::EmptyData {
        figure: kind.name(),
        reason: "not computed (panel hidden, effect off, still running, or its node failed)".into(),
    }
}

fn empty(kind: PanelKind, what: &str) -> ExportError {
    ExportError::EmptyData {
        figure: kind.name(),
        reason: what.into(),
    }
}

/// Draws `kind` into an RGB bitmap of base size × `scale`.
pub(crate) fn render_bitmap(
    kind: PanelKind,
    ctx: &FigureContext,
    data: &ColumnData,
    scale: u32,
) -> Result<Rgb, ExportError> {
    ensure_font()?;
    check_data(kind, data)?;
    let (bw, bh) = kind.base_size();
    let (w, h) = (bw * scale, bh * scale);
    let mut buf = vec![255u8; (w as usize) * (h as usize) * 3];
    {
        let root = crisp_bitmap(&mut buf, (w, h))?.into_drawing_area();
        draw(&root, kind, ctx, data, Look { s: scale }, &mut Sink::Bitmap)?;
        root.present().map_err(|e| draw_err(kind, e))?;
    }
    Ok(Rgb {
        width: w,
        height: h,
        data: buf,
    })
}

/// Draws `kind` as SVG text of base size × `scale`; the images to embed come back separately.
pub(crate) fn render_svg(
    kind: PanelKind,
    ctx: &FigureContext,
    data: &ColumnData,
    scale: u32,
) -> Result<(String, Vec<SvgImage>), ExportError> {
    ensure_font()?;
    check_data(kind, data)?;
    let (bw, bh) = kind.base_size();
    let mut text = String::new();
    let mut sink = Sink::Svg(Vec::new());
    {
        let root = SVGBackend::with_string(&mut text, (bw * scale, bh * scale)).into_drawing_area();
        draw(&root, kind, ctx, data, Look { s: scale }, &mut sink)?;
        root.present().map_err(|e| draw_err(kind, e))?;
    }
    let images = match sink {
        Sink::Svg(v) => v,
        Sink::Bitmap => Vec::new(),
    };
    Ok((text, images))
}

/// Refuses missing or empty data before anything is drawn.
fn check_data(kind: PanelKind, d: &ColumnData) -> Result<(), ExportError> {
    let image_ok = |im: &ImageData| im.width > 0 && im.height > 0;
    match kind {
        PanelKind::Pattern => {
            let p = d.points.as_ref().ok_or_else(|| missing(kind))?;
            if p.points.is_empty() {
                return Err(empty(kind, "the point set is empty"));
            }
        }
        PanelKind::Spectrum => {
            let s = d.spectrum.as_ref().ok_or_else(|| missing(kind))?;
            if !image_ok(&s.image) {
                return Err(empty(kind, "the periodogram image is empty"));
            }
        }
        PanelKind::Raps => {
            let s = d.spectrum.as_ref().ok_or_else(|| missing(kind))?;
            if !s.raps.iter().any(|p| p[0].is_finite() && p[1].is_finite()) {
                return Err(empty(kind, "the radial average has no finite bin"));
            }
        }
        PanelKind::Reconstruction => {
            let r = d.reconstruction.as_ref().ok_or_else(|| missing(kind))?;
            if !image_ok(&r.image) {
                return Err(empty(kind, "the image is empty"));
            }
        }
        PanelKind::Reference => {
            let r = d.reference.as_ref().ok_or_else(|| missing(kind))?;
            if !image_ok(&r.image) {
                return Err(empty(kind, "the image is empty"));
            }
        }
        PanelKind::Error => {
            let r = d.error.as_ref().ok_or_else(|| missing(kind))?;
            if !image_ok(&r.image) {
                return Err(empty(kind, "the image is empty"));
            }
        }
        PanelKind::Kernel | PanelKind::Response => {
            let r = d.response.as_ref().ok_or_else(|| missing(kind))?;
            let curve = if kind == PanelKind::Kernel {
                &r.kernel
            } else {
                &r.magnitude
            };
            if !curve.iter().any(|p| p[0].is_finite() && p[1].is_finite()) {
                return Err(empty(kind, "the curve has no finite point"));
            }
        }
        PanelKind::Convergence => {
            let c = d.convergence.as_ref().ok_or_else(|| missing(kind))?;
            if !c
                .iter()
                .any(|p| p.spp > 0 && p.rmse.is_finite() && p.rmse > 0.0)
            {
                return Err(empty(kind, "no point with spp > 0 and a positive RMSE"));
            }
        }
        PanelKind::TheoremSignal
        | PanelKind::TheoremSpectrum
        | PanelKind::TheoremReconstructed
        | PanelKind::TheoremPair => {
            let v = d.theorem.as_ref().ok_or_else(|| missing(kind))?;
            let sp = &v.spectrum;
            let any = |c: &[[f64; 2]]| c.iter().any(|p| p[0].is_finite() && p[1].is_finite());
            let ok = match kind {
                PanelKind::TheoremSignal => any(&v.signal),
                PanelKind::TheoremPair => {
                    let pp = &v.pair;
                    (any(&pp.spatial) && any(&pp.magnitude))
                        || (any(&pp.impulses_x) && !pp.impulses_omega.is_empty())
                }
                PanelKind::TheoremSpectrum => {
                    any(&sp.gain) && (any(&sp.original) || sp.lines.iter().any(|(_, c)| any(c)))
                }
                _ => any(&sp.original) || any(&sp.reconstructed_lines),
            };
            if !ok {
                return Err(empty(kind, "the curves have no finite point"));
            }
            if !(v.settings.rate.is_finite() && v.settings.rate > 0.0) {
                return Err(empty(kind, "the sampling rate is not positive"));
            }
        }
    }
    Ok(())
}

fn draw<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    kind: PanelKind,
    ctx: &FigureContext,
    data: &ColumnData,
    look: Look,
    sink: &mut Sink,
) -> Result<(), ExportError> {
    let de = |e: DrawingAreaErrorKind<DB::ErrorType>| draw_err(kind, e);
    root.fill(&WHITE).map_err(de)?;
    let (title_area, body) = root.split_vertically(look.u(TITLE_H));
    title(&title_area, &figure_title(kind, ctx, data), look, kind)?;
    // `check_data` has run: the unwraps below are on data it found present.
    match kind {
        PanelKind::Pattern => pattern(&body, ctx, data, look),
        PanelKind::Spectrum => {
            let s = data.spectrum.as_ref().ok_or_else(|| missing(kind))?;
            let (lo, hi) = ordered_range(ctx.spectrum_range.unwrap_or(s.auto_range));
            let m = s.image.width as f64;
            let k0 = -((s.image.width / 2) as f64);
            let ky0 = -((s.image.height / 2) as f64);
            let kh = s.image.height as f64;
            image_figure(
                root,
                &body,
                kind,
                look,
                sink,
                ImageSpec {
                    image: &s.image,
                    x: (k0 - 0.5)..(k0 + m - 0.5),
                    y: (ky0 - 0.5)..(ky0 + kh - 0.5),
                    x_desc: "kx (cycles per unit)",
                    y_desc: "ky",
                    integer_ticks: true,
                    lo,
                    hi,
                    colormap: ctx.spectrum_colormap,
                    bar: Some("log10 P"),
                },
            )
        }
        PanelKind::Reconstruction | PanelKind::Reference | PanelKind::Error => {
            let (image, lo, hi, colormap, bar) = match kind {
                PanelKind::Reconstruction => {
                    let r = data.reconstruction.as_ref().ok_or_else(|| missing(kind))?;
                    (&r.image, 0.0, 1.0, FigureColormap::Greys, None)
                }
                PanelKind::Reference => {
                    let r = data.reference.as_ref().ok_or_else(|| missing(kind))?;
                    (&r.image, 0.0, 1.0, FigureColormap::Greys, None)
                }
                _ => {
                    let r = data.error.as_ref().ok_or_else(|| missing(kind))?;
                    (
                        &r.image,
                        0.0,
                        r.max_error.max(1e-6) as f64,
                        FigureColormap::Inferno,
                        Some("|reconstruction − reference|"),
                    )
                }
            };
            image_figure(
                root,
                &body,
                kind,
                look,
                sink,
                ImageSpec {
                    image,
                    x: 0.0..1.0,
                    y: 0.0..1.0,
                    x_desc: "x",
                    y_desc: "y",
                    integer_ticks: false,
                    lo,
                    hi,
                    colormap,
                    bar,
                },
            )
        }
        PanelKind::Raps => {
            let s = data.spectrum.as_ref().ok_or_else(|| missing(kind))?;
            raps(&body, &s.raps, look)
        }
        PanelKind::Kernel => {
            let r = data.response.as_ref().ok_or_else(|| missing(kind))?;
            kernel(&body, &r.kernel, ctx, look)
        }
        PanelKind::Response => {
            let r = data.response.as_ref().ok_or_else(|| missing(kind))?;
            response(&body, &r.magnitude, r.omega_max, ctx, look)
        }
        PanelKind::Convergence => {
            let c = data.convergence.as_ref().ok_or_else(|| missing(kind))?;
            let pts: Vec<(f64, f64)> = c
                .iter()
                .filter(|p| p.spp > 0 && p.rmse.is_finite() && p.rmse > 0.0)
                .map(|p| (p.spp as f64, p.rmse))
                .collect();
            convergence(&body, &pts, look)
        }
        PanelKind::TheoremSignal | PanelKind::TheoremSpectrum | PanelKind::TheoremReconstructed => {
            let v = data.theorem.as_ref().ok_or_else(|| missing(kind))?;
            let (_, h) = body.dim_in_pixel();
            let (plot, caption) = body.split_vertically(h - look.u(CAPTION_LINE));
            fitted_text(&caption, &theorem_caption(v), DESC_PX, look, kind)?;
            match kind {
                PanelKind::TheoremSignal => theorem_signal(&plot, v, look),
                PanelKind::TheoremSpectrum => theorem_spectrum(&plot, v, look),
                _ => theorem_reconstructed(&plot, v, look),
            }
        }
        PanelKind::TheoremPair => {
            let v = data.theorem.as_ref().ok_or_else(|| missing(kind))?;
            let (_, h) = body.dim_in_pixel();
            let (plot, caption) = body.split_vertically(h - look.u(CAPTION_LINE));
            fitted_text(
                &caption,
                "p(x) = g(a(x − s))  <->  P(ω) = e^(−2πiωs) G(ω/a) / |a|",
                DESC_PX,
                look,
                kind,
            )?;
            theorem_pair(&plot, v, look)
        }
    }
}

/// The title, centred in its band, its font shrunk until it fits the width.
fn title<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    text: &str,
    look: Look,
    kind: PanelKind,
) -> Result<(), ExportError> {
    fitted_text(area, text, TITLE_PX, look, kind)
}

/// `text` centred in `area`, at `start_px` (× scale) or smaller until it fits the width.
fn fitted_text<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    text: &str,
    start_px: f64,
    look: Look,
    kind: PanelKind,
) -> Result<(), ExportError> {
    let (w, h) = area.dim_in_pixel();
    let room = w.saturating_sub(2 * look.u(MARGIN));
    let mut px = start_px;
    let mut style = look.text(px);
    while px > 8.0 {
        let (tw, _) = area
            .estimate_text_size(text, &style)
            .map_err(|e| draw_err(kind, e))?;
        if tw <= room {
            break;
        }
        px -= 1.0;
        style = look.text(px);
    }
    let style = style.pos(Pos::new(HPos::Center, VPos::Center));
    area.draw_text(text, &style, ((w / 2) as i32, (h / 2) as i32))
        .map_err(|e| draw_err(kind, e))
}

/// A chart with the standard margins and label areas on `area`.
fn chart<'a, DB: DrawingBackend>(
    area: &'a DrawingArea<DB, Shift>,
    x: Range<f64>,
    y: Range<f64>,
    look: Look,
    kind: PanelKind,
) -> Result<ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>, ExportError> {
    ChartBuilder::on(area)
        .margin(look.u(MARGIN))
        .x_label_area_size(look.u(X_LABEL))
        .y_label_area_size(look.u(Y_LABEL))
        .build_cartesian_2d(x, y)
        .map_err(|e| draw_err(kind, e))
}

fn int_label(v: &f64) -> String {
    format!("{v:.0}")
}

/// Axes with ticks, tick labels and descriptions; a light grid when `grid`.
fn axes<DB: DrawingBackend>(
    chart: &mut ChartContext<'_, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>,
    x_desc: &str,
    y_desc: &str,
    grid: bool,
    integer_ticks: bool,
    look: Look,
    kind: PanelKind,
) -> Result<(), ExportError> {
    let mut mesh = chart.configure_mesh();
    mesh.x_desc(x_desc)
        .y_desc(y_desc)
        .label_style(look.text(TICK_PX))
        .axis_desc_style(look.text(DESC_PX))
        .axis_style(look.line(BLACK, 1))
        .set_all_tick_mark_size(look.i(5))
        .x_labels(7)
        .y_labels(7)
        .max_light_lines(0)
        .bold_line_style(look.line(RGBColor(225, 225, 225), 1));
    if integer_ticks {
        mesh.x_label_formatter(&int_label)
            .y_label_formatter(&int_label);
    }
    if !grid {
        mesh.disable_mesh();
    }
    mesh.draw().map_err(|e| draw_err(kind, e))
}

fn pattern<DB: DrawingBackend>(
    body: &DrawingArea<DB, Shift>,
    ctx: &FigureContext,
    data: &ColumnData,
    look: Look,
) -> Result<(), ExportError> {
    let kind = PanelKind::Pattern;
    let de = |e| draw_err(kind, e);
    let pts = &data.points.as_ref().ok_or_else(|| missing(kind))?.points;
    let mut ch = chart(body, 0.0..1.0, 0.0..1.0, look, kind)?;
    axes(&mut ch, "x", "y", false, false, look, kind)?;
    if let Some((cols, rows)) = elementary_grid(ctx.elementary_k, pts.len()) {
        let thin = look.line(INTERVALS, 1);
        let verticals = (1..cols).map(|i| {
            let x = i as f64 / cols as f64;
            PathElement::new(vec![(x, 0.0), (x, 1.0)], thin)
        });
        let horizontals = (1..rows).map(|j| {
            let y = j as f64 / rows as f64;
            PathElement::new(vec![(0.0, y), (1.0, y)], thin)
        });
        ch.draw_series(verticals.chain(horizontals)).map_err(de)?;
    }
    let (xr, _) = ch.plotting_area().get_pixel_range();
    let side = (xr.end - xr.start) as f64;
    let radius = (side / (pts.len() as f64).sqrt() * 0.18)
        .clamp(1.0, 4.0 * look.s as f64)
        .round() as u32;
    ch.draw_series(
        pts.iter()
            .map(|p| Circle::new((p.x, p.y), radius, INK.filled())),
    )
    .map_err(de)?;
    ch.plotting_area()
        .draw(&Rectangle::new(
            [(0.0, 0.0), (1.0, 1.0)],
            look.line(BLACK, 1),
        ))
        .map_err(de)?;
    Ok(())
}

/// What an image figure shows.
struct ImageSpec<'a> {
    image: &'a ImageData,
    x: Range<f64>,
    y: Range<f64>,
    x_desc: &'a str,
    y_desc: &'a str,
    integer_ticks: bool,
    lo: f64,
    hi: f64,
    colormap: FigureColormap,
    /// Description of the colour bar, if one is drawn.
    bar: Option<&'a str>,
}

fn ordered_range((lo, hi): (f32, f32)) -> (f64, f64) {
    let (lo, hi) = (lo as f64, hi as f64);
    if !(lo.is_finite() && hi.is_finite()) {
        return (0.0, 1.0);
    }
    if hi > lo {
        (lo, hi)
    } else {
        (lo, lo + 1e-3)
    }
}

/// The image through the colour map, [lo, hi] → [0, 1].
fn colorize(image: &ImageData, lo: f64, hi: f64, cmap: FigureColormap) -> Rgb {
    let span = if hi > lo { hi - lo } else { 1.0 };
    let mut data = Vec::with_capacity(image.values.len() * 3);
    for &v in image.values.iter() {
        data.extend_from_slice(&cmap.eval((v as f64 - lo) / span));
    }
    Rgb {
        width: image.width as u32,
        height: image.height as u32,
        data,
    }
}

/// Nearest-neighbour resampling of `img` to `w`×`h` (pixel centres map to pixel centres).
fn resample(img: &Rgb, w: u32, h: u32) -> Vec<u8> {
    let (sw, sh) = (img.width as u64, img.height as u64);
    let cols: Vec<usize> = (0..w as u64)
        .map(|x| (((2 * x + 1) * sw) / (2 * w as u64)) as usize)
        .collect();
    let mut out = Vec::with_capacity(w as usize * h as usize * 3);
    for y in 0..h as u64 {
        let sy = (((2 * y + 1) * sh) / (2 * h as u64)) as usize;
        let row = &img.data[sy * sw as usize * 3..(sy + 1) * sw as usize * 3];
        for &sx in &cols {
            out.extend_from_slice(&row[sx * 3..sx * 3 + 3]);
        }
    }
    out
}

/// Puts `img` over the pixel rectangle `range` (absolute pixels of `root`).
fn paint<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    range: (Range<i32>, Range<i32>),
    img: Rgb,
    sink: &mut Sink,
    kind: PanelKind,
) -> Result<(), ExportError> {
    let (xr, yr) = range;
    let w = (xr.end - xr.start).max(1) as u32;
    let h = (yr.end - yr.start).max(1) as u32;
    match sink {
        Sink::Bitmap => {
            let buf = resample(&img, w, h);
            let elem = BitMapElement::with_owned_buffer((xr.start, yr.start), (w, h), buf)
                .ok_or_else(|| draw_err(kind, "image buffer size"))?;
            root.draw(&elem).map_err(|e| draw_err(kind, e))
        }
        Sink::Svg(images) => {
            images.push(SvgImage {
                x: xr.start,
                y: yr.start,
                width: w,
                height: h,
                image: img,
            });
            Ok(())
        }
    }
}

fn image_figure<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    body: &DrawingArea<DB, Shift>,
    kind: PanelKind,
    look: Look,
    sink: &mut Sink,
    spec: ImageSpec<'_>,
) -> Result<(), ExportError> {
    let (main, bar_area) = if spec.bar.is_some() {
        let (w, _) = body.dim_in_pixel();
        body.split_horizontally(w - look.u(BAR_PART))
    } else {
        (body.clone(), body.clone())
    };
    let mut ch = chart(&main, spec.x.clone(), spec.y.clone(), look, kind)?;
    let rgb = colorize(spec.image, spec.lo, spec.hi, spec.colormap);
    paint(root, ch.plotting_area().get_pixel_range(), rgb, sink, kind)?;
    axes(
        &mut ch,
        spec.x_desc,
        spec.y_desc,
        false,
        spec.integer_ticks,
        look,
        kind,
    )?;
    if let Some(desc) = spec.bar {
        let mut bar = ChartBuilder::on(&bar_area)
            .margin_top(look.u(MARGIN))
            .margin_bottom(look.u(MARGIN))
            .margin_left(look.u(14))
            .margin_right(look.u(4))
            .x_label_area_size(look.u(X_LABEL))
            .right_y_label_area_size(look.u(68))
            .build_cartesian_2d(0.0..1.0, spec.lo..spec.hi)
            .map_err(|e| draw_err(kind, e))?;
        let steps = 256u32;
        let mut data = Vec::with_capacity(steps as usize * 3);
        for r in 0..steps {
            let t = 1.0 - (r as f64 + 0.5) / steps as f64;
            data.extend_from_slice(&spec.colormap.eval(t));
        }
        let gradient = Rgb {
            width: 1,
            height: steps,
            data,
        };
        paint(
            root,
            bar.plotting_area().get_pixel_range(),
            gradient,
            sink,
            kind,
        )?;
        bar.configure_mesh()
            .disable_mesh()
            .disable_x_axis()
            .x_labels(0)
            .y_labels(6)
            .y_desc(desc)
            .label_style(look.text(TICK_PX))
            .axis_desc_style(look.text(DESC_PX))
            .axis_style(look.line(BLACK, 1))
            .set_all_tick_mark_size(look.i(5))
            .draw()
            .map_err(|e| draw_err(kind, e))?;
    }
    Ok(())
}

/// A range around the finite values of `v`, padded by 5 % (and never empty).
fn padded(v: impl Iterator<Item = f64>, include: &[f64]) -> Range<f64> {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for x in v.chain(include.iter().copied()).filter(|x| x.is_finite()) {
        lo = lo.min(x);
        hi = hi.max(x);
    }
    if !(lo.is_finite() && hi.is_finite()) {
        return 0.0..1.0;
    }
    if hi - lo < 1e-12 {
        return (lo - 0.5)..(hi + 0.5);
    }
    let pad = 0.05 * (hi - lo);
    (lo - pad)..(hi + pad)
}

fn legend_box<'a, DB: DrawingBackend + 'a>(
    ch: &mut ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>,
    position: SeriesLabelPosition,
    look: Look,
    kind: PanelKind,
) -> Result<(), ExportError> {
    ch.configure_series_labels()
        .position(position)
        .margin(look.i(8))
        .legend_area_size(look.i(26))
        .label_font(look.text(TICK_PX))
        .border_style(look.line(GUIDE, 1))
        .background_style(WHITE.filled())
        .draw()
        .map_err(|e| draw_err(kind, e))
}

fn finite(curve: &[[f64; 2]]) -> Vec<(f64, f64)> {
    curve
        .iter()
        .filter(|p| p[0].is_finite() && p[1].is_finite())
        .map(|p| (p[0], p[1]))
        .collect()
}

fn raps<DB: DrawingBackend>(
    body: &DrawingArea<DB, Shift>,
    raps: &[[f64; 2]],
    look: Look,
) -> Result<(), ExportError> {
    let kind = PanelKind::Raps;
    let de = |e| draw_err(kind, e);
    let pts = finite(raps);
    let x_hi = pts.iter().map(|p| p.0).fold(0.0f64, f64::max).max(1.0);
    let y = padded(pts.iter().map(|p| p.1), &[0.0, 1.0]);
    let mut ch = chart(body, 0.0..x_hi, y.start.max(0.0)..y.end, look, kind)?;
    axes(
        &mut ch,
        "|k| (cycles per unit)",
        "RAPS  P",
        true,
        false,
        look,
        kind,
    )?;
    let guide = look.line(GUIDE, 1);
    ch.draw_series(LineSeries::new([(0.0, 1.0), (x_hi, 1.0)], guide))
        .map_err(de)?
        .label("white noise, P = 1")
        .legend(move |(x, y)| PathElement::new([(x, y), (x + look.i(20), y)], guide));
    let line = look.line(DATA, 2);
    ch.draw_series(LineSeries::new(pts, line))
        .map_err(de)?
        .label("RAPS")
        .legend(move |(x, y)| PathElement::new([(x, y), (x + look.i(20), y)], line));
    legend_box(&mut ch, SeriesLabelPosition::LowerRight, look, kind)
}

fn kernel<DB: DrawingBackend>(
    body: &DrawingArea<DB, Shift>,
    curve: &[[f64; 2]],
    ctx: &FigureContext,
    look: Look,
) -> Result<(), ExportError> {
    let kind = PanelKind::Kernel;
    let de = |e| draw_err(kind, e);
    let pts = finite(curve);
    let x0 = pts.iter().map(|p| p.0).fold(f64::INFINITY, f64::min);
    let x1 = pts.iter().map(|p| p.0).fold(f64::NEG_INFINITY, f64::max);
    let x = if x1 > x0 {
        x0..x1
    } else {
        (x0 - 1.0)..(x0 + 1.0)
    };
    let y = padded(pts.iter().map(|p| p.1), &[0.0]);
    let mut ch = chart(body, x.clone(), y, look, kind)?;
    axes(
        &mut ch,
        "x (sample spacings)",
        "h(x)",
        true,
        false,
        look,
        kind,
    )?;
    ch.draw_series(LineSeries::new(
        [(x.start, 0.0), (x.end, 0.0)],
        look.line(GUIDE, 1),
    ))
    .map_err(de)?;
    let line = look.line(DATA, 2);
    let name = filter_name(ctx);
    ch.draw_series(LineSeries::new(pts, line))
        .map_err(de)?
        .label(name)
        .legend(move |(x, y)| PathElement::new([(x, y), (x + look.i(20), y)], line));
    legend_box(&mut ch, SeriesLabelPosition::UpperRight, look, kind)
}

/// The filter's name as the legend shows it (the `kind` tag of its RON text).
fn filter_name(ctx: &FigureContext) -> String {
    ctx.filter
        .split("kind:\"")
        .nth(1)
        .and_then(|s| s.split('"').next())
        .unwrap_or("h")
        .to_string()
}

fn response<DB: DrawingBackend>(
    body: &DrawingArea<DB, Shift>,
    magnitude: &[[f64; 2]],
    omega_max: f64,
    ctx: &FigureContext,
    look: Look,
) -> Result<(), ExportError> {
    let kind = PanelKind::Response;
    let de = |e| draw_err(kind, e);
    let db = ctx.response_db;
    let floor_db = -120.0;
    let value = |m: f64| {
        if db {
            (20.0 * m.abs().max(1e-12).log10()).max(floor_db)
        } else {
            m
        }
    };
    let pts: Vec<(f64, f64)> = finite(magnitude)
        .into_iter()
        .map(|(w, m)| (w, value(m)))
        .collect();
    let w_hi = if omega_max.is_finite() && omega_max > 0.0 {
        omega_max
    } else {
        pts.iter().map(|p| p.0).fold(0.5, f64::max)
    };
    let (one, zero) = if db { (0.0, floor_db) } else { (1.0, 0.0) };
    let y = padded(pts.iter().map(|p| p.1), &[one, zero]);
    let mut ch = chart(body, 0.0..w_hi, y.clone(), look, kind)?;
    axes(
        &mut ch,
        "ω (cycles per sample)",
        if db {
            "|H(ω)|  dB"
        } else {
            "|H(ω)| / |H(0)|"
        },
        true,
        false,
        look,
        kind,
    )?;
    let guide = look.line(GUIDE, 1);
    ch.draw_series(LineSeries::new(
        [(0.0, one), (0.5, one), (0.5, zero), (w_hi, zero)],
        guide,
    ))
    .map_err(de)?
    .label("ideal low-pass")
    .legend(move |(x, y)| PathElement::new([(x, y), (x + look.i(20), y)], guide));
    let red = look.line(NYQUIST, 1);
    ch.draw_series(LineSeries::new([(0.5, y.start), (0.5, y.end)], red))
        .map_err(de)?
        .label("Nyquist, ω = 0.5")
        .legend(move |(x, y)| PathElement::new([(x, y), (x + look.i(20), y)], red));
    let line = look.line(DATA, 2);
    ch.draw_series(LineSeries::new(pts, line))
        .map_err(de)?
        .label(format!("{}, |H(ω)|", filter_name(ctx)))
        .legend(move |(x, y)| PathElement::new([(x, y), (x + look.i(20), y)], line));
    legend_box(&mut ch, SeriesLabelPosition::UpperRight, look, kind)
}

/// Ticks of a logarithmic axis over [lo, hi] (0 < lo < hi): 1, 2 and 5 times the powers of
/// ten inside, or every integer multiple when that gives fewer than three.
fn log_ticks(lo: f64, hi: f64) -> Vec<f64> {
    let ticks = |mantissas: &[f64]| -> Vec<f64> {
        let (k0, k1) = (lo.log10().floor() as i32, hi.log10().ceil() as i32);
        (k0..=k1)
            .flat_map(|k| mantissas.iter().map(move |m| m * 10f64.powi(k)))
            .filter(|v| *v >= lo && *v <= hi)
            .collect()
    };
    let coarse = ticks(&[1.0, 2.0, 5.0]);
    if coarse.len() >= 3 {
        coarse
    } else {
        ticks(&[1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0])
    }
}

/// A tick value with as many decimals as its magnitude needs (0.02, 0.5, 20).
fn tick_label(v: &f64) -> String {
    let decimals = if *v > 0.0 {
        (-v.log10().floor()).max(0.0) as usize
    } else {
        0
    };
    format!("{v:.decimals$}")
}

fn convergence<DB: DrawingBackend>(
    body: &DrawingArea<DB, Shift>,
    pts: &[(f64, f64)],
    look: Look,
) -> Result<(), ExportError> {
    let kind = PanelKind::Convergence;
    let de = |e| draw_err(kind, e);
    let (mut x0, mut x1) = (f64::INFINITY, f64::NEG_INFINITY);
    let (mut y0, mut y1) = (f64::INFINITY, f64::NEG_INFINITY);
    for &(x, y) in pts {
        x0 = x0.min(x);
        x1 = x1.max(x);
        y0 = y0.min(y);
        y1 = y1.max(y);
    }
    let (x0, x1) = (x0 / 1.5, x1 * 1.5);
    let (y0, y1) = (y0 / 1.5, y1 * 1.5);
    let mut ch = ChartBuilder::on(body)
        .margin(look.u(MARGIN))
        .x_label_area_size(look.u(X_LABEL))
        .y_label_area_size(look.u(Y_LABEL))
        .build_cartesian_2d(
            (x0..x1).log_scale().with_key_points(log_ticks(x0, x1)),
            (y0..y1).log_scale().with_key_points(log_ticks(y0, y1)),
        )
        .map_err(de)?;
    ch.configure_mesh()
        .x_desc("samples per pixel")
        .y_desc("RMSE")
        .label_style(look.text(TICK_PX))
        .axis_desc_style(look.text(DESC_PX))
        .axis_style(look.line(BLACK, 1))
        .set_all_tick_mark_size(look.i(5))
        .max_light_lines(0)
        .bold_line_style(look.line(RGBColor(225, 225, 225), 1))
        .x_label_formatter(&tick_label)
        .y_label_formatter(&tick_label)
        .draw()
        .map_err(de)?;
    ch.draw_series(LineSeries::new(pts.iter().copied(), look.line(DATA, 2)))
        .map_err(de)?;
    ch.draw_series(
        pts.iter()
            .map(|&p| Circle::new(p, look.u(3), DATA.filled())),
    )
    .map_err(de)?;
    Ok(())
}

/// The colour of replica k (k = 0, the signal itself, in ink).
fn replica_colour(k: i64) -> RGBColor {
    if k == 0 {
        INK
    } else {
        REPLICA_COLOURS[(k + 3).clamp(0, 6) as usize]
    }
}

/// The largest finite second coordinate of the curves (0 when none).
fn max_of<'a>(curves: impl Iterator<Item = &'a [[f64; 2]]>) -> f64 {
    curves
        .flat_map(|c| c.iter())
        .filter(|p| p[0].is_finite() && p[1].is_finite())
        .map(|p| p[1])
        .fold(0.0, f64::max)
}

/// A magnitude axis from 0 to a little above `hi` (0..1 when `hi` is not positive).
fn magnitude_range(hi: f64) -> Range<f64> {
    if hi.is_finite() && hi > 0.0 {
        0.0..hi * 1.08
    } else {
        0.0..1.0
    }
}

/// Stems from 0 to each point, with a filled marker of `radius` (× scale) on top when there
/// are at most [`MAX_MARKERS`]; labelled `label` in the legend.
fn stems<DB: DrawingBackend>(
    ch: &mut ChartContext<'_, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>,
    pts: &[(f64, f64)],
    colour: RGBColor,
    radius: u32,
    label: &str,
    look: Look,
    kind: PanelKind,
) -> Result<(), ExportError> {
    let de = |e| draw_err(kind, e);
    let stem = look.line(colour, 1);
    let anno = ch
        .draw_series(
            pts.iter()
                .map(|&(x, y)| PathElement::new(vec![(x, 0.0), (x, y)], stem)),
        )
        .map_err(de)?;
    let r = look.u(radius);
    anno.label(label)
        .legend(move |(x, y)| Circle::new((x + look.i(10), y), r, colour.filled()));
    if pts.len() <= MAX_MARKERS {
        ch.draw_series(pts.iter().map(|&p| Circle::new(p, r, colour.filled())))
            .map_err(de)?;
    }
    Ok(())
}

/// The vertical Nyquist lines ±f_s/2 over the y range `y`, labelled once.
fn nyquist_lines<DB: DrawingBackend>(
    ch: &mut ChartContext<'_, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>,
    rate: f64,
    y: &Range<f64>,
    look: Look,
    kind: PanelKind,
) -> Result<(), ExportError> {
    let red = look.line(NYQUIST, 1);
    let half = 0.5 * rate;
    ch.draw_series([
        PathElement::new(vec![(-half, y.start), (-half, y.end)], red),
        PathElement::new(vec![(half, y.start), (half, y.end)], red),
    ])
    .map_err(|e| draw_err(kind, e))?
    .label("Nyquist ±f_s/2")
    .legend(move |(x, y)| PathElement::new([(x, y), (x + look.i(20), y)], red));
    Ok(())
}

fn theorem_signal<DB: DrawingBackend>(
    body: &DrawingArea<DB, Shift>,
    v: &TheoremView,
    look: Look,
) -> Result<(), ExportError> {
    let kind = PanelKind::TheoremSignal;
    let de = |e| draw_err(kind, e);
    let ext = v.settings.extent;
    let f = finite(&v.signal);
    let fr = finite(&v.reconstruction);
    let samples = finite(&v.samples);
    let y = padded(f.iter().chain(&fr).chain(&samples).map(|p| p.1), &[0.0]);
    let mut ch = chart(body, -ext..ext, y, look, kind)?;
    axes(&mut ch, "x (units)", "value", true, false, look, kind)?;
    ch.draw_series(LineSeries::new(
        [(-ext, 0.0), (ext, 0.0)],
        look.line(GUIDE, 1),
    ))
    .map_err(de)?;
    let grey = look.line(RGBColor(110, 110, 110), 2);
    ch.draw_series(LineSeries::new(f, grey))
        .map_err(de)?
        .label("f(x)")
        .legend(move |(x, y)| PathElement::new([(x, y), (x + look.i(20), y)], grey));
    stems(&mut ch, &samples, DATA, 3, "samples f(nT)", look, kind)?;
    let orange = look.line(RECON, 2);
    ch.draw_series(LineSeries::new(fr, orange))
        .map_err(de)?
        .label("reconstruction f_r(x)")
        .legend(move |(x, y)| PathElement::new([(x, y), (x + look.i(20), y)], orange));
    legend_box(&mut ch, SeriesLabelPosition::UpperRight, look, kind)
}

/// How an entry of the legend column is drawn.
enum Mark {
    Line(ShapeStyle),
    Dot(RGBColor),
}

fn theorem_spectrum<DB: DrawingBackend>(
    body: &DrawingArea<DB, Shift>,
    v: &TheoremView,
    look: Look,
) -> Result<(), ExportError> {
    let kind = PanelKind::TheoremSpectrum;
    let de = |e| draw_err(kind, e);
    let sp = &v.spectrum;
    let (w, _) = body.dim_in_pixel();
    let (main, legend_area) = body.split_horizontally(w - look.u(LEGEND_PART));
    let hi = max_of(
        std::iter::once(sp.original.as_slice())
            .chain(std::iter::once(sp.gain.as_slice()))
            .chain(sp.replicas.iter().map(|(_, c)| c.as_slice()))
            .chain(sp.lines.iter().map(|(_, c)| c.as_slice())),
    );
    let y = magnitude_range(hi);
    let wm = sp.omega_max;
    let mut ch = chart(&main, -wm..wm, y.clone(), look, kind)?;
    axes(
        &mut ch,
        "ω (cycles per unit)",
        "magnitude",
        true,
        false,
        look,
        kind,
    )?;
    let mut entries: Vec<(String, Mark)> = Vec::new();
    for (k, c) in &sp.replicas {
        let style = look.line(replica_colour(*k), 2);
        ch.draw_series(LineSeries::new(finite(c), style))
            .map_err(de)?;
        let label = if *k < 0 {
            format!("F(ω + {}·f_s)", -k)
        } else {
            format!("F(ω − {k}·f_s)")
        };
        entries.push((label, Mark::Line(style)));
    }
    for (k, c) in &sp.lines {
        let colour = replica_colour(*k);
        let name = if *k == 0 {
            "|F| (lines)".to_string()
        } else {
            format!("lines, k = {k}")
        };
        stems(&mut ch, &finite(c), colour, 3, &name, look, kind)?;
        entries.push((name, Mark::Dot(colour)));
    }
    if !sp.original.is_empty() {
        let style = look.line(INK, 3);
        ch.draw_series(LineSeries::new(finite(&sp.original), style))
            .map_err(de)?;
        entries.insert(0, ("|F(ω)|".to_string(), Mark::Line(style)));
    }
    let gain = look.line(RGBColor(110, 110, 110), 2);
    ch.draw_series(LineSeries::new(finite(&sp.gain), gain))
        .map_err(de)?;
    entries.push(("|G(ω)| (filter)".to_string(), Mark::Line(gain)));
    nyquist_lines(&mut ch, v.settings.rate, &y, look, kind)?;
    entries.push((
        "Nyquist ±f_s/2".to_string(),
        Mark::Line(look.line(NYQUIST, 1)),
    ));
    legend_column(&legend_area, &entries, look, kind)
}

/// The legend as a column of entries (a line or dot sample, then the label) from the top of
/// `area`, level with the plot.
fn legend_column<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    entries: &[(String, Mark)],
    look: Look,
    kind: PanelKind,
) -> Result<(), ExportError> {
    let de = |e| draw_err(kind, e);
    let style = look.text(TICK_PX).pos(Pos::new(HPos::Left, VPos::Center));
    let x0 = look.i(8);
    let step = look.i(24);
    for (i, (label, mark)) in entries.iter().enumerate() {
        let y = look.i(MARGIN + 12) + step * i as i32;
        match mark {
            Mark::Line(s) => area
                .draw(&PathElement::new(vec![(x0, y), (x0 + look.i(24), y)], *s))
                .map_err(de)?,
            Mark::Dot(c) => area
                .draw(&Circle::new((x0 + look.i(12), y), look.u(4), c.filled()))
                .map_err(de)?,
        }
        area.draw_text(label, &style, (x0 + look.i(32), y))
            .map_err(de)?;
    }
    Ok(())
}

fn theorem_reconstructed<DB: DrawingBackend>(
    body: &DrawingArea<DB, Shift>,
    v: &TheoremView,
    look: Look,
) -> Result<(), ExportError> {
    let kind = PanelKind::TheoremReconstructed;
    let de = |e| draw_err(kind, e);
    let sp = &v.spectrum;
    let original_lines: &[[f64; 2]] = sp
        .lines
        .iter()
        .find(|(k, _)| *k == 0)
        .map(|(_, c)| c.as_slice())
        .unwrap_or(&[]);
    let hi = max_of(
        [
            sp.original.as_slice(),
            sp.reconstructed.as_slice(),
            original_lines,
            sp.reconstructed_lines.as_slice(),
        ]
        .into_iter(),
    );
    let y = magnitude_range(hi);
    let wm = sp.omega_max;
    let mut ch = chart(body, -wm..wm, y.clone(), look, kind)?;
    axes(
        &mut ch,
        "ω (cycles per unit)",
        "magnitude",
        true,
        false,
        look,
        kind,
    )?;
    let grey = RGBColor(110, 110, 110);
    if !sp.original.is_empty() {
        let f = look.line(grey, 2);
        ch.draw_series(LineSeries::new(finite(&sp.original), f))
            .map_err(de)?
            .label("|F(ω)|")
            .legend(move |(x, y)| PathElement::new([(x, y), (x + look.i(20), y)], f));
        let r = look.line(RECON, 2);
        ch.draw_series(LineSeries::new(finite(&sp.reconstructed), r))
            .map_err(de)?
            .label("|F_r(ω)|")
            .legend(move |(x, y)| PathElement::new([(x, y), (x + look.i(20), y)], r));
    } else {
        let r = look.u(5);
        ch.draw_series(
            finite(original_lines)
                .into_iter()
                .map(|p| Circle::new(p, r, grey.stroke_width(look.u(2)))),
        )
        .map_err(de)?
        .label("|F| (lines)")
        .legend(move |(x, y)| Circle::new((x + look.i(10), y), r, grey.stroke_width(look.u(2))));
        stems(
            &mut ch,
            &finite(&sp.reconstructed_lines),
            RECON,
            3,
            "|F_r| (lines)",
            look,
            kind,
        )?;
    }
    nyquist_lines(&mut ch, v.settings.rate, &y, look, kind)?;
    legend_box(&mut ch, SeriesLabelPosition::UpperRight, look, kind)
}

fn theorem_pair<DB: DrawingBackend>(
    body: &DrawingArea<DB, Shift>,
    v: &TheoremView,
    look: Look,
) -> Result<(), ExportError> {
    let kind = PanelKind::TheoremPair;
    let de = |e| draw_err(kind, e);
    let pp = &v.pair;
    let (w, _) = body.dim_in_pixel();
    let (left, right) = body.split_horizontally(w / 2);
    let shah = !pp.impulses_x.is_empty();
    // Space domain.
    let spatial = if shah {
        finite(&pp.impulses_x)
    } else {
        finite(&pp.spatial)
    };
    let y = padded(spatial.iter().map(|p| p.1), &[0.0]);
    let mut ch = chart(&left, -pp.x_max..pp.x_max, y, look, kind)?;
    axes(&mut ch, "x", "p(x)", true, false, look, kind)?;
    if shah {
        stems(
            &mut ch,
            &spatial,
            DATA,
            3,
            "impulses, weight 1/|a|",
            look,
            kind,
        )?;
    } else {
        let line = look.line(DATA, 2);
        ch.draw_series(LineSeries::new(spatial, line))
            .map_err(de)?
            .label("p(x) = g(a(x − s))")
            .legend(move |(x, y)| PathElement::new([(x, y), (x + look.i(20), y)], line));
    }
    legend_box(&mut ch, SeriesLabelPosition::UpperRight, look, kind)?;
    // Frequency domain.
    let (re, im): (Vec<_>, Vec<_>) = if shah {
        (
            pp.impulses_omega.iter().map(|i| (i[0], i[1])).collect(),
            pp.impulses_omega.iter().map(|i| (i[0], i[2])).collect(),
        )
    } else {
        (finite(&pp.re), finite(&pp.im))
    };
    let magnitude = finite(&pp.magnitude);
    let has_im = im.iter().any(|p| p.1.abs() > 1e-12);
    let y = padded(re.iter().chain(&im).chain(&magnitude).map(|p| p.1), &[0.0]);
    let mut ch = chart(&right, -pp.omega_max..pp.omega_max, y, look, kind)?;
    axes(&mut ch, "ω", "P(ω)", true, false, look, kind)?;
    if shah {
        stems(&mut ch, &re, DATA, 3, "Re P (impulses)", look, kind)?;
        if has_im {
            stems(&mut ch, &im, RECON, 2, "Im P (impulses)", look, kind)?;
        }
    } else {
        let abs = look.line(INK, 2);
        ch.draw_series(LineSeries::new(magnitude, abs))
            .map_err(de)?
            .label("|P(ω)|")
            .legend(move |(x, y)| PathElement::new([(x, y), (x + look.i(20), y)], abs));
        let re_style = look.line(DATA, 1);
        ch.draw_series(LineSeries::new(re, re_style))
            .map_err(de)?
            .label("Re P(ω)")
            .legend(move |(x, y)| PathElement::new([(x, y), (x + look.i(20), y)], re_style));
        if has_im {
            let im_style = look.line(RECON, 1);
            ch.draw_series(LineSeries::new(im, im_style))
                .map_err(de)?
                .label("Im P(ω)")
                .legend(move |(x, y)| PathElement::new([(x, y), (x + look.i(20), y)], im_style));
        }
    }
    legend_box(&mut ch, SeriesLabelPosition::UpperRight, look, kind)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn resample_maps_pixel_centres() {
        let img = Rgb {
            width: 2,
            height: 1,
            data: vec![0, 0, 0, 255, 255, 255],
        };
        let out = resample(&img, 4, 2);
        assert_eq!(out.len(), 4 * 2 * 3);
        let firsts: Vec<u8> = out.chunks(3).map(|p| p[0]).collect();
        assert_eq!(firsts, vec![0, 0, 255, 255, 0, 0, 255, 255]);
    }

    #[test]
    fn padded_range_covers_data_and_guides() {
        let r = padded([2.0, 4.0, f64::NAN].into_iter(), &[0.0]);
        assert!(r.start < 0.0 && r.end > 4.0);
        let flat = padded([3.0].into_iter(), &[]);
        assert!(flat.start < 3.0 && flat.end > 3.0);
        assert_eq!(padded(std::iter::empty(), &[]), 0.0..1.0);
    }

    #[test]
    fn log_ticks_are_one_two_five_or_finer_in_narrow_ranges() {
        assert_eq!(
            log_ticks(0.7, 300.0),
            vec![1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0, 200.0]
        );
        let narrow = log_ticks(0.013, 0.12);
        assert!(narrow.len() >= 3, "{narrow:?}");
        assert!(narrow.iter().all(|&v| (0.013..=0.12).contains(&v)));
        assert_eq!(tick_label(&0.02), "0.02");
        assert_eq!(tick_label(&0.5), "0.5");
        assert_eq!(tick_label(&200.0), "200");
    }

    #[test]
    fn degenerate_colour_ranges_are_widened() {
        assert_eq!(ordered_range((1.0, 1.0)), (1.0, 1.0 + 1e-3));
        assert_eq!(ordered_range((f32::NAN, 1.0)), (0.0, 1.0));
        assert_eq!(ordered_range((-1.0, 2.0)), (-1.0, 2.0));
    }
}
