//! The player: play, pause, step, rewind and the readout of an animated scene — one
//! component for both kinds of animation (`scene::animation`): a scene with motion plays its
//! time, a scene whose columns come in order plays its prefix (the first k points, with the
//! spectrum and statistics of those k).
//!
//! Only an animated scene shows these controls and only while it plays does the app ask for
//! frames; a still scene submits nothing per frame.
//!
//! - **Motion**: frame k shows the scene at t = k / `motion.frame_rate`
//!   ([`crate::scene::Scene::at_time`]); the scene itself is not edited.
//! - **Prefix**: the shown k is the scene's own `prefix` setting (saved with it, rendered by
//!   `render`): the slider and the steps edit it, and playing walks the animation's frames
//!   (frame i shows ⌈N (i + 1) / F⌉ points, [`crate::scene::animation::prefix_at`]) at
//!   `animation.fps`, stopping at all N points.
//!
//! Playback never skips a frame: the next frame is submitted when the previous one is computed
//! and its frame interval has passed, so when the computation is slower than the frame rate
//! the animation slows down (the readout shows the rate reached) instead of dropping frames,
//! which would add temporal aliasing of its own.

use crate::scene::animation::prefix_at;
use crate::scene::Scene;
use eframe::egui;
use std::time::{Duration, Instant};

/// The player's state: the frame shown, playing or not, and the rate reached.
#[derive(Debug, Clone, Copy, Default)]
pub struct Playback {
    /// The motion frame shown (t = frame / frame_rate); may be negative after stepping back.
    /// For a prefix: the animation frame reached while playing.
    frame: i64,
    /// Whether frames advance on their own.
    playing: bool,
    /// When the shown frame was submitted.
    last_advance: Option<Instant>,
    /// Measured frames per second while playing (exponential average).
    achieved_fps: f64,
}

/// What the player drives for a scene.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Mode {
    /// The time of a scene with motion (its frame rate).
    Motion { rate: f64 },
    /// The prefix of a scene whose columns come in order.
    Prefix,
}

fn mode(scene: &Scene) -> Option<Mode> {
    match &scene.motion {
        Some(m) => Some(Mode::Motion { rate: m.frame_rate }),
        None => scene.plays_prefix().then_some(Mode::Prefix),
    }
}

impl Playback {
    /// Back to frame 0, paused.
    pub fn reset(&mut self) {
        *self = Playback::default();
    }

    /// The motion frame shown (0 for a scene without motion).
    pub fn frame(&self) -> i64 {
        self.frame
    }

    /// Whether frames advance on their own.
    pub fn is_playing(&self) -> bool {
        self.playing
    }

    /// The scene of the frame shown, when `scene` moves and the frame is not the first
    /// (`None`: the scene itself is shown; a prefix is part of the scene).
    pub fn moved_scene(&self, scene: &Scene) -> Option<Scene> {
        let m = scene.motion?;
        if self.frame == 0 {
            return None;
        }
        // The scene was validated when loaded and the time is finite, so this cannot fail; if
        // it did, the still scene is shown rather than nothing.
        scene.at_time(m.frame_time(self.frame)).ok()
    }

    /// While playing: moves to the next frame once the shown one is computed (`engine_idle`)
    /// and its frame interval has passed, and asks for a repaint when the next one is due.
    /// Does nothing for a still scene or while paused. A prefix left on a scene whose columns
    /// no longer come in order (a pattern switched in the controls) is dropped.
    pub fn advance(&mut self, ctx: &egui::Context, scene: &mut Scene, engine_idle: bool) {
        let Some(mode) = mode(scene) else {
            self.playing = false;
            if scene.prefix.is_some() && !scene.plays_prefix() {
                scene.prefix = None;
            }
            return;
        };
        if !self.playing {
            return;
        }
        let rate = match mode {
            Mode::Motion { rate } => rate,
            Mode::Prefix => scene.animation.fps,
        };
        let interval = Duration::from_secs_f64(1.0 / rate);
        let now = Instant::now();
        let due = match self.last_advance {
            Some(t) => now.duration_since(t) >= interval,
            None => true,
        };
        if due && engine_idle {
            if let Some(t) = self.last_advance {
                let fps = 1.0 / now.duration_since(t).as_secs_f64().max(1e-6);
                self.achieved_fps = if self.achieved_fps > 0.0 {
                    0.8 * self.achieved_fps + 0.2 * fps
                } else {
                    fps
                };
            }
            match mode {
                Mode::Motion { .. } => self.frame += 1,
                Mode::Prefix => {
                    // Stopped at the end: all N points shown (the last frame).
                    if !self.next_prefix(scene) || scene.prefix.is_none() {
                        self.playing = false;
                        ctx.request_repaint();
                    }
                }
            }
            self.last_advance = Some(now);
            ctx.request_repaint_after(interval);
        } else if due {
            // Waiting for the engine: its result triggers a repaint; poll as a fallback.
            ctx.request_repaint_after(Duration::from_millis(5));
        } else if let Some(t) = self.last_advance {
            ctx.request_repaint_after(interval.saturating_sub(now.duration_since(t)));
        }
    }

