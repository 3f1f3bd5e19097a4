//! A figure's [`Drawing`] as a one-page PDF (pdf-writer): the same shapes as the PNG and
//! the SVG, vector graphics, the text as real text in the embedded figure font, images
//! uncompressed to their own pixels (Flate, no interpolation), and the metadata in the
//! document information dictionary.
//!
//! - **Page.** One pixel of the figure is ¾ pt (the CSS pixel: a figure at scale 1 is as
//!   large in a PDF viewer as its SVG in a browser). The content stream maps the drawing's
//!   pixel coordinates (y down) onto the page once.
//! - **Font.** Ubuntu Light is embedded whole as a TrueType font program (`FontFile2`, a
//!   CID-keyed `Type0` font with `Identity-H` encoding and glyph ids as CIDs), with the
//!   widths of the glyphs used and a `ToUnicode` map, so the text can be searched, copied and
//!   extracted. Each glyph is placed at the position the layout gave it (kerning included).
//! - **Document info.** `Title` is the figure's title, `Subject` its metadata lines
//!   (`key: value`, one per line, as the PNG's text chunks and the SVG's `<desc>`),
//!   `Creator` and `Producer` name samplescope and its version. No dates: the same inputs
//!   give the same bytes.

use super::drawing::{font, glyph_matrix, Drawing, Op, Rgba};
use crate::export::ExportError;
use ab_glyph::{Font, GlyphId};
use miniz_oxide::deflate::compress_to_vec_zlib;
use pdf_writer::types::{
    CidFontType, FontFlags, LineCapStyle, LineJoinStyle, SystemInfo, UnicodeCmap,
};
use pdf_writer::{Content, Filter, Name, Pdf, Rect, Ref, Str, TextStr};
use std::collections::BTreeMap;

/// Points per figure pixel.
pub const PT_PER_PX: f32 = 0.75;

/// Zlib level of the streams (6: the usual balance of size and time).
const LEVEL: u8 = 6;

/// The font's name in the PDF.
const FONT_NAME: Name<'static> = Name(b"Ubuntu-Light");

/// A circle's Bézier control distance (4 cubic arcs), (4/3)·tan(π/8).
const KAPPA: f32 = 0.552_284_8;

struct Ids(i32);

impl Ids {
    fn next(&mut self) -> Ref {
        self.0 += 1;
        Ref::new(self.0)
    }
}

fn set_colour(c: &mut Content, color: Rgba, stroke: bool) {
    let [r, g, b] = color.rgb.map(|v| v as f32 / 255.0);
    if stroke {
        c.set_stroke_rgb(r, g, b);
    } else {
        c.set_fill_rgb(r, g, b);
    }
}

fn polyline(c: &mut Content, points: &[[f32; 2]], closed: bool) {
    for (i, p) in points.iter().enumerate() {
        if i == 0 {
            c.move_to(p[0], p[1]);
        } else {
            c.line_to(p[0], p[1]);
        }
    }
    if closed {
        c.close_path();
    }
}

fn circle(c: &mut Content, [x, y]: [f32; 2], r: f32) {
    let k = KAPPA * r;
    c.move_to(x + r, y);
    c.cubic_to(x + r, y + k, x + k, y + r, x, y + r);
    c.cubic_to(x - k, y + r, x - r, y + k, x - r, y);
    c.cubic_to(x - r, y - k, x - k, y - r, x, y - r);
    c.cubic_to(x + k, y - r, x + r, y - k, x + r, y);
    c.close_path();
}

/// What the font descriptor needs and ab_glyph does not read from the font's tables: the
/// bounding box of every glyph and the cap height (the top of "H"), in font units, and a
/// dominant vertical stem width (PDF units) for a light weight.
struct Metrics {
    bbox: [f32; 4],
    cap_height: f32,
    stem_v: f32,
}

