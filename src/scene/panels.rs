//! The panel table: one entry per panel in [`panel_list!`], the one list of panels and of
//! the figures they save. An entry says the panel's switch in the scene ([`Panels`]), its
//! label, where the GUI places it, its GUI type, the figures it saves (each with its file
//! name, its drawing type, whether a composite holds it and when it is available) and the
//! nodes it reads (each with when it is wanted). Each layer expands the part it owns, so no
//! other list of panels or figures is written anywhere:
//!
//! - here, [`PanelKind`], [`PANELS`] (one [`PanelSpec`] row per panel) and the default
//!   [`Panels`]; from them the node table's `shown` rule ([`asks_for`], read by
//!   `graph::column_plan`), the figures `samplescope render` writes ([`available_in`]), the
//!   composites, the GUI's visibility ([`PanelKind::is_shown`]), its Panels checkboxes and its
//!   Save menus ([`PanelSpec::figures`]);
//! - `model::FigureKind` (the figures' identities, names, order and composite membership);
//! - `export::figure::figure`, the figure that draws each kind;
//! - `ui::panels::make`, the GUI panel of each row.
//!
//! Only names cross the layers: each expansion resolves the paths of its own layer (the GUI
//! type relative to `ui::panels`, the figure type relative to `export::figure`), so the
//! dependencies still point downwards.
//!
//! One rule, one place: a panel is shown when its switch is on (the cost panel's per-node
//! table needs no effect); a figure of a shown panel is listed, and a node of a shown panel
//! computed, when its own condition holds (the convergence figure and node need the
//! convergence effect, the zone plate's reference and error the error effect).

use super::graph::NodeKind;
use super::Scene;
use crate::model::FigureKind;
use serde::{Deserialize, Serialize};

