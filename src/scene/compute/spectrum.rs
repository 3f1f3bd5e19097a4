//! The spectrum node: the periodogram averaged over the realizations, its radial average and
//! anisotropy.

use super::prelude::*;

/// The input nodes and scene fields of the node in column `c` of scene `s`.
pub(in crate::scene) fn inputs(s: &Scene, c: usize) -> Inputs {
    // Realization 0 is the points node's set; realizations r > 0 are generated from the
    // pattern (an imported file has one realization: K does not matter, see `import`).
    let col = &s.columns[c];
    let sp = s.spectrum;
    match &col.points {
        Some(_) => Inputs::new(
            NodeKind::Spectrum,
            &[NodeKind::Points],
            (sp.size, sp.tolerance, sp.exact, sp.mask_dc),
        ),
        None => Inputs::new(
            NodeKind::Spectrum,
            &[NodeKind::Points],
            (&col.pattern, s.n, col.seed, sp),
        ),
    }
}

/// What the node computes in column `c` of scene `s` (the budget's estimate).
pub(in crate::scene) fn estimate(s: &Scene, c: usize) -> Vec<Estimate> {
    let col = &s.columns[c];
    let (n, imported) = (n_of(s, c), col.points.is_some());
    let req = s.spectrum.request(n, imported);
    let generator = (!imported).then_some(&col.pattern);
    vec![budget::spectrum(&req, n, generator)]
}

/// The job: the node's value from the scene, the column and the declared inputs.
pub(in crate::scene) fn run(ctx: &JobCtx) -> Output {
    use crate::core::spectrum::average_periodogram_staged;
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
    let n = scene.n;
    let shown = scene.prefix.unwrap_or(n);
    let mut on_progress = |p: Progress<'_, crate::core::spectrum::Spectrum>| {
        if let Some(Ok(data)) = p
            .interim()
            .map(|spec| spectrum_data(Arc::new(spec.clone()), Vec::new()))
        {
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
    let (spec, mut report, check) = average_periodogram_staged(
        &req,
        col.seed,
        move |sd| {
            if sd == first || imported {
                Ok(points0.points.clone())
            } else {
                // Another realization of what the column shows (its projection in D > 2
                // dimensions): its first k with a prefix.
                col.generate_2d(n, sd, cancel).map(|mut v| {
                    v.truncate(shown);
                    v
                })
            }
        },
        cancel,
        crate::core::spectrum::average::PARTIAL_INTERVAL,
        &mut on_progress,
    )?;
    let stages = |report: &crate::core::spectrum::SpectrumReport| {
        report
            .stages
            .iter()
            .map(|(name, d)| (name.to_string(), ms(*d)))
            .collect()
    };
    let mut data = spectrum_data(Arc::new(spec), stages(&report))?;
    let shown_accuracy = |accuracy: Accuracy| {
        Some(if imported && asked_k > 1 {
            Accuracy::ImportedOneRealization {
                asked: asked_k,
                spectrum: Box::new(accuracy),
            }
        } else {
            accuracy
        })
    };
    if let (Some(check), Some(tol)) = (check, report.tolerance) {
        // The picture is complete: show it now, and its measured error (two exact DFT rows at
        // the default scene, about as long as the NUFFT itself) when it is ready.
        let data_now = Arc::new(data);
        ctx.publish_final_value(
            NodeValue::Spectrum(data_now.clone()),
            shown_accuracy(Accuracy::SpectrumMeasuring { asked: tol }),
        );
        report.finish_check(Some(check), cancel)?;
        data = Arc::unwrap_or_clone(data_now);
        data.stages = stages(&report);
    }
    let accuracy = match (report.tolerance, report.error) {
        (Some(tol), Some(e)) => Accuracy::SpectrumMeasured {
            relative_l2: e.relative_l2,
            asked: tol,
            frequencies: e.frequencies,
        },
        (Some(tol), None) => Accuracy::SpectrumAsked { tolerance: tol },
        (None, _) => Accuracy::ExactDft,
    };
    Ok((
        NodeValue::Spectrum(Arc::new(data)),
        shown_accuracy(accuracy),
    ))
}

/// The rank of the q-quantile among `len` sorted values (the one the display range uses).
fn quantile_rank(len: usize, q: f64) -> usize {
    ((len - 1) as f64 * q) as usize
}

/// The display data of a periodogram: log image, auto range, RAPS and anisotropy (a
/// periodogram averaged elsewhere, `analyze`'s over files, is shown through it too). The
/// spectrum is kept in the result as it is, not copied.
pub fn spectrum_data(
    spec: Arc<crate::core::spectrum::Spectrum>,
    stages: Vec<(String, f64)>,
) -> Result<SpectrumData, crate::core::spectrum::SpectrumError> {
    let m = spec.m;
    // The display image and its range beside the radial average (both read the periodogram).
    let ((image, auto_range), bins) = rayon::join(
        || {
            let log = spec.to_display_image();
            // Row iy = ky − k_min: flip so that ky points up.
            let image = ImageData::from_y_up(m, m, |i| log[i]);
            // The 2% and 99.8% quantiles by selection (O(M²), the elements a full sort would
            // give), in the log buffer itself once the image is made: the second one among
            // the values above the first.
            let mut finite = log;
            finite.retain(|v| v.is_finite());
            let auto_range = match finite.len() {
                0 => (0.0, 1e-3),
                len => {
                    let (i_lo, i_hi) = (quantile_rank(len, 0.02), quantile_rank(len, 0.998));
                    let (_, &mut lo, above) =
                        finite.select_nth_unstable_by(i_lo, |a, b| a.total_cmp(b));
                    let hi = if i_hi == i_lo {
                        lo
                    } else {
                        *above
                            .select_nth_unstable_by(i_hi - i_lo - 1, |a, b| a.total_cmp(b))
                            .1
                    };
                    (lo, hi.max(lo + 1e-3))
                }
            };
            (image, auto_range)
        },
        || crate::core::spectrum::radial_average(&spec),
    );
    let bins = bins?;
    let raps = bins.iter().map(|b| [b.radius, b.mean_power]).collect();
    let anisotropy = bins
        .iter()
        .filter(|b| b.anisotropy_db.is_finite())
        .map(|b| [b.radius, b.anisotropy_db])
        .collect();
    Ok(SpectrumData {
        image,
        auto_range,
        raps,
        anisotropy,
        stages,
        power: spec,
    })
}
