//! The Python module's errors: bad input is a `ValueError` carrying the CLI's one-line message
//! (the library's error text, which names the field and the allowed range).

use pyo3::exceptions::PyValueError;
use pyo3::PyErr;

/// Bad input (the CLI's exit status 2) as a `ValueError` with the error's one-line message.
pub fn bad_input(e: impl std::fmt::Display) -> PyErr {
    PyValueError::new_err(e.to_string())
}

/// An integer argument `name = value` outside `min..=max`, in the CLI's words
/// (`n = 0: must be an integer in 1..=16777216`).
pub fn int_range(name: &str, value: impl std::fmt::Display, min: u128, max: u128) -> PyErr {
    bad_input(format!(
        "{name} = {value}: must be an integer in {min}..={max}"
    ))
}

/// `value` as an integer in `min..=max`, or [`int_range`]'s error.
pub fn checked_int<T: TryFrom<i128>>(
    name: &str,
    value: i128,
    min: u128,
    max: u128,
) -> Result<T, PyErr> {
    let inside = value >= 0 && (min..=max).contains(&(value as u128));
    inside
        .then(|| T::try_from(value).ok())
        .flatten()
        .ok_or_else(|| int_range(name, value, min, max))
}

/// A subcommand's error as Python's: cancellation as `KeyboardInterrupt`, the environment's
/// failures (the CLI's exit status 1: a file that cannot be read or written) as `OSError`,
/// bad input (status 2, the budget included) as `ValueError`, each with the CLI's message.
pub fn cli(e: crate::cli::CliError) -> PyErr {
    match e {
        crate::cli::CliError::Cancelled => {
            pyo3::exceptions::PyKeyboardInterrupt::new_err("interrupted")
        }
        e if e.exit_code() == 1 => pyo3::exceptions::PyOSError::new_err(e.to_string()),
        e => bad_input(e),
    }
}
