//! The filter panel: the kernel h(x), its frequency response |H(ω)| (a low-pass one against the ideal low-pass)
//! with the Nyquist line, the 2D response image and the filter's metrics.

use super::{Panel, PanelCx};
use crate::model::FigureKind;
use crate::model::ResponseData;
use crate::model::Slot;
use crate::scene::panels::PanelKind;
use crate::ui::gpu::DisplayRange;
use crate::ui::view::ViewState;
use crate::ui::widgets::status::{error_label, time_label};
use eframe::egui::{self, Color32};
use egui_plot::{Line, Plot, VLine};

/// The 2D response's side, in image sides.
const RESPONSE_SIDE: f32 = 0.6;

/// The filter panel.
#[derive(Debug, Default)]
pub struct FilterPanel;

impl Panel for FilterPanel {
    fn kind(&self) -> PanelKind {
        PanelKind::Filter
    }

    /// The kernel and response plots sharing the height left, the 2D response (0.6 of a side) and three lines of captions.
    fn extent(&self) -> super::Extent {
        super::Extent {
            images: RESPONSE_SIDE,
            lines: 4.0,
            plots: 2.0,
        }
    }

    /// Ctrl+S over the panel saves the frequency response (its main plot).
    fn figure(&self, _view: &ViewState) -> FigureKind {
        FigureKind::Response
    }

    fn ui(&mut self, ui: &mut egui::Ui, cx: &mut PanelCx<'_>) {
        let (ci, side, h) = (cx.column, cx.cell.side, cx.cell.plot_height);
        ui.horizontal_wrapped(|ui| {
            ui.label("Filter");
            ui.checkbox(&mut cx.view.response_db, "dB");
            cx.figures.panel_menu_ui(ui, ci, PanelKind::Filter);
        });
        let (r, d) = match cx.get::<ResponseData>() {
            Slot::Ready { status: r, data: d } => (r, d),
            Slot::Failed { error: e, .. } => {
                error_label(ui, "filter", &e);
                return;
            }
            Slot::Missing => {
                ui.spinner();
                return;
            }
        };
        let kernel = ui
            .scope(|ui| {
                Plot::new(("kernel", ci))
                    .height(h)
                    .width(side)
                    .allow_drag(false)
                    .allow_zoom(false)
                    .allow_scroll(false)
                    .x_axis_label("x (sample spacings)")
                    .y_axis_label("h(x)")
                    .show(ui, |p| {
                        p.line(Line::new("h", d.kernel.clone()));
                    })
            })
            .response;
        cx.picture(PanelKind::Filter, false, kernel.rect);
        let db = cx.view.response_db;
        let mag: Vec<[f64; 2]> = d
            .magnitude
            .iter()
            .map(|&[w, m]| [w, if db { crate::model::amplitude_db(m) } else { m }])
            .collect();
        let (one, zero) = if db {
            (0.0, crate::model::DB_FLOOR)
        } else {
            (1.0, 0.0)
        };
        let ideal_parts = [
            vec![[0.0, one], [0.5, one]],
            vec![[0.5, one], [0.5, zero]],
            vec![[0.5, zero], [d.omega_max, zero]],
        ];
        let response = ui
            .scope(|ui| {
                Plot::new(("response", ci))
                    .height(h)
                    .width(side)
                    .allow_drag(false)
                    .allow_zoom(false)
                    .allow_scroll(false)
                    .x_axis_label("ω (cycles/sample)")
                    .y_axis_label(match (db, d.normalised) {
                        (true, true) => "|H|/|H(0)| dB",
                        (true, false) => "|H| dB",
                        (false, true) => "|H|/|H(0)|",
                        (false, false) => "|H|",
                    })
                    .show(ui, |p| {
                        // Only a low-pass filter (normalised to H(0) = 1) is compared with the ideal one.
                        if d.normalised {
                            for part in &ideal_parts {
                                p.line(
                                    Line::new("ideal low-pass", part.clone()).color(Color32::GRAY),
                                );
                            }
                        }
                        p.line(Line::new("|H(ω)|", mag));
                        let [r, g, b] = crate::model::palette::NYQUIST;
                        p.vline(VLine::new("Nyquist", 0.5).color(Color32::from_rgb(r, g, b)));
                    })
            })
            .response;
        cx.picture(PanelKind::Filter, false, response.rect);
        let range = DisplayRange {
            lo: 0.0,
            hi: 1.0,
            colormap: cx.view.colormap,
        };
        let rect = cx.images.ui(
            ui,
            egui::Id::NULL.with(("response2d", ci)),
            &d.image,
            range,
            [0.0, 0.0, 1.0, 1.0],
            side * RESPONSE_SIDE,
        );
        cx.picture(PanelKind::Filter, true, rect);
        ui.small(format!("2D |H|, omega in [-{0}, {0}]²", d.omega_max));
        ui.small(
            d.metrics
                .iter()
                .map(|(k, v)| format!("{k} {v:.3}"))
                .collect::<Vec<_>>()
                .join(" · "),
        );
        time_label(ui, &r, cx.view.show_timings);
    }
}
