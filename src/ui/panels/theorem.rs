//! The 1D sampling-theorem panel: draws a [`TheoremView`] computed by the engine and edits the
//! scene's [`TheoremSettings`] (the engine recomputes the node when they change). No maths here.

use super::{Panel, PanelCx};
use crate::core::filter::Filter;
use crate::core::signal::theorem::{
    AliasingErrors, PairKind, Reconstructor, TheoremSettings, TheoremView,
};
use crate::model::Slot;
use crate::model::{palette, FigureKind};
use crate::scene::panels::PanelKind;
use crate::ui::figures::FigureRequests;
use crate::ui::widgets::params::{family_ui, labelled_params_ui, params_ui, setting_ui};
use eframe::egui::{self, Color32};
use egui_plot::{Legend, Line, Plot, Points, VLine};

const fn colour(c: [u8; 3]) -> Color32 {
    Color32::from_rgb(c[0], c[1], c[2])
}

const NYQUIST: Color32 = colour(palette::NYQUIST);
const RECON: Color32 = colour(palette::RECON);
const DATA: Color32 = colour(palette::DATA);

/// Small legend text, so that the legend leaves the curves visible.
fn legend() -> Legend {
    Legend::default()
        .text_style(egui::TextStyle::Small)
        .background_alpha(0.5)
}

/// The colour of replica k (k = 0, the original, is drawn in the text colour).
fn replica_colour(k: i64) -> Color32 {
    colour(palette::replica(k))
}

/// The panel's own display state.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct TheoremPanel {
    /// Show Re/Im of the pair's transform instead of |P|.
    pub pair_re_im: bool,
}

impl Panel for TheoremPanel {
    fn kind(&self) -> PanelKind {
        PanelKind::Theorem
    }

    fn dock_size(&self) -> f32 {
        520.0
    }

    /// Draws the controls (editing the scene's theorem settings) and the plots of the theorem
    /// node's result (column-independent: it is computed for column 0 only).
    fn ui(&mut self, ui: &mut egui::Ui, cx: &mut PanelCx<'_>) {
        let result = cx.get_in::<TheoremView>(0);
        ui.horizontal_top(|ui| {
            ui.vertical(|ui| {
                ui.set_width(270.0);
                egui::ScrollArea::vertical()
                    .id_salt("theorem-controls")
                    .show(ui, |ui| controls_ui(ui, &mut cx.scene.theorem));
            });
            ui.separator();
            let view = match result {
                Slot::Ready { data: v, .. } => v.clone(),
                Slot::Failed { error: e, .. } => {
                    ui.colored_label(NYQUIST, format!("sampling theorem: {e}"));
                    return;
                }
                Slot::Missing => {
                    ui.spinner();
                    return;
                }
            };
            egui::ScrollArea::vertical()
                .id_salt("theorem-plots")
                .show(ui, |ui| {
                    ui.vertical(|ui| self.plots_ui(ui, &view, cx.figures))
                });
        });
    }
}

impl TheoremPanel {
    fn plots_ui(&mut self, ui: &mut egui::Ui, v: &TheoremView, figures: &mut FigureRequests) {
        let width = (ui.available_width() / 3.0 - 8.0).max(160.0);
        let height = 190.0;
        // The numbers first, so that they stay in view when the panel is short.
        ui.horizontal(|ui| {
            // The view belongs to column 0 (it does not depend on the column).
            figures.panel_menu_ui(ui, 0, PanelKind::Theorem);
            ui.weak("figures of the three plots below (Ctrl+S over a plot saves it)");
        });
        errors_ui(ui, &v.errors, v.settings.rate);
        ui.horizontal_top(|ui| {
            let signal = ui.vertical(|ui| {
                ui.strong("Signal f, samples f(nT), reconstruction f_r");
                signal_plot_ui(ui, v, width, height);
            });
            let spectrum = ui.vertical(|ui| {
                ui.strong("Spectrum: |F|, replicas F(ω − k·f_s), |G|");
                spectrum_plot_ui(ui, v, width, height);
            });
            let recon = ui.vertical(|ui| {
                ui.strong("Reconstructed spectrum |G·T·F_s|");
                recon_spectrum_plot_ui(ui, v, width, height);
            });
            for (r, kind) in [
                (signal.response.rect, FigureKind::TheoremSignal),
                (spectrum.response.rect, FigureKind::TheoremSpectrum),
                (recon.response.rect, FigureKind::TheoremReconstructed),
            ] {
                figures.panel_drawn(r, 0, kind);
            }
        });
        ui.separator();
        ui.horizontal_top(|ui| {
            ui.vertical(|ui| {
                ui.strong(format!(
                    "Transform pair {} (a = {:.3}, s = {:.3})",
                    v.settings.pair.kind.name(),
                    v.settings.pair.scale,
                    v.settings.pair.shift
                ));
                ui.checkbox(&mut self.pair_re_im, "Show Re/Im of the transform");
                pair_plots_ui(ui, v, self.pair_re_im, width, height);
            });
            ui.vertical(|ui| {
                ui.strong("van der Corput (base 2)");
                vdc_table_ui(ui, v);
            });
        });
    }
}

