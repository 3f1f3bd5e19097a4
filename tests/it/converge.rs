//! The `samplescope converge` command: JSON and CSV output, the slope of jittered sampling on
//! the disk, Genz's integrands in d dimensions (`--dims`), exit codes and one-line errors.

use samplescope::core::cancel::Cancel;
use samplescope::core::integration::{run_study, Integrand, StudyRequest};
use samplescope::core::pattern::Pattern;
use samplescope::core::progress::no_progress;
use std::process::Command;

fn samplescope(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_samplescope"))
        .args(args)
        .output()
        .expect("the binary runs")
}

fn json(args: &[&str]) -> serde_json::Value {
    let out = samplescope(args);
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("one JSON object")
}

#[test]
fn json_has_every_key_and_matches_the_library() {
    let v = json(&[
        "converge",
        "--pattern",
        "jitter",
        "--integrand",
        "disk",
        "--integrand-set",
        "r=0.25",
        "--n",
        "16,64,256",
        "--realizations",
        "32",
        "--seed",
        "9",
        "--json",
    ]);
    assert_eq!(v["pattern"], "jitter");
    assert_eq!(v["integrand"], "disk");
    assert_eq!(v["integrand_params"]["r"], 0.25);
    assert_eq!(v["realizations"], 32);
    for key in ["reference", "slope", "slope_stderr"] {
        assert!(v[key].is_f64(), "{key}: {v}");
    }
    for key in ["points", "evaluation", "statistics", "total"] {
        assert!(v["timings_ms"][key].as_f64().unwrap() >= 0.0, "{key}");
    }
    // The same numbers as the library (serde_json's default parser may be off by an ulp).
    let mut integrand = Integrand::from_name("disk").unwrap();
    samplescope::core::params::Params::set(&mut integrand, "r", "0.25").unwrap();
    let req = StudyRequest {
        pattern: Pattern::from_name("jitter").unwrap(),
        integrand,
        ns: vec![16, 64, 256],
        realizations: 32,
        seed: 9,
        shift: true,
        randomize: false,
        dims: 2,
    };
    let study = run_study(&req, &Cancel::never(), &mut no_progress).unwrap();
    let close = |a: Option<f64>, b: Option<f64>| match (a, b) {
        (Some(a), Some(b)) => (a - b).abs() <= 1e-15 * b.abs(),
        (a, b) => a == b,
    };
    assert!(close(v["reference"].as_f64(), Some(study.reference)));
    let rows = v["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 3);
    for (row, want) in rows.iter().zip(&study.rows) {
        assert_eq!(row["n"].as_u64().unwrap() as usize, want.n);
        assert!(close(row["mse"].as_f64(), Some(want.mse)), "{row}");
        assert!(close(row["mse_stderr"].as_f64(), want.mse_stderr), "{row}");
        assert!(
            close(row["variance"].as_f64(), Some(want.variance)),
            "{row}"
        );
        assert!(close(row["bias2"].as_f64(), Some(want.bias2)), "{row}");
    }
    assert!(close(v["slope"].as_f64(), study.slope));
    assert!(close(v["slope_stderr"].as_f64(), study.slope_stderr));
}

#[test]
fn jitter_on_the_disk_has_slope_near_minus_one_and_a_half() {
    // MSE ∝ N^(−3/2) for stratified sampling of an edge; window [−1.65, −1.35] with 256
    // realizations over N = 16 … 16384.
    let v = json(&[
        "converge",
        "--pattern",
        "jitter",
        "--integrand",
        "disk",
        "--n",
        "16,64,256,1024,4096,16384",
        "--realizations",
        "256",
        "--json",
    ]);
    let slope = v["slope"].as_f64().unwrap();
    assert!((-1.65..=-1.35).contains(&slope), "slope {slope}");
    // White noise on the same disk: slope −1 (window ±0.1).
    let v = json(&[
        "converge",
        "--pattern",
        "random",
        "--integrand",
        "disk",
        "--n",
        "16,64,256,1024,4096",
        "--realizations",
        "256",
        "--json",
    ]);
    let slope = v["slope"].as_f64().unwrap();
    assert!((slope + 1.0).abs() < 0.1, "slope {slope}");
}

#[test]
fn text_output_has_a_row_per_n_and_the_slope() {
    let out = samplescope(&[
        "converge",
        "--pattern",
        "halton",
        "--integrand",
        "heaviside",
        "--randomize",
        "--n",
        "16,32,64,128",
        "--realizations",
        "16",
    ]);
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert!(
        lines[0].starts_with("halton on heaviside (randomized)"),
        "{text}"
    );
    assert!(lines[0].contains("Cranley–Patterson"), "{text}");
    for (line, n) in lines[2..6].iter().zip(["16", "32", "64", "128"]) {
        assert_eq!(line.split_whitespace().next(), Some(n), "{text}");
    }
    assert!(lines[6].starts_with("slope  -"), "{text}");
}

#[test]
fn csv_is_written_whole_with_one_row_per_n() {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("converge");
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("rows.csv");
    let _ = std::fs::remove_file(&file);
    let out = samplescope(&[
        "converge",
        "--pattern",
        "grid",
        "--integrand",
        "bilinear",
        "--no-shift",
        "--n",
        "16,64",
        "--realizations",
        "1",
        "--csv",
        file.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(&file).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines[0], "n,mse,mse_stderr,variance,bias2");
    assert_eq!(lines.len(), 3);
    // Grid midpoints integrate x·y exactly: mse 0 up to rounding; no stderr with R = 1.
    for line in &lines[1..] {
        let f: Vec<&str> = line.split(',').collect();
        assert_eq!(f.len(), 5);
        assert_eq!(f[2], "");
        assert!(f[1].parse::<f64>().unwrap() < 1e-30, "{line}");
    }
    let leftovers: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .filter_map(|e| e.ok())
        .filter(|e| e.file_name().to_string_lossy().ends_with(".partial"))
        .collect();
    assert!(leftovers.is_empty());
}

#[test]
fn bad_input_exits_with_status_2_and_one_line() {
    let base = |extra: &[&'static str]| {
        let mut v = vec![
            "converge",
            "--pattern",
            "jitter",
            "--integrand",
            "disk",
            "--n",
            "16,64",
            "--realizations",
            "4",
        ];
        v.extend_from_slice(extra);
        v
    };
    let with = |i: usize, value: &'static str| {
        let mut v = base(&[]);
        v[i] = value;
        v
    };
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (with(4, "nosuch"), "unknown integrand 'nosuch'"),
        (
            with(6, "16,0"),
            "--n 0: each sample count must be an integer in 1..=1048576",
        ),
        (with(6, "16,abc"), "--n abc"),
        (with(6, "2097152"), "--n 2097152"),
        (
            with(8, "0"),
            "--realizations 0: must be an integer in 1..=4096",
        ),
        (with(8, "5000"), "--realizations 5000"),
        (with(2, "nosuch"), "unknown pattern 'nosuch'"),
        (with(2, "fibonacci"), "--n 16: fibonacci: n = 16"),
        (base(&["--integrand-set", "r=0"]), "disk.r = 0"),
        (
            base(&["--integrand-set", "nokey=1"]),
            "unknown parameter 'nokey'",
        ),
        (base(&["--set", "amount=2"]), "jitter.amount = 2"),
        (base(&["--budget", "0.000001"]), "the limit is"),
        (
            base(&["--dims", "0"]),
            "--dims 0: must be an integer in 1..=1024",
        ),
        (base(&["--dims", "x"]), "--dims x: must be an integer in 1..=1024"),
        (
            base(&["--dims", "3"]),
            "--dims 3: disk is defined on [0,1]² only (--dims 2)",
        ),
        (
            with(4, "genz-gaussian").into_iter().chain(["--dims", "3"]).collect(),
            "--dims 3: jitter: dims = 3: must be 2 (jitter is defined in 2 dimensions only",
        ),
        (
            with(2, "random")
                .into_iter()
                .map(|a| if a == "disk" { "genz-product-peak" } else { a })
                .chain(["--dims", "3", "--integrand-set", "a=[1,2]"])
                .collect(),
            "genz-product-peak.a = [1,2] (2 numbers): must be one number (every dimension) or a list of 3",
        ),
        (
            with(4, "genz-product-peak")
                .into_iter()
                .chain(["--integrand-set", "a=0"])
                .collect(),
            "genz-product-peak.a = 0: must be each entry in (0, 1000]",
        ),
    ];
    for (args, needle) in &cases {
        let out = samplescope(args);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(needle), "{args:?}: {err}");
        assert_eq!(err.trim().lines().count(), 1, "{args:?}: {err}");
        assert!(out.stdout.is_empty(), "{args:?}");
    }
    // Hex with odd N (jittered hex is random: the error comes from the realizations).
    let out = samplescope(&[
        "converge",
        "--pattern",
        "hex",
        "--set",
        "amount=0.5",
        "--integrand",
        "gaussian",
        "--n",
        "64,33",
        "--realizations",
        "2",
    ]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.starts_with("error: --n 33: hex"), "{err}");
    assert_eq!(err.trim().lines().count(), 1, "{err}");
}

