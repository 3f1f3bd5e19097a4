//! Every shipped scene, as shipped: the files in `assets/scenes` (read from the directory, so a
//! new file cannot be forgotten) and the built-in list match one to one, every scene has notes,
//! and every node of every scene evaluates without an error at the scene's own sizes.
//!
//! Heavy by design: `texture-256spp` (256 samples per pixel on 256², ~17 M samples) and the
//! 512² resampling scenes; the whole test stays well under two minutes in the dev profile.

use samplescope::core::cancel::Cancel;
use samplescope::core::params::Params;
use samplescope::engine::Evaluator;
use samplescope::model::FigureKind;
use samplescope::scene::graph::NodeKind;
use samplescope::scene::{panels, Scene, BUILTIN};
use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

fn scene_files() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().and_then(|e| e.to_str()) == Some("ron"))
        .collect();
    files.sort();
    files
}

fn file_name(p: &Path) -> String {
    p.file_name().unwrap().to_string_lossy().into_owned()
}

#[test]
fn builtin_list_matches_the_directory() {
    let on_disk: BTreeSet<String> = scene_files().iter().map(|p| file_name(p)).collect();
    let built_in: BTreeSet<String> = BUILTIN.iter().map(|(n, _)| n.to_string()).collect();
    assert_eq!(
        BUILTIN.len(),
        built_in.len(),
        "a built-in name appears twice"
    );
    let missing: Vec<_> = on_disk.difference(&built_in).collect();
    let stale: Vec<_> = built_in.difference(&on_disk).collect();
    assert!(
        missing.is_empty() && stale.is_empty(),
        "files not in BUILTIN: {missing:?}; BUILTIN entries without a file: {stale:?}"
    );
    // The built-in text is the file's text (include_str! of the same path).
    for (name, text) in BUILTIN {
        let path = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("assets/scenes")
            .join(name);
        assert_eq!(std::fs::read_to_string(&path).unwrap(), *text, "{name}");
    }
    assert!(
        on_disk.len() >= 30,
        "expected the lecture's scenes, found {}",
        on_disk.len()
    );
}

#[test]
fn every_scene_has_a_title_and_notes() {
    for (name, text) in BUILTIN {
        let s = Scene::from_ron(text, name).unwrap_or_else(|e| panic!("{e}"));
        assert!(
            !s.title.is_empty() && s.title != "untitled",
            "{name}: title"
        );
        assert!(s.notes.len() >= 40, "{name}: notes say what to look at");
    }
}

