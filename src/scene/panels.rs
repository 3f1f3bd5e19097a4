//! The panel table: one row per panel ([`PANELS`]) saying its switch in the scene
//! ([`Panels`]), where the GUI places it, the figures it saves and the nodes it reads, each
//! with the condition (an effect, column 0) under which it is wanted. Everything else derives
//! from it: the node table's `shown` rule ([`asks_for`], read by `graph::column_plan`), the
//! figures `samplescope render` writes ([`available_in`]), the composites, the GUI's panels
//! (shown when [`PanelKind::is_shown`]) and their Save menus ([`PanelSpec::figures`]).
//!
//! One rule, one place: a panel is shown when its switch is on (the cost panel's per-node
//! table needs no effect); a figure of a shown panel is listed, and a node of a shown panel
//! computed, when its own condition holds (the convergence figure and node need the
//! convergence effect, the zone plate's reference and error the error effect).

use super::graph::NodeKind;
use super::Scene;
use crate::model::FigureKind;
use serde::{Deserialize, Serialize};

/// Which panels are visible: one switch per row of [`PANELS`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Panels {
    pub pattern: bool,
    pub spectrum: bool,
    pub zoneplate: bool,
    pub filter: bool,
    /// The cost view (every node's time and error, and the convergence plot).
    pub cost: bool,
    /// The 1D sampling-theorem view (signal, replicas, filter, pre-/post-aliasing).
    pub theorem: bool,
    /// The integration-error study: MSE of the Monte Carlo estimate against N, every column
    /// on one log–log plot.
    pub integration: bool,
    /// The points wrapped onto the sphere (the lecture's cylinder wrap and radial projection).
    pub sphere: bool,
}

impl Default for Panels {
    fn default() -> Self {
        Panels {
            pattern: true,
            spectrum: true,
            zoneplate: true,
            filter: true,
            cost: false,
            theorem: false,
            integration: false,
            sphere: false,
        }
    }
}

/// One of the panels (a row of [`PANELS`], in the GUI's order).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum PanelKind {
    Pattern,
    Sphere,
    Spectrum,
    ZonePlate,
    Filter,
    Cost,
    Integration,
    Theorem,
}

/// Where the GUI places a panel.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Place {
    /// In every column's grid, in table order.
    Column,
    /// Docked below the columns (one for the whole scene), in table order.
    Dock,
}

/// When a figure or node of a shown panel is wanted in column `c` of the scene.
pub type Need = fn(&Scene, usize) -> bool;

/// Always (while the panel is shown).
fn always(_: &Scene, _: usize) -> bool {
    true
}

/// Column 0 only (the data does not depend on the column).
fn column_zero(_: &Scene, c: usize) -> bool {
    c == 0
}

fn statistics(s: &Scene, _: usize) -> bool {
    s.effects.statistics
}

fn reconstruction(s: &Scene, _: usize) -> bool {
    s.effects.reconstruction
}

fn reconstruction_and_error(s: &Scene, _: usize) -> bool {
    s.effects.reconstruction && s.effects.error
}

fn convergence(s: &Scene, _: usize) -> bool {
    s.effects.convergence
}

/// One row of the panel table.
pub struct PanelSpec {
    pub kind: PanelKind,
    /// Its name (the scene's switch, in menus).
    pub name: &'static str,
    /// Its switch in the scene's [`Panels`].
    pub switch: fn(&mut Panels) -> &mut bool,
    /// Where the GUI places it.
    pub place: Place,
    /// The figures it saves (its Save menu, in this order), each with when it is available.
    pub figures: &'static [(FigureKind, Need)],
    /// The nodes it reads, each with when it asks for it (their inputs are added by the plan).
    pub nodes: &'static [(NodeKind, Need)],
}

