//! Reading what peer tools write (`tests/data/interop`, each file made by the tool itself; see
//! its README): pmj-cpp's `(x, y),` rows, PSA's `.rps` and count-line text, NumPy's `.npy`
//! (float32/float64, C/Fortran order, format 1.0/2.0, big-endian) and `savetxt` text, and the
//! closed square [0,1]² as `numpy.linspace` gives it. Every entry point shares the reader:
//! `analyze --points`, a scene's `points: Some((path: …))` and the GUI's import.

use glam::DVec2;
use samplescope::core::pattern::ONE_MINUS_EPSILON;
use samplescope::core::pointset::{
    read_points_file, read_points_file_report, read_points_named, OutOfRange, PointFormat,
    PointsFileError, Position,
};
use samplescope::scene::{ImportedPoints, Scene};
use std::path::{Path, PathBuf};
use std::process::Command;

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/interop")
        .join(name)
}

fn read(name: &str) -> Vec<DVec2> {
    read_points_file(&data(name), OutOfRange::Reject).unwrap_or_else(|e| panic!("{name}: {e}"))
}

fn scratch(name: &str) -> PathBuf {
    let d = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("interop");
    std::fs::create_dir_all(&d).unwrap();
    d.join(name)
}

fn samplescope(args: &[&str]) -> (Option<i32>, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_samplescope"))
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn pmj_cpp_rows_are_read_exactly() {
    let p = read("pmj-cpp-pmj02-256.txt");
    assert_eq!(p.len(), 256);
    // The first and last rows of the file, as pmj-cpp printed them (17 digits: exact f64).
    let first: Vec<f64> = ["0.91553402424626096", "0.42208719915920739"]
        .iter()
        .map(|v| v.parse().unwrap())
        .collect();
    assert_eq!(p[0], DVec2::new(first[0], first[1]));
    let text = std::fs::read_to_string(data("pmj-cpp-pmj02-256.txt")).unwrap();
    let last = text.lines().last().unwrap();
    assert!(last.starts_with('(') && last.ends_with("),"), "{last}");
    let inner: Vec<f64> = last[1..last.len() - 2]
        .split(", ")
        .map(|v| v.parse().unwrap())
        .collect();
    assert_eq!(p[255], DVec2::new(inner[0], inner[1]));
}

#[test]
fn psa_rps_matches_psa_text_of_the_same_points() {
    let r = read_points_file_report(&data("psa-jitter-64.rps"), OutOfRange::Reject).unwrap();
    assert_eq!(r.format, PointFormat::Rps);
    let t = read_points_file_report(&data("psa-jitter-64.txt"), OutOfRange::Reject).unwrap();
    assert_eq!(t.format, PointFormat::Text);
    assert_eq!((r.points.len(), t.points.len()), (64, 64));
    // PSA's text keeps 6 significant digits of the same float32 values.
    for (a, b) in r.points.iter().zip(&t.points) {
        assert!((*a - *b).abs().max_element() <= 5e-7, "{a} vs {b}");
        // The .rps values are float32.
        assert_eq!(a.x as f32 as f64, a.x);
        assert_eq!(a.y as f32 as f64, a.y);
    }
    // The 8 × 8 strata hold one point each.
    let mut cells: Vec<usize> = r
        .points
        .iter()
        .map(|p| (p.y * 8.0) as usize * 8 + (p.x * 8.0) as usize)
        .collect();
    cells.sort();
    assert_eq!(cells, (0..64).collect::<Vec<_>>());
}

#[test]
fn npy_in_every_layout_equals_the_savetxt_values() {
    let reference = read("numpy-savetxt.txt");
    assert_eq!(reference.len(), 16);
    for name in [
        "npy-f64-c-v1.npy",
        "npy-f64-fortran-v1.npy",
        "npy-f64-c-v2.npy",
        "npy-f64-big-endian.npy",
    ] {
        let r = read_points_file_report(&data(name), OutOfRange::Reject).unwrap();
        assert_eq!(r.format, PointFormat::Npy, "{name}");
        assert_eq!(r.points, reference, "{name}");
    }
    let f32s = read("npy-f32-c-v1.npy");
    let rounded: Vec<DVec2> = reference
        .iter()
        .map(|p| DVec2::new(p.x as f32 as f64, p.y as f32 as f64))
        .collect();
    assert_eq!(f32s, rounded);
    // Tab-separated with NumPy's `# x\ty` header line.
    assert_eq!(read("numpy-savetxt-tab-header.tsv"), reference);
    // The magic decides, not the name: the same bytes under another name.
    let renamed = scratch("points-without-extension");
    std::fs::copy(data("npy-f64-c-v1.npy"), &renamed).unwrap();
    assert_eq!(
        read_points_file(&renamed, OutOfRange::Reject).unwrap(),
        reference
    );
}

#[test]
fn text_separators_headers_and_wrappers() {
    let expected = vec![DVec2::new(0.25, 0.5), DVec2::new(0.75, 0.125)];
    for text in [
        "x,y\n0.25,0.5\n0.75,0.125\n",
        "X Y\n0.25 0.5\n0.75 0.125\n",
        "\"x\",\"y\"\n0.25,0.5\n0.75,0.125\n",
        "px\tpy\n0.25\t0.5\n0.75\t0.125\n",
        "0.25, 0.5\n0.75 ,0.125\n",
        "0.25\t0.5\n0.75  0.125\n",
        "(0.25, 0.5),\n(0.75, 0.125),\n",
        "(0.25, 0.5),\n(0.75, 0.125)\n",
        "[0.25, 0.5],\n[0.75, 0.125]\n",
        "2\n(0.25 0.5)\n(0.75 0.125)\n",
    ] {
        let p = read_points_named(text.as_bytes(), Path::new("t.txt"), OutOfRange::Reject)
            .unwrap_or_else(|e| panic!("{text:?}: {e}"));
        assert_eq!(p.points, expected, "{text:?}");
    }
    for (text, line, needle) in [
        ("(0.25, 0.5\n", 1, "never closes"),
        ("(0.25, 0.5),,\n", 1, "after `)`"),
        ("(0.25, 0.5, 0.1),\n", 1, "3 fields"),
        ("x,y,z\n0.1,0.2\n", 1, "header of two column names"),
        ("0.1,0.2\n0.3,0.4,\n", 2, "trailing separator"),
    ] {
        match read_points_named(text.as_bytes(), Path::new("t.txt"), OutOfRange::Reject) {
            Err(PointsFileError::Malformed { line: l, message }) => {
                assert_eq!(l, line, "{text:?}: {message}");
                assert!(message.contains(needle), "{text:?}: {message}");
            }
            other => panic!("{text:?}: {other:?}"),
        }
    }
}

#[test]
fn the_closed_square_is_accepted_with_one_minus_epsilon() {
    let r =
        read_points_file_report(&data("numpy-linspace-closed.csv"), OutOfRange::Reject).unwrap();
    assert_eq!(r.points.len(), 9);
    // x = 1 in 3 points, y = 1 in 3, both in 1.
    assert_eq!(r.on_closed_edge, 5);
    assert_eq!(r.points[2], DVec2::new(ONE_MINUS_EPSILON, 0.0));
    assert_eq!(r.points[8], DVec2::splat(ONE_MINUS_EPSILON));
    assert_eq!(r.points[4], DVec2::splat(0.5));
    // The next f64 above 1 is outside, named by its line.
    let above = format!("0.5 {}\n", f64::from_bits(1f64.to_bits() + 1));
    match read_points_named(above.as_bytes(), Path::new("a.txt"), OutOfRange::Reject) {
        Err(PointsFileError::OutOfRange {
            at: Position::Line(1),
            ..
        }) => {}
        other => panic!("{other:?}"),
    }
    // analyze reads it, with a note saying what was done.
    let path = data("numpy-linspace-closed.csv");
    let (code, out, err) = samplescope(&[
        "analyze",
        "--points",
        path.to_str().unwrap(),
        "--size",
        "16",
        "--json",
    ]);
    assert_eq!(code, Some(0), "{err}");
    assert!(
        err.contains("5 point(s) on the closed edge") && err.contains("1 − 2⁻⁵³"),
        "{err}"
    );
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["n"], 9);
}