#[test]
fn every_scene_evaluates_without_a_node_error() {
    let mut failures = Vec::new();
    // One evaluator for all scenes, as in the app: scenes that share a node (the kernel-*
    // scenes' reference image) compute it once.
    let eval = Evaluator::default();
    for path in scene_files() {
        let name = file_name(&path);
        let scene = match Scene::load(&path) {
            Ok(s) => s,
            Err(e) => {
                failures.push(format!("{name}: {e}"));
                continue;
            }
        };
        // The built-in copy parses to the same scene.
        let (_, text) = BUILTIN.iter().find(|(n, _)| *n == name).unwrap();
        assert_eq!(Scene::from_ron(text, &name).unwrap(), scene, "{name}");
        let mut nodes = 0;
        let mut reconstructions = 0;
        let start = std::time::Instant::now();
        eval.evaluate(&scene, &Cancel::new(), &mut |c, kind, r| {
            nodes += 1;
            reconstructions += usize::from(kind == NodeKind::Reconstruction);
            if let Err(e) = &r.value {
                failures.push(format!("{name}: column {} {}: {e}", c + 1, kind.name()));
            }
        });
        assert!(nodes > 0, "{name}: no node evaluated");
        // A scene that shows the zone plate computes a reconstruction for every column.
        if scene.panels.zoneplate && scene.effects.reconstruction {
            assert_eq!(
                reconstructions,
                scene.columns.len(),
                "{name}: one reconstruction per column"
            );
        }
        // Scenes with motion also evaluate a later frame.
        if let Some(m) = scene.motion {
            let later = scene.at_time(m.frame_time(5)).unwrap();
            eval.evaluate(&later, &Cancel::new(), &mut |c, kind, r| {
                if let Err(e) = &r.value {
                    failures.push(format!(
                        "{name} (frame 5): column {} {}: {e}",
                        c + 1,
                        kind.name()
                    ));
                }
            });
        }
        eprintln!("{name}: {nodes} nodes in {:.2?}", start.elapsed());
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

/// The net scene's claim, checked exactly: every Hammersley column has one point in each of the
/// 16 elementary intervals 2^-k × 2^-(4-k) of its own shape k, and the jittered column, drawn
/// with a non-square shape, does not.
#[test]
fn net_scene_columns_hold_one_point_per_elementary_interval_of_their_shape() {
    let (name, text) = BUILTIN
        .iter()
        .find(|(n, _)| *n == "net-0-4-2-elementary-intervals.ron")
        .expect("net scene shipped");
    let scene = Scene::from_ron(text, name).unwrap();
    assert_eq!(scene.n, 16);
    let mut shapes = BTreeSet::new();
    for col in &scene.columns {
        let k = col.elementary_k.expect("every column draws a shape");
        let pts = col.pattern.generate(scene.n, col.seed).unwrap();
        let (nx, ny) = (1usize << k, 1usize << (4 - k));
        let mut counts = vec![0usize; 16];
        for p in &pts {
            let i = (p.x * nx as f64).floor() as usize;
            let j = (p.y * ny as f64).floor() as usize;
            counts[j * nx + i] += 1;
        }
        let one_each = counts.iter().all(|&c| c == 1);
        if col.pattern.name() == "hammersley" {
            assert!(one_each, "{}: {counts:?}", col.title());
            shapes.insert(k);
        } else {
            assert!(!one_each, "{} should not be a net for k = {k}", col.title());
        }
    }
    assert_eq!(
        shapes,
        (0..=4).collect::<BTreeSet<u32>>(),
        "all five shapes"
    );
}

#[test]
fn the_hammersley_scene_shows_every_p1_on_the_sphere_as_the_lecture_does() {
    let text = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes/hammersley-p1.ron"),
    )
    .unwrap();
    let scene = Scene::from_ron(&text, "hammersley-p1.ron").unwrap();
    let mut p1s = Vec::new();
    for (c, col) in scene.columns.iter().enumerate() {
        assert_eq!(col.pattern.name(), "hammersley");
        p1s.push(col.pattern.get("p1").unwrap().to_string());
        assert!(panels::available_in(&scene, c).contains(&FigureKind::Sphere));
    }
    assert_eq!(p1s, ["2", "3", "5", "7", "11"]);
    // The comparison holds the square and the sphere of every column.
    let kinds = panels::comparison(&scene);
    assert!(kinds.contains(&FigureKind::Pattern) && kinds.contains(&FigureKind::Sphere));
}

#[test]
fn elementary_k_out_of_range_names_the_column_field() {
    let text = "(columns: [(elementary_k: Some(25))])";
    let err = Scene::from_ron(text, "bad.ron").unwrap_err().to_string();
    assert!(err.contains("columns[0].elementary_k"), "{err}");
    assert!(err.contains("0..=24"), "{err}");
}

#[test]
fn recon_mode_and_transform_pair_errors_come_from_their_descriptors() {
    // Each line: the scene text, the field path and the message its descriptor gives, with
    // the scene file's line:column.
    for (text, want) in [
        (
            "(recon: (mode: supersample(spp: 0)))",
            "recon.mode.spp = 0: must be an integer in 1..=1024",
        ),
        (
            "(recon: (mode: supersample(spp: 1025)))",
            "recon.mode.spp = 1025: must be an integer in 1..=1024",
        ),
        (
            "(recon: (mode: resample(grid: 1)))",
            "recon.mode.grid = 1: must be an integer in 2..=4096",
        ),
        (
            "(theorem: (pair: (scale: -30.0)))",
            "theorem.pair.scale = -30: must be a finite number with |scale| in [0.05, 20]",
        ),
        (
            "(theorem: (pair: (scale: 0.0)))",
            "theorem.pair.scale = 0: must be a finite number with |scale| in [0.05, 20]",
        ),
        (
            "(theorem: (pair: (shift: 10.5)))",
            "theorem.pair.shift = 10.5: must be a finite number in [-10, 10]",
        ),
        (
            "(theorem: (vdc_rows: 0))",
            "theorem.vdc_rows = 0: must be an integer in 1..=1024",
        ),
    ] {
        let err = Scene::from_ron(text, "bad.ron").unwrap_err().to_string();
        assert!(err.contains(want), "{text}: {err}");
    }
    // Their ends are allowed, negative scales included.
    for text in [
        "(recon: (mode: supersample(spp: 1024)))",
        "(recon: (mode: resample(grid: 4096)))",
        "(theorem: (pair: (scale: -0.05, shift: -10.0)))",
        "(theorem: (pair: (scale: 20.0, shift: 10.0)))",
    ] {
        Scene::from_ron(text, "ok.ron").unwrap_or_else(|e| panic!("{text}: {e}"));
    }
}
