//! `samplescope recon`: sample a test signal with a pattern, reconstruct it, and report the
//! error against the signal's reference image.

use super::outln;
use super::session::{check_outputs, write_output, Session};
use super::{from_args, parse_n, CliError};
use samplescope::core::budget;
use samplescope::core::filter::{Filter, Filter2D, Mode2D};
use samplescope::core::pattern::Pattern;
use samplescope::core::recon::{ReconError, MAX_SPP, MAX_W};
use samplescope::core::signal::Signal;
use samplescope::engine::cache::DEFAULT_BUDGET;
use samplescope::engine::Evaluator;
use samplescope::export::figure::base_size;
use samplescope::model::FigureKind;
use samplescope::scene::graph::{NodeError, NodeKind, NodeResult, NodeValue};
use samplescope::scene::panels::PanelKind;
use samplescope::scene::{figure, Column, ImportedPoints, Panels, ReconMode, Scene};
use std::collections::HashMap;
use std::path::Path;
use std::sync::Arc;
use std::time::Instant;

/// The reconstruction's estimator, as the JSON output names it (`core::recon` module docs).
const RULE: &str =
    "Σw·f/Σw where Σw ≥ c·Σ|w|, else (Σw·f + (c·Σ|w| − Σw)·P)/(c·Σ|w|) with P = Σ|w|·f/Σ|w|";

/// Arguments of `samplescope recon`.
#[derive(clap::Args, Debug)]
pub struct ReconArgs {
    /// Test signal: zone-plate (alias zoneplate), checkerboard, grating, step-edge, polygon.
    #[arg(long, default_value = "zone-plate")]
    pub signal: String,
    /// Signal parameter `key=value`; repeatable. Numbers as typed (`k=512`), enum values
    /// unquoted (`--signal polygon --signal-set shape=square`), booleans `true`/`false`, lists
    /// in brackets (`--signal sum-of-sines --signal-set amps=[0.5,0.25]`; missing entries are
    /// 0). Parameters: zone-plate k, cx, cy; checkerboard checks, height, horizon, tilt;
    /// grating frequency, angle, phase; step-edge angle, offset; polygon shape, angle, size;
    /// sum-of-sines freqs, amps; chirp f0, f1; square frequency; constant value.
    #[arg(long = "signal-set", value_name = "KEY=VALUE")]
    pub signal_set: Vec<String>,
    /// Sample pattern (see `points --list`).
    #[arg(long, default_value = "jitter")]
    pub pattern: String,
    /// Pattern parameter `key=value`; repeatable.
    #[arg(long = "set", value_name = "KEY=VALUE")]
    pub set: Vec<String>,
    /// Number of scattered samples over the whole image (without --spp).
    #[arg(short = 'n', value_parser = parse_n, conflicts_with = "spp")]
    pub n: Option<usize>,
    /// Samples per pixel: supersample with the pattern in every pixel instead.
    #[arg(long)]
    pub spp: Option<usize>,
    /// Seed [default: 0] (refused with a deterministic pattern, which has none).
    #[arg(long)]
    pub seed: Option<u64>,
    /// With -n: keep the samples placed when the pattern stops short of N (poisson-dart,
    /// poisson-bridson) instead of failing. Not with --spp: every pixel needs all its samples.
    #[arg(long, conflicts_with = "spp")]
    pub allow_fewer: bool,
    /// Reconstruction filter (see `filter --list`).
    #[arg(long, default_value = "gaussian")]
    pub filter: String,
    /// Filter parameter `key=value`; repeatable.
    #[arg(long = "filter-set", value_name = "KEY=VALUE")]
    pub filter_set: Vec<String>,
    /// 2D extension of the filter: separable or radial.
    #[arg(long, default_value = "separable")]
    pub mode: String,
    /// Output size W (W×W pixels).
    #[arg(long, default_value_t = 512)]
    pub size: usize,
    /// Output PNG of the reconstruction.
    #[arg(long, value_name = "IMG.png")]
    pub out: Option<String>,
    /// Print one JSON object.
    #[arg(long)]
    pub json: bool,
}

/// The 2D filter from its name, settings and mode.
pub fn filter_from_args(name: &str, settings: &[String], mode: &str) -> Result<Filter2D, CliError> {
    let f: Filter = from_args(
        "",
        name,
        "--filter-set",
        settings,
        "samplescope filter --list",
    )?;
    let mode = Mode2D::from_name(mode).map_err(|e| CliError::Usage(e.to_string()))?;
    Filter2D::new(f, mode).map_err(|e| CliError::Usage(e.to_string()))
}