#[test]
fn normalising_a_single_point_is_refused_not_moved_to_the_origin() {
    let one = scratch("one-point.txt");
    std::fs::write(&one, "0.5 0.5\n").unwrap();
    match read_points_file(&one, OutOfRange::NormalizeToBoundingBox) {
        Err(PointsFileError::DegenerateBoundingBox { n: 1, x, y }) => {
            assert_eq!((x, y), (0.5, 0.5))
        }
        other => panic!("{other:?}"),
    }
    let same = scratch("same-points.txt");
    std::fs::write(&same, "3\n2 7\n2 7\n2 7\n").unwrap();
    let e = read_points_file(&same, OutOfRange::NormalizeToBoundingBox).unwrap_err();
    assert!(
        matches!(e, PointsFileError::DegenerateBoundingBox { n: 3, .. }),
        "{e:?}"
    );
    let (code, out, err) = samplescope(&[
        "analyze",
        "--points",
        one.to_str().unwrap(),
        "--normalize",
        "--size",
        "16",
    ]);
    assert_eq!(code, Some(2), "{out}{err}");
    assert_eq!(err.trim().lines().count(), 1, "{err}");
    assert!(
        err.contains("bounding box") && err.contains("(0.5, 0.5)"),
        "{err}"
    );
    // Points on a line (zero extent on one axis only) are mapped, aspect kept.
    let line = scratch("line.txt");
    std::fs::write(&line, "2 5\n4 5\n3 5\n").unwrap();
    let p = read_points_file(&line, OutOfRange::NormalizeToBoundingBox).unwrap();
    assert_eq!(
        p,
        vec![
            DVec2::new(0.0, 0.0),
            DVec2::new(ONE_MINUS_EPSILON, 0.0),
            DVec2::new(0.5, 0.0)
        ]
    );
}

