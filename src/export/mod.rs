//! Figure and data writers: PNG images through a perceptual colour map, CSV, and the
//! [`figure`]s for slides (axes, labels, colour bars; PNG, SVG, CSV and composites). They
//! read the plain data of [`crate::model`] only.

pub mod encode;
pub mod figure;
pub mod gif;
pub mod publish;

/// Why a figure could not be written.
#[derive(Debug, thiserror::Error)]
pub enum ExportError {
    #[error("{path}: {source}")]
    Io {
        path: String,
        source: std::io::Error,
    },
    #[error("{path}: PNG encoding failed: {message}")]
    Png { path: String, message: String },
    #[error("image size {width}×{height} does not match {len} values")]
    Size {
        width: usize,
        height: usize,
        len: usize,
    },
    /// A numeric argument (e.g. the figure scale) is outside its documented range.
    #[error("{field} = {value}: must be an integer in {min}..={max}")]
    OutOfRange {
        field: &'static str,
        value: i64,
        min: i64,
        max: i64,
    },
    /// A figure has no data to draw (not computed, or empty).
    #[error("{figure}: no data: {reason}")]
    EmptyData {
        figure: &'static str,
        reason: String,
    },
    /// The plotting backend failed.
    #[error("{figure}: drawing failed: {message}")]
    Draw {
        figure: &'static str,
        message: String,
    },
    /// CSV asked for a composite, which is a picture.
    #[error("the {what} is a picture: CSV is written per figure")]
    NotAPicture { what: &'static str },
    /// One picture asked for several files' worth of figures.
    #[error("everything is many pictures, not one: pick a figure, a column or the comparison")]
    NotOnePicture,
    /// The work was cancelled.
    #[error("cancelled")]
    Cancelled,
    /// An animated figure could not be encoded (its frames, its size or its rate).
    #[error("{0}")]
    Encode(String),
    /// A composite would exceed the pixel limit.
    #[error("composite of {width}×{height} pixels exceeds {max_pixels} pixels: use a smaller scale or fewer columns")]
    TooLarge {
        width: u64,
        height: u64,
        max_pixels: u64,
    },
}

use crate::model::Colormap;

/// Encodes `values` (row-major, row 0 at the top) as an 8-bit RGB PNG, mapping
/// [lo, hi] → [0, 1] → colour map; values outside are clamped, NaN maps to 0.
/// `text` entries become PNG text metadata (parameters of the figure).
pub fn png_bytes(
    values: &[f64],
    width: usize,
    height: usize,
    lo: f64,
    hi: f64,
    colormap: Colormap,
    text: &[(&str, String)],
) -> Result<Vec<u8>, ExportError> {
    if values.len() != width * height || width == 0 || height == 0 {
        return Err(ExportError::Size {
            width,
            height,
            len: values.len(),
        });
    }
    let rgb = crate::model::colorize(values, lo, hi, colormap);
    let text: Vec<(String, String)> = text
        .iter()
        .map(|(k, v)| (k.to_string(), v.clone()))
        .collect();
    encode::png_rgb(width as u32, height as u32, &rgb, &text)
}

/// Reverses the row order of a `width`-wide row-major image: images stored with row 0 at the
/// bottom (y up, as periodograms and reconstructions are) become row 0 at the top (as PNG is).
pub fn flip_rows<T: Copy>(values: &[T], width: usize) -> Vec<T> {
    if width == 0 {
        return Vec::new();
    }
    values.chunks(width).rev().flatten().copied().collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flip_rows_reverses_row_order() {
        assert_eq!(flip_rows(&[1, 2, 3, 4, 5, 6], 2), vec![5, 6, 3, 4, 1, 2]);
        assert!(flip_rows::<u8>(&[], 0).is_empty());
    }

    #[test]
    fn png_round_trips_size_metadata_and_end_colours() {
        let values = vec![0.0, 1.0, 0.5, f64::NAN];
        let bytes = png_bytes(
            &values,
            2,
            2,
            0.0,
            1.0,
            Colormap::Greys,
            &[("pattern", "jitter".into())],
        )
        .unwrap();
        let dec = png::Decoder::new(std::io::Cursor::new(bytes));
        let mut reader = dec.read_info().unwrap();
        let mut buf = vec![0; reader.output_buffer_size()];
        let info = reader.next_frame(&mut buf).unwrap();
        assert_eq!((info.width, info.height), (2, 2));
        assert_eq!(&buf[..6], &[0, 0, 0, 255, 255, 255]);
        assert_eq!(buf[6], 128);
        assert_eq!(buf[9], 0);
        let texts = &reader.info().uncompressed_latin1_text;
        assert!(texts
            .iter()
            .any(|t| t.keyword == "pattern" && t.text == "jitter"));
        assert!(png_bytes(&values, 3, 2, 0.0, 1.0, Colormap::Greys, &[]).is_err());
    }
}
