//! The net-prefixes node: the (0,k,2)-net check of the power-of-two prefixes (read by `analyze`, by
//! no panel).

use super::prelude::*;

/// The input nodes and scene fields of the node in column `c` of scene `s`.
pub(in crate::scene) fn inputs(_: &Scene, _: usize) -> Inputs {
    Inputs::new(NodeKind::NetPrefixes, &[NodeKind::Points], ())
}

/// What the node computes in column `c` of scene `s` (the budget's estimate).
pub(in crate::scene) fn estimate(s: &Scene, c: usize) -> Vec<Estimate> {
    vec![budget::net_prefixes(n_of(s, c))]
}

/// The job: the node's value from the scene, the column and the declared inputs.
pub(in crate::scene) fn run(ctx: &JobCtx) -> Output {
    let p = points_of(ctx.deps)?;
    let v = crate::core::metrics::net_prefixes(&p.points, ctx.cancel)?;
    Ok((NodeValue::NetPrefixes(Arc::new(v)), None))
}
