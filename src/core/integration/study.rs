//! The integration-error study: for each N of a list, the mean squared error of the estimate
//! (1/N)·Σ f(xᵢ) of I = ∫ f over [0,1]^D (D = 2 by default) over many realizations of a
//! pattern, and the log–log slope.
//!
//! # Dimensions
//!
//! [`StudyRequest::dims`] is D, in 1..=[`MAX_DIMS`]. D = 2 is the 2D study: every pattern,
//! every integrand, the points of [`Pattern::generate_with`]. Other D need a d-dimensional
//! integrand (Genz's families, [`super::genz`]) and a pattern with a d-dimensional form
//! ([`Pattern::max_dims`] ≥ D, points from [`Pattern::generate_cube`]), with N·D at most
//! [`MAX_COORDS`]. Points are held as [`CubePoints`] in every D (D = 2: x, y).
//!
//! # Realizations
//!
//! Realization r (0 ≤ r < R) uses the stream s_r = [`derive_seed`]`(seed, r)`:
//! - a pattern whose points depend on the seed ([`Pattern::is_random`]) generates with seed s_r,
//!   the same seed for every N (so a progressive pattern's N-point set is a prefix of its
//!   larger ones);
//! - a deterministic pattern is moved by a Cranley–Patterson rotation: u = (u₁, …, u_D), the
//!   first D [`Rng::next_f64`] of `Rng::new(s_r)`, is added to every point modulo 1 — unless
//!   [`StudyRequest::shift`] is false, when every realization is the same point set;
//! - with [`StudyRequest::randomize`], f itself is a new random instance of its family,
//!   [`Integrand::randomized_in`] D with `Rng::new(derive_seed(s_r, INTEGRAND_STREAM))`, and the
//!   error is measured against that instance's exact integral.
//!
//! # Statistics per N
//!
//! With eᵣ = (1/N)Σ f(xᵢ) − I_r the error of realization r and R realizations:
//! - `mse` = (1/R) Σ eᵣ²;
//! - `mse_stderr` = s/√R, s² = (1/(R−1)) Σ (eᵣ² − mse)²: the standard error of that mean
//!   (`None` for R = 1);
//! - `bias2` = ē², ē = (1/R) Σ eᵣ: the squared bias of the mean estimate;
//! - `variance` = (1/R) Σ (eᵣ − ē)²: so that mse = bias2 + variance (up to rounding).
//!
//! # Slope
//!
//! [`log_log_fit`]: ordinary least squares of yₖ = ln mseₖ on xₖ = ln Nₖ over the K rows with
//! mse > 0: slope b = Σ(x − x̄)(y − ȳ)/Sxx, Sxx = Σ(x − x̄)², and its standard error
//! √(Σ rₖ² / (K − 2) / Sxx) from the residuals rₖ = yₖ − ȳ − b(xₖ − x̄) (`None` for K ≤ 2).
//! It measures how well one power law fits the rows, statistical noise and curvature
//! together.
//!
//! # Speed and determinism
//!
//! [`run_study`] splits the work into tasks — one per realization for a progressive pattern
//! (the largest N is generated once and every N is read off its prefix sums), one per
//! (realization, N) otherwise — run in parallel with rayon in chunks and collected in task
//! order; a deterministic pattern is generated once per N (or once for a progressive one) and
//! shared by every realization, and when every realization is the same (deterministic, no
//! shift, no randomisation) only one is computed. The statistics are reduced serially in
//! realization order, so the results are the same bits whatever the number of threads, and the
//! same as [`run_study_naive`], the plain serial loop over realizations and N.

use super::genz::Genz;
use super::integrands::{Integrand, Prepared};
use crate::core::budget::{self, Estimate, Unit};
use crate::core::cancel::Cancel;
use crate::core::cube::{CubePoints, MAX_COORDS, MAX_DIMS};
use crate::core::params::{ParamError, Params};
use crate::core::pattern::{Pattern, PatternError};
use crate::core::progress::{OnProgress, Progress};
use crate::core::rng::{derive_seed, Rng};
use glam::DVec2;
use rayon::prelude::*;
use std::time::{Duration, Instant};

/// The largest N of a study.
pub const MAX_STUDY_N: usize = 1 << 20;
/// The most values of N in one study.
pub const MAX_NS: usize = 64;
/// The most realizations of a study.
pub const MAX_REALIZATIONS: usize = 4096;
/// Child stream (of each realization's stream) that draws the random integrand instance.
pub const INTEGRAND_STREAM: u64 = 0x1A7E_6EA7_E000_0001;
/// Points evaluated between two checks of the cancellation token.
const CHECK_EVERY: usize = 4096;
/// Largest total of points of a deterministic pattern kept to be shared by all realizations.
const CACHE_BYTES: usize = 1 << 28;

/// What to study.
#[derive(Debug, Clone, PartialEq)]
pub struct StudyRequest {
    /// The sample pattern.
    pub pattern: Pattern,
    /// The integrand (with `randomize`, the family drawn from).
    pub integrand: Integrand,
    /// The sample counts, each in 1..=[`MAX_STUDY_N`], at most [`MAX_NS`] values; rows follow
    /// this order.
    pub ns: Vec<usize>,
    /// Realizations R in 1..=[`MAX_REALIZATIONS`].
    pub realizations: usize,
    /// Seed of every realization's stream.
    pub seed: u64,
    /// Cranley–Patterson rotation of deterministic patterns (ignored by random ones).
    pub shift: bool,
    /// A new random instance of the integrand's family per realization.
    pub randomize: bool,
    /// The dimension D of the cube integrated over, in 1..=[`MAX_DIMS`] (module docs).
    pub dims: usize,
}

impl Default for StudyRequest {
    /// Jittered sampling of the default disk, N = 16 … 4096 (powers of 4), 64 realizations.
    fn default() -> Self {
        StudyRequest {
            pattern: Pattern::default(),
            integrand: Integrand::default(),
            ns: vec![16, 64, 256, 1024, 4096],
            realizations: 64,
            seed: 0,
            shift: true,
            randomize: false,
            dims: 2,
        }
    }
}

impl StudyRequest {
    /// Whether realizations are Cranley–Patterson rotated: a deterministic pattern with
    /// [`StudyRequest::shift`].
    pub fn applies_shift(&self) -> bool {
        self.shift && !self.pattern.is_random()
    }

    /// Whether every realization is the same computation (deterministic pattern, no shift,
    /// no randomisation).
    fn identical_realizations(&self) -> bool {
        !self.pattern.is_random() && !self.shift && !self.randomize
    }
}

/// The statistics of one N.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StudyRow {
    /// The sample count.
    pub n: usize,
    /// Mean squared error over the realizations.
    pub mse: f64,
    /// Standard error of `mse` (`None` with one realization).
    pub mse_stderr: Option<f64>,
    /// Variance of the estimate over the realizations (divided by R).
    pub variance: f64,
    /// Squared bias of the mean estimate.
    pub bias2: f64,
}

/// Where the time of a study went.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct StudyTimings {
    /// Generating points, summed over tasks (so over threads).
    pub points: Duration,
    /// Evaluating the integrand, summed over tasks.
    pub evaluation: Duration,
    /// The serial reduction into rows and the fit.
    pub statistics: Duration,
    /// Wall time of the whole study.
    pub total: Duration,
}

/// The result of a study.
#[derive(Debug, Clone, PartialEq)]
pub struct Study {
    /// One row per requested N, in the requested order.
    pub rows: Vec<StudyRow>,
    /// Least-squares slope of ln mse on ln N ([`log_log_fit`]); `None` with fewer than two
    /// distinct N with mse > 0.
    pub slope: Option<f64>,
    /// Standard error of the slope; `None` with fewer than three such N.
    pub slope_stderr: Option<f64>,
    /// The exact integral (with randomisation: the mean of the instances' integrals).
    pub reference: f64,
    /// The realizations it averages: the request's R, or r < R in a partial study
    /// ([`run_study`]'s progress).
    pub realizations: usize,
    /// Timings (not part of the deterministic result).
    pub timings: StudyTimings,
}

