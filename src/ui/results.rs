//! The engine's results as the UI holds them: what is on screen per column, and the last
//! generation that finished. Plain data, shared by the app (which fills it) and the panels
//! (which draw it).

use crate::engine::{Progress, Update};
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
    /// `Some` while the node refines (a coarse result is on screen).
    pub progress: Option<Progress>,
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