#[test]
fn unknown_binary_truncated_and_oversized_files_get_one_line() {
    // Not text and not a known binary format: one line naming what is expected.
    let png = scratch("picture.dat");
    std::fs::write(&png, b"\x89PNG\r\n\x1a\n\0\0\0\rIHDR").unwrap();
    let e = read_points_file(&png, OutOfRange::Reject)
        .unwrap_err()
        .to_string();
    assert!(
        e.contains(".npy") && e.contains(".rps") && e.contains("(x, y),") && !e.contains('\n'),
        "{e}"
    );
    // .npy by name without the magic.
    let fake = scratch("fake.npy");
    std::fs::write(&fake, "0.1 0.2\n").unwrap();
    let e = read_points_file(&fake, OutOfRange::Reject)
        .unwrap_err()
        .to_string();
    assert!(e.starts_with("NumPy .npy:") && e.contains("magic"), "{e}");
    // A truncated .rps (PSA would silently drop the half pair).
    let bytes = std::fs::read(data("psa-jitter-64.rps")).unwrap();
    let cut = scratch("cut.rps");
    std::fs::write(&cut, &bytes[..bytes.len() - 3]).unwrap();
    let e = read_points_file(&cut, OutOfRange::Reject)
        .unwrap_err()
        .to_string();
    assert_eq!(
        e,
        "PSA .rps: 509 bytes is not a whole number of float32 pairs (8 bytes each): the file is truncated"
    );
    // A .npy declaring more points than any file may hold is refused before its data is read
    // (nothing sized by the declared shape).
    let header = "{'descr': '<f8', 'fortran_order': False, 'shape': (1000000000000, 2), }";
    let mut npy = b"\x93NUMPY\x01\x00".to_vec();
    npy.extend_from_slice(&(header.len() as u16).to_le_bytes());
    npy.extend_from_slice(header.as_bytes());
    npy.extend_from_slice(&[0u8; 32]);
    let e = read_points_named(&npy[..], Path::new("big.npy"), OutOfRange::Reject).unwrap_err();
    assert!(
        matches!(
            e,
            PointsFileError::TooMany {
                found: 1_000_000_000_000,
                ..
            }
        ),
        "{e:?}"
    );
    // A declared shape larger than the data: truncated, after reading what is there.
    let header = "{'descr': '<f8', 'fortran_order': False, 'shape': (1000, 2), }";
    let mut npy = b"\x93NUMPY\x01\x00".to_vec();
    npy.extend_from_slice(&(header.len() as u16).to_le_bytes());
    npy.extend_from_slice(header.as_bytes());
    npy.extend_from_slice(&0.5f64.to_le_bytes().repeat(10));
    let e = read_points_named(&npy[..], Path::new("short.npy"), OutOfRange::Reject)
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("after 10 of the 2000 values") && e.contains("truncated"),
        "{e}"
    );
    // Shapes and types other than (N, 2) floats.
    for (header, needle) in [
        (
            "{'descr': '<f8', 'fortran_order': False, 'shape': (16, 3), }",
            "shape (16, 3)",
        ),
        (
            "{'descr': '<f8', 'fortran_order': False, 'shape': (32,), }",
            "shape (32)",
        ),
        (
            "{'descr': '<i8', 'fortran_order': False, 'shape': (16, 2), }",
            "descr '<i8'",
        ),
        (
            "{'descr': '<f8', 'shape': (16, 2), }",
            "fortran_order is missing",
        ),
        (
            "{'descr': '<f8', 'fortran_order': False, 'shape': (16, 2), 'x': 1}",
            "unknown key",
        ),
    ] {
        let mut npy = b"\x93NUMPY\x01\x00".to_vec();
        npy.extend_from_slice(&(header.len() as u16).to_le_bytes());
        npy.extend_from_slice(header.as_bytes());
        let e = read_points_named(&npy[..], Path::new("h.npy"), OutOfRange::Reject)
            .unwrap_err()
            .to_string();
        assert!(e.contains(needle), "{header}: {e}");
    }
}

