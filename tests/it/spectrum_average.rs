//! Averages over realizations, the request API and its report.

use glam::DVec2;
use samplescope::core::cancel::Cancel;
use samplescope::core::rng::{derive_seed, Rng};
use samplescope::core::spectrum::*;
use std::convert::Infallible;

fn uniform(n: usize, seed: u64) -> Vec<DVec2> {
    let mut r = Rng::new(seed);
    (0..n)
        .map(|_| DVec2::new(r.next_f64(), r.next_f64()))
        .collect()
}

fn request(m: usize, method: Method, k: usize) -> SpectrumRequest {
    SpectrumRequest {
        size: m,
        method,
        realizations: k,
        dc: DcMode::Show,
        error_check_budget: DEFAULT_ERROR_CHECK_BUDGET,
    }
}

#[test]
fn average_is_the_mean_of_the_realizations_in_order() {
    // Reference: P̄ = (Σ_r P_r) · (1/K), summed in realization order, realization r generated
    // from derive_seed(seed, r): identical bits.
    let c = Cancel::never();
    let (m, k, seed) = (32usize, 5usize, 42u64);
    let req = request(m, Method::Nufft { tolerance: 1e-6 }, k);
    let gen = |s: u64| Ok::<_, Infallible>(uniform(100, s));
    let (avg, report) = average_periodogram(&req, seed, gen, &c).unwrap();
    let plan = NufftPlan::new(m, 1e-6).unwrap();
    let mut acc = vec![0.0; m * m];
    for r in 0..k {
        let p = plan
            .periodogram(&uniform(100, derive_seed(seed, r as u64)), &c)
            .unwrap();
        acc.iter_mut().zip(&p.power).for_each(|(a, v)| *a += v);
    }
    acc.iter_mut().for_each(|a| *a *= 1.0 / k as f64);
    assert!(avg
        .power
        .iter()
        .zip(&acc)
        .all(|(a, b)| a.to_bits() == b.to_bits()));
    assert_eq!((avg.m, avg.n_points, avg.realizations), (m, 100, k));
    assert_eq!(report.realizations, k);
    assert_eq!(report.n_points_range, (100, 100));
}

#[test]
fn exact_and_nufft_averages_agree_within_tolerance() {
    let c = Cancel::never();
    let gen = |s: u64| Ok::<_, Infallible>(uniform(300, s));
    let (exact, rep_exact) =
        average_periodogram(&request(40, Method::Exact, 3), 9, gen, &c).unwrap();
    let (nufft, rep_nufft) = average_periodogram(
        &request(40, Method::Nufft { tolerance: 1e-9 }, 3),
        9,
        gen,
        &c,
    )
    .unwrap();
    assert!(relative_l2_error(&nufft, &exact, true) <= 1e-9);
    assert_eq!(rep_exact.tolerance, None);
    assert!(rep_exact.error.is_none() && rep_exact.kernel.is_none());
    assert_eq!(rep_nufft.tolerance, Some(1e-9));
    let names: Vec<&str> = rep_exact.stages.iter().map(|s| s.0).collect();
    assert_eq!(names, ["generate", "exact", "average"]);
    let names: Vec<&str> = rep_nufft.stages.iter().map(|s| s.0).collect();
    assert_eq!(
        names,
        [
            "generate",
            "spread",
            "fft",
            "deconvolve",
            "error-check",
            "average"
        ]
    );
}

#[test]
fn same_bits_on_one_and_two_threads() {
    let c = Cancel::never();
    let req = request(48, Method::Nufft { tolerance: 1e-3 }, 7);
    let gen = |s: u64| Ok::<_, Infallible>(uniform(500, s));
    let one = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap();
    let two = rayon::ThreadPoolBuilder::new()
        .num_threads(2)
        .build()
        .unwrap();
    let a = one.install(|| average_periodogram(&req, 3, gen, &c).unwrap().0);
    let b = two.install(|| average_periodogram(&req, 3, gen, &c).unwrap().0);
    assert!(a
        .power
        .iter()
        .zip(&b.power)
        .all(|(x, y)| x.to_bits() == y.to_bits()));
}

#[test]
fn white_noise_average_has_unit_mean() {
    // E[P(k)] = 1 for k ≠ 0; mean over K = 32 realizations and 32² − 1 frequencies
    // (≈ 16 000 independent values, Var ≈ 1): σ ≈ 0.008, allow 5σ.
    let c = Cancel::never();
    let req = request(32, Method::Nufft { tolerance: 1e-3 }, 32);
    let (s, _) =
        average_periodogram(&req, 5, |seed| Ok::<_, Infallible>(uniform(256, seed)), &c).unwrap();
    let dc = s.dc_index();
    let mean = s
        .power
        .iter()
        .enumerate()
        .filter(|(i, _)| *i != dc)
        .map(|(_, p)| p)
        .sum::<f64>()
        / (s.power.len() - 1) as f64;
    assert!((mean - 1.0).abs() < 0.04, "mean {mean}");
    assert!((s.power[dc] - 256.0).abs() < 256.0 * 1e-3);
}

