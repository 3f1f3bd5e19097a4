//! What each node computes, as plain data for the panels.

use super::node::{Deps, JobCtx, NodeError, NodeKind, NodeValue, Output, Partial};
use super::ReconMode;
use crate::core::progress::{Progress, Steps, Throttle};
use crate::core::recon::image_plane::{ImagePlaneProvider, ZSobolProvider};
use crate::core::recon::supersample::SampleProvider;
use crate::model::Accuracy;
use crate::scene::PixelSampling;
use std::sync::Arc;
use std::time::Duration;

use crate::model::{
    next_version, ConvergencePoint, ErrorData, ImageData, IntegrationData, PointsData, PsaData,
    ReconData, ReferenceData, ResponseData, ResponseMetrics, SpectrumData, StatsData,
};

impl JobCtx<'_> {
    fn col(&self) -> &super::Column {
        &self.scene.columns[self.column]
    }

    /// Publishes a coarse value while the node refines, `progress` of the way (never the
    /// last step: the job returns that).
    fn publish(&self, value: NodeValue, accuracy: Option<Accuracy>, progress: Steps) {
        (self.progress)(Partial {
            value,
            accuracy,
            progress,
        })
    }
}

pub(super) fn theorem(ctx: &JobCtx) -> Output {
    ctx.cancel.check()?;
    let v = crate::core::signal::theorem::compute_view(&ctx.scene.theorem)?;
    let e = &v.errors;
    let accuracy = Some(Accuracy::TheoremBand {
        band: e.band,
        tail: e.tail_bound,
    });
    Ok((NodeValue::Theorem(Arc::new(v)), accuracy))
}

fn dep(done: &Deps, kind: NodeKind) -> Result<&NodeValue, NodeError> {
    match done.get(&kind).map(|r| &r.value) {
        Some(Ok(v)) => Ok(v),
        Some(Err(e)) => Err(NodeError::Input {
            input: kind,
            cause: Arc::new(e.clone()),
        }),
        None => Err(NodeError::Internal(format!(
            "the {} input is missing",
            kind.name()
        ))),
    }
}

fn points_of(done: &Deps) -> Result<Arc<PointsData>, NodeError> {
    match dep(done, NodeKind::Points)? {
        NodeValue::Points(p) => Ok(p.clone()),
        _ => Err(NodeError::Internal(
            "the points input has another kind".into(),
        )),
    }
}

fn ms(d: Duration) -> f64 {
    d.as_secs_f64() * 1e3
}

pub(super) fn points(ctx: &JobCtx) -> Output {
    let (scene, col, cancel) = (ctx.scene, ctx.col(), ctx.cancel);
    if let Some(imp) = &col.points {
        let points = imp.to_dvec();
        let gpu = points.iter().map(|p| [p.x as f32, p.y as f32]).collect();
        return Ok((
            NodeValue::Points(Arc::new(PointsData {
                points,
                gpu: Arc::new(gpu),
                version: next_version(),
                note: None,
            })),
            Some(Accuracy::Imported {
                source: imp.label(),
            }),
        ));
    }
    // An optimiser (Lloyd, SOT, GBN) shows the points it has reached, at most every
    // POINTS_PARTIAL_INTERVAL, so the pattern panel relaxes live; the final points do not
    // depend on what was shown.
    let mut throttle = Throttle::new(POINTS_PARTIAL_INTERVAL);
    let g = col
        .pattern
        .generate_observed(scene.n, col.seed, cancel, &mut |p| {
            if let Some(points) = p.interim().filter(|_| throttle.due()) {
                let accuracy = Accuracy::Iterations {
                    done: p.done,
                    of: p.total,
                };
                ctx.publish(
                    points_value(points.to_vec(), None),
                    Some(accuracy),
                    p.steps(),
                );
                throttle.restart();
            }
        })?;
    // A column never shows fewer points than the scene asks for: a pattern that stops short
    // (dart throwing's max_misses, Bridson's radius) fails the column with the one line that
    // names the parameter.
    let points = g.require_all(col.pattern.name())?;
    Ok((points_value(points, None), None))
}

/// How often an iterative pattern's points node publishes the points reached so far.
pub(crate) const POINTS_PARTIAL_INTERVAL: Duration = Duration::from_millis(100);

