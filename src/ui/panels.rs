//! The panels of a column. Each takes plain data computed by the engine and draws it.

use super::app::{ColumnResults, Shown};
use super::figures;
use super::gpu::{self, Colormap, DisplayRange, FloatImage};
use crate::engine::Evaluator;
use crate::export::figure::PanelKind;
use crate::scene::graph::{ImageData, NodeKind, NodeValue};
use crate::scene::{Panels, Scene};
use eframe::egui::{self, Color32, Pos2, Rect, Stroke, Vec2};
use eframe::egui_wgpu;
use egui_plot::{Line, Plot, VLine};
use serde::{Deserialize, Serialize};
use std::collections::HashMap;

/// Which image the zone-plate panel shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
pub enum ZoneImage {
    #[default]
    Reconstruction,
    Reference,
    Error,
}

/// Display state shared by the panels (persisted between runs).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct ViewState {
    /// Same spectrum display range in every column.
    pub lock_scales: bool,
    /// Locked spectrum range, log10 P.
    pub spectrum_lo: f32,
    pub spectrum_hi: f32,
    pub colormap: Colormap,
    pub zone_image: ZoneImage,
    /// Nearest-neighbour magnification of the zone plate.
    pub zoom: u32,
    /// |H| in dB instead of linear.
    pub response_db: bool,
    /// Overlays on the pattern panel.
    pub show_strata: bool,
    pub show_min_disc: bool,
    pub show_star_box: bool,
    /// Elementary intervals b^k × b^(m−k) in base 2: `Some(k)`.
    pub elementary_k: Option<u32>,
    /// Draw only the first i points (progressive sequences).
    pub prefix: Option<usize>,
    /// Show wall times next to the panels (off for reproducible figures and snapshots).
    pub show_timings: bool,
    /// Lecture mode: light projector theme, large fonts, content letterboxed to 16:9.
    pub lecture: bool,
    /// Zoom factor of everything in lecture mode (fonts, widgets, plots).
    pub lecture_scale: f32,
    /// The controls side panel is hidden (F9).
    pub controls_hidden: bool,
    /// Folder the figures are saved into.
    pub figure_dir: String,
    /// Scale of PNG figures saved by Ctrl+S (1..=3).
    pub figure_scale: u32,
}

impl Default for ViewState {
    fn default() -> Self {
        ViewState {
            lock_scales: true,
            spectrum_lo: -1.0,
            spectrum_hi: 1.0,
            colormap: Colormap::Viridis,
            zone_image: ZoneImage::Reconstruction,
            zoom: 1,
            response_db: false,
            show_strata: false,
            show_min_disc: false,
            show_star_box: false,
            elementary_k: None,
            prefix: None,
            show_timings: true,
            lecture: false,
            lecture_scale: LECTURE_SCALE_DEFAULT,
            controls_hidden: false,
            figure_dir: "figures".into(),
            figure_scale: 2,
        }
    }
}

/// Default zoom factor of lecture mode.
pub const LECTURE_SCALE_DEFAULT: f32 = 1.6;
/// Range of the lecture-mode zoom factor.
pub const LECTURE_SCALE_RANGE: std::ops::RangeInclusive<f32> = 1.0..=3.0;

/// CPU textures for the fallback path, keyed per panel.
#[derive(Default)]
pub struct TextureCache {
    entries: HashMap<egui::Id, (u64, [u32; 4], egui::TextureHandle)>,
}

/// `screen_from_unit`: maps the unit square (y up) onto `rect`.
pub fn screen_from_unit(rect: Rect, p: [f64; 2]) -> Pos2 {
    Pos2::new(
        rect.left() + p[0] as f32 * rect.width(),
        rect.bottom() - p[1] as f32 * rect.height(),
    )
}

fn result_of(col: Option<&ColumnResults>, kind: NodeKind) -> Option<&Shown> {
    col.and_then(|c| c.get(&kind))
}

