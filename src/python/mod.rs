//! The Python extension module `samplescope._native` (cargo feature `python`, built by maturin
//! from `pyproject.toml`; the package `samplescope` in `src/python/samplescope/` re-exports it).
//!
//! One file per area, each with a `register` that adds its functions to the module: `points.rs`
//! (`points`, `patterns`). Shared by all of them: `errors.rs` (bad input as `ValueError` with
//! the CLI's one-line message), `params.rs` (keyword arguments through the parameter
//! descriptors, as `--set` goes) and `run.rs` (long work off the GIL, Ctrl-C as
//! `KeyboardInterrupt`). The numbers are the library's, computed by the same calls the CLI
//! makes; nothing here computes.

mod errors;
mod params;
mod points;
mod run;

use pyo3::prelude::*;

/// samplescope's computation: sample patterns, spectra, filters, reconstruction, discrepancy
/// and integration error, on NumPy arrays.
#[pymodule]
#[pyo3(name = "_native")]
fn native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    points::register(m)?;
    Ok(())
}
