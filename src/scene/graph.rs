//! The compute graph: a node table, stable keys and the per-column plan.
//!
//! ```text
//! Points(pattern, n, seed) ─┬─> Spectrum(points; size, tolerance, realizations)
//!                           ├─> Psa(points) ─> Statistics(points; PSA for N ≤ 8192)
//!                           ├─> Rdf(points), NetPrefixes(points)   (asked by `analyze`)
//!                           └─> Samples(points; signal) ─> Reconstruction(filter, size) ─┐
//!                                             Reference(signal, size) ─────────────────> Error
//! Filter ─> Response         Convergence(pattern, seed, signal, filter)    Theorem(settings)
//! Integration(pattern, seed, integration settings)
//! With a prefix k: Sequence(pattern, n, seed) ─> Points(sequence; k), the first k of the run.
//! ```
//!
//! Every node kind has **one entry** in [`NODES`], expanded from the node list
//! (`compute::node_list!`): which other nodes and which scene fields it reads
//! ([`NodeDef::inputs`]), the job that computes it ([`NodeDef::run`]) and its estimate
//! ([`NodeDef::estimate`]), all three in its file in `compute/`; which panels ask for it, and
//! under which effects, is their entry in the panel list ([`panels::PANELS`], asked through
//! [`panels::asks_for`]). [`plan`] derives, per column, the nodes to compute (those a shown
//! panel asks for plus their inputs, transitively), in dependency order, with their keys; the
//! job of a node gets exactly the results of the inputs it declared. Adding a node is its file
//! in `compute/` and its entry in the node list. A front that needs nodes no panel reads
//! (`samplescope analyze`: the RDF, the net check) asks for them by name ([`plan_asking`]).
//!
//! **Keys.** A node's key is the BLAKE3 hash of its kind, its algorithm's version
//! ([`NodeKind::version`]), the RON text of the scene fields it reads (every field and float bit; streamed into the hasher, never shared by default) and
//! the keys of its input nodes; a change therefore invalidates exactly its dependents, two
//! columns with equal inputs share one key (one evaluation), and keys are stable across runs,
//! builds and platforms (the on-disk cache relies on it). A field that cannot be serialised
//! makes no key: the node (and its dependents) reports that error instead of running.

use super::compute;
use super::node::Output;
use super::{panels, Scene};
use crate::core::budget::Estimate;

pub use super::node::{
    key_of, Inputs, JobCtx, KeyError, NodeError, NodeKey, NodeKind, NodeResult, NodeValue, Partial,
};

impl NodeKind {
    /// This kind's entry in the node table.
    pub fn def(self) -> &'static NodeDef {
        &NODES[self as usize]
    }
}

/// One row of the node table: what the node's file in `compute/` declares.
pub struct NodeDef {
    pub kind: NodeKind,
    /// The input nodes and scene fields of this node in column `c` of the scene.
    pub inputs: fn(&Scene, usize) -> Inputs,
    /// The job: computes the value from the scene, the column and the declared inputs.
    pub run: fn(&JobCtx) -> Output,
    /// What it computes in column `c` of the scene (the budget's estimate, `scene::cost`).
    pub estimate: fn(&Scene, usize) -> Vec<Estimate>,
    /// Whether its result is worth keeping on disk across runs (slow, plain-image results).
    pub disk_cached: bool,
}

/// Expands the node list (`compute::node_list!`) into [`NODES`].
macro_rules! node_table {
    (
        kinds: $kinds:tt
        table: [$($kind:ident $file:ident $disk:literal;)*]
        $($rest:tt)*
    ) => {
        /// The node table, indexed by `NodeKind as usize`.
        pub static NODES: [NodeDef; NodeKind::ALL.len()] = [$(
            NodeDef {
                kind: NodeKind::$kind,
                inputs: compute::$file::inputs,
                run: compute::$file::run,
                estimate: compute::$file::estimate,
                disk_cached: $disk,
            },
        )*];
    };
}

