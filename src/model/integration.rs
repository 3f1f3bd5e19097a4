//! The integration-error study of a column, and the curves of every column that the panel
//! and its figure draw on one plot.

use super::ImageData;
use crate::core::integration::Study;
use std::sync::Arc;

/// One column's study: its rows (MSE per N with standard errors), fitted slope and exact
/// integral, how many of the asked realizations are in, and a small image of the integrand.
#[derive(Debug, Clone)]
pub struct IntegrationData {
    pub study: Study,
    /// Realizations in this result (`of` when final).
    pub done: usize,
    /// Realizations asked.
    pub of: usize,
    /// The integrand's name and parameters, e.g. `disk cx=0.5 cy=0.5 r=0.3`.
    pub integrand: String,
    /// Whether each realization drew a random instance of the integrand's family.
    pub randomized: bool,
    /// f on a small grid over [0,1]² (row 0 at the top), for the integrand picker's preview.
    pub thumbnail: ImageData,
}

/// One curve of the integration plot.
#[derive(Debug, Clone)]
pub struct IntegrationCurve {
    /// The column's label.
    pub label: String,
    pub data: Arc<IntegrationData>,
}

/// Every column's study, in column order (columns without one are left out): what the
/// integration figure draws.
#[derive(Debug, Clone, Default)]
pub struct IntegrationPlot {
    pub curves: Vec<IntegrationCurve>,
}

/// The reference lines of the plot: N^slope for these slopes (MSE convergence rates of random
/// sampling, of jittered sampling of discontinuities, and of smooth integrands under
/// stratified and Owen-scrambled sampling).
pub const GUIDE_SLOPES: [f64; 4] = [-1.0, -1.5, -2.0, -3.0];

/// The guide line of `slope` through the point (n0, mse0): its values at `n_lo` and `n_hi`.
pub fn guide_line(slope: f64, n0: f64, mse0: f64, n_lo: f64, n_hi: f64) -> [(f64, f64); 2] {
    [
        (n_lo, mse0 * (n_lo / n0).powf(slope)),
        (n_hi, mse0 * (n_hi / n0).powf(slope)),
    ]
}

impl IntegrationPlot {
    /// The point the guide lines pass through: the first row with a positive MSE of the first
    /// curve that has one (the guides then start at the data).
    pub fn anchor(&self) -> Option<(f64, f64)> {
        self.curves.iter().find_map(|c| {
            c.data
                .study
                .rows
                .iter()
                .find(|r| r.mse > 0.0 && r.mse.is_finite())
                .map(|r| (r.n as f64, r.mse))
        })
    }

    /// The N and MSE ranges of every drawable point, error bars included:
    /// ((n_lo, n_hi), (mse_lo, mse_hi)).
    pub fn ranges(&self) -> Option<((f64, f64), (f64, f64))> {
        let mut n = (f64::INFINITY, f64::NEG_INFINITY);
        let mut m = (f64::INFINITY, f64::NEG_INFINITY);
        for c in &self.curves {
            for r in &c.data.study.rows {
                if !(r.mse > 0.0 && r.mse.is_finite()) {
                    continue;
                }
                let se = r.mse_stderr.unwrap_or(0.0);
                let lo = if r.mse - se > 0.0 { r.mse - se } else { r.mse };
                n = (n.0.min(r.n as f64), n.1.max(r.n as f64));
                m = (m.0.min(lo), m.1.max(r.mse + se));
            }
        }
        (n.0 <= n.1).then_some((n, m))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_guide_line_has_its_slope_on_log_log_axes() {
        let [(x0, y0), (x1, y1)] = guide_line(-1.5, 16.0, 1e-3, 4.0, 4096.0);
        let slope = (y1.ln() - y0.ln()) / (x1.ln() - x0.ln());
        assert!((slope + 1.5).abs() < 1e-12, "{slope}");
        // Through the anchor: at n0 the line is mse0.
        let [(_, y), _] = guide_line(-3.0, 16.0, 1e-3, 16.0, 64.0);
        assert_eq!(y, 1e-3);
    }
}
