//! The statistics node: a column's point statistics (minimum distances, discrepancies, t-value;
//! PSA's from their node when it is an input).

use super::prelude::*;

/// The input nodes and scene fields of the node in column `c` of scene `s`.
pub(in crate::scene) fn inputs(s: &Scene, c: usize) -> Inputs {
    // PSA's statistics are part of the overlay's for N ≤ STATS_PSA_MAX_N (their node is
    // then an input); the column's N is known before its points are.
    let n = n_of(s, c);
    let psa = (crate::core::metrics::PSA_MIN_N..=crate::model::STATS_PSA_MAX_N).contains(&n);
    let nodes: &[NodeKind] = if psa {
        &[NodeKind::Points, NodeKind::Psa]
    } else {
        &[NodeKind::Points]
    };
    Inputs::new(NodeKind::Statistics, nodes, ())
}

/// What the node computes in column `c` of scene `s` (the budget's estimate).
pub(in crate::scene) fn estimate(s: &Scene, c: usize) -> Vec<Estimate> {
    // PSA's statistics are their own node (an input of the statistics for small N).
    vec![budget::statistics(n_of(s, c))]
}

/// The job: the node's value from the scene, the column and the declared inputs.
pub(in crate::scene) fn run(ctx: &JobCtx) -> Output {
    let (done, cancel) = (ctx.deps, ctx.cancel);
    let p = points_of(done)?;
    let s = crate::core::metrics::statistics(&p.points, cancel)?;
    // PSA's statistics when the plan made them an input (N ≤ STATS_PSA_MAX_N).
    let psa = match done.get(&NodeKind::Psa) {
        Some(_) => match dep(done, NodeKind::Psa)? {
            NodeValue::Psa(d) => d.statistics,
            _ => return Err(NodeError::Internal("the PSA input has another kind".into())),
        },
        None => None,
    };
    let md = s.min_distance.as_ref();
    Ok((
        NodeValue::Statistics(Arc::new(StatsData {
            min_distance: md.map(|m| m.min_distance).unwrap_or(f64::NAN),
            normalized_min_distance: md.map(|m| m.normalized_min_distance).unwrap_or(f64::NAN),
            mean_nn: md.map(|m| m.mean_nn_distance).unwrap_or(f64::NAN),
            star: s.star.as_ref().map(|st| (st.value, st.worst_box)),
            l2_star: s.l2_star,
            t_value: s.t_value.as_ref().map(|t| t.t),
            psa,
            full: s,
        })),
        None,
    ))
}
