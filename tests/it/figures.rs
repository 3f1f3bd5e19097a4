//! Figures for slides: PNG/SVG/CSV of every panel, composites, metadata, determinism and
//! errors, on a small scene evaluated through the compute graph (N = 256, 64² images).

use samplescope::core::cancel::Cancel;
use samplescope::core::recon::{Reconstruction, ZERO_WEIGHT_FILL};
use samplescope::core::signal::theorem::TheoremView;
use samplescope::engine::Evaluator;
use samplescope::export::figure::{
    base_size, column_layout, column_png, column_size, comparison_layout, comparison_png,
    comparison_size, comparison_title_lines, figure, fill, panel_csv, panel_file_name, panel_png,
    panel_rgba, panel_svg, text_width, Aspect, Layout, MAX_COMPOSITE_PIXELS, SCALES,
};
use samplescope::export::ExportError;
use samplescope::model::{ColumnData, FigureContext, FigureKind, PointsData, ReconData};
use samplescope::scene::graph::{NodeKind, NodeResult};
use samplescope::scene::{figure as scene_figure, panels, Scene};
use std::collections::HashMap;
use std::sync::Arc;

const SCENE: &str = r#"(
    title: "Figure test, jitter ω²",
    columns: [
        (pattern: (kind: "jitter", cols: 0, amount: 1.0), seed: 7),
        (pattern: (kind: "random"), seed: 3, label: "white noise"),
    ],
    n: 256,
    signal: (kind: "zone-plate", k: 32.0, cx: 0.5, cy: 0.5),
    filter: (filter: (kind: "gaussian", sigma: 0.5, radius: 2.0, subtract_edge: true), mode: separable),
    recon: (mode: scattered, size: 64),
    spectrum: (size: 64, tolerance: 1e-6, exact: false, realizations: 1, mask_dc: true),
    panels: (pattern: true, spectrum: true, zoneplate: true, filter: true, cost: true, integration: true, matrix: true),
    effects: (reconstruction: true, error: true, convergence: true, statistics: false),
    integration: (ns: [16, 64, 256], realizations: 8),
)"#;

/// The test scene with every figure, the convergence curve included (its evaluation is the
/// slowest part: 341 samples per pixel over 64²).
fn scene() -> Scene {
    Scene::from_ron(SCENE, "figures.ron").expect("test scene parses")
}

/// The test scene without the cost view (no convergence curve): fast to evaluate.
fn quick_scene() -> Scene {
    let mut s = scene();
    s.panels.cost = false;
    s.panels.integration = false;
    s.effects.convergence = false;
    s
}

/// Evaluates the scene and returns each column's context and data.
fn columns(scene: &Scene) -> Vec<(FigureContext, ColumnData)> {
    let mut results: Vec<HashMap<NodeKind, Arc<NodeResult>>> =
        vec![HashMap::new(); scene.columns.len()];
    Evaluator::default().evaluate(scene, &Cancel::never(), &mut |c, kind, r| {
        assert!(
            r.value.is_ok(),
            "{kind:?} failed: {:?}",
            r.value.as_ref().err()
        );
        results[c].insert(kind, r);
    });
    scene_figure::columns_data(scene, &results)
        .into_iter()
        .enumerate()
        .map(|(c, d)| (scene_figure::context(scene, c, "figure-test").unwrap(), d))
        .collect()
}

fn decode(bytes: &[u8]) -> (png::OutputInfo, Vec<u8>, Vec<(String, String)>) {
    let mut reader = png::Decoder::new(std::io::Cursor::new(bytes))
        .read_info()
        .expect("PNG header");
    let mut buf = vec![0; reader.output_buffer_size()];
    let info = reader.next_frame(&mut buf).expect("PNG frame");
    buf.truncate(info.buffer_size());
    let text = crate::png_text(reader.info());
    (info, buf, text)
}

fn meta<'a>(text: &'a [(String, String)], key: &str) -> &'a str {
    text.iter()
        .find(|(k, _)| k == key)
        .map(|(_, v)| v.as_str())
        .unwrap_or_else(|| panic!("no metadata {key:?} in {text:?}"))
}

#[test]
fn every_panel_png_decodes_at_base_size_times_scale() {
    let scene = scene();
    let cols = columns(&scene);
    let (ctx, data) = &cols[0];
    let kinds = panels::available(&scene);
    assert_eq!(
        kinds.len(),
        FigureKind::ALL
            .iter()
            .filter(|&&k| !k.is_theorem() && k != FigureKind::Sphere)
            .count(),
        "the scene shows every figure but the theorem's and the sphere's (tested on their own \
         scenes below)"
    );
    for kind in kinds {
        for scale in [1, 2] {
            let bytes = panel_png(kind, ctx, data, scale).unwrap();
            assert_eq!(
                bytes,
                panel_png(kind, ctx, data, scale).unwrap(),
                "{kind:?} twice"
            );
            let (info, pixels, _) = decode(&bytes);
            let (bw, bh) = base_size(kind);
            assert_eq!(
                (info.width, info.height),
                (bw * scale, bh * scale),
                "{kind:?} at {scale}x"
            );
            assert_eq!(info.color_type, png::ColorType::Rgb);
            assert_eq!(info.bit_depth, png::BitDepth::Eight);
            // Something besides the white background was drawn.
            assert!(pixels.iter().any(|&v| v < 100), "{kind:?} is blank");
        }
    }
}

#[test]
fn png_metadata_names_scene_pattern_n_seed_filter_signal_and_scale() {
    let scene = quick_scene();
    let cols = columns(&scene);
    let (ctx, data) = &cols[0];
    let bytes = panel_png(FigureKind::Spectrum, ctx, data, 2).unwrap();
    let (_, _, text) = decode(&bytes);
    assert_eq!(meta(&text, "scene"), "Figure test, jitter ω²");
    assert_eq!(meta(&text, "pattern"), "jitter");
    assert_eq!(meta(&text, "pattern parameters"), "cols=0 amount=1");
    assert_eq!(meta(&text, "N"), "256");
    assert_eq!(meta(&text, "seed"), "7");
    assert_eq!(meta(&text, "scale"), "2");
    assert_eq!(meta(&text, "figure"), "spectrum");
    assert!(meta(&text, "filter").contains("gaussian"));
    assert!(meta(&text, "signal").contains("zone-plate"));
    assert_eq!(
        meta(&text, "Software"),
        format!("samplescope {}", env!("CARGO_PKG_VERSION"))
    );
    assert!(meta(&text, "Title").contains("N = 256, seed 7"));
    assert!(meta(&text, "colour range").starts_with("log10 P in ["));
    // No timings anywhere.
    assert!(!text
        .iter()
        .any(|(k, v)| k.contains("ms") || v.contains(" ms")));
}

