//! Editors of the scene's parameters: the pattern of a column, the signal, the filter, and one
//! control per parameter descriptor. One entry point per editor: [`pattern_ui`],
//! [`signal_ui`], [`filter_ui`], [`integrand_ui`]; [`family_ui`] (the one picker of a family
//! member), [`params_ui`] and [`param_ui`] are the controls they share (the theorem panel uses
//! them for its signal and filter too).

use crate::core::family::Family;
use crate::core::params::{ParamKind, ParamSpec, ParamValue, Params};
use crate::scene::Column;
use crate::ui::view::screen_from_unit;
use eframe::egui::{self, Color32, Stroke, Vec2};

/// The one picker of a family member (pattern, filter, signal, integrand): a combo box
/// `label` (`id` keeps two pickers with one label apart) of the members `offer` accepts, each
/// with its summary on hover; picking another member gives it its default parameters.
pub fn family_ui<F: Family>(
    ui: &mut egui::Ui,
    id: &str,
    label: &str,
    member: &mut F,
    offer: impl Fn(&F) -> bool,
) {
    let mut name = member.name();
    egui::ComboBox::new(id, label)
        .selected_text(name)
        .show_ui(ui, |ui| {
            for m in F::all().iter().filter(|m| offer(m)) {
                ui.selectable_value(&mut name, m.name(), m.name())
                    .on_hover_text(m.summary());
            }
        });
    if name != member.name() {
        if let Ok(m) = F::from_name(name) {
            *member = m;
        }
    }
}

/// Pattern selection, its dimensions (for a pattern defined in d dimensions) and one control
/// per parameter descriptor; `n` is the scene's N (N·D bounds D).
pub fn pattern_ui(ui: &mut egui::Ui, column: &mut Column, n: usize) {
    family_ui(ui, "Pattern", "Pattern", &mut column.pattern, |_| true);
    if column.points.is_none() {
        dims_ui(ui, column, n);
    }
    params_ui(ui, &mut column.pattern);
    let mut seed = column.seed;
    ui.horizontal(|ui| {
        let label = ui.label("seed");
        ui.add(egui::DragValue::new(&mut seed))
            .labelled_by(label.id);
    });
    column.seed = seed;
}

/// The largest D a column of `pattern` may have with N = `n` (`Scene::validate`'s range:
/// the pattern's `max_dims`, and N·D within the coordinates a point set holds).
pub fn max_column_dims(pattern: &crate::core::pattern::Pattern, n: usize) -> usize {
    let max = pattern.max_dims();
    if max == 2 {
        return 2;
    }
    max.min(crate::core::cube::MAX_COORDS / n.max(1)).max(2)
}

/// A column's dimension D (a drag over exactly the range the scene allows, shown for the
/// patterns defined in d dimensions) and, for D > 2, its dimension-pair picker: the pair
/// (i, j) its 2D panels show. A pattern picked without a d-dimensional form takes the column
/// back to D = 2; a smaller D that drops a shown dimension shows (0, 1).
pub fn dims_ui(ui: &mut egui::Ui, column: &mut Column, n: usize) {
    use crate::scene::{DEFAULT_DIMS, DEFAULT_PROJECT};
    let max = max_column_dims(&column.pattern, n);
    if column.dims > column.pattern.max_dims() {
        // The user picked a 2D-only pattern (or one with fewer dimensions).
        column.dims = DEFAULT_DIMS;
        column.project = DEFAULT_PROJECT;
    }
    if max <= 2 && column.dims == 2 && column.project == DEFAULT_PROJECT {
        return;
    }
    let mut dims = column.dims;
    ui.horizontal(|ui| {
        let label = ui.label("dims");
        ui.add(egui::DragValue::new(&mut dims).range(2..=max.max(column.dims)))
            .labelled_by(label.id)
            .on_hover_text(
                "the dimension D of the column's points; its 2D panels show the projection \
                 onto the pair of dimensions picked beside",
            );
    });
    if dims != column.dims {
        column.dims = dims;
        let (i, j) = column.project;
        if i >= dims || j >= dims {
            column.project = DEFAULT_PROJECT;
        }
    }
    if column.dims <= 2 && column.project == DEFAULT_PROJECT {
        return;
    }
    let d = column.dims;
    let mut pair = [column.project.0, column.project.1];
    ui.horizontal(|ui| {
        ui.label("projection");
        for (a, (salt, axis)) in [("project-i", "pair x"), ("project-j", "pair y")]
            .into_iter()
            .enumerate()
        {
            let other = pair[1 - a];
            let mut v = pair[a];
            egui::ComboBox::new(salt, axis)
                .selected_text(format!("x{v}"))
                .height(400.0)
                .show_ui(ui, |ui| {
                    for k in (0..d).filter(|&k| k != other) {
                        ui.selectable_value(&mut v, k, format!("x{k}"));
                    }
                });
            pair[a] = v;
        }
    })
    .response
    .on_hover_text("the pair of dimensions (i, j) the column's 2D panels show");
    column.project = (pair[0], pair[1]);
}

