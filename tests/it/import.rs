//! Importing point sets from other tools: every format in `tests/data` parses, every bad file
//! fails naming its line, and a scene column with imported points evaluates with exactly those
//! points (spectrum as one realization; supersampling refused with a clear message).

use glam::DVec2;
use samplescope::core::cancel::Cancel;
use samplescope::core::pointset::{read_points_file, OutOfRange, PointsFileError, Position};
use samplescope::engine::Evaluator;
use samplescope::scene::graph::{NodeKind, NodeValue};
use samplescope::scene::node::NodeError;
use samplescope::scene::{Column, ImportedPoints, ReconMode, Scene, SceneError};
use std::path::{Path, PathBuf};

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data")
        .join(name)
}

fn read(name: &str) -> Result<Vec<DVec2>, PointsFileError> {
    read_points_file(&data(name), OutOfRange::Reject)
}

#[test]
fn psa_text_with_count_line_parses() {
    let p = read("psa-with-count.txt").unwrap();
    assert_eq!(p.len(), 6);
    assert_eq!(p[0], DVec2::new(0.125, 0.25));
    assert_eq!(p[5], DVec2::new(0.75, 0.875));
}

#[test]
fn csv_with_and_without_header_parse() {
    let a = read("csv-with-header.csv").unwrap();
    assert_eq!(
        a,
        vec![
            DVec2::new(0.1, 0.2),
            DVec2::new(0.3, 0.4),
            DVec2::new(0.5, 0.6),
            DVec2::new(0.7, 0.8)
        ]
    );
    let b = read("csv-no-header.csv").unwrap();
    assert_eq!(b.len(), 3);
    assert_eq!(b[2], DVec2::new(0.25, 0.75));
}

#[test]
fn point_outside_the_unit_square_names_its_line() {
    match read("outside-line-5.txt") {
        Err(PointsFileError::OutOfRange { at, x, y }) => {
            assert_eq!((at, x, y), (Position::Line(5), 1.25, 0.5));
        }
        other => panic!("{other:?}"),
    }
    let msg = read("outside-line-5.txt").unwrap_err().to_string();
    assert!(
        msg.starts_with("line 5:") && msg.contains("bounding-box"),
        "{msg}"
    );
    // The explicit choice maps the bounding box [0.1, 1.25] × [0.1, 0.9] into [0,1)².
    let p = read_points_file(
        &data("outside-line-5.txt"),
        OutOfRange::NormalizeToBoundingBox,
    )
    .unwrap();
    assert_eq!(p.len(), 5);
    assert!(p
        .iter()
        .all(|q| (0.0..1.0).contains(&q.x) && (0.0..1.0).contains(&q.y)));
    assert_eq!(p[0], DVec2::new(0.0, 0.0));
    // Aspect kept: y is scaled by the x extent 1.15.
    assert!((p[4].y - 0.8 / 1.15).abs() < 1e-12, "{}", p[4].y);
}