#[test]
fn svg_has_axes_text_metadata_and_embedded_images() {
    let scene = quick_scene();
    let cols = columns(&scene);
    let (ctx, data) = &cols[1];
    let pattern = panel_svg(FigureKind::Pattern, ctx, data, 1).unwrap();
    assert!(pattern.starts_with("<svg"));
    assert!(pattern.contains("width=\"480\" height=\"510\""));
    assert!(pattern.contains("<title>white noise, N = 256, seed 3</title>"));
    assert!(pattern.contains("pattern: random"));
    assert!(pattern.contains("seed: 3"));
    assert!(pattern.contains("N: 256"));
    assert!(pattern.contains("scene: Figure test, jitter ω²"));
    // Tick labels and axis descriptions are glyph runs labelled with their text.
    assert!(pattern.contains("aria-label=\"0.2\"") && pattern.contains("aria-label=\"1.0\""));
    assert!(pattern.contains("aria-label=\"x\"") && pattern.contains("aria-label=\"y\""));
    // The glyphs are outlines defined once and placed: no viewer needs the font.
    assert!(!pattern.contains("<text") && pattern.contains("<use xlink:href=\"#g"));
    assert_eq!(
        pattern.matches("<circle").count(),
        256,
        "one circle per point"
    );

    let response = panel_svg(FigureKind::Response, ctx, data, 2).unwrap();
    assert!(response.contains("ω (cycles per sample)"));
    assert!(response.contains("Nyquist, ω = 0.5"));
    assert!(response.contains("width=\"1280\" height=\"1020\""));

    let spectrum = panel_svg(FigureKind::Spectrum, ctx, data, 1).unwrap();
    assert_eq!(
        spectrum.matches("<image ").count(),
        2,
        "the periodogram and its colour bar"
    );
    assert!(spectrum.contains("xlink:href=\"data:image/png;base64,iVBORw0KGgo"));
    assert!(spectrum.contains("log₁₀ P   (white noise: 0)"));
    assert!(spectrum.contains("kx (cycles per unit)"));
}

fn parse_pairs(csv: &str, header: &str) -> Vec<[f64; 2]> {
    let mut lines = csv.lines();
    assert_eq!(lines.next(), Some(header));
    lines
        .map(|l| {
            let (a, b) = l.split_once(',').unwrap();
            [a.parse().unwrap(), b.parse().unwrap()]
        })
        .collect()
}

#[test]
fn csv_round_trips_the_drawn_numbers() {
    let scene = scene();
    let cols = columns(&scene);
    let (ctx, data) = &cols[0];

    let points = parse_pairs(&panel_csv(FigureKind::Pattern, ctx, data).unwrap(), "x,y");
    let want: Vec<[f64; 2]> = data
        .points
        .data()
        .unwrap()
        .points
        .iter()
        .map(|p| [p.x, p.y])
        .collect();
    assert_eq!(points, want, "points round-trip bit for bit");

    let spectrum = data.spectrum.data().unwrap();
    let raps = parse_pairs(
        &panel_csv(FigureKind::Raps, ctx, data).unwrap(),
        "radius,power",
    );
    assert_eq!(raps, spectrum.raps);

    let response = data.response.data().unwrap();
    let kernel = parse_pairs(&panel_csv(FigureKind::Kernel, ctx, data).unwrap(), "x,h");
    assert_eq!(kernel, response.kernel);
    let mag = parse_pairs(
        &panel_csv(FigureKind::Response, ctx, data).unwrap(),
        "omega,magnitude",
    );
    assert_eq!(mag, response.magnitude);

    let conv = parse_pairs(
        &panel_csv(FigureKind::Convergence, ctx, data).unwrap(),
        "spp,rmse",
    );
    let want: Vec<[f64; 2]> = data
        .convergence
        .data()
        .unwrap()
        .iter()
        .map(|p| [p.spp as f64, p.rmse])
        .collect();
    assert_eq!(conv, want);

    // Periodogram: M² rows of (kx, ky, log10 P), kx and ky in [−M/2, M/2).
    let csv = panel_csv(FigureKind::Spectrum, ctx, data).unwrap();
    let mut lines = csv.lines();
    assert_eq!(lines.next(), Some("kx,ky,log10_power"));
    let rows: Vec<(i64, i64, f32)> = lines
        .map(|l| {
            let v: Vec<&str> = l.split(',').collect();
            (
                v[0].parse().unwrap(),
                v[1].parse().unwrap(),
                v[2].parse().unwrap(),
            )
        })
        .collect();
    assert_eq!(rows.len(), 64 * 64);
    assert_eq!((rows[0].0, rows[0].1), (-32, -32));
    assert_eq!((rows[64 * 64 - 1].0, rows[64 * 64 - 1].1), (31, 31));
    // Display row 0 is the highest ky: (kx = −32, ky = 31) is the first value of the image.
    let top_left = rows.iter().find(|r| r.0 == -32 && r.1 == 31).unwrap().2;
    assert_eq!(top_left.to_bits(), spectrum.image.values[0].to_bits());

    // Images: one row per line, top row first.
    let recon = data.reconstruction.data().unwrap();
    let csv = panel_csv(FigureKind::Reconstruction, ctx, data).unwrap();
    let values: Vec<f32> = csv
        .lines()
        .flat_map(|l| l.split(',').map(|v| v.parse::<f32>().unwrap()))
        .collect();
    assert_eq!(csv.lines().count(), 64);
    assert_eq!(values, *recon.image.values);
}

#[test]
fn same_inputs_give_byte_identical_png_and_svg() {
    let scene = quick_scene();
    let a = columns(&scene);
    let b = columns(&scene); // a fresh evaluation of the same scene
    for kind in panels::available(&scene) {
        for ((ca, da), (cb, db)) in a.iter().zip(&b) {
            let pa = panel_png(kind, ca, da, 1).unwrap();
            assert_eq!(pa, panel_png(kind, ca, da, 1).unwrap(), "{kind:?} twice");
            assert_eq!(
                pa,
                panel_png(kind, cb, db, 1).unwrap(),
                "{kind:?} re-evaluated"
            );
            assert_eq!(
                panel_svg(kind, ca, da, 1).unwrap(),
                panel_svg(kind, cb, db, 1).unwrap(),
                "{kind:?} SVG"
            );
        }
    }
    let kinds = panels::composite(&scene);
    assert_eq!(
        comparison_png(&kinds, &a, 1, Aspect::SLIDE).unwrap(),
        comparison_png(&kinds, &b, 1, Aspect::SLIDE).unwrap()
    );
}

