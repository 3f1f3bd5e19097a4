//! Spectrum requests: one periodogram or the average of K realizations, with a report of
//! what each stage cost and how accurate the result is.

use super::dft::{exact_field_few_rows, periodogram_exact};
use super::nufft::{KernelParams, NufftPlan};
use super::{
    check_points, check_size, k_min, ratio_of_norms, relative_l2_error, Spectrum, SpectrumError,
    MAX_REALIZATIONS,
};
use crate::core::cancel::Cancel;
use crate::core::progress::{no_progress, OnProgress, Progress, Throttle};
use crate::core::rng::derive_seed;
use glam::DVec2;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// Default budget of the error check, in complex multiply-adds of the exact reference
/// (2²² ≈ 4.2 M: a few milliseconds on one core).
pub const DEFAULT_ERROR_CHECK_BUDGET: u64 = 1 << 22;
/// Realizations in flight at once are limited so that their buffers stay under this many
/// bytes: about 56·M² each for the NUFFT (upsampled grid 32·M², kept columns 16·M², output
/// 8·M²), counted as 64·M².
const IN_FLIGHT_BYTES: usize = 1 << 30;

/// How a periodogram is computed.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub enum Method {
    /// The exact DFT ([`periodogram_exact`]): N·M²/2 complex multiply-adds.
    Exact,
    /// The NUFFT ([`NufftPlan`]) with a relative ℓ2 tolerance on P in [1e-12, 1e-2].
    Nufft {
        /// Requested relative ℓ2 error of the periodogram (DC excluded).
        tolerance: f64,
    },
}

/// Whether displays show DC (P(0) = N) or mask it. The data always hold the true value.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
pub enum DcMode {
    /// Show P(0) as computed.
    #[default]
    Show,
    /// Paint DC over with its neighbours' mean in display images.
    Mask,
}

/// What to compute: an M×M periodogram by `method`, averaged over `realizations` point sets.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct SpectrumRequest {
    /// Grid size M (2..=4096); [`super::psa_default_size`] gives PSA's choice for N points.
    pub size: usize,
    /// Exact DFT or NUFFT with a tolerance.
    pub method: Method,
    /// Number of realizations K averaged (1..=1024).
    pub realizations: usize,
    /// Display treatment of DC.
    pub dc: DcMode,
    /// Largest cost of the error check, in complex multiply-adds of the exact reference
    /// (0 disables it). See [`SpectrumReport::error`].
    pub error_check_budget: u64,
}

impl Default for SpectrumRequest {
    /// 256², NUFFT at 1e-6, one realization, DC shown, default error-check budget.
    fn default() -> Self {
        SpectrumRequest {
            size: 256,
            method: Method::Nufft { tolerance: 1e-6 },
            realizations: 1,
            dc: DcMode::Show,
            error_check_budget: DEFAULT_ERROR_CHECK_BUDGET,
        }
    }
}

impl SpectrumRequest {
    /// Checks size, tolerance and realizations.
    ///
    /// # Errors
    /// [`SpectrumError::InvalidSize`], [`SpectrumError::InvalidTolerance`],
    /// [`SpectrumError::InvalidRealizations`].
    pub fn validate(&self) -> Result<(), SpectrumError> {
        check_size(self.size)?;
        if let Method::Nufft { tolerance } = self.method {
            super::nufft::kernel_params(tolerance)?;
        }
        if !(1..=MAX_REALIZATIONS).contains(&self.realizations) {
            return Err(SpectrumError::InvalidRealizations {
                k: self.realizations,
                max: MAX_REALIZATIONS,
            });
        }
        Ok(())
    }
}

/// The measured error of a NUFFT periodogram against the exact one (realization 0).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ErrorCheck {
    /// ‖P_nufft − P_exact‖₂ / ‖P_exact‖₂ over the checked frequencies, DC excluded.
    pub relative_l2: f64,
    /// Frequencies compared (M² when `full`).
    pub frequencies: usize,
    /// Whether the whole grid was compared (else a set of evenly spaced rows).
    pub full: bool,
}

