//! The scene's prefix (the first k points of columns that play in order): the shown points are
//! the first k of the full run; the spectrum and statistics of a prefix are those of a k-point
//! file; moving k slices the cached run (one generation); a scene without prefix computes no
//! sequence; a bad prefix is one line naming the field and the range.

use samplescope::core::cancel::Cancel;
use samplescope::core::pattern::Pattern;
use samplescope::engine::Evaluator;
use samplescope::scene::graph::{NodeKind, NodeResult, NodeValue};
use samplescope::scene::{ImportedPoints, Panels, Scene};
use std::collections::HashMap;
use std::sync::Arc;

fn prefix_scene(pattern: Pattern, n: usize, k: Option<usize>) -> Scene {
    let mut s = Scene::default();
    s.columns[0].pattern = pattern;
    s.columns[0].seed = 7;
    s.n = n;
    s.prefix = k;
    s.panels = Panels {
        pattern: true,
        spectrum: true,
        ..Panels::none()
    };
    s.effects.reconstruction = false;
    s.effects.error = false;
    s.effects.statistics = true;
    s.spectrum.size = 32;
    s.spectrum.exact = true;
    s
}

fn results(eval: &Evaluator, scene: &Scene) -> Vec<HashMap<NodeKind, Arc<NodeResult>>> {
    let mut out = vec![HashMap::new(); scene.columns.len()];
    eval.evaluate(scene, &Cancel::new(), &mut |c, k, r| {
        assert!(r.value.is_ok(), "{k:?}: {:?}", r.value.as_ref().err());
        out[c].insert(k, r);
    });
    out
}

fn points(r: &HashMap<NodeKind, Arc<NodeResult>>) -> Vec<glam::DVec2> {
    match r[&NodeKind::Points].value.as_ref().unwrap() {
        NodeValue::Points(p) => p.points.clone(),
        _ => unreachable!(),
    }
}

fn power(r: &HashMap<NodeKind, Arc<NodeResult>>) -> Vec<u64> {
    match r[&NodeKind::Spectrum].value.as_ref().unwrap() {
        NodeValue::Spectrum(s) => s.power.power.iter().map(|v| v.to_bits()).collect(),
        _ => unreachable!(),
    }
}

fn stats(r: &HashMap<NodeKind, Arc<NodeResult>>) -> String {
    match r[&NodeKind::Statistics].value.as_ref().unwrap() {
        NodeValue::Statistics(s) => format!(
            "{:?} {:?} {:?} {:?} {:?}",
            s.min_distance.to_bits(),
            s.star,
            s.l2_star.to_bits(),
            s.t_value,
            s.psa
        ),
        _ => unreachable!(),
    }
}

fn bits(p: &[glam::DVec2]) -> Vec<(u64, u64)> {
    p.iter().map(|q| (q.x.to_bits(), q.y.to_bits())).collect()
}

/// Every pattern that plays in order, at a few k: the shown points are the first k of the
/// pattern's N-point run, and a progressive one's are its k-point run.
#[test]
fn the_prefix_shows_the_first_k_points_of_the_run() {
    let n = 256;
    let eval = Evaluator::default();
    let players: Vec<Pattern> = Pattern::all()
        .into_iter()
        .filter(|p| p.plays_in_order())
        .collect();
    assert!(players.len() >= 9, "{players:?}");
    for p in players {
        let full = p.generate(n, 7).unwrap();
        for k in [1, 5, 64, 100, 256] {
            let r = results(&eval, &prefix_scene(p, n, Some(k)));
            let shown = points(&r[0]);
            assert_eq!(bits(&shown), bits(&full[..k]), "{} k = {k}", p.name());
            if p.is_progressive() {
                assert_eq!(
                    bits(&shown),
                    bits(&p.generate(k, 7).unwrap()),
                    "{}",
                    p.name()
                );
            }
        }
    }
}