/// How a supersampling column gives its pixels their samples: per pixel, one pattern over the
/// image plane, or ZSobol.
pub fn pixel_sampling_ui(ui: &mut egui::Ui, column: &mut Column) {
    use crate::scene::PixelSampling;
    let mut choice = column.pixels;
    egui::ComboBox::from_label("Pixel samples")
        .selected_text(choice.name())
        .show_ui(ui, |ui| {
            for p in [
                PixelSampling::PerPixel,
                PixelSampling::ImagePlane { tile: 0 },
                PixelSampling::ZSobol,
            ] {
                let selected = std::mem::discriminant(&choice) == std::mem::discriminant(&p);
                if ui.selectable_label(selected, p.name()).clicked() && !selected {
                    choice = p;
                }
            }
        })
        .response
        .on_hover_text(
            "per-pixel: an independent copy of the pattern in every pixel; image-plane: one \
             pattern over the whole image, each pixel takes its points; zsobol: one Sobol' \
             sequence over the pixels in Morton order (blue-noise error)",
        );
    column.pixels = choice;
}

/// One control per parameter descriptor of `params`; a change is applied only if the whole
/// set stays valid ([`Params::set_value`]).
pub fn params_ui(ui: &mut egui::Ui, params: &mut impl Params) {
    labelled_params_ui(ui, params, "");
}

/// As [`params_ui`], each control labelled `prefix` + the parameter's name (the theorem panel
/// has a signal radius and a filter radius).
pub fn labelled_params_ui(ui: &mut egui::Ui, params: &mut impl Params, prefix: &str) {
    for spec in params.specs() {
        let Some(value) = params.get(spec.name) else {
            continue;
        };
        if let Some(v) = param_ui(ui, &spec, &format!("{prefix}{}", spec.name), value) {
            let _ = params.set_value(spec.name, &v);
        }
    }
}

/// One setting `key` of `params` (a scene setting) through its descriptor: the widget's kind
/// and range are the descriptor's, the label is `label`, the hover text the descriptor's doc.
/// A change is applied only if the whole set stays valid. Returns whether it changed.
pub fn setting_ui(ui: &mut egui::Ui, params: &mut impl Params, key: &str, label: &str) -> bool {
    let (Some(spec), Some(value)) = (params.spec(key), params.get(key)) else {
        return false;
    };
    match param_ui(ui, &spec, label, value) {
        Some(v) => params.set_value(key, &v).is_ok(),
        None => false,
    }
}

/// Signal selection (the 2D signals) and its parameters.
pub fn signal_ui(ui: &mut egui::Ui, signal: &mut crate::core::signal::Signal) {
    family_ui(ui, "Signal", "Signal", signal, |s| !s.is_1d());
    params_ui(ui, signal);
}

/// Integrand selection (the integration study's families) and its parameters.
pub fn integrand_ui(ui: &mut egui::Ui, f: &mut crate::core::integration::Integrand) {
    family_ui(ui, "Integrand", "Integrand", f, |_| true);
    params_ui(ui, f);
}

