//! The projection matrix: its node's cells are the projection table's rows (the first K
//! dimensions of the column's points), it is planned only while its panel is shown, its figure
//! and CSV are written, and a click on a cell shows that pair in the column's panels.

use crate::scene_dims::{gui_with, points_of};
use samplescope::core::cancel::Cancel;
use samplescope::core::cube::CubePoints;
use samplescope::core::metrics::cube::{projection_table, ProjectionMeasure};
use samplescope::core::params::Params;
use samplescope::core::pattern::Pattern;
use samplescope::core::progress::no_progress;
use samplescope::engine::Evaluator;
use samplescope::model::{MatrixAxis, MatrixData};
use samplescope::scene::graph::{self, NodeKind, NodeValue};
use samplescope::scene::panels::PanelKind;
use samplescope::scene::{Column, Panels, Scene};
use std::sync::Arc;

fn scene(pattern: &str, settings: &[(&str, &str)], n: usize, dims: usize, k: usize) -> Scene {
    let mut p = Pattern::from_name(pattern).unwrap();
    for (key, v) in settings {
        p.set_field(key, v).unwrap();
    }
    let mut s = Scene {
        n,
        columns: vec![Column {
            pattern: p,
            seed: 3,
            dims,
            ..Column::default()
        }],
        panels: Panels::only(PanelKind::Matrix),
        ..Scene::default()
    };
    s.matrix.dims = k;
    s
}

fn matrix_of(s: &Scene) -> Arc<MatrixData> {
    let mut out = None;
    Evaluator::default().evaluate(s, &Cancel::new(), &mut |_, k, r| {
        if k == NodeKind::Matrix {
            match &r.value {
                Ok(NodeValue::Matrix(m)) => out = Some(m.clone()),
                other => panic!("{other:?}"),
            }
        }
    });
    out.expect("the matrix node ran")
}

#[test]
fn the_cells_are_the_projection_table_of_the_first_k_dimensions() {
    for (pattern, settings, dims, k) in [
        ("sobol", &[("scramble", "owen-shuffled")][..], 16, 16),
        ("halton", &[][..], 16, 6),
        ("padded", &[][..], 8, 8),
        ("rank1", &[][..], 12, 5),
    ] {
        let s = scene(pattern, settings, 256, dims, k);
        s.validate("t").unwrap();
        let m = matrix_of(&s);
        assert_eq!((m.k, m.dims, m.n), (k, dims, 256));
        assert_eq!(m.cells.len(), k * (k - 1) / 2);
        let cube = s.columns[0]
            .pattern
            .generate_cube(256, dims, 3, &Cancel::never())
            .unwrap();
        let first: Vec<f64> = cube.rows().flat_map(|r| r[..k].to_vec()).collect();
        let table = projection_table(
            &CubePoints::new(k, first).unwrap(),
            &Cancel::never(),
            &mut no_progress,
        )
        .unwrap();
        for row in &table {
            let cell = m
                .cell(row.dims[0], row.dims[1])
                .expect("every pair has a cell");
            assert_eq!(cell.row.as_ref(), Some(row), "{pattern} {:?}", row.dims);
            // The cell's scatter plot holds the points of that projection.
            let dark = cell.coverage.iter().filter(|&&c| c > 0).count();
            assert!(
                dark > 100 && dark <= 256,
                "{pattern} {:?}: {dark}",
                row.dims
            );
        }
        assert!(m.complete());
    }
}

#[test]
fn k_is_at_most_the_column_s_dims_and_a_2d_column_has_one_cell() {
    let s = scene("jitter", &[], 64, 2, 16);
    let m = matrix_of(&s);
    assert_eq!((m.k, m.cells.len()), (2, 1));
    assert_eq!(m.cells[0].pair, [0, 1]);
    // The same points as the points node shows.
    let mut both = s.clone();
    both.panels.pattern = true;
    let pts = &points_of(&both)[0];
    let table = samplescope::core::metrics::cube::projection_table(
        &CubePoints::from_2d(&pts.points),
        &Cancel::never(),
        &mut no_progress,
    )
    .unwrap();
    assert_eq!(m.cells[0].row.as_ref(), Some(&table[0]));
}

#[test]
fn the_node_is_planned_only_while_the_panel_is_shown_and_the_measure_is_not_in_its_key() {
    let mut s = scene("sobol", &[], 256, 16, 8);
    s.panels = Panels::default();
    let has = |s: &Scene| {
        graph::plan(s)[0]
            .nodes
            .iter()
            .find(|n| n.kind == NodeKind::Matrix)
            .map(|n| n.key.clone().unwrap())
    };
    assert!(has(&s).is_none());
    s.panels.matrix = true;
    let key = has(&s).unwrap();
    s.matrix.measure = ProjectionMeasure::MinDistance;
    assert_eq!(has(&s).unwrap(), key, "the measure only tints");
    s.matrix.dims = 9;
    assert_ne!(has(&s).unwrap(), key);
}

