//! The one drawing surface of every figure: a plotters backend that records what it is asked
//! to draw into a [`Drawing`] (see `drawing.rs`), so that each figure is laid out once and
//! its PNG, SVG and PDF are pictures of the same shapes.
//!
//! plotters speaks integer pixel coordinates. The canvas tells it the page is [`SUB`] times
//! larger than it is (the figures lay out with every length × `SUB`) and records every
//! coordinate divided by `SUB`: curves, markers and text get quarter-pixel positions (and
//! markers fractional radii), so the antialiased raster shows smooth curves instead of
//! stair-steps of whole pixels. Axis-aligned lines and rectangles (axes, ticks, grids,
//! frames, stems) are snapped to whole pixels (a line of odd width onto pixel centres), so
//! they stay crisp in every picture.

use super::drawing::{font, Drawing, Op, Rgba};
use super::Rgb;
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::element::{Drawable, PointCollection};
use plotters::prelude::*;
use plotters_backend::text_anchor::{HPos, VPos};
use plotters_backend::{
    BackendColor, BackendCoord, BackendStyle, BackendTextStyle, DrawingBackend, DrawingErrorKind,
    FontTransform,
};
use std::sync::Arc;

/// The font family every text names (the canvas draws every text in the figures' one font).
pub(super) const FONT: &str = "sans-serif";

/// plotters' pixels per page pixel.
pub(super) const SUB: u32 = 4;
const K: f32 = SUB as f32;

/// A figure being drawn: it appends to the drawing it borrows.
pub struct Canvas<'a> {
    drawing: &'a mut Drawing,
}

impl<'a> Canvas<'a> {
    /// A canvas over `drawing` (its size is the page's).
    pub(crate) fn new(drawing: &'a mut Drawing) -> Canvas<'a> {
        Canvas { drawing }
    }

    fn push(&mut self, op: Op) {
        self.drawing.ops.push(op);
    }
}

/// A drawing area of a [`Canvas`].
pub type Area<'a> = DrawingArea<Canvas<'a>, Shift>;

/// A chart with linear f64 axes on a [`Canvas`].
pub(super) type Chart<'a, 'b> =
    ChartContext<'a, Canvas<'b>, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// Why the canvas failed (only the font can).
#[derive(Debug)]
pub struct CanvasError(String);

impl std::fmt::Display for CanvasError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for CanvasError {}

fn colour(c: BackendColor) -> Rgba {
    Rgba {
        rgb: [c.rgb.0, c.rgb.1, c.rgb.2],
        alpha: c.alpha.clamp(0.0, 1.0) as f32,
    }
}

/// The page point of plotters' pixel `p` (its centre).
fn centre(p: BackendCoord) -> [f32; 2] {
    [(p.0 as f32 + 0.5) / K, (p.1 as f32 + 0.5) / K]
}

/// A page line width of a plotters stroke width (at least a quarter pixel).
fn width<S: BackendStyle>(style: &S) -> f32 {
    style.stroke_width().max(1) as f32 / K
}

/// `v` snapped so that a line `w` wide across it covers whole pixels: onto a pixel centre
/// for odd widths, onto a pixel edge for even ones.
fn snap(v: f32, w: f32) -> f32 {
    if (w.round() as i64) % 2 == 1 {
        v.floor() + 0.5
    } else {
        v.round()
    }
}

/// A two-point stroke, snapped when horizontal or vertical.
fn segment(a: [f32; 2], b: [f32; 2], w: f32) -> Vec<[f32; 2]> {
    if a[1] == b[1] {
        let y = snap(a[1], w);
        vec![[a[0], y], [b[0], y]]
    } else if a[0] == b[0] {
        let x = snap(a[0], w);
        vec![[x, a[1]], [x, b[1]]]
    } else {
        vec![a, b]
    }
}

/// The rotation (a, b, c, d), (x, y) ↦ (a x + c y, b x + d y), of a plotters text transform.
fn rotation(t: FontTransform) -> [f32; 4] {
    match t {
        FontTransform::None => [1.0, 0.0, 0.0, 1.0],
        FontTransform::Rotate90 => [0.0, 1.0, -1.0, 0.0],
        FontTransform::Rotate180 => [-1.0, 0.0, 0.0, -1.0],
        FontTransform::Rotate270 => [0.0, -1.0, 1.0, 0.0],
    }
}

type Result<T> = std::result::Result<T, DrawingErrorKind<CanvasError>>;

/// A label as it should read: a number that is a negative zero ("-0.0", the default tick
/// formatting of a tiny negative value) loses its sign.
fn tidy(text: &str) -> std::borrow::Cow<'_, str> {
    match text.strip_prefix('-').or_else(|| text.strip_prefix('−')) {
        Some(rest) if rest.parse::<f64>().is_ok_and(|v| v == 0.0) => rest.to_string().into(),
        _ => text.into(),
    }
}

