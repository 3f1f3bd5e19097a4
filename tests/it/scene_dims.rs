//! A column in d dimensions (`dims`, `project`): through the scene file (round trip, the 2D
//! text unchanged, validation naming the field and its range), the points node (the
//! projection `points --dims D --project i,j` writes; the 2D key and points unchanged), and
//! the GUI's pair picker.

use samplescope::core::cancel::Cancel;
use samplescope::core::params::Params;
use samplescope::core::pattern::Pattern;
use samplescope::engine::Evaluator;
use samplescope::model::PointsData;
use samplescope::scene::graph::{self, NodeKind, NodeValue};
use samplescope::scene::{Column, Panels, Scene};
use std::sync::Arc;

/// The points node's value in every column of `scene`.
pub fn points_of(scene: &Scene) -> Vec<Arc<PointsData>> {
    let mut out = vec![None; scene.columns.len()];
    Evaluator::default().evaluate(scene, &Cancel::new(), &mut |c, k, r| {
        if k == NodeKind::Points {
            match &r.value {
                Ok(NodeValue::Points(p)) => out[c] = Some(p.clone()),
                other => panic!("column {c}: {other:?}"),
            }
        }
    });
    out.into_iter()
        .map(|p| p.expect("points computed"))
        .collect()
}

/// A scene of one `pattern` column in `dims` dimensions showing `project`, pattern panel only.
fn cube_scene(pattern: &str, n: usize, dims: usize, project: (usize, usize), seed: u64) -> Scene {
    Scene {
        n,
        columns: vec![Column {
            pattern: Pattern::from_name(pattern).unwrap(),
            seed,
            dims,
            project,
            ..Column::default()
        }],
        panels: Panels::only(samplescope::scene::panels::PanelKind::Pattern),
        ..Scene::default()
    }
}

#[test]
fn dims_and_project_round_trip_and_a_2d_scene_s_text_does_not_change() {
    let text = r#"(title: "d", n: 256, columns: [(pattern: (kind: "sobol"), dims: 16, project: (3, 7)), (pattern: (kind: "jitter"))])"#;
    let s = Scene::from_ron(text, "d.ron").unwrap();
    assert_eq!((s.columns[0].dims, s.columns[0].project), (16, (3, 7)));
    assert_eq!((s.columns[1].dims, s.columns[1].project), (2, (0, 1)));
    let written = s.to_ron();
    assert!(written.contains("dims: 16"), "{written}");
    assert_eq!(Scene::from_ron(&written, "again.ron").unwrap(), s);
    // The defaults are left out: every 2D scene is written as before.
    let plain = Scene::builtin_default().to_ron();
    assert!(
        !plain.contains("dims") && !plain.contains("project"),
        "{plain}"
    );
    for (name, text) in samplescope::scene::BUILTIN {
        let s = Scene::from_ron(text, name).unwrap();
        if s.columns.iter().all(|c| c.is_plain_2d()) {
            assert!(!s.to_ron().contains("project:"), "{name}");
        }
    }
}

