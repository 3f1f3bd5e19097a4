//! `converge(…)`: the integration error of a pattern on an integrand as N grows, as
//! `samplescope converge --json` computes it (`cli::converge::study`), with the rows as arrays.

use super::{input, output, run};
use crate::cli::converge::{study, study_json, ConvergeArgs};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// The convergence study of ``pattern`` on ``integrand``: a dict.
///
/// The study of ``samplescope converge``: for each N of ``n`` (a list of sample counts, each
/// in 1..=1048576, at most 64), ``realizations`` R estimates of the integral over [0,1]^dims
/// (deterministic patterns shifted by a Cranley–Patterson rotation per realization unless
/// ``no_shift``; ``randomize`` draws a new instance of the integrand's family per
/// realization); pattern and integrand parameters in ``pattern_params`` and
/// ``integrand_params``. Arguments are the CLI's ``--pattern``, ``--set``, ``--integrand``,
/// ``--integrand-set``, ``--n``, ``--realizations``, ``--dims``, ``--seed``, ``--no-shift``,
/// ``--randomize``, checked the same way.
///
/// The dict holds every key ``converge --json`` prints (``pattern``, ``integrand``, their
/// ``*_params``, ``dims``, ``shift``, ``seed``, ``realizations``, ``reference`` (the exact
/// integral), ``rows``, ``slope``, ``slope_stderr``, ``timings_ms``) and the rows as float64
/// arrays: ``n``, ``mse``, ``mse_stderr`` (NaN where undefined: R = 1), ``variance``,
/// ``bias2``. ``slope`` is the least-squares slope of ln MSE on ln N (None with fewer than two
/// N of MSE > 0). Releases the GIL; Ctrl-C raises KeyboardInterrupt.
#[pyfunction]
#[pyo3(signature = (pattern, integrand, n, realizations, dims = 2, *, seed = None, no_shift = false, randomize = false, pattern_params = None, integrand_params = None, budget = None, budget_memory = None))]
#[allow(clippy::too_many_arguments)]
fn converge<'py>(
    py: Python<'py>,
    pattern: &str,
    integrand: &str,
    n: Vec<usize>,
    realizations: usize,
    dims: usize,
    seed: Option<u64>,
    no_shift: bool,
    randomize: bool,
    pattern_params: Option<&Bound<'py, PyDict>>,
    integrand_params: Option<&Bound<'py, PyDict>>,
    budget: Option<f64>,
    budget_memory: Option<f64>,
) -> PyResult<Bound<'py, PyDict>> {
    let args = ConvergeArgs {
        pattern: pattern.into(),
        set: input::settings(pattern_params)?,
        integrand: integrand.into(),
        integrand_set: input::settings(integrand_params)?,
        randomize,
        n: n.iter()
            .map(|v| v.to_string())
            .collect::<Vec<_>>()
            .join(","),
        realizations: realizations.to_string(),
        dims: Some(dims.to_string()),
        seed,
        no_shift,
        json: true,
        csv: None,
    };
    let session = run::session(budget, budget_memory)?;
    let (req, result) = run::run(py, session, move |session| {
        Ok(study(&args, session)?.expect("no estimate-only run"))
    })?;
    let d = output::dict(py, &study_json(&req, &result))?;
    let rows = &result.rows;
    let column = |f: fn(&crate::core::integration::StudyRow) -> f64| {
        output::vector(py, rows.iter().map(f).collect())
    };
    let ns: Vec<i64> = rows.iter().map(|r| r.n as i64).collect();
    d.set_item("n", numpy::PyArray1::from_vec(py, ns))?;
    d.set_item("mse", column(|r| r.mse))?;
    d.set_item("mse_stderr", column(|r| r.mse_stderr.unwrap_or(f64::NAN)))?;
    d.set_item("variance", column(|r| r.variance))?;
    d.set_item("bias2", column(|r| r.bias2))?;
    Ok(d)
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(converge, m)?)
}
