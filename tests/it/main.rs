//! All integration tests, as one binary: one link against eframe/wgpu instead of one per file.
//! Each former `tests/<name>.rs` is a module here; `cargo test <module>::` runs one of them.

use samplescope::engine::Engine;
use samplescope::scene::{Scene, BUILTIN};
use samplescope::ui::SamplescopeApp;
use std::sync::Arc;
use std::time::{Duration, Instant};

mod analyze_cube;
mod analyze_scene;
mod animated_gif;
mod bad_input;
mod budget_cli;
mod budget_memory;
mod cli_points;
mod converge;
mod cube_discrepancy;
mod cube_patterns;
mod cube_reader;
mod faults;
mod figures;
mod filter_cli;
mod filter_metrics;
mod filter_numerics;
mod fuzz;
mod import;
mod integration_study;
mod interop;
mod layout;
mod metrics_common;
mod metrics_l2;
mod metrics_min_distance;
mod metrics_published;
mod metrics_star;
mod metrics_statistics;
mod metrics_tvalue;
mod motion;
mod no_clamp;
mod params;
mod patterns_lowdisc;
mod patterns_poisson;
mod patterns_stratified;
mod prefix;
mod progress;
mod projection_matrix;
mod psa;
mod recon_error;
mod recon_grid;
mod recon_kernels;
mod recon_reference;
mod recon_scattered;
mod recon_stability;
mod recon_supersample;
mod render_cli;
mod scene_cost;
mod scene_dims;
mod scene_graph;
mod scenes_all;
mod signal_shapes;
mod signal_zone_plate;
mod slide_figures;
mod spectrum_average;
mod spectrum_exact;
mod spectrum_nufft;
mod spectrum_pair;
mod spectrum_radial;
mod theorem;
mod ui;
mod validation;

/// The GUI app on an engine without a disk cache: UI tests neither read reference images a
/// previous run left in the user's cache nor write there.
pub fn hermetic_app(cc: &eframe::CreationContext<'_>) -> SamplescopeApp {
    let ctx = cc.egui_ctx.clone();
    let engine = Engine::new_in_memory(Arc::new(move || ctx.request_repaint()));
    SamplescopeApp::with_engine(cc, None, engine)
}

/// The GUI (egui_kittest, no rendering: no GPU needed) showing the built-in scene `name`,
/// lightened by `shrink` (smaller images where a test is about the controls), computed and
/// drawn once more.
pub fn builtin_harness(
    name: &str,
    shrink: impl FnOnce(&mut Scene),
) -> egui_kittest::Harness<'static, SamplescopeApp> {
    let (_, text) = BUILTIN
        .iter()
        .find(|(n, _)| *n == name)
        .unwrap_or_else(|| panic!("no built-in scene {name}"));
    let mut scene = Scene::from_ron(text, name).unwrap();
    shrink(&mut scene);
    let mut h = egui_kittest::Harness::builder()
        .with_size(eframe::egui::Vec2::new(1400.0, 1000.0))
        .build_eframe(move |cc| {
            let mut app = hermetic_app(cc);
            app.view.show_timings = false;
            app.set_scene(scene.clone(), name.to_string());
            app
        });
    settle(&mut h, 1);
    h
}

/// Steps the UI until the engine has delivered every node of the current scene, then `extra`
/// more frames (so the last results are drawn).
pub fn settle(h: &mut egui_kittest::Harness<'static, SamplescopeApp>, extra: usize) {
    let deadline = Instant::now() + Duration::from_secs(120);
    loop {
        h.step();
        let app = h.state();
        if app.engine.is_idle() && app.results.len() == app.scene.columns.len() {
            break;
        }
        assert!(Instant::now() < deadline, "engine did not finish");
        std::thread::sleep(Duration::from_millis(5));
    }
    for _ in 0..extra {
        h.step();
    }
}

/// A PNG's text chunks (tEXt and iTXt) as (keyword, text) pairs, in that order.
pub fn png_text(info: &png::Info<'_>) -> Vec<(String, String)> {
    info.uncompressed_latin1_text
        .iter()
        .map(|t| (t.keyword.clone(), t.text.clone()))
        .chain(
            info.utf8_text
                .iter()
                .map(|t| (t.keyword.clone(), t.get_text().expect("UTF-8 text chunk"))),
        )
        .collect()
}

/// A CSV of numbers: its header line and one row of numbers per line after it.
pub fn parse_csv(text: &str) -> (String, Vec<Vec<f64>>) {
    let mut lines = text.lines();
    let header = lines.next().expect("a header line").to_string();
    let rows = lines
        .map(|l| {
            l.split(',')
                .map(|v| v.parse().unwrap_or_else(|e| panic!("{v:?} in {l:?}: {e}")))
                .collect()
        })
        .collect();
    (header, rows)
}

/// Runs `samplescope ARGS` (a `points` command), which must succeed, and parses the CSV it
/// writes ([`parse_csv`]).
pub fn points_csv(args: &[&str]) -> (String, Vec<Vec<f64>>) {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_samplescope"))
        .args(args)
        .output()
        .expect("the binary runs");
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    parse_csv(&String::from_utf8(out.stdout).expect("UTF-8 CSV"))
}
