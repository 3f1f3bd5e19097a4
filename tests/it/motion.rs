//! Motion: a scene moves its signal only when it asks to; each frame re-runs only the nodes that
//! depend on the signal; the moved signal is exact (identity at t = 0, after a whole turn and
//! after a drift by a whole grating period); bad motion parameters name their field.

use glam::DVec2;
use samplescope::core::cancel::Cancel;
use samplescope::core::signal::{Grating, Signal, StepEdge, ZonePlate};
use samplescope::engine::Evaluator;
use samplescope::scene::graph::NodeKind;
use samplescope::scene::{Motion, ReconMode, Scene, SceneError};

/// A small scene with every panel on and a drifting zone plate.
fn moving_scene() -> Scene {
    let mut s = Scene {
        n: 1024,
        signal: Signal::ZonePlate(ZonePlate {
            k: 200.0,
            ..ZonePlate::default()
        }),
        motion: Some(Motion {
            velocity_x: 0.02,
            velocity_y: 0.01,
            angular_velocity: 5.0,
            frame_rate: 24.0,
            ..Motion::default()
        }),
        ..Scene::default()
    };
    s.recon.size = 64;
    s.recon.mode = ReconMode::Scattered;
    s.spectrum.size = 32;
    s.effects.error = false;
    s
}

fn evaluate(eval: &Evaluator, scene: &Scene) {
    eval.evaluate(scene, &Cancel::new(), &mut |c, k, r| {
        assert!(
            r.value.is_ok(),
            "column {c} {k:?}: {:?}",
            r.value.as_ref().err()
        );
    });
}

fn image(signal: &Signal, w: usize) -> Vec<f64> {
    let mut v = Vec::with_capacity(w * w);
    for j in 0..w {
        for i in 0..w {
            v.push(signal.eval(DVec2::new(
                (i as f64 + 0.5) / w as f64,
                (j as f64 + 0.5) / w as f64,
            )));
        }
    }
    v
}

