//! Playback of scenes with motion: play, pause, step and the time readout.
//!
//! Only a scene with `motion` shows these controls and only while it plays does the app ask
//! for frames; a still scene submits nothing per frame. Frame k shows the scene at
//! t = k / frame_rate ([`crate::scene::Scene::at_time`]). Playback never skips a frame:
//! the next frame is submitted when the previous one is computed and its frame interval has
//! passed, so when the computation is slower than the frame rate the animation slows down (the
//! readout shows the rate reached) instead of dropping frames, which would add temporal
//! aliasing of its own.

use crate::scene::Scene;
use eframe::egui;
use std::time::{Duration, Instant};

/// Playback of a scene with motion: the frame shown, playing or not, and the rate reached.
#[derive(Debug, Clone, Copy, Default)]
pub struct Playback {
    /// The frame shown (t = frame / frame_rate); may be negative after stepping back.
    frame: i64,
    /// Whether frames advance on their own.
    playing: bool,
    /// When the shown frame was submitted.
    last_advance: Option<Instant>,
    /// Measured frames per second while playing (exponential average).
    achieved_fps: f64,
}

impl Playback {
    /// Back to frame 0, paused.
    pub fn reset(&mut self) {
        *self = Playback::default();
    }

    /// The frame shown (0 for a scene without motion).
    pub fn frame(&self) -> i64 {
        self.frame
    }

    /// The scene of the frame shown, when `scene` moves and the frame is not the first
    /// (`None`: the scene itself is shown).
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
    /// Does nothing for a scene without motion or while paused.
    pub fn advance(&mut self, ctx: &egui::Context, scene: &Scene, engine_idle: bool) {
        let Some(m) = scene.motion else {
            self.playing = false;
            return;
        };
        if !self.playing {
            return;
        }
        let interval = Duration::from_secs_f64(1.0 / m.frame_rate);
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
            self.frame += 1;
            self.last_advance = Some(now);
            ctx.request_repaint_after(interval);
        } else if due {
            // Waiting for the engine: its result triggers a repaint; poll as a fallback.
            ctx.request_repaint_after(Duration::from_millis(5));
        } else if let Some(t) = self.last_advance {
            ctx.request_repaint_after(interval.saturating_sub(now.duration_since(t)));
        }
    }

    /// Play/pause, step back/forward, rewind and the time readout (only for scenes with
    /// motion).
    pub fn transport_ui(&mut self, ui: &mut egui::Ui, scene: &Scene) {
        let Some(m) = scene.motion else {
            return;
        };
        ui.horizontal_wrapped(|ui| {
            if ui
                .button("Step back")
                .on_hover_text("Previous frame")
                .clicked()
            {
                self.playing = false;
                self.frame -= 1;
            }
            let label = if self.playing { "Pause" } else { "Play" };
            if ui.button(label).clicked() {
                self.playing = !self.playing;
                self.last_advance = None;
                self.achieved_fps = 0.0;
            }
            if ui
                .button("Step forward")
                .on_hover_text("Next frame")
                .clicked()
            {
                self.playing = false;
                self.frame += 1;
            }
            if ui.button("Rewind").on_hover_text("Back to t = 0").clicked() {
                self.reset();
            }
            let t = m.frame_time(self.frame);
            let mut readout = format!(
                "t = {t:.3} s · frame {} at {} fps",
                self.frame, m.frame_rate
            );
            if self.playing && self.achieved_fps > 0.0 && self.achieved_fps < 0.95 * m.frame_rate {
                readout.push_str(&format!(
                    " (computing reaches {:.1} fps)",
                    self.achieved_fps
                ));
            }
            ui.label(readout);
            // The signal can be switched in the controls to one that cannot move: say so
            // (the still scene is shown meanwhile).
            if let Err(e) = crate::scene::Motion::check_signal(&scene.signal) {
                ui.colored_label(egui::Color32::from_rgb(200, 40, 40), e.to_string());
            }
        });
    }
}
