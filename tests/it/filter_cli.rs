//! End-to-end tests of `samplescope filter`, running the built binary.

use std::f64::consts::PI;
use std::process::Command;

fn samplescope(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_samplescope"))
        .args(args)
        .output()
        .expect("run samplescope")
}

fn stdout(o: &std::process::Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

fn stderr(o: &std::process::Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

#[test]
fn json_prints_the_four_metrics_name_and_params() {
    let o = samplescope(&["filter", "catmull-rom", "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_str(stdout(&o).trim()).expect("one JSON object");
    for key in ["smoothing", "post_aliasing", "ringing", "anisotropy"] {
        assert!(v[key].as_f64().is_some_and(f64::is_finite), "{key}: {v}");
    }
    assert_eq!(v["name"], "mitchell");
    assert_eq!(v["mode"], "separable");
    assert_eq!(v["params"]["b"], 0.0);
    assert_eq!(v["params"]["c"], 0.5);
    // Catmull–Rom's step response overshoots by exactly 1/24.
    assert!((v["ringing"].as_f64().unwrap() - 1.0 / 24.0).abs() < 1e-10);
    // Booleans are JSON booleans.
    let o = samplescope(&[
        "filter",
        "gaussian",
        "--set",
        "subtract_edge=false",
        "--json",
    ]);
    let v: serde_json::Value = serde_json::from_str(stdout(&o).trim()).unwrap();
    assert_eq!(v["params"]["subtract_edge"], false);
}

#[test]
fn response_csv_is_normalised_and_spans_zero_to_two() {
    let dir = std::env::temp_dir().join(format!("samplescope-filter-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("box.csv");
    let p = path.to_str().unwrap();
    let o = samplescope(&["filter", "box", "--set", "radius=0.5", "--response", p]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stdout(&o).contains("smoothing"), "metrics are printed too");
    let text = std::fs::read_to_string(&path).unwrap();
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("omega,magnitude,phase"));
    let rows: Vec<[f64; 3]> = lines
        .map(|l| {
            let v: Vec<f64> = l.split(',').map(|x| x.parse().unwrap()).collect();
            [v[0], v[1], v[2]]
        })
        .collect();
    assert_eq!(rows.len(), 513);
    assert_eq!(rows[0], [0.0, 1.0, 0.0]);
    assert_eq!(rows[512][0], 2.0);
    for (i, r) in rows.iter().enumerate() {
        assert_eq!(r[0], i as f64 / 256.0);
        // Box of radius ½: H(ω)/H(0) = sinc(ω).
        let w = r[0];
        let s = if w == 0.0 {
            1.0
        } else {
            (PI * w).sin() / (PI * w)
        };
        assert!((r[1] - s.abs()).abs() < 1e-14, "ω = {w}");
        if s < -1e-12 {
            assert_eq!(r[2], PI);
        } else if s > 1e-12 {
            assert_eq!(r[2], 0.0);
        }
    }
    // Radial mode writes the Hankel profile, also normalised at DC.
    let o = samplescope(&[
        "filter",
        "gaussian",
        "--mode",
        "radial",
        "--response",
        p,
        "--json",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&path).unwrap();
    let first: Vec<&str> = text.lines().nth(1).unwrap().split(',').collect();
    assert!((first[1].parse::<f64>().unwrap() - 1.0).abs() < 1e-14);
    let v: serde_json::Value = serde_json::from_str(stdout(&o).trim()).unwrap();
    assert_eq!(v["anisotropy"], 0.0);
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn bad_parameters_exit_2_with_one_line_naming_the_field() {
    for (args, needle) in [
        (vec!["filter", "box", "--set", "radius=-1"], "radius"),
        (vec!["filter", "box", "--set", "radius=nan"], "radius"),
        (vec!["filter", "gaussian", "--set", "sigma=0"], "sigma"),
        (
            vec![
                "filter",
                "windowed-sinc",
                "--set",
                "window=kaiser",
                "--set",
                "beta=-2",
            ],
            "beta",
        ),
        (
            vec![
                "filter",
                "band-pass",
                "--set",
                "low=0.4",
                "--set",
                "high=0.3",
            ],
            "low",
        ),
        (vec!["filter", "box", "--set", "width=2"], "width"),
        (vec!["filter", "box", "--set", "radius"], "key=value"),
        (vec!["filter", "nope"], "unknown filter"),
        (vec!["filter", "cosc", "--mode", "radial"], "radial"),
        (vec!["filter", "box", "--mode", "diagonal"], "mode"),
    ] {
        let o = samplescope(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        let err = stderr(&o);
        assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains(needle), "{args:?}: {err}");
        assert!(stdout(&o).is_empty());
    }
}

#[test]
fn window_is_applied_before_beta_in_any_order() {
    let a = samplescope(&[
        "filter",
        "windowed-sinc",
        "--set",
        "beta=6",
        "--set",
        "window=kaiser",
        "--json",
    ]);
    let b = samplescope(&[
        "filter",
        "windowed-sinc",
        "--set",
        "window=kaiser",
        "--set",
        "beta=6",
        "--json",
    ]);
    assert!(a.status.success(), "{}", stderr(&a));
    assert_eq!(stdout(&a), stdout(&b));
    let v: serde_json::Value = serde_json::from_str(stdout(&a).trim()).unwrap();
    assert_eq!(v["params"]["beta"], 6.0);
    assert_eq!(v["params"]["window"], "kaiser");
}

#[test]
fn list_names_every_filter_and_text_output_names_every_metric() {
    let o = samplescope(&["filter", "--list"]);
    assert!(o.status.success());
    let text = stdout(&o);
    for name in [
        "box",
        "tent",
        "gaussian",
        "mitchell",
        "sinc",
        "windowed-sinc",
        "cosc",
        "low-pass",
        "band-pass",
        "high-pass",
        "catmull-rom",
        "b-spline",
        "lanczos",
        "beta",
    ] {
        assert!(text.contains(name), "--list lacks {name}");
    }
    let o = samplescope(&["filter", "tent"]);
    assert!(o.status.success());
    let text = stdout(&o);
    for key in ["smoothing", "post_aliasing", "ringing", "anisotropy"] {
        assert!(text.contains(key), "{text}");
    }
}