#[test]
fn every_entry_point_reads_the_peer_formats() {
    let reference = read("numpy-savetxt.txt");
    // The scene and the GUI's drop and `--points` go through ImportedPoints::from_file.
    let imp = ImportedPoints::from_file(&data("npy-f64-fortran-v1.npy"), false).unwrap();
    assert_eq!(imp.to_dvec(), reference);
    let scene_path = scratch("scene-with-rps.ron");
    let text = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/scene-with-imported-points.ron"),
    )
    .unwrap()
    .replace(
        "psa-with-count.txt",
        data("psa-jitter-64.rps").to_str().unwrap(),
    );
    std::fs::write(&scene_path, text).unwrap();
    let scene = Scene::load(&scene_path).unwrap_or_else(|e| panic!("{e}"));
    let pts = scene.columns[0].points.as_ref().unwrap();
    assert_eq!(pts.points.len(), 64);
    // analyze --points on the pmj-cpp file and the .npy.
    for name in [
        "pmj-cpp-pmj02-256.txt",
        "npy-f32-c-v1.npy",
        "psa-jitter-64.rps",
    ] {
        let path = data(name);
        let (code, out, err) = samplescope(&[
            "analyze",
            "--points",
            path.to_str().unwrap(),
            "--size",
            "16",
            "--json",
        ]);
        assert_eq!(code, Some(0), "{name}: {err}");
        let v: serde_json::Value = serde_json::from_str(&out).unwrap();
        assert!(v["n"].as_u64().unwrap() >= 16, "{name}");
    }
}

/// Runs `analyze` and parses its JSON.
fn analyze_json(args: &[&str]) -> serde_json::Value {
    let mut all = vec!["analyze"];
    all.extend_from_slice(args);
    all.push("--json");
    let (code, out, err) = samplescope(&all);
    assert_eq!(code, Some(0), "{all:?}: {err}");
    serde_json::from_str(&out).unwrap_or_else(|e| panic!("{e}: {out}"))
}