/// Why a study could not run. Every variant names the offending flag or value.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum StudyError {
    /// No sample count was given.
    #[error("--n: no value given; give 1 to {max} sample counts, each in 1..={MAX_STUDY_N}", max = MAX_NS)]
    NoN,
    /// Too many sample counts.
    #[error("--n: {count} values given; at most {max} are allowed", max = MAX_NS)]
    TooManyN { count: usize },
    /// A sample count out of range.
    #[error("--n {value}: each sample count must be an integer in 1..={max}", max = MAX_STUDY_N)]
    NOutOfRange { value: usize },
    /// The number of realizations is out of range.
    #[error("--realizations {value}: must be an integer in 1..={max}", max = MAX_REALIZATIONS)]
    Realizations { value: usize },
    /// A pattern or integrand parameter is out of range.
    #[error(transparent)]
    Param(#[from] ParamError),
    /// The pattern cannot make this N.
    #[error("--n {n}: {source}")]
    Pattern { n: usize, source: PatternError },
    /// The dimension is out of range.
    #[error("--dims {dims}: must be an integer in 1..={MAX_DIMS}")]
    Dims { dims: usize },
    /// A 2D integrand asked for in another dimension.
    #[error(
        "--dims {dims}: {integrand} is defined on [0,1]² only (--dims 2); the integrands \
         defined in any dimension are {}",
        genz_names()
    )]
    PlanarIntegrand {
        integrand: &'static str,
        dims: usize,
    },
    /// The pattern has no form in this dimension ([`Pattern::check_dims`]).
    #[error("--dims {dims}: {source}")]
    PatternDims { dims: usize, source: PatternError },
    /// N points of D coordinates are more than a point set holds.
    #[error(
        "--n {n} with --dims {dims}: N · D must be at most {MAX_COORDS} (N ≤ {} in {dims} \
         dimensions)",
        MAX_COORDS / dims
    )]
    TooManyCoords { n: usize, dims: usize },
    /// The study was cancelled.
    #[error("cancelled")]
    Cancelled,
}

impl From<crate::core::cancel::Cancelled> for StudyError {
    fn from(_: crate::core::cancel::Cancelled) -> Self {
        StudyError::Cancelled
    }
}

/// The integrands defined in any dimension, comma-separated.
fn genz_names() -> String {
    Integrand::all()
        .iter()
        .filter(|f| !f.is_planar())
        .map(|f| f.name())
        .collect::<Vec<_>>()
        .join(", ")
}

/// Checks the limits of a request (the sizes first, then the dimension, then the parameter
/// sets).
pub fn check_request(req: &StudyRequest) -> Result<(), StudyError> {
    if req.ns.is_empty() {
        return Err(StudyError::NoN);
    }
    if req.ns.len() > MAX_NS {
        return Err(StudyError::TooManyN {
            count: req.ns.len(),
        });
    }
    if let Some(&value) = req.ns.iter().find(|&&n| !(1..=MAX_STUDY_N).contains(&n)) {
        return Err(StudyError::NOutOfRange { value });
    }
    if !(1..=MAX_REALIZATIONS).contains(&req.realizations) {
        return Err(StudyError::Realizations {
            value: req.realizations,
        });
    }
    let dims = req.dims;
    if !(1..=MAX_DIMS).contains(&dims) {
        return Err(StudyError::Dims { dims });
    }
    if dims != 2 && req.integrand.is_planar() {
        return Err(StudyError::PlanarIntegrand {
            integrand: req.integrand.name(),
            dims,
        });
    }
    req.pattern.check_params()?;
    req.integrand.check_params()?;
    // The lists of a Genz integrand have 1 or D entries (a random instance draws D).
    if !req.randomize {
        if let Some(g) = req.integrand.in_dims(dims) {
            g?;
        }
    }
    req.pattern
        .check_dims(dims)
        .map_err(|source| StudyError::PatternDims { dims, source })?;
    // Every N the pattern would refuse is refused before any estimate or work.
    for &n in &req.ns {
        if n.saturating_mul(dims) > MAX_COORDS {
            return Err(StudyError::TooManyCoords { n, dims });
        }
        req.pattern
            .validate_cube(n, dims)
            .map_err(|source| StudyError::Pattern { n, source })?;
    }
    Ok(())
}

/// `n` points of the pattern in `dims` dimensions (D = 2: its 2D points), or the error naming
/// `n`.
fn points(
    pattern: &Pattern,
    n: usize,
    dims: usize,
    seed: u64,
    cancel: &Cancel,
) -> Result<CubePoints, StudyError> {
    if dims == 2 {
        return generate(pattern, n, seed, cancel).map(|p| CubePoints::from_2d(&p));
    }
    pattern
        .generate_cube(n, dims, seed, cancel)
        .map_err(|e| match e {
            PatternError::Cancelled => StudyError::Cancelled,
            source => StudyError::Pattern { n, source },
        })
}

/// `n` points of the pattern, or the error naming `n`.
fn generate(
    pattern: &Pattern,
    n: usize,
    seed: u64,
    cancel: &Cancel,
) -> Result<Vec<DVec2>, StudyError> {
    // A pattern that stops short of N (dart throwing) is [`PatternError::TooFew`], naming the
    // parameter that stopped it.
    pattern
        .generate_with(n, seed, cancel)
        .and_then(|g| g.require_all(pattern.name()))
        .map_err(|e| match e {
            PatternError::Cancelled => StudyError::Cancelled,
            source => StudyError::Pattern { n, source },
        })
}

/// x + u modulo 1 for x, u in [0, 1).
#[inline]
fn wrap(v: f64) -> f64 {
    if v >= 1.0 {
        v - 1.0
    } else {
        v
    }
}

/// Realization r's integrand instance, rotation (D coordinates) and stream.
fn instance(req: &StudyRequest, r: usize) -> (Integrand, Option<Vec<f64>>, u64) {
    let stream = derive_seed(req.seed, r as u64);
    let integrand = if req.randomize {
        req.integrand.randomized_in(
            req.dims,
            &mut Rng::new(derive_seed(stream, INTEGRAND_STREAM)),
        )
    } else {
        req.integrand
    };
    let shift = req.applies_shift().then(|| {
        let mut rng = Rng::new(stream);
        (0..req.dims).map(|_| rng.next_f64()).collect()
    });
    (integrand, shift, stream)
}

/// An integrand ready for the hot loop: a 2D one ([`Prepared`], D = 2) or a d-dimensional
/// one ([`Genz`], any D).
enum Evaluator {
    Plane(Prepared),
    Cube(Genz),
}

impl Evaluator {
    fn new(integrand: &Integrand, dims: usize) -> Result<Evaluator, StudyError> {
        Ok(match integrand.in_dims(dims) {
            Some(g) => Evaluator::Cube(g?),
            None => Evaluator::Plane(Prepared::new(integrand)?),
        })
    }

    fn integral(&self, integrand: &Integrand) -> f64 {
        match self {
            Evaluator::Plane(_) => integrand.integral(),
            Evaluator::Cube(g) => g.integral(),
        }
    }
}

/// Per N, the statistics of the errors `errors[r·K + k]` (R rows of K values, realization
/// order), reduced serially in that order.
fn reduce(ns: &[usize], errors: &[f64], realizations: usize) -> Vec<StudyRow> {
    let k_len = ns.len();
    let rf = realizations as f64;
    ns.iter()
        .enumerate()
        .map(|(k, &n)| {
            let column = || (0..realizations).map(|r| errors[r * k_len + k]);
            let mean = column().sum::<f64>() / rf;
            let mse = column().map(|e| e * e).sum::<f64>() / rf;
            let variance = column().map(|e| (e - mean) * (e - mean)).sum::<f64>() / rf;
            let mse_stderr = (realizations > 1).then(|| {
                let s2 = column().map(|e| (e * e - mse) * (e * e - mse)).sum::<f64>() / (rf - 1.0);
                (s2 / rf).sqrt()
            });
            StudyRow {
                n,
                mse,
                mse_stderr,
                variance,
                bias2: mean * mean,
            }
        })
        .collect()
}

