//! Test signals for sampling and reconstruction.
//!
//! A signal is a small `Copy` parameter struct; [`Signal`] is the enum that dispatches over
//! them (serde: internally tagged, `{"kind": "zone-plate", "k": 256, ...}`).
//!
//! ## Conventions
//! - **Domain.** [`Signal::eval`]`(p)` takes p in image coordinates: the image is the unit square
//!   [0,1)², x to the right, y **downwards** (row j of a W×W image covers y ∈ [j/W, (j+1)/W),
//!   row 0 is drawn at the top). Signals are defined on the whole plane (they are not periodic),
//!   but only [0,1)² is ever sampled.
//! - **Range.** Every value lies in [0, 1] (results are clamped against the last ulp).
//! - **Frequencies** are in cycles per unit: a W×W grid has Nyquist W/2.
//! - **Angles** are in degrees.
//! - **Phases** are carried in units of π in double-double and reduced modulo 2 exactly before
//!   [`exact::sin_pi`]; nothing is evaluated in `f32` (see [`zone_plate`] for the error bound).
//! - **1D view.** [`Signal::eval1`]`(x)` is the 1D signal itself for the 1D signals
//!   ([`oned`]), and the scan line y = ½ of the 2D ones.
//!
//! | signal | module | what it shows |
//! |---|---|---|
//! | zone plate ½(1 + sin(πK\|p − c\|²)) | [`zone_plate`] | aliasing: rings that are not in the signal |
//! | Duff's perspective checkerboard | [`checkerboard`] | moiré towards the horizon, supersampling |
//! | grating ½(1 + sin(2πf n·p)) | [`shapes`] | a single frequency: aliasing into another frequency |
//! | step edge | [`shapes`] | jaggies, ringing of sinc-like filters |
//! | slanted polygon | [`shapes`] | jaggies, thin features breaking up |
//! | sum of sines, chirp, square wave | [`oned`] | the 1D sampling theorem |
//! | constant | [`oned`] | reconstruction must reproduce it exactly |

pub mod checkerboard;
pub mod exact;
pub mod oned;
pub mod shapes;
pub mod theorem;
pub mod zone_plate;

pub use checkerboard::{Checkerboard, PreparedCheckerboard};
pub use exact::{cos_pi, sin_pi, sinc_pi};
pub use oned::{Chirp, Constant, Square, SumOfSines};
pub use shapes::{Grating, Polygon, PolygonShape, StepEdge};
pub use zone_plate::ZonePlate;

use crate::core::family::family;
use crate::core::params::{ParamError, Params};
use glam::DVec2;

/// A parameter of a signal is unknown, malformed or out of its range.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SignalError {
    /// `signal.field = value` is not allowed; the error says what is.
    #[error(transparent)]
    Param(#[from] ParamError),
}

family! {
    /// Every test signal, as a small parameter struct per variant.
    Signal = "signal", "signals" {
        /// ½(1 + sin(π K |p − c|²)).
        ZonePlate(ZonePlate) = "zone-plate",
        /// Tom Duff's perspective checkerboard.
        Checkerboard(Checkerboard) = "checkerboard",
        /// ½(1 + sin(2π f n·p)).
        Grating(Grating) = "grating",
        /// 1 on one side of a line, 0 on the other.
        StepEdge(StepEdge) = "step-edge",
        /// A filled convex polygon with slanted edges.
        Polygon(Polygon) = "polygon",
        /// 1D: ½(1 + Σ aₖ sin(2π fₖ x)).
        SumOfSines(SumOfSines) = "sum-of-sines",
        /// 1D: linear chirp from f₀ to f₁.
        Chirp(Chirp) = "chirp",
        /// 1D: square wave.
        Square(Square) = "square",
        /// The constant field.
        Constant(Constant) = "constant",
    }
    impl {
        const ALIASES: &'static [(&'static str, &'static str)] = &[("zoneplate", "zone-plate")];
    }
}

impl Default for Signal {
    fn default() -> Self {
        Signal::ZonePlate(ZonePlate::default())
    }
}

impl Signal {
    /// Whether this is a 1D signal (constant along y).
    pub fn is_1d(&self) -> bool {
        matches!(
            self,
            Signal::SumOfSines(_) | Signal::Chirp(_) | Signal::Square(_) | Signal::Constant(_)
        )
    }

    /// Checks every parameter against its range; the error names the signal and the field.
    pub fn validate(&self) -> Result<(), SignalError> {
        Ok(self.check_params()?)
    }

