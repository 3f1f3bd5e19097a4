//! The real UI driven by its labels (egui_kittest, wgpu renderer on Mesa lavapipe/llvmpipe).
//! These tests need a wgpu adapter; without one they fail (they never skip).

use eframe::egui::accesskit::Role;
use egui_kittest::kittest::Queryable;
use egui_kittest::Harness;
use samplescope::scene::graph::NodeKind;
use samplescope::ui::SamplescopeApp;
use std::time::{Duration, Instant};

fn harness() -> Harness<'static, SamplescopeApp> {
    let mut h = Harness::builder()
        .with_size(eframe::egui::Vec2::new(1400.0, 1000.0))
        .wgpu()
        .build_eframe(|cc| {
            let mut app = crate::hermetic_app(cc);
            app.view.show_timings = false;
            app
        });
    crate::settle(&mut h, 2);
    h
}

#[test]
fn default_scene_shows_four_panels_for_one_column() {
    let h = harness();
    let app = h.state();
    assert_eq!(app.scene.columns.len(), 1);
    let col = &app.results[0];
    for kind in [
        NodeKind::Points,
        NodeKind::Spectrum,
        NodeKind::Reconstruction,
        NodeKind::Response,
    ] {
        let r = col.get(&kind).unwrap_or_else(|| panic!("{kind:?} missing"));
        assert!(r.value.is_ok(), "{kind:?}: {:?}", r.value.as_ref().err());
    }
    h.get_by_role_and_label(Role::ComboBox, "Pattern");
    h.get_by_label("Add column");
}

#[test]
fn add_column_by_button_and_equal_inputs_share_one_evaluation() {
    let mut h = harness();
    let before = h.state().engine.evaluator().count(NodeKind::Response);
    h.get_by_label("Add column").click();
    crate::settle(&mut h, 2);
    let app = h.state();
    assert_eq!(app.scene.columns.len(), 2);
    assert_eq!(app.results.len(), 2);
    // The filter is shared: its response was computed once for both columns.
    assert_eq!(app.engine.evaluator().count(NodeKind::Response), before);
    // The new column has a new seed: new points.
    assert!(app.engine.evaluator().count(NodeKind::Points) >= 2);
}

#[test]
fn hiding_the_spectrum_panel_stops_spectrum_work() {
    let mut h = harness();
    h.get_by_label("Spectrum (F2)").click();
    crate::settle(&mut h, 2);
    assert!(!h.state().scene.panels.spectrum);
    let spectra = h.state().engine.evaluator().count(NodeKind::Spectrum);
    // Change N: points and reconstruction recompute, the hidden spectrum does not.
    h.get_by_role_and_label(Role::Slider, "N")
        .set_value_accesskit(1000.0);
    crate::settle(&mut h, 2);
    let app = h.state();
    assert_eq!(app.scene.n, 1000);
    assert_eq!(app.engine.evaluator().count(NodeKind::Spectrum), spectra);
    assert!(app.engine.evaluator().count(NodeKind::Points) >= 2);
}

#[test]
fn dragging_n_updates_every_panel() {
    let mut h = harness();
    h.get_by_role_and_label(Role::Slider, "N")
        .set_value_accesskit(256.0);
    crate::settle(&mut h, 2);
    let app = h.state();
    assert_eq!(app.scene.n, 256);
    match &app.results[0][&NodeKind::Points].value {
        Ok(samplescope::scene::graph::NodeValue::Points(p)) => assert_eq!(p.points.len(), 256),
        other => panic!("{other:?}"),
    }
}

#[test]
fn changing_the_pattern_through_the_combo_box() {
    let mut h = harness();
    h.get_by_role_and_label(Role::ComboBox, "Pattern").click();
    h.run_steps(2);
    h.get_by_label("halton").click_accesskit();
    h.run_steps(2);
    crate::settle(&mut h, 2);
    assert_eq!(h.state().scene.columns[0].pattern.name(), "halton");
    // The filter did not change: no new response evaluation.
    assert_eq!(h.state().engine.evaluator().count(NodeKind::Response), 1);
}

#[test]
fn snapshot_default_scene() {
    let mut h = harness();
    h.snapshot("default_scene");
}

