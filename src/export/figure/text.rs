//! Text for the bitmap figures, laid out and rasterised with `ab_glyph` directly.
//!
//! plotters' own `ab_glyph` text path places each glyph at the pen position without its
//! left side bearing and truncates the pen to whole pixels, so at 13-pixel labels the letter
//! spacing wobbles visibly ("p eriodogram"). [`CrispText`] wraps a backend and replaces only
//! `draw_text` and `estimate_text_size`: glyphs are positioned at their exact sub-pixel pen
//! position (advance + kerning) and drawn with their coverage as alpha. Everything else is
//! forwarded unchanged. The SVG figures keep plotters' text elements (the viewer lays them out).

use ab_glyph::{point, Font, FontRef, PxScale, ScaleFont};
use plotters_backend::text_anchor::{HPos, VPos};
use plotters_backend::{
    BackendColor, BackendCoord, BackendStyle, BackendTextStyle, DrawingBackend, DrawingErrorKind,
};

/// A backend whose text is drawn with `font` (the family named in a style is ignored: the
/// figures use one font).
pub struct CrispText<B> {
    inner: B,
    font: FontRef<'static>,
}

impl<B> CrispText<B> {
    /// Wraps `inner`; `font_bytes` is a TrueType/OpenType font.
    pub(crate) fn new(inner: B, font_bytes: &'static [u8]) -> Option<Self> {
        Some(CrispText {
            inner,
            font: FontRef::try_from_slice(font_bytes).ok()?,
        })
    }

    /// Glyphs of `text` at `px` pixels per em-box height, positioned on a baseline at the
    /// ascent (the text box is (0, 0)–(width, height)); returns (glyphs, width, height).
    fn layout(&self, text: &str, px: f32) -> (Vec<ab_glyph::Glyph>, f32, f32) {
        let sf = self.font.as_scaled(PxScale::from(px));
        let ascent = sf.ascent();
        let mut x = 0.0f32;
        let mut prev = None;
        let mut glyphs = Vec::with_capacity(text.len());
        for c in text.chars() {
            let id = sf.glyph_id(c);
            if let Some(p) = prev {
                x += sf.kern(p, id);
            }
            glyphs.push(id.with_scale_and_position(px, point(x, ascent)));
            x += sf.h_advance(id);
            prev = Some(id);
        }
        (glyphs, x, ascent - sf.descent())
    }
}

impl<B: DrawingBackend> DrawingBackend for CrispText<B> {
    type ErrorType = B::ErrorType;

    fn get_size(&self) -> (u32, u32) {
        self.inner.get_size()
    }

