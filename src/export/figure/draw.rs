//! What every figure is drawn with: the layout, the frame around a figure's own drawing (white
//! page, title band, into the figure's vector drawing), and the shared helpers (charts, axes, text, legends,
//! images with colour bars, stems, Nyquist lines, ticks and ranges).
//!
//! Layout at scale 1 (every length is multiplied by the scale): a title band of
//! [`TITLE_H`] pixels, then a chart with [`MARGIN`] on every side, [`Y_LABEL`] pixels for the
//! y tick labels and description and [`X_LABEL`] pixels for the x ones. With the figures'
//! base sizes the plotting area of the pattern and image figures is a 400 × 400 square and
//! that of the line plots 560 × 400. The theorem figures keep a [`CAPTION_LINE`] band under the
//! chart for the aliasing numbers.

use super::canvas::{ensure_font, Area, Canvas, Chart, PlacedImage, FONT, SUB};
use super::drawing::Drawing;
use super::{Figure, Rgb};
use crate::core::format;
use crate::export::ExportError;
use crate::model::{palette, Colormap, ColumnData, FigureContext, FigureKind, ImageData};
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use std::ops::Range;
use std::sync::Arc;

/// Height of the title band.
const TITLE_H: u32 = 40;
/// Margin around a chart.
pub(super) const MARGIN: u32 = 10;
/// Width of the y label area.
pub(super) const Y_LABEL: u32 = 60;
/// Height of the x label area.
pub(super) const X_LABEL: u32 = 50;
/// Width of the colour-bar part of the periodogram and error figures.
pub(super) const BAR_PART: u32 = 110;
/// Title, tick-label and axis-description font sizes.
const TITLE_PX: f64 = 17.0;
pub(super) const TICK_PX: f64 = 14.0;
pub(super) const DESC_PX: f64 = 16.0;
/// Tick labels asked of plotters per axis.
const TICKS: usize = 7;
/// Height of the caption line under the theorem figures' charts.
pub(super) const CAPTION_LINE: u32 = 26;
/// Sample markers are drawn up to this many samples (beyond, the stems alone: the markers
/// would merge into a band).
const MAX_MARKERS: usize = 400;

const fn rgb(c: [u8; 3]) -> RGBColor {
    RGBColor(c[0], c[1], c[2])
}

/// Line colour of the data.
pub(super) const DATA: RGBColor = rgb(palette::DATA);
/// Reference lines (white noise, ideal low-pass, zero).
pub(super) const GUIDE: RGBColor = rgb(palette::GUIDE);
/// The Nyquist line.
pub(super) const NYQUIST: RGBColor = rgb(palette::NYQUIST);
/// The points of a pattern.
pub(super) const INK: RGBColor = rgb(palette::INK);
/// The elementary-interval grid under the points (the GUI's overlay colour).
pub(super) const INTERVALS: RGBColor = rgb(palette::INTERVALS);
/// The reconstruction f_r and its spectrum (the theorem panel's colour).
pub(super) const RECON: RGBColor = rgb(palette::RECON);
/// The signal f(x) and the filter's gain in the theorem figures.
pub(super) const GREY: RGBColor = RGBColor(110, 110, 110);

/// The colour of replica k of the theorem's spectrum (k = 0, the signal, in [`INK`]).
pub(super) fn replica_colour(k: i64) -> RGBColor {
    if k == 0 {
        INK
    } else {
        rgb(palette::replica(k))
    }
}

/// Scaled lengths and styles, in plotters' pixels: [`SUB`] per page pixel at scale 1.
#[derive(Clone, Copy)]
pub struct Look {
    /// plotters' pixels per base-size pixel: the figure scale × [`SUB`].
    pub(super) s: u32,
}

impl Look {
    pub(super) fn u(self, v: u32) -> u32 {
        v * self.s
    }
    pub(super) fn i(self, v: u32) -> i32 {
        (v * self.s) as i32
    }
    pub(super) fn text(self, px: f64) -> TextStyle<'static> {
        (FONT, px * self.s as f64).into_font().color(&BLACK)
    }
    pub(super) fn line(self, color: RGBColor, width: u32) -> ShapeStyle {
        color.stroke_width(width * self.s)
    }
}

