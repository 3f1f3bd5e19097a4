//! Reading point sets written by samplescope and by other tools.
//!
//! One reader for every entry point (`analyze --points`, the GUI's `--points` and file drop,
//! a scene's `points: Some((path: …))`). The format is decided per file, by content first and
//! extension second:
//! - **NumPy `.npy`**: a file that starts with the magic `\x93NUMPY` (whatever its name).
//!   Format versions 1.0, 2.0 and 3.0; `descr` float32 or float64, little- or big-endian
//!   (`<f4`, `<f8`, `>f4`, `>f8`); `shape` `(N, 2)`; C or Fortran order. The header is at most
//!   [`MAX_NPY_HEADER_BYTES`] (NumPy's own default limit); bytes after the data are refused.
//! - **PSA `.rps`** (by extension, case-insensitive, as PSA itself decides): raw little-endian
//!   float32 pairs `x y`, no header, N = bytes / 8; a size that is not a multiple of 8 is
//!   refused as truncated.
//! - **Text**, everything else: one point per line, the two coordinates separated by a comma,
//!   spaces or tabs (`x,y`, `x, y`, `x y`, `x\ty`), optionally wrapped as pmj-cpp writes them,
//!   `(x, y),` (or `[x, y],`). The first line that is not blank or a `#` comment may be a
//!   header of two column names (`x,y`, `X Y`, `"u","v"`) or the point count alone (PSA's text
//!   format; it must match the number of points). A file whose first bytes are not text gets
//!   one line naming these formats ([`EXPECTED_FORMATS`]).
//!
//! **The closed square.** A coordinate exactly 1 (as `numpy.linspace(0, 1, n)` and tools that
//! sample the closed square [0,1]² write) is taken as `1 − 2⁻⁵³`, the largest f64 below 1
//! ([`ONE_MINUS_EPSILON`], what every pattern here is clamped to), and counted
//! ([`PointsRead::on_closed_edge`]; `analyze` prints a note). On the torus, which every spectrum
//! and distance here assumes, 1 and 0 are the same place, and `1 − 2⁻⁵³` is within 2⁻⁵³ of it:
//! the periodogram at an integer frequency k changes by a phase of at most 2π·k·2⁻⁵³ (below
//! 2·10⁻¹² for every |k| ≤ 2048 a spectrum here uses), toroidal distances by 2⁻⁵³. Wrapping to 0 would give
//! the same toroidal values, but it would move the point across the whole square for the
//! measures that are not periodic (star discrepancy, t-value, elementary intervals), where a
//! closed-square point at x = 1 belongs to the last column, as `1 − 2⁻⁵³` keeps it. Anything
//! above 1 or below 0 is outside and refused with its line (or point index), unless
//! [`OutOfRange::NormalizeToBoundingBox`] maps the set's bounding box onto [0,1)² (each axis
//! scaled by the larger extent so the aspect ratio is kept, then clamped to at most 1 − 2⁻⁵³).
//! A bounding box that is a single point (one point, or all points equal) cannot be mapped
//! and is refused ([`PointsFileError::DegenerateBoundingBox`]), never moved to (0, 0).
//!
//! **Bounded reads.** At most [`MAX_FILE_BYTES`] of text, lines of at most [`MAX_LINE_BYTES`],
//! and [`crate::core::pattern::MAX_N`] points in every format; memory grows with the points
//! actually read (a declared count or shape never sizes an allocation), so a huge, binary or
//! endless input (`/dev/zero`, a FIFO that never ends) is refused without holding more than
//! the points allowed.

use crate::core::cube::{CubeError, CubePoints};
use crate::core::pattern::ONE_MINUS_EPSILON;
use glam::DVec2;
use std::io::Read;
use std::path::Path;

/// What to do with points outside [0,1)².
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum OutOfRange {
    /// Report the first such point as an error (default); a coordinate exactly 1 is taken as
    /// `1 − 2⁻⁵³` (see the module docs).
    #[default]
    Reject,
    /// Map the set's bounding box onto the unit square (aspect kept).
    NormalizeToBoundingBox,
}

/// The format a point file was read as.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PointFormat {
    /// Text rows (CSV, whitespace- or tab-separated, pmj-cpp's `(x, y),`, PSA's text).
    Text,
    /// NumPy `.npy`.
    Npy,
    /// PSA's raw `.rps` (little-endian float32 pairs).
    Rps,
}

impl std::fmt::Display for PointFormat {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            PointFormat::Text => "text",
            PointFormat::Npy => "NumPy .npy",
            PointFormat::Rps => "PSA .rps",
        })
    }
}

/// Where a point stands in its file: a line of a text file, or the 1-based index of a point
/// in a binary one.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Position {
    /// A 1-based line of a text file.
    Line(usize),
    /// The 1-based index of a point in a `.npy` or `.rps` file.
    Point(usize),
}

impl std::fmt::Display for Position {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Position::Line(l) => write!(f, "line {l}"),
            Position::Point(i) => write!(f, "point {i}"),
        }
    }
}

