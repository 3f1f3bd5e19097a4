//! Long calls: the work runs on a worker thread with the GIL released (other Python threads,
//! and a second computation, run meanwhile) while the calling thread checks for signals every
//! [`POLL`]; a Ctrl-C cancels the work's token and, once the work has stopped, reaches the
//! caller as `KeyboardInterrupt` (nothing is left half-made: the work's result is dropped).

use crate::core::cancel::Cancel;
use pyo3::prelude::*;
use std::sync::{Condvar, Mutex};
use std::time::Duration;

/// How often the calling thread looks for a signal (Python's handlers run only there).
pub const POLL: Duration = Duration::from_millis(20);

/// Runs `work` with a cancellation token on a worker thread, the GIL released; returns its
/// result, or the error of a Python signal handler (`KeyboardInterrupt` for Ctrl-C) after
/// cancelling the token and waiting for `work` to return.
pub fn interruptible<T, F>(py: Python<'_>, work: F) -> PyResult<T>
where
    T: Send,
    F: FnOnce(&Cancel) -> T + Send,
{
    let cancel = Cancel::new();
    let done = (Mutex::new(false), Condvar::new());
    std::thread::scope(|s| {
        let worker = s.spawn(|| {
            let result = work(&cancel);
            *done.0.lock().unwrap_or_else(|e| e.into_inner()) = true;
            done.1.notify_all();
            result
        });
        let mut interrupted = None;
        loop {
            let finished = py.detach(|| {
                let guard = done.0.lock().unwrap_or_else(|e| e.into_inner());
                let (guard, _) = done
                    .1
                    .wait_timeout_while(guard, POLL, |finished| !*finished)
                    .unwrap_or_else(|e| e.into_inner());
                *guard
            });
            if finished {
                break;
            }
            if interrupted.is_none() {
                if let Err(e) = py.check_signals() {
                    cancel.cancel();
                    interrupted = Some(e);
                }
            }
        }
        let result = py.detach(|| worker.join());
        match (interrupted, result) {
            (Some(e), _) => Err(e),
            (None, Ok(r)) => Ok(r),
            (None, Err(panic)) => std::panic::resume_unwind(panic),
        }
    })
}
