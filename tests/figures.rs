//! Figures for slides: PNG/SVG/CSV of every panel, composites, metadata, determinism and
//! errors, on a small scene evaluated through the compute graph (N = 256, 64² images).

use samplescope::core::cancel::Cancel;
use samplescope::export::figure::{
    column_png, column_size, comparison_png, comparison_size, panel_csv, panel_file_name,
    panel_png, panel_rgba, panel_svg, ColumnData, FigureContext, PanelKind, MAX_COMPOSITE_PIXELS,
    SCALES,
};
use samplescope::export::ExportError;
use samplescope::scene::graph::{Evaluator, ImageData, NodeKind, NodeResult, PointsData};
use samplescope::scene::Scene;
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
    panels: (pattern: true, spectrum: true, zoneplate: true, filter: true, cost: true),
    effects: (reconstruction: true, error: true, convergence: true, statistics: false),
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
    results
        .iter()
        .enumerate()
        .map(|(c, r)| {
            (
                FigureContext::new(scene, c, "figure-test").unwrap(),
                ColumnData::from_results(r),
            )
        })
        .collect()
}

fn decode(bytes: &[u8]) -> (png::OutputInfo, Vec<u8>, Vec<(String, String)>) {
    let mut reader = png::Decoder::new(std::io::Cursor::new(bytes))
        .read_info()
        .expect("PNG header");
    let mut buf = vec![0; reader.output_buffer_size()];
    let info = reader.next_frame(&mut buf).expect("PNG frame");
    buf.truncate(info.buffer_size());
    let mut text: Vec<(String, String)> = reader
        .info()
        .uncompressed_latin1_text
        .iter()
        .map(|t| (t.keyword.clone(), t.text.clone()))
        .collect();
    text.extend(
        reader
            .info()
            .utf8_text
            .iter()
            .map(|t| (t.keyword.clone(), t.get_text().unwrap())),
    );
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
    let kinds = PanelKind::available(&scene);
    assert_eq!(
        kinds.len(),
        PanelKind::ALL.len(),
        "the scene shows every figure"
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
            let (bw, bh) = kind.base_size();
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
    let bytes = panel_png(PanelKind::Spectrum, ctx, data, 2).unwrap();
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
    let pattern = panel_svg(PanelKind::Pattern, ctx, data, 1).unwrap();
    assert!(pattern.starts_with("<svg"));
    assert!(pattern.contains("width=\"480\" height=\"510\""));
    assert!(pattern.contains("<title>white noise, N = 256, seed 3</title>"));
    assert!(pattern.contains("pattern: random"));
    assert!(pattern.contains("seed: 3"));
    assert!(pattern.contains("N: 256"));
    assert!(pattern.contains("scene: Figure test, jitter ω²"));
    // Tick labels and axis descriptions are text elements.
    assert!(pattern.contains(">\n0.2\n</text>") && pattern.contains(">\n1.0\n</text>"));
    assert!(pattern.contains(">\nx\n</text>") && pattern.contains(">\ny\n</text>"));
    assert_eq!(
        pattern.matches("<circle").count(),
        256,
        "one circle per point"
    );

    let response = panel_svg(PanelKind::Response, ctx, data, 2).unwrap();
    assert!(response.contains("ω (cycles per sample)"));
    assert!(response.contains("Nyquist, ω = 0.5"));
    assert!(response.contains("width=\"1280\" height=\"1020\""));

    let spectrum = panel_svg(PanelKind::Spectrum, ctx, data, 1).unwrap();
    assert_eq!(
        spectrum.matches("<image ").count(),
        2,
        "the periodogram and its colour bar"
    );
    assert!(spectrum.contains("xlink:href=\"data:image/png;base64,iVBORw0KGgo"));
    assert!(spectrum.contains("log10 P"));
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

    let points = parse_pairs(&panel_csv(PanelKind::Pattern, ctx, data).unwrap(), "x,y");
    let want: Vec<[f64; 2]> = data
        .points
        .as_ref()
        .unwrap()
        .points
        .iter()
        .map(|p| [p.x, p.y])
        .collect();
    assert_eq!(points, want, "points round-trip bit for bit");

    let spectrum = data.spectrum.as_ref().unwrap();
    let raps = parse_pairs(
        &panel_csv(PanelKind::Raps, ctx, data).unwrap(),
        "radius,power",
    );
    assert_eq!(raps, spectrum.raps);

    let response = data.response.as_ref().unwrap();
    let kernel = parse_pairs(&panel_csv(PanelKind::Kernel, ctx, data).unwrap(), "x,h");
    assert_eq!(kernel, response.kernel);
    let mag = parse_pairs(
        &panel_csv(PanelKind::Response, ctx, data).unwrap(),
        "omega,magnitude",
    );
    assert_eq!(mag, response.magnitude);

    let conv = parse_pairs(
        &panel_csv(PanelKind::Convergence, ctx, data).unwrap(),
        "spp,rmse",
    );
    let want: Vec<[f64; 2]> = data
        .convergence
        .as_ref()
        .unwrap()
        .iter()
        .map(|p| [p.spp as f64, p.rmse])
        .collect();
    assert_eq!(conv, want);

    // Periodogram: M² rows of (kx, ky, log10 P), kx and ky in [−M/2, M/2).
    let csv = panel_csv(PanelKind::Spectrum, ctx, data).unwrap();
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
    let recon = data.reconstruction.as_ref().unwrap();
    let csv = panel_csv(PanelKind::Reconstruction, ctx, data).unwrap();
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
    for kind in PanelKind::available(&scene) {
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
    let kinds = PanelKind::composite(&scene);
    assert_eq!(
        comparison_png(&kinds, &a, 1).unwrap(),
        comparison_png(&kinds, &b, 1).unwrap()
    );
}

#[test]
fn scale_out_of_range_is_a_typed_error_naming_the_field_and_range() {
    let scene = quick_scene();
    let cols = columns(&scene);
    let (ctx, data) = &cols[0];
    for bad in [0, SCALES.end() + 1, 9] {
        let e = panel_png(PanelKind::Pattern, ctx, data, bad).unwrap_err();
        assert!(
            matches!(e, ExportError::OutOfRange { field: "scale", .. }),
            "{e:?}"
        );
        let msg = e.to_string();
        assert!(
            msg.contains(&format!("scale = {bad}")) && msg.contains("1..=4"),
            "{msg}"
        );
        assert!(panel_svg(PanelKind::Pattern, ctx, data, bad).is_err());
        assert!(column_png(&[PanelKind::Pattern], ctx, data, bad).is_err());
    }
}

#[test]
fn missing_or_empty_data_is_an_error_naming_the_figure() {
    let scene = quick_scene();
    let ctx = FigureContext::new(&scene, 0, "x").unwrap();
    let none = ColumnData::default();
    for kind in PanelKind::ALL {
        let e = panel_png(kind, &ctx, &none, 1).unwrap_err();
        assert!(
            matches!(e, ExportError::EmptyData { .. }),
            "{kind:?}: {e:?}"
        );
        assert!(e.to_string().starts_with(kind.name()), "{e}");
    }
    let empty = ColumnData {
        points: Some(Arc::new(PointsData {
            points: vec![],
            gpu: Arc::new(vec![]),
            version: 0,
            note: None,
        })),
        ..Default::default()
    };
    let e = panel_png(PanelKind::Pattern, &ctx, &empty, 1).unwrap_err();
    assert!(e.to_string().contains("empty"), "{e}");
    assert!(column_png(&[], &ctx, &empty, 1).is_err());
    assert!(FigureContext::new(&scene, 5, "x").is_err());
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
    let ctx = FigureContext::new(&scene, 0, "x").unwrap();
    let mut colours = Vec::new();
    for level in [0.0f32, 1.0] {
        let data = ColumnData {
            reconstruction: Some(Arc::new(samplescope::scene::graph::ReconData {
                image: ImageData::new(8, 8, vec![level; 64]),
                zero_weight: 0,
            })),
            ..Default::default()
        };
        let (w, h, rgba) = panel_rgba(PanelKind::Reconstruction, &ctx, &data, 1).unwrap();
        assert_eq!((w, h), (480, 510));
        let rgb: Vec<u8> = rgba
            .chunks(4)
            .flat_map(|p| {
                assert_eq!(p[3], 255);
                [p[0], p[1], p[2]]
            })
            .collect();
        let (_, decoded, _) =
            decode(&panel_png(PanelKind::Reconstruction, &ctx, &data, 1).unwrap());
        assert_eq!(rgb, decoded, "RGBA and PNG hold the same pixels");
        colours.push(plot_centre(&rgb));
    }
    assert_eq!(colours, vec![[0, 0, 0], [255, 255, 255]]);

    // One point in the middle of the unit square: dark there, white a bit away.
    let one = ColumnData {
        points: Some(Arc::new(PointsData {
            points: vec![glam::DVec2::new(0.5, 0.5)],
            gpu: Arc::new(vec![[0.5, 0.5]]),
            version: 0,
            note: None,
        })),
        ..Default::default()
    };
    let (_, px, _) = decode(&panel_png(PanelKind::Pattern, &ctx, &one, 1).unwrap());
    let centre = plot_centre(&px);
    assert!(centre.iter().all(|&c| c < 60), "{centre:?}");
    let off = ((40 + 10 + 100) * 480 + 10 + 60 + 100) * 3;
    assert_eq!(&px[off..off + 3], &[255, 255, 255]);
}

#[test]
fn composites_put_every_panel_of_every_column_side_by_side() {
    let scene = quick_scene();
    let cols = columns(&scene);
    let kinds = PanelKind::composite(&scene);
    assert_eq!(
        kinds,
        vec![
            PanelKind::Pattern,
            PanelKind::Spectrum,
            PanelKind::Reconstruction,
            PanelKind::Kernel,
            PanelKind::Response
        ]
    );
    let width: u32 = kinds.iter().map(|k| k.base_size().0).sum();
    let (ctx, data) = &cols[0];
    let (info, _, text) = decode(&column_png(&kinds, ctx, data, 1).unwrap());
    assert_eq!((info.width, info.height), (width, 510 + 36));
    assert_eq!(meta(&text, "figure"), "column");
    assert_eq!(meta(&text, "seed"), "7");
    let (info, _, text) = decode(&comparison_png(&kinds, &cols, 2).unwrap());
    assert_eq!(
        comparison_size(&kinds, 2, 2),
        (info.width as u64, info.height as u64)
    );
    assert_eq!(column_size(&kinds, 1), (width as u64, 510 + 36));
    // Eight columns of five figures at scale 4 exceed the limit: refused, not allocated.
    let (w, h) = comparison_size(&kinds, 8, 4);
    assert!(w * h > MAX_COMPOSITE_PIXELS);
    let many: Vec<_> = (0..8).map(|_| cols[0].clone()).collect();
    let e = comparison_png(&kinds, &many, 4).unwrap_err();
    assert!(matches!(e, ExportError::TooLarge { .. }), "{e:?}");
    assert_eq!(
        (info.width, info.height),
        (2 * width, 2 * (44 + 2 * (510 + 36)))
    );
    assert_eq!(meta(&text, "figure"), "comparison");
    let columns_meta = meta(&text, "columns");
    assert!(columns_meta.contains("jitter") && columns_meta.contains("white noise: random"));
}

#[test]
fn file_names_carry_scene_pattern_n_seed_kind_and_scale() {
    let scene = quick_scene();
    let ctx = FigureContext::new(&scene, 0, "zone-plate-128-to-512").unwrap();
    assert_eq!(
        panel_file_name(PanelKind::Spectrum, &ctx, Some(2), "png"),
        "zone-plate-128-to-512_jitter_n256_seed7_spectrum@2x.png"
    );
    let ctx = FigureContext::new(&scene, 1, "").unwrap();
    assert_eq!(
        panel_file_name(PanelKind::Raps, &ctx, None, "csv"),
        "figure-test-jitter_random-white-noise_n256_seed3_raps.csv"
    );
    assert_eq!(
        panel_file_name(PanelKind::Pattern, &ctx, Some(3), ""),
        "figure-test-jitter_random-white-noise_n256_seed3_pattern@3x"
    );
}
