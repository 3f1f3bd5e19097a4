//! Long calls: the work runs on a worker thread with the GIL released (other Python threads,
//! and a second computation, run meanwhile) while the calling thread checks for signals every
//! [`POLL`]; a Ctrl-C (or any signal handler that raises) cancels the work's token and reaches
//! the caller as `KeyboardInterrupt` as soon as the work has stopped, or [`GRACE`] after the
//! signal if it has not (what does not look at the token, a figure being drawn, finishes in the
//! background and its result is dropped; files are written through `core::output` under the
//! same token, so none is left half-written). [`run`] also gives the work a CLI [`Session`]:
//! the budget checked before any work (`budget`, `budget_memory` as the CLI's flags), the token,
//! and the CLI's errors as Python's ([`errors::cli`]).

use super::errors;
use crate::cli::session::{BudgetArgs, Session};
use crate::cli::CliError;
use crate::core::cancel::Cancel;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use std::sync::mpsc::{self, RecvTimeoutError};
use std::time::Duration;

/// How often the calling thread looks for a signal (Python's handlers run only there).
pub const POLL: Duration = Duration::from_millis(20);

/// After a signal, how long the call waits for the work to stop before it raises anyway.
pub const GRACE: Duration = Duration::from_millis(150);

/// Runs `work` with a fresh cancellation token off the GIL; returns its result, or the error
/// of a Python signal handler (`KeyboardInterrupt` for Ctrl-C) after cancelling the token.
pub fn interruptible<T, F>(py: Python<'_>, work: F) -> PyResult<T>
where
    T: Send + 'static,
    F: FnOnce(&Cancel) -> T + Send + 'static,
{
    run_with(py, Cancel::new(), work)
}

/// The session of one call: the CLI's budget (`budget` seconds, `budget_memory` GiB; the
/// CLI's defaults of 60 s and 4 GiB when `None`) and a fresh token.
pub fn session(budget: Option<f64>, budget_memory: Option<f64>) -> PyResult<Session> {
    for (name, value) in [("budget", budget), ("budget_memory", budget_memory)] {
        if let Some(v) = value.filter(|v| !(v.is_finite() && *v > 0.0)) {
            return Err(PyValueError::new_err(format!(
                "{name} = {v}: must be a positive number"
            )));
        }
    }
    Ok(Session::new(&BudgetArgs {
        budget,
        budget_memory,
        estimate: false,
    }))
}

/// Runs `work` under `session` off the GIL as [`interruptible`] runs it, with the session's
/// token; a CLI error becomes its Python exception ([`errors::cli`]).
pub fn run<T, F>(py: Python<'_>, session: Session, work: F) -> PyResult<T>
where
    T: Send + 'static,
    F: FnOnce(&Session) -> Result<T, CliError> + Send + 'static,
{
    let cancel = session.cancel.clone();
    run_with(py, cancel, move |_| work(&session))?.map_err(errors::cli)
}

/// The one runner: `work` on a thread of its own, the calling thread polling for signals.
fn run_with<T, F>(py: Python<'_>, cancel: Cancel, work: F) -> PyResult<T>
where
    T: Send + 'static,
    F: FnOnce(&Cancel) -> T + Send + 'static,
{
    let (done_tx, mut done_rx) = mpsc::channel::<T>();
    let token = cancel.clone();
    let worker = std::thread::Builder::new()
        .name("samplescope".into())
        .spawn(move || {
            let _ = done_tx.send(work(&token));
        })
        .map_err(|e| pyo3::exceptions::PyOSError::new_err(format!("cannot start a thread: {e}")))?;
    loop {
        // The receiver moves into the GIL-free wait and back (it is not `Sync`).
        let (rx, waited) = py.detach(move || {
            let waited = done_rx.recv_timeout(POLL);
            (done_rx, waited)
        });
        done_rx = rx;
        match waited {
            Ok(result) => {
                let _ = py.detach(move || worker.join());
                return Ok(result);
            }
            // The work panicked before it could send: the panic, re-raised here, becomes
            // pyo3's PanicException.
            Err(RecvTimeoutError::Disconnected) => {
                return match py.detach(move || worker.join()) {
                    Err(panic) => std::panic::resume_unwind(panic),
                    Ok(()) => Err(pyo3::exceptions::PyRuntimeError::new_err(
                        "the computation ended without a result",
                    )),
                };
            }
            Err(RecvTimeoutError::Timeout) => {}
        }
        if let Err(e) = py.check_signals() {
            cancel.cancel();
            let _ = py.detach(move || done_rx.recv_timeout(GRACE));
            return Err(e);
        }
    }
}
