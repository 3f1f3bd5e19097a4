//! Importing point files into a column: from the command line (`--points FILE`) and by
//! dragging a file onto a column.
//!
//! A file dropped on the window goes to the column under the pointer (the columns' rectangles
//! as last drawn; a drop outside them goes to the nearest one).
//! When the file cannot be used, the message (naming the line) stays on screen with a
//! "Normalise to bounding box" button when the problem is a point outside [0,1)², which
//! retries the same file with the bounding-box normalisation.

use super::app::SamplescopeApp;
use crate::core::pointset::PointsFileError;
use crate::scene::ImportedPoints;
use eframe::egui;
use std::path::{Path, PathBuf};

/// A point file that could not be imported, kept for the error line and the retry button.
#[derive(Debug, Clone, PartialEq)]
pub struct ImportFailure {
    /// The column it was meant for (0-based).
    pub column: usize,
    /// The file.
    pub path: PathBuf,
    /// The error (names the line).
    pub error: PointsFileError,
}

impl SamplescopeApp {
    /// Shows the points of `path` in `column` (0-based; a column is added when it is the next
    /// one). On error the current scene stays and the failure is shown.
    pub fn import_points(&mut self, column: usize, path: &Path, normalize: bool) {
        match ImportedPoints::from_file(path, normalize) {
            Ok(imp) => {
                if column == self.scene.columns.len() {
                    self.add_column();
                }
                let Some(col) = self.scene.columns.get_mut(column) else {
                    return;
                };
                if imp.points.len() > crate::scene::MAX_SCENE_N {
                    self.scene_error = Some(format!(
                        "{}: {} points; a column shows at most {}",
                        path.display(),
                        imp.points.len(),
                        crate::scene::MAX_SCENE_N
                    ));
                    return;
                }
                col.label = String::new();
                col.points = Some(imp);
                self.import_failure = None;
            }
            Err(error) => {
                self.import_failure = Some(ImportFailure {
                    column,
                    path: path.to_path_buf(),
                    error,
                });
            }
        }
    }

    /// The column under `x`: the one whose rectangle (as drawn in the last frame) spans `x`,
    /// else the nearest one; before any column was drawn, columns split `central` equally.
    pub fn column_at(&self, central: egui::Rect, x: f32) -> usize {
        let n = self.scene.columns.len().max(1);
        if self.column_rects.len() == n {
            let distance = |r: &egui::Rect| {
                if x < r.left() {
                    r.left() - x
                } else if x > r.right() {
                    x - r.right()
                } else {
                    0.0
                }
            };
            return self
                .column_rects
                .iter()
                .enumerate()
                .min_by(|a, b| distance(a.1).total_cmp(&distance(b.1)))
                .map_or(0, |(i, _)| i);
        }
        let f = ((x - central.left()) / central.width().max(1.0)).clamp(0.0, 0.999_999);
        ((f * n as f32) as usize).min(n - 1)
    }

    /// Handles files hovering over and dropped onto the window: a hint while hovering, an
    /// import into the column under the pointer on drop.
    pub fn handle_file_drops(&mut self, ctx: &egui::Context, central: egui::Rect) {
        let (hovered, dropped, pointer) = ctx.input(|i| {
            (
                !i.raw.hovered_files.is_empty(),
                i.raw.dropped_files.clone(),
                i.pointer.hover_pos().or(i.pointer.interact_pos()),
            )
        });
        if hovered {
            let column = pointer.map_or(0, |p| self.column_at(central, p.x));
            let painter = ctx.layer_painter(egui::LayerId::new(
                egui::Order::Foreground,
                egui::Id::unique("samplescope-drop-hint"),
            ));
            let rect = match self.column_rects.get(column) {
                Some(r) if self.column_rects.len() == self.scene.columns.len() => {
                    egui::Rect::from_x_y_ranges(r.x_range(), central.y_range())
                }
                _ => {
                    let n = self.scene.columns.len().max(1) as f32;
                    let w = central.width() / n;
                    egui::Rect::from_min_size(
                        egui::pos2(central.left() + w * column as f32, central.top()),
                        egui::vec2(w, central.height()),
                    )
                }
            };
            painter.rect_filled(rect, 4.0, egui::Color32::from_black_alpha(120));
            painter.text(
                rect.center(),
                egui::Align2::CENTER_CENTER,
                format!(
                    "Drop a point file (CSV or x y text) on column {}",
                    column + 1
                ),
                egui::FontId::proportional(18.0),
                egui::Color32::WHITE,
            );
        }
        for file in dropped {
            let path = file.path().to_path_buf();
            let column = pointer.map_or(0, |p| self.column_at(central, p.x));
            self.import_points(column, &path, false);
        }
    }

    /// The last import failure, with the retry button when normalising would help.
    pub fn import_failure_ui(&mut self, ui: &mut egui::Ui) {
        let Some(f) = self.import_failure.clone() else {
            return;
        };
        ui.horizontal_wrapped(|ui| {
            ui.colored_label(
                egui::Color32::from_rgb(200, 40, 40),
                format!("Column {}: {}: {}", f.column + 1, f.path.display(), f.error),
            );
            if matches!(f.error, PointsFileError::OutOfRange { .. })
                && ui
                    .button("Normalise to bounding box")
                    .on_hover_text(
                        "Map the points' bounding box onto [0,1)², keeping the aspect ratio",
                    )
                    .clicked()
            {
                self.import_points(f.column, &f.path, true);
            }
            if ui.small_button("Dismiss").clicked() {
                self.import_failure = None;
            }
        });
    }
}

/// For a column showing imported points: where they come from, and a button that goes back to
/// the column's pattern (drawn above the pattern controls, which apply again after it).
pub fn imported_column_ui(ui: &mut egui::Ui, column: &mut crate::scene::Column) {
    let Some(imp) = &column.points else {
        return;
    };
    let text = format!(
        "Imported: {} ({} points{})",
        imp.label(),
        imp.points.len(),
        if imp.normalize { ", normalised" } else { "" }
    );
    ui.horizontal_wrapped(|ui| {
        ui.label(text);
        if ui
            .small_button("Use the pattern")
            .on_hover_text("Drop the imported points and show the pattern below")
            .clicked()
        {
            column.points = None;
        }
    });
}