compute::node_list!(node_table);

/// One node of a column's plan.
#[derive(Debug, Clone, PartialEq)]
pub struct PlannedNode {
    pub kind: NodeKind,
    /// Its key, or why none could be made (then it is reported as that error, never run).
    pub key: Result<NodeKey, KeyError>,
    /// Its input nodes (kind and key), as declared by the table.
    pub deps: Vec<(NodeKind, NodeKey)>,
}

/// The nodes one column needs, in dependency order.
#[derive(Debug, Clone, PartialEq)]
pub struct ColumnPlan {
    pub nodes: Vec<PlannedNode>,
}

impl ColumnPlan {
    /// The keys of the nodes that have one.
    pub fn keys(&self) -> impl Iterator<Item = NodeKey> + '_ {
        self.nodes
            .iter()
            .filter_map(|n| n.key.as_ref().ok().copied())
    }
}

/// The plan of column `c`: the nodes the scene shows plus their inputs, transitively, in
/// dependency order, each with its key.
pub fn column_plan(scene: &Scene, c: usize) -> ColumnPlan {
    column_plan_asking(scene, c, &[])
}

/// [`column_plan`] with the nodes `also` wanted besides those the scene shows (a front that
/// reads nodes no panel reads: `samplescope analyze`).
pub fn column_plan_asking(scene: &Scene, c: usize, also: &[NodeKind]) -> ColumnPlan {
    let inputs: Vec<Inputs> = NODES.iter().map(|d| (d.inputs)(scene, c)).collect();
    // Wanted: shown, or an input of a wanted node (inputs come earlier in NodeKind order).
    let mut wanted = [false; NodeKind::ALL.len()];
    for d in NODES.iter().rev() {
        let i = d.kind as usize;
        if panels::asks_for(scene, c, d.kind) || also.contains(&d.kind) || wanted[i] {
            wanted[i] = true;
            for k in &inputs[i].nodes {
                debug_assert!((*k as usize) < i, "inputs come first in NodeKind order");
                wanted[*k as usize] = true;
            }
        }
    }
    let mut keys: [Option<Result<NodeKey, KeyError>>; NodeKind::ALL.len()] = Default::default();
    let mut nodes = Vec::new();
    for kind in NodeKind::ALL {
        let i = kind as usize;
        if !wanted[i] {
            continue;
        }
        let mut deps = Vec::new();
        let mut failed = None;
        for &k in &inputs[i].nodes {
            match &keys[k as usize] {
                Some(Ok(key)) => deps.push((k, *key)),
                Some(Err(e)) => failed = Some(e.clone()),
                None => {
                    failed = Some(KeyError {
                        kind: kind.name(),
                        message: format!("input {} is not planned", k.name()),
                    })
                }
            }
        }
        let dep_keys: Vec<NodeKey> = deps.iter().map(|(_, k)| *k).collect();
        let key = match failed {
            Some(e) => Err(e),
            None => inputs[i].key(&dep_keys),
        };
        keys[i] = Some(key.clone());
        nodes.push(PlannedNode { kind, key, deps });
    }
    ColumnPlan { nodes }
}

/// A scene's plan: every column's [`ColumnPlan`], in column order. The GUI and `render` make
/// it once per change and hand it both to the cost estimate (`cost::estimate_plan`) and to the
/// engine (`Engine::submit_planned`, `Evaluator::evaluate_planned`).
pub type Plan = Vec<ColumnPlan>;

/// Lists, per column, the nodes that the scene's visible panels and effects need.
pub fn plan(scene: &Scene) -> Plan {
    plan_asking(scene, &[])
}

/// [`plan`] with the nodes `also` wanted in every column besides those the scene shows
/// ([`column_plan_asking`]).
pub fn plan_asking(scene: &Scene, also: &[NodeKind]) -> Plan {
    (0..scene.columns.len())
        .map(|c| column_plan_asking(scene, c, also))
        .collect()
}