#[test]
fn scale_out_of_range_is_a_typed_error_naming_the_field_and_range() {
    let scene = quick_scene();
    let cols = columns(&scene);
    let (ctx, data) = &cols[0];
    for bad in [0, SCALES.end() + 1, 9] {
        let e = panel_png(FigureKind::Pattern, ctx, data, bad).unwrap_err();
        assert!(
            matches!(e, ExportError::OutOfRange { field: "scale", .. }),
            "{e:?}"
        );
        let msg = e.to_string();
        assert!(
            msg.contains(&format!("scale = {bad}")) && msg.contains("1..=4"),
            "{msg}"
        );
        assert!(panel_svg(FigureKind::Pattern, ctx, data, bad).is_err());
        assert!(column_png(&[FigureKind::Pattern], ctx, data, bad, Aspect::SLIDE).is_err());
    }
}

#[test]
fn missing_or_empty_data_is_an_error_naming_the_figure() {
    let scene = quick_scene();
    let ctx = scene_figure::context(&scene, 0, "x").unwrap();
    let none = ColumnData::default();
    for kind in FigureKind::ALL {
        let e = panel_png(kind, &ctx, &none, 1).unwrap_err();
        assert!(
            matches!(e, ExportError::EmptyData { .. }),
            "{kind:?}: {e:?}"
        );
        assert!(e.to_string().starts_with(kind.name()), "{e}");
    }
    let empty = ColumnData {
        points: samplescope::model::Slot::from(Arc::new(PointsData {
            points: vec![],
            gpu: Arc::new(vec![]),
            version: 0,
            note: None,
        })),
        ..Default::default()
    };
    let e = panel_png(FigureKind::Pattern, &ctx, &empty, 1).unwrap_err();
    assert!(e.to_string().contains("empty"), "{e}");
    assert!(column_png(&[], &ctx, &empty, 1, Aspect::SLIDE).is_err());
    assert!(scene_figure::context(&scene, 5, "x").is_err());
}

/// The pixel at the centre of the plotting area of a 480×510 image figure at scale 1
/// (title 40, margin 10, y labels 60, plot 400×400).
fn plot_centre(pixels: &[u8]) -> [u8; 3] {
    let (x, y) = (10 + 60 + 200, 40 + 10 + 200);
    let i = (y * 480 + x) * 3;
    [pixels[i], pixels[i + 1], pixels[i + 2]]
}

#[test]
fn images_and_points_are_drawn_where_their_data_says() {
    let scene = quick_scene();
    let ctx = scene_figure::context(&scene, 0, "x").unwrap();
    let mut colours = Vec::new();
    for level in [0.0, 1.0] {
        let data = ColumnData {
            reconstruction: samplescope::model::Slot::from(Arc::new(ReconData::new(
                Reconstruction {
                    w: 8,
                    pixels: vec![level; 64],
                    zero_weight: 0,
                    floored: 0,
                    floor: 0.5,
                    mask: vec![false; 64],
                    fill: ZERO_WEIGHT_FILL,
                    samples: 64,
                    wall_time: std::time::Duration::ZERO,
                },
            ))),
            ..Default::default()
        };
        let (w, h, rgba) = panel_rgba(FigureKind::Reconstruction, &ctx, &data, 1).unwrap();
        assert_eq!((w, h), (480, 510));
        let rgb: Vec<u8> = rgba
            .chunks(4)
            .flat_map(|p| {
                assert_eq!(p[3], 255);
                [p[0], p[1], p[2]]
            })
            .collect();
        let (_, decoded, _) =
            decode(&panel_png(FigureKind::Reconstruction, &ctx, &data, 1).unwrap());
        assert_eq!(rgb, decoded, "RGBA and PNG hold the same pixels");
        colours.push(plot_centre(&rgb));
    }
    assert_eq!(colours, vec![[0, 0, 0], [255, 255, 255]]);

    // One point in the middle of the unit square: dark there, white a bit away.
    let one = ColumnData {
        points: samplescope::model::Slot::from(Arc::new(PointsData {
            points: vec![glam::DVec2::new(0.5, 0.5)],
            gpu: Arc::new(vec![[0.5, 0.5]]),
            version: 0,
            note: None,
        })),
        ..Default::default()
    };
    let (_, px, _) = decode(&panel_png(FigureKind::Pattern, &ctx, &one, 1).unwrap());
    let centre = plot_centre(&px);
    assert!(centre.iter().all(|&c| c < 60), "{centre:?}");
    let off = ((40 + 10 + 100) * 480 + 10 + 60 + 100) * 3;
    assert_eq!(&px[off..off + 3], &[255, 255, 255]);
}

#[test]
fn composites_put_the_panels_of_every_column_in_the_grid_that_fills_the_frame() {
    let scene = quick_scene();
    let cols = columns(&scene);
    let kinds = panels::composite(&scene);
    assert_eq!(
        kinds,
        vec![
            FigureKind::Pattern,
            FigureKind::Spectrum,
            FigureKind::Reconstruction,
            FigureKind::Kernel,
            FigureKind::Response
        ]
    );
    let (ctx, data) = &cols[0];
    // A column of five figures at 16:9: three over two (pattern, periodogram,
    // reconstruction; kernel, response), the widest row setting the width.
    let l = column_layout(&kinds, Aspect::SLIDE);
    assert_eq!((l.panel_cols, l.panel_rows), (3, 2), "{l}");
    let row1: u32 = kinds[..3].iter().map(|&k| base_size(k).0).sum();
    let row2: u32 = kinds[3..].iter().map(|&k| base_size(k).0).sum();
    let (info, _, text) = decode(&column_png(&kinds, ctx, data, 1, Aspect::SLIDE).unwrap());
    assert_eq!((info.width, info.height), (row1.max(row2), 36 + 2 * 510));
    assert_eq!(
        column_size(&kinds, 1, Aspect::SLIDE),
        (info.width as u64, info.height as u64)
    );
    assert_eq!(meta(&text, "figure"), "column");
    assert_eq!(meta(&text, "seed"), "7");
    assert_eq!(meta(&text, "aspect"), "16:9");
    // A 1:4 frame stacks them.
    let tall = column_layout(&kinds, "1:4".parse().unwrap());
    assert_eq!((tall.panel_cols, tall.panel_rows), (1, 5));

    let (info, _, text) = decode(&comparison_png(&kinds, &cols, 2, Aspect::SLIDE).unwrap());
    assert_eq!(
        comparison_size(&kinds, &cols, 2, Aspect::SLIDE),
        (info.width as u64, info.height as u64)
    );
    assert_eq!(meta(&text, "figure"), "comparison");
    assert_eq!(
        meta(&text, "layout"),
        comparison_layout(&kinds, &cols, Aspect::SLIDE).to_string()
    );
    let columns_meta = meta(&text, "columns");
    assert!(columns_meta.contains("jitter") && columns_meta.contains("white noise: random"));
    // Eight columns of five figures at scale 4 exceed the limit: refused, not allocated.
    let many: Vec<_> = (0..8).map(|_| cols[0].clone()).collect();
    let (w, h) = comparison_size(&kinds, &many, 4, Aspect::SLIDE);
    assert!(w * h > MAX_COMPOSITE_PIXELS);
    let e = comparison_png(&kinds, &many, 4, Aspect::SLIDE).unwrap_err();
    assert!(matches!(e, ExportError::TooLarge { .. }), "{e:?}");
}

