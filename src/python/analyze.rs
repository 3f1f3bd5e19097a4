//! `analyze(points, …)` and `periodogram(…)`: the fronts of `samplescope analyze`. `analyze`
//! runs the command's own path (`cli::analyze::analyze_2d` over the one-column scene, or
//! `cli::analyze_cube::run` for D ≠ 2) and keeps what `--json` prints, with the arrays behind
//! it; `periodogram` evaluates the same scene asking for its spectrum alone.

use super::{input, output, run};
use crate::cli::analyze::{self as cli_analyze, AnalyzeArgs, Input, Kept, Sink};
use crate::cli::CliError;
use crate::model::SpectrumData;
use crate::scene::cost;
use crate::scene::graph::{self, NodeKind, NodeValue};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};
use std::sync::Arc;

/// The arguments of `analyze` for points given as an array (one "file" named `points`).
fn args(size: usize, tolerance: Option<f64>, exact: bool) -> AnalyzeArgs {
    AnalyzeArgs {
        pattern: None,
        n: None,
        seed: None,
        allow_fewer: false,
        set: Vec::new(),
        points: vec!["points".into()],
        normalize: false,
        project: None,
        dims: None,
        size,
        realizations: 1,
        tolerance,
        exact,
        spectrum: None,
        spectrum_data: None,
        raps: None,
        rdf: None,
        json: true,
    }
}

/// Checks `tolerance` and `exact` as the CLI's parser does.
fn check_tolerance(tolerance: Option<f64>, exact: bool) -> PyResult<()> {
    use crate::core::spectrum::{MAX_TOLERANCE, MIN_TOLERANCE};
    if let Some(t) = tolerance {
        if exact {
            return Err(PyValueError::new_err(
                "tolerance: not with exact=True (the exact DFT has no tolerance)",
            ));
        }
        if !(MIN_TOLERANCE..=MAX_TOLERANCE).contains(&t) {
            return Err(PyValueError::new_err(format!(
                "tolerance = {t}: must be a number in [{MIN_TOLERANCE:e}, {MAX_TOLERANCE:e}]"
            )));
        }
    }
    Ok(())
}

/// Statistics, discrepancies and spectrum of a point set: the dict `samplescope analyze
/// --points FILE --json` prints for the same points (the same keys and numbers), plus numpy
/// arrays.
///
/// ``points``: an (N, D) array of points in [0,1)^D. For D = 2 (or with ``project=(i, j)``,
/// the 2D projection onto columns i and j): the statistics (``min_distance``,
/// ``star_discrepancy`` and its box, ``l2_star_discrepancy``, ``t_value``, PSA's
/// ``effective_nyquist``, ``oscillations``, ``bond_orientational_order``), ``net_prefixes``,
/// ``spectrum`` (its size, method, tolerance and measured error) and ``timings_ms``; and the
/// arrays ``periodogram`` (M×M, ``P[ky + M//2, kx + M//2]``, DC with its true value N),
/// ``raps`` (rows ``radius, power``), ``anisotropy`` (rows ``radius, dB``) and ``rdf`` (rows
/// ``r_min, r_max, r_mid_normalized, g``). For D ≠ 2: the d-dimensional measures (the five L2
/// discrepancies, scipy's conventions: L2-star the root, CD, WD, MD and SD squared; the
/// minimum toroidal distance; 1D stratification; the table of 2D projections).
///
/// ``size`` (M), ``tolerance`` (NUFFT, default 1e-6) and ``exact`` (exact DFT) are the CLI's
/// ``--size``, ``--tolerance`` and ``--exact``; ``budget`` and ``budget_memory`` its
/// ``--budget`` (seconds) and ``--budget-memory`` (GiB). Releases the GIL; Ctrl-C raises
/// KeyboardInterrupt.
#[pyfunction]
#[pyo3(signature = (points, *, size = 256, tolerance = None, exact = false, project = None, budget = None, budget_memory = None))]
#[allow(clippy::too_many_arguments)]
fn analyze<'py>(
    py: Python<'py>,
    points: &Bound<'py, PyAny>,
    size: usize,
    tolerance: Option<f64>,
    exact: bool,
    project: Option<(usize, usize)>,
    budget: Option<f64>,
    budget_memory: Option<f64>,
) -> PyResult<Bound<'py, PyDict>> {
    check_tolerance(tolerance, exact)?;
    let cube = input::cube(points, "points")?;
    let mut args = args(size, tolerance, exact);
    args.project = project.map(|(i, j)| format!("{i},{j}"));
    let session = run::session(budget, budget_memory)?;
    let kept = run::run(py, session, move |session| {
        let mut kept = Kept::default();
        if cube.dims() != 2 && args.project.is_none() {
            crate::cli::analyze_cube::run(&args, "points", &cube, session, Sink::Keep(&mut kept))?;
        } else {
            let plane = crate::cli::analyze_cube::plane("points", &cube, args.project.as_deref())?;
            let input = Input::Files {
                files: vec!["points".into()],
                sets: vec![plane],
            };
            cli_analyze::analyze_2d(&args, input, 0.0, session, Sink::Keep(&mut kept))?;
        }
        Ok(kept)
    })?;
    let d = output::dict(py, &kept.json)?;
    if let Some(s) = &kept.spectrum {
        let m = s.power.m;
        d.set_item(
            "periodogram",
            output::matrix(py, s.power.power.clone(), m, m)?,
        )?;
        d.set_item("raps", output::table(py, &s.raps)?)?;
        d.set_item("anisotropy", output::table(py, &s.anisotropy)?)?;
    }
    if let Some(rows) = &kept.rdf {
        d.set_item("rdf", output::table(py, rows)?)?;
    }
    Ok(d)
}

