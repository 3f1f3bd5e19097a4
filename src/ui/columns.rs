//! The panels of the panel table placed where their rows say ([`placed`]), and the columns side by side,
//! each a grid of its visible column panels sized by the layout rule ([`grid`]: the pictures
//! take the space they are given); and adding a column.

use super::panels::{make, Extent, Panel, PanelCx};
use crate::model::PointsData;
use crate::scene::panels::{PanelKind, Place};
use crate::scene::{Scene, MAX_COLUMNS};
use eframe::egui::{self, Rect, Vec2};
use std::collections::BTreeMap;

/// The panels placed at `place`, in table order.
pub fn placed(place: Place) -> Vec<Box<dyn Panel>> {
    PanelKind::ALL
        .into_iter()
        .filter(|k| k.spec().place == place)
        .map(make)
        .collect()
}

/// The column grid: the column panels in the panel table's order, and each column's screen
/// rectangle as last drawn (files dropped on the window go to the column under the pointer).
pub struct Columns {
    panels: Vec<Box<dyn Panel>>,
    rects: Vec<Rect>,
    cells: Vec<DrawnCell>,
    /// Each panel's rows of text as measured in the last frame it drew its pictures (the
    /// tallest over the columns), in lines, with the cell width they wrapped to: the grid's
    /// estimate for cells of that width, better than the panel's own ([`Panel::extent`]).
    measured: BTreeMap<PanelKind, (f32, f32)>,
}

/// Where a column panel was drawn in the last frame: the cell the grid gave it and the
/// rectangle its contents took (wider than the cell only if something in it could not wrap).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DrawnCell {
    /// The panel's row of the panel table.
    pub kind: PanelKind,
    /// Its column.
    pub column: usize,
    /// The width the grid gave it, in points.
    pub width: f32,
    /// The rectangle it took.
    pub rect: Rect,
}

impl Default for Columns {
    fn default() -> Self {
        Columns {
            panels: placed(Place::Column),
            rects: Vec::new(),
            cells: Vec::new(),
            measured: BTreeMap::new(),
        }
    }
}

impl Columns {
    /// Each column's screen rectangle in the last frame, in column order.
    pub fn rects(&self) -> &[Rect] {
        &self.rects
    }

    /// Every column panel's cell in the last frame, column by column.
    pub fn cells(&self) -> &[DrawnCell] {
        &self.cells
    }