/// What the reader accepts, for the error a file of another kind gets.
pub const EXPECTED_FORMATS: &str = "expected text rows `x y`, `x,y` or `(x, y),`, \
     NumPy .npy (float32/float64, shape (N, 2)) or PSA .rps (float32 pairs)";

/// Why a point file could not be read. Lines and points are 1-based.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PointsFileError {
    #[error("line {line}: {message}")]
    Malformed { line: usize, message: String },
    #[error(
        "{at}: point ({x}, {y}) is outside [0,1]²; use the bounding-box normalisation to map it in"
    )]
    OutOfRange { at: Position, x: f64, y: f64 },
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
    #[error("line {line}: longer than {max} bytes: not a point file ({EXPECTED_FORMATS})")]
    LineTooLong { line: usize, max: usize },
    /// The bytes are not UTF-8 text.
    #[error("line {line}: byte {offset} is not UTF-8 text: not a point file ({EXPECTED_FORMATS})")]
    NotUtf8 { line: usize, offset: u64 },
    /// The file is larger than [`MAX_FILE_BYTES`].
    #[error("larger than {max_bytes} bytes: point files are read up to that size")]
    TooLarge { max_bytes: u64 },
    /// A `.npy` or `.rps` file whose header, size or values are wrong.
    #[error("{format}: {message}")]
    Binary {
        format: PointFormat,
        message: String,
    },
    /// The bounding-box normalisation was asked for a set whose bounding box is one point.
    #[error("the bounding box of the {n} point(s) is the single point ({x}, {y}): there is no box to map onto [0,1)² (normalising would move every point to (0, 0))")]
    DegenerateBoundingBox { n: usize, x: f64, y: f64 },
    /// The file could not be read.
    #[error("{path}: {message}")]
    Io { path: String, message: String },
    /// A coordinate of a file of other than two columns lies outside [0,1].
    #[error(
        "{at}: x{dim} = {value} is outside [0,1]; use the bounding-box normalisation to map it in"
    )]
    OutsideCube {
        at: Position,
        dim: usize,
        value: f64,
    },
    /// The bounding-box normalisation was asked for a set of other than two columns whose
    /// bounding box is one point.
    #[error("the bounding box of the {n} point(s) is a single point: there is no box to map onto [0,1)^{dims}")]
    DegenerateCubeBox { n: usize, dims: usize },
    /// The points do not make a d-dimensional point set (beyond the limits of [`CubePoints`]).
    #[error(transparent)]
    Cube(#[from] CubeError),
}

/// The longest line accepted in a file of any number of columns (1024 coordinates of up to
/// 31 bytes each, with their separators).
pub const MAX_CUBE_LINE_BYTES: usize = 32 * 1024;

/// A point file of any number of columns as read: the points in [0,1)^d, the format, and how
/// many points had a coordinate exactly 1 (taken as `1 − 2⁻⁵³`).
#[derive(Debug, Clone, PartialEq)]
pub struct CubeRead {
    /// The points; `dims` is the file's column count (2 for `.rps`).
    pub points: CubePoints,
    /// The format the file was read as.
    pub format: PointFormat,
    /// Points with a coordinate exactly 1 (0 with the bounding-box normalisation).
    pub on_closed_edge: usize,
}

/// Reads a point file of any number of columns (see [`read_cube_named`]). Errors do not name
/// the file; callers prefix its path.
pub fn read_cube_file(path: &Path, out_of_range: OutOfRange) -> Result<CubeRead, PointsFileError> {
    let io = |e: std::io::Error| PointsFileError::Io {
        path: path.display().to_string(),
        message: e.to_string(),
    };
    let file = std::fs::File::open(path).map_err(io)?;
    read_cube_named(file, path, out_of_range).map_err(|e| match e {
        PointsFileError::Io { message, .. } => PointsFileError::Io {
            path: path.display().to_string(),
            message,
        },
        e => e,
    })
}

/// Parses the text of a point file of any number of columns (see [`read_cube_named`]).
pub fn parse_cube(text: &str, out_of_range: OutOfRange) -> Result<CubePoints, PointsFileError> {
    read_cube_named(text.as_bytes(), Path::new(""), out_of_range).map(|r| r.points)
}

