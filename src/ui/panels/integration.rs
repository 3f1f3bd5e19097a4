//! The integration-error panel: the MSE of the Monte Carlo estimate of ∫∫f against N, every
//! column on one log–log plot with ±1 standard-error bars, the fitted slopes in the legend and
//! guide lines N⁻¹ … N⁻³; the integrand picker with a small image of f, and the study's N range,
//! realizations, shift and randomisation. The realizations come in progressively (1, 2, 4, …
//! R), and the panel says how many are in.

use super::{Panel, PanelCx};
use crate::model::Slot;
use crate::model::{guide_line, palette, IntegrationData, GUIDE_SLOPES};
use crate::scene::integration::limits;
use crate::scene::panels::PanelKind;
use crate::ui::gpu::DisplayRange;
use crate::ui::widgets::params::{integrand_ui, setting_ui};
use crate::ui::widgets::status::error_label;
use eframe::egui::{self, Color32};
use egui_plot::{Corner, Legend, Line, LineStyle, Plot, PlotPoints, Points};
use std::sync::Arc;

/// The integration panel (below the columns; it reads every column's study).
#[derive(Debug, Default)]
pub struct IntegrationPanel;

/// Column `i`'s colour (the figure's too).
fn colour(i: usize) -> Color32 {
    let [r, g, b] = palette::series(i);
    Color32::from_rgb(r, g, b)
}

/// The powers of two from 2^lo to 2^hi.
fn powers_of_two(lo: u32, hi: u32) -> Vec<usize> {
    (lo..=hi).map(|k| 1usize << k).collect()
}

impl Panel for IntegrationPanel {
    fn kind(&self) -> PanelKind {
        PanelKind::Integration
    }

    fn dock_size(&self) -> f32 {
        380.0
    }

