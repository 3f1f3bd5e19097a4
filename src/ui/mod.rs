//! The eframe GUI: columns of live panels (pattern, spectrum, zone plate, filter), the cost and
//! sampling-theorem views below them, and the controls. Panels only draw plain data computed by
//! the engine; no maths here.
//!
//! # Layering
//!
//! Each line may import the lines below it, never one above, so there is no import circle
//! (`panels/mod.rs` declares the panel files but imports none of them):
//!
//! ```text
//! app                  SamplescopeApp: owns the state, lends it to everything below
//! dropped, playback    components owning their state: point import, motion playback
//! columns              the column grid (the column panels, each column's rectangle), add_column
//! lecture              lecture-mode style and letterbox
//! panels/<name>        one panel each: a struct implementing panels::Panel, reading a PanelCx
//! panels (mod.rs)      the Panel trait and PanelCx
//! widgets/             image view (texture cache), parameter editors, status labels
//! figures              figure requests (the outbox lent to panels), the background saver
//! view, results        shared display state; the engine's results as the UI holds them
//! gpu                  the wgpu display pipelines
//! ```
//!
//! A panel reaches the app's state only through [`panels::PanelCx`]; components get what they
//! need as arguments. The state of a frame (figure requests, where panels were drawn, whether
//! wall times are shown) travels in that context, not in egui's temporary data.

pub mod app;
pub mod columns;
pub mod dropped;
pub mod figures;
pub mod gpu;
pub mod lecture;
pub mod panels;
pub mod playback;
pub mod results;
pub mod view;
pub mod widgets;

pub use app::SamplescopeApp;

/// Window title.
pub const APP_NAME: &str = "samplescope";

/// Opens the GUI window (blocking until it closes).
pub fn run_gui(scene_path: Option<std::path::PathBuf>) -> Result<(), String> {
    run_gui_with_points(scene_path, None)
}

/// Opens the GUI window with column 1 showing the points of a file: `points` = (file,
/// normalise to the bounding box). A file that cannot be used is reported in the window.
pub fn run_gui_with_points(
    scene_path: Option<std::path::PathBuf>,
    points: Option<(std::path::PathBuf, bool)>,
) -> Result<(), String> {
    let options = eframe::NativeOptions {
        viewport: eframe::egui::ViewportBuilder::default()
            .with_inner_size([1500.0, 950.0])
            .with_title(APP_NAME)
            .with_drag_and_drop(true),
        renderer: eframe::Renderer::Wgpu,
        ..Default::default()
    };
    eframe::run_native(
        APP_NAME,
        options,
        Box::new(move |cc| {
            let mut app = SamplescopeApp::new(cc, scene_path.as_deref());
            if let Some((path, normalize)) = &points {
                app.import_points(0, path, *normalize);
            }
            Ok(Box::new(app))
        }),
    )
    .map_err(|e| e.to_string())
}