/// Least-squares slope of ln mse on ln N over the rows with a positive, finite mse, and its
/// standard error from the residuals (module docs): `(None, None)` with fewer than two distinct
/// N, no standard error with fewer than three rows.
pub fn log_log_fit(rows: &[StudyRow]) -> (Option<f64>, Option<f64>) {
    let pts: Vec<(f64, f64)> = rows
        .iter()
        .filter(|r| r.mse > 0.0 && r.mse.is_finite())
        .map(|r| ((r.n as f64).ln(), r.mse.ln()))
        .collect();
    let k = pts.len();
    if k < 2 {
        return (None, None);
    }
    let kf = k as f64;
    let xm = pts.iter().map(|p| p.0).sum::<f64>() / kf;
    let ym = pts.iter().map(|p| p.1).sum::<f64>() / kf;
    let sxx: f64 = pts.iter().map(|p| (p.0 - xm) * (p.0 - xm)).sum();
    if sxx <= 0.0 {
        return (None, None);
    }
    let sxy: f64 = pts.iter().map(|p| (p.0 - xm) * (p.1 - ym)).sum();
    let slope = sxy / sxx;
    let stderr = (k > 2).then(|| {
        let ss: f64 = pts
            .iter()
            .map(|p| {
                let res = p.1 - ym - slope * (p.0 - xm);
                res * res
            })
            .sum();
        (ss / (kf - 2.0) / sxx).sqrt()
    });
    (Some(slope), stderr)
}

/// The rows, fit and reference of the errors and per-realization integrals.
fn finish(
    req: &StudyRequest,
    errors: &[f64],
    references: &[f64],
    mut timings: StudyTimings,
    start: Instant,
) -> Study {
    let t = Instant::now();
    let rows = reduce(&req.ns, errors, errors.len() / req.ns.len().max(1));
    let (slope, slope_stderr) = log_log_fit(&rows);
    let reference = if req.randomize {
        references.iter().sum::<f64>() / references.len() as f64
    } else {
        references.first().copied().unwrap_or(f64::NAN)
    };
    timings.statistics = t.elapsed();
    timings.total = start.elapsed();
    Study {
        rows,
        slope,
        slope_stderr,
        reference,
        realizations: req.realizations,
        timings,
    }
}

/// The study, in parallel (module docs). `progress` ([`crate::core::progress`]) gets, on the
/// calling thread after each chunk of tasks, the points evaluated of all to evaluate; whenever
/// the realizations done reach 1, 2, 4, 8, … (checked after each chunk of tasks, so some powers
/// may be passed over) the report carries the study of the first r < R realizations
/// (`so_far`, its [`Study::realizations`] = r): exactly [`run_study`] with R = r, so the curve
/// sharpens as realizations come in. The result is the same bits whatever `progress` does.
pub fn run_study(
    req: &StudyRequest,
    cancel: &Cancel,
    progress: &mut OnProgress<'_, Study>,
) -> Result<Study, StudyError> {
    check_request(req)?;
    let start = Instant::now();
    let mut timings = StudyTimings::default();
    let plan = Plan::new(req);
    let t = Instant::now();
    let cache = plan.cache(cancel)?;
    timings.points += t.elapsed();

    // One task per realization (progressive: every N from one prefix) or per (realization, N).
    let distinct = if plan.identical { 1 } else { req.realizations };
    let tasks: Vec<Task> = if plan.progressive {
        (0..distinct).map(|r| Task { r, k: None }).collect()
    } else {
        (0..distinct)
            .flat_map(|r| (0..req.ns.len()).map(move |k| Task { r, k: Some(k) }))
            .collect()
    };
    let weight = |t: &Task| t.k.map_or(plan.nmax, |k| req.ns[k]);
    let total = tasks.iter().map(weight).fold(0usize, usize::saturating_add);
    let threads = rayon::current_num_threads().max(1);
    let target = (total / 64).max(1 << 16);

    let k_len = req.ns.len();
    let mut errors = vec![0.0; distinct * k_len];
    let mut references = vec![0.0; distinct];
    let mut done = 0usize;
    let mut next_partial = 1usize;
    let mut i = 0;
    // The first batch is one realization's work and each next one as much as is done, up to
    // `target`: the partial studies of 1, 2, 4, … realizations come as early as they can (a
    // scene's first picture waits for every column's first one), and the batches stay few.
    let per_realization = (total / distinct.max(1)).max(1);
    while i < tasks.len() {
        cancel.check()?;
        let mut j = i;
        let mut w = 0usize;
        let batch = done.max(per_realization).min(target);
        while j < tasks.len() && (j - i < 2 * threads || w < batch) && j - i < 4096 {
            w = w.saturating_add(weight(&tasks[j]));
            j += 1;
        }
        let outs: Vec<Result<TaskOut, StudyError>> = tasks[i..j]
            .par_iter()
            .map(|t| plan.run(t, &cache, cancel))
            .collect();
        for (task, out) in tasks[i..j].iter().zip(outs) {
            let out = out?;
            for (k, e) in out.estimates {
                errors[task.r * k_len + k] = e - out.reference;
            }
            references[task.r] = out.reference;
            timings.points += out.points;
            timings.evaluation += out.evaluation;
        }
        done = done.saturating_add(w);
        i = j;
        // Tasks run in realization order: every realization before task j's is complete.
        let complete = tasks.get(j).map_or(distinct, |t| t.r);
        let mut partial = None;
        if !plan.identical && complete >= next_partial && complete < req.realizations {
            let mut t = timings;
            t.total = start.elapsed();
            let sub = StudyRequest {
                realizations: complete,
                ..req.clone()
            };
            let study = finish(
                &sub,
                &errors[..complete * k_len],
                &references[..complete],
                t,
                start,
            );
            partial = Some(study);
            next_partial = complete * 2;
        }
        progress(Progress {
            done,
            total,
            so_far: partial.as_ref(),
        });
    }
    if plan.identical {
        errors = errors.repeat(req.realizations);
        references = references.repeat(req.realizations);
    }
    Ok(finish(req, &errors, &references, timings, start))
}

/// The same study as [`run_study`], as the plain serial loop: for each realization, for each
/// N, generate the points, sum f over them through [`Integrand::eval`], divide by N. The same
/// bits as [`run_study`]; `progress` counts realizations (no partial studies).
pub fn run_study_naive(
    req: &StudyRequest,
    cancel: &Cancel,
    progress: &mut OnProgress<'_, Study>,
) -> Result<Study, StudyError> {
    check_request(req)?;
    let start = Instant::now();
    let mut timings = StudyTimings::default();
    let mut errors = Vec::with_capacity(req.realizations * req.ns.len());
    let mut references = Vec::with_capacity(req.realizations);
    for r in 0..req.realizations {
        cancel.check()?;
        let (integrand, shift, stream) = instance(req, r);
        // A Genz integrand made ready once per realization; a 2D one evaluated by
        // `Integrand::eval` point by point.
        let genz = integrand.in_dims(req.dims).transpose()?;
        let reference = genz
            .as_ref()
            .map_or_else(|| integrand.integral(), Genz::integral);
        references.push(reference);
        let mut x = vec![0.0; req.dims];
        for &n in &req.ns {
            let t = Instant::now();
            let points = points(&req.pattern, n, req.dims, stream, cancel)?;
            timings.points += t.elapsed();
            let t = Instant::now();
            let mut sum = 0.0;
            for (i, p) in points.rows().enumerate() {
                if i % CHECK_EVERY == 0 {
                    cancel.check()?;
                }
                for (j, xj) in x.iter_mut().enumerate() {
                    *xj = match &shift {
                        Some(u) => wrap(p[j] + u[j]),
                        None => p[j],
                    };
                }
                sum += match &genz {
                    Some(g) => g.eval(&x),
                    None => integrand.eval(DVec2::new(x[0], x[1])),
                };
            }
            errors.push(sum / n as f64 - reference);
            timings.evaluation += t.elapsed();
        }
        progress(Progress::at(r + 1, req.realizations));
    }
    Ok(finish(req, &errors, &references, timings, start))
}

/// One unit of parallel work: realization r, at N = ns[k] or (progressive) at every N.
struct Task {
    r: usize,
    k: Option<usize>,
}

