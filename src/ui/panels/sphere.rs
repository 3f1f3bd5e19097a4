//! The sphere panel: a column's points wrapped onto the unit sphere (the lecture's cylinder
//! wrap and radial projection, [`crate::core::pattern::sphere`]) in an orthographic view that
//! dragging turns; the far hemisphere's points show through dimmed.

use super::{Panel, PanelCx};
use crate::core::pattern::sphere::{square_to_sphere, OrthoView};
use crate::model::PointsData;
use crate::model::Slot;
use crate::model::{marks, palette};
use crate::scene::panels::PanelKind;
use crate::ui::widgets::status::{error_label, time_label};
use eframe::egui::{self, Color32, Pos2, Sense, Stroke, Vec2};

/// At most this many points are drawn (the first ones); each is one egui circle.
pub const MAX_SPLATS: usize = 20_000;
/// Radians the view turns per point dragged.
const TURN_PER_POINT: f64 = 0.01;

/// The sphere panel. Its view (azimuth and elevation) is its own and the same for every
/// column, so that the columns turn together; a double-click resets it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpherePanel {
    pub view: OrthoView,
}

impl Default for SpherePanel {
    fn default() -> Self {
        SpherePanel {
            view: OrthoView::FRONT,
        }
    }
}

impl Panel for SpherePanel {
    fn kind(&self) -> PanelKind {
        PanelKind::Sphere
    }

    /// The view, under its heading; the time and the view's angles under it.
    fn extent(&self) -> super::Extent {
        super::Extent {
            images: 1.0,
            lines: 3.0,
            plots: 0.0,
        }
    }

    fn ui(&mut self, ui: &mut egui::Ui, cx: &mut PanelCx<'_>) {
        let (ci, side) = (cx.column, cx.cell.side);
        ui.horizontal_wrapped(|ui| {
            ui.label("Sphere (cylinder wrap)");
            cx.figures.panel_menu_ui(ui, ci, PanelKind::Sphere);
        });
        let (rect, response) = ui.allocate_exact_size(Vec2::splat(side), Sense::click_and_drag());
        cx.picture(PanelKind::Sphere, true, rect);
        response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Image, true, "sphere view"));
        if response.dragged() {
            let d = response.drag_delta();
            // The surface follows the pointer: dragging right turns the camera left.
            self.view = self
                .view
                .turned(-d.x as f64 * TURN_PER_POINT, d.y as f64 * TURN_PER_POINT);
        }
        if response.double_clicked() {
            self.view = OrthoView::FRONT;
        }
        response.on_hover_text("drag to turn · double-click to reset");
        let painter = ui.painter_at(rect);
        painter.rect_filled(rect, 0.0, Color32::WHITE);
        let centre = rect.center();
        let r = side * 0.5 - 6.0;
        let (res, data) = match cx.get::<PointsData>() {
            Slot::Ready { status: r, data: d } => (r, d),
            Slot::Failed { error: e, .. } => {
                error_label(ui, "sphere", &e);
                return;
            }
            Slot::Missing => {
                ui.spinner();
                return;
            }
        };
        let shown = data.points.len();
        let count = shown.min(MAX_SPLATS);
        let rad = marks::disc_radius(f64::from(r), count)
            .clamp(marks::MIN_RADIUS_PX, marks::MAX_RADIUS_PX) as f32;
        let view = self.view;
        let screen =
            |s: glam::DVec2| Pos2::new(centre.x + s.x as f32 * r, centre.y - s.y as f32 * r);
        let projected: Vec<(Pos2, bool)> = data.points[..count]
            .iter()
            .map(|&p| {
                let (s, depth) = view.project(square_to_sphere(p));
                (screen(s), depth >= 0.0)
            })
            .collect();
        let dimmed = Color32::from_rgb(196, 200, 212);
        for &(p, near) in &projected {
            if !near {
                painter.circle_filled(p, (rad * 0.7).max(0.7), dimmed);
            }
        }
        painter.circle_stroke(centre, r, Stroke::new(1.0, Color32::from_gray(60)));
        let [ir, ig, ib] = palette::INK;
        let ink = Color32::from_rgb(ir, ig, ib);
        for &(p, near) in &projected {
            if near {
                painter.circle_filled(p, rad, ink);
            }
        }
        time_label(ui, &res, cx.view.show_timings);
        let yaw = view.yaw.to_degrees().rem_euclid(360.0).round();
        let pitch = view.pitch.to_degrees().round();
        ui.small(format!(
            "azimuth {yaw}°, elevation {pitch}° · far side dimmed · drag to turn"
        ));
        if count < shown {
            ui.small(format!("the first {count} of {shown} points drawn"));
        }
    }
}