/// The spectrum and statistics of a prefix equal those of a file holding the k points.
#[test]
fn a_prefix_s_spectrum_and_statistics_are_those_of_a_k_point_file() {
    let dir = std::env::temp_dir().join(format!("samplescope-prefix-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let eval = Evaluator::default();
    for (p, k) in [
        (Pattern::from_name("sobol").unwrap(), 64),
        (Pattern::from_name("halton").unwrap(), 100),
        (Pattern::from_name("poisson-dart").unwrap(), 37),
    ] {
        let scene = prefix_scene(p, 256, Some(k));
        let r = results(&eval, &scene);
        let shown = points(&r[0]);
        // The k points as a text file (shortest round-trip digits), read back as a column.
        let path = dir.join(format!("{}-{k}.txt", p.name()));
        let text: String = shown
            .iter()
            .map(|q| format!("{:?} {:?}\n", q.x, q.y))
            .collect();
        std::fs::write(&path, text).unwrap();
        let mut file_scene = prefix_scene(p, 256, None);
        file_scene.n = k;
        file_scene.columns[0].points = Some(ImportedPoints::from_file(&path, false).unwrap());
        let f = results(&eval, &file_scene);
        assert_eq!(bits(&points(&f[0])), bits(&shown), "{}", p.name());
        assert_eq!(power(&f[0]), power(&r[0]), "{} spectrum", p.name());
        assert_eq!(stats(&f[0]), stats(&r[0]), "{} statistics", p.name());
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// Moving k slices the cached run: the sequence is generated once for every k; a scene
/// without prefix computes no sequence (its points are generated directly, as before).
#[test]
fn moving_the_prefix_slices_the_cached_run() {
    let eval = Evaluator::default();
    let p = Pattern::from_name("pmj02").unwrap();
    results(&eval, &prefix_scene(p, 1024, None));
    assert_eq!(eval.count(NodeKind::Sequence), 0);
    assert_eq!(eval.count(NodeKind::Points), 1);
    eval.reset_counts();
    for k in [16, 17, 512, 1024, 3] {
        results(&eval, &prefix_scene(p, 1024, Some(k)));
    }
    assert_eq!(eval.count(NodeKind::Sequence), 1);
    assert_eq!(eval.count(NodeKind::Points), 5);
    assert_eq!(eval.count(NodeKind::Spectrum), 5);
    // Back to a k seen before: everything is cached.
    eval.reset_counts();
    results(&eval, &prefix_scene(p, 1024, Some(512)));
    assert!(eval.counts().iter().all(|(_, c)| *c == 0));
}

/// A prefix out of 1..=N, or with a column that does not play in order, is one line naming
/// `prefix` and what is allowed.
#[test]
fn a_bad_prefix_names_the_field_and_the_range() {
    let sobol = Pattern::from_name("sobol").unwrap();
    for k in [0, 257] {
        let e = prefix_scene(sobol, 256, Some(k))
            .validate("x")
            .unwrap_err()
            .to_string();
        assert!(e.contains("prefix") && e.contains("1..=256"), "{e}");
        assert_eq!(e.lines().count(), 1, "{e}");
    }
    let e = prefix_scene(Pattern::default(), 256, Some(4))
        .validate("x")
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("prefix") && e.contains("jitter") && e.contains("sobol"),
        "{e}"
    );
    prefix_scene(sobol, 256, Some(256)).validate("x").unwrap();
    let mut s = prefix_scene(sobol, 256, None);
    s.animation.frames = 1;
    let e = s.validate("x").unwrap_err().to_string();
    assert!(e.contains("animation.frames") && e.contains("1000"), "{e}");
    s.animation.frames = 48;
    s.animation.fps = 60.0;
    let e = s.validate("x").unwrap_err().to_string();
    assert!(e.contains("animation.fps") && e.contains("50"), "{e}");
}

/// The shipped scenes' notes name the player's controls, not the draw-only slider it replaced.
#[test]
fn notes_name_the_player_s_controls() {
    use samplescope::scene::BUILTIN;
    for (name, text) in BUILTIN {
        let s = Scene::from_ron(text, name).unwrap();
        assert!(!s.notes.contains("first i points"), "{name}: {}", s.notes);
        if s.notes.contains("first k points") {
            assert!(
                s.animates().is_some() || s.columns.iter().any(|c| c.pattern.plays_in_order()),
                "{name}: its notes name the player, which it cannot show"
            );
        }
    }
    let text = BUILTIN
        .iter()
        .find(|(n, _)| *n == "dart-throwing-step-by-step.ron")
        .unwrap()
        .1;
    let dart = Scene::from_ron(text, "dart").unwrap();
    assert!(dart.notes.contains("Play") && dart.notes.contains("'first k points'"));
    assert!(dart.plays_prefix());
}

/// Which scenes animate: motion, or every column in order; the others do not.
#[test]
fn which_shipped_scenes_animate() {
    use samplescope::scene::{Animates, BUILTIN};
    let mut motion = 0;
    let mut prefix = Vec::new();
    for (name, text) in BUILTIN {
        let s = Scene::from_ron(text, name).unwrap();
        match s.animates() {
            Some(Animates::Motion) => motion += 1,
            Some(Animates::Prefix) => prefix.push(*name),
            None => {}
        }
    }
    assert_eq!(motion, 3);
    assert!(
        prefix.contains(&"dart-throwing-step-by-step.ron"),
        "{prefix:?}"
    );
    assert!(prefix.contains(&"sobol-net.ron"), "{prefix:?}");
}

/// The player of a prefix in the GUI: the slider sets k (the pattern panel's data holds k
/// points), play advances k frame by frame, a still scene shows no player.
mod gui {
    use eframe::egui::accesskit::Role;
    use egui_kittest::kittest::Queryable;
    use egui_kittest::Harness;
    use samplescope::model::{PointsData, Slot};
    use samplescope::ui::SamplescopeApp;
    use std::time::{Duration, Instant};

    fn harness(name: &str) -> Harness<'static, SamplescopeApp> {
        crate::builtin_harness(name, |s| s.spectrum.size = s.spectrum.size.min(32))
    }

    fn shown(h: &Harness<'static, SamplescopeApp>) -> usize {
        match h.state().data[0].get::<PointsData>() {
            Slot::Ready { data, .. } => data.points.len(),
            _ => 0,
        }
    }

    #[test]
    fn the_prefix_slider_sets_the_points_shown() {
        let mut h = harness("dart-throwing-step-by-step.ron");
        assert_eq!(shown(&h), 256);
        h.get_by_label_contains("first 256 = 2^8 of 256 points");
        h.get_by_label_contains("dart throwing · N = 256 · seed 4");
        h.get_by_role_and_label(Role::Slider, "first k points")
            .set_value_accesskit(10.0);
        h.step();
        crate::settle(&mut h, 1);
        assert_eq!(h.state().scene.prefix, Some(10));
        assert_eq!(shown(&h), 10);
        h.get_by_label_contains("first 10 of 256 points");
        // The column's header shows the prefix, not N.
        h.get_by_label_contains("dart throwing · k = 10 of 256 · seed 4");
        assert!(h.query_by_label_contains("· N = 256").is_none());
        // One point more, one fewer.
        h.get_by_label("Step forward").click();
        h.step();
        crate::settle(&mut h, 1);
        assert_eq!(shown(&h), 11);
        h.get_by_label("Step back").click();
        h.get_by_label("Step back").click();
        h.step();
        crate::settle(&mut h, 1);
        assert_eq!(shown(&h), 9);
    }

    #[test]
    fn play_advances_the_prefix_to_all_points() {
        let mut h = harness("dart-throwing-step-by-step.ron");
        h.state_mut().scene.animation.frames = 8;
        h.state_mut().scene.animation.fps = 50.0;
        h.get_by_label("Play").click();
        let deadline = Instant::now() + Duration::from_secs(60);
        let mut seen = vec![];
        while h.state().scene.prefix.is_some() || seen.is_empty() {
            h.step();
            if let Some(k) = h.state().scene.prefix {
                if seen.last() != Some(&k) {
                    seen.push(k);
                }
            }
            std::thread::sleep(Duration::from_millis(5));
            assert!(
                Instant::now() < deadline,
                "playback did not advance: {seen:?}"
            );
        }
        // Frames 0..7 of 8: ⌈256 (i + 1) / 8⌉ points, then all 256 (no prefix); stopped.
        assert_eq!(seen, [32, 64, 96, 128, 160, 192, 224]);
        crate::settle(&mut h, 1);
        assert_eq!(shown(&h), 256);
        h.get_by_label("Play");
    }

    #[test]
    fn a_still_scene_has_no_player() {
        let h = harness("default.ron");
        assert!(h.query_by_label("Play").is_none());
        assert!(h.query_by_label_contains("first k points").is_none());
    }
}
