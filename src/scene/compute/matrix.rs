//! The projection-matrix node: the first K dimensions of the column's points (its pattern's in
//! [0,1)^dims, or the imported 2D set), one cell per pair i < j with the pair's scatter-plot
//! coverage and its row of the projection table (t-value, L2-star discrepancy, minimum
//! distance). The coverage comes first (published at once), the rows as they are measured.

use super::prelude::*;
use crate::core::cube::CubePoints;
use crate::core::metrics::cube::{projection_rows, projections::pairs, CubeMeasure};
use crate::core::metrics::MetricsError;
use crate::model::{coverage, MatrixCell, MatrixData};

/// K for column `c`: the scene's setting, at most the column's dims (2 for imported points).
fn shown_k(s: &Scene, c: usize) -> usize {
    let col = &s.columns[c];
    let dims = if col.points.is_some() { 2 } else { col.dims };
    s.matrix.shown(dims)
}

/// The input nodes and scene fields of the node in column `c` of scene `s`.
pub(in crate::scene) fn inputs(s: &Scene, c: usize) -> Inputs {
    let col = &s.columns[c];
    let k = shown_k(s, c);
    // The measure only tints the cells: every row holds all three, so it is not an input.
    match &col.points {
        // Imported points come from the points node (its key holds their bits).
        Some(_) => Inputs::new(NodeKind::Matrix, &[NodeKind::Points], ("imported", k)),
        None => Inputs::new(
            NodeKind::Matrix,
            &[],
            (&col.pattern, s.n, col.seed, col.dims, k),
        ),
    }
}

/// What the node computes in column `c` of scene `s` (the budget's estimate): the points in
/// [0,1)^dims (a pattern's), and the projection table of the first K dimensions.
pub(in crate::scene) fn estimate(s: &Scene, c: usize) -> Vec<Estimate> {
    let col = &s.columns[c];
    let (n, k) = (n_of(s, c), shown_k(s, c));
    let mut v = Vec::new();
    if col.points.is_none() {
        v.push(budget::pattern_cube(&col.pattern, n, col.dims));
    }
    v.push(budget::cube_measure(CubeMeasure::Projections, n, k));
    v
}

/// How often the node publishes the cells measured so far.
const PARTIAL_INTERVAL: Duration = Duration::from_millis(150);

/// The job: the node's value from the scene, the column and the declared inputs.
pub(in crate::scene) fn run(ctx: &JobCtx) -> Output {
    let (scene, col, cancel) = (ctx.scene, ctx.col(), ctx.cancel);
    let k = shown_k(scene, ctx.column);
    let cube = match &col.points {
        Some(_) => CubePoints::from_2d(&points_of(ctx.deps)?.points),
        None => col
            .pattern
            .generate_cube(scene.n, col.dims, col.seed, cancel)?,
    };
    let dims = cube.dims();
    // The first K dimensions as a point set of its own (the table's input).
    let first = if k == dims {
        cube
    } else {
        let coords = cube.rows().flat_map(|r| r[..k].iter().copied()).collect();
        CubePoints::new(k, coords).map_err(|e| NodeError::Internal(e.to_string()))?
    };
    let n = first.n();
    let all = pairs(k);
    let mut cells = Vec::with_capacity(all.len());
    for &[i, j] in &all {
        cancel.check()?;
        cells.push(MatrixCell {
            pair: [i, j],
            row: None,
            coverage: coverage(first.rows().map(|r| (r[i], r[j])), n),
        });
    }
    let data =
        |cells: Vec<MatrixCell>| NodeValue::Matrix(Arc::new(MatrixData { k, dims, n, cells }));
    // The scatter plots at once, then the tints as the pairs are measured.
    let total = all.len();
    ctx.publish(
        data(cells.clone()),
        Some(Accuracy::Pairs { done: 0, of: total }),
        Steps::at(0, total),
    );
    let mut throttle = Throttle::new(PARTIAL_INTERVAL);
    let rows = projection_rows(&first, &all, cancel, &mut |p| {
        if let Some(rows) = p.interim().filter(|_| throttle.due()) {
            let mut part = cells.clone();
            for (c, r) in part.iter_mut().zip(rows) {
                c.row = Some(*r);
            }
            let accuracy = Accuracy::Pairs {
                done: p.done,
                of: p.total,
            };
            ctx.publish(data(part), Some(accuracy), p.steps());
            throttle.restart();
        }
    })
    .map_err(|e| match e {
        MetricsError::Cancelled => NodeError::Cancelled,
        e => NodeError::Metrics(e),
    })?;
    for (c, r) in cells.iter_mut().zip(rows) {
        c.row = Some(r);
    }
    Ok((data(cells), None))
}