/// Reads a CSV written by analyze (header, then numbers).
fn csv_rows(path: &Path) -> Vec<Vec<f64>> {
    crate::parse_csv(&std::fs::read_to_string(path).unwrap()).1
}

/// Three jittered sets of 64 points (seeds 1, 2, 3) and one of 32, written by `points` into
/// the scratch folder `name` (one per test: tests run in parallel and this one empties it).
fn realizations(name: &str) -> (PathBuf, Vec<String>) {
    let dir = scratch(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let mut files = Vec::new();
    for seed in 1..=3 {
        let f = dir.join(format!("jit-{seed}.csv"));
        let (code, _, err) = samplescope(&[
            "points",
            "jitter",
            "-n",
            "64",
            "--seed",
            &seed.to_string(),
            "--out",
            f.to_str().unwrap(),
        ]);
        assert_eq!(code, Some(0), "{err}");
        files.push(f.to_str().unwrap().to_string());
    }
    let (code, _, err) = samplescope(&[
        "points",
        "jitter",
        "-n",
        "32",
        "--out",
        dir.join("other-32.csv").to_str().unwrap(),
    ]);
    assert_eq!(code, Some(0), "{err}");
    (dir, files)
}

#[test]
fn averaging_files_equals_the_per_file_results_averaged_by_hand() {
    let (dir, files) = realizations("avg-by-hand");
    let out = |name: &str| dir.join(name).to_str().unwrap().to_string();
    let common = ["--size", "16", "--exact"];
    let mut args: Vec<&str> = vec!["--points"];
    args.extend(files.iter().map(String::as_str));
    let (s, r, g) = (out("avg-s.csv"), out("avg-r.csv"), out("avg-g.csv"));
    args.extend(common);
    args.extend(["--spectrum-data", &s, "--raps", &r, "--rdf", &g]);
    let avg = analyze_json(&args);
    // Per file, the single-file command.
    let mut singles = Vec::new();
    let mut spectra = Vec::new();
    let mut raps = Vec::new();
    let mut rdfs = Vec::new();
    for (i, f) in files.iter().enumerate() {
        let (si, ri, gi) = (
            out(&format!("s{i}.csv")),
            out(&format!("r{i}.csv")),
            out(&format!("g{i}.csv")),
        );
        let mut a: Vec<&str> = vec!["--points", f];
        a.extend(common);
        a.extend(["--spectrum-data", &si, "--raps", &ri, "--rdf", &gi]);
        singles.push(analyze_json(&a));
        spectra.push(csv_rows(Path::new(&si)));
        raps.push(csv_rows(Path::new(&ri)));
        rdfs.push(csv_rows(Path::new(&gi)));
    }
    let k = files.len() as f64;
    assert_eq!(avg["n"], 64);
    assert_eq!(avg["files"].as_array().unwrap().len(), 3);
    assert_eq!(avg["spectrum"]["realizations"], 3);
    for key in [
        "min_distance",
        "min_distance_normalized",
        "mean_nn_distance",
        "star_discrepancy",
        "l2_star_discrepancy",
        "t_value",
        "effective_nyquist",
        "oscillations",
        "bond_orientational_order",
    ] {
        let v: Vec<f64> = singles.iter().map(|s| s[key].as_f64().unwrap()).collect();
        let mean = v.iter().sum::<f64>() / k;
        let sd = (v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (k - 1.0)).sqrt();
        let got = &avg[key];
        assert!(
            (got["mean"].as_f64().unwrap() - mean).abs() <= 1e-12 * mean.abs().max(1e-300),
            "{key}: {got} vs mean {mean}"
        );
        assert!(
            (got["std_dev"].as_f64().unwrap() - sd).abs() <= 1e-9 * sd.max(1e-300),
            "{key}: {got} vs sd {sd}"
        );
        let per: Vec<f64> = got["per_file"]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_f64().unwrap())
            .collect();
        assert_eq!(per, v, "{key}");
    }
    // Spectrum, RAPS and RDF: the mean of the per-file curves, bin by bin.
    for (name, mean_file, per) in [
        ("spectrum", &s, &spectra),
        ("RAPS", &r, &raps),
        ("RDF", &g, &rdfs),
    ] {
        let got = csv_rows(Path::new(mean_file));
        assert_eq!(got.len(), per[0].len(), "{name}");
        for (row, values) in got.iter().enumerate() {
            let col = values.len() - 1;
            for c in 0..col {
                assert_eq!(values[c], per[0][row][c], "{name} row {row}");
            }
            let want = per.iter().map(|p| p[row][col]).sum::<f64>() / k;
            assert!(
                (values[col] - want).abs() <= 1e-12 * want.abs().max(1e-12),
                "{name} row {row}: {} vs {want}",
                values[col]
            );
        }
    }
    // A glob the shell did not expand gives the same files, sorted.
    let pattern = dir.join("jit-*.csv");
    let globbed = analyze_json(&[
        "--points",
        pattern.to_str().unwrap(),
        "--size",
        "16",
        "--exact",
    ]);
    assert_eq!(globbed["files"], avg["files"]);
    assert_eq!(globbed["min_distance"], avg["min_distance"]);
    // Text: mean ± sd, saying which spread.
    let (code, text, err) = samplescope(&[
        "analyze",
        "--points",
        pattern.to_str().unwrap(),
        "--size",
        "16",
    ]);
    assert_eq!(code, Some(0), "{err}");
    assert!(
        text.contains("3, each n = 64; mean ± sample standard deviation"),
        "{text}"
    );
    let mean = avg["min_distance"]["mean"].as_f64().unwrap();
    assert!(text.contains(&format!("{mean:.6e} ±")), "{text}");
}