struct TaskOut {
    /// (k, estimate) pairs.
    estimates: Vec<(usize, f64)>,
    reference: f64,
    points: Duration,
    evaluation: Duration,
}

/// Points of a deterministic pattern shared by every realization.
enum Cache {
    None,
    /// The largest N of a progressive pattern.
    Prefix(CubePoints),
    /// One set per N (index k).
    PerN(Vec<CubePoints>),
}

struct Plan<'a> {
    req: &'a StudyRequest,
    progressive: bool,
    identical: bool,
    nmax: usize,
    /// Indices k in increasing order of ns[k] (stable).
    order: Vec<usize>,
}

impl<'a> Plan<'a> {
    fn new(req: &'a StudyRequest) -> Self {
        let mut order: Vec<usize> = (0..req.ns.len()).collect();
        order.sort_by_key(|&k| req.ns[k]);
        Plan {
            req,
            progressive: req.pattern.is_progressive(),
            identical: req.identical_realizations(),
            nmax: req.ns.iter().copied().max().unwrap_or(1),
            order,
        }
    }

    /// Whether a deterministic pattern's points are kept for every realization.
    fn caches(&self) -> bool {
        let points = if self.progressive {
            self.nmax
        } else {
            self.req.ns.iter().sum()
        };
        !self.req.pattern.is_random() && points.saturating_mul(8 * self.req.dims) <= CACHE_BYTES
    }

    fn cache(&self, cancel: &Cancel) -> Result<Cache, StudyError> {
        if !self.caches() {
            return Ok(Cache::None);
        }
        let req = self.req;
        let seed = derive_seed(req.seed, 0);
        if self.progressive {
            match points(&req.pattern, self.nmax, req.dims, seed, cancel) {
                Ok(points) => return Ok(Cache::Prefix(points)),
                Err(StudyError::Cancelled) => return Err(StudyError::Cancelled),
                // The largest N failed: find the first N that fails, in request order.
                Err(_) => {}
            }
        }
        let sets: Vec<Result<CubePoints, StudyError>> = req
            .ns
            .par_iter()
            .map(|&n| points(&req.pattern, n, req.dims, seed, cancel))
            .collect();
        Ok(Cache::PerN(sets.into_iter().collect::<Result<_, _>>()?))
    }

    fn run(&self, task: &Task, cache: &Cache, cancel: &Cancel) -> Result<TaskOut, StudyError> {
        let req = self.req;
        let (integrand, shift, stream) = instance(req, task.r);
        let f = Evaluator::new(&integrand, req.dims)?;
        let shift = shift.as_deref();
        let mut out = TaskOut {
            estimates: Vec::new(),
            reference: f.integral(&integrand),
            points: Duration::ZERO,
            evaluation: Duration::ZERO,
        };
        let t = Instant::now();
        match (task.k, cache) {
            (Some(k), Cache::PerN(sets)) => {
                let m = prefix_means(&f, &sets[k], shift, &[req.ns[k]], cancel)?;
                out.estimates.push((k, m[0]));
            }
            (Some(k), _) => {
                let points = points(&req.pattern, req.ns[k], req.dims, stream, cancel)?;
                out.points = t.elapsed();
                let t = Instant::now();
                let m = prefix_means(&f, &points, shift, &[req.ns[k]], cancel)?;
                out.estimates.push((k, m[0]));
                out.evaluation = t.elapsed();
                return Ok(out);
            }
            (None, Cache::Prefix(points)) => self.all_n(&f, points, shift, cancel, &mut out)?,
            (None, Cache::PerN(sets)) => {
                for (k, set) in sets.iter().enumerate() {
                    let m = prefix_means(&f, set, shift, &[req.ns[k]], cancel)?;
                    out.estimates.push((k, m[0]));
                }
            }
            (None, Cache::None) => {
                match points(&req.pattern, self.nmax, req.dims, stream, cancel) {
                    Ok(points) => {
                        out.points = t.elapsed();
                        let t = Instant::now();
                        self.all_n(&f, &points, shift, cancel, &mut out)?;
                        out.evaluation = t.elapsed();
                        return Ok(out);
                    }
                    Err(StudyError::Cancelled) => return Err(StudyError::Cancelled),
                    Err(_) => {
                        // The largest N failed: one set per N, so the error names the first
                        // N that fails (in request order).
                        for (k, &n) in req.ns.iter().enumerate() {
                            let points = points(&req.pattern, n, req.dims, stream, cancel)?;
                            let m = prefix_means(&f, &points, shift, &[n], cancel)?;
                            out.estimates.push((k, m[0]));
                        }
                    }
                }
            }
        }
        out.evaluation = t.elapsed();
        Ok(out)
    }

    /// Every N read off the prefix sums of one progressive set.
    fn all_n(
        &self,
        f: &Evaluator,
        points: &CubePoints,
        shift: Option<&[f64]>,
        cancel: &Cancel,
        out: &mut TaskOut,
    ) -> Result<(), StudyError> {
        let marks: Vec<usize> = self.order.iter().map(|&k| self.req.ns[k]).collect();
        let means = prefix_means(f, points, shift, &marks, cancel)?;
        out.estimates.extend(self.order.iter().copied().zip(means));
        Ok(())
    }
}

/// The means (1/m)·Σ_{i<m} f(xᵢ) at every mark m (marks increasing, each ≤ points.len()), the
/// sum accumulated in point order from 0 — the same additions as the plain loop to m.
fn prefix_means(
    f: &Evaluator,
    points: &CubePoints,
    shift: Option<&[f64]>,
    marks: &[usize],
    cancel: &Cancel,
) -> Result<Vec<f64>, StudyError> {
    match f {
        Evaluator::Plane(g) => match shift.map(|u| DVec2::new(u[0], u[1])) {
            Some(u) => means(points, marks, cancel, |p| {
                g.eval(DVec2::new(wrap(p[0] + u.x), wrap(p[1] + u.y)))
            }),
            None => means(points, marks, cancel, |p| g.eval(DVec2::new(p[0], p[1]))),
        },
        Evaluator::Cube(g) => means(points, marks, cancel, |p| g.eval_shifted(p, shift)),
    }
}

/// [`prefix_means`] of `f` over the points' rows.
#[inline]
fn means(
    points: &CubePoints,
    marks: &[usize],
    cancel: &Cancel,
    f: impl Fn(&[f64]) -> f64,
) -> Result<Vec<f64>, StudyError> {
    let mut out = Vec::with_capacity(marks.len());
    let mut sum = 0.0;
    let mut next = 0;
    let dims = points.dims();
    for (start, block) in (0..)
        .step_by(CHECK_EVERY)
        .zip(points.coords().chunks(CHECK_EVERY * dims))
    {
        cancel.check()?;
        for (i, p) in (start..).zip(block.chunks_exact(dims)) {
            sum += f(p);
            while next < marks.len() && marks[next] == i + 1 {
                out.push(sum / (i + 1) as f64);
                next += 1;
            }
        }
    }
    Ok(out)
}

/// CPU nanoseconds of one integrand evaluation with its share of the loop (point load,
/// rotation, sum) on the reference machine, release build, as `benches/converge.rs` measures
/// them (`eval_*` rows, points in cache): 2.1 (disk), 2.2 (heaviside), 2.3 (bilinear), 6.5
/// (gaussian), 22.6 (cosines), rounded up; sets of 2^20 points streamed from memory cost
/// about 4 ns per point for the simple integrands.
///
/// A Genz integrand costs about `GENZ_NS.0 + GENZ_NS.1 · D` (a term per coordinate, with its
/// rotation), its exp/cos/powi once per point.
fn eval_ns(integrand: &Integrand, dims: usize) -> f64 {
    let genz = GENZ_NS.0 + GENZ_NS.1 * dims as f64;
    match integrand {
        Integrand::Disk(_) | Integrand::Heaviside(_) | Integrand::Bilinear(_) => 2.5,
        Integrand::Gaussian(_) => 7.0,
        Integrand::Cosines(_) => 23.0,
        Integrand::GenzOscillatory(_)
        | Integrand::GenzProductPeak(_)
        | Integrand::GenzCornerPeak(_)
        | Integrand::GenzGaussian(_)
        | Integrand::GenzContinuous(_)
        | Integrand::GenzDiscontinuous(_) => genz,
    }
}