/// Where a figure is drawn: as a file of its own, or as a panel of a composite, under a block
/// caption that already names the column (pattern, N, seed) or, for the sampling theorem,
/// its setup and error terms; a panel's title then says only what it plots.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Role {
    Alone,
    Panel,
}

/// What a figure draws with: the whole page (images are placed in its pixels), the context
/// and data, the scale, and whether it stands alone or is a composite's panel.
pub struct Frame<'a, 'b> {
    pub(super) root: &'a Area<'b>,
    pub(super) ctx: &'a FigureContext,
    pub(super) data: &'a ColumnData,
    pub(super) look: Look,
    pub(super) role: Role,
}

pub(super) fn draw_err(kind: FigureKind, e: impl std::fmt::Display) -> ExportError {
    ExportError::Draw {
        figure: kind.name(),
        message: e.to_string(),
    }
}

/// The error of a figure whose data was not computed.
pub(super) fn missing(kind: FigureKind) -> ExportError {
    ExportError::EmptyData {
        figure: kind.name(),
        reason: "not computed (panel hidden, effect off, still running, or its node failed)".into(),
    }
}

/// The data of `kind`, or the error that it was not computed.
pub(super) fn present<T>(kind: FigureKind, data: Option<&T>) -> Result<&T, ExportError> {
    data.ok_or_else(|| missing(kind))
}

/// The error of a figure whose data is there but empty.
pub(super) fn empty(kind: FigureKind, what: &str) -> ExportError {
    ExportError::EmptyData {
        figure: kind.name(),
        reason: what.into(),
    }
}

/// Lays `figure` out at base size × `scale` into its vector drawing (which the PNG, SVG and
/// PDF writers read), in its `role`.
pub(super) fn render_drawing(
    figure: &dyn Figure,
    ctx: &FigureContext,
    data: &ColumnData,
    scale: u32,
    role: Role,
) -> Result<Drawing, ExportError> {
    ensure_font()?;
    figure.check(data)?;
    let kind = figure.kind();
    let (bw, bh) = figure.base_size();
    let mut drawing = Drawing::new(bw * scale, bh * scale);
    {
        let root = Canvas::new(&mut drawing).into_drawing_area();
        page(&root, figure, ctx, data, Look { s: scale * SUB }, role)?;
        root.present().map_err(|e| draw_err(kind, e))?;
    }
    Ok(drawing)
}

/// The white page, the title in its band, and the figure's own drawing under it.
fn page(
    root: &Area<'_>,
    figure: &dyn Figure,
    ctx: &FigureContext,
    data: &ColumnData,
    look: Look,
    role: Role,
) -> Result<(), ExportError> {
    let kind = figure.kind();
    root.fill(&WHITE).map_err(|e| draw_err(kind, e))?;
    let (title_area, body) = root.split_vertically(look.u(TITLE_H));
    let title = match role {
        Role::Alone => figure.title(ctx, data),
        Role::Panel => figure.panel_title(ctx, data),
    };
    fitted_text(&title_area, &title, TITLE_PX, look, kind)?;
    let mut frame = Frame {
        root,
        ctx,
        data,
        look,
        role,
    };
    figure.draw(&mut frame, &body)
}

/// `text` centred in `area`, at `start_px` (× scale) or smaller until it fits the width.
pub(super) fn fitted_text(
    area: &Area<'_>,
    text: &str,
    start_px: f64,
    look: Look,
    kind: FigureKind,
) -> Result<(), ExportError> {
    let (w, h) = area.dim_in_pixel();
    let room = w.saturating_sub(2 * look.u(MARGIN));
    let px = fitting_px(area, &[text], room, (start_px, 1.0, 8.0), look, kind)?;
    let style = look.text(px).pos(Pos::new(HPos::Center, VPos::Center));
    area.draw_text(text, &style, ((w / 2) as i32, (h / 2) as i32))
        .map_err(|e| draw_err(kind, e))
}