/// The list of panels, in the GUI's order (the order of the Panels checkboxes, of the
/// column grid, of the docks from the bottom up, and of the figures `render` writes). It
/// calls `$then!` with one entry per panel:
///
/// ```text
/// /// doc of the panel
/// Kind {
///     switch: field,            // its bool in `Panels` (also its name in menus and files)
///     label: "…",               // its checkbox in the GUI's Panels section
///     place: Column | Dock,     // where the GUI places it
///     column_free: bool,        // its figures depend on no column (named without one)
///     gui: module::Type,        // its GUI panel, in `ui/panels/module.rs` (a `Default`)
///     figures: [                // the figures it saves, in its Save menu's order
///         /// doc of the figure
///         Kind { name: "…", when: condition, composite: bool, draw: module::Type },
///     ],
///     nodes: [(NodeKind, condition)],   // the nodes it reads (inputs are added by the plan)
/// }
/// ```
///
/// A condition is a [`Need`]: a function of the scene and the column (those below, or a
/// closure). A new panel is its entry here and its switch in [`Panels`], its GUI file
/// (`ui/panels/<name>.rs` with its `pub mod` line) and, for a new figure, the figure's file
/// (`export/figure/<name>.rs` with its `mod` line).
macro_rules! panel_list {
    ($then:path) => {
        $crate::scene::panels::panel_project! {
            $then;
            /// The points of each column, with their overlays and statistics.
            Pattern {
                switch: pattern,
                label: "Pattern",
                place: Column,
                column_free: false,
                gui: pattern::PatternPanel,
                figures: [
                    /// The points in the unit square.
                    Pattern { name: "pattern", when: always, composite: true, draw: pattern::Pattern },
                ],
                nodes: [(Points, always), (Statistics, statistics)],
            }
            /// The points wrapped onto the sphere (the lecture's cylinder wrap and radial
            /// projection).
            Sphere {
                switch: sphere,
                label: "Sphere",
                place: Column,
                column_free: false,
                gui: sphere::SpherePanel,
                figures: [
                    /// The points wrapped onto the sphere (cylinder wrap, radial projection):
                    /// front and back orthographic views.
                    Sphere { name: "sphere", when: always, composite: true, draw: sphere::Sphere },
                ],
                nodes: [(Points, always)],
            }
            /// The periodogram and its radial average.
            Spectrum {
                switch: spectrum,
                label: "Spectrum (F2)",
                place: Column,
                column_free: false,
                gui: spectrum::SpectrumPanel,
                figures: [
                    /// The periodogram image (log10 P through a colour map) with a colour bar.
                    Spectrum { name: "spectrum", when: always, composite: true, draw: spectrum::Spectrum },
                    /// The radially averaged power spectrum as a line plot.
                    Raps { name: "raps", when: always, composite: false, draw: raps::Raps },
                ],
                nodes: [(Spectrum, always)],
            }
            /// The zone plate sampled and reconstructed, its reference and the error.
            ZonePlate {
                switch: zoneplate,
                label: "Zone plate",
                place: Column,
                column_free: false,
                gui: zoneplate::ZonePlatePanel,
                figures: [
                    /// The reconstructed signal (grey, 0..1).
                    Reconstruction { name: "reconstruction", when: reconstruction, composite: true, draw: reconstruction::Reconstruction },
                    /// The reference image of the signal (grey, 0..1).
                    Reference { name: "reference", when: reconstruction_and_error, composite: false, draw: reference::Reference },
                    /// |reconstruction − reference| (inferno, 0..max) with a colour bar.
                    Error { name: "error", when: reconstruction_and_error, composite: false, draw: error::Error },
                ],
                nodes: [
                    (Reconstruction, reconstruction),
                    (Reference, reconstruction_and_error),
                    (Error, reconstruction_and_error),
                ],
            }
            /// The reconstruction filter: its kernel and frequency response.
            Filter {
                switch: filter,
                label: "Filter",
                place: Column,
                column_free: false,
                gui: filter::FilterPanel,
                figures: [
                    /// The filter kernel h(x).
                    Kernel { name: "kernel", when: always, composite: true, draw: kernel::Kernel },
                    /// The filter's frequency response |H(ω)| with the Nyquist line and the
                    /// ideal low-pass.
                    Response { name: "response", when: always, composite: true, draw: response::Response },
                ],
                nodes: [(Response, always)],
            }
            /// The cost view: every node's time and error, and the convergence plot.
            Cost {
                switch: cost,
                label: "Cost view (F4)",
                place: Dock,
                column_free: false,
                gui: cost::CostPanel,
                figures: [
                    /// RMSE against samples per pixel (log–log).
                    Convergence { name: "convergence", when: convergence, composite: false, draw: convergence::Convergence },
                ],
                nodes: [(Convergence, convergence)],
            }
            /// The 1D sampling theorem: signal, replicas, filter, pre- and post-aliasing. The
            /// view does not depend on the column: computed and saved for column 0 only.
            Theorem {
                switch: theorem,
                label: "Sampling theorem (1D)",
                place: Dock,
                column_free: true,
                gui: theorem::TheoremPanel,
                figures: [
                    /// The 1D sampling theorem: f(x), the samples f(nT) as stems and the
                    /// reconstruction f_r(x).
                    TheoremSignal { name: "theorem-signal", when: column_zero, composite: true, draw: theorem_signal::TheoremSignal },
                    /// The 1D sampling theorem: |F(ω)|, the replicas F(ω − k f_s) (one colour
                    /// per k), the filter's gain |G(ω)| and the Nyquist lines ±f_s/2, with a
                    /// legend beside the plot.
                    TheoremSpectrum { name: "theorem-spectrum", when: column_zero, composite: true, draw: theorem_spectrum::TheoremSpectrum },
                    /// The 1D sampling theorem: the reconstructed spectrum |F_r(ω)| against
                    /// |F(ω)|.
                    TheoremReconstructed { name: "theorem-reconstructed", when: column_zero, composite: true, draw: theorem_reconstructed::TheoremReconstructed },
                    /// The theorem panel's transform pair p(x) = g(a(x − s)) and its transform
                    /// P(ω) side by side (|P|, Re P and Im P; the shah as impulses).
                    TheoremPair { name: "theorem-pair", when: column_zero, composite: false, draw: theorem_pair::TheoremPair },
                ],
                nodes: [(Theorem, column_zero)],
            }
            /// The integration-error study: MSE of the Monte Carlo estimate against N, every
            /// column on one log–log plot.
            Integration {
                switch: integration,
                label: "Integration error",
                place: Dock,
                column_free: false,
                gui: integration::IntegrationPanel,
                figures: [
                    /// The integration-error study: MSE against N (log–log) of every column on
                    /// one plot, with standard-error bars, fitted slopes in the legend and
                    /// guide lines N⁻¹ … N⁻³ (column 0 only: the plot holds all columns).
                    Integration { name: "integration", when: column_zero, composite: false, draw: integration::Integration },
                ],
                nodes: [(Integration, always)],
            }
            /// The projection matrix: the first K dimensions of the column's points, one small
            /// scatter plot per pair i < j tinted by a measure of that projection; a click shows
            /// that pair in the column's panels.
            Matrix {
                switch: matrix,
                label: "Projection matrix",
                place: Column,
                column_free: false,
                gui: matrix::MatrixPanel,
                figures: [
                    /// The projection matrix: the pairs of the first K dimensions as a triangle
                    /// of scatter plots tinted by the measure, with its colour bar (CSV: the
                    /// pair table).
                    Matrix { name: "matrix", when: always, composite: false, draw: matrix::Matrix },
                ],
                nodes: [(Matrix, always)],
            }
        }
    };
}
pub(crate) use panel_list;

