//! The figures' one vector drawing, and its two pictures: an antialiased raster (tiny-skia)
//! and SVG text. The PDF writer (`pdf.rs`) reads the same drawing.
//!
//! A figure is laid out once (by plotters, onto [`super::Canvas`], which records what it is
//! asked to draw) into a [`Drawing`]: a list of strokes, fills, circles, text runs and images
//! in page pixels, y down, in continuous coordinates (pixel `i` of the raster spans
//! `[i, i + 1)`; the canvas records plotters' coordinates at quarter-pixel precision and
//! snaps axis-aligned lines to whole pixels, so that a one-pixel axis line covers exactly one
//! row of pixels in every picture). Text is kept as positioned
//! glyphs of the figures' one font (Ubuntu Light, from egui's fonts): the raster fills their
//! outlines, the SVG draws the same outlines (defined once in `<defs>` and placed with
//! `<use>`, so no viewer needs the font), the PDF shows them with the font embedded. So the
//! PNG is the SVG's picture, and the same inputs give the same bytes.

mod base64;
mod font;
mod markup;
mod raster;
mod svg;
#[cfg(test)]
mod tests;

pub(crate) use base64::base64;
pub(crate) use font::{font, glyph_matrix, FigureFont, PlacedGlyph, Seg};
pub(crate) use markup::SCRIPT_SIZE;
use markup::{scripts, Script};

use super::Rgb;
use ab_glyph::Font;
use std::collections::BTreeMap;
use std::sync::Arc;

/// A colour with opacity in `0.0..=1.0`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Rgba {
    pub rgb: [u8; 3],
    pub alpha: f32,
}

impl Rgba {
    pub const WHITE: Rgba = Rgba {
        rgb: [255, 255, 255],
        alpha: 1.0,
    };
    pub const BLACK: Rgba = Rgba {
        rgb: [0, 0, 0],
        alpha: 1.0,
    };

    fn hex(self) -> String {
        format!("#{:02x}{:02x}{:02x}", self.rgb[0], self.rgb[1], self.rgb[2])
    }

    fn skia(self) -> tiny_skia::Color {
        tiny_skia::Color::from_rgba8(
            self.rgb[0],
            self.rgb[1],
            self.rgb[2],
            (self.alpha.clamp(0.0, 1.0) * 255.0).round() as u8,
        )
    }
}

/// One shape of a drawing. Lengths are page pixels.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Op {
    /// A polyline (closed: a polygon outline), square caps, round joins.
    Stroke {
        points: Vec<[f32; 2]>,
        closed: bool,
        width: f32,
        color: Rgba,
    },
    /// A filled polygon (non-zero winding).
    Fill { points: Vec<[f32; 2]>, color: Rgba },
    /// A circle, filled or stroked.
    Circle {
        centre: [f32; 2],
        radius: f32,
        fill: bool,
        width: f32,
        color: Rgba,
    },
    /// A run of glyphs: page point = `origin` + R · (frame point), R = `rot` as
    /// (a, b, c, d): (x, y) ↦ (a x + c y, b x + d y); `scale` maps font units to pixels.
    Text {
        text: String,
        glyphs: Vec<PlacedGlyph>,
        origin: [f32; 2],
        rot: [f32; 4],
        scale: f32,
        color: Rgba,
    },
    /// An image shown nearest-neighbour over the rectangle (x, y, width, height).
    Image {
        x: f32,
        y: f32,
        width: f32,
        height: f32,
        image: Arc<Rgb>,
    },
}

impl Op {
    /// The colour a shape is painted in (images carry their own).
    pub(crate) fn color(&self) -> Option<Rgba> {
        match self {
            Op::Stroke { color, .. }
            | Op::Fill { color, .. }
            | Op::Circle { color, .. }
            | Op::Text { color, .. } => Some(*color),
            Op::Image { .. } => None,
        }
    }

