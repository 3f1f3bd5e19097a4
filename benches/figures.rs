//! Cost of a figure for slides against the plain image export.
//!
//! `figure::panel_png` of a 512² zone plate (axes, ticks, labels, title, the image resampled
//! nearest-neighbour into the 400² plotting area at scale 1, 800² at scale 2; PNG with text
//! metadata) against `export::png_bytes` of the same 512² image (grey map and PNG encoding
//! only), both on one thread. The GUI calls `panel_png` on the UI thread, so its time is a
//! frame budget question. A summary (best of 15 runs) with the ratios is printed after the
//! criterion measurements.
//!
//! And the figure users save most: the comparison of the default scene's columns at scale 2
//! (`figure::comparison_png`, 16:9 layout), against the PNG encoding alone of an image of the
//! same size (`export::png_bytes`), the floor any raster figure of that size pays.

use criterion::{criterion_group, criterion_main, Criterion};
use samplescope::core::cancel::Cancel;
use samplescope::core::recon::{Reconstruction, ZERO_WEIGHT_FILL};
use samplescope::engine::Evaluator;
use samplescope::export::figure::{comparison_png, comparison_size, panel_png, Aspect};
use samplescope::export::{flip_rows, png_bytes};
use samplescope::model::Colormap;
use samplescope::model::{ColumnData, FigureContext, FigureKind, ReconData};
use samplescope::scene::{figure, Scene};
use std::hint::black_box;
use std::sync::Arc;
use std::time::{Duration, Instant};

const W: usize = 512;
const K: f64 = 64.0;

/// The zone plate ½(1 + sin(π K |p − c|²)), c = (½, ½), at pixel centres, row 0 at the top.
fn zone_plate() -> Vec<f64> {
    let mut v = Vec::with_capacity(W * W);
    for row in 0..W {
        for col in 0..W {
            let x = (col as f64 + 0.5) / W as f64 - 0.5;
            let y = 1.0 - (row as f64 + 0.5) / W as f64 - 0.5;
            v.push(0.5 * (1.0 + (std::f64::consts::PI * K * (x * x + y * y)).sin()));
        }
    }
    v
}

fn setup() -> (FigureContext, ColumnData, Vec<f64>) {
    let values = zone_plate();
    // The reconstruction's pixels are stored with row 0 at the bottom.
    let exact = Reconstruction {
        w: W,
        pixels: flip_rows(&values, W),
        zero_weight: 0,
        floored: 0,
        floor: 0.5,
        mask: vec![false; W * W],
        fill: ZERO_WEIGHT_FILL,
        samples: W * W,
        wall_time: Duration::ZERO,
    };
    let data = ColumnData {
        reconstruction: samplescope::model::Slot::from(Arc::new(ReconData::new(exact))),
        ..Default::default()
    };
    let ctx = figure::context(&Scene::default(), 0, "bench").expect("column 0 exists");
    (ctx, data, values)
}

fn best_of(runs: usize, f: impl Fn()) -> Duration {
    (0..runs)
        .map(|_| {
            let t = Instant::now();
            f();
            t.elapsed()
        })
        .min()
        .unwrap_or_default()
}

fn bench(c: &mut Criterion) {
    let (ctx, data, values) = setup();
    let plain = || {
        black_box(png_bytes(&values, W, W, 0.0, 1.0, Colormap::Greys, &[]).expect("valid image"));
    };
    let figure = |scale: u32| {
        black_box(panel_png(FigureKind::Reconstruction, &ctx, &data, scale).expect("figure draws"));
    };
    let mut g = c.benchmark_group("figure 512² zone plate");
    g.sample_size(20);
    g.bench_function("export::png_bytes (plain image)", |b| b.iter(plain));
    g.bench_function("figure::panel_png scale 1", |b| b.iter(|| figure(1)));
    g.bench_function("figure::panel_png scale 2", |b| b.iter(|| figure(2)));
    g.finish();

    let p = best_of(15, plain);
    let f1 = best_of(15, || figure(1));
    let f2 = best_of(15, || figure(2));
    let ms = |d: Duration| d.as_secs_f64() * 1e3;
    println!("\nbest of 15, one thread:");
    println!("  export::png_bytes 512² plain image   {:8.2} ms", ms(p));
    println!(
        "  figure::panel_png scale 1 (480×510)   {:8.2} ms   {:.2}× plain",
        ms(f1),
        ms(f1) / ms(p)
    );
    println!(
        "  figure::panel_png scale 2 (960×1020)  {:8.2} ms   {:.2}× plain",
        ms(f2),
        ms(f2) / ms(p)
    );
}

/// The default scene evaluated (no disk cache) and prepared as `render` prepares it.
fn default_comparison() -> (Vec<FigureKind>, Vec<(FigureContext, ColumnData)>) {
    let scene = Scene::default();
    let mut results = vec![std::collections::HashMap::new(); scene.columns.len()];
    Evaluator::new(samplescope::engine::cache::DEFAULT_BUDGET, None).evaluate(
        &scene,
        &Cancel::new(),
        &mut |c, kind, r| {
            results[c].insert(kind, r);
        },
    );
    let columns = figure::figure_columns(&scene, &results, "default").expect("columns exist");
    (samplescope::scene::panels::comparison(&scene), columns)
}

fn bench_comparison(c: &mut Criterion) {
    let (kinds, columns) = default_comparison();
    let aspect = Aspect::default();
    let (w, h) = comparison_size(&kinds, &columns, 2, aspect);
    let (w, h) = (w as usize, h as usize);
    // A smooth image of the comparison's size: what encoding alone costs.
    let plain_values: Vec<f64> = (0..w * h)
        .map(|i| ((i % w) as f64 / w as f64 + (i / w) as f64 / h as f64) * 0.5)
        .collect();
    let plain = || {
        black_box(
            png_bytes(&plain_values, w, h, 0.0, 1.0, Colormap::Greys, &[]).expect("valid image"),
        );
    };
    let comparison = || {
        black_box(comparison_png(&kinds, &columns, 2, aspect).expect("comparison draws"));
    };
    let mut g = c.benchmark_group("comparison of the default scene, scale 2");
    g.sample_size(10);
    g.bench_function("export::png_bytes (same size, plain)", |b| b.iter(plain));
    g.bench_function("figure::comparison_png scale 2", |b| b.iter(comparison));
    g.finish();
    let p = best_of(9, plain);
    let f = best_of(9, comparison);
    let ms = |d: Duration| d.as_secs_f64() * 1e3;
    println!("\nbest of 9, default scene comparison at scale 2 ({w}×{h}):");
    println!("  export::png_bytes same size, plain    {:8.2} ms", ms(p));
    println!(
        "  figure::comparison_png scale 2        {:8.2} ms   {:.2}× plain",
        ms(f),
        ms(f) / ms(p)
    );
}

criterion_group!(benches, bench, bench_comparison);
criterion_main!(benches);
