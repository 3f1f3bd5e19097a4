//! The 1D sampling theorem: the reconstructed spectrum |F_r(ω)| against |F(ω)|.

use super::csv::series;
use super::draw::{
    any_finite, axes, chart, draw_err, finite, legend_box, line_sample, magnitude_range, max_of,
    nyquist_lines, stems, with_caption, Frame, GREY, RECON,
};
use super::theorem::{self, view};
use super::{Area, Figure};
use crate::export::ExportError;
use crate::model::{ColumnData, FigureContext, FigureKind};
use plotters::prelude::*;

/// The theorem's reconstructed-spectrum figure.
pub(super) struct TheoremReconstructed;

/// What the figure plots (its title, before the theorem's setup).
const WHAT: &str = "reconstructed spectrum |F_r(ω)| vs |F(ω)|";

const KIND: FigureKind = FigureKind::TheoremReconstructed;

impl Figure for TheoremReconstructed {
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
        theorem::check(KIND, data, |v| {
            any_finite(&v.spectrum.original) || any_finite(&v.spectrum.reconstructed_lines)
        })
    }

    fn draw(&self, f: &mut Frame<'_, '_>, body: &Area<'_>) -> Result<(), ExportError> {
        let de = |e| draw_err(KIND, e);
        let look = f.look;
        let v = view(KIND, f.data)?;
        let plot = with_caption(body, &theorem::caption(f, v), look, KIND)?;
        let sp = &v.spectrum;
        let original_lines: &[[f64; 2]] = sp
            .lines
            .iter()
            .find(|(k, _)| *k == 0)
            .map(|(_, c)| c.as_slice())
            .unwrap_or(&[]);
        let hi = max_of(
            [
                sp.original.as_slice(),
                sp.reconstructed.as_slice(),
                original_lines,
                sp.reconstructed_lines.as_slice(),
            ]
            .into_iter(),
        );
        let y = magnitude_range(hi);
        let wm = sp.omega_max;
        let mut ch = chart(&plot, -wm..wm, y.clone(), look, KIND)?;
        axes(
            &mut ch,
            "ω (cycles per unit)",
            "magnitude",
            true,
            false,
            look,
            KIND,
        )?;
        if !sp.original.is_empty() {
            let fl = look.line(GREY, 2);
            ch.draw_series(LineSeries::new(finite(&sp.original), fl))
                .map_err(de)?
                .label("|F(ω)|")
                .legend(line_sample(fl, look));
            let r = look.line(RECON, 2);
            ch.draw_series(LineSeries::new(finite(&sp.reconstructed), r))
                .map_err(de)?
                .label("|F_r(ω)|")
                .legend(line_sample(r, look));
        } else {
            let r = look.u(5);
            ch.draw_series(
                finite(original_lines)
                    .into_iter()
                    .map(|p| Circle::new(p, r, GREY.stroke_width(look.u(2)))),
            )
            .map_err(de)?
            .label("|F| (lines)")
            .legend(move |(x, y)| {
                Circle::new((x + look.i(10), y), r, GREY.stroke_width(look.u(2)))
            });
            stems(
                &mut ch,
                &finite(&sp.reconstructed_lines),
                RECON,
                3,
                "|F_r| (lines)",
                look,
                KIND,
            )?;
        }
        nyquist_lines(&mut ch, v.settings.rate, &y, look, KIND)?;
        legend_box(&mut ch, SeriesLabelPosition::UpperRight, look, KIND)
    }

    fn csv(&self, data: &ColumnData) -> Result<String, ExportError> {
        let sp = &view(KIND, data)?.spectrum;
        let mut curves: Vec<(String, &[[f64; 2]])> = Vec::new();
        if sp.original.is_empty() {
            if let Some((_, c)) = sp.lines.iter().find(|(k, _)| *k == 0) {
                curves.push(("F_line".into(), c));
            }
            curves.push(("F_r_line".into(), &sp.reconstructed_lines));
        } else {
            curves.push(("F".into(), &sp.original));
            curves.push(("F_r".into(), &sp.reconstructed));
        }
        series("series,omega,magnitude", &curves, KIND)
    }

    fn metadata(&self, ctx: &FigureContext, data: &ColumnData) -> Vec<(String, String)> {
        theorem::metadata(ctx, data)
    }
}