fn points_value(points: Vec<glam::DVec2>, note: Option<String>) -> NodeValue {
    let gpu = points.iter().map(|p| [p.x as f32, p.y as f32]).collect();
    NodeValue::Points(Arc::new(PointsData {
        points,
        gpu: Arc::new(gpu),
        version: next_version(),
        note,
    }))
}

pub(super) fn statistics(ctx: &JobCtx) -> Output {
    let (done, cancel) = (ctx.deps, ctx.cancel);
    let p = points_of(done)?;
    let s = crate::core::metrics::statistics(&p.points, cancel)?;
    // PSA's statistics when the plan made them an input (N ≤ STATS_PSA_MAX_N).
    let psa = match done.get(&NodeKind::Psa) {
        Some(_) => match dep(done, NodeKind::Psa)? {
            NodeValue::Psa(d) => d.statistics,
            _ => return Err(NodeError::Internal("the PSA input has another kind".into())),
        },
        None => None,
    };
    let md = s.min_distance.as_ref();
    Ok((
        NodeValue::Statistics(Arc::new(StatsData {
            min_distance: md.map(|m| m.min_distance).unwrap_or(f64::NAN),
            normalized_min_distance: md.map(|m| m.normalized_min_distance).unwrap_or(f64::NAN),
            mean_nn: md.map(|m| m.mean_nn_distance).unwrap_or(f64::NAN),
            star: s.star.as_ref().map(|st| (st.value, st.worst_box)),
            l2_star: s.l2_star,
            t_value: s.t_value.as_ref().map(|t| t.t),
            psa,
            full: s,
        })),
        None,
    ))
}

pub(super) fn psa(ctx: &JobCtx) -> Output {
    use crate::core::metrics::{psa_statistics, PSA_MAX_N, PSA_MIN_N};
    let p = points_of(ctx.deps)?;
    let n = p.points.len();
    let data = if (PSA_MIN_N..=PSA_MAX_N).contains(&n) {
        PsaData {
            statistics: Some(psa_statistics(&p.points, ctx.cancel)?),
            skipped: None,
        }
    } else {
        PsaData {
            statistics: None,
            skipped: Some(format!(
                "PSA statistics need {PSA_MIN_N} ≤ n ≤ {PSA_MAX_N} points (the RDF costs O(N²)), got n = {n}"
            )),
        }
    };
    Ok((NodeValue::Psa(Arc::new(data)), None))
}

pub(super) fn rdf(ctx: &JobCtx) -> Output {
    let p = points_of(ctx.deps)?;
    // PSA's bins: N/8 of them up to 8 hexagonal spacings.
    let (bins, r_max) = crate::core::metrics::psa::psa_rdf_range(p.points.len());
    let g = crate::core::metrics::rdf(&p.points, bins, r_max, ctx.cancel)?;
    Ok((NodeValue::Rdf(Arc::new(g)), None))
}

pub(super) fn net_prefixes(ctx: &JobCtx) -> Output {
    let p = points_of(ctx.deps)?;
    let v = crate::core::metrics::net_prefixes(&p.points, ctx.cancel)?;
    Ok((NodeValue::NetPrefixes(Arc::new(v)), None))
}

pub(super) fn samples(ctx: &JobCtx) -> Output {
    let p = points_of(ctx.deps)?;
    let v = crate::core::recon::sample_signal(&ctx.scene.signal, &p.points, ctx.cancel)?;
    Ok((NodeValue::Samples(Arc::new(v)), None))
}

