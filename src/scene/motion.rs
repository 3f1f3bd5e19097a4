//! Motion: a scene's signal moving over time (drift and rotation), for the lecture's point that
//! uniform sampling of a moving pattern flickers and strobes coherently while jitter turns the
//! same aliasing into noise.
//!
//! ## The moved signal
//! A [`Motion`] is a rigid motion of the image plane that grows with time t (seconds):
//!
//! M_t(p) = R(θ(t)) (p − q) + q + v t,  θ(t) = ω t,
//!
//! with the drift velocity v (image units per second, x to the right, y downwards), the angular
//! velocity ω (degrees per second, measured like every angle of the signals: from +x towards +y,
//! i.e. clockwise on screen) and the pivot q. The signal at time t is s_t(p) = s(M_t⁻¹(p)): the
//! pattern is carried along by M_t. [`signal_at`] expresses s_t exactly as a signal of the same
//! kind with moved parameters (no resampling, no interpolation):
//!
//! | signal | moved parameters |
//! |---|---|
//! | zone plate | centre c → M_t(c) (the zone plate is symmetric about its centre) |
//! | grating | angle θ₀ → θ₀ + θ, phase φ → φ + f (n·q − n′·(q + v t)) with n′ = n(θ₀ + θ) |
//! | step edge | angle θ₀ → θ₀ + θ, offset → offset + n′·(q + v t − h) − n·(q − h), h = (½, ½) |
//!
//! Angles are reduced modulo 360° (an exact operation) and the grating phase modulo 1 cycle, so
//! a rotation by a whole turn or a drift by a whole period gives back the same signal up to the
//! rounding of one f64 addition. The zone plate keeps its exact phase reduction: only its centre
//! is rounded (once, to f64), and the phase K|p − c|² is then formed exactly from p and c.
//!
//! A zone plate centre or a step-edge offset cannot leave its allowed range: it wraps around
//! (centre coordinates periodically in [−1, 2), the offset in [−1, 1)), far outside the image,
//! so a long animation keeps running instead of failing. Other signals (checkerboard, polygon,
//! the 1D signals) have no exact moved form here; a scene that asks to move them is rejected.
//!
//! ## Frames
//! Time is sampled at the frame rate: frame k shows t = k / `frame_rate`. That rate is the
//! sampling rate in time — a drift of one grating period per frame looks frozen, slightly less
//! looks like slow motion backwards (temporal strobing, the wagon-wheel effect).

use super::{Location, Scene, SceneError};
use crate::core::signal::shapes::{direction, CENTRE};
use crate::core::signal::Signal;
use glam::DVec2;
use serde::{Deserialize, Serialize};

/// How a scene's signal moves (scene files: `motion: Some((velocity_x: 0.01, frame_rate: 24.0))`).
///
/// Every field has a default, so a scene names only what it uses.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Motion {
    /// Drift velocity along x, image units per second (the image is the unit square).
    pub velocity_x: f64,
    /// Drift velocity along y (downwards), image units per second.
    pub velocity_y: f64,
    /// Angular velocity about the pivot, degrees per second (positive: clockwise on screen).
    pub angular_velocity: f64,
    /// Pivot of the rotation, x.
    pub pivot_x: f64,
    /// Pivot of the rotation, y.
    pub pivot_y: f64,
    /// Frames per second: frame k shows t = k / frame_rate.
    pub frame_rate: f64,
}

impl Default for Motion {
    fn default() -> Self {
        Motion {
            velocity_x: 0.0,
            velocity_y: 0.0,
            angular_velocity: 0.0,
            pivot_x: 0.5,
            pivot_y: 0.5,
            frame_rate: 24.0,
        }
    }
}

/// Why a motion cannot be applied: the field and what it allows.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum MotionError {
    /// A parameter is out of range (the field is named as in scene files, e.g. `motion.frame_rate`).
    #[error("{field} = {value}: must be {allowed}")]
    InvalidParam {
        field: &'static str,
        value: f64,
        allowed: String,
    },
    /// The signal has no exact moved form.
    #[error("motion: the {signal} signal cannot move; allowed: zone-plate, grating, step-edge")]
    Unsupported { signal: &'static str },
}

impl Motion {
    /// Largest |velocity| per axis (image units per second).
    pub const MAX_VELOCITY: f64 = 100.0;
    /// Largest |angular velocity| (degrees per second).
    pub const MAX_ANGULAR_VELOCITY: f64 = 36_000.0;
    /// Allowed frame rates (frames per second).
    pub const FRAME_RATE_RANGE: (f64, f64) = (0.1, 240.0);

