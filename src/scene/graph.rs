//! The compute graph: nodes keyed by a hash of their inputs, cached, evaluated on demand.
//!
//! ```text
//! Points(pattern, n, seed) ─┬─> Spectrum(points, size, tolerance, realizations)
//!                           ├─> Statistics(points)
//!                           └─> Samples(points, signal) ─> Reconstruction(filter, size) ─┐
//!                                             Reference(signal, size) ─────────────────> Error
//! Filter ─> Response
//! ```
//!
//! [`plan`] lists, for each column, the nodes that the visible panels and the effects that are
//! on need; a hidden panel or an effect that is off adds no node. A node's key hashes its own
//! parameters and its inputs' keys, so a change invalidates exactly its dependents, and two
//! columns with equal inputs share one evaluation. [`Evaluator`] counts evaluations per node
//! kind so tests can check what was (not) computed.

use super::Scene;
use crate::core::cancel::Cancel;
use serde::Serialize;
use std::collections::HashMap;
use std::hash::{Hash, Hasher};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

pub use super::compute::{
    column_nodes, ConvergencePoint, ErrorData, ImageData, Job, NodeValue, PointsData, ReconData,
    ReferenceData, ResponseData, SpectrumData, StatsData,
};

/// The kinds of node.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
pub enum NodeKind {
    Points,
    Statistics,
    Spectrum,
    Samples,
    Reconstruction,
    Reference,
    Error,
    Response,
    Convergence,
    /// The 1D sampling-theorem view (column-independent: computed for column 0 only).
    Theorem,
}

impl NodeKind {
    /// Every kind, in evaluation order.
    pub const ALL: [NodeKind; 10] = [
        NodeKind::Points,
        NodeKind::Statistics,
        NodeKind::Spectrum,
        NodeKind::Samples,
        NodeKind::Reconstruction,
        NodeKind::Reference,
        NodeKind::Error,
        NodeKind::Response,
        NodeKind::Convergence,
        NodeKind::Theorem,
    ];

    /// Display name.
    pub fn name(self) -> &'static str {
        match self {
            NodeKind::Points => "points",
            NodeKind::Statistics => "statistics",
            NodeKind::Spectrum => "spectrum",
            NodeKind::Samples => "samples",
            NodeKind::Reconstruction => "reconstruction",
            NodeKind::Reference => "reference",
            NodeKind::Error => "error",
            NodeKind::Response => "filter response",
            NodeKind::Convergence => "convergence",
            NodeKind::Theorem => "sampling theorem",
        }
    }
}

/// A node's identity: its kind and a hash of everything it depends on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct NodeKey {
    pub kind: NodeKind,
    pub hash: u64,
}

/// Hashes `inputs` (through their RON text, which covers every field and float bit) with the
/// keys of the nodes they depend on.
pub fn key_of(kind: NodeKind, inputs: &impl Serialize, deps: &[NodeKey]) -> NodeKey {
    let mut h = std::collections::hash_map::DefaultHasher::new();
    kind.hash(&mut h);
    ron::to_string(inputs).unwrap_or_default().hash(&mut h);
    for d in deps {
        d.hash(&mut h);
    }
    NodeKey {
        kind,
        hash: h.finish(),
    }
}

/// A node's result: its value or the error that stopped it, what it cost, and its accuracy.
#[derive(Debug, Clone)]
pub struct NodeResult {
    pub value: Result<NodeValue, String>,
    /// Wall time of this evaluation (of the original evaluation for cache hits).
    pub wall: Duration,
    /// Accuracy reached, where defined (e.g. "rel. ℓ2 error 3.1e-8 (asked 1e-6)").
    pub accuracy: Option<String>,
}

/// The nodes one column needs, in dependency order.
#[derive(Debug, Clone, PartialEq)]
pub struct ColumnPlan {
    pub nodes: Vec<NodeKey>,
}

/// Lists, per column, the nodes that the scene's visible panels and effects need.
pub fn plan(scene: &Scene) -> Vec<ColumnPlan> {
    (0..scene.columns.len())
        .map(|c| ColumnPlan {
            nodes: column_nodes(scene, c).into_iter().map(|(k, _)| k).collect(),
        })
        .collect()
}

