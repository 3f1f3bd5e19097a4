//! The drawing as SVG text: outlines defined once and placed, images inline as base64.

use super::*;
use crate::core::format::decimals;
use crate::export::ExportError;
use std::collections::BTreeMap;
use std::fmt::Write as _;

impl Drawing {
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
                    let png = crate::export::figure::encode_png(image, &[])?;
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

/// A length in the SVG text: at most two decimals ([`decimals`]).
fn num(v: f32) -> String {
    decimals(f64::from(v), 2)
}

/// A coefficient of a transform in the SVG text: at most five decimals.
fn fine(v: f32) -> String {
    decimals(f64::from(v), 5)
}
