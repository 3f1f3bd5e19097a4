//! Switching to each shipped scene with cold caches, as a user who picks it from the menu:
//! the time until every visible panel shows a result (a coarse one counts) and until the final
//! refined picture (every node final, the error readouts included), through the engine the app uses; beside it the serial reference (the same
//! jobs one after the other on one thread, to the final picture).
//!
//! Targets on 2 cores: first complete picture ≤ 300 ms, final ≤ 1.5 s, for every scene.
//! Prints a table (median of 3 runs per scene) and the worst ratios; criterion then times the
//! default scene and `zone-plate-128-to-512` both ways. `SCENE_SWITCH_ONLY=a.ron,b.ron` limits
//! the table to those scenes (and skips the criterion part); `SCENE_SWITCH_TIMELINE=1` prints
//! when each panel's first result arrived, run by run.

use criterion::{criterion_group, criterion_main, Criterion};
use samplescope::core::cancel::Cancel;
use samplescope::engine::{Engine, Evaluator};
use samplescope::scene::graph::{self, NodeKind};
use samplescope::scene::{Scene, BUILTIN};
use std::collections::HashSet;
use std::sync::Arc;
use std::time::{Duration, Instant};

const FIRST_TARGET_MS: f64 = 300.0;
const FINAL_TARGET_MS: f64 = 1500.0;

/// (first complete picture, final picture) of `scene` through a fresh engine.
fn switch(scene: &Scene) -> (Duration, Duration) {
    let mut engine = Engine::with_evaluator(Evaluator::default(), Arc::new(|| {}));
    // "Every visible panel has a result": the node that draws each visible panel (pattern:
    // points; periodogram: spectrum; zone plate: reconstruction; filter: response; cost view:
    // convergence; sampling theorem: theorem; integration: its study; projection matrix: its
    // cells), a coarse result counts. The zone plate's RMSE line (the error node) follows with
    // the final reference.
    const PANEL_NODES: [NodeKind; 8] = [
        NodeKind::Points,
        NodeKind::Spectrum,
        NodeKind::Reconstruction,
        NodeKind::Response,
        NodeKind::Convergence,
        NodeKind::Theorem,
        NodeKind::Integration,
        NodeKind::Matrix,
    ];
    let mut want: HashSet<(usize, NodeKind)> = HashSet::new();
    for (c, p) in graph::plan(scene).iter().enumerate() {
        for n in &p.nodes {
            if samplescope::scene::panels::asks_for(scene, c, n.kind)
                && PANEL_NODES.contains(&n.kind)
            {
                want.insert((c, n.kind));
            }
        }
    }
    // SCENE_SWITCH_TIMELINE=1: when each panel's first result arrived (where the time goes).
    let timeline = std::env::var_os("SCENE_SWITCH_TIMELINE").is_some();
    let t = Instant::now();
    engine.submit(scene);
    let mut first = None;
    while !engine.is_idle() {
        for u in engine.poll() {
            if want.remove(&(u.column, u.kind)) && timeline {
                eprintln!(
                    "  {:>8.1} ms  column {} {} ({})",
                    t.elapsed().as_secs_f64() * 1e3,
                    u.column,
                    u.kind.name(),
                    if u.progress.is_none() {
                        "final"
                    } else {
                        "partial"
                    }
                );
            }
        }
        if first.is_none() && want.is_empty() {
            first = Some(t.elapsed());
        }
        std::thread::sleep(Duration::from_micros(200));
    }
    let last = t.elapsed();
    (first.unwrap_or(last), last)
}

fn serial(scene: &Scene) -> Duration {
    let eval = Evaluator::default();
    let t = Instant::now();
    eval.evaluate_serial(scene, &Cancel::never(), &mut |_, _, _| {});
    t.elapsed()
}

fn median(mut v: Vec<Duration>) -> f64 {
    v.sort();
    v[v.len() / 2].as_secs_f64() * 1e3
}

fn scene_switch(c: &mut Criterion) {
    println!(
        "\nscene_switch (cold caches; median of 3): first complete picture / final picture / serial reference, ms"
    );
    println!(
        "{:<40} {:>8} {:>8} {:>9} {:>7}",
        "scene", "first", "final", "serial", "ratio"
    );
    let (mut worst_first, mut worst_final) = (0.0f64, 0.0f64);
    let only = std::env::var("SCENE_SWITCH_ONLY").ok();
    let picked = |name: &str| {
        only.as_ref()
            .is_none_or(|o| o.split(',').any(|n| n == name))
    };
    for (name, text) in BUILTIN.iter().filter(|(n, _)| picked(n)) {
        let scene = Scene::from_ron(text, name).expect("shipped scene");
        let runs: Vec<(Duration, Duration)> = (0..3).map(|_| switch(&scene)).collect();
        let first = median(runs.iter().map(|r| r.0).collect());
        let last = median(runs.iter().map(|r| r.1).collect());
        let ser = median((0..3).map(|_| serial(&scene)).collect());
        worst_first = worst_first.max(first);
        worst_final = worst_final.max(last);
        println!(
            "{name:<40} {first:>8.1} {last:>8.1} {ser:>9.1} {:>7.2}",
            last / ser
        );
    }
    println!(
        "worst: first {worst_first:.1} ms (target ≤ {FIRST_TARGET_MS}, ratio {:.2}), final {worst_final:.1} ms (target ≤ {FINAL_TARGET_MS}, ratio {:.2})",
        worst_first / FIRST_TARGET_MS,
        worst_final / FINAL_TARGET_MS
    );

    if only.is_some() {
        return;
    }
    for name in ["default.ron", "zone-plate-128-to-512.ron"] {
        let text = BUILTIN.iter().find(|(n, _)| *n == name).unwrap().1;
        let scene = Scene::from_ron(text, name).unwrap();
        c.bench_function(&format!("scene_switch/{name}/engine_final"), |b| {
            b.iter(|| switch(&scene).1)
        });
        c.bench_function(&format!("scene_switch/{name}/serial_reference"), |b| {
            b.iter(|| serial(&scene))
        });
    }
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10).measurement_time(Duration::from_secs(4));
    targets = scene_switch
}
criterion_main!(benches);
