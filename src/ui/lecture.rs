//! Lecture mode: what changes when samplescope is shown on a projector.
//!
//! - a light theme with strong contrast (black text, thick strokes, no faint greys), because
//!   projectors wash out dark themes and thin lines;
//! - the text zoomed by one factor (fonts, widgets, plot labels), set by a slider, while the
//!   pictures keep at least the size they have in normal mode: the margins and gaps around
//!   them keep their size on screen, the controls their width, and the column grid never
//!   makes an image smaller than normal-sized text would (`ui::columns`);
//! - the controls can be hidden (F9) and the window made full screen (F11);
//!   `samplescope --lecture` starts that way.
//!
//! Only presentation changes: the scene, and so the compute graph, is the same in both modes.

use super::view::{ViewState, LECTURE_SCALE_DEFAULT, LECTURE_SCALE_RANGE};
use eframe::egui::{self, Color32, Stroke, Theme};

/// The style last applied to the context, so that it is set only when it changes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AppliedStyle {
    lecture: bool,
    scale: f32,
}

/// The projector-friendly light visuals.
pub fn projector_visuals() -> egui::Visuals {
    let mut v = egui::Visuals::light();
    v.override_text_color = Some(Color32::BLACK);
    v.panel_fill = Color32::WHITE;
    v.window_fill = Color32::WHITE;
    v.extreme_bg_color = Color32::WHITE;
    v.faint_bg_color = Color32::from_gray(240);
    let strong = Stroke::new(1.5, Color32::from_gray(40));
    v.widgets.noninteractive.bg_stroke = Stroke::new(1.0, Color32::from_gray(120));
    v.widgets.noninteractive.fg_stroke = strong;
    v.widgets.inactive.fg_stroke = strong;
    v.widgets.inactive.bg_stroke = Stroke::new(1.0, Color32::from_gray(90));
    v.widgets.hovered.fg_stroke = Stroke::new(2.0, Color32::BLACK);
    v.widgets.active.fg_stroke = Stroke::new(2.0, Color32::BLACK);
    v.selection.bg_fill = Color32::from_rgb(255, 200, 60);
    v.selection.stroke = Stroke::new(2.0, Color32::BLACK);
    v
}

/// Applies the theme and zoom of `view` to `ctx` when they differ from `applied`.
///
/// Returns whether anything was changed (the zoom takes effect from the next frame).
pub fn apply_style(
    ctx: &egui::Context,
    view: &ViewState,
    applied: &mut Option<AppliedStyle>,
) -> bool {
    let scale = clamp_scale(view.lecture_scale);
    let want = AppliedStyle {
        lecture: view.lecture,
        scale: if view.lecture { scale } else { 1.0 },
    };
    if *applied == Some(want) {
        return false;
    }
    if want.lecture {
        ctx.set_visuals_of(Theme::Light, projector_visuals());
        ctx.set_theme(Theme::Light);
    } else if applied.is_some_and(|a| a.lecture) {
        ctx.set_visuals_of(Theme::Light, egui::Visuals::light());
        ctx.set_theme(egui::ThemePreference::System);
    }
    ctx.set_zoom_factor(want.scale);
    *applied = Some(want);
    true
}

/// The lecture scale limited to its range (a NaN or out-of-range persisted value falls back
/// to the nearest end, or the default for NaN).
pub fn clamp_scale(scale: f32) -> f32 {
    if scale.is_nan() {
        return LECTURE_SCALE_DEFAULT;
    }
    scale.clamp(*LECTURE_SCALE_RANGE.start(), *LECTURE_SCALE_RANGE.end())
}

/// `px` screen pixels (at one pixel per point) in points at the context's zoom, rounded down:
/// a margin that keeps its size on screen when lecture mode zooms the text.
pub fn unzoomed_margin(ctx: &egui::Context, px: i8) -> i8 {
    (f32::from(px) / ctx.zoom_factor().max(1.0)).floor() as i8
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scale_is_limited_to_its_range() {
        assert_eq!(clamp_scale(0.1), 1.0);
        assert_eq!(clamp_scale(10.0), 3.0);
        assert_eq!(clamp_scale(2.0), 2.0);
        assert_eq!(clamp_scale(f32::NAN), LECTURE_SCALE_DEFAULT);
    }

    #[test]
    fn projector_theme_is_light_with_black_text() {
        let v = projector_visuals();
        assert!(!v.dark_mode);
        assert_eq!(v.override_text_color, Some(Color32::BLACK));
        assert_eq!(v.panel_fill, Color32::WHITE);
    }
}