/// Three columns of (pattern, periodogram) sharing one colour range, as `render` draws them.
fn locked(scene: &Scene) -> Vec<(FigureContext, ColumnData)> {
    let mut cols = columns(scene);
    let range = (-1.0f32, 2.0f32);
    for (c, _) in &mut cols {
        c.spectrum_range = Some(range);
    }
    cols
}

#[test]
fn five_columns_of_three_figures_stand_side_by_side_at_16_9() {
    let mut scene = quick_scene();
    scene.panels.zoneplate = false;
    scene.panels.filter = false;
    let two = columns(&scene);
    let cols: Vec<_> = (0..5).map(|i| two[i % 2].clone()).collect();
    let kinds = panels::comparison(&scene);
    let stacked = Layout {
        block_cols: 5,
        block_rows: 1,
        panel_cols: 1,
        panel_rows: 3,
    };
    // With equal panels five columns of three stacked figures are the 16:9 choice.
    let equal = [
        FigureKind::Pattern,
        FigureKind::Reconstruction,
        FigureKind::Pattern,
    ];
    assert_eq!(comparison_layout(&equal, &cols, Aspect::SLIDE), stacked);
    let (w, h) = comparison_size(&equal, &cols, 1, Aspect::SLIDE);
    assert_eq!((w, h), (5 * 480, 44 + 36 + 3 * 510));
    assert!(fill(w, h, Aspect::SLIDE) > 0.8, "{w}×{h}");
    // Whatever the figures, the chosen grid is drawn at its computed size.
    let l = comparison_layout(&kinds, &cols, Aspect::SLIDE);
    let (info, _, _) = decode(&comparison_png(&kinds, &cols, 1, Aspect::SLIDE).unwrap());
    assert_eq!(
        (info.width as u64, info.height as u64),
        comparison_size(&kinds, &cols, 1, Aspect::SLIDE),
        "{l}"
    );
}

#[test]
fn locked_scales_draw_one_shared_colour_bar() {
    let mut scene = quick_scene();
    scene.panels.zoneplate = false;
    scene.panels.filter = false;
    let kinds = panels::comparison(&scene);
    assert_eq!(kinds, vec![FigureKind::Pattern, FigureKind::Spectrum]);
    let free = columns(&scene);
    let lock = locked(&scene);
    let (wf, _) = comparison_size(&kinds, &free, 1, Aspect::SLIDE);
    let (wl, _) = comparison_size(&kinds, &lock, 1, Aspect::SLIDE);
    let lf = comparison_layout(&kinds, &free, Aspect::SLIDE);
    let ll = comparison_layout(&kinds, &lock, Aspect::SLIDE);
    assert_eq!(lf, ll, "the same grid");
    // Each periodogram loses its 110-pixel bar; one bar of 110 pixels is added.
    assert_eq!(wl + 110 * ll.block_cols as u64 - 110, wf, "{lf}");
    let (info, px, text) = decode(&comparison_png(&kinds, &lock, 1, Aspect::SLIDE).unwrap());
    assert!(meta(&text, "layout").contains("columns"));
    // The shared bar's gradient: a column of the strip at the right holds many colours.
    let (w, h) = (info.width as usize, info.height as usize);
    let x = w - 110 + 14 + 5;
    let colours: std::collections::BTreeSet<[u8; 3]> = (0..h)
        .map(|y| {
            let i = (y * w + x) * 3;
            [px[i], px[i + 1], px[i + 2]]
        })
        .collect();
    assert!(
        colours.len() > 100,
        "{} colours in the bar strip",
        colours.len()
    );
}

#[test]
fn comparison_titles_wrap_or_shorten_and_never_run_past_the_image() {
    let mut scene = quick_scene();
    scene.panels.zoneplate = false;
    scene.panels.filter = false;
    scene.panels.spectrum = false;
    scene.columns.truncate(1);
    let mut cols = columns(&scene);
    let long = "A very long scene title that names every column, every parameter and every                 setting of the scene, far wider than one pattern figure can hold on one line";
    cols[0].0.scene_title = long.into();
    cols[0].0.column_title = "a label far too long for the caption band of one figure".into();
    let kinds = panels::comparison(&scene);
    assert_eq!(kinds, vec![FigureKind::Pattern]);
    for scale in [1, 2] {
        let (w, h) = comparison_size(&kinds, &cols, scale, Aspect::SLIDE);
        assert_eq!(w, 480 * scale as u64);
        let lines = comparison_title_lines(&kinds, &cols, scale, Aspect::SLIDE);
        assert_eq!(lines.len(), 2, "{lines:?}");
        assert!(lines[1].ends_with('…'), "{lines:?}");
        for l in &lines {
            assert!(
                (text_width(l, 20.0 * scale as f64) as u64) < w,
                "{l:?} wider than {w}"
            );
        }
        // Two title lines: the band is one line higher.
        assert_eq!(h, (44 + 26 + 36 + 510) * scale as u64);
        // No ink in the first and last columns of pixels of the title and caption bands.
        let (info, px, _) = decode(&comparison_png(&kinds, &cols, scale, Aspect::SLIDE).unwrap());
        let (w, band) = (info.width as usize, ((44 + 26 + 36) * scale) as usize);
        for y in 0..band {
            for x in [0, 1, w - 2, w - 1] {
                let i = (y * w + x) * 3;
                assert_eq!(&px[i..i + 3], &[255, 255, 255], "ink at ({x}, {y})");
            }
        }
    }
    // A title that fits stays one line.
    cols[0].0.scene_title = "short".into();
    assert_eq!(
        comparison_title_lines(&kinds, &cols, 1, Aspect::SLIDE),
        vec!["short".to_string()]
    );
}