    /// Checks every field; the error names it and the allowed range.
    pub fn validate(&self) -> Result<(), MotionError> {
        let check = |field: &'static str, value: f64, lo: f64, hi: f64| {
            if value.is_finite() && value >= lo && value <= hi {
                Ok(())
            } else {
                Err(MotionError::InvalidParam {
                    field,
                    value,
                    allowed: format!("a finite number in [{lo}, {hi}]"),
                })
            }
        };
        let v = Self::MAX_VELOCITY;
        check("motion.velocity_x", self.velocity_x, -v, v)?;
        check("motion.velocity_y", self.velocity_y, -v, v)?;
        let w = Self::MAX_ANGULAR_VELOCITY;
        check("motion.angular_velocity", self.angular_velocity, -w, w)?;
        check("motion.pivot_x", self.pivot_x, -1.0, 2.0)?;
        check("motion.pivot_y", self.pivot_y, -1.0, 2.0)?;
        let (lo, hi) = Self::FRAME_RATE_RANGE;
        check("motion.frame_rate", self.frame_rate, lo, hi)?;
        Ok(())
    }

    /// Checks that `signal` can move (see the module table).
    pub fn check_signal(signal: &Signal) -> Result<(), MotionError> {
        match signal {
            Signal::ZonePlate(_) | Signal::Grating(_) | Signal::StepEdge(_) => Ok(()),
            other => Err(MotionError::Unsupported {
                signal: other.name(),
            }),
        }
    }

    /// The time of frame `k`: k / frame_rate seconds.
    pub fn frame_time(&self, k: i64) -> f64 {
        k as f64 / self.frame_rate
    }

    /// The rotation angle θ(t) = ω t reduced into [0, 360) degrees.
    pub fn angle_at(&self, t: f64) -> f64 {
        reduce_degrees(self.angular_velocity * t)
    }

    /// M_t(p) = R(θ(t)) (p − q) + q + v t.
    pub fn apply(&self, p: DVec2, t: f64) -> DVec2 {
        let q = DVec2::new(self.pivot_x, self.pivot_y);
        let r = direction(self.angle_at(t));
        let d = p - q;
        DVec2::new(r.x * d.x - r.y * d.y, r.y * d.x + r.x * d.y)
            + q
            + DVec2::new(self.velocity_x, self.velocity_y) * t
    }
}

/// x reduced into [0, 360) (exact: `rem_euclid` of f64 is exact).
fn reduce_degrees(x: f64) -> f64 {
    let r = x.rem_euclid(360.0);
    if r >= 360.0 {
        0.0
    } else {
        r
    }
}

/// θ₀ + θ reduced into [−360, 360]: θ is in [0, 360) and θ₀ in [−360, 360].
fn add_angle(base: f64, theta: f64) -> f64 {
    let a = base + theta;
    if a > 360.0 {
        a - 360.0
    } else {
        a
    }
}

/// x wrapped periodically into [lo, hi).
fn wrap(x: f64, lo: f64, hi: f64) -> f64 {
    let r = lo + (x - lo).rem_euclid(hi - lo);
    if r >= hi {
        lo
    } else {
        r
    }
}

/// The signal s_t(p) = s(M_t⁻¹(p)) at time `t` seconds, as a signal of the same kind (see the
/// module docs for the formulas). `t = 0` returns `signal` unchanged, bit for bit.
pub fn signal_at(signal: &Signal, motion: &Motion, t: f64) -> Result<Signal, MotionError> {
    motion.validate()?;
    Motion::check_signal(signal)?;
    if !t.is_finite() {
        return Err(MotionError::InvalidParam {
            field: "t",
            value: t,
            allowed: "a finite time in seconds".into(),
        });
    }
    if t == 0.0 {
        return Ok(*signal);
    }
    let theta = motion.angle_at(t);
    let q = DVec2::new(motion.pivot_x, motion.pivot_y);
    let shift = q + DVec2::new(motion.velocity_x, motion.velocity_y) * t;
    Ok(match *signal {
        Signal::ZonePlate(mut z) => {
            let c = motion.apply(DVec2::new(z.cx, z.cy), t);
            z.cx = wrap(c.x, -1.0, 2.0);
            z.cy = wrap(c.y, -1.0, 2.0);
            Signal::ZonePlate(z)
        }
        Signal::Grating(mut g) => {
            let n0 = direction(g.angle);
            let angle = add_angle(g.angle, theta);
            let n1 = direction(angle);
            let dphase = g.frequency * (n0.dot(q) - n1.dot(shift));
            // φ + Δφ modulo one cycle, into [0, 1): sin(2π(·)) is 1-periodic in the phase.
            g.phase = wrap(g.phase + dphase.rem_euclid(1.0), 0.0, 1.0);
            g.angle = angle;
            Signal::Grating(g)
        }
        Signal::StepEdge(mut e) => {
            let n0 = direction(e.angle);
            let angle = add_angle(e.angle, theta);
            let n1 = direction(angle);
            let offset = e.offset + n1.dot(shift - CENTRE) - n0.dot(q - CENTRE);
            e.offset = wrap(offset, -1.0, 1.0);
            e.angle = angle;
            Signal::StepEdge(e)
        }
        // Rejected by `check_signal` above.
        other => other,
    })
}

