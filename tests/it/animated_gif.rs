//! Animated figures: `samplescope render --format gif` of a moving scene and of a prefix
//! playback, decoded with the gif crate (frame count, delays, the looping extension, size,
//! the frames' content), byte-identical reruns, the budget refused before any work, scenes that
//! do not animate refused in one line, and the flags' ranges.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// A small moving scene: a grating drifting 0.9 period per frame.
const MOTION: &str = r#"(
    title: "GIF test: drifting grating",
    columns: [
        (pattern: (kind: "grid", cols: 0), seed: 1),
        (pattern: (kind: "jitter", cols: 0, amount: 1.0), seed: 1),
    ],
    n: 1024,
    signal: (kind: "grating", frequency: 8.0, angle: 0.0, phase: 0.0),
    filter: (filter: (kind: "gaussian", sigma: 0.5, radius: 2.0, subtract_edge: true), mode: separable),
    recon: (mode: scattered, size: 64),
    panels: (pattern: false, spectrum: false, zoneplate: true, filter: false, cost: false),
    effects: (reconstruction: true, error: false, convergence: false, statistics: false),
    motion: Some((velocity_x: 2.7, frame_rate: 24.0)),
)"#;

/// A small prefix playback: a Sobol' sequence filling the square.
const PREFIX: &str = r#"(
    title: "GIF test: Sobol' prefixes",
    columns: [(pattern: (kind: "sobol", scramble: none, skip: 0), seed: 0)],
    n: 64,
    spectrum: (size: 32, exact: true),
    panels: (pattern: true, spectrum: true, zoneplate: false, filter: false, cost: false),
    effects: (reconstruction: false, error: false, convergence: false, statistics: false),
    animation: (frames: 8, fps: 12.0),
)"#;

fn temp_dir(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("animated_gif-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn render(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_samplescope"))
        .arg("render")
        .args(args)
        .env("SAMPLESCOPE_NO_CACHE", "1")
        .output()
        .expect("run samplescope")
}

fn scene_file(dir: &Path, name: &str, text: &str) -> String {
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path.display().to_string()
}

fn only_file(dir: &Path) -> PathBuf {
    let files: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    assert_eq!(files.len(), 1, "{files:?}");
    files[0].clone()
}

/// The decoded GIF: (width, height, looping for ever, per frame (delay, RGBA pixels)).
fn decode(bytes: &[u8]) -> (u16, u16, bool, Vec<(u16, Vec<u8>)>) {
    let mut opts = gif::DecodeOptions::new();
    opts.set_color_output(gif::ColorOutput::RGBA);
    let mut d = opts.read_info(bytes).unwrap();
    let (w, h) = (d.width(), d.height());
    let mut frames = Vec::new();
    while let Some(f) = d.read_next_frame().unwrap() {
        assert_eq!((f.width, f.height, f.left, f.top), (w, h, 0, 0));
        frames.push((f.delay, f.buffer.to_vec()));
    }
    let forever = d.repeat() == gif::Repeat::Infinite;
    (w, h, forever, frames)
}