#[test]
fn genz_integrands_in_d_dimensions() {
    // Random points on the Genz Gaussian in 8 dimensions: MSE ∝ 1/N (slope −1 ± 0.15), the
    // reference the closed form's, "dims" in the JSON, and the same numbers as the library.
    let args = [
        "converge",
        "--pattern",
        "random",
        "--integrand",
        "genz-gaussian",
        "--integrand-set",
        "a=[1,2,3,4,1,2,3,4]",
        "--dims",
        "8",
        "--n",
        "16,64,256,1024",
        "--realizations",
        "256",
        "--seed",
        "3",
        "--json",
    ];
    let v = json(&args);
    assert_eq!(v["dims"], 8);
    assert_eq!(v["integrand"], "genz-gaussian");
    assert_eq!(
        v["integrand_params"]["a"],
        serde_json::json!([1.0, 2.0, 3.0, 4.0, 1.0, 2.0, 3.0, 4.0])
    );
    let slope = v["slope"].as_f64().unwrap();
    assert!((slope + 1.0).abs() < 0.15, "slope {slope}");
    let mut integrand = Integrand::from_name("genz-gaussian").unwrap();
    samplescope::core::params::Params::set(&mut integrand, "a", "[1,2,3,4,1,2,3,4]").unwrap();
    let req = StudyRequest {
        pattern: Pattern::from_name("random").unwrap(),
        integrand,
        ns: vec![16, 64, 256, 1024],
        realizations: 256,
        seed: 3,
        shift: true,
        randomize: false,
        dims: 8,
    };
    let study = run_study(&req, &Cancel::never(), &mut no_progress).unwrap();
    let reference = v["reference"].as_f64().unwrap();
    assert!((reference - study.reference).abs() <= 1e-15 * study.reference);
    for (row, want) in v["rows"].as_array().unwrap().iter().zip(&study.rows) {
        let mse = row["mse"].as_f64().unwrap();
        assert!((mse - want.mse).abs() <= 1e-15 * want.mse);
    }
    // Text output names the dimension; randomized Genz instances run in 32 dimensions.
    let out = samplescope(&[
        "converge",
        "--pattern",
        "random",
        "--integrand",
        "genz-corner-peak",
        "--randomize",
        "--dims",
        "32",
        "--n",
        "64,256",
        "--realizations",
        "8",
    ]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        text.starts_with("random on genz-corner-peak in 32 dimensions (randomized): reference "),
        "{text}"
    );
}