pub(super) fn reconstruction(ctx: &JobCtx) -> Output {
    let (scene, c, done, cancel) = (ctx.scene, ctx.column, ctx.deps, ctx.cancel);
    let w = scene.recon.size;
    if let Some(why) = scene.filter.reconstruction_refusal() {
        return Err(NodeError::CannotReconstruct(why));
    }
    let r = match scene.recon.mode {
        ReconMode::Scattered => {
            let p = points_of(done)?;
            let values = match dep(done, NodeKind::Samples)? {
                NodeValue::Samples(v) => v.clone(),
                _ => {
                    return Err(NodeError::Internal(
                        "the samples input has another kind".into(),
                    ))
                }
            };
            crate::core::recon::reconstruct_scattered(&p.points, &values, w, &scene.filter, cancel)?
        }
        ReconMode::Resample { grid } => {
            crate::core::recon::resample_grid(&scene.signal, grid, w, &scene.filter, cancel)?
        }
        ReconMode::Supersample { spp } => {
            let col = &scene.columns[c];
            if col.points.is_some() {
                return Err(NodeError::ImportedNeedsPattern {
                    column: c,
                    what: "supersampling",
                });
            }
            let provider = |spp: usize| -> Result<Box<dyn SampleProvider>, NodeError> {
                Ok(match col.pixels {
                    PixelSampling::PerPixel => Box::new(crate::core::recon::PatternProvider {
                        pattern: col.pattern,
                        seed: col.seed,
                    }),
                    PixelSampling::ImagePlane { tile } => Box::new(ImagePlaneProvider::new(
                        &col.pattern,
                        w,
                        spp,
                        col.seed,
                        tile,
                        cancel,
                    )?),
                    PixelSampling::ZSobol => Box::new(ZSobolProvider { seed: col.seed, w }),
                })
            };
            // A heavy supersampling (over PREVIEW_SAMPLES samples) shows a preview at 1/16
            // of the samples per pixel first (6 % extra work), then the full image.
            let preview_spp = spp / PREVIEW_DIVISOR;
            if preview_spp >= 1 && w * w * spp > PREVIEW_SAMPLES {
                let p = crate::core::recon::supersample(
                    &scene.signal,
                    w,
                    preview_spp,
                    provider(preview_spp)?.as_ref(),
                    &scene.filter,
                    cancel,
                )?;
                ctx.publish(
                    NodeValue::Reconstruction(Arc::new(ReconData::new(p))),
                    Some(Accuracy::Preview {
                        spp: preview_spp,
                        of: spp,
                        noise: (PREVIEW_DIVISOR as f64).sqrt(),
                    }),
                    Steps::at(1, 2),
                );
            }
            crate::core::recon::supersample(
                &scene.signal,
                w,
                spp,
                provider(spp)?.as_ref(),
                &scene.filter,
                cancel,
            )?
        }
    };
    let accuracy = (r.zero_weight > 0).then_some(Accuracy::ZeroWeightPixels {
        pixels: r.zero_weight,
    });
    Ok((
        NodeValue::Reconstruction(Arc::new(ReconData::new(r))),
        accuracy,
    ))
}

/// Supersampled reconstructions of more samples than this show a preview first.
pub(crate) const PREVIEW_SAMPLES: usize = 2 << 20;
/// The preview's samples per pixel are the full spp over this.
pub(crate) const PREVIEW_DIVISOR: usize = 16;

pub(super) fn reference(ctx: &JobCtx) -> Output {
    let (scene, cancel) = (ctx.scene, ctx.cancel);
    let w = scene.recon.size;
    let data = |r: &crate::core::recon::ReferenceImage| {
        let accuracy = Accuracy::reference(r.method, r.error_estimate);
        let value = NodeValue::Reference(Arc::new(ReferenceData::new(
            w,
            r.pixels.clone(),
            r.error_estimate,
            r.method,
        )));
        (value, accuracy)
    };
    // A supersampled reference shows its s×s pass first, then the 2s×2s one.
    let r = crate::core::recon::reference_image_progressive(
        &scene.signal,
        w,
        &crate::core::recon::ReferenceOptions::default(),
        cancel,
        &mut |p| {
            if let Some(img) = p.interim() {
                let (value, accuracy) = data(img);
                ctx.publish(value, accuracy, p.steps());
            }
        },
    )?;
    Ok(data(&r))
}