#[test]
fn averaging_files_of_different_n_or_no_match_is_refused_in_one_line() {
    let (dir, files) = realizations("avg-refused");
    let other = dir.join("other-32.csv");
    let (code, out, err) = samplescope(&[
        "analyze",
        "--points",
        &files[0],
        other.to_str().unwrap(),
        "--size",
        "16",
    ]);
    assert_eq!(code, Some(2), "{out}{err}");
    assert_eq!(err.trim().lines().count(), 1, "{err}");
    assert!(
        err.contains("holds 64 points") && err.contains("holds 32") && err.contains("same N"),
        "{err}"
    );
    let none = dir.join("nothing-*.csv");
    let (code, _, err) = samplescope(&["analyze", "--points", none.to_str().unwrap()]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("no file matches"), "{err}");
    // The single-file JSON keeps its keys (and adds the prefix check).
    let single = analyze_json(&["--points", &files[0], "--size", "16"]);
    let pattern = analyze_json(&["jitter", "-n", "64", "--size", "16"]);
    let keys =
        |v: &serde_json::Value| -> Vec<String> { v.as_object().unwrap().keys().cloned().collect() };
    let mut want = keys(&pattern);
    want.push("net_prefixes".into());
    want.sort();
    let mut got = keys(&single);
    got.sort();
    assert_eq!(got, want);
    assert!(single["min_distance"].is_f64());
}

/// pmj-cpp's first 32 points with point 13 (index 12, in the prefix of 16 but not of 8)
/// moved, written in pmj-cpp's format.
fn moved_pmj(dir: &Path, name: &str, moved: DVec2) -> PathBuf {
    let mut p = read("pmj-cpp-pmj02-256.txt");
    p.truncate(32);
    p[12] = moved;
    let text: String = p
        .iter()
        .map(|q| format!("({:?}, {:?}),\n", q.x, q.y))
        .collect();
    let f = dir.join(name);
    std::fs::write(&f, text).unwrap();
    f
}

