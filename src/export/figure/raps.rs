//! The radially averaged power spectrum against the white-noise level.

use super::csv::curve;
use super::draw::{
    any_finite, axes, chart, draw_err, emptiest_corner, empty, finite, legend_box, line_sample,
    padded, present, Frame, DATA, GUIDE,
};
use super::{Area, Figure};
use crate::export::ExportError;
use crate::model::{ColumnData, FigureContext, FigureKind};
use plotters::prelude::*;

/// The RAPS figure.
pub(super) struct Raps;

const KIND: FigureKind = FigureKind::Raps;

impl Figure for Raps {
    fn kind(&self) -> FigureKind {
        KIND
    }

    fn base_size(&self) -> (u32, u32) {
        (640, 510)
    }

    fn title(&self, ctx: &FigureContext, _data: &ColumnData) -> String {
        format!("RAPS, {}", ctx.column_caption())
    }

    fn panel_title(&self, _ctx: &FigureContext, _data: &ColumnData) -> String {
        "radially averaged power spectrum".to_string()
    }

    fn has_data(&self, data: &ColumnData) -> bool {
        data.spectrum.is_ready()
    }

    fn check(&self, data: &ColumnData) -> Result<(), ExportError> {
        let s = present(KIND, data.spectrum.data())?;
        if !any_finite(&s.raps) {
            return Err(empty(KIND, "the radial average has no finite bin"));
        }
        Ok(())
    }

    fn draw(&self, f: &mut Frame<'_, '_>, body: &Area<'_>) -> Result<(), ExportError> {
        let de = |e| draw_err(KIND, e);
        let look = f.look;
        let pts = finite(&present(KIND, f.data.spectrum.data())?.raps);
        let x_hi = pts.iter().map(|p| p.0).fold(0.0f64, f64::max).max(1.0);
        let y = padded(pts.iter().map(|p| p.1), &[0.0, 1.0]);
        let y = y.start.max(0.0)..y.end;
        let mut guide_pts = pts.clone();
        guide_pts.extend((0..=20).map(|i| (x_hi * i as f64 / 20.0, 1.0)));
        let corner = emptiest_corner(
            &guide_pts,
            &(0.0..x_hi),
            &y,
            SeriesLabelPosition::LowerRight,
        );
        let mut ch = chart(body, 0.0..x_hi, y, look, KIND)?;
        axes(
            &mut ch,
            "|k| (cycles per unit)",
            "radially averaged power P",
            true,
            false,
            look,
            KIND,
        )?;
        let guide = look.line(GUIDE, 1);
        ch.draw_series(LineSeries::new([(0.0, 1.0), (x_hi, 1.0)], guide))
            .map_err(de)?
            .label("white noise, P = 1")
            .legend(line_sample(guide, look));
        let line = look.line(DATA, 2);
        ch.draw_series(LineSeries::new(pts, line))
            .map_err(de)?
            .label("RAPS")
            .legend(line_sample(line, look));
        legend_box(&mut ch, corner, look, KIND)
    }

    fn csv(&self, data: &ColumnData) -> Result<String, ExportError> {
        let s = present(KIND, data.spectrum.data())?;
        curve("radius,power", &s.raps, KIND)
    }
}