/// Reads a point file of any number of columns, the one reader of [`read_points_named`] with
/// the columns the file declares: text with a header of D column names (`x0,x1,…`, or any
/// names) or, without one, the column count of its first row, every row then holding exactly
/// that many (an error names the line, the count expected and where it was set); `.npy` of
/// shape (N, D) or (N,); `.rps` (always two). At most [`crate::core::cube::MAX_DIMS`] columns,
/// N·D ≤ [`crate::core::cube::MAX_COORDS`], lines of at most [`MAX_CUBE_LINE_BYTES`]; a single
/// integer on the first line is a count, as in 2D (a one-column file whose first value is
/// exactly 0 or 1 needs a header). A file of two columns gives exactly what
/// [`read_points_named`] gives (the same checks, errors and normalisation); for other counts
/// a coordinate exactly 1 is taken as `1 − 2⁻⁵³` as in 2D, one outside [0,1] is an error naming
/// its line (or point) and dimension, and the bounding-box normalisation maps the box onto
/// [0,1)^D keeping the aspect ratio (every axis scaled by the largest extent).
pub fn read_cube_named(
    reader: impl std::io::Read,
    name: &Path,
    out_of_range: OutOfRange,
) -> Result<CubeRead, PointsFileError> {
    let raw = read_raw(
        reader,
        name,
        MAX_FILE_BYTES,
        crate::core::pattern::MAX_N,
        Columns::Any,
    )?;
    if raw.dims == 2 {
        let r = finish(raw, out_of_range)?;
        return Ok(CubeRead {
            points: CubePoints::from_2d(&r.points),
            format: r.format,
            on_closed_edge: r.on_closed_edge,
        });
    }
    let dims = raw.dims;
    let n = raw.coords.len() / dims;
    if n == 0 {
        return Err(PointsFileError::Empty);
    }
    let (coords, on_closed_edge) = match out_of_range {
        OutOfRange::Reject => {
            if let Some(k) = raw.coords.iter().position(|v| !(0.0..=1.0).contains(v)) {
                return Err(PointsFileError::OutsideCube {
                    at: raw.position(k / dims),
                    dim: k % dims,
                    value: raw.coords[k],
                });
            }
            let on_edge = raw
                .coords
                .chunks_exact(dims)
                .filter(|p| p.contains(&1.0))
                .count();
            let coords = raw
                .coords
                .into_iter()
                .map(|v| if v == 1.0 { ONE_MINUS_EPSILON } else { v })
                .collect();
            (coords, on_edge)
        }
        OutOfRange::NormalizeToBoundingBox => (normalize_cube(dims, &raw.coords)?, 0),
    };
    Ok(CubeRead {
        points: CubePoints::new(dims, coords)?,
        format: raw.format,
        on_closed_edge,
    })
}