#[test]
fn net_prefixes_of_exact_sequences_pass_and_a_moved_point_is_located() {
    // pmj-cpp's pmj02 and samplescope's Sobol': every prefix 1, 2, …, 256 is a (0,k,2)-net.
    let dir = scratch("nets");
    std::fs::create_dir_all(&dir).unwrap();
    let sobol = dir.join("sobol-256.csv");
    let (code, _, err) = samplescope(&[
        "points",
        "sobol",
        "-n",
        "256",
        "--out",
        sobol.to_str().unwrap(),
    ]);
    assert_eq!(code, Some(0), "{err}");
    for f in [data("pmj-cpp-pmj02-256.txt"), sobol.clone()] {
        let v = analyze_json(&["--points", f.to_str().unwrap(), "--size", "16"]);
        let np = &v["net_prefixes"];
        let prefixes = np["prefixes"].as_array().unwrap();
        assert_eq!(prefixes.len(), 9, "{}", f.display());
        for (k, c) in prefixes.iter().enumerate() {
            assert_eq!(c["n"], 1 << k);
            assert_eq!(c["net"], true, "{}: {c}", f.display());
        }
        assert!(np["first_failure"].is_null());
    }
    let orig = read("pmj-cpp-pmj02-256.txt")[12];
    // (a) y moved to another row of 1/16, x kept: the 1 × 16 intervals fail first (kx = 0
    // is checked first); the first wrong cell in row order is the lower of the two rows: the
    // one left empty (count 0) or the one now holding two points (count 2).
    let r = (orig.y * 16.0) as u64;
    let r_new = (r + 5) % 16;
    let f = moved_pmj(
        &dir,
        "moved-y.txt",
        DVec2::new(orig.x, (r_new as f64 + 0.5) / 16.0),
    );
    let v = analyze_json(&["--points", f.to_str().unwrap(), "--size", "16"]);
    let np = &v["net_prefixes"];
    let nets: Vec<bool> = np["prefixes"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c["net"].as_bool().unwrap())
        .collect();
    assert_eq!(nets, [true, true, true, true, false, false]);
    let ff = &np["first_failure"];
    let (row, count) = if r < r_new { (r, 0) } else { (r_new, 2) };
    assert_eq!(ff["n"], 16, "{ff}");
    assert_eq!(
        (ff["kx"].as_u64(), ff["ky"].as_u64()),
        (Some(0), Some(4)),
        "{ff}"
    );
    assert_eq!(ff["cell"], json(&[0, row]), "{ff}");
    assert_eq!(ff["count"], count, "{ff}");
    assert_eq!(ff["expected"], 1);
    // (b) x moved to the neighbouring column of 1/16 (c XOR 1), y kept: every coarser column
    // (1/2, 1/4, 1/8) and every row still holds its point, so only the 16 × 1 intervals fail.
    let c = (orig.x * 16.0) as u64;
    let c_new = c ^ 1;
    let f = moved_pmj(
        &dir,
        "moved-x.txt",
        DVec2::new((c_new as f64 + 0.5) / 16.0, orig.y),
    );
    let v = analyze_json(&["--points", f.to_str().unwrap(), "--size", "16"]);
    let ff = &v["net_prefixes"]["first_failure"];
    let (col, count) = if c < c_new { (c, 0) } else { (c_new, 2) };
    assert_eq!(ff["n"], 16, "{ff}");
    assert_eq!(
        (ff["kx"].as_u64(), ff["ky"].as_u64()),
        (Some(4), Some(0)),
        "{ff}"
    );
    assert_eq!(ff["cell"], json(&[col, 0]), "{ff}");
    assert_eq!(ff["count"], count, "{ff}");
    let w = 1.0 / 16.0;
    assert_eq!(
        ff["interval"],
        serde_json::json!([[col as f64 * w, (col + 1) as f64 * w], [0.0, 1.0]])
    );
    // The text says the same.
    let (code, text, err) =
        samplescope(&["analyze", "--points", f.to_str().unwrap(), "--size", "16"]);
    assert_eq!(code, Some(0), "{err}");
    let want = format!(
        "nets: N = 1, 2, 4, 8; not nets: N = 16, 32; first failure N = 16 (k = 4): the 2^-4 × 2^-0 intervals (16 columns × 1 row), cell (column {col}, row 0) = [{col}/16, {}/16) × [0/1, 1/1) holds {count} point(s), expected 1",
        col + 1
    );
    assert!(text.contains(&want), "{text}\nwant: {want}");
}

fn json(v: &[u64]) -> serde_json::Value {
    serde_json::json!(v)
}
