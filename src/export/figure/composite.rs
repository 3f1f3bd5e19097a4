//! Composites for slides: a column's figures under its caption, and every column of a scene
//! under the scene's title, laid out to fill a W:H frame (16:9 unless asked otherwise).
//!
//! **Blocks and panels.** A column is a *block*: its caption (label, N, seed) over its figures
//! (the *panels*). A composite arranges the C blocks (C = 1 for a column composite) in a grid
//! of `block_cols` × `block_rows` (reading order, the last row left-aligned), and the K panels
//! of every block alike in a grid of `panel_cols` per row (row-major, as the GUI's column
//! grid; each row centred in its block). Columns stand side by side as in the app. Under a
//! block caption the panels' titles say only what they plot ("points", "periodogram"), not
//! the column again; a block of sampling-theorem panels is captioned with the theorem's
//! setup and error terms, once, instead of a column and three repeated caption lines.
//!
//! **The layout rule.** Every arrangement without an empty row or column of blocks (or
//! panels) is measured at scale 1 — blocks as wide as their widest panel row, rows as high as
//! their tallest panel, the title band and the shared colour bar included. The figure is
//! scaled to fit inside the W:H frame, and the arrangement whose *panels* then cover the
//! largest fraction of the frame is taken: coverage = A·k²/F for a frame F × 1 (F = W/H),
//! the panels' total area A and the fit k = min(F/w, 1/h) of a w × h figure. So the panels
//! are shown as large as the frame allows, and empty cells, captions and centring gaps count
//! against a layout (the figure's own fill of the frame, [`fill`] = min(a/F, F/a) for its
//! aspect a, follows: a figure that fills its frame badly cannot show its panels large).
//! Ties (within 10⁻⁹) go to more blocks side by side, then fewer panels per row (stacked as
//! in the app), then the smaller figure. Every length scales with the scale, so the choice
//! does not depend on it. The figure is not padded to the frame: it has the chosen grid's
//! own size.
//!
//! **The scene's own figure.** A figure of the whole scene rather than of a column — the
//! integration study's MSE plot, with every column's curve — stands right of the blocks,
//! centred on their height, in a comparison whose column 0 carries it; the layout rule counts
//! it as panel area, so the blocks rearrange around it.
//!
//! **Locked scales.** When every column of a comparison draws its periodogram with the same
//! colour range and map (the GUI's "Lock scales"; `samplescope render` always shares one
//! range), the periodograms are drawn without their bars and one shared bar stands at the
//! right of the first row of blocks, level with their images — where the periodogram ends its
//! row of panels, so that the bar stands beside one (elsewhere each keeps its own bar, with
//! the same range). The layouts are measured each with its own choice.
//!
//! **Titles never cut.** The scene's title wraps onto a second line when it is wider than the
//! figure (less a margin each side), and the second line ends in "…" if the rest does not fit;
//! a column's caption is one line, shortened with "…" to its block's width. Widths are
//! measured with the figures' own text layout (the one every picture of a figure draws).

use super::canvas::ensure_font;
use super::draw::{render_drawing, Role};
use super::drawing::{font, Drawing, Op, Rgba};
use super::spectrum::{SharedBar, SpectrumWithoutBar};
use super::{
    check_scale, context_metadata, encode, figure, rgb_to_rgba, ColumnData, Figure, FigureContext,
    FigureKind, FileFormat, MAX_COMPOSITE_PIXELS,
};
use crate::export::ExportError;
use crate::model::Colormap;
use std::fmt;
use std::str::FromStr;

/// Height of a column's caption band at scale 1.
const CAPTION_H: u32 = 36;
/// Height of the comparison's title band at scale 1 (one line), and of each further line.
const HEADING_H: u32 = 44;
const HEADING_LINE: u32 = 26;
/// Font sizes of the caption and the title at scale 1.
const CAPTION_PX: f64 = 16.0;
const HEADING_PX: f64 = 20.0;
/// Lines of the scene's title at most.
const HEADING_LINES: usize = 2;

/// The shape of a frame, W:H, that a composite is laid out to fill.
///
/// Written `W:H` with W and H positive finite decimal numbers (`16:9`, `4:3`, `1:1`,
/// `2.39:1`); W/H must lie in [`Aspect::RATIOS`] (1:10 to 10:1).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Aspect {
    w: f64,
    h: f64,
}

/// Why a `W:H` text is not an [`Aspect`].
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum AspectError {
    /// Not two numbers separated by one `:`.
    #[error("{text:?}: must be W:H with two positive numbers, e.g. 16:9 or 4:3")]
    Format { text: String },
    /// A side is not a positive finite number.
    #[error("{text:?}: {side} = {value}: must be a positive finite number")]
    Side {
        text: String,
        side: &'static str,
        value: String,
    },
    /// W/H is outside [`Aspect::RATIOS`].
    #[error("{text:?}: W/H = {}: must lie in 0.1..=10 (1:10 to 10:1)", crate::core::params::fmt_num(*.ratio))]
    Ratio { text: String, ratio: f64 },
}

impl Aspect {
    /// A 16:9 slide.
    pub const SLIDE: Aspect = Aspect { w: 16.0, h: 9.0 };

    /// The allowed ratios W/H.
    pub const RATIOS: std::ops::RangeInclusive<f64> = 0.1..=10.0;

    /// W:H from its two sides.
    pub fn new(w: f64, h: f64) -> Result<Aspect, AspectError> {
        format!("{w}:{h}").parse()
    }

    /// W/H.
    pub fn ratio(self) -> f64 {
        self.w / self.h
    }
}

impl Default for Aspect {
    fn default() -> Self {
        Aspect::SLIDE
    }
}

impl fmt::Display for Aspect {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}", self.w, self.h)
    }
}

impl FromStr for Aspect {
    type Err = AspectError;

