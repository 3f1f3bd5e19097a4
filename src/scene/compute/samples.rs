//! The samples node: the signal at the column's points (scattered reconstruction's input).

use super::prelude::*;

/// The input nodes and scene fields of the node in column `c` of scene `s`.
pub(in crate::scene) fn inputs(s: &Scene, _: usize) -> Inputs {
    Inputs::new(NodeKind::Samples, &[NodeKind::Points], s.signal)
}

/// What the node computes in column `c` of scene `s` (the budget's estimate).
pub(in crate::scene) fn estimate(s: &Scene, c: usize) -> Vec<Estimate> {
    vec![budget::sampling(&s.signal, n_of(s, c))]
}

/// The job: the node's value from the scene, the column and the declared inputs.
pub(in crate::scene) fn run(ctx: &JobCtx) -> Output {
    let p = points_of(ctx.deps)?;
    let v = crate::core::recon::sample_signal(&ctx.scene.signal, &p.points, ctx.cancel)?;
    Ok((NodeValue::Samples(Arc::new(v)), None))
}
