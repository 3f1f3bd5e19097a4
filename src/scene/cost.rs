//! The estimated cost of a scene: what its shown nodes compute, before any of it runs.
//!
//! [`estimate`] walks the scene's plan ([`graph::plan`]: the nodes its visible panels and
//! effects need, with their inputs; [`estimate_plan`] takes a plan already made, the one the
//! engine is then given) and gives one [`Estimate`] per node that will be
//! evaluated, in plan order; nodes with the same key in several columns are one job and are
//! counted once, and nodes without a key (they report an error instead of running) not at
//! all. [`check`] refuses a scene beyond a [`Budget`]; `samplescope render` calls it before
//! evaluating, and the GUI can call it before submitting a scene.

use super::compute::{CONVERGENCE_SIZE, CONVERGENCE_SPP, PREVIEW_DIVISOR, PREVIEW_SAMPLES};
use super::graph::{self, NodeKind, Plan};
use super::{ReconMode, Scene};
use crate::core::budget::{self, Budget, Estimate, OverBudget};
use std::collections::HashSet;

/// The estimates of every node the scene will evaluate (see the module docs).
pub fn estimate(scene: &Scene) -> Vec<Estimate> {
    estimate_plan(scene, &graph::plan(scene))
}

/// [`estimate`] of the scene's plan `plan` (`graph::plan(scene)`, made once by the caller, who
/// hands the same plan to the engine).
pub fn estimate_plan(scene: &Scene, plan: &Plan) -> Vec<Estimate> {
    let mut seen = HashSet::new();
    let mut out = Vec::new();
    for (c, plan) in plan.iter().enumerate() {
        for node in &plan.nodes {
            let Ok(key) = node.key else { continue };
            if seen.insert(key) {
                out.extend(node_estimates(scene, c, node.kind));
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

/// What node `kind` of column `c` computes (as the jobs of `compute` do).
fn node_estimates(scene: &Scene, c: usize, kind: NodeKind) -> Vec<Estimate> {
    let Some(col) = scene.columns.get(c) else {
        return Vec::new();
    };
    let imported = col.points.as_ref().map(|p| p.points.len());
    let n = imported.unwrap_or(scene.n);
    let w = scene.recon.size;
    let (signal, filter) = (&scene.signal, &scene.filter);
    match kind {
        // Imported points are copied, not generated.
        NodeKind::Points => match imported {
            Some(_) => Vec::new(),
            None => vec![budget::pattern(&col.pattern, scene.n)],
        },
        // PSA's statistics are their own node (an input of the statistics for small N).
        NodeKind::Statistics => vec![budget::statistics(n)],
        NodeKind::Psa => vec![budget::psa_statistics(n)],
        NodeKind::Rdf => vec![budget::rdf(
            n,
            crate::core::metrics::psa::psa_rdf_range(n).0,
        )],
        NodeKind::NetPrefixes => vec![budget::net_prefixes(n)],
        NodeKind::Spectrum => {
            let req = scene.spectrum.request(n, imported.is_some());
            let generator = imported.is_none().then_some(&col.pattern);
            vec![budget::spectrum(&req, n, generator)]
        }
        NodeKind::Samples => vec![budget::sampling(signal, n)],
        NodeKind::Reconstruction => match scene.recon.mode {
            ReconMode::Scattered => vec![budget::scattered(n, w, filter)],
            ReconMode::Resample { grid } => vec![budget::resample(signal, grid, w, filter)],
            ReconMode::Supersample { spp } => {
                let mut v = Vec::new();
                let preview = spp / PREVIEW_DIVISOR;
                if preview >= 1 && w * w * spp > PREVIEW_SAMPLES {
                    v.push(budget::supersampling(
                        signal,
                        w,
                        preview,
                        &col.pattern,
                        filter,
                    ));
                }
                v.push(budget::supersampling(signal, w, spp, &col.pattern, filter));
                if let crate::scene::PixelSampling::ImagePlane { tile } = col.pixels {
                    // One pattern of s·T² points over the tile, generated once.
                    let t = if tile == 0 { w } else { tile };
                    v.push(budget::pattern(&col.pattern, spp.saturating_mul(t * t)));
                }
                v
            }
        },
        NodeKind::Reference => vec![budget::reference(signal, w)],
        NodeKind::Error => vec![budget::error_image(w)],
        NodeKind::Response => vec![budget::filter_metrics(filter)],
        NodeKind::Convergence => vec![budget::convergence(
            signal,
            &col.pattern,
            &CONVERGENCE_SPP,
            CONVERGENCE_SIZE,
            filter,
        )],
        NodeKind::Theorem => vec![budget::theorem()],
        // Imported points report an error instead of running.
        NodeKind::Integration => match imported {
            Some(_) => Vec::new(),
            None => crate::core::integration::estimate(
                &scene.integration.request(col.pattern, col.seed),
            ),
        },
    }
}
