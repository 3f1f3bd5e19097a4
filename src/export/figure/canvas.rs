//! The one drawing surface of every figure: a bitmap (text by [`CrispText`]) or SVG text,
//! behind one plotters backend, so that each figure is drawn by one non-generic function.
//!
//! [`Canvas`] forwards every [`DrawingBackend`] method to the backend it holds, unchanged:
//! a figure drawn on it is the figure drawn on that backend directly, byte for byte.

use super::text::CrispText;
use crate::export::ExportError;
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters_backend::{
    BackendColor, BackendCoord, BackendStyle, BackendTextStyle, DrawingBackend, DrawingErrorKind,
};
use std::sync::OnceLock;

/// The font family every text uses (registered from bytes, see [`ensure_font`]).
pub(super) const FONT: &str = "sans-serif";

type BitmapError = <BitMapBackend<'static> as DrawingBackend>::ErrorType;
type SvgError = <SVGBackend<'static> as DrawingBackend>::ErrorType;

/// A bitmap or an SVG document being drawn.
pub enum Canvas<'a> {
    /// An RGB buffer whose text is drawn by `CrispText` (boxed: the font tables make it
    /// large).
    Bitmap(Box<CrispText<BitMapBackend<'a>>>),
    /// SVG text (the viewer lays out the text).
    Svg(SVGBackend<'a>),
}

/// A drawing area of a [`Canvas`].
pub type Area<'a> = DrawingArea<Canvas<'a>, Shift>;

/// A chart with linear f64 axes on a [`Canvas`].
pub(super) type Chart<'a, 'b> =
    ChartContext<'a, Canvas<'b>, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// Why the canvas's backend failed.
#[derive(Debug)]
pub enum CanvasError {
    /// The bitmap backend's error.
    Bitmap(BitmapError),
    /// The SVG backend's error.
    Svg(SvgError),
}

impl std::fmt::Display for CanvasError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            CanvasError::Bitmap(e) => e.fmt(f),
            CanvasError::Svg(e) => e.fmt(f),
        }
    }
}

impl std::error::Error for CanvasError {}

fn lift<E: std::error::Error + Send + Sync>(
    e: DrawingErrorKind<E>,
    wrap: impl FnOnce(E) -> CanvasError,
) -> DrawingErrorKind<CanvasError> {
    match e {
        DrawingErrorKind::DrawingError(x) => DrawingErrorKind::DrawingError(wrap(x)),
        DrawingErrorKind::FontError(x) => DrawingErrorKind::FontError(x),
    }
}

/// Forwards a backend call to the backend the canvas holds.
macro_rules! forward {
    ($self:ident, $b:ident => $call:expr) => {
        match $self {
            Canvas::Bitmap($b) => $call.map_err(|e| lift(e, CanvasError::Bitmap)),
            Canvas::Svg($b) => $call.map_err(|e| lift(e, CanvasError::Svg)),
        }
    };
}

impl DrawingBackend for Canvas<'_> {
    type ErrorType = CanvasError;

    fn get_size(&self) -> (u32, u32) {
        match self {
            Canvas::Bitmap(b) => b.get_size(),
            Canvas::Svg(b) => b.get_size(),
        }
    }

    fn ensure_prepared(&mut self) -> Result<(), DrawingErrorKind<CanvasError>> {
        forward!(self, b => b.ensure_prepared())
    }

    fn present(&mut self) -> Result<(), DrawingErrorKind<CanvasError>> {
        forward!(self, b => b.present())
    }

    fn draw_pixel(
        &mut self,
        point: BackendCoord,
        color: BackendColor,
    ) -> Result<(), DrawingErrorKind<CanvasError>> {
        forward!(self, b => b.draw_pixel(point, color))
    }

    fn draw_line<S: BackendStyle>(
        &mut self,
        from: BackendCoord,
        to: BackendCoord,
        style: &S,
    ) -> Result<(), DrawingErrorKind<CanvasError>> {
        forward!(self, b => b.draw_line(from, to, style))
    }

    fn draw_rect<S: BackendStyle>(
        &mut self,
        upper_left: BackendCoord,
        bottom_right: BackendCoord,
        style: &S,
        fill: bool,
    ) -> Result<(), DrawingErrorKind<CanvasError>> {
        forward!(self, b => b.draw_rect(upper_left, bottom_right, style, fill))
    }

    fn draw_path<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        path: I,
        style: &S,
    ) -> Result<(), DrawingErrorKind<CanvasError>> {
        forward!(self, b => b.draw_path(path, style))
    }

    fn draw_circle<S: BackendStyle>(
        &mut self,
        center: BackendCoord,
        radius: u32,
        style: &S,
        fill: bool,
    ) -> Result<(), DrawingErrorKind<CanvasError>> {
        forward!(self, b => b.draw_circle(center, radius, style, fill))
    }

    fn fill_polygon<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        vert: I,
        style: &S,
    ) -> Result<(), DrawingErrorKind<CanvasError>> {
        forward!(self, b => b.fill_polygon(vert, style))
    }

    fn draw_text<TStyle: BackendTextStyle>(
        &mut self,
        text: &str,
        style: &TStyle,
        pos: BackendCoord,
    ) -> Result<(), DrawingErrorKind<CanvasError>> {
        forward!(self, b => b.draw_text(text, style, pos))
    }

    fn estimate_text_size<TStyle: BackendTextStyle>(
        &self,
        text: &str,
        style: &TStyle,
    ) -> Result<(u32, u32), DrawingErrorKind<CanvasError>> {
        forward!(self, b => b.estimate_text_size(text, style))
    }

    fn blit_bitmap(
        &mut self,
        pos: BackendCoord,
        size: (u32, u32),
        src: &[u8],
    ) -> Result<(), DrawingErrorKind<CanvasError>> {
        forward!(self, b => b.blit_bitmap(pos, size, src))
    }
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
