//! What a filter's metrics and response curves cost. Rates and method: [`crate::core::budget`].

use crate::core::budget::{Estimate, Unit};
use crate::core::filter::Filter2D;

/// A filter's metrics and curves (the filter panel, `samplescope filter`): fixed quadratures.
pub(crate) const FILTER_METRICS_S: f64 = 0.05;

/// A filter's metrics and response curves (`samplescope filter`, the filter panel).
pub fn filter_metrics(filter: &Filter2D) -> Estimate {
    Estimate::new(
        format!("metrics of the {} filter", filter.filter.name()),
        1.0,
        Unit::Evaluations,
        FILTER_METRICS_S,
        1e6,
    )
}