/// The periodogram of points and its radially averaged power spectrum: ``(P, raps)``.
///
/// ``points``: an (N, 2) array of points in [0,1)²; a (K, N, 2) array of K realizations
/// (their periodograms averaged); or a pattern name (see ``samplescope.patterns()``) with
/// ``n`` points, ``realizations`` K averaged (seeds derived from ``seed``) and the pattern's
/// parameters as keyword arguments.
///
/// ``P`` is M×M (``size`` M): ``P[ky + M//2, kx + M//2] = |Σ_j exp(−2πi k·x_j)|² / N``, DC
/// with its true value N; ``raps`` has rows ``radius, power`` (annuli of width 1, DC
/// excluded). The NUFFT meets ``tolerance`` (relative ℓ2 error of P; default 1e-6), or
/// ``exact=True`` uses the exact DFT. The numbers are those of ``samplescope analyze``
/// (``--spectrum-data``, ``--raps``). ``budget``/``budget_memory`` as in ``analyze``.
#[pyfunction]
#[pyo3(signature = (points, size = 256, tolerance = None, exact = false, realizations = None, *, n = None, seed = None, budget = None, budget_memory = None, **params))]
#[allow(clippy::too_many_arguments)]
fn periodogram<'py>(
    py: Python<'py>,
    points: &Bound<'py, PyAny>,
    size: usize,
    tolerance: Option<f64>,
    exact: bool,
    realizations: Option<usize>,
    n: Option<usize>,
    seed: Option<u64>,
    budget: Option<f64>,
    budget_memory: Option<f64>,
    params: Option<&Bound<'py, PyDict>>,
) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyAny>)> {
    check_tolerance(tolerance, exact)?;
    let mut args = args(size, tolerance, exact);
    let input = if points.is_instance_of::<PyString>() {
        let name: String = points.extract()?;
        let n =
            n.ok_or_else(|| PyValueError::new_err(format!("n: required with a pattern ({name})")))?;
        crate::cli::parse_n(&n.to_string()).map_err(PyValueError::new_err)?;
        args.points.clear();
        args.pattern = Some(name);
        args.n = Some(n);
        args.seed = seed;
        args.set = input::settings(params)?;
        args.realizations = realizations.unwrap_or(1);
        None
    } else {
        for (name, given) in [
            ("n", n.is_some()),
            ("seed", seed.is_some()),
            ("realizations", realizations.is_some()),
            ("pattern parameters", params.is_some_and(|p| !p.is_empty())),
        ] {
            if given {
                return Err(PyValueError::new_err(format!(
                    "{name}: only with a pattern name; points given as an array are used as \
                     they are (a (K, N, 2) array gives K realizations)"
                )));
            }
        }
        let sets = input::plane_sets(points, "points")?;
        if sets.iter().any(|s| s.len() != sets[0].len()) {
            return Err(PyValueError::new_err(
                "points: the realizations must hold the same N",
            ));
        }
        Some(sets)
    };
    let session = run::session(budget, budget_memory)?;
    let spectrum = run::run(py, session, move |session| {
        let input = match input {
            Some(sets) => Input::Files {
                files: (0..sets.len()).map(|k| format!("points[{k}]")).collect(),
                sets,
            },
            None => cli_analyze::read_input(&args)?,
        };
        spectrum_of(&args, input, session)
    })?;
    let m = spectrum.power.m;
    Ok((
        output::matrix(py, spectrum.power.power.clone(), m, m)?,
        output::table(py, &spectrum.raps)?,
    ))
}

/// The spectrum of `analyze`'s scene for `input` (the mean over the columns for K files),
/// within the budget: the scene `analyze` evaluates, asked for its spectrum node alone.
fn spectrum_of(
    args: &AnalyzeArgs,
    input: Input,
    session: &crate::cli::session::Session,
) -> Result<Arc<SpectrumData>, CliError> {
    let settings = cli_analyze::spectrum_settings(args, &input)?;
    let scene = cli_analyze::analysis_scene(&input, settings, args.seed.unwrap_or(0), false);
    let plan = graph::plan_asking(&scene, &[NodeKind::Spectrum]);
    let _progress = session.admit(cost::estimate_plan(&scene, &plan))?;
    let results = cli_analyze::evaluate(&scene, plan, &session.cancel)?;
    let spectra = cli_analyze::values(&results, NodeKind::Spectrum, |v| match v {
        NodeValue::Spectrum(s) => Some(s),
        _ => None,
    })?;
    if spectra.len() > 1 {
        Ok(Arc::new(cli_analyze::mean_spectrum(&spectra)?))
    } else {
        Ok(spectra[0].clone())
    }
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(analyze, m)?)?;
    m.add_function(wrap_pyfunction!(periodogram, m)?)
}
