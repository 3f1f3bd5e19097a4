//! The PSA node: PSA's statistics of a column's points (effective Nyquist frequency, oscillations,
//! bond-orientational order), or why they were skipped.

use super::prelude::*;

/// The input nodes and scene fields of the node in column `c` of scene `s`.
pub(in crate::scene) fn inputs(_: &Scene, _: usize) -> Inputs {
    Inputs::new(NodeKind::Psa, &[NodeKind::Points], ())
}

/// What the node computes in column `c` of scene `s` (the budget's estimate).
pub(in crate::scene) fn estimate(s: &Scene, c: usize) -> Vec<Estimate> {
    vec![budget::psa_statistics(n_of(s, c))]
}

/// The job: the node's value from the scene, the column and the declared inputs.
pub(in crate::scene) fn run(ctx: &JobCtx) -> Output {
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
                "PSA statistics need {PSA_MIN_N} ≤ n ≤ {PSA_MAX_N} points (the RDF's pairs closer than ¼ cost O(N²)), got n = {n}"
            )),
        }
    };
    Ok((NodeValue::Psa(Arc::new(data)), None))
}
