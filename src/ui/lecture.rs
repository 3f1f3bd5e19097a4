//! Lecture mode: what changes when samplescope is shown on a projector.
//!
//! - a light theme with strong contrast (black text, thick strokes, no faint greys), because
//!   projectors wash out dark themes and thin lines;
//! - everything zoomed by one factor (fonts, widgets, plots), set by a slider;
//! - the content letterboxed to 16:9 so the panels fill a projector frame;
//! - the controls can be hidden (F9) and the window made full screen (F11).
//!
//! Only presentation changes: the scene, and so the compute graph, is the same in both modes.

use super::view::{ViewState, LECTURE_SCALE_DEFAULT, LECTURE_SCALE_RANGE};
use eframe::egui::{self, Color32, Rect, Stroke, Theme, Vec2};

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

/// The largest rectangle of aspect 16:9 in `rect`, centred horizontally and at the top (so the
/// panels stay under the top bar rather than floating mid-screen).
pub fn letterbox_16_9(rect: Rect) -> Rect {
    const ASPECT: f32 = 16.0 / 9.0;
    let (w, h) = (rect.width().max(0.0), rect.height().max(0.0));
    let size = if w > h * ASPECT {
        Vec2::new(h * ASPECT, h)
    } else {
        Vec2::new(w, w / ASPECT)
    };
    Rect::from_min_size(
        egui::Pos2::new(rect.center().x - size.x / 2.0, rect.top()),
        size,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use eframe::egui::Pos2;

    #[test]
    fn letterbox_keeps_16_9_and_stays_inside() {
        for (w, h) in [
            (1600.0, 1000.0),
            (1000.0, 1600.0),
            (1920.0, 1080.0),
            (0.0, 10.0),
        ] {
            let outer = Rect::from_min_size(Pos2::new(10.0, 20.0), Vec2::new(w, h));
            let r = letterbox_16_9(outer);
            assert!(outer.expand(1e-3).contains_rect(r), "{r:?} in {outer:?}");
            if r.height() > 0.0 {
                assert!((r.width() / r.height() - 16.0 / 9.0).abs() < 1e-4);
            }
            // One side touches the outer rectangle: it is the largest such box.
            assert!(
                (r.width() - outer.width()).abs() < 1e-3
                    || (r.height() - outer.height()).abs() < 1e-3
            );
        }
    }

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
