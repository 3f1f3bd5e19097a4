//! Scenes and the compute graph: loading errors name line and field; every shipped scene
//! evaluates; only what a scene shows is computed (counted evaluations); changes re-run only
//! their dependents; equal inputs share one evaluation; the engine drops stale generations.

use samplescope::core::cancel::Cancel;
use samplescope::core::params::Params;
use samplescope::core::progress::no_progress;
use samplescope::engine::{Engine, Evaluator};
use samplescope::scene::graph::{self, NodeKind, NodeResult, NodeValue};
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
    // Only the spectrum panel: the points node once (it is the spectrum's realization 0), and
    // nothing of the zone plate or the filter.
    let mut s = small(Scene::builtin_default());
    s.panels.pattern = false;
    s.panels.zoneplate = false;
    s.panels.filter = false;
    let eval = Evaluator::default();
    let seen = evaluate(&eval, &s);
    assert_eq!(eval.count(NodeKind::Spectrum), 1);
    assert_eq!(eval.count(NodeKind::Points), 1);
    assert!(seen
        .iter()
        .all(|(_, k)| *k == NodeKind::Spectrum || *k == NodeKind::Points));
    for k in [
        NodeKind::Statistics,
        NodeKind::Samples,
        NodeKind::Reconstruction,
        NodeKind::Response,
    ] {
        assert_eq!(eval.count(k), 0, "{k:?}");
    }
}

