//! Importing point files into a column: from the command line (`--points FILE`) and by
//! dragging a file onto a column.
//!
//! A file dropped on the window goes to the column under the pointer (the columns' rectangles
//! as last drawn; a drop outside them goes to the nearest one).
//! When the file cannot be used, the message (naming the line) stays on screen with a
//! "Normalise to bounding box" button when the problem is a point outside [0,1)², which
//! retries the same file with the bounding-box normalisation.

use super::columns::add_column;
use crate::core::pointset::PointsFileError;
use crate::scene::{ImportedPoints, Scene};
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

/// Importing point files into columns: owns the last failure, shown with its retry button.
#[derive(Debug, Default)]
pub struct PointImport {
    failure: Option<ImportFailure>,
}

impl PointImport {
    /// Shows the points of `path` in `column` of `scene` (0-based; a column is added when it is
    /// the next one). A file that cannot be read leaves the scene as it is and becomes the
    /// failure [`PointImport::failure_ui`] shows. `Err` carries the message for the scene's
    /// error line when the file holds more points than a column shows.
    pub fn import(
        &mut self,
        scene: &mut Scene,
        column: usize,
        path: &Path,
        normalize: bool,
    ) -> Result<(), String> {
        match ImportedPoints::from_file(path, normalize) {
            Ok(imp) => {
                if column == scene.columns.len() {
                    add_column(scene);
                }
                let Some(col) = scene.columns.get_mut(column) else {
                    return Ok(());
                };
                if imp.points.len() > crate::scene::MAX_SCENE_N {
                    return Err(format!(
                        "{}: {} points; a column shows at most {}",
                        path.display(),
                        imp.points.len(),
                        crate::scene::MAX_SCENE_N
                    ));
                }
                col.label = String::new();
                col.points = Some(imp);
                self.failure = None;
            }
            Err(error) => {
                self.failure = Some(ImportFailure {
                    column,
                    path: path.to_path_buf(),
                    error,
                });
            }
        }
        Ok(())
    }

    /// Handles files hovering over and dropped onto the window: a hint over the column under
    /// the pointer while hovering, an import into it on drop. `central` is the area of the
    /// columns, `column_rects` the columns as drawn in the last frame. `Err` as for
    /// [`PointImport::import`] (the last such message when several files are dropped).
    pub fn drops_ui(
        &mut self,
        ctx: &egui::Context,
        central: egui::Rect,
        column_rects: &[egui::Rect],
        scene: &mut Scene,
    ) -> Result<(), String> {
        let (hovered, dropped, pointer) = ctx.input(|i| {
            (
                !i.raw.hovered_files.is_empty(),
                i.raw.dropped_files.clone(),
                i.pointer.hover_pos().or(i.pointer.interact_pos()),
            )
        });
        let ncols = scene.columns.len();
        let target = |x: f32| column_at(column_rects, ncols, central, x);
        if hovered {
            let column = pointer.map_or(0, |p| target(p.x));
            let painter = ctx.layer_painter(egui::LayerId::new(
                egui::Order::Foreground,
                egui::Id::unique("samplescope-drop-hint"),
            ));
            let rect = match column_rects.get(column) {
                Some(r) if column_rects.len() == ncols => {
                    egui::Rect::from_x_y_ranges(r.x_range(), central.y_range())
                }
                _ => {
                    let n = ncols.max(1) as f32;
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
                    "Drop a point file (CSV, x y text, .npy or .rps) on column {}",
                    column + 1
                ),
                egui::FontId::proportional(18.0),
                egui::Color32::WHITE,
            );
        }
        let mut outcome = Ok(());
        for file in dropped {
            let path = file.path().to_path_buf();
            let column = pointer.map_or(0, |p| target(p.x));
            if let Err(e) = self.import(scene, column, &path, false) {
                outcome = Err(e);
            }
        }
        outcome
    }

    /// The last import failure, with the retry button when normalising would help. `Err` as
    /// for [`PointImport::import`] (from the retry).
    pub fn failure_ui(&mut self, ui: &mut egui::Ui, scene: &mut Scene) -> Result<(), String> {
        let Some(f) = self.failure.clone() else {
            return Ok(());
        };
        let mut outcome = Ok(());
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
                outcome = self.import(scene, f.column, &f.path, true);
            }
            if ui.small_button("Dismiss").clicked() {
                self.failure = None;
            }
        });
        outcome
    }
}

/// The column under `x` among `ncols` columns: the one whose rectangle (as drawn in the last
/// frame) spans `x`, else the nearest one; before every column was drawn, columns split
/// `central` equally.
pub fn column_at(column_rects: &[egui::Rect], ncols: usize, central: egui::Rect, x: f32) -> usize {
    let n = ncols.max(1);
    if column_rects.len() == n {
        let distance = |r: &egui::Rect| {
            if x < r.left() {
                r.left() - x
            } else if x > r.right() {
                x - r.right()
            } else {
                0.0
            }
        };
        return column_rects
            .iter()
            .enumerate()
            .min_by(|a, b| distance(a.1).total_cmp(&distance(b.1)))
            .map_or(0, |(i, _)| i);
    }
    let f = ((x - central.left()) / central.width().max(1.0)).clamp(0.0, 0.999_999);
    ((f * n as f32) as usize).min(n - 1)
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