#[test]
fn error_check_is_full_when_cheap_by_rows_when_not_and_absent_without_budget() {
    let c = Cancel::never();
    let gen = |s: u64| Ok::<_, Infallible>(uniform(200, s));
    // 200 · 17 · 33 = 112 200 multiply-adds ≤ default budget: the whole grid.
    let (_, rep) = average_periodogram(
        &request(32, Method::Nufft { tolerance: 1e-6 }, 2),
        1,
        gen,
        &c,
    )
    .unwrap();
    let check = rep.error.unwrap();
    assert!(check.full && check.frequencies == 32 * 32);
    assert!(check.relative_l2 <= 1e-6 && check.relative_l2 > 0.0);
    // The reported error is exactly the error of realization 0 against periodogram_exact.
    let pts = uniform(200, derive_seed(1, 0));
    let exact = periodogram_exact(&pts, 32, &c).unwrap();
    let approx = NufftPlan::new(32, 1e-6)
        .unwrap()
        .periodogram(&pts, &c)
        .unwrap();
    assert_eq!(check.relative_l2, relative_l2_error(&approx, &exact, true));
    // Budget for 3 rows of 128: 200 · 128 · 3.
    let mut req = request(128, Method::Nufft { tolerance: 1e-3 }, 1);
    req.error_check_budget = 200 * 128 * 3;
    let check = average_periodogram(&req, 1, gen, &c)
        .unwrap()
        .1
        .error
        .unwrap();
    assert!(!check.full && check.frequencies == 3 * 128);
    assert!(check.relative_l2 <= 1e-3 && check.relative_l2 > 0.0);
    // Too small for one row, or disabled.
    req.error_check_budget = 200 * 128 - 1;
    assert!(average_periodogram(&req, 1, gen, &c)
        .unwrap()
        .1
        .error
        .is_none());
    req.error_check_budget = 0;
    let rep = average_periodogram(&req, 1, gen, &c).unwrap().1;
    assert!(rep.error.is_none());
    assert!(rep.stages.iter().all(|s| s.0 != "error-check"));
}

#[test]
fn report_carries_kernel_and_point_count_range() {
    let c = Cancel::never();
    // Realization r has 10 + (seed % 7) points: the range is reported, n_points is the minimum.
    let gen = |s: u64| Ok::<_, Infallible>(uniform(10 + (s % 7) as usize, s));
    let (s, rep) = average_periodogram(
        &request(16, Method::Nufft { tolerance: 1e-6 }, 12),
        2,
        gen,
        &c,
    )
    .unwrap();
    let counts: Vec<usize> = (0..12)
        .map(|r| 10 + (derive_seed(2, r) % 7) as usize)
        .collect();
    let (lo, hi) = (*counts.iter().min().unwrap(), *counts.iter().max().unwrap());
    assert_eq!(rep.n_points_range, (lo, hi));
    assert_eq!(s.n_points, lo);
    let (kernel, n) = rep.kernel.unwrap();
    assert_eq!((kernel.width, n), (9, 32));
    assert!(rep.wall > std::time::Duration::ZERO);
}

#[derive(Debug)]
struct Boom(u64);
impl std::fmt::Display for Boom {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "boom at seed {}", self.0)
    }
}
impl std::error::Error for Boom {}

#[test]
fn generator_failure_names_the_lowest_failing_realization() {
    let c = Cancel::never();
    let bad = [derive_seed(8, 3), derive_seed(8, 5)];
    let gen = |s: u64| {
        if bad.contains(&s) {
            Err(Boom(s))
        } else {
            Ok(uniform(20, s))
        }
    };
    let e = average_periodogram(&request(16, Method::Exact, 8), 8, gen, &c).unwrap_err();
    match &e {
        SpectrumError::Generator {
            realization,
            source,
        } => {
            assert_eq!(*realization, 3);
            assert!(source.to_string().contains("boom"));
        }
        other => panic!("unexpected {other}"),
    }
    assert!(e.to_string().contains("realization 3"));
    // Bad points from a generator are typed errors too.
    let e = average_periodogram(
        &request(16, Method::Exact, 1),
        8,
        |_| Ok::<_, Infallible>(vec![DVec2::new(2.0, 0.0)]),
        &c,
    )
    .unwrap_err();
    assert!(matches!(e, SpectrumError::InvalidPoint { index: 0, .. }));
}

