//! Every iterative routine in `core` reports its progress by the rules of `core::progress`:
//! one table, one row per routine that reports, each run twice (reporting and silent).

use crate::recon_kernels::BoxKernel;
use glam::DVec2;
use samplescope::core::cancel::Cancel;
use samplescope::core::cube::CubePoints;
use samplescope::core::integration::{run_study, run_study_naive, Study, StudyRequest};
use samplescope::core::metrics::cube;
use samplescope::core::params::Params;
use samplescope::core::pattern::{optimize, Pattern};
use samplescope::core::progress::{no_progress, OnProgress};
use samplescope::core::recon::{
    convergence_curve_progressive, reference_image_progressive, ConvergencePoint, Jittered,
    ReferenceImage, ReferenceOptions,
};
use samplescope::core::rng::Rng;
use samplescope::core::signal::{Checkerboard, Polygon, Signal, ZonePlate};
use samplescope::core::spectrum::{
    average_periodogram_progressive, DcMode, Method, Spectrum, SpectrumRequest,
};
use std::convert::Infallible;
use std::time::Duration;

/// One run of a routine: its reports (done, total, whether a partial result came), the bits
/// of the partial result of the last report (when it had one), of the result, and of the
/// result of the same call with [`no_progress`].
struct Run {
    reports: Vec<(usize, usize, bool)>,
    last_so_far: Option<Vec<u64>>,
    result: Vec<u64>,
    silent: Vec<u64>,
}

fn run<T: ?Sized, R>(
    go: impl Fn(&mut OnProgress<'_, T>) -> R,
    bits_of_result: impl Fn(&R) -> Vec<u64>,
    bits_of_so_far: impl Fn(&T) -> Vec<u64>,
) -> Run {
    let mut reports = Vec::new();
    let mut last_so_far = None;
    let result = go(&mut |p| {
        reports.push((p.done, p.total, p.so_far.is_some()));
        last_so_far = p.so_far.map(&bits_of_so_far);
    });
    let silent = go(&mut no_progress);
    Run {
        reports,
        last_so_far,
        result: bits_of_result(&result),
        silent: bits_of_result(&silent),
    }
}

fn point_bits(points: &[DVec2]) -> Vec<u64> {
    points
        .iter()
        .flat_map(|p| [p.x.to_bits(), p.y.to_bits()])
        .collect()
}

fn study_bits(s: &Study) -> Vec<u64> {
    let mut bits = vec![s.realizations as u64, s.reference.to_bits()];
    bits.extend(s.rows.iter().map(|r| r.mse.to_bits()));
    bits
}

fn curve_bits(points: &[ConvergencePoint]) -> Vec<u64> {
    points
        .iter()
        .flat_map(|p| [p.spp as u64, p.rmse.to_bits()])
        .collect()
}

fn image_bits(r: &ReferenceImage) -> Vec<u64> {
    r.pixels.iter().map(|v| v.to_bits()).collect()
}

fn spectrum_bits(s: &Spectrum) -> Vec<u64> {
    s.power.iter().map(|v| v.to_bits()).collect()
}

fn pattern(name: &str, set: &[(&str, &str)]) -> Pattern {
    let mut p = Pattern::from_name(name).unwrap();
    for (k, v) in set {
        p.set(k, v).unwrap();
    }
    p
}

fn generate(p: Pattern, n: usize) -> Run {
    let never = Cancel::never();
    run(
        |progress: &mut OnProgress<'_, [DVec2]>| {
            p.generate_observed(n, 3, &never, progress).unwrap()
        },
        |g| point_bits(&g.points),
        point_bits,
    )
}

fn periodogram(interval: Duration) -> Run {
    let req = SpectrumRequest {
        size: 16,
        method: Method::Exact,
        realizations: 24,
        dc: DcMode::Show,
        error_check_budget: 0,
    };
    let uniform = |seed: u64| {
        let mut rng = Rng::new(seed);
        let points: Vec<DVec2> = (0..40)
            .map(|_| DVec2::new(rng.next_f64(), rng.next_f64()))
            .collect();
        Ok::<_, Infallible>(points)
    };
    let never = Cancel::never();
    run(
        |progress: &mut OnProgress<'_, Spectrum>| {
            average_periodogram_progressive(&req, 5, uniform, &never, interval, progress)
                .unwrap()
                .0
        },
        spectrum_bits,
        spectrum_bits,
    )
}

fn reference(signal: Signal) -> Run {
    let never = Cancel::never();
    run(
        |progress: &mut OnProgress<'_, ReferenceImage>| {
            let opts = ReferenceOptions { strata: 2, seed: 4 };
            reference_image_progressive(&signal, 8, &opts, &never, progress).unwrap()
        },
        image_bits,
        image_bits,
    )
}