fn font_err(e: crate::export::ExportError) -> DrawingErrorKind<CanvasError> {
    DrawingErrorKind::DrawingError(CanvasError(e.to_string()))
}

impl DrawingBackend for Canvas<'_> {
    type ErrorType = CanvasError;

    fn get_size(&self) -> (u32, u32) {
        (self.drawing.width * SUB, self.drawing.height * SUB)
    }

    fn ensure_prepared(&mut self) -> Result<()> {
        Ok(())
    }

    fn present(&mut self) -> Result<()> {
        Ok(())
    }

    fn draw_pixel(&mut self, p: BackendCoord, color: BackendColor) -> Result<()> {
        if color.alpha > 0.0 {
            let (x, y, d) = (p.0 as f32 / K, p.1 as f32 / K, 1.0 / K);
            self.push(Op::Fill {
                points: vec![[x, y], [x + d, y], [x + d, y + d], [x, y + d]],
                color: colour(color),
            });
        }
        Ok(())
    }

    fn draw_line<S: BackendStyle>(
        &mut self,
        from: BackendCoord,
        to: BackendCoord,
        style: &S,
    ) -> Result<()> {
        if style.color().alpha > 0.0 {
            let w = width(style);
            self.push(Op::Stroke {
                points: segment(centre(from), centre(to), w),
                closed: false,
                width: w,
                color: colour(style.color()),
            });
        }
        Ok(())
    }

    fn draw_rect<S: BackendStyle>(
        &mut self,
        ul: BackendCoord,
        br: BackendCoord,
        style: &S,
        fill: bool,
    ) -> Result<()> {
        if style.color().alpha <= 0.0 {
            return Ok(());
        }
        let (x0, x1) = (ul.0.min(br.0), ul.0.max(br.0));
        let (y0, y1) = (ul.1.min(br.1), ul.1.max(br.1));
        if fill {
            // Whole page pixels: plotters' pixels a..=b are [a, b + 1) / SUB, rounded.
            let edge = |v: i32| (v as f32 / K).round();
            let (x0, y0, x1, y1) = (edge(x0), edge(y0), edge(x1 + 1), edge(y1 + 1));
            self.push(Op::Fill {
                points: vec![[x0, y0], [x1, y0], [x1, y1], [x0, y1]],
                color: colour(style.color()),
            });
        } else {
            let w = width(style);
            let (a, b) = (centre((x0, y0)), centre((x1, y1)));
            let (l, t, r, b) = (snap(a[0], w), snap(a[1], w), snap(b[0], w), snap(b[1], w));
            self.push(Op::Stroke {
                points: vec![[l, t], [r, t], [r, b], [l, b]],
                closed: true,
                width: w,
                color: colour(style.color()),
            });
        }
        Ok(())
    }

    fn draw_path<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        path: I,
        style: &S,
    ) -> Result<()> {
        let mut points: Vec<[f32; 2]> = path.into_iter().map(centre).collect();
        if style.color().alpha > 0.0 && points.len() >= 2 {
            if points.len() == 2 {
                points = segment(points[0], points[1], width(style));
            }
            self.push(Op::Stroke {
                points,
                closed: false,
                width: width(style),
                color: colour(style.color()),
            });
        }
        Ok(())
    }

    fn draw_circle<S: BackendStyle>(
        &mut self,
        c: BackendCoord,
        radius: u32,
        style: &S,
        fill: bool,
    ) -> Result<()> {
        if style.color().alpha > 0.0 {
            self.push(Op::Circle {
                centre: centre(c),
                radius: radius.max(1) as f32 / K,
                fill,
                width: width(style),
                color: colour(style.color()),
            });
        }
        Ok(())
    }

    fn fill_polygon<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        vert: I,
        style: &S,
    ) -> Result<()> {
        let points: Vec<[f32; 2]> = vert.into_iter().map(centre).collect();
        if style.color().alpha > 0.0 && points.len() >= 3 {
            self.push(Op::Fill {
                points,
                color: colour(style.color()),
            });
        }
        Ok(())
    }

    fn draw_text<TStyle: BackendTextStyle>(
        &mut self,
        text: &str,
        style: &TStyle,
        pos: BackendCoord,
    ) -> Result<()> {
        let color = style.color();
        if color.alpha <= 0.0 || text.is_empty() {
            return Ok(());
        }
        let text = &*tidy(text);
        let line = font()
            .map_err(font_err)?
            .layout(text, style.size() as f32 / K);
        // Anchor offsets in the text's own (unrotated) frame, as plotters' backends do.
        let dx = match style.anchor().h_pos {
            HPos::Left => 0.0,
            HPos::Center => -line.width / 2.0,
            HPos::Right => -line.width,
        };
        let dy = match style.anchor().v_pos {
            VPos::Top => 0.0,
            VPos::Center => -line.height / 2.0,
            VPos::Bottom => -line.height,
        };
        let rot = rotation(style.transform());
        let [a, b, c, d] = rot;
        self.push(Op::Text {
            text: text.to_string(),
            glyphs: line.glyphs,
            origin: [
                pos.0 as f32 / K + a * dx + c * dy,
                pos.1 as f32 / K + b * dx + d * dy,
            ],
            rot,
            scale: line.scale,
            color: colour(color),
        });
        Ok(())
    }

    fn estimate_text_size<TStyle: BackendTextStyle>(
        &self,
        text: &str,
        style: &TStyle,
    ) -> Result<(u32, u32)> {
        let line = font()
            .map_err(font_err)?
            .layout(text, style.size() as f32 / K);
        Ok((
            (line.width * K).ceil() as u32,
            (line.height * K).ceil() as u32,
        ))
    }

    fn blit_bitmap(&mut self, pos: BackendCoord, size: (u32, u32), src: &[u8]) -> Result<()> {
        let (w, h) = size;
        if src.len() != w as usize * h as usize * 3 {
            return Err(DrawingErrorKind::DrawingError(CanvasError(
                "bitmap size does not match its buffer".into(),
            )));
        }
        self.push(Op::Image {
            x: pos.0 as f32 / K,
            y: pos.1 as f32 / K,
            width: w as f32 / K,
            height: h as f32 / K,
            image: Arc::new(Rgb {
                width: w,
                height: h,
                data: src.to_vec(),
            }),
        });
        Ok(())
    }
}