    /// The rows `[top, bottom]` the shape can touch (a conservative bound: strokes widened by
    /// their width, text by its line height and width).
    fn rows(&self, font: &FigureFont) -> [f32; 2] {
        let span = |points: &[[f32; 2]], pad: f32| {
            let (lo, hi) = points
                .iter()
                .fold((f32::INFINITY, f32::NEG_INFINITY), |(lo, hi), p| {
                    (lo.min(p[1]), hi.max(p[1]))
                });
            [lo - pad, hi + pad]
        };
        match self {
            Op::Stroke { points, width, .. } => span(points, *width + 1.0),
            Op::Fill { points, .. } => span(points, 1.0),
            Op::Circle {
                centre,
                radius,
                width,
                ..
            } => [
                centre[1] - radius - width - 1.0,
                centre[1] + radius + width + 1.0,
            ],
            Op::Text {
                glyphs,
                origin,
                rot,
                scale,
                ..
            } => {
                // Each glyph lies within a line height of its pen position, whatever the
                // rotation.
                let em = (font.font.ascent_unscaled() - font.font.descent_unscaled()).abs() * scale;
                let (lo, hi) =
                    glyphs
                        .iter()
                        .fold((f32::INFINITY, f32::NEG_INFINITY), |(lo, hi), g| {
                            let y = origin[1] + rot[1] * g.x + rot[3] * g.y;
                            (lo.min(y), hi.max(y))
                        });
                [lo - 1.5 * em, hi + 1.5 * em]
            }
            Op::Image { y, height, .. } => [*y - 1.0, *y + height + 1.0],
        }
    }

    fn translate(&mut self, dx: f32, dy: f32) {
        let shift = |p: &mut [f32; 2]| {
            p[0] += dx;
            p[1] += dy;
        };
        match self {
            Op::Stroke { points, .. } | Op::Fill { points, .. } => {
                points.iter_mut().for_each(shift)
            }
            Op::Circle { centre, .. } => shift(centre),
            Op::Text { origin, .. } => shift(origin),
            Op::Image { x, y, .. } => {
                *x += dx;
                *y += dy;
            }
        }
    }
}

/// A page of `width` × `height` pixels and what is drawn on it, in order.
#[derive(Debug, Clone, PartialEq, Default)]
pub(crate) struct Drawing {
    pub width: u32,
    pub height: u32,
    pub ops: Vec<Op>,
}

impl Drawing {
    /// An empty page.
    pub(crate) fn new(width: u32, height: u32) -> Drawing {
        Drawing {
            width,
            height,
            ops: Vec::new(),
        }
    }

    /// Whether `op` paints this whole page opaque white (a figure's background: the raster
    /// starts white, and a placed figure lies on a white page already).
    fn is_page_fill(&self, op: &Op) -> bool {
        let (w, h) = (self.width as f32, self.height as f32);
        matches!(op, Op::Fill { points, color }
            if *color == Rgba::WHITE
                && points.len() == 4
                && points.iter().all(|p| (p[0] == 0.0 || p[0] == w) && (p[1] == 0.0 || p[1] == h))
                && points.iter().any(|p| p[0] == w && p[1] == h))
    }

    /// Draws `other` over this drawing with its top-left corner at (dx, dy); its white
    /// background is left out when this drawing starts with one (the page is white there).
    pub(crate) fn place(&mut self, other: Drawing, dx: f32, dy: f32) {
        let skip = self.ops.first().is_some_and(|op| self.is_page_fill(op))
            && other.ops.first().is_some_and(|op| other.is_page_fill(op));
        self.ops
            .extend(other.ops.into_iter().skip(usize::from(skip)).map(|mut op| {
                op.translate(dx, dy);
                op
            }));
    }

    /// The glyphs the drawing's text uses, with a character each shows (for the PDF's
    /// ToUnicode map), in glyph order.
    pub(crate) fn glyphs_used(&self) -> BTreeMap<u16, char> {
        let mut used = BTreeMap::new();
        for op in &self.ops {
            if let Op::Text { text, glyphs, .. } = op {
                for (g, ch) in glyphs.iter().zip(text.chars()) {
                    used.entry(g.id).or_insert(ch);
                }
            }
        }
        used
    }
}
