//! Keyword arguments as parameters: each value becomes the text `--set key=value` would carry
//! and goes through the same descriptors ([`Params::set_all`]), so a Python call accepts and
//! refuses exactly what the CLI does, with the same message; and the descriptors as Python
//! data (the catalogue of `patterns()`).

use super::errors::bad_input;
use crate::core::family::Family;
use crate::core::params::{fmt_exact, ParamKind, ParamSpec, ParamValue, Params};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString};

/// A keyword argument's value as `--set` text: `True`/`False` as `true`/`false`, integers in
/// full, floats with round-trip digits, strings as given, sequences (lists, tuples, 1D arrays)
/// as `[a,b,…]`, any other number (NumPy scalars) through `float()`. A value of another type
/// becomes its `repr`, which the descriptor then refuses with the CLI's message.
pub fn value_text(value: &Bound<'_, PyAny>) -> PyResult<String> {
    if value.is_instance_of::<PyBool>() {
        return Ok(value.extract::<bool>()?.to_string());
    }
    if value.is_instance_of::<PyInt>() {
        return Ok(value.str()?.to_string());
    }
    if value.is_instance_of::<PyFloat>() {
        return Ok(fmt_exact(value.extract::<f64>()?));
    }
    if let Ok(s) = value.cast::<PyString>() {
        return Ok(s.to_string());
    }
    if let Ok(items) = value.extract::<Vec<f64>>() {
        let items: Vec<String> = items.into_iter().map(fmt_exact).collect();
        return Ok(format!("[{}]", items.join(",")));
    }
    if let Ok(v) = value.extract::<f64>() {
        return Ok(fmt_exact(v));
    }
    Ok(value.repr()?.to_string())
}

/// Applies keyword arguments to `params` as `--set` does ([`Params::set_all`]).
pub fn apply_kwargs(params: &mut impl Params, kwargs: Option<&Bound<'_, PyDict>>) -> PyResult<()> {
    let Some(kwargs) = kwargs else {
        return Ok(());
    };
    let mut pairs: Vec<(String, String)> = Vec::with_capacity(kwargs.len());
    for (key, value) in kwargs.iter() {
        pairs.push((key.extract::<String>()?, value_text(&value)?));
    }
    let pairs: Vec<(&str, &str)> = pairs
        .iter()
        .map(|(k, v)| (k.as_str(), v.as_str()))
        .collect();
    params.set_all(&pairs).map_err(bad_input)
}

/// The member of family `F` named `name` (or a preset), with keyword arguments applied: the
/// CLI's `from_args` for Python.
pub fn member_from_kwargs<F: Family>(
    name: &str,
    kwargs: Option<&Bound<'_, PyDict>>,
) -> PyResult<F> {
    let mut member = F::from_name(name).map_err(bad_input)?;
    apply_kwargs(&mut member, kwargs)?;
    Ok(member)
}

/// A parameter value as a Python object: int, float, str, bool or list of floats.
pub fn value_object<'py>(py: Python<'py>, value: &ParamValue) -> PyResult<Bound<'py, PyAny>> {
    Ok(match value {
        ParamValue::Int(v) => v.into_pyobject(py)?.into_any(),
        ParamValue::Float(v) => v.into_pyobject(py)?.into_any(),
        ParamValue::Choice(v) => v.into_pyobject(py)?.into_any(),
        ParamValue::Bool(v) => PyBool::new(py, *v).to_owned().into_any(),
        ParamValue::List(v) => PyList::new(py, v)?.into_any(),
    })
}

/// One descriptor as a dict: `name`, `doc`, `kind` (`int`, `float`, `scale`, `choice`, `bool`,
/// `list`, `per_dim`, `int_list`), `default`, `allowed` (the range in the CLI's words) and, by kind, `min`
/// and `max` (with `min_exclusive`/`max_exclusive` for floats), `options` or `length`.
pub fn spec_dict<'py>(py: Python<'py>, spec: &ParamSpec) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("name", spec.name)?;
    d.set_item("doc", spec.doc)?;
    d.set_item("default", value_object(py, &spec.default_value())?)?;
    d.set_item("allowed", spec.allowed())?;
    let kind = match &spec.kind {
        ParamKind::Int { min, max, .. } => {
            d.set_item("min", min)?;
            d.set_item("max", max)?;
            "int"
        }
        ParamKind::Float {
            min,
            max,
            min_exclusive,
            max_exclusive,
            ..
        } => {
            d.set_item("min", min)?;
            d.set_item("max", max)?;
            d.set_item("min_exclusive", min_exclusive)?;
            d.set_item("max_exclusive", max_exclusive)?;
            "float"
        }
        ParamKind::Scale { min, max, .. } => {
            d.set_item("min", min)?;
            d.set_item("max", max)?;
            "scale"
        }
        ParamKind::Choice { options, .. } => {
            d.set_item("options", options.to_vec())?;
            "choice"
        }
        ParamKind::Bool { .. } => "bool",
        ParamKind::List { default, min, max } => {
            d.set_item("min", min)?;
            d.set_item("max", max)?;
            d.set_item("length", default.len())?;
            "list"
        }
        ParamKind::PerDim { min, max, .. } => {
            d.set_item("min", min)?;
            d.set_item("max", max)?;
            "per_dim"
        }
        ParamKind::IntList { min, max } => {
            d.set_item("min", min)?;
            d.set_item("max", max)?;
            "int_list"
        }
    };
    d.set_item("kind", kind)?;
    Ok(d)
}
