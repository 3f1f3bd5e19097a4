//! The integration-error study in the app and in `render`: the node per column, its partial
//! results as realizations come in, only the nodes the scene shows, the figure and its CSV,
//! and the scene's settings checked with their field paths.

use samplescope::core::cancel::Cancel;
use samplescope::core::integration::run_study;
use samplescope::core::progress::no_progress;
use samplescope::engine::{Engine, Evaluator};
use samplescope::model::Accuracy;
use samplescope::scene::graph::{NodeKind, NodeValue};
use samplescope::scene::{Scene, BUILTIN};
use std::process::Command;
use std::sync::Arc;
use std::time::Duration;

fn shipped(name: &str) -> Scene {
    let (_, text) = BUILTIN.iter().find(|(n, _)| *n == name).unwrap();
    Scene::from_ron(text, name).unwrap()
}

#[test]
fn every_column_gets_its_study_with_partials_as_realizations_come_in() {
    let mut scene = shipped("integration-error-disk.ron");
    scene.panels.pattern = false;
    scene.integration.realizations = 256;
    let evaluator = Evaluator::default();
    let mut engine = Engine::with_evaluator(evaluator.clone(), Arc::new(|| {}));
    engine.submit(&scene);
    let updates = engine.wait(Duration::from_secs(300));
    // Only what the scene shows: the study, nothing else (not even points).
    for (kind, count) in evaluator.counts() {
        let want = if kind == NodeKind::Integration { 4 } else { 0 };
        assert_eq!(count, want, "{} evaluated {count} times", kind.name());
    }
    for c in 0..scene.columns.len() {
        let mine: Vec<_> = updates
            .iter()
            .filter(|u| u.kind == NodeKind::Integration && u.column == c)
            .collect();
        let (last, partials) = mine.split_last().unwrap();
        assert!(last.progress.is_none());
        let data = |u: &samplescope::engine::Update| match &u.result.value {
            Ok(NodeValue::Integration(d)) => d.clone(),
            other => panic!("{other:?}"),
        };
        let col = &scene.columns[c];
        let want = run_study(
            &scene.integration.request(col.pattern, col.seed, col.dims),
            &Cancel::never(),
            &mut no_progress,
        )
        .unwrap();
        let got = data(last);
        assert_eq!((got.done, got.of), (256, 256));
        assert_eq!(
            got.study.rows, want.rows,
            "column {c}: the plain study, bit for bit"
        );
        assert_eq!(got.study.slope, want.slope);
        assert_eq!(got.integrand, "disk cx=0.5 cy=0.5 r=0.3");
        // The thumbnail is the disk: bright in the centre, dark in the corner.
        let t = &got.thumbnail;
        assert_eq!(t.values[(t.height / 2) * t.width + t.width / 2], 1.0);
        assert_eq!(t.values[0], 0.0);
        // 256 realizations of 8188 points each come in several chunks.
        assert!(!partials.is_empty(), "column {c}: no partial study");
        for u in partials {
            let d = data(u);
            assert!(d.done < 256);
            assert_eq!(
                u.result.accuracy,
                Some(Accuracy::Realizations {
                    done: d.done,
                    of: 256
                })
            );
        }
    }
}

#[test]
fn the_measured_slopes_are_those_the_scene_notes_state() {
    // The notes quote `samplescope converge` with seed 1; the scene's columns use seed 1.
    for (name, want) in [
        (
            "integration-error-disk.ron",
            &[-1.05, -1.48, -1.37, -1.46][..],
        ),
        (
            "integration-error-gaussian.ron",
            &[-1.01, -1.97, -2.77, -2.76][..],
        ),
        (
            "integration-error-dims.ron",
            &[-0.88, -1.92, -1.67, -0.88, -1.88][..],
        ),
    ] {
        let scene = shipped(name);
        assert_eq!(want.len(), scene.columns.len(), "{name}");
        for (col, &w) in scene.columns.iter().zip(want) {
            let s = run_study(
                &scene.integration.request(col.pattern, col.seed, col.dims),
                &Cancel::never(),
                &mut no_progress,
            )
            .unwrap();
            let slope = s.slope.unwrap();
            assert!((slope - w).abs() < 0.006, "{name} {}: {slope}", col.title());
            assert!(
                scene
                    .notes
                    .contains(&format!("{w:.2}").replacen('-', "−", 1)),
                "{name}: the notes quote {w}"
            );
        }
    }
}

#[test]
fn the_settings_are_checked_with_their_field_and_position() {
    let cases = [
        (
            "(panels: (integration: true), integration: (realizations: 0))",
            "s.ron:1:45: integration.realizations = 0: must be an integer in 1..=4096",
        ),
        (
            "(integration: (ns: []))",
            "integration.ns = 0 values: must be 1 to 64 sample counts",
        ),
        (
            "(integration: (ns: [16, 0]))",
            "integration.ns = 0: must be sample counts in 1..=1048576",
        ),
        (
            r#"(integration: (integrand: (kind: "disk", r: 0.0)))"#,
            "integration.integrand.r = 0",
        ),
    ];
    for (text, want) in cases {
        let e = Scene::from_ron(text, "s.ron").unwrap_err().to_string();
        assert!(e.contains(want), "{text}: {e}");
    }
}

#[test]
fn render_writes_the_integration_figure_with_every_column_and_its_csv() {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("integration-render-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let scene_path = dir.with_extension("ron");
    let text = BUILTIN
        .iter()
        .find(|(n, _)| *n == "integration-error-gaussian.ron")
        .unwrap()
        .1
        .replace("realizations: 64", "realizations: 8")
        .replace("pattern: true", "pattern: false");
    std::fs::write(&scene_path, text).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_samplescope"))
        .arg("render")
        .arg(&scene_path)
        .arg("--out")
        .arg(&dir)
        .args(["--format", "png,csv", "--no-cache"])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let names: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    let png = names
        .iter()
        .find(|n| n.contains("integration") && n.ends_with(".png"))
        .unwrap_or_else(|| panic!("{names:?}"));
    let bytes = std::fs::read(dir.join(png)).unwrap();
    let decoder = png::Decoder::new(std::io::Cursor::new(&bytes));
    let info = decoder.read_info().unwrap().info().clone();
    assert_eq!((info.width, info.height), (900, 510));
    let csv = names
        .iter()
        .find(|n| n.contains("integration") && n.ends_with(".csv"));
    let csv = std::fs::read_to_string(dir.join(csv.unwrap())).unwrap();
    let mut lines = csv.lines();
    assert_eq!(
        lines.next(),
        Some("column,n,mse,mse_stderr,variance,bias2,realizations")
    );
    // Four columns × nine N, in column order, with 8 realizations each.
    let rows: Vec<&str> = lines.collect();
    assert_eq!(rows.len(), 36);
    assert!(rows[0].starts_with("random,16,"), "{}", rows[0]);
    assert!(rows.iter().all(|r| r.ends_with(",8")));
    // Only column 0 has the figure (it holds every column).
    assert_eq!(
        names.iter().filter(|n| n.contains("integration")).count(),
        2
    );
    let _ = std::fs::remove_dir_all(&dir);
    let _ = std::fs::remove_file(&scene_path);
}