/// The node's wall time and accuracy; while it refines, a progress bar with
/// "refining i/n" and its current error estimate.
fn time_label(ui: &mut egui::Ui, r: &Shown) {
    if let Some(p) = r.progress {
        let text = match &r.accuracy {
            Some(a) => format!("refining {}/{}, {a}", p.step, p.steps),
            None => format!("refining {}/{}", p.step, p.steps),
        };
        ui.add(
            egui::ProgressBar::new(p.step as f32 / p.steps.max(1) as f32)
                .desired_height(4.0)
                .desired_width(ui.available_width().min(260.0)),
        );
        ui.small(text);
        return;
    }
    let show = ui.ctx().data(|d| {
        d.get_temp::<bool>(egui::Id::NULL.with(SHOW_TIMINGS))
            .unwrap_or(true)
    });
    let mut parts = Vec::new();
    if show {
        parts.push(format!("{:.1} ms", r.wall.as_secs_f64() * 1e3));
    }
    if let Some(a) = &r.accuracy {
        parts.push(a.clone());
    }
    if !parts.is_empty() {
        ui.small(parts.join(" · "));
    }
}

/// Temp-data key holding [`ViewState::show_timings`] for the current frame.
pub const SHOW_TIMINGS: &str = "samplescope.show_timings";

fn error_label(ui: &mut egui::Ui, what: &str, e: &str) {
    ui.colored_label(Color32::from_rgb(200, 40, 40), format!("{what}: {e}"));
}

/// Every column side by side. Returns each column's screen rectangle, in column order (files
/// dropped on the window go to the column under the pointer).
pub fn columns_ui(
    ui: &mut egui::Ui,
    scene: &Scene,
    results: &[ColumnResults],
    view: &mut ViewState,
    gpu: bool,
    textures: &mut TextureCache,
) -> Vec<Rect> {
    let mut column_rects = Vec::with_capacity(scene.columns.len());
    let show_timings = view.show_timings;
    ui.ctx()
        .data_mut(|d| d.insert_temp(egui::Id::NULL.with(SHOW_TIMINGS), show_timings));
    let ncols = scene.columns.len().max(1);
    let visible = visible_panels(&scene.panels).max(1);
    let spacing = ui.spacing().item_spacing.x;
    let width = ((ui.available_width() - spacing * (ncols as f32 - 1.0)) / ncols as f32).max(120.0);
    let height = ui.available_height() - 30.0;
    // Panels of a column sit in a grid of `per_row` panels per row; pick the arrangement that
    // gives the largest panels (each panel needs ~110 points below its image for its text and plots).
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
    egui::ScrollArea::both().show(ui, |ui| {
        ui.horizontal_top(|ui| {
            for (ci, column) in scene.columns.iter().enumerate() {
                let col = results.get(ci);
                ui.push_id(ci, |ui| {
                    let shown = ui.allocate_ui(Vec2::new(width, ui.available_height()), |ui| {
                        ui.vertical(|ui| {
                            ui.horizontal(|ui| {
                                ui.strong(match &column.points {
                                    // An imported set has its own size and no seed.
                                    Some(p) => {
                                        format!("{} · N = {}", column.title(), p.points.len())
                                    }
                                    // Labelled from the scene the shown points were
                                    // computed for (a recompute may be running).
                                    None => {
                                        let lab = result_of(col, NodeKind::Points)
                                            .map_or(scene, |r| r.scene.as_ref());
                                        let c = lab.columns.get(ci).unwrap_or(column);
                                        format!("{} · N = {} · seed {}", c.title(), lab.n, c.seed)
                                    }
                                });
                                figures::column_menu_ui(ui, ci);
                            });
                            let mut shown: Vec<u8> = Vec::new();
                            if scene.panels.pattern {
                                shown.push(0);
                            }
                            if scene.panels.spectrum {
                                shown.push(1);
                            }
                            if scene.panels.zoneplate {
                                shown.push(2);
                            }
                            if scene.panels.filter {
                                shown.push(3);
                            }
                            for row in shown.chunks(per_row) {
                                ui.horizontal_top(|ui| {
                                    for &panel in row {
                                        let kind = match panel {
                                            0 => PanelKind::Pattern,
                                            1 => PanelKind::Spectrum,
                                            2 => match view.zone_image {
                                                ZoneImage::Reconstruction => {
                                                    PanelKind::Reconstruction
                                                }
                                                ZoneImage::Reference => PanelKind::Reference,
                                                ZoneImage::Error => PanelKind::Error,
                                            },
                                            _ => PanelKind::Response,
                                        };
                                        let shown =
                                            ui.allocate_ui(Vec2::new(side + 8.0, 10.0), |ui| {
                                                ui.vertical(|ui| match panel {
                                                    0 => pattern_panel(
                                                        ui, ci, scene, col, view, gpu, side,
                                                    ),
                                                    1 => spectrum_panel(
                                                        ui, ci, scene, col, view, gpu, textures,
                                                        side,
                                                    ),
                                                    2 => zoneplate_panel(
                                                        ui, ci, scene, col, view, gpu, textures,
                                                        side,
                                                    ),
                                                    _ => filter_panel(
                                                        ui, ci, col, view, gpu, textures, side,
                                                    ),
                                                });
                                            });
                                        figures::register_panel(
                                            ui.ctx(),
                                            shown.response.rect,
                                            ci,
                                            kind,
                                        );
                                    }
                                });
                            }
                        });
                    });
                    column_rects.push(shown.response.rect);
                });
            }
        });
    });
    column_rects
}

