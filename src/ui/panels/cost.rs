//! The cost view: every node's wall time and accuracy per column, the evaluation counters, and
//! the convergence curves (RMSE against samples per pixel and against time).

use super::{Panel, PanelCx};
use crate::model::ConvergencePoint;
use crate::scene::panels::PanelKind;
use eframe::egui;
use egui_plot::{Line, Plot};

/// A named convergence curve: (label, log-log RMSE vs spp, log-log RMSE vs ms).
type Curve = (String, Vec<[f64; 2]>, Vec<[f64; 2]>);

/// The cost view (below the columns; it reads every column's results).
#[derive(Debug, Default)]
pub struct CostPanel;

impl Panel for CostPanel {
    fn kind(&self) -> PanelKind {
        PanelKind::Cost
    }

    fn ui(&mut self, ui: &mut egui::Ui, cx: &mut PanelCx<'_>) {
        ui.horizontal_top(|ui| {
            ui.vertical(|ui| {
                ui.strong("Cost per node");
                egui::Grid::new("cost-grid").striped(true).show(ui, |ui| {
                    ui.label("column");
                    for kind in crate::scene::graph::NodeKind::ALL {
                        ui.label(kind.name());
                    }
                    ui.end_row();
                    for (ci, col) in cx.data.iter().enumerate() {
                        ui.label(
                            cx.scene
                                .columns
                                .get(ci)
                                .map(|c| c.title())
                                .unwrap_or_default(),
                        );
                        for row in &col.nodes {
                            match &row.status {
                                Some(r) => {
                                    let t = format!("{:.1} ms", r.wall.as_secs_f64() * 1e3);
                                    let resp = ui.label(t);
                                    if let Some(a) = &r.accuracy {
                                        resp.on_hover_text(a.to_string());
                                    }
                                }
                                None => {
                                    ui.label("—");
                                }
                            }
                        }
                        ui.end_row();
                    }
                    ui.label("evaluations");
                    for (_, count) in cx.evaluator.counts() {
                        ui.label(count.to_string());
                    }
                    ui.end_row();
                });
            });
            ui.vertical(|ui| {
                ui.strong("Convergence (log-log)");
                if !cx.scene.effects.convergence {
                    ui.small("turn on the convergence effect to compute it");
                }
                let curves: Vec<Curve> = cx
                    .data
                    .iter()
                    .enumerate()
                    .filter_map(
                        |(ci, col)| match col.get::<Vec<ConvergencePoint>>().data() {
                            Some(c) => Some((
                                cx.scene
                                    .columns
                                    .get(ci)
                                    .map(|c| c.title())
                                    .unwrap_or_default(),
                                c.iter()
                                    .map(|p| [(p.spp as f64).log10(), p.rmse.max(1e-12).log10()])
                                    .collect(),
                                c.iter()
                                    .map(|p| {
                                        [p.millis.max(1e-3).log10(), p.rmse.max(1e-12).log10()]
                                    })
                                    .collect(),
                            )),
                            _ => None,
                        },
                    )
                    .collect();
                ui.horizontal(|ui| {
                    Plot::new("conv-spp")
                        .width(320.0)
                        .height(160.0)
                        .x_axis_label("log10 spp")
                        .y_axis_label("log10 RMSE")
                        .legend(egui_plot::Legend::default())
                        .show(ui, |p| {
                            for (name, a, _) in &curves {
                                p.line(Line::new(name.clone(), a.clone()));
                            }
                        });
                    Plot::new("conv-time")
                        .width(320.0)
                        .height(160.0)
                        .x_axis_label("log10 ms")
                        .y_axis_label("log10 RMSE")
                        .legend(egui_plot::Legend::default())
                        .show(ui, |p| {
                            for (name, _, b) in &curves {
                                p.line(Line::new(name.clone(), b.clone()));
                            }
                        });
                });
            });
        });
    }
}
