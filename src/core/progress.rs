//! The one progress report of every iterative routine in `core`: how many of its steps are done,
//! and the partial result it has reached when it has one to lend.
//!
//! A routine that works in steps (an optimiser's iterations, an integration study's chunks of
//! tasks, a supersampled reference's passes, a convergence curve's spp levels, a periodogram
//! average's groups of realizations) takes `progress: &mut OnProgress<'_, T>` and calls it with
//! a [`Progress`]: `done` of `total` steps, and `so_far`, the partial result of type `T` it
//! reached (the points of a refining pattern, the running mean periodogram, the study of the
//! first realizations, …) when it has one. Every such routine keeps these rules (a table-driven
//! test in `tests/it/progress.rs` checks them routine by routine):
//!
//! - `done` never decreases and never passes `total`; `total` is the same in every report.
//! - A routine with at least one step ends with a report of `done == total`, made after its
//!   last step and before it returns. Its `so_far`, when present, is the final result or a
//!   view of it, bit for bit what the routine returns; consumers that show only partial results
//!   (the engine publishes the final result itself) read [`Progress::interim`].
//! - The result never depends on the callback (what it does, or whether it is [`no_progress`]).
//!
//! # Rate limiting
//! A routine reports after every step when the report is free (its `so_far` borrows state it
//! holds anyway). When making `so_far` costs work (a copy of a running sum), the routine makes
//! it only at a pace and reports `so_far: None` in between: the periodogram average at most
//! once per `min_interval` (the engine passes 60 ms), checked with a [`Throttle`]; the
//! integration study when the completed realizations reach 1, 2, 4, 8, …. A consumer may thin
//! the reports further: the points node forwards a refining pattern's points at most every
//! 100 ms (a [`Throttle`] too), the command-line bar is redrawn by its own ticker.

use std::time::{Duration, Instant};

/// One progress report: `done` of `total` steps, and the partial result reached so far when
/// the routine has one to lend (see the module docs for the rules every routine keeps).
#[derive(Debug)]
pub struct Progress<'a, T: ?Sized> {
    /// Steps done (never decreasing, at most `total`).
    pub done: usize,
    /// Steps in all.
    pub total: usize,
    /// The partial result after `done` steps (the final one when `done == total`), when the
    /// routine has one to lend at this report.
    pub so_far: Option<&'a T>,
}

// By hand: derived impls would ask `T: Clone`, which `[DVec2]` is not.
impl<T: ?Sized> Clone for Progress<'_, T> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<T: ?Sized> Copy for Progress<'_, T> {}

impl<T: ?Sized> Eq for Progress<'_, T> {}

impl<T: ?Sized> PartialEq for Progress<'_, T> {
    /// The counts, and whether a partial result came (not its value).
    fn eq(&self, other: &Self) -> bool {
        (self.done, self.total, self.so_far.is_some())
            == (other.done, other.total, other.so_far.is_some())
    }
}

/// The callback an iterative routine reports its [`Progress`] to.
pub type OnProgress<'f, T> = dyn FnMut(Progress<'_, T>) + 'f;

/// A report without a partial result: what travels beside a partial result that is carried
/// on its own (the engine's published node values, the UI's "refining i/n").
pub type Steps = Progress<'static, ()>;

/// The callback that ignores every report (`&mut no_progress`), for callers that want only
/// the result.
pub fn no_progress<T: ?Sized>(_: Progress<'_, T>) {}

impl<'a, T: ?Sized> Progress<'a, T> {
    /// `done` of `total` steps, with no partial result.
    pub fn at(done: usize, total: usize) -> Self {
        Progress {
            done,
            total,
            so_far: None,
        }
    }

    /// `done` of `total` steps, with the partial result `so_far`.
    pub fn with(done: usize, total: usize, so_far: &'a T) -> Self {
        Progress {
            done,
            total,
            so_far: Some(so_far),
        }
    }

    /// The share done, in [0, 1]; 0 when there are no steps.
    pub fn fraction(&self) -> f64 {
        if self.total == 0 {
            0.0
        } else {
            (self.done as f64 / self.total as f64).min(1.0)
        }
    }

    /// Whether this is the routine's last report (`done == total`).
    pub fn is_final(&self) -> bool {
        self.done >= self.total
    }

    /// The partial result when this is not the last report: what a consumer that publishes
    /// the routine's returned result itself shows meanwhile.
    pub fn interim(&self) -> Option<&'a T> {
        self.so_far.filter(|_| !self.is_final())
    }

    /// The counts alone, detached from the partial result.
    pub fn steps(&self) -> Steps {
        Progress::at(self.done, self.total)
    }
}