#[test]
fn scrambled_halton_draws_a_new_scramble_per_realization() {
    for (scramble, integrand, dims) in [
        ("permute", "gaussian", 2),
        ("owen", "gaussian", 2),
        ("owen", "genz-gaussian", 8),
    ] {
        let mut pattern = Pattern::from_name("halton").unwrap();
        samplescope::core::params::Params::set(&mut pattern, "scramble", scramble).unwrap();
        let req = StudyRequest {
            pattern,
            integrand: Integrand::from_name(integrand).unwrap(),
            ns: vec![64, 256],
            realizations: 16,
            seed: 1,
            shift: false,
            randomize: false,
            dims,
        };
        assert!(
            !req.applies_shift(),
            "{scramble}: a random pattern is not shifted"
        );
        let study = run_study(&req, &Cancel::never(), &mut no_progress).unwrap();
        // One scramble reused would make every realization the same estimate (variance 0, the
        // error all bias); independent scrambles are unbiased, so the error is all variance.
        for row in &study.rows {
            assert!(
                row.variance > 0.5 * row.mse,
                "{scramble} D = {dims} N = {}: variance {} of mse {}",
                row.n,
                row.variance,
                row.mse
            );
        }
    }
    // The command line says so, and takes the seed; --no-shift has nothing to leave out.
    let out = samplescope(&[
        "converge",
        "--pattern",
        "halton",
        "--set",
        "scramble=owen",
        "--integrand",
        "gaussian",
        "--n",
        "16,64",
        "--realizations",
        "4",
        "--seed",
        "3",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(
        text.lines()
            .next()
            .unwrap()
            .contains("shift: none (random pattern)"),
        "{text}"
    );
    let out = samplescope(&[
        "converge",
        "--pattern",
        "halton",
        "--set",
        "scramble=owen",
        "--integrand",
        "gaussian",
        "--n",
        "16,64",
        "--realizations",
        "4",
        "--no-shift",
    ]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("--no-shift") && err.contains("random pattern"),
        "{err}"
    );
}
