//! The one PNG encoder: 8-bit RGB with text metadata (figures, composites, the images embedded
//! in SVG figures, and the PNGs of `analyze` and `recon`), fed whole images or rows in order.

use super::ExportError;

/// The longest metadata value written, in bytes: longer ones are cut (at a character
/// boundary) and end in "…", so a figure's size does not grow with its text.
pub const MAX_TEXT_BYTES: usize = 8192;

/// `v` cut to at most [`MAX_TEXT_BYTES`] bytes.
fn bounded(v: &str) -> String {
    if v.len() <= MAX_TEXT_BYTES {
        return v.to_string();
    }
    let mut end = MAX_TEXT_BYTES - '…'.len_utf8();
    while !v.is_char_boundary(end) {
        end -= 1;
    }
    format!("{}…", &v[..end])
}

/// Whether `text` can be stored in a tEXt chunk (Latin-1, no NUL).
fn is_latin1(text: &str) -> bool {
    text.chars().all(|c| (c as u32) < 256 && c != '\0')
}

/// A PNG encoder fed rows in order: 8-bit RGB, each row filtered with PNG's Sub filter and
/// deflated by fdeflate into one zlib stream (what the `png` crate does for
/// `Compression::Fast`, whose filter is Sub by default), written as one IDAT chunk by the
/// `png` crate with the text chunks. Feeding rows as they are produced lets a caller overlap
/// the encoding with the rasterising of later rows.
pub struct RowEncoder {
    width: u32,
    height: u32,
    rows: u32,
    filtered: Vec<u8>,
    zlib: fdeflate::Compressor<Vec<u8>>,
}

fn png_err(e: &dyn std::fmt::Display) -> ExportError {
    ExportError::Png {
        path: String::new(),
        message: e.to_string(),
    }
}

impl RowEncoder {
    /// An encoder for a `width` × `height` image (both positive).
    pub fn new(width: u32, height: u32) -> Result<RowEncoder, ExportError> {
        if width == 0 || height == 0 {
            return Err(png_err(&format!("an image of {width}×{height} pixels")));
        }
        Ok(RowEncoder {
            width,
            height,
            rows: 0,
            filtered: Vec::with_capacity(width as usize * 3 + 1),
            zlib: fdeflate::Compressor::new(Vec::new()).map_err(|e| png_err(&e))?,
        })
    }

    /// Appends whole rows (`rgb`: three bytes per pixel, the next rows from the top).
    pub fn rows(&mut self, rgb: &[u8]) -> Result<(), ExportError> {
        let row_len = self.width as usize * 3;
        if rgb.len() % row_len != 0
            || self.rows as usize + rgb.len() / row_len > self.height as usize
        {
            return Err(png_err(&format!(
                "{} bytes do not make whole rows of the {}×{} image after row {}",
                rgb.len(),
                self.width,
                self.height,
                self.rows
            )));
        }
        for row in rgb.chunks_exact(row_len) {
            self.filtered.clear();
            // Filter type 1 (Sub): each byte minus the byte of the pixel to its left.
            self.filtered.push(1);
            self.filtered.extend_from_slice(&row[..3]);
            self.filtered.extend(
                row[3..]
                    .iter()
                    .zip(row)
                    .map(|(b, left)| b.wrapping_sub(*left)),
            );
            self.zlib
                .write_data(&self.filtered)
                .map_err(|e| png_err(&e))?;
            self.rows += 1;
        }
        Ok(())
    }