#[test]
fn file_names_carry_scene_pattern_n_seed_kind_and_scale() {
    let scene = quick_scene();
    let ctx = scene_figure::context(&scene, 0, "zone-plate-128-to-512").unwrap();
    assert_eq!(
        panel_file_name(FigureKind::Spectrum, &ctx, Some(2), "png"),
        "zone-plate-128-to-512_jitter_n256_seed7_spectrum@2x.png"
    );
    let ctx = scene_figure::context(&scene, 1, "").unwrap();
    assert_eq!(
        panel_file_name(FigureKind::Raps, &ctx, None, "csv"),
        "figure-test-jitter_random-white-noise_n256_seed3_raps.csv"
    );
    assert_eq!(
        panel_file_name(FigureKind::Pattern, &ctx, Some(3), ""),
        "figure-test-jitter_random-white-noise_n256_seed3_pattern@3x"
    );
}

/// A scene showing only the 1D sampling-theorem panel: sinc² (B = 1.5) sampled at 2.5 < 2B,
/// tent reconstruction; `signal` replaces the signal's RON.
fn theorem_scene(signal: &str) -> Scene {
    let text = format!(
        r#"(
    title: "Theorem figure test",
    columns: [(pattern: (kind: "jitter", cols: 0, amount: 1.0), seed: 1)],
    n: 64,
    panels: (pattern: false, spectrum: false, zoneplate: false, filter: false, cost: false, theorem: true),
    theorem: (
        signal: {signal},
        rate: 2.5,
        filter: (kind: "tent", radius: 1.0),
        extent: 3.0,
        pair: (kind: box, scale: 1.0, shift: 0.0),
        vdc_rows: 4,
    ),
)"#
    );
    Scene::from_ron(&text, "theorem.ron").expect("theorem scene parses")
}

const SINC2: &str = r#"(kind: "sinc-squared", bandwidth: 1.5)"#;

fn theorem_view(data: &ColumnData) -> &TheoremView {
    data.theorem
        .data()
        .expect("the theorem node ran for column 0")
}

#[test]
fn theorem_figures_are_available_for_column_zero_only() {
    let scene = theorem_scene(SINC2);
    assert_eq!(panels::available(&scene), FigureKind::THEOREM.to_vec());
    // The composites show the three plots of the sampling process, not the transform pair.
    let three = vec![
        FigureKind::TheoremSignal,
        FigureKind::TheoremSpectrum,
        FigureKind::TheoremReconstructed,
    ];
    assert_eq!(panels::composite(&scene), three);
    assert_eq!(panels::comparison(&scene), three);
    // With a second column (and the pattern panel), only column 0 has the theorem figures.
    let mut two = quick_scene();
    two.panels.theorem = true;
    assert!(panels::available_in(&two, 0).contains(&FigureKind::TheoremSpectrum));
    assert!(!panels::available_in(&two, 1).iter().any(|k| k.is_theorem()));
    assert!(!panels::composite_in(&two, 1).iter().any(|k| k.is_theorem()));
    assert!(!panels::comparison(&two).iter().any(|k| k.is_theorem()));
    let cols = columns(&two);
    assert!(figure(FigureKind::TheoremSignal).has_data(&cols[0].1));
    assert!(!figure(FigureKind::TheoremSignal).has_data(&cols[1].1));
    for (c, (_, data)) in cols.iter().enumerate() {
        for kind in panels::available_in(&two, c) {
            assert!(figure(kind).has_data(data), "column {c} lacks {kind:?}");
        }
    }
}

#[test]
fn theorem_figures_decode_at_base_size_times_scale_and_repeat_byte_for_byte() {
    let scene = theorem_scene(SINC2);
    let a = columns(&scene);
    let b = columns(&scene); // a fresh evaluation
    let (ctx, data) = &a[0];
    let v = theorem_view(data);
    assert!(
        v.errors.pre_aliasing > 0.0,
        "2.5 < 2B: the replicas overlap"
    );
    for kind in FigureKind::THEOREM {
        for scale in [1, 2] {
            let bytes = panel_png(kind, ctx, data, scale).unwrap();
            assert_eq!(
                bytes,
                panel_png(kind, ctx, data, scale).unwrap(),
                "{kind:?}"
            );
            assert_eq!(
                bytes,
                panel_png(kind, &b[0].0, &b[0].1, scale).unwrap(),
                "{kind:?} re-evaluated"
            );
            let (info, pixels, text) = decode(&bytes);
            let (bw, bh) = base_size(kind);
            assert_eq!((info.width, info.height), (bw * scale, bh * scale));
            assert_eq!(bh, 510, "every figure is 510 high");
            assert!(pixels.iter().any(|&p| p < 100), "{kind:?} is blank");
            assert_eq!(meta(&text, "figure"), kind.name());
            assert_eq!(meta(&text, "scale"), scale.to_string());
            let pre = meta(&text, "pre-aliasing");
            assert!(
                pre.starts_with(&format!("{:e}", v.errors.pre_aliasing)),
                "{pre}"
            );
            let post = meta(&text, "post-aliasing");
            assert!(
                post.starts_with(&format!("{:e}", v.errors.post_aliasing)),
                "{post}"
            );
            assert!(meta(&text, "signal").contains("sinc-squared"));
            assert_eq!(meta(&text, "sampling rate"), "2.5 samples per unit");
            assert!(meta(&text, "filter").contains("tent"));
            if kind == FigureKind::TheoremPair {
                assert_eq!(
                    meta(&text, "Title"),
                    "transform pair box <-> sinc, scale a = 1, shift s = 0"
                );
            } else {
                assert!(meta(&text, "Title").contains("f_s = 2.5"));
            }
            // The 2D pattern, N and seed do not apply to the theorem's figures.
            assert!(!text.iter().any(|(k, _)| k == "pattern" || k == "seed"));
        }
        let svg = panel_svg(kind, ctx, data, 1).unwrap();
        assert_eq!(svg, panel_svg(kind, &b[0].0, &b[0].1, 1).unwrap());
        assert!(svg.contains("pre-aliasing") && svg.contains("post-aliasing"));
        // The caption line under the sampling plots (the pair's states its formula).
        let caption = format!(
            "({:.3} % of energy)",
            100.0 * v.errors.relative(v.errors.pre_aliasing)
        );
        assert_eq!(
            svg.contains(&caption),
            kind != FigureKind::TheoremPair,
            "{kind:?}"
        );
    }
    assert_eq!(
        panel_file_name(FigureKind::TheoremSpectrum, ctx, Some(2), "png"),
        "figure-test_theorem-spectrum@2x.png"
    );
    assert_eq!(
        panel_file_name(FigureKind::TheoremSignal, ctx, None, "csv"),
        "figure-test_theorem-signal.csv"
    );
}

/// Whether the RGB pixels hold exactly `colour` somewhere.
fn has_colour(pixels: &[u8], colour: [u8; 3]) -> bool {
    pixels.chunks(3).any(|p| p == colour)
}

