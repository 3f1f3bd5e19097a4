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
//!
//! **One colour range.** Every frame's periodograms are drawn with one colour range: the
//! last frame's (the shared range `render` gives that frame's columns,
//! [`figure::figure_columns`]). For a prefix the last frame shows all N points, so the GIF
//! ends on the still comparison `render` draws and a colour means the same power in every
//! frame (each frame normalised on its own made the spectrum flicker as k grew); a few
//! points' noisier periodogram shows its values beyond that range at its ends. A moving
//! scene's points do not move, so its periodograms and their range are the same in every
//! frame anyway. The last frame is therefore computed first (its results kept and drawn
//! last): the first frame appears after two frames' work.

use super::{ColumnResults, ColumnsError, Evaluator};
use crate::core::budget::Estimate;
use crate::core::cancel::Cancel;
use crate::export::figure::{comparison_file_name, comparison_size, Aspect, FileFormat};
use crate::export::publish::{picture, Target};
use crate::export::{gif, ExportError};
use crate::model::{ColumnData, FigureContext};
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

/// What [`render_gif`] reports after each frame is encoded.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FrameDone {
    /// The frame encoded (0-based).
    pub index: usize,
    /// How many frames the animation has.
    pub frames: usize,
    /// The colour range (log10 P) its periodograms were drawn with: the animation's one range
    /// (see the module docs); `None` when it draws no periodogram.
    pub spectrum_range: Option<(f32, f32)>,
}

/// Evaluates frame `i` (its scene and plan): every column's results, or why not.
fn evaluate_frame(
    i: usize,
    scene: &Scene,
    plan: &Arc<Plan>,
    eval: &Evaluator,
    cancel: &Cancel,
) -> Result<ColumnResults, AnimationError> {
    if cancel.is_cancelled() {
        return Err(AnimationError::Cancelled);
    }
    eval.evaluate_columns(scene, plan.clone(), cancel)
        .map_err(|e| match e {
            ColumnsError::Cancelled => AnimationError::Cancelled,
            ColumnsError::Failed(e) => AnimationError::Failed(format!("frame {i}: {e}")),
        })
}

/// The shared colour range of the periodograms of a frame's figure columns (`None`: none).
fn columns_range(columns: &[(FigureContext, ColumnData)]) -> Option<(f32, f32)> {
    columns.iter().find_map(|(ctx, _)| ctx.spectrum_range)
}

/// Computes and draws every frame of `prepared` and returns the GIF's bytes; `on_frame` is
/// called after each frame is encoded. The last frame is computed first: its periodograms'
/// colour range is every frame's (see the module docs). Nothing is written here.
pub fn render_gif(
    prepared: &Prepared,
    eval: &Evaluator,
    cancel: &Cancel,
    on_frame: &mut dyn FnMut(FrameDone),
) -> Result<Vec<u8>, AnimationError> {
    let count = prepared.frames.len();
    let Some((last_scene, last_plan)) = prepared.frames.last() else {
        return Err(AnimationError::Failed("no frames".into()));
    };
    let last_results = evaluate_frame(count - 1, last_scene, last_plan, eval, cancel)?;
    let range = figure::figure_columns(last_scene, &last_results, &prepared.stem)
        .map(|columns| columns_range(&columns))
        .map_err(|e| AnimationError::Failed(e.to_string()))?;
    let mut last = Some(last_results);
    let mut writer: Option<gif::GifWriter> = None;
    let mut first_size = (0, 0);
    for (i, (scene, plan)) in prepared.frames.iter().enumerate() {
        let results = match last.take_if(|_| i + 1 == count) {
            Some(r) => r,
            None => evaluate_frame(i, scene, plan, eval, cancel)?,
        };
        let mut columns = figure::figure_columns(scene, &results, &prepared.stem)
            .map_err(|e| AnimationError::Failed(e.to_string()))?;
        if range.is_some() {
            for (ctx, _) in &mut columns {
                ctx.spectrum_range = range;
            }
        }
        let spectrum_range = columns_range(&columns);
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
        on_frame(FrameDone {
            index: i,
            frames: count,
            spectrum_range,
        });
    }
    let Some(gif) = writer else {
        return Err(AnimationError::Failed("no frames".into()));
    };
    gif.finish()
        .map_err(|e| AnimationError::Failed(e.to_string()))
}