/// The panel table, indexed by `PanelKind as usize`.
pub static PANELS: [PanelSpec; 8] = [
    PanelSpec {
        kind: PanelKind::Pattern,
        name: "pattern",
        switch: |p| &mut p.pattern,
        place: Place::Column,
        figures: &[(FigureKind::Pattern, always)],
        nodes: &[
            (NodeKind::Points, always),
            (NodeKind::Statistics, statistics),
        ],
    },
    PanelSpec {
        kind: PanelKind::Sphere,
        name: "sphere",
        switch: |p| &mut p.sphere,
        place: Place::Column,
        figures: &[(FigureKind::Sphere, always)],
        nodes: &[(NodeKind::Points, always)],
    },
    PanelSpec {
        kind: PanelKind::Spectrum,
        name: "spectrum",
        switch: |p| &mut p.spectrum,
        place: Place::Column,
        figures: &[(FigureKind::Spectrum, always), (FigureKind::Raps, always)],
        nodes: &[(NodeKind::Spectrum, always)],
    },
    PanelSpec {
        kind: PanelKind::ZonePlate,
        name: "zoneplate",
        switch: |p| &mut p.zoneplate,
        place: Place::Column,
        figures: &[
            (FigureKind::Reconstruction, reconstruction),
            (FigureKind::Reference, reconstruction_and_error),
            (FigureKind::Error, reconstruction_and_error),
        ],
        nodes: &[
            (NodeKind::Reconstruction, reconstruction),
            (NodeKind::Reference, reconstruction_and_error),
            (NodeKind::Error, reconstruction_and_error),
        ],
    },
    PanelSpec {
        kind: PanelKind::Filter,
        name: "filter",
        switch: |p| &mut p.filter,
        place: Place::Column,
        figures: &[(FigureKind::Kernel, always), (FigureKind::Response, always)],
        nodes: &[(NodeKind::Response, always)],
    },
    PanelSpec {
        kind: PanelKind::Cost,
        name: "cost",
        switch: |p| &mut p.cost,
        place: Place::Dock,
        figures: &[(FigureKind::Convergence, convergence)],
        nodes: &[(NodeKind::Convergence, convergence)],
    },
    PanelSpec {
        kind: PanelKind::Integration,
        name: "integration",
        switch: |p| &mut p.integration,
        place: Place::Dock,
        // One plot of every column's study: the figure is column 0's.
        figures: &[(FigureKind::Integration, column_zero)],
        nodes: &[(NodeKind::Integration, always)],
    },
    PanelSpec {
        kind: PanelKind::Theorem,
        name: "theorem",
        switch: |p| &mut p.theorem,
        place: Place::Dock,
        // The view does not depend on the column: computed and saved for column 0 only.
        figures: &[
            (FigureKind::TheoremSignal, column_zero),
            (FigureKind::TheoremSpectrum, column_zero),
            (FigureKind::TheoremReconstructed, column_zero),
            (FigureKind::TheoremPair, column_zero),
        ],
        nodes: &[(NodeKind::Theorem, column_zero)],
    },
];

impl PanelKind {
    /// Every panel, in table order.
    pub const ALL: [PanelKind; 8] = [
        PanelKind::Pattern,
        PanelKind::Sphere,
        PanelKind::Spectrum,
        PanelKind::ZonePlate,
        PanelKind::Filter,
        PanelKind::Cost,
        PanelKind::Integration,
        PanelKind::Theorem,
    ];

    /// This panel's row.
    pub fn spec(self) -> &'static PanelSpec {
        &PANELS[self as usize]
    }

    /// The panel that saves `figure`.
    pub fn of(figure: FigureKind) -> PanelKind {
        PanelKind::ALL
            .into_iter()
            .find(|p| p.spec().figures.iter().any(|&(f, _)| f == figure))
            .expect("every figure belongs to a panel (tested)")
    }

    /// Whether the scene shows this panel: its switch is on.
    pub fn is_shown(self, panels: &Panels) -> bool {
        let mut p = *panels;
        *(self.spec().switch)(&mut p)
    }
}

impl PanelSpec {
    /// The figures this panel saves, in its order.
    pub fn figure_kinds(&self) -> impl Iterator<Item = FigureKind> + '_ {
        self.figures.iter().map(|&(f, _)| f)
    }
}