/// Filter selection, parameters (from the filter's descriptors), 2D mode and the
/// Mitchell–Netravali (B, C) picker.
pub fn filter_ui(ui: &mut egui::Ui, f2: &mut crate::core::filter::Filter2D) {
    use crate::core::filter::{Filter, Mode2D};
    family_ui(ui, "Kernel", "Kernel", &mut f2.filter, |_| true);
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
    params_ui(ui, &mut f2.filter);
    if let Filter::Mitchell(m) = f2.filter {
        bc_picker(ui, f2, m.b, m.c);
    }
    if let Some(why) = reconstruction_refusal(f2) {
        // The kernel stays selectable (its panels show both domains), but the reconstruction
        // panels show this refusal instead of an image.
        ui.colored_label(Color32::from_rgb(200, 120, 0), why);
    }
}

/// [`Filter2D::reconstruction_refusal`](crate::core::filter::Filter2D::reconstruction_refusal)
/// of the last filter asked about, cached: it integrates the kernel, and the controls are
/// drawn every frame.
fn reconstruction_refusal(f2: &crate::core::filter::Filter2D) -> Option<String> {
    use std::cell::RefCell;
    type Cached = Option<(crate::core::filter::Filter2D, Option<String>)>;
    thread_local!(static LAST: RefCell<Cached> = const { RefCell::new(None) });
    LAST.with(|last| {
        let mut last = last.borrow_mut();
        match &*last {
            Some((f, why)) if f == f2 => why.clone(),
            _ => {
                let why = f2.reconstruction_refusal();
                *last = Some((*f2, why.clone()));
                why
            }
        }
    })
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
        let _ = f2.filter.set_value("b", &ParamValue::Float(nb));
        let _ = f2.filter.set_value("c", &ParamValue::Float(nc));
    }
    ui.small(format!("B = {b:.3}, C = {c:.3} (line: B + 2C = 1)"));
}

/// Integer and float ranges wider than this get a drag value instead of a slider.
const SLIDER_SPAN: f64 = 10_000.0;

