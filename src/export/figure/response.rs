//! The filter's frequency response |H(ω)|, linear or in dB, with the Nyquist line; a
//! low-pass filter's (normalised to H(0) = 1) against the ideal low-pass, a filter that blocks
//! DC (band-pass, high-pass, derivative) raw.

use super::csv::curve;
use super::draw::{
    axes, chart, draw_err, emptiest_corner, finite, legend_box, line_sample, padded, present,
    Frame, DATA, GUIDE, NYQUIST,
};
use super::kernel::{check_curve, filter_name};
use super::{Area, Figure};
use crate::export::ExportError;
use crate::model::{amplitude_db, ColumnData, FigureContext, FigureKind, DB_FLOOR};
use plotters::prelude::*;

/// The frequency-response figure.
pub(super) struct Response;

const KIND: FigureKind = FigureKind::Response;

impl Figure for Response {
    fn kind(&self) -> FigureKind {
        KIND
    }

    fn base_size(&self) -> (u32, u32) {
        (640, 510)
    }

    fn title(&self, _ctx: &FigureContext, _data: &ColumnData) -> String {
        "frequency response |H(ω)|".to_string()
    }

    fn has_data(&self, data: &ColumnData) -> bool {
        data.response.is_ready()
    }

    fn check(&self, data: &ColumnData) -> Result<(), ExportError> {
        check_curve(&present(KIND, data.response.data())?.magnitude, KIND)
    }

    fn draw(&self, f: &mut Frame<'_, '_>, body: &Area<'_>) -> Result<(), ExportError> {
        let de = |e| draw_err(KIND, e);
        let look = f.look;
        let r = present(KIND, f.data.response.data())?;
        let db = f.ctx.response_db;
        let value = |m: f64| if db { amplitude_db(m) } else { m };
        let pts: Vec<(f64, f64)> = finite(&r.magnitude)
            .into_iter()
            .map(|(w, m)| (w, value(m)))
            .collect();
        let w_hi = if r.omega_max.is_finite() && r.omega_max > 0.0 {
            r.omega_max
        } else {
            pts.iter().map(|p| p.0).fold(0.5, f64::max)
        };
        let (one, zero) = if db { (0.0, DB_FLOOR) } else { (1.0, 0.0) };
        // The ideal low-pass is the reference of a low-pass filter (normalised to H(0) = 1);
        // a filter that blocks DC (band-pass, high-pass, derivative) is drawn as it is, with
        // its own scale, and compared with nothing it does not try to be.
        let ideal = r.normalised;
        let guides = [one, zero];
        let y = padded(
            pts.iter().map(|p| p.1),
            if ideal { &guides[..] } else { &guides[1..] },
        );
        // The legend takes the corner the curve and the ideal low-pass leave free.
        let mut drawn = pts.clone();
        if ideal {
            drawn.extend((0..=10).map(|i| (0.05 * i as f64, one)));
            drawn.extend((0..=20).map(|i| (0.5 + (w_hi - 0.5) * i as f64 / 20.0, zero)));
        }
        let corner = emptiest_corner(&drawn, &(0.0..w_hi), &y, SeriesLabelPosition::UpperRight);
        let mut ch = chart(body, 0.0..w_hi, y.clone(), look, KIND)?;
        let y_desc = match (db, ideal) {
            (true, true) => "|H(ω)| / |H(0)|  dB",
            (true, false) => "|H(ω)|  dB",
            (false, true) => "|H(ω)| / |H(0)|",
            (false, false) => "|H(ω)|",
        };
        axes(
            &mut ch,
            "ω (cycles per sample)",
            y_desc,
            true,
            false,
            look,
            KIND,
        )?;
        if ideal {
            let guide = look.line(GUIDE, 1);
            ch.draw_series(LineSeries::new(
                [(0.0, one), (0.5, one), (0.5, zero), (w_hi, zero)],
                guide,
            ))
            .map_err(de)?
            .label("ideal low-pass")
            .legend(line_sample(guide, look));
        }
        let red = look.line(NYQUIST, 1);
        ch.draw_series(LineSeries::new([(0.5, y.start), (0.5, y.end)], red))
            .map_err(de)?
            .label("Nyquist, ω = 0.5")
            .legend(line_sample(red, look));
        let line = look.line(DATA, 2);
        ch.draw_series(LineSeries::new(pts, line))
            .map_err(de)?
            .label(format!("{}, |H(ω)|", filter_name(f.ctx)))
            .legend(line_sample(line, look));
        legend_box(&mut ch, corner, look, KIND)
    }

    fn csv(&self, data: &ColumnData) -> Result<String, ExportError> {
        let r = present(KIND, data.response.data())?;
        curve("omega,magnitude", &r.magnitude, KIND)
    }
}
