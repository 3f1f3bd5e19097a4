//! `samplescope render`: figures from a scene with no window; byte-identical reruns; errors.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

const SCENE: &str = r#"// A small two-column scene for the render tests.
(
    title: "Render test",
    columns: [
        (pattern: (kind: "jitter", cols: 0, amount: 1.0), seed: 1),
        (pattern: (kind: "halton", base_x: 2, base_y: 3, skip: 0), seed: 0, label: "Halton"),
    ],
    n: 256,
    signal: (kind: "zone-plate", k: 32.0, cx: 0.5, cy: 0.5),
    filter: (filter: (kind: "gaussian", sigma: 0.5, radius: 2.0, subtract_edge: true), mode: separable),
    recon: (mode: scattered, size: 64),
    spectrum: (size: 64, tolerance: 1e-6, exact: false, realizations: 1, mask_dc: true),
    panels: (pattern: true, spectrum: true, zoneplate: true, filter: true, cost: false),
    effects: (reconstruction: true, error: true, convergence: false, statistics: false),
)
"#;

/// A fresh directory under the target's temporary directory.
fn temp_dir(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("render_cli-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The disk cache of these tests' renders (never the user's).
fn cache_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("render_cli-cache-{}", std::process::id()))
}

fn render(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_samplescope"))
        .arg("render")
        .args(args)
        .env("SAMPLESCOPE_CACHE_DIR", cache_dir())
        .env_remove("SAMPLESCOPE_NO_CACHE")
        .output()
        .expect("run samplescope")
}