#[test]
fn lecture_mode_switches_theme_and_zoom_without_recomputing() {
    let mut h = harness();
    let before = h.state().engine.evaluator().counts();
    assert!(!h.state().view.lecture);
    h.get_by_label("Lecture mode").click();
    h.run_steps(3);
    let app = h.state();
    assert!(app.view.lecture);
    assert_eq!(
        h.ctx.theme(),
        eframe::egui::Theme::Light,
        "lecture mode uses the light theme"
    );
    assert!(!h.ctx.global_style().visuals.dark_mode);
    let zoom = h.ctx.zoom_factor();
    assert!(
        (zoom - app.view.lecture_scale).abs() < 1e-6,
        "zoom {zoom} vs scale {}",
        app.view.lecture_scale
    );
    // Presentation only: no node was evaluated again.
    assert_eq!(app.engine.evaluator().counts(), before);
    // The controls can be hidden and shown again.
    h.get_by_label("Hide controls").click();
    h.run_steps(2);
    assert!(h.state().view.controls_hidden);
    assert!(h.query_by_role_and_label(Role::Slider, "N").is_none());
    h.get_by_label("Show controls").click();
    h.run_steps(2);
    assert!(h.query_by_role_and_label(Role::Slider, "N").is_some());
    // Leaving lecture mode restores zoom 1.
    h.get_by_label("Lecture mode").click();
    h.run_steps(3);
    assert!((h.ctx.zoom_factor() - 1.0).abs() < 1e-6);
}