/// Evaluation counters and the node cache.
#[derive(Default)]
pub struct Evaluator {
    cache: Mutex<HashMap<NodeKey, (Arc<NodeResult>, u64)>>,
    counts: [AtomicUsize; NodeKind::ALL.len()],
    tick: AtomicUsize,
}

/// How many cached results are kept beyond those of the latest scene.
const CACHE_EXTRA: usize = 48;

impl Evaluator {
    /// How many times nodes of `kind` were evaluated (cache hits do not count).
    pub fn count(&self, kind: NodeKind) -> usize {
        self.counts[kind as usize].load(Ordering::Relaxed)
    }

    /// Every counter, by kind.
    pub fn counts(&self) -> Vec<(NodeKind, usize)> {
        NodeKind::ALL.iter().map(|&k| (k, self.count(k))).collect()
    }

    /// Resets every counter to zero.
    pub fn reset_counts(&self) {
        for c in &self.counts {
            c.store(0, Ordering::Relaxed);
        }
    }

    /// A cached result, if any.
    pub fn cached(&self, key: &NodeKey) -> Option<Arc<NodeResult>> {
        let cache = self.cache.lock().ok()?;
        cache.get(key).map(|(r, _)| r.clone())
    }

    /// Evaluates every node the scene needs, column by column, calling `sink` with each result
    /// (cached or fresh). Stops early, without caching partial results, when `cancel` fires.
    pub fn evaluate(
        &self,
        scene: &Scene,
        cancel: &Cancel,
        sink: &mut dyn FnMut(usize, NodeKind, Arc<NodeResult>),
    ) {
        let tick = self.tick.fetch_add(1, Ordering::Relaxed) as u64 + 1;
        for column in 0..scene.columns.len() {
            let mut done: HashMap<NodeKind, Arc<NodeResult>> = HashMap::new();
            for (key, job) in column_nodes(scene, column) {
                if cancel.is_cancelled() {
                    return;
                }
                let result = match self.lookup(&key, tick) {
                    Some(r) => r,
                    None => {
                        let start = Instant::now();
                        let outcome =
                            std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
                                job.run(scene, column, &done, cancel)
                            }));
                        if cancel.is_cancelled() {
                            return;
                        }
                        self.counts[key.kind as usize].fetch_add(1, Ordering::Relaxed);
                        let (value, accuracy) = match outcome {
                            Ok(Ok((v, acc))) => (Ok(v), acc),
                            Ok(Err(e)) => (Err(e), None),
                            Err(panic) => (Err(panic_message(panic)), None),
                        };
                        let r = Arc::new(NodeResult {
                            value,
                            wall: start.elapsed(),
                            accuracy,
                        });
                        if let Ok(mut cache) = self.cache.lock() {
                            cache.insert(key, (r.clone(), tick));
                        }
                        r
                    }
                };
                done.insert(key.kind, result.clone());
                sink(column, key.kind, result);
            }
        }
        self.trim(tick);
    }

    fn lookup(&self, key: &NodeKey, tick: u64) -> Option<Arc<NodeResult>> {
        let mut cache = self.cache.lock().ok()?;
        let entry = cache.get_mut(key)?;
        entry.1 = tick;
        Some(entry.0.clone())
    }

    fn trim(&self, tick: u64) {
        if let Ok(mut cache) = self.cache.lock() {
            let mut old: Vec<(NodeKey, u64)> = cache
                .iter()
                .filter(|(_, (_, t))| *t < tick)
                .map(|(k, (_, t))| (*k, *t))
                .collect();
            if old.len() > CACHE_EXTRA {
                old.sort_by_key(|(_, t)| *t);
                for (k, _) in &old[..old.len() - CACHE_EXTRA] {
                    cache.remove(k);
                }
            }
        }
    }
}

fn panic_message(panic: Box<dyn std::any::Any + Send>) -> String {
    let text = panic
        .downcast_ref::<String>()
        .cloned()
        .or_else(|| panic.downcast_ref::<&str>().map(|s| s.to_string()))
        .unwrap_or_else(|| "unknown panic".into());
    format!("internal error (panic): {text}")
}
