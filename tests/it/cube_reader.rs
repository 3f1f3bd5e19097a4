//! Point files of any number of columns (`core::pointset::read_cube_named`): headers and
//! column counts, ragged rows, `.npy` of shape (N, D), the limits, and the 2D reader unchanged.

use samplescope::core::cube::MAX_DIMS;
use samplescope::core::pointset::{
    parse_cube, parse_points, read_cube_named, OutOfRange, PointFormat, PointsFileError,
};
use std::path::Path;

fn cube(text: &str) -> Result<samplescope::core::cube::CubePoints, PointsFileError> {
    parse_cube(text, OutOfRange::Reject)
}

#[test]
fn header_or_first_row_sets_the_columns() {
    let p = cube("x0,x1,x2\n0.1,0.2,0.3\n0.4,0.5,0.6\n").unwrap();
    assert_eq!((p.n(), p.dims()), (2, 3));
    assert_eq!(p.point(1), &[0.4, 0.5, 0.6]);
    let q = cube("# comment\n0.1 0.2 0.3\n0.4\t0.5 0.6\n").unwrap();
    assert_eq!(p, q);
    let one = cube("0.25\n0.5\n0.75\n").unwrap();
    assert_eq!((one.n(), one.dims()), (3, 1));
    let counted = cube("2\n0.1 0.2 0.3 0.4\n0.5 0.6 0.7 0.8\n").unwrap();
    assert_eq!((counted.n(), counted.dims()), (2, 4));
    // A coordinate exactly 1 is the closed edge, as in 2D.
    let edge =
        read_cube_named("0.5,1,0.5\n".as_bytes(), Path::new(""), OutOfRange::Reject).unwrap();
    assert_eq!(edge.on_closed_edge, 1);
    assert!(edge.points.point(0)[1] < 1.0);
}

#[test]
fn ragged_rows_name_the_line_and_the_expected_count() {
    let e = cube("x0,x1,x2\n0.1,0.2,0.3\n0.4,0.5\n").unwrap_err();
    assert_eq!(
        e.to_string(),
        "line 3: expected 3 coordinates (the columns of the header on line 1), found 2 in `0.4,0.5`"
    );
    let e = cube("0.1 0.2 0.3\n\n0.4 0.5 0.6 0.7\n").unwrap_err();
    assert_eq!(
        e.to_string(),
        "line 3: expected 3 coordinates (the columns of line 1), found 4 in `0.4 0.5 0.6 0.7`"
    );
    let e = cube("x0,x1,x2\n0.1,0.2,0.3,\n").unwrap_err();
    assert!(
        e.to_string().starts_with("line 2: a trailing separator"),
        "{e}"
    );
    let e = cube("0.1,0.2,abc\n").unwrap_err();
    assert_eq!(e.to_string(), "line 1: column 3: `abc` is not a number");
    let e = cube("x0,x1,x2\n0.1,1.5,0.3\n").unwrap_err();
    assert_eq!(
        e.to_string(),
        "line 2: x1 = 1.5 is outside [0,1]; use the bounding-box normalisation to map it in"
    );
}

#[test]
fn more_columns_than_the_limit_are_refused_with_the_limit() {
    let header: Vec<String> = (0..=MAX_DIMS).map(|k| format!("x{k}")).collect();
    let e = cube(&format!("{}\n", header.join(","))).unwrap_err();
    assert_eq!(
        e.to_string(),
        "line 1: 1025 columns: a point has at most 1024 coordinates (dims)"
    );
    // 1024 columns of 17-digit numbers fit on one line.
    let row: Vec<String> = (0..MAX_DIMS)
        .map(|k| format!("{:.17}", k as f64 / 2048.0))
        .collect();
    let p = cube(&format!("{}\n", row.join(","))).unwrap();
    assert_eq!(p.dims(), MAX_DIMS);
}

/// A version 1.0 `.npy` of little-endian float64 in C order.
fn npy(shape: &str, values: &[f64]) -> Vec<u8> {
    let mut header = format!("{{'descr': '<f8', 'fortran_order': False, 'shape': {shape}, }}");
    while (10 + header.len() + 1) % 64 != 0 {
        header.push(' ');
    }
    header.push('\n');
    let mut out = b"\x93NUMPY\x01\x00".to_vec();
    out.extend((header.len() as u16).to_le_bytes());
    out.extend(header.as_bytes());
    for v in values {
        out.extend(v.to_le_bytes());
    }
    out
}

#[test]
fn npy_of_any_width_and_the_2d_reader_unchanged() {
    let values = [0.1, 0.2, 0.3, 0.4, 0.5, 0.6];
    let r = read_cube_named(
        &npy("(2, 3)", &values)[..],
        Path::new("a.npy"),
        OutOfRange::Reject,
    )
    .unwrap();
    assert_eq!(r.format, PointFormat::Npy);
    assert_eq!((r.points.n(), r.points.dims()), (2, 3));
    assert_eq!(r.points.coords(), &values);
    let r = read_cube_named(
        &npy("(6,)", &values)[..],
        Path::new("a.npy"),
        OutOfRange::Reject,
    )
    .unwrap();
    assert_eq!(r.points.dims(), 1);
    // The 2D reader still wants (N, 2) and two columns, with the same messages.
    let e = samplescope::core::pointset::read_points_named(
        &npy("(2, 3)", &values)[..],
        Path::new("a.npy"),
        OutOfRange::Reject,
    )
    .unwrap_err();
    assert_eq!(
        e.to_string(),
        "NumPy .npy: header: shape (2, 3): must be (N, 2)"
    );
    let e = parse_points("0.1,0.2,0.3\n", OutOfRange::Reject).unwrap_err();
    assert!(e.to_string().contains("expected two coordinates"), "{e}");
    // Two columns through the any-column reader: the 2D reader's points.
    let text = "x,y\n0.25,0.5\n1,0.125\n";
    let two = parse_points(text, OutOfRange::Reject).unwrap();
    assert_eq!(cube(text).unwrap().to_2d().unwrap(), two);
}

#[test]
fn the_scipy_reference_sets_read_back_exactly() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/scipy/discrepancy");
    for (name, dims) in [
        ("d1-random-n512", 1),
        ("d8-sobol-n128", 8),
        ("d32-random-n64", 32),
    ] {
        let path = dir.join(format!("{name}.csv"));
        let r = samplescope::core::pointset::read_cube_file(&path, OutOfRange::Reject).unwrap();
        assert_eq!(r.points.dims(), dims);
        let text = std::fs::read_to_string(&path).unwrap();
        let first: Vec<f64> = text
            .lines()
            .nth(1)
            .unwrap()
            .split(',')
            .map(|v| v.parse().unwrap())
            .collect();
        assert_eq!(r.points.point(0), &first[..]);
    }
    // Normalisation maps the bounding box onto [0,1)^d, the aspect kept.
    let p = parse_cube("0 0 0\n2 1 4\n", OutOfRange::NormalizeToBoundingBox).unwrap();
    assert_eq!(p.point(1)[0], 0.5);
    assert_eq!(p.point(1)[1], 0.25);
    assert!(p.point(1)[2] < 1.0);
}