/// The text size for `texts` in `area`: from `start` down by `step` while the widest of them
/// is wider than `room` (plotters' pixels), stopping at `floor`.
pub(super) fn fitting_px(
    area: &Area<'_>,
    texts: &[&str],
    room: u32,
    (start, step, floor): (f64, f64, f64),
    look: Look,
    kind: FigureKind,
) -> Result<f64, ExportError> {
    let mut px = start;
    while px > floor {
        let style = look.text(px);
        let widest = texts
            .iter()
            .map(|t| area.estimate_text_size(t, &style).map(|s| s.0))
            .try_fold(0, |a, w| w.map(|w| a.max(w)))
            .map_err(|e| draw_err(kind, e))?;
        if widest <= room {
            break;
        }
        px -= step;
    }
    Ok(px)
}

/// Splits `body` into the plot and the [`CAPTION_LINE`] band under it, and writes `caption`
/// there (nothing when it is empty: the band stays blank); returns the plot's area.
pub(super) fn with_caption<'b>(
    body: &Area<'b>,
    caption: &str,
    look: Look,
    kind: FigureKind,
) -> Result<Area<'b>, ExportError> {
    let (_, h) = body.dim_in_pixel();
    let (plot, band) = body.split_vertically(h - look.u(CAPTION_LINE));
    if !caption.is_empty() {
        fitted_text(&band, caption, DESC_PX, look, kind)?;
    }
    Ok(plot)
}