pub(super) fn error(ctx: &JobCtx) -> Output {
    let done = ctx.deps;
    let (recon, reference) = match (
        dep(done, NodeKind::Reconstruction)?,
        dep(done, NodeKind::Reference)?,
    ) {
        (NodeValue::Reconstruction(a), NodeValue::Reference(b)) => (a.clone(), b.clone()),
        _ => {
            return Err(NodeError::Internal(
                "the error node's inputs have other kinds".into(),
            ))
        }
    };
    let a = &recon.image;
    let b = &reference.image;
    if a.values.len() != b.values.len() {
        return Err(NodeError::Internal(
            "reconstruction and reference sizes differ".into(),
        ));
    }
    // RMSE and PSNR over the f64 pixels, as `samplescope recon` reports them; the image
    // shown is the difference of the two display images.
    let report = crate::core::recon::error_report(&recon.exact, &reference.pixels)?;
    let (rmse, psnr, max_abs) = (report.rmse, report.psnr, report.max_abs);
    // Blue-noise error (image-plane samplers) keeps its energy away from low frequencies.
    let w = a.width;
    let signed: Vec<f64> = recon
        .exact
        .pixels
        .iter()
        .zip(reference.pixels.iter())
        .map(|(x, y)| x - y)
        .collect();
    let periodogram = (w == a.height && w <= crate::core::recon::image_plane::MAX_SPECTRUM_W)
        .then(|| crate::core::recon::image_plane::error_periodogram(&signed, w).ok())
        .flatten();
    let low_frequency = periodogram
        .as_ref()
        .map(|p| {
            crate::core::recon::image_plane::periodogram_low_frequency_share(p, w, w as f64 / 8.0)
        })
        .filter(|v| v.is_finite() && *v > 0.0);
    let spectrum = periodogram.map(|p| {
        let floor = 1e-12;
        let logs: Vec<f32> = p.iter().map(|v| (v.max(floor)).log10() as f32).collect();
        let hi = logs.iter().copied().fold(f32::MIN, f32::max);
        let lo = (hi - 6.0).max(floor.log10() as f32);
        (ImageData::new(w, w, logs), lo, hi)
    });
    let mut max = 0.0f32;
    let diff: Vec<f32> = a
        .values
        .iter()
        .zip(b.values.iter())
        .map(|(x, y)| {
            let d = (x - y).abs();
            max = max.max(d);
            d
        })
        .collect();
    Ok((
        NodeValue::Error(Arc::new(ErrorData {
            rmse,
            psnr,
            max_abs,
            image: ImageData::new(a.width, a.height, diff),
            max_error: max,
            low_frequency,
            spectrum,
        })),
        Some(Accuracy::Error {
            rmse,
            psnr,
            low_frequency,
        }),
    ))
}

/// ω range of the response plots and image (cycles per sample).
pub const RESPONSE_OMEGA_MAX: f64 = 1.5;
/// Side of the 2D response image.
pub const RESPONSE_IMAGE_SIZE: usize = 96;

pub(super) fn response(ctx: &JobCtx) -> Output {
    let (f2, cancel) = (&ctx.scene.filter, ctx.cancel);
    cancel.check()?;
    let f = &f2.filter;
    let r = f.radius();
    let kernel: Vec<[f64; 2]> = (0..=400)
        .map(|i| {
            let x = -r - 0.25 + (2.0 * r + 0.5) * i as f64 / 400.0;
            [x, f.eval(x)]
        })
        .collect();
    let curve = f.response_curve(RESPONSE_OMEGA_MAX, 300)?;
    let normalised = curve.normalised_by.is_some();
    let magnitude = curve
        .samples
        .iter()
        .map(|s| [s.omega, s.magnitude])
        .collect();
    let image = f2.response_image(RESPONSE_IMAGE_SIZE, RESPONSE_OMEGA_MAX)?;
    let norm = image
        .iter()
        .fold(0.0f64, |a, &b| a.max(b.abs()))
        .max(1e-300);
    let n = RESPONSE_IMAGE_SIZE;
    // Row 0 of the response image is the most negative ω_y: flip so ω_y points up.
    let image = ImageData::from_y_up(n, n, |i| (image[i].abs() / norm) as f32);
    cancel.check()?;
    let m = f2.metrics_with(crate::core::filter::metrics::OMEGA_MAX, cancel)?;
    Ok((
        NodeValue::Response(Arc::new(ResponseData {
            kernel,
            magnitude,
            normalised,
            omega_max: RESPONSE_OMEGA_MAX,
            image,
            metrics: ResponseMetrics {
                smoothing: m.smoothing,
                post_aliasing: m.post_aliasing,
                ringing: m.ringing,
                anisotropy: m.anisotropy,
            },
        })),
        None,
    ))
}

