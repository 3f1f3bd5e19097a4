//! The reference node: the signal's reference image (quadrature or supersampling, with its error
//! estimate).

use super::prelude::*;

/// The input nodes and scene fields of the node in column `c` of scene `s`.
pub(in crate::scene) fn inputs(s: &Scene, _: usize) -> Inputs {
    Inputs::new(NodeKind::Reference, &[], (&s.signal, s.recon.size))
}

/// What the node computes in column `c` of scene `s` (the budget's estimate).
pub(in crate::scene) fn estimate(s: &Scene, _: usize) -> Vec<Estimate> {
    vec![budget::reference(&s.signal, s.recon.size)]
}

/// The job: the node's value from the scene, the column and the declared inputs.
pub(in crate::scene) fn run(ctx: &JobCtx) -> Output {
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