fn controls_ui(ui: &mut egui::Ui, s: &mut TheoremSettings) {
    ui.heading("Sampling theorem (1D)");
    family_ui(ui, "theorem-signal", "Signal", &mut s.signal, |_| true);
    labelled_params_ui(ui, &mut s.signal, "signal ");
    setting_ui(ui, s, "rate", "sampling rate f_s");
    if let Some(b) = s.signal.bandwidth() {
        ui.label(format!("Nyquist rate 2B = {:.3}", 2.0 * b));
    } else {
        ui.label("not band-limited: no rate avoids pre-aliasing");
    }
    family_ui(
        ui,
        "theorem-filter",
        "Reconstruction filter",
        &mut s.filter,
        |f: &Filter| Reconstructor::new(*f, 1.0, 1.0).is_ok(),
    );
    params_ui(ui, &mut s.filter);
    setting_ui(ui, s, "extent", "plot half-width (units)");
    ui.separator();
    ui.strong("Transform pair");
    egui::ComboBox::new("theorem-pair", "Pair")
        .selected_text(s.pair.kind.name())
        .show_ui(ui, |ui| {
            for k in PairKind::ALL {
                ui.selectable_value(&mut s.pair.kind, k, k.name());
            }
        });
    setting_ui(ui, &mut s.pair, "scale", "scale |a|");
    setting_ui(ui, &mut s.pair, "shift", "shift s");
    ui.separator();
    setting_ui(ui, s, "vdc_rows", "van der Corput rows n");
}

fn signal_plot_ui(ui: &mut egui::Ui, v: &TheoremView, width: f32, height: f32) {
    Plot::new("theorem-signal-plot")
        .width(width)
        .height(height)
        .legend(legend())
        .x_axis_label("x (units)")
        .show(ui, |p| {
            p.line(Line::new("f(x)", v.signal.clone()).color(Color32::GRAY));
            p.points(
                Points::new("samples f(nT)", v.samples.clone())
                    .stems(0.0)
                    .radius(2.5)
                    .color(DATA),
            );
            p.line(Line::new("f_r(x)", v.reconstruction.clone()).color(RECON));
        });
}

fn nyquist_lines(p: &mut egui_plot::PlotUi<'_>, rate: f64) {
    p.vline(VLine::new("±f_s/2", 0.5 * rate).color(NYQUIST));
    p.vline(VLine::new("±f_s/2", -0.5 * rate).color(NYQUIST));
}

fn spectrum_plot_ui(ui: &mut egui::Ui, v: &TheoremView, width: f32, height: f32) {
    let sp = &v.spectrum;
    let text = ui.visuals().text_color();
    Plot::new("theorem-spectrum-plot")
        .width(width)
        .height(height)
        .legend(legend())
        .x_axis_label("ω (cycles/unit)")
        .show(ui, |p| {
            for (k, curve) in &sp.replicas {
                p.line(Line::new(format!("k = {k}"), curve.clone()).color(replica_colour(*k)));
            }
            for (k, lines) in &sp.lines {
                let name = if *k == 0 {
                    "|F| (lines)".to_string()
                } else {
                    format!("k = {k}")
                };
                let colour = if *k == 0 { text } else { replica_colour(*k) };
                p.points(
                    Points::new(name, lines.clone())
                        .stems(0.0)
                        .radius(3.0)
                        .color(colour),
                );
            }
            if !sp.original.is_empty() {
                p.line(Line::new("|F(ω)|", sp.original.clone()).width(2.0));
            }
            p.line(Line::new("|G(ω)| (filter)", sp.gain.clone()).color(Color32::GRAY));
            nyquist_lines(p, v.settings.rate);
        });
}