#[test]
fn save_menu_writes_the_panel_figure_with_scene_pattern_n_and_seed_in_its_name() {
    let mut h = harness();
    let dir = std::env::temp_dir().join(format!("samplescope-ui-figures-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    h.state_mut().view.figure_dir = dir.display().to_string();
    // The first "Save" menu is the pattern panel's.
    h.get_all_by_label("Save")
        .next()
        .expect("a Save menu")
        .click();
    h.run_steps(2);
    h.get_by_label("PNG 2×").click();
    let deadline = Instant::now() + Duration::from_secs(60);
    while h.state().saver.busy() || h.state().saver.status.is_none() {
        h.step();
        std::thread::sleep(Duration::from_millis(10));
        assert!(Instant::now() < deadline, "figure not written");
    }
    let status = h.state().saver.status.clone().unwrap();
    assert!(status.starts_with("saved "), "{status}");
    let path = dir.join("default_jitter_n4096_seed1_pattern@2x.png");
    let bytes =
        std::fs::read(&path).unwrap_or_else(|e| panic!("{}: {e} ({status})", path.display()));
    let decoder = png::Decoder::new(std::io::Cursor::new(bytes));
    let reader = decoder.read_info().unwrap();
    let (w, h2) = (reader.info().width, reader.info().height);
    let (bw, bh) = samplescope::export::figure::base_size(samplescope::model::FigureKind::Pattern);
    assert_eq!((w, h2), (2 * bw, 2 * bh));
    let text: Vec<_> = reader
        .info()
        .uncompressed_latin1_text
        .iter()
        .map(|t| format!("{}={}", t.keyword, t.text))
        .collect();
    assert!(text.iter().any(|t| t.contains("jitter")), "{text:?}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// Steps until the figure saver reports, and returns its status line.
fn saved(h: &mut Harness<'static, SamplescopeApp>) -> String {
    let deadline = Instant::now() + Duration::from_secs(60);
    while h.state().saver.busy() || h.state().saver.status.is_none() {
        h.step();
        std::thread::sleep(Duration::from_millis(10));
        assert!(Instant::now() < deadline, "figure not written");
    }
    h.state().saver.status.clone().unwrap_or_default()
}

#[test]
fn ctrl_s_saves_the_panel_under_the_pointer() {
    use eframe::egui::{Key, Modifiers};
    let mut h = harness();
    let dir = std::env::temp_dir().join(format!("samplescope-ui-ctrl-s-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    h.state_mut().view.figure_dir = dir.display().to_string();
    // Over the spectrum panel: its figure at the figure scale (2×).
    h.get_by_label_contains("Periodogram").hover();
    h.run_steps(2);
    h.key_press_modifiers(Modifiers::COMMAND, Key::S);
    h.step();
    let status = saved(&mut h);
    let path = dir.join("default_jitter_n4096_seed1_spectrum@2x.png");
    assert!(path.exists(), "{} ({status})", path.display());
    // The zone plate's figure follows the image it shows.
    h.get_by_label("error").click();
    h.run_steps(2);
    h.get_by_label("error").hover();
    h.run_steps(2);
    h.key_press_modifiers(Modifiers::COMMAND, Key::S);
    h.step();
    let status = saved(&mut h);
    assert!(
        status.contains("error@2x.png"),
        "the error figure, not the reconstruction: {status}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_figure_saved_during_a_recompute_has_labels_and_pixels_of_one_scene() {
    use samplescope::model::FigureKind;
    use samplescope::ui::figures::{Done, Output, Request, Target};
    let mut h = harness();
    // A slow recompute: 64 spectrum realizations and a new N.
    h.state_mut().scene.spectrum.realizations = 64;
    h.state_mut().scene.n = 1000;
    h.step();
    let check = |app: &SamplescopeApp, when: &str| {
        let snap = app.figure_snapshot();
        let points = snap.columns[0]
            .points
            .data()
            .expect("points in the snapshot");
        assert_eq!(
            snap.scene.n,
            points.points.len(),
            "{when}: the labels' N and the drawn points differ"
        );
        snap
    };
    let mut mid = false;
    for _ in 0..200 {
        h.step();
        let app = h.state();
        if app.engine.is_idle() {
            break;
        }
        // Mid-recompute (the new points may be on screen already): the saved figure is the
        // last complete picture, N = 4096 with 4096 points.
        let snap = check(app, "during the recompute");
        mid |= snap.scene.n == 4096;
        let dir = std::env::temp_dir().join(format!("samplescope-ui-mid-{}", std::process::id()));
        let req = Request {
            target: Target::Panel {
                column: 0,
                kind: FigureKind::Pattern,
            },
            output: Output::Png { scale: 1 },
        };
        match snap.run(req, &dir) {
            Done::Written(p) => {
                let name = p.file_name().unwrap().to_string_lossy().into_owned();
                assert!(name.contains(&format!("_n{}_", snap.scene.n)), "{name}");
            }
            Done::Failed(e) => panic!("{e}"),
            Done::Clipboard(..) => panic!("not a file"),
        }
        let _ = std::fs::remove_dir_all(&dir);
        std::thread::sleep(Duration::from_millis(10));
    }
    assert!(mid, "never saw the recompute in flight");
    crate::settle(&mut h, 2);
    let snap = check(h.state(), "after the recompute");
    assert_eq!(snap.scene.n, 1000);
}

#[test]
fn a_dead_engine_shows_a_banner() {
    let mut h = harness();
    h.state().engine.crash_for_test();
    h.state_mut().scene.n = 777;
    for _ in 0..50 {
        h.step();
        if h.state().engine.failure().is_some() {
            break;
        }
        std::thread::sleep(Duration::from_millis(10));
    }
    h.run_steps(2);
    assert!(h.state().engine.failure().is_some());
    h.get_by_label_contains("compute engine stopped");
}

#[test]
fn the_hammersley_scene_draws_a_sphere_per_column_that_dragging_turns() {
    let mut h = harness();
    let text = samplescope::scene::BUILTIN
        .iter()
        .find(|(name, _)| name.starts_with("hammersley-p1"))
        .map(|(_, t)| *t)
        .expect("the hammersley-p1 scene is built in");
    let scene = samplescope::scene::Scene::from_ron(text, "hammersley-p1").unwrap();
    h.state_mut().set_scene(scene, "hammersley-p1".into());
    crate::settle(&mut h, 3);
    assert!(h.state().scene.panels.sphere);
    let views: Vec<_> = h.get_all_by_label("sphere view").collect();
    assert_eq!(views.len(), 5, "one sphere per column");
    let rect = views[0].rect();
    drop(views);
    let before = h.get_all_by_label_contains("azimuth 30°").count();
    assert_eq!(before, 5, "every column starts at the front view");
    // Drag the first sphere 60 points to the right: all turn together by 0.6 rad (34°).
    let start = rect.center();
    h.hover_at(start);
    h.event(eframe::egui::Event::PointerButton {
        pos: start,
        button: eframe::egui::PointerButton::Primary,
        pressed: true,
        modifiers: Default::default(),
    });
    h.step();
    for i in 1..=6 {
        h.hover_at(start + eframe::egui::vec2(10.0 * i as f32, 0.0));
        h.step();
    }
    h.event(eframe::egui::Event::PointerButton {
        pos: start + eframe::egui::vec2(60.0, 0.0),
        button: eframe::egui::PointerButton::Primary,
        pressed: false,
        modifiers: Default::default(),
    });
    h.step();
    h.step();
    assert_eq!(h.query_all_by_label_contains("azimuth 30°").count(), 0);
    let after: std::collections::BTreeSet<Option<String>> = h
        .get_all_by_label_contains("azimuth ")
        .map(|n| n.value())
        .collect();
    assert_eq!(after.len(), 1, "the columns turn together: {after:?}");
    // Only the points were computed: the sphere needs no node of its own.
    let app = h.state();
    assert!(app
        .results
        .iter()
        .all(|c| c.get(&NodeKind::Points).is_some()));
}
