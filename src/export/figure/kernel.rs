//! The filter kernel h(x).

use super::csv::curve;
use super::draw::{
    any_finite, axes, chart, draw_err, emptiest_corner, empty, finite, legend_box, line_sample,
    padded, present, Frame, DATA, GUIDE,
};
use super::{Area, Figure};
use crate::export::ExportError;
use crate::model::{ColumnData, FigureContext, FigureKind};
use plotters::prelude::*;

/// The kernel figure.
pub(super) struct Kernel;

const KIND: FigureKind = FigureKind::Kernel;

/// The filter's name as the legends show it (the `kind` tag of its RON text).
pub(super) fn filter_name(ctx: &FigureContext) -> String {
    ctx.filter
        .split("kind:\"")
        .nth(1)
        .and_then(|s| s.split('"').next())
        .unwrap_or("h")
        .to_string()
}

/// Refuses a filter curve without a finite point.
pub(super) fn check_curve(curve: &[[f64; 2]], kind: FigureKind) -> Result<(), ExportError> {
    if !any_finite(curve) {
        return Err(empty(kind, "the curve has no finite point"));
    }
    Ok(())
}

impl Figure for Kernel {
    fn kind(&self) -> FigureKind {
        KIND
    }

    fn base_size(&self) -> (u32, u32) {
        (640, 510)
    }

    fn title(&self, _ctx: &FigureContext, _data: &ColumnData) -> String {
        "kernel h(x)".to_string()
    }

    fn has_data(&self, data: &ColumnData) -> bool {
        data.response.is_ready()
    }

    fn check(&self, data: &ColumnData) -> Result<(), ExportError> {
        check_curve(&present(KIND, data.response.data())?.kernel, KIND)
    }

    fn draw(&self, f: &mut Frame<'_, '_>, body: &Area<'_>) -> Result<(), ExportError> {
        let de = |e| draw_err(KIND, e);
        let look = f.look;
        let pts = finite(&present(KIND, f.data.response.data())?.kernel);
        let x0 = pts.iter().map(|p| p.0).fold(f64::INFINITY, f64::min);
        let x1 = pts.iter().map(|p| p.0).fold(f64::NEG_INFINITY, f64::max);
        let x = if x1 > x0 {
            x0..x1
        } else {
            (x0 - 1.0)..(x0 + 1.0)
        };
        let y = padded(pts.iter().map(|p| p.1), &[0.0]);
        let corner = emptiest_corner(&pts, &x, &y, SeriesLabelPosition::UpperRight);
        let mut ch = chart(body, x.clone(), y, look, KIND)?;
        axes(
            &mut ch,
            "x (sample spacings)",
            "h(x)",
            true,
            false,
            look,
            KIND,
        )?;
        ch.draw_series(LineSeries::new(
            [(x.start, 0.0), (x.end, 0.0)],
            look.line(GUIDE, 1),
        ))
        .map_err(de)?;
        let line = look.line(DATA, 2);
        ch.draw_series(LineSeries::new(pts, line))
            .map_err(de)?
            .label(filter_name(f.ctx))
            .legend(line_sample(line, look));
        legend_box(&mut ch, corner, look, KIND)
    }

    fn csv(&self, data: &ColumnData) -> Result<String, ExportError> {
        curve("x,h", &present(KIND, data.response.data())?.kernel, KIND)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn missing_data_is_an_error_naming_the_figure() {
        let e = Kernel.csv(&ColumnData::default()).unwrap_err().to_string();
        assert!(e.starts_with("kernel:"), "{e}");
    }
}
