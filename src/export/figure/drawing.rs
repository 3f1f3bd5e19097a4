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

use super::Rgb;
use crate::export::ExportError;
use ab_glyph::{Font, FontRef, GlyphId, OutlineCurve, PxScale, ScaleFont};
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::sync::{Arc, OnceLock};

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

/// Size of sub- and superscripts relative to the text.
pub(crate) const SCRIPT_SIZE: f32 = 0.7;

/// Where a run of text sits: on the baseline, or as a sub- or superscript.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Script {
    Normal,
    Sub,
    Super,
}

/// Splits `text` into runs of normal text, subscripts and superscripts. The figures write
/// subscripts as `f_s`, `F_r`, `Φ_p1` and superscripts as `N^s`, `N^-1`: a `_` or `^` right
/// after a one-letter symbol (a letter not preceded by a letter or digit; for `^` also a
/// number: `10^-3`), followed by one or
/// two letters or digits (a superscript may start with a minus) and then nothing that
/// continues a word or another marker, marks a script; the marker is not drawn. Anything
/// else is literal (`per_pixel`, `my_scene_v2`, `a_b_c`, a lone `^`), so that the labels users
/// write stay as they are.
fn scripts(text: &str) -> Vec<(Script, String)> {
    let chars: Vec<char> = text.chars().collect();
    let mut out: Vec<(Script, String)> = Vec::new();
    let mut push = |kind: Script, c: char| match out.last_mut() {
        Some((k, s)) if *k == kind => s.push(c),
        _ => out.push((kind, c.to_string())),
    };
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        // The symbol: one letter, not the end of a word.
        let after_symbol = i > 0
            && chars[i - 1].is_alphabetic()
            && !(i > 1 && (chars[i - 2].is_alphanumeric() || matches!(chars[i - 2], '_' | '^')));
        // A power of a number: digits not ending a word (10^-3).
        let after_number = c == '^' && i > 0 && chars[i - 1].is_ascii_digit() && {
            let mut k = i - 1;
            while k > 0 && chars[k - 1].is_ascii_digit() {
                k -= 1;
            }
            k == 0 || !(chars[k - 1].is_alphanumeric() || matches!(chars[k - 1], '_' | '^' | '.'))
        };
        if (c == '_' || c == '^') && (after_symbol || after_number) {
            let mut j = i + 1;
            if c == '^' && matches!(chars.get(j), Some('-' | '−')) {
                j += 1;
            }
            let start = j;
            while j < chars.len() && chars[j].is_alphanumeric() && j - start < 3 {
                j += 1;
            }
            let len = j - start;
            let ends = !chars
                .get(j)
                .is_some_and(|c| c.is_alphanumeric() || *c == '_' || *c == '^');
            if (1..=2).contains(&len) && ends {
                let kind = if c == '_' { Script::Sub } else { Script::Super };
                for &d in &chars[i + 1..j] {
                    push(kind, if d == '-' { '−' } else { d });
                }
                i = j;
                continue;
            }
        }
        push(Script::Normal, c);
        i += 1;
    }
    out
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

/// Rows per band of the parallel rasteriser.
const BAND: u32 = 64;

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

/// What the bands of one raster share (see [`Drawing::prepare`]).
struct Prepared {
    glyphs: BTreeMap<u16, tiny_skia::Path>,
    boxes: Vec<[f32; 2]>,
    stamps: BTreeMap<StampKey, Stamp>,
}

/// A filled circle up to its position's whole pixels: radius, RGBA colour and the centre's
/// fractional pixel offsets, as bits (the canvas puts centres on quarter pixels, so a pattern's
/// markers share at most 16 keys per radius and colour).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
struct StampKey {
    radius: u32,
    rgba: [u8; 4],
    fx: u32,
    fy: u32,
}

/// Largest stamped circle radius in pixels (larger circles are filled as paths).
const MAX_STAMP_RADIUS: f32 = 32.0;

impl StampKey {
    /// The key of a filled circle of finite centre and radius up to [`MAX_STAMP_RADIUS`].
    fn of(op: &Op) -> Option<StampKey> {
        let Op::Circle {
            centre,
            radius,
            fill: true,
            color,
            ..
        } = op
        else {
            return None;
        };
        let ok = centre.iter().all(|c| c.is_finite() && c.abs() < 1e7);
        if !(ok && *radius > 0.0 && *radius <= MAX_STAMP_RADIUS) {
            return None;
        }
        let c = color.skia().to_color_u8();
        Some(StampKey {
            radius: radius.to_bits(),
            rgba: [c.red(), c.green(), c.blue(), c.alpha()],
            fx: (centre[0] - centre[0].floor()).to_bits(),
            fy: (centre[1] - centre[1].floor()).to_bits(),
        })
    }
}

