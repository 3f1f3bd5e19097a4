//! The points in the unit square, over the strata and the elementary intervals when the
//! column asks.
//!
//! The axes are padded by one marker radius (and a pixel) on every side, so that points on
//! the square's border (0 and 1 are common coordinates: grids, Hammersley, lattices) are drawn
//! whole; the unit square is outlined in a light line, the padded area framed.

use super::canvas::SUB;
use super::csv::curve;
use super::draw::{axes, chart, draw_err, empty, present, Frame, GUIDE, INK, INTERVALS};
use super::{context_metadata, Area, Figure};
use crate::export::ExportError;
use crate::model::{
    drawn_strata, elementary_grid, marks, palette, ColumnData, FigureContext, FigureKind,
};
use plotters::prelude::*;

/// The pattern figure.
pub(super) struct Pattern;

/// The strata's lines (the GUI's overlay colour).
const STRATA: RGBColor = RGBColor(palette::STRATA[0], palette::STRATA[1], palette::STRATA[2]);

/// The inner lines of a `cols` × `rows` grid over the unit square.
fn grid(
    ch: &mut super::canvas::Chart<'_, '_>,
    cols: usize,
    rows: usize,
    style: ShapeStyle,
) -> Result<(), plotters::drawing::DrawingAreaErrorKind<super::canvas::CanvasError>> {
    let verticals = (1..cols).map(|i| {
        let x = i as f64 / cols as f64;
        PathElement::new(vec![(x, 0.0), (x, 1.0)], style)
    });
    let horizontals = (1..rows).map(|j| {
        let y = j as f64 / rows as f64;
        PathElement::new(vec![(0.0, y), (1.0, y)], style)
    });
    ch.draw_series(verticals.chain(horizontals)).map(|_| ())
}

const KIND: FigureKind = FigureKind::Pattern;

/// The radius of the markers of `n` points on a plotting area `side` wide, in plotters'
/// pixels (`s` of them per base pixel): about a fifth of the mean spacing, from one page
/// pixel to 4 base pixels.
fn marker_radius(side: f64, n: usize, s: u32) -> u32 {
    marks::marker_radius(side, n)
        .clamp(SUB as f64, marks::MAX_RADIUS_PX * s as f64)
        .round() as u32
}

impl Figure for Pattern {
    fn kind(&self) -> FigureKind {
        KIND
    }

    fn base_size(&self) -> (u32, u32) {
        (480, 510)
    }

    fn title(&self, ctx: &FigureContext, _data: &ColumnData) -> String {
        ctx.column_caption()
    }

    fn panel_title(&self, _ctx: &FigureContext, _data: &ColumnData) -> String {
        "points".to_string()
    }

    fn has_data(&self, data: &ColumnData) -> bool {
        data.points.is_ready()
    }

    fn check(&self, data: &ColumnData) -> Result<(), ExportError> {
        let p = present(KIND, data.points.data())?;
        if p.points.is_empty() {
            return Err(empty(KIND, "the point set is empty"));
        }
        Ok(())
    }

    fn draw(&self, f: &mut Frame<'_, '_>, body: &Area<'_>) -> Result<(), ExportError> {
        let de = |e| draw_err(KIND, e);
        let look = f.look;
        let pts = &present(KIND, f.data.points.data())?.points;
        // The marker radius follows the plotting area's side, which the padding barely
        // changes: measured on the unpadded chart (building a chart draws nothing).
        let side = {
            let unpadded = chart(body, 0.0..1.0, 0.0..1.0, look, KIND)?;
            let (xr, _) = unpadded.plotting_area().get_pixel_range();
            (xr.end - xr.start).max(1) as f64
        };
        let radius = marker_radius(side, pts.len(), look.s);
        let pad = (radius as f64 + SUB as f64) / side;
        let mut ch = chart(body, -pad..1.0 + pad, -pad..1.0 + pad, look, KIND)?;
        axes(&mut ch, "x", "y", false, false, look, KIND)?;
        // The strata, then the elementary intervals.
        if let Some((cols, rows)) = drawn_strata(f.ctx.strata) {
            grid(&mut ch, cols, rows, look.line(STRATA, 1)).map_err(de)?;
        }
        if let Some((cols, rows)) = elementary_grid(f.ctx.elementary_k, pts.len()) {
            grid(&mut ch, cols, rows, look.line(INTERVALS, 1)).map_err(de)?;
        }
        // The unit square in a light line under the points, and a closed frame around the
        // padded plotting area: the axes, and a top and a right side.
        ch.plotting_area()
            .draw(&Rectangle::new(
                [(0.0, 0.0), (1.0, 1.0)],
                look.line(GUIDE, 1),
            ))
            .map_err(de)?;
        ch.draw_series(
            pts.iter()
                .map(|p| Circle::new((p.x, p.y), radius, INK.filled())),
        )
        .map_err(de)?;
        let (lo, hi) = (-pad, 1.0 + pad);
        ch.draw_series([
            PathElement::new(vec![(lo, hi), (hi, hi)], look.line(BLACK, 1)),
            PathElement::new(vec![(hi, lo), (hi, hi)], look.line(BLACK, 1)),
        ])
        .map_err(de)?;
        Ok(())
    }

    fn csv(&self, data: &ColumnData) -> Result<String, ExportError> {
        let p = present(KIND, data.points.data())?;
        let pts: Vec<[f64; 2]> = p.points.iter().map(|p| [p.x, p.y]).collect();
        curve("x,y", &pts, KIND)
    }

    /// The context, and the strata and elementary intervals when they are drawn.
    fn metadata(&self, ctx: &FigureContext, data: &ColumnData) -> Vec<(String, String)> {
        let mut m = context_metadata(ctx);
        if let Some((c, r)) = drawn_strata(ctx.strata) {
            m.push(("strata".into(), format!("{c}×{r} cells")));
        }
        if let Some(grid) = data
            .points
            .data()
            .and_then(|p| elementary_grid(ctx.elementary_k, p.points.len()))
        {
            m.push((
                "elementary intervals".into(),
                format!(
                    "k = {}: {}×{} boxes of 2^-{} × 2^-{}",
                    grid.0.trailing_zeros(),
                    grid.0,
                    grid.1,
                    grid.0.trailing_zeros(),
                    grid.1.trailing_zeros()
                ),
            ));
        }
        m
    }
}
