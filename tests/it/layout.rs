//! The layout rule on the real UI (egui_kittest, wgpu renderer): the pictures take the space
//! they are given. A panel's image grows with the window; lecture mode never makes a picture
//! smaller; captions wrap inside their cell; on 1920×1080 in lecture mode with the controls
//! hidden the default scene's pictures cover most of the window; a comparison's columns share
//! the width and its rows fit the height (in normal mode: lecture mode's larger text may make
//! a column scroll rather than shrink its pictures). These tests need a wgpu adapter; without one they
//! fail (they never skip).

use eframe::egui::{Rect, Vec2};
use egui_kittest::Harness;
use samplescope::scene::panels::PanelKind;
use samplescope::ui::panels::Picture;
use samplescope::ui::SamplescopeApp;

/// The app on `size` (points at one pixel per point) with `scene` (a built-in name; None: the
/// default), lecture mode and hidden controls as given, settled.
fn app(
    size: [f32; 2],
    scene: Option<&str>,
    lecture: bool,
    hidden: bool,
) -> Harness<'static, SamplescopeApp> {
    let mut h = Harness::builder()
        .with_size(Vec2::from(size))
        .wgpu()
        .build_eframe(|cc| {
            let mut app = crate::hermetic_app(cc);
            app.view.show_timings = false;
            app
        });
    if let Some(name) = scene {
        let text = samplescope::scene::BUILTIN
            .iter()
            .find(|(n, _)| *n == name)
            .unwrap_or_else(|| panic!("{name} is built in"))
            .1;
        let s = samplescope::scene::Scene::from_ron(text, name).unwrap();
        h.state_mut().set_scene(s, name.into());
    }
    h.state_mut().view.lecture = lecture;
    h.state_mut().view.controls_hidden = hidden;
    crate::settle(&mut h, 4);
    h
}

/// The pictures of the last frame, in screen pixels.
fn pictures(h: &Harness<'static, SamplescopeApp>) -> Vec<Picture> {
    let ppp = h.ctx.pixels_per_point();
    h.state()
        .pictures()
        .iter()
        .map(|p| Picture {
            rect: Rect::from_min_max(
                (p.rect.min.to_vec2() * ppp).to_pos2(),
                (p.rect.max.to_vec2() * ppp).to_pos2(),
            ),
            ..*p
        })
        .collect()
}

/// The side of the largest square image, in pixels.
fn largest_image(pics: &[Picture]) -> f32 {
    pics.iter()
        .filter(|p| p.image)
        .map(|p| p.rect.width().min(p.rect.height()))
        .fold(0.0, f32::max)
}

/// The pattern panel's image of column 0, in pixels.
fn pattern_image(pics: &[Picture]) -> Rect {
    pics.iter()
        .find(|p| p.image && p.kind == PanelKind::Pattern && p.column == 0)
        .expect("the pattern panel drew its image")
        .rect
}

#[test]
fn a_panels_image_grows_with_the_window() {
    let small = pattern_image(&pictures(&app([1000.0, 700.0], None, false, false)));
    let large = pattern_image(&pictures(&app([1800.0, 1100.0], None, false, false)));
    assert!(
        large.width() > small.width() * 1.3,
        "{small:?} at 1000×700, {large:?} at 1800×1100"
    );
    // Square, in both.
    for r in [small, large] {
        assert!((r.width() - r.height()).abs() < 0.5, "{r:?}");
    }
}

#[test]
fn lecture_mode_never_shrinks_the_pictures() {
    for (size, hidden) in [
        ([1400.0, 1000.0], false),
        ([1920.0, 1080.0], true),
        ([1100.0, 800.0], false),
    ] {
        let normal = pictures(&app(size, None, false, hidden));
        let lecture = pictures(&app(size, None, true, hidden));
        assert_eq!(normal.len(), lecture.len(), "{size:?}");
        for (n, l) in normal.iter().zip(&lecture) {
            assert_eq!((n.kind, n.column, n.image), (l.kind, l.column, l.image));
            if n.image {
                assert!(
                    l.rect.width() >= n.rect.width() - 0.5,
                    "{size:?}, controls hidden {hidden}: {:?}'s image {} px in lecture mode, {} px in normal mode",
                    n.kind,
                    l.rect.width(),
                    n.rect.width()
                );
            }
        }
    }
}