/// A filled circle rasterised once, antialiased, on a transparent square (premultiplied
/// RGBA), and composited source-over wherever the same circle is drawn at another whole-pixel
/// position: the coverage tiny-skia computes for the circle there (its supersampling grid is
/// aligned to whole pixels), without a path fill per marker.
struct Stamp {
    /// Pixels from the centre's whole pixel to the stamp's left and top edge.
    reach: i64,
    side: u32,
    rgba: Vec<u8>,
}

impl Stamp {
    fn new(key: StampKey) -> Option<Stamp> {
        let radius = f32::from_bits(key.radius);
        let reach = radius.ceil() as i64 + 1;
        let side = 2 * reach as u32 + 2;
        let mut pm = tiny_skia::Pixmap::new(side, side)?;
        let [r, g, b, a] = key.rgba;
        let mut paint = tiny_skia::Paint::default();
        paint.set_color_rgba8(r, g, b, a);
        paint.anti_alias = true;
        let (cx, cy) = (
            reach as f32 + f32::from_bits(key.fx),
            reach as f32 + f32::from_bits(key.fy),
        );
        let path = tiny_skia::PathBuilder::from_circle(cx, cy, radius)?;
        pm.fill_path(
            &path,
            &paint,
            tiny_skia::FillRule::Winding,
            tiny_skia::Transform::identity(),
            None,
        );
        Some(Stamp {
            reach,
            side,
            rgba: pm.take(),
        })
    }

    /// Composites the stamp for the circle at `centre` (of this stamp's key) into `pm`, the
    /// band whose top row is page row `y0`: source-over as tiny-skia's pipeline does it
    /// (d ← s + d·(255 − sₐ)/255, rounded up by (v + 255) >> 8).
    fn blend(&self, pm: &mut tiny_skia::Pixmap, centre: [f32; 2], y0: u32) {
        let (pw, ph) = (pm.width() as i64, pm.height() as i64);
        let x0 = centre[0].floor() as i64 - self.reach;
        let top = centre[1].floor() as i64 - self.reach - y0 as i64;
        let side = self.side as i64;
        let data = pm.data_mut();
        for sy in 0..side {
            let y = top + sy;
            if !(0..ph).contains(&y) {
                continue;
            }
            for sx in 0..side {
                let x = x0 + sx;
                if !(0..pw).contains(&x) {
                    continue;
                }
                let s = &self.rgba[((sy * side + sx) * 4) as usize..][..4];
                if s[3] == 0 {
                    continue;
                }
                let inv = 255 - s[3] as u16;
                let d = &mut data[((y * pw + x) * 4) as usize..][..4];
                for c in 0..4 {
                    d[c] = (s[c] as u16 + ((d[c] as u16 * inv + 255) >> 8)) as u8;
                }
            }
        }
    }
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

    /// The drawing rasterised, antialiased, on white: 8-bit RGB, row 0 at the top.
    ///
    /// The page is drawn in bands of [`BAND`] rows, in parallel, each band drawing the
    /// shapes that reach it with the page shifted up by a whole number of rows (so a band's
    /// pixels are those of the whole page); the bands do not depend on the number of threads,
    /// so neither do the bytes.
    pub(crate) fn raster(&self) -> Result<Rgb, ExportError> {
        self.raster_with(true)
    }

    /// [`Drawing::raster`], with the circle stamps or (the reference) every circle filled as
    /// a path.
    fn raster_with(&self, stamps: bool) -> Result<Rgb, ExportError> {
        use rayon::prelude::*;
        let prep = self.prepare(stamps)?;
        let row_bytes = self.width as usize * 3;
        let mut data = vec![0u8; row_bytes * self.height as usize];
        data.par_chunks_mut(row_bytes * BAND as usize)
            .enumerate()
            .try_for_each(|(b, out)| {
                let y0 = b as u32 * BAND;
                self.raster_band(y0, (out.len() / row_bytes) as u32, &prep, out)
            })?;
        Ok(Rgb {
            width: self.width,
            height: self.height,
            data,
        })
    }

