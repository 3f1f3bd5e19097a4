//! A result's status under its panel: wall time and accuracy, progress while it refines, or
//! the error.

use crate::model::NodeStatus;
use eframe::egui::{self, Color32};

/// The node's wall time (when `show_timings`) and accuracy; while it refines, a progress bar
/// with "refining i/n" and its current error estimate.
pub fn time_label(ui: &mut egui::Ui, r: &NodeStatus, show_timings: bool) {
    if let Some(p) = r.progress {
        let text = match &r.accuracy {
            Some(a) => format!("refining {}/{}, {a}", p.done, p.total),
            None => format!("refining {}/{}", p.done, p.total),
        };
        ui.add(
            egui::ProgressBar::new(p.fraction() as f32)
                .desired_height(4.0)
                .desired_width(ui.available_width().min(260.0)),
        );
        ui.small(text);
        return;
    }
    let mut parts = Vec::new();
    if show_timings {
        parts.push(format!("{:.1} ms", r.wall.as_secs_f64() * 1e3));
    }
    if let Some(a) = &r.accuracy {
        parts.push(a.to_string());
    }
    if !parts.is_empty() {
        ui.small(parts.join(" · "));
    }
}

/// A node's error, in red, prefixed with what failed.
pub fn error_label(ui: &mut egui::Ui, what: &str, e: &dyn std::fmt::Display) {
    ui.colored_label(Color32::from_rgb(200, 40, 40), format!("{what}: {e}"));
}
