//! The theorem panel's transform pair p(x) = g(a(x − s)) and its transform P(ω) side by side
//! (|P|, Re P and Im P; the shah as impulses).

use super::csv::series;
use super::draw::{
    any_finite, axes, chart, draw_err, finite, legend_box, line_sample, padded, stems,
    with_caption, Frame, DATA, INK, RECON,
};
use super::theorem::{self, view};
use super::{Area, Figure};
use crate::export::ExportError;
use crate::model::{ColumnData, FigureContext, FigureKind};
use plotters::prelude::*;

/// The transform-pair figure.
pub(super) struct TheoremPair;

const KIND: FigureKind = FigureKind::TheoremPair;

impl Figure for TheoremPair {
    fn kind(&self) -> FigureKind {
        KIND
    }

    /// Two plots side by side.
    fn base_size(&self) -> (u32, u32) {
        (1000, 510)
    }

    fn title(&self, _ctx: &FigureContext, data: &ColumnData) -> String {
        match data.theorem.data() {
            Some(v) => {
                let p = &v.settings.pair;
                format!(
                    "transform pair {}, scale a = {}, shift s = {}",
                    p.kind.name(),
                    p.scale,
                    p.shift
                )
            }
            None => "transform pair".to_string(),
        }
    }

    fn has_data(&self, data: &ColumnData) -> bool {
        data.theorem.is_ready()
    }

    fn check(&self, data: &ColumnData) -> Result<(), ExportError> {
        theorem::check(KIND, data, |v| {
            let pp = &v.pair;
            (any_finite(&pp.spatial) && any_finite(&pp.magnitude))
                || (any_finite(&pp.impulses_x) && !pp.impulses_omega.is_empty())
        })
    }

    fn draw(&self, f: &mut Frame<'_, '_>, body: &Area<'_>) -> Result<(), ExportError> {
        let de = |e| draw_err(KIND, e);
        let look = f.look;
        let v = view(KIND, f.data)?;
        let plot = with_caption(
            body,
            "p(x) = g(a(x − s))  <->  P(ω) = e^(−2πiωs) G(ω/a) / |a|",
            look,
            KIND,
        )?;
        let pp = &v.pair;
        let (w, _) = plot.dim_in_pixel();
        let (left, right) = plot.split_horizontally(w / 2);
        let shah = !pp.impulses_x.is_empty();
        // Space domain.
        let spatial = if shah {
            finite(&pp.impulses_x)
        } else {
            finite(&pp.spatial)
        };
        let y = padded(spatial.iter().map(|p| p.1), &[0.0]);
        let mut ch = chart(&left, -pp.x_max..pp.x_max, y, look, KIND)?;
        axes(&mut ch, "x", "p(x)", true, false, look, KIND)?;
        if shah {
            stems(
                &mut ch,
                &spatial,
                DATA,
                3,
                "impulses, weight 1/|a|",
                look,
                KIND,
            )?;
        } else {
            let line = look.line(DATA, 2);
            ch.draw_series(LineSeries::new(spatial, line))
                .map_err(de)?
                .label("p(x) = g(a(x − s))")
                .legend(line_sample(line, look));
        }
        legend_box(&mut ch, SeriesLabelPosition::UpperRight, look, KIND)?;
        // Frequency domain.
        let (re, im): (Vec<_>, Vec<_>) = if shah {
            (
                pp.impulses_omega.iter().map(|i| (i[0], i[1])).collect(),
                pp.impulses_omega.iter().map(|i| (i[0], i[2])).collect(),
            )
        } else {
            (finite(&pp.re), finite(&pp.im))
        };
        let magnitude = finite(&pp.magnitude);
        let has_im = im.iter().any(|p| p.1.abs() > 1e-12);
        let y = padded(re.iter().chain(&im).chain(&magnitude).map(|p| p.1), &[0.0]);
        let mut ch = chart(&right, -pp.omega_max..pp.omega_max, y, look, KIND)?;
        axes(&mut ch, "ω", "P(ω)", true, false, look, KIND)?;
        if shah {
            stems(&mut ch, &re, DATA, 3, "Re P (impulses)", look, KIND)?;
            if has_im {
                stems(&mut ch, &im, RECON, 2, "Im P (impulses)", look, KIND)?;
            }
        } else {
            let abs = look.line(INK, 2);
            ch.draw_series(LineSeries::new(magnitude, abs))
                .map_err(de)?
                .label("|P(ω)|")
                .legend(line_sample(abs, look));
            let re_style = look.line(DATA, 1);
            ch.draw_series(LineSeries::new(re, re_style))
                .map_err(de)?
                .label("Re P(ω)")
                .legend(line_sample(re_style, look));
            if has_im {
                let im_style = look.line(RECON, 1);
                ch.draw_series(LineSeries::new(im, im_style))
                    .map_err(de)?
                    .label("Im P(ω)")
                    .legend(line_sample(im_style, look));
            }
        }
        legend_box(&mut ch, SeriesLabelPosition::UpperRight, look, KIND)
    }

    fn csv(&self, data: &ColumnData) -> Result<String, ExportError> {
        let pp = &view(KIND, data)?.pair;
        let impulse_re: Vec<[f64; 2]> = pp.impulses_omega.iter().map(|i| [i[0], i[1]]).collect();
        let impulse_im: Vec<[f64; 2]> = pp.impulses_omega.iter().map(|i| [i[0], i[2]]).collect();
        let curves: Vec<(String, &[[f64; 2]])> = if pp.impulses_x.is_empty() {
            vec![
                ("p".into(), &pp.spatial),
                ("abs_P".into(), &pp.magnitude),
                ("re_P".into(), &pp.re),
                ("im_P".into(), &pp.im),
            ]
        } else {
            vec![
                ("impulse_x".into(), &pp.impulses_x),
                ("impulse_re".into(), &impulse_re),
                ("impulse_im".into(), &impulse_im),
            ]
        };
        series("series,position,value", &curves, KIND)
    }

    fn metadata(&self, ctx: &FigureContext, data: &ColumnData) -> Vec<(String, String)> {
        theorem::metadata(ctx, data)
    }
}