    fn ui(&mut self, ui: &mut egui::Ui, cx: &mut PanelCx<'_>) {
        let studies: Vec<(usize, Slot<IntegrationData>)> = (0..cx.scene.columns.len())
            .map(|c| (c, cx.get_in::<IntegrationData>(c)))
            .collect();
        ui.horizontal_top(|ui| {
            ui.vertical(|ui| {
                ui.set_max_width(260.0);
                ui.horizontal(|ui| {
                    ui.strong("Integration error");
                    cx.figures.panel_menu_ui(ui, 0, PanelKind::Integration);
                });
                let s = &mut cx.scene.integration;
                integrand_ui(ui, &mut s.integrand);
                // The image of f (column 0's study carries it).
                if let Some(d) = studies.first().and_then(|(_, r)| r.data()) {
                    cx.images.ui(
                        ui,
                        egui::Id::NULL.with("integrand-thumbnail"),
                        &d.thumbnail,
                        DisplayRange {
                            lo: 0.0,
                            hi: 1.0,
                            colormap: crate::model::Colormap::Greys,
                        },
                        [0.0, 0.0, 1.0, 1.0],
                        96.0,
                    );
                }
                setting_ui(ui, s, "randomize", "random instance per realization");
                setting_ui(ui, s, "shift", "Cranley–Patterson shift");
                setting_ui(ui, s, "realizations", "realizations R");
                // N as powers of two 2^lo … 2^hi; an explicit list of a scene is kept until a
                // bound is moved.
                let (min_n, max_n) = (
                    s.ns.iter().copied().min().unwrap_or(1),
                    s.ns.iter().copied().max().unwrap_or(1),
                );
                let (mut lo, mut hi) = (min_n.ilog2(), max_n.ilog2());
                let top = limits::N.end().ilog2();
                let a = ui.add(egui::Slider::new(&mut lo, 0..=top).text("min log2 N"));
                let b = ui.add(egui::Slider::new(&mut hi, 0..=top).text("max log2 N"));
                if a.changed() || b.changed() {
                    let (l, h) = if a.changed() {
                        (lo, hi.max(lo))
                    } else {
                        (lo.min(hi), hi)
                    };
                    s.ns = powers_of_two(l, h);
                }
                ui.small(format!("N: {} values, {} … {}", s.ns.len(), min_n, max_n));
            });
            ui.vertical(|ui| {
                let mut status = Vec::new();
                let mut curves: Vec<(usize, String, Arc<IntegrationData>)> = Vec::new();
                for (c, r) in &studies {
                    let title = cx
                        .scene
                        .columns
                        .get(*c)
                        .map(|c| c.title())
                        .unwrap_or_default();
                    match r {
                        Slot::Ready { data, .. } => curves.push((*c, title, data.clone())),
                        Slot::Failed { error, .. } => status.push((title, Err(error.clone()))),
                        Slot::Missing => status.push((title, Ok("computing…".to_string()))),
                    }
                }
                let done = curves.iter().map(|c| c.2.done).min();
                let of = curves.first().map(|c| c.2.of);
                if let (Some(done), Some(of)) = (done, of) {
                    let text = if done < of {
                        format!("{done} of {of} realizations in (refining)")
                    } else {
                        format!("all {of} realizations in")
                    };
                    ui.small(text);
                }
                for (title, s) in &status {
                    match s {
                        Ok(t) => {
                            ui.small(format!("{title}: {t}"));
                        }
                        Err(e) => error_label(ui, title, e),
                    }
                }
                let anchor = curves.iter().find_map(|(_, _, d)| {
                    d.study
                        .rows
                        .iter()
                        .find(|r| r.mse > 0.0 && r.mse.is_finite())
                        .map(|r| (r.n as f64, r.mse))
                });
                let n_hi = curves
                    .iter()
                    .flat_map(|c| c.2.study.rows.iter().map(|r| r.n))
                    .max()
                    .unwrap_or(1) as f64;
                Plot::new("integration-error")
                    .width((ui.available_width() - 10.0).max(300.0))
                    .height(220.0)
                    .x_axis_label("log10 N")
                    .y_axis_label("log10 MSE")
                    .legend(Legend::default().position(Corner::RightTop))
                    .show(ui, |p| {
                        if let Some((n0, mse0)) = anchor {
                            for s in GUIDE_SLOPES {
                                let [a, b] = guide_line(s, n0, mse0, n0, n_hi);
                                let name = format!("N^{s}");
                                p.line(
                                    Line::new(
                                        name,
                                        PlotPoints::new(vec![
                                            [a.0.log10(), a.1.log10()],
                                            [b.0.log10(), b.1.log10()],
                                        ]),
                                    )
                                    .color(Color32::from_gray(150))
                                    .style(LineStyle::dashed_loose()),
                                );
                            }
                        }
                        for (c, title, d) in &curves {
                            let colour = colour(*c);
                            let name = crate::export::figure::integration_legend(
                                title,
                                d.study.slope,
                                d.study.slope_stderr,
                            );
                            let mut rows: Vec<_> = d
                                .study
                                .rows
                                .iter()
                                .filter(|r| r.mse > 0.0 && r.mse.is_finite())
                                .collect();
                            rows.sort_by_key(|r| r.n);
                            let pts: Vec<[f64; 2]> = rows
                                .iter()
                                .map(|r| [(r.n as f64).log10(), r.mse.log10()])
                                .collect();
                            for r in &rows {
                                if let Some(se) = r.mse_stderr.filter(|s| *s > 0.0) {
                                    let x = (r.n as f64).log10();
                                    let lo = (r.mse - se).max(r.mse * 1e-3).log10();
                                    let hi = (r.mse + se).log10();
                                    p.line(
                                        Line::new(name.clone(), vec![[x, lo], [x, hi]])
                                            .color(colour)
                                            .width(1.0),
                                    );
                                }
                            }
                            p.line(
                                Line::new(name.clone(), pts.clone())
                                    .color(colour)
                                    .width(2.0),
                            );
                            p.points(Points::new(name, pts).color(colour).radius(3.0));
                        }
                    });
            });
        });
    }
}
