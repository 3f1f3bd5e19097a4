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
//! ```
//!
//! Every node kind has **one entry** in [`NODES`]: which other nodes and which scene fields it
//! reads ([`NodeDef::inputs`]), and the job that computes it ([`NodeDef::run`]); which panels
//! ask for it, and under which effects, is their row of the panel table
//! ([`panels::PANELS`], asked through [`panels::asks_for`]). [`plan`] derives, per column, the
//! nodes to compute (those a shown panel asks for plus their inputs, transitively), in
//! dependency order, with their keys; the job of a node gets exactly the results of the inputs
//! it declared. Adding a node is one table entry and one job function. A front that needs
//! nodes no panel reads (`samplescope analyze`: the RDF, the net check) asks for them by name
//! ([`plan_asking`]).
//!
//! **Keys.** A node's key is the BLAKE3 hash of its kind, its algorithm's version
//! ([`NodeDef::version`]), the RON text of the scene fields it reads (every field and float bit; streamed into the hasher, never shared by default) and
//! the keys of its input nodes; a change therefore invalidates exactly its dependents, two
//! columns with equal inputs share one key (one evaluation), and keys are stable across runs,
//! builds and platforms (the on-disk cache relies on it). A field that cannot be serialised
//! makes no key: the node (and its dependents) reports that error instead of running.

use super::compute;
use super::node::Output;
use super::{panels, ReconMode, Scene};
use serde::Serialize;

pub use super::node::{
    JobCtx, KeyError, NodeError, NodeKey, NodeKind, NodeResult, NodeValue, Partial,
};

/// A `fmt::Write` that feeds BLAKE3 (RON text is streamed, never built in memory).
struct HashWriter(blake3::Hasher);

impl std::fmt::Write for HashWriter {
    fn write_str(&mut self, s: &str) -> std::fmt::Result {
        self.0.update(s.as_bytes());
        Ok(())
    }
}

/// A hasher fed with a node's kind and the RON text of its scene fields.
fn fields_hasher(
    kind: NodeKind,
    fields: &(impl Serialize + ?Sized),
) -> Result<blake3::Hasher, KeyError> {
    let mut w = HashWriter(blake3::Hasher::new());
    w.0.update(b"samplescope-node-v1\0");
    w.0.update(kind.name().as_bytes());
    w.0.update(b"\0");
    w.0.update(&kind.def().version.to_le_bytes());
    ron::ser::to_writer(&mut w, fields).map_err(|e| KeyError {
        kind: kind.name(),
        message: e.to_string(),
    })?;
    w.0.update(b"\0");
    Ok(w.0)
}

fn finish_key(kind: NodeKind, mut h: blake3::Hasher, deps: &[NodeKey]) -> NodeKey {
    for d in deps {
        h.update(&d.hash);
    }
    NodeKey {
        kind,
        hash: *h.finalize().as_bytes(),
    }
}

/// The key of a `kind` node whose scene fields are `fields` and whose input nodes have `deps`.
pub fn key_of(
    kind: NodeKind,
    fields: &(impl Serialize + ?Sized),
    deps: &[NodeKey],
) -> Result<NodeKey, KeyError> {
    Ok(finish_key(kind, fields_hasher(kind, fields)?, deps))
}

/// What a node reads: the nodes it takes results from and its scene fields (hashed).
pub struct Inputs {
    pub nodes: Vec<NodeKind>,
    fields: Result<FieldsOf, KeyError>,
}

/// The scene fields of a node, already fed to the key's hasher.
struct FieldsOf {
    kind: NodeKind,
    hasher: blake3::Hasher,
}

impl Inputs {
    /// A `kind` node with input nodes `nodes` and scene fields `fields` (anything serialisable).
    pub fn new(kind: NodeKind, nodes: &[NodeKind], fields: impl Serialize) -> Self {
        Inputs {
            nodes: nodes.to_vec(),
            fields: fields_hasher(kind, &fields).map(|hasher| FieldsOf { kind, hasher }),
        }
    }

    fn key(&self, deps: &[NodeKey]) -> Result<NodeKey, KeyError> {
        match &self.fields {
            Ok(f) => Ok(finish_key(f.kind, f.hasher.clone(), deps)),
            Err(e) => Err(e.clone()),
        }
    }
}

impl NodeKind {
    /// This kind's entry in the node table.
    pub fn def(self) -> &'static NodeDef {
        &NODES[self as usize]
    }
}

/// One row of the node table.
pub struct NodeDef {
    pub kind: NodeKind,
    /// The input nodes and scene fields of this node in column `c` of the scene.
    pub inputs: fn(&Scene, usize) -> Inputs,
    /// The job: computes the value from the scene, the column and the declared inputs.
    pub run: fn(&JobCtx) -> Output,
    /// Whether its result is worth keeping on disk across runs (slow, plain-image results).
    pub disk_cached: bool,
    /// The version of the job's algorithm, part of the key: bump it whenever the job computes
    /// different numbers for the same inputs, so that no cache (the disk cache above all)
    /// serves results of the old algorithm.
    pub version: u32,
}

