//! The spectrum panel: the periodogram (log10 P, centred) through the colour map, the radially
//! averaged power spectrum and the anisotropy.

use super::{Panel, PanelCx};
use crate::model::Slot;
use crate::model::SpectrumData;
use crate::scene::panels::PanelKind;
use crate::ui::gpu::DisplayRange;
use crate::ui::results::scene_of;
use crate::ui::widgets::status::{error_label, time_label};
use eframe::egui::{self, Color32};
use egui_plot::{Line, Plot};

/// The spectrum panel.
#[derive(Debug, Default)]
pub struct SpectrumPanel;

impl Panel for SpectrumPanel {
    fn kind(&self) -> PanelKind {
        PanelKind::Spectrum
    }

    /// The periodogram under its heading, its time and stages, then the RAPS and anisotropy plots sharing the height left.
    fn extent(&self) -> super::Extent {
        super::Extent {
            images: 1.0,
            lines: 3.0,
            plots: 2.0,
        }
    }

    fn ui(&mut self, ui: &mut egui::Ui, cx: &mut PanelCx<'_>) {
        let (ci, side, plot_height) = (cx.column, cx.cell.side, cx.cell.plot_height);
        ui.horizontal_wrapped(|ui| {
            let slot = cx.get::<SpectrumData>();
            let size = slot
                .status()
                .and_then(scene_of)
                .map_or(cx.scene.spectrum.size, |s| s.spectrum.size);
            ui.label(format!("Periodogram {size}² (log10 P, centred)"));
            cx.figures.panel_menu_ui(ui, ci, PanelKind::Spectrum);
        });
        let (r, d) = match cx.get::<SpectrumData>() {
            Slot::Ready { status: r, data: d } => (r, d),
            Slot::Failed { error: e, .. } => {
                error_label(ui, "spectrum", &e);
                return;
            }
            Slot::Missing => {
                ui.spinner();
                return;
            }
        };
        let (lo, hi) = if cx.view.lock_scales {
            (cx.view.spectrum_lo, cx.view.spectrum_hi)
        } else {
            d.auto_range
        };
        let range = DisplayRange {
            lo,
            hi,
            colormap: cx.view.colormap,
        };
        let rect = cx.images.ui(
            ui,
            egui::Id::NULL.with(("spectrum", ci)),
            &d.image,
            range,
            [0.0, 0.0, 1.0, 1.0],
            side,
        );
        cx.picture(PanelKind::Spectrum, true, rect);
        time_label(ui, &r, cx.view.show_timings);
        if cx.view.show_timings {
            ui.small(
                d.stages
                    .iter()
                    .map(|(s, ms)| format!("{s} {ms:.2} ms"))
                    .collect::<Vec<_>>()
                    .join(" · "),
            );
        }
        // RAPS the larger share: its peaks are the lecture's point.
        let raps = ui
            .scope(|ui| {
                Plot::new(("raps", ci))
                    .height(plot_height * 1.2)
                    .width(side)
                    .allow_drag(false)
                    .allow_zoom(false)
                    .allow_scroll(false)
                    .x_axis_label("|k|")
                    .y_axis_label("RAPS")
                    .show(ui, |p| {
                        p.line(Line::new("RAPS", d.raps.clone()));
                        p.hline(egui_plot::HLine::new("white noise", 1.0).color(Color32::GRAY));
                    })
            })
            .response;
        cx.picture(PanelKind::Spectrum, false, raps.rect);
        let aniso = ui
            .scope(|ui| {
                Plot::new(("aniso", ci))
                    .height(plot_height * 0.8)
                    .width(side)
                    .allow_drag(false)
                    .allow_zoom(false)
                    .allow_scroll(false)
                    .x_axis_label("|k|")
                    .y_axis_label("aniso. dB")
                    .show(ui, |p| {
                        p.line(Line::new("anisotropy", d.anisotropy.clone()));
                    })
            })
            .response;
        cx.picture(PanelKind::Spectrum, false, aniso.rect);
    }
}
