//! The RDF node: PSA's radial distribution function of a column's points (read by `analyze --rdf`,
//! by no panel).

use super::prelude::*;

/// The input nodes and scene fields of the node in column `c` of scene `s`.
pub(in crate::scene) fn inputs(_: &Scene, _: usize) -> Inputs {
    Inputs::new(NodeKind::Rdf, &[NodeKind::Points], ())
}

/// What the node computes in column `c` of scene `s` (the budget's estimate).
pub(in crate::scene) fn estimate(s: &Scene, c: usize) -> Vec<Estimate> {
    let n = n_of(s, c);
    let (bins, r_max) = crate::core::metrics::psa::psa_rdf_range(n);
    vec![budget::rdf(n, bins, r_max)]
}

/// The job: the node's value from the scene, the column and the declared inputs.
pub(in crate::scene) fn run(ctx: &JobCtx) -> Output {
    let p = points_of(ctx.deps)?;
    // PSA's bins: N/8 of them up to 8 hexagonal spacings.
    let (bins, r_max) = crate::core::metrics::psa::psa_rdf_range(p.points.len());
    let g = crate::core::metrics::rdf(&p.points, bins, r_max, ctx.cancel)?;
    Ok((NodeValue::Rdf(Arc::new(g)), None))
}