fn metrics() -> &'static Metrics {
    static METRICS: std::sync::OnceLock<Metrics> = std::sync::OnceLock::new();
    METRICS.get_or_init(|| {
        let mut bbox = [0.0f32; 4];
        let mut cap_height = 0.0;
        if let Ok(ff) = font() {
            for id in 0..ff.font.glyph_count() {
                if let Some(o) = ff.font.outline(GlyphId(id as u16)) {
                    bbox[0] = bbox[0].min(o.bounds.min.x);
                    bbox[1] = bbox[1].min(o.bounds.min.y);
                    bbox[2] = bbox[2].max(o.bounds.max.x);
                    bbox[3] = bbox[3].max(o.bounds.max.y);
                }
            }
            if let Some(o) = ff.font.outline(ff.font.glyph_id('H')) {
                cap_height = o.bounds.max.y;
            }
        }
        Metrics {
            bbox,
            cap_height,
            // Ubuntu Light's stems are about 60 units of 1000.
            stem_v: 60.0,
        }
    })
}

/// The drawing as PDF bytes; `meta` is the figure's metadata (`Title` first).
pub(crate) fn write(drawing: &Drawing, meta: &[(String, String)]) -> Result<Vec<u8>, ExportError> {
    let ff = font()?;
    let upem = ff.font.units_per_em().unwrap_or(1000.0);
    let (w, h) = (drawing.width as f32, drawing.height as f32);
    let mut ids = Ids(0);
    let catalog = ids.next();
    let tree = ids.next();
    let page = ids.next();
    let contents = ids.next();
    let info = ids.next();
    let used = drawing.glyphs_used();
    let font_ids =
        (!used.is_empty()).then(|| (ids.next(), ids.next(), ids.next(), ids.next(), ids.next()));

    // Opacity states, one per alpha value used (fill and stroke alike).
    let mut alphas: BTreeMap<u8, Ref> = BTreeMap::new();
    let alpha_key = |a: f32| (a.clamp(0.0, 1.0) * 255.0).round() as u8;
    for color in drawing.ops.iter().filter_map(Op::color) {
        let k = alpha_key(color.alpha);
        if k < 255 && !alphas.contains_key(&k) {
            alphas.insert(k, ids.next());
        }
    }
    let gs_name = |k: u8| format!("A{k}");

    let mut c = Content::new();
    c.transform([PT_PER_PX, 0.0, 0.0, -PT_PER_PX, 0.0, h * PT_PER_PX]);
    c.set_line_cap(LineCapStyle::ProjectingSquareCap);
    c.set_line_join(LineJoinStyle::RoundJoin);
    let mut images: Vec<(Ref, String, &super::Rgb)> = Vec::new();
    for op in &drawing.ops {
        let alpha = op.color().map_or(255, |c| alpha_key(c.alpha));
        c.save_state();
        if alpha < 255 {
            c.set_parameters(Name(gs_name(alpha).as_bytes()));
        }
        match op {
            Op::Stroke {
                points,
                closed,
                width,
                color,
            } => {
                set_colour(&mut c, *color, true);
                c.set_line_width(*width);
                polyline(&mut c, points, *closed);
                c.stroke();
            }
            Op::Fill { points, color } => {
                set_colour(&mut c, *color, false);
                polyline(&mut c, points, true);
                c.fill_nonzero();
            }
            Op::Circle {
                centre,
                radius,
                fill,
                width,
                color,
            } => {
                circle(&mut c, *centre, *radius);
                if *fill {
                    set_colour(&mut c, *color, false);
                    c.fill_nonzero();
                } else {
                    set_colour(&mut c, *color, true);
                    c.set_line_width(*width);
                    c.stroke();
                }
            }
            Op::Text {
                glyphs,
                origin,
                rot,
                scale,
                color,
                ..
            } => {
                set_colour(&mut c, *color, false);
                c.begin_text();
                c.set_font(Name(b"F0"), 1.0);
                for g in glyphs {
                    let m = glyph_matrix(*origin, *rot, *scale, *g);
                    c.set_text_matrix([
                        m[0] * upem,
                        m[1] * upem,
                        m[2] * upem,
                        m[3] * upem,
                        m[4],
                        m[5],
                    ]);
                    c.show(Str(&g.id.to_be_bytes()));
                }
                c.end_text();
            }
            Op::Image {
                x,
                y,
                width,
                height,
                image,
            } => {
                let id = ids.next();
                let name = format!("Im{}", images.len());
                c.transform([*width, 0.0, 0.0, -*height, *x, *y + *height]);
                c.x_object(Name(name.as_bytes()));
                images.push((id, name, image));
            }
        }
        c.restore_state();
    }
    let content = compress_to_vec_zlib(&c.finish(), LEVEL);

    let mut pdf = Pdf::new();
    pdf.catalog(catalog).pages(tree);
    pdf.pages(tree).kids([page]).count(1);
    {
        let mut p = pdf.page(page);
        p.parent(tree)
            .media_box(Rect::new(0.0, 0.0, w * PT_PER_PX, h * PT_PER_PX))
            .contents(contents);
        let mut res = p.resources();
        if let Some((type0, ..)) = font_ids {
            res.fonts().pair(Name(b"F0"), type0);
        }
        if !images.is_empty() {
            let mut xo = res.x_objects();
            for (id, name, _) in &images {
                xo.pair(Name(name.as_bytes()), *id);
            }
        }
        if !alphas.is_empty() {
            let mut gs = res.ext_g_states();
            for (k, id) in &alphas {
                gs.pair(Name(gs_name(*k).as_bytes()), *id);
            }
        }
    }
    pdf.stream(contents, &content).filter(Filter::FlateDecode);
    for (k, id) in &alphas {
        let a = *k as f32 / 255.0;
        pdf.ext_graphics(*id)
            .non_stroking_alpha(a)
            .stroking_alpha(a);
    }
    for (id, _, img) in &images {
        let data = compress_to_vec_zlib(&img.data, LEVEL);
        let mut x = pdf.image_xobject(*id, &data);
        x.filter(Filter::FlateDecode);
        x.width(img.width as i32)
            .height(img.height as i32)
            .bits_per_component(8)
            .interpolate(false);
        x.color_space().device_rgb();
    }
    if let Some((type0, cid, descriptor, file, cmap)) = font_ids {
        let system = SystemInfo {
            registry: Str(b"Adobe"),
            ordering: Str(b"Identity"),
            supplement: 0,
        };
        pdf.type0_font(type0)
            .base_font(FONT_NAME)
            .encoding_predefined(Name(b"Identity-H"))
            .descendant_font(cid)
            .to_unicode(cmap);
        {
            let mut cf = pdf.cid_font(cid);
            cf.subtype(CidFontType::Type2)
                .base_font(FONT_NAME)
                .system_info(system)
                .font_descriptor(descriptor)
                .cid_to_gid_map_predefined(Name(b"Identity"));
            let mut widths = cf.widths();
            for &id in used.keys() {
                let adv = ff.font.h_advance_unscaled(GlyphId(id)) / upem * 1000.0;
                widths.consecutive(id, [adv]);
            }
        }
        let per = |v: f32| v / upem * 1000.0;
        let m = metrics();
        pdf.font_descriptor(descriptor)
            .name(FONT_NAME)
            .flags(FontFlags::NON_SYMBOLIC)
            .bbox(Rect::new(
                per(m.bbox[0]),
                per(m.bbox[1]),
                per(m.bbox[2]),
                per(m.bbox[3]),
            ))
            .italic_angle(0.0)
            .ascent(per(ff.font.ascent_unscaled()))
            .descent(per(ff.font.descent_unscaled()))
            .cap_height(per(m.cap_height))
            .stem_v(m.stem_v)
            .font_file2(file);
        let program = compress_to_vec_zlib(ff.bytes, LEVEL);
        pdf.stream(file, &program)
            .filter(Filter::FlateDecode)
            .pair(Name(b"Length1"), ff.bytes.len() as i32);
        let mut map = UnicodeCmap::new(Name(b"Custom"), system);
        for (&id, &ch) in &used {
            map.pair(id, ch);
        }
        pdf.cmap(cmap, &map.finish());
    }
    let title = meta
        .iter()
        .find(|(k, _)| k == "Title")
        .map(|(_, v)| v.as_str())
        .unwrap_or("");
    let subject = meta
        .iter()
        .filter(|(k, _)| k != "Title")
        .map(|(k, v)| format!("{k}: {v}"))
        .collect::<Vec<_>>()
        .join("\n");
    let software = format!("samplescope {}", env!("CARGO_PKG_VERSION"));
    pdf.document_info(info)
        .title(TextStr(title))
        .subject(TextStr(&subject))
        .creator(TextStr(&software))
        .producer(TextStr(&software));
    Ok(pdf.finish())
}
