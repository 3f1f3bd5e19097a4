//! Refinements that follow a complete picture (a spectrum's measured error): they run on one
//! thread of the lowest scheduling priority, so that they never take a core from a node the
//! picture still waits for (on 2 cores, the default scene's exact DFT rows used to share the
//! cores with its reconstruction). The readout still comes, as soon as a core is free.

use std::sync::OnceLock;

/// Runs `f` on the refinement thread and waits for it; parallel iterators inside `f` stay on
/// that one thread. Callers pass work whose result does not depend on the number of threads
/// (the exact DFT rows: every sum in the same order), so the bits are those of `f()` anywhere.
/// Where the thread cannot be started, `f` runs on the calling thread.
pub fn run<R: Send>(f: impl FnOnce() -> R + Send) -> R {
    match pool() {
        Some(pool) => pool.install(f),
        None => f(),
    }
}

fn pool() -> Option<&'static rayon::ThreadPool> {
    static POOL: OnceLock<Option<rayon::ThreadPool>> = OnceLock::new();
    POOL.get_or_init(|| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(1)
            .thread_name(|_| "samplescope-refine".to_string())
            .start_handler(|_| lower_priority())
            .build()
            .ok()
    })
    .as_ref()
}

/// Nice 19 for the calling thread (Linux keeps a nice value per thread).
#[cfg(all(target_os = "linux", target_env = "gnu"))]
fn lower_priority() {
    // SAFETY: setpriority takes no pointers; PRIO_PROCESS with who = 0 changes only the calling
    // thread's nice value on Linux. A failure leaves the priority as it was, which is harmless.
    unsafe {
        libc::setpriority(libc::PRIO_PROCESS, 0, 19);
    }
}

#[cfg(not(all(target_os = "linux", target_env = "gnu")))]
fn lower_priority() {}

#[cfg(test)]
mod tests {
    /// The work runs on the refinement thread, on one thread, and gives its value.
    #[test]
    fn runs_on_one_named_thread() {
        let (name, threads, sum) = super::run(|| {
            use rayon::prelude::*;
            (
                std::thread::current().name().map(str::to_string),
                rayon::current_num_threads(),
                (0..1000u64).into_par_iter().sum::<u64>(),
            )
        });
        assert_eq!(name.as_deref(), Some("samplescope-refine"));
        assert_eq!(threads, 1);
        assert_eq!(sum, 499_500);
    }

    /// The thread's nice value is 19 where the system keeps one per thread.
    #[cfg(all(target_os = "linux", target_env = "gnu"))]
    #[test]
    fn the_refinement_thread_has_the_lowest_priority() {
        // SAFETY: getpriority takes no pointers; errno is not consulted (19 is not -1).
        let nice = super::run(|| unsafe { libc::getpriority(libc::PRIO_PROCESS, 0) });
        assert_eq!(nice, 19);
    }
}