/// [`normalize_to_bounding_box`] in `dims` dimensions, the same arithmetic per axis.
fn normalize_cube(dims: usize, coords: &[f64]) -> Result<Vec<f64>, PointsFileError> {
    let n = coords.len() / dims;
    let mut lo = vec![f64::INFINITY; dims];
    let mut hi = vec![f64::NEG_INFINITY; dims];
    for p in coords.chunks_exact(dims) {
        for k in 0..dims {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    let half_extent = (0..dims)
        .map(|k| hi[k] * 0.5 - lo[k] * 0.5)
        .fold(f64::NEG_INFINITY, f64::max);
    if half_extent.is_nan() || half_extent <= 0.0 {
        return Err(PointsFileError::DegenerateCubeBox { n, dims });
    }
    let inverse = 1.0 / half_extent;
    Ok(coords
        .iter()
        .enumerate()
        .map(|(i, &v)| {
            let half = v * 0.5 - lo[i % dims] * 0.5;
            let q = if inverse.is_finite() {
                half * inverse
            } else {
                half / half_extent
            };
            q.clamp(0.0, ONE_MINUS_EPSILON)
        })
        .collect())
}

/// The largest text point file read: 1 GiB (16 777 216 points at up to 64 bytes a line).
pub const MAX_FILE_BYTES: u64 = 1 << 30;
/// The longest line accepted, in bytes (a longer one is not a point: a binary or endless file).
pub const MAX_LINE_BYTES: usize = 4096;
/// The longest `.npy` header read, in bytes (NumPy's own default `max_header_size`).
pub const MAX_NPY_HEADER_BYTES: usize = 10_000;

/// A point file as read: the points, its format, and how many points had a coordinate exactly
/// 1 (taken as `1 − 2⁻⁵³`, see the module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct PointsRead {
    /// The points, in [0,1)².
    pub points: Vec<DVec2>,
    /// The format the file was read as.
    pub format: PointFormat,
    /// Points with x = 1 or y = 1 exactly (0 with the bounding-box normalisation).
    pub on_closed_edge: usize,
}

/// Reads and parses a point file (see [`read_points_named`]). Errors do not name the file;
/// callers prefix its path.
pub fn read_points_file(
    path: &Path,
    out_of_range: OutOfRange,
) -> Result<Vec<DVec2>, PointsFileError> {
    read_points_file_report(path, out_of_range).map(|r| r.points)
}

/// [`read_points_file`] with the format and the points on the closed edge.
pub fn read_points_file_report(
    path: &Path,
    out_of_range: OutOfRange,
) -> Result<PointsRead, PointsFileError> {
    let io = |e: std::io::Error| PointsFileError::Io {
        path: path.display().to_string(),
        message: e.to_string(),
    };
    let file = std::fs::File::open(path).map_err(io)?;
    read_points_named(file, path, out_of_range).map_err(|e| match e {
        PointsFileError::Io { message, .. } => PointsFileError::Io {
            path: path.display().to_string(),
            message,
        },
        e => e,
    })
}

/// Maps the bounding box of `points` onto [0,1)², keeping the aspect ratio: every axis is
/// scaled by 1/(the larger extent) after subtracting the lower corner, then clamped to at most
/// 1 − 2⁻⁵³. Points must be finite; the arithmetic is done on halves, so coordinates spanning
/// more than `f64::MAX` (e.g. −1e308 and 1e308) do not overflow.
///
/// Errors: no points ([`PointsFileError::Empty`]); a bounding box that is a single point (one
/// point, or all equal: [`PointsFileError::DegenerateBoundingBox`]), which has no extent to
/// scale by.
pub fn normalize_to_bounding_box(raw: &[DVec2]) -> Result<Vec<DVec2>, PointsFileError> {
    let Some(&first) = raw.first() else {
        return Err(PointsFileError::Empty);
    };
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
    if half_extent.is_nan() || half_extent <= 0.0 {
        return Err(PointsFileError::DegenerateBoundingBox {
            n: raw.len(),
            x: first.x,
            y: first.y,
        });
    }
    let inverse = 1.0 / half_extent;
    Ok(raw
        .iter()
        .map(|p| {
            let half = *p * 0.5 - lo * 0.5;
            let q = if inverse.is_finite() {
                half * inverse
            } else {
                half / half_extent
            };
            DVec2::new(
                q.x.clamp(0.0, ONE_MINUS_EPSILON),
                q.y.clamp(0.0, ONE_MINUS_EPSILON),
            )
        })
        .collect())
}

/// Parses the text of a point file (see [`read_points`]).
pub fn parse_points(text: &str, out_of_range: OutOfRange) -> Result<Vec<DVec2>, PointsFileError> {
    read_points(text.as_bytes(), out_of_range)
}

/// Reads a point file without a name: `.npy` by its magic, otherwise text (see
/// [`read_points_named`], which also knows `.rps` by the extension).
pub fn read_points(
    reader: impl std::io::Read,
    out_of_range: OutOfRange,
) -> Result<Vec<DVec2>, PointsFileError> {
    read_points_named(reader, Path::new(""), out_of_range).map(|r| r.points)
}

/// Reads a point file as a stream, deciding its format by content (the `.npy` magic) and by
/// the extension of `name` (`.rps`; `.npy` without the magic is an error); see the module
/// docs for the formats and limits.
///
/// Text is strict: a data line has exactly two fields; extra columns and trailing separators
/// (other than the comma after pmj-cpp's `(x, y)`) are errors naming the line. A UTF-8
/// byte-order mark and CRLF line ends are accepted. A line longer than [`MAX_LINE_BYTES`], text
/// that is not UTF-8 (the error gives the byte offset), more than [`MAX_FILE_BYTES`] or more
/// than [`crate::core::pattern::MAX_N`] points end the read at once, so a binary or endless
/// input (`/dev/zero`, `/dev/urandom`) is refused after at most one line.
pub fn read_points_named(
    reader: impl std::io::Read,
    name: &Path,
    out_of_range: OutOfRange,
) -> Result<PointsRead, PointsFileError> {
    let raw = read_raw(
        reader,
        name,
        MAX_FILE_BYTES,
        crate::core::pattern::MAX_N,
        Columns::Two,
    )?;
    finish(raw, out_of_range)
}

fn io_error(e: std::io::Error) -> PointsFileError {
    PointsFileError::Io {
        path: String::new(),
        message: e.to_string(),
    }
}

/// Points as parsed, before the range check: each with where it stands in the file.
struct Raw {
    /// Coordinates per point.
    dims: usize,
    /// Every coordinate, row-major.
    coords: Vec<f64>,
    /// The line of each point (text), or empty (binary: the index is the position).
    lines: Vec<usize>,
    format: PointFormat,
}

/// How many columns a reader takes: exactly two (the 2D API: its messages name `x y`), or any
/// number the file declares (a header's names, a `.npy` shape, the first row).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Columns {
    Two,
    Any,
}

impl Raw {
    fn position(&self, i: usize) -> Position {
        match self.lines.get(i) {
            Some(&l) => Position::Line(l),
            None => Position::Point(i + 1),
        }
    }
}

/// [`read_points_named`] with other limits (bytes of text read, points kept).
#[cfg(test)]
fn read_limited(
    reader: impl std::io::Read,
    name: &Path,
    out_of_range: OutOfRange,
    max_bytes: u64,
    max: usize,
) -> Result<PointsRead, PointsFileError> {
    finish(
        read_raw(reader, name, max_bytes, max, Columns::Two)?,
        out_of_range,
    )
}

/// Reads a file's points before the range check: the format by content and name, at most
/// `max_bytes` of text and `max` points, the columns `columns` allows.
fn read_raw(
    reader: impl std::io::Read,
    name: &Path,
    max_bytes: u64,
    max: usize,
    columns: Columns,
) -> Result<Raw, PointsFileError> {
    let mut reader = reader;
    // The first bytes decide: the .npy magic, whatever the name.
    let mut head = [0u8; 6];
    let mut got = 0;
    while got < head.len() {
        match reader.read(&mut head[got..]) {
            Ok(0) => break,
            Ok(k) => got += k,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => {}
            Err(e) => return Err(io_error(e)),
        }
    }
    let stream = (&head[..got]).chain(reader);
    let ext = name
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase());
    if &head[..got] == NPY_MAGIC {
        read_npy(stream, max, columns)
    } else if ext.as_deref() == Some("npy") {
        Err(PointsFileError::Binary {
            format: PointFormat::Npy,
            message: format!(
                "the file does not start with the NumPy magic `\\x93NUMPY` ({EXPECTED_FORMATS})"
            ),
        })
    } else if ext.as_deref() == Some("rps") {
        read_rps(stream, max)
    } else {
        read_text(stream, max_bytes, max, columns)
    }
}

