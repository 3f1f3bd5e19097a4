//! The UI thread's cost per frame while a slider is dragged, in normal and in lecture mode.
//!
//! The real app (egui_kittest harness, no renderer: layout, widgets, plots and tessellation,
//! the CPU work of a frame) shows the default scene; every frame sets N to a new value, as a
//! drag does, so the app submits a new scene to the engine each frame and draws whatever results
//! have arrived. The engine computes on its own thread; this measures only what the UI thread
//! does. Lecture mode (zoom 1.6, light theme, 16:9 letterbox) is compared with normal mode in
//! the same run and the ratio printed. Target: p50 ≤ 8 ms per frame in both modes (half a 60 Hz
//! frame, leaving the other half to the GPU).

use criterion::{criterion_group, criterion_main, Criterion};
use egui_kittest::Harness;
use samplescope::engine::Engine;
use samplescope::ui::SamplescopeApp;
use std::sync::Arc;
use std::time::{Duration, Instant};

fn harness(lecture: bool) -> Harness<'static, SamplescopeApp> {
    let mut h = Harness::builder()
        .with_size(eframe::egui::Vec2::new(1600.0, 1000.0))
        .build_eframe(move |cc| {
            let ctx = cc.egui_ctx.clone();
            let engine = Engine::new_in_memory(Arc::new(move || ctx.request_repaint()));
            let mut app = SamplescopeApp::with_engine(cc, None, engine);
            app.view.show_timings = false;
            app.view.lecture = lecture;
            app
        });
    // Let the first results arrive so the panels draw real data.
    let deadline = Instant::now() + Duration::from_secs(300);
    while !h.state().engine.is_idle() || h.state().results.is_empty() {
        h.step();
        std::thread::sleep(Duration::from_millis(5));
        assert!(Instant::now() < deadline, "engine did not finish");
    }
    h.step();
    h
}

/// One dragged-slider frame: a new N, then one UI frame.
fn drag_frame(h: &mut Harness<'static, SamplescopeApp>, i: &mut usize) {
    *i += 1;
    h.state_mut().scene.n = 2048 + (*i % 4096);
    h.step();
}

fn percentiles(h: &mut Harness<'static, SamplescopeApp>) -> (f64, f64) {
    let mut i = 0;
    let mut t: Vec<Duration> = (0..120)
        .map(|_| {
            let s = Instant::now();
            drag_frame(h, &mut i);
            s.elapsed()
        })
        .collect();
    t.sort();
    (
        t[t.len() / 2].as_secs_f64() * 1e3,
        t[t.len() * 9 / 10].as_secs_f64() * 1e3,
    )
}

fn frames(c: &mut Criterion) {
    let mut normal = harness(false);
    let mut lecture = harness(true);
    let (n50, n90) = percentiles(&mut normal);
    let (l50, l90) = percentiles(&mut lecture);
    println!(
        "\nui frame while dragging N: normal p50 {n50:.2} ms p90 {n90:.2} ms; lecture p50 {l50:.2} ms p90 {l90:.2} ms; lecture/normal {:.2} (target p50 ≤ 8 ms)",
        l50 / n50
    );
    let mut g = c.benchmark_group("ui_frame");
    g.sample_size(30);
    let mut i = 0;
    g.bench_function("drag N, normal mode", |b| {
        b.iter(|| drag_frame(&mut normal, &mut i))
    });
    g.bench_function("drag N, lecture mode", |b| {
        b.iter(|| drag_frame(&mut lecture, &mut i))
    });
    g.finish();
}

criterion_group!(benches, frames);
criterion_main!(benches);