    /// Every column side by side, sharing the width; in each, its visible panels in the grid
    /// [`grid`] chooses: square images as large as the row allows, plots sharing the height
    /// left, captions wrapped to the cell. In lecture mode (a zoom above 1) the pictures are
    /// never smaller than the same grid with normal-sized text would make them: the larger
    /// text costs height, not picture (the column scrolls when it must). Sets `cx.column` and
    /// `cx.cell` for each panel.
    pub fn ui(&mut self, ui: &mut egui::Ui, cx: &mut PanelCx<'_>) {
        let Columns {
            panels,
            rects,
            cells,
            measured,
        } = self;
        rects.clear();
        cells.clear();
        let zoom = ui.ctx().zoom_factor().max(1.0);
        let metrics = Metrics::of(ui, zoom);
        let ncols = cx.scene.columns.len().max(1);
        let shown: Vec<(PanelKind, Extent)> = panels
            .iter()
            .filter(|p| p.is_shown(&cx.scene.panels))
            .map(|p| (p.kind(), p.extent()))
            .collect();
        let declared: Vec<Extent> = shown.iter().map(|s| s.1).collect();
        let mut measuring = BTreeMap::new();
        let avail = ui.available_size();
        let width = ((avail.x - metrics.gap * (ncols as f32 - 1.0)) / ncols as f32).max(MIN_SIDE);
        // Under the column header (one line).
        let height = avail.y - metrics.line;
        // The arrangement from the panels' own estimates (the same for any wrapping); the
        // side from the text as it wrapped in cells of that width in the last frame.
        let arranged = |m: Metrics, height: f32| {
            let per_row = grid(width, height, &declared, m).per_row;
            let cell_width = cell_width(width, per_row, m);
            let extents: Vec<Extent> = shown
                .iter()
                .map(|&(kind, mut e)| {
                    if let Some(&(w, lines)) = measured.get(&kind) {
                        if (w - cell_width).abs() < 0.5 {
                            e.lines = lines;
                        }
                    }
                    e
                })
                .collect();
            (grid_of(per_row, width, height, &extents, m), extents)
        };
        let (mut layout, mut extents) = arranged(metrics, height);
        if zoom > 1.0 {
            // The grid normal-sized text would give, in its own arrangement: the column header
            // and the text above the columns (the top bar, `top` points) at their normal size
            // leave it more height.
            let top = ui.max_rect().top().max(0.0);
            let normal_height = avail.y + top * (1.0 - 1.0 / zoom) - metrics.line / zoom;
            let (normal, normal_extents) = arranged(metrics.text_scaled(1.0 / zoom), normal_height);
            if normal.side > layout.side {
                layout = Grid { height, ..normal }.with_metrics(&normal_extents, metrics);
                extents = normal_extents;
            }
        }
        let cell_spacing = ui.spacing().item_spacing;
        egui::ScrollArea::both().show(ui, |ui| {
            ui.spacing_mut().item_spacing = Vec2::splat(metrics.gap);
            ui.horizontal_top(|ui| {
                for ci in 0..cx.scene.columns.len() {
                    cx.column = ci;
                    let header = column_header(cx);
                    ui.push_id(ci, |ui| {
                        let shown = ui.allocate_ui(Vec2::new(width, avail.y), |ui| {
                            ui.set_width(width);
                            ui.vertical(|ui| {
                                ui.horizontal(|ui| {
                                    ui.spacing_mut().item_spacing = cell_spacing;
                                    ui.strong(header);
                                    cx.figures.column_menu_ui(ui, ci);
                                });
                                let mut shown: Vec<&mut Box<dyn Panel>> = panels
                                    .iter_mut()
                                    .filter(|p| p.is_shown(&cx.scene.panels))
                                    .collect();
                                let rows = shown.chunks_mut(layout.per_row);
                                for ((row, &row_height), extents) in
                                    rows.zip(&layout.rows).zip(extents.chunks(layout.per_row))
                                {
                                    ui.horizontal_top(|ui| {
                                        for (panel, extent) in row.iter_mut().zip(extents) {
                                            // What Ctrl+S over it saves: the figure shown
                                            // when the frame began.
                                            let figure = panel.figure(cx.view);
                                            cx.cell.side = layout.side;
                                            cx.cell.plot_height =
                                                layout.plot_height(extent, row_height, metrics);
                                            let size = Vec2::new(layout.cell_width, row_height);
                                            let drew = cx.cell.pictures.len();
                                            let drawn = ui.allocate_ui(size, |ui| {
                                                let s = ui.spacing_mut();
                                                s.item_spacing = cell_spacing;
                                                // A slider with its value and label fits the
                                                // cell (the value box and label take ~60%).
                                                s.slider_width =
                                                    s.slider_width.min(0.35 * layout.cell_width);
                                                ui.set_width(layout.cell_width);
                                                ui.vertical(|ui| panel.ui(ui, cx))
                                            });
                                            cx.figures.panel_drawn(drawn.response.rect, ci, figure);
                                            if cx.cell.pictures.len() > drew {
                                                let text = drawn.response.rect.height()
                                                    - extent.images * layout.side
                                                    - extent.plots * cx.cell.plot_height;
                                                let lines = (text / metrics.line).max(0.0);
                                                let m = measuring
                                                    .entry(panel.kind())
                                                    .or_insert((layout.cell_width, 0.0f32));
                                                m.1 = m.1.max(lines);
                                            }
                                            cells.push(DrawnCell {
                                                kind: panel.kind(),
                                                column: ci,
                                                width: layout.cell_width,
                                                rect: drawn.response.rect,
                                            });
                                        }
                                    });
                                }
                            });
                        });
                        rects.push(shown.response.rect);
                    });
                }
            });
        });
        measured.extend(measuring);
    }
}

/// The smallest side of a square image, in points: below it the columns scroll.
pub const MIN_SIDE: f32 = 100.0;
/// The smallest height of a plot, in lines of text.
pub const MIN_PLOT: f32 = 3.0;

/// The measures the grid works in, in points.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Metrics {
    /// One row of text: a body line or a widget, with the spacing below it.
    pub line: f32,
    /// The space between cells and between columns.
    pub gap: f32,
}