/// Reads the entries of [`panel_list!`] (the one place their grammar is written) and hands
/// `$then!` four views of them: every figure with its name and flags (`figures`), every
/// figure's drawing type (`draw`), every panel's GUI type (`gui`), and the panels' rows
/// (`rows`).
macro_rules! panel_project {
    ($then:path; $(
        $(#[$doc:meta])*
        $kind:ident {
            switch: $switch:ident,
            label: $label:literal,
            place: $place:ident,
            column_free: $free:literal,
            gui: $gmod:ident :: $gty:ident,
            figures: [$(
                $(#[$fdoc:meta])*
                $fig:ident { name: $fname:literal, when: $fneed:expr, composite: $comp:literal, draw: $fmod:ident :: $fty:ident $(,)? }
            ),* $(,)?],
            nodes: [$(($node:ident, $nneed:expr)),* $(,)?] $(,)?
        }
    )*) => {
        $then! {
            figures: [$($(
                $(#[$fdoc])* $fig $fname $comp $free;
            )*)*]
            draw: [$($($fig $fmod::$fty;)*)*]
            gui: [$($kind $gmod::$gty;)*]
            rows: [$(
                $(#[$doc])* $kind $switch $label $place [$(($fig, $fneed)),*] [$(($node, $nneed)),*];
            )*]
        }
    };
}
pub(crate) use panel_project;

/// Which panels are visible: one switch per entry of [`panel_list!`] (the field order is the
/// scene files' and stays as it was written).
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
    /// The projection matrix: the first K dimensions' pairs as scatter plots tinted by a
    /// measure.
    pub matrix: bool,
}

impl Default for Panels {
    /// What a scene shows when it does not say: the four column panels of the lecture.
    fn default() -> Self {
        let mut p = Panels::none();
        for k in [
            PanelKind::Pattern,
            PanelKind::Spectrum,
            PanelKind::ZonePlate,
            PanelKind::Filter,
        ] {
            *(k.spec().switch)(&mut p) = true;
        }
        p
    }
}

impl Panels {
    /// Every switch off.
    pub fn none() -> Self {
        Panels {
            pattern: false,
            spectrum: false,
            zoneplate: false,
            filter: false,
            cost: false,
            theorem: false,
            integration: false,
            sphere: false,
            matrix: false,
        }
    }

    /// Only `kind` shown.
    pub fn only(kind: PanelKind) -> Self {
        let mut p = Panels::none();
        *(kind.spec().switch)(&mut p) = true;
        p
    }
}

/// Where the GUI places a panel.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Place {
    /// In every column's grid, in table order.
    Column,
    /// Docked below the columns (one for the whole scene), in table order from the bottom up.
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
    /// Its checkbox in the GUI's Panels section.
    pub label: &'static str,
    /// Its switch in the scene's [`Panels`].
    pub switch: fn(&mut Panels) -> &mut bool,
    /// Where the GUI places it.
    pub place: Place,
    /// The figures it saves (its Save menu, in this order), each with when it is available.
    pub figures: &'static [(FigureKind, Need)],
    /// The nodes it reads, each with when it asks for it (their inputs are added by the plan).
    pub nodes: &'static [(NodeKind, Need)],
}

/// Expands [`panel_list!`] into [`PanelKind`] and [`PANELS`].
macro_rules! panel_rows {
    (
        figures: $figures:tt
        draw: $draw:tt
        gui: $gui:tt
        rows: [$(
            $(#[$doc:meta])* $kind:ident $switch:ident $label:literal $place:ident
            [$(($fig:ident, $fneed:expr)),*] [$(($node:ident, $nneed:expr)),*];
        )*]
    ) => {
        /// One of the panels (an entry of [`panel_list!`], a row of [`PANELS`], in the GUI's
        /// order).
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
        pub enum PanelKind {
            $($(#[$doc])* $kind,)*
        }

        impl PanelKind {
            /// Every panel, in table order.
            pub const ALL: [PanelKind; [$(PanelKind::$kind),*].len()] = [$(PanelKind::$kind),*];
        }

        /// The panel table, indexed by `PanelKind as usize`.
        pub static PANELS: [PanelSpec; PanelKind::ALL.len()] = [$(
            PanelSpec {
                kind: PanelKind::$kind,
                name: stringify!($switch),
                label: $label,
                switch: |p| &mut p.$switch,
                place: Place::$place,
                figures: &[$((FigureKind::$fig, $fneed)),*],
                nodes: &[$((NodeKind::$node, $nneed)),*],
            },
        )*];
    };
}

panel_list!(panel_rows);

impl PanelKind {
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
        // Every node a panel reads is in the node table, and only `Samples`, `Psa` and
        // `Sequence` (inputs of the reconstruction, the statistics and a prefix's points) and
        // the nodes `analyze` asks for by name (`Rdf`, `NetPrefixes`) are asked for by no panel.
        for k in NodeKind::ALL {
            let readers = PANELS
                .iter()
                .filter(|p| p.nodes.iter().any(|&(n, _)| n == k))
                .count();
            let unread = matches!(
                k,
                NodeKind::Samples
                    | NodeKind::Psa
                    | NodeKind::Sequence
                    | NodeKind::Rdf
                    | NodeKind::NetPrefixes
            );
            assert_eq!(readers == 0, unread, "{}", k.name());
        }
    }

    #[test]
    fn the_list_gives_each_figure_one_name_one_row_and_the_composite_its_order() {
        let rows: Vec<FigureKind> = PANELS.iter().flat_map(|p| p.figure_kinds()).collect();
        assert_eq!(
            rows,
            FigureKind::ALL.to_vec(),
            "ALL is the rows' figures in order"
        );
        let names: std::collections::HashSet<&str> =
            FigureKind::ALL.iter().map(|k| k.name()).collect();
        assert_eq!(
            names.len(),
            FigureKind::ALL.len(),
            "figure names are unique"
        );
        for p in &PANELS {
            assert_eq!(PANELS.iter().filter(|q| q.name == p.name).count(), 1);
            assert_eq!(PANELS.iter().filter(|q| q.label == p.label).count(), 1);
        }
        // Written out independently of the list: what a composite holds, in its order.
        assert_eq!(
            FigureKind::COMPOSITE,
            [
                FigureKind::Pattern,
                FigureKind::Sphere,
                FigureKind::Spectrum,
                FigureKind::Reconstruction,
                FigureKind::Kernel,
                FigureKind::Response,
                FigureKind::TheoremSignal,
                FigureKind::TheoremSpectrum,
                FigureKind::TheoremReconstructed,
            ]
        );
        let theorem: Vec<FigureKind> = PanelKind::Theorem.spec().figure_kinds().collect();
        assert_eq!(FigureKind::THEOREM.to_vec(), theorem);
        let lecture = Panels {
            pattern: true,
            spectrum: true,
            zoneplate: true,
            filter: true,
            ..Panels::none()
        };
        assert_eq!(Panels::default(), lecture);
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
            FigureKind::Matrix => NodeKind::Matrix,
        }
    }

    #[test]
    fn every_figure_render_writes_has_its_node_planned_for_every_switch_and_effect() {
        let mut scene = Scene {
            columns: vec![Default::default(), Default::default()],
            ..Default::default()
        };
        // One bit per panel, then one per effect.
        let np = PanelKind::ALL.len() as u32;
        for bits in 0u32..1 << (np + 4) {
            let on = |i: u32| bits & (1 << i) != 0;
            for (i, p) in PanelKind::ALL.into_iter().enumerate() {
                *(p.spec().switch)(&mut scene.panels) = on(i as u32);
            }
            scene.effects.reconstruction = on(np);
            scene.effects.error = on(np + 1);
            scene.effects.convergence = on(np + 2);
            scene.effects.statistics = on(np + 3);
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
            let panels = Panels::only(p);
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