#[test]
fn the_sphere_panel_alone_computes_the_points_and_nothing_else() {
    let mut s = small(Scene::builtin_default());
    s.panels = Default::default();
    s.panels.pattern = false;
    s.panels.spectrum = false;
    s.panels.zoneplate = false;
    s.panels.filter = false;
    s.panels.sphere = true;
    let eval = Evaluator::default();
    let seen = evaluate(&eval, &s);
    assert_eq!(eval.count(NodeKind::Points), 1);
    assert!(seen.iter().all(|(_, k)| *k == NodeKind::Points), "{seen:?}");
    // Hidden, it costs nothing.
    s.panels.sphere = false;
    assert!(graph::column_plan(&s, 0).nodes.is_empty());
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
fn a_cancelled_token_computes_nothing_and_completed_work_is_cached() {
    // A token cancelled up front stops evaluation before anything is started.
    let s = small(Scene::builtin_default());
    let eval = Evaluator::default();
    let cancel = Cancel::new();
    cancel.cancel();
    let mut n = 0;
    eval.evaluate(&s, &cancel, &mut |_, _, _| n += 1);
    assert_eq!(n, 0);
    assert!(eval.counts().iter().all(|(_, c)| *c == 0));
    // Every node that completed is in the cache under its planned key.
    evaluate(&eval, &s);
    for node in graph::plan(&s).iter().flat_map(|p| p.nodes.iter()) {
        let key = node.key.clone().unwrap();
        assert!(eval.cached(&key).is_some(), "{:?} not cached", node.kind);
    }
}

#[test]
fn plan_is_derived_from_the_node_table_with_declared_inputs() {
    // The default scene: statistics overlay off, cost view off, no theorem panel.
    let s = small(Scene::builtin_default());
    let plans = graph::plan(&s);
    let kinds: Vec<NodeKind> = plans[0].nodes.iter().map(|n| n.kind).collect();
    assert_eq!(
        kinds,
        [
            NodeKind::Points,
            NodeKind::Spectrum,
            NodeKind::Samples,
            NodeKind::Reconstruction,
            NodeKind::Reference,
            NodeKind::Error,
            NodeKind::Response,
        ]
    );
    for n in &plans[0].nodes {
        // Inputs are exactly the table's declaration, each planned before its user.
        let declared = (n.kind.def().inputs)(&s, 0).nodes;
        let deps: Vec<NodeKind> = n.deps.iter().map(|(k, _)| *k).collect();
        assert_eq!(deps, declared, "{:?}", n.kind);
        for (k, key) in &n.deps {
            let pos = plans[0]
                .nodes
                .iter()
                .position(|m| m.key.as_ref() == Ok(key));
            let me = plans[0].nodes.iter().position(|m| m.kind == n.kind);
            assert!(pos < me, "{k:?} planned after {:?}", n.kind);
        }
    }
}

#[test]
fn keys_are_stable_distinct_and_change_with_their_inputs_only() {
    let s = small(Scene::builtin_default());
    let a = graph::plan(&s);
    assert_eq!(a, graph::plan(&s.clone()), "same scene, same keys");
    let key = |p: &[graph::ColumnPlan], k: NodeKind| {
        p[0].nodes
            .iter()
            .find(|n| n.kind == k)
            .unwrap()
            .key
            .clone()
            .unwrap()
    };
    // A change of the filter changes its dependents' keys only.
    let mut s2 = s.clone();
    s2.filter.filter.set("sigma", "0.6").unwrap();
    let b = graph::plan(&s2);
    for k in [
        NodeKind::Points,
        NodeKind::Spectrum,
        NodeKind::Samples,
        NodeKind::Reference,
    ] {
        assert_eq!(key(&a, k), key(&b, k), "{k:?}");
    }
    for k in [
        NodeKind::Reconstruction,
        NodeKind::Error,
        NodeKind::Response,
    ] {
        assert_ne!(key(&a, k), key(&b, k), "{k:?}");
    }
    // Keys are BLAKE3 over fixed text: the same on every run and platform. This is the key
    // of `Samples` (algorithm version 1) with fields `42u32` and no inputs.
    let k = graph::key_of(NodeKind::Samples, &42u32, &[]).unwrap();
    let again = graph::key_of(NodeKind::Samples, &42u32, &[]).unwrap();
    assert_eq!(k, again);
    assert_ne!(k, graph::key_of(NodeKind::Samples, &43u32, &[]).unwrap());
    assert_ne!(k, graph::key_of(NodeKind::Points, &42u32, &[]).unwrap());
    let mut h = blake3::Hasher::new();
    h.update(b"samplescope-node-v1\x00samples\x00\x01\x00\x00\x0042\x00");
    assert_eq!(k.hash, *h.finalize().as_bytes());
}

#[test]
fn a_key_that_cannot_be_made_is_an_error_not_a_default() {
    struct Unkeyable;
    impl serde::Serialize for Unkeyable {
        fn serialize<S: serde::Serializer>(&self, _: S) -> Result<S::Ok, S::Error> {
            Err(serde::ser::Error::custom("no text for this value"))
        }
    }
    let e = graph::key_of(NodeKind::Reference, &Unkeyable, &[]).unwrap_err();
    assert!(
        e.to_string().contains("reference") && e.to_string().contains("no text"),
        "{e}"
    );
}

#[test]
fn twenty_rapid_filter_changes_evaluate_spectrum_and_reference_once() {
    // The spectrum and the reference do not depend on the filter: their keys stay in every
    // plan, so their jobs keep running through all 20 submits and are used.
    let mut s = small(Scene::builtin_default());
    s.spectrum.realizations = 8;
    let eval = Evaluator::default();
    let mut engine = Engine::with_evaluator(eval.clone(), Arc::new(|| {}));
    for i in 0..20 {
        let mut si = s.clone();
        si.filter
            .filter
            .set("sigma", &format!("{}", 0.4 + 0.01 * i as f64))
            .unwrap();
        engine.submit(&si);
    }
    let updates = engine.wait(Duration::from_secs(120));
    assert!(engine.is_idle());
    assert_eq!(eval.count(NodeKind::Spectrum), 1);
    assert_eq!(eval.count(NodeKind::Reference), 1);
    assert_eq!(eval.count(NodeKind::Points), 1);
    let last = engine.generation();
    assert!(updates.iter().all(|u| u.generation == last));
    for k in [
        NodeKind::Spectrum,
        NodeKind::Reference,
        NodeKind::Error,
        NodeKind::Response,
    ] {
        assert!(
            updates.iter().any(|u| u.kind == k && u.progress.is_none()),
            "{k:?} missing"
        );
    }
}

#[test]
fn five_hundred_slider_steps_stay_within_the_memory_budget() {
    let budget = 3 << 20;
    let eval = Evaluator::new(budget, None);
    let mut engine = Engine::with_evaluator(eval.clone(), Arc::new(|| {}));
    let mut s = Scene::builtin_default();
    s.n = 256;
    s.recon.size = 48;
    s.spectrum.size = 32;
    let mut max = 0;
    for i in 0..500 {
        s.columns[0]
            .pattern
            .set("amount", &format!("{:?}", 1.0 - i as f64 * 1e-4))
            .unwrap();
        engine.submit(&s);
        if i % 7 == 0 {
            // Sometimes let it finish, mostly cancel in flight, as a drag does.
            engine.wait(Duration::from_secs(30));
        } else {
            engine.poll();
        }
        max = max.max(eval.cache_bytes());
        assert!(
            eval.cache_bytes() <= budget,
            "step {i}: {} bytes",
            eval.cache_bytes()
        );
    }
    engine.wait(Duration::from_secs(60));
    max = max.max(eval.cache_bytes());
    assert!(
        max <= budget && max > budget / 4,
        "cache peaked at {max} of {budget}"
    );
}

#[test]
fn a_dead_engine_says_so_and_nothing_waits_forever() {
    let mut engine = Engine::with_evaluator(Evaluator::default(), Arc::new(|| {}));
    assert!(engine.failure().is_none());
    engine.crash_for_test();
    let t = std::time::Instant::now();
    // The coordinator is gone: submitting and waiting return at once with a failure.
    let mut s = small(Scene::builtin_default());
    s.n = 64;
    loop {
        engine.submit(&s);
        engine.wait(Duration::from_secs(5));
        if engine.failure().is_some() {
            break;
        }
        assert!(
            t.elapsed() < Duration::from_secs(20),
            "failure never reported"
        );
    }
    assert!(engine.is_idle());
    assert!(
        engine.failure().unwrap().contains("stopped"),
        "{:?}",
        engine.failure()
    );
}

#[test]
fn slow_nodes_publish_coarse_results_then_the_exact_final_one() {
    // 128 realizations of a 256² spectrum of 4096 points take well over the partial interval.
    let mut s = Scene::builtin_default();
    s.panels.pattern = false;
    s.panels.zoneplate = false;
    s.panels.filter = false;
    s.n = 4096;
    s.spectrum.size = 256;
    s.spectrum.realizations = 128;
    let mut engine = Engine::with_evaluator(Evaluator::default(), Arc::new(|| {}));
    engine.submit(&s);
    let updates = engine.wait(Duration::from_secs(300));
    let spectra: Vec<_> = updates
        .iter()
        .filter(|u| u.kind == NodeKind::Spectrum)
        .collect();
    let partial = spectra.iter().filter(|u| u.progress.is_some()).count();
    assert!(partial >= 1, "no coarse result");
    let last = spectra.last().unwrap();
    assert!(
        last.progress.is_none(),
        "the last spectrum is the final one"
    );
    // Coarse means of the first realizations, then (just before the final) the final
    // picture while its error is measured.
    let (coarse, picture) = spectra[..spectra.len() - 1].split_at(spectra.len() - 2);
    for u in coarse {
        let p = u.progress.unwrap();
        assert!(p.done < p.total && p.total == 128 && !u.value_final);
        assert!(matches!(
            u.result.accuracy,
            Some(samplescope::model::Accuracy::Realizations { .. })
        ));
    }
    assert!(picture[0].value_final && picture[0].progress.is_some());
    assert!(matches!(
        picture[0].result.accuracy,
        Some(samplescope::model::Accuracy::SpectrumMeasuring { .. })
    ));
    // The final result is exactly what a plain evaluation computes.
    let mut plain = None;
    Evaluator::default().evaluate(&s, &Cancel::never(), &mut |_, k, r| {
        if k == NodeKind::Spectrum {
            plain = Some(r);
        }
    });
    let image = |r: &NodeResult| match &r.value {
        Ok(NodeValue::Spectrum(d)) => d.image.values.clone(),
        other => panic!("{other:?}"),
    };
    let (a, b) = (image(&last.result), image(&plain.unwrap()));
    assert!(a
        .iter()
        .zip(b.iter())
        .all(|(x, y)| x.to_bits() == y.to_bits()));
    let c = image(&picture[0].result);
    assert!(a
        .iter()
        .zip(c.iter())
        .all(|(x, y)| x.to_bits() == y.to_bits()));
}

#[test]
fn the_spectrum_shows_first_and_its_measured_error_follows_with_the_same_number() {
    // The default scene's spectrum (NUFFT at 1e-6, error measured on exact DFT rows): the
    // engine publishes the final picture first (its readout says the error is being measured),
    // then the final result with the measured error, which is the number the one-call
    // spectrum of the same points reports.
    use samplescope::core::spectrum::{analyze_points, Method};
    use samplescope::model::Accuracy;
    let mut s = Scene::builtin_default();
    s.panels.zoneplate = false;
    s.panels.filter = false;
    let mut engine = Engine::with_evaluator(Evaluator::default(), Arc::new(|| {}));
    engine.submit(&s);
    let updates = engine.wait(Duration::from_secs(120));
    assert!(engine.is_idle());
    let spectra: Vec<_> = updates
        .iter()
        .filter(|u| u.kind == NodeKind::Spectrum)
        .collect();
    assert_eq!(spectra.len(), 2, "the picture, then the final result");
    let (picture, last) = (spectra[0], spectra[1]);
    assert!(picture.value_final && picture.progress.is_some());
    assert!(last.value_final && last.progress.is_none());
    assert_eq!(
        picture.result.accuracy,
        Some(Accuracy::SpectrumMeasuring { asked: 1e-6 })
    );
    assert_eq!(
        picture.result.accuracy.as_ref().unwrap().to_string(),
        "asked 1e-6, measuring the error…"
    );
    let (a, b) = match (&picture.result.value, &last.result.value) {
        (Ok(NodeValue::Spectrum(a)), Ok(NodeValue::Spectrum(b))) => (a.clone(), b.clone()),
        other => panic!("{other:?}"),
    };
    assert!(a
        .power
        .power
        .iter()
        .zip(&b.power.power)
        .all(|(x, y)| x.to_bits() == y.to_bits()));
    assert!(a
        .image
        .values
        .iter()
        .zip(b.image.values.iter())
        .all(|(x, y)| x.to_bits() == y.to_bits()));
    assert_eq!(
        (&a.raps, &a.anisotropy, a.auto_range),
        (&b.raps, &b.anisotropy, b.auto_range)
    );
    // The stages say what the error check cost once it is there.
    assert!(!a.stages.iter().any(|(n, _)| n == "error-check"));
    assert!(b.stages.iter().any(|(n, _)| n == "error-check"));
    // The same number as the spectrum computed in one call (check included) on these points.
    let points = updates
        .iter()
        .find_map(|u| match (&u.kind, &u.result.value) {
            (NodeKind::Points, Ok(NodeValue::Points(p))) => Some(p.points.clone()),
            _ => None,
        })
        .unwrap();
    let req = s.spectrum.request(points.len(), false);
    assert_eq!(req.method, Method::Nufft { tolerance: 1e-6 });
    let (_, report) = analyze_points(&req, &points, &Cancel::never()).unwrap();
    let e = report.error.unwrap();
    match &last.result.accuracy {
        Some(Accuracy::SpectrumMeasured {
            relative_l2,
            asked,
            frequencies,
        }) => {
            assert_eq!(relative_l2.to_bits(), e.relative_l2.to_bits());
            assert_eq!((*asked, *frequencies), (1e-6, e.frequencies));
            assert!(*relative_l2 > 0.0 && *relative_l2 < 1e-6, "{relative_l2}");
        }
        other => panic!("{other:?}"),
    }
    // A plain evaluation (render, the command line) sees only the final result.
    let mut finals = 0;
    Evaluator::default().evaluate(&s, &Cancel::never(), &mut |_, k, r| {
        if k == NodeKind::Spectrum {
            finals += 1;
            assert_eq!(r.accuracy, last.result.accuracy);
        }
    });
    assert_eq!(finals, 1);
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

fn temp_dir(name: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("samplescope-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

fn reference_of(eval: &Evaluator, s: &Scene) -> Vec<f32> {
    let mut out = None;
    eval.evaluate(s, &Cancel::never(), &mut |_, k, r| {
        if k == NodeKind::Reference {
            match &r.value {
                Ok(NodeValue::Reference(d)) => out = Some(d.image.values.as_ref().clone()),
                other => panic!("{other:?}"),
            }
        }
    });
    out.expect("reference delivered")
}

#[test]
fn reference_images_persist_on_disk_and_a_corrupt_file_is_recomputed() {
    use samplescope::engine::disk_cache::DiskCache;
    let dir = temp_dir("disk-cache");
    let mut s = small(Scene::builtin_default());
    // The checkerboard's reference is supersampled: worth keeping.
    s.signal = samplescope::core::signal::Signal::Checkerboard(Default::default());
    s.recon.size = 64;
    let open = || {
        Evaluator::new(
            1 << 30,
            Some(DiskCache::open(dir.clone(), 1 << 30).unwrap()),
        )
    };
    let first = open();
    let a = reference_of(&first, &s);
    assert_eq!(first.count(NodeKind::Reference), 1);
    // A new process (fresh evaluator, empty memory cache) finds it on disk: no evaluation,
    // same bits.
    let second = open();
    let b = reference_of(&second, &s);
    assert_eq!(second.count(NodeKind::Reference), 0, "not taken from disk");
    assert!(a.iter().zip(&b).all(|(x, y)| x.to_bits() == y.to_bits()));
    // Corrupt every entry: the next evaluator ignores them and computes again, same bits.
    for e in std::fs::read_dir(&dir).unwrap() {
        let p = e.unwrap().path();
        let mut bytes = std::fs::read(&p).unwrap();
        let mid = bytes.len() / 2;
        bytes[mid] ^= 0x40;
        std::fs::write(&p, bytes).unwrap();
    }
    let third = open();
    let c = reference_of(&third, &s);
    assert_eq!(
        third.count(NodeKind::Reference),
        1,
        "a corrupt file was trusted"
    );
    assert!(a
        .iter()
        .zip(c.iter())
        .all(|(x, y)| x.to_bits() == y.to_bits()));
    // Without a disk cache nothing is read.
    let none = Evaluator::default();
    reference_of(&none, &s);
    assert_eq!(none.count(NodeKind::Reference), 1);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn parallel_and_serial_evaluation_give_the_same_bits() {
    let mut s = small(Scene::builtin_default());
    s.columns.push(s.columns[0].clone());
    s.columns[1].seed = 9;
    s.effects.statistics = true;
    // A column in 8 dimensions showing a projection, and the projection matrix.
    s.columns.push(samplescope::scene::Column {
        pattern: samplescope::core::pattern::Pattern::from_name("sobol").unwrap(),
        dims: 8,
        project: (5, 2),
        ..Default::default()
    });
    s.panels.matrix = true;
    let collect = |serial: bool| {
        let eval = Evaluator::default();
        let mut out: Vec<(usize, NodeKind, String)> = Vec::new();
        let mut sink = |c: usize, k: NodeKind, r: Arc<NodeResult>| {
            out.push((c, k, bits(r.value.as_ref().unwrap())));
        };
        if serial {
            eval.evaluate_serial(&s, &Cancel::never(), &mut sink);
        } else {
            eval.evaluate(&s, &Cancel::never(), &mut sink);
        }
        out.sort_by_key(|a| (a.0, a.1));
        out
    };
    let (p, q) = (collect(false), collect(true));
    assert_eq!(p.len(), q.len());
    for (a, b) in p.iter().zip(&q) {
        assert_eq!((a.0, a.1), (b.0, b.1));
        assert!(a.2 == b.2, "{:?} column {} differs", a.1, a.0);
    }
}

/// The computed numbers of a value (not its timings or upload versions), printed exactly.
fn bits(v: &NodeValue) -> String {
    let img = |i: &samplescope::model::ImageData| format!("{:?}", i.values);
    match v {
        NodeValue::Points(p) => format!("{:?}", p.points),
        NodeValue::Sequence(s) => format!("{:?}", s.0.points),
        NodeValue::Statistics(s) => {
            // The core's whole result without its stage timings.
            let mut full = s.full.clone();
            full.timings.clear();
            format!(
                "{:?} {:?} {:?} {:?} {:?} {:?} {:?} {full:?}",
                s.min_distance,
                s.normalized_min_distance,
                s.mean_nn,
                s.star,
                s.l2_star,
                s.t_value,
                s.psa
            )
        }
        NodeValue::Psa(p) => format!("{p:?}"),
        NodeValue::Rdf(r) => format!("{r:?}"),
        NodeValue::NetPrefixes(p) => format!("{p:?}"),
        NodeValue::Spectrum(s) => format!(
            "{} {:?} {:?} {:?}",
            img(&s.image),
            s.raps,
            s.anisotropy,
            s.power.power
        ),
        NodeValue::Samples(s) => format!("{s:?}"),
        NodeValue::Reconstruction(r) => img(&r.image),
        NodeValue::Reference(r) => format!("{} {:?}", img(&r.image), r.error_estimate),
        NodeValue::Error(e) => format!("{} {}", img(&e.image), e.rmse),
        NodeValue::Response(r) => format!("{} {:?} {:?}", img(&r.image), r.magnitude, r.metrics),
        NodeValue::Convergence(c) => format!("{:?}", c.iter().map(|p| p.rmse).collect::<Vec<_>>()),
        NodeValue::Theorem(t) => format!("{:?}", t.errors),
        NodeValue::Integration(i) => format!("{:?} {:?}", i.study.rows, i.study.slope),
        NodeValue::Matrix(m) => format!("{:?}", m.cells),
    }
}

#[test]
fn heavy_supersampling_previews_at_a_sixteenth_then_gives_the_plain_result() {
    let mut s = Scene::builtin_default();
    s.panels.pattern = false;
    s.panels.spectrum = false;
    s.panels.filter = false;
    s.effects.error = false;
    s.recon.mode = samplescope::scene::ReconMode::Supersample { spp: 64 };
    s.recon.size = 256; // 4.2 M samples: over the preview threshold
    let mut engine = Engine::with_evaluator(Evaluator::default(), Arc::new(|| {}));
    engine.submit(&s);
    let updates = engine.wait(Duration::from_secs(300));
    let recon: Vec<_> = updates
        .iter()
        .filter(|u| u.kind == NodeKind::Reconstruction)
        .collect();
    assert_eq!(recon.len(), 2, "one preview, one final");
    assert_eq!(recon[0].progress.map(|p| (p.done, p.total)), Some((1, 2)));
    assert_eq!(
        recon[0].result.accuracy,
        Some(samplescope::model::Accuracy::Preview {
            spp: 4,
            of: 64,
            noise: 4.0
        })
    );
    assert!(recon[1].progress.is_none());
    // Reference: the plain supersampling at the full spp (same bits) and at 4 spp.
    let sup = |spp| {
        let provider = samplescope::core::recon::PatternProvider {
            pattern: s.columns[0].pattern,
            seed: s.columns[0].seed,
        };
        samplescope::core::recon::supersample(
            &s.signal,
            256,
            spp,
            &provider,
            &s.filter,
            &Cancel::never(),
        )
        .unwrap()
    };
    let image = |u: &samplescope::engine::Update| match &u.result.value {
        Ok(NodeValue::Reconstruction(r)) => r.image.values.clone(),
        other => panic!("{other:?}"),
    };
    for (u, spp) in [(recon[0], 4), (recon[1], 64)] {
        let want = sup(spp);
        let got = image(u);
        // Rows are flipped for display (row 0 at the top).
        for j in 0..256 {
            for i in 0..256 {
                let a = got[(255 - j) * 256 + i];
                let b = want.pixels[j * 256 + i] as f32;
                assert_eq!(a.to_bits(), b.to_bits(), "spp {spp}, pixel ({i},{j})");
            }
        }
    }
}

#[test]
fn lloyd_publishes_the_points_it_has_reached_then_gives_the_plain_result() {
    use samplescope::core::pattern::{optimize, Pattern};
    let mut s = Scene::builtin_default();
    s.panels.spectrum = false;
    s.panels.zoneplate = false;
    s.panels.filter = false;
    s.effects = samplescope::scene::Effects {
        reconstruction: false,
        error: false,
        convergence: false,
        statistics: false,
    };
    s.n = 4096;
    let mut pattern = Pattern::from_name("lloyd").unwrap();
    pattern.set("iterations", "400").unwrap();
    s.columns.truncate(1);
    s.columns[0].pattern = pattern;
    let mut engine = Engine::with_evaluator(Evaluator::default(), Arc::new(|| {}));
    engine.submit(&s);
    let updates = engine.wait(Duration::from_secs(300));
    let points: Vec<_> = updates
        .iter()
        .filter(|u| u.kind == NodeKind::Points)
        .collect();
    let (last, partials) = points.split_last().expect("a final points result");
    assert!(last.progress.is_none());
    assert!(
        !partials.is_empty(),
        "400 Lloyd steps of 4096 points take over 100 ms"
    );
    let value = |u: &samplescope::engine::Update| match &u.result.value {
        Ok(NodeValue::Points(p)) => p.points.clone(),
        other => panic!("{other:?}"),
    };
    let seed = s.columns[0].seed;
    let mut prev = 0;
    for u in partials {
        let (step, steps) = u.progress.map(|p| (p.done, p.total)).unwrap();
        assert_eq!(steps, 400);
        assert!(
            step > prev && step < steps,
            "steps rise: {prev} then {step}"
        );
        prev = step;
        assert_eq!(
            u.result.accuracy,
            Some(samplescope::model::Accuracy::Iterations {
                done: step,
                of: 400
            })
        );
    }
    // A run of k steps is the prefix of a longer one: a partial is exactly Lloyd with k steps.
    for u in [partials[0], partials[partials.len() - 1]] {
        let step = u.progress.unwrap().done;
        let want =
            optimize::lloyd(4096, step as u32, seed, &Cancel::never(), &mut no_progress).unwrap();
        assert_eq!(value(u), want, "step {step}");
    }
    assert_eq!(value(last), pattern.generate(4096, seed).unwrap());
}
