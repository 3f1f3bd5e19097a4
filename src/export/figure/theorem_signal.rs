//! The 1D sampling theorem: f(x), the samples f(nT) as stems and the reconstruction f_r(x).

use super::csv::series;
use super::draw::{
    any_finite, axes, chart, draw_err, finite, legend_box, line_sample, padded, stems,
    with_caption, Frame, DATA, GREY, GUIDE, RECON,
};
use super::theorem::{self, view};
use super::{Area, Figure};
use crate::export::ExportError;
use crate::model::{ColumnData, FigureContext, FigureKind};
use plotters::prelude::*;

/// The theorem's signal figure.
pub(super) struct TheoremSignal;

/// What the figure plots (its title, before the theorem's setup).
const WHAT: &str = "f(x), samples f(nT), reconstruction f_r(x)";

const KIND: FigureKind = FigureKind::TheoremSignal;

impl Figure for TheoremSignal {
    fn kind(&self) -> FigureKind {
        KIND
    }

    fn base_size(&self) -> (u32, u32) {
        (640, 510)
    }

    fn title(&self, _ctx: &FigureContext, data: &ColumnData) -> String {
        theorem::title(WHAT, data)
    }

    fn panel_title(&self, _ctx: &FigureContext, _data: &ColumnData) -> String {
        WHAT.to_string()
    }

    fn has_data(&self, data: &ColumnData) -> bool {
        data.theorem.is_ready()
    }

    fn check(&self, data: &ColumnData) -> Result<(), ExportError> {
        theorem::check(KIND, data, |v| any_finite(&v.signal))
    }

    fn draw(&self, f: &mut Frame<'_, '_>, body: &Area<'_>) -> Result<(), ExportError> {
        let de = |e| draw_err(KIND, e);
        let look = f.look;
        let v = view(KIND, f.data)?;
        let plot = with_caption(body, &theorem::caption(f, v), look, KIND)?;
        let ext = v.settings.extent;
        let fx = finite(&v.signal);
        let fr = finite(&v.reconstruction);
        let samples = finite(&v.samples);
        let y = padded(fx.iter().chain(&fr).chain(&samples).map(|p| p.1), &[0.0]);
        let mut ch = chart(&plot, -ext..ext, y, look, KIND)?;
        axes(&mut ch, "x (units)", "value", true, false, look, KIND)?;
        ch.draw_series(LineSeries::new(
            [(-ext, 0.0), (ext, 0.0)],
            look.line(GUIDE, 1),
        ))
        .map_err(de)?;
        let grey = look.line(GREY, 2);
        ch.draw_series(LineSeries::new(fx, grey))
            .map_err(de)?
            .label("f(x)")
            .legend(line_sample(grey, look));
        stems(&mut ch, &samples, DATA, 3, "samples f(nT)", look, KIND)?;
        let orange = look.line(RECON, 2);
        ch.draw_series(LineSeries::new(fr, orange))
            .map_err(de)?
            .label("reconstruction f_r(x)")
            .legend(line_sample(orange, look));
        legend_box(&mut ch, SeriesLabelPosition::UpperRight, look, KIND)
    }

    fn csv(&self, data: &ColumnData) -> Result<String, ExportError> {
        let v = view(KIND, data)?;
        let curves: [(String, &[[f64; 2]]); 3] = [
            ("f".into(), &v.signal),
            ("sample".into(), &v.samples),
            ("f_r".into(), &v.reconstruction),
        ];
        series("series,x,value", &curves, KIND)
    }

    fn metadata(&self, ctx: &FigureContext, data: &ColumnData) -> Vec<(String, String)> {
        theorem::metadata(ctx, data)
    }
}
