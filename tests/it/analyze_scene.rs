//! `samplescope analyze` is a front over a scene run by the engine: its spectrum estimate and
//! error check are the scene's rule, its measured error is the spectrum node's, and its
//! `--spectrum` PNG is the scene's spectrum figure with the figures' metadata.

use samplescope::core::budget;
use samplescope::core::cancel::Cancel;
use samplescope::core::pattern::Pattern;
use samplescope::core::spectrum::DEFAULT_ERROR_CHECK_BUDGET;
use samplescope::engine::Evaluator;
use samplescope::model::{Accuracy, FigureKind};
use samplescope::scene::graph::NodeKind;
use samplescope::scene::{Column, Scene, SpectrumSettings};
use std::path::PathBuf;
use std::process::{Command, Output};

fn samplescope(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_samplescope"))
        .args(args)
        .env("SAMPLESCOPE_NO_CACHE", "1")
        .output()
        .expect("run samplescope")
}

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

fn temp_dir(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("analyze_scene-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir
}

fn jitter() -> Pattern {
    Pattern::from_name("jitter").unwrap()
}

#[test]
fn the_spectrum_estimate_checks_the_error_by_the_scene_s_rule() {
    // 65536 points on 2048²: the scene's check (two rows of the exact DFT, 2·N·M = 2.7·10⁸
    // multiply-adds) costs far more than the core's default 2²², so the two estimates differ.
    let (n, m) = (65536, 2048);
    let o = samplescope(&[
        "analyze",
        "jitter",
        "-n",
        "65536",
        "--size",
        "2048",
        "--estimate",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stdout(&o));
    let text = stdout(&o);
    let settings = SpectrumSettings {
        size: m,
        ..SpectrumSettings::default()
    };
    let scene_rule = settings.request(n, false);
    assert_eq!(scene_rule.error_check_budget, 2 * (n * m) as u64);
    let want = budget::spectrum(&scene_rule, n, Some(&jitter())).to_string();
    let core_default = budget::spectrum(
        &samplescope::core::spectrum::SpectrumRequest {
            error_check_budget: DEFAULT_ERROR_CHECK_BUDGET,
            ..scene_rule
        },
        n,
        Some(&jitter()),
    )
    .to_string();
    assert_ne!(want, core_default, "the case must tell the rules apart");
    assert!(text.lines().any(|l| l == want), "{want}\nnot in\n{text}");
    // Every node's estimate is the scene's: statistics and PSA's are listed too.
    assert!(text.contains("statistics of 65536 points"), "{text}");
    assert!(text.contains("PSA statistics of 65536 points"), "{text}");
}

#[test]
fn the_measured_spectrum_error_is_the_spectrum_node_s() {
    let o = samplescope(&[
        "analyze", "jitter", "-n", "1024", "--seed", "5", "--size", "64", "--json",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stdout(&o));
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    // The same column in a scene the GUI would show, evaluated by the engine.
    let mut scene = Scene {
        columns: vec![Column {
            pattern: jitter(),
            seed: 5,
            ..Column::default()
        }],
        n: 1024,
        ..Scene::default()
    };
    scene.spectrum.size = 64;
    let mut accuracy = None;
    Evaluator::default().evaluate(&scene, &Cancel::never(), &mut |_, kind, r| {
        if kind == NodeKind::Spectrum {
            accuracy = r.accuracy.clone();
        }
    });
    let Some(Accuracy::SpectrumMeasured { relative_l2, .. }) = accuracy else {
        panic!("{accuracy:?}");
    };
    assert_eq!(
        v["spectrum"]["measured_relative_l2_error"].as_f64(),
        Some(relative_l2)
    );
}

#[test]
fn the_spectrum_png_is_the_spectrum_figure_with_the_figures_metadata() {
    let dir = temp_dir("png");
    let out = dir.join("s.png");
    let o = samplescope(&[
        "analyze",
        "jitter",
        "-n",
        "256",
        "--size",
        "32",
        "--spectrum",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stdout(&o));
    let decoder = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(&out).unwrap()));
    let reader = decoder.read_info().unwrap();
    let info = reader.info();
    assert_eq!(
        (info.width, info.height),
        samplescope::export::figure::base_size(FigureKind::Spectrum)
    );
    let text = super::png_text(info);
    let keys: Vec<&str> = text.iter().map(|(k, _)| k.as_str()).collect();
    assert_eq!(
        keys,
        [
            "Title",
            "Software",
            "figure",
            "scene",
            "column",
            "pattern",
            "pattern parameters",
            "N",
            "seed",
            "signal",
            "filter",
            "reconstruction",
            "colour range",
            "scale"
        ]
    );
    let get = |k: &str| text.iter().find(|(key, _)| key == k).unwrap().1.clone();
    assert_eq!(get("figure"), "spectrum");
    assert_eq!(get("pattern"), "jitter");
    assert_eq!(get("N"), "256");
    // No Debug-printed parameters (the bare PNG once said `method=Nufft { tolerance: … }`).
    for (k, v) in &text {
        assert!(!v.contains("Nufft") && !v.contains("{ "), "{k}: {v}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