#[test]
fn malformed_line_is_named() {
    match read("malformed-line-4.csv") {
        Err(PointsFileError::Malformed { line, message }) => {
            assert_eq!(line, 4);
            assert!(message.contains("zero"), "{message}");
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn count_mismatch_names_the_count_line() {
    assert_eq!(
        read("count-mismatch.txt"),
        Err(PointsFileError::CountMismatch {
            line: 1,
            declared: 5,
            found: 3
        })
    );
}

#[test]
fn missing_file_is_an_io_error_with_the_path() {
    let e = read("no-such-file.txt").unwrap_err();
    assert!(matches!(e, PointsFileError::Io { .. }), "{e:?}");
    assert!(e.to_string().contains("no-such-file.txt"));
}

/// Evaluates `scene`, returning the first column's points and the accuracy line of its spectrum.
fn points_and_spectrum_note(scene: &Scene) -> (Vec<DVec2>, Option<String>, Evaluator) {
    let eval = Evaluator::default();
    let mut pts = None;
    let mut note = None;
    eval.evaluate(scene, &Cancel::new(), &mut |c, kind, r| {
        assert!(
            r.value.is_ok(),
            "column {c} {kind:?}: {:?}",
            r.value.as_ref().err()
        );
        if c == 0 {
            match (&r.value, kind) {
                (Ok(NodeValue::Points(p)), _) => pts = Some(p.points.clone()),
                (Ok(_), NodeKind::Spectrum) => note = r.accuracy.as_ref().map(|a| a.to_string()),
                _ => {}
            }
        }
    });
    (pts.expect("points node"), note, eval)
}

#[test]
fn scene_column_with_a_point_file_evaluates_with_exactly_those_points() {
    let scene =
        Scene::load(&data("scene-with-imported-points.ron")).unwrap_or_else(|e| panic!("{e}"));
    let expected = read("psa-with-count.txt").unwrap();
    let imp = scene.columns[0].points.as_ref().unwrap();
    assert_eq!(imp.to_dvec(), expected);
    assert_eq!(scene.columns[0].title(), "psa-with-count.txt (6 points)");
    let (pts, note, eval) = points_and_spectrum_note(&scene);
    assert_eq!(pts, expected);
    // Imported points are one realization: K is forced to 1 for that column, with a note.
    let note = note.unwrap_or_default();
    assert!(note.contains("K = 1"), "{note}");
    // Both columns were computed (points of each, spectrum of each).
    assert_eq!(eval.count(NodeKind::Points), 2);
    assert_eq!(eval.count(NodeKind::Spectrum), 2);
}

#[test]
fn inline_points_evaluate_and_are_keyed_by_their_content() {
    let mut scene = Scene::default();
    scene.panels.spectrum = false;
    scene.panels.filter = false;
    scene.panels.zoneplate = false;
    let pts = vec![[0.5, 0.5], [0.25, 0.75], [0.0, 0.999]];
    scene.columns = vec![
        Column {
            points: Some(ImportedPoints {
                points: pts.clone(),
                ..ImportedPoints::default()
            }),
            ..Column::default()
        };
        2
    ];
    scene.validate("inline").unwrap();
    let (got, _, eval) = points_and_spectrum_note(&scene);
    assert_eq!(
        got,
        pts.iter()
            .map(|&[x, y]| DVec2::new(x, y))
            .collect::<Vec<_>>()
    );
    // Two columns with equal points share one evaluation.
    assert_eq!(eval.count(NodeKind::Points), 1);
    // A changed point is a new key.
    scene.columns[1].points.as_mut().unwrap().points[0] = [0.5, 0.5000001];
    eval.evaluate(&scene, &Cancel::new(), &mut |_, _, _| {});
    assert_eq!(eval.count(NodeKind::Points), 2);
}

#[test]
fn supersampling_an_imported_column_fails_on_that_panel_only() {
    let mut scene = Scene::load(&data("scene-with-imported-points.ron")).unwrap();
    scene.recon.mode = ReconMode::Supersample { spp: 4 };
    let eval = Evaluator::default();
    let mut errors = Vec::new();
    eval.evaluate(&scene, &Cancel::new(), &mut |c, kind, r| {
        if let Err(e) = &r.value {
            errors.push((c, kind, e.clone()));
        }
    });
    assert_eq!(errors.len(), 1, "{errors:?}");
    let (c, kind, msg) = &errors[0];
    assert_eq!((*c, *kind), (0, NodeKind::Reconstruction));
    assert!(
        matches!(
            msg,
            NodeError::ImportedNeedsPattern {
                column: 0,
                what: "supersampling"
            }
        ),
        "{msg:?}"
    );
    let text = msg.to_string();
    assert!(
        text.contains("column 1") && text.contains("imported"),
        "{text}"
    );
}

#[test]
fn bad_points_in_scenes_name_column_and_line() {
    let text = r#"(title: "x", columns: [(points: Some((path: "outside-line-5.txt")))])"#;
    match Scene::from_ron_in(text, "s.ron", Some(data("").as_path())) {
        Err(SceneError::Points { column, error, .. }) => {
            assert_eq!(column, 0);
            assert!(matches!(
                error,
                PointsFileError::OutOfRange {
                    at: Position::Line(5),
                    ..
                }
            ));
        }
        other => panic!("{other:?}"),
    }
    // Asking for the normalisation accepts the same file.
    let text =
        r#"(title: "x", columns: [(points: Some((path: "outside-line-5.txt", normalize: true)))])"#;
    let s = Scene::from_ron_in(text, "s.ron", Some(data("").as_path())).unwrap();
    assert_eq!(s.columns[0].points.as_ref().unwrap().points.len(), 5);
    // Inline points outside [0,1)² without normalize: the field and index are named.
    let text = r#"(title: "x", columns: [(points: Some((points: [(0.5, 0.5), (0.2, 1.5)])))])"#;
    match Scene::from_ron(text, "s.ron") {
        Err(SceneError::Invalid { field, .. }) => {
            assert_eq!(field, "columns[0].points.points[1]")
        }
        other => panic!("{other:?}"),
    }
    // Empty imports are refused.
    let text = r#"(title: "x", columns: [(points: Some(()))])"#;
    assert!(matches!(
        Scene::from_ron(text, "s.ron"),
        Err(SceneError::Invalid { .. })
    ));
}

mod ui {
    //! Import in the real app (egui_kittest, no rendering: no GPU needed): an error names the
    //! line and offers the normalisation, which retries the same file.

    use super::data;
    use egui_kittest::kittest::Queryable;
    use egui_kittest::Harness;
    use samplescope::ui::SamplescopeApp;

    fn harness() -> Harness<'static, SamplescopeApp> {
        let mut h = Harness::builder()
            .with_size(eframe::egui::Vec2::new(1400.0, 1000.0))
            .build_eframe(|cc| {
                let mut app = crate::hermetic_app(cc);
                app.view.show_timings = false;
                app
            });
        h.step();
        h
    }

    #[test]
    fn out_of_range_file_shows_the_line_and_normalise_retries() {
        let mut h = harness();
        h.state_mut()
            .import_points(0, &data("outside-line-5.txt"), false);
        h.step();
        h.get_by_label_contains("line 5");
        assert!(h.state().scene.columns[0].points.is_none());
        h.get_by_label("Normalise to bounding box").click();
        h.step();
        h.step();
        let imp = h.state().scene.columns[0].points.clone().expect("imported");
        assert_eq!(imp.points.len(), 5);
        assert!(imp.normalize);
        assert!(h.query_by_label("Normalise to bounding box").is_none());
        h.get_by_label_contains("outside-line-5.txt (5 points)");
        // Back to the pattern.
        h.get_by_label("Use the pattern").click();
        h.step();
        h.step();
        assert!(h.state().scene.columns[0].points.is_none());
    }

    #[test]
    fn malformed_file_has_no_normalise_button() {
        let mut h = harness();
        h.state_mut()
            .import_points(0, &data("malformed-line-4.csv"), false);
        h.step();
        h.get_by_label_contains("line 4");
        assert!(h.query_by_label("Normalise to bounding box").is_none());
    }

    #[test]
    fn drop_target_is_the_column_under_the_pointer() {
        let mut h = harness();
        h.state_mut().add_column();
        h.state_mut().add_column();
        let app = h.state();
        let central = eframe::egui::Rect::from_min_size(
            eframe::egui::pos2(300.0, 50.0),
            eframe::egui::vec2(900.0, 800.0),
        );
        assert_eq!(app.column_at(central, 310.0), 0);
        assert_eq!(app.column_at(central, 899.0), 1);
        assert_eq!(app.column_at(central, 1199.0), 2);
        // Outside the columns: the nearest one.
        assert_eq!(app.column_at(central, 10.0), 0);
        assert_eq!(app.column_at(central, 1500.0), 2);
    }

    /// Once drawn, the columns' own rectangles decide (they need not split the area equally).
    #[test]
    fn drop_target_follows_the_drawn_columns() {
        let mut h = harness();
        h.state_mut().add_column();
        h.state_mut().add_column();
        h.run_steps(3);
        let app = h.state();
        assert_eq!(app.column_rects().len(), 3);
        let central = eframe::egui::Rect::from_min_size(
            eframe::egui::pos2(0.0, 0.0),
            eframe::egui::vec2(10.0, 10.0),
        );
        for (i, r) in app.column_rects().iter().enumerate() {
            assert_eq!(app.column_at(central, r.center().x), i, "{r:?}");
        }
        let last = app.column_rects()[2];
        assert_eq!(app.column_at(central, last.right() + 500.0), 2);
    }
}

/// `--normalize` only makes sense with `--points`: the command line refuses it alone (exit 2)
/// without opening a window.
#[test]
fn cli_normalize_requires_points() {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_samplescope"))
        .arg("--normalize")
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("--points"), "{err}");
}