fn visible_panels(p: &Panels) -> usize {
    [p.pattern, p.spectrum, p.zoneplate, p.filter]
        .iter()
        .filter(|&&b| b)
        .count()
}

fn pattern_panel(
    ui: &mut egui::Ui,
    ci: usize,
    scene: &Scene,
    col: Option<&ColumnResults>,
    view: &mut ViewState,
    gpu: bool,
    side: f32,
) {
    ui.horizontal_wrapped(|ui| {
        ui.label("Sample pattern");
        figures::panel_menu_ui(ui, ci, &[PanelKind::Pattern]);
    });
    let (rect, _) = ui.allocate_exact_size(Vec2::splat(side), egui::Sense::hover());
    let painter = ui.painter_at(rect);
    painter.rect_filled(rect, 0.0, Color32::WHITE);
    let Some(r) = result_of(col, NodeKind::Points) else {
        ui.spinner();
        return;
    };
    let data = match &r.value {
        Ok(NodeValue::Points(d)) => d.clone(),
        Ok(_) => return,
        Err(e) => {
            error_label(ui, "pattern", e);
            return;
        }
    };
    let count = view.prefix.unwrap_or(usize::MAX).min(data.points.len());
    let radius = (side / (data.points.len() as f32).sqrt() * 0.18).clamp(0.8, 4.0);
    // Overlays under the points.
    let grid_stroke = Stroke::new(0.5, Color32::from_gray(190));
    if view.show_strata {
        let (c, rws) = strata_shape(scene, ci, data.points.len());
        for i in 1..c {
            let x = i as f64 / c as f64;
            painter.line_segment(
                [
                    screen_from_unit(rect, [x, 0.0]),
                    screen_from_unit(rect, [x, 1.0]),
                ],
                grid_stroke,
            );
        }
        for j in 1..rws {
            let y = j as f64 / rws as f64;
            painter.line_segment(
                [
                    screen_from_unit(rect, [0.0, y]),
                    screen_from_unit(rect, [1.0, y]),
                ],
                grid_stroke,
            );
        }
    }
    if let Some(k) = scene.columns[ci].elementary_k.or(view.elementary_k) {
        let n = data.points.len();
        if n.is_power_of_two() {
            let m = n.trailing_zeros();
            let k = k.min(m);
            let (cx, cy) = (1usize << k, 1usize << (m - k));
            for i in 1..cx {
                let x = i as f64 / cx as f64;
                painter.line_segment(
                    [
                        screen_from_unit(rect, [x, 0.0]),
                        screen_from_unit(rect, [x, 1.0]),
                    ],
                    Stroke::new(0.6, Color32::from_rgb(120, 160, 220)),
                );
            }
            for j in 1..cy {
                let y = j as f64 / cy as f64;
                painter.line_segment(
                    [
                        screen_from_unit(rect, [0.0, y]),
                        screen_from_unit(rect, [1.0, y]),
                    ],
                    Stroke::new(0.6, Color32::from_rgb(120, 160, 220)),
                );
            }
        }
    }
    let stats = match result_of(col, NodeKind::Statistics).map(|r| &r.value) {
        Some(Ok(NodeValue::Statistics(s))) => Some(s.clone()),
        _ => None,
    };
    if let Some(s) = &stats {
        if view.show_min_disc && data.points.len() <= 16384 {
            let rad = (s.min_distance / 2.0) as f32 * side;
            for p in &data.points[..count] {
                painter.circle_stroke(
                    screen_from_unit(rect, [p.x, p.y]),
                    rad,
                    Stroke::new(0.5, Color32::from_rgb(230, 150, 60)),
                );
            }
        }
        if view.show_star_box {
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
    let color = Color32::from_rgb(20, 20, 30);
    if gpu {
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
    time_label(ui, r);
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
    }
    ui.horizontal_wrapped(|ui| {
        ui.checkbox(&mut view.show_strata, "strata");
        ui.checkbox(&mut view.show_min_disc, "min-dist discs");
        ui.checkbox(&mut view.show_star_box, "D* box");
        let mut elem = view.elementary_k.is_some();
        if ui.checkbox(&mut elem, "elementary").changed() {
            view.elementary_k = elem.then_some(view.elementary_k.unwrap_or(0));
        }
        if let Some(k) = &mut view.elementary_k {
            let label = ui.label("k");
            ui.add(egui::DragValue::new(k).range(0..=24))
                .labelled_by(label.id);
        }
    });
    if scene.columns[ci].pattern.is_progressive() {
        let n = data.points.len();
        let mut p = view.prefix.unwrap_or(n).min(n);
        if ui
            .add(egui::Slider::new(&mut p, 1..=n.max(1)).text("first i points"))
            .changed()
        {
            view.prefix = (p < n).then_some(p);
        }
    }
}

/// Columns × rows of the strata drawn for a pattern.
fn strata_shape(scene: &Scene, ci: usize, n: usize) -> (usize, usize) {
    use crate::core::pattern::{resolve_cols, Pattern};
    let cols = match &scene.columns[ci].pattern {
        Pattern::Jitter(j) => j.cols,
        Pattern::Grid(g) => g.cols,
        Pattern::MultiJitter(m) => m.cols,
        Pattern::CorrelatedMultiJitter(m) => m.cols,
        Pattern::NRooks(_) | Pattern::Lhs(_) => return (n.min(256), n.min(256)),
        _ => 0,
    };
    resolve_cols("strata", cols, n).unwrap_or((1, 1))
}

#[allow(clippy::too_many_arguments)]
fn image_widget(
    ui: &mut egui::Ui,
    id: egui::Id,
    image: &ImageData,
    range: DisplayRange,
    window: [f32; 4],
    gpu: bool,
    textures: &mut TextureCache,
    side: f32,
) -> Rect {
    let (rect, _) = ui.allocate_exact_size(Vec2::splat(side), egui::Sense::hover());
    let float = FloatImage {
        width: image.width as u32,
        height: image.height as u32,
        values: image.values.clone(),
        version: image.version,
    };
    if gpu {
        let cb = gpu::ImageCallback {
            id,
            image: float,
            range,
            window,
        };
        ui.painter()
            .add(egui_wgpu::Callback::new_paint_callback(rect, cb));
    } else {
        let key = [
            range.lo.to_bits(),
            range.hi.to_bits(),
            range.log as u32,
            range.colormap as u32,
        ];
        let entry = textures.entries.get(&id);
        let fresh = entry.is_none_or(|(v, k, _)| *v != image.version || *k != key);
        if fresh {
            let ci = gpu::colorize(&float, range);
            let tex = ui
                .ctx()
                .load_texture(format!("{id:?}"), ci, egui::TextureOptions::NEAREST);
            textures.entries.insert(id, (image.version, key, tex));
        }
        if let Some((_, _, tex)) = textures.entries.get(&id) {
            let uv = Rect::from_min_size(
                Pos2::new(window[0], window[1]),
                Vec2::new(window[2], window[3]),
            );
            ui.painter().image(tex.id(), rect, uv, Color32::WHITE);
        }
    }
    rect
}

#[allow(clippy::too_many_arguments)]
fn spectrum_panel(
    ui: &mut egui::Ui,
    ci: usize,
    scene: &Scene,
    col: Option<&ColumnResults>,
    view: &mut ViewState,
    gpu: bool,
    textures: &mut TextureCache,
    side: f32,
) {
    ui.horizontal_wrapped(|ui| {
        let size = result_of(col, NodeKind::Spectrum)
            .map_or(scene.spectrum.size, |r| r.scene.spectrum.size);
        ui.label(format!("Periodogram {size}² (log10 P, centred)"));
        figures::panel_menu_ui(ui, ci, &[PanelKind::Spectrum, PanelKind::Raps]);
    });
    let Some(r) = result_of(col, NodeKind::Spectrum) else {
        ui.spinner();
        return;
    };
    let d = match &r.value {
        Ok(NodeValue::Spectrum(d)) => d.clone(),
        Ok(_) => return,
        Err(e) => {
            error_label(ui, "spectrum", e);
            return;
        }
    };
    let (lo, hi) = if view.lock_scales {
        (view.spectrum_lo, view.spectrum_hi)
    } else {
        d.auto_range
    };
    let range = DisplayRange {
        lo,
        hi,
        log: false,
        colormap: view.colormap,
    };
    image_widget(
        ui,
        egui::Id::NULL.with(("spectrum", ci)),
        &d.image,
        range,
        [0.0, 0.0, 1.0, 1.0],
        gpu,
        textures,
        side,
    );
    time_label(ui, r);
    if view.show_timings {
        ui.small(
            d.stages
                .iter()
                .map(|(s, ms)| format!("{s} {ms:.2} ms"))
                .collect::<Vec<_>>()
                .join(" · "),
        );
    }
    let h = (side * 0.3).max(80.0);
    Plot::new(("raps", ci))
        .height(h)
        .width(side)
        .allow_drag(false)
        .allow_zoom(false)
        .allow_scroll(false)
        .x_axis_label("|k|")
        .y_axis_label("RAPS")
        .show(ui, |p| {
            p.line(Line::new("RAPS", d.raps.clone()));
            p.hline(egui_plot::HLine::new("white noise", 1.0).color(Color32::GRAY));
        });
    Plot::new(("aniso", ci))
        .height((h * 0.7).max(70.0))
        .width(side)
        .allow_drag(false)
        .allow_zoom(false)
        .allow_scroll(false)
        .x_axis_label("|k|")
        .y_axis_label("aniso. dB")
        .show(ui, |p| {
            p.line(Line::new("anisotropy", d.anisotropy.clone()));
        });
}

#[allow(clippy::too_many_arguments)]
fn zoneplate_panel(
    ui: &mut egui::Ui,
    ci: usize,
    scene: &Scene,
    col: Option<&ColumnResults>,
    view: &mut ViewState,
    gpu: bool,
    textures: &mut TextureCache,
    side: f32,
) {
    ui.horizontal_wrapped(|ui| {
        let lab = result_of(col, NodeKind::Reconstruction).map_or(scene, |r| r.scene.as_ref());
        ui.label(format!("{} {}²", lab.signal.name(), lab.recon.size));
        ui.selectable_value(&mut view.zone_image, ZoneImage::Reconstruction, "recon");
        ui.selectable_value(&mut view.zone_image, ZoneImage::Reference, "reference");
        ui.selectable_value(&mut view.zone_image, ZoneImage::Error, "error");
        figures::panel_menu_ui(
            ui,
            ci,
            &[
                PanelKind::Reconstruction,
                PanelKind::Reference,
                PanelKind::Error,
            ],
        );
    });
    if !scene.effects.reconstruction {
        ui.small("reconstruction effect is off");
        return;
    }
    let kind = match view.zone_image {
        ZoneImage::Reconstruction => NodeKind::Reconstruction,
        ZoneImage::Reference => NodeKind::Reference,
        ZoneImage::Error => NodeKind::Error,
    };
    let Some(r) = result_of(col, kind) else {
        if view.zone_image != ZoneImage::Reconstruction && !scene.effects.error {
            ui.small("reference/error effect is off");
        } else {
            ui.spinner();
        }
        return;
    };
    let grey = DisplayRange {
        lo: 0.0,
        hi: 1.0,
        log: false,
        colormap: Colormap::Greys,
    };
    let (image, range) = match &r.value {
        Ok(NodeValue::Reconstruction(d)) => (d.image.clone(), grey),
        Ok(NodeValue::Reference(d)) => (d.image.clone(), grey),
        Ok(NodeValue::Error(d)) => (
            d.image.clone(),
            DisplayRange {
                lo: 0.0,
                hi: d.max_error.max(1e-6),
                log: false,
                colormap: Colormap::Inferno,
            },
        ),
        Ok(_) => return,
        Err(e) => {
            error_label(ui, "reconstruction", e);
            return;
        }
    };
    let z = view.zoom.max(1) as f32;
    let s = 1.0 / z;
    let window = [0.5 - s / 2.0, 0.5 - s / 2.0, s, s];
    image_widget(
        ui,
        egui::Id::NULL.with(("zone", ci, kind)),
        &image,
        range,
        window,
        gpu,
        textures,
        side,
    );
    time_label(ui, r);
    if let Some(Ok(NodeValue::Reconstruction(d))) =
        result_of(col, NodeKind::Reconstruction).map(|r| &r.value)
    {
        if d.zero_weight > 0 {
            ui.colored_label(
                Color32::from_rgb(200, 120, 0),
                format!(
                    "{} pixels had zero filter weight (shown grey)",
                    d.zero_weight
                ),
            );
        }
    }
    if let Some(Ok(NodeValue::Error(e))) = result_of(col, NodeKind::Error).map(|r| &r.value) {
        ui.small(format!("RMSE {:.4} · PSNR {:.2} dB", e.rmse, e.psnr));
    }
    if let Some(r) = result_of(col, NodeKind::Reference) {
        if let Ok(NodeValue::Reference(rf)) = &r.value {
            // The node's own words: "≤" for a bound, "≈" for an estimate.
            let own = r.accuracy.as_ref().map(|a| format!(", {a}"));
            let refining = r
                .progress
                .map(|p| format!(" (refining {}/{})", p.step, p.steps));
            ui.small(format!(
                "reference: {}{}{}",
                rf.method,
                own.unwrap_or_default(),
                refining.unwrap_or_default()
            ));
        }
    }
}

fn filter_panel(
    ui: &mut egui::Ui,
    ci: usize,
    col: Option<&ColumnResults>,
    view: &mut ViewState,
    gpu: bool,
    textures: &mut TextureCache,
    side: f32,
) {
    ui.horizontal_wrapped(|ui| {
        ui.label("Filter");
        ui.checkbox(&mut view.response_db, "dB");
        figures::panel_menu_ui(ui, ci, &[PanelKind::Kernel, PanelKind::Response]);
    });
    let Some(r) = result_of(col, NodeKind::Response) else {
        ui.spinner();
        return;
    };
    let d = match &r.value {
        Ok(NodeValue::Response(d)) => d.clone(),
        Ok(_) => return,
        Err(e) => {
            error_label(ui, "filter", e);
            return;
        }
    };
    let h = (side * 0.3).max(60.0);
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
        });
    let db = view.response_db;
    let mag: Vec<[f64; 2]> = d
        .magnitude
        .iter()
        .map(|&[w, m]| [w, if db { 20.0 * m.max(1e-12).log10() } else { m }])
        .collect();
    let (one, zero) = if db { (0.0, -120.0) } else { (1.0, 0.0) };
    let ideal_parts = [
        vec![[0.0, one], [0.5, one]],
        vec![[0.5, one], [0.5, zero]],
        vec![[0.5, zero], [d.omega_max, zero]],
    ];
    Plot::new(("response", ci))
        .height(h)
        .width(side)
        .allow_drag(false)
        .allow_zoom(false)
        .allow_scroll(false)
        .x_axis_label("ω (cycles/sample)")
        .y_axis_label(if db { "|H| dB" } else { "|H|" })
        .show(ui, |p| {
            for part in &ideal_parts {
                p.line(Line::new("ideal low-pass", part.clone()).color(Color32::GRAY));
            }
            p.line(Line::new("|H(ω)|", mag));
            p.vline(VLine::new("Nyquist", 0.5).color(Color32::from_rgb(200, 60, 60)));
        });
    let range = DisplayRange {
        lo: 0.0,
        hi: 1.0,
        log: false,
        colormap: view.colormap,
    };
    image_widget(
        ui,
        egui::Id::NULL.with(("response2d", ci)),
        &d.image,
        range,
        [0.0, 0.0, 1.0, 1.0],
        gpu,
        textures,
        side * 0.6,
    );
    ui.small(format!("2D |H|, omega in [-{0}, {0}]²", d.omega_max));
    ui.small(
        d.metrics
            .iter()
            .map(|(k, v)| format!("{k} {v:.3}"))
            .collect::<Vec<_>>()
            .join(" · "),
    );
    time_label(ui, r);
}