/// An image shown over a pixel rectangle at the image's own resolution (nearest-neighbour
/// in the raster, pixelated in SVG, uninterpolated in PDF): plotters' bitmap element would
/// resample it to the rectangle's pixels first.
pub(super) struct PlacedImage {
    /// The rectangle's top-left pixel (plotters' pixels of the area it is drawn on).
    pub at: BackendCoord,
    /// The rectangle's size in plotters' pixels.
    pub size: (u32, u32),
    pub image: Arc<Rgb>,
}

impl<'b> PointCollection<'b, BackendCoord> for &'b PlacedImage {
    type Point = &'b BackendCoord;
    type IntoIter = std::iter::Once<&'b BackendCoord>;
    fn point_iter(self) -> Self::IntoIter {
        std::iter::once(&self.at)
    }
}

impl<'a> Drawable<Canvas<'a>> for PlacedImage {
    fn draw<I: Iterator<Item = BackendCoord>>(
        &self,
        mut pos: I,
        backend: &mut Canvas<'a>,
        _parent_dim: (u32, u32),
    ) -> Result<()> {
        if let Some((x, y)) = pos.next() {
            backend.push(Op::Image {
                x: x as f32 / K,
                y: y as f32 / K,
                width: self.size.0 as f32 / K,
                height: self.size.1 as f32 / K,
                image: self.image.clone(),
            });
        }
        Ok(())
    }
}

/// Registers the figures' font with plotters once (its own text code is never used to
/// draw, but a text style must name a registered family).
pub(super) fn ensure_font() -> std::result::Result<(), crate::export::ExportError> {
    static REGISTERED: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
    let ok = *REGISTERED.get_or_init(|| {
        plotters::style::register_font(FONT, FontStyle::Normal, epaint_default_fonts::UBUNTU_LIGHT)
            .is_ok()
    });
    font()?;
    if ok {
        Ok(())
    } else {
        Err(crate::export::ExportError::Draw {
            figure: "font",
            message: "the built-in font could not be parsed".into(),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::tidy;

    #[test]
    fn negative_zero_labels_lose_their_sign_and_nothing_else_changes() {
        assert_eq!(tidy("-0.0"), "0.0");
        assert_eq!(tidy("-0"), "0");
        assert_eq!(tidy("−0.00"), "0.00");
        assert_eq!(tidy("-0.5"), "-0.5");
        assert_eq!(tidy("-x"), "-x");
        assert_eq!(tidy("0.0"), "0.0");
    }
}