/// ns per point of a Genz integrand: (constant, per coordinate).
const GENZ_NS: (f64, f64) = (20.0, 3.0);

/// ns of one closed-form integral: the corner peak's quadrature evaluates its D terms at a few
/// hundred nodes (about 20 ns each, `exp_m1` and `ln`); the other Genz closed forms are a
/// product of D factors; the 2D integrands' are counted in their evaluations.
fn integral_ns(integrand: &Integrand, dims: usize) -> f64 {
    match integrand {
        Integrand::GenzCornerPeak(_) => 600.0 * 20.0 * dims as f64,
        f if f.is_planar() => 0.0,
        _ => 50.0 * dims as f64,
    }
}

/// The cost of a study before it starts: the points it generates and the integrand
/// evaluations, following [`run_study`]'s tasks (a deterministic pattern generated once per N,
/// a progressive one once per realization at the largest N, one realization when all are the
/// same). Parallel work is divided by [`budget::REFERENCE_CORES`]. Call [`check_request`]
/// first: the estimate assumes the limits hold.
pub fn estimate(req: &StudyRequest) -> Vec<Estimate> {
    let plan = Plan::new(req);
    let realizations = req.realizations.clamp(1, MAX_REALIZATIONS) as f64;
    let distinct = if plan.identical { 1.0 } else { realizations };
    let ns: Vec<usize> = req
        .ns
        .iter()
        .map(|&n| n.clamp(1, MAX_STUDY_N))
        .take(MAX_NS)
        .collect();
    let nmax = ns.iter().copied().max().unwrap_or(1);
    let cores = budget::REFERENCE_CORES;
    let dims = req.dims.clamp(1, MAX_DIMS);
    let largest = pattern_cost(&req.pattern, nmax, dims);
    // (N generated, how many times, whether in parallel).
    let generated: Vec<(usize, f64, bool)> = match (plan.caches(), plan.progressive) {
        (true, true) => vec![(nmax, 1.0, false)],
        (true, false) => ns.iter().map(|&n| (n, 1.0, true)).collect(),
        (false, true) => vec![(nmax, distinct, true)],
        (false, false) => ns.iter().map(|&n| (n, distinct, true)).collect(),
    };
    let (mut amount, mut seconds, mut cached_bytes) = (0.0, 0.0, 0.0);
    for &(n, times, parallel) in &generated {
        let e = pattern_cost(&req.pattern, n, dims);
        amount += e.amount * times;
        seconds += e.seconds * times / if parallel { cores } else { 1.0 };
        cached_bytes += e.bytes;
    }
    let bytes = if plan.caches() {
        cached_bytes.max(largest.bytes)
    } else {
        largest.bytes * cores
    };
    let range = if ns.len() > 1 {
        format!(" (largest of {} values of N)", ns.len())
    } else {
        String::new()
    };
    let points = Estimate {
        operation: format!(
            "{}{range}, {} realization{}",
            largest.operation,
            req.realizations,
            if req.realizations == 1 { "" } else { "s" }
        ),
        amount,
        unit: largest.unit,
        seconds,
        bytes,
        concurrent: false,
    };
    let per_realization: f64 = if plan.progressive {
        nmax as f64
    } else {
        ns.iter().map(|&n| n as f64).sum()
    };
    let evaluations = distinct * per_realization;
    let results = 8.0 * realizations * ns.len() as f64;
    // The closed forms: once, or once per realization with randomisation.
    let instances = if req.randomize { distinct } else { 1.0 };
    let eval = Estimate {
        operation: format!(
            "{} integrand at {} points per realization{}",
            req.integrand.name(),
            per_realization,
            if dims == 2 {
                String::new()
            } else {
                format!(" in {dims} dimensions")
            }
        ),
        amount: evaluations,
        unit: Unit::Evaluations,
        seconds: evaluations * eval_ns(&req.integrand, dims) * 1e-9 / cores
            + instances * integral_ns(&req.integrand, dims) * 1e-9 / cores
            + results * budget::BYTE_NS * 1e-9,
        bytes: results,
        concurrent: false,
    };
    vec![points, eval]
}