/// The range check (or the normalisation) every format shares.
fn finish(raw: Raw, out_of_range: OutOfRange) -> Result<PointsRead, PointsFileError> {
    debug_assert_eq!(raw.dims, 2);
    let points: Vec<DVec2> = raw
        .coords
        .chunks_exact(2)
        .map(|c| DVec2::new(c[0], c[1]))
        .collect();
    if points.is_empty() {
        return Err(PointsFileError::Empty);
    }
    match out_of_range {
        OutOfRange::Reject => {
            let mut on_closed_edge = 0;
            let edge = |v: f64| if v == 1.0 { ONE_MINUS_EPSILON } else { v };
            for (i, p) in points.iter().enumerate() {
                let ok = |v: f64| (0.0..=1.0).contains(&v);
                if !ok(p.x) || !ok(p.y) {
                    return Err(PointsFileError::OutOfRange {
                        at: raw.position(i),
                        x: p.x,
                        y: p.y,
                    });
                }
                if p.x == 1.0 || p.y == 1.0 {
                    on_closed_edge += 1;
                }
            }
            let points = if on_closed_edge > 0 {
                points
                    .iter()
                    .map(|p| DVec2::new(edge(p.x), edge(p.y)))
                    .collect()
            } else {
                points
            };
            Ok(PointsRead {
                points,
                format: raw.format,
                on_closed_edge,
            })
        }
        OutOfRange::NormalizeToBoundingBox => Ok(PointsRead {
            points: normalize_to_bounding_box(&points)?,
            format: raw.format,
            on_closed_edge: 0,
        }),
    }
}

