//! `reconstruct(…)`: a test signal sampled by a pattern (or by given points), reconstructed
//! with a filter, its reference image and the error: `samplescope recon`'s one-column scene
//! evaluated by the engine (`cli::recon::reconstruct`).

use super::{input, output, run};
use crate::cli::recon::{reconstruct as recon_scene, ReconArgs};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// Reconstructs a test signal: ``(image, reference, report)``.
///
/// ``signal`` (``zone-plate``, ``checkerboard``, ``grating``, ``step-edge``, ``polygon``,
/// ``sum-of-sines``, ``chirp``, ``square``, ``constant``) with ``signal_params``; sampled by
/// ``pattern`` (with ``pattern_params``, ``seed``) at ``n`` scattered samples over the image or
/// ``spp`` samples per pixel, or by ``points`` (an (N, 2) array of samples in [0,1)²; not with
/// ``n``, ``spp`` or ``pattern``); reconstructed with ``filter`` (``filter_params``, ``mode``
/// separable or radial) at ``size`` × ``size`` pixels. These are ``samplescope recon``'s
/// ``--signal``, ``--signal-set``, ``--pattern``, ``--set``, ``-n``, ``--spp``, ``--seed``,
/// ``--filter``, ``--filter-set``, ``--mode`` and ``--size``, checked the same way.
///
/// ``image`` and ``reference`` are float64 arrays (size, size) with row 0 at the **bottom**
/// (pixel (i, j) covers y ≈ (j + ½)/size: show with ``imshow(origin="lower")``); ``report``
/// is the dict ``recon --json`` prints (``rmse``, ``psnr``, ``max_abs_error``,
/// ``zero_weight_pixels``, ``normaliser``, ``reference_error_estimate``, ``reference_method``,
/// ``timings_ms``). Releases the GIL; Ctrl-C raises KeyboardInterrupt.
#[pyfunction]
#[pyo3(signature = (signal = "zone-plate", pattern = None, points = None, filter = "gaussian", size = 512, *, n = None, spp = None, seed = None, mode = "separable", signal_params = None, pattern_params = None, filter_params = None, allow_fewer = false, budget = None, budget_memory = None))]
#[allow(clippy::too_many_arguments)]
fn reconstruct<'py>(
    py: Python<'py>,
    signal: &str,
    pattern: Option<&str>,
    points: Option<&Bound<'py, PyAny>>,
    filter: &str,
    size: usize,
    n: Option<usize>,
    spp: Option<usize>,
    seed: Option<u64>,
    mode: &str,
    signal_params: Option<&Bound<'py, PyDict>>,
    pattern_params: Option<&Bound<'py, PyDict>>,
    filter_params: Option<&Bound<'py, PyDict>>,
    allow_fewer: bool,
    budget: Option<f64>,
    budget_memory: Option<f64>,
) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyAny>, Bound<'py, PyDict>)> {
    let samples = match points {
        Some(p) => {
            if pattern.is_some() || pattern_params.is_some_and(|p| !p.is_empty()) || seed.is_some()
            {
                return Err(pyo3::exceptions::PyValueError::new_err(
                    "points: the samples are given, so pattern, pattern_params and seed would have no effect; leave them out",
                ));
            }
            Some(input::plane(p, "points")?)
        }
        None => None,
    };
    if let (None, None, None) = (&samples, n, spp) {
        return Err(pyo3::exceptions::PyValueError::new_err(
            "reconstruct: give n (scattered samples), spp (samples per pixel) or points",
        ));
    }
    let args = ReconArgs {
        signal: signal.into(),
        signal_set: input::settings(signal_params)?,
        pattern: pattern.unwrap_or("jitter").into(),
        set: input::settings(pattern_params)?,
        n: match n {
            Some(n) => Some(
                crate::cli::parse_n(&n.to_string())
                    .map_err(pyo3::exceptions::PyValueError::new_err)?,
            ),
            None => None,
        },
        spp,
        seed,
        allow_fewer,
        filter: filter.into(),
        filter_set: input::settings(filter_params)?,
        mode: mode.into(),
        size,
        out: None,
        json: true,
    };
    let session = run::session(budget, budget_memory)?;
    let made = run::run(py, session, move |session| {
        Ok(recon_scene(&args, samples, session)?.expect("no estimate-only run"))
    })?;
    let w = made.recon.w;
    Ok((
        output::matrix(py, made.recon.pixels.clone(), w, w)?,
        output::matrix(py, made.reference.pixels.to_vec(), w, w)?,
        output::dict(py, &made.json())?,
    ))
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(reconstruct, m)?)
}