/// A named convergence curve: (label, log-log RMSE vs spp, log-log RMSE vs ms).
type Curve = (String, Vec<[f64; 2]>, Vec<[f64; 2]>);

/// The cost view: every node's time and accuracy, and the convergence plot.
pub fn cost_ui(ui: &mut egui::Ui, scene: &Scene, results: &[ColumnResults], eval: &Evaluator) {
    ui.horizontal_top(|ui| {
        ui.vertical(|ui| {
            ui.strong("Cost per node");
            egui::Grid::new("cost-grid").striped(true).show(ui, |ui| {
                ui.label("column");
                for k in NodeKind::ALL {
                    ui.label(k.name());
                }
                ui.end_row();
                for (ci, col) in results.iter().enumerate() {
                    ui.label(scene.columns.get(ci).map(|c| c.title()).unwrap_or_default());
                    for k in NodeKind::ALL {
                        match col.get(&k) {
                            Some(r) => {
                                let t = format!("{:.1} ms", r.wall.as_secs_f64() * 1e3);
                                let resp = ui.label(t);
                                if let Some(a) = &r.accuracy {
                                    resp.on_hover_text(a);
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
                for k in NodeKind::ALL {
                    ui.label(eval.count(k).to_string());
                }
                ui.end_row();
            });
        });
        ui.vertical(|ui| {
            ui.strong("Convergence (log-log)");
            if !scene.effects.convergence {
                ui.small("turn on the convergence effect to compute it");
            }
            let curves: Vec<Curve> = results
                .iter()
                .enumerate()
                .filter_map(
                    |(ci, col)| match col.get(&NodeKind::Convergence).map(|r| &r.value) {
                        Some(Ok(NodeValue::Convergence(c))) => Some((
                            scene.columns.get(ci).map(|c| c.title()).unwrap_or_default(),
                            c.iter()
                                .map(|p| [(p.spp as f64).log10(), p.rmse.max(1e-12).log10()])
                                .collect(),
                            c.iter()
                                .map(|p| [p.millis.max(1e-3).log10(), p.rmse.max(1e-12).log10()])
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

/// Signal selection and its parameters (edited through the signal's serialised fields).
pub fn signal_ui(ui: &mut egui::Ui, signal: &mut crate::core::signal::Signal) {
    use crate::core::signal::Signal;
    let mut name = signal.name();
    egui::ComboBox::from_label("Signal")
        .selected_text(name)
        .show_ui(ui, |ui| {
            for s in Signal::all().iter().filter(|s| !s.is_1d()) {
                ui.selectable_value(&mut name, s.name(), s.name());
            }
        });
    if name != signal.name() {
        if let Some(s) = Signal::all().into_iter().find(|s| s.name() == name) {
            *signal = s;
        }
    }
    // Numeric fields as drag values; a change is kept only if the signal still validates.
    let Ok(serde_json::Value::Object(mut map)) = serde_json::to_value(*signal) else {
        return;
    };
    let mut changed = false;
    for (key, value) in map.iter_mut() {
        if key == "kind" {
            continue;
        }
        if let Some(mut v) = value.as_f64() {
            ui.horizontal(|ui| {
                let label = ui.label(key.as_str());
                let speed = (v.abs() * 0.01).max(0.001);
                if ui
                    .add(egui::DragValue::new(&mut v).speed(speed))
                    .labelled_by(label.id)
                    .changed()
                {
                    if let Some(n) = serde_json::Number::from_f64(v) {
                        *value = serde_json::Value::Number(n);
                        changed = true;
                    }
                }
            });
        } else if let Some(mut b) = value.as_bool() {
            if ui.checkbox(&mut b, key.as_str()).changed() {
                *value = serde_json::Value::Bool(b);
                changed = true;
            }
        }
    }
    if changed {
        if let Ok(s) = serde_json::from_value::<Signal>(serde_json::Value::Object(map)) {
            if s.validate().is_ok() {
                *signal = s;
            }
        }
    }
}

/// Filter selection, parameters (from the filter's descriptors), 2D mode and the
/// Mitchell–Netravali (B, C) picker.
pub fn filter_ui(ui: &mut egui::Ui, f2: &mut crate::core::filter::Filter2D) {
    use crate::core::filter::{Filter, Mode2D};
    let mut name = f2.filter.name();
    egui::ComboBox::from_label("Kernel")
        .selected_text(name)
        .show_ui(ui, |ui| {
            for f in Filter::all() {
                ui.selectable_value(&mut name, f.name(), f.name())
                    .on_hover_text(f.summary());
            }
        });
    if name != f2.filter.name() {
        if let Ok(f) = Filter::from_name(name) {
            f2.filter = f;
        }
    }
    ui.horizontal(|ui| {
        let mut mode = f2.mode;
        ui.selectable_value(&mut mode, Mode2D::Separable, "separable");
        ui.selectable_value(&mut mode, Mode2D::Radial, "radial");
        if mode != f2.mode {
            let candidate = crate::core::filter::Filter2D {
                filter: f2.filter,
                mode,
            };
            if candidate.validate().is_ok() {
                f2.mode = mode;
            }
        }
    });
    for spec in f2.filter.specs() {
        let Some(value) = f2.filter.get(spec.name) else {
            continue;
        };
        let text = param_ui(ui, &spec, value);
        if let Some(t) = text {
            let _ = f2.filter.set(spec.name, &t);
        }
    }
    if let Filter::Mitchell(m) = f2.filter {
        bc_picker(ui, f2, m.b, m.c);
    }
}

/// A square (B, C) ∈ [0,1]² picker with the B + 2C = 1 line (Mitchell–Netravali's family of
/// interpolating-quality filters) and the usual presets marked.
fn bc_picker(ui: &mut egui::Ui, f2: &mut crate::core::filter::Filter2D, b: f64, c: f64) {
    let side = 120.0;
    let (rect, resp) = ui.allocate_exact_size(Vec2::splat(side), egui::Sense::click_and_drag());
    let p = ui.painter_at(rect);
    p.rect_filled(rect, 0.0, Color32::from_gray(245));
    p.line_segment(
        [
            screen_from_unit(rect, [1.0, 0.0]),
            screen_from_unit(rect, [0.0, 0.5]),
        ],
        Stroke::new(1.0, Color32::from_gray(150)),
    );
    for (pb, pc) in [(1.0 / 3.0, 1.0 / 3.0), (0.0, 0.5), (1.0, 0.0)] {
        p.circle_stroke(
            screen_from_unit(rect, [pb, pc]),
            3.0,
            Stroke::new(1.0, Color32::GRAY),
        );
    }
    p.circle_filled(
        screen_from_unit(rect, [b, c]),
        4.0,
        Color32::from_rgb(200, 60, 60),
    );
    if let Some(pos) = resp.interact_pointer_pos() {
        let nb = ((pos.x - rect.left()) / rect.width()).clamp(0.0, 1.0) as f64;
        let nc = ((rect.bottom() - pos.y) / rect.height()).clamp(0.0, 1.0) as f64;
        let _ = f2.filter.set("b", &format!("{nb:?}"));
        let _ = f2.filter.set("c", &format!("{nc:?}"));
    }
    ui.small(format!("B = {b:.3}, C = {c:.3} (line: B + 2C = 1)"));
}

/// One control for a parameter descriptor (slider over its allowed range, logarithmic when the
/// range spans more than three decades; a combo box for choices). Returns the new value as
/// text when the user changed it, for the owner's range-checked `set`.
pub fn param_ui(
    ui: &mut egui::Ui,
    spec: &crate::core::pattern::params::ParamSpec,
    value: crate::core::pattern::params::ParamValue,
) -> Option<String> {
    use crate::core::pattern::params::{ParamKind, ParamValue};
    match (spec.kind.clone(), value) {
        (ParamKind::Int { min, max, .. }, ParamValue::Int(mut v)) => {
            let hi = max.min(min.saturating_add(100_000));
            let log = min >= 1 && hi > 1000 * min;
            ui.add(
                egui::Slider::new(&mut v, min..=hi)
                    .logarithmic(log)
                    .text(spec.name),
            )
            .on_hover_text(spec.doc)
            .changed()
            .then(|| v.to_string())
        }
        (ParamKind::Float { min, max, .. }, ParamValue::Float(mut v)) => {
            let log = min > 0.0 && max > 1000.0 * min;
            ui.add(
                egui::Slider::new(&mut v, min..=max)
                    .logarithmic(log)
                    .text(spec.name),
            )
            .on_hover_text(spec.doc)
            .changed()
            .then(|| format!("{v:?}"))
        }
        (ParamKind::Choice { options, .. }, ParamValue::Choice(current)) => {
            let mut chosen = current;
            egui::ComboBox::from_label(spec.name)
                .selected_text(current)
                .show_ui(ui, |ui| {
                    for o in options {
                        ui.selectable_value(&mut chosen, o, *o);
                    }
                });
            (chosen != current).then(|| chosen.to_string())
        }
        _ => None,
    }
}