/// Reads text rows (see the module docs).
fn read_text(
    reader: impl std::io::Read,
    max_bytes: u64,
    max: usize,
    columns: Columns,
) -> Result<Raw, PointsFileError> {
    use std::io::BufRead;
    let max_line = match columns {
        Columns::Two => MAX_LINE_BYTES,
        Columns::Any => MAX_CUBE_LINE_BYTES,
    };
    let mut reader = std::io::BufReader::new(reader.take(max_bytes + 1));
    let mut coords: Vec<f64> = Vec::new();
    // Columns::Two: 2. Columns::Any: set by the header or the first row, with that line.
    let mut dims: Option<(usize, usize, &str)> = match columns {
        Columns::Two => Some((2, 0, "")),
        Columns::Any => None,
    };
    let mut lines: Vec<usize> = Vec::new();
    let mut count_line: Option<(usize, usize)> = None;
    let mut first_content = true;
    let mut buf: Vec<u8> = Vec::with_capacity(128);
    let mut offset: u64 = 0;
    let mut line = 0usize;
    loop {
        buf.clear();
        // At most MAX_LINE_BYTES + 1 bytes of one line are ever held.
        let n = (&mut reader)
            .take(max_line as u64 + 1)
            .read_until(b'\n', &mut buf)
            .map_err(io_error)?;
        if n == 0 {
            break;
        }
        line += 1;
        if offset + n as u64 > max_bytes {
            return Err(PointsFileError::TooLarge { max_bytes });
        }
        let ended = buf.last() == Some(&b'\n');
        if !ended && n > max_line {
            return Err(PointsFileError::LineTooLong {
                line,
                max: max_line,
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
        let body = unwrap_row(t).map_err(|message| PointsFileError::Malformed { line, message })?;
        let fields: Vec<&str> = if body.contains(',') {
            body.split(',').map(str::trim).collect()
        } else {
            body.split_whitespace().collect()
        };
        if first_content {
            first_content = false;
            // A header (column names: two, or any number) or a count line.
            if fields.iter().all(|f| f.parse::<f64>().is_err()) {
                let names = fields.iter().all(|f| is_column_name(f));
                match columns {
                    Columns::Two if names && fields.len() == 2 => continue,
                    Columns::Any if names => {
                        check_columns(fields.len(), line)?;
                        dims = Some((fields.len(), line, "the header on line"));
                        continue;
                    }
                    Columns::Two => {
                        return Err(PointsFileError::Malformed {
                            line,
                            message: format!(
                                "expected a header of two column names (`x,y`), a count or a point, found `{t}`"
                            ),
                        })
                    }
                    Columns::Any => {
                        return Err(PointsFileError::Malformed {
                            line,
                            message: format!(
                                "expected a header of column names (`x0,x1,…`), a count or a point, found `{t}`"
                            ),
                        })
                    }
                }
            }
            // In any-column files a single value that is not a count is a 1D point.
            let count_like = columns == Columns::Two || fields[0].parse::<usize>().is_ok();
            if fields.len() == 1 && count_like {
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
        let (want, since, what) = match dims {
            Some(d) => d,
            None => {
                check_columns(fields.len(), line)?;
                dims = Some((fields.len(), line, "line"));
                (fields.len(), line, "line")
            }
        };
        if columns == Columns::Any && fields.len() != want {
            let message = if fields.len() > want && fields.last() == Some(&"") {
                format!("a trailing separator after the coordinates in `{t}`")
            } else {
                format!(
                    "expected {want} coordinates (the columns of {what} {since}), found {} in `{t}`",
                    fields.len()
                )
            };
            return Err(PointsFileError::Malformed { line, message });
        }
        if fields.len() != want {
            let message = if fields.len() > 2 && fields.last() == Some(&"") {
                format!("a trailing separator after the coordinates in `{t}`")
            } else if fields.len() > 2 {
                format!(
                    "expected two coordinates `x y`, `x,y` or `(x, y),`, found {} fields in `{t}`",
                    fields.len()
                )
            } else {
                format!("expected two coordinates `x y`, `x,y` or `(x, y),`, found `{t}`")
            };
            return Err(PointsFileError::Malformed { line, message });
        }
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
            coords.push(v);
        }
        // At most `max` points, and n·dims within the coordinate limit.
        let max = max.min(crate::core::cube::MAX_COORDS / want);
        if lines.len() >= max {
            return Err(PointsFileError::TooMany {
                found: lines.len() + 1,
                max,
            });
        }
        lines.push(line);
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
    Ok(Raw {
        dims: dims.map_or(2, |d| d.0),
        coords,
        lines,
        format: PointFormat::Text,
    })
}

/// Checks a file's column count against [`crate::core::cube::MAX_DIMS`].
fn check_columns(k: usize, line: usize) -> Result<(), PointsFileError> {
    use crate::core::cube::MAX_DIMS;
    if k > MAX_DIMS {
        return Err(PointsFileError::Malformed {
            line,
            message: format!("{k} columns: a point has at most {MAX_DIMS} coordinates (dims)"),
        });
    }
    Ok(())
}

/// The inside of a row wrapped as pmj-cpp writes it, `(x, y),` (or `[x, y],`): the text
/// between the brackets, which may be followed by one comma. Other rows are returned as they
/// are.
fn unwrap_row(t: &str) -> Result<&str, String> {
    let close = match t.as_bytes()[0] {
        b'(' => ')',
        b'[' => ']',
        _ => return Ok(t),
    };
    let Some(end) = t.rfind(close) else {
        return Err(format!("`{t}` opens `{}` but never closes it", &t[..1]));
    };
    let rest = t[end + 1..].trim();
    if !(rest.is_empty() || rest == ",") {
        return Err(format!(
            "`{rest}` after `{close}` in `{t}` (expected `(x, y)` with at most one comma after it)"
        ));
    }
    Ok(&t[1..end])
}

/// Whether a header field is a column name: a letter or `_` first (after optional quotes),
/// then letters, digits, `_`, `-`, `.` or spaces.
fn is_column_name(f: &str) -> bool {
    let f = f.trim_matches(|c| c == '"' || c == '\'');
    let mut chars = f.chars();
    chars.next().is_some_and(|c| c.is_alphabetic() || c == '_')
        && chars.all(|c| c.is_alphanumeric() || matches!(c, '_' | '-' | '.' | ' '))
}

/// Reads exactly `buf.len()` bytes, or says how many came before the end.
fn read_full(reader: &mut impl std::io::Read, buf: &mut [u8]) -> Result<usize, PointsFileError> {
    let mut got = 0;
    while got < buf.len() {
        match reader.read(&mut buf[got..]) {
            Ok(0) => break,
            Ok(k) => got += k,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => {}
            Err(e) => return Err(io_error(e)),
        }
    }
    Ok(got)
}

/// Checks a coordinate read from a binary file: finite.
fn binary_value(format: PointFormat, v: f64, i: usize, axis: &str) -> Result<f64, PointsFileError> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(PointsFileError::Binary {
            format,
            message: format!("point {}: {axis} = {v} is not finite", i + 1),
        })
    }
}

/// Reads PSA's `.rps`: little-endian float32 pairs, no header (PSA: N = file size / 8).
fn read_rps(reader: impl std::io::Read, max: usize) -> Result<Raw, PointsFileError> {
    let format = PointFormat::Rps;
    let mut reader = std::io::BufReader::new(reader);
    let mut coords: Vec<f64> = Vec::new();
    let mut pair = [0u8; 8];
    loop {
        let got = read_full(&mut reader, &mut pair)?;
        if got == 0 {
            break;
        }
        let i = coords.len() / 2;
        if got < 8 {
            let bytes = i as u64 * 8 + got as u64;
            return Err(PointsFileError::Binary {
                format,
                message: format!(
                    "{bytes} bytes is not a whole number of float32 pairs (8 bytes each): the file is truncated"
                ),
            });
        }
        if i >= max {
            return Err(PointsFileError::TooMany { found: i + 1, max });
        }
        let x = f32::from_le_bytes([pair[0], pair[1], pair[2], pair[3]]) as f64;
        let y = f32::from_le_bytes([pair[4], pair[5], pair[6], pair[7]]) as f64;
        coords.push(binary_value(format, x, i, "x")?);
        coords.push(binary_value(format, y, i, "y")?);
    }
    Ok(Raw {
        dims: 2,
        coords,
        lines: Vec::new(),
        format,
    })
}

/// The magic a `.npy` file starts with.
const NPY_MAGIC: &[u8] = b"\x93NUMPY";

/// A `.npy` header's fields.
#[derive(Debug, PartialEq)]
struct NpyHeader {
    /// 4 or 8.
    width: usize,
    big_endian: bool,
    fortran: bool,
    n: usize,
    /// Columns: 2 for `(N, 2)`, D for `(N, D)`, 1 for `(N,)`.
    dims: usize,
}

/// Reads a NumPy `.npy` file of shape (N, 2) (with [`Columns::Any`]: (N, D) or (N,)),
/// float32 or float64.
fn read_npy(
    reader: impl std::io::Read,
    max: usize,
    columns: Columns,
) -> Result<Raw, PointsFileError> {
    let format = PointFormat::Npy;
    let err = |message: String| PointsFileError::Binary { format, message };
    let mut reader = std::io::BufReader::new(reader);
    let mut pre = [0u8; 8];
    if read_full(&mut reader, &mut pre)? < 8 {
        return Err(err("the file ends inside the magic and version".into()));
    }
    let (major, minor) = (pre[6], pre[7]);
    let header_len = match major {
        1 => {
            let mut l = [0u8; 2];
            if read_full(&mut reader, &mut l)? < 2 {
                return Err(err("the file ends inside the header length".into()));
            }
            u16::from_le_bytes(l) as usize
        }
        2 | 3 => {
            let mut l = [0u8; 4];
            if read_full(&mut reader, &mut l)? < 4 {
                return Err(err("the file ends inside the header length".into()));
            }
            u32::from_le_bytes(l) as usize
        }
        _ => {
            return Err(err(format!(
                "format version {major}.{minor}: must be 1.0, 2.0 or 3.0"
            )))
        }
    };
    if header_len > MAX_NPY_HEADER_BYTES {
        return Err(err(format!(
            "header of {header_len} bytes: at most {MAX_NPY_HEADER_BYTES} (NumPy's own limit)"
        )));
    }
    let mut header = vec![0u8; header_len];
    if read_full(&mut reader, &mut header)? < header_len {
        return Err(err(format!(
            "the file ends inside the {header_len}-byte header"
        )));
    }
    let text = std::str::from_utf8(&header).map_err(|_| err("the header is not text".into()))?;
    let h = parse_npy_header(text, columns).map_err(|m| err(format!("header: {m}")))?;
    if h.n == 0 {
        return Err(PointsFileError::Empty);
    }
    let max = max.min(crate::core::cube::MAX_COORDS / h.dims);
    if h.n > max {
        return Err(PointsFileError::TooMany { found: h.n, max });
    }
    // Grows with the values actually read: the declared shape never sizes an allocation.
    let d = h.dims;
    let total = d * h.n;
    let mut values: Vec<f64> = Vec::with_capacity(total.min(1 << 16));
    let mut word = [0u8; 8];
    let w = h.width;
    while values.len() < total {
        let got = read_full(&mut reader, &mut word[..w])?;
        if got < w {
            return Err(err(format!(
                "the data ends after {} of the {} values of shape ({}, {d}): the file is truncated",
                values.len(),
                total,
                h.n
            )));
        }
        let v = match (w, h.big_endian) {
            (4, false) => f32::from_le_bytes([word[0], word[1], word[2], word[3]]) as f64,
            (4, true) => f32::from_be_bytes([word[0], word[1], word[2], word[3]]) as f64,
            (_, false) => f64::from_le_bytes(word),
            (_, true) => f64::from_be_bytes(word),
        };
        values.push(v);
    }
    let mut extra = [0u8; 1];
    if read_full(&mut reader, &mut extra)? > 0 {
        return Err(err(format!(
            "bytes after the {} values of shape ({}, {d}): not what numpy.save writes",
            total, h.n
        )));
    }
    let mut coords = Vec::with_capacity(total);
    for i in 0..h.n {
        for k in 0..d {
            let v = if h.fortran {
                values[k * h.n + i]
            } else {
                values[d * i + k]
            };
            let axis = match (d, k) {
                (2, 0) => "x".to_string(),
                (2, _) => "y".to_string(),
                _ => format!("x{k}"),
            };
            coords.push(binary_value(format, v, i, &axis)?);
        }
    }
    Ok(Raw {
        dims: d,
        coords,
        lines: Vec::new(),
        format,
    })
}

/// Parses the Python dict literal of a `.npy` header:
/// `{'descr': '<f8', 'fortran_order': False, 'shape': (N, 2), }` (keys in any order, each
/// once, no others, as NumPy requires).
fn parse_npy_header(text: &str, columns: Columns) -> Result<NpyHeader, String> {
    let t = text.trim_end_matches(['\n', ' ', '\0']).trim_start();
    let inner = t
        .strip_prefix('{')
        .and_then(|s| s.strip_suffix('}'))
        .ok_or_else(|| format!("`{}`: must be a dict `{{…}}`", short(t)))?;
    let (mut descr, mut fortran, mut shape) = (None, None, None);
    let mut rest = inner.trim_start();
    while !rest.is_empty() {
        let (key, after) =
            py_string(rest).ok_or_else(|| format!("`{}`: expected a quoted key", short(rest)))?;
        let after = after
            .trim_start()
            .strip_prefix(':')
            .ok_or_else(|| format!("`{key}`: expected `:` after the key"))?
            .trim_start();
        let after = match key {
            "descr" if descr.is_none() => {
                let (v, a) = py_string(after)
                    .ok_or_else(|| "descr: expected a quoted type such as '<f8'".to_string())?;
                descr = Some(v);
                a
            }
            "fortran_order" if fortran.is_none() => {
                if let Some(a) = after.strip_prefix("True") {
                    fortran = Some(true);
                    a
                } else if let Some(a) = after.strip_prefix("False") {
                    fortran = Some(false);
                    a
                } else {
                    return Err("fortran_order: must be True or False".into());
                }
            }
            "shape" if shape.is_none() => {
                let a = after
                    .strip_prefix('(')
                    .ok_or_else(|| "shape: expected a tuple `(N, 2)`".to_string())?;
                let end = a
                    .find(')')
                    .ok_or_else(|| "shape: the tuple is not closed".to_string())?;
                let dims: Result<Vec<usize>, _> = a[..end]
                    .split(',')
                    .map(str::trim)
                    .filter(|s| !s.is_empty())
                    .map(|s| s.parse::<usize>())
                    .collect();
                let dims = dims.map_err(|_| format!("shape ({}): must be (N, 2)", &a[..end]))?;
                shape = Some(dims);
                &a[end + 1..]
            }
            "descr" | "fortran_order" | "shape" => return Err(format!("`{key}` is given twice")),
            other => {
                return Err(format!(
                "unknown key `{other}`: a .npy header holds exactly descr, fortran_order and shape"
            ))
            }
        };
        let after = after.trim_start();
        rest = match after.strip_prefix(',') {
            Some(r) => r.trim_start(),
            None if after.is_empty() => after,
            None => {
                return Err(format!(
                    "`{}`: expected `,` between the entries",
                    short(after)
                ))
            }
        };
    }
    let descr = descr.ok_or("descr is missing")?;
    let fortran = fortran.ok_or("fortran_order is missing")?;
    let shape = shape.ok_or("shape is missing")?;
    let (width, big_endian) = match descr {
        "<f8" => (8, false),
        "<f4" => (4, false),
        ">f8" => (8, true),
        ">f4" => (4, true),
        other => {
            return Err(format!(
                "descr '{other}': must be float32 or float64 ('<f4', '<f8', '>f4' or '>f8')"
            ))
        }
    };
    use crate::core::cube::MAX_DIMS;
    let (n, dims) = match (columns, shape.as_slice()) {
        (_, [n, 2]) => (*n, 2),
        (Columns::Any, [n, d]) if (1..=MAX_DIMS).contains(d) => (*n, *d),
        (Columns::Any, [n]) => (*n, 1),
        (columns, dims) => {
            let d: Vec<String> = dims.iter().map(|d| d.to_string()).collect();
            return Err(match columns {
                Columns::Two => format!("shape ({}): must be (N, 2)", d.join(", ")),
                Columns::Any => format!(
                    "shape ({}): must be (N, D) with 1 ≤ D ≤ {MAX_DIMS} (dims), or (N,)",
                    d.join(", ")
                ),
            });
        }
    };
    Ok(NpyHeader {
        width,
        big_endian,
        fortran,
        n,
        dims,
    })
}

/// A Python string literal in single or double quotes at the start of `s` (no escapes, which
/// no key or type name of a `.npy` header holds), and the text after it.
fn py_string(s: &str) -> Option<(&str, &str)> {
    let q = s.chars().next().filter(|c| *c == '\'' || *c == '"')?;
    let end = s[1..].find(q)? + 1;
    Some((&s[1..end], &s[end + 1..]))
}

/// At most 40 characters of `s`, control characters escaped, for one-line messages.
fn short(s: &str) -> String {
    let mut out: String = s
        .chars()
        .take(40)
        .flat_map(|c| {
            let escaped: Vec<char> = if c.is_control() {
                c.escape_debug().collect()
            } else {
                vec![c]
            };
            escaped
        })
        .collect();
    if s.chars().count() > 40 {
        out.push('…');
    }
    out
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
        assert!(matches!(
            e,
            PointsFileError::OutOfRange {
                at: Position::Line(2),
                ..
            }
        ));
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
        let name = Path::new("");
        let e = read_limited(endless(), name, OutOfRange::Reject, 1 << 20, 1000).unwrap_err();
        assert_eq!(
            e,
            PointsFileError::TooMany {
                found: 1001,
                max: 1000
            }
        );
        let e = read_limited(endless(), name, OutOfRange::Reject, 800, 1000).unwrap_err();
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
