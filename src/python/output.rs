//! What the module gives back to Python: the CLI's JSON objects as dicts (the same keys and
//! values `--json` prints) and the arrays behind them as float64 numpy arrays.

use numpy::{PyArray1, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use pyo3::IntoPyObjectExt;
use serde_json::Value;

/// A JSON value as Python: null → None, numbers as int or float, arrays as lists, objects as
/// dicts (keys in the CLI's order).
pub fn json<'py>(py: Python<'py>, value: &Value) -> PyResult<Bound<'py, PyAny>> {
    Ok(match value {
        Value::Null => py.None().into_bound(py),
        Value::Bool(b) => b.into_bound_py_any(py)?,
        Value::Number(n) => match (n.as_u64(), n.as_i64(), n.as_f64()) {
            (Some(u), _, _) => u.into_bound_py_any(py)?,
            (_, Some(i), _) => i.into_bound_py_any(py)?,
            (_, _, f) => f.unwrap_or(f64::NAN).into_bound_py_any(py)?,
        },
        Value::String(s) => s.into_bound_py_any(py)?,
        Value::Array(items) => {
            let list = PyList::empty(py);
            for v in items {
                list.append(json(py, v)?)?;
            }
            list.into_any()
        }
        Value::Object(map) => {
            let dict = PyDict::new(py);
            for (k, v) in map {
                dict.set_item(k, json(py, v)?)?;
            }
            dict.into_any()
        }
    })
}

/// A JSON object as a dict (see [`json`]).
pub fn dict<'py>(py: Python<'py>, value: &Value) -> PyResult<Bound<'py, PyDict>> {
    Ok(json(py, value)?.cast_into::<PyDict>()?)
}

/// `rows` of `W` numbers as a float64 array of shape (len, W).
pub fn table<'py, const W: usize>(
    py: Python<'py>,
    rows: &[[f64; W]],
) -> PyResult<Bound<'py, PyAny>> {
    let flat: Vec<f64> = rows.iter().flatten().copied().collect();
    Ok(PyArray1::from_vec(py, flat)
        .reshape([rows.len(), W])?
        .into_any())
}

/// `values`, row-major, as a float64 array of shape (rows, columns).
pub fn matrix(
    py: Python<'_>,
    values: Vec<f64>,
    rows: usize,
    columns: usize,
) -> PyResult<Bound<'_, PyAny>> {
    Ok(PyArray1::from_vec(py, values)
        .reshape([rows, columns])?
        .into_any())
}

/// `values` as a float64 array of shape (len,).
pub fn vector(py: Python<'_>, values: Vec<f64>) -> Bound<'_, PyAny> {
    PyArray1::from_vec(py, values).into_any()
}
