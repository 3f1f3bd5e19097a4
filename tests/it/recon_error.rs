//! RMSE and PSNR against closed forms; the error report counts zero-weight pixels.

use crate::recon_kernels::BoxKernel;
use glam::DVec2;
use samplescope::core::cancel::Cancel;
use samplescope::core::recon::{error_report, psnr, reconstruct_scattered, rmse, ReconError};
use samplescope::model::FigureKind;

#[test]
fn rmse_and_psnr_closed_forms() {
    let n = 100;
    let zeros = vec![0.0; n];
    let ones = vec![1.0; n];
    // Opposite extremes: rmse 1, psnr 0 dB.
    assert_eq!(rmse(&zeros, &ones).unwrap(), 1.0);
    assert_eq!(psnr(1.0), 0.0);
    // A constant offset 0.1: rmse 0.1, psnr 20 dB.
    let a: Vec<f64> = (0..n).map(|k| k as f64 / n as f64 * 0.5).collect();
    let b: Vec<f64> = a.iter().map(|x| x + 0.1).collect();
    assert!((rmse(&a, &b).unwrap() - 0.1).abs() < 1e-15);
    assert!((psnr(0.1) - 20.0).abs() < 1e-12);
    // Alternating ±0.25: rmse 0.25, psnr 20·log10(4) = 12.0412 dB.
    let c: Vec<f64> = (0..n)
        .map(|k| 0.5 + if k % 2 == 0 { 0.25 } else { -0.25 })
        .collect();
    let half = vec![0.5; n];
    assert_eq!(rmse(&c, &half).unwrap(), 0.25);
    assert!((psnr(0.25) - 12.041_199_826_559_248).abs() < 1e-12);
    // One pixel off by 1 among 100: rmse 0.1.
    let mut d = zeros.clone();
    d[17] = 1.0;
    assert!((rmse(&d, &zeros).unwrap() - 0.1).abs() < 1e-15);
    // Identical: 0 and +∞ dB (never NaN).
    assert_eq!(rmse(&a, &a).unwrap(), 0.0);
    assert_eq!(psnr(0.0), f64::INFINITY);
}

#[test]
fn rmse_rejects_mismatched_or_empty_images() {
    assert!(matches!(
        rmse(&[0.0; 4], &[0.0; 5]),
        Err(ReconError::LengthMismatch {
            got: 5,
            expected: 4,
            ..
        })
    ));
    assert!(rmse(&[], &[]).is_err());
}

#[test]
fn error_report_counts_zero_weight_pixels_with_their_fill() {
    // One sample at the centre, a small box: only the 2×2 middle pixels of a 4×4 image are
    // reached; the other 12 hold the fill ½.
    let r = reconstruct_scattered(
        &[DVec2::splat(0.5)],
        &[1.0],
        4,
        &BoxKernel { radius: 0.3 },
        &Cancel::never(),
    )
    .unwrap();
    assert_eq!(r.zero_weight, 12);
    let reference = vec![1.0; 16];
    let e = error_report(&r, &reference).unwrap();
    // 12 pixels off by ½: mse = 12·¼/16 = 3/16.
    assert!((e.rmse - (3.0f64 / 16.0).sqrt()).abs() < 1e-15);
    assert_eq!(e.max_abs, 0.5);
    assert_eq!(e.zero_weight, 12);
    assert!((e.psnr - 10.0 * (16.0f64 / 3.0).log10()).abs() < 1e-12);
    let mut bad = reference.clone();
    bad[3] = f64::NAN;
    assert!(error_report(&r, &bad)
        .unwrap_err()
        .to_string()
        .starts_with("reference[3] = NaN"));
    assert!(error_report(&r, &reference[..15]).is_err());
}