/// Whether column `column` of `scene` shows `kind`: its panel is visible and the figure's
/// condition (effects, column 0) holds.
pub fn shows(scene: &Scene, column: usize, kind: FigureKind) -> bool {
    let panel = PanelKind::of(kind);
    panel.is_shown(&scene.panels)
        && panel
            .spec()
            .figures
            .iter()
            .any(|&(f, need)| f == kind && need(scene, column))
}

/// Whether a shown panel asks for node `kind` in column `column` (the node table's `shown`
/// rule; nodes that only feed others are added by the plan as inputs).
pub fn asks_for(scene: &Scene, column: usize, kind: NodeKind) -> bool {
    PANELS.iter().any(|p| {
        p.kind.is_shown(&scene.panels)
            && p.nodes
                .iter()
                .any(|&(n, need)| n == kind && need(scene, column))
    })
}

/// The figures column `column` has, in [`FigureKind::ALL`] order: what `render` writes for it.
pub fn available_in(scene: &Scene, column: usize) -> Vec<FigureKind> {
    FigureKind::ALL
        .into_iter()
        .filter(|&k| shows(scene, column, k))
        .collect()
}

/// The figures the scene computes (those of column 0, the theorem's included).
pub fn available(scene: &Scene) -> Vec<FigureKind> {
    available_in(scene, 0)
}

/// The figures of column `column`'s composite: the [`FigureKind::COMPOSITE`] kinds it shows.
pub fn composite_in(scene: &Scene, column: usize) -> Vec<FigureKind> {
    FigureKind::COMPOSITE
        .into_iter()
        .filter(|&k| shows(scene, column, k))
        .collect()
}

/// The figures of a column composite of the scene (column 0's, the theorem's included).
pub fn composite(scene: &Scene) -> Vec<FigureKind> {
    composite_in(scene, 0)
}

