//! Playback of scenes with motion: play, pause, step and the time readout.
//!
//! Only a scene with `motion` shows these controls and only while it plays does the app ask
//! for frames; a still scene submits nothing per frame. Frame k shows the scene at
//! t = k / frame_rate ([`crate::scene::Scene::at_time`]). Playback never skips a frame:
//! the next frame is submitted when the previous one is computed and its frame interval has
//! passed, so when the computation is slower than the frame rate the animation slows down (the
//! readout shows the rate reached) instead of dropping frames, which would add temporal
//! aliasing of its own.

use super::app::SamplescopeApp;
use crate::scene::Scene;
use eframe::egui;
use std::time::{Duration, Instant};

/// The playback state of a scene with motion.
#[derive(Debug, Clone, Copy, Default)]
pub struct MotionClock {
    /// The frame shown (t = frame / frame_rate); may be negative after stepping back.
    pub frame: i64,
    /// Whether frames advance on their own.
    pub playing: bool,
    /// When the shown frame was submitted.
    last_advance: Option<Instant>,
    /// Measured frames per second while playing (exponential average).
    achieved_fps: f64,
}

impl MotionClock {
    /// Back to frame 0, paused.
    pub fn reset(&mut self) {
        *self = MotionClock::default();
    }
}

impl SamplescopeApp {
    /// The frame shown (0 for a scene without motion).
    pub fn motion_frame(&self) -> i64 {
        self.motion_clock.frame
    }

    /// The scene of the frame shown, when the scene moves and the frame is not the first
    /// (`None`: the scene itself is shown).
    pub fn moved_scene(&self) -> Option<Scene> {
        let m = self.scene.motion?;
        if self.motion_clock.frame == 0 {
            return None;
        }
        // The scene was validated when loaded and the time is finite, so this cannot fail; if
        // it did, the still scene is shown rather than nothing.
        self.scene
            .at_time(m.frame_time(self.motion_clock.frame))
            .ok()
    }

    /// While playing: moves to the next frame once the shown one is computed and its frame
    /// interval has passed, and asks for a repaint when the next one is due. Does nothing for
    /// a scene without motion or while paused.
    pub fn advance_motion(&mut self, ctx: &egui::Context) {
        let Some(m) = self.scene.motion else {
            self.motion_clock.playing = false;
            return;
        };
        if !self.motion_clock.playing {
            return;
        }
        let interval = Duration::from_secs_f64(1.0 / m.frame_rate);
        let now = Instant::now();
        let due = match self.motion_clock.last_advance {
            Some(t) => now.duration_since(t) >= interval,
            None => true,
        };
        if due && self.engine.is_idle() {
            if let Some(t) = self.motion_clock.last_advance {
                let fps = 1.0 / now.duration_since(t).as_secs_f64().max(1e-6);
                let c = &mut self.motion_clock;
                c.achieved_fps = if c.achieved_fps > 0.0 {
                    0.8 * c.achieved_fps + 0.2 * fps
                } else {
                    fps
                };
            }
            self.motion_clock.frame += 1;
            self.motion_clock.last_advance = Some(now);
            ctx.request_repaint_after(interval);
        } else if due {
            // Waiting for the engine: its result triggers a repaint; poll as a fallback.
            ctx.request_repaint_after(Duration::from_millis(5));
        } else if let Some(t) = self.motion_clock.last_advance {
            ctx.request_repaint_after(interval.saturating_sub(now.duration_since(t)));
        }
    }

    /// Play/pause, step back/forward, rewind and the time readout (only for scenes with motion).
    pub fn transport_ui(&mut self, ui: &mut egui::Ui) {
        let Some(m) = self.scene.motion else {
            return;
        };
        ui.horizontal_wrapped(|ui| {
            let clock = &mut self.motion_clock;
            if ui
                .button("Step back")
                .on_hover_text("Previous frame")
                .clicked()
            {
                clock.playing = false;
                clock.frame -= 1;
            }
            let label = if clock.playing { "Pause" } else { "Play" };
            if ui.button(label).clicked() {
                clock.playing = !clock.playing;
                clock.last_advance = None;
                clock.achieved_fps = 0.0;
            }
            if ui
                .button("Step forward")
                .on_hover_text("Next frame")
                .clicked()
            {
                clock.playing = false;
                clock.frame += 1;
            }
            if ui.button("Rewind").on_hover_text("Back to t = 0").clicked() {
                clock.reset();
            }
            let t = m.frame_time(clock.frame);
            let mut readout = format!(
                "t = {t:.3} s · frame {} at {} fps",
                clock.frame, m.frame_rate
            );
            if clock.playing && clock.achieved_fps > 0.0 && clock.achieved_fps < 0.95 * m.frame_rate
            {
                readout.push_str(&format!(
                    " (computing reaches {:.1} fps)",
                    clock.achieved_fps
                ));
            }
            ui.label(readout);
            // The signal can be switched in the controls to one that cannot move: say so
            // (the still scene is shown meanwhile).
            if let Err(e) = crate::scene::Motion::check_signal(&self.scene.signal) {
                ui.colored_label(egui::Color32::from_rgb(200, 40, 40), e.to_string());
            }
        });
    }
}
