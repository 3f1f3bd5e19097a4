//! The 1D sampling theorem: |F(ω)|, the replicas F(ω − k f_s) (one colour per k), the
//! filter's gain |G(ω)| and the Nyquist lines ±f_s/2, with a legend column beside the plot
//! (nine entries in a box would hide the curves).

use super::csv::series;
use super::draw::{
    any_finite, axes, chart, draw_err, finite, fitting_px, magnitude_range, max_of, nyquist_lines,
    replica_colour, stems, with_caption, Frame, GREY, INK, MARGIN, NYQUIST, TICK_PX,
};
use super::theorem::{self, view};
use super::{Area, Figure};
use crate::export::ExportError;
use crate::model::{ColumnData, FigureContext, FigureKind};
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// The theorem's spectrum figure.
pub(super) struct TheoremSpectrum;

/// What the figure plots (its title, before the theorem's setup).
const WHAT: &str = "|F(ω)|, replicas F(ω − k·f_s), filter |G(ω)|";

const KIND: FigureKind = FigureKind::TheoremSpectrum;

/// Width of the legend column right of the plot.
const LEGEND_PART: u32 = 180;

/// How an entry of the legend column is drawn.
pub(super) enum Mark {
    Line(ShapeStyle),
    Dot(RGBColor),
}

/// The legend as a column of entries (a line or dot sample, then the label) from the top of
/// `area`, level with the plot; the labels at the tick size, or smaller where the longest
/// would not fit the column's width.
pub(super) fn legend_column(
    area: &Area<'_>,
    entries: &[(String, Mark)],
    f: &Frame<'_, '_>,
    kind: FigureKind,
) -> Result<(), ExportError> {
    let de = |e| draw_err(kind, e);
    let look = f.look;
    let x0 = look.i(8);
    // The labels at the tick size, or smaller until the longest fits the column.
    let (w, _) = area.dim_in_pixel();
    let room = w.saturating_sub(look.u(8 + 32 + 4));
    let labels: Vec<&str> = entries.iter().map(|(label, _)| label.as_str()).collect();
    let px = fitting_px(area, &labels, room, (TICK_PX, 0.5, 9.0), look, kind)?;
    let style = look.text(px).pos(Pos::new(HPos::Left, VPos::Center));
    let step = look.i(24);
    for (i, (label, mark)) in entries.iter().enumerate() {
        let y = look.i(MARGIN + 12) + step * i as i32;
        match mark {
            Mark::Line(s) => area
                .draw(&PathElement::new(vec![(x0, y), (x0 + look.i(24), y)], *s))
                .map_err(de)?,
            Mark::Dot(c) => area
                .draw(&Circle::new((x0 + look.i(12), y), look.u(4), c.filled()))
                .map_err(de)?,
        }
        area.draw_text(label, &style, (x0 + look.i(32), y))
            .map_err(de)?;
    }
    Ok(())
}

impl Figure for TheoremSpectrum {
    fn kind(&self) -> FigureKind {
        KIND
    }

    /// Wider than the other line plots by its legend column.
    fn base_size(&self) -> (u32, u32) {
        (820, 510)
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
            let sp = &v.spectrum;
            any_finite(&sp.gain)
                && (any_finite(&sp.original) || sp.lines.iter().any(|(_, c)| any_finite(c)))
        })
    }

    fn draw(&self, f: &mut Frame<'_, '_>, body: &Area<'_>) -> Result<(), ExportError> {
        let de = |e| draw_err(KIND, e);
        let look = f.look;
        let v = view(KIND, f.data)?;
        let plot = with_caption(body, &theorem::caption(f, v), look, KIND)?;
        let sp = &v.spectrum;
        let (w, _) = plot.dim_in_pixel();
        let (main, legend_area) = plot.split_horizontally(w - look.u(LEGEND_PART));
        let hi = max_of(
            std::iter::once(sp.original.as_slice())
                .chain(std::iter::once(sp.gain.as_slice()))
                .chain(sp.replicas.iter().map(|(_, c)| c.as_slice()))
                .chain(sp.lines.iter().map(|(_, c)| c.as_slice())),
        );
        let y = magnitude_range(hi);
        let wm = sp.omega_max;
        let mut ch = chart(&main, -wm..wm, y.clone(), look, KIND)?;
        axes(
            &mut ch,
            "ω (cycles per unit)",
            "magnitude",
            true,
            false,
            look,
            KIND,
        )?;
        let mut entries: Vec<(String, Mark)> = Vec::new();
        for (k, c) in &sp.replicas {
            let style = look.line(replica_colour(*k), 2);
            ch.draw_series(LineSeries::new(finite(c), style))
                .map_err(de)?;
            let label = if *k < 0 {
                format!("F(ω + {}·f_s)", -k)
            } else {
                format!("F(ω − {k}·f_s)")
            };
            entries.push((label, Mark::Line(style)));
        }
        for (k, c) in &sp.lines {
            let colour = replica_colour(*k);
            let name = if *k == 0 {
                "|F| (lines)".to_string()
            } else {
                format!("lines, k = {k}")
            };
            stems(&mut ch, &finite(c), colour, 3, &name, look, KIND)?;
            entries.push((name, Mark::Dot(colour)));
        }
        if !sp.original.is_empty() {
            let style = look.line(INK, 3);
            ch.draw_series(LineSeries::new(finite(&sp.original), style))
                .map_err(de)?;
            entries.insert(0, ("|F(ω)|".to_string(), Mark::Line(style)));
        }
        let gain = look.line(GREY, 2);
        ch.draw_series(LineSeries::new(finite(&sp.gain), gain))
            .map_err(de)?;
        entries.push(("|G(ω)| (filter)".to_string(), Mark::Line(gain)));
        nyquist_lines(&mut ch, v.settings.rate, &y, look, KIND)?;
        entries.push((
            "Nyquist ±f_s/2".to_string(),
            Mark::Line(look.line(NYQUIST, 1)),
        ));
        legend_column(&legend_area, &entries, f, KIND)
    }

    fn csv(&self, data: &ColumnData) -> Result<String, ExportError> {
        let sp = &view(KIND, data)?.spectrum;
        let mut curves: Vec<(String, &[[f64; 2]])> = Vec::new();
        if !sp.original.is_empty() {
            curves.push(("F".into(), &sp.original));
        }
        for (k, c) in &sp.replicas {
            curves.push((format!("replica_{k}"), c));
        }
        for (k, c) in &sp.lines {
            curves.push((format!("line_{k}"), c));
        }
        curves.push(("G".into(), &sp.gain));
        series("series,omega,magnitude", &curves, KIND)
    }

    fn metadata(&self, ctx: &FigureContext, data: &ColumnData) -> Vec<(String, String)> {
        theorem::metadata(ctx, data)
    }
}
