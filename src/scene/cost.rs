//! The estimated cost of a scene: what its shown nodes compute, before any of it runs.
//!
//! [`estimate`] walks the scene's plan ([`graph::plan`]: the nodes its visible panels and
//! effects need, with their inputs; [`estimate_plan`] takes a plan already made, the one the
//! engine is then given) and gives one [`Estimate`] per node that will be
//! evaluated, in plan order; nodes with the same key in several columns are one job and are
//! counted once, and nodes without a key (they report an error instead of running) not at
//! all. [`check`] refuses a scene beyond a [`Budget`]; `samplescope render` calls it before
//! evaluating, and the GUI can call it before submitting a scene.

use super::graph::{self, NodeKind, Plan};
use super::Scene;
use crate::core::budget::{Budget, Estimate, OverBudget};
use std::collections::HashSet;

/// The estimates of every node the scene will evaluate (see the module docs).
pub fn estimate(scene: &Scene) -> Vec<Estimate> {
    estimate_plan(scene, &graph::plan(scene))
}

/// [`estimate`] of the scene's plan `plan` (`graph::plan(scene)`, made once by the caller, who
/// hands the same plan to the engine).
pub fn estimate_plan(scene: &Scene, plan: &Plan) -> Vec<Estimate> {
    estimate_frames(&[(scene, plan)])
}

/// [`estimate_plan`] of several scenes evaluated one after another on one cache (the frames
/// of an animation, `scene::animation`): a node whose key an earlier frame computed is counted
/// once.
pub fn estimate_frames(frames: &[(&Scene, &Plan)]) -> Vec<Estimate> {
    let mut seen = HashSet::new();
    let mut out = Vec::new();
    for (scene, plan) in frames {
        for (c, plan) in plan.iter().enumerate() {
            for node in &plan.nodes {
                let Ok(key) = node.key else { continue };
                if seen.insert(key) {
                    out.extend(node_estimate(scene, c, node.kind));
                }
            }
        }
    }
    out
}

/// Refuses the scene when [`estimate`] is beyond `budget` (the error names the costliest node
/// and the limit).
pub fn check(scene: &Scene, budget: &Budget) -> Result<(), OverBudget> {
    check_plan(scene, &graph::plan(scene), budget)
}

/// [`check`] of the scene's plan `plan`, made once by the caller.
pub fn check_plan(scene: &Scene, plan: &Plan, budget: &Budget) -> Result<(), OverBudget> {
    budget.check(&estimate_plan(scene, plan))
}

/// What node `kind` of column `c` computes (its file's estimate, as its job computes): the
/// estimates [`estimate`] lists for it.
pub fn node_estimate(scene: &Scene, c: usize, kind: NodeKind) -> Vec<Estimate> {
    if c >= scene.columns.len() {
        return Vec::new();
    }
    (kind.def().estimate)(scene, c)
}