#[test]
fn a_moving_scene_renders_as_a_looping_gif_byte_identical_twice() {
    let dir = temp_dir("motion");
    let scene = scene_file(&dir, "drift.ron", MOTION);
    let (a, b) = (dir.join("a"), dir.join("b"));
    for out in [&a, &b] {
        let o = render(&[
            &scene,
            "--out",
            out.to_str().unwrap(),
            "--format",
            "gif",
            "--frames",
            "6",
            "--fps",
            "24",
        ]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    }
    let (fa, fb) = (only_file(&a), only_file(&b));
    assert_eq!(
        fa.file_name().unwrap().to_str().unwrap(),
        "drift_n1024_comparison@1x.gif"
    );
    let bytes = std::fs::read(&fa).unwrap();
    assert_eq!(bytes, std::fs::read(&fb).unwrap(), "two renders differ");
    assert_eq!(&bytes[..6], b"GIF89a");
    assert!(bytes.windows(11).any(|w| w == b"NETSCAPE2.0"));
    let (w, h, forever, frames) = decode(&bytes);
    assert!(forever);
    assert_eq!(frames.len(), 6);
    // 24 fps: 4, 4, 5, 4, 4, 4 centiseconds (25 cs per 6 frames).
    let delays: Vec<u16> = frames.iter().map(|f| f.0).collect();
    assert_eq!(delays, [4, 4, 5, 4, 4, 4]);
    // The frame is the comparison's PNG, at the same size.
    let png = dir.join("png");
    let o = render(&[&scene, "--out", png.to_str().unwrap(), "--format", "png"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let cmp = png.join("drift_n1024_comparison@1x.png");
    let dec = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(&cmp).unwrap()));
    let info = dec.read_info().unwrap();
    assert_eq!(
        (u32::from(w), u32::from(h)),
        (info.info().width, info.info().height)
    );
    // The grating moves: consecutive frames differ.
    for pair in frames.windows(2) {
        assert_ne!(pair[0].1, pair[1].1);
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_prefix_playback_grows_frame_by_frame_at_the_scene_s_rate() {
    let dir = temp_dir("prefix");
    let scene = scene_file(&dir, "fill.ron", PREFIX);
    let out = dir.join("out");
    let o = render(&[&scene, "--out", out.to_str().unwrap(), "--format", "gif"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let bytes = std::fs::read(only_file(&out)).unwrap();
    let (_, _, forever, frames) = decode(&bytes);
    assert!(forever);
    // The scene's animation: 8 frames at 12 fps (8, 8, 9, 8, 8, 9, … cs).
    assert_eq!(frames.len(), 8);
    let total: u32 = frames.iter().map(|f| u32::from(f.0)).sum();
    assert_eq!(total, (100.0 * 8.0 / 12.0_f64).round() as u32);
    // Frame i is the comparison figure of the scene showing its first ⌈64 (i + 1) / 8⌉
    // points (as `render` draws it in PNG, up to the palette): frame 0 that of 8 points,
    // frame 7 that of all 64.
    let still = |k: Option<usize>| -> Vec<u8> {
        let text = match k {
            Some(k) => PREFIX.replace("n: 64,", &format!("n: 64,\n    prefix: Some({k}),")),
            None => PREFIX.to_string(),
        };
        let sub = dir.join(format!("still-{k:?}"));
        std::fs::create_dir_all(&sub).unwrap();
        let file = scene_file(&sub, "fill.ron", &text);
        let o = render(&[
            &file,
            "--out",
            sub.join("out").to_str().unwrap(),
            "--format",
            "png",
        ]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let path = sub.join("out/fill_n64_comparison@1x.png");
        let mut dec =
            png::Decoder::new(std::io::BufReader::new(std::fs::File::open(path).unwrap()));
        dec.set_transformations(png::Transformations::EXPAND);
        let mut r = dec.read_info().unwrap();
        let mut buf = vec![0; r.output_buffer_size()];
        let info = r.next_frame(&mut buf).unwrap();
        buf.truncate(info.buffer_size());
        let rgb: Vec<u8> = match info.color_type {
            png::ColorType::Rgb => buf,
            png::ColorType::Rgba => buf
                .chunks_exact(4)
                .flat_map(|p| [p[0], p[1], p[2]])
                .collect(),
            other => panic!("{other:?}"),
        };
        rgb
    };
    let diff = |rgb: &[u8], rgba: &[u8]| -> f64 {
        assert_eq!(rgb.len() / 3, rgba.len() / 4);
        let sum: u64 = rgb
            .chunks_exact(3)
            .zip(rgba.chunks_exact(4))
            .map(|(a, b)| (0..3).map(|c| u64::from(a[c].abs_diff(b[c]))).sum::<u64>())
            .sum();
        sum as f64 / rgb.len() as f64
    };
    let last = still(None);
    let (f0, f7) = (&frames[0].1, &frames[7].1);
    // The last frame is the still comparison of all 64 points (up to the palette).
    assert!(
        diff(&last, f7) < 2.0,
        "frame 7 vs 64 points: {}",
        diff(&last, f7)
    );
    // Frame 0 is the comparison of its 8 points with the periodogram in the last frame's
    // colour range (the animation's one range), drawn here by the library.
    let first = {
        use samplescope::core::cancel::Cancel;
        use samplescope::engine::Evaluator;
        use samplescope::export::figure::Aspect;
        use samplescope::export::publish::{picture, Target};
        use samplescope::scene::{figure, Scene};
        let scene = samplescope::scene::Scene::from_ron(PREFIX, "fill.ron").unwrap();
        let eval = Evaluator::default();
        let columns = |s: &Scene| {
            let mut results = vec![std::collections::HashMap::new(); s.columns.len()];
            eval.evaluate(s, &Cancel::never(), &mut |c, k, r| {
                results[c].insert(k, r);
            });
            figure::figure_columns(s, &results, "fill").unwrap()
        };
        let range = columns(&scene.frame(7).unwrap())[0].0.spectrum_range;
        let s0 = scene.frame(0).unwrap();
        assert_eq!(s0.prefix, Some(8));
        let mut c0 = columns(&s0);
        assert_ne!(
            c0[0].0.spectrum_range, range,
            "8 points have a range of their own"
        );
        for (ctx, _) in &mut c0 {
            ctx.spectrum_range = range;
        }
        let p = figure::publication(&s0, c0, "fill");
        let (_, _, rgba, _) = picture(&p, Target::Comparison, 1, Aspect::SLIDE).unwrap();
        rgba.chunks_exact(4)
            .flat_map(|p| [p[0], p[1], p[2]])
            .collect::<Vec<u8>>()
    };
    assert!(
        diff(&first, f0) < 2.0,
        "frame 0 vs 8 points: {}",
        diff(&first, f0)
    );
    assert!(
        diff(&first, f7) > 2.0 * diff(&first, f0),
        "frame 7 looks like 8 points"
    );
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn gif_refusals_are_one_line_before_any_work() {
    let dir = temp_dir("refuse");
    let moving = scene_file(&dir, "drift.ron", MOTION);
    let out = dir.join("out");
    let out_s = out.to_str().unwrap();
    let check = |args: &[&str], needles: &[&str]| {
        let o = render(args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(err.trim().lines().count(), 1, "{err}");
        for n in needles {
            assert!(err.contains(n), "{n:?} not in {err}");
        }
        assert!(!out.exists() || std::fs::read_dir(&out).unwrap().next().is_none());
    };
    // The budget: 1000 frames of the comparison at scale 4 are far beyond it.
    check(
        &[
            &moving, "--out", out_s, "--format", "gif", "--frames", "1000", "--scale", "4",
        ],
        &["--frames = 1000", "2..="],
    );
    check(
        &[&moving, "--out", out_s, "--format", "gif", "--frames", "1"],
        &["--frames = 1", "2..=1000"],
    );
    check(
        &[&moving, "--out", out_s, "--format", "gif", "--fps", "60"],
        &["--fps = 60", "1..=50"],
    );
    check(
        &[&moving, "--out", out_s, "--format", "png", "--frames", "4"],
        &["--frames", "--format gif"],
    );
    // A still scene: which scenes animate.
    let still = scene_file(
        &dir,
        "still.ron",
        &MOTION.replace("motion: Some((velocity_x: 2.7, frame_rate: 24.0)),", ""),
    );
    check(
        &[&still, "--out", out_s, "--format", "gif"],
        &["does not animate", "motion", "sobol", "poisson-dart"],
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// Every frame's periodograms share one colour range, the last frame's (all N points), so the
/// spectrum does not flicker as the prefix grows; drawn on its own, frame 0's range differs.
#[test]
fn every_frame_uses_the_last_frame_s_spectrum_range() {
    use samplescope::core::cancel::Cancel;
    use samplescope::engine::animation::{prepare, render_gif};
    use samplescope::engine::Evaluator;
    use samplescope::export::figure::Aspect;
    use samplescope::scene::graph::NodeKind;
    use samplescope::scene::{figure, Scene};
    use std::collections::HashMap;
    let scene = Scene::from_ron(PREFIX, "fill.ron").unwrap();
    let prepared = prepare(&scene, "fill", 1, Aspect::SLIDE, "animation.frames").unwrap();
    let eval = Evaluator::default();
    let mut ranges = Vec::new();
    let bytes = render_gif(&prepared, &eval, &Cancel::never(), &mut |f| {
        assert_eq!(f.index, ranges.len());
        assert_eq!(f.frames, 8);
        ranges.push(f.spectrum_range.expect("the scene draws a periodogram"));
    })
    .unwrap();
    assert_eq!(ranges.len(), 8);
    assert!(ranges.iter().all(|r| *r == ranges[7]), "{ranges:?}");
    // Each frame's own range (what `render` gives that frame's still figure).
    let own = |i: usize| {
        let s = scene.frame(i).unwrap();
        let mut results = vec![HashMap::new(); s.columns.len()];
        eval.evaluate(&s, &Cancel::never(), &mut |c, k: NodeKind, r| {
            results[c].insert(k, r);
        });
        let columns = figure::figure_columns(&s, &results, "fill").unwrap();
        columns[0].0.spectrum_range.unwrap()
    };
    assert_eq!(
        own(7),
        ranges[7],
        "the last frame's range is its still figure's"
    );
    assert_ne!(
        own(0),
        ranges[0],
        "frame 0 on its own would use another range"
    );
    // The same GIF again: deterministic.
    let again = render_gif(&prepared, &eval, &Cancel::never(), &mut |_| {}).unwrap();
    assert_eq!(bytes, again);
}

/// The GUI's Save comparison menu: an animated scene offers its animated GIF, which is the
/// file `render --format gif` writes, byte for byte; a still scene offers none; a GIF beyond
/// the budget is refused before any work; a cancelled one leaves no file.
mod gui {
    use super::*;
    use egui_kittest::kittest::Queryable;
    use egui_kittest::Harness;
    use samplescope::scene::graph::NodeKind;
    use samplescope::scene::Scene;
    use samplescope::ui::SamplescopeApp;
    use std::time::{Duration, Instant};

    fn harness(text: &str, name: &str, dir: &Path) -> Harness<'static, SamplescopeApp> {
        let scene = Scene::from_ron(text, name).unwrap();
        let (name, dir) = (name.to_string(), dir.display().to_string());
        let mut h = Harness::builder()
            .with_size(eframe::egui::Vec2::new(1400.0, 1000.0))
            .build_eframe(move |cc| {
                let mut app = crate::hermetic_app(cc);
                app.view.show_timings = false;
                app.view.figure_dir = dir.clone();
                app.set_scene(scene.clone(), name.clone());
                app
            });
        crate::settle(&mut h, 1);
        h
    }

    fn open_menu(h: &mut Harness<'static, SamplescopeApp>) {
        h.get_by_label("Save comparison").click();
        h.run_steps(2);
    }

    /// Steps until the GIF saver is done; its status.
    fn finished(h: &mut Harness<'static, SamplescopeApp>) -> String {
        let deadline = Instant::now() + Duration::from_secs(120);
        while h.state().gif.busy() {
            h.step();
            std::thread::sleep(Duration::from_millis(10));
            assert!(Instant::now() < deadline, "GIF not finished");
        }
        h.state().gif.status.clone().unwrap_or_default()
    }

    #[test]
    fn save_menu_writes_the_gif_render_writes() {
        let dir = temp_dir("gui");
        let figures = dir.join("figures");
        let mut h = harness(PREFIX, "fill.ron", &figures);
        open_menu(&mut h);
        h.get_by_label("Animated GIF 1×").click();
        h.step();
        assert!(h.state().gif.busy() || h.state().gif.status.is_some());
        let status = finished(&mut h);
        let path = figures.join("fill_n64_comparison@1x.gif");
        assert!(
            status.starts_with("saved ") && status.contains("8 frames"),
            "{status}"
        );
        let ours = std::fs::read(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let file = scene_file(&dir, "fill.ron", PREFIX);
        let out = dir.join("cli");
        let o = render(&[&file, "--out", out.to_str().unwrap(), "--format", "gif"]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let theirs = std::fs::read(out.join("fill_n64_comparison@1x.gif")).unwrap();
        assert!(ours == theirs, "the GUI's GIF differs from render's");
        // Nothing else was left in the folder (no partial file).
        assert_eq!(only_file(&figures), path);
        std::fs::remove_dir_all(&dir).ok();
    }

    #[test]
    fn a_still_scene_offers_no_gif_and_a_moving_one_does() {
        let dir = temp_dir("gui-still");
        let still = MOTION.replace("motion: Some((velocity_x: 2.7, frame_rate: 24.0)),", "");
        let mut h = harness(&still, "still.ron", &dir);
        open_menu(&mut h);
        h.get_by_label("PNG 1×");
        assert!(h.query_by_label_contains("Animated GIF").is_none());
        let mut h = harness(MOTION, "drift.ron", &dir);
        open_menu(&mut h);
        h.get_by_label("Animated GIF 1×");
        h.get_by_label("Animated GIF 2×");
        std::fs::remove_dir_all(&dir).ok();
    }

    #[test]
    fn a_gif_over_the_budget_is_refused_before_any_work() {
        let dir = temp_dir("gui-budget");
        let figures = dir.join("figures");
        let mut h = harness(PREFIX, "fill.ron", &figures);
        let eval = h.state().engine.evaluator().clone();
        // 1000 frames at 2× are beyond the GIF's pixel budget.
        h.state_mut().scene.animation.frames = 1000;
        crate::settle(&mut h, 1);
        let before_spectra = eval.count(NodeKind::Spectrum);
        open_menu(&mut h);
        h.get_by_label("Animated GIF 2×").click();
        h.step();
        assert!(!h.state().gif.busy());
        let status = h.state().gif.status.clone().unwrap_or_default();
        assert!(
            status.starts_with("GIF not saved: animation.frames = 1000:")
                && status.contains("2..="),
            "{status}"
        );
        assert_eq!(
            eval.count(NodeKind::Spectrum),
            before_spectra,
            "work was done"
        );
        assert!(!figures.exists());
        // The compute budget: a budget of almost nothing refuses the GIF the same way.
        h.state_mut().scene.animation.frames = 8;
        h.state_mut().budget.seconds = 1e-9;
        h.step();
        open_menu(&mut h);
        h.get_by_label("Animated GIF 1×").click();
        h.step();
        assert!(!h.state().gif.busy());
        let status = h.state().gif.status.clone().unwrap_or_default();
        assert!(status.starts_with("GIF not saved: "), "{status}");
        assert!(!figures.exists());
        std::fs::remove_dir_all(&dir).ok();
    }

    #[test]
    fn a_cancelled_gif_leaves_no_file() {
        let dir = temp_dir("gui-cancel");
        let figures = dir.join("figures");
        // Many frames of a larger scene: far from done when cancelled.
        let text = PREFIX
            .replace("n: 64,", "n: 4096,")
            .replace("frames: 8,", "frames: 200,");
        let mut h = harness(&text, "fill.ron", &figures);
        open_menu(&mut h);
        h.get_by_label("Animated GIF 1×").click();
        h.run_steps(2);
        assert!(h.state().gif.busy());
        h.get_by_label_contains("saving GIF: frame");
        h.get_by_label("Cancel GIF").click();
        let status = finished(&mut h);
        assert_eq!(
            status,
            "GIF cancelled: fill_n4096_comparison@1x.gif not written"
        );
        let left: Vec<_> = std::fs::read_dir(&figures)
            .map(|d| d.map(|e| e.unwrap().path()).collect())
            .unwrap_or_default();
        assert!(left.is_empty(), "{left:?}");
        std::fs::remove_dir_all(&dir).ok();
    }
}
