//! One slider change on the default scene until all four panels' data are ready: the parallel
//! scheduler against the serial reference (same jobs, same caches, one node at a time).
//!
//! The default scene: N = 4096 jittered points, 256² spectrum at tolerance 1e-6, 512² zone plate
//! reconstructed from the N samples with a radius-2 filter, and the filter response. Each
//! iteration changes a pattern parameter (the jitter amount) to a value never seen before, so
//! the points, statistics, spectrum, samples, reconstruction and error are recomputed; the
//! reference image and the filter response are cached, exactly as in the app.
//! Target: p50 ≤ 12 ms on 2 cores.

use criterion::{criterion_group, criterion_main, Criterion};
use samplescope::core::cancel::Cancel;
use samplescope::core::params::Params;
use samplescope::engine::Evaluator;
use samplescope::scene::graph::{NodeKind, NodeResult};
use samplescope::scene::Scene;
use std::sync::Arc;
use std::time::{Duration, Instant};

const TARGET_MS: f64 = 12.0;

type Eval = fn(&Evaluator, &Scene, &Cancel, &mut dyn FnMut(usize, NodeKind, Arc<NodeResult>));

fn parallel(
    e: &Evaluator,
    s: &Scene,
    c: &Cancel,
    f: &mut dyn FnMut(usize, NodeKind, Arc<NodeResult>),
) {
    e.evaluate(s, c, f)
}

fn serial(
    e: &Evaluator,
    s: &Scene,
    c: &Cancel,
    f: &mut dyn FnMut(usize, NodeKind, Arc<NodeResult>),
) {
    e.evaluate_serial(s, c, f)
}

struct Stepper {
    scene: Scene,
    eval: Evaluator,
    run: Eval,
    i: u64,
}

impl Stepper {
    fn new(run: Eval, offset: u64) -> Self {
        let mut s = Stepper {
            scene: Scene::builtin_default(),
            eval: Evaluator::default(),
            run,
            i: offset,
        };
        // Warm the cache (reference image, filter response) as the app has it after start-up.
        s.step();
        s
    }

    fn step(&mut self) -> usize {
        self.i += 1;
        let mut s = self.scene.clone();
        let amount = 1.0 - (self.i % 100_000) as f64 * 1e-6;
        s.columns[0]
            .pattern
            .set("amount", &format!("{amount:?}"))
            .ok();
        let mut kinds = 0usize;
        (self.run)(&self.eval, &s, &Cancel::never(), &mut |_, _, r| {
            assert!(r.value.is_ok(), "{:?}", r.value.as_ref().err());
            kinds += 1;
        });
        kinds
    }

    fn percentiles(&mut self, n: usize) -> (f64, f64) {
        let mut times: Vec<Duration> = (0..n)
            .map(|_| {
                let t = Instant::now();
                self.step();
                t.elapsed()
            })
            .collect();
        times.sort();
        let ms = |d: Duration| d.as_secs_f64() * 1e3;
        (ms(times[n / 2]), ms(times[n * 9 / 10]))
    }
}

fn slider_change(c: &mut Criterion) {
    let mut par = Stepper::new(parallel, 0);
    // Different amounts from the parallel run's, so neither sees the other's results.
    let mut ser = Stepper::new(serial, 500_000);
    // Interleaved rounds, so that both see the same machine load.
    let (mut pp, mut sp) = (Vec::new(), Vec::new());
    for _ in 0..3 {
        pp.push(par.percentiles(20));
        sp.push(ser.percentiles(20));
    }
    let med = |v: &mut Vec<(f64, f64)>| {
        v.sort_by(|a, b| a.0.total_cmp(&b.0));
        v[v.len() / 2]
    };
    let (p50, p90) = med(&mut pp);
    let (s50, s90) = med(&mut sp);
    println!(
        "\ninteractive: slider change → all panels ready: parallel p50 {p50:.2} ms (p90 {p90:.2}), \
         serial reference p50 {s50:.2} ms (p90 {s90:.2}); parallel/serial {:.2}; \
         target p50 ≤ {TARGET_MS} ms: ratio to target {:.2}",
        p50 / s50,
        p50 / TARGET_MS
    );
    par.eval.reset_counts();
    par.step();
    for k in NodeKind::ALL {
        print!("{}={} ", k.name(), par.eval.count(k));
    }
    println!();
    // Each recomputed node's own wall time (serial run: no contention between nodes).
    ser.i += 1;
    let mut s = ser.scene.clone();
    s.columns[0].pattern.set("amount", "0.123456789").ok();
    print!("node wall times (serial):");
    ser.eval
        .evaluate_serial(&s, &Cancel::never(), &mut |_, k, r| {
            print!(" {} {:.2} ms;", k.name(), r.wall.as_secs_f64() * 1e3);
            if let Ok(samplescope::scene::graph::NodeValue::Spectrum(d)) = &r.value {
                print!(" (stages:");
                for (name, ms) in &d.stages {
                    print!(" {name} {ms:.2}");
                }
                print!(")");
            }
        });
    println!();

    c.bench_function("interactive/slider_change_default_scene", |b| {
        b.iter(|| par.step())
    });
    c.bench_function(
        "interactive/slider_change_default_scene_serial_reference",
        |b| b.iter(|| ser.step()),
    );
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(30).measurement_time(Duration::from_secs(5));
    targets = slider_change
}
criterion_main!(benches);
