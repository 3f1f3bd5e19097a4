//! RMSE against samples per pixel, log–log (its timings are never drawn).

use super::csv::curve;
use super::draw::{
    draw_err, empty, log_ticks, present, tick_label, Frame, DATA, DESC_PX, MARGIN, TICK_PX,
    X_LABEL, Y_LABEL,
};
use super::{Area, Figure};
use crate::export::ExportError;
use crate::model::{ColumnData, ConvergencePoint, FigureContext, FigureKind};
use plotters::prelude::*;

/// The convergence figure.
pub(super) struct Convergence;

const KIND: FigureKind = FigureKind::Convergence;

/// Whether a point can be drawn on log–log axes.
fn drawable(p: &ConvergencePoint) -> bool {
    p.spp > 0 && p.rmse.is_finite() && p.rmse > 0.0
}

impl Figure for Convergence {
    fn kind(&self) -> FigureKind {
        KIND
    }

    fn base_size(&self) -> (u32, u32) {
        (640, 510)
    }

    fn title(&self, ctx: &FigureContext, _data: &ColumnData) -> String {
        format!("RMSE vs samples per pixel, {}", ctx.column_title)
    }

    fn panel_title(&self, _ctx: &FigureContext, _data: &ColumnData) -> String {
        "RMSE vs samples per pixel".to_string()
    }

    fn has_data(&self, data: &ColumnData) -> bool {
        data.convergence.is_ready()
    }

    fn check(&self, data: &ColumnData) -> Result<(), ExportError> {
        let c = present(KIND, data.convergence.data())?;
        if !c.iter().any(drawable) {
            return Err(empty(KIND, "no point with spp > 0 and a positive RMSE"));
        }
        Ok(())
    }

    fn draw(&self, f: &mut Frame<'_, '_>, body: &Area<'_>) -> Result<(), ExportError> {
        let de = |e| draw_err(KIND, e);
        let look = f.look;
        let pts: Vec<(f64, f64)> = present(KIND, f.data.convergence.data())?
            .iter()
            .filter(|p| drawable(p))
            .map(|p| (p.spp as f64, p.rmse))
            .collect();
        let (mut x0, mut x1) = (f64::INFINITY, f64::NEG_INFINITY);
        let (mut y0, mut y1) = (f64::INFINITY, f64::NEG_INFINITY);
        for &(x, y) in &pts {
            x0 = x0.min(x);
            x1 = x1.max(x);
            y0 = y0.min(y);
            y1 = y1.max(y);
        }
        let (x0, x1) = (x0 / 1.5, x1 * 1.5);
        let (y0, y1) = (y0 / 1.5, y1 * 1.5);
        let mut ch = ChartBuilder::on(body)
            .margin(look.u(MARGIN))
            .x_label_area_size(look.u(X_LABEL))
            .y_label_area_size(look.u(Y_LABEL))
            .build_cartesian_2d(
                (x0..x1).log_scale().with_key_points(log_ticks(x0, x1)),
                (y0..y1).log_scale().with_key_points(log_ticks(y0, y1)),
            )
            .map_err(de)?;
        ch.configure_mesh()
            .x_desc("samples per pixel")
            .y_desc("RMSE")
            .label_style(look.text(TICK_PX))
            .axis_desc_style(look.text(DESC_PX))
            .axis_style(look.line(BLACK, 1))
            .set_all_tick_mark_size(look.i(5))
            .max_light_lines(0)
            .bold_line_style(look.line(RGBColor(225, 225, 225), 1))
            .x_label_formatter(&tick_label)
            .y_label_formatter(&tick_label)
            .draw()
            .map_err(de)?;
        ch.draw_series(LineSeries::new(pts.iter().copied(), look.line(DATA, 2)))
            .map_err(de)?;
        ch.draw_series(
            pts.iter()
                .map(|&p| Circle::new(p, look.u(3), DATA.filled())),
        )
        .map_err(de)?;
        Ok(())
    }

    fn csv(&self, data: &ColumnData) -> Result<String, ExportError> {
        let c = present(KIND, data.convergence.data())?;
        let pts: Vec<[f64; 2]> = c.iter().map(|p| [p.spp as f64, p.rmse]).collect();
        curve("spp,rmse", &pts, KIND)
    }
}