fn files(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

/// The files of two renders of one scene: the same names, each of `want` among them, every
/// file non-empty and byte-identical in both. Returns the names.
fn same_files(a: &Path, b: &Path, want: &[&str]) -> Vec<String> {
    let names = files(a);
    assert_eq!(names, files(b));
    for w in want {
        assert!(names.iter().any(|n| n == w), "{w} missing from {names:#?}");
    }
    for n in &names {
        let (x, y) = (
            std::fs::read(a.join(n)).unwrap(),
            std::fs::read(b.join(n)).unwrap(),
        );
        assert!(!x.is_empty(), "{n} is empty");
        assert!(x == y, "{n} differs between two renders");
    }
    names
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

#[test]
fn render_twice_gives_byte_identical_files() {
    let dir = temp_dir("twice");
    let scene = dir.join("small.ron");
    std::fs::write(&scene, SCENE).unwrap();
    // a computes the references (and stores them on disk), b takes them from the disk cache,
    // c computes them again with --no-cache: all three write the same bytes.
    let (a, b, c) = (dir.join("a"), dir.join("b"), dir.join("c"));
    for (i, out) in [&a, &b, &c].into_iter().enumerate() {
        let mut args = vec![
            scene.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
            "--scale",
            "1",
        ];
        if i == 2 {
            args.push("--no-cache");
        }
        let o = render(&args);
        assert!(o.status.success(), "{}", stderr(&o));
        // One printed line per written file.
        let printed = String::from_utf8(o.stdout).unwrap();
        assert_eq!(printed.lines().count(), files(out).len());
        for line in printed.lines() {
            assert!(Path::new(line).is_file(), "{line}");
        }
    }
    let cached = std::fs::read_dir(cache_dir())
        .unwrap()
        .filter(|e| {
            let n = e.as_ref().unwrap().file_name();
            n.to_string_lossy().starts_with("reference-")
        })
        .count();
    assert!(cached >= 1, "no reference image in the disk cache");
    same_files(&a, &c, &[]);
    let names = same_files(
        &a,
        &b,
        &[
            "small_jitter_n256_seed1_pattern@1x.png",
            "small_jitter_n256_seed1_spectrum@1x.svg",
            "small_jitter_n256_seed1_raps.csv",
            "small_halton_n256_seed0_response@1x.png",
            "small_jitter_n256_seed1_column@1x.png",
            "small_n256_comparison@1x.png",
        ],
    );
    // 2 columns × 8 figures (pattern, spectrum, raps, reconstruction, reference, error,
    // kernel, response) × (png, svg, csv) + (2 column composites + 1 comparison) × (png, svg).
    assert_eq!(names.len(), 2 * 8 * 3 + (2 + 1) * 2, "{names:#?}");
    assert!(names.contains(&"small_n256_comparison@1x.svg".to_string()));
}

#[test]
fn scale_two_doubles_the_figures_and_format_selects_files() {
    let dir = temp_dir("scale2");
    let scene = dir.join("small.ron");
    std::fs::write(&scene, SCENE).unwrap();
    let out = dir.join("out");
    // CSV alone draws nothing: a scale would have no effect and is refused.
    let o = render(&[
        scene.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--scale",
        "2",
        "--format",
        "csv",
    ]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("--scale 2 cannot be used with --format csv"));
    assert!(!out.exists());
    let o = render(&[
        scene.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--format",
        "csv",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let names = files(&out);
    assert_eq!(names.len(), 2 * 8, "{names:#?}");
    assert!(names.iter().all(|n| n.ends_with(".csv")));

    let o = render(&[
        scene.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--scale",
        "2",
        "--format",
        "png",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let png = std::fs::read(out.join("small_jitter_n256_seed1_pattern@2x.png")).unwrap();
    let reader = png::Decoder::new(std::io::Cursor::new(png))
        .read_info()
        .unwrap();
    assert_eq!((reader.info().width, reader.info().height), (960, 1020));

    // PDF: every figure, both column composites and the comparison, one page each.
    let pdf_out = dir.join("pdf");
    let o = render(&[
        scene.to_str().unwrap(),
        "--out",
        pdf_out.to_str().unwrap(),
        "--format",
        "pdf",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let names = files(&pdf_out);
    assert_eq!(names.len(), 2 * 8 + 2 + 1, "{names:#?}");
    for n in &names {
        assert!(n.ends_with(".pdf"), "{n}");
        let bytes = std::fs::read(pdf_out.join(n)).unwrap();
        assert!(
            bytes.starts_with(b"%PDF-1.") && bytes.trim_ascii_end().ends_with(b"%%EOF"),
            "{n}"
        );
        let doc = lopdf::Document::load_mem(&bytes).unwrap();
        assert_eq!(doc.get_pages().len(), 1, "{n}");
    }
}

#[test]
fn malformed_scene_exits_2_naming_line_and_column() {
    let dir = temp_dir("malformed");
    let scene = dir.join("bad.ron");
    std::fs::write(&scene, "(\n    title: \"x\",\n    n: twelve,\n)\n").unwrap();
    let o = render(&[
        scene.to_str().unwrap(),
        "--out",
        dir.join("o").to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let e = stderr(&o);
    assert!(e.contains("bad.ron:3:"), "{e}");
    assert_eq!(e.trim().lines().count(), 1, "one line: {e}");
    assert!(
        !dir.join("o").exists(),
        "nothing is written for a bad scene"
    );
}

#[test]
fn missing_scene_exits_2_naming_the_path() {
    // A file the user names that is not there is bad input (see the README's exit status).
    let dir = temp_dir("missing");
    let missing = dir.join("nope.ron");
    let o = render(&[
        missing.to_str().unwrap(),
        "--out",
        dir.join("o").to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("nope.ron"), "{}", stderr(&o));
}

#[test]
fn bad_aspect_exits_2_naming_the_option_and_what_it_must_be() {
    let dir = temp_dir("aspect");
    let scene = dir.join("small.ron");
    std::fs::write(&scene, SCENE).unwrap();
    for (bad, says) in [
        ("0:9", "positive finite"),
        ("16:", "W:H"),
        ("abc", "W:H"),
        ("NaN:9", "positive finite"),
        ("100:1", "0.1..=10"),
    ] {
        let o = render(&[
            scene.to_str().unwrap(),
            "--out",
            dir.join("o").to_str().unwrap(),
            "--aspect",
            bad,
        ]);
        assert_eq!(o.status.code(), Some(2), "{bad}: {}", stderr(&o));
        let e = stderr(&o);
        assert!(e.contains("--aspect") && e.contains(says), "{bad}: {e}");
        assert!(!dir.join("o").exists(), "nothing written for {bad}");
    }
}

#[test]
fn scale_out_of_range_exits_2_naming_scale_and_range() {
    let dir = temp_dir("scale");
    let scene = dir.join("small.ron");
    std::fs::write(&scene, SCENE).unwrap();
    for bad in ["0", "9"] {
        let o = render(&[
            scene.to_str().unwrap(),
            "--out",
            dir.join("o").to_str().unwrap(),
            "--scale",
            bad,
        ]);
        assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
        let e = stderr(&o);
        assert!(
            e.contains(&format!("--scale = {bad}")) && e.contains("1..=4"),
            "{e}"
        );
        assert_eq!(e.trim().lines().count(), 1, "one line: {e}");
    }
    let o = render(&[
        scene.to_str().unwrap(),
        "--out",
        dir.join("o").to_str().unwrap(),
        "--format",
        "png,jpeg",
    ]);
    assert_eq!(o.status.code(), Some(2));
    let e = stderr(&o);
    assert!(
        e.contains("'jpeg'") && e.contains("--format") && e.contains("png, svg, pdf, csv"),
        "{e}"
    );
}

#[test]
fn unwritable_output_exits_1_naming_the_path() {
    let dir = temp_dir("unwritable");
    let scene = dir.join("small.ron");
    std::fs::write(&scene, SCENE).unwrap();
    // A regular file where the output directory should be.
    let blocker = dir.join("file");
    std::fs::write(&blocker, "not a directory").unwrap();
    let out = blocker.join("out");
    let o = render(&[scene.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(stderr(&o).contains(out.to_str().unwrap()), "{}", stderr(&o));
}

#[test]
fn failing_node_exits_2_naming_column_and_node() {
    let dir = temp_dir("node");
    let scene = dir.join("poisson.ron");
    // Dart throwing with a radius no 256 points can keep.
    let text = SCENE.replace(
        r#"(pattern: (kind: "halton", base_x: 2, base_y: 3, skip: 0), seed: 0, label: "Halton")"#,
        r#"(pattern: (kind: "poisson-dart", radius: 0.4, max_misses: 1000), seed: 0, label: "too sparse")"#,
    );
    assert_ne!(text, SCENE);
    std::fs::write(&scene, text).unwrap();
    let o = render(&[
        scene.to_str().unwrap(),
        "--out",
        dir.join("o").to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let e = stderr(&o);
    assert!(
        e.contains("column 2 (too sparse)") && e.contains("points node failed"),
        "{e}"
    );
}

#[test]
fn evaluate_columns_collects_every_column_or_names_the_first_failed_node() {
    use samplescope::core::cancel::Cancel;
    use samplescope::engine::{ColumnsError, Evaluator};
    use samplescope::scene::graph::{self, NodeKind};
    use samplescope::scene::Scene;
    use std::sync::Arc;
    let eval = Evaluator::default();
    let run = |scene: &Scene, cancel: &Cancel| {
        eval.evaluate_columns(scene, Arc::new(graph::plan(scene)), cancel)
    };
    let ok = Scene::from_ron(SCENE, "ok.ron").unwrap();
    let results = run(&ok, &Cancel::never()).unwrap();
    assert_eq!(results.len(), 2);
    for col in &results {
        assert!(col[&NodeKind::Points].value.is_ok());
    }
    let text = SCENE.replace(
        r#"(pattern: (kind: "halton", base_x: 2, base_y: 3, skip: 0), seed: 0, label: "Halton")"#,
        r#"(pattern: (kind: "poisson-dart", radius: 0.4, max_misses: 1000), seed: 0, label: "too sparse")"#,
    );
    let bad = Scene::from_ron(&text, "bad.ron").unwrap();
    match run(&bad, &Cancel::never()) {
        Err(ColumnsError::Failed(e)) => assert!(
            e.starts_with("column 2 (too sparse): points node failed: "),
            "{e}"
        ),
        other => panic!("{:?}", other.map(|r| r.len())),
    }
    let cancel = Cancel::new();
    cancel.cancel();
    assert!(matches!(run(&ok, &cancel), Err(ColumnsError::Cancelled)));
}

#[test]
fn scene_without_drawable_panels_warns_and_writes_nothing() {
    let dir = temp_dir("nopanels");
    let scene = dir.join("none.ron");
    let text = SCENE.replace(
        "panels: (pattern: true, spectrum: true, zoneplate: true, filter: true, cost: false)",
        "panels: (pattern: false, spectrum: false, zoneplate: false, filter: false, cost: false)",
    );
    assert_ne!(text, SCENE);
    std::fs::write(&scene, text).unwrap();
    let out = dir.join("o");
    let o = render(&[scene.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stderr(&o).contains("nothing written"), "{}", stderr(&o));
    assert!(o.stdout.is_empty());
    assert!(files(&out).is_empty());
}

/// A one-column scene showing only the 1D sampling-theorem panel (a Gaussian sampled at 3,
/// box reconstruction: both aliasing terms non-zero).
const THEOREM_SCENE: &str = r#"(
    title: "Theorem render test",
    columns: [(pattern: (kind: "jitter", cols: 0, amount: 1.0), seed: 1)],
    n: 64,
    panels: (pattern: false, spectrum: false, zoneplate: false, filter: false, cost: false, theorem: true),
    theorem: (
        signal: (kind: "gaussian", sigma: 0.2),
        rate: 3.0,
        filter: (kind: "box", radius: 0.5),
        extent: 2.0,
        pair: (kind: gaussian, scale: 1.0, shift: 0.0),
        vdc_rows: 4,
    ),
)
"#;

#[test]
fn theorem_scene_writes_the_theorem_figures_byte_identically() {
    let dir = temp_dir("theorem");
    let scene = dir.join("theory.ron");
    std::fs::write(&scene, THEOREM_SCENE).unwrap();
    let (a, b) = (dir.join("a"), dir.join("b"));
    for out in [&a, &b] {
        let o = render(&[scene.to_str().unwrap(), "--out", out.to_str().unwrap()]);
        assert!(o.status.success(), "{}", stderr(&o));
        assert!(!stderr(&o).contains("nothing written"), "{}", stderr(&o));
        let printed = String::from_utf8(o.stdout).unwrap();
        assert_eq!(printed.lines().count(), files(out).len());
    }
    let names = same_files(
        &a,
        &b,
        &[
            "theory_theorem-signal@1x.png",
            "theory_theorem-signal@1x.svg",
            "theory_theorem-signal.csv",
            "theory_theorem-spectrum@1x.png",
            "theory_theorem-spectrum.csv",
            "theory_theorem-reconstructed@1x.svg",
            "theory_theorem-reconstructed.csv",
            "theory_theorem-pair@1x.png",
            "theory_theorem-pair.csv",
            "theory_jitter_n64_seed1_column@1x.png",
            "theory_n64_comparison@1x.png",
        ],
    );
    // 4 theorem figures × (png, svg, csv) + (the column composite + the comparison) × (png,
    // svg).
    assert_eq!(names.len(), 4 * 3 + 2 * 2, "{names:#?}");
    // The spectrum figure: its base size (wider by the legend) and the aliasing numbers.
    let png = std::fs::read(a.join("theory_theorem-spectrum@1x.png")).unwrap();
    let reader = png::Decoder::new(std::io::Cursor::new(png))
        .read_info()
        .unwrap();
    let info = reader.info();
    assert_eq!((info.width, info.height), (820, 510));
    let text = crate::png_text(info);
    for key in ["pre-aliasing", "post-aliasing", "signal", "sampling rate"] {
        assert!(text.iter().any(|(k, _)| k == key), "no {key} in {text:?}");
    }
    let csv = std::fs::read_to_string(a.join("theory_theorem-signal.csv")).unwrap();
    assert!(csv.starts_with("series,x,value\n"));
    assert!(
        csv.lines().any(|l| l.starts_with("sample,0,1")),
        "f(0) = 1 is a sample"
    );
}

#[test]
fn an_out_path_that_is_a_file_is_refused_before_any_work() {
    let dir = temp_dir("out-is-file");
    let scene = dir.join("small.ron");
    std::fs::write(&scene, SCENE).unwrap();
    let file = dir.join("taken");
    std::fs::write(&file, "keep me").unwrap();
    let o = render(&[scene.to_str().unwrap(), "--out", file.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    let e = stderr(&o);
    assert!(e.contains("exists and is not a directory"), "{e}");
    assert_eq!(e.trim().lines().count(), 1, "{e}");
    assert_eq!(std::fs::read_to_string(&file).unwrap(), "keep me");
}
