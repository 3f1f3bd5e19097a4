//! Scenes and the compute graph: loading errors name line and field; every shipped scene
//! evaluates; only what a scene shows is computed (counted evaluations); changes re-run only
//! their dependents; equal inputs share one evaluation; the engine drops stale generations.

use samplescope::core::cancel::Cancel;
use samplescope::engine::Engine;
use samplescope::scene::graph::{Evaluator, NodeKind};
use samplescope::scene::{Scene, SceneError, BUILTIN};
use std::sync::Arc;
use std::time::Duration;

fn small(mut s: Scene) -> Scene {
    // Keep the tests quick: smaller images, same structure.
    s.n = 1024;
    s.recon.size = 128;
    s.spectrum.size = 64;
    s
}

fn evaluate(eval: &Evaluator, scene: &Scene) -> Vec<(usize, NodeKind)> {
    let mut seen = Vec::new();
    eval.evaluate(scene, &Cancel::new(), &mut |c, k, r| {
        assert!(r.value.is_ok(), "{k:?}: {:?}", r.value.as_ref().err());
        seen.push((c, k));
    });
    seen
}

#[test]
fn every_shipped_scene_loads_and_evaluates() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes");
    let mut files = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().and_then(|e| e.to_str()) != Some("ron") {
            continue;
        }
        files += 1;
        let scene = Scene::load(&path).unwrap_or_else(|e| panic!("{e}"));
        let eval = Evaluator::default();
        let mut quick = scene.clone();
        quick.recon.size = quick.recon.size.min(128);
        quick.spectrum.size = quick.spectrum.size.min(64);
        let seen = evaluate(&eval, &quick);
        assert!(!seen.is_empty(), "{}", path.display());
        // Every built-in name refers to a shipped file.
        assert!(
            BUILTIN.iter().any(|(n, _)| path.ends_with(n)),
            "{} not built in",
            path.display()
        );
    }
    assert_eq!(files, BUILTIN.len());
}

#[test]
fn malformed_scene_names_line_and_field() {
    let text = "(\n    title: \"x\",\n    n: 4096,\n    bogus_field: 3,\n)";
    match Scene::from_ron(text, "bad.ron") {
        Err(SceneError::Parse { line, message, .. }) => {
            assert_eq!(line, 4);
            assert!(message.contains("bogus_field"), "{message}");
        }
        other => panic!("{other:?}"),
    }
    let text = "(n: 0)";
    match Scene::from_ron(text, "zero.ron") {
        Err(SceneError::Invalid { field, allowed, .. }) => {
            assert_eq!(field, "n");
            assert!(allowed.contains("1..="));
        }
        other => panic!("{other:?}"),
    }
    let text = "(spectrum: (size: 64, tolerance: 0.5))";
    assert!(matches!(
        Scene::from_ron(text, "tol.ron"),
        Err(SceneError::Invalid { field, .. }) if field == "spectrum.tolerance"
    ));
    let text = "(columns: [(pattern: (kind: \"nosuch\"))])";
    assert!(matches!(
        Scene::from_ron(text, "p.ron"),
        Err(SceneError::Parse { .. })
    ));
}

#[test]
fn scene_round_trips_through_ron() {
    let s = Scene::builtin_default();
    let back = Scene::from_ron(&s.to_ron(), "round-trip").unwrap();
    assert_eq!(s, back);
}

