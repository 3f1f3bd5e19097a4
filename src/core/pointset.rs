//! Reading point sets written by samplescope and by other tools.
//!
//! Accepted formats, detected per file:
//! - CSV with the header `x,y` (what `samplescope points` writes) or without a header;
//! - PSA-style text: whitespace-separated `x y` per line, optionally preceded by a line
//!   holding only the point count (checked against the number of points read).
//!
//! Blank lines and lines starting with `#` are skipped. Points must lie in [0,1)²; a point
//! outside gets an error naming its line, unless [`OutOfRange::NormalizeToBoundingBox`] asks
//! to map the bounding box of the set onto [0,1)² (each axis scaled by the larger extent so
//! the aspect ratio is kept, then clamped to at most 1 − 2⁻⁵³).

use crate::core::pattern::ONE_MINUS_EPSILON;
use glam::DVec2;

/// What to do with points outside [0,1)².
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum OutOfRange {
    /// Report the first such point as an error (default).
    #[default]
    Reject,
    /// Map the set's bounding box onto the unit square (aspect kept).
    NormalizeToBoundingBox,
}

/// Why a point file could not be read. Lines are 1-based.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PointsFileError {
    #[error("line {line}: {message}")]
    Malformed { line: usize, message: String },
    #[error("line {line}: point ({x}, {y}) is outside [0,1)²; use the bounding-box normalisation to map it in")]
    OutOfRange { line: usize, x: f64, y: f64 },
    #[error("line {line}: the count line says {declared} points but the file holds {found}")]
    CountMismatch {
        line: usize,
        declared: usize,
        found: usize,
    },
    #[error("the file holds no points")]
    Empty,
    #[error("too many points: {found} (at most {max})")]
    TooMany { found: usize, max: usize },
    /// The file could not be read.
    #[error("{path}: {message}")]
    Io { path: String, message: String },
}

/// Reads and parses a point file (see [`parse_points`]).
pub fn read_points_file(
    path: &std::path::Path,
    out_of_range: OutOfRange,
) -> Result<Vec<DVec2>, PointsFileError> {
    let text = std::fs::read_to_string(path).map_err(|e| PointsFileError::Io {
        path: path.display().to_string(),
        message: e.to_string(),
    })?;
    parse_points(&text, out_of_range)
}

/// Maps the bounding box of `points` onto [0,1)², keeping the aspect ratio: every axis is
/// scaled by 1/(the larger extent) after subtracting the lower corner, then clamped to at most
/// 1 − 2⁻⁵³. A single point (zero extent) maps to the origin. Points must be finite.
pub fn normalize_to_bounding_box(raw: &[DVec2]) -> Vec<DVec2> {
    let lo = raw
        .iter()
        .fold(DVec2::splat(f64::INFINITY), |a, p| a.min(*p));
    let hi = raw
        .iter()
        .fold(DVec2::splat(f64::NEG_INFINITY), |a, p| a.max(*p));
    let extent = (hi - lo).max_element();
    let scale = if extent > 0.0 { 1.0 / extent } else { 1.0 };
    raw.iter()
        .map(|p| {
            let q = (*p - lo) * scale;
            DVec2::new(
                q.x.clamp(0.0, ONE_MINUS_EPSILON),
                q.y.clamp(0.0, ONE_MINUS_EPSILON),
            )
        })
        .collect()
}