    /// The drawing rasterised as [`Drawing::raster`] does, as a PNG file with `text`: worker
    /// threads rasterise the bands (taking the next band in page order as they finish one)
    /// while the calling thread encodes the finished bands in order, so that the encoding
    /// overlaps the rasterising. The same bytes as encoding [`Drawing::raster`]'s image.
    pub(crate) fn png(&self, text: &[(String, String)]) -> Result<Vec<u8>, ExportError> {
        use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering::Relaxed};
        let prep = self.prepare(true)?;
        let mut enc = crate::export::encode::RowEncoder::new(self.width, self.height)?;
        let bands = self.height.div_ceil(BAND) as usize;
        let workers = std::thread::available_parallelism()
            .map_or(1, |n| n.get())
            .clamp(1, bands);
        let row_bytes = self.width as usize * 3;
        let (next, stop) = (AtomicUsize::new(0), AtomicBool::new(false));
        std::thread::scope(|scope| -> Result<(), ExportError> {
            type Band = (usize, Result<Vec<u8>, ExportError>);
            let (tx, rx) = std::sync::mpsc::channel::<Band>();
            for _ in 0..workers {
                let (tx, next, stop, prep) = (tx.clone(), &next, &stop, &prep);
                scope.spawn(move || {
                    while !stop.load(Relaxed) {
                        let b = next.fetch_add(1, Relaxed);
                        if b >= bands {
                            break;
                        }
                        let y0 = b as u32 * BAND;
                        let rows = BAND.min(self.height - y0);
                        let mut out = vec![0u8; row_bytes * rows as usize];
                        let band = self.raster_band(y0, rows, prep, &mut out).map(|()| out);
                        if tx.send((b, band)).is_err() {
                            break;
                        }
                    }
                });
            }
            drop(tx);
            // Bands arrive nearly in order; the few ahead of the encoder wait here.
            let mut ahead = BTreeMap::new();
            let mut want = 0;
            let result = rx.iter().try_for_each(|(b, band)| {
                ahead.insert(b, band);
                while let Some(band) = ahead.remove(&want) {
                    enc.rows(&band?)?;
                    want += 1;
                }
                Ok(())
            });
            if result.is_err() {
                stop.store(true, Relaxed);
            }
            result
        })?;
        enc.finish(text)
    }

    /// What every band shares: each glyph's outline once, each shape's row span, and the
    /// coverage stamps of the filled circles drawn more than once at the same radius, colour
    /// and sub-pixel position (the markers of a pattern) when `stamps`.
    fn prepare(&self, stamps: bool) -> Result<Prepared, ExportError> {
        let font = font()?;
        if self.width == 0 || self.height == 0 {
            return Err(ExportError::Draw {
                figure: "raster",
                message: "the page has no pixels".into(),
            });
        }
        let glyphs: BTreeMap<u16, tiny_skia::Path> = self
            .glyphs_used()
            .into_keys()
            .filter_map(|id| Some((id, skia_path(&font.outline(id))?)))
            .collect();
        let boxes: Vec<[f32; 2]> = self.ops.iter().map(|op| op.rows(font)).collect();
        let mut uses: BTreeMap<StampKey, usize> = BTreeMap::new();
        if stamps {
            for op in &self.ops {
                if let Some(key) = StampKey::of(op) {
                    *uses.entry(key).or_default() += 1;
                }
            }
        }
        let stamps = uses
            .into_iter()
            .filter(|&(_, n)| n > 1)
            .filter_map(|(key, _)| Some((key, Stamp::new(key)?)))
            .collect();
        Ok(Prepared {
            glyphs,
            boxes,
            stamps,
        })
    }

    /// Rows `y0 .. y0 + rows` of the page as RGB into `out`.
    fn raster_band(
        &self,
        y0: u32,
        rows: u32,
        prep: &Prepared,
        out: &mut [u8],
    ) -> Result<(), ExportError> {
        let (glyphs, boxes) = (&prep.glyphs, &prep.boxes);
        use tiny_skia::{
            FillRule, LineCap, LineJoin, Paint, PathBuilder, Pixmap, Stroke, Transform,
        };
        // White, opaque: written once.
        let size =
            tiny_skia::IntSize::from_wh(self.width, rows).ok_or_else(|| ExportError::Draw {
                figure: "raster",
                message: "the page has no pixels".into(),
            })?;
        let white = vec![255u8; self.width as usize * rows as usize * 4];
        let mut pm = Pixmap::from_vec(white, size).ok_or_else(|| ExportError::Draw {
            figure: "raster",
            message: "the page has no pixels".into(),
        })?;
        let shift = Transform::from_translate(0.0, -(y0 as f32));
        let (top, bottom) = (y0 as f32, (y0 + rows) as f32);
        let paint = |c: Rgba| {
            let mut p = Paint::default();
            p.set_color(c.skia());
            p.anti_alias = true;
            p
        };
        let poly = |points: &[[f32; 2]], closed: bool| {
            let mut pb = PathBuilder::new();
            for (i, p) in points.iter().enumerate() {
                if i == 0 {
                    pb.move_to(p[0], p[1]);
                } else {
                    pb.line_to(p[0], p[1]);
                }
            }
            if closed {
                pb.close();
            }
            pb.finish()
        };
        for (i, (op, &[lo, hi])) in self.ops.iter().zip(boxes).enumerate() {
            if hi < top || lo > bottom || (i == 0 && self.is_page_fill(op)) {
                continue;
            }
            match op {
                Op::Stroke {
                    points,
                    closed,
                    width,
                    color,
                } => {
                    if let Some(path) = poly(points, *closed) {
                        let stroke = Stroke {
                            width: *width,
                            line_cap: LineCap::Square,
                            line_join: LineJoin::Round,
                            ..Stroke::default()
                        };
                        pm.stroke_path(&path, &paint(*color), &stroke, shift, None);
                    }
                }
                Op::Fill { points, color } => {
                    if let Some(path) = poly(points, true) {
                        pm.fill_path(&path, &paint(*color), FillRule::Winding, shift, None);
                    }
                }
                Op::Circle {
                    centre,
                    radius,
                    fill,
                    width,
                    color,
                } => {
                    if let Some(stamp) = StampKey::of(op).and_then(|k| prep.stamps.get(&k)) {
                        stamp.blend(&mut pm, *centre, y0);
                    } else if let Some(path) =
                        PathBuilder::from_circle(centre[0], centre[1], *radius)
                    {
                        if *fill {
                            pm.fill_path(&path, &paint(*color), FillRule::Winding, shift, None);
                        } else {
                            let stroke = Stroke {
                                width: *width,
                                ..Stroke::default()
                            };
                            pm.stroke_path(&path, &paint(*color), &stroke, shift, None);
                        }
                    }
                }
                Op::Text {
                    glyphs: run,
                    origin,
                    rot,
                    scale,
                    color,
                    ..
                } => {
                    let p = paint(*color);
                    for g in run {
                        if let Some(path) = glyphs.get(&g.id) {
                            let [a, b, c, d, e, f] = glyph_matrix(*origin, *rot, *scale, *g);
                            pm.fill_path(
                                path,
                                &p,
                                FillRule::Winding,
                                Transform::from_row(a, b, c, d, e, f - y0 as f32),
                                None,
                            );
                        }
                    }
                }
                Op::Image {
                    x,
                    y,
                    width,
                    height,
                    image,
                } => blit_nearest(&mut pm, image, [*x, *y - y0 as f32, *width, *height]),
            }
        }
        // Every pixel is opaque (the page is white), so premultiplied RGBA is plain RGB.
        for (dst, src) in out.chunks_exact_mut(3).zip(pm.data().chunks_exact(4)) {
            dst.copy_from_slice(&src[..3]);
        }
        Ok(())
    }

    /// The drawing as an SVG document of `width` × `height` user units, with `title` and the
    /// metadata lines (`key: value`) as `<title>` and `<desc>`.
    pub(crate) fn svg(&self, meta: &[(String, String)]) -> Result<String, ExportError> {
        let font = font()?;
        let (w, h) = (self.width, self.height);
        let mut out = String::with_capacity(16 * 1024);
        let _ = writeln!(
            out,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" \
             width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\">"
        );
        let title = meta
            .iter()
            .find(|(k, _)| k == "Title")
            .map(|(_, v)| v.as_str())
            .unwrap_or("");
        let desc = meta
            .iter()
            .map(|(k, v)| format!("{}: {}", escape(k), escape(v)))
            .collect::<Vec<_>>()
            .join("\n");
        let _ = writeln!(out, "<title>{}</title>\n<desc>{desc}</desc>", escape(title));
        // Each glyph's outline once; glyphs without one (spaces) are not placed.
        let outlined: BTreeMap<u16, String> = self
            .glyphs_used()
            .into_keys()
            .map(|id| (id, svg_path(&font.outline(id))))
            .filter(|(_, d)| !d.is_empty())
            .collect();
        if !outlined.is_empty() {
            out.push_str("<defs>\n");
            for (id, d) in &outlined {
                let _ = writeln!(out, "<path id=\"g{id}\" d=\"{d}\"/>");
            }
            out.push_str("</defs>\n");
        }
        for op in &self.ops {
            match op {
                Op::Stroke {
                    points,
                    closed,
                    width,
                    color,
                } => {
                    let tag = if *closed { "polygon" } else { "polyline" };
                    let _ = writeln!(
                        out,
                        "<{tag} points=\"{}\" fill=\"none\" stroke=\"{}\"{} stroke-width=\"{}\" \
                         stroke-linecap=\"square\" stroke-linejoin=\"round\"/>",
                        svg_points(points),
                        color.hex(),
                        opacity("stroke-opacity", color.alpha),
                        num(*width)
                    );
                }
                Op::Fill { points, color } => {
                    let _ = writeln!(
                        out,
                        "<polygon points=\"{}\" fill=\"{}\"{}/>",
                        svg_points(points),
                        color.hex(),
                        opacity("fill-opacity", color.alpha)
                    );
                }
                Op::Circle {
                    centre,
                    radius,
                    fill,
                    width,
                    color,
                } => {
                    let paint = if *fill {
                        format!(
                            "fill=\"{}\"{}",
                            color.hex(),
                            opacity("fill-opacity", color.alpha)
                        )
                    } else {
                        format!(
                            "fill=\"none\" stroke=\"{}\"{} stroke-width=\"{}\"",
                            color.hex(),
                            opacity("stroke-opacity", color.alpha),
                            num(*width)
                        )
                    };
                    let _ = writeln!(
                        out,
                        "<circle cx=\"{}\" cy=\"{}\" r=\"{}\" {paint}/>",
                        num(centre[0]),
                        num(centre[1]),
                        num(*radius)
                    );
                }
                Op::Text {
                    text,
                    glyphs,
                    origin,
                    rot,
                    scale,
                    color,
                } => {
                    let _ = writeln!(
                        out,
                        "<g role=\"img\" aria-label=\"{}\" fill=\"{}\"{}>",
                        escape(text),
                        color.hex(),
                        opacity("fill-opacity", color.alpha)
                    );
                    for g in glyphs.iter().filter(|g| outlined.contains_key(&g.id)) {
                        let m = glyph_matrix(*origin, *rot, *scale, *g);
                        let _ = writeln!(
                            out,
                            "<use xlink:href=\"#g{}\" transform=\"matrix({})\"/>",
                            g.id,
                            m.iter().map(|v| fine(*v)).collect::<Vec<_>>().join(" ")
                        );
                    }
                    out.push_str("</g>\n");
                }
                Op::Image {
                    x,
                    y,
                    width,
                    height,
                    image,
                } => {
                    let png = super::encode_png(image, &[])?;
                    let _ = writeln!(
                        out,
                        "<image x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" \
                         preserveAspectRatio=\"none\" image-rendering=\"optimizeSpeed\" \
                         style=\"image-rendering:pixelated\" \
                         xlink:href=\"data:image/png;base64,{}\"/>",
                        num(*x),
                        num(*y),
                        num(*width),
                        num(*height),
                        base64(&png)
                    );
                }
            }
        }
        out.push_str("</svg>\n");
        Ok(out)
    }
}

