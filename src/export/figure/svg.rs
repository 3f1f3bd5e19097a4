//! Finishing an SVG figure drawn by plotters: metadata and embedded images.

use super::draw::SvgImage;
use super::encode_png;
use crate::export::ExportError;

/// XML-escapes `text` for element content and attribute values.
fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '&' => out.push_str("&amp;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            other => out.push(other),
        }
    }
    out
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

fn malformed(what: &str) -> ExportError {
    ExportError::Draw {
        figure: "svg",
        message: format!("unexpected SVG from the plotting backend: {what}"),
    }
}

/// Adds `<title>` and `<desc>` (the metadata, one `key: value` per line) after the `<svg>`
/// tag, declares the xlink namespace, and inserts the images right after the background
/// rectangle, so that axes and labels are drawn over them.
pub(crate) fn finish(
    mut text: String,
    images: &[SvgImage],
    meta: &[(String, String)],
) -> Result<String, ExportError> {
    let svg_start = text.find("<svg").ok_or_else(|| malformed("no <svg> tag"))?;
    let open_end = svg_start
        + text[svg_start..]
            .find('>')
            .ok_or_else(|| malformed("unterminated <svg> tag"))?;
    // Images go after the first element (the background fill), before any axis.
    let mut image_xml = String::new();
    for im in images {
        let png = encode_png(&im.image, &[])?;
        image_xml.push_str(&format!(
            "<image x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" preserveAspectRatio=\"none\" \
             image-rendering=\"optimizeSpeed\" style=\"image-rendering:pixelated\" \
             xlink:href=\"data:image/png;base64,{}\"/>\n",
            im.x,
            im.y,
            im.width,
            im.height,
            base64(&png)
        ));
    }
    if !image_xml.is_empty() {
        let first = text[open_end..]
            .find("/>\n")
            .map(|i| open_end + i + 3)
            .ok_or_else(|| malformed("no background element"))?;
        text.insert_str(first, &image_xml);
    }
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
    let head = format!("\n<title>{}</title>\n<desc>{desc}</desc>", escape(title));
    text.insert_str(open_end + 1, &head);
    text.insert_str(open_end, " xmlns:xlink=\"http://www.w3.org/1999/xlink\"");
    Ok(text)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::export::figure::Rgb;

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
    fn finish_adds_metadata_namespace_and_images_after_the_background() {
        let svg = "<svg width=\"10\" height=\"10\" xmlns=\"http://www.w3.org/2000/svg\">\n\
                   <rect x=\"0\" y=\"0\" width=\"10\" height=\"10\" fill=\"#FFFFFF\"/>\n\
                   <line x1=\"0\" y1=\"0\" x2=\"1\" y2=\"1\"/>\n</svg>\n"
            .to_string();
        let img = SvgImage {
            x: 1,
            y: 2,
            width: 3,
            height: 4,
            image: Rgb {
                width: 1,
                height: 1,
                data: vec![0, 0, 0],
            },
        };
        let out = finish(
            svg,
            &[img],
            &[
                ("Title".into(), "a <b> & c".into()),
                ("seed".into(), "7".into()),
            ],
        )
        .unwrap();
        assert!(out.contains("xmlns:xlink=\"http://www.w3.org/1999/xlink\">"));
        assert!(out.contains("<title>a &lt;b&gt; &amp; c</title>"));
        assert!(out.contains("seed: 7"));
        let rect = out.find("<rect").unwrap();
        let image = out
            .find("<image x=\"1\" y=\"2\" width=\"3\" height=\"4\"")
            .unwrap();
        let line = out.find("<line").unwrap();
        assert!(rect < image && image < line, "{out}");
        assert!(finish("no svg here".into(), &[], &[]).is_err());
    }
}
