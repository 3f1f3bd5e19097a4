//! The panels: one file each, one struct each, drawing plain data computed by the engine (no
//! maths here). A panel implements [`Panel`] and reads everything it needs from a [`PanelCx`]
//! lent by the app for the frame.
//!
//! The column panels ([`pattern`], [`sphere`], [`spectrum`], [`zoneplate`], [`filter`]) are
//! laid out per column by [`crate::ui::columns`]; [`cost`], [`integration`] and [`theorem`] are
//! docked below the columns by the app. A new panel is a new file here implementing [`Panel`],
//! plus one line where it is
//! placed (the column list in `columns.rs`, or a dock in `app.rs`).

pub mod cost;
pub mod filter;
pub mod integration;
pub mod pattern;
pub mod spectrum;
pub mod sphere;
pub mod theorem;
pub mod zoneplate;

use crate::engine::Evaluator;
use crate::model::FigureKind;
use crate::scene::graph::NodeKind;
use crate::scene::{Panels, Scene};
use crate::ui::figures::FigureRequests;
use crate::ui::results::{ColumnResults, Shown};
use crate::ui::view::ViewState;
use crate::ui::widgets::image::ImageView;
use eframe::egui;

/// A panel: a small struct holding its own display state, drawn from a [`PanelCx`].
pub trait Panel {
    /// The panel's identity: the figure it stands for.
    fn kind(&self) -> FigureKind;

    /// Whether the scene shows the panel (its switch in the scene's panels).
    fn is_shown(&self, panels: &Panels) -> bool;

    /// The figure saved by Ctrl+S over the panel, which may follow the view (the zone plate
    /// shows one of three images); by default the panel's [`Panel::kind`].
    fn figure(&self, _view: &ViewState) -> FigureKind {
        self.kind()
    }

    /// Draws the panel.
    fn ui(&mut self, ui: &mut egui::Ui, cx: &mut PanelCx<'_>);
}

/// Everything a panel reads and edits in one frame, lent by the app.
pub struct PanelCx<'a> {
    /// The scene being edited. Panels label their data from their results' scenes (what the
    /// data was computed for) and fall back to this one; a panel with controls of its own (the
    /// theorem view) edits it.
    pub scene: &'a mut Scene,
    /// The column drawn (0 for the panels below the columns).
    pub column: usize,
    /// Every column's latest results.
    pub results: &'a [ColumnResults],
    /// The shared display state.
    pub view: &'a mut ViewState,
    /// Draws images (GPU or CPU) and says whether the GPU path is on.
    pub images: &'a mut ImageView,
    /// Where panels request figures and record where they were drawn.
    pub figures: &'a mut FigureRequests,
    /// The evaluator's counters (the cost view shows them).
    pub evaluator: &'a Evaluator,
    /// Side of a column panel's square image, in points.
    pub side: f32,
}

impl<'a> PanelCx<'a> {
    /// The drawn column's latest result of `kind` (borrowed from the results, not from the
    /// context, so the context stays usable while it is held).
    pub fn result(&self, kind: NodeKind) -> Option<&'a Shown> {
        let results: &'a [ColumnResults] = self.results;
        results.get(self.column).and_then(|c| c.get(&kind))
    }
}
