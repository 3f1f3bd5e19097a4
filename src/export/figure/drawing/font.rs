//! The figures' one font and its layout: lines of positioned glyphs, outlines, glyph placement.

use super::*;
use crate::export::ExportError;
use ab_glyph::{Font, FontRef, GlyphId, OutlineCurve, PxScale, ScaleFont};
use std::sync::OnceLock;

/// A glyph of a text run: its font glyph id, its pen position (on the baseline) in the
/// run's own frame (x right, y down, the run's box starting at (0, 0)) and its size relative
/// to the run's (1, or [`SCRIPT_SIZE`] in a sub- or superscript).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct PlacedGlyph {
    pub id: u16,
    pub x: f32,
    pub y: f32,
    pub size: f32,
}

/// The figures' font.
pub(crate) struct FigureFont {
    pub font: FontRef<'static>,
    pub bytes: &'static [u8],
}

/// The figures' one font (Ubuntu Light, the font egui ships), parsed once.
pub(crate) fn font() -> Result<&'static FigureFont, ExportError> {
    static FONT: OnceLock<Option<FigureFont>> = OnceLock::new();
    FONT.get_or_init(|| {
        let bytes = epaint_default_fonts::UBUNTU_LIGHT;
        FontRef::try_from_slice(bytes)
            .ok()
            .map(|font| FigureFont { font, bytes })
    })
    .as_ref()
    .ok_or_else(|| ExportError::Draw {
        figure: "font",
        message: "the built-in font could not be parsed".into(),
    })
}

/// A laid-out line of text at `px` pixels per line height (ab_glyph's scale): its glyphs on
/// a baseline at the ascent, the pixels per font unit, and the box (width, height).
pub(crate) struct Line {
    pub glyphs: Vec<PlacedGlyph>,
    pub scale: f32,
    pub width: f32,
    pub height: f32,
}

impl FigureFont {
    /// Lays out `text` on one line: advances and kerning at sub-pixel positions.
    pub(crate) fn layout(&self, text: &str, px: f32) -> Line {
        let sf = self.font.as_scaled(PxScale::from(px));
        let ascent = sf.ascent();
        let mut x = 0.0f32;
        let mut prev: Option<GlyphId> = None;
        let mut glyphs = Vec::with_capacity(text.len());
        for (kind, run) in scripts(text) {
            let (size, y) = match kind {
                Script::Normal => (1.0, ascent),
                Script::Sub => (SCRIPT_SIZE, ascent + 0.18 * px),
                Script::Super => (SCRIPT_SIZE, ascent - 0.36 * px),
            };
            for c in run.chars() {
                let id = sf.glyph_id(c);
                if let Some(p) = prev {
                    x += sf.kern(p, id) * size;
                }
                glyphs.push(PlacedGlyph {
                    id: id.0,
                    x,
                    y,
                    size,
                });
                x += sf.h_advance(id) * size;
                prev = Some(id);
            }
        }
        Line {
            glyphs,
            scale: sf.h_scale_factor(),
            width: x,
            height: ascent - sf.descent(),
        }
    }

    /// The outline of glyph `id` in font units (y up), as path commands.
    pub(crate) fn outline(&self, id: u16) -> Vec<Seg> {
        let mut segs = Vec::new();
        let Some(outline) = self.font.outline(GlyphId(id)) else {
            return segs;
        };
        let mut at: Option<[f32; 2]> = None;
        for c in &outline.curves {
            let (start, seg) = match *c {
                OutlineCurve::Line(a, b) => ([a.x, a.y], Seg::Line([b.x, b.y])),
                OutlineCurve::Quad(a, b, c) => ([a.x, a.y], Seg::Quad([b.x, b.y], [c.x, c.y])),
                OutlineCurve::Cubic(a, b, c, d) => {
                    ([a.x, a.y], Seg::Cubic([b.x, b.y], [c.x, c.y], [d.x, d.y]))
                }
            };
            if at != Some(start) {
                if at.is_some() {
                    segs.push(Seg::Close);
                }
                segs.push(Seg::Move(start));
            }
            at = Some(seg.end());
            segs.push(seg);
        }
        if at.is_some() {
            segs.push(Seg::Close);
        }
        segs
    }
}

/// A path command of a glyph outline.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Seg {
    Move([f32; 2]),
    Line([f32; 2]),
    Quad([f32; 2], [f32; 2]),
    Cubic([f32; 2], [f32; 2], [f32; 2]),
    Close,
}

impl Seg {
    fn end(self) -> [f32; 2] {
        match self {
            Seg::Move(p) | Seg::Line(p) | Seg::Quad(_, p) | Seg::Cubic(_, _, p) => p,
            Seg::Close => [0.0, 0.0],
        }
    }
}

/// The affine map (a, b, c, d, e, f): (u, v) ↦ (a u + c v + e, b u + d v + f) from a glyph's
/// font units (y up) to the page, for glyph `g` of a text run.
pub(crate) fn glyph_matrix(
    origin: [f32; 2],
    rot: [f32; 4],
    scale: f32,
    g: PlacedGlyph,
) -> [f32; 6] {
    let [a, b, c, d] = rot;
    let scale = scale * g.size;
    [
        a * scale,
        b * scale,
        -c * scale,
        -d * scale,
        origin[0] + a * g.x + c * g.y,
        origin[1] + b * g.x + d * g.y,
    ]
}