/// Copies `img` nearest-neighbour over `rect` (pixel centres map to pixel centres), clipped
/// to the page.
fn blit_nearest(pm: &mut tiny_skia::Pixmap, img: &Rgb, rect: [f32; 4]) {
    let (pw, ph) = (pm.width() as i64, pm.height() as i64);
    let [x, y, w, h] = rect;
    if img.width == 0 || img.height == 0 || w <= 0.0 || h <= 0.0 {
        return;
    }
    let x0 = (x.round() as i64).clamp(0, pw);
    let x1 = ((x + w).round() as i64).clamp(0, pw);
    let y0 = (y.round() as i64).clamp(0, ph);
    let y1 = ((y + h).round() as i64).clamp(0, ph);
    let (sw, sh) = (img.width as f32, img.height as f32);
    let cols: Vec<usize> = (x0..x1)
        .map(|px| {
            (((px as f32 + 0.5 - x) / w * sw).floor().max(0.0) as usize).min(img.width as usize - 1)
        })
        .collect();
    let data = pm.data_mut();
    for py in y0..y1 {
        let sy = (((py as f32 + 0.5 - y) / h * sh).floor().max(0.0) as usize)
            .min(img.height as usize - 1);
        let src = &img.data[sy * img.width as usize * 3..(sy + 1) * img.width as usize * 3];
        let row = (py * pw) as usize * 4;
        for (i, &sx) in cols.iter().enumerate() {
            let d = row + (x0 as usize + i) * 4;
            data[d..d + 3].copy_from_slice(&src[sx * 3..sx * 3 + 3]);
            data[d + 3] = 255;
        }
    }
}