/// A row: the routine, its run, and whether a report before the last carries a partial
/// result (`None`: it depends on the machine, e.g. on the number of threads).
type Row = (&'static str, Run, Option<bool>);

fn table() -> Vec<Row> {
    let never = Cancel::never();
    let study = StudyRequest {
        pattern: pattern("jitter", &[]),
        ns: vec![1024, 16384],
        realizations: 16,
        seed: 2,
        ..StudyRequest::default()
    };
    vec![
        (
            "lloyd",
            generate(pattern("lloyd", &[("iterations", "3")]), 64),
            Some(true),
        ),
        (
            "sot",
            generate(
                pattern("sot", &[("iterations", "4"), ("directions", "8")]),
                64,
            ),
            Some(true),
        ),
        (
            "gbn",
            generate(pattern("gbn", &[("iterations", "3")]), 64),
            Some(true),
        ),
        (
            "lloyd_naive",
            run(
                |p: &mut OnProgress<'_, [DVec2]>| {
                    optimize::lloyd_naive(16, 2, 1, &never, p).unwrap()
                },
                |r| point_bits(r),
                point_bits,
            ),
            Some(true),
        ),
        (
            "run_study",
            run(
                |p: &mut OnProgress<'_, Study>| run_study(&study, &never, p).unwrap(),
                study_bits,
                study_bits,
            ),
            None,
        ),
        (
            "run_study_naive",
            run(
                |p: &mut OnProgress<'_, Study>| run_study_naive(&study, &never, p).unwrap(),
                study_bits,
                study_bits,
            ),
            Some(false),
        ),
        (
            "convergence_curve",
            run(
                |p: &mut OnProgress<'_, [ConvergencePoint]>| {
                    let signal = Signal::Polygon(Polygon::default());
                    let kernel = BoxKernel { radius: 0.5 };
                    let provider = Jittered { seed: 1 };
                    convergence_curve_progressive(
                        &signal,
                        &provider,
                        &[1, 4, 16],
                        12,
                        &kernel,
                        &never,
                        p,
                    )
                    .unwrap()
                    .points
                },
                |points| curve_bits(points),
                curve_bits,
            ),
            Some(true),
        ),
        (
            "reference (supersampled)",
            reference(Signal::Checkerboard(Checkerboard::default())),
            Some(true),
        ),
        (
            "reference (quadrature)",
            reference(Signal::ZonePlate(ZonePlate::default())),
            Some(false),
        ),
        (
            "average_periodogram (every group)",
            periodogram(Duration::ZERO),
            Some(true),
        ),
        (
            "average_periodogram (no partial means)",
            periodogram(Duration::MAX),
            Some(false),
        ),
        (
            "cube discrepancy (centred)",
            run(
                |p: &mut OnProgress<'_, ()>| {
                    cube::discrepancy(&cube_points(), cube::Discrepancy::Centered, &never, p)
                        .unwrap()
                },
                |v| vec![v.to_bits()],
                |_| Vec::new(),
            ),
            Some(false),
        ),
        (
            "cube discrepancies",
            run(
                |p: &mut OnProgress<'_, ()>| {
                    let d = cube::discrepancies(&cube_points(), &never, p).unwrap();
                    cube::Discrepancy::ALL.map(|w| d.get(w).to_bits()).to_vec()
                },
                |v| v.clone(),
                |_| Vec::new(),
            ),
            Some(false),
        ),
        (
            "cube min distance",
            run(
                |p: &mut OnProgress<'_, ()>| {
                    cube::min_distance_cube(&cube_points(), &never, p).unwrap()
                },
                |m| vec![m.min_distance.to_bits(), m.pair.0 as u64, m.pair.1 as u64],
                |_| Vec::new(),
            ),
            Some(false),
        ),
        (
            "cube projection table",
            run(
                |p: &mut OnProgress<'_, ()>| {
                    cube::projection_table(&cube_points(), &never, p).unwrap()
                },
                |rows| {
                    rows.iter()
                        .flat_map(|r| {
                            [
                                r.dims[0] as u64,
                                r.dims[1] as u64,
                                r.l2_star_discrepancy.to_bits(),
                            ]
                        })
                        .collect()
                },
                |_| Vec::new(),
            ),
            Some(false),
        ),
    ]
}

/// 300 random points in 7 dimensions (the d-dimensional measures' rows).
fn cube_points() -> CubePoints {
    let mut r = Rng::new(77);
    CubePoints::new(7, (0..300 * 7).map(|_| r.next_f64()).collect()).unwrap()
}

#[test]
fn every_iterative_routine_reports_monotone_progress_ending_at_its_total() {
    for (name, r, interim) in table() {
        let reports = &r.reports;
        assert!(!reports.is_empty(), "{name}: no report");
        let total = reports[0].1;
        assert!(total > 0, "{name}: no steps");
        for w in reports.windows(2) {
            assert!(w[0].0 <= w[1].0, "{name}: done went back: {reports:?}");
        }
        for &(done, t, _) in reports {
            assert_eq!(t, total, "{name}: the total changed: {reports:?}");
            assert!(done <= total, "{name}: done past the total: {reports:?}");
        }
        let finals = reports.iter().filter(|r| r.0 == total).count();
        assert_eq!(finals, 1, "{name}: one last report: {reports:?}");
        assert_eq!(reports.last().unwrap().0, total, "{name}: {reports:?}");
        if let Some(bits) = &r.last_so_far {
            assert_eq!(bits, &r.result, "{name}: the last report's result");
        }
        assert_eq!(
            r.result, r.silent,
            "{name}: the result depends on the callback"
        );
        if let Some(want) = interim {
            let got = reports[..reports.len() - 1].iter().any(|r| r.2);
            assert_eq!(
                got, want,
                "{name}: partial results before the end: {reports:?}"
            );
        }
    }
}