/// The one-column scene `recon` runs: the signal sampled by the pattern (`Err(n)`: n scattered
/// samples; `Ok(spp)`: supersampled), reconstructed with the filter at W×W, the reference and
/// the error; the zone-plate panel with its reconstruction and error effects, nothing else.
fn one_column_scene(
    signal: Signal,
    pattern: Pattern,
    filter: Filter2D,
    seed: u64,
    w: usize,
    sampling: Result<usize, usize>,
) -> Scene {
    let mut scene = Scene {
        title: "recon".into(),
        columns: vec![Column {
            pattern,
            seed,
            ..Column::default()
        }],
        signal,
        filter,
        ..Scene::default()
    };
    scene.recon.size = w;
    match sampling {
        Ok(spp) => {
            scene.recon.mode = ReconMode::Supersample { spp };
            scene.n = spp;
        }
        Err(n) => {
            scene.recon.mode = ReconMode::Scattered;
            scene.n = n;
        }
    }
    scene.panels = Panels::only(PanelKind::ZonePlate);
    scene.effects.reconstruction = true;
    scene.effects.error = true;
    scene.effects.convergence = false;
    scene.effects.statistics = false;
    scene
}

/// What [`reconstruct`] made: the reconstruction, the reference, the error and the times.
pub struct Reconstructed {
    /// The reconstruction (f64 pixels, row 0 at the bottom).
    pub recon: Arc<samplescope::core::recon::Reconstruction>,
    /// The signal's reference image.
    pub reference: Arc<samplescope::model::ReferenceData>,
    /// The reconstruction's error against the reference.
    pub report: Arc<samplescope::model::ErrorData>,
    /// Sampling and reconstruction, and the reference, in ms.
    pub recon_ms: f64,
    pub reference_ms: f64,
}

impl Reconstructed {
    /// The object `recon --json` prints.
    pub fn json(&self) -> serde_json::Value {
        let (recon, report, reference) = (&self.recon, &self.report, &self.reference);
        serde_json::json!({
            "rmse": report.rmse,
            "psnr": report.psnr,
            "max_abs_error": report.max_abs,
            "zero_weight_pixels": recon.zero_weight,
            "normaliser": {
                "rule": RULE,
                "c": recon.floor,
                "floored_pixels": recon.floored,
            },
            "reference_error_estimate": reference.error_estimate,
            "reference_method": reference.method.label(),
            "timings_ms": { "reconstruction": self.recon_ms, "reference": self.reference_ms },
        })
    }
}

/// Runs `samplescope recon`.
pub fn run(args: &ReconArgs, session: &Session) -> Result<(), CliError> {
    let Some(made) = reconstruct(args, None, session)? else {
        return Ok(());
    };
    let (recon, reference, report) = (&made.recon, &made.reference, &made.report);
    let (recon_ms, reference_ms) = (made.recon_ms, made.reference_ms);
    if args.json {
        outln!("{}", made.json())?;
    } else {
        outln!("RMSE   {:.6}", report.rmse)?;
        outln!("PSNR   {:.3} dB", report.psnr)?;
        outln!("time   {recon_ms:.2} ms (reconstruction, sampling included); reference {reference_ms:.2} ms")?;
        outln!(
            "norm   Σw·f/Σw, floored where Σw < c·Σ|w| (c = {:.3}): {} pixels floored",
            recon.floor,
            recon.floored
        )?;
        if recon.zero_weight > 0 {
            outln!(
                "note   {} pixels had zero total filter weight",
                recon.zero_weight
            )?;
        }
        if let Some(e) = reference.error_estimate {
            if reference.method.estimate_is_bound() {
                outln!("reference's own error ≤ {e:.2e} (any pixel)")?;
            } else {
                outln!("reference's own RMS error ≈ {e:.2e}")?;
            }
        }
    }
    Ok(())
}

