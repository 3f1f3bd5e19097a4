//! `points` and `patterns`: a pattern's points as an (n, dims) float64 array, by the calls
//! `samplescope points` makes (the same bits), and the catalogue `points --list` prints.

use super::errors::{bad_input, checked_int, int_range};
use super::params::{member_from_kwargs, spec_dict};
use super::run::interruptible;
use crate::core::cube::MAX_DIMS;
use crate::core::family::Family;
use crate::core::pattern::{Pattern, PatternError, MAX_N};
use numpy::ndarray::Array2;
use numpy::PyArray2;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

/// Adds `points` and `patterns` to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(points, m)?)?;
    m.add_function(wrap_pyfunction!(patterns, m)?)?;
    Ok(())
}

/// The first `n` points of `pattern` in [0,1)^dims as a float64 array of shape (n, dims):
/// exactly the numbers `samplescope points PATTERN -n N --dims D --seed S --set key=value` writes.
///
/// `params` are the pattern's parameters (`samplescope.patterns()` lists them with their
/// defaults and ranges), validated by the same descriptors as `--set`. `seed` (default 0, as the
/// CLI's) is refused for a pattern that is deterministic with these parameters. `dims` other
/// than 2 takes the patterns with a d-dimensional form. With `allow_fewer=True` a Poisson-disk
/// pattern that stops short returns the points it placed (fewer than n rows).
///
/// `budget` (seconds) and `budget_memory` (GiB) are the CLI's `--budget` and `--budget-memory`
/// (defaults 60 s and 4 GiB): a generation estimated beyond them raises `ValueError` naming the
/// budget, before any work. Bad input raises `ValueError` with the CLI's one-line message;
/// Ctrl-C stops the work and raises `KeyboardInterrupt`.
#[pyfunction]
#[pyo3(signature = (pattern, n, *, dims = 2, seed = None, allow_fewer = false, budget = None, budget_memory = None, **params))]
#[allow(clippy::too_many_arguments)]
fn points<'py>(
    py: Python<'py>,
    pattern: &str,
    n: i128,
    dims: i128,
    seed: Option<i128>,
    allow_fewer: bool,
    budget: Option<f64>,
    budget_memory: Option<f64>,
    params: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let member: Pattern = member_from_kwargs(pattern, params)?;
    let n: usize = checked_int("n", n, 1, MAX_N as u128)?;
    let dims: usize = match checked_int("dims", dims, 0, MAX_DIMS as u128) {
        Ok(d) => d,
        // The pattern's own range (2 only for a 2D pattern) as `--dims` says it.
        Err(_) => return Err(dims_error(&member, dims)),
    };
    let seed = match seed {
        Some(s) => {
            let s: u64 = checked_int("seed", s, 0, u64::MAX as u128)?;
            if let Some(message) = member.seed_refusal(s, "seed") {
                return Err(bad_input(message));
            }
            s
        }
        None => 0,
    };
    if allow_fewer && !member.may_place_fewer() {
        return Err(bad_input(format!(
            "allow_fewer: {} always places exactly N points, so allow_fewer would have no \
             effect (only poisson-dart and poisson-bridson can stop short)",
            member.name()
        )));
    }
    if allow_fewer && dims != 2 {
        return Err(bad_input(
            "allow_fewer: applies to 2D patterns only (dims = 2)",
        ));
    }
    member.validate_cube(n, dims).map_err(bad_input)?;
    // The CLI's budget, checked before any work with `points`' estimate of the generation.
    let session = super::run::session(budget, budget_memory)?;
    let plan = vec![if dims == 2 {
        crate::core::budget::pattern(&member, n)
    } else {
        crate::core::budget::pattern_cube(&member, n, dims)
    }];
    let _progress = session.admit(plan).map_err(super::errors::cli)?;
    let generated = interruptible(
        py,
        move |cancel| -> Result<(usize, Vec<f64>), PatternError> {
            if allow_fewer {
                let placed = member.generate_with(n, seed, cancel)?.points;
                let coords = placed.iter().flat_map(|p| [p.x, p.y]).collect();
                return Ok((placed.len(), coords));
            }
            let cube = member.generate_cube(n, dims, seed, cancel)?;
            Ok((cube.n(), cube.into_coords()))
        },
    )?;
    let (rows, coords) = generated.map_err(|e| match e {
        e @ PatternError::TooFew { .. } => bad_input(format!(
            "{e}; or pass allow_fewer=True to keep the points placed"
        )),
        e => bad_input(e),
    })?;
    let array = Array2::from_shape_vec((rows, dims), coords)
        .map_err(|e| bad_input(format!("points: {e}")))?;
    Ok(PyArray2::from_owned_array(py, array))
}

/// The error of `dims` outside 1..=MAX_DIMS (a negative one included), in the words of the
/// pattern's own check.
fn dims_error(pattern: &Pattern, dims: i128) -> PyErr {
    match pattern.check_dims(0) {
        Err(PatternError::InvalidDims { allowed, .. }) => {
            bad_input(format!("{}: dims = {dims}: {allowed}", pattern.name()))
        }
        _ => int_range("dims", dims, 1, MAX_DIMS as u128),
    }
}

/// The catalogue of patterns, in the order `samplescope points --list` prints them: a list of
/// dicts with `name`, `summary`, `max_dims` (2 for the 2D-only patterns), `random` (whether
/// the default parameters use the seed) and `params`, one dict per parameter with `name`,
/// `doc`, `kind` (int, float, scale, choice, bool, list, per_dim), `default`, `allowed` (the
/// range in the CLI's words) and by kind `min`/`max`, `options` or `length`.
#[pyfunction]
fn patterns(py: Python<'_>) -> PyResult<Bound<'_, PyList>> {
    let list = PyList::empty(py);
    for p in Pattern::all() {
        let d = PyDict::new(py);
        d.set_item("name", p.name())?;
        d.set_item("summary", p.summary())?;
        d.set_item("max_dims", p.max_dims())?;
        d.set_item("random", p.is_random())?;
        let specs = PyList::empty(py);
        for spec in p.listed_specs() {
            specs.append(spec_dict(py, &spec)?)?;
        }
        d.set_item("params", specs)?;
        list.append(d)?;
    }
    Ok(list)
}