impl Scene {
    /// The scene at time `t` seconds: the signal moved by [`Scene::motion`] (see the module docs),
    /// everything else unchanged (the points and their spectrum do not depend on the signal,
    /// so the compute graph reuses them). A scene without motion, or t = 0, is returned as is.
    pub fn at_time(&self, t: f64) -> Result<Scene, SceneError> {
        let mut out = self.clone();
        if let Some(m) = &self.motion {
            out.signal = signal_at(&self.signal, m, t).map_err(|e| {
                let (field, value, allowed) = match &e {
                    MotionError::InvalidParam {
                        field,
                        value,
                        allowed,
                    } => (field.to_string(), value.to_string(), allowed.clone()),
                    MotionError::Unsupported { signal } => (
                        "motion".to_string(),
                        signal.to_string(),
                        "used with a zone-plate, grating or step-edge signal".to_string(),
                    ),
                };
                SceneError::Invalid {
                    source_name: self.title.clone(),
                    location: Location::default(),
                    field,
                    value,
                    allowed,
                }
            })?;
        }
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::signal::{Grating, StepEdge, ZonePlate};

    fn max_diff(a: &Signal, b: &Signal) -> f64 {
        let mut worst: f64 = 0.0;
        for j in 0..64 {
            for i in 0..64 {
                let p = DVec2::new((i as f64 + 0.5) / 64.0, (j as f64 + 0.5) / 64.0);
                worst = worst.max((a.eval(p) - b.eval(p)).abs());
            }
        }
        worst
    }

    /// s_t(M_t(p)) = s(p) for every supported signal: the moved parameters carry the pattern.
    #[test]
    fn moved_signal_carries_points_along() {
        let motion = Motion {
            velocity_x: 0.013,
            velocity_y: -0.007,
            angular_velocity: 17.0,
            pivot_x: 0.4,
            pivot_y: 0.6,
            frame_rate: 30.0,
        };
        let signals = [
            Signal::ZonePlate(ZonePlate::default()),
            Signal::Grating(Grating {
                frequency: 9.0,
                angle: 25.0,
                phase: 0.1,
            }),
            Signal::StepEdge(StepEdge {
                angle: 10.0,
                offset: 0.05,
            }),
        ];
        for s in signals {
            for t in [0.5, 1.25, 3.0] {
                let moved = signal_at(&s, &motion, t).unwrap();
                moved.validate().unwrap();
                for k in 0..200 {
                    let p = DVec2::new((k as f64 * 0.618).fract(), (k as f64 * 0.377).fract());
                    let (a, b) = (moved.eval(motion.apply(p, t)), s.eval(p));
                    // A step edge may flip on points within rounding of the edge: skip those.
                    if let Signal::StepEdge(e) = s {
                        let n = direction(e.angle);
                        if (n.dot(p - CENTRE) - e.offset).abs() < 1e-9 {
                            continue;
                        }
                    }
                    assert!((a - b).abs() < 1e-9, "{} t={t} p={p}: {a} vs {b}", s.name());
                }
            }
        }
    }

    #[test]
    fn pure_rotation_of_zone_plate_about_its_centre_is_still() {
        let m = Motion {
            angular_velocity: 33.0,
            ..Motion::default()
        };
        let z = Signal::ZonePlate(ZonePlate::default());
        assert!(max_diff(&signal_at(&z, &m, 2.7).unwrap(), &z) < 1e-12);
    }

    #[test]
    fn zone_plate_centre_wraps_instead_of_failing() {
        let m = Motion {
            velocity_x: 1.0,
            ..Motion::default()
        };
        let z = Signal::ZonePlate(ZonePlate::default());
        let moved = signal_at(&z, &m, 10.0).unwrap();
        moved.validate().unwrap();
    }
}
