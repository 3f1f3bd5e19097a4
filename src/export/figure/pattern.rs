//! The points in the unit square, over the elementary intervals when the column asks.

use super::csv::curve;
use super::draw::{axes, chart, draw_err, empty, present, Frame, INK, INTERVALS};
use super::{context_metadata, Area, Figure};
use crate::export::ExportError;
use crate::model::{elementary_grid, ColumnData, FigureContext, PanelKind};
use plotters::prelude::*;

/// The pattern figure.
pub(super) struct Pattern;

const KIND: PanelKind = PanelKind::Pattern;

impl Figure for Pattern {
    fn kind(&self) -> PanelKind {
        KIND
    }

    fn base_size(&self) -> (u32, u32) {
        (480, 510)
    }

    fn title(&self, ctx: &FigureContext, _data: &ColumnData) -> String {
        ctx.column_caption()
    }

    fn has_data(&self, data: &ColumnData) -> bool {
        data.points.is_some()
    }

    fn check(&self, data: &ColumnData) -> Result<(), ExportError> {
        let p = present(KIND, data.points.as_ref())?;
        if p.points.is_empty() {
            return Err(empty(KIND, "the point set is empty"));
        }
        Ok(())
    }

    fn draw(&self, f: &mut Frame<'_, '_>, body: &Area<'_>) -> Result<(), ExportError> {
        let de = |e| draw_err(KIND, e);
        let look = f.look;
        let pts = &present(KIND, f.data.points.as_ref())?.points;
        let mut ch = chart(body, 0.0..1.0, 0.0..1.0, look, KIND)?;
        axes(&mut ch, "x", "y", false, false, look, KIND)?;
        if let Some((cols, rows)) = elementary_grid(f.ctx.elementary_k, pts.len()) {
            let thin = look.line(INTERVALS, 1);
            let verticals = (1..cols).map(|i| {
                let x = i as f64 / cols as f64;
                PathElement::new(vec![(x, 0.0), (x, 1.0)], thin)
            });
            let horizontals = (1..rows).map(|j| {
                let y = j as f64 / rows as f64;
                PathElement::new(vec![(0.0, y), (1.0, y)], thin)
            });
            ch.draw_series(verticals.chain(horizontals)).map_err(de)?;
        }
        let (xr, _) = ch.plotting_area().get_pixel_range();
        let side = (xr.end - xr.start) as f64;
        let radius = (side / (pts.len() as f64).sqrt() * 0.18)
            .clamp(1.0, 4.0 * look.s as f64)
            .round() as u32;
        ch.draw_series(
            pts.iter()
                .map(|p| Circle::new((p.x, p.y), radius, INK.filled())),
        )
        .map_err(de)?;
        ch.plotting_area()
            .draw(&Rectangle::new(
                [(0.0, 0.0), (1.0, 1.0)],
                look.line(BLACK, 1),
            ))
            .map_err(de)?;
        Ok(())
    }

    fn csv(&self, data: &ColumnData) -> Result<String, ExportError> {
        let p = present(KIND, data.points.as_ref())?;
        let pts: Vec<[f64; 2]> = p.points.iter().map(|p| [p.x, p.y]).collect();
        curve("x,y", &pts, KIND)
    }

    /// The context, and the elementary intervals when they are drawn.
    fn metadata(&self, ctx: &FigureContext, data: &ColumnData) -> Vec<(String, String)> {
        let mut m = context_metadata(ctx);
        if let Some(grid) = data
            .points
            .as_ref()
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
