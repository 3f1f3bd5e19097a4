//! The reconstruction node: the signal reconstructed from the column's samples (scattered), a grid
//! (resampled) or fresh samples in every pixel (supersampled, with a preview first when heavy).

use super::prelude::*;

/// The input nodes and scene fields of the node in column `c` of scene `s`.
pub(in crate::scene) fn inputs(s: &Scene, c: usize) -> Inputs {
    let col = &s.columns[c];
    let (f, w) = (&s.filter, s.recon.size);
    match s.recon.mode {
        ReconMode::Scattered => Inputs::new(
            NodeKind::Reconstruction,
            &[NodeKind::Points, NodeKind::Samples],
            (f, w),
        ),
        ReconMode::Resample { grid } => {
            Inputs::new(NodeKind::Reconstruction, &[], (grid, &s.signal, f, w))
        }
        ReconMode::Supersample { spp } => Inputs::new(
            NodeKind::Reconstruction,
            &[],
            (&col.pattern, col.seed, spp, &s.signal, f, w, col.pixels),
        ),
    }
}

/// What the node computes in column `c` of scene `s` (the budget's estimate).
pub(in crate::scene) fn estimate(s: &Scene, c: usize) -> Vec<Estimate> {
    let col = &s.columns[c];
    let (n, w) = (n_of(s, c), s.recon.size);
    let (signal, filter) = (&s.signal, &s.filter);
    match s.recon.mode {
        ReconMode::Scattered => vec![budget::scattered(n, w, filter)],
        ReconMode::Resample { grid } => vec![budget::resample(signal, grid, w, filter)],
        ReconMode::Supersample { spp } => {
            let mut v = Vec::new();
            let preview = spp / PREVIEW_DIVISOR;
            if preview >= 1 && w * w * spp > PREVIEW_SAMPLES {
                v.push(budget::supersampling(
                    signal,
                    w,
                    preview,
                    &col.pattern,
                    filter,
                ));
            }
            v.push(budget::supersampling(signal, w, spp, &col.pattern, filter));
            if let PixelSampling::ImagePlane { tile } = col.pixels {
                // One pattern of s·T² points over the tile, generated once.
                let t = if tile == 0 { w } else { tile };
                v.push(budget::pattern(&col.pattern, spp.saturating_mul(t * t)));
            }
            v
        }
    }
}

/// The job: the node's value from the scene, the column and the declared inputs.
pub(in crate::scene) fn run(ctx: &JobCtx) -> Output {
    let (scene, c, done, cancel) = (ctx.scene, ctx.column, ctx.deps, ctx.cancel);
    let w = scene.recon.size;
    if let Some(why) = scene.filter.reconstruction_refusal() {
        return Err(NodeError::CannotReconstruct(why));
    }
    let r = match scene.recon.mode {
        ReconMode::Scattered => {
            let p = points_of(done)?;
            let values = match dep(done, NodeKind::Samples)? {
                NodeValue::Samples(v) => v.clone(),
                _ => {
                    return Err(NodeError::Internal(
                        "the samples input has another kind".into(),
                    ))
                }
            };
            crate::core::recon::reconstruct_scattered(&p.points, &values, w, &scene.filter, cancel)?
        }
        ReconMode::Resample { grid } => {
            crate::core::recon::resample_grid(&scene.signal, grid, w, &scene.filter, cancel)?
        }
        ReconMode::Supersample { spp } => {
            let col = &scene.columns[c];
            if col.points.is_some() {
                return Err(NodeError::ImportedNeedsPattern {
                    column: c,
                    what: "supersampling",
                });
            }
            if !col.is_plain_2d() {
                return Err(NodeError::ProjectedNeedsPattern {
                    column: c,
                    dims: col.dims,
                    project: col.project,
                    what: "supersampling",
                });
            }
            let provider = |spp: usize| -> Result<Box<dyn SampleProvider>, NodeError> {
                Ok(match col.pixels {
                    PixelSampling::PerPixel => Box::new(crate::core::recon::PatternProvider {
                        pattern: col.pattern,
                        seed: col.seed,
                    }),
                    PixelSampling::ImagePlane { tile } => Box::new(ImagePlaneProvider::new(
                        &col.pattern,
                        w,
                        spp,
                        col.seed,
                        tile,
                        cancel,
                    )?),
                    PixelSampling::ZSobol => Box::new(ZSobolProvider { seed: col.seed, w }),
                })
            };
            // A heavy supersampling (over PREVIEW_SAMPLES samples) shows a preview at 1/16
            // of the samples per pixel first (6 % extra work), then the full image.
            let preview_spp = spp / PREVIEW_DIVISOR;
            if preview_spp >= 1 && w * w * spp > PREVIEW_SAMPLES {
                let p = crate::core::recon::supersample(
                    &scene.signal,
                    w,
                    preview_spp,
                    provider(preview_spp)?.as_ref(),
                    &scene.filter,
                    cancel,
                )?;
                ctx.publish(
                    NodeValue::Reconstruction(Arc::new(ReconData::new(p))),
                    Some(Accuracy::Preview {
                        spp: preview_spp,
                        of: spp,
                        noise: (PREVIEW_DIVISOR as f64).sqrt(),
                    }),
                    Steps::at(1, 2),
                );
            }
            crate::core::recon::supersample(
                &scene.signal,
                w,
                spp,
                provider(spp)?.as_ref(),
                &scene.filter,
                cancel,
            )?
        }
    };
    let accuracy = (r.zero_weight > 0).then_some(Accuracy::ZeroWeightPixels {
        pixels: r.zero_weight,
    });
    Ok((
        NodeValue::Reconstruction(Arc::new(ReconData::new(r))),
        accuracy,
    ))
}

/// Supersampled reconstructions of more samples than this show a preview first.
pub const PREVIEW_SAMPLES: usize = 2 << 20;

/// The preview's samples per pixel are the full spp over this.
pub const PREVIEW_DIVISOR: usize = 16;
