//! The one drawing surface of every figure: a plotters backend that records what it is asked
//! to draw into a [`Drawing`] (see `drawing.rs`), so that each figure is laid out once and
//! its PNG, SVG and PDF are pictures of the same shapes.
//!
//! plotters speaks integer pixel coordinates, pixel `i` being the `i`-th row or column of a
//! bitmap; the canvas records them at pixel centres (`i + 0.5`) and a filled rectangle of
//! pixels `a..=b` as the area `[a, b + 1)`, so that one-pixel axis lines and ticks stay
//! crisp in every picture while curves, markers and text are antialiased.

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

fn centre(p: BackendCoord) -> [f32; 2] {
    [p.0 as f32 + 0.5, p.1 as f32 + 0.5]
}

fn width<S: BackendStyle>(style: &S) -> f32 {
    style.stroke_width().max(1) as f32
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

fn font_err(e: crate::export::ExportError) -> DrawingErrorKind<CanvasError> {
    DrawingErrorKind::DrawingError(CanvasError(e.to_string()))
}

impl DrawingBackend for Canvas<'_> {
    type ErrorType = CanvasError;

    fn get_size(&self) -> (u32, u32) {
        (self.drawing.width, self.drawing.height)
    }

    fn ensure_prepared(&mut self) -> Result<()> {
        Ok(())
    }

    fn present(&mut self) -> Result<()> {
        Ok(())
    }

    fn draw_pixel(&mut self, p: BackendCoord, color: BackendColor) -> Result<()> {
        if color.alpha > 0.0 {
            let (x, y) = (p.0 as f32, p.1 as f32);
            self.push(Op::Fill {
                points: vec![[x, y], [x + 1.0, y], [x + 1.0, y + 1.0], [x, y + 1.0]],
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
            self.push(Op::Stroke {
                points: vec![centre(from), centre(to)],
                closed: false,
                width: width(style),
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
            let (x0, y0, x1, y1) = (x0 as f32, y0 as f32, x1 as f32 + 1.0, y1 as f32 + 1.0);
            self.push(Op::Fill {
                points: vec![[x0, y0], [x1, y0], [x1, y1], [x0, y1]],
                color: colour(style.color()),
            });
        } else {
            let (a, b) = (centre((x0, y0)), centre((x1, y1)));
            self.push(Op::Stroke {
                points: vec![a, [b[0], a[1]], b, [a[0], b[1]]],
                closed: true,
                width: width(style),
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
        let points: Vec<[f32; 2]> = path.into_iter().map(centre).collect();
        if style.color().alpha > 0.0 && points.len() >= 2 {
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
                radius: radius.max(1) as f32,
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
        let line = font().map_err(font_err)?.layout(text, style.size() as f32);
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
                pos.0 as f32 + a * dx + c * dy,
                pos.1 as f32 + b * dx + d * dy,
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
        let line = font().map_err(font_err)?.layout(text, style.size() as f32);
        Ok((line.width.ceil() as u32, line.height.ceil() as u32))
    }

    fn blit_bitmap(&mut self, pos: BackendCoord, size: (u32, u32), src: &[u8]) -> Result<()> {
        let (w, h) = size;
        if src.len() != w as usize * h as usize * 3 {
            return Err(DrawingErrorKind::DrawingError(CanvasError(
                "bitmap size does not match its buffer".into(),
            )));
        }
        self.push(Op::Image {
            x: pos.0 as f32,
            y: pos.1 as f32,
            width: w as f32,
            height: h as f32,
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
    /// The rectangle's top-left pixel (in the coordinates of the area it is drawn on).
    pub at: BackendCoord,
    /// The rectangle's size in pixels.
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
                x: x as f32,
                y: y as f32,
                width: self.size.0 as f32,
                height: self.size.1 as f32,
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