/// The figures of the comparison (every column one row, the same figures in each): the
/// composite figures every column has, so the theorem figures only when the scene has a
/// single column.
pub fn comparison(scene: &Scene) -> Vec<FigureKind> {
    let mut kinds = composite(scene);
    kinds.retain(|k| scene.columns.len() == 1 || !k.is_theorem());
    kinds
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_table_is_indexed_by_kind_and_every_figure_has_one_panel() {
        for (i, p) in PANELS.iter().enumerate() {
            assert_eq!(p.kind as usize, i, "{}", p.name);
            assert_eq!(PanelKind::ALL[i], p.kind);
        }
        for f in FigureKind::ALL {
            let owners = PANELS
                .iter()
                .filter(|p| p.figure_kinds().any(|g| g == f))
                .count();
            assert_eq!(owners, 1, "{} is saved by {owners} panels", f.name());
        }
        // Every node a panel reads is in the node table, and only `Samples` and `Psa`
        // (inputs of the reconstruction and the statistics) and the nodes `analyze` asks for
        // by name (`Rdf`, `NetPrefixes`) are asked for by no panel.
        for k in NodeKind::ALL {
            let readers = PANELS
                .iter()
                .filter(|p| p.nodes.iter().any(|&(n, _)| n == k))
                .count();
            let unread = matches!(
                k,
                NodeKind::Samples | NodeKind::Psa | NodeKind::Rdf | NodeKind::NetPrefixes
            );
            assert_eq!(readers == 0, unread, "{}", k.name());
        }
    }

    /// The node each figure draws, written out here independently of the table.
    fn drawn_from(f: FigureKind) -> NodeKind {
        match f {
            FigureKind::Pattern | FigureKind::Sphere => NodeKind::Points,
            FigureKind::Spectrum | FigureKind::Raps => NodeKind::Spectrum,
            FigureKind::Reconstruction => NodeKind::Reconstruction,
            FigureKind::Reference => NodeKind::Reference,
            FigureKind::Error => NodeKind::Error,
            FigureKind::Kernel | FigureKind::Response => NodeKind::Response,
            FigureKind::Convergence => NodeKind::Convergence,
            FigureKind::TheoremSignal
            | FigureKind::TheoremSpectrum
            | FigureKind::TheoremReconstructed
            | FigureKind::TheoremPair => NodeKind::Theorem,
            FigureKind::Integration => NodeKind::Integration,
        }
    }

    #[test]
    fn every_figure_render_writes_has_its_node_planned_for_every_switch_and_effect() {
        let mut scene = Scene {
            columns: vec![Default::default(), Default::default()],
            ..Default::default()
        };
        for bits in 0u32..1 << 12 {
            let on = |i: u32| bits & (1 << i) != 0;
            for (i, p) in PanelKind::ALL.into_iter().enumerate() {
                *(p.spec().switch)(&mut scene.panels) = on(i as u32);
            }
            scene.effects.reconstruction = on(8);
            scene.effects.error = on(9);
            scene.effects.convergence = on(10);
            scene.effects.statistics = on(11);
            for c in 0..2 {
                let planned: Vec<NodeKind> = super::super::graph::column_plan(&scene, c)
                    .nodes
                    .iter()
                    .map(|n| n.kind)
                    .collect();
                for f in available_in(&scene, c) {
                    let node = drawn_from(f);
                    assert!(planned.contains(&node), "{}: {bits:b}", f.name());
                }
                // And nothing is planned that no shown figure draws, but the nodes read
                // only by panels (statistics, and the inputs of what is drawn).
                for k in &planned {
                    let drawn = available_in(&scene, c).iter().any(|&f| drawn_from(f) == *k);
                    let input = matches!(k, NodeKind::Points | NodeKind::Samples | NodeKind::Psa);
                    let panel_only = *k == NodeKind::Statistics
                        || (*k == NodeKind::Integration && scene.panels.integration);
                    assert!(drawn || input || panel_only, "{}: {bits:b}", k.name());
                }
            }
        }
    }

    #[test]
    fn a_switch_shows_its_panel_alone() {
        for p in PanelKind::ALL {
            let mut panels = Panels {
                pattern: false,
                spectrum: false,
                zoneplate: false,
                filter: false,
                cost: false,
                theorem: false,
                integration: false,
                sphere: false,
            };
            *(p.spec().switch)(&mut panels) = true;
            for q in PanelKind::ALL {
                assert_eq!(
                    q.is_shown(&panels),
                    p == q,
                    "{} vs {}",
                    p.spec().name,
                    q.spec().name
                );
            }
        }
    }

    #[test]
    fn theorem_figures_belong_to_column_zero_and_single_column_comparisons() {
        let mut scene = Scene {
            columns: vec![Default::default(), Default::default()],
            ..Default::default()
        };
        scene.panels.theorem = true;
        assert!(available_in(&scene, 0).contains(&FigureKind::TheoremPair));
        assert!(!available_in(&scene, 1).iter().any(|k| k.is_theorem()));
        assert!(composite_in(&scene, 0).contains(&FigureKind::TheoremSignal));
        assert!(!composite(&scene).contains(&FigureKind::TheoremPair));
        assert!(!comparison(&scene).iter().any(|k| k.is_theorem()));
        scene.columns.truncate(1);
        assert!(comparison(&scene).contains(&FigureKind::TheoremSpectrum));
    }

    #[test]
    fn error_figures_need_the_reconstruction_and_error_effects() {
        let mut scene = Scene::default();
        assert!(shows(&scene, 0, FigureKind::Error));
        scene.effects.error = false;
        assert!(shows(&scene, 0, FigureKind::Reconstruction));
        assert!(!shows(&scene, 0, FigureKind::Reference));
        scene.effects.reconstruction = false;
        assert!(!shows(&scene, 0, FigureKind::Reconstruction));
    }

    #[test]
    fn the_cost_panel_shows_without_the_convergence_effect_but_its_figure_does_not() {
        let mut scene = Scene::default();
        scene.panels.cost = true;
        assert!(PanelKind::Cost.is_shown(&scene.panels));
        assert!(!shows(&scene, 0, FigureKind::Convergence));
        assert!(!asks_for(&scene, 0, NodeKind::Convergence));
        scene.effects.convergence = true;
        assert!(shows(&scene, 0, FigureKind::Convergence));
        assert!(asks_for(&scene, 0, NodeKind::Convergence));
    }
}