fn skia_path(segs: &[Seg]) -> Option<tiny_skia::Path> {
    let mut pb = tiny_skia::PathBuilder::new();
    for s in segs {
        match *s {
            Seg::Move(p) => pb.move_to(p[0], p[1]),
            Seg::Line(p) => pb.line_to(p[0], p[1]),
            Seg::Quad(c, p) => pb.quad_to(c[0], c[1], p[0], p[1]),
            Seg::Cubic(c1, c2, p) => pb.cubic_to(c1[0], c1[1], c2[0], c2[1], p[0], p[1]),
            Seg::Close => pb.close(),
        }
    }
    pb.finish()
}

fn svg_path(segs: &[Seg]) -> String {
    let mut d = String::new();
    let pt = |p: [f32; 2]| format!("{} {}", num(p[0]), num(p[1]));
    for s in segs {
        let _ = match *s {
            Seg::Move(p) => write!(d, "M{}", pt(p)),
            Seg::Line(p) => write!(d, "L{}", pt(p)),
            Seg::Quad(c, p) => write!(d, "Q{} {}", pt(c), pt(p)),
            Seg::Cubic(a, b, p) => write!(d, "C{} {} {}", pt(a), pt(b), pt(p)),
            Seg::Close => write!(d, "Z"),
        };
    }
    d
}

