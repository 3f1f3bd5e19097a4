//! The panels: one file each, one struct each, drawing plain data computed by the engine (no
//! maths here). A panel implements [`Panel`] and reads everything it needs from a [`PanelCx`]
//! lent by the app for the frame: its column's plain `model::ColumnData` (the same data the
//! figures read), each node's data with its status ([`PanelCx::get`], a [`Slot`]), never the
//! graph's node values.
//!
//! Which panels exist, when each is shown, where it goes and which figures it saves is the
//! panel list (`scene::panels::panel_list!`, whose rows are [`crate::scene::panels::PANELS`]);
//! [`make`], expanded from it, builds each row's panel from the GUI type its entry names.
//! The column panels ([`pattern`], [`sphere`], [`spectrum`], [`zoneplate`], [`filter`]) are
//! laid out per column by [`crate::ui::columns`]; the docked ones ([`cost`], [`theorem`],
//! [`integration`]) go below the columns (the app). A new panel is a new file here
//! implementing [`Panel`] and `Default`, its `pub mod` line, and its entry in the panel list.

pub mod cost;
pub mod filter;
pub mod integration;
pub mod matrix;
pub mod pattern;
pub mod spectrum;
pub mod sphere;
pub mod theorem;
pub mod zoneplate;

use crate::engine::Evaluator;
use crate::model::{ColumnData, FigureKind, InColumn, Slot};
use crate::scene::panels::PanelKind;
use crate::scene::{Panels, Scene};
use crate::ui::figures::FigureRequests;
use crate::ui::view::ViewState;
use crate::ui::widgets::image::ImageView;
use eframe::egui;

/// Expands the panel list into [`make`]: each row's GUI type, named by the list relative to
/// this module (its file is `panels/<module>.rs`, declared above).
macro_rules! panel_registry {
    (
        figures: $figures:tt
        draw: $draw:tt
        gui: [$($kind:ident $module:ident :: $ty:ident;)*]
        $($rest:tt)*
    ) => {
        /// The panel of row `kind` of the panel table, in its initial state.
        pub fn make(kind: PanelKind) -> Box<dyn Panel> {
            match kind {
                $(PanelKind::$kind => Box::new(<$module::$ty>::default()),)*
            }
        }
    };
}

crate::scene::panels::panel_list!(panel_registry);

/// A panel: a small struct holding its own display state, drawn from a [`PanelCx`].
pub trait Panel {
    /// The panel's identity: its row of the panel table ([`crate::scene::panels::PANELS`]),
    /// which says when it is shown and which figures its Save menu lists.
    fn kind(&self) -> PanelKind;

    /// Whether the scene shows the panel: its switch, as the table says.
    fn is_shown(&self, panels: &Panels) -> bool {
        self.kind().is_shown(panels)
    }

    /// The figure saved by Ctrl+S over the panel, which may follow the view (the zone plate
    /// shows one of three images); by default the first figure of the panel's row.
    fn figure(&self, _view: &ViewState) -> FigureKind {
        self.kind().spec().figures[0].0
    }

    /// The height a docked panel first gets, in points (column panels are sized by the grid).
    fn dock_size(&self) -> f32 {
        220.0
    }

    /// What a column panel holds, by which the grid sizes it ([`crate::ui::columns`]): by
    /// default one square image under a heading, with three lines of captions.
    fn extent(&self) -> Extent {
        Extent {
            images: 1.0,
            lines: 4.0,
            plots: 0.0,
        }
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
    /// Every column's latest data, with each node's status.
    pub data: &'a [ColumnData],
    /// The shared display state.
    pub view: &'a mut ViewState,
    /// Draws images (GPU or CPU) and says whether the GPU path is on.
    pub images: &'a mut ImageView,
    /// Where panels request figures and record where they were drawn.
    pub figures: &'a mut FigureRequests,
    /// The evaluator's counters (the cost view shows them).
    pub evaluator: &'a Evaluator,
    /// Where the grid put the column panel drawn: its image side and plot height, and the
    /// pictures it drew.
    pub cell: Cell,
}

/// What a column panel holds, stacked top to bottom: square images, rows of text (its heading,
/// captions, checkboxes) and plots. The grid gives the images the largest side the row allows
/// and the plots the height left ([`crate::ui::columns::grid`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Extent {
    /// The height of its images, in image sides (a pattern 1, the filter's 2D response 0.6).
    pub images: f32,
    /// Rows of text, each one line of the style's body text high.
    pub lines: f32,
    /// Plots sharing the height left, each at least [`crate::ui::columns::MIN_PLOT`] lines.
    pub plots: f32,
}

/// The place the grid gives a column panel for one frame, and the pictures (images and plots)
/// the panel drew there: where the layout rule's tests and measurements find them.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Cell {
    /// Side of the panel's square images, in points.
    pub side: f32,
    /// Height of each of its plots, in points.
    pub plot_height: f32,
    /// The pictures drawn this frame (every column's), in drawing order.
    pub pictures: Vec<Picture>,
}

/// A picture a panel drew: an image or a plot, its column and its screen rectangle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Picture {
    /// The panel's row of the panel table.
    pub kind: PanelKind,
    /// The column it belongs to.
    pub column: usize,
    /// A square image (else a plot).
    pub image: bool,
    /// Where it was drawn, in points.
    pub rect: egui::Rect,
}

impl<'a> PanelCx<'a> {
    /// Records a picture panel `kind` drew in the current column (an image when `image`, else
    /// a plot).
    pub fn picture(&mut self, kind: PanelKind, image: bool, rect: egui::Rect) {
        let column = self.column;
        self.cell.pictures.push(Picture {
            kind,
            column,
            image,
            rect,
        });
    }

    /// The drawn column's latest `T` with its status.
    pub fn get<T: InColumn>(&self) -> Slot<T> {
        self.get_in(self.column)
    }

    /// Column `column`'s latest `T` with its status.
    pub fn get_in<T: InColumn>(&self, column: usize) -> Slot<T> {
        self.data
            .get(column)
            .map_or(Slot::Missing, |d| d.get::<T>().clone())
    }
}
