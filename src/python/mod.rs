//! The Python extension module `samplescope._native` (cargo feature `python`, built by maturin
//! from `pyproject.toml`; the package `samplescope` in `src/python/samplescope/` re-exports it).
//!
//! One file per area, each with a `register` that adds its functions to the module: `points.rs`
//! (`points`, `patterns`), `discrepancy.rs` (`discrepancy`), `analyze.rs` (`analyze`,
//! `periodogram`), `filter.rs` (`filter_response`), `recon.rs` (`reconstruct`), `converge.rs`
//! (`converge`), `render.rs` (`render`). Shared by all of them: `errors.rs` (bad input as
//! `ValueError` with the CLI's one-line message), `params.rs` (keyword arguments through the
//! parameter descriptors, as `--set` goes), `input.rs` (point arrays in), `output.rs` (the CLI's
//! JSON objects as dicts, arrays out) and `run.rs` (long work off the GIL under the CLI's
//! budget, Ctrl-C as `KeyboardInterrupt`). The numbers are the library's, computed by the same
//! calls the CLI makes (the subcommands' own functions in `crate::cli`); nothing here
//! computes.

mod analyze;
mod converge;
mod discrepancy;
mod errors;
mod filter;
mod input;
mod output;
mod params;
mod points;
mod recon;
mod render;
mod run;

use pyo3::prelude::*;

/// samplescope's computation: sample patterns, spectra, filters, reconstruction, discrepancy
/// and integration error, on NumPy arrays.
#[pymodule]
#[pyo3(name = "_native")]
fn native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    points::register(m)?;
    discrepancy::register(m)?;
    analyze::register(m)?;
    filter::register(m)?;
    recon::register(m)?;
    converge::register(m)?;
    render::register(m)?;
    Ok(())
}
