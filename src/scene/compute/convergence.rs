//! The convergence node: RMSE against samples per pixel, one level at a time.

use super::prelude::*;

/// The input nodes and scene fields of the node in column `c` of scene `s`.
pub(in crate::scene) fn inputs(s: &Scene, c: usize) -> Inputs {
    let col = &s.columns[c];
    Inputs::new(
        NodeKind::Convergence,
        &[],
        (&col.pattern, col.seed, &s.signal, &s.filter),
    )
}

/// What the node computes in column `c` of scene `s` (the budget's estimate).
pub(in crate::scene) fn estimate(s: &Scene, c: usize) -> Vec<Estimate> {
    vec![budget::convergence(
        &s.signal,
        &s.columns[c].pattern,
        &CONVERGENCE_SPP,
        CONVERGENCE_SIZE,
        &s.filter,
    )]
}

/// Samples per pixel of the convergence curve.
pub const CONVERGENCE_SPP: [usize; 5] = [1, 4, 16, 64, 256];

/// Image size of the convergence curve (small: 256 spp per pixel).
pub const CONVERGENCE_SIZE: usize = 64;

/// The job: the node's value from the scene, the column and the declared inputs.
pub(in crate::scene) fn run(ctx: &JobCtx) -> Output {
    let (scene, c, cancel) = (ctx.scene, ctx.column, ctx.cancel);
    let col = &scene.columns[c];
    if col.points.is_some() {
        return Err(NodeError::ImportedNeedsPattern {
            column: c,
            what: "the convergence curve",
        });
    }
    if !col.is_plain_2d() {
        return Err(NodeError::ProjectedNeedsPattern {
            column: c,
            dims: col.dims,
            project: col.project,
            what: "the convergence curve",
        });
    }
    if let Some(why) = scene.filter.reconstruction_refusal() {
        return Err(NodeError::CannotReconstruct(why));
    }
    let provider = crate::core::recon::PatternProvider {
        pattern: col.pattern,
        seed: col.seed,
    };
    let plain = |points: &[crate::core::recon::ConvergencePoint]| -> Vec<ConvergencePoint> {
        points
            .iter()
            .map(|p| ConvergencePoint {
                spp: p.spp,
                rmse: p.rmse,
                millis: ms(p.time),
            })
            .collect()
    };
    // The curve grows one spp level at a time on screen.
    let curve = crate::core::recon::convergence_curve_progressive(
        &scene.signal,
        &provider,
        &CONVERGENCE_SPP,
        CONVERGENCE_SIZE,
        &scene.filter,
        cancel,
        &mut |p| {
            if let Some(points) = p.interim() {
                let accuracy = Accuracy::ConvergenceLevels {
                    done: p.done,
                    of: p.total,
                };
                let value = NodeValue::Convergence(Arc::new(plain(points)));
                ctx.publish(value, Some(accuracy), p.steps());
            }
        },
    )?;
    Ok((NodeValue::Convergence(Arc::new(plain(&curve.points))), None))
}