#[test]
fn invalid_requests_are_typed_errors() {
    let c = Cancel::never();
    let gen = |s: u64| Ok::<_, Infallible>(uniform(20, s));
    for k in [0usize, 1025] {
        let e = average_periodogram(&request(16, Method::Exact, k), 1, gen, &c).unwrap_err();
        assert!(matches!(e, SpectrumError::InvalidRealizations { .. }));
        assert!(e.to_string().contains("realizations K") && e.to_string().contains("1..=1024"));
    }
    let e = average_periodogram(
        &request(
            16,
            Method::Nufft {
                tolerance: f64::NAN,
            },
            1,
        ),
        1,
        gen,
        &c,
    )
    .unwrap_err();
    assert!(matches!(e, SpectrumError::InvalidTolerance { .. }));
    let e = average_periodogram(&request(5000, Method::Exact, 1), 1, gen, &c).unwrap_err();
    assert!(matches!(e, SpectrumError::InvalidSize { m: 5000, .. }));
    assert!(request(16, Method::Exact, 1024).validate().is_ok());
    // analyze_points computes one periodogram of the given points.
    let pts = uniform(30, 1);
    let (s, _) = analyze_points(&request(16, Method::Exact, 1), &pts, &c).unwrap();
    assert_eq!(s, {
        let mut e = periodogram_exact(&pts, 16, &c).unwrap();
        e.realizations = 1;
        e
    });
    let e = analyze_points(&request(16, Method::Exact, 2), &pts, &c).unwrap_err();
    assert!(matches!(
        e,
        SpectrumError::InvalidRealizations { k: 2, max: 1 }
    ));
}

#[test]
fn cancelled_average_stops() {
    let c = Cancel::new();
    c.cancel();
    let gen = |s: u64| Ok::<_, Infallible>(uniform(20, s));
    let e = average_periodogram(
        &request(16, Method::Nufft { tolerance: 1e-3 }, 4),
        1,
        gen,
        &c,
    )
    .unwrap_err();
    assert!(matches!(e, SpectrumError::Cancelled));
}

#[test]
fn dc_mask_is_a_display_setting_only() {
    let c = Cancel::never();
    let pts = uniform(400, 4);
    let mut req = request(16, Method::Exact, 1);
    req.dc = DcMode::Mask;
    let (s, _) = analyze_points(&req, &pts, &c).unwrap();
    assert!((s.power[s.dc_index()] - 400.0).abs() < 1e-9);
    let shown = s.to_log_image(false);
    let masked = s.to_display_image();
    assert!((shown[s.dc_index()] - 400f32.log10()).abs() < 1e-5);
    assert!(
        masked[s.dc_index()] < 1.5,
        "DC painted with its neighbours: {}",
        masked[s.dc_index()]
    );
    let differs: Vec<usize> = (0..256).filter(|&i| shown[i] != masked[i]).collect();
    assert_eq!(differs, vec![s.dc_index()]);
    let rows = s.to_csv_rows();
    assert_eq!(rows[s.dc_index()], (0, 0, s.power[s.dc_index()]));
}

#[test]
fn request_serde_round_trip_and_default() {
    let d = SpectrumRequest::default();
    assert_eq!(d.size, 256);
    assert_eq!(d.method, Method::Nufft { tolerance: 1e-6 });
    assert!(d.validate().is_ok());
    let json = serde_json::to_string(&d).unwrap();
    assert_eq!(serde_json::from_str::<SpectrumRequest>(&json).unwrap(), d);
}

#[test]
fn progressive_average_reports_running_means_and_ends_bit_identical() {
    // Reference: the plain average (same request, seed and generator) and, for each partial,
    // the naive mean of the first d realizations in order.
    let c = Cancel::never();
    let (m, k, seed) = (16usize, 40usize, 7u64);
    let req = request(m, Method::Exact, k);
    let gen = |s: u64| Ok::<_, Infallible>(uniform(50, s));
    let (plain, _) = average_periodogram(&req, seed, gen, &c).unwrap();
    let mut partials: Vec<(usize, Vec<f64>)> = Vec::new();
    let mut final_bits = None;
    let (prog, _) =
        average_periodogram_progressive(&req, seed, gen, &c, std::time::Duration::ZERO, &mut |p| {
            assert_eq!(p.total, k);
            if let Some(s) = p.interim() {
                assert_eq!(s.realizations, p.done);
                partials.push((p.done, s.power.clone()));
            }
            if p.is_final() {
                final_bits = p
                    .so_far
                    .map(|s| s.power.iter().map(|v| v.to_bits()).collect());
            }
        })
        .unwrap();
    let want: Vec<u64> = plain.power.iter().map(|v| v.to_bits()).collect();
    assert_eq!(final_bits, Some(want), "the last report carries the result");
    assert!(prog
        .power
        .iter()
        .zip(&plain.power)
        .all(|(a, b)| a.to_bits() == b.to_bits()));
    assert!(
        !partials.is_empty(),
        "no partial result with a zero interval"
    );
    let mut last = 0;
    for (d, power) in &partials {
        assert!(*d > last && *d < k, "partials grow and stop before K: {d}");
        last = *d;
        let mut acc = vec![0.0; m * m];
        for r in 0..*d {
            let p = periodogram_exact(&uniform(50, derive_seed(seed, r as u64)), m, &c).unwrap();
            acc.iter_mut().zip(&p.power).for_each(|(a, v)| *a += v);
        }
        for (a, b) in acc.iter().zip(power) {
            let mean = a / *d as f64;
            assert!(
                (mean - b).abs() <= 1e-12 * mean.abs().max(1.0),
                "d = {d}: {mean} vs {b}"
            );
        }
    }
}
