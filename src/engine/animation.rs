//! Animated figures: the frames of an animated scene (its motion's time or its prefix's
//! growth, [`crate::scene::animation`]) evaluated one after another by one [`Evaluator`] (its
//! cache keeps what frames share: the points and spectra of a moving scene, the sequence of a
//! prefix), each drawn as the scene's comparison through [`export::publish`] (the drawing of
//! its PNG) and appended to one GIF ([`export::gif`]). `samplescope render --format gif` and
//! the GUI's Save menu both make their GIF here; they write it through `core::output`.
//!
//! Everything that can refuse is checked before any frame is computed ([`prepare`]): that
//! the scene animates, the frames' pixels against [`gif::MAX_GIF_PIXELS`] (the frame's size
//! from the scene's layout, before any data), and the frames' plans (for the caller's
//! compute budget, [`Prepared::estimates`]).

use super::{ColumnResults, ColumnsError, Evaluator};
use crate::core::budget::Estimate;
use crate::core::cancel::Cancel;
use crate::export::figure::{comparison_file_name, comparison_size, Aspect, FileFormat};
use crate::export::publish::{picture, Target};
use crate::export::{gif, ExportError};
use crate::scene::graph::{self, Plan};
use crate::scene::{animation, figure, Scene};
use std::collections::HashMap;
use std::sync::Arc;

/// Why an animated figure was not made.
#[derive(Debug, thiserror::Error)]
pub enum AnimationError {
    /// The scene does not animate, or its frames do not fit the budget: bad input.
    #[error("{0}")]
    Refused(String),
    /// A frame's node failed or its figure could not be drawn.
    #[error("{0}")]
    Failed(String),
    /// Cancelled between or during frames.
    #[error("cancelled")]
    Cancelled,
}

/// An animation checked and planned, before any frame is computed.
pub struct Prepared {
    /// The scene of every frame with its plan.
    frames: Vec<(Scene, Arc<Plan>)>,
    /// The file name: the comparison's, `.gif`.
    pub name: String,
    /// The frame's estimated size in pixels (the comparison's layout).
    pub size: (u64, u64),
    /// Frames per second.
    pub fps: f64,
    /// What the frames compute, each node once (for the compute budget).
    pub estimates: Vec<Estimate>,
    scale: u32,
    aspect: Aspect,
    stem: String,
    field: &'static str,
}

impl Prepared {
    /// How many frames.
    pub fn frames(&self) -> usize {
        self.frames.len()
    }
}

/// The figure size of `scene`'s comparison at `scale` in a frame of `aspect`, from its layout
/// alone (no data: the colour bar of shared spectra counted as drawn).
fn layout_size(scene: &Scene, stem: &str, scale: u32, aspect: Aspect) -> (u64, u64) {
    let empty: ColumnResults = vec![HashMap::new(); scene.columns.len()];
    let Ok(mut columns) = figure::figure_columns(scene, &empty, stem) else {
        return (0, 0);
    };
    for (ctx, _) in &mut columns {
        ctx.spectrum_range = Some((0.0, 1.0));
    }
    let p = figure::publication(scene, columns, stem);
    comparison_size(&p.comparison, &p.columns, scale, aspect)
}