#[test]
fn bad_dims_and_projections_name_the_field_and_the_range() {
    let err = |columns: &str| {
        let text = format!("(n: 256, columns: [{columns}])");
        Scene::from_ron(&text, "bad.ron").unwrap_err().to_string()
    };
    let e = err(r#"(pattern: (kind: "sobol"), dims: 1)"#);
    assert!(
        e.contains("columns[0].dims = 1") && e.contains("an integer in 2..=1024"),
        "{e}"
    );
    let e = err(r#"(pattern: (kind: "sobol"), dims: 1025)"#);
    assert!(e.contains("columns[0].dims = 1025"), "{e}");
    let e = err(r#"(pattern: (kind: "jitter")), (pattern: (kind: "jitter"), dims: 3)"#);
    assert!(
        e.contains("columns[1].dims = 3") && e.contains("jitter is defined in 2 dimensions only"),
        "{e}"
    );
    let e = err(r#"(pattern: (kind: "halton"), dims: 16, project: (3, 3))"#);
    assert!(
        e.contains("columns[0].project = (3, 3)")
            && e.contains("two different dimensions (i, j) in 0..=15"),
        "{e}"
    );
    let e = err(r#"(pattern: (kind: "halton"), dims: 16, project: (0, 16))"#);
    assert!(e.contains("columns[0].project = (0, 16)"), "{e}");
    let e = err(r#"(pattern: (kind: "halton"), project: (0, 2))"#);
    assert!(e.contains("in 0..=1 (dims = 2)"), "{e}");
    // The error points at the line and column of the field.
    let text = "(n: 256,\n columns: [(pattern: (kind: \"sobol\"),\n   dims: 0)])";
    let e = Scene::from_ron(text, "bad.ron").unwrap_err().to_string();
    assert!(e.contains("bad.ron:3:"), "{e}");
    // N · D within the coordinates a point set holds.
    let text = r#"(n: 1048576, columns: [(pattern: (kind: "random"), dims: 64)])"#;
    let e = Scene::from_ron(text, "big.ron").unwrap_err().to_string();
    assert!(
        e.contains("columns[0].dims = 64") && e.contains("2..=32"),
        "{e}"
    );
    // Supersampling draws fresh 2D samples per pixel: a projection is refused there.
    let text = r#"(n: 256, recon: (mode: supersample(spp: 4)), columns: [(pattern: (kind: "sobol"), dims: 4)])"#;
    let e = Scene::from_ron(text, "ss.ron").unwrap_err().to_string();
    assert!(
        e.contains("columns[0].dims") && e.contains("Supersample"),
        "{e}"
    );
    // The integration panel's 2D integrand in D = 8; a Genz one is taken.
    let text =
        r#"(n: 256, panels: (integration: true), columns: [(pattern: (kind: "sobol"), dims: 8)])"#;
    let e = Scene::from_ron(text, "int.ron").unwrap_err().to_string();
    assert!(
        e.contains("columns[0].dims = 8") && e.contains("genz-*"),
        "{e}"
    );
    let text = r#"(n: 256, panels: (integration: true), integration: (integrand: (kind: "genz-gaussian")), columns: [(pattern: (kind: "sobol"), dims: 8)])"#;
    Scene::from_ron(text, "genz.ron").unwrap();
}

#[test]
fn the_points_node_in_16_dimensions_is_the_projection_points_writes() {
    for (pattern, set, (i, j), seed) in [
        ("sobol", Some("scramble=owen-shuffled"), (3, 7), 5),
        ("halton", None, (14, 15), 0),
        ("padded", Some("base=pmj02"), (0, 9), 9),
    ] {
        let mut scene = cube_scene(pattern, 256, 16, (i, j), seed);
        if let Some((k, v)) = set.and_then(|s| s.split_once('=')) {
            scene.columns[0].pattern.set_field(k, v).unwrap();
        }
        scene.validate("t").unwrap();
        let node = &points_of(&scene)[0];
        let project = format!("{i},{j}");
        let seed_text = seed.to_string();
        let mut args = vec![
            "points",
            pattern,
            "-n",
            "256",
            "--dims",
            "16",
            "--project",
            &project,
        ];
        if let Some(s) = set {
            args.extend(["--set", s, "--seed", &seed_text]);
        }
        let (header, rows) = crate::points_csv(&args);
        assert_eq!(header, "x,y");
        let cli: Vec<[f64; 2]> = rows.iter().map(|r| [r[0], r[1]]).collect();
        let shown: Vec<[f64; 2]> = node.points.iter().map(|p| [p.x, p.y]).collect();
        assert_eq!(shown, cli, "{pattern} ({i}, {j})");
        // And it is the core's projection of the cube, bit for bit.
        let cube = scene.columns[0]
            .pattern
            .generate_cube(256, 16, seed, &Cancel::never())
            .unwrap();
        assert_eq!(node.points, cube.project(i, j).unwrap());
    }
}

#[test]
fn a_2d_column_keeps_its_key_and_points_and_other_projections_key_apart() {
    let s = cube_scene("sobol", 256, 2, (0, 1), 3);
    let key = |s: &Scene| {
        graph::plan(s)[0]
            .nodes
            .iter()
            .find(|n| n.kind == NodeKind::Points)
            .unwrap()
            .key
            .clone()
            .unwrap()
    };
    // The key of a 2D column is the one made before dimensions existed: pattern, N, seed.
    let col = &s.columns[0];
    let old = graph::key_of(NodeKind::Points, &(&col.pattern, s.n, col.seed), &[]).unwrap();
    assert_eq!(key(&s), old);
    assert_eq!(
        points_of(&s)[0].points,
        col.pattern.generate(256, 3).unwrap()
    );
    let mut keys = vec![key(&s)];
    for (d, p) in [
        (2, (1, 0)),
        (16, (0, 1)),
        (16, (3, 7)),
        (16, (7, 3)),
        (8, (3, 7)),
    ] {
        let t = cube_scene("sobol", 256, d, p, 3);
        keys.push(key(&t));
    }
    for (a, ka) in keys.iter().enumerate() {
        for kb in &keys[a + 1..] {
            assert_ne!(ka, kb);
        }
    }
    // D = 2 with the pair swapped shows (y, x).
    let swapped = points_of(&cube_scene("sobol", 256, 2, (1, 0), 3));
    let plain = points_of(&s);
    assert!(swapped[0]
        .points
        .iter()
        .zip(&plain[0].points)
        .all(|(a, b)| a.x == b.y && a.y == b.x));
}

/// The GUI with `scene` shown and computed (a missing wgpu adapter fails the test).
pub fn gui_with(
    scene: Scene,
    size: eframe::egui::Vec2,
) -> egui_kittest::Harness<'static, samplescope::ui::SamplescopeApp> {
    let mut h = egui_kittest::Harness::builder()
        .with_size(size)
        .wgpu()
        .build_eframe(|cc| {
            let mut app = crate::hermetic_app(cc);
            app.view.show_timings = false;
            app
        });
    h.state_mut().set_scene(scene, "dims".into());
    crate::settle(&mut h, 2);
    h
}

#[test]
fn the_pair_picker_changes_the_projection_the_panels_show() {
    use eframe::egui::accesskit::Role;
    use egui_kittest::kittest::Queryable;
    let mut scene = cube_scene("halton", 256, 16, (0, 1), 1);
    scene.panels.spectrum = true;
    let mut h = gui_with(scene, eframe::egui::Vec2::new(1400.0, 1000.0));
    let shown = |h: &egui_kittest::Harness<'static, samplescope::ui::SamplescopeApp>| {
        h.state().data[0]
            .get::<PointsData>()
            .data()
            .expect("points shown")
            .points
            .clone()
    };
    let cube = Pattern::from_name("halton")
        .unwrap()
        .generate_cube(256, 16, 1, &Cancel::never())
        .unwrap();
    assert_eq!(shown(&h), cube.project(0, 1).unwrap());
    // The picker offers every dimension but the other axis's: pick x = x14.
    h.get_by_role_and_label(Role::ComboBox, "pair x").click();
    h.run_steps(2);
    h.get_by_label("x14").click_accesskit();
    h.run_steps(2);
    crate::settle(&mut h, 2);
    assert_eq!(h.state().scene.columns[0].project, (14, 1));
    assert_eq!(shown(&h), cube.project(14, 1).unwrap());
    h.get_by_role_and_label(Role::ComboBox, "pair y").click();
    h.run_steps(2);
    h.get_by_label("x15").click_accesskit();
    h.run_steps(2);
    crate::settle(&mut h, 2);
    assert_eq!(h.state().scene.columns[0].project, (14, 15));
    assert_eq!(shown(&h), cube.project(14, 15).unwrap());
    // The spectrum is that projection's too (its key follows the points').
    assert!(h.state().data[0]
        .get::<samplescope::model::SpectrumData>()
        .is_ready());
    // A 2D-only pattern takes the column back to D = 2.
    h.get_by_role_and_label(Role::ComboBox, "Pattern").click();
    h.run_steps(2);
    h.get_by_label("jitter").click_accesskit();
    h.run_steps(2);
    crate::settle(&mut h, 2);
    let c = &h.state().scene.columns[0];
    assert_eq!((c.pattern.name(), c.dims, c.project), ("jitter", 2, (0, 1)));
    assert!(h.state().scene.validate("after").is_ok());
}