    /// The signal's value at image point p, in [0, 1].
    ///
    /// Parameters are assumed valid ([`Signal::validate`]); with invalid ones the result is
    /// unspecified (possibly NaN) but the call never panics.
    #[inline]
    pub fn eval(&self, p: DVec2) -> f64 {
        match self {
            Signal::ZonePlate(s) => s.eval(p),
            Signal::Checkerboard(s) => s.eval(p),
            Signal::Grating(s) => s.eval(p),
            Signal::StepEdge(s) => s.eval(p),
            Signal::Polygon(s) => s.eval(p),
            Signal::SumOfSines(s) => s.eval1(p.x),
            Signal::Chirp(s) => s.eval1(p.x),
            Signal::Square(s) => s.eval1(p.x),
            Signal::Constant(s) => s.value,
        }
    }

    /// The signal ready for evaluating many points: per-signal constants (the checkerboard's
    /// rotation) computed once. [`PreparedSignal::eval`] gives exactly the bits of
    /// [`Signal::eval`].
    #[inline]
    pub fn prepare(&self) -> PreparedSignal<'_> {
        match self {
            Signal::Checkerboard(c) => PreparedSignal::Checkerboard(c.prepare()),
            other => PreparedSignal::Plain(other),
        }
    }

    /// The 1D view: the signal itself for 1D signals, the scan line y = ½ for 2D ones.
    #[inline]
    pub fn eval1(&self, x: f64) -> f64 {
        self.eval(DVec2::new(x, 0.5))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_are_valid_and_in_unit_range() {
        for s in Signal::all() {
            s.validate().unwrap();
            for j in 0..37 {
                for i in 0..37 {
                    let p = DVec2::new(i as f64 / 37.0, j as f64 / 37.0);
                    let v = s.eval(p);
                    assert!((0.0..=1.0).contains(&v), "{} at {p}: {v}", s.name());
                }
            }
        }
    }

    #[test]
    fn serde_round_trip_with_kind_tag() {
        for s in Signal::all() {
            let json = serde_json::to_string(&s).unwrap();
            assert!(
                json.contains(&format!("\"kind\":\"{}\"", s.name())),
                "{json}"
            );
            let back: Signal = serde_json::from_str(&json).unwrap();
            assert_eq!(back, s);
        }
        let z: Signal = serde_json::from_str(r#"{"kind":"zone-plate","k":100}"#).unwrap();
        assert_eq!(
            z,
            Signal::ZonePlate(ZonePlate {
                k: 100.0,
                ..ZonePlate::default()
            })
        );
    }

    #[test]
    fn invalid_params_name_the_field() {
        let cases = [
            (
                Signal::ZonePlate(ZonePlate {
                    k: f64::NAN,
                    ..Default::default()
                }),
                "zone-plate.k",
            ),
            (
                Signal::Checkerboard(Checkerboard {
                    height: 0.0,
                    ..Default::default()
                }),
                "checkerboard.height",
            ),
            (
                Signal::Grating(Grating {
                    frequency: -1.0,
                    ..Default::default()
                }),
                "grating.frequency",
            ),
            (
                Signal::StepEdge(StepEdge {
                    offset: 2.0,
                    ..Default::default()
                }),
                "step-edge.offset",
            ),
            (
                Signal::Polygon(Polygon {
                    size: 0.0,
                    ..Default::default()
                }),
                "polygon.size",
            ),
            (
                Signal::Chirp(Chirp {
                    f1: f64::INFINITY,
                    ..Default::default()
                }),
                "chirp.f1",
            ),
            (
                Signal::Square(Square { frequency: 0.0 }),
                "square.frequency",
            ),
            (Signal::Constant(Constant { value: 1.5 }), "constant.value"),
        ];
        for (s, field) in cases {
            let e = s.validate().unwrap_err().to_string();
            assert!(e.starts_with(field), "{e}");
            assert!(e.contains("must be"), "{e}");
        }
    }

    #[test]
    fn eval1_is_scan_line_for_2d_signals() {
        let z = Signal::ZonePlate(ZonePlate::default());
        assert_eq!(z.eval1(0.3), z.eval(DVec2::new(0.3, 0.5)));
        let s = Signal::Square(Square { frequency: 2.0 });
        assert_eq!(s.eval(DVec2::new(0.1, 0.9)), s.eval1(0.1));
    }
}

/// A [`Signal`] prepared for many evaluations ([`Signal::prepare`]).
#[derive(Debug, Clone, Copy)]
pub enum PreparedSignal<'a> {
    Checkerboard(PreparedCheckerboard),
    Plain(&'a Signal),
}

impl PreparedSignal<'_> {
    /// The same value as [`Signal::eval`], bit for bit.
    #[inline]
    pub fn eval(&self, p: DVec2) -> f64 {
        match self {
            PreparedSignal::Checkerboard(c) => c.eval(p),
            PreparedSignal::Plain(s) => s.eval(p),
        }
    }
}
