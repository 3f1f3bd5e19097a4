//! The projection-matrix panel: the column's first K dimensions as a triangle of small scatter
//! plots tinted by a measure (`model::MatrixData::picture_sized`, drawn at its size on screen),
//! with its K and measure controls, a
//! colour bar, each cell's values on hover, and a click that shows that pair in the column's
//! panels (it sets the column's `project`).

use super::{Panel, PanelCx};
use crate::core::format::significant;
use crate::core::metrics::cube::{ProjectionMeasure, ProjectionRow};
use crate::model::{Colormap, MatrixData, Slot};
use crate::scene::panels::PanelKind;
use crate::ui::widgets::params::setting_ui;
use crate::ui::widgets::status::{error_label, time_label};
use eframe::egui::{self, Color32, Stroke};
use eframe::emath::GuiRounding as _;
use std::sync::Arc;

/// The projection-matrix panel: the texture of the last picture drawn and what it shows.
#[derive(Default)]
pub struct MatrixPanel {
    texture: Option<(PictureKey, egui::TextureHandle)>,
}

/// What a picture was drawn from: the data (by address), the measure and the colour map.
/// The data, measure, colour map and size in pixels a texture was drawn for.
type PictureKey = (usize, ProjectionMeasure, Colormap, (usize, usize));

impl std::fmt::Debug for MatrixPanel {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("MatrixPanel").finish_non_exhaustive()
    }
}

/// One row's values as text (the hover text and the figure's table share the digits).
pub fn row_text(r: &ProjectionRow) -> String {
    let t = r
        .t_value
        .map_or("t: — (N not 2^m)".to_string(), |t| format!("t = {t}"));
    let md = r
        .min_distance
        .map_or("—".to_string(), |m| significant(m, 4));
    format!(
        "{t} · L2* = {} · min dist = {md}",
        significant(r.l2_star_discrepancy, 4)
    )
}

impl Panel for MatrixPanel {
    fn kind(&self) -> PanelKind {
        PanelKind::Matrix
    }

    fn ui(&mut self, ui: &mut egui::Ui, cx: &mut PanelCx<'_>) {
        let (ci, side) = (cx.column, cx.cell.side);
        ui.horizontal_wrapped(|ui| {
            ui.label("Projection matrix");
            cx.figures.panel_menu_ui(ui, ci, PanelKind::Matrix);
        });
        ui.horizontal_wrapped(|ui| {
            setting_ui(ui, &mut cx.scene.matrix, "dims", "K");
            setting_ui(ui, &mut cx.scene.matrix, "measure", "tint");
        });
        let (status, data) = match cx.get::<MatrixData>() {
            Slot::Ready { status, data } => (status, data),
            Slot::Failed { error, .. } => {
                error_label(ui, "projection matrix", &error);
                return;
            }
            Slot::Missing => {
                ui.spinner();
                return;
            }
        };
        let measure = cx.scene.matrix.measure;
        let colormap = cx.view.colormap;
        let (rect, response) = ui.allocate_exact_size(egui::vec2(side, side), egui::Sense::click());
        response.widget_info(|| {
            egui::WidgetInfo::labeled(egui::Role::Image, true, "projection matrix")
        });
        // Drawn at the pixels it covers on screen, never scaled: the gaps between cells stay
        // even whole pixels at every size.
        let ppp = ui.ctx().pixels_per_point();
        let shown = rect.round_to_pixels(ppp);
        let px = (
            ((shown.width() * ppp).round() as usize).max(1),
            ((shown.height() * ppp).round() as usize).max(1),
        );
        let key = (Arc::as_ptr(&data) as usize, measure, colormap, px);
        if self.texture.as_ref().is_none_or(|(k, _)| *k != key) {
            let (w, h, rgb) = data.picture_sized(measure, colormap, px);
            let image = egui::ColorImage::from_rgb([w, h], &rgb);
            let tex =
                ui.ctx()
                    .load_texture(format!("matrix-{ci}"), image, egui::TextureOptions::NEAREST);
            self.texture = Some((key, tex));
        }
        let Some((_, tex)) = &self.texture else {
            return;
        };
        let painter = ui.painter_at(rect);
        painter.image(
            tex.id(),
            shown,
            egui::Rect::from_min_max(egui::pos2(0.0, 0.0), egui::pos2(1.0, 1.0)),
            Color32::WHITE,
        );
        let to_screen = |x: usize, y: usize| shown.min + egui::vec2(x as f32, y as f32) / ppp;
        // The pair the column's panels show, outlined.
        let col = &cx.scene.columns[ci];
        let (i, j) = col.project;
        let (a, b) = (i.min(j), i.max(j));
        if let Some(cell) = data.cell(a, b) {
            let [x0, y0, w, h] = data.cell_rect(cell.pair, px);
            let r = egui::Rect::from_min_max(to_screen(x0, y0), to_screen(x0 + w, y0 + h));
            painter.rect_stroke(
                r.expand(1.0),
                0.0,
                Stroke::new(2.5, Color32::from_rgb(230, 40, 40)),
                egui::StrokeKind::Outside,
            );
        }
        // A cell under the pointer: its values, and a click shows its pair.
        let hovered = response.hover_pos().and_then(|p| {
            let q = (p - shown.min) * ppp;
            (q.x >= 0.0 && q.y >= 0.0)
                .then(|| data.cell_at_pixel((q.x as usize, q.y as usize), px))
                .flatten()
        });
        if let Some(cell) = hovered {
            let [i, j] = cell.pair;
            let text = match &cell.row {
                Some(r) => format!("x{i} × x{j}: {}", row_text(r)),
                None => format!("x{i} × x{j}: measuring…"),
            };
            let response = response.on_hover_text(format!("{text}\nclick: show this pair"));
            if response.clicked() {
                cx.scene.columns[ci].project = (i, j);
            }
        }
        colour_bar(ui, &data, measure, colormap, side);
        time_label(ui, &status, cx.view.show_timings);
    }
}

/// The measure's colour bar under the matrix: the gradient and its two ends.
fn colour_bar(
    ui: &mut egui::Ui,
    data: &MatrixData,
    measure: ProjectionMeasure,
    colormap: Colormap,
    width: f32,
) {
    let Some((lo, hi)) = data.range(measure) else {
        ui.small(format!(
            "{}: no values (N not a power of two?)",
            measure.label()
        ));
        return;
    };
    let (rect, _) = ui.allocate_exact_size(egui::vec2(width, 10.0), egui::Sense::hover());
    let painter = ui.painter_at(rect);
    let steps = 64;
    for s in 0..steps {
        let t = (s as f64 + 0.5) / steps as f64;
        let [r, g, b] = colormap.eval(t);
        let x0 = rect.left() + rect.width() * s as f32 / steps as f32;
        let x1 = rect.left() + rect.width() * (s + 1) as f32 / steps as f32;
        painter.rect_filled(
            egui::Rect::from_x_y_ranges(x0..=x1 + 0.5, rect.y_range()),
            0.0,
            Color32::from_rgb(r, g, b),
        );
    }
    ui.small(format!(
        "{}: {} … {}",
        measure.label(),
        significant(lo, 3),
        significant(hi, 3)
    ));
}