fn max_abs_diff(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

#[test]
fn without_motion_many_frames_evaluate_each_node_once() {
    let mut scene = moving_scene();
    scene.motion = None;
    let eval = Evaluator::default();
    for frame in 0..20 {
        // What the app submits per frame for a still scene: the same scene (at_time is the
        // identity without motion).
        let s = scene.at_time(frame as f64 / 24.0).unwrap();
        assert_eq!(s, scene);
        evaluate(&eval, &s);
    }
    for kind in [
        NodeKind::Points,
        NodeKind::Spectrum,
        NodeKind::Samples,
        NodeKind::Reconstruction,
        NodeKind::Response,
    ] {
        assert_eq!(eval.count(kind), 1, "{kind:?}");
    }
}

#[test]
fn with_motion_each_frame_reevaluates_samples_and_reconstruction_only() {
    let scene = moving_scene();
    let m = scene.motion.unwrap();
    let eval = Evaluator::default();
    evaluate(&eval, &scene.at_time(0.0).unwrap());
    let frames = 6;
    for k in 1..=frames {
        let s = scene.at_time(m.frame_time(k)).unwrap();
        assert_ne!(s.signal, scene.signal, "frame {k} must move the signal");
        evaluate(&eval, &s);
    }
    let f = frames as usize + 1;
    assert_eq!(eval.count(NodeKind::Points), 1);
    assert_eq!(eval.count(NodeKind::Spectrum), 1);
    assert_eq!(eval.count(NodeKind::Response), 1);
    assert_eq!(eval.count(NodeKind::Samples), f);
    assert_eq!(eval.count(NodeKind::Reconstruction), f);
    // Stepping back to a frame already seen is a cache hit.
    evaluate(&eval, &scene.at_time(m.frame_time(3)).unwrap());
    assert_eq!(eval.count(NodeKind::Samples), f);
}

#[test]
fn at_time_zero_is_the_base_scene() {
    let scene = moving_scene();
    assert_eq!(scene.at_time(0.0).unwrap(), scene);
    for sig in [
        Signal::Grating(Grating {
            frequency: 12.0,
            angle: 33.0,
            phase: 0.25,
        }),
        Signal::StepEdge(StepEdge::default()),
    ] {
        let mut s = scene.clone();
        s.signal = sig;
        assert_eq!(s.at_time(0.0).unwrap(), s);
    }
}

#[test]
fn grating_drift_by_a_whole_period_gives_the_same_image() {
    let f = 8.0;
    // Wave vector along 0°: one period is 1/f along x. Drift it in exactly 1.5 s.
    let g = Signal::Grating(Grating {
        frequency: f,
        angle: 0.0,
        phase: 0.0,
    });
    let t = 1.5;
    let m = Motion {
        velocity_x: 1.0 / (f * t),
        frame_rate: 24.0,
        ..Motion::default()
    };
    let mut scene = moving_scene();
    scene.signal = g;
    scene.motion = Some(m);
    let moved = scene.at_time(t).unwrap();
    let (a, b) = (image(&g, 64), image(&moved.signal, 64));
    assert!(max_abs_diff(&a, &b) < 1e-12, "{}", max_abs_diff(&a, &b));
    // Half a period later the grating is inverted: the test can fail.
    let half = scene.at_time(t / 2.0).unwrap();
    let c = image(&half.signal, 64);
    let inverted = a.iter().zip(&c).all(|(x, y)| (x + y - 1.0).abs() < 1e-9);
    assert!(inverted);
    // A slanted grating drifting along its own normal by one period.
    let slanted = Grating {
        frequency: 5.0,
        angle: 30.0,
        phase: 0.1,
    };
    let n = DVec2::new((30f64).to_radians().cos(), (30f64).to_radians().sin());
    let m2 = Motion {
        velocity_x: n.x / 5.0,
        velocity_y: n.y / 5.0,
        ..Motion::default()
    };
    scene.signal = Signal::Grating(slanted);
    scene.motion = Some(m2);
    let moved = scene.at_time(1.0).unwrap();
    let d = max_abs_diff(&image(&scene.signal, 64), &image(&moved.signal, 64));
    assert!(d < 1e-9, "{d}");
}

#[test]
fn rotation_by_a_whole_turn_is_the_identity() {
    // 90°/s for 4 s about a pivot off the zone plate's centre.
    let m = Motion {
        angular_velocity: 90.0,
        pivot_x: 0.3,
        pivot_y: 0.7,
        ..Motion::default()
    };
    let signals = [
        Signal::ZonePlate(ZonePlate {
            k: 150.0,
            cx: 0.45,
            cy: 0.55,
        }),
        Signal::Grating(Grating {
            frequency: 7.0,
            angle: 20.0,
            phase: 0.3,
        }),
    ];
    for sig in signals {
        let mut scene = moving_scene();
        scene.signal = sig;
        scene.motion = Some(m);
        let a = image(&sig, 64);
        let turned = scene.at_time(4.0).unwrap();
        let d = max_abs_diff(&a, &image(&turned.signal, 64));
        assert!(d < 1e-9, "{}: {d}", sig.name());
        // A quarter turn about that pivot does change the image.
        let quarter = scene.at_time(1.0).unwrap();
        assert!(max_abs_diff(&a, &image(&quarter.signal, 64)) > 0.1);
    }
}

#[test]
fn bad_motion_parameters_name_the_field() {
    let cases: [(Motion, &str); 5] = [
        (
            Motion {
                frame_rate: -24.0,
                ..Motion::default()
            },
            "motion.frame_rate",
        ),
        (
            Motion {
                frame_rate: 0.0,
                ..Motion::default()
            },
            "motion.frame_rate",
        ),
        (
            Motion {
                velocity_x: f64::NAN,
                ..Motion::default()
            },
            "motion.velocity_x",
        ),
        (
            Motion {
                angular_velocity: f64::INFINITY,
                ..Motion::default()
            },
            "motion.angular_velocity",
        ),
        (
            Motion {
                pivot_y: 9.0,
                ..Motion::default()
            },
            "motion.pivot_y",
        ),
    ];
    for (m, field) in cases {
        let mut s = moving_scene();
        s.motion = Some(m);
        match s.validate("test") {
            Err(SceneError::Invalid {
                field: f, allowed, ..
            }) => {
                assert_eq!(f, field);
                assert!(allowed.contains('['), "{allowed}");
            }
            other => panic!("{field}: {other:?}"),
        }
        match s.at_time(1.0) {
            Err(SceneError::Invalid { field: f, .. }) => assert_eq!(f, field),
            other => panic!("{field}: {other:?}"),
        }
    }
    // From a scene file: the message carries the field and the range.
    let text = r#"(title: "bad", motion: Some((frame_rate: -1.0)))"#;
    let e = Scene::from_ron(text, "bad.ron").unwrap_err().to_string();
    assert!(e.contains("motion.frame_rate") && e.contains("0.1"), "{e}");
    // A signal without an exact moved form is refused, naming `motion`.
    let text = r#"(title: "bad", signal: (kind: "checkerboard"), motion: Some(()))"#;
    match Scene::from_ron(text, "bad.ron") {
        Err(SceneError::Invalid { field, .. }) => assert_eq!(field, "motion"),
        other => panic!("{other:?}"),
    }
    // A non-finite time is refused.
    assert!(moving_scene().at_time(f64::NAN).is_err());
}

/// The lecture's point: a uniform grid samples a drifting zone plate coherently, so between
/// frames the reconstruction changes by a structured (aliased) pattern; the scene shipped for
/// it evaluates frame after frame with both columns.
#[test]
fn shipped_motion_scenes_animate() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes");
    let mut found = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().and_then(|e| e.to_str()) != Some("ron") {
            continue;
        }
        let scene = Scene::load(&path).unwrap_or_else(|e| panic!("{e}"));
        let Some(m) = scene.motion else { continue };
        found += 1;
        let mut quick = scene.clone();
        quick.recon.size = quick.recon.size.min(128);
        quick.spectrum.size = quick.spectrum.size.min(64);
        let eval = Evaluator::default();
        for k in 0..3 {
            evaluate(&eval, &quick.at_time(m.frame_time(k)).unwrap());
        }
        let points = eval.count(NodeKind::Points);
        assert!(points <= quick.columns.len(), "{}", path.display());
    }
    assert!(found >= 1, "no shipped scene has motion");
}

