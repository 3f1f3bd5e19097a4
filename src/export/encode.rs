//! The one PNG encoder: 8-bit RGB with text metadata (figures, composites, the images embedded
//! in SVG figures, and the PNGs of `analyze` and `recon`).

use super::ExportError;

/// Whether `text` can be stored in a tEXt chunk (Latin-1, no NUL).
fn is_latin1(text: &str) -> bool {
    text.chars().all(|c| (c as u32) < 256 && c != '\0')
}

/// Encodes a `width` × `height` RGB image (`rgb`: three bytes per pixel, row 0 at the top)
/// as PNG with `text` as tEXt chunks (iTXt, UTF-8, for values that are not Latin-1).
pub fn png_rgb(
    width: u32,
    height: u32,
    rgb: &[u8],
    text: &[(String, String)],
) -> Result<Vec<u8>, ExportError> {
    let png_err = |e: &dyn std::fmt::Display| ExportError::Png {
        path: String::new(),
        message: e.to_string(),
    };
    let mut out = Vec::new();
    {
        let mut enc = png::Encoder::new(&mut out, width, height);
        enc.set_color(png::ColorType::Rgb);
        enc.set_depth(png::BitDepth::Eight);
        for (k, v) in text {
            if is_latin1(v) {
                enc.add_text_chunk(k.clone(), v.clone())
                    .map_err(|e| png_err(&e))?;
            } else {
                enc.add_itxt_chunk(k.clone(), v.clone())
                    .map_err(|e| png_err(&e))?;
            }
        }
        let mut w = enc.write_header().map_err(|e| png_err(&e))?;
        w.write_image_data(rgb).map_err(|e| png_err(&e))?;
        w.finish().map_err(|e| png_err(&e))?;
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn latin1_values_use_text_and_others_itxt() {
        assert!(is_latin1("128² points, seed 1"));
        assert!(!is_latin1("ω in cycles"));
        let bytes = png_rgb(
            1,
            1,
            &[1, 2, 3],
            &[("a".into(), "x²".into()), ("b".into(), "ω".into())],
        )
        .unwrap();
        let reader = png::Decoder::new(std::io::Cursor::new(bytes))
            .read_info()
            .unwrap();
        let info = reader.info();
        assert!(info
            .uncompressed_latin1_text
            .iter()
            .any(|t| t.keyword == "a" && t.text == "x²"));
        assert!(info
            .utf8_text
            .iter()
            .any(|t| t.keyword == "b" && t.get_text().unwrap() == "ω"));
    }
}