    fn ensure_prepared(&mut self) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.inner.ensure_prepared()
    }

    fn present(&mut self) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.inner.present()
    }

    fn draw_pixel(
        &mut self,
        point: BackendCoord,
        color: BackendColor,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.inner.draw_pixel(point, color)
    }

    fn draw_line<S: BackendStyle>(
        &mut self,
        from: BackendCoord,
        to: BackendCoord,
        style: &S,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.inner.draw_line(from, to, style)
    }

    fn draw_rect<S: BackendStyle>(
        &mut self,
        upper_left: BackendCoord,
        bottom_right: BackendCoord,
        style: &S,
        fill: bool,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.inner.draw_rect(upper_left, bottom_right, style, fill)
    }

    fn draw_path<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        path: I,
        style: &S,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.inner.draw_path(path, style)
    }

    fn draw_circle<S: BackendStyle>(
        &mut self,
        center: BackendCoord,
        radius: u32,
        style: &S,
        fill: bool,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.inner.draw_circle(center, radius, style, fill)
    }

    fn fill_polygon<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        vert: I,
        style: &S,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.inner.fill_polygon(vert, style)
    }

    fn blit_bitmap(
        &mut self,
        pos: BackendCoord,
        size: (u32, u32),
        src: &[u8],
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.inner.blit_bitmap(pos, size, src)
    }

    fn estimate_text_size<TStyle: BackendTextStyle>(
        &self,
        text: &str,
        style: &TStyle,
    ) -> Result<(u32, u32), DrawingErrorKind<Self::ErrorType>> {
        let (_, w, h) = self.layout(text, style.size() as f32);
        Ok((w.ceil() as u32, h.ceil() as u32))
    }

    fn draw_text<TStyle: BackendTextStyle>(
        &mut self,
        text: &str,
        style: &TStyle,
        pos: BackendCoord,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        let color = style.color();
        if color.alpha == 0.0 {
            return Ok(());
        }
        let (glyphs, w, h) = self.layout(text, style.size() as f32);
        // Anchor offsets in the text's own (unrotated) frame, as plotters' default does.
        let dx = match style.anchor().h_pos {
            HPos::Left => 0.0,
            HPos::Center => -w / 2.0,
            HPos::Right => -w,
        };
        let dy = match style.anchor().v_pos {
            VPos::Top => 0.0,
            VPos::Center => -h / 2.0,
            VPos::Bottom => -h,
        };
        let (dx, dy) = (dx.round() as i32, dy.round() as i32);
        let trans = style.transform();
        let (sw, sh) = self.inner.get_size();
        let mut pixels: Vec<(i32, i32, f32)> = Vec::new();
        for g in glyphs {
            if let Some(outline) = self.font.outline_glyph(g) {
                let b = outline.px_bounds();
                let (bx, by) = (b.min.x as i32, b.min.y as i32);
                outline.draw(|x, y, c| {
                    if c > 0.0 {
                        pixels.push((bx + x as i32, by + y as i32, c.min(1.0)));
                    }
                });
            }
        }
        for (x, y, c) in pixels {
            let (x, y) = trans.transform(x + dx, y + dy);
            let (x, y) = (pos.0 + x, pos.1 + y);
            if x >= 0 && y >= 0 && x < sw as i32 && y < sh as i32 {
                self.inner.draw_pixel(
                    (x, y),
                    BackendColor {
                        alpha: color.alpha * c as f64,
                        rgb: color.rgb,
                    },
                )?;
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use plotters::prelude::*;
    use plotters::style::text_anchor::Pos;

    /// Bounding box (x0, y0, x1, y1) of the non-white pixels of an RGB buffer `w` wide.
    fn ink(buf: &[u8], w: usize) -> (usize, usize, usize, usize) {
        let mut b = (usize::MAX, usize::MAX, 0, 0);
        for (i, p) in buf.chunks(3).enumerate() {
            if p.iter().any(|&v| v < 200) {
                let (x, y) = (i % w, i / w);
                b = (b.0.min(x), b.1.min(y), b.2.max(x), b.3.max(y));
            }
        }
        b
    }

    fn render(text: &str, pos: Pos, rotate: FontTransform) -> (Vec<u8>, (u32, u32)) {
        let (w, h) = (200u32, 200u32);
        let mut buf = vec![255u8; (w * h * 3) as usize];
        let mut b = CrispText::new(
            BitMapBackend::with_buffer(&mut buf, (w, h)),
            epaint_default_fonts::UBUNTU_LIGHT,
        )
        .unwrap();
        let style = ("sans-serif", 20.0)
            .into_font()
            .transform(rotate)
            .color(&BLACK)
            .pos(pos);
        let size = b.estimate_text_size(text, &style).unwrap();
        b.draw_text(text, &style, (100, 100)).unwrap();
        b.present().unwrap();
        drop(b);
        (buf, size)
    }

    #[test]
    fn centred_text_is_centred_on_its_anchor_and_fits_its_estimate() {
        let (buf, (tw, th)) = render(
            "periodogram",
            Pos::new(HPos::Center, VPos::Center),
            FontTransform::None,
        );
        let (x0, y0, x1, y1) = ink(&buf, 200);
        let (cx, cy) = ((x0 + x1) as f64 / 2.0, (y0 + y1) as f64 / 2.0);
        assert!((cx - 100.0).abs() <= 2.0, "ink x {x0}..{x1}");
        assert!((cy - 100.0).abs() <= 4.0, "ink y {y0}..{y1}");
        assert!((x1 - x0 + 1) as u32 <= tw + 1 && (y1 - y0 + 1) as u32 <= th + 1);
        assert!(tw > 80 && th >= 18, "{tw}×{th}");
    }

    #[test]
    fn rotated_text_runs_vertically() {
        let (buf, _) = render(
            "|H(ω)| / |H(0)|",
            Pos::new(HPos::Center, VPos::Top),
            FontTransform::Rotate270,
        );
        let (x0, y0, x1, y1) = ink(&buf, 200);
        assert!(y1 - y0 > 3 * (x1 - x0), "ink {x0}..{x1} × {y0}..{y1}");
    }

    #[test]
    fn strokes_are_one_advance_apart() {
        // Four "l" strokes: each starts one advance of 'l' (plus kerning, none for "ll")
        // after the previous one, within a pixel.
        let (buf, _) = render("llll", Pos::new(HPos::Left, VPos::Top), FontTransform::None);
        let font = FontRef::try_from_slice(epaint_default_fonts::UBUNTU_LIGHT).unwrap();
        let sf = font.as_scaled(PxScale::from(20.0));
        let advance = sf.h_advance(sf.glyph_id('l')) as f64;
        let inked = |x: usize| (0..200).any(|y| buf[(y * 200 + x) * 3] < 200);
        let starts: Vec<usize> = (1..200).filter(|&x| inked(x) && !inked(x - 1)).collect();
        assert_eq!(starts.len(), 4, "{starts:?}");
        for w in starts.windows(2) {
            let pitch = (w[1] - w[0]) as f64;
            assert!(
                (pitch - advance).abs() <= 1.0,
                "{starts:?} vs advance {advance}"
            );
        }
    }
}