fn recon_spectrum_plot_ui(ui: &mut egui::Ui, v: &TheoremView, width: f32, height: f32) {
    let sp = &v.spectrum;
    Plot::new("theorem-recon-spectrum-plot")
        .width(width)
        .height(height)
        .legend(legend())
        .x_axis_label("ω (cycles/unit)")
        .show(ui, |p| {
            if !sp.original.is_empty() {
                p.line(Line::new("|F(ω)|", sp.original.clone()).color(Color32::GRAY));
                p.line(Line::new("|F_r(ω)|", sp.reconstructed.clone()).color(RECON));
            }
            if let Some((_, orig)) = sp.lines.iter().find(|(k, _)| *k == 0) {
                p.points(
                    Points::new("|F| (lines)", orig.clone())
                        .radius(4.0)
                        .color(Color32::GRAY),
                );
            }
            if !sp.reconstructed_lines.is_empty() {
                p.points(
                    Points::new("|F_r| (lines)", sp.reconstructed_lines.clone())
                        .stems(0.0)
                        .radius(2.5)
                        .color(RECON),
                );
            }
            nyquist_lines(p, v.settings.rate);
        });
}

fn errors_ui(ui: &mut egui::Ui, e: &AliasingErrors, rate: f64) {
    let unit = if e.periodic { "power" } else { "energy" };
    ui.horizontal_wrapped(|ui| {
        let terms = [
            (
                "pre-aliasing",
                e.pre_aliasing,
                "replicas folded into |ω| < f_s/2 by sampling",
            ),
            (
                "post-aliasing",
                e.post_aliasing,
                "replicas the filter passes beyond f_s/2",
            ),
            ("smoothing", e.smoothing, "pass-band attenuation"),
            (
                "lost above Nyquist",
                e.lost,
                "signal content above f_s/2 not reproduced",
            ),
            (
                "total ∫|f_r − f|²",
                e.total,
                "the whole reconstruction error",
            ),
        ];
        for (name, value, hover) in terms {
            ui.group(|ui| {
                ui.vertical(|ui| {
                    ui.label(egui::RichText::new(name).strong())
                        .on_hover_text(hover);
                    ui.label(format!("{value:.3e}"));
                    ui.label(format!("{:.3} % of {unit}", 100.0 * e.relative(value)));
                });
            });
        }
    });
    ui.label(format!(
        "{unit} of f = {:.4}; f_s = {rate:.3}, Nyquist f_s/2 = {:.3}; integrated over |ω| ≤ {:.1}, tail ≤ {:.1e}",
        e.signal_energy,
        0.5 * rate,
        e.band,
        e.tail_bound
    ));
}

fn pair_plots_ui(ui: &mut egui::Ui, v: &TheoremView, re_im: bool, width: f32, height: f32) {
    let pp = &v.pair;
    let shah = v.settings.pair.kind == PairKind::Shah;
    ui.horizontal_top(|ui| {
        Plot::new("theorem-pair-spatial")
            .width(width)
            .height(height)
            .legend(legend())
            .x_axis_label("x")
            .include_x(-pp.x_max)
            .include_x(pp.x_max)
            .show(ui, |p| {
                if shah {
                    p.points(
                        Points::new("impulses (weight 1/|a|)", pp.impulses_x.clone())
                            .stems(0.0)
                            .radius(3.0),
                    );
                } else {
                    p.line(Line::new("f(a(x − s))", pp.spatial.clone()));
                }
            });
        Plot::new("theorem-pair-frequency")
            .width(width)
            .height(height)
            .legend(legend())
            .x_axis_label("ω")
            .include_x(-pp.omega_max)
            .include_x(pp.omega_max)
            .show(ui, |p| {
                if shah {
                    let re: Vec<[f64; 2]> =
                        pp.impulses_omega.iter().map(|i| [i[0], i[1]]).collect();
                    let im: Vec<[f64; 2]> =
                        pp.impulses_omega.iter().map(|i| [i[0], i[2]]).collect();
                    p.points(Points::new("Re", re).stems(0.0).radius(3.0));
                    p.points(Points::new("Im", im).stems(0.0).radius(2.0).color(RECON));
                } else if re_im {
                    p.line(Line::new("Re F", pp.re.clone()));
                    p.line(Line::new("Im F", pp.im.clone()).color(RECON));
                } else {
                    p.line(Line::new("|F(ω)|", pp.magnitude.clone()));
                }
            });
    });
}

fn vdc_table_ui(ui: &mut egui::Ui, v: &TheoremView) {
    egui::ScrollArea::vertical()
        .id_salt("theorem-vdc")
        .max_height(200.0)
        .show(ui, |ui| {
            egui::Grid::new("theorem-vdc-grid")
                .striped(true)
                .num_columns(4)
                .show(ui, |ui| {
                    for h in ["i", "binary", "reversed", "Φ₂(i)"] {
                        ui.strong(h);
                    }
                    ui.end_row();
                    for row in &v.vdc {
                        ui.label(row.i.to_string());
                        ui.monospace(row.digits_string());
                        ui.monospace(row.reversed_string());
                        ui.label(format!("{}", row.value));
                        ui.end_row();
                    }
                });
        });
}
