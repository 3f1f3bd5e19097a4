//! The integration node: the integration-error study of the column's pattern.

use super::prelude::*;

/// The input nodes and scene fields of the node in column `c` of scene `s`.
pub(in crate::scene) fn inputs(s: &Scene, c: usize) -> Inputs {
    // Every column's curve goes on the one plot (whose figure belongs to column 0).
    let col = &s.columns[c];
    match &col.points {
        // Imported points have one N: the job reports that instead of running.
        Some(p) => Inputs::new(NodeKind::Integration, &[], ("imported", p.content_digest())),
        // The study's D is the column's (the 2D key is unchanged).
        None if col.dims == 2 => Inputs::new(
            NodeKind::Integration,
            &[],
            (&col.pattern, col.seed, &s.integration),
        ),
        None => Inputs::new(
            NodeKind::Integration,
            &[],
            (&col.pattern, col.seed, &s.integration, col.dims),
        ),
    }
}

/// What the node computes in column `c` of scene `s` (the budget's estimate).
pub(in crate::scene) fn estimate(s: &Scene, c: usize) -> Vec<Estimate> {
    // Imported points report an error instead of running.
    let col = &s.columns[c];
    match &col.points {
        Some(_) => Vec::new(),
        None => crate::core::integration::estimate(&s.integration.request(
            col.pattern,
            col.seed,
            col.dims,
        )),
    }
}

/// Side of the integrand's preview image.
pub const INTEGRAND_THUMBNAIL: usize = 48;

/// f at the pixel centres of a `side`² grid over [0,1]² (row 0 at the top), scaled to [0, 1]
/// by its own minimum and maximum (a constant f is drawn as 0.5).
pub fn integrand_thumbnail(f: &crate::core::integration::Integrand, side: usize) -> ImageData {
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

/// The job: the node's value from the scene, the column and the declared inputs.
pub(in crate::scene) fn run(ctx: &JobCtx) -> Output {
    use crate::core::integration::{run_study, Study, StudyError};
    use crate::core::params::Params;
    let (scene, col, cancel) = (ctx.scene, ctx.col(), ctx.cancel);
    if col.points.is_some() {
        return Err(NodeError::ImportedNoStudy { column: ctx.column });
    }
    let settings = &scene.integration;
    let req = settings.request(col.pattern, col.seed, col.dims);
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
