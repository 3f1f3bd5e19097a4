//! The zone-plate panel: the reconstruction, the reference image or the error of a column
//! (one at a time, chosen in the shared view state), with its metrics and the reference's method.

use super::{Panel, PanelCx};
use crate::model::FigureKind;
use crate::model::Slot;
use crate::model::{Colormap, ErrorData, ReconData, ReferenceData};
use crate::scene::panels::PanelKind;
use crate::ui::gpu::DisplayRange;
use crate::ui::results::scene_of;
use crate::ui::view::{ViewState, ZoneImage};
use crate::ui::widgets::status::{error_label, time_label};
use eframe::egui::{self, Color32};

/// The zone-plate panel.
#[derive(Debug, Default)]
pub struct ZonePlatePanel;

impl Panel for ZonePlatePanel {
    fn kind(&self) -> PanelKind {
        PanelKind::ZonePlate
    }

    /// The image under its heading (two lines when narrow); the time, the normaliser (two lines), the error and the reference's method under it.
    fn extent(&self) -> super::Extent {
        super::Extent {
            images: 1.0,
            lines: 5.0,
            plots: 0.0,
        }
    }

    fn figure(&self, view: &ViewState) -> FigureKind {
        match view.zone_image {
            ZoneImage::Reconstruction => FigureKind::Reconstruction,
            ZoneImage::Reference => FigureKind::Reference,
            ZoneImage::Error | ZoneImage::ErrorSpectrum => FigureKind::Error,
        }
    }

    fn ui(&mut self, ui: &mut egui::Ui, cx: &mut PanelCx<'_>) {
        let (ci, side) = (cx.column, cx.cell.side);
        ui.horizontal_wrapped(|ui| {
            let slot = cx.get::<ReconData>();
            let lab = slot.status().and_then(scene_of).unwrap_or(&*cx.scene);
            ui.label(format!("{} {}²", lab.signal.name(), lab.recon.size));
            ui.selectable_value(&mut cx.view.zone_image, ZoneImage::Reconstruction, "recon");
            ui.selectable_value(&mut cx.view.zone_image, ZoneImage::Reference, "reference");
            ui.selectable_value(&mut cx.view.zone_image, ZoneImage::Error, "error");
            ui.selectable_value(
                &mut cx.view.zone_image,
                ZoneImage::ErrorSpectrum,
                "error spectrum",
            )
            .on_hover_text("periodogram of the signed error (log10 P, DC in the centre)");
            cx.figures.panel_menu_ui(ui, ci, PanelKind::ZonePlate);
        });
        if !cx.scene.effects.reconstruction {
            ui.small("reconstruction effect is off");
            return;
        }
        let grey = DisplayRange {
            lo: 0.0,
            hi: 1.0,
            colormap: Colormap::Greys,
        };
        let error_effect = cx.scene.effects.error;
        let zone = cx.view.zone_image;
        let (r, image, range, name) = match zone {
            ZoneImage::Reconstruction => match cx.get::<ReconData>() {
                Slot::Ready { status: r, data: d } => (r, d.image.clone(), grey, "reconstruction"),
                other => return not_ready(ui, zone, error_effect, &other),
            },
            ZoneImage::Reference => match cx.get::<ReferenceData>() {
                Slot::Ready { status: r, data: d } => (r, d.image.clone(), grey, "reference"),
                other => return not_ready(ui, zone, error_effect, &other),
            },
            ZoneImage::ErrorSpectrum => match cx.get::<ErrorData>() {
                Slot::Ready { status: r, data: d } => match &d.spectrum {
                    Some((img, lo, hi)) => (
                        r,
                        img.clone(),
                        DisplayRange {
                            lo: *lo,
                            hi: *hi,
                            colormap: Colormap::Viridis,
                        },
                        "error",
                    ),
                    None => {
                        ui.small("no error spectrum for this image size");
                        return;
                    }
                },
                other => return not_ready(ui, zone, error_effect, &other),
            },
            ZoneImage::Error => match cx.get::<ErrorData>() {
                Slot::Ready { status: r, data: d } => (
                    r,
                    d.image.clone(),
                    DisplayRange {
                        lo: 0.0,
                        hi: d.max_error.max(1e-6),
                        colormap: Colormap::Inferno,
                    },
                    "error",
                ),
                other => return not_ready(ui, zone, error_effect, &other),
            },
        };
        let z = cx.view.zoom.max(1) as f32;
        let s = 1.0 / z;
        let window = [0.5 - s / 2.0, 0.5 - s / 2.0, s, s];
        let rect = cx.images.ui(
            ui,
            egui::Id::NULL.with(("zone", ci, name)),
            &image,
            range,
            window,
            side,
        );
        cx.picture(PanelKind::ZonePlate, true, rect);
        time_label(ui, &r, cx.view.show_timings);
        if let Some(d) = cx.get::<ReconData>().data() {
            if d.zero_weight > 0 {
                ui.colored_label(
                    Color32::from_rgb(200, 120, 0),
                    format!(
                        "{} pixels had zero filter weight (shown grey)",
                        d.zero_weight
                    ),
                );
            }
            ui.small(format!(
                "normaliser: Σw with floor c·Σ|w| (c = {:.3}) · {} pixels floored",
                d.exact.floor, d.exact.floored
            ))
            .on_hover_text(
                "each pixel is Σw·f / max(Σw, c·Σ|w|): where a kernel's negative lobes cancel                  (sparse samples), the plain Σw could approach 0; c is half the kernel's own                  ratio ∫∫w/∫∫|w|, so grids and dense samples are divided by Σw as before",
            );
        }
        if let Some(e) = cx.get::<ErrorData>().data() {
            let low = e.low_frequency.map_or(String::new(), |l| {
                format!(" · low-freq. error {:.1} % (white ≈ 4.9 %)", 100.0 * l)
            });
            ui.small(format!("RMSE {:.4} · PSNR {:.2} dB{low}", e.rmse, e.psnr))
                .on_hover_text(
                    "low-freq. error: the share of the error image's energy at frequencies up to \
                     W/8 cycles per image; blue-noise error (zsobol) keeps it small",
                );
        }
        if let Slot::Ready {
            status: r,
            data: rf,
        } = cx.get::<ReferenceData>()
        {
            {
                // The node's own words: "≤" for a bound, "≈" for an estimate.
                let own = r.accuracy.as_ref().map(|a| format!(", {a}"));
                let refining = r
                    .progress
                    .map(|p| format!(" (refining {}/{})", p.done, p.total));
                ui.small(format!(
                    "reference: {}{}{}",
                    rf.method,
                    own.unwrap_or_default(),
                    refining.unwrap_or_default()
                ));
            }
        }
    }
}

/// What the panel says when the image chosen has no data: the node's error, that the error
/// effect is off (reference and error need it), or a spinner while it is computed.
fn not_ready<T>(ui: &mut egui::Ui, zone: ZoneImage, error_effect: bool, slot: &Slot<T>) {
    match slot.error() {
        Some(e) => error_label(ui, "reconstruction", &e),
        None if zone != ZoneImage::Reconstruction && !error_effect => {
            ui.small("reference/error effect is off");
        }
        None => {
            ui.spinner();
        }
    }
}
