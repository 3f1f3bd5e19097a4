//! `analyze --points F` for files of other than two columns: the d-dimensional measures as
//! text and `--json`, `--project i,j` into the 2D analyses, and bad input refused with one line
//! naming the field (exit 2).

use samplescope::core::cancel::Cancel;
use samplescope::core::metrics::cube::{self, Discrepancy};
use samplescope::core::pointset::{read_cube_file, OutOfRange};
use samplescope::core::progress::no_progress;
use std::path::{Path, PathBuf};
use std::process::Command;

fn analyze(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_samplescope"))
        .arg("analyze")
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn set(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("tests/data/scipy/discrepancy/{name}.csv"))
}

fn scratch(name: &str, text: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("samplescope-analyze-cube-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

#[test]
fn json_has_the_measures_of_the_core() {
    let path = set("d8-sobol-n128");
    let (code, out, err) = analyze(&["--points", path.to_str().unwrap(), "--json"]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["dims"], 8);
    let points = read_cube_file(&path, OutOfRange::Reject).unwrap().points;
    let d = cube::discrepancies(&points, &Cancel::never(), &mut no_progress).unwrap();
    for which in Discrepancy::ALL {
        assert_eq!(v[which.key()].as_f64().unwrap(), d.get(which), "{which:?}");
    }
    let md = cube::min_distance_cube(&points, &Cancel::never(), &mut no_progress).unwrap();
    assert_eq!(v["min_distance"].as_f64().unwrap(), md.min_distance);
    let rows = v["projections"].as_array().unwrap();
    assert_eq!(rows.len(), 28);
    for key in ["dims", "t_value", "l2_star_discrepancy", "min_distance"] {
        assert!(rows[0].get(key).is_some(), "{key}");
    }
    assert_eq!(v["stratified"].as_array().unwrap().len(), 8);
    // Text: every measure is named.
    let (code, out, _) = analyze(&["--points", path.to_str().unwrap()]);
    assert_eq!(code, 0);
    for what in [
        "L2-star discrepancy",
        "centred discrepancy CD²",
        "wrap-around",
        "mixture",
        "symmetric",
        "min toroidal distance",
        "1D stratified",
        "projections (worst first)",
    ] {
        assert!(out.contains(what), "{what}: {out}");
    }
}

#[test]
fn project_takes_a_pair_into_the_2d_analyses() {
    let path = set("d3-sobol-n256");
    let (code, out, err) = analyze(&[
        "--points",
        path.to_str().unwrap(),
        "--project",
        "0,2",
        "--json",
    ]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["n"], 256);
    assert!(v.get("t_value").is_some(), "{out}");
}

#[test]
fn bad_input_is_refused_with_one_line_naming_the_field() {
    let ragged = scratch("ragged.csv", "x0,x1,x2\n0.1,0.2,0.3\n0.4,0.5\n");
    let (code, _, err) = analyze(&["--points", ragged.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert_eq!(err.trim().lines().count(), 1, "{err}");
    assert!(err.contains("line 3: expected 3 coordinates"), "{err}");
    let header: Vec<String> = (0..1025).map(|k| format!("x{k}")).collect();
    let wide = scratch("wide.csv", &format!("{}\n", header.join(",")));
    let (code, _, err) = analyze(&["--points", wide.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(
        err.contains("1025 columns: a point has at most 1024 coordinates (dims)"),
        "{err}"
    );
    let path = set("d3-random-n256");
    let (code, _, err) = analyze(&["--points", path.to_str().unwrap(), "--project", "1,3"]);
    assert_eq!(code, 2);
    assert!(
        err.contains("--project 1,3: must be two different dimensions i,j in 0..=2"),
        "{err}"
    );
    let (code, _, err) = analyze(&["--points", path.to_str().unwrap(), "--raps", "/tmp/x.csv"]);
    assert_eq!(code, 2);
    assert!(err.contains("--raps"), "{err}");
}