#[test]
fn hidden_panels_and_effects_cost_nothing() {
    let mut s = small(Scene::builtin_default());
    s.panels.spectrum = false;
    s.panels.filter = false;
    s.effects.error = false;
    let eval = Evaluator::default();
    evaluate(&eval, &s);
    assert_eq!(eval.count(NodeKind::Spectrum), 0);
    assert_eq!(eval.count(NodeKind::Response), 0);
    assert_eq!(eval.count(NodeKind::Reference), 0);
    assert_eq!(eval.count(NodeKind::Error), 0);
    assert_eq!(eval.count(NodeKind::Points), 1);
    assert_eq!(eval.count(NodeKind::Reconstruction), 1);
    // Only the spectrum panel: no points node at all (the spectrum generates its realizations).
    let mut s = small(Scene::builtin_default());
    s.panels.pattern = false;
    s.panels.zoneplate = false;
    s.panels.filter = false;
    let eval = Evaluator::default();
    evaluate(&eval, &s);
    assert_eq!(eval.count(NodeKind::Spectrum), 1);
    for k in [
        NodeKind::Points,
        NodeKind::Samples,
        NodeKind::Reconstruction,
        NodeKind::Response,
    ] {
        assert_eq!(eval.count(k), 0, "{k:?}");
    }
}

#[test]
fn a_filter_change_reruns_only_response_reconstruction_and_error() {
    let s = small(Scene::builtin_default());
    let eval = Evaluator::default();
    evaluate(&eval, &s);
    let before: Vec<_> = eval.counts();
    let mut s2 = s.clone();
    s2.filter.filter.set("sigma", "0.6").unwrap();
    evaluate(&eval, &s2);
    for ((k, b), (_, a)) in before.iter().zip(eval.counts()) {
        let expected = matches!(
            k,
            NodeKind::Response | NodeKind::Reconstruction | NodeKind::Error
        );
        assert_eq!(a - b, usize::from(expected), "{k:?}");
    }
}

#[test]
fn an_n_change_keeps_filter_and_reference() {
    let s = small(Scene::builtin_default());
    let eval = Evaluator::default();
    evaluate(&eval, &s);
    let mut s2 = s.clone();
    s2.n = 900;
    eval.reset_counts();
    evaluate(&eval, &s2);
    assert_eq!(eval.count(NodeKind::Response), 0);
    assert_eq!(eval.count(NodeKind::Reference), 0);
    for k in [
        NodeKind::Points,
        NodeKind::Spectrum,
        NodeKind::Samples,
        NodeKind::Reconstruction,
        NodeKind::Error,
    ] {
        assert_eq!(eval.count(k), 1, "{k:?}");
    }
}

#[test]
fn two_columns_with_equal_inputs_share_one_evaluation() {
    let mut s = small(Scene::builtin_default());
    s.columns.push(s.columns[0].clone());
    let eval = Evaluator::default();
    let seen = evaluate(&eval, &s);
    assert!(seen.iter().any(|(c, _)| *c == 1));
    for k in NodeKind::ALL {
        assert!(
            eval.count(k) <= 1,
            "{k:?} evaluated {} times",
            eval.count(k)
        );
    }
}

#[test]
fn cancelled_work_is_neither_computed_nor_cached() {
    // A cancelled token stops evaluation before anything is computed or cached.
    let s = small(Scene::builtin_default());
    let eval = Evaluator::default();
    let cancel = Cancel::new();
    cancel.cancel();
    let mut n = 0;
    eval.evaluate(&s, &cancel, &mut |_, _, _| n += 1);
    assert_eq!(n, 0);
    assert!(eval.counts().iter().all(|(_, c)| *c == 0));
}

#[test]
fn engine_delivers_the_latest_generation_only() {
    let mut engine = Engine::new(Arc::new(|| {}));
    let s = small(Scene::builtin_default());
    let mut s2 = s.clone();
    s2.n = 700;
    engine.submit(&s);
    let g2 = engine.submit(&s2);
    let updates = engine.wait(Duration::from_secs(120));
    assert!(engine.is_idle());
    assert!(!updates.is_empty());
    assert!(updates.iter().all(|u| u.generation == g2));
    let points = updates.iter().find(|u| u.kind == NodeKind::Points).unwrap();
    match &points.result.value {
        Ok(samplescope::scene::graph::NodeValue::Points(p)) => assert_eq!(p.points.len(), 700),
        other => panic!("{other:?}"),
    }
}
