//! The eframe GUI: columns of live panels (pattern, spectrum, zone plate, filter), the cost and
//! sampling-theorem views below them, and the controls. Panels only draw plain data computed by
//! the engine; no maths here.
//!
//! # Layering
//!
//! Each line may import the lines below it, never one above, so there is no import circle
//! (`panels/mod.rs` declares the panel files but imports none of them; `columns` makes them):
//!
//! ```text
//! app                  SamplescopeApp: owns the state, lends it to everything below
//! dropped, playback    components owning their state: point import, motion playback
//! columns              the panel of each row of the panel table (make), the column grid
//!                      (the column panels, each column's rectangle), add_column
//! lecture              lecture-mode style
//! panels/<name>        one panel each: a struct implementing panels::Panel, reading a PanelCx
//! panels (mod.rs)      the Panel trait and PanelCx
//! widgets/             image view (texture cache), parameter editors, status labels
//! figures, animated     figure requests (the outbox lent to panels), the background saver;
//!                      the animated GIF's saver (engine::animation, progress, cancel)
//! view, results        shared display state; the engine's results as the UI holds them (the one
//!                      decoder of the graph's values: panels get plain `model` data, `Slot`)
//! gpu                  the wgpu display pipelines
//! ```
//!
//! A panel reaches the app's state only through [`panels::PanelCx`]; components get what they
//! need as arguments. The state of a frame (figure requests, where panels were drawn, whether
//! wall times are shown) travels in that context, not in egui's temporary data.

pub mod animated;
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

/// The window's size on a first run where the monitor's is not known (later runs open at the
/// size and state of the last, which eframe stores with the app's state).
pub const FIRST_WINDOW_SIZE: [f32; 2] = [1600.0, 1000.0];

/// How the window starts: the scene, a point file for column 1, lecture mode.
#[derive(Debug, Clone, Default)]
pub struct Start {
    /// The scene file to open (else the last scene, else the default one).
    pub scene: Option<std::path::PathBuf>,
    /// A point file shown in column 1: (file, normalise to the bounding box).
    pub points: Option<(std::path::PathBuf, bool)>,
    /// Start in lecture mode with the controls hidden, full screen where the window system
    /// allows (`--lecture`).
    pub lecture: bool,
}

/// Opens the GUI window (blocking until it closes).
pub fn run_gui(scene_path: Option<std::path::PathBuf>) -> Result<(), String> {
    run(Start {
        scene: scene_path,
        ..Start::default()
    })
}

/// Opens the GUI window as `start` says. A point file that cannot be used is reported in the
/// window. The window opens maximized on a first run (and at the monitor's size where the
/// window system does not maximize, [`SamplescopeApp::new`]); later runs restore the last
/// size and state, stored by eframe with the app's state (on Linux
/// `$XDG_DATA_HOME/samplescope/app.ron`, by default `~/.local/share/samplescope/app.ron`).
pub fn run(start: Start) -> Result<(), String> {
    let Start {
        scene: scene_path,
        points,
        lecture,
    } = start;
    if cfg!(target_os = "linux")
        && ["DISPLAY", "WAYLAND_DISPLAY", "WAYLAND_SOCKET"]
            .iter()
            .all(|v| std::env::var_os(v).is_none_or(|s| s.is_empty()))
    {
        return Err(NO_DISPLAY.into());
    }
    let options = eframe::NativeOptions {
        viewport: eframe::egui::ViewportBuilder::default()
            .with_inner_size(FIRST_WINDOW_SIZE)
            .with_maximized(true)
            .with_fullscreen(lecture)
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
            if lecture {
                app.start_lecture();
            }
            if let Some((path, normalize)) = &points {
                app.import_points(0, path, *normalize);
            }
            Ok(Box::new(app))
        }),
    )
    .map_err(|e| describe_start_error(&e.to_string()))
}

/// Why the window cannot open on a machine without a display.
const NO_DISPLAY: &str = "no display: DISPLAY and WAYLAND_DISPLAY are unset; run it in a desktop \
     session, or on a virtual X display (package xvfb): `Xvfb :99 &` then `DISPLAY=:99 samplescope`";

/// One line naming what is missing when eframe cannot start: a graphics driver for wgpu, or
/// the display; other errors as eframe gives them.
fn describe_start_error(e: &str) -> String {
    let lower = e.to_ascii_lowercase();
    if lower.contains("wgpu") || lower.contains("adapter") || lower.contains("surface") {
        format!(
            "no Vulkan or OpenGL driver that wgpu can use ({e}); install your GPU's driver, or \
             Mesa's software ones: apt-get install mesa-vulkan-drivers libvulkan1 libegl1 libgl1-mesa-dri"
        )
    } else if lower.contains("display") {
        format!("{NO_DISPLAY} ({e})")
    } else {
        e.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::describe_start_error;

    #[test]
    fn start_errors_name_what_is_missing_on_one_line() {
        let e = describe_start_error(
            "WGPU error: Failed to create surface for any enabled backend: {}",
        );
        assert!(
            e.contains("mesa-vulkan-drivers") && !e.contains('\n'),
            "{e}"
        );
        let e = describe_start_error(
            "winit EventLoopError: neither WAYLAND_DISPLAY nor DISPLAY is set.",
        );
        assert!(e.contains("xvfb") && !e.contains('\n'), "{e}");
        assert_eq!(describe_start_error("something else"), "something else");
    }
}
