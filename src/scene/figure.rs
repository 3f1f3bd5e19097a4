//! From a scene to what its figures say and draw: the [`FigureContext`] of a column (titles,
//! metadata and file names as plain strings), a column's [`ColumnData`] (its node results),
//! and the [`Publication`] of a scene's figures. Which figures a column has is
//! [`super::panels`]' rule.

use super::graph::{NodeKind, NodeResult, NodeValue};
use super::{panels, ReconMode, Scene};
use crate::core::params::Params;
use crate::model::{
    sanitize, Colormap, ColumnData, FigureContext, IntegrationCurve, IntegrationPlot, NodeRow,
    NodeStatus, Publication, Slot,
};
use std::collections::HashMap;
use std::sync::Arc;

use crate::model::IMPORTED;

/// A column index the scene does not have.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("column = {column}: must be an integer in 0..={}", *.columns as i64 - 1)]
pub struct NoSuchColumn {
    /// The index asked for.
    pub column: usize,
    /// How many columns the scene has.
    pub columns: usize,
}

/// The figure context of column `column` of `scene`; `scene_name` names the scene in file
/// names (its file stem; the title is used when empty). The display choices start at what
/// the GUI first shows: the data's own colour range, viridis, linear |H|, the column's own
/// elementary intervals.
pub fn context(
    scene: &Scene,
    column: usize,
    scene_name: &str,
) -> Result<FigureContext, NoSuchColumn> {
    let col = scene.columns.get(column).ok_or(NoSuchColumn {
        column,
        columns: scene.columns.len(),
    })?;
    let slugs = column_slugs(scene);
    let (pattern, pattern_params) = match &col.points {
        Some(p) => (
            IMPORTED.to_string(),
            format!("file={} normalize={}", p.label(), p.normalize),
        ),
        None => (col.pattern.name().to_string(), col.pattern.params_text()),
    };
    let recon = match scene.recon.mode {
        ReconMode::Scattered => "scattered".to_string(),
        ReconMode::Supersample { spp } => format!("supersample {spp} spp"),
        ReconMode::Resample { grid } => format!("resample {grid}² grid"),
    };
    let name = if scene_name.trim().is_empty() {
        &scene.title
    } else {
        scene_name
    };
    Ok(FigureContext {
        scene_title: scene.title.clone(),
        scene_name: sanitize(name),
        column,
        column_title: col.title(),
        column_slug: slugs[column].clone(),
        pattern,
        pattern_params,
        // What the column shows: the prefix's k of a scene with a prefix.
        n: scene.shown_n(column),
        seed: col.seed,
        signal: ron::to_string(&scene.signal).unwrap_or_else(|_| scene.signal.name().into()),
        filter: ron::to_string(&scene.filter).unwrap_or_else(|_| scene.filter.filter.name().into()),
        recon: format!("{recon}, {}²", scene.recon.size),
        spectrum_range: None,
        spectrum_colormap: Colormap::Viridis,
        response_db: false,
        elementary_k: col.elementary_k,
        strata: strata(scene, column, false),
        projection: (!col.is_plain_2d() && col.points.is_none()).then_some((
            col.project.0,
            col.project.1,
            col.dims,
        )),
        matrix_measure: scene.matrix.measure,
    })
}

/// The strata drawn under column `column`'s points, in its figures and on its pattern panel:
/// when the column's `strata` or the GUI's `overlay` is on, the pattern's strata for N (none
/// for imported points, none beyond [`crate::model::MAX_STRATA_LINES`] per axis).
pub fn strata(scene: &Scene, column: usize, overlay: bool) -> Option<(usize, usize)> {
    let col = scene.columns.get(column)?;
    if (col.strata || overlay) && col.points.is_none() {
        crate::model::drawn_strata(col.pattern.strata(scene.n))
    } else {
        None
    }
}