fn svg_points(points: &[[f32; 2]]) -> String {
    points
        .iter()
        .map(|p| format!("{},{}", num(p[0]), num(p[1])))
        .collect::<Vec<_>>()
        .join(" ")
}

fn opacity(attr: &str, alpha: f32) -> String {
    if alpha >= 1.0 {
        String::new()
    } else {
        format!(" {attr}=\"{}\"", fine(alpha.max(0.0)))
    }
}

/// A length with at most two decimals, trailing zeros dropped ("12", "12.5", "-0.25").
pub(crate) fn num(v: f32) -> String {
    trim(format!("{:.2}", v))
}

/// A coefficient with at most five decimals.
fn fine(v: f32) -> String {
    trim(format!("{:.5}", v))
}

fn trim(s: String) -> String {
    let t = if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.')
    } else {
        &s
    };
    if t == "-0" {
        "0".into()
    } else {
        t.into()
    }
}

/// Standard base64 (RFC 4648, with padding).
pub(crate) fn base64(bytes: &[u8]) -> String {
    const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let b = [
            chunk[0],
            chunk.get(1).copied().unwrap_or(0),
            chunk.get(2).copied().unwrap_or(0),
        ];
        let n = (u32::from(b[0]) << 16) | (u32::from(b[1]) << 8) | u32::from(b[2]);
        for i in 0..4 {
            if i <= chunk.len() {
                out.push(ALPHABET[((n >> (18 - 6 * i)) & 63) as usize] as char);
            } else {
                out.push('=');
            }
        }
    }
    out
}

