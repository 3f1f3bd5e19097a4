//! The panels of the panel table placed where their rows say ([`placed`]), and the columns side by side,
//! each a grid of its visible column panels; and adding a column.

use super::panels::{make, Panel, PanelCx};
use crate::model::PointsData;
use crate::scene::panels::{PanelKind, Place};
use crate::scene::{Scene, MAX_COLUMNS};
use eframe::egui::{self, Rect, Vec2};

/// The panels placed at `place`, in table order.
pub fn placed(place: Place) -> Vec<Box<dyn Panel>> {
    PanelKind::ALL
        .into_iter()
        .filter(|k| k.spec().place == place)
        .map(make)
        .collect()
}

/// The column grid: the column panels in the panel table's order, and each column's screen
/// rectangle as last drawn (files dropped on the window go to the column under the pointer).
pub struct Columns {
    panels: Vec<Box<dyn Panel>>,
    rects: Vec<Rect>,
}

impl Default for Columns {
    fn default() -> Self {
        Columns {
            panels: placed(Place::Column),
            rects: Vec::new(),
        }
    }
}

impl Columns {
    /// Each column's screen rectangle in the last frame, in column order.
    pub fn rects(&self) -> &[Rect] {
        &self.rects
    }

    /// Every column side by side, each with its visible panels in a grid sized so that the
    /// panels are as large as they can be. Sets `cx.column` and `cx.side` for each panel.
    pub fn ui(&mut self, ui: &mut egui::Ui, cx: &mut PanelCx<'_>) {
        let Columns { panels, rects } = self;
        rects.clear();
        let ncols = cx.scene.columns.len().max(1);
        let visible = panels
            .iter()
            .filter(|p| p.is_shown(&cx.scene.panels))
            .count()
            .max(1);
        let spacing = ui.spacing().item_spacing.x;
        let width =
            ((ui.available_width() - spacing * (ncols as f32 - 1.0)) / ncols as f32).max(120.0);
        let height = ui.available_height() - 30.0;
        // Panels of a column sit in a grid of `per_row` panels per row; pick the arrangement
        // that gives the largest panels (each panel needs ~110 points below its image for its
        // text and plots).
        let (per_row, side) = [1usize, 2, 4]
            .iter()
            .filter(|&&k| k <= visible)
            .map(|&k| {
                let rows = visible.div_ceil(k) as f32;
                let s = (width / k as f32 - 12.0).min(height / rows - 150.0);
                (k, s)
            })
            .fold((1, 0.0f32), |best, c| if c.1 > best.1 { c } else { best });
        let side = side.max(100.0);
        cx.side = side;
        egui::ScrollArea::both().show(ui, |ui| {
            ui.horizontal_top(|ui| {
                for ci in 0..cx.scene.columns.len() {
                    cx.column = ci;
                    let header = column_header(cx);
                    ui.push_id(ci, |ui| {
                        let shown = ui.allocate_ui(Vec2::new(width, ui.available_height()), |ui| {
                            ui.vertical(|ui| {
                                ui.horizontal(|ui| {
                                    ui.strong(header);
                                    cx.figures.column_menu_ui(ui, ci);
                                });
                                let mut shown: Vec<&mut Box<dyn Panel>> = panels
                                    .iter_mut()
                                    .filter(|p| p.is_shown(&cx.scene.panels))
                                    .collect();
                                for row in shown.chunks_mut(per_row) {
                                    ui.horizontal_top(|ui| {
                                        for panel in row {
                                            // What Ctrl+S over it saves: the figure shown
                                            // when the frame began.
                                            let figure = panel.figure(cx.view);
                                            let drawn = ui
                                                .allocate_ui(Vec2::new(side + 8.0, 10.0), |ui| {
                                                    ui.vertical(|ui| panel.ui(ui, cx))
                                                });
                                            cx.figures.panel_drawn(drawn.response.rect, ci, figure);
                                        }
                                    });
                                }
                            });
                        });
                        rects.push(shown.response.rect);
                    });
                }
            });
        });
    }
}

/// The title of column `cx.column`: its pattern, N, seed (and the pair of dimensions shown of a
/// column in D > 2 dimensions), labelled from the scene its points
/// were computed for (a recompute may be running); an imported set has its own size and no seed.
fn column_header(cx: &PanelCx<'_>) -> String {
    let ci = cx.column;
    let scene: &Scene = cx.scene;
    let Some(column) = scene.columns.get(ci) else {
        return String::new();
    };
    match &column.points {
        Some(p) => format!("{} · N = {}", column.title(), p.points.len()),
        None => {
            let slot = cx.get::<PointsData>();
            let lab = slot
                .status()
                .and_then(crate::ui::results::scene_of)
                .unwrap_or(scene);
            let c = lab.columns.get(ci).unwrap_or(column);
            let projection = if c.is_plain_2d() {
                String::new()
            } else {
                format!(" · x{} × x{} of D = {}", c.project.0, c.project.1, c.dims)
            };
            format!(
                "{} · N = {} · seed {}{projection}",
                c.title(),
                lab.n,
                c.seed
            )
        }
    }
}

/// Adds a column (a copy of the last one with the next seed), up to [`MAX_COLUMNS`].
pub fn add_column(scene: &mut Scene) {
    if scene.columns.len() < MAX_COLUMNS {
        let mut c = scene.columns.last().cloned().unwrap_or_default();
        c.seed = c.seed.wrapping_add(1);
        scene.columns.push(c);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_row_of_the_panel_table_is_made_once_at_its_place() {
        for kind in PanelKind::ALL {
            assert_eq!(make(kind).kind(), kind);
        }
        let columns: Vec<PanelKind> = placed(Place::Column).iter().map(|p| p.kind()).collect();
        let docks: Vec<PanelKind> = placed(Place::Dock).iter().map(|p| p.kind()).collect();
        let mut all = [columns, docks].concat();
        all.sort();
        assert_eq!(all, PanelKind::ALL.to_vec());
    }
}