/// Samples per pixel of the convergence curve.
pub const CONVERGENCE_SPP: [usize; 5] = [1, 4, 16, 64, 256];
/// Image size of the convergence curve (small: 256 spp per pixel).
pub const CONVERGENCE_SIZE: usize = 64;

pub(super) fn convergence(ctx: &JobCtx) -> Output {
    let (scene, c, cancel) = (ctx.scene, ctx.column, ctx.cancel);
    let col = &scene.columns[c];
    if col.points.is_some() {
        return Err(NodeError::ImportedNeedsPattern {
            column: c,
            what: "the convergence curve",
        });
    }
    if let Some(why) = scene.filter.reconstruction_refusal() {
        return Err(NodeError::CannotReconstruct(why));
    }
    let provider = crate::core::recon::PatternProvider {
        pattern: col.pattern,
        seed: col.seed,
    };
    let plain = |points: &[crate::core::recon::ConvergencePoint]| -> Vec<ConvergencePoint> {
        points
            .iter()
            .map(|p| ConvergencePoint {
                spp: p.spp,
                rmse: p.rmse,
                millis: ms(p.time),
            })
            .collect()
    };
    // The curve grows one spp level at a time on screen.
    let curve = crate::core::recon::convergence_curve_progressive(
        &scene.signal,
        &provider,
        &CONVERGENCE_SPP,
        CONVERGENCE_SIZE,
        &scene.filter,
        cancel,
        &mut |p| {
            if let Some(points) = p.interim() {
                let accuracy = Accuracy::ConvergenceLevels {
                    done: p.done,
                    of: p.total,
                };
                let value = NodeValue::Convergence(Arc::new(plain(points)));
                ctx.publish(value, Some(accuracy), p.steps());
            }
        },
    )?;
    Ok((NodeValue::Convergence(Arc::new(plain(&curve.points))), None))
}

pub(super) fn spectrum(ctx: &JobCtx) -> Output {
    use crate::core::spectrum::average_periodogram_progressive;
    let (scene, cancel) = (ctx.scene, ctx.cancel);
    let col = ctx.col();
    let s = scene.spectrum;
    // Realization 0 is the points node's set: the points the pattern panel shows.
    let points0 = points_of(ctx.deps)?;
    let imported = col.points.is_some();
    let n_points = points0.points.len();
    let asked_k = s.realizations;
    let req = s.request(n_points, imported);
    let first = crate::core::rng::derive_seed(col.seed, 0);
    let (pattern, n) = (col.pattern, scene.n);
    let mut on_progress = |p: Progress<'_, crate::core::spectrum::Spectrum>| {
        if let Some(Ok(data)) = p.interim().map(|spec| spectrum_data(spec, Vec::new())) {
            let accuracy = Accuracy::Realizations {
                done: p.done,
                of: p.total,
            };
            ctx.publish(
                NodeValue::Spectrum(Arc::new(data)),
                Some(accuracy),
                p.steps(),
            );
        }
    };
    let (spec, report) = average_periodogram_progressive(
        &req,
        col.seed,
        move |sd| {
            if sd == first || imported {
                Ok(points0.points.clone())
            } else {
                pattern.generate(n, sd)
            }
        },
        cancel,
        crate::core::spectrum::average::PARTIAL_INTERVAL,
        &mut on_progress,
    )?;
    let stages = report
        .stages
        .iter()
        .map(|(name, d)| (name.to_string(), ms(*d)))
        .collect();
    let data = spectrum_data(&spec, stages)?;
    let accuracy = match (report.tolerance, report.error) {
        (Some(tol), Some(e)) => Accuracy::SpectrumMeasured {
            relative_l2: e.relative_l2,
            asked: tol,
            frequencies: e.frequencies,
        },
        (Some(tol), None) => Accuracy::SpectrumAsked { tolerance: tol },
        (None, _) => Accuracy::ExactDft,
    };
    let accuracy = Some(if imported && asked_k > 1 {
        Accuracy::ImportedOneRealization {
            asked: asked_k,
            spectrum: Box::new(accuracy),
        }
    } else {
        accuracy
    });
    Ok((NodeValue::Spectrum(Arc::new(data)), accuracy))
}

