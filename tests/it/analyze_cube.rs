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

/// `v` without its timings (the only numbers that differ between two runs).
fn without_timings(mut v: serde_json::Value) -> serde_json::Value {
    v.as_object_mut().unwrap().remove("timings_ms");
    v
}

#[test]
fn a_pattern_s_projection_is_the_2d_point_set_its_file_is() {
    let dir = std::env::temp_dir().join(format!("samplescope-project-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = |name: &str| dir.join(name).to_string_lossy().into_owned();
    for (settings, seed) in [(vec![], None), (vec!["--set", "scramble=owen"], Some("3"))] {
        let mut common: Vec<&str> = vec!["-n", "1024", "--dims", "8", "--project", "3,5"];
        common.extend(&settings);
        if let Some(s) = seed {
            common.extend(["--seed", s]);
        }
        // The projection written by `points`, then analysed as a file.
        let csv = file("proj.csv");
        let mut points_args = vec!["points", "sobol"];
        points_args.extend(&common);
        points_args.extend(["--out", &csv]);
        let o = Command::new(env!("CARGO_BIN_EXE_samplescope"))
            .args(&points_args)
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let (raps_p, rdf_p, raps_f, rdf_f) = (
            file("raps-p.csv"),
            file("rdf-p.csv"),
            file("raps-f.csv"),
            file("rdf-f.csv"),
        );
        let mut from_pattern = vec!["sobol"];
        from_pattern.extend(&common);
        from_pattern.extend(["--json", "--raps", &raps_p, "--rdf", &rdf_p]);
        let (code, out_p, err) = analyze(&from_pattern);
        assert_eq!(code, 0, "{err}");
        let (code, out_f, err) = analyze(&[
            "--points", &csv, "--json", "--raps", &raps_f, "--rdf", &rdf_f,
        ]);
        assert_eq!(code, 0, "{err}");
        let p: serde_json::Value = serde_json::from_str(&out_p).unwrap();
        let f: serde_json::Value = serde_json::from_str(&out_f).unwrap();
        // Every statistic (discrepancies, t-value, distances, PSA's, the prefixes' nets, the
        // spectrum's accuracy) is the file's, bit for bit; so are the RAPS and the RDF.
        assert_eq!(
            without_timings(p.clone()),
            without_timings(f),
            "{settings:?}"
        );
        for key in [
            "t_value",
            "l2_star_discrepancy",
            "effective_nyquist",
            "net_prefixes",
        ] {
            assert!(!p[key].is_null(), "{key}: {out_p}");
        }
        assert_eq!(
            std::fs::read(&raps_p).unwrap(),
            std::fs::read(&raps_f).unwrap()
        );
        assert_eq!(
            std::fs::read(&rdf_p).unwrap(),
            std::fs::read(&rdf_f).unwrap()
        );
    }
    // The text form and the spectrum figure (its metadata names the pattern and the pair).
    let png = file("spectrum.png");
    let (code, out, err) = analyze(&[
        "halton",
        "-n",
        "256",
        "--dims",
        "5",
        "--project",
        "4,1",
        "--size",
        "64",
        "--spectrum",
        &png,
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("t-value (base 2)"), "{out}");
    let bytes = std::fs::read(&png).unwrap();
    assert_eq!(&bytes[1..4], b"PNG");
    let text = String::from_utf8_lossy(&bytes);
    assert!(
        text.contains("dims=5 project=4,1"),
        "the figure's metadata names the pair"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_pattern_s_bad_projection_is_refused_with_one_line() {
    let cases: [(&[&str], &str); 7] = [
        (
            &["sobol", "-n", "64", "--dims", "8", "--project", "3,3"],
            "--project 3,3: must be two different dimensions i,j in 0..=7 (dims = 8)",
        ),
        (
            &["sobol", "-n", "64", "--dims", "8", "--project", "0,8"],
            "--project 0,8: must be two different dimensions i,j in 0..=7 (dims = 8)",
        ),
        (
            &["sobol", "-n", "64", "--project", "0,2"],
            "--project 0,2: must be two different dimensions i,j in 0..=1 (dims = 2)",
        ),
        (
            &["sobol", "-n", "64", "--dims", "8"],
            "--dims 8: analyze takes a pattern's 2D projection: add --project i,j",
        ),
        (
            &["jitter", "-n", "64", "--dims", "3", "--project", "0,1"],
            "jitter is defined in 2 dimensions only",
        ),
        (
            &["sobol", "-n", "64", "--dims", "2000", "--project", "0,1"],
            "must be an integer in 1..=1024",
        ),
        (
            &[
                "random",
                "-n",
                "64",
                "--dims",
                "3",
                "--project",
                "0,1",
                "--realizations",
                "2",
            ],
            "--realizations = 2: must be 1 with --project",
        ),
    ];
    for (args, want) in cases {
        let (code, out, err) = analyze(args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(out.is_empty(), "{args:?}");
        assert_eq!(err.trim().lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains(want), "{args:?}: {err}");
    }
}

#[test]
fn the_cube_measures_estimates_count_their_loops_at_the_measured_rates() {
    use samplescope::core::budget::{cube_measure, Estimate, REFERENCE_CORES};
    use samplescope::core::metrics::cube::CubeMeasure::*;
    // CPU ns of one unit of the estimate (each measure's loop is parallel).
    let ns = |e: &Estimate| e.seconds * REFERENCE_CORES * 1e9 / e.amount;
    let n = 4096;
    let nf = n as f64;
    for d in [1, 4, 32] {
        let all = cube_measure(Discrepancies, n, d);
        assert_eq!(
            all.amount,
            5.0 * nf * (nf + 1.0) / 2.0,
            "the pairs i ≤ j of 5 sums"
        );
        let one = cube::cost::cube_discrepancy(Discrepancy::Centered, n, d);
        assert!((all.seconds - 5.0 * one.seconds).abs() <= 1e-12 * all.seconds);
        assert_eq!(
            cube_measure(MinDistance, n, d).amount,
            nf * (nf - 1.0) / 2.0
        );
        assert_eq!(cube_measure(Stratification, n, d).amount, nf * d as f64);
    }
    // Per pair, linear in d and within 1.5× of benches/cube.rs (one thread, N = 4096, unscrambled
    // Sobol'; BENCHMARKS.md): the five discrepancies 6.68 ns at D = 4, 31.84 at D = 32; the
    // minimum distance 3.16 and 31.54.
    for (m, d, measured) in [
        (Discrepancies, 4, 6.68),
        (Discrepancies, 32, 31.84),
        (MinDistance, 4, 3.16),
        (MinDistance, 32, 31.54),
    ] {
        let r = ns(&cube_measure(m, n, d)) / measured;
        assert!(
            (1.0 / 1.5..=1.5).contains(&r),
            "{m:?} D = {d}: {r:.2}× measured"
        );
    }
    let slope = |m| ns(&cube_measure(m, n, 32)) - ns(&cube_measure(m, n, 31));
    for m in [Discrepancies, MinDistance] {
        let step = slope(m);
        assert!(
            step > 0.0
                && (ns(&cube_measure(m, n, 9)) - ns(&cube_measure(m, n, 8)) - step).abs() < 1e-9
        );
    }
    // The pair table: every pair of dimensions one 2D projection of the N points, so its time
    // goes with the pairs (quadratic in D); within 1.5× of the measured CPU at 4096 × 32.
    let table = |n, d| cube_measure(Projections, n, d);
    assert_eq!(table(n, 32).amount, 496.0 * nf);
    let ratio = table(n, 32).seconds / table(n, 16).seconds;
    assert!((ratio - 496.0 / 120.0).abs() < 1e-9, "{ratio}");
    let measured = 1.014; // s of CPU, one thread
    let r = table(n, 32).seconds * REFERENCE_CORES / measured;
    assert!(
        (1.0 / 1.5..=1.5).contains(&r),
        "pair table: {r:.2}× measured"
    );
    // Without a power-of-two N there is no t-value to compute.
    assert!(table(n - 1, 8).seconds < table(n, 8).seconds * (nf - 1.0) / nf * 0.99);
}
