//! Point arrays from Python, converted once and checked with the core's words: any (N, D)
//! array-like of real numbers (C or Fortran order or strided, float32 or float64, integers,
//! nested lists) to the core's point sets (`CubePoints`; a 2D set for D = 2), NaN, other
//! shapes, empty sets and coordinates outside [0, 1) refused naming the argument; and keyword
//! arguments as the CLI's `key=value` settings.

use crate::core::cube::{CubePoints, MAX_DIMS};
use glam::DVec2;
use numpy::{PyReadonlyArrayDyn, PyUntypedArrayMethods};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// The array of `obj` as float64 (a view where it already is one): real numbers only (a
/// complex, boolean, string or object array is refused rather than cast), named `name` in
/// errors.
fn float_array<'py>(obj: &Bound<'py, PyAny>, name: &str) -> PyResult<PyReadonlyArrayDyn<'py, f64>> {
    let py = obj.py();
    let np = py.import("numpy")?;
    let refuse = |what: String| {
        PyValueError::new_err(format!(
            "{name}: expected an array of real numbers of shape (N, D), got {what}"
        ))
    };
    let array = np
        .call_method1("asarray", (obj,))
        .map_err(|e| refuse(e.value(py).to_string()))?;
    let kind: String = array.getattr("dtype")?.getattr("kind")?.extract()?;
    if !matches!(kind.as_str(), "f" | "i" | "u") {
        let dtype = array.getattr("dtype")?.str()?.to_string();
        return Err(refuse(format!("an array of {dtype}")));
    }
    let array = if kind == "f"
        && array
            .getattr("dtype")?
            .getattr("itemsize")?
            .extract::<usize>()?
            == 8
    {
        array
    } else {
        array.call_method1("astype", ("float64",))?
    };
    array
        .extract::<PyReadonlyArrayDyn<'py, f64>>()
        .map_err(|e| refuse(e.to_string()))
}

/// An (N, D) array of points in [0,1)^D: at least one point, 1 ≤ D ≤ 1024, every coordinate
/// a number in [0, 1) (NaN and 1.0 refused), copied row-major whatever the array's order.
pub fn cube(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<CubePoints> {
    let array = float_array(obj, name)?;
    let shape = array.shape().to_vec();
    if shape.len() != 2 {
        return Err(PyValueError::new_err(format!(
            "{name}: expected an array of shape (N, D), got shape {}",
            shape_text(&shape)
        )));
    }
    let (n, dims) = (shape[0], shape[1]);
    if n == 0 {
        return Err(PyValueError::new_err(format!(
            "{name}: holds no points (shape {}): give at least one",
            shape_text(&shape)
        )));
    }
    if dims == 0 || dims > MAX_DIMS {
        return Err(PyValueError::new_err(format!(
            "{name}: {dims} columns (shape {}): D must be an integer in 1..={MAX_DIMS}",
            shape_text(&shape)
        )));
    }
    crate::core::cube::check_size(n, dims)
        .map_err(|e| PyValueError::new_err(format!("{name}: {e}")))?;
    let view = array.as_array();
    let coords: Vec<f64> = view.iter().copied().collect();
    CubePoints::new(dims, coords).map_err(|e| PyValueError::new_err(format!("{name}: {e}")))
}

/// An (N, 2) array of points in [0,1)² (as [`cube`], exactly two columns).
pub fn plane(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<Vec<DVec2>> {
    let points = cube(obj, name)?;
    points.to_2d().ok_or_else(|| {
        PyValueError::new_err(format!(
            "{name}: {} columns: expected a 2D point set of shape (N, 2)",
            points.dims()
        ))
    })
}

/// K realizations of 2D points: an (N, 2) array (K = 1) or a (K, N, 2) array.
pub fn plane_sets(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<Vec<Vec<DVec2>>> {
    let ndim: usize = float_array(obj, name)?.ndim();
    if ndim != 3 {
        return Ok(vec![plane(obj, name)?]);
    }
    let mut sets = Vec::new();
    for (k, item) in obj.try_iter()?.enumerate() {
        sets.push(plane(&item?, &format!("{name}[{k}]"))?);
    }
    if sets.is_empty() {
        return Err(PyValueError::new_err(format!(
            "{name}: holds no realizations (shape (0, N, 2))"
        )));
    }
    Ok(sets)
}

fn shape_text(shape: &[usize]) -> String {
    match shape {
        [one] => format!("({one},)"),
        _ => format!(
            "({})",
            shape
                .iter()
                .map(|s| s.to_string())
                .collect::<Vec<_>>()
                .join(", ")
        ),
    }
}

/// Keyword arguments as the CLI's `key=value` settings, in the order given (each value as
/// `--set` text, [`super::params::value_text`]), for the CLI's `from_args`.
pub fn settings(kwargs: Option<&Bound<'_, PyDict>>) -> PyResult<Vec<String>> {
    let mut out = Vec::new();
    if let Some(kwargs) = kwargs {
        for (k, v) in kwargs.iter() {
            let key: String = k.extract()?;
            out.push(format!("{key}={}", super::params::value_text(&v)?));
        }
    }
    Ok(out)
}