/// One control for a parameter descriptor, spanning exactly the descriptor's range (so a
/// valid value is never clamped): a slider (logarithmic over more than three decades) or, for
/// very wide ranges, a drag value; for a signed scale, a logarithmic slider of its magnitude
/// and a checkbox for its sign; a checkbox for booleans; a combo box for choices; one drag
/// value per entry of a list. Returns the new value when the user changed it.
pub fn param_ui(
    ui: &mut egui::Ui,
    spec: &ParamSpec,
    label: &str,
    value: ParamValue,
) -> Option<ParamValue> {
    match (&spec.kind, value) {
        (&ParamKind::Int { min, max, .. }, ParamValue::Int(mut v)) => {
            let changed = if (max - min) as f64 > SLIDER_SPAN {
                ui.horizontal(|ui| {
                    let label = ui.label(label);
                    ui.add(egui::DragValue::new(&mut v).range(min..=max))
                        .labelled_by(label.id)
                        .on_hover_text(spec.doc)
                        .changed()
                })
                .inner
            } else {
                let log = min >= 1 && max > 1000 * min;
                ui.add(
                    egui::Slider::new(&mut v, min..=max)
                        .logarithmic(log)
                        .text(label),
                )
                .on_hover_text(spec.doc)
                .changed()
            };
            changed.then_some(ParamValue::Int(v))
        }
        (
            &ParamKind::Float {
                min,
                max,
                max_exclusive,
                ..
            },
            ParamValue::Float(mut v),
        ) => {
            // An open upper end (`[0, 1)`) stops the widget at the largest value below it.
            let max = if max_exclusive { next_below(max) } else { max };
            let log = min > 0.0 && max > 1000.0 * min;
            let changed = if !log && max - min > SLIDER_SPAN {
                ui.horizontal(|ui| {
                    let label = ui.label(label);
                    let speed = (v.abs() * 0.01).max(0.01);
                    ui.add(egui::DragValue::new(&mut v).range(min..=max).speed(speed))
                        .labelled_by(label.id)
                        .on_hover_text(spec.doc)
                        .changed()
                })
                .inner
            } else {
                ui.add(
                    egui::Slider::new(&mut v, min..=max)
                        .logarithmic(log)
                        .text(label),
                )
                .on_hover_text(spec.doc)
                .changed()
            };
            changed.then_some(ParamValue::Float(v))
        }
        (&ParamKind::Scale { min, max, .. }, ParamValue::Float(v)) => {
            // |v| on a logarithmic slider over its allowed range (a scale is a ratio) and the
            // sign on a checkbox, so that a negative value is shown as it is, never clamped.
            let mut magnitude = v.abs();
            let mut negative = v < 0.0;
            let changed = ui
                .horizontal(|ui| {
                    let m = ui
                        .add(
                            egui::Slider::new(&mut magnitude, min..=max)
                                .logarithmic(true)
                                .text(label),
                        )
                        .on_hover_text(spec.doc);
                    let sign = ui.checkbox(&mut negative, format!("{} < 0", spec.name));
                    m.changed() || sign.changed()
                })
                .inner;
            changed.then_some(ParamValue::Float(if negative {
                -magnitude
            } else {
                magnitude
            }))
        }
        (ParamKind::Choice { options, .. }, ParamValue::Choice(current)) => {
            let mut chosen = current;
            egui::ComboBox::from_label(label)
                .selected_text(current)
                .show_ui(ui, |ui| {
                    for o in options.iter() {
                        ui.selectable_value(&mut chosen, o, *o);
                    }
                });
            (chosen != current).then_some(ParamValue::Choice(chosen))
        }
        (ParamKind::Bool { .. }, ParamValue::Bool(mut b)) => ui
            .checkbox(&mut b, label)
            .on_hover_text(spec.doc)
            .changed()
            .then_some(ParamValue::Bool(b)),
        (&ParamKind::List { min, max, .. }, ParamValue::List(items)) => {
            list_ui(ui, label, spec.doc, items, min, max).map(ParamValue::List)
        }
        // A value per dimension: its one number or its list, one drag value per entry.
        (&ParamKind::PerDim { min, max, .. }, ParamValue::Float(v)) => {
            list_ui(ui, label, spec.doc, vec![v], min, max).map(|v| ParamValue::Float(v[0]))
        }
        (&ParamKind::PerDim { min, max, .. }, ParamValue::List(items)) => {
            list_ui(ui, label, spec.doc, items, min, max).map(ParamValue::List)
        }
        // A list of integers: one integer drag value per entry; one not given says so (it is
        // given on the command line or in the scene file, its length is the dimension).
        (ParamKind::IntList { .. }, ParamValue::List(items)) if items.is_empty() => {
            ui.label(format!("{label}: not given"))
                .on_hover_text(spec.doc);
            None
        }
        (&ParamKind::IntList { min, max }, ParamValue::List(items)) => {
            let mut ints: Vec<i64> = items.iter().map(|&x| x as i64).collect();
            let changed = ui
                .horizontal(|ui| {
                    let label = ui.label(label).on_hover_text(spec.doc);
                    let mut changed = false;
                    for x in ints.iter_mut() {
                        changed |= ui
                            .add(egui::DragValue::new(x).range(min..=max).speed(1.0))
                            .labelled_by(label.id)
                            .changed();
                    }
                    changed
                })
                .inner;
            changed.then(|| ParamValue::List(ints.iter().map(|&x| x as f64).collect()))
        }
        _ => None,
    }
}

/// One drag value per entry of a list, each over `[min, max]`; the list when one changed.
fn list_ui(
    ui: &mut egui::Ui,
    label: &str,
    doc: &str,
    mut items: Vec<f64>,
    min: f64,
    max: f64,
) -> Option<Vec<f64>> {
    let changed = ui
        .horizontal(|ui| {
            let label = ui.label(label).on_hover_text(doc);
            let mut changed = false;
            for x in items.iter_mut() {
                let speed = (x.abs() * 0.01).max(0.01);
                changed |= ui
                    .add(egui::DragValue::new(x).range(min..=max).speed(speed))
                    .labelled_by(label.id)
                    .changed();
            }
            changed
        })
        .inner;
    changed.then_some(items)
}

/// The largest f64 below `x` (finite `x`; `f64::next_down` needs Rust 1.86).
fn next_below(x: f64) -> f64 {
    if x > 0.0 {
        f64::from_bits(x.to_bits() - 1)
    } else if x == 0.0 {
        -f64::from_bits(1)
    } else {
        f64::from_bits(x.to_bits() + 1)
    }
}
