//! The drawing rasterised: antialiased bands on worker threads, marker stamps, the PNG.

use super::*;
use crate::export::figure::Rgb;
use crate::export::ExportError;
use std::collections::BTreeMap;

/// Rows per band of the parallel rasteriser.
pub(super) const BAND: u32 = 64;

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

impl Drawing {
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
    pub(super) fn raster_with(&self, stamps: bool) -> Result<Rgb, ExportError> {
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