#[test]
fn captions_wrap_inside_their_cell() {
    // Narrow cells (two columns in a small window) and large text (lecture mode with the
    // controls shown): the statistics and the normaliser's caption must wrap rather than widen
    // their panel.
    for (lecture, size) in [(false, [1000.0, 800.0]), (true, [1920.0, 1080.0])] {
        let h = app(size, Some("two-columns.ron"), lecture, false);
        let app = h.state();
        let cells = app.panel_cells();
        assert!(cells.len() >= 4, "{cells:?}");
        let columns = app.column_rects();
        for c in cells {
            assert!(
                c.rect.width() <= c.width + 0.5,
                "lecture {lecture}: {:?} in column {} is {} wide in a cell of {}",
                c.kind,
                c.column,
                c.rect.width(),
                c.width
            );
            let col = columns[c.column];
            assert!(
                c.rect.left() >= col.left() - 0.5 && c.rect.right() <= col.right() + 0.5,
                "lecture {lecture}: {c:?} outside its column {col:?}"
            );
        }
        for p in app.pictures() {
            let cell = cells
                .iter()
                .find(|c| c.kind == p.kind && c.column == p.column)
                .expect("a picture belongs to a drawn cell");
            assert!(
                p.rect.width() <= cell.width + 0.5,
                "lecture {lecture}: {p:?} wider than its cell {}",
                cell.width
            );
        }
    }
}

#[test]
fn lecture_mode_on_1920x1080_gives_the_pictures_most_of_the_window() {
    let h = app([1920.0, 1080.0], None, true, true);
    let pics = pictures(&h);
    let window = 1920.0 * 1080.0;
    let covered: f32 = pics.iter().map(|p| p.rect.area()).sum();
    // The pictures do not overlap, so their areas add up to the area they cover.
    for (i, a) in pics.iter().enumerate() {
        for b in &pics[i + 1..] {
            assert!(
                a.rect.intersect(b.rect).area() < 1.0,
                "{a:?} overlaps {b:?}"
            );
        }
    }
    let largest = largest_image(&pics);
    println!(
        "1920×1080, lecture, controls hidden: largest image {largest:.0} px ({:.0} % of the height), pictures cover {:.0} % of the window",
        100.0 * largest / 1080.0,
        100.0 * covered / window
    );
    assert!(largest >= 0.4 * 1080.0, "largest image {largest} px");
    assert!(
        covered > 0.55 * window,
        "pictures cover {:.2}",
        covered / window
    );
    // Everything is on screen: nothing to scroll to.
    for p in &pics {
        assert!(
            p.rect.max.x <= 1920.5 && p.rect.max.y <= 1080.5,
            "{p:?} off screen"
        );
    }
}

#[test]
fn a_comparisons_columns_share_the_width_and_its_rows_fit_the_height() {
    for lecture in [false, true] {
        let h = app(
            [1920.0, 1080.0],
            Some("lattices-and-sequences.ron"),
            lecture,
            lecture,
        );
        let ppp = h.ctx.pixels_per_point();
        let app = h.state();
        let n = app.scene.columns.len();
        assert!(n >= 4, "{n} columns");
        let columns = app.column_rects();
        assert_eq!(columns.len(), n);
        for c in columns {
            assert!(
                c.right() * ppp <= 1920.5,
                "lecture {lecture}: column {c:?} past the window"
            );
        }
        let pics = pictures(&h);
        for p in &pics {
            // In lecture mode the larger text may push the last plots below the window (the
            // column scrolls) rather than make the pictures smaller than in normal mode.
            assert!(
                p.rect.max.x <= 1920.5 && (lecture || p.rect.max.y <= 1080.5),
                "lecture {lecture}: {p:?} off screen"
            );
        }
        // Every column shows its pictures at one size.
        let sides: Vec<f32> = pics
            .iter()
            .filter(|p| p.image && p.kind == PanelKind::Pattern)
            .map(|p| p.rect.width())
            .collect();
        assert_eq!(sides.len(), n);
        assert!(
            sides.iter().all(|s| (s - sides[0]).abs() < 0.5),
            "{sides:?}"
        );
        // And uses the width: n columns of a square each take most of it.
        assert!(
            sides[0] * n as f32 > 0.6 * 1920.0 || sides[0] > 0.3 * 1080.0,
            "lecture {lecture}: {n} columns of {} px",
            sides[0]
        );
    }
}

#[test]
fn starting_in_lecture_mode_hides_the_controls() {
    let mut h = Harness::builder()
        .with_size(Vec2::new(1280.0, 800.0))
        .wgpu()
        .build_eframe(|cc| {
            let mut app = crate::hermetic_app(cc);
            app.start_lecture();
            app
        });
    crate::settle(&mut h, 3);
    let app = h.state();
    assert!(app.view.lecture && app.view.controls_hidden);
    use egui_kittest::kittest::Queryable;
    assert!(h.query_by_label("Show controls").is_some());
    assert!((h.ctx.zoom_factor() - app.view.lecture_scale).abs() < 1e-6);
}