/// The node table, indexed by `NodeKind as usize`.
pub static NODES: [NodeDef; 14] = [
    NodeDef {
        kind: NodeKind::Points,
        inputs: |s, c| {
            let col = &s.columns[c];
            match &col.points {
                // Imported points are keyed by their bits, a pattern by its parameters, N, seed.
                Some(p) => Inputs::new(NodeKind::Points, &[], ("imported", p.content_digest())),
                None => Inputs::new(NodeKind::Points, &[], (&col.pattern, s.n, col.seed)),
            }
        },
        run: compute::points,
        disk_cached: false,
        version: 1,
    },
    NodeDef {
        kind: NodeKind::Psa,
        inputs: |_, _| Inputs::new(NodeKind::Psa, &[NodeKind::Points], ()),
        run: compute::psa,
        disk_cached: false,
        version: 1,
    },
    NodeDef {
        kind: NodeKind::Statistics,
        // PSA's statistics are part of the overlay's for N ≤ STATS_PSA_MAX_N (their node is
        // then an input); the column's N is known before its points are.
        inputs: |s, c| {
            let n = s.columns[c].points.as_ref().map_or(s.n, |p| p.points.len());
            let psa =
                (crate::core::metrics::PSA_MIN_N..=crate::model::STATS_PSA_MAX_N).contains(&n);
            let nodes: &[NodeKind] = if psa {
                &[NodeKind::Points, NodeKind::Psa]
            } else {
                &[NodeKind::Points]
            };
            Inputs::new(NodeKind::Statistics, nodes, ())
        },
        run: compute::statistics,
        disk_cached: false,
        version: 1,
    },
    NodeDef {
        kind: NodeKind::Spectrum,
        // Realization 0 is the points node's set; realizations r > 0 are generated from the
        // pattern (an imported file has one realization: K does not matter, see `import`).
        inputs: |s, c| {
            let col = &s.columns[c];
            let sp = s.spectrum;
            match &col.points {
                Some(_) => Inputs::new(
                    NodeKind::Spectrum,
                    &[NodeKind::Points],
                    (sp.size, sp.tolerance, sp.exact, sp.mask_dc),
                ),
                None => Inputs::new(
                    NodeKind::Spectrum,
                    &[NodeKind::Points],
                    (&col.pattern, s.n, col.seed, sp),
                ),
            }
        },
        run: compute::spectrum,
        disk_cached: false,
        version: 1,
    },
    NodeDef {
        kind: NodeKind::Samples,
        inputs: |s, _| Inputs::new(NodeKind::Samples, &[NodeKind::Points], s.signal),
        run: compute::samples,
        disk_cached: false,
        version: 1,
    },
    NodeDef {
        kind: NodeKind::Reconstruction,
        inputs: |s, c| {
            let col = &s.columns[c];
            let (f, w) = (&s.filter, s.recon.size);
            match s.recon.mode {
                ReconMode::Scattered => Inputs::new(
                    NodeKind::Reconstruction,
                    &[NodeKind::Points, NodeKind::Samples],
                    (f, w),
                ),
                ReconMode::Resample { grid } => {
                    Inputs::new(NodeKind::Reconstruction, &[], (grid, &s.signal, f, w))
                }
                ReconMode::Supersample { spp } => Inputs::new(
                    NodeKind::Reconstruction,
                    &[],
                    (&col.pattern, col.seed, spp, &s.signal, f, w, col.pixels),
                ),
            }
        },
        run: compute::reconstruction,
        disk_cached: false,
        version: 1,
    },
    NodeDef {
        kind: NodeKind::Reference,
        inputs: |s, _| Inputs::new(NodeKind::Reference, &[], (&s.signal, s.recon.size)),
        run: compute::reference,
        disk_cached: true,
        // 2: separable quadrature for the zone plate and the chirp.
        version: 2,
    },
    NodeDef {
        kind: NodeKind::Error,
        inputs: |_, _| {
            Inputs::new(
                NodeKind::Error,
                &[NodeKind::Reconstruction, NodeKind::Reference],
                (),
            )
        },
        run: compute::error,
        disk_cached: false,
        // 2: RMSE and PSNR over the f64 pixels (core's error report).
        version: 2,
    },
    NodeDef {
        kind: NodeKind::Response,
        inputs: |s, _| Inputs::new(NodeKind::Response, &[], s.filter),
        run: compute::response,
        disk_cached: false,
        version: 1,
    },
    NodeDef {
        kind: NodeKind::Convergence,
        inputs: |s, c| {
            let col = &s.columns[c];
            Inputs::new(
                NodeKind::Convergence,
                &[],
                (&col.pattern, col.seed, &s.signal, &s.filter),
            )
        },
        run: compute::convergence,
        disk_cached: false,
        version: 1,
    },
    NodeDef {
        kind: NodeKind::Theorem,
        // Column-independent: keyed by its settings alone (the theorem panel asks for it in
        // column 0 only).
        inputs: |s, _| Inputs::new(NodeKind::Theorem, &[], s.theorem),
        run: compute::theorem,
        disk_cached: false,
        version: 1,
    },
    NodeDef {
        kind: NodeKind::Integration,
        // Every column's curve goes on the one plot (whose figure belongs to column 0).
        inputs: |s, c| {
            let col = &s.columns[c];
            match &col.points {
                // Imported points have one N: the job reports that instead of running.
                Some(p) => {
                    Inputs::new(NodeKind::Integration, &[], ("imported", p.content_digest()))
                }
                None => Inputs::new(
                    NodeKind::Integration,
                    &[],
                    (&col.pattern, col.seed, &s.integration),
                ),
            }
        },
        run: compute::integration,
        disk_cached: false,
        version: 1,
    },
    NodeDef {
        kind: NodeKind::Rdf,
        inputs: |_, _| Inputs::new(NodeKind::Rdf, &[NodeKind::Points], ()),
        run: compute::rdf,
        disk_cached: false,
        version: 1,
    },
    NodeDef {
        kind: NodeKind::NetPrefixes,
        inputs: |_, _| Inputs::new(NodeKind::NetPrefixes, &[NodeKind::Points], ()),
        run: compute::net_prefixes,
        disk_cached: false,
        version: 1,
    },
];

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