mod ui {
    //! The transport controls in the real app (egui_kittest, no rendering: no GPU needed).

    use egui_kittest::kittest::Queryable;
    use egui_kittest::Harness;
    use samplescope::scene::graph::NodeKind;
    use samplescope::ui::SamplescopeApp;
    use std::time::{Duration, Instant};

    fn harness_with(name: &str) -> Harness<'static, SamplescopeApp> {
        crate::builtin_harness(name, |s| {
            s.recon.size = s.recon.size.min(128);
            s.spectrum.size = s.spectrum.size.min(64);
        })
    }

    fn count(h: &Harness<'static, SamplescopeApp>, kind: NodeKind) -> usize {
        h.state().engine.evaluator().count(kind)
    }

    #[test]
    fn still_scene_has_no_transport_and_computes_nothing_per_frame() {
        let mut h = harness_with("default.ron");
        assert!(h.query_by_label("Play").is_none());
        assert!(h.query_by_label("Step forward").is_none());
        let before = h.state().engine.evaluator().counts();
        for _ in 0..30 {
            h.step();
        }
        assert_eq!(h.state().engine.evaluator().counts(), before);
    }

    #[test]
    fn step_forward_recomputes_samples_but_not_points() {
        let mut h = harness_with("motion-zone-plate-drift.ron");
        let cols = h.state().scene.columns.len();
        h.get_by_label("Play");
        h.get_by_label("Step back");
        let points = count(&h, NodeKind::Points);
        let samples = count(&h, NodeKind::Samples);
        // Paused: nothing per frame.
        for _ in 0..10 {
            h.step();
        }
        assert_eq!(count(&h, NodeKind::Samples), samples);
        h.get_by_label("Step forward").click();
        h.step();
        crate::settle(&mut h, 1);
        assert_eq!(h.state().motion_frame(), 1);
        h.get_by_label_contains("t = 0.042 s · frame 1 at 24 fps");
        assert_eq!(count(&h, NodeKind::Points), points);
        assert_eq!(count(&h, NodeKind::Samples), samples + cols);
        assert_eq!(count(&h, NodeKind::Reconstruction), samples + cols);
        // Back to frame 0: every node is cached.
        h.get_by_label("Step back").click();
        h.step();
        crate::settle(&mut h, 1);
        assert_eq!(h.state().motion_frame(), 0);
        assert_eq!(count(&h, NodeKind::Samples), samples + cols);
    }

    #[test]
    fn switching_to_a_signal_that_cannot_move_is_reported() {
        let mut h = harness_with("motion-zone-plate-drift.ron");
        h.state_mut().scene.signal =
            samplescope::core::signal::Signal::Checkerboard(Default::default());
        h.step();
        h.get_by_label_contains("checkerboard signal cannot move");
    }

    #[test]
    fn play_advances_frames_until_paused() {
        let mut h = harness_with("motion-grating-strobe.ron");
        h.get_by_label("Play").click();
        let deadline = Instant::now() + Duration::from_secs(60);
        while h.state().motion_frame() < 3 {
            h.step();
            std::thread::sleep(Duration::from_millis(10));
            assert!(Instant::now() < deadline, "playback did not advance");
        }
        h.get_by_label("Pause").click();
        h.step();
        let frame = h.state().motion_frame();
        for _ in 0..20 {
            h.step();
            std::thread::sleep(Duration::from_millis(5));
        }
        assert_eq!(h.state().motion_frame(), frame);
    }
}
