//! Cooperative cancellation for long computations.
//!
//! Hot loops call [`Cancel::check`] every few thousand iterations; when the token has been
//! cancelled (a newer request superseded the job, or the user pressed Esc) they return
//! `Err(Cancelled)` promptly instead of finishing stale work.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

/// The error a cancelled computation returns.
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
#[error("cancelled")]
pub struct Cancelled;

/// A shareable cancellation flag. Cloning shares the flag.
#[derive(Debug, Clone, Default)]
pub struct Cancel(Arc<AtomicBool>);

impl Cancel {
    /// A fresh, not-cancelled token.
    pub fn new() -> Self {
        Self::default()
    }

    /// A token that is never cancelled (for CLI use and tests).
    pub fn never() -> Self {
        Self::default()
    }

    /// A token on an existing flag, e.g. one a signal handler sets (an atomic store is all a
    /// handler may do): the token is cancelled once the flag is `true`.
    pub fn from_flag(flag: Arc<AtomicBool>) -> Self {
        Cancel(flag)
    }

    /// Requests cancellation; every holder sees it at its next check.
    pub fn cancel(&self) {
        self.0.store(true, Ordering::Relaxed);
    }

    /// Whether cancellation was requested.
    #[inline]
    pub fn is_cancelled(&self) -> bool {
        self.0.load(Ordering::Relaxed)
    }

    /// `Err(Cancelled)` once cancellation was requested.
    #[inline]
    pub fn check(&self) -> Result<(), Cancelled> {
        if self.is_cancelled() {
            Err(Cancelled)
        } else {
            Ok(())
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_token_on_a_flag_sees_the_flag() {
        let flag = Arc::new(AtomicBool::new(false));
        let c = Cancel::from_flag(flag.clone());
        assert!(c.check().is_ok());
        flag.store(true, Ordering::Relaxed);
        assert_eq!(c.check(), Err(Cancelled));
        assert!(c.clone().is_cancelled());
    }
}
