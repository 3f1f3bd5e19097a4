//! The theorem node: the 1D sampling-theorem view (column-independent: computed for column 0 only).

use super::prelude::*;

/// The input nodes and scene fields of the node in column `c` of scene `s`.
pub(in crate::scene) fn inputs(s: &Scene, _: usize) -> Inputs {
    // Column-independent: keyed by its settings alone (the theorem panel asks for it in
    // column 0 only).
    Inputs::new(NodeKind::Theorem, &[], s.theorem)
}

/// What the node computes in column `c` of scene `s` (the budget's estimate).
pub(in crate::scene) fn estimate(_: &Scene, _: usize) -> Vec<Estimate> {
    vec![budget::theorem()]
}

/// The job: the node's value from the scene, the column and the declared inputs.
pub(in crate::scene) fn run(ctx: &JobCtx) -> Output {
    ctx.cancel.check()?;
    let v = crate::core::signal::theorem::compute_view(&ctx.scene.theorem)?;
    let e = &v.errors;
    let accuracy = Some(Accuracy::TheoremBand {
        band: e.band,
        tail: e.tail_bound,
    });
    Ok((NodeValue::Theorem(Arc::new(v)), accuracy))
}