#[test]
fn theorem_spectrum_draws_replicas_in_distinct_colours_nyquist_lines_and_a_legend() {
    let scene = theorem_scene(SINC2);
    let cols = columns(&scene);
    let (ctx, data) = &cols[0];
    let (_, px, _) = decode(&panel_png(FigureKind::TheoremSpectrum, ctx, data, 1).unwrap());
    // k = −2, −1, 1, 2 (green, orange, red, cyan) and the Nyquist red.
    for c in [
        [44, 160, 44],
        [255, 127, 14],
        [214, 39, 40],
        [23, 190, 207],
        [200, 60, 60],
    ] {
        assert!(has_colour(&px, c), "{c:?} missing");
    }
    let svg = panel_svg(FigureKind::TheoremSpectrum, ctx, data, 1).unwrap();
    for label in [
        "|F(ω)|",
        "F(ω + 1·f_s)",
        "F(ω − 2·f_s)",
        "|G(ω)| (filter)",
        "Nyquist ±f_s/2",
    ] {
        assert!(svg.contains(label), "legend lacks {label}");
    }
    // The reconstructed spectrum is drawn in the reconstruction's orange, not the replicas'.
    let (_, px, _) = decode(&panel_png(FigureKind::TheoremReconstructed, ctx, data, 1).unwrap());
    assert!(has_colour(&px, [230, 120, 20]));
    assert!(!has_colour(&px, [44, 160, 44]));
}

fn parse_series(csv: &str, header: &str) -> Vec<(String, [f64; 2])> {
    let mut lines = csv.lines();
    assert_eq!(lines.next(), Some(header));
    lines
        .map(|l| {
            let v: Vec<&str> = l.split(',').collect();
            assert_eq!(v.len(), 3, "{l}");
            (
                v[0].to_string(),
                [v[1].parse().unwrap(), v[2].parse().unwrap()],
            )
        })
        .collect()
}

fn series(rows: &[(String, [f64; 2])], name: &str) -> Vec<[f64; 2]> {
    rows.iter()
        .filter(|(n, _)| n == name)
        .map(|(_, p)| *p)
        .collect()
}

#[test]
fn theorem_csv_round_trips_the_plotted_numbers() {
    let scene = theorem_scene(SINC2);
    let cols = columns(&scene);
    let (ctx, data) = &cols[0];
    let v = theorem_view(data);

    let rows = parse_series(
        &panel_csv(FigureKind::TheoremSignal, ctx, data).unwrap(),
        "series,x,value",
    );
    assert_eq!(series(&rows, "f"), v.signal);
    assert_eq!(series(&rows, "sample"), v.samples);
    assert_eq!(series(&rows, "f_r"), v.reconstruction);
    assert_eq!(
        rows.len(),
        v.signal.len() + v.samples.len() + v.reconstruction.len()
    );

    let rows = parse_series(
        &panel_csv(FigureKind::TheoremSpectrum, ctx, data).unwrap(),
        "series,omega,magnitude",
    );
    let sp = &v.spectrum;
    assert_eq!(series(&rows, "F"), sp.original);
    assert_eq!(series(&rows, "G"), sp.gain);
    assert_eq!(sp.replicas.len(), 6);
    for (k, c) in &sp.replicas {
        assert_eq!(&series(&rows, &format!("replica_{k}")), c, "k = {k}");
    }

    let rows = parse_series(
        &panel_csv(FigureKind::TheoremReconstructed, ctx, data).unwrap(),
        "series,omega,magnitude",
    );
    assert_eq!(series(&rows, "F"), sp.original);
    assert_eq!(series(&rows, "F_r"), sp.reconstructed);

    let rows = parse_series(
        &panel_csv(FigureKind::TheoremPair, ctx, data).unwrap(),
        "series,position,value",
    );
    let pp = &v.pair;
    assert_eq!(series(&rows, "p"), pp.spatial);
    assert_eq!(series(&rows, "abs_P"), pp.magnitude);
    assert_eq!(series(&rows, "re_P"), pp.re);
    assert_eq!(series(&rows, "im_P"), pp.im);
    assert!(!pp.spatial.is_empty());
}

#[test]
fn shah_pair_figure_draws_and_exports_its_impulses() {
    let mut scene = theorem_scene(SINC2);
    scene.theorem.pair = samplescope::core::signal::theorem::TransformPair {
        kind: samplescope::core::signal::theorem::PairKind::Shah,
        scale: 1.5,
        shift: 0.2,
    };
    let cols = columns(&scene);
    let (ctx, data) = &cols[0];
    let pp = &theorem_view(data).pair;
    let (info, px, text) = decode(&panel_png(FigureKind::TheoremPair, ctx, data, 1).unwrap());
    assert_eq!((info.width, info.height), (1000, 510));
    // Re in blue, and Im (non-zero: the shift) in the reconstruction's orange.
    assert!(has_colour(&px, [31, 119, 180]) && has_colour(&px, [230, 120, 20]));
    assert_eq!(
        meta(&text, "transform pair"),
        "shah <-> shah, a = 1.5, s = 0.2"
    );
    let rows = parse_series(
        &panel_csv(FigureKind::TheoremPair, ctx, data).unwrap(),
        "series,position,value",
    );
    assert_eq!(series(&rows, "impulse_x"), pp.impulses_x);
    let re: Vec<[f64; 2]> = pp.impulses_omega.iter().map(|i| [i[0], i[1]]).collect();
    let im: Vec<[f64; 2]> = pp.impulses_omega.iter().map(|i| [i[0], i[2]]).collect();
    assert_eq!(series(&rows, "impulse_re"), re);
    assert_eq!(series(&rows, "impulse_im"), im);
    assert!(series(&rows, "p").is_empty());
}