/// The RMSE and PSNR of the engine's error node for a one-column scene of `signal` sampled
/// by `pattern` (seed 3, N = 1024) in `mode`, reconstructed with the default Gaussian onto
/// 96², the reference computed or (with `disk`) taken from the disk cache.
fn engine_error(
    signal: &str,
    pattern: &str,
    mode: samplescope::scene::ReconMode,
    disk: Option<&std::path::Path>,
) -> (f64, f64) {
    use samplescope::core::filter::{Filter, Filter2D, Mode2D};
    use samplescope::core::pattern::Pattern;
    use samplescope::core::signal::Signal;
    use samplescope::engine::disk_cache::DiskCache;
    use samplescope::engine::Evaluator;
    use samplescope::scene::graph::{NodeKind, NodeValue};
    use samplescope::scene::{Column, Scene};
    let mut scene = Scene {
        columns: vec![Column {
            pattern: Pattern::from_name(pattern).unwrap(),
            seed: 3,
            ..Default::default()
        }],
        n: 1024,
        signal: Signal::all()
            .into_iter()
            .find(|s| s.name() == signal)
            .unwrap(),
        filter: Filter2D::new(Filter::from_name("gaussian").unwrap(), Mode2D::Separable).unwrap(),
        ..Default::default()
    };
    scene.recon.mode = mode;
    scene.recon.size = 96;
    scene.panels.pattern = false;
    scene.panels.spectrum = false;
    scene.panels.filter = false;
    let disk = disk.map(|d| DiskCache::open(d.to_path_buf(), 1 << 30).unwrap());
    let eval = Evaluator::new(1 << 30, disk);
    let mut out = None;
    eval.evaluate(&scene, &Cancel::never(), &mut |_, kind, r| {
        if kind == NodeKind::Error {
            match &r.value {
                Ok(NodeValue::Error(e)) => out = Some((e.rmse, e.psnr)),
                other => panic!("error node: {other:?}"),
            }
        }
    });
    out.expect("the scene shows the error")
}

/// (rmse, psnr) as `samplescope recon --json` prints them for the same settings.
fn recon_cli_error(signal: &str, pattern: &str, samples: &[&str]) -> (f64, f64) {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_samplescope"))
        .args(["recon", "--json", "--signal", signal, "--pattern", pattern])
        .args(["--seed", "3", "--filter", "gaussian", "--mode", "separable"])
        .args(["--size", "96"])
        .args(samples)
        .output()
        .expect("run samplescope");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // Read the numbers with Rust's correctly rounded parser: the JSON text is the shortest
    // round-trip form, so this gives back the printed f64 exactly.
    let text = String::from_utf8(out.stdout).expect("UTF-8");
    let number = |key: &str| -> f64 {
        let at = text.find(&format!("\"{key}\":")).expect(key) + key.len() + 3;
        let end = text[at..].find([',', '}']).expect("a number") + at;
        text[at..end].trim().parse().expect("a finite number")
    };
    (number("rmse"), number("psnr"))
}

#[test]
fn engine_error_node_and_recon_cli_report_the_same_rmse_bit_for_bit() {
    use samplescope::scene::ReconMode;
    // Both are core's error report over the f64 pixels: the same bits, whether the engine
    // computed the reference or read it back from the disk cache.
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("recon_error-disk-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    for (signal, pattern, mode, samples) in [
        ("zone-plate", "jitter", ReconMode::Scattered, ["-n", "1024"]),
        (
            "checkerboard",
            "random",
            ReconMode::Supersample { spp: 4 },
            ["--spp", "4"],
        ),
    ] {
        let cli = recon_cli_error(signal, pattern, &samples);
        let computed = engine_error(signal, pattern, mode, Some(&dir));
        let from_disk = engine_error(signal, pattern, mode, Some(&dir));
        let in_memory = engine_error(signal, pattern, mode, None);
        for (what, e) in [
            ("computed", computed),
            ("from disk", from_disk),
            ("in memory", in_memory),
        ] {
            assert_eq!(
                e.0.to_bits(),
                cli.0.to_bits(),
                "{signal} {what}: RMSE {e:?} vs {cli:?}"
            );
            assert_eq!(
                e.1.to_bits(),
                cli.1.to_bits(),
                "{signal} {what}: PSNR {e:?} vs {cli:?}"
            );
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// `recon --out` publishes the scene's reconstruction figure through the one publishing path:
/// the figure's base size and metadata (no debug-printed parameters).
#[test]
fn recon_out_is_the_scenes_reconstruction_figure() {
    let dir = std::env::temp_dir().join(format!("recon-out-{}", std::process::id()));
    let _ = std::fs::create_dir_all(&dir);
    let out = dir.join("zp.png");
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_samplescope"))
        .args(["recon", "--pattern", "jitter", "-n", "1024", "--size", "48"])
        .args(["--seed", "3", "--out", out.to_str().expect("utf-8")])
        .output()
        .expect("run samplescope");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let bytes = std::fs::read(&out).expect("the PNG");
    let reader = png::Decoder::new(std::io::Cursor::new(&bytes))
        .read_info()
        .expect("a PNG");
    let info = reader.info();
    let size = samplescope::export::figure::base_size(FigureKind::Reconstruction);
    assert_eq!((info.width, info.height), size);
    let text = crate::png_text(info);
    assert!(
        text.iter()
            .any(|(k, v)| k == "figure" && v == "reconstruction"),
        "{text:?}"
    );
    assert!(!text.iter().any(|(k, _)| k == "Parameters"), "{text:?}");
    let _ = std::fs::remove_dir_all(&dir);
}
