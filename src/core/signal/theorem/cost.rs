//! What the 1D sampling-theorem view costs. Rates and method: [`crate::core::budget`].

use crate::core::budget::{Estimate, Unit};

/// The 1D sampling-theorem view (bounded by its own limits).
pub(crate) const THEOREM_S: f64 = 0.1;

/// The 1D sampling-theorem view (bounded by its own settings' limits).
pub fn theorem() -> Estimate {
    Estimate::new(
        "sampling-theorem view".into(),
        1.0,
        Unit::Evaluations,
        THEOREM_S,
        8e6,
    )
}