/// XML-escapes `text` for element content and attribute values.
pub(crate) fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '&' => out.push_str("&amp;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            '\n' => out.push_str("&#10;"),
            other => out.push(other),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::BTreeSet;

    fn ink(img: &Rgb) -> usize {
        img.data.chunks_exact(3).filter(|p| p[0] < 250).count()
    }

    /// 3000 markers of two radii and colours at quarter-pixel centres (seed 11), a translucent
    /// one and one across the page's edge, over a line: many share a stamp.
    fn markers() -> Drawing {
        let mut d = Drawing::new(300, 200);
        d.ops.push(Op::Stroke {
            points: vec![[0.0, 100.5], [300.0, 100.5]],
            closed: false,
            width: 1.0,
            color: Rgba::BLACK,
        });
        let mut state = 11u64;
        let mut next = |m: u64| {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (state >> 33) % m
        };
        for i in 0..3000 {
            let (x, y) = (next(1240) as f32 / 4.0 - 5.0, next(840) as f32 / 4.0 - 5.0);
            d.ops.push(Op::Circle {
                centre: [x, y],
                radius: if i % 3 == 0 { 2.25 } else { 1.5 },
                fill: true,
                width: 0.0,
                color: Rgba {
                    rgb: if i % 2 == 0 {
                        [20, 20, 20]
                    } else {
                        [31, 119, 180]
                    },
                    alpha: if i % 7 == 0 { 0.5 } else { 1.0 },
                },
            });
        }
        d
    }

    #[test]
    fn circle_stamps_match_filling_each_circle_as_a_path() {
        let d = markers();
        let stamped = d.raster_with(true).unwrap();
        let filled = d.raster_with(false).unwrap();
        // The pixels on the edge of a band's pixmap (a band's top and bottom rows, the page's
        // first and last columns) are left out: there tiny-skia fills a path clipped by the
        // pixmap, and the edge pixel comes out up to ~16 levels off the unclipped coverage; a
        // stamp is rasterised whole and only clipped pixel by pixel, so it is right there too.
        let (w, h) = (d.width as usize, d.height as usize);
        let edge = |y: usize, x: usize| {
            matches!(y as u32 % BAND, 0 | 63) || y == h - 1 || x == 0 || x == w - 1
        };
        let diffs: Vec<i32> = (0..stamped.data.len())
            .filter(|i| !edge(i / 3 / w, (i / 3) % w))
            .map(|i| (stamped.data[i] as i32 - filled.data[i] as i32).abs())
            .collect();
        let max = diffs.iter().copied().max().unwrap();
        let mean = diffs.iter().sum::<i32>() as f64 / diffs.len() as f64;
        // Rounding only (coverage applied before or while compositing; a level or two per
        // marker, three where translucent markers overlap): under a quarter level on average
        // over this dense page, where most pixels lie under a marker's antialiased edge.
        assert!(max <= 3, "largest difference {max}");
        assert!(mean < 0.25, "mean difference {mean}");
        assert!(ink(&filled) > 10_000, "the markers are drawn");
    }

    #[test]
    fn the_pipelined_png_is_the_raster_encoded() {
        let d = markers();
        let meta = [("Title".to_string(), "markers".to_string())];
        let img = d.raster().unwrap();
        let whole = crate::export::encode::png_rgb(img.width, img.height, &img.data, &meta);
        assert_eq!(d.png(&meta).unwrap(), whole.unwrap());
    }

    #[test]
    fn scripts_are_marked_after_a_letter_and_one_or_two_characters_long() {
        use Script::*;
        let s = |t: &str| scripts(t);
        assert_eq!(
            s("f_s/2"),
            vec![
                (Normal, "f".into()),
                (Sub, "s".into()),
                (Normal, "/2".into())
            ]
        );
        assert_eq!(
            s("Φ_p1(i)"),
            vec![
                (Normal, "Φ".into()),
                (Sub, "p1".into()),
                (Normal, "(i)".into())
            ]
        );
        assert_eq!(s("N^-1"), vec![(Normal, "N".into()), (Super, "−1".into())]);
        assert_eq!(
            s("10^-3"),
            vec![(Normal, "10".into()), (Super, "−3".into())]
        );
        // Words, repeated markers and markers after a non-letter stay literal.
        for literal in [
            "per_pixel",
            "my_scene_v2",
            "log10_power",
            "a_b_c",
            "x ^ 2",
            "2_3",
            "x10^2",
            "_s",
        ] {
            assert_eq!(s(literal), vec![(Normal, literal.into())], "{literal}");
        }
    }

    #[test]
    fn scripts_are_smaller_and_off_the_baseline_and_the_marker_is_not_drawn() {
        let font = font().unwrap();
        let plain = font.layout("fs", 20.0);
        let sub = font.layout("f_s", 20.0);
        let sup = font.layout("f^s", 20.0);
        assert_eq!(sub.glyphs.len(), 2);
        assert_eq!(sub.glyphs[0], plain.glyphs[0]);
        let (s, p) = (sub.glyphs[1], plain.glyphs[1]);
        assert_eq!((s.id, s.size), (p.id, SCRIPT_SIZE));
        assert!(
            s.y > p.y && sup.glyphs[1].y < p.y,
            "below and above the baseline"
        );
        assert!(sub.width < plain.width);
    }

    #[test]
    fn base64_matches_rfc4648_vectors() {
        assert_eq!(base64(b""), "");
        assert_eq!(base64(b"f"), "Zg==");
        assert_eq!(base64(b"fo"), "Zm8=");
        assert_eq!(base64(b"foo"), "Zm9v");
        assert_eq!(base64(b"foob"), "Zm9vYg==");
        assert_eq!(base64(b"fooba"), "Zm9vYmE=");
        assert_eq!(base64(b"foobar"), "Zm9vYmFy");
        assert_eq!(base64(&[0xff, 0xfe, 0xfd]), "//79");
    }

    #[test]
    fn numbers_are_short_and_signless_at_zero() {
        assert_eq!(num(12.0), "12");
        assert_eq!(num(12.5), "12.5");
        assert_eq!(num(-0.001), "0");
        assert_eq!(num(0.126), "0.13");
        assert_eq!(fine(0.123456), "0.12346");
    }

    #[test]
    fn a_one_pixel_line_on_pixel_centres_covers_one_row_exactly() {
        let mut d = Drawing::new(20, 10);
        d.ops.push(Op::Stroke {
            points: vec![[2.5, 4.5], [17.5, 4.5]],
            closed: false,
            width: 1.0,
            color: Rgba::BLACK,
        });
        let img = d.raster().unwrap();
        for y in 0..10usize {
            for x in 0..20usize {
                let v = img.data[(y * 20 + x) * 3];
                let want = if y == 4 && (2..=17).contains(&x) {
                    0
                } else {
                    255
                };
                assert_eq!(v, want, "pixel ({x}, {y})");
            }
        }
    }

    #[test]
    fn a_diagonal_line_is_antialiased() {
        let mut d = Drawing::new(40, 40);
        d.ops.push(Op::Stroke {
            points: vec![[2.0, 3.0], [38.0, 30.0]],
            closed: false,
            width: 1.5,
            color: Rgba::BLACK,
        });
        let img = d.raster().unwrap();
        let partial = img
            .data
            .chunks_exact(3)
            .filter(|p| p[0] > 10 && p[0] < 245)
            .count();
        let full = img.data.chunks_exact(3).filter(|p| p[0] <= 10).count();
        assert!(partial > full / 2, "blended {partial}, solid {full}");
    }

    #[test]
    fn text_is_drawn_where_its_layout_says_and_rotated_runs_are_vertical() {
        let f = font().unwrap();
        let line = f.layout("periodogram", 26.0);
        assert!(line.width > 100.0 && line.width < 160.0, "{}", line.width);
        let mut d = Drawing::new(200, 200);
        d.ops.push(Op::Text {
            text: "periodogram".into(),
            glyphs: line.glyphs.clone(),
            origin: [20.0, 20.0],
            rot: [1.0, 0.0, 0.0, 1.0],
            scale: line.scale,
            color: Rgba::BLACK,
        });
        let img = d.raster().unwrap();
        let (mut x0, mut x1, mut y0, mut y1) = (usize::MAX, 0, usize::MAX, 0);
        for (i, p) in img.data.chunks_exact(3).enumerate() {
            if p[0] < 128 {
                let (x, y) = (i % 200, i / 200);
                x0 = x0.min(x);
                x1 = x1.max(x);
                y0 = y0.min(y);
                y1 = y1.max(y);
            }
        }
        assert!(
            x0 >= 20 && (x1 as f32) <= 20.0 + line.width + 1.0,
            "{x0}..{x1}"
        );
        assert!(
            y0 >= 20 && (y1 as f32) <= 20.0 + line.height + 1.0,
            "{y0}..{y1}"
        );
        assert!(x1 - x0 > 3 * (y1 - y0), "a horizontal run");
        // The same run turned by R = Rotate270, as plotters' y-axis labels.
        let mut v = Drawing::new(200, 200);
        v.ops.push(Op::Text {
            text: "periodogram".into(),
            glyphs: line.glyphs,
            origin: [20.0, 180.0],
            rot: [0.0, -1.0, 1.0, 0.0],
            scale: line.scale,
            color: Rgba::BLACK,
        });
        let img = v.raster().unwrap();
        let rows: BTreeSet<usize> = img
            .data
            .chunks_exact(3)
            .enumerate()
            .filter(|(_, p)| p[0] < 128)
            .map(|(i, _)| i / 200)
            .collect();
        let cols: BTreeSet<usize> = img
            .data
            .chunks_exact(3)
            .enumerate()
            .filter(|(_, p)| p[0] < 128)
            .map(|(i, _)| i % 200)
            .collect();
        assert!(
            rows.len() > 3 * cols.len(),
            "{} rows, {} cols",
            rows.len(),
            cols.len()
        );
        assert!(ink(&img) > 100);
    }

    #[test]
    fn placing_a_drawing_translates_every_shape() {
        let mut a = Drawing::new(10, 10);
        a.ops.push(Op::Circle {
            centre: [1.0, 2.0],
            radius: 1.0,
            fill: true,
            width: 0.0,
            color: Rgba::BLACK,
        });
        a.ops.push(Op::Image {
            x: 0.0,
            y: 0.0,
            width: 2.0,
            height: 2.0,
            image: Arc::new(Rgb {
                width: 1,
                height: 1,
                data: vec![0, 0, 0],
            }),
        });
        let mut page = Drawing::new(100, 100);
        page.place(a, 10.0, 20.0);
        assert!(matches!(
            page.ops[0],
            Op::Circle {
                centre: [11.0, 22.0],
                ..
            }
        ));
        assert!(matches!(
            page.ops[1],
            Op::Image {
                x: 10.0,
                y: 20.0,
                ..
            }
        ));
    }

    #[test]
    fn images_are_nearest_neighbour_over_their_rectangle() {
        let mut d = Drawing::new(8, 4);
        d.ops.push(Op::Image {
            x: 2.0,
            y: 0.0,
            width: 4.0,
            height: 4.0,
            // 2×2: black, white / white, black.
            image: Arc::new(Rgb {
                width: 2,
                height: 2,
                data: vec![0, 0, 0, 255, 255, 255, 255, 255, 255, 0, 0, 0],
            }),
        });
        let img = d.raster().unwrap();
        let at = |x: usize, y: usize| img.data[(y * 8 + x) * 3];
        assert_eq!(
            [at(1, 0), at(2, 0), at(3, 1), at(4, 0), at(6, 0)],
            [255, 0, 0, 255, 255]
        );
        assert_eq!([at(2, 2), at(4, 3), at(5, 2)], [255, 0, 0]);
    }
}
