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
    /// A line is longer than [`MAX_LINE_BYTES`] (a binary or endless file).
    #[error("line {line}: longer than {max} bytes: not a point file")]
    LineTooLong { line: usize, max: usize },
    /// The bytes are not UTF-8 text.
    #[error("line {line}: byte {offset} is not UTF-8 text: not a point file")]
    NotUtf8 { line: usize, offset: u64 },
    /// The file is larger than [`MAX_FILE_BYTES`].
    #[error("larger than {max_bytes} bytes: point files are read up to that size")]
    TooLarge { max_bytes: u64 },
    /// The file could not be read.
    #[error("{path}: {message}")]
    Io { path: String, message: String },
}

/// The largest point file read: 1 GiB (16 777 216 points at up to 64 bytes a line).
pub const MAX_FILE_BYTES: u64 = 1 << 30;
/// The longest line accepted, in bytes (a longer one is not a point: a binary or endless file).
pub const MAX_LINE_BYTES: usize = 4096;

/// Reads and parses a point file (see [`read_points`]). Errors do not name the file; callers
/// prefix its path.
pub fn read_points_file(
    path: &std::path::Path,
    out_of_range: OutOfRange,
) -> Result<Vec<DVec2>, PointsFileError> {
    let io = |e: std::io::Error| PointsFileError::Io {
        path: path.display().to_string(),
        message: e.to_string(),
    };
    let file = std::fs::File::open(path).map_err(io)?;
    read_points(std::io::BufReader::new(file), out_of_range).map_err(|e| match e {
        PointsFileError::Io { message, .. } => PointsFileError::Io {
            path: path.display().to_string(),
            message,
        },
        e => e,
    })
}

/// Maps the bounding box of `points` onto [0,1)², keeping the aspect ratio: every axis is
/// scaled by 1/(the larger extent) after subtracting the lower corner, then clamped to at most
/// 1 − 2⁻⁵³. A single point (zero extent) maps to the origin. Points must be finite; the
/// arithmetic is done on halves, so coordinates spanning more than `f64::MAX` (e.g.
/// −1e308 and 1e308) do not overflow.
pub fn normalize_to_bounding_box(raw: &[DVec2]) -> Vec<DVec2> {
    let lo = raw
        .iter()
        .fold(DVec2::splat(f64::INFINITY), |a, p| a.min(*p));
    let hi = raw
        .iter()
        .fold(DVec2::splat(f64::NEG_INFINITY), |a, p| a.max(*p));
    // (hi − lo)/2 is finite for finite hi, lo; the ratio of halves is the ratio.
    // Multiplying by the reciprocal gives the bits of (p − lo)·(1/extent) whenever that does
    // not overflow (scaling by ½ and 2 is exact); a subnormal extent divides instead.
    let half_extent = (hi * 0.5 - lo * 0.5).max_element();
    let inverse = 1.0 / half_extent;
    raw.iter()
        .map(|p| {
            let half = *p * 0.5 - lo * 0.5;
            let q = if half_extent.is_nan() || half_extent <= 0.0 {
                DVec2::ZERO
            } else if inverse.is_finite() {
                half * inverse
            } else {
                half / half_extent
            };
            DVec2::new(
                q.x.clamp(0.0, ONE_MINUS_EPSILON),
                q.y.clamp(0.0, ONE_MINUS_EPSILON),
            )
        })
        .collect()
}

/// Parses the text of a point file (see [`read_points`]).
pub fn parse_points(text: &str, out_of_range: OutOfRange) -> Result<Vec<DVec2>, PointsFileError> {
    read_points(text.as_bytes(), out_of_range)
}

/// Reads a point file as a stream (see the module docs for the formats), never holding more
/// than one line besides the points.
///
/// Strict: a data line has exactly two fields (`x,y` or `x y`); extra columns and trailing
/// separators are errors naming the line. A UTF-8 byte-order mark and CRLF line ends are
/// accepted. Bounded: a line longer than [`MAX_LINE_BYTES`], text that is not UTF-8 (the
/// error gives the byte offset), more than [`MAX_FILE_BYTES`] or more than
/// [`crate::core::pattern::MAX_N`] points end the read at once, so a binary or endless input
/// (`/dev/zero`, `/dev/urandom`) is refused after at most one line.
pub fn read_points(
    reader: impl std::io::Read,
    out_of_range: OutOfRange,
) -> Result<Vec<DVec2>, PointsFileError> {
    read_points_limited(
        reader,
        out_of_range,
        MAX_FILE_BYTES,
        crate::core::pattern::MAX_N,
    )
}

