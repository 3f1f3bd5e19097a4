//! The eframe GUI: columns of four live panels (pattern, spectrum, zone plate, filter), a cost
//! view, and the controls. Panels only draw plain data computed by the engine; no maths here.

pub mod app;
pub mod gpu;
pub mod panels;
pub mod theorem;

pub use app::SamplescopeApp;

/// Window title.
pub const APP_NAME: &str = "samplescope";

/// Opens the GUI window (blocking until it closes).
pub fn run_gui(scene_path: Option<std::path::PathBuf>) -> Result<(), String> {
    let options = eframe::NativeOptions {
        viewport: eframe::egui::ViewportBuilder::default()
            .with_inner_size([1500.0, 950.0])
            .with_title(APP_NAME),
        renderer: eframe::Renderer::Wgpu,
        ..Default::default()
    };
    eframe::run_native(
        APP_NAME,
        options,
        Box::new(move |cc| Ok(Box::new(SamplescopeApp::new(cc, scene_path.as_deref())))),
    )
    .map_err(|e| e.to_string())
}