/// A chart with the standard margins and label areas on `area`.
pub(super) fn chart<'a, 'b>(
    area: &'a Area<'b>,
    x: Range<f64>,
    y: Range<f64>,
    look: Look,
    kind: FigureKind,
) -> Result<Chart<'a, 'b>, ExportError> {
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

/// Whether every tick plotters puts on `range` (asking for `n` labels) is a whole number,
/// so that the labels read "−2, −1, 0, 1, 2" instead of "−2.0, −1.0, 0.0, 1.0, 2.0"; ticks
/// with a fractional step keep plotters' uniform decimals ("0.0, 0.2, … 1.0").
pub(super) fn whole_ticks(range: Range<f64>, n: usize) -> bool {
    use plotters::coord::ranged1d::Ranged;
    use plotters::coord::types::RangedCoordf64;
    let ticks = RangedCoordf64::from(range).key_points(n);
    !ticks.is_empty()
        && ticks
            .iter()
            .all(|t| t.is_finite() && (t - t.round()).abs() < 1e-9 && t.abs() < 1e15)
}

/// Axes with ticks, tick labels and descriptions; a light grid when `grid`.
#[allow(clippy::too_many_arguments)]
pub(super) fn axes(
    chart: &mut Chart<'_, '_>,
    x_desc: &str,
    y_desc: &str,
    grid: bool,
    integer_ticks: bool,
    look: Look,
    kind: FigureKind,
) -> Result<(), ExportError> {
    let (xs, ys) = (chart.x_range(), chart.y_range());
    let mut mesh = chart.configure_mesh();
    mesh.x_desc(x_desc)
        .y_desc(y_desc)
        .label_style(look.text(TICK_PX))
        .axis_desc_style(look.text(DESC_PX))
        .axis_style(look.line(BLACK, 1))
        .set_all_tick_mark_size(look.i(5))
        .x_labels(TICKS)
        .y_labels(TICKS)
        .max_light_lines(0)
        .bold_line_style(look.line(RGBColor(225, 225, 225), 1));
    if integer_ticks || whole_ticks(xs, TICKS) {
        mesh.x_label_formatter(&int_label);
    }
    if integer_ticks || whole_ticks(ys, TICKS) {
        mesh.y_label_formatter(&int_label);
    }
    if !grid {
        mesh.disable_mesh();
    }
    mesh.draw().map_err(|e| draw_err(kind, e))
}

/// The legend of the series drawn with a label, boxed, at `position`.
pub(super) fn legend_box<'a, 'b: 'a>(
    ch: &mut Chart<'a, 'b>,
    position: SeriesLabelPosition,
    look: Look,
    kind: FigureKind,
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

/// The corner of the plot whose legend-sized box (the outer 45 % of the width and 30 % of the
/// height) holds the fewest of `pts` (the points of the curves and guides drawn), `prefer`
/// first among equals, so that a legend does not cover the data it explains.
pub(super) fn emptiest_corner(
    pts: &[(f64, f64)],
    x: &Range<f64>,
    y: &Range<f64>,
    prefer: SeriesLabelPosition,
) -> SeriesLabelPosition {
    use SeriesLabelPosition::{LowerLeft, LowerRight, UpperLeft, UpperRight};
    let (w, h) = (x.end - x.start, y.end - y.start);
    let inside = |corner: &SeriesLabelPosition| {
        let (right, upper) = match corner {
            UpperRight => (true, true),
            UpperLeft => (false, true),
            LowerRight => (true, false),
            _ => (false, false),
        };
        let xs = if right {
            (x.end - 0.45 * w)..=x.end
        } else {
            x.start..=(x.start + 0.45 * w)
        };
        let ys = if upper {
            (y.end - 0.3 * h)..=y.end
        } else {
            y.start..=(y.start + 0.3 * h)
        };
        pts.iter()
            .filter(|p| xs.contains(&p.0) && ys.contains(&p.1))
            .count()
    };
    let mut order = vec![prefer];
    for c in [UpperRight, UpperLeft, LowerRight, LowerLeft] {
        if !order
            .iter()
            .any(|o| std::mem::discriminant(o) == std::mem::discriminant(&c))
        {
            order.push(c);
        }
    }
    let best = order.iter().map(inside).min().unwrap_or(0);
    order
        .into_iter()
        .find(|c| inside(c) == best)
        .unwrap_or(UpperRight)
}

/// A legend entry's sample: a short line in `style`.
pub(super) fn line_sample(
    style: ShapeStyle,
    look: Look,
) -> impl Fn((i32, i32)) -> PathElement<(i32, i32)> {
    move |(x, y)| PathElement::new([(x, y), (x + look.i(20), y)], style)
}

/// The finite points of a curve.
pub(super) fn finite(curve: &[[f64; 2]]) -> Vec<(f64, f64)> {
    curve
        .iter()
        .filter(|p| p[0].is_finite() && p[1].is_finite())
        .map(|p| (p[0], p[1]))
        .collect()
}

/// Whether a curve has a finite point.
pub(super) fn any_finite(curve: &[[f64; 2]]) -> bool {
    curve.iter().any(|p| p[0].is_finite() && p[1].is_finite())
}

/// A range around the finite values of `v`, padded by 5 % (and never empty).
pub(super) fn padded(v: impl Iterator<Item = f64>, include: &[f64]) -> Range<f64> {
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

/// The largest finite second coordinate of the curves (0 when none).
pub(super) fn max_of<'a>(curves: impl Iterator<Item = &'a [[f64; 2]]>) -> f64 {
    curves
        .flat_map(|c| c.iter())
        .filter(|p| p[0].is_finite() && p[1].is_finite())
        .map(|p| p[1])
        .fold(0.0, f64::max)
}

/// A magnitude axis from 0 to a little above `hi` (0..1 when `hi` is not positive).
pub(super) fn magnitude_range(hi: f64) -> Range<f64> {
    if hi.is_finite() && hi > 0.0 {
        0.0..hi * 1.08
    } else {
        0.0..1.0
    }
}

/// Ticks of a logarithmic axis over [lo, hi] (0 < lo < hi): 1, 2 and 5 times the powers of
/// ten inside, or every integer multiple when that gives fewer than three.
pub(super) fn log_ticks(lo: f64, hi: f64) -> Vec<f64> {
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

/// A tick value of a log axis (m·10^k, m = 1…9) with as many decimals as its magnitude needs:
/// one significant digit in plain notation ([`format::plain`]: 0.02, 0.5, 20, 1000000).
pub(super) fn tick_label(v: &f64) -> String {
    format::plain(*v, 1)
}

/// Stems from 0 to each point, with a filled marker of `radius` (× scale) on top when there
/// are at most [`MAX_MARKERS`]; labelled `label` in the legend.
#[allow(clippy::too_many_arguments)]
pub(super) fn stems(
    ch: &mut Chart<'_, '_>,
    pts: &[(f64, f64)],
    colour: RGBColor,
    radius: u32,
    label: &str,
    look: Look,
    kind: FigureKind,
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
pub(super) fn nyquist_lines(
    ch: &mut Chart<'_, '_>,
    rate: f64,
    y: &Range<f64>,
    look: Look,
    kind: FigureKind,
) -> Result<(), ExportError> {
    let red = look.line(NYQUIST, 1);
    let half = 0.5 * rate;
    ch.draw_series([
        PathElement::new(vec![(-half, y.start), (-half, y.end)], red),
        PathElement::new(vec![(half, y.start), (half, y.end)], red),
    ])
    .map_err(|e| draw_err(kind, e))?
    .label("Nyquist ±f_s/2")
    .legend(line_sample(red, look));
    Ok(())
}

/// What an image figure shows.
pub(super) struct ImageSpec<'a> {
    pub image: &'a ImageData,
    pub x: Range<f64>,
    pub y: Range<f64>,
    pub x_desc: &'a str,
    pub y_desc: &'a str,
    pub integer_ticks: bool,
    pub lo: f64,
    pub hi: f64,
    pub colormap: Colormap,
    /// Description of the colour bar, if one is drawn.
    pub bar: Option<&'a str>,
}

/// A colour range from f32 bounds: (0, 1) when one is not finite, widened by 10⁻³ when empty.
pub(super) fn ordered_range((lo, hi): (f32, f32)) -> (f64, f64) {
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

impl Frame<'_, '_> {
    /// Puts `img` over the pixel rectangle `range` (absolute pixels of the page), at the
    /// image's own resolution.
    fn paint(
        &mut self,
        range: (Range<i32>, Range<i32>),
        img: Rgb,
        kind: FigureKind,
    ) -> Result<(), ExportError> {
        let (xr, yr) = range;
        let w = (xr.end - xr.start).max(1) as u32;
        let h = (yr.end - yr.start).max(1) as u32;
        let placed = PlacedImage {
            at: (xr.start, yr.start),
            size: (w, h),
            image: Arc::new(img),
        };
        self.root.draw(&placed).map_err(|e| draw_err(kind, e))
    }

    /// An image through its colour map on axes, with a colour bar right of it when
    /// `spec.bar` names one.
    pub(super) fn image(
        &mut self,
        body: &Area<'_>,
        kind: FigureKind,
        spec: ImageSpec<'_>,
    ) -> Result<(), ExportError> {
        let rgb = Rgb {
            width: spec.image.width as u32,
            height: spec.image.height as u32,
            data: crate::model::colorize(
                spec.image.values.as_slice(),
                spec.lo,
                spec.hi,
                spec.colormap,
            ),
        };
        self.picture(body, kind, |_, _| rgb, &spec)
    }

    /// A picture already in colour over the axes of `spec` (whose `image` is not read), with
    /// the colour bar of `spec.colormap` over [lo, hi] right of it when `spec.bar` names one.
    /// `rgb(width, height)` makes the picture given the plotting area's size in pixels (a
    /// picture of that size is placed pixel for pixel; another is scaled to it, nearest
    /// neighbour).
    pub(super) fn picture(
        &mut self,
        body: &Area<'_>,
        kind: FigureKind,
        rgb: impl FnOnce(u32, u32) -> Rgb,
        spec: &ImageSpec<'_>,
    ) -> Result<(), ExportError> {
        let look = self.look;
        let (main, bar_area) = if spec.bar.is_some() {
            let (w, _) = body.dim_in_pixel();
            body.split_horizontally(w - look.u(BAR_PART))
        } else {
            (body.clone(), body.clone())
        };
        let mut ch = chart(&main, spec.x.clone(), spec.y.clone(), look, kind)?;
        let (xr, yr) = ch.plotting_area().get_pixel_range();
        let size = (
            (xr.end - xr.start).max(1) as u32,
            (yr.end - yr.start).max(1) as u32,
        );
        self.paint((xr, yr), rgb(size.0, size.1), kind)?;
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
            self.paint(bar.plotting_area().get_pixel_range(), gradient, kind)?;
            bar_axis(&mut bar, desc, look, kind)?;
        }
        Ok(())
    }
}

/// The value axis of a colour bar (its chart's y axis): ticks, whole numbers without ".0",
/// and the description `desc` (what the colour means, with its unit).
pub(super) fn bar_axis(
    bar: &mut Chart<'_, '_>,
    desc: &str,
    look: Look,
    kind: FigureKind,
) -> Result<(), ExportError> {
    const BAR_TICKS: usize = 6;
    let whole = whole_ticks(bar.y_range(), BAR_TICKS);
    let mut mesh = bar.configure_mesh();
    mesh.disable_mesh()
        .disable_x_axis()
        .x_labels(0)
        .y_labels(BAR_TICKS)
        .y_desc(desc)
        .label_style(look.text(TICK_PX))
        .axis_desc_style(look.text(DESC_PX))
        .axis_style(look.line(BLACK, 1))
        .set_all_tick_mark_size(look.i(5));
    if whole {
        mesh.y_label_formatter(&int_label);
    }
    mesh.draw().map_err(|e| draw_err(kind, e))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_legend_goes_to_the_corner_the_curve_leaves_empty() {
        use SeriesLabelPosition::*;
        let (x, y) = (0.0..1.0, 0.0..1.0);
        // A curve falling from the top left: the upper right is free.
        let falling: Vec<(f64, f64)> = (0..=100)
            .map(|i| (i as f64 / 100.0, 1.0 - i as f64 / 100.0))
            .collect();
        assert!(matches!(
            emptiest_corner(&falling, &x, &y, UpperRight),
            UpperRight
        ));
        // A curve rising to the top right: the preferred corner is taken, the upper left is free.
        let rising: Vec<(f64, f64)> = (0..=100)
            .map(|i| (i as f64 / 100.0, i as f64 / 100.0))
            .collect();
        assert!(matches!(
            emptiest_corner(&rising, &x, &y, UpperRight),
            UpperLeft
        ));
        // A curve along the bottom: the preference among the free upper corners stands.
        let flat: Vec<(f64, f64)> = (0..=100).map(|i| (i as f64 / 100.0, 0.05)).collect();
        assert!(matches!(
            emptiest_corner(&flat, &x, &y, LowerRight),
            UpperRight
        ));
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

    /// The tick labels are what they were before the one formatter (decimals from the
    /// magnitude's floor), for every tick any log axis can have: m·10^k, m = 1…9, |k| ≤ 15.
    #[test]
    fn tick_labels_are_unchanged_on_every_log_tick() {
        let before = |v: f64| {
            let decimals = (-v.log10().floor()).max(0.0) as usize;
            format!("{v:.decimals$}")
        };
        for lo in [1e-15, 3e-9, 1e-3, 0.7, 5.0, 1e3, 2e6, 1e12] {
            for v in log_ticks(lo, lo * 1e3) {
                assert_eq!(tick_label(&v), before(v), "{v:e}");
            }
        }
        for k in -15..=15 {
            for m in 1..=9 {
                let v = f64::from(m) * 10f64.powi(k);
                assert_eq!(tick_label(&v), before(v), "{v:e}");
            }
        }
    }

    #[test]
    fn whole_ticks_drop_their_decimals_and_fractional_ones_keep_them() {
        // A kernel of radius 2 padded by a quarter: ticks −2, −1, 0, 1, 2.
        assert!(whole_ticks(-2.25..2.25, TICKS));
        assert!(whole_ticks(-128.0..128.0, TICKS));
        // The unit square and a magnitude axis: 0.0, 0.2, …
        assert!(!whole_ticks(0.0..1.0, TICKS));
        assert!(!whole_ticks(-0.05..1.08, TICKS));
    }

    #[test]
    fn degenerate_colour_ranges_are_widened() {
        assert_eq!(ordered_range((1.0, 1.0)), (1.0, 1.0 + 1e-3));
        assert_eq!(ordered_range((f32::NAN, 1.0)), (0.0, 1.0));
        assert_eq!(ordered_range((-1.0, 2.0)), (-1.0, 2.0));
    }
}
