//! The CSV writers the figures share (numbers in Rust's shortest round-trip form).

use crate::export::ExportError;
use crate::model::{FigureKind, ImageData};
use std::fmt::Write as _;

/// `header`, then one `x,y` line per point; an empty curve is an error.
pub(super) fn curve(
    header: &str,
    points: &[[f64; 2]],
    kind: FigureKind,
) -> Result<String, ExportError> {
    if points.is_empty() {
        return Err(ExportError::EmptyData {
            figure: kind.name(),
            reason: "the curve is empty".into(),
        });
    }
    let mut out = format!("{header}\n");
    for p in points {
        let _ = writeln!(out, "{},{}", p[0], p[1]);
    }
    Ok(out)
}

/// One image row per line, the top row first.
pub(super) fn image_rows(image: &ImageData, kind: FigureKind) -> Result<String, ExportError> {
    if image.width == 0 || image.height == 0 {
        return Err(ExportError::EmptyData {
            figure: kind.name(),
            reason: "the image is empty".into(),
        });
    }
    let mut out = String::with_capacity(image.values.len() * 10);
    for row in image.values.chunks(image.width) {
        for (i, v) in row.iter().enumerate() {
            if i > 0 {
                out.push(',');
            }
            let _ = write!(out, "{v}");
        }
        out.push('\n');
    }
    Ok(out)
}

/// `header`, then one `name,x,y` line per point of each named curve, in order; all curves
/// empty is an error.
pub(super) fn series(
    header: &str,
    series: &[(String, &[[f64; 2]])],
    kind: FigureKind,
) -> Result<String, ExportError> {
    if series.iter().all(|(_, c)| c.is_empty()) {
        return Err(ExportError::EmptyData {
            figure: kind.name(),
            reason: "the curves are empty".into(),
        });
    }
    let mut out = format!("{header}\n");
    for (name, c) in series {
        for p in c.iter() {
            let _ = writeln!(out, "{name},{},{}", p[0], p[1]);
        }
    }
    Ok(out)
}