    fn from_str(text: &str) -> Result<Aspect, AspectError> {
        // User text in messages is cut to 40 characters, numbers to 6 significant digits.
        let shown = crate::core::params::fmt_text(text);
        let format = || AspectError::Format {
            text: shown.clone(),
        };
        let (a, b) = text.trim().split_once(':').ok_or_else(format)?;
        if b.contains(':') {
            return Err(format());
        }
        let side = |s: &str, name: &'static str| -> Result<f64, AspectError> {
            let s = s.trim();
            if s.is_empty() {
                return Err(format());
            }
            match s.parse::<f64>() {
                Ok(v) if v.is_finite() && v > 0.0 => Ok(v),
                _ => Err(AspectError::Side {
                    text: shown.clone(),
                    side: name,
                    value: crate::core::params::fmt_text(s),
                }),
            }
        };
        let (w, h) = (side(a, "W")?, side(b, "H")?);
        let ratio = w / h;
        if !Aspect::RATIOS.contains(&ratio) {
            return Err(AspectError::Ratio { text: shown, ratio });
        }
        Ok(Aspect { w, h })
    }
}

/// How a composite's blocks (columns) and their panels are arranged; see the module docs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Layout {
    /// Blocks per row, and rows of blocks.
    pub block_cols: usize,
    pub block_rows: usize,
    /// Panels per row in a block, and rows of panels.
    pub panel_cols: usize,
    pub panel_rows: usize,
}

impl fmt::Display for Layout {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}×{} columns, {}×{} panels each",
            self.block_cols, self.block_rows, self.panel_cols, self.panel_rows
        )
    }
}

/// (width, height) of every row of panels of a block: `sizes` row-major, `cols` per row.
fn panel_rows(sizes: &[(u32, u32)], cols: usize) -> Vec<(u64, u64)> {
    sizes
        .chunks(cols.max(1))
        .map(|row| {
            let w = row.iter().map(|s| s.0 as u64).sum();
            let h = row.iter().map(|s| s.1 as u64).max().unwrap_or(0);
            (w, h)
        })
        .collect()
}

/// The sizes of a block's panels at scale 1, in order.
type Sizes<'a> = &'a [(u32, u32)];

/// What a layout is measured with, at scale 1.
#[derive(Debug, Clone)]
struct Shape<'a> {
    /// The panels of every block, in order, each with its own colour bar.
    own: &'a [(u32, u32)],
    /// Where the periodograms share one bar: the panels with the periodogram's bar left out,
    /// the periodogram's index and the shared bar's width.
    shared: Option<(Sizes<'a>, usize, u64)>,
    /// Number of blocks.
    blocks: usize,
    /// Height of the band above the blocks (the title).
    head: u64,
    /// A figure of the whole scene right of the blocks (the integration study's plot, which
    /// has every column's curve), at its size.
    side: Option<(u32, u32)>,
}

impl Shape<'_> {
    /// Whether `layout` draws the shared bar: only where the periodogram ends its row of
    /// panels, so that the bar at the right of the first row of blocks stands beside one.
    fn uses_bar(&self, layout: Layout) -> bool {
        self.shared
            .is_some_and(|(p, i, _)| (i + 1) % layout.panel_cols.max(1) == 0 || i + 1 == p.len())
    }

    /// The panels of `layout`'s blocks.
    fn panels(&self, layout: Layout) -> &[(u32, u32)] {
        match self.shared {
            Some((p, _, _)) if self.uses_bar(layout) => p,
            _ => self.own,
        }
    }

    /// The width of the shared bar's strip in `layout` (0 without one).
    fn bar(&self, layout: Layout) -> u64 {
        match self.shared {
            Some((_, _, w)) if self.uses_bar(layout) => w,
            _ => 0,
        }
    }

    /// (block width, block height) of `layout`.
    fn block(&self, layout: Layout) -> (u64, u64) {
        let rows = panel_rows(self.panels(layout), layout.panel_cols);
        let w = rows.iter().map(|r| r.0).max().unwrap_or(0);
        let h = rows.iter().map(|r| r.1).sum::<u64>() + CAPTION_H as u64;
        (w, h)
    }

    /// (width, height) of the blocks of `layout` with the shared bar (no title, no side figure).
    fn grid(&self, layout: Layout) -> (u64, u64) {
        let (bw, bh) = self.block(layout);
        (
            bw * layout.block_cols as u64 + self.bar(layout),
            bh * layout.block_rows as u64,
        )
    }

    /// (width, height) of the figure of `layout`.
    fn size(&self, layout: Layout) -> (u64, u64) {
        let (gw, gh) = self.grid(layout);
        let (sw, sh) = self.side.map_or((0, 0), |(w, h)| (w as u64, h as u64));
        (gw + sw, self.head + gh.max(sh))
    }

    /// Every layout with no empty row or column of blocks or panels.
    fn candidates(&self) -> Vec<Layout> {
        let grids = |n: usize| -> Vec<(usize, usize)> {
            let n = n.max(1);
            (1..=n)
                .filter_map(|cols| {
                    let rows = n.div_ceil(cols);
                    (n.div_ceil(rows) == cols).then_some((cols, rows))
                })
                .collect()
        };
        let mut out = Vec::new();
        for &(block_cols, block_rows) in &grids(self.blocks) {
            for &(panel_cols, panel_rows) in &grids(self.own.len()) {
                out.push(Layout {
                    block_cols,
                    block_rows,
                    panel_cols,
                    panel_rows,
                });
            }
        }
        out
    }

    /// The fraction of a frame of `aspect` that the panels of `layout` cover when the
    /// figure is scaled to fit in it: A·k²/F for a frame F × 1 (F = W/H), the panels' total
    /// area A and the fit k = min(F/w, 1/h).
    fn coverage(&self, layout: Layout, aspect: Aspect) -> f64 {
        let (w, h) = self.size(layout);
        if w == 0 || h == 0 {
            return 0.0;
        }
        let f = aspect.ratio();
        let area: f64 = self.blocks as f64
            * self
                .panels(layout)
                .iter()
                .map(|&(w, h)| w as f64 * h as f64)
                .sum::<f64>()
            + self.side.map_or(0.0, |(w, h)| w as f64 * h as f64);
        let k = (f / w as f64).min(1.0 / h as f64);
        area * k * k / f
    }

    /// The layout the rule of the module docs picks for a frame of `aspect`.
    fn choose(&self, aspect: Aspect) -> Layout {
        let key = |l: Layout| (self.coverage(l, aspect), l);
        let better = |a: (f64, Layout), b: (f64, Layout)| -> bool {
            let (fa, la) = a;
            let (fb, lb) = b;
            if (fa - fb).abs() > 1e-9 {
                return fa > fb;
            }
            if la.block_cols != lb.block_cols {
                return la.block_cols > lb.block_cols;
            }
            if la.panel_cols != lb.panel_cols {
                return la.panel_cols < lb.panel_cols;
            }
            let (wa, ha) = self.size(la);
            let (wb, hb) = self.size(lb);
            wa * ha < wb * hb
        };
        let mut it = self.candidates().into_iter().map(key);
        let first = it.next().expect("at least the one-by-one layout");
        it.fold(first, |best, c| if better(c, best) { c } else { best })
            .1
    }
}

