//! The integration-error study: MSE of the Monte Carlo estimate against N on log–log axes,
//! every column on one plot (colour per column, ±1 standard-error bars, the fitted slope in
//! the legend) with grey guide lines N^s, s = −1, −1.5, −2, −3, through the first point.

use super::draw::{draw_err, log_ticks, tick_label, with_caption, Frame, DESC_PX, GUIDE, TICK_PX};
use super::draw::{MARGIN, X_LABEL, Y_LABEL};
use super::theorem_spectrum::{legend_column, Mark};
use super::{Area, Figure};
use crate::export::ExportError;
use crate::model::{
    guide_line, palette, ColumnData, FigureContext, FigureKind, IntegrationPlot, GUIDE_SLOPES,
};
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// The integration figure.
pub(super) struct Integration;

const KIND: FigureKind = FigureKind::Integration;

/// Width of the legend column right of the plot.
const LEGEND_PART: u32 = 250;

fn plot_of(data: &ColumnData) -> Result<&IntegrationPlot, ExportError> {
    data.integration_plot
        .as_deref()
        .ok_or_else(|| super::draw::missing(KIND))
}

/// The powers of ten in [lo, hi] (every other one beyond eight decades), or the 1-2-5 ticks
/// when fewer than two powers fall inside.
fn decades(lo: f64, hi: f64) -> Vec<f64> {
    let (k0, k1) = (lo.log10().ceil() as i32, hi.log10().floor() as i32);
    if k1 - k0 < 1 {
        return log_ticks(lo, hi);
    }
    let step = if k1 - k0 > 8 { 2 } else { 1 };
    (k0..=k1).step_by(step).map(|k| 10f64.powi(k)).collect()
}

/// An MSE tick: 10⁻³ (written `10^-3`, drawn as a power) for a power of ten, else 2e-3.
fn mse_label(v: &f64) -> String {
    let k = v.log10().round();
    if (v / 10f64.powf(k) - 1.0).abs() < 1e-9 {
        format!("10^{k}")
    } else {
        format!("{v:.0e}")
    }
}

/// "label: slope −1.52 ± 0.03" (or "no slope" with fewer than two usable N).
pub fn legend_label(label: &str, slope: Option<f64>, stderr: Option<f64>) -> String {
    match (slope, stderr) {
        (Some(s), Some(e)) => format!("{label}: slope {} ± {e:.2}", signed(s)),
        (Some(s), None) => format!("{label}: slope {}", signed(s)),
        _ => format!("{label}: no slope"),
    }
}

/// A slope with a true minus sign.
fn signed(s: f64) -> String {
    let t = format!("{s:.2}");
    t.replacen('-', "−", 1)
}

/// The caption: integrand, realizations in, what the bars and guides are.
fn caption(plot: &IntegrationPlot) -> String {
    let Some(first) = plot.curves.first() else {
        return String::new();
    };
    let d = &first.data;
    let done = plot.curves.iter().map(|c| c.data.done).min().unwrap_or(0);
    let random = if d.randomized {
        " (random instances)"
    } else {
        ""
    };
    format!(
        "{}{random}, R = {done} of {} realizations; bars ±1 s.e.; grey: N^s, s = −1, −1.5, −2, −3",
        d.integrand, d.of
    )
}

impl Figure for Integration {
    fn kind(&self) -> FigureKind {
        KIND
    }

    /// Wider than the other line plots by its legend column.
    fn base_size(&self) -> (u32, u32) {
        (900, 510)
    }

    fn title(&self, _ctx: &FigureContext, data: &ColumnData) -> String {
        let integrand = plot_of(data)
            .ok()
            .and_then(|p| p.curves.first())
            .map(|c| c.data.integrand.split(' ').next().unwrap_or("").to_string())
            .unwrap_or_default();
        format!("Monte Carlo integration error of the {integrand} integrand: MSE against N")
    }

    fn has_data(&self, data: &ColumnData) -> bool {
        data.integration_plot.is_some()
    }

    fn check(&self, data: &ColumnData) -> Result<(), ExportError> {
        let plot = plot_of(data)?;
        if plot.ranges().is_none() {
            return Err(super::draw::empty(KIND, "no N with a positive MSE"));
        }
        Ok(())
    }

