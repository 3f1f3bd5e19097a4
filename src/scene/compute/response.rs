//! The response node: the filter's kernel, frequency response (curve and 2D image) and metrics.

use super::prelude::*;

/// The input nodes and scene fields of the node in column `c` of scene `s`.
pub(in crate::scene) fn inputs(s: &Scene, _: usize) -> Inputs {
    Inputs::new(NodeKind::Response, &[], s.filter)
}

/// What the node computes in column `c` of scene `s` (the budget's estimate).
pub(in crate::scene) fn estimate(s: &Scene, _: usize) -> Vec<Estimate> {
    vec![budget::filter_metrics(&s.filter)]
}

/// ω range of the response plots and image (cycles per sample).
pub const RESPONSE_OMEGA_MAX: f64 = 1.5;

/// Side of the 2D response image.
pub const RESPONSE_IMAGE_SIZE: usize = 96;

/// The job: the node's value from the scene, the column and the declared inputs.
pub(in crate::scene) fn run(ctx: &JobCtx) -> Output {
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
