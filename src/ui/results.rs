//! The engine's results as the UI holds them: what is on screen per column, and the last
//! generation that finished. The app keeps them and makes each column's plain
//! `model::ColumnData` from them (`scene::figure::column_data`, with the status [`Shown`]
//! knows: progress and the scene); the panels read only that data, never the graph's values.

use crate::core::progress::Steps;
use crate::engine::Update;
use crate::model::NodeStatus;
use crate::scene::figure::HeldResult;
use crate::scene::graph::{NodeKind, NodeResult};
use crate::scene::Scene;
use std::collections::HashMap;
use std::sync::Arc;

/// A result on screen, with the generation and the scene snapshot it was computed for (its
/// panel's labels and saved figures come from that scene, never from a newer one).
#[derive(Clone)]
pub struct Shown {
    /// The node's result.
    pub result: Arc<NodeResult>,
    /// The scene it was computed for.
    pub scene: Arc<Scene>,
    /// The generation it belongs to.
    pub generation: u64,
    /// `Some` while the node refines (a coarse result is on screen; `None` for a final value
    /// whose readout is still being measured).
    pub progress: Option<Steps>,
}

impl std::ops::Deref for Shown {
    type Target = NodeResult;
    fn deref(&self) -> &NodeResult {
        &self.result
    }
}

impl AsRef<NodeResult> for Shown {
    fn as_ref(&self) -> &NodeResult {
        &self.result
    }
}

impl From<Update> for Shown {
    /// A final value published before its readout is shown as final (no "refining" bar):
    /// its accuracy says what is still being measured.
    fn from(u: Update) -> Self {
        Shown {
            result: u.result,
            scene: u.scene,
            generation: u.generation,
            progress: u.progress.filter(|_| !u.value_final),
        }
    }
}

/// Results of one column, by node kind.
pub type ColumnResults = HashMap<NodeKind, Shown>;

/// Every column's results of one generation that finished, with its scene.
#[derive(Clone)]
pub struct CompleteResults {
    /// The scene the generation was computed for.
    pub scene: Arc<Scene>,
    /// The generation.
    pub generation: u64,
    /// Each column's results, in column order.
    pub columns: Vec<ColumnResults>,
}

impl HeldResult for Shown {
    /// The result's status with what the UI holds besides: the refinement under way and the
    /// scene it was computed for.
    fn status(&self) -> NodeStatus {
        NodeStatus {
            wall: self.result.wall,
            accuracy: self.result.accuracy.clone(),
            progress: self.progress,
            computed_for: Some(self.scene.clone()),
        }
    }
}

/// The scene a status says its data was computed for (the GUI's results carry it; see
/// [`NodeStatus::computed_for`]).
pub fn scene_of(status: &NodeStatus) -> Option<&Scene> {
    status.computed_for.as_ref()?.downcast_ref::<Scene>()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{ColumnData, PointsData, SpectrumData, StatsData};
    use crate::scene::graph::{NodeError, NodeValue};
    use crate::scene::node::KeyError;
    use std::time::Duration;

    fn shown(value: Result<NodeValue, NodeError>, scene: &Arc<Scene>) -> Shown {
        Shown {
            result: Arc::new(NodeResult {
                value,
                wall: Duration::from_millis(3),
                accuracy: None,
            }),
            scene: scene.clone(),
            generation: 1,
            progress: Some(Steps {
                done: 1,
                total: 4,
                so_far: None,
            }),
        }
    }

    #[test]
    fn a_column_s_data_holds_each_node_s_data_error_or_nothing_with_its_status() {
        let points = Arc::new(PointsData {
            points: vec![glam::DVec2::new(0.5, 0.25)],
            gpu: Arc::new(vec![[0.5, 0.25]]),
            version: 1,
            note: None,
        });
        let failed = NodeError::Key(KeyError {
            kind: "spectrum",
            message: "no key".into(),
        });
        let scene = Arc::new(Scene {
            n: 77,
            ..Scene::default()
        });
        let mut column = ColumnResults::new();
        column.insert(
            NodeKind::Points,
            shown(Ok(NodeValue::Points(points.clone())), &scene),
        );
        column.insert(NodeKind::Spectrum, shown(Err(failed), &scene));
        let data: ColumnData = crate::scene::figure::column_data(&column);
        let got = data.get::<PointsData>();
        assert!(Arc::ptr_eq(got.data().unwrap(), &points));
        let status = got.status().unwrap();
        assert_eq!(status.wall, Duration::from_millis(3));
        assert_eq!(status.progress.map(|p| (p.done, p.total)), Some((1, 4)));
        assert_eq!(scene_of(status).map(|s| s.n), Some(77));
        // A failed node: its error in the plain data, with its status.
        let spectrum = data.get::<SpectrumData>();
        assert!(spectrum.data().is_none());
        assert!(spectrum.error().unwrap().contains("no key"));
        assert!(spectrum.status().is_some());
        assert!(data.get::<StatsData>().status().is_none());
        // Every node's status in the node table's order, for the cost view.
        assert_eq!(data.nodes.len(), NodeKind::ALL.len());
        let with_result: Vec<&str> = data
            .nodes
            .iter()
            .filter_map(|n| n.status.as_ref().map(|_| n.name))
            .collect();
        assert_eq!(with_result, vec!["points", "spectrum"]);
    }
}
