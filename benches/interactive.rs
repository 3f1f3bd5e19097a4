//! One slider change on the default scene until all four panels' data are ready.
//!
//! The default scene: N = 4096 jittered points, 256² spectrum at tolerance 1e-6, 512² zone plate
//! reconstructed from the N samples with a radius-2 filter, and the filter response. Each
//! iteration changes a pattern parameter (the jitter amount) to a value never seen before, so
//! the points, spectrum, samples, reconstruction and error are recomputed; the reference image
//! and the filter response are cached, exactly as in the app. Target: p50 ≤ 16 ms on 2 cores.

use criterion::{criterion_group, criterion_main, Criterion};
use samplescope::core::cancel::Cancel;
use samplescope::scene::graph::{Evaluator, NodeKind};
use samplescope::scene::Scene;
use std::time::{Duration, Instant};

fn slider_change(c: &mut Criterion) {
    let scene = Scene::builtin_default();
    let eval = Evaluator::default();
    let cancel = Cancel::new();
    let mut i = 0u64;
    let mut step = |eval: &Evaluator| {
        i += 1;
        let mut s = scene.clone();
        let amount = 1.0 - (i % 100_000) as f64 * 1e-6;
        s.columns[0]
            .pattern
            .set("amount", &format!("{amount:?}"))
            .ok();
        let mut kinds = 0usize;
        eval.evaluate(&s, &cancel, &mut |_, _, r| {
            assert!(r.value.is_ok(), "{:?}", r.value.as_ref().err());
            kinds += 1;
        });
        kinds
    };
    // Warm the cache (reference image, filter response) as the app has it after start-up.
    step(&eval);

    // Our own percentile table, printed next to the target.
    let mut times: Vec<Duration> = (0..60)
        .map(|_| {
            let t = Instant::now();
            step(&eval);
            t.elapsed()
        })
        .collect();
    times.sort();
    let p50 = times[times.len() / 2];
    let p90 = times[times.len() * 9 / 10];
    println!(
        "\ninteractive: slider change → all panels ready: p50 {:.2} ms, p90 {:.2} ms (target p50 ≤ 16 ms; ratio {:.2})",
        p50.as_secs_f64() * 1e3,
        p90.as_secs_f64() * 1e3,
        p50.as_secs_f64() * 1e3 / 16.0
    );
    eval.reset_counts();
    step(&eval);
    for k in NodeKind::ALL {
        print!("{}={} ", k.name(), eval.count(k));
    }
    println!();

    c.bench_function("interactive/slider_change_default_scene", |b| {
        b.iter(|| step(&eval))
    });
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(30).measurement_time(Duration::from_secs(5));
    targets = slider_change
}
criterion_main!(benches);
