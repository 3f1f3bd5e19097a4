//! Editors of the scene's parameters: the pattern of a column, the signal, the filter, and one
//! control per parameter descriptor. One entry point per editor: [`pattern_ui`],
//! [`signal_ui`], [`filter_ui`]; [`param_ui`] is the control they share (the theorem panel
//! uses it for its filter too).

use crate::core::pattern::Pattern;
use crate::scene::Column;
use crate::ui::view::screen_from_unit;
use eframe::egui::{self, Color32, Stroke, Vec2};

/// Pattern selection and parameter sliders generated from the pattern's descriptors.
pub fn pattern_ui(ui: &mut egui::Ui, column: &mut Column) {
    let mut name = column.pattern.name();
    egui::ComboBox::from_label("Pattern")
        .selected_text(name)
        .show_ui(ui, |ui| {
            for p in Pattern::all() {
                ui.selectable_value(&mut name, p.name(), p.name())
                    .on_hover_text(p.summary());
            }
        });
    if name != column.pattern.name() {
        if let Ok(p) = Pattern::from_name(name) {
            column.pattern = p;
        }
    }
    for spec in column.pattern.specs() {
        let Some(value) = column.pattern.get(spec.name) else {
            continue;
        };
        let text = param_ui(ui, &spec, value);
        if let Some(t) = text {
            // The slider's range is the parameter's range, so this cannot fail; if it did, the
            // old value stays.
            let _ = column.pattern.set(spec.name, &t);
        }
    }
    let mut seed = column.seed;
    ui.horizontal(|ui| {
        let label = ui.label("seed");
        ui.add(egui::DragValue::new(&mut seed))
            .labelled_by(label.id);
    });
    column.seed = seed;
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