#[test]
fn theorem_figures_of_a_line_spectrum_draw_and_export_the_lines() {
    // Cosines up to B = 1.5 sampled at 2.5: the line at 1.5 > f_s/2 pre-aliases.
    let scene = theorem_scene(r#"(kind: "cosines", bandwidth: 1.5)"#);
    let cols = columns(&scene);
    let (ctx, data) = &cols[0];
    let v = theorem_view(data);
    assert!(v.errors.periodic && v.errors.pre_aliasing > 0.0);
    for kind in FigureKind::THEOREM {
        let (info, px, text) = decode(&panel_png(kind, ctx, data, 1).unwrap());
        assert_eq!(info.width, base_size(kind).0);
        assert!(px.iter().any(|&p| p < 100));
        assert!(meta(&text, "pre-aliasing").contains("% of the signal's power"));
    }
    let rows = parse_series(
        &panel_csv(FigureKind::TheoremSpectrum, ctx, data).unwrap(),
        "series,omega,magnitude",
    );
    assert!(series(&rows, "F").is_empty());
    for (k, c) in &v.spectrum.lines {
        assert_eq!(&series(&rows, &format!("line_{k}")), c, "k = {k}");
    }
    let rows = parse_series(
        &panel_csv(FigureKind::TheoremReconstructed, ctx, data).unwrap(),
        "series,omega,magnitude",
    );
    assert_eq!(series(&rows, "F_r_line"), v.spectrum.reconstructed_lines);
    assert_eq!(series(&rows, "F_line").len(), 6, "three cosines, ± each");
}

#[test]
fn missing_theorem_data_is_a_typed_error_naming_the_figure() {
    // Column 1 of a two-column scene with the theorem panel has no theorem view.
    let mut two = quick_scene();
    two.panels.theorem = true;
    let cols = columns(&two);
    let (ctx, data) = &cols[1];
    for kind in FigureKind::THEOREM {
        for e in [
            panel_png(kind, ctx, data, 1).unwrap_err(),
            panel_svg(kind, ctx, data, 1).unwrap_err(),
            panel_csv(kind, ctx, data).unwrap_err(),
        ] {
            match &e {
                ExportError::EmptyData { figure, .. } => assert_eq!(*figure, kind.name()),
                other => panic!("{kind:?}: {other:?}"),
            }
            assert!(e.to_string().starts_with(kind.name()), "{e}");
        }
    }
    // A column composite asking for them fails the same way.
    let e = column_png(&FigureKind::THEOREM, ctx, data, 1, Aspect::SLIDE).unwrap_err();
    assert!(e.to_string().starts_with("theorem-signal"), "{e}");
}

/// N = 4 points at the centres of the 2×2 boxes, and a context whose column draws the
/// elementary intervals with k = `k`.
fn four_points(k: Option<u32>) -> (FigureContext, ColumnData) {
    let scene = quick_scene();
    let mut ctx = scene_figure::context(&scene, 0, "x").unwrap();
    ctx.elementary_k = k;
    let pts = [[0.25, 0.25], [0.75, 0.25], [0.25, 0.75], [0.75, 0.75]];
    let data = ColumnData {
        points: samplescope::model::Slot::from(Arc::new(PointsData {
            points: pts.iter().map(|p| glam::DVec2::new(p[0], p[1])).collect(),
            gpu: Arc::new(pts.iter().map(|p| [p[0] as f32, p[1] as f32]).collect()),
            version: 0,
            note: None,
        })),
        ..Default::default()
    };
    (ctx, data)
}

/// Whether some pixel within ±2 of (x, y) of a 480-wide figure is light blue (the
/// elementary-interval lines: blue well above red).
fn blue_near(px: &[u8], x: usize, y: usize) -> bool {
    (y - 2..=y + 2).any(|yy| {
        (x - 2..=x + 2).any(|xx| {
            let i = (yy * 480 + xx) * 3;
            let (r, b) = (px[i] as i32, px[i + 2] as i32);
            b > r + 40 && b > 150
        })
    })
}

#[test]
fn pattern_draws_the_elementary_interval_grid_when_the_column_asks() {
    // Plot area at scale 1: x in 70..470, y in 50..450 (y = 1 at the top).
    let (x_half, y_10) = (70 + 200, 50 + 360); // x = 0.5, y = 0.1: on the k = 1 vertical
    let (x_10, y_half) = (70 + 40, 50 + 200); // x = 0.1, y = 0.5: on the horizontal
    let (plain_ctx, data) = four_points(None);
    let (_, plain, plain_text) =
        decode(&panel_png(FigureKind::Pattern, &plain_ctx, &data, 1).unwrap());
    assert!(!blue_near(&plain, x_half, y_10));
    assert!(!blue_near(&plain, x_10, y_half));
    assert!(!plain_text.iter().any(|(k, _)| k == "elementary intervals"));

    // k = 1 with N = 4 = 2²: 2 × 2 boxes, one line each way through the centre.
    let (ctx, data) = four_points(Some(1));
    let (_, grid, text) = decode(&panel_png(FigureKind::Pattern, &ctx, &data, 1).unwrap());
    assert!(blue_near(&grid, x_half, y_10));
    assert!(blue_near(&grid, x_10, y_half));
    assert_eq!(
        meta(&text, "elementary intervals"),
        "k = 1: 2×2 boxes of 2^-1 × 2^-1"
    );
    // k = 2: 4 × 1 boxes: verticals at 0.25, 0.5, 0.75 and no horizontal.
    let (ctx, data) = four_points(Some(2));
    let (_, tall, _) = decode(&panel_png(FigureKind::Pattern, &ctx, &data, 1).unwrap());
    assert!(blue_near(&tall, x_half, y_10));
    assert!(blue_near(&tall, 70 + 100, y_10));
    assert!(!blue_near(&tall, x_10, y_half));
    // Three points are not a power of two: nothing drawn.
    let (ctx, mut data) = four_points(Some(1));
    let p = data.points.data().unwrap();
    data.points = samplescope::model::Slot::from(Arc::new(PointsData {
        points: p.points[..3].to_vec(),
        gpu: Arc::new(p.gpu[..3].to_vec()),
        version: 0,
        note: None,
    }));
    let (_, three, _) = decode(&panel_png(FigureKind::Pattern, &ctx, &data, 1).unwrap());
    assert!(!blue_near(&three, x_half, y_10));
}

/// Whether some pixel within ±2 of (x, y) of a 480-wide figure is the strata's light grey.
fn grey_near(px: &[u8], x: usize, y: usize) -> bool {
    (y - 2..=y + 2).any(|yy| {
        (x - 2..=x + 2).any(|xx| {
            let i = (yy * 480 + xx) * 3;
            let (r, g, b) = (px[i] as i32, px[i + 1] as i32, px[i + 2] as i32);
            (r - g).abs() < 6 && (g - b).abs() < 6 && (150..235).contains(&r)
        })
    })
}

#[test]
fn pattern_draws_the_strata_when_the_column_asks() {
    // x = 0.5, y = 0.1 lies on the middle vertical of a 2 × 2 grid, between the points.
    let (x_half, y_10) = (70 + 200, 50 + 360);
    let (mut ctx, data) = four_points(None);
    let (_, plain, _) = decode(&panel_png(FigureKind::Pattern, &ctx, &data, 1).unwrap());
    assert!(!grey_near(&plain, x_half, y_10));
    ctx.strata = Some((2, 2));
    let (_, grid, text) = decode(&panel_png(FigureKind::Pattern, &ctx, &data, 1).unwrap());
    assert!(grey_near(&grid, x_half, y_10));
    assert_eq!(meta(&text, "strata"), "2×2 cells");
}

#[test]
fn the_nrooks_scene_draws_n_by_n_strata_and_strata_need_a_stratified_pattern() {
    let scene = Scene::load(std::path::Path::new("assets/scenes/nrooks-and-lhs.ron")).unwrap();
    for c in 0..scene.columns.len() {
        let ctx = scene_figure::context(&scene, c, "nrooks").unwrap();
        assert_eq!(ctx.strata, Some((10, 10)), "column {c}");
    }
    let e = Scene::from_ron(
        r#"(columns: [(pattern: (kind: "random"), seed: 1, strata: true)], n: 16)"#,
        "strata.ron",
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("columns[0].strata"), "{e}");
    assert!(e.contains("random has no strata"), "{e}");
}

#[test]
fn the_net_scene_columns_carry_their_elementary_k_into_the_figures() {
    let scene = Scene::load(std::path::Path::new(
        "assets/scenes/net-0-4-2-elementary-intervals.ron",
    ))
    .unwrap();
    for (c, want) in [(0, Some(0)), (2, Some(2)), (4, Some(4))] {
        let ctx = scene_figure::context(&scene, c, "net").unwrap();
        assert_eq!(ctx.elementary_k, want);
    }
}

/// The sphere figure of a Hammersley set of 256 points (p1 = 3), the only panel shown.
fn sphere_data() -> (FigureContext, ColumnData) {
    let scene = Scene::from_ron(
        r#"(
            title: "Sphere test",
            columns: [(pattern: (kind: "hammersley", p1: 3), seed: 0, label: "p1 = 3")],
            n: 256,
            panels: (pattern: false, spectrum: false, zoneplate: false, filter: false, sphere: true),
        )"#,
        "sphere.ron",
    )
    .unwrap();
    assert_eq!(panels::available(&scene), vec![FigureKind::Sphere]);
    columns(&scene).remove(0)
}