/// What a spectrum cost and how accurate it is.
#[derive(Debug, Clone, PartialEq)]
pub struct SpectrumReport {
    /// Time per stage, summed over realizations (thread time: realizations run in parallel,
    /// so the sum may exceed `wall`). Stages: `generate`, then `spread`, `fft`, `deconvolve`
    /// (NUFFT) or `exact`, then `error-check` (NUFFT with a budget) and `average` (the sum
    /// and the division, on the calling thread).
    pub stages: Vec<(&'static str, Duration)>,
    /// Wall time of the whole request.
    pub wall: Duration,
    /// The tolerance asked for (`None` for the exact method).
    pub tolerance: Option<f64>,
    /// The NUFFT kernel used and the upsampled grid size.
    pub kernel: Option<(KernelParams, usize)>,
    /// The measured error of realization 0 against the exact periodogram, when affordable:
    /// the whole grid if N·(⌊M/2⌋+1)·(2⌊M/2⌋+1) ≤ budget, else R = ⌊budget/(N·M)⌋ evenly
    /// spaced rows (R ≥ 1), else `None` (also for the exact method and a budget of 0).
    pub error: Option<ErrorCheck>,
    /// Fewest and most points over the realizations.
    pub n_points_range: (usize, usize),
    /// Number of realizations averaged.
    pub realizations: usize,
}

struct Realization {
    power: Vec<f64>,
    n_points: usize,
    times: [Duration; 4],
    check: Option<PendingCheck>,
}

const STAGE_NAMES: [&str; 4] = ["generate", "spread", "fft", "deconvolve"];
/// The stage of the error check ([`SpectrumReport::finish_check`]).
const ERROR_CHECK_STAGE: &str = "error-check";

/// How many NUFFT plans [`cached_plan`] keeps (most recently used first).
const PLAN_CACHE: usize = 4;
/// Largest M whose plan is kept: its workspaces (a (2M)² complex grid each, 16 MiB at M = 512)
/// stay allocated while it is cached, so larger plans are made afresh every time.
const PLAN_CACHE_MAX_M: usize = 512;

/// Recently used plans by (M, tolerance bits): a plan's FFT plan, deconvolution table and
/// workspace buffers are reused by the next periodogram of the same size and tolerance (a
/// slider drag), instead of being planned and allocated (and page-faulted) again. The same
/// plan computes the same bits as a fresh one.
static PLANS: Mutex<Vec<(usize, u64, std::sync::Arc<NufftPlan>)>> = Mutex::new(Vec::new());

/// The plan for (m, tolerance), from [`PLANS`] or new.
fn cached_plan(m: usize, tolerance: f64) -> Result<std::sync::Arc<NufftPlan>, SpectrumError> {
    if m > PLAN_CACHE_MAX_M {
        return Ok(std::sync::Arc::new(NufftPlan::new(m, tolerance)?));
    }
    let key = (m, tolerance.to_bits());
    let mut plans = PLANS.lock().unwrap_or_else(|e| e.into_inner());
    if let Some(i) = plans.iter().position(|(a, b, _)| (*a, *b) == key) {
        let entry = plans.remove(i);
        let plan = entry.2.clone();
        plans.insert(0, entry);
        return Ok(plan);
    }
    drop(plans);
    let plan = std::sync::Arc::new(NufftPlan::new(m, tolerance)?);
    let mut plans = PLANS.lock().unwrap_or_else(|e| e.into_inner());
    plans.insert(0, (m, tolerance.to_bits(), plan.clone()));
    plans.truncate(PLAN_CACHE);
    Ok(plan)
}

/// Least time between two partial results of [`average_periodogram_progressive`].
pub const PARTIAL_INTERVAL: Duration = Duration::from_millis(60);

/// The mean periodogram of K point sets `generate(derive_seed(seed, r))`, r = 0..K, with the
/// method of `req`:
///
/// P̄(k) = (1/K) Σ_r P_r(k).
///
/// Realizations run in parallel (rayon) in groups (two per thread, at most 16, fewer for
/// large M so that the buffers in flight stay under 1 GiB; buffers are recycled between
/// groups); the sum runs in realization order on the calling thread, so the bits do not
/// depend on the number of threads. A NUFFT request builds its
/// plan once. For the NUFFT, realization 0 is also compared with the exact periodogram when
/// the request's error-check budget allows ([`SpectrumReport::error`]).
///
/// # Errors
/// Request errors ([`SpectrumRequest::validate`]); [`SpectrumError::Generator`] when
/// `generate` fails (the lowest failing realization is reported);
/// [`SpectrumError::EmptyPointSet`] / [`SpectrumError::InvalidPoint`] for bad points;
/// [`SpectrumError::Cancelled`].
pub fn average_periodogram<G, E>(
    req: &SpectrumRequest,
    seed: u64,
    generate: G,
    cancel: &Cancel,
) -> Result<(Spectrum, SpectrumReport), SpectrumError>
where
    G: Fn(u64) -> Result<Vec<DVec2>, E> + Sync,
    E: Into<Box<dyn std::error::Error + Send + Sync>>,
{
    average_periodogram_progressive(req, seed, generate, cancel, Duration::MAX, &mut no_progress)
}

/// [`average_periodogram`] that also reports the running average to `progress`
/// ([`crate::core::progress`]): after each group of realizations, d of K done; while more
/// remain, the report carries the mean of the first d realizations (a copy, so at most once
/// per `min_interval` since the start or the last such report: the engine uses
/// [`PARTIAL_INTERVAL`]); the last report, K of K, carries the returned spectrum. The returned
/// spectrum is bit-identical to [`average_periodogram`]'s (the partial means are copies; the
/// running sum is untouched).
pub fn average_periodogram_progressive<G, E>(
    req: &SpectrumRequest,
    seed: u64,
    generate: G,
    cancel: &Cancel,
    min_interval: Duration,
    progress: &mut OnProgress<'_, Spectrum>,
) -> Result<(Spectrum, SpectrumReport), SpectrumError>
where
    G: Fn(u64) -> Result<Vec<DVec2>, E> + Sync,
    E: Into<Box<dyn std::error::Error + Send + Sync>>,
{
    let (spectrum, mut report, check) =
        average_periodogram_staged(req, seed, generate, cancel, min_interval, progress)?;
    report.finish_check(check, cancel)?;
    Ok((spectrum, report))
}

/// [`average_periodogram_progressive`] in two stages, so that a caller can show the spectrum
/// before its measured error: the spectrum (bit-identical) and a report without the error
/// check, plus the check made ready (realization 0's points and the part of its periodogram
/// compared), which [`SpectrumReport::finish_check`] runs and records; the report is then the
/// one [`average_periodogram_progressive`] returns. The check is `None` for the exact method
/// or a budget of 0.
pub fn average_periodogram_staged<G, E>(
    req: &SpectrumRequest,
    seed: u64,
    generate: G,
    cancel: &Cancel,
    min_interval: Duration,
    progress: &mut OnProgress<'_, Spectrum>,
) -> Result<(Spectrum, SpectrumReport, Option<PendingCheck>), SpectrumError>
where
    G: Fn(u64) -> Result<Vec<DVec2>, E> + Sync,
    E: Into<Box<dyn std::error::Error + Send + Sync>>,
{
    let start = Instant::now();
    req.validate()?;
    let m = req.size;
    let plan = match req.method {
        Method::Nufft { tolerance } => Some(cached_plan(m, tolerance)?),
        Method::Exact => None,
    };
    let k = req.realizations;
    // Realizations in flight: two per thread (so that a slow one does not idle a thread),
    // fewer when their buffers would pass IN_FLIGHT_BYTES. The sum below runs in realization
    // order whatever the group size, so the bits do not depend on it.
    let group = (2 * rayon::current_num_threads())
        .min(IN_FLIGHT_BYTES / (64 * m * m))
        .clamp(1, 16);
    // Periodogram buffers are recycled between groups (fresh M² buffers cost page faults).
    let buffers: Mutex<Vec<Vec<f64>>> = Mutex::new(Vec::new());
    let take_buffer = || {
        buffers
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .pop()
            .unwrap_or_default()
    };
    let one = |r: usize| -> Result<Realization, SpectrumError> {
        cancel.check()?;
        let mut times = [Duration::ZERO; 4];
        let t0 = Instant::now();
        let points =
            generate(derive_seed(seed, r as u64)).map_err(|e| SpectrumError::Generator {
                realization: r,
                source: e.into(),
            })?;
        times[0] = t0.elapsed();
        check_points(&points)?;
        let mut check = None;
        let n_points = points.len();
        let power = match &plan {
            Some(plan) => {
                let mut power = take_buffer();
                let t = plan.periodogram_into(&points, &mut power, cancel)?;
                times[1] = t.spread;
                times[2] = t.fft;
                times[3] = t.deconvolve;
                if r == 0 && req.error_check_budget > 0 {
                    // Kept for the error check, which runs once the average is complete.
                    check = Some(PendingCheck::new(points, &power, m, req.error_check_budget));
                }
                power
            }
            None => {
                let t = Instant::now();
                let s = periodogram_exact(&points, m, cancel)?;
                times[1] = t.elapsed();
                s.power
            }
        };
        Ok(Realization {
            power,
            n_points,
            times,
            check,
        })
    };

    // The running sum; realization 0's periodogram becomes it (0 + p = p exactly, so the bits
    // are those of summing from zero, without an M² buffer to fault in and add).
    let mut acc: Vec<f64> = Vec::new();
    let mut times = [Duration::ZERO; 4];
    let mut average_time = Duration::ZERO;
    let mut check = None;
    let (mut n_min, mut n_max) = (usize::MAX, 0);
    let mut throttle = Throttle::new(min_interval);
    for g0 in (0..k).step_by(group) {
        let done = g0;
        if done > 0 && throttle.due() {
            let inv = 1.0 / done as f64;
            let partial = Spectrum {
                m,
                power: acc.iter().map(|a| a * inv).collect(),
                n_points: n_min,
                realizations: done,
                dc: req.dc,
            };
            progress(Progress::with(done, k, &partial));
            throttle.restart();
        } else if done > 0 {
            progress(Progress::at(done, k));
        }
        cancel.check()?;
        let results: Vec<Result<Realization, SpectrumError>> =
            (g0..(g0 + group).min(k)).into_par_iter().map(one).collect();
        for result in results {
            let real = result?;
            let t = Instant::now();
            if acc.is_empty() {
                acc = real.power;
            } else {
                for (a, p) in acc.iter_mut().zip(&real.power) {
                    *a += p;
                }
                buffers
                    .lock()
                    .unwrap_or_else(|e| e.into_inner())
                    .push(real.power);
            }
            average_time += t.elapsed();
            for (total, t) in times.iter_mut().zip(real.times) {
                *total += t;
            }
            n_min = n_min.min(real.n_points);
            n_max = n_max.max(real.n_points);
            if real.check.is_some() {
                check = real.check;
            }
        }
    }
    let t = Instant::now();
    if k > 1 {
        let inv = 1.0 / k as f64;
        acc.iter_mut().for_each(|a| *a *= inv);
    }
    average_time += t.elapsed();

    let mut stages = vec![(STAGE_NAMES[0], times[0])];
    match &plan {
        Some(_) => stages.extend((1..4).map(|i| (STAGE_NAMES[i], times[i]))),
        None => stages.push(("exact", times[1])),
    }
    stages.push(("average", average_time));
    let spectrum = Spectrum {
        m,
        power: acc,
        n_points: n_min,
        realizations: k,
        dc: req.dc,
    };
    let report = SpectrumReport {
        stages,
        wall: start.elapsed(),
        tolerance: plan.as_ref().and_then(|p| p.tolerance()),
        kernel: plan.as_ref().map(|p| (p.kernel(), p.upsampled())),
        error: None,
        n_points_range: (n_min, n_max),
        realizations: k,
    };
    progress(Progress::with(k, k, &spectrum));
    Ok((spectrum, report, check))
}

/// The spectrum of one given point set (K must be 1): [`average_periodogram`] with a
/// generator that returns `points`.
///
/// # Errors
/// [`SpectrumError::InvalidRealizations`] (with max 1) when `req.realizations != 1`; otherwise
/// as [`average_periodogram`].
pub fn analyze_points(
    req: &SpectrumRequest,
    points: &[DVec2],
    cancel: &Cancel,
) -> Result<(Spectrum, SpectrumReport), SpectrumError> {
    if req.realizations != 1 {
        return Err(SpectrumError::InvalidRealizations {
            k: req.realizations,
            max: 1,
        });
    }
    average_periodogram(
        req,
        0,
        |_| Ok::<_, std::convert::Infallible>(points.to_vec()),
        cancel,
    )
}

/// The error check of realization 0, made ready while its periodogram is at hand and run
/// once the average is complete ([`average_periodogram_staged`]; see
/// [`SpectrumReport::error`]): its points and the part of its NUFFT periodogram the check
/// compares (the whole grid when the exact periodogram fits the budget, else the checked rows).
#[derive(Debug, Clone)]
pub struct PendingCheck {
    points: Vec<DVec2>,
    m: usize,
    what: Option<CheckedPart>,
}

#[derive(Debug, Clone)]
enum CheckedPart {
    /// The whole periodogram (N·(⌊M/2⌋+1)·(2⌊M/2⌋+1) ≤ budget).
    Full(Vec<f64>),
    /// Rows `ky` (frequencies), each M values of the periodogram, row after row.
    Rows { ky: Vec<i64>, power: Vec<f64> },
}

impl PendingCheck {
    /// The check of `power` (the M×M NUFFT periodogram of `points`) within `budget` complex
    /// multiply-adds of the exact reference: the whole grid, R = ⌊budget/(N·M)⌋ evenly spaced
    /// rows, or nothing when not even one row fits (then [`Self::run`] gives `None`).
    fn new(points: Vec<DVec2>, power: &[f64], m: usize, budget: u64) -> Self {
        let n = points.len() as u64;
        let k0 = k_min(m);
        let full_cost = n * (-k0 + 1) as u64 * (-2 * k0 + 1) as u64;
        let what = if full_cost <= budget {
            Some(CheckedPart::Full(power.to_vec()))
        } else {
            let rows = (budget / (n * m as u64)) as usize;
            (rows > 0).then(|| {
                let ky: Vec<i64> = (0..rows)
                    .map(|i| k0 + ((2 * i + 1) * m / (2 * rows)) as i64)
                    .collect();
                let power = ky
                    .iter()
                    .flat_map(|&kyr| {
                        let row = (kyr - k0) as usize * m;
                        power[row..row + m].iter().copied()
                    })
                    .collect();
                CheckedPart::Rows { ky, power }
            })
        };
        PendingCheck { points, m, what }
    }