impl Metrics {
    /// The measures of `ui`'s style; the gaps keep their size on screen at any `zoom`.
    pub fn of(ui: &egui::Ui, zoom: f32) -> Self {
        let s = ui.spacing();
        let body = ui.text_style_height(&egui::TextStyle::Body);
        Metrics {
            line: body.max(s.interact_size.y) + s.item_spacing.y,
            gap: s.item_spacing.x / zoom,
        }
    }

    /// The same with text `f` times as tall (the normal-mode text seen from lecture mode).
    pub fn text_scaled(self, f: f32) -> Self {
        Metrics {
            line: self.line * f,
            ..self
        }
    }
}

/// The arrangement of a column's visible panels: `per_row` panels a row, each in a cell
/// `cell_width` wide, with square images of `side` and rows of the heights in `rows`.
#[derive(Debug, Clone, PartialEq)]
pub struct Grid {
    /// Panels in a row.
    pub per_row: usize,
    /// Width of a panel's cell, in points.
    pub cell_width: f32,
    /// Side of the square images, in points.
    pub side: f32,
    /// Height of each row, in points: what its tallest panel needs with plots at their
    /// smallest, and the height left over shared by the rows that hold plots.
    pub rows: Vec<f32>,
    /// The height the rows fill (the height given, or more when even the smallest images
    /// need more: then the column scrolls).
    pub height: f32,
}

/// What a panel of extent `e` needs at image side `side`, with plots at their smallest.
fn need(e: &Extent, side: f32, m: Metrics) -> f32 {
    e.images * side + e.lines * m.line + e.plots * MIN_PLOT * m.line
}

/// The grid of panels of `extents` (in table order) in a column `width` × `height` points:
/// of the arrangements with 1 to all panels a row, the one whose square images are largest
/// (ties: fewer panels a row); the images take the largest side that both the cell's width
/// and the column's height allow; the rows fill the height, the plots taking what is left.
pub fn grid(width: f32, height: f32, extents: &[Extent], m: Metrics) -> Grid {
    let n = extents.len().max(1);
    let mut best: Option<Grid> = None;
    for k in 1..=n {
        let g = fit(k, width, height, extents, m);
        if best.as_ref().is_none_or(|b| g.side > b.side) {
            best = Some(g);
        }
    }
    let per_row = best.map_or(1, |b| b.per_row);
    grid_of(per_row, width, height, extents, m)
}

/// The width of a cell with `per_row` cells a row in `width`.
pub fn cell_width(width: f32, per_row: usize, m: Metrics) -> f32 {
    let k = per_row.max(1) as f32;
    ((width - m.gap * (k - 1.0)) / k).max(0.0)
}

/// The grid of `per_row` panels a row (see [`grid`]).
pub fn grid_of(per_row: usize, width: f32, height: f32, extents: &[Extent], m: Metrics) -> Grid {
    let g = fit(per_row, width, height, extents, m);
    let side = g.side.max(MIN_SIDE);
    Grid {
        side,
        cell_width: g.cell_width.max(side),
        ..g
    }
    .with_metrics(extents, m)
}

/// The largest side (0 when none fits) of `per_row` panels a row; no rows yet.
fn fit(per_row: usize, width: f32, height: f32, extents: &[Extent], m: Metrics) -> Grid {
    let k = per_row.max(1);
    let cell_width = cell_width(width, k, m);
    let rows = extents.len().div_ceil(k).max(1) as f32;
    let total = |side: f32| -> f32 {
        extents
            .chunks(k)
            .map(|row| row.iter().map(|e| need(e, side, m)).fold(0.0, f32::max))
            .sum::<f32>()
            + m.gap * (rows - 1.0)
    };
    Grid {
        per_row: k,
        cell_width,
        side: largest_side(cell_width, height, total),
        rows: Vec::new(),
        height,
    }
}