#[test]
fn render_writes_the_matrix_figure_and_its_table() {
    let dir = std::env::temp_dir().join(format!("samplescope-matrix-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let scene_file = dir.join("m.ron");
    std::fs::write(
        &scene_file,
        r#"(title: "m", n: 256, columns: [(pattern: (kind: "halton"), dims: 8, project: (6, 7))], panels: (pattern: false, spectrum: false, zoneplate: false, filter: false, matrix: true), effects: (reconstruction: false, error: false), matrix: (dims: 8, measure: r#l2-star))"#,
    )
    .unwrap();
    let out = crate::cli_points::samplescope(&[
        "render",
        scene_file.to_str().unwrap(),
        "--out",
        dir.join("out").to_str().unwrap(),
        "--format",
        "png,svg,pdf,csv",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let files: Vec<String> = std::fs::read_dir(dir.join("out"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    for ext in ["png", "svg", "pdf", "csv"] {
        assert!(
            files
                .iter()
                .any(|f| f.contains("_matrix") && f.ends_with(&format!(".{ext}"))),
            "{ext}: {files:?}"
        );
    }
    let csv_name = files.iter().find(|f| f.ends_with("_matrix.csv")).unwrap();
    let csv = std::fs::read_to_string(dir.join("out").join(csv_name)).unwrap();
    let mut lines = csv.lines();
    assert_eq!(
        lines.next(),
        Some("i,j,t_value,l2_star_discrepancy,min_distance")
    );
    assert_eq!(lines.count(), 28);
    let svg_name = files
        .iter()
        .find(|f| f.ends_with("_matrix@1x.svg"))
        .unwrap();
    let svg = std::fs::read_to_string(dir.join("out").join(svg_name)).unwrap();
    assert!(
        svg.contains("L2-star discrepancy") || svg.contains("x6 × x7"),
        "metadata"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn clicking_a_matrix_cell_shows_that_pair() {
    use egui_kittest::kittest::Queryable;
    let mut s = scene("halton", &[("scramble", "owen")], 256, 8, 8);
    s.panels.pattern = true;
    let mut h = gui_with(s, eframe::egui::Vec2::new(1400.0, 1000.0));
    assert_eq!(h.state().scene.columns[0].project, (0, 1));
    let rect = h.get_by_label("projection matrix").rect();
    // Cell (i, j) = (1, 6): grid column 1, row K − 1 − j = 1, at its centre (the picture is
    // drawn at the rectangle's pixels: one pixel per point here).
    assert_eq!(h.ctx.pixels_per_point(), 1.0);
    let (ax, ay) = (
        MatrixAxis::new(7, rect.width().round() as usize),
        MatrixAxis::new(7, rect.height().round() as usize),
    );
    let at = |i: usize, row: usize| {
        let ((x, w), (y, hh)) = (ax.span(i), ay.span(row));
        rect.min.round() + eframe::egui::vec2(x as f32 + w as f32 / 2.0, y as f32 + hh as f32 / 2.0)
    };
    let pos = at(1, 1);
    // Hovering shows the cell's values (tooltips at once, the pointer held still).
    h.ctx.all_styles_mut(|s| {
        s.interaction.tooltip_delay = 0.0;
        s.interaction.show_tooltips_only_when_still = false;
    });
    h.hover_at(pos);
    let mut shown = false;
    for _ in 0..120 {
        h.step();
        if h.query_by_label_contains("x1 × x6:").is_some() {
            shown = true;
            break;
        }
    }
    assert!(shown, "no hover text over cell (1, 6)");
    for pressed in [true, false] {
        h.event(eframe::egui::Event::PointerButton {
            pos,
            button: eframe::egui::PointerButton::Primary,
            pressed,
            modifiers: Default::default(),
        });
        h.step();
    }
    crate::settle(&mut h, 2);
    assert_eq!(h.state().scene.columns[0].project, (1, 6));
    let cube = h.state().scene.columns[0]
        .pattern
        .generate_cube(256, 8, 3, &Cancel::never())
        .unwrap();
    let shown = h.state().data[0]
        .get::<samplescope::model::PointsData>()
        .data()
        .unwrap()
        .points
        .clone();
    assert_eq!(shown, cube.project(1, 6).unwrap());
    // A click outside the triangle changes nothing.
    let below = at(5, 5);
    h.hover_at(below);
    for pressed in [true, false] {
        h.event(eframe::egui::Event::PointerButton {
            pos: below,
            button: eframe::egui::PointerButton::Primary,
            pressed,
            modifiers: Default::default(),
        });
        h.step();
    }
    h.run_steps(2);
    assert_eq!(h.state().scene.columns[0].project, (1, 6));
}