    /// The next frame's prefix: the first animation frame showing more points than now.
    /// False at the end (all N points shown).
    fn next_prefix(&mut self, scene: &mut Scene) -> bool {
        let (n, frames) = (scene.n, scene.animation.frames);
        let shown = scene.prefix.unwrap_or(n);
        if shown >= n {
            return false;
        }
        let next = (0..frames)
            .map(|i| (i, prefix_at(i, frames, n)))
            .find(|&(_, k)| k > shown);
        match next {
            Some((i, k)) => {
                self.frame = i as i64;
                scene.prefix = (k < n).then_some(k);
                true
            }
            None => false,
        }
    }

    /// Play/pause, step back/forward, rewind and the readout (only for animated scenes); for a
    /// prefix also its slider and the animation's frames and rate.
    pub fn transport_ui(&mut self, ui: &mut egui::Ui, scene: &mut Scene) {
        let Some(mode) = mode(scene) else {
            return;
        };
        ui.horizontal_wrapped(|ui| {
            let back = match mode {
                Mode::Motion { .. } => "Previous frame",
                Mode::Prefix => "One point fewer",
            };
            if ui.button("Step back").on_hover_text(back).clicked() {
                self.playing = false;
                match mode {
                    Mode::Motion { .. } => self.frame -= 1,
                    Mode::Prefix => {
                        let k = scene.prefix.unwrap_or(scene.n);
                        scene.prefix = Some(k.saturating_sub(1).max(1));
                    }
                }
            }
            let label = if self.playing { "Pause" } else { "Play" };
            if ui.button(label).clicked() {
                self.playing = !self.playing;
                self.last_advance = None;
                self.achieved_fps = 0.0;
                // A prefix played from all N points starts again from the first frame.
                if self.playing && mode == Mode::Prefix && scene.prefix.is_none() {
                    self.frame = 0;
                    let k = prefix_at(0, scene.animation.frames, scene.n);
                    scene.prefix = (k < scene.n).then_some(k);
                    // The first frame is shown for its interval too.
                    self.last_advance = Some(Instant::now());
                }
            }
            let forward = match mode {
                Mode::Motion { .. } => "Next frame",
                Mode::Prefix => "One point more",
            };
            if ui.button("Step forward").on_hover_text(forward).clicked() {
                self.playing = false;
                match mode {
                    Mode::Motion { .. } => self.frame += 1,
                    Mode::Prefix => {
                        if let Some(k) = scene.prefix {
                            scene.prefix = (k + 1 < scene.n).then_some(k + 1);
                        }
                    }
                }
            }
            let rewind = match mode {
                Mode::Motion { .. } => "Back to t = 0",
                Mode::Prefix => "Back to the first frame's points",
            };
            if ui.button("Rewind").on_hover_text(rewind).clicked() {
                self.reset();
                if mode == Mode::Prefix {
                    let k = prefix_at(0, scene.animation.frames, scene.n);
                    scene.prefix = (k < scene.n).then_some(k);
                }
            }
            let (mut readout, rate) = match mode {
                Mode::Motion { rate } => (
                    format!(
                        "t = {:.3} s · frame {} at {} fps",
                        self.frame as f64 / rate,
                        self.frame,
                        rate
                    ),
                    rate,
                ),
                Mode::Prefix => {
                    let n = scene.n;
                    let k = scene.prefix.unwrap_or(n);
                    let power = if k.is_power_of_two() {
                        format!(" = 2^{}", k.trailing_zeros())
                    } else {
                        String::new()
                    };
                    (
                        format!("first {k}{power} of {n} points"),
                        scene.animation.fps,
                    )
                }
            };
            if self.playing && self.achieved_fps > 0.0 && self.achieved_fps < 0.95 * rate {
                readout.push_str(&format!(
                    " (computing reaches {:.1} fps)",
                    self.achieved_fps
                ));
            }
            ui.label(readout);
            // The signal can be switched in the controls to one that cannot move: say so
            // (the still scene is shown meanwhile).
            if let Err(e) = crate::scene::Motion::check_signal(&scene.signal) {
                if mode != Mode::Prefix {
                    ui.colored_label(egui::Color32::from_rgb(200, 40, 40), e.to_string());
                }
            }
        });
        if mode == Mode::Prefix {
            let n = scene.n.max(1);
            let mut k = scene.prefix.unwrap_or(n).min(n);
            let slider = egui::Slider::new(&mut k, 1..=n)
                .text("first k points")
                .logarithmic(n > 64);
            if ui
                .add(slider)
                .on_hover_text(
                    "The first k of the N points, with the spectrum and statistics of those k \
                     (every 2^m prefix of a (0,2)-sequence is a (0,m,2)-net: turn on the \
                     elementary intervals)",
                )
                .changed()
            {
                self.playing = false;
                scene.prefix = (k < n).then_some(k);
            }
        }
        // The frames and rate of the prefix player and of the saved GIF.
        egui::CollapsingHeader::new("Animation (frames, fps)")
            .default_open(true)
            .show(ui, |ui| {
                crate::ui::widgets::params::params_ui(ui, &mut scene.animation);
            });
    }
}