/// The largest side in [0, `most`] whose `total` height fits `height` (0 when none does);
/// `total` grows with the side.
fn largest_side(most: f32, height: f32, total: impl Fn(f32) -> f32) -> f32 {
    if total(most) <= height {
        return most;
    }
    if total(0.0) > height {
        return 0.0;
    }
    let (mut lo, mut hi) = (0.0f32, most);
    for _ in 0..40 {
        let mid = 0.5 * (lo + hi);
        if total(mid) <= height {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    lo
}

impl Grid {
    /// The row heights of this arrangement and side for text and gaps of `m`: each row what
    /// its tallest panel needs, and the height left shared equally by the rows with plots.
    pub fn with_metrics(mut self, extents: &[Extent], m: Metrics) -> Grid {
        let rows: Vec<&[Extent]> = extents.chunks(self.per_row.max(1)).collect();
        let mut heights: Vec<f32> = rows
            .iter()
            .map(|row| {
                row.iter()
                    .map(|e| need(e, self.side, m))
                    .fold(0.0, f32::max)
            })
            .collect();
        let used = heights.iter().sum::<f32>() + m.gap * (rows.len() as f32 - 1.0).max(0.0);
        let with_plots: Vec<usize> = (0..rows.len())
            .filter(|&r| rows[r].iter().any(|e| e.plots > 0.0))
            .collect();
        let left = self.height - used;
        if left > 0.0 && !with_plots.is_empty() {
            for &r in &with_plots {
                heights[r] += left / with_plots.len() as f32;
            }
        }
        self.rows = heights;
        self
    }

    /// The height of each plot of a panel of extent `e` in a row `row_height` tall: the
    /// height its images and text leave, shared by its plots (at least [`MIN_PLOT`] lines).
    pub fn plot_height(&self, e: &Extent, row_height: f32, m: Metrics) -> f32 {
        if e.plots <= 0.0 {
            return 0.0;
        }
        let left = row_height - e.images * self.side - e.lines * m.line;
        (left / e.plots).max(MIN_PLOT * m.line)
    }
}

/// The title of column `cx.column`: its pattern, the points shown, seed (and the pair of
/// dimensions shown of a column in D > 2 dimensions), labelled from the scene its points were
/// computed for (a recompute may be running); an imported set has its own size and no seed.
/// The points shown are `N = n`, or `k = k of n` while a prefix shows the first k.
fn column_header(cx: &PanelCx<'_>) -> String {
    let ci = cx.column;
    let scene: &Scene = cx.scene;
    let Some(column) = scene.columns.get(ci) else {
        return String::new();
    };
    match &column.points {
        Some(_) => format!("{} · {}", column.title(), shown_points(scene, ci)),
        None => {
            let slot = cx.get::<PointsData>();
            let lab = slot
                .status()
                .and_then(crate::ui::results::scene_of)
                .unwrap_or(scene);
            let c = lab.columns.get(ci).unwrap_or(column);
            let projection = if c.is_plain_2d() {
                String::new()
            } else {
                format!(" · x{} × x{} of D = {}", c.project.0, c.project.1, c.dims)
            };
            format!(
                "{} · {} · seed {}{projection}",
                c.title(),
                shown_points(lab, ci),
                c.seed
            )
        }
    }
}

/// The points column `c` of `scene` shows: `N = n`, or `k = k of n` when a prefix shows
/// fewer than all of them.
fn shown_points(scene: &Scene, c: usize) -> String {
    let (k, n) = (scene.shown_n(c), scene.column_n(c));
    if k < n {
        format!("k = {k} of {n}")
    } else {
        format!("N = {n}")
    }
}

/// Adds a column (a copy of the last one with the next seed), up to [`MAX_COLUMNS`].
pub fn add_column(scene: &mut Scene) {
    if scene.columns.len() < MAX_COLUMNS {
        let mut c = scene.columns.last().cloned().unwrap_or_default();
        c.seed = c.seed.wrapping_add(1);
        scene.columns.push(c);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_row_of_the_panel_table_is_made_once_at_its_place() {
        for kind in PanelKind::ALL {
            assert_eq!(make(kind).kind(), kind);
        }
        let columns: Vec<PanelKind> = placed(Place::Column).iter().map(|p| p.kind()).collect();
        let docks: Vec<PanelKind> = placed(Place::Dock).iter().map(|p| p.kind()).collect();
        let mut all = [columns, docks].concat();
        all.sort();
        assert_eq!(all, PanelKind::ALL.to_vec());
    }

    #[test]
    fn the_header_shows_the_prefix_k_of_n_while_one_is_shown() {
        let mut scene = Scene {
            n: 1024,
            ..Scene::default()
        };
        assert_eq!(shown_points(&scene, 0), "N = 1024");
        scene.prefix = Some(37);
        assert_eq!(shown_points(&scene, 0), "k = 37 of 1024");
        // A prefix of all the points (or more than an imported set has) shows N.
        scene.prefix = Some(1024);
        assert_eq!(shown_points(&scene, 0), "N = 1024");
    }
}