/// Generating `n` points of the pattern in `dims` dimensions ([`budget::pattern_cube`]; D = 2
/// is [`budget::pattern`]).
fn pattern_cost(pattern: &Pattern, n: usize, dims: usize) -> Estimate {
    budget::pattern_cube(pattern, n, dims)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::integration::integrands::{Disk, Gaussian, Heaviside};
    use crate::core::pattern::{Grid, Jitter, Random, Scramble, Sobol};
    use crate::core::progress::no_progress;

    fn study(req: &StudyRequest) -> Study {
        run_study(req, &Cancel::never(), &mut no_progress).expect("study")
    }

    fn disk() -> Integrand {
        Integrand::Disk(Disk {
            cx: 0.43,
            cy: 0.52,
            r: 0.31,
        })
    }

    #[test]
    fn grid_without_shift_is_the_count_of_grid_points_in_the_disk() {
        // One realization, no shift: mse = (count/N − I)² exactly, the count made here from
        // the cell centres ((i+½)/c, (j+½)/c), with the same f64 expressions as the pattern.
        let ns = vec![16, 64, 100, 256, 1024];
        let req = StudyRequest {
            pattern: Pattern::Grid(Grid::default()),
            integrand: disk(),
            ns: ns.clone(),
            realizations: 1,
            shift: false,
            ..StudyRequest::default()
        };
        let s = study(&req);
        let exact = disk().integral();
        for (row, &n) in s.rows.iter().zip(&ns) {
            let c = (n as f64).sqrt() as usize;
            assert_eq!(c * c, n);
            let mut count = 0usize;
            for j in 0..c {
                for i in 0..c {
                    let x = (i as f64 + 0.5) / c as f64;
                    let y = (j as f64 + 0.5) / c as f64;
                    if (x - 0.43) * (x - 0.43) + (y - 0.52) * (y - 0.52) <= 0.31 * 0.31 {
                        count += 1;
                    }
                }
            }
            let e = count as f64 / n as f64 - exact;
            assert_eq!(row.mse, e * e, "N = {n}");
            assert_eq!(row.bias2, e * e);
            assert_eq!(row.variance, 0.0);
            assert_eq!(row.mse_stderr, None);
        }
        assert_eq!(s.reference, exact);
        // With 2 realizations and no shift both are the same (means of two equal values are
        // exact).
        let s8 = study(&StudyRequest {
            realizations: 2,
            ..req.clone()
        });
        for (a, b) in s8.rows.iter().zip(&s.rows) {
            assert_eq!((a.mse, a.variance), (b.mse, 0.0));
            assert_eq!(a.mse_stderr, Some(0.0));
        }
    }

    #[test]
    fn random_sampling_of_an_indicator_has_mse_i_one_minus_i_over_n() {
        // E[MSE] = I(1−I)/N for white noise. With R = 4096 realizations the relative standard
        // error of the measured MSE is √(2/R)·(1 + O(1/N)) ≈ 2.2 %; tolerance 5 standard
        // errors as reported by the study itself, and the reported one within 20 % of
        // √((E[e⁴] − E[e²]²)/R) ≈ √(2/R)·I(1−I)/N.
        let f = Integrand::Heaviside(Heaviside {
            px: 0.37,
            py: 0.61,
            theta: 200.0,
        });
        let i = f.integral();
        let req = StudyRequest {
            pattern: Pattern::Random(Random {}),
            integrand: f,
            ns: vec![64, 256],
            realizations: 4096,
            seed: 11,
            ..StudyRequest::default()
        };
        let s = study(&req);
        for row in &s.rows {
            let expect = i * (1.0 - i) / row.n as f64;
            let se = row.mse_stderr.unwrap();
            assert!(
                (row.mse - expect).abs() < 5.0 * se,
                "N = {}: mse {} vs {expect} (stderr {se})",
                row.n,
                row.mse
            );
            let se_model = (2.0 / 4096.0f64).sqrt() * expect;
            assert!((se / se_model - 1.0).abs() < 0.2, "{se} vs {se_model}");
            assert!((row.mse - (row.variance + row.bias2)).abs() <= 1e-12 * row.mse);
        }
        let slope = s.slope.unwrap();
        assert!((slope + 1.0).abs() < 0.1, "slope {slope}");
    }

    #[test]
    fn jittered_sampling_of_the_disk_has_slope_near_minus_one_and_a_half() {
        // Jitter on an edge: MSE ∝ N^(−3/2). Accepted window [−1.65, −1.35] over
        // N = 16 … 16384 (powers of 4), 512 realizations.
        let req = StudyRequest {
            pattern: Pattern::Jitter(Jitter::default()),
            integrand: disk(),
            ns: vec![16, 64, 256, 1024, 4096, 16384],
            realizations: 512,
            seed: 3,
            ..StudyRequest::default()
        };
        let s = study(&req);
        let slope = s.slope.unwrap();
        assert!((-1.65..=-1.35).contains(&slope), "slope {slope}");
        assert!(s.slope_stderr.unwrap() < 0.1);
    }

    #[test]
    fn owen_scrambled_sobol_on_the_gaussian_is_steeper_than_minus_two_and_a_half() {
        // Smooth integrand: Owen scrambling gives MSE ~ N^(−3) (log factors): slope < −2.5
        // over N = 16 … 4096 (powers of 2), 256 realizations.
        let req = StudyRequest {
            pattern: Pattern::Sobol(Sobol {
                scramble: Scramble::Owen,
                skip: 0,
            }),
            integrand: Integrand::Gaussian(Gaussian::default()),
            ns: (4..=12).map(|m| 1usize << m).collect(),
            realizations: 256,
            seed: 5,
            ..StudyRequest::default()
        };
        let s = study(&req);
        let slope = s.slope.unwrap();
        assert!(slope < -2.5, "slope {slope}");
    }

    #[test]
    fn unscrambled_sobol_without_shift_reproduces_a_direct_evaluation() {
        let f = Integrand::Gaussian(Gaussian {
            cx: 0.3,
            cy: 0.7,
            sigma: 0.2,
        });
        let pattern = Pattern::Sobol(Sobol::default());
        let ns = vec![1, 7, 64, 1000];
        let req = StudyRequest {
            pattern,
            integrand: f,
            ns: ns.clone(),
            realizations: 3,
            shift: false,
            ..StudyRequest::default()
        };
        let s = study(&req);
        for (row, &n) in s.rows.iter().zip(&ns) {
            let pts = pattern.generate(n, 0).unwrap();
            let mut sum = 0.0;
            for p in &pts {
                let (dx, dy) = (p.x - 0.3, p.y - 0.7);
                sum += (-(dx * dx + dy * dy) / (2.0 * 0.2 * 0.2)).exp();
            }
            let e = sum / n as f64 - f.integral();
            // The study's f multiplies by 1/(2σ²): a few ulps of each term.
            assert!((row.mse.sqrt() - e.abs()).abs() <= 1e-15, "N = {n}");
            assert_eq!(row.variance, 0.0);
        }
    }

    /// A mix of patterns: random/deterministic × progressive/not, with shift, randomisation
    /// and a pattern-set cache, and unordered N with a repeat.
    fn mixed_requests() -> Vec<StudyRequest> {
        let names = [
            "random",
            "jitter",
            "halton",
            "kronecker",
            "rank1",
            "best-candidate",
            "pmj02",
            "hammersley",
            "grid",
            "van-der-corput",
            "halton-zaremba",
            "pmj02bn",
        ];
        let mut reqs = Vec::new();
        for (i, name) in names.iter().enumerate() {
            let pattern = Pattern::from_name(name).unwrap();
            let integrand = Integrand::all()[i % 5];
            reqs.push(StudyRequest {
                pattern,
                integrand,
                ns: vec![64, 16, 100, 64, 256],
                realizations: 6,
                seed: 17 + i as u64,
                shift: i % 3 != 2,
                randomize: i % 2 == 1,
                dims: 2,
            });
        }
        reqs.push(StudyRequest {
            pattern: Pattern::Sobol(Sobol {
                scramble: Scramble::Owen,
                skip: 0,
            }),
            integrand: Integrand::Gaussian(Gaussian::default()),
            ns: vec![32, 8, 512],
            realizations: 9,
            seed: 2,
            shift: true,
            randomize: true,
            dims: 2,
        });
        // Genz integrands: in D = 2 (the 2D path), 1, 3 and 8 dimensions, randomized or not.
        for (i, (name, dims)) in [
            ("genz-gaussian", 2),
            ("genz-corner-peak", 8),
            ("genz-discontinuous", 1),
            ("genz-oscillatory", 3),
            ("genz-product-peak", 8),
            ("genz-continuous", 3),
        ]
        .into_iter()
        .enumerate()
        {
            reqs.push(StudyRequest {
                pattern: Pattern::from_name(if dims == 2 { "jitter" } else { "random" }).unwrap(),
                integrand: Integrand::from_name(name).unwrap(),
                ns: vec![64, 16, 100],
                realizations: 5,
                seed: 40 + i as u64,
                shift: true,
                randomize: i % 2 == 0,
                dims,
            });
        }
        // d-dimensional patterns: deterministic (shifted, or all realizations the same),
        // progressive or not, randomised Owen scrambling.
        for (i, (name, set, dims, shift)) in [
            ("halton", None, 8, true),
            ("sobol", Some(("scramble", "owen")), 3, true),
            ("hammersley", None, 3, false),
            ("lhs", None, 8, true),
            ("sobol", None, 32, true),
        ]
        .into_iter()
        .enumerate()
        {
            let mut pattern = Pattern::from_name(name).unwrap();
            if let Some((k, v)) = set {
                pattern.set(k, v).unwrap();
            }
            reqs.push(StudyRequest {
                pattern,
                integrand: Integrand::all()[5 + i % 6],
                ns: vec![64, 16, 100],
                realizations: 5,
                seed: 60 + i as u64,
                shift,
                randomize: i % 2 == 1,
                dims,
            });
        }
        reqs
    }

    fn same_bits(a: &Study, b: &Study) {
        assert_eq!(a.realizations, b.realizations);
        assert_eq!(a.rows.len(), b.rows.len());
        for (x, y) in a.rows.iter().zip(&b.rows) {
            assert_eq!(x.n, y.n);
            assert_eq!(x.mse.to_bits(), y.mse.to_bits());
            assert_eq!(x.variance.to_bits(), y.variance.to_bits());
            assert_eq!(x.bias2.to_bits(), y.bias2.to_bits());
            assert_eq!(
                x.mse_stderr.map(f64::to_bits),
                y.mse_stderr.map(f64::to_bits)
            );
        }
        assert_eq!(a.slope.map(f64::to_bits), b.slope.map(f64::to_bits));
        assert_eq!(
            a.slope_stderr.map(f64::to_bits),
            b.slope_stderr.map(f64::to_bits)
        );
        assert_eq!(a.reference.to_bits(), b.reference.to_bits());
    }

    #[test]
    fn naive_and_fast_give_the_same_bits() {
        for req in mixed_requests() {
            let fast = study(&req);
            let naive = run_study_naive(&req, &Cancel::never(), &mut no_progress).unwrap();
            same_bits(&fast, &naive);
        }
    }

    #[test]
    fn partial_studies_are_the_studies_of_their_first_realizations() {
        // Enough points per realization that chunks end between realizations.
        let req = StudyRequest {
            pattern: Pattern::from_name("jitter").unwrap(),
            ns: vec![64, 1024, 16384],
            realizations: 40,
            seed: 5,
            ..StudyRequest::default()
        };
        let mut partials = Vec::new();
        let last = run_study(&req, &Cancel::never(), &mut |p| {
            if let Some(s) = p.so_far {
                partials.push((s.realizations, s.clone()))
            }
        })
        .unwrap();
        assert!(partials.len() >= 2, "{} partials", partials.len());
        let mut prev = 0;
        for (r, s) in &partials {
            assert!(*r > prev && *r < 40, "{prev} then {r}");
            assert!(*r >= 2 * prev, "powers of two or later: {prev} then {r}");
            prev = *r;
            let sub = StudyRequest {
                realizations: *r,
                ..req.clone()
            };
            same_bits(
                s,
                &run_study_naive(&sub, &Cancel::never(), &mut no_progress).unwrap(),
            );
        }
        same_bits(&last, &study(&req));
        // The first partial comes after 2 × threads realizations at most (a scene's first
        // picture waits for it), also where the whole study is less than one batch's `target`
        // of work (it came only after half of it), with a pattern that makes a task per
        // (realization, N) and one that makes a task per realization.
        let threads = rayon::current_num_threads().max(1);
        for name in ["jitter", "sobol"] {
            let small = StudyRequest {
                pattern: Pattern::from_name(name).unwrap(),
                ns: vec![16, 64, 256, 1024, 4096],
                realizations: 32,
                seed: 1,
                ..StudyRequest::default()
            };
            let mut first = None;
            run_study(&small, &Cancel::never(), &mut |p| {
                if let (None, Some(s)) = (first, p.so_far) {
                    first = Some(s.realizations);
                }
            })
            .unwrap();
            let first = first.unwrap_or_else(|| panic!("{name}: no partial study"));
            assert!(
                first <= 2 * threads,
                "{name}: first partial after {first} realizations"
            );
        }
        // Identical realizations publish nothing part way.
        let mut none = 0;
        let fixed = StudyRequest {
            pattern: Pattern::from_name("hammersley").unwrap(),
            shift: false,
            ..req.clone()
        };
        run_study(&fixed, &Cancel::never(), &mut |p| {
            none += usize::from(p.so_far.is_some())
        })
        .unwrap();
        assert_eq!(none, 0);
    }

    #[test]
    fn results_do_not_depend_on_the_thread_count() {
        let pool = |n| {
            rayon::ThreadPoolBuilder::new()
                .num_threads(n)
                .build()
                .unwrap()
        };
        let (one, four) = (pool(1), pool(4));
        for req in mixed_requests().into_iter().step_by(3) {
            let a = one.install(|| study(&req));
            let b = four.install(|| study(&req));
            same_bits(&a, &b);
        }
    }

    #[test]
    fn progressive_patterns_are_prefixes_of_their_larger_sets_in_every_dimension() {
        // The study reads every N off the largest set of a progressive pattern in D dims too.
        for p in Pattern::all()
            .into_iter()
            .filter(|p| p.is_progressive() && p.max_dims() > 2)
        {
            for dims in [1, 3, 8, 32] {
                let never = Cancel::never();
                let big = p.generate_cube(300, dims, 9, &never).unwrap();
                for n in [1, 17, 64, 299] {
                    let small = p.generate_cube(n, dims, 9, &never).unwrap();
                    assert_eq!(
                        small.coords(),
                        &big.coords()[..n * dims],
                        "{} D = {dims}",
                        p.name()
                    );
                }
            }
        }
    }

    #[test]
    fn progressive_patterns_are_prefixes_of_their_larger_sets() {
        // The prefix reuse of `run_study` relies on it; checked for every progressive pattern.
        for p in Pattern::all().into_iter().filter(|p| p.is_progressive()) {
            let big = p.generate(300, 9).unwrap();
            for n in [1, 17, 64, 299] {
                assert_eq!(p.generate(n, 9).unwrap()[..], big[..n], "{}", p.name());
            }
        }
    }

    #[test]
    fn bad_requests_name_the_flag_and_the_value() {
        let ok = StudyRequest::default();
        let err = |req: StudyRequest| {
            run_study(&req, &Cancel::never(), &mut no_progress)
                .unwrap_err()
                .to_string()
        };
        assert_eq!(
            err(StudyRequest {
                ns: vec![16, 0],
                ..ok.clone()
            }),
            "--n 0: each sample count must be an integer in 1..=1048576"
        );
        assert_eq!(
            err(StudyRequest {
                ns: vec![1 << 21],
                ..ok.clone()
            }),
            "--n 2097152: each sample count must be an integer in 1..=1048576"
        );
        assert!(err(StudyRequest {
            ns: vec![],
            ..ok.clone()
        })
        .starts_with("--n: no value"));
        assert_eq!(
            err(StudyRequest {
                ns: vec![4; 65],
                ..ok.clone()
            }),
            "--n: 65 values given; at most 64 are allowed"
        );
        assert_eq!(
            err(StudyRequest {
                realizations: 0,
                ..ok.clone()
            }),
            "--realizations 0: must be an integer in 1..=4096"
        );
        assert_eq!(
            err(StudyRequest {
                realizations: 4097,
                ..ok.clone()
            }),
            "--realizations 4097: must be an integer in 1..=4096"
        );
        // A pattern that cannot make a given N names it, for deterministic and random ones.
        let fib = Pattern::from_name("fibonacci").unwrap();
        let e = err(StudyRequest {
            pattern: fib,
            ns: vec![89, 100, 144],
            ..ok.clone()
        });
        assert!(e.starts_with("--n 100: fibonacci: n = 100"), "{e}");
        let mut hex = Pattern::from_name("hex").unwrap();
        hex.set("amount", "0.5").unwrap();
        let e = err(StudyRequest {
            pattern: hex,
            ns: vec![16, 33],
            ..ok.clone()
        });
        assert!(e.starts_with("--n 33: hex"), "{e}");
        // The same error from the naive loop.
        let naive = run_study_naive(
            &StudyRequest {
                pattern: hex,
                ns: vec![16, 33],
                ..ok.clone()
            },
            &Cancel::never(),
            &mut no_progress,
        )
        .unwrap_err();
        assert_eq!(naive.to_string(), e);
        // A parameter written directly out of range.
        let bad = Integrand::Disk(Disk {
            r: -1.0,
            ..Disk::default()
        });
        assert!(err(StudyRequest {
            integrand: bad,
            ..ok.clone()
        })
        .starts_with("disk.r = -1"));
    }

    #[test]
    fn cancellation_stops_the_study() {
        let cancel = Cancel::new();
        cancel.cancel();
        let e = run_study(&StudyRequest::default(), &cancel, &mut no_progress).unwrap_err();
        assert_eq!(e, StudyError::Cancelled);
        // Cancelled from the progress callback after the first chunk.
        let cancel = Cancel::new();
        let req = StudyRequest {
            realizations: 4096,
            ..StudyRequest::default()
        };
        let mut calls = 0;
        let c = cancel.clone();
        let e = run_study(&req, &cancel, &mut |p| {
            calls += 1;
            assert!(p.done < p.total);
            c.cancel();
        })
        .unwrap_err();
        assert_eq!((e, calls), (StudyError::Cancelled, 1));
    }

    #[test]
    fn progress_reaches_the_total_and_the_fit_follows_its_formula() {
        let mut last = (0, 0);
        study(&StudyRequest::default());
        run_study(&StudyRequest::default(), &Cancel::never(), &mut |p| {
            assert!(p.done >= last.0);
            last = (p.done, p.total);
        })
        .unwrap();
        assert_eq!(last.0, last.1);
        assert_eq!(last.1, 64 * (16 + 64 + 256 + 1024 + 4096));
        // An exact power law: slope −1.5, zero residuals; rows with mse = 0 are left out.
        let row = |n: usize, mse: f64| StudyRow {
            n,
            mse,
            mse_stderr: None,
            variance: mse,
            bias2: 0.0,
        };
        let rows: Vec<StudyRow> = [16usize, 64, 256, 1024]
            .iter()
            .map(|&n| row(n, 3.0 * (n as f64).powf(-1.5)))
            .chain([row(4096, 0.0)])
            .collect();
        let (b, se) = log_log_fit(&rows);
        assert!((b.unwrap() + 1.5).abs() < 1e-12);
        assert!(se.unwrap() < 1e-7);
        // Three points off a line: the textbook formula computed by hand.
        let rows = [row(1, 1.0), row(2, 0.25), row(4, 0.125)];
        let (b, se) = log_log_fit(&rows);
        // With l = ln 2: x = 0, l, 2l; y = 0, −2l, −3l: slope −1.5, residuals (1/6, −1/3, 1/6)·l, Sxx = 2l²,
        // so stderr = √((l²/6)/(3 − 2)/(2l²)) = √(1/12).
        assert!((b.unwrap() + 1.5).abs() < 1e-14);
        let want = (1.0f64 / 12.0).sqrt();
        assert!((se.unwrap() - want).abs() < 1e-14);
        assert_eq!(log_log_fit(&rows[..1]), (None, None));
        assert_eq!(log_log_fit(&[row(8, 1.0), row(8, 2.0)]), (None, None));
    }

    #[test]
    fn estimate_follows_the_tasks() {
        // Random non-progressive: R generations per N, R·ΣN evaluations.
        let req = StudyRequest::default();
        let plan = estimate(&req);
        assert_eq!(plan.len(), 2);
        let sum: usize = req.ns.iter().sum();
        assert_eq!(plan[1].amount, (64 * sum) as f64);
        assert_eq!(plan[0].amount, (64 * sum) as f64);
        assert_eq!(plan[1].unit, Unit::Evaluations);
        // Progressive: R generations of the largest N, R·N_max evaluations.
        let req = StudyRequest {
            pattern: Pattern::Random(Random {}),
            ..StudyRequest::default()
        };
        let plan = estimate(&req);
        assert_eq!(plan[0].amount, (64 * 4096) as f64);
        assert_eq!(plan[1].amount, (64 * 4096) as f64);
        // Deterministic without shift: one realization computed.
        let req = StudyRequest {
            pattern: Pattern::Grid(Grid::default()),
            shift: false,
            ..StudyRequest::default()
        };
        assert_eq!(estimate(&req)[1].amount, sum as f64);
        // The largest study estimates without allocating and is refused by the default budget.
        let req = StudyRequest {
            ns: vec![MAX_STUDY_N; MAX_NS],
            realizations: MAX_REALIZATIONS,
            ..StudyRequest::default()
        };
        let plan = estimate(&req);
        assert!(budget::Budget::default().check(&plan).is_err());
    }

    fn genz(name: &str, settings: &[(&str, &str)]) -> Integrand {
        let mut f = Integrand::from_name(name).unwrap();
        for (k, v) in settings {
            f.set(k, v).unwrap();
        }
        f
    }

    #[test]
    fn random_points_on_a_genz_integrand_in_8_dimensions_have_mse_var_over_n() {
        // Uniform random points: MSE = Var(f)/N. Var(f) of the Gaussian family with a, u per
        // axis: the product of its 1D second moments (a√2 for f²) minus I². Each N within 5
        // standard errors; slope −1 ± 0.1.
        let f = genz("genz-gaussian", &[("a", "[1,2,3,1,2,3,1,2]"), ("u", "0.3")]);
        let (a, u) = ([1.0, 2.0, 3.0, 1.0, 2.0, 3.0, 1.0, 2.0], [0.3; 8]);
        let second = crate::core::integration::genz::integral(
            crate::core::integration::GenzKind::Gaussian,
            &a.map(|x: f64| x * std::f64::consts::SQRT_2),
            &u,
        );
        let i = f.in_dims(8).unwrap().unwrap().integral();
        let var = second - i * i;
        let req = StudyRequest {
            pattern: Pattern::Random(Random {}),
            integrand: f,
            ns: vec![16, 64, 256, 1024],
            realizations: 2048,
            seed: 11,
            dims: 8,
            ..StudyRequest::default()
        };
        let s = study(&req);
        assert_eq!(s.reference.to_bits(), i.to_bits());
        for row in &s.rows {
            let expect = var / row.n as f64;
            let se = row.mse_stderr.unwrap();
            assert!(
                (row.mse - expect).abs() < 5.0 * se,
                "N = {}: mse {} vs {expect} (stderr {se})",
                row.n,
                row.mse
            );
        }
        assert!((s.slope.unwrap() + 1.0).abs() < 0.1, "{:?}", s.slope);
    }

    #[test]
    fn a_genz_integrand_in_two_dimensions_is_the_2d_study() {
        // D = 2 goes through the 2D patterns (jitter has no d-dimensional form): the estimate
        // of realization 0 with one point set, by hand.
        let f = genz("genz-continuous", &[("a", "[3,7]"), ("u", "[0.2,0.6]")]);
        let req = StudyRequest {
            pattern: Pattern::Hammersley(Default::default()),
            integrand: f,
            ns: vec![64, 256],
            realizations: 1,
            shift: false,
            ..StudyRequest::default()
        };
        let s = study(&req);
        let g = f.in_dims(2).unwrap().unwrap();
        for (row, &n) in s.rows.iter().zip(&req.ns) {
            let pts = req.pattern.generate(n, 0).unwrap();
            let sum: f64 = pts.iter().map(|p| g.eval(&[p.x, p.y])).sum();
            let e = sum / n as f64 - g.integral();
            assert_eq!(row.mse.to_bits(), (e * e).to_bits(), "N = {n}");
        }
    }

    #[test]
    fn bad_dimensions_name_the_flag_and_the_range() {
        let err = |req: StudyRequest| check_request(&req).unwrap_err().to_string();
        let ok = StudyRequest {
            pattern: Pattern::Random(Random {}),
            integrand: genz("genz-gaussian", &[]),
            dims: 8,
            ..StudyRequest::default()
        };
        check_request(&ok).unwrap();
        assert_eq!(
            err(StudyRequest {
                dims: 0,
                ..ok.clone()
            }),
            "--dims 0: must be an integer in 1..=1024"
        );
        assert_eq!(
            err(StudyRequest {
                dims: 1025,
                ..ok.clone()
            }),
            "--dims 1025: must be an integer in 1..=1024"
        );
        let e = err(StudyRequest {
            integrand: disk(),
            ..ok.clone()
        });
        assert!(
            e.starts_with("--dims 8: disk is defined on [0,1]² only (--dims 2); the integrands defined in any dimension are genz-oscillatory, "),
            "{e}"
        );
        let e = err(StudyRequest {
            pattern: Pattern::Jitter(Jitter::default()),
            ..ok.clone()
        });
        assert!(
            e.starts_with("--dims 8: jitter: dims = 8: must be 2 (jitter is defined in 2 dimensions only; the patterns defined in d dimensions are "),
            "{e}"
        );
        assert!(e.contains("sobol"), "{e}");
        let e = err(StudyRequest {
            integrand: genz("genz-gaussian", &[("a", "[1,2,3]")]),
            ..ok.clone()
        });
        assert_eq!(
            e,
            "genz-gaussian.a = [1,2,3] (3 numbers): must be one number (every dimension) or a \
             list of 8, one per dimension (dims = 8)"
        );
        // With --randomize the lists are drawn in D dimensions: the given ones do not matter.
        check_request(&StudyRequest {
            integrand: genz("genz-gaussian", &[("a", "[1,2,3]")]),
            randomize: true,
            ..ok.clone()
        })
        .unwrap();
        assert_eq!(
            err(StudyRequest {
                ns: vec![16, 1 << 20],
                dims: 64,
                ..ok.clone()
            }),
            "--n 1048576 with --dims 64: N · D must be at most 33554432 (N ≤ 524288 in 64 dimensions)"
        );
        // The same errors from the naive loop.
        let naive = run_study_naive(
            &StudyRequest { dims: 0, ..ok },
            &Cancel::never(),
            &mut no_progress,
        );
        assert_eq!(naive.unwrap_err(), StudyError::Dims { dims: 0 });
    }

    #[test]
    fn the_estimate_grows_with_the_dimension() {
        let req = |dims| StudyRequest {
            pattern: Pattern::Random(Random {}),
            integrand: genz("genz-corner-peak", &[]),
            randomize: true,
            dims,
            ..StudyRequest::default()
        };
        let secs = |d| budget::total_seconds(&estimate(&req(d)));
        assert!(secs(32) > 4.0 * secs(2), "{} vs {}", secs(32), secs(2));
        let plan = estimate(&req(32));
        assert!(
            plan[1].operation.ends_with("in 32 dimensions"),
            "{}",
            plan[1].operation
        );
        assert!(plan[0].bytes >= (4096 * 32 * 8) as f64);
    }
}