/// A node's result as its holder keeps it: the bare result (`render`, the CLI's fronts,
/// `Evaluator::evaluate`'s sink) or with what the holder knows besides (the GUI's results:
/// the progress of a coarse result, the scene it was computed for).
pub trait HeldResult: AsRef<NodeResult> {
    /// Its status; by default what the result alone says (no progress, no scene).
    fn status(&self) -> NodeStatus {
        let r = self.as_ref();
        NodeStatus {
            wall: r.wall,
            accuracy: r.accuracy.clone(),
            progress: None,
            computed_for: None,
        }
    }
}

impl HeldResult for Arc<NodeResult> {}

/// The slot of one node: its data if it is of `pick`'s kind, its error if it failed.
fn slot_of<'a, T: 'a, R: HeldResult>(
    held: Option<&'a R>,
    pick: impl Fn(&'a NodeValue) -> Option<&'a Arc<T>>,
) -> Slot<T> {
    let Some(held) = held else {
        return Slot::Missing;
    };
    match &held.as_ref().value {
        Err(e) => Slot::Failed {
            status: held.status(),
            error: e.to_string(),
        },
        Ok(v) => pick(v).map_or(Slot::Missing, |d| Slot::Ready {
            status: held.status(),
            data: d.clone(),
        }),
    }
}

/// Expands the node list (`compute::node_list!`) into [`column_data`]: one slot per node,
/// its `ColumnData` field named as the node's file.
macro_rules! column_slots {
    (
        kinds: $kinds:tt
        table: $table:tt
        columns: [$($(#[$doc:meta])* $kind:ident($ty:ty) $field:ident;)*]
    ) => {
        /// A column's data from its node results (the GUI's, or what `Evaluator::evaluate`
        /// sent for the column): every node as a [`Slot`] (data with status, error, or
        /// missing), and every node's status for the cost view. The one place a column's node
        /// values become plain data.
        pub fn column_data<R: HeldResult>(results: &HashMap<NodeKind, R>) -> ColumnData {
            use super::graph::NodeValue as V;
            ColumnData {
                $($field: slot_of(results.get(&NodeKind::$kind), |v| match v {
                    V::$kind(d) => Some(d),
                    _ => None,
                }),)*
                integration_plot: None,
                nodes: NodeKind::ALL
                    .into_iter()
                    .map(|k| NodeRow {
                        name: k.name(),
                        status: results.get(&k).map(HeldResult::status),
                    })
                    .collect(),
            }
        }
    };
}

super::compute::node_list!(column_slots);

/// Every column's data ([`column_data`]), with column 0 also holding the integration plot:
/// the studies of all columns, labelled with their titles.
pub fn columns_data<R: HeldResult>(
    scene: &Scene,
    results: &[HashMap<NodeKind, R>],
) -> Vec<ColumnData> {
    let mut columns: Vec<ColumnData> = results.iter().map(column_data).collect();
    let curves: Vec<IntegrationCurve> = columns
        .iter()
        .enumerate()
        .filter_map(|(c, d)| {
            let data = d.integration.data()?.clone();
            let label = scene.columns.get(c).map(|col| col.title())?;
            Some(IntegrationCurve { label, data })
        })
        .collect();
    if let Some(first) = columns.first_mut() {
        if !curves.is_empty() {
            first.integration_plot = Some(Arc::new(IntegrationPlot { curves }));
        }
    }
    columns
}

/// Every column's context and data as `samplescope render` draws them: [`context`] and
/// [`columns_data`], with one colour range for every periodogram
/// ([`crate::model::shared_spectrum_range`] of the columns' automatic ranges), so that a
/// comparison's periodograms share one colour bar.
pub fn figure_columns<R: HeldResult>(
    scene: &Scene,
    results: &[HashMap<NodeKind, R>],
    scene_name: &str,
) -> Result<Vec<(FigureContext, ColumnData)>, NoSuchColumn> {
    let mut columns = Vec::with_capacity(scene.columns.len());
    for (c, data) in columns_data(scene, results).into_iter().enumerate() {
        columns.push((context(scene, c, scene_name)?, data));
    }
    let ranges: Vec<(f32, f32)> = columns
        .iter()
        .filter_map(|(_, d)| d.spectrum.data().map(|s| s.auto_range))
        .collect();
    if let Some(shared) = crate::model::shared_spectrum_range(&ranges) {
        for (ctx, _) in &mut columns {
            ctx.spectrum_range = Some(shared);
        }
    }
    Ok(columns)
}

/// What a publication of `scene`'s figures draws ([`Publication`]): `columns` (every column's
/// context and data, in order; [`figure_columns`] or the GUI's own), the figures each column
/// lists, each column's composite and the comparison ([`super::panels`]' rule). The
/// comparison's file name takes the scene name of column 0's context (`scene_name` when the
/// scene has no column).
pub fn publication(
    scene: &Scene,
    columns: Vec<(FigureContext, ColumnData)>,
    scene_name: &str,
) -> Publication {
    let count = scene.columns.len();
    Publication {
        name: columns
            .first()
            .map_or_else(|| scene_name.to_string(), |(c, _)| c.scene_name.clone()),
        n: scene.n,
        figures: (0..count).map(|c| panels::available_in(scene, c)).collect(),
        composites: (0..count).map(|c| panels::composite_in(scene, c)).collect(),
        comparison: panels::comparison(scene),
        columns,
    }
}

/// Unique file-name parts for the columns of a scene.
fn column_slugs(scene: &Scene) -> Vec<String> {
    let base: Vec<String> = scene
        .columns
        .iter()
        .map(|c| {
            let name = sanitize(if c.points.is_some() {
                IMPORTED
            } else {
                c.pattern.name()
            });
            let label = sanitize(&c.title());
            if label == name {
                name
            } else {
                format!("{name}-{label}")
            }
        })
        .collect();
    base.iter()
        .enumerate()
        .map(|(i, s)| {
            if base.iter().filter(|t| *t == s).count() > 1 {
                format!("{s}-c{}", i + 1)
            } else {
                s.clone()
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn column_slugs_are_unique_within_a_scene() {
        let mut scene = Scene {
            columns: vec![Default::default(), Default::default()],
            ..Default::default()
        };
        scene.columns[1].label = "jitter".into();
        assert_eq!(column_slugs(&scene), vec!["jitter-c1", "jitter-c2"]);
        scene.columns[1].label = "p1 = 3".into();
        assert_eq!(column_slugs(&scene), vec!["jitter", "jitter-p1-3"]);
    }

    #[test]
    fn imported_columns_are_named_by_their_file() {
        let text = r#"(title: "x", n: 2, columns: [
            (points: Some((path: "", points: [(0.5, 0.5), (0.25, 0.75)]))),
            (pattern: (kind: "random")),
        ])"#;
        let scene = Scene::from_ron(text, "imported.ron").unwrap();
        let ctx = context(&scene, 0, "imp").unwrap();
        assert_eq!(ctx.pattern, "imported");
        assert_eq!(ctx.pattern_params, "file=inline points normalize=false");
        assert!(
            ctx.column_slug.starts_with("imported"),
            "{}",
            ctx.column_slug
        );
        assert_eq!(context(&scene, 1, "imp").unwrap().pattern, "random");
        // A file's points have no seed: their captions name none; a pattern's name its seed.
        assert!(!ctx.seeded());
        assert!(
            !ctx.column_caption().contains("seed"),
            "{}",
            ctx.column_caption()
        );
        let random = context(&scene, 1, "imp").unwrap();
        assert!(random.seeded());
        let tail = format!(", N = 2, seed {}", random.seed);
        assert!(
            random.column_caption().ends_with(&tail),
            "{}",
            random.column_caption()
        );
    }

    #[test]
    fn a_column_the_scene_lacks_names_the_range() {
        let scene = Scene::default();
        let e = context(&scene, 3, "x").unwrap_err().to_string();
        assert_eq!(e, "column = 3: must be an integer in 0..=0");
    }
}
