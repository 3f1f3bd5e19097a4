//! The sampling-theorem view's settings ([`TheoremSettings`], part of a scene) and their checks.

use super::errors::check_width_samples;
use super::{
    Reconstructor, Signal1D, TheoremError, TransformPair, ERROR_BAND, EXTENT_RANGE, MAX_RATE,
    MAX_SAMPLES, MAX_VDC_ROWS, MIN_RATE,
};
use crate::core::filter::Filter;
use crate::core::params::{declare_params, ParamError, Params};
use serde::{Deserialize, Serialize};

/// Everything the sampling-theorem view shows (part of a scene).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct TheoremSettings {
    /// The signal.
    pub signal: Signal1D,
    /// Sampling rate f_s (samples per unit), in [0.05, 1000]; this and `extent`, `vdc_rows`
    /// have descriptors (below).
    pub rate: f64,
    /// The reconstruction filter (sample-spacing units, scaled to T = 1/f_s).
    pub filter: Filter,
    /// Half-width of the spatial plots (units), in [0.1, 1000].
    pub extent: f64,
    /// The transform-pair sub-view.
    pub pair: TransformPair,
    /// Rows i = 0..vdc_rows of the van der Corput table (base 2), in 1..=1024.
    pub vdc_rows: usize,
}

impl Default for TheoremSettings {
    fn default() -> Self {
        TheoremSettings {
            signal: Signal1D::default(),
            rate: 4.0,
            filter: Filter::Tent(crate::core::filter::Tent { radius: 1.0 }),
            extent: 3.0,
            pair: TransformPair::default(),
            vdc_rows: 8,
        }
    }
}

declare_params! {
    impl TheoremSettings = "theorem" {
        rate: float(4.0, MIN_RATE, MAX_RATE, "sampling rate f_s (samples per unit)"),
        extent: float(3.0, EXTENT_RANGE.0, EXTENT_RANGE.1, "half-width of the spatial plots (units)"),
        vdc_rows: count(8, 1, MAX_VDC_ROWS, "rows i = 0..n of the van der Corput table (base 2)"),
    }
}

impl TheoremSettings {
    /// Checks every field; the error names it (`theorem.rate`, `theorem.signal.width`, …).
    pub fn validate(&self) -> Result<(), TheoremError> {
        self.signal.validate()?;
        self.check_params().map_err(|e| match e {
            ParamError::Invalid {
                field,
                value,
                allowed,
                ..
            } => TheoremError::InvalidParam {
                field,
                value,
                allowed,
            },
            other => TheoremError::Param(other),
        })?;
        check_width_samples(&self.signal, self.rate)?;
        Reconstructor::new(self.filter, self.rate, ERROR_BAND * self.rate)?;
        self.pair.validate()?;
        if 2.0 * (self.extent * self.rate).floor() + 1.0 > MAX_SAMPLES as f64 {
            return Err(TheoremError::InvalidParam {
                field: "rate",
                value: format!("{}", self.rate),
                allowed: format!(
                    "at most {MAX_SAMPLES} samples in the window: 2·extent·rate + 1 ≤ {MAX_SAMPLES} (extent = {})",
                    self.extent
                ),
            });
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn serde_round_trip_of_settings() {
        let s = TheoremSettings::default();
        let text = ron::to_string(&s).unwrap();
        let back: TheoremSettings = ron::from_str(&text).unwrap();
        assert_eq!(back, s);
        for sig in Signal1D::all() {
            let t = ron::to_string(&sig).unwrap();
            assert_eq!(ron::from_str::<Signal1D>(&t).unwrap(), sig, "{t}");
            sig.validate().unwrap();
        }
    }
}
