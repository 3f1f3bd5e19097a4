//! `filter_response(kernel, …)`: a reconstruction filter's response profile and its four
//! quality metrics, as `samplescope filter --response --json` computes them.

use super::{input, output, run};
use crate::cli::filter::{metrics_json, CSV_OMEGA_MAX, CSV_STEPS};
use crate::cli::CliError;
use crate::core::budget;
use crate::core::filter::{Filter, Filter2D, Mode2D};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// `(omega, magnitude, phase, metrics)`.
type Response<'py> = (
    Bound<'py, PyAny>,
    Bound<'py, PyAny>,
    Bound<'py, PyAny>,
    Bound<'py, PyDict>,
);

/// A filter's frequency response and quality metrics: ``(omega, magnitude, phase, metrics)``.
///
/// ``kernel`` is a filter name or preset (``samplescope filter --list`` lists them with their
/// parameters, defaults and ranges); its parameters are keyword arguments (``radius=2``,
/// ``window="kaiser"``, ``beta=8``), checked by the CLI's descriptors. ``mode`` is
/// ``"separable"`` (h(x)h(y)) or ``"radial"`` (h(|p|)).
///
/// ``omega`` runs from 0 to 2 cycles per sample in steps of 1/256 (513 values; Nyquist is
/// 0.5); ``magnitude`` is H(ω)/H(0) where H(0) ≠ 0 (raw H for zero-DC filters) and ``phase``
/// is in radians in (−π, π]: the 1D response in separable mode, the Hankel profile H₂(ρ) in
/// radial mode (the CSV ``filter --response`` writes). ``metrics`` is the dict ``filter
/// --json`` prints: ``smoothing``, ``post_aliasing``, ``ringing`` (with ``overshoot`` and
/// ``undershoot``), ``anisotropy``, ``omega_max``, and the filter's ``name``, ``mode`` and
/// ``params``.
#[pyfunction]
#[pyo3(signature = (kernel, *, mode = "separable", budget = None, budget_memory = None, **params))]
fn filter_response<'py>(
    py: Python<'py>,
    kernel: &str,
    mode: &str,
    budget: Option<f64>,
    budget_memory: Option<f64>,
    params: Option<&Bound<'py, PyDict>>,
) -> PyResult<Response<'py>> {
    let settings = input::settings(params)?;
    let (kernel, mode) = (kernel.to_string(), mode.to_string());
    let session = run::session(budget, budget_memory)?;
    let (curve, json) = run::run(py, session, move |session| {
        let filter: Filter =
            crate::cli::from_args("", &kernel, "--set", &settings, "samplescope filter --list")?;
        let mode = Mode2D::from_name(&mode)?;
        let f2 = Filter2D::new(filter, mode)?;
        let _progress = session.admit(vec![budget::filter_metrics(&f2)])?;
        let curve = f2.response_profile(CSV_OMEGA_MAX, CSV_STEPS)?;
        session.cancel.check().map_err(|_| CliError::Cancelled)?;
        let metrics = f2.metrics()?;
        Ok((curve, metrics_json(&f2, &metrics)))
    })?;
    let column = |f: fn(&crate::core::filter::ResponseSample) -> f64| {
        output::vector(py, curve.samples.iter().map(f).collect())
    };
    Ok((
        column(|s| s.omega),
        column(|s| s.magnitude),
        column(|s| s.phase),
        output::dict(py, &json)?,
    ))
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(filter_response, m)?)
}