    /// The PNG file, with `text` as tEXt chunks (iTXt, UTF-8, for values that are not
    /// Latin-1); every row must have been given.
    pub fn finish(self, text: &[(String, String)]) -> Result<Vec<u8>, ExportError> {
        if self.rows != self.height {
            return Err(png_err(&format!(
                "{} of {} rows given",
                self.rows, self.height
            )));
        }
        let idat = self.zlib.finish().map_err(|e| png_err(&e))?;
        let mut out = Vec::with_capacity(idat.len() + 1024);
        {
            let mut enc = png::Encoder::new(&mut out, self.width, self.height);
            enc.set_color(png::ColorType::Rgb);
            enc.set_depth(png::BitDepth::Eight);
            for (k, v) in text {
                let v = &bounded(v);
                if is_latin1(v) {
                    enc.add_text_chunk(k.clone(), v.clone())
                        .map_err(|e| png_err(&e))?;
                } else {
                    enc.add_itxt_chunk(k.clone(), v.clone())
                        .map_err(|e| png_err(&e))?;
                }
            }
            let mut w = enc.write_header().map_err(|e| png_err(&e))?;
            w.write_chunk(png::chunk::IDAT, &idat)
                .map_err(|e| png_err(&e))?;
            w.finish().map_err(|e| png_err(&e))?;
        }
        Ok(out)
    }
}

/// Encodes a `width` × `height` RGB image (`rgb`: three bytes per pixel, row 0 at the top)
/// as PNG with `text` as tEXt chunks (iTXt, UTF-8, for values that are not Latin-1).
pub fn png_rgb(
    width: u32,
    height: u32,
    rgb: &[u8],
    text: &[(String, String)],
) -> Result<Vec<u8>, ExportError> {
    if rgb.len() != width as usize * height as usize * 3 {
        return Err(png_err(&format!(
            "{} bytes for a {width}×{height} RGB image",
            rgb.len()
        )));
    }
    let mut enc = RowEncoder::new(width, height)?;
    enc.rows(rgb)?;
    enc.finish(text)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn decode(bytes: &[u8]) -> (u32, u32, Vec<u8>) {
        let mut reader = png::Decoder::new(std::io::Cursor::new(bytes))
            .read_info()
            .unwrap();
        let mut buf = vec![0; reader.output_buffer_size()];
        let info = reader.next_frame(&mut buf).unwrap();
        assert_eq!(info.color_type, png::ColorType::Rgb);
        buf.truncate(info.buffer_size());
        (info.width, info.height, buf)
    }

    #[test]
    fn rows_fed_in_bands_decode_to_the_image_and_equal_the_whole_image_bytes() {
        // Noise, runs and a gradient, seed 7: the decoder (the png crate, an independent
        // implementation of the format) gives back every byte.
        let (w, h) = (37u32, 29u32);
        let mut state = 7u64;
        let rgb: Vec<u8> = (0..w * h * 3)
            .map(|i| {
                state = state
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                match (i / (w * 3)) % 3 {
                    0 => (state >> 56) as u8,
                    1 => 255,
                    _ => (i % 256) as u8,
                }
            })
            .collect();
        let whole = png_rgb(w, h, &rgb, &[]).unwrap();
        assert_eq!(decode(&whole), (w, h, rgb.clone()));
        let mut enc = RowEncoder::new(w, h).unwrap();
        for band in rgb.chunks(w as usize * 3 * 4) {
            enc.rows(band).unwrap();
        }
        assert_eq!(enc.finish(&[]).unwrap(), whole);
    }

    #[test]
    fn partial_rows_missing_rows_and_empty_images_are_errors() {
        assert!(RowEncoder::new(0, 4).is_err());
        let mut enc = RowEncoder::new(2, 2).unwrap();
        assert!(enc.rows(&[0; 5]).is_err(), "not a whole row");
        enc.rows(&[0; 6]).unwrap();
        assert!(enc.rows(&[0; 12]).is_err(), "more rows than the image has");
        assert!(enc.finish(&[]).is_err(), "one row of two");
        assert!(png_rgb(2, 2, &[0; 11], &[]).is_err());
    }

    #[test]
    fn metadata_values_are_bounded() {
        let long = "é".repeat(3 * MAX_TEXT_BYTES);
        let cut = bounded(&long);
        assert!(
            cut.len() <= MAX_TEXT_BYTES && cut.ends_with('…'),
            "{}",
            cut.len()
        );
        assert_eq!(bounded("short"), "short");
        let png = png_rgb(1, 1, &[0, 0, 0], &[("Title".into(), long)]).unwrap();
        assert!(png.len() < MAX_TEXT_BYTES + 1024, "{} bytes", png.len());
    }

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
