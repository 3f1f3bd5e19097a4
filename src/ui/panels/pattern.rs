//! The pattern panel: the points of a column in the unit square, with overlays (strata,
//! elementary intervals, minimum-distance discs, the star-discrepancy box) and the point
//! statistics.

use super::{Panel, PanelCx};
use crate::model::Slot;
use crate::model::{marks, palette};
use crate::model::{PointsData, StatsData};
use crate::scene::panels::PanelKind;
use crate::ui::gpu;
use crate::ui::view::screen_from_unit;
use crate::ui::widgets::status::{error_label, time_label};
use eframe::egui::{self, Color32, Rect, Stroke, Vec2};
use eframe::egui_wgpu;

/// The pattern panel (its overlays' switches live in the shared view state).
#[derive(Debug, Default)]
pub struct PatternPanel;

impl Panel for PatternPanel {
    fn kind(&self) -> PanelKind {
        PanelKind::Pattern
    }

    /// The square, under its heading; the time, the statistics, the overlays' checkboxes and, for progressive patterns, the prefix slider under it.
    fn extent(&self) -> super::Extent {
        super::Extent {
            images: 1.0,
            lines: 4.5,
            plots: 0.0,
        }
    }

    fn ui(&mut self, ui: &mut egui::Ui, cx: &mut PanelCx<'_>) {
        let (ci, side) = (cx.column, cx.cell.side);
        ui.horizontal_wrapped(|ui| {
            ui.label("Sample pattern");
            cx.figures.panel_menu_ui(ui, ci, PanelKind::Pattern);
        });
        let (rect, _) = ui.allocate_exact_size(Vec2::splat(side), egui::Sense::hover());
        cx.picture(PanelKind::Pattern, true, rect);
        let painter = ui.painter_at(rect);
        painter.rect_filled(rect, 0.0, Color32::WHITE);
        let (r, data) = match cx.get::<PointsData>() {
            Slot::Ready { status: r, data: d } => (r, d),
            Slot::Failed { error: e, .. } => {
                error_label(ui, "pattern", &e);
                return;
            }
            Slot::Missing => {
                ui.spinner();
                return;
            }
        };
        // A prefix is the scene's: the data holds exactly the points shown.
        let count = data.points.len();
        let radius = marks::marker_radius(f64::from(side), data.points.len())
            .clamp(marks::MIN_RADIUS_PX, marks::MAX_RADIUS_PX) as f32;
        // Overlays under the points.
        let grid_stroke = {
            let [r, g, b] = crate::model::palette::STRATA;
            Stroke::new(0.5, Color32::from_rgb(r, g, b))
        };
        // The figure's rule: the column's own strata or the overlay, all of them or none.
        if let Some((c, rws)) = crate::scene::figure::strata(
            crate::ui::results::scene_of(&r).unwrap_or(cx.scene),
            ci,
            cx.view.show_strata,
        ) {
            grid_lines(&painter, rect, c, rws, grid_stroke);
        }
        let k = cx.scene.columns[ci].elementary_k.or(cx.view.elementary_k);
        if let Some((cols, rows)) = crate::model::elementary_grid(k, data.points.len()) {
            let [r, g, b] = crate::model::palette::INTERVALS;
            let stroke = Stroke::new(0.6, Color32::from_rgb(r, g, b));
            grid_lines(&painter, rect, cols, rows, stroke);
        }
        let stats = cx.get::<StatsData>().data().cloned();
        if let Some(s) = &stats {
            if cx.view.show_min_disc && data.points.len() <= 16384 {
                let rad = (s.min_distance / 2.0) as f32 * side;
                for p in &data.points[..count] {
                    painter.circle_stroke(
                        screen_from_unit(rect, [p.x, p.y]),
                        rad,
                        Stroke::new(0.5, Color32::from_rgb(230, 150, 60)),
                    );
                }
            }
            if cx.view.show_star_box {
                if let Some((_, (a, b))) = s.star {
                    let r2 = Rect::from_two_pos(
                        screen_from_unit(rect, [0.0, 0.0]),
                        screen_from_unit(rect, [a, b]),
                    );
                    painter.rect_stroke(
                        r2,
                        0.0,
                        Stroke::new(1.5, Color32::from_rgb(220, 40, 40)),
                        egui::StrokeKind::Inside,
                    );
                }
            }
        }
        let [ir, ig, ib] = palette::INK;
        let color = Color32::from_rgb(ir, ig, ib);
        if cx.images.gpu() {
            let ppp = ui.ctx().pixels_per_point();
            let cb = gpu::PointsCallback {
                id: egui::Id::NULL.with(("points", ci)),
                points: data.gpu.clone(),
                version: data.version,
                count: count as u32,
                window: [0.0, 0.0, 1.0, 1.0],
                radius_px: radius * ppp,
                color,
                rect_px: [rect.width() * ppp, rect.height() * ppp],
            };
            ui.painter()
                .add(egui_wgpu::Callback::new_paint_callback(rect, cb));
        } else {
            for p in &data.points[..count] {
                painter.circle_filled(screen_from_unit(rect, [p.x, p.y]), radius, color);
            }
        }
        time_label(ui, &r, cx.view.show_timings);
        if let Some(note) = &data.note {
            ui.small(note);
        }
        if let Some(s) = &stats {
            ui.small(format!(
                "min dist {:.4} ({:.3}× hex) · mean NN {:.4} · D* {} · L2* {:.2e}{}",
                s.min_distance,
                s.normalized_min_distance,
                s.mean_nn,
                s.star
                    .map(|(d, _)| format!("{d:.2e}"))
                    .unwrap_or_else(|| "—".into()),
                s.l2_star,
                s.t_value.map(|t| format!(" · t = {t}")).unwrap_or_default()
            ));
            if let Some(p) = &s.psa {
                ui.small(format!(
                    "PSA: eff. Nyquist {:.3} · oscillations {:.3} · BOO |ψ₆| {:.3}",
                    p.effective_nyquist, p.oscillations, p.bond_orientational_order
                ))
                .on_hover_text(
                    "Heck, Schlömer, Deussen 2013: effective Nyquist frequency (× √N/2) and \
                     oscillations from the radial power spectrum; mean |ψ₆| over Delaunay \
                     neighbours (1 = hexagonal)",
                );
            }
        }
        ui.horizontal_wrapped(|ui| {
            ui.checkbox(&mut cx.view.show_strata, "strata");
            ui.checkbox(&mut cx.view.show_min_disc, "min-dist discs");
            ui.checkbox(&mut cx.view.show_star_box, "D* box");
            let mut elem = cx.view.elementary_k.is_some();
            if ui.checkbox(&mut elem, "elementary").changed() {
                cx.view.elementary_k = elem.then_some(cx.view.elementary_k.unwrap_or(0));
            }
            if let Some(k) = &mut cx.view.elementary_k {
                let label = ui.label("k");
                ui.add(egui::DragValue::new(k).range(crate::scene::limits::ELEMENTARY_K))
                    .labelled_by(label.id);
            }
        });
    }
}

/// The inner lines of a `cols × rows` grid over the unit square drawn in `rect`.
fn grid_lines(painter: &egui::Painter, rect: Rect, cols: usize, rows: usize, stroke: Stroke) {
    for i in 1..cols {
        let x = i as f64 / cols as f64;
        painter.line_segment(
            [
                screen_from_unit(rect, [x, 0.0]),
                screen_from_unit(rect, [x, 1.0]),
            ],
            stroke,
        );
    }
    for j in 1..rows {
        let y = j as f64 / rows as f64;
        painter.line_segment(
            [
                screen_from_unit(rect, [0.0, y]),
                screen_from_unit(rect, [1.0, y]),
            ],
            stroke,
        );
    }
}
