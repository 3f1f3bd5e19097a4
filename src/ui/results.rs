//! The engine's results as the UI holds them: what is on screen per column, and the last
//! generation that finished. Plain data, shared by the app (which fills it) and the panels
//! (which draw it). The one place the UI decodes the graph's `NodeValue`: a panel asks for the
//! plain `model` data it draws ([`slot`], `PanelCx::get`) and gets it with its status.

use crate::core::progress::Steps;
use crate::engine::Update;
use crate::model::{
    ConvergencePoint, ErrorData, IntegrationData, PointsData, ReconData, ReferenceData,
    ResponseData, SpectrumData, StatsData, TheoremView,
};
use crate::scene::graph::{NodeError, NodeKind, NodeResult, NodeValue};
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
    /// `Some` while the node refines (a coarse result is on screen).
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
    fn from(u: Update) -> Self {
        Shown {
            result: u.result,
            scene: u.scene,
            generation: u.generation,
            progress: u.progress,
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

/// A node's plain data type, and where it is among a column's results.
pub trait NodeData: 'static {
    /// The node that computes it.
    const KIND: NodeKind;
    /// The data, if `value` is this node's.
    fn of(value: &NodeValue) -> Option<&Arc<Self>>;
}

macro_rules! node_data {
    ($($t:ty => $kind:ident),* $(,)?) => {$(
        impl NodeData for $t {
            const KIND: NodeKind = NodeKind::$kind;
            fn of(value: &NodeValue) -> Option<&Arc<Self>> {
                match value {
                    NodeValue::$kind(d) => Some(d),
                    _ => None,
                }
            }
        }
    )*};
}

node_data! {
    PointsData => Points,
    StatsData => Statistics,
    SpectrumData => Spectrum,
    ReconData => Reconstruction,
    ReferenceData => Reference,
    ErrorData => Error,
    ResponseData => Response,
    Vec<ConvergencePoint> => Convergence,
    TheoremView => Theorem,
    IntegrationData => Integration,
}

/// What a panel finds for one node of a column.
pub enum Slot<'a, T> {
    /// Not computed (yet, or not asked for).
    Missing,
    /// The node failed: its result (wall time, scene) and the error.
    Failed(&'a Shown, &'a NodeError),
    /// Its data, with its result's status (a coarse one while `progress` is `Some`).
    Ready(&'a Shown, &'a Arc<T>),
}

impl<'a, T> Slot<'a, T> {
    /// The data, if there is any.
    pub fn data(&self) -> Option<&'a Arc<T>> {
        match self {
            Slot::Ready(_, d) => Some(d),
            _ => None,
        }
    }

    /// The node's error, if it failed.
    pub fn error(&self) -> Option<&'a NodeError> {
        match self {
            Slot::Failed(_, e) => Some(e),
            _ => None,
        }
    }

    /// The result (status and the scene it was computed for), failed or not.
    pub fn shown(&self) -> Option<&'a Shown> {
        match self {
            Slot::Ready(r, _) | Slot::Failed(r, _) => Some(r),
            Slot::Missing => None,
        }
    }
}

/// The `T` node of a column's results.
pub fn slot<T: NodeData>(column: &ColumnResults) -> Slot<'_, T> {
    let Some(r) = column.get(&T::KIND) else {
        return Slot::Missing;
    };
    match &r.value {
        Err(e) => Slot::Failed(r, e),
        Ok(v) => T::of(v).map_or(Slot::Missing, |d| Slot::Ready(r, d)),
    }
}

/// Every node's name, in the node table's order (the cost view's columns).
pub fn node_names() -> impl Iterator<Item = &'static str> {
    NodeKind::ALL.into_iter().map(|k| k.name())
}

/// Every node's result in a column (`None` where it has none), in [`node_names`]' order.
pub fn node_results(column: &ColumnResults) -> impl Iterator<Item = Option<&Shown>> {
    NodeKind::ALL.into_iter().map(|k| column.get(&k))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::node::KeyError;
    use std::time::Duration;

    fn shown(value: Result<NodeValue, NodeError>) -> Shown {
        Shown {
            result: Arc::new(NodeResult {
                value,
                wall: Duration::from_millis(3),
                accuracy: None,
            }),
            scene: Arc::new(Scene::default()),
            generation: 1,
            progress: None,
        }
    }

    #[test]
    fn a_slot_is_the_plain_data_its_error_or_missing() {
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
        let mut column = ColumnResults::new();
        column.insert(
            NodeKind::Points,
            shown(Ok(NodeValue::Points(points.clone()))),
        );
        column.insert(NodeKind::Spectrum, shown(Err(failed)));
        let got = slot::<PointsData>(&column);
        assert!(Arc::ptr_eq(got.data().unwrap(), &points));
        assert_eq!(got.shown().unwrap().wall, Duration::from_millis(3));
        let spectrum = slot::<SpectrumData>(&column);
        assert!(spectrum.data().is_none());
        assert!(spectrum.error().unwrap().to_string().contains("no key"));
        assert!(spectrum.shown().is_some());
        assert!(matches!(slot::<StatsData>(&column), Slot::Missing));
        let names: Vec<&str> = node_names().collect();
        assert_eq!(names.len(), node_results(&column).count());
        let with_result: Vec<&str> = node_names()
            .zip(node_results(&column))
            .filter_map(|(n, r)| r.map(|_| n))
            .collect();
        assert_eq!(with_result, vec!["points", "spectrum"]);
    }
}