#[test]
fn sphere_figure_draws_discs_in_both_views_and_repeats_byte_for_byte() {
    let (ctx, data) = sphere_data();
    let n = data.points.data().unwrap().points.len();
    assert_eq!(n, 256);
    let bytes = panel_png(FigureKind::Sphere, &ctx, &data, 1).unwrap();
    assert_eq!(
        bytes,
        panel_png(FigureKind::Sphere, &ctx, &data, 1).unwrap()
    );
    let (info, px, text) = decode(&bytes);
    assert_eq!((info.width, info.height), base_size(FigureKind::Sphere));
    assert_eq!(meta(&text, "figure"), "sphere");
    assert!(meta(&text, "views").contains("front") && meta(&text, "mapping").contains("cylinder"));
    let w = info.width as usize;
    // Dark (near points) and dimmed (far points) pixels in each half, inside the disc band.
    for (x0, x1) in [(0, w / 2), (w / 2, w)] {
        let (mut ink, mut dim) = (0, 0);
        for y in 60..460 {
            for x in x0..x1 {
                let i = (y * w + x) * 3;
                let p = [px[i], px[i + 1], px[i + 2]];
                if p.iter().all(|&c| c < 80) {
                    ink += 1;
                }
                if p == [196, 200, 212] {
                    dim += 1;
                }
            }
        }
        assert!(ink > 20 * 128 / 2, "{x0}..{x1}: {ink} ink pixels");
        assert!(dim > 10 * 128 / 2, "{x0}..{x1}: {dim} dimmed pixels");
    }
    // The CSV holds every point on the unit sphere.
    let csv = panel_csv(FigureKind::Sphere, &ctx, &data).unwrap();
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(lines[0], "x,y,z");
    assert_eq!(lines.len(), n + 1);
    for l in &lines[1..] {
        let v: Vec<f64> = l.split(',').map(|t| t.parse().unwrap()).collect();
        let r = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        assert!((r - 1.0).abs() < 1e-12, "{l}");
    }
    // At scale 2 the same picture, twice the size.
    let (info, _, _) = decode(&panel_png(FigureKind::Sphere, &ctx, &data, 2).unwrap());
    assert_eq!(info.width, 2 * base_size(FigureKind::Sphere).0);
}

/// The one publishing path: everything `render` writes (`Target::All`) is exactly the files of
/// each column's figures, each column's composite and the comparison published one target at
/// a time, as the GUI's Save menus ask for them; bytes included.
#[test]
fn publishing_everything_is_publishing_each_target() {
    use samplescope::export::figure::FileFormat;
    use samplescope::export::publish::{publish, Format, Target};
    let scene = quick_scene();
    let p = scene_figure::publication(&scene, columns(&scene), "figure-test");
    let never = Cancel::never();
    let formats = [Format::Picture(FileFormat::Png), Format::Csv];
    let all = publish(&p, Target::All, &formats, 1, Aspect::SLIDE, &never).unwrap();
    assert!(all.comparison_too_large.is_none());
    let mut each = Vec::new();
    for c in 0..scene.columns.len() {
        assert_eq!(p.figures[c], panels::available_in(&scene, c));
        for &kind in &p.figures[c] {
            let t = Target::Panel { column: c, kind };
            each.extend(
                publish(&p, t, &formats, 1, Aspect::SLIDE, &never)
                    .unwrap()
                    .files,
            );
        }
        let t = Target::Column { column: c };
        each.extend(
            publish(&p, t, &formats, 1, Aspect::SLIDE, &never)
                .unwrap()
                .files,
        );
    }
    let t = Target::Comparison;
    each.extend(
        publish(&p, t, &formats, 1, Aspect::SLIDE, &never)
            .unwrap()
            .files,
    );
    let names = |f: &[(String, Vec<u8>)]| f.iter().map(|(n, _)| n.clone()).collect::<Vec<_>>();
    assert_eq!(names(&all.files), names(&each));
    assert!(all.files == each, "same bytes");
    // A composite is a picture: CSV alone is refused, naming it; so is a column not there.
    let csv = publish(
        &p,
        Target::Column { column: 0 },
        &[Format::Csv],
        1,
        Aspect::SLIDE,
        &never,
    );
    assert!(matches!(
        csv,
        Err(ExportError::NotAPicture { what: "column" })
    ));
    let far = publish(
        &p,
        Target::Column { column: 9 },
        &formats,
        1,
        Aspect::SLIDE,
        &never,
    );
    assert!(matches!(
        far,
        Err(ExportError::OutOfRange {
            field: "column",
            ..
        })
    ));
    // A cancelled publication stops between files.
    let cancel = Cancel::new();
    cancel.cancel();
    let stopped = publish(&p, Target::All, &formats, 1, Aspect::SLIDE, &cancel);
    assert!(matches!(stopped, Err(ExportError::Cancelled)));
}