/// The display data of a periodogram: log image, auto range, RAPS and anisotropy (a
/// periodogram averaged elsewhere, `analyze`'s over files, is shown through it too).
pub fn spectrum_data(
    spec: &crate::core::spectrum::Spectrum,
    stages: Vec<(String, f64)>,
) -> Result<SpectrumData, crate::core::spectrum::SpectrumError> {
    let m = spec.m;
    let log = spec.to_display_image();
    // The q-quantiles by selection (O(M²), the same elements a full sort would give).
    let mut finite: Vec<f32> = log.iter().copied().filter(|v| v.is_finite()).collect();
    let mut pick = |q: f64| {
        if finite.is_empty() {
            return 0.0;
        }
        let i = ((finite.len() - 1) as f64 * q) as usize;
        *finite.select_nth_unstable_by(i, |a, b| a.total_cmp(b)).1
    };
    let (lo, hi) = (pick(0.02), pick(0.998));
    let auto_range = (lo, hi.max(lo + 1e-3));
    let bins = crate::core::spectrum::radial_average(spec)?;
    let raps = bins.iter().map(|b| [b.radius, b.mean_power]).collect();
    let anisotropy = bins
        .iter()
        .filter(|b| b.anisotropy_db.is_finite())
        .map(|b| [b.radius, b.anisotropy_db])
        .collect();
    Ok(SpectrumData {
        // Row iy = ky − k_min: flip so that ky points up.
        image: ImageData::from_y_up(m, m, |i| log[i]),
        auto_range,
        raps,
        anisotropy,
        stages,
        power: Arc::new(spec.clone()),
    })
}

/// Side of the integrand's preview image.
pub(crate) const INTEGRAND_THUMBNAIL: usize = 48;

/// f at the pixel centres of a `side`² grid over [0,1]² (row 0 at the top), scaled to [0, 1]
/// by its own minimum and maximum (a constant f is drawn as 0.5).
pub(crate) fn integrand_thumbnail(
    f: &crate::core::integration::Integrand,
    side: usize,
) -> ImageData {
    let values: Vec<f64> = (0..side * side)
        .map(|i| {
            let (col, row) = (i % side, i / side);
            f.eval(glam::DVec2::new(
                (col as f64 + 0.5) / side as f64,
                (row as f64 + 0.5) / side as f64,
            ))
        })
        .collect();
    let lo = values.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let scale = |v: f64| {
        if hi > lo {
            ((v - lo) / (hi - lo)) as f32
        } else {
            0.5
        }
    };
    ImageData::from_y_up(side, side, |i| scale(values[i]))
}

pub(super) fn integration(ctx: &JobCtx) -> Output {
    use crate::core::integration::{run_study, Study, StudyError};
    use crate::core::params::Params;
    let (scene, col, cancel) = (ctx.scene, ctx.col(), ctx.cancel);
    if col.points.is_some() {
        return Err(NodeError::ImportedNoStudy { column: ctx.column });
    }
    let settings = &scene.integration;
    let req = settings.request(col.pattern, col.seed);
    let f = settings.integrand;
    let integrand = format!("{} {}", f.name(), f.params_text());
    let thumbnail = integrand_thumbnail(&f, INTEGRAND_THUMBNAIL);
    let of = req.realizations;
    let data = |study: &Study, done: usize| {
        NodeValue::Integration(Arc::new(IntegrationData {
            study: study.clone(),
            done,
            of,
            integrand: integrand.trim().to_string(),
            randomized: settings.randomize,
            thumbnail: thumbnail.clone(),
        }))
    };
    // The curve shows 1, 2, 4, … realizations as they come in, then all R.
    let study = run_study(&req, cancel, &mut |p| {
        if let Some(s) = p.interim() {
            let r = s.realizations;
            let accuracy = Accuracy::Realizations { done: r, of };
            ctx.publish(data(s, r), Some(accuracy), Steps::at(r, of));
        }
    })
    .map_err(|e| match e {
        StudyError::Cancelled => NodeError::Cancelled,
        e => NodeError::Study(e),
    })?;
    Ok((data(&study, of), None))
}