    /// Compares the kept periodogram with the exact one: ‖P_nufft − P_exact‖₂ / ‖P_exact‖₂ over
    /// the checked frequencies, DC excluded (`None` when no row fitted the budget).
    ///
    /// # Errors
    /// [`SpectrumError::Cancelled`].
    pub fn run(&self, cancel: &Cancel) -> Result<Option<ErrorCheck>, SpectrumError> {
        let (points, m) = (&self.points, self.m);
        let n = points.len();
        let k0 = k_min(m);
        match &self.what {
            None => Ok(None),
            Some(CheckedPart::Full(power)) => {
                let exact = periodogram_exact(points, m, cancel)?;
                let approx = Spectrum::from_power(m, power.clone(), n);
                Ok(Some(ErrorCheck {
                    relative_l2: relative_l2_error(&approx, &exact, true),
                    frequencies: m * m,
                    full: true,
                }))
            }
            Some(CheckedPart::Rows { ky, power }) => {
                let field = exact_field_few_rows(points, k0, m, ky, cancel)?;
                let inv_n = 1.0 / n as f64;
                let (mut num, mut den) = (0.0f64, 0.0f64);
                for (r, &kyr) in ky.iter().enumerate() {
                    for ix in 0..m {
                        let kx = k0 + ix as i64;
                        if kx == 0 && kyr == 0 {
                            continue;
                        }
                        let re = field[r * 2 * m + ix];
                        let im = field[r * 2 * m + m + ix];
                        let exact = (re * re + im * im) * inv_n;
                        let a = power[r * m + ix];
                        num += (a - exact) * (a - exact);
                        den += exact * exact;
                    }
                }
                Ok(Some(ErrorCheck {
                    relative_l2: ratio_of_norms(num, den),
                    frequencies: ky.len() * m,
                    full: false,
                }))
            }
        }
    }
}

impl SpectrumReport {
    /// Runs the error check made ready by [`average_periodogram_staged`] (if any) and records
    /// it: [`Self::error`], its stage `error-check` (before `average`) and its time in the wall
    /// time. The report is then the one [`average_periodogram`] returns.
    ///
    /// # Errors
    /// [`SpectrumError::Cancelled`].
    pub fn finish_check(
        &mut self,
        check: Option<PendingCheck>,
        cancel: &Cancel,
    ) -> Result<(), SpectrumError> {
        let Some(check) = check else {
            return Ok(());
        };
        let t = Instant::now();
        self.error = check.run(cancel)?;
        let took = t.elapsed();
        let at = self
            .stages
            .iter()
            .position(|(name, _)| *name == "average")
            .unwrap_or(self.stages.len());
        self.stages.insert(at, (ERROR_CHECK_STAGE, took));
        self.wall += took;
        Ok(())
    }
}