/// At most one event per interval: [`Throttle::due`] once `interval` has passed since the
/// throttle was made or last [`Throttle::restart`]ed. A routine checks it before making a
/// costly partial result and restarts it once the report is made (so the time the report
/// takes is not counted in the next interval). `Duration::MAX` is never due.
#[derive(Debug, Clone, Copy)]
pub struct Throttle {
    interval: Duration,
    last: Instant,
}

impl Throttle {
    /// A throttle whose first event is due `interval` from now.
    pub fn new(interval: Duration) -> Self {
        Throttle {
            interval,
            last: Instant::now(),
        }
    }

    /// Whether `interval` has passed since the start or the last restart.
    pub fn due(&self) -> bool {
        self.last.elapsed() >= self.interval
    }

    /// Starts the next interval now.
    pub fn restart(&mut self) {
        self.last = Instant::now();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fraction_is_the_share_done_clamped_and_zero_without_steps() {
        assert_eq!(Progress::<()>::at(0, 4).fraction(), 0.0);
        assert_eq!(Progress::<()>::at(1, 4).fraction(), 0.25);
        assert_eq!(Progress::<()>::at(4, 4).fraction(), 1.0);
        assert_eq!(Progress::<()>::at(5, 4).fraction(), 1.0);
        assert_eq!(Progress::<()>::at(0, 0).fraction(), 0.0);
        // Large counts keep their ratio (no overflow in a product).
        assert_eq!(
            Progress::<()>::at(usize::MAX / 2, usize::MAX).fraction(),
            0.5
        );
    }

    #[test]
    fn interim_is_the_partial_result_before_the_last_report_only() {
        let pts = [1.0, 2.0];
        assert_eq!(Progress::with(1, 3, &pts[..]).interim(), Some(&pts[..]));
        assert_eq!(Progress::<[f64]>::at(1, 3).interim(), None);
        let last = Progress::with(3, 3, &pts[..]);
        assert!(last.is_final());
        assert_eq!(last.interim(), None);
        assert_eq!(last.so_far, Some(&pts[..]));
        assert!(!Progress::with(2, 3, &pts[..]).is_final());
        // Zero steps: the one report is the last.
        assert!(Progress::<()>::at(0, 0).is_final());
    }

    #[test]
    fn steps_detach_the_counts_and_equality_ignores_the_value() {
        let v = [7u8; 3];
        let p = Progress::with(2, 5, &v[..]);
        let s: Steps = p.steps();
        assert_eq!((s.done, s.total, s.so_far), (2, 5, None));
        let w = [9u8; 3];
        assert_eq!(p, Progress::with(2, 5, &w[..]));
        assert_ne!(p, Progress::at(2, 5));
        assert_ne!(p, Progress::with(3, 5, &v[..]));
    }

    #[test]
    fn no_progress_is_an_on_progress_of_any_type() {
        fn run(progress: &mut OnProgress<'_, [u32]>) -> usize {
            let v = [1, 2, 3];
            for k in 1..=3 {
                progress(Progress::with(k, 3, &v[..k]));
            }
            v.len()
        }
        assert_eq!(run(&mut no_progress), 3);
        let mut seen = Vec::new();
        run(&mut |p| seen.push((p.done, p.so_far.map_or(0, <[u32]>::len))));
        assert_eq!(seen, [(1, 1), (2, 2), (3, 3)]);
    }

    #[test]
    fn throttle_is_due_after_its_interval_and_restarts() {
        let mut t = Throttle::new(Duration::ZERO);
        assert!(t.due());
        t.restart();
        assert!(t.due(), "a zero interval is always due");
        let hour = Duration::from_secs(3600);
        assert!(!Throttle::new(hour).due(), "not before the interval");
        let mut t = Throttle::new(Duration::from_secs(10));
        t.last = Instant::now()
            .checked_sub(Duration::from_secs(11))
            .expect("the clock has run for 11 s");
        assert!(t.due(), "due once the interval has passed");
        t.restart();
        assert!(!t.due(), "a restart starts a new interval");
        assert!(!Throttle::new(Duration::MAX).due(), "MAX is never due");
    }
}
