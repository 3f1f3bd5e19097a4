//! The error node: |reconstruction − reference| with RMSE, PSNR and the error's periodogram.

use super::prelude::*;

/// The input nodes and scene fields of the node in column `c` of scene `s`.
pub(in crate::scene) fn inputs(_: &Scene, _: usize) -> Inputs {
    Inputs::new(
        NodeKind::Error,
        &[NodeKind::Reconstruction, NodeKind::Reference],
        (),
    )
}

/// What the node computes in column `c` of scene `s` (the budget's estimate).
pub(in crate::scene) fn estimate(s: &Scene, _: usize) -> Vec<Estimate> {
    vec![budget::error_image(s.recon.size)]
}

/// The job: the node's value from the scene, the column and the declared inputs.
pub(in crate::scene) fn run(ctx: &JobCtx) -> Output {
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