/// The reconstruction of `recon` (`None` after `--estimate`), its PNG written with `--out`:
/// the one-column scene evaluated by the engine. `samples` (the Python module's `points=`)
/// replaces the pattern's points by these scattered samples (N = their count; not with
/// `--spp`, `-n` or `--allow-fewer`).
pub fn reconstruct(
    args: &ReconArgs,
    samples: Option<Vec<glam::DVec2>>,
    session: &Session,
) -> Result<Option<Reconstructed>, CliError> {
    let cancel = &session.cancel;
    let signal: Signal = from_args(
        "--signal",
        &args.signal,
        "--signal-set",
        &args.signal_set,
        "samplescope recon --help",
    )?;
    let pattern = super::pattern_from_args(&args.pattern, &args.set)?;
    let filter = filter_from_args(&args.filter, &args.filter_set, &args.mode)?;
    if let Some(why) = filter.reconstruction_refusal() {
        return Err(CliError::Usage(format!("--filter: {why}")));
    }
    super::check_seed(&pattern, args.seed, "--seed")?;
    super::check_allow_fewer(&pattern, args.allow_fewer)?;
    let seed = args.seed.unwrap_or(0);
    let usage = |e: &dyn std::fmt::Display| CliError::Usage(e.to_string());
    // The sizes the estimates take are checked first (the same errors the core gives).
    let range = |field: &'static str, value: usize, max: usize| {
        if (1..=max).contains(&value) {
            Ok(())
        } else {
            Err(usage(&ReconError::OutOfRange {
                field,
                value,
                min: 1,
                max,
            }))
        }
    };
    range("--size", args.size, MAX_W)?;
    let w = args.size;
    // Ok(spp): supersampling; Err(n): n scattered samples.
    let sampling = match (args.spp, args.n) {
        _ if samples.is_some() => {
            if args.spp.is_some() || args.n.is_some() || args.allow_fewer {
                return Err(CliError::Usage(
                    "recon: points are scattered samples: give them without n, spp or allow_fewer"
                        .into(),
                ));
            }
            Err(samples.as_ref().map_or(0, Vec::len))
        }
        (Some(spp), _) => Ok(spp),
        (None, Some(n)) => Err(n),
        (None, None) => {
            return Err(CliError::Usage(
                "recon: give -n N (scattered samples) or --spp S (samples per pixel)".into(),
            ))
        }
    };
    match sampling {
        Ok(spp) => {
            range("--spp", spp, MAX_SPP)?;
            pattern.validate(spp)?;
        }
        Err(n) => pattern.validate(n)?,
    }
    check_outputs(&[("--out", args.out.as_deref())])?;
    // A pattern that may stop short with --allow-fewer: its points are generated here (as the
    // scene's points node would) and the column shows them as imported points.
    let kept = match sampling {
        Err(n) if args.allow_fewer => Some(n),
        _ => None,
    };
    // The scene's estimate (its points node's included, made here with --allow-fewer).
    let mut scene = one_column_scene(signal, pattern, filter, seed, w, sampling);
    if let Some(points) = &samples {
        scene.columns[0].points = Some(ImportedPoints {
            points: points.iter().map(|p| [p.x, p.y]).collect(),
            source: "points".into(),
            ..Default::default()
        });
    }
    let mut plan = samplescope::scene::cost::estimate(&scene);
    if args.out.is_some() {
        // The reconstruction figure's PNG, at its base size.
        let (fw, fh) = base_size(FigureKind::Reconstruction);
        plan.push(budget::png(fw as usize, fh as usize));
    }
    let Some(progress) = session.admit(plan)? else {
        return Ok(None);
    };
    progress.stage(0);
    let t0 = Instant::now();
    if let Some(n) = kept {
        let g = pattern.generate_with(n, seed, cancel)?;
        let points = super::require_points(g, &pattern, true)?;
        scene.columns[0].points = Some(ImportedPoints {
            path: String::new(),
            normalize: false,
            points: points.iter().map(|p| [p.x, p.y]).collect(),
            ..Default::default()
        });
    }
    let generated_ms = t0.elapsed().as_secs_f64() * 1e3;
    // The scene's reconstruction, reference and error nodes, run by the engine's evaluator
    // (no disk cache: recon computes its reference).
    let mut results: HashMap<NodeKind, Arc<NodeResult>> = HashMap::new();
    Evaluator::new(DEFAULT_BUDGET, None).evaluate(&scene, cancel, &mut |_, kind, r| {
        results.insert(kind, r);
    });
    if cancel.is_cancelled() {
        return Err(CliError::Cancelled);
    }
    let value = |kind: NodeKind| results.get(&kind).map(|r| &r.value);
    // The first node that failed by itself (later ones fail through their inputs).
    for kind in NodeKind::ALL {
        match value(kind) {
            Some(Err(NodeError::Input { .. })) | Some(Ok(_)) | None => {}
            Some(Err(e)) => return Err(super::node_error(e)),
        }
    }
    let wall = |kinds: &[NodeKind]| {
        kinds
            .iter()
            .filter_map(|k| results.get(k))
            .map(|r| r.wall.as_secs_f64() * 1e3)
            .sum::<f64>()
    };
    // Sampling included, as before: the points (generated here or by the node) and samples.
    let recon_ms = generated_ms
        + wall(&[
            NodeKind::Points,
            NodeKind::Samples,
            NodeKind::Reconstruction,
        ]);
    let reference_ms = wall(&[NodeKind::Reference]);
    let (recon, reference, report) = match (
        value(NodeKind::Reconstruction),
        value(NodeKind::Reference),
        value(NodeKind::Error),
    ) {
        (
            Some(Ok(NodeValue::Reconstruction(a))),
            Some(Ok(NodeValue::Reference(b))),
            Some(Ok(NodeValue::Error(e))),
        ) => (a.exact.clone(), b.clone(), e.clone()),
        _ => {
            return Err(CliError::Environment(
                "recon: the reconstruction, reference or error node did not finish".into(),
            ))
        }
    };
    if let Some(path) = &args.out {
        // The reconstruction figure, published as `render` publishes it.
        let columns = figure::figure_columns(&scene, std::slice::from_ref(&results), "recon")
            .map_err(|e| usage(&e))?;
        let bytes =
            super::figure_png(&scene, columns, "recon", FigureKind::Reconstruction, cancel)?;
        write_output(Path::new(path), &bytes, cancel)?;
    }
    drop(progress);
    Ok(Some(Reconstructed {
        recon,
        reference,
        report,
        recon_ms,
        reference_ms,
    }))
}