/// The fraction of a frame of `aspect` that a `w`×`h` figure covers when scaled to fit in it.
pub fn fill(w: u64, h: u64, aspect: Aspect) -> f64 {
    if w == 0 || h == 0 {
        return 0.0;
    }
    let a = w as f64 / h as f64;
    let f = aspect.ratio();
    (a / f).min(f / a)
}

/// Width in pixels of `text` in the figures' font at `px` pixels (what the figures measure
/// text with).
pub fn text_width(text: &str, px: f64) -> u32 {
    #[cfg(test)]
    MEASURED.with(|m| m.set(m.get() + text.chars().count() as u64));
    match font() {
        Ok(f) => f.layout(text, px as f32).width.ceil() as u32,
        Err(_) => u32::MAX,
    }
}

#[cfg(test)]
thread_local! {
    /// Characters measured by [`text_width`] on this thread: the work of a layout.
    static MEASURED: std::cell::Cell<u64> = const { std::cell::Cell::new(0) };
}

/// `text` shortened to fit `room` pixels at `px`, ending in "…" when shortened ("" when not
/// even "…" fits): the longest prefix that fits, found by doubling then bisecting the prefix
/// length, so the work grows with what fits (bounded by `room`), not with the text's length.
fn shorten(text: &str, room: u32, px: f64) -> String {
    if text_width(text, px) <= room {
        return text.to_string();
    }
    let chars: Vec<char> = text.chars().collect();
    let candidate = |keep: usize| -> String {
        let head: String = chars[..keep].iter().collect();
        format!("{}…", head.trim_end_matches([' ', ',', '·', ';', ':', '-']))
    };
    let fits = |keep: usize| text_width(&candidate(keep), px) <= room;
    if !fits(0) {
        return String::new();
    }
    // Doubling: `lo` fits, `hi` does not (or is past the end; the whole text does not fit).
    let (mut lo, mut hi) = (0usize, 1usize);
    while hi < chars.len() && fits(hi) {
        lo = hi;
        hi = (hi * 2).min(chars.len());
    }
    let mut hi = hi.min(chars.len());
    // Bisection between them (a prefix that fits stays the answer's lower bound).
    while hi - lo > 1 {
        let mid = lo + (hi - lo) / 2;
        if fits(mid) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    candidate(lo)
}

/// `text` in at most `max_lines` lines of at most `room` pixels at `px`, broken between
/// words; the last line is shortened with "…" if the rest does not fit, and so is a word
/// wider than a line on its own.
pub fn wrap(text: &str, room: u32, px: f64, max_lines: usize) -> Vec<String> {
    let words: Vec<&str> = text.split_whitespace().collect();
    let mut lines = Vec::new();
    let mut i = 0;
    while i < words.len() && lines.len() < max_lines {
        if lines.len() + 1 == max_lines {
            lines.push(shorten(&words[i..].join(" "), room, px));
            break;
        }
        let mut line = words[i].to_string();
        i += 1;
        if text_width(&line, px) > room {
            lines.push(shorten(&line, room, px));
            continue;
        }
        while i < words.len() {
            let longer = format!("{line} {}", words[i]);
            if text_width(&longer, px) > room {
                break;
            }
            line = longer;
            i += 1;
        }
        lines.push(line);
    }
    lines
}

/// Left padding of a text line at `px`, and its room in a band `width` wide.
fn padding(px: f64) -> u32 {
    (px * 0.8) as u32
}

fn room(width: u64, px: f64) -> u32 {
    (width as u32).saturating_sub(2 * padding(px))
}

/// The shared colour range of a comparison's periodograms, if every column has one and the
/// same colour map, and there are several columns to share it.
fn shared_range(
    kinds: &[FigureKind],
    columns: &[(FigureContext, ColumnData)],
) -> Option<((f32, f32), Colormap)> {
    if columns.len() < 2 || !kinds.contains(&FigureKind::Spectrum) {
        return None;
    }
    let (first, _) = columns.first()?;
    let range = first.spectrum_range?;
    columns
        .iter()
        .all(|(c, _)| {
            c.spectrum_range == Some(range) && c.spectrum_colormap == first.spectrum_colormap
        })
        .then_some((range, first.spectrum_colormap))
}

/// A composite worked out before it is drawn.
struct Plan {
    kinds: Vec<FigureKind>,
    layout: Layout,
    scale: u32,
    /// Scaled sizes of the panels of a block.
    panels: Vec<(u32, u32)>,
    /// The title's lines and the band's height (0 without a title).
    heading: Vec<String>,
    head: u64,
    bar: Option<((f32, f32), Colormap)>,
    bar_w: u64,
    block: (u64, u64),
    /// The scene's own figure right of the blocks, and its top-left corner (scaled).
    side: Option<(FigureKind, (u64, u64))>,
    size: (u64, u64),
}

/// Works out a composite of `blocks` blocks of `kinds`, with the shared bar `bar`, the
/// title `title` (none for a column composite) and the scene's figure `side` right of the
/// blocks.
fn plan(
    kinds: &[FigureKind],
    blocks: usize,
    bar: Option<((f32, f32), Colormap)>,
    title: Option<&str>,
    side: Option<FigureKind>,
    scale: u32,
    aspect: Aspect,
) -> Plan {
    let own: Vec<(u32, u32)> = kinds.iter().map(|&k| figure(k).base_size()).collect();
    let without_bar: Vec<(u32, u32)> = kinds
        .iter()
        .map(|&k| match k {
            FigureKind::Spectrum => SpectrumWithoutBar.base_size(),
            _ => figure(k).base_size(),
        })
        .collect();
    let bar_w = SharedBar {
        lo: 0.0,
        hi: 1.0,
        colormap: Colormap::Viridis,
    }
    .base_size()
    .0 as u64;
    let shared = bar.and_then(|_| {
        let i = kinds.iter().position(|&k| k == FigureKind::Spectrum)?;
        Some((without_bar.as_slice(), i, bar_w))
    });
    let head1 = if title.is_some() { HEADING_H as u64 } else { 0 };
    let shape = Shape {
        own: &own,
        shared,
        blocks: blocks.max(1),
        head: head1,
        side: side.map(|k| figure(k).base_size()),
    };
    let layout = shape.choose(aspect);
    let s = scale as u64;
    let (w1, _) = shape.size(layout);
    let px = HEADING_PX * scale as f64;
    let heading = title
        .map(|t| wrap(t, room(w1 * s, px), px, HEADING_LINES))
        .unwrap_or_default();
    let head = if title.is_some() {
        (HEADING_H + HEADING_LINE * heading.len().saturating_sub(1) as u32) as u64
    } else {
        0
    };
    let shape = Shape { head, ..shape };
    let (w, h) = shape.size(layout);
    let (bw, bh) = shape.block(layout);
    let uses_bar = shape.uses_bar(layout);
    let (gw, gh) = shape.grid(layout);
    // The side figure is centred on the blocks' height, right of them.
    let side = side.map(|k| {
        let sh = figure(k).base_size().1 as u64;
        (k, (gw * s, (head + gh.saturating_sub(sh) / 2) * s))
    });
    Plan {
        kinds: kinds.to_vec(),
        layout,
        scale,
        panels: shape
            .panels(layout)
            .iter()
            .map(|&(w, h)| (w * scale, h * scale))
            .collect(),
        heading,
        head: head * s,
        bar: bar.filter(|_| uses_bar),
        bar_w: shape.bar(layout) * s,
        block: (bw * s, bh * s),
        side,
        size: (w * s, h * s),
    }
}

fn check_size((width, height): (u64, u64)) -> Result<(u32, u32), ExportError> {
    if width * height > MAX_COMPOSITE_PIXELS {
        return Err(ExportError::TooLarge {
            width,
            height,
            max_pixels: MAX_COMPOSITE_PIXELS,
        });
    }
    Ok((width as u32, height as u32))
}

/// Draws the line `text` left-aligned at (x0 + padding, centre of the band y0..y0 + h).
fn text_line(
    d: &mut Drawing,
    text: &str,
    (x0, y0): (u32, u32),
    h: u32,
    px: f64,
) -> Result<(), ExportError> {
    if text.is_empty() {
        return Ok(());
    }
    let line = font()?.layout(text, px as f32);
    d.ops.push(Op::Text {
        text: text.to_string(),
        glyphs: line.glyphs,
        origin: [
            (x0 + padding(px)) as f32,
            (y0 + h / 2) as f32 - line.height / 2.0,
        ],
        rot: [1.0, 0.0, 0.0, 1.0],
        scale: line.scale,
        color: Rgba::BLACK,
    });
    Ok(())
}

impl Plan {
    /// Draws block `i` (column `ctx`, `data`) onto `d`.
    fn draw_block(
        &self,
        d: &mut Drawing,
        i: usize,
        ctx: &FigureContext,
        data: &ColumnData,
    ) -> Result<(), ExportError> {
        let l = self.layout;
        let (bw, _) = self.block;
        let x0 = ((i % l.block_cols) as u64 * bw) as u32;
        let y0 = (self.head + (i / l.block_cols) as u64 * self.block.1) as u32;
        let cap_h = CAPTION_H * self.scale;
        let px = CAPTION_PX * self.scale as f64;
        // A block of theorem panels is captioned with the theorem's setup and error terms
        // (its panels then leave them out); any other block with its column.
        let theorem = match data.theorem.data() {
            Some(v) if self.kinds.iter().all(|k| k.is_theorem()) => Some(v),
            _ => None,
        };
        let caption = match theorem {
            Some(v) => super::theorem::block_caption(v),
            None => format!(
                "{} · N = {}{}",
                ctx.column_title,
                ctx.n,
                ctx.seed_part(" · ")
            ),
        };
        // Theorem panels in a mixed block keep their own setup and caption line.
        let role = |k: FigureKind| {
            if k.is_theorem() && theorem.is_none() {
                Role::Alone
            } else {
                Role::Panel
            }
        };
        text_line(d, &shorten(&caption, room(bw, px), px), (x0, y0), cap_h, px)?;
        let mut y = y0 + cap_h;
        let rows = panel_rows(&self.panels, l.panel_cols);
        for (r, kinds) in self.kinds.chunks(l.panel_cols).enumerate() {
            let (rw, rh) = rows[r];
            let mut x = x0 + ((bw - rw) / 2) as u32;
            for &k in kinds {
                check_scale(self.scale)?;
                let panel = match (k, self.bar) {
                    (FigureKind::Spectrum, Some(_)) => {
                        render_drawing(&SpectrumWithoutBar, ctx, data, self.scale, role(k))?
                    }
                    _ => render_drawing(figure(k), ctx, data, self.scale, role(k))?,
                };
                let (pw, ph) = (panel.width, panel.height);
                d.place(panel, x as f32, (y + (rh as u32 - ph) / 2) as f32);
                x += pw;
            }
            y += rh as u32;
        }
        Ok(())
    }

    /// Draws the shared colour bar right of the first row of blocks, level with the
    /// periodograms' images.
    fn draw_bar(&self, d: &mut Drawing, ctx: &FigureContext) -> Result<(), ExportError> {
        let Some(((lo, hi), colormap)) = self.bar else {
            return Ok(());
        };
        let Some(p) = self.kinds.iter().position(|&k| k == FigureKind::Spectrum) else {
            return Ok(());
        };
        let l = self.layout;
        let rows = panel_rows(&self.panels, l.panel_cols);
        let r = p / l.panel_cols;
        let row_y: u64 = rows[..r].iter().map(|r| r.1).sum();
        let (lo, hi) = super::draw::ordered_range((lo, hi));
        let img = render_drawing(
            &SharedBar { lo, hi, colormap },
            ctx,
            &ColumnData::default(),
            self.scale,
            Role::Panel,
        )?;
        let x = (l.block_cols as u64 * self.block.0) as u32;
        let y = (self.head + (CAPTION_H * self.scale) as u64 + row_y) as u32
            + (rows[r].1 as u32 - img.height) / 2;
        debug_assert_eq!(img.width as u64, self.bar_w);
        d.place(img, x as f32, y as f32);
        Ok(())
    }

    fn draw(&self, columns: &[(FigureContext, ColumnData)]) -> Result<Drawing, ExportError> {
        let (w, h) = check_size(self.size)?;
        let mut d = Drawing::new(w, h);
        let (fw, fh) = (w as f32, h as f32);
        d.ops.push(Op::Fill {
            points: vec![[0.0, 0.0], [fw, 0.0], [fw, fh], [0.0, fh]],
            color: Rgba::WHITE,
        });
        let px = HEADING_PX * self.scale as f64;
        // One line is centred in the title band; two lines share it, a line apart.
        let (line_h, top) = if self.heading.len() > 1 {
            (HEADING_LINE, (HEADING_H - HEADING_LINE) / 2)
        } else {
            (HEADING_H, 0)
        };
        for (i, line) in self.heading.iter().enumerate() {
            let y0 = (top + i as u32 * line_h) * self.scale;
            text_line(&mut d, line, (0, y0), line_h * self.scale, px)?;
        }
        for (i, (ctx, data)) in columns.iter().enumerate() {
            self.draw_block(&mut d, i, ctx, data)?;
        }
        if let Some((ctx, data)) = columns.first() {
            self.draw_bar(&mut d, ctx)?;
            if let Some((k, (x, y))) = self.side {
                let fig = render_drawing(figure(k), ctx, data, self.scale, Role::Alone)?;
                d.place(fig, x as f32, y as f32);
            }
        }
        Ok(d)
    }
}

fn panels_list(kinds: &[FigureKind]) -> String {
    kinds
        .iter()
        .map(|k| k.name())
        .collect::<Vec<_>>()
        .join(", ")
}

fn no_panels(figure: &'static str) -> ExportError {
    ExportError::EmptyData {
        figure,
        reason: "no panel to compose".into(),
    }
}

/// The layout [`column_png`] uses for figures `kinds` in a frame of `aspect`.
pub fn column_layout(kinds: &[FigureKind], aspect: Aspect) -> Layout {
    plan(kinds, 1, None, None, None, 1, aspect).layout
}

/// (width, height) in pixels of [`column_png`] with figures `kinds` at `scale` in a frame of
/// `aspect`.
pub fn column_size(kinds: &[FigureKind], scale: u32, aspect: Aspect) -> (u64, u64) {
    plan(kinds, 1, None, None, None, scale, aspect).size
}

/// The figure of the whole scene a comparison shows right of its columns: the integration
/// study's plot (every column's curve on one plot, carried by column 0) when it was computed.
fn side_figure(columns: &[(FigureContext, ColumnData)]) -> Option<FigureKind> {
    let (_, data) = columns.first()?;
    figure(FigureKind::Integration)
        .check(data)
        .is_ok()
        .then_some(FigureKind::Integration)
}

/// The plan of the comparison of `columns`.
fn comparison_plan(
    kinds: &[FigureKind],
    columns: &[(FigureContext, ColumnData)],
    scale: u32,
    aspect: Aspect,
) -> Plan {
    let title = columns.first().map_or("", |(c, _)| c.scene_title.as_str());
    let bar = shared_range(kinds, columns);
    plan(
        kinds,
        columns.len(),
        bar,
        Some(title),
        side_figure(columns),
        scale,
        aspect,
    )
}

/// The layout [`comparison_png`] uses for `columns` with figures `kinds` in a frame of
/// `aspect`.
pub fn comparison_layout(
    kinds: &[FigureKind],
    columns: &[(FigureContext, ColumnData)],
    aspect: Aspect,
) -> Layout {
    comparison_plan(kinds, columns, 1, aspect).layout
}

/// The lines the comparison's title is drawn in at `scale` (each fits the figure's width).
pub fn comparison_title_lines(
    kinds: &[FigureKind],
    columns: &[(FigureContext, ColumnData)],
    scale: u32,
    aspect: Aspect,
) -> Vec<String> {
    comparison_plan(kinds, columns, scale, aspect).heading
}

/// (width, height) in pixels of [`comparison_png`] of `columns` with figures `kinds` at
/// `scale` in a frame of `aspect`; compare its product with [`MAX_COMPOSITE_PIXELS`] before
/// asking for it.
pub fn comparison_size(
    kinds: &[FigureKind],
    columns: &[(FigureContext, ColumnData)],
    scale: u32,
    aspect: Aspect,
) -> (u64, u64) {
    comparison_plan(kinds, columns, scale, aspect).size
}

fn column_drawing(
    kinds: &[FigureKind],
    ctx: &FigureContext,
    data: &ColumnData,
    scale: u32,
    aspect: Aspect,
) -> Result<(Drawing, Layout), ExportError> {
    check_scale(scale)?;
    ensure_font()?;
    if kinds.is_empty() {
        return Err(no_panels("column"));
    }
    let one = [(ctx.clone(), data.clone())];
    let p = plan(kinds, 1, None, None, None, scale, aspect);
    Ok((p.draw(&one)?, p.layout))
}

fn column_meta(
    kinds: &[FigureKind],
    ctx: &FigureContext,
    scale: u32,
    aspect: Aspect,
    layout: Layout,
) -> Vec<(String, String)> {
    let mut m = vec![
        ("Title".to_string(), ctx.column_caption()),
        (
            "Software".to_string(),
            format!("samplescope {}", env!("CARGO_PKG_VERSION")),
        ),
        ("figure".to_string(), "column".to_string()),
    ];
    m.extend(context_metadata(ctx));
    m.push(("panels".into(), panels_list(kinds)));
    m.push(("aspect".into(), aspect.to_string()));
    m.push(("layout".into(), layout.to_string()));
    m.push(("scale".into(), scale.to_string()));
    m
}

/// A column's figures `kinds` under a caption (label, N, seed), in the grid that best fills
/// a frame of `aspect` (the module docs give the rule), as a file in `format` with the
/// column's metadata.
pub fn column_file(
    kinds: &[FigureKind],
    ctx: &FigureContext,
    data: &ColumnData,
    scale: u32,
    aspect: Aspect,
    format: FileFormat,
) -> Result<Vec<u8>, ExportError> {
    let (d, layout) = column_drawing(kinds, ctx, data, scale, aspect)?;
    encode(&d, format, &column_meta(kinds, ctx, scale, aspect, layout))
}

/// [`column_file`] as PNG.
pub fn column_png(
    kinds: &[FigureKind],
    ctx: &FigureContext,
    data: &ColumnData,
    scale: u32,
    aspect: Aspect,
) -> Result<Vec<u8>, ExportError> {
    column_file(kinds, ctx, data, scale, aspect, FileFormat::Png)
}

/// [`column_file`]'s picture as (width, height, RGBA8), for the clipboard.
pub fn column_rgba(
    kinds: &[FigureKind],
    ctx: &FigureContext,
    data: &ColumnData,
    scale: u32,
    aspect: Aspect,
) -> Result<(u32, u32, Vec<u8>), ExportError> {
    let img = column_drawing(kinds, ctx, data, scale, aspect)?
        .0
        .raster()?;
    Ok((img.width, img.height, rgb_to_rgba(&img.data)))
}

fn comparison_drawing(
    kinds: &[FigureKind],
    columns: &[(FigureContext, ColumnData)],
    scale: u32,
    aspect: Aspect,
) -> Result<(Drawing, Layout), ExportError> {
    check_scale(scale)?;
    ensure_font()?;
    if kinds.is_empty() {
        return Err(no_panels("comparison"));
    }
    if columns.is_empty() {
        return Err(ExportError::EmptyData {
            figure: "comparison",
            reason: "no column".into(),
        });
    }
    let p = comparison_plan(kinds, columns, scale, aspect);
    Ok((p.draw(columns)?, p.layout))
}

fn comparison_meta(
    kinds: &[FigureKind],
    columns: &[(FigureContext, ColumnData)],
    scale: u32,
    aspect: Aspect,
    layout: Layout,
) -> Vec<(String, String)> {
    let mut m = vec![(
        "Software".to_string(),
        format!("samplescope {}", env!("CARGO_PKG_VERSION")),
    )];
    if let Some((c, _)) = columns.first() {
        m.insert(0, ("Title".into(), c.scene_title.clone()));
        m.push(("figure".into(), "comparison".into()));
        m.push(("scene".into(), c.scene_title.clone()));
        m.push(("N".into(), c.n.to_string()));
        m.push(("signal".into(), c.signal.clone()));
        m.push(("filter".into(), c.filter.clone()));
        m.push(("reconstruction".into(), c.recon.clone()));
    }
    let cols = columns
        .iter()
        .map(|(c, _)| {
            format!(
                "{}: {} {} seed {}",
                c.column_title, c.pattern, c.pattern_params, c.seed
            )
        })
        .collect::<Vec<_>>()
        .join("; ");
    m.push(("columns".into(), cols));
    let mut panels = panels_list(kinds);
    if let Some(k) = side_figure(columns) {
        panels.push_str(&format!("; beside the columns: {}", k.name()));
    }
    m.push(("panels".into(), panels));
    m.push(("aspect".into(), aspect.to_string()));
    m.push(("layout".into(), layout.to_string()));
    m.push(("scale".into(), scale.to_string()));
    m
}

/// Every column of a comparison (its caption over its figures `kinds`), side by side in the
/// grid that best fills a frame of `aspect` (the module docs give the rule), under the
/// scene's title, as a file in `format` with the scene's metadata and every column's
/// pattern, parameters and seed. Locked periodogram scales share one colour bar. Refused with
/// [`ExportError::TooLarge`] beyond [`MAX_COMPOSITE_PIXELS`] (in every format: a vector
/// figure that large would not be readable either).
pub fn comparison_file(
    kinds: &[FigureKind],
    columns: &[(FigureContext, ColumnData)],
    scale: u32,
    aspect: Aspect,
    format: FileFormat,
) -> Result<Vec<u8>, ExportError> {
    let (d, layout) = comparison_drawing(kinds, columns, scale, aspect)?;
    encode(
        &d,
        format,
        &comparison_meta(kinds, columns, scale, aspect, layout),
    )
}

/// [`comparison_file`] as PNG.
pub fn comparison_png(
    kinds: &[FigureKind],
    columns: &[(FigureContext, ColumnData)],
    scale: u32,
    aspect: Aspect,
) -> Result<Vec<u8>, ExportError> {
    comparison_file(kinds, columns, scale, aspect, FileFormat::Png)
}

/// [`comparison_file`]'s picture as (width, height, RGBA8), for the clipboard.
pub fn comparison_rgba(
    kinds: &[FigureKind],
    columns: &[(FigureContext, ColumnData)],
    scale: u32,
    aspect: Aspect,
) -> Result<(u32, u32, Vec<u8>), ExportError> {
    let img = comparison_drawing(kinds, columns, scale, aspect)?
        .0
        .raster()?;
    Ok((img.width, img.height, rgb_to_rgba(&img.data)))
}

#[cfg(test)]
mod tests {
    use super::*;

    const PATTERN: (u32, u32) = (480, 510);
    const SPECTRUM: (u32, u32) = (590, 510);
    const LINE_PLOT: (u32, u32) = (640, 510);

    fn shape(panels: &[(u32, u32)], blocks: usize) -> Shape<'_> {
        Shape {
            own: panels,
            shared: None,
            blocks,
            head: HEADING_H as u64,
            side: None,
        }
    }

    #[test]
    fn a_side_figure_stands_right_of_the_blocks_and_counts_as_panel_area() {
        // Four integration-error columns of one pattern each, and the MSE plot of all four.
        let own = [PATTERN];
        let s = Shape {
            side: Some(LINE_PLOT),
            ..shape(&own, 4)
        };
        let l = s.choose(Aspect::SLIDE);
        let (gw, gh) = s.grid(l);
        let (w, h) = s.size(l);
        assert_eq!(w, gw + LINE_PLOT.0 as u64);
        assert_eq!(h, HEADING_H as u64 + gh.max(LINE_PLOT.1 as u64));
        // Without the side figure the four blocks stand in a row; beside it, 2 × 2 fills
        // a 16:9 frame better (2·480 + 640 = 1600 wide, 2·590 + title high).
        assert_eq!(l.block_cols, 2, "{l}");
        assert_eq!(shape(&own, 4).choose(Aspect::SLIDE).block_cols, 4);
        let best = s.coverage(l, Aspect::SLIDE);
        for c in s.candidates() {
            assert!(s.coverage(c, Aspect::SLIDE) <= best + 1e-12, "{c}");
        }
    }

    #[test]
    fn the_shared_bar_stands_only_where_a_periodogram_ends_its_row() {
        const BARLESS: (u32, u32) = (480, 510);
        // Two panels, the periodogram second: stacked or side by side, it ends its row.
        let own = [PATTERN, SPECTRUM];
        let without = [PATTERN, BARLESS];
        let s = Shape {
            shared: Some((&without, 1, 110)),
            ..shape(&own, 3)
        };
        let l = s.choose(Aspect::SLIDE);
        assert!(s.uses_bar(l), "{l}");
        assert_eq!(s.size(l).0, l.block_cols as u64 * s.block(l).0 + 110);
        // Five panels in one row, the periodogram second: no shared bar, each keeps its own.
        let own = [PATTERN, SPECTRUM, PATTERN, LINE_PLOT, LINE_PLOT];
        let without = [PATTERN, BARLESS, PATTERN, LINE_PLOT, LINE_PLOT];
        let s = Shape {
            shared: Some((&without, 1, 110)),
            ..shape(&own, 3)
        };
        let row = Layout {
            block_cols: 1,
            block_rows: 3,
            panel_cols: 5,
            panel_rows: 1,
        };
        assert!(!s.uses_bar(row));
        assert_eq!(s.size(row).0, 480 + 590 + 480 + 640 + 640);
        let pairs = Layout {
            panel_cols: 2,
            panel_rows: 3,
            ..row
        };
        assert!(s.uses_bar(pairs));
        // Rows (pattern, periodogram), (pattern, kernel), (response): the widest sets it.
        assert_eq!(s.size(pairs).0, 480 + 640 + 110);
    }

    #[test]
    fn aspect_parses_w_colon_h_and_refuses_the_rest_by_name() {
        assert_eq!("16:9".parse::<Aspect>().unwrap(), Aspect::SLIDE);
        assert_eq!(" 4 : 3 ".parse::<Aspect>().unwrap().ratio(), 4.0 / 3.0);
        assert!(("2.39:1".parse::<Aspect>().unwrap().ratio() - 2.39).abs() < 1e-12);
        for bad in ["abc", "16", "16:", ":9", "16:9:1", ""] {
            let e = bad.parse::<Aspect>().unwrap_err();
            assert!(matches!(e, AspectError::Format { .. }), "{bad}: {e:?}");
            assert!(e.to_string().contains("W:H"), "{e}");
        }
        for bad in ["0:9", "-16:9", "16:0", "NaN:9", "16:inf", "x:9"] {
            let e = bad.parse::<Aspect>().unwrap_err();
            assert!(matches!(e, AspectError::Side { .. }), "{bad}: {e:?}");
            assert!(e.to_string().contains("positive finite"), "{e}");
        }
        for bad in ["11:1", "1:11", "1e300:1e-300"] {
            let e = bad.parse::<Aspect>().unwrap_err();
            assert!(matches!(e, AspectError::Ratio { .. }), "{bad}: {e:?}");
        }
        assert_eq!("10:1".parse::<Aspect>().unwrap().ratio(), 10.0);
        assert_eq!(Aspect::SLIDE.to_string(), "16:9");
        assert!(Aspect::new(f64::NAN, 1.0).is_err());
    }

    #[test]
    fn five_columns_of_three_panels_stand_side_by_side_at_16_9() {
        let panels = [PATTERN, PATTERN, PATTERN];
        let s = shape(&panels, 5);
        let l = s.choose(Aspect::SLIDE);
        assert_eq!(
            l,
            Layout {
                block_cols: 5,
                block_rows: 1,
                panel_cols: 1,
                panel_rows: 3
            }
        );
        let (w, h) = s.size(l);
        assert_eq!((w, h), (5 * 480, 44 + 36 + 3 * 510));
        assert!(fill(w, h, Aspect::SLIDE) > 0.8, "{w}×{h}");
        // Two rows of blocks with three panels in a row fill the frame better (0.96) but
        // leave a sixth of the cells empty: their panels would be smaller.
        let rows = Layout {
            block_cols: 2,
            block_rows: 3,
            panel_cols: 3,
            panel_rows: 1,
        };
        let (w2, h2) = s.size(rows);
        assert!(fill(w2, h2, Aspect::SLIDE) > fill(w, h, Aspect::SLIDE));
        assert!(s.coverage(rows, Aspect::SLIDE) < s.coverage(l, Aspect::SLIDE));
    }

    #[test]
    fn the_chosen_layout_fills_the_frame_best_of_all_candidates() {
        let sets: [&[(u32, u32)]; 4] = [
            &[PATTERN],
            &[PATTERN, SPECTRUM],
            &[PATTERN, SPECTRUM, PATTERN, LINE_PLOT, LINE_PLOT],
            &[PATTERN, (760, 510), SPECTRUM],
        ];
        for panels in sets {
            for blocks in 1..=8 {
                for aspect in [
                    Aspect::SLIDE,
                    "4:3".parse().unwrap(),
                    "1:1".parse().unwrap(),
                ] {
                    let s = shape(panels, blocks);
                    let chosen = s.choose(aspect);
                    // The panels cover at most the figure, which covers at most the frame.
                    let (w, h) = s.size(chosen);
                    assert!(s.coverage(chosen, aspect) <= fill(w, h, aspect) + 1e-12);
                    let best = s
                        .candidates()
                        .into_iter()
                        .map(|l| s.coverage(l, aspect))
                        .fold(0.0, f64::max);
                    assert!(
                        s.coverage(chosen, aspect) >= best - 1e-9,
                        "{} panels × {blocks} at {aspect}: {chosen}",
                        panels.len()
                    );
                    // Every block is placed, none is a whole empty row or column.
                    assert!(chosen.block_cols * chosen.block_rows >= blocks);
                    assert!(chosen.block_cols * (chosen.block_rows - 1) < blocks);
                    assert!(chosen.panel_cols * chosen.panel_rows >= panels.len());
                }
            }
        }
        // One row of six square-ish panels: the best 16:9 grid is 3×2 (aspect 1.27).
        let s = shape(&[PATTERN], 6);
        let l = s.choose(Aspect::SLIDE);
        assert_eq!((l.block_cols, l.block_rows), (3, 2));
        // A tall frame stacks them.
        let l = s.choose("9:16".parse().unwrap());
        assert!(l.block_rows > l.block_cols, "{l}");
    }

    #[test]
    fn title_layout_work_grows_linearly_with_the_text() {
        // Characters measured while wrapping a title of `len` characters into two lines.
        let work = |len: usize| {
            let title = "Hammersley sequence ".repeat(len / 20);
            MEASURED.with(|m| m.set(0));
            let lines = wrap(&title, 1200, 24.0, 2);
            assert_eq!(lines.len(), 2);
            assert!(lines.iter().all(|l| text_width(l, 24.0) <= 1200));
            // One word wider than a line on its own is shortened too.
            let word = "x".repeat(len);
            let one = wrap(&word, 1200, 24.0, 2);
            assert!(one[0].ends_with('…') && text_width(&one[0], 24.0) <= 1200);
            MEASURED.with(|m| m.get())
        };
        let (small, large) = (work(4_000), work(40_000));
        // Linear: ten times the text, about ten times the work (quadratic would be 100×).
        assert!(
            large < 15 * small,
            "4 000 chars: {small} measured, 40 000 chars: {large}"
        );
        assert!(
            large < 40 * 40_000,
            "{large} characters measured for 40 000"
        );
    }

    #[test]
    fn long_titles_wrap_then_shorten_and_every_line_fits() {
        ensure_font().unwrap();
        let px = HEADING_PX;
        let title = "Hammersley (i/N, Φ_p1(i)) for p1 = 2, 3, 5, 7, 11 and a much longer tail \
                     that no single line of a narrow figure can hold at all, however it is set";
        for room in [200u32, 440, 900, 3000] {
            let lines = wrap(title, room, px, 2);
            assert!(!lines.is_empty() && lines.len() <= 2, "{lines:?}");
            for l in &lines {
                assert!(text_width(l, px) <= room, "{room}: {l:?}");
            }
            if lines.len() == 1 {
                assert_eq!(lines[0], title, "one line only when it fits whole");
            } else {
                assert!(lines[1].ends_with('…') || lines.concat().len() >= title.len() - 2);
            }
        }
        assert_eq!(wrap("short", 400, px, 2), vec!["short".to_string()]);
        let one = shorten("p1 = 11 · N = 256 · seed 0", 80, CAPTION_PX);
        assert!(
            one.ends_with('…') && text_width(&one, CAPTION_PX) <= 80,
            "{one}"
        );
        assert_eq!(shorten("wide", 1, px), "");
    }
}
