//! The sequence node: a column's full run of N points, computed only when the scene shows a
//! prefix of it (the points node is then its first k; `scene::animation`).

use super::prelude::*;

/// The input nodes and scene fields of the node in column `c` of scene `s`: those of the
/// points of a scene without prefix.
pub(in crate::scene) fn inputs(s: &Scene, c: usize) -> Inputs {
    let col = &s.columns[c];
    match &col.points {
        Some(p) => Inputs::new(NodeKind::Sequence, &[], ("imported", p.content_digest())),
        None if col.is_plain_2d() => {
            Inputs::new(NodeKind::Sequence, &[], (&col.pattern, s.n, col.seed))
        }
        // A column in D > 2 dimensions: the run of its projection.
        None => Inputs::new(
            NodeKind::Sequence,
            &[],
            (&col.pattern, s.n, col.seed, col.dims, col.project),
        ),
    }
}

/// What the node computes in column `c` of scene `s` (the budget's estimate).
pub(in crate::scene) fn estimate(s: &Scene, c: usize) -> Vec<Estimate> {
    let col = &s.columns[c];
    match &col.points {
        Some(_) => Vec::new(),
        None => vec![budget::pattern_cube(&col.pattern, s.n, col.dims)],
    }
}

/// The job: the points node's job for all N points, kept as the sequence.
pub(in crate::scene) fn run(ctx: &JobCtx) -> Output {
    let (value, accuracy) = super::points::generate(ctx)?;
    match value {
        NodeValue::Points(p) => Ok((
            NodeValue::Sequence(Arc::new(SequenceData((*p).clone()))),
            accuracy,
        )),
        _ => Err(NodeError::Internal(
            "the points job returned another kind".into(),
        )),
    }
}
