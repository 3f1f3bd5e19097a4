//! Saving an animated scene's comparison as an animated GIF from the GUI (the Save comparison
//! menu's *Animated GIF* entries): the GIF `samplescope render --format gif` writes, made by
//! the same code ([`crate::engine::animation`]: [`prepare`] then [`render_gif`]), so the same
//! scene gives the same bytes.
//!
//! - **Before any work** (on the UI thread, when the entry is clicked): the scene must
//!   animate, its frames must fit the GIF's pixel budget ([`prepare`]), their estimated cost
//!   must fit the app's compute budget (the one the scene itself is checked against) and the
//!   folder must take a new file; a refusal is one line in the top bar and nothing runs.
//! - **While it runs** (on a thread of its own, on the engine's evaluator, so it reuses what
//!   the window computed): the top bar shows `frame i of F` and a *Cancel* button.
//! - **Never a partial file**: the GIF is made whole in memory and written beside its name,
//!   then renamed into place ([`crate::core::output::write_atomic`]); a cancel or a failure
//!   leaves no file.
//!
//! The GIF draws the scene with its own settings, as `render` does (not the window's colour
//! map or locked spectrum range).

use crate::core::budget::Budget;
use crate::core::cancel::Cancel;
use crate::engine::animation::{prepare, render_gif, AnimationError};
use crate::engine::Evaluator;
use crate::export::figure::Aspect;
use crate::scene::Scene;
use eframe::egui;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::mpsc::{channel, Receiver};
use std::sync::Arc;

/// The frame count's name in a refusal (the scene's setting: the GUI has no `--frames`).
const FRAMES_FIELD: &str = "animation.frames";

/// A GIF being made.
struct Job {
    cancel: Cancel,
    /// Frames encoded so far.
    done: Arc<AtomicUsize>,
    frames: usize,
    name: String,
    finished: Receiver<Result<PathBuf, AnimationError>>,
}

/// The GUI's animated-GIF saver: at most one GIF at a time.
#[derive(Default)]
pub struct GifSaver {
    job: Option<Job>,
    /// The last outcome (saved, refused, cancelled, failed), shown in the top bar.
    pub status: Option<String>,
}

impl GifSaver {
    /// Whether a GIF is being made.
    pub fn busy(&self) -> bool {
        self.job.is_some()
    }

    /// Frames encoded and frames in all, while a GIF is being made.
    pub fn progress(&self) -> Option<(usize, usize)> {
        self.job
            .as_ref()
            .map(|j| (j.done.load(Ordering::Relaxed), j.frames))
    }

    /// Checks the GIF of `scene`'s comparison (file stem `stem`) at `scale` against the GIF
    /// budget, `budget` and the folder `dir`, then makes it on a thread of its own with `eval`;
    /// a refusal sets [`Self::status`] and starts nothing. Returns whether it started.
    #[allow(clippy::too_many_arguments)]
    pub fn start(
        &mut self,
        ctx: &egui::Context,
        scene: &Scene,
        stem: &str,
        scale: u32,
        aspect: Aspect,
        budget: &Budget,
        eval: Evaluator,
        dir: PathBuf,
    ) -> bool {
        if self.busy() {
            self.status = Some("GIF not started: another GIF is being saved".into());
            return false;
        }
        let refused = |e: String| Some(format!("GIF not saved: {e}"));
        let prepared = match prepare(scene, stem, scale, aspect, FRAMES_FIELD) {
            Ok(p) => p,
            Err(e) => {
                self.status = refused(e.to_string());
                return false;
            }
        };
        if let Err(e) = budget.check(&prepared.estimates) {
            self.status = refused(format!(
                "{e}; fewer frames (animation.frames) or a smaller scene fit"
            ));
            return false;
        }
        if let Err(e) = crate::core::output::check_output_dir("figure folder", &dir) {
            self.status = refused(e.to_string());
            return false;
        }
        let cancel = Cancel::new();
        let done = Arc::new(AtomicUsize::new(0));
        let (tx, rx) = channel();
        let name = prepared.name.clone();
        let frames = prepared.frames();
        let (job_cancel, job_done, repaint) = (cancel.clone(), done.clone(), ctx.clone());
        let spawned = std::thread::Builder::new()
            .name("samplescope-gif".into())
            .spawn(move || {
                let made = render_gif(&prepared, &eval, &job_cancel, &mut |f| {
                    job_done.store(f.index + 1, Ordering::Relaxed);
                    repaint.request_repaint();
                })
                .and_then(|bytes| write(&dir, &prepared.name, &bytes, &job_cancel));
                let _ = tx.send(made);
                repaint.request_repaint();
            });
        if let Err(e) = spawned {
            self.status = refused(format!("cannot start the GIF thread: {e}"));
            return false;
        }
        self.status = None;
        self.job = Some(Job {
            cancel,
            done,
            frames,
            name,
            finished: rx,
        });
        true
    }

    /// Stops the GIF being made (no file is written).
    pub fn cancel(&mut self) {
        if let Some(j) = &self.job {
            j.cancel.cancel();
        }
    }

    /// Takes the outcome of a finished GIF into [`Self::status`].
    pub fn poll(&mut self) {
        let Some(job) = &self.job else {
            return;
        };
        let outcome = match job.finished.try_recv() {
            Ok(r) => r,
            Err(std::sync::mpsc::TryRecvError::Empty) => return,
            Err(std::sync::mpsc::TryRecvError::Disconnected) => Err(AnimationError::Failed(
                "the GIF thread stopped without a result".into(),
            )),
        };
        self.status = Some(match outcome {
            Ok(path) => format!("saved {} ({} frames)", path.display(), job.frames),
            Err(AnimationError::Cancelled) => {
                format!("GIF cancelled: {} not written", job.name)
            }
            Err(e) => format!("GIF not saved: {e}"),
        });
        self.job = None;
    }

    /// The top bar's part: while a GIF is made, its progress and a Cancel button; after, the
    /// outcome.
    pub fn ui(&mut self, ui: &mut egui::Ui) {
        if let Some((done, frames)) = self.progress() {
            ui.spinner();
            ui.label(format!("saving GIF: frame {done} of {frames}"));
            if ui
                .button("Cancel GIF")
                .on_hover_text("Stop making the GIF (no file is written)")
                .clicked()
            {
                self.cancel();
            }
        } else if let Some(status) = &self.status {
            ui.small(status);
        }
    }
}

/// Writes the finished GIF `name` into `dir` (created when needed) beside its name and renamed
/// into place; nothing is left on failure or cancel.
fn write(dir: &Path, name: &str, bytes: &[u8], cancel: &Cancel) -> Result<PathBuf, AnimationError> {
    if cancel.is_cancelled() {
        return Err(AnimationError::Cancelled);
    }
    let failed = |e: String| AnimationError::Failed(e);
    std::fs::create_dir_all(dir).map_err(|e| failed(format!("{}: {e}", dir.display())))?;
    let path = dir.join(name);
    crate::core::output::write_atomic(&path, bytes, cancel).map_err(|e| {
        if cancel.is_cancelled() {
            AnimationError::Cancelled
        } else {
            failed(e.to_string())
        }
    })?;
    Ok(path)
}