    fn draw(&self, f: &mut Frame<'_, '_>, body: &Area<'_>) -> Result<(), ExportError> {
        let de = |e| draw_err(KIND, e);
        let look = f.look;
        let plot = plot_of(f.data)?;
        let ((n_lo, n_hi), (m_lo, m_hi)) = plot
            .ranges()
            .ok_or_else(|| super::draw::empty(KIND, "no N with a positive MSE"))?;
        let area = with_caption(body, &caption(plot), look, KIND)?;
        let (w, _) = area.dim_in_pixel();
        let (main, legend_area) = area.split_horizontally(w - look.u(LEGEND_PART));
        let (x0, x1) = (n_lo / 1.5, n_hi * 1.5);
        let (y0, y1) = (m_lo / 3.0, m_hi * 3.0);
        let mut ch = ChartBuilder::on(&main)
            .margin(look.u(MARGIN))
            .x_label_area_size(look.u(X_LABEL))
            .y_label_area_size(look.u(Y_LABEL + 10))
            .build_cartesian_2d(
                (x0..x1).log_scale().with_key_points(log_ticks(x0, x1)),
                (y0..y1).log_scale().with_key_points(decades(y0, y1)),
            )
            .map_err(de)?;
        ch.configure_mesh()
            .x_desc("N (samples)")
            .y_desc("MSE")
            .label_style(look.text(TICK_PX))
            .axis_desc_style(look.text(DESC_PX))
            .axis_style(look.line(BLACK, 1))
            .set_all_tick_mark_size(look.i(5))
            .max_light_lines(0)
            .bold_line_style(look.line(RGBColor(232, 232, 232), 1))
            .x_label_formatter(&tick_label)
            .y_label_formatter(&mse_label)
            .draw()
            .map_err(de)?;
        // Guides, clipped to the plot, labelled with their slope at their right end.
        if let Some((n0, mse0)) = plot.anchor() {
            let text = look.text(TICK_PX).color(&GUIDE);
            for s in GUIDE_SLOPES {
                // Where the guide leaves the plot at the bottom, it ends there.
                let x_end = (n0 * (y0 / mse0).powf(1.0 / s)).min(x1 / 1.2);
                let [a, b] = guide_line(s, n0, mse0, n0, x_end);
                ch.draw_series(DashedLineSeries::new(
                    [a, b],
                    look.u(6),
                    look.u(4),
                    look.line(GUIDE, 1),
                ))
                .map_err(de)?;
                let label = crate::core::params::fmt_num(s).replacen('-', "−", 1);
                let anchor = if b.1 <= y0 * 1.01 {
                    Pos::new(HPos::Center, VPos::Bottom)
                } else {
                    Pos::new(HPos::Left, VPos::Center)
                };
                ch.draw_series(std::iter::once(Text::new(
                    label,
                    b,
                    text.clone().pos(anchor),
                )))
                .map_err(de)?;
            }
        }
        let mut entries: Vec<(String, Mark)> = Vec::new();
        for (i, c) in plot.curves.iter().enumerate() {
            let [r, g, b] = palette::series(i);
            let colour = RGBColor(r, g, b);
            let rows: Vec<_> = c
                .data
                .study
                .rows
                .iter()
                .filter(|r| r.mse > 0.0 && r.mse.is_finite())
                .collect();
            let mut pts: Vec<(f64, f64)> = rows.iter().map(|r| (r.n as f64, r.mse)).collect();
            pts.sort_by(|a, b| a.0.total_cmp(&b.0));
            // Error bars ±1 s.e. (down to the axis where mse − s.e. ≤ 0), capped; the caps
            // span ±1 % of the N axis' decades.
            let cap = (x1 / x0).powf(0.01);
            for r in &rows {
                if let Some(se) = r.mse_stderr.filter(|s| *s > 0.0 && s.is_finite()) {
                    let x = r.n as f64;
                    let lo = if r.mse - se > y0 { r.mse - se } else { y0 };
                    let hi = (r.mse + se).min(y1);
                    let style = look.line(colour, 1);
                    ch.draw_series(
                        [
                            vec![(x, lo), (x, hi)],
                            vec![(x / cap, lo), (x * cap, lo)],
                            vec![(x / cap, hi), (x * cap, hi)],
                        ]
                        .into_iter()
                        .map(|seg| PathElement::new(seg, style)),
                    )
                    .map_err(de)?;
                }
            }
            let style = look.line(colour, 2);
            ch.draw_series(LineSeries::new(pts.iter().copied(), style))
                .map_err(de)?;
            ch.draw_series(
                pts.iter()
                    .map(|&p| Circle::new(p, look.u(3), colour.filled())),
            )
            .map_err(de)?;
            entries.push((
                legend_label(&c.label, c.data.study.slope, c.data.study.slope_stderr),
                Mark::Line(style),
            ));
        }
        legend_column(&legend_area, &entries, f, KIND)
    }

    fn csv(&self, data: &ColumnData) -> Result<String, ExportError> {
        let plot = plot_of(data)?;
        let mut s = String::from("column,n,mse,mse_stderr,variance,bias2,realizations\n");
        for c in &plot.curves {
            let label = c.label.replace([',', '"', '\n'], " ");
            for r in &c.data.study.rows {
                let se = r.mse_stderr.map(|e| e.to_string()).unwrap_or_default();
                s.push_str(&format!(
                    "{label},{},{},{se},{},{},{}\n",
                    r.n, r.mse, r.variance, r.bias2, c.data.done
                ));
            }
        }
        Ok(s)
    }

    /// The scene, the integrand and every column's pattern and slope (no N or seed: each
    /// column has its own seed and the curve spans many N).
    fn metadata(&self, ctx: &FigureContext, data: &ColumnData) -> Vec<(String, String)> {
        let mut m = vec![("scene".to_string(), ctx.scene_title.clone())];
        if let Ok(plot) = plot_of(data) {
            if let Some(c) = plot.curves.first() {
                m.push(("integrand".into(), c.data.integrand.clone()));
                m.push((
                    "realizations".into(),
                    format!("{} of {}", c.data.done, c.data.of),
                ));
            }
            for (i, c) in plot.curves.iter().enumerate() {
                m.push((
                    format!("column {}", i + 1),
                    legend_label(&c.label, c.data.study.slope, c.data.study.slope_stderr),
                ));
            }
        }
        m
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn legend_labels_carry_the_slope_with_a_true_minus() {
        assert_eq!(
            legend_label("jitter", Some(-1.5234), Some(0.031)),
            "jitter: slope −1.52 ± 0.03"
        );
        assert_eq!(legend_label("grid", Some(-2.0), None), "grid: slope −2.00");
        assert_eq!(legend_label("x", None, None), "x: no slope");
    }
}