/// Parses a point file (see the module docs for the formats).
pub fn parse_points(text: &str, out_of_range: OutOfRange) -> Result<Vec<DVec2>, PointsFileError> {
    let max = crate::core::pattern::MAX_N;
    let mut points = Vec::new();
    let mut lines: Vec<(usize, Vec<(usize, f64)>)> = Vec::new();
    let mut count_line: Option<(usize, usize)> = None;
    let mut first_content = true;
    for (idx, raw) in text.lines().enumerate() {
        let line = idx + 1;
        let t = raw.trim();
        if t.is_empty() || t.starts_with('#') {
            continue;
        }
        let fields: Vec<&str> = if t.contains(',') {
            t.split(',').map(str::trim).collect()
        } else {
            t.split_whitespace().collect()
        };
        if first_content {
            first_content = false;
            // A header (`x,y`) or a count line.
            if fields.iter().all(|f| f.parse::<f64>().is_err()) {
                let lower: Vec<String> = fields.iter().map(|f| f.to_ascii_lowercase()).collect();
                if lower.len() >= 2 && lower[0] == "x" && lower[1] == "y" {
                    continue;
                }
                return Err(PointsFileError::Malformed {
                    line,
                    message: format!("expected a header `x,y`, a count or a point, found `{t}`"),
                });
            }
            if fields.len() == 1 {
                let declared =
                    fields[0]
                        .parse::<usize>()
                        .map_err(|_| PointsFileError::Malformed {
                            line,
                            message: format!("a single value must be the point count, found `{t}`"),
                        })?;
                count_line = Some((line, declared));
                continue;
            }
        }
        if fields.len() < 2 {
            return Err(PointsFileError::Malformed {
                line,
                message: format!("expected two coordinates `x y` or `x,y`, found `{t}`"),
            });
        }
        let mut coords = Vec::with_capacity(2);
        for (col, f) in fields.iter().take(2).enumerate() {
            let v: f64 = f.parse().map_err(|_| PointsFileError::Malformed {
                line,
                message: format!("column {}: `{f}` is not a number", col + 1),
            })?;
            if !v.is_finite() {
                return Err(PointsFileError::Malformed {
                    line,
                    message: format!("column {}: `{f}` is not finite", col + 1),
                });
            }
            coords.push((col, v));
        }
        if lines.len() >= max {
            return Err(PointsFileError::TooMany {
                found: lines.len() + 1,
                max,
            });
        }
        lines.push((line, coords));
    }
    if lines.is_empty() {
        return Err(PointsFileError::Empty);
    }
    if let Some((line, declared)) = count_line {
        if declared != lines.len() {
            return Err(PointsFileError::CountMismatch {
                line,
                declared,
                found: lines.len(),
            });
        }
    }
    let raw: Vec<(usize, DVec2)> = lines
        .into_iter()
        .map(|(l, c)| (l, DVec2::new(c[0].1, c[1].1)))
        .collect();
    match out_of_range {
        OutOfRange::Reject => {
            for (line, p) in &raw {
                if !(0.0..1.0).contains(&p.x) || !(0.0..1.0).contains(&p.y) {
                    return Err(PointsFileError::OutOfRange {
                        line: *line,
                        x: p.x,
                        y: p.y,
                    });
                }
                points.push(*p);
            }
        }
        OutOfRange::NormalizeToBoundingBox => {
            let xy: Vec<DVec2> = raw.iter().map(|(_, p)| *p).collect();
            points = normalize_to_bounding_box(&xy);
        }
    }
    Ok(points)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn csv_with_header_psa_with_count_and_plain_whitespace() {
        let a = parse_points("x,y\n0.25,0.5\n0.75,0.125\n", OutOfRange::Reject).unwrap();
        let b = parse_points("2\n0.25 0.5\n0.75\t0.125\n", OutOfRange::Reject).unwrap();
        let c = parse_points("# comment\n0.25 0.5\n\n0.75 0.125\n", OutOfRange::Reject).unwrap();
        let expected = vec![DVec2::new(0.25, 0.5), DVec2::new(0.75, 0.125)];
        assert_eq!(a, expected);
        assert_eq!(b, expected);
        assert_eq!(c, expected);
    }

    #[test]
    fn errors_name_the_line() {
        let e = parse_points("x,y\n0.1,0.2\n0.3,abc\n", OutOfRange::Reject).unwrap_err();
        assert_eq!(
            e,
            PointsFileError::Malformed {
                line: 3,
                message: "column 2: `abc` is not a number".into()
            }
        );
        let e = parse_points("0.1 0.2\n1.5 0.2\n", OutOfRange::Reject).unwrap_err();
        assert!(matches!(e, PointsFileError::OutOfRange { line: 2, .. }));
        let e = parse_points("3\n0.1 0.2\n", OutOfRange::Reject).unwrap_err();
        assert!(matches!(
            e,
            PointsFileError::CountMismatch {
                line: 1,
                declared: 3,
                found: 1
            }
        ));
        assert_eq!(
            parse_points("\n\n", OutOfRange::Reject),
            Err(PointsFileError::Empty)
        );
        let e = parse_points("0.1 NaN\n", OutOfRange::Reject).unwrap_err();
        assert!(matches!(e, PointsFileError::Malformed { line: 1, .. }));
        let e = parse_points("0.1\n", OutOfRange::Reject).unwrap_err();
        assert!(matches!(e, PointsFileError::Malformed { line: 1, .. }));
    }

    #[test]
    fn bounding_box_normalisation_keeps_aspect() {
        let p = parse_points("-1 0\n1 1\n0 0.5\n", OutOfRange::NormalizeToBoundingBox).unwrap();
        assert_eq!(p[0], DVec2::new(0.0, 0.0));
        assert_eq!(p[1], DVec2::new(ONE_MINUS_EPSILON, 0.5));
        assert_eq!(p[2], DVec2::new(0.5, 0.25));
    }
}