/// Checks and plans the animation of `scene` (its file stem `stem`) at `scale` and `aspect`:
/// it must animate, its comparison must have figures, and `frames` × width × height must fit
/// the GIF budget (`field` names the frame count in the error: `--frames`,
/// `animation.frames`). The frame count and rate are the scene's `animation`.
pub fn prepare(
    scene: &Scene,
    stem: &str,
    scale: u32,
    aspect: Aspect,
    field: &'static str,
) -> Result<Prepared, AnimationError> {
    if scene.animates().is_none() {
        return Err(AnimationError::Refused(format!(
            "this scene does not animate: animated figures are made of {}",
            animation::animated_scenes()
        )));
    }
    if crate::scene::panels::comparison(scene).is_empty() {
        return Err(AnimationError::Refused(
            "this scene shows none of the panels its figures draw; turn one on to animate it"
                .into(),
        ));
    }
    let frames = scene.animation.frames;
    let (w, h) = layout_size(scene, stem, scale, aspect);
    gif::check_budget(field, frames, w, h).map_err(AnimationError::Refused)?;
    let mut planned = Vec::with_capacity(frames);
    for i in 0..frames {
        let s = scene
            .frame(i)
            .map_err(|e| AnimationError::Refused(e.to_string()))?;
        let plan = Arc::new(graph::plan(&s));
        planned.push((s, plan));
    }
    let pairs: Vec<(&Scene, &Plan)> = planned.iter().map(|(s, p)| (s, p.as_ref())).collect();
    let estimates = crate::scene::cost::estimate_frames(&pairs);
    let name = comparison_file_name(
        if stem.trim().is_empty() {
            &scene.title
        } else {
            stem
        },
        scene.n,
        scale,
        FileFormat::Png,
    );
    let name = format!("{}.gif", name.trim_end_matches(".png"));
    Ok(Prepared {
        frames: planned,
        name,
        size: (w, h),
        fps: scene.animation.fps,
        estimates,
        scale,
        aspect,
        stem: stem.to_string(),
        field,
    })
}

/// Computes and draws every frame of `prepared` and returns the GIF's bytes; `on_frame(i, n)`
/// is called after frame i of n is encoded. Nothing is written here.
pub fn render_gif(
    prepared: &Prepared,
    eval: &Evaluator,
    cancel: &Cancel,
    on_frame: &mut dyn FnMut(usize, usize),
) -> Result<Vec<u8>, AnimationError> {
    let count = prepared.frames.len();
    let mut writer: Option<gif::GifWriter> = None;
    let mut first_size = (0, 0);
    for (i, (scene, plan)) in prepared.frames.iter().enumerate() {
        if cancel.is_cancelled() {
            return Err(AnimationError::Cancelled);
        }
        let results = eval
            .evaluate_columns(scene, plan.clone(), cancel)
            .map_err(|e| match e {
                ColumnsError::Cancelled => AnimationError::Cancelled,
                ColumnsError::Failed(e) => AnimationError::Failed(format!("frame {i}: {e}")),
            })?;
        let columns = figure::figure_columns(scene, &results, &prepared.stem)
            .map_err(|e| AnimationError::Failed(e.to_string()))?;
        let publication = figure::publication(scene, columns, &prepared.stem);
        let (w, h, mut rgba, _) = picture(
            &publication,
            Target::Comparison,
            prepared.scale,
            prepared.aspect,
        )
        .map_err(|e| match e {
            ExportError::Cancelled => AnimationError::Cancelled,
            other => AnimationError::Failed(format!("frame {i}: {other}")),
        })?;
        let gif = match &mut writer {
            Some(g) => {
                if (w, h) != first_size {
                    return Err(AnimationError::Failed(format!(
                        "frame {i} is {w}×{h} pixels, frame 0 {}×{}: an animation's frames \
                         share one size",
                        first_size.0, first_size.1
                    )));
                }
                g
            }
            None => {
                // The layout's estimate missed a figure that only data shows: check again.
                gif::check_budget(prepared.field, count, u64::from(w), u64::from(h))
                    .map_err(AnimationError::Refused)?;
                first_size = (w, h);
                writer.insert(
                    gif::GifWriter::new(w, h, prepared.fps)
                        .map_err(|e| AnimationError::Failed(e.to_string()))?,
                )
            }
        };
        gif.frame(&mut rgba)
            .map_err(|e| AnimationError::Failed(e.to_string()))?;
        on_frame(i, count);
    }
    let Some(gif) = writer else {
        return Err(AnimationError::Failed("no frames".into()));
    };
    gif.finish()
        .map_err(|e| AnimationError::Failed(e.to_string()))
}
