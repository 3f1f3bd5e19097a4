//! A node's data with its status, as panels and figures read it: ready (with its wall time,
//! accuracy, progress and the scene it was computed for), failed (with the error), or
//! missing.

use super::Accuracy;
use crate::core::progress::Steps;
use std::any::Any;
use std::sync::Arc;
use std::time::Duration;

/// What a node's result says beside its data.
#[derive(Clone, Default)]
pub struct NodeStatus {
    /// Wall time of its evaluation (of the original evaluation for a cached result).
    pub wall: Duration,
    /// The accuracy reached, where defined.
    pub accuracy: Option<Accuracy>,
    /// `Some` while the node refines (a coarse result is shown): the steps done of all.
    pub progress: Option<Steps>,
    /// What it was computed for: the scene snapshot where the holder keeps one (the GUI; the
    /// scene's type is above `model`, so it is held as `Any` and read back by its owner,
    /// `ui::results::scene_of`); `None` where nobody asks (`render`, the CLI's fronts).
    pub computed_for: Option<Arc<dyn Any + Send + Sync>>,
}

impl std::fmt::Debug for NodeStatus {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("NodeStatus")
            .field("wall", &self.wall)
            .field("accuracy", &self.accuracy)
            .field("progress", &self.progress.map(|p| (p.done, p.total)))
            .field("computed_for", &self.computed_for.is_some())
            .finish()
    }
}

/// One node's data in a column, with its status.
#[derive(Debug, Default)]
pub enum Slot<T> {
    /// Not computed (yet, or not asked for).
    #[default]
    Missing,
    /// The node failed: its status and the error's message.
    Failed { status: NodeStatus, error: String },
    /// Its data, with its status (a coarse one while `status.progress` is `Some`).
    Ready { status: NodeStatus, data: Arc<T> },
}

impl<T> Clone for Slot<T> {
    fn clone(&self) -> Self {
        match self {
            Slot::Missing => Slot::Missing,
            Slot::Failed { status, error } => Slot::Failed {
                status: status.clone(),
                error: error.clone(),
            },
            Slot::Ready { status, data } => Slot::Ready {
                status: status.clone(),
                data: data.clone(),
            },
        }
    }
}

impl<T> From<Arc<T>> for Slot<T> {
    /// Data ready, with no status to tell (a figure's data made by hand).
    fn from(data: Arc<T>) -> Self {
        Slot::Ready {
            status: NodeStatus::default(),
            data,
        }
    }
}

impl<T> Slot<T> {
    /// The data, if there is any.
    pub fn data(&self) -> Option<&Arc<T>> {
        match self {
            Slot::Ready { data, .. } => Some(data),
            _ => None,
        }
    }

    /// Whether there is data.
    pub fn is_ready(&self) -> bool {
        matches!(self, Slot::Ready { .. })
    }

    /// The node's error message, if it failed.
    pub fn error(&self) -> Option<&str> {
        match self {
            Slot::Failed { error, .. } => Some(error),
            _ => None,
        }
    }

    /// The status (time, accuracy, progress, what it was computed for), failed or not.
    pub fn status(&self) -> Option<&NodeStatus> {
        match self {
            Slot::Ready { status, .. } | Slot::Failed { status, .. } => Some(status),
            Slot::Missing => None,
        }
    }
}

/// One node's status in a column, by its name (the cost view's table: every node, in the
/// node table's order).
#[derive(Debug, Clone)]
pub struct NodeRow {
    /// The node's name.
    pub name: &'static str,
    /// Its status, `None` when it has no result.
    pub status: Option<NodeStatus>,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_slot_gives_its_data_error_and_status() {
        let ready: Slot<u32> = Slot::from(Arc::new(7));
        assert_eq!(ready.data().map(|d| **d), Some(7));
        assert!(ready.is_ready() && ready.error().is_none());
        assert_eq!(ready.status().unwrap().wall, Duration::ZERO);
        let failed: Slot<u32> = Slot::Failed {
            status: NodeStatus {
                wall: Duration::from_millis(3),
                ..Default::default()
            },
            error: "spectrum failed: no".into(),
        };
        assert!(failed.data().is_none() && !failed.is_ready());
        assert_eq!(failed.error(), Some("spectrum failed: no"));
        assert_eq!(failed.status().unwrap().wall, Duration::from_millis(3));
        let missing: Slot<u32> = Slot::default();
        assert!(missing.status().is_none() && missing.error().is_none());
    }
}