/// [`read_points`] with other limits (bytes read, points kept).
fn read_points_limited(
    reader: impl std::io::Read,
    out_of_range: OutOfRange,
    max_bytes: u64,
    max: usize,
) -> Result<Vec<DVec2>, PointsFileError> {
    use std::io::{BufRead, Read};
    let mut reader = std::io::BufReader::new(reader.take(max_bytes + 1));
    let mut raw: Vec<(usize, DVec2)> = Vec::new();
    let mut count_line: Option<(usize, usize)> = None;
    let mut first_content = true;
    let mut buf: Vec<u8> = Vec::with_capacity(128);
    let mut offset: u64 = 0;
    let mut line = 0usize;
    loop {
        buf.clear();
        // At most MAX_LINE_BYTES + 1 bytes of one line are ever held.
        let n = (&mut reader)
            .take(MAX_LINE_BYTES as u64 + 1)
            .read_until(b'\n', &mut buf)
            .map_err(|e| PointsFileError::Io {
                path: String::new(),
                message: e.to_string(),
            })?;
        if n == 0 {
            break;
        }
        line += 1;
        if offset + n as u64 > max_bytes {
            return Err(PointsFileError::TooLarge { max_bytes });
        }
        let ended = buf.last() == Some(&b'\n');
        if !ended && n > MAX_LINE_BYTES {
            return Err(PointsFileError::LineTooLong {
                line,
                max: MAX_LINE_BYTES,
            });
        }
        let mut bytes: &[u8] = &buf;
        if line == 1 {
            bytes = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes);
        }
        let text = std::str::from_utf8(bytes).map_err(|e| PointsFileError::NotUtf8 {
            line,
            offset: offset + (n - bytes.len()) as u64 + e.valid_up_to() as u64,
        })?;
        offset += n as u64;
        let t = text.trim();
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
                if lower.len() == 2 && lower[0] == "x" && lower[1] == "y" {
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
        if fields.len() != 2 {
            let message = if fields.len() > 2 && fields.last() == Some(&"") {
                format!("a trailing separator after the coordinates in `{t}`")
            } else if fields.len() > 2 {
                format!(
                    "expected two coordinates `x y` or `x,y`, found {} fields in `{t}`",
                    fields.len()
                )
            } else {
                format!("expected two coordinates `x y` or `x,y`, found `{t}`")
            };
            return Err(PointsFileError::Malformed { line, message });
        }
        let mut xy = [0.0f64; 2];
        for (col, f) in fields.iter().enumerate() {
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
            xy[col] = v;
        }
        if raw.len() >= max {
            return Err(PointsFileError::TooMany {
                found: raw.len() + 1,
                max,
            });
        }
        raw.push((line, DVec2::new(xy[0], xy[1])));
    }
    if raw.is_empty() {
        return Err(PointsFileError::Empty);
    }
    if let Some((line, declared)) = count_line {
        if declared != raw.len() {
            return Err(PointsFileError::CountMismatch {
                line,
                declared,
                found: raw.len(),
            });
        }
    }
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
            }
            Ok(raw.into_iter().map(|(_, p)| p).collect())
        }
        OutOfRange::NormalizeToBoundingBox => {
            let xy: Vec<DVec2> = raw.iter().map(|(_, p)| *p).collect();
            Ok(normalize_to_bounding_box(&xy))
        }
    }
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
    fn strict_rows_extra_columns_and_trailing_separators_name_the_line() {
        for (text, what) in [
            ("0.1,0.2\n0.3,0.4,abc\n", "3 fields"),
            ("0.1,0.2\n0.3,0.4,\n", "trailing separator"),
            ("0.1 0.2\n0.3 0.4 0.5\n", "3 fields"),
        ] {
            match parse_points(text, OutOfRange::Reject) {
                Err(PointsFileError::Malformed { line: 2, message }) => {
                    assert!(message.contains(what), "{text:?}: {message}")
                }
                other => panic!("{text:?}: {other:?}"),
            }
        }
        // A header with a third column is not the `x,y` header.
        let e = parse_points("x,y,z\n0.1,0.2\n", OutOfRange::Reject).unwrap_err();
        assert!(
            matches!(e, PointsFileError::Malformed { line: 1, .. }),
            "{e:?}"
        );
    }

    #[test]
    fn bom_and_crlf_are_accepted() {
        let expected = vec![DVec2::new(0.25, 0.5), DVec2::new(0.75, 0.125)];
        let p = parse_points(
            "\u{feff}x,y\r\n0.25,0.5\r\n0.75,0.125\r\n",
            OutOfRange::Reject,
        );
        assert_eq!(p.unwrap(), expected);
        let p = parse_points("\u{feff}2\r\n0.25 0.5\r\n0.75 0.125", OutOfRange::Reject);
        assert_eq!(p.unwrap(), expected);
    }

    #[test]
    fn binary_and_endless_input_is_refused_after_one_line() {
        // /dev/zero: NUL bytes without a newline.
        let zeros = std::io::Read::take(std::io::repeat(0), u64::MAX);
        let e = read_points(zeros, OutOfRange::Reject).unwrap_err();
        assert_eq!(
            e,
            PointsFileError::LineTooLong {
                line: 1,
                max: MAX_LINE_BYTES
            }
        );
        // Invalid UTF-8 on line 2, at byte 8 of the file.
        let e = read_points(&b"0.1 0.2\n0.3 \xff\xfe\n"[..], OutOfRange::Reject).unwrap_err();
        assert_eq!(
            e,
            PointsFileError::NotUtf8 {
                line: 2,
                offset: 12
            }
        );
        // Endless valid rows stop at the point limit, or at the byte limit.
        let endless = || std::io::Read::bytes(&b"0.5 0.5\n"[..]).cycle_bytes();
        let e = read_points_limited(endless(), OutOfRange::Reject, 1 << 20, 1000).unwrap_err();
        assert_eq!(
            e,
            PointsFileError::TooMany {
                found: 1001,
                max: 1000
            }
        );
        let e = read_points_limited(endless(), OutOfRange::Reject, 800, 1000).unwrap_err();
        assert_eq!(e, PointsFileError::TooLarge { max_bytes: 800 });
    }

    /// An endless reader repeating the bytes of a slice.
    trait CycleBytes {
        fn cycle_bytes(self) -> Cycle;
    }
    struct Cycle(Vec<u8>, usize);
    impl<R: Iterator<Item = std::io::Result<u8>>> CycleBytes for R {
        fn cycle_bytes(self) -> Cycle {
            Cycle(self.map(|b| b.unwrap()).collect(), 0)
        }
    }
    impl std::io::Read for Cycle {
        fn read(&mut self, out: &mut [u8]) -> std::io::Result<usize> {
            for o in out.iter_mut() {
                *o = self.0[self.1 % self.0.len()];
                self.1 += 1;
            }
            Ok(out.len())
        }
    }

    #[test]
    fn normalisation_survives_coordinates_spanning_more_than_f64_max() {
        let p = parse_points(
            "-1e308,1e308\n1e308,-1e308\n",
            OutOfRange::NormalizeToBoundingBox,
        )
        .unwrap();
        assert_eq!(
            p,
            vec![
                DVec2::new(0.0, ONE_MINUS_EPSILON),
                DVec2::new(ONE_MINUS_EPSILON, 0.0)
            ]
        );
        assert!(p.iter().all(|q| q.is_finite()));
    }

    #[test]
    fn bounding_box_normalisation_keeps_aspect() {
        let p = parse_points("-1 0\n1 1\n0 0.5\n", OutOfRange::NormalizeToBoundingBox).unwrap();
        assert_eq!(p[0], DVec2::new(0.0, 0.0));
        assert_eq!(p[1], DVec2::new(ONE_MINUS_EPSILON, 0.5));
        assert_eq!(p[2], DVec2::new(0.5, 0.25));
    }
}
