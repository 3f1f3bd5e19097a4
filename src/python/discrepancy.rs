//! `discrepancy(points, method)`: one discrepancy of a point set, scipy's conventions
//! (`core::metrics::cube`): "L2-star" the root, "CD", "WD", "MD" and "SD" squared, "star" the
//! exact 2D star discrepancy (`core::metrics::star`).

use super::{input, run};
use crate::cli::CliError;
use crate::core::metrics::cube::{self, Discrepancy};
use crate::core::metrics::{self, MetricsError};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

/// The methods, as `method=` names them.
pub const METHODS: [&str; 6] = ["star", "L2-star", "CD", "WD", "MD", "SD"];

fn metrics_err(e: MetricsError) -> CliError {
    match e {
        MetricsError::Cancelled => CliError::Cancelled,
        e => CliError::Usage(e.to_string()),
    }
}

/// The discrepancy `method` of `points`, an (N, D) array of points in [0,1)^D.
///
/// Methods (the numbers of ``scipy.stats.qmc.discrepancy`` where scipy has the method):
///
/// - ``"L2-star"`` (default): Warnock's L2-star discrepancy T_N, the root (as scipy's).
/// - ``"CD"``: Hickernell's centred L2 discrepancy, **squared** (CD², as scipy's "CD").
/// - ``"WD"``: the wrap-around L2 discrepancy, **squared** (WD², as scipy's "WD").
/// - ``"MD"``: Zhou, Fang and Ning's mixture discrepancy, **squared** (MD², as scipy's "MD").
/// - ``"SD"``: Hickernell's symmetric L2 discrepancy, **squared** (SD²; scipy has none).
/// - ``"star"``: the exact star discrepancy D*_N (2D only, N ≤ 262144, O(N²)).
///
/// ``budget`` (seconds) and ``budget_memory`` (GiB) bound the estimated work as the CLI's
/// ``--budget`` and ``--budget-memory`` do (defaults 60 s and 4 GiB); over them, ValueError.
/// Releases the GIL; Ctrl-C raises KeyboardInterrupt.
#[pyfunction]
#[pyo3(signature = (points, method = "L2-star", *, budget = None, budget_memory = None))]
fn discrepancy(
    py: Python<'_>,
    points: &Bound<'_, PyAny>,
    method: &str,
    budget: Option<f64>,
    budget_memory: Option<f64>,
) -> PyResult<f64> {
    if !METHODS.contains(&method) {
        return Err(PyValueError::new_err(format!(
            "method = {method}: must be one of {}",
            METHODS.join(", ")
        )));
    }
    let points = input::cube(points, "points")?;
    let session = run::session(budget, budget_memory)?;
    if method == "star" {
        let plane = points.to_2d().ok_or_else(|| {
            PyValueError::new_err(format!(
                "method = star: the exact star discrepancy is 2D, and points has {} columns \
                 (use L2-star, CD, WD, MD or SD)",
                points.dims()
            ))
        })?;
        let plan = vec![metrics::cost::star_discrepancy(plane.len())];
        return run::run(py, session, move |session| {
            let _progress = session.admit(plan)?;
            metrics::star_discrepancy(&plane, &session.cancel)
                .map(|s| s.value)
                .map_err(metrics_err)
        });
    }
    let which = Discrepancy::ALL
        .into_iter()
        .find(|d| d.scipy_method() == Some(method))
        .unwrap_or(Discrepancy::Symmetric);
    let plan = vec![cube::cost::cube_discrepancy(
        which,
        points.n(),
        points.dims(),
    )];
    run::run(py, session, move |session| {
        let _progress = session.admit(plan)?;
        cube::discrepancy(&points, which, &session.cancel, &mut |_| {}).map_err(metrics_err)
    })
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(discrepancy, m)?)
}
