//! What a scene plays: the first k points of columns whose points come in order (the scene's
//! `prefix`, computed through the graph like any setting), and the frames of its animation —
//! the motion's time or the prefix's growth — that the GUI's player and `render --format gif`
//! share.
//!
//! ## The prefix
//! `prefix: Some(k)` shows the first k of each column's N points (all of an imported set
//! with fewer): the pattern panel, the spectrum, the statistics and the scattered
//! reconstruction are those of the k points. The column's full run is the `Sequence` node
//! (keyed by pattern, N and seed, as the points of a scene without prefix), so moving k slices
//! the cached run instead of generating again; the `Points` node of a prefix is that slice.
//! A prefix plays only where the first k points mean something ([`Pattern::plays_in_order`]):
//! the progressive patterns, whose first k points are the k-point run (random, best
//! candidate, the sequences), and dart throwing, whose first k points are the first k darts
//! accepted (at the N-point radius).
//!
//! ## The frames
//! An animation has [`AnimationSettings::frames`] frames played at
//! [`AnimationSettings::fps`]. A scene with motion shows, in frame i, the scene at
//! t = i / `motion.frame_rate` ([`Scene::at_time`]; the frame rate is the time sampling, the
//! player's and the GIF's rate only the speed they are shown at). A scene that plays a prefix
//! shows, in frame i of F, the first ⌈N (i + 1) / F⌉ points ([`prefix_at`]): the last frame
//! shows all N.

use super::{Motion, Scene, SceneError};
use crate::core::params::declare_params;
use crate::core::pattern::Pattern;

declare_params! {
    /// How an animated scene plays (its player in the GUI and its animated figure).
    AnimationSettings = "animation", "the frames of an animated scene (its player and its animated GIF)" {
        frames: count(48, 2, 1000, "frames of the animation; a prefix reaches all N points in the last"),
        fps: float(24.0, 1.0, 50.0, "frames per second the animation plays at (a GIF holds each frame whole centiseconds, alternated to keep this mean rate)"),
    }
}

/// What a scene animates.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Animates {
    /// Its signal moves ([`Scene::motion`]): frame i is the scene at t = i / frame rate.
    Motion,
    /// Its columns' points come in order: frame i shows a growing prefix.
    Prefix,
}

/// The patterns whose points come in order ([`Pattern::plays_in_order`]), comma-separated.
pub fn in_order_patterns() -> String {
    let names: Vec<&str> = Pattern::all()
        .iter()
        .filter(|p| p.plays_in_order())
        .map(|p| p.name())
        .collect();
    names.join(", ")
}

/// Which scenes animate, for the one line that refuses an animation of another.
pub fn animated_scenes() -> String {
    format!(
        "scenes with motion (a moving zone-plate, grating or step-edge signal) and scenes whose \
         every column plays in order ({}, or imported points)",
        in_order_patterns()
    )
}

/// The prefix frame `i` of `frames` shows of `n` points: ⌈n (i + 1) / frames⌉, at least 1
/// and at most n (the last frame shows all).
pub fn prefix_at(i: usize, frames: usize, n: usize) -> usize {
    let frames = frames.max(1) as u128;
    let i = (i as u128).min(frames - 1);
    let k = (n as u128 * (i + 1)).div_ceil(frames);
    (k as usize).clamp(1, n.max(1))
}

impl Scene {
    /// Whether every column's points come in an order a prefix shows (imported points: the
    /// file's order).
    pub fn plays_prefix(&self) -> bool {
        self.columns
            .iter()
            .all(|c| c.points.is_some() || c.pattern.plays_in_order())
    }

    /// What the scene animates: its motion (with a signal that can move), else its prefix when
    /// every column plays in order, else nothing.
    pub fn animates(&self) -> Option<Animates> {
        if self.motion.is_some() && Motion::check_signal(&self.signal).is_ok() {
            Some(Animates::Motion)
        } else if self.plays_prefix() {
            Some(Animates::Prefix)
        } else {
            None
        }
    }

    /// How many points column `c` has: its imported set's, else N (known before the points
    /// are).
    pub fn column_n(&self, c: usize) -> usize {
        self.columns
            .get(c)
            .and_then(|col| col.points.as_ref())
            .map_or(self.n, |p| p.points.len())
    }

    /// How many points column `c` shows: the prefix's k (at most the column's points), else
    /// all of them.
    pub fn shown_n(&self, c: usize) -> usize {
        let n = self.column_n(c);
        self.prefix.map_or(n, |k| k.min(n))
    }

    /// The scene of frame `i` of its animation (see the module docs); a scene that does not
    /// animate is returned as is.
    pub fn frame(&self, i: usize) -> Result<Scene, SceneError> {
        match (self.animates(), &self.motion) {
            (Some(Animates::Motion), Some(m)) => {
                self.at_time(m.frame_time(i64::try_from(i).unwrap_or(i64::MAX)))
            }
            (Some(Animates::Prefix), _) => {
                let mut s = self.clone();
                s.prefix = Some(prefix_at(i, self.animation.frames, self.n));
                Ok(s)
            }
            _ => Ok(self.clone()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_prefix_grows_to_all_points_in_the_last_frame() {
        for (frames, n) in [(48, 256), (2, 1), (1000, 7), (64, 4096), (5, 5)] {
            let ks: Vec<usize> = (0..frames).map(|i| prefix_at(i, frames, n)).collect();
            assert_eq!(*ks.last().unwrap(), n);
            assert!(ks.windows(2).all(|w| w[0] <= w[1]), "{ks:?}");
            assert!(ks[0] >= 1);
        }
        // N a multiple of F: every frame adds N/F points, so every power of two ≥ N/F that
        // is a multiple of it is a frame.
        let ks: Vec<usize> = (0..64).map(|i| prefix_at(i, 64, 256)).collect();
        for m in 2..=8 {
            assert!(ks.contains(&(1 << m)), "2^{m}");
        }
    }

    #[test]
    fn defaults_agree_with_descriptors() {
        use crate::core::params::Params;
        let a = AnimationSettings::default();
        for spec in a.specs() {
            assert_eq!(
                a.get(spec.name),
                Some(spec.default_value()),
                "{}",
                spec.name
            );
        }
        a.check_params().unwrap();
    }
}
