//! RMSE and PSNR against closed forms; the error report counts zero-weight pixels.

use glam::DVec2;
use samplescope::core::cancel::Cancel;
use samplescope::core::recon::kernels::BoxKernel;
use samplescope::core::recon::{error_report, psnr, reconstruct_scattered, rmse, ReconError};

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
