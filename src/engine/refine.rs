//! Refinements that follow a complete picture (a spectrum's measured error): they run on their
//! own threads (one per core) at a low scheduling priority (nice 10: about a tenth of a core's
//! share against a normal thread), so that they hardly take a core from a node the picture
//! still waits for (on 2 cores, the default scene's exact DFT rows used to share the cores with
//! its reconstruction). The readout still comes, as soon as a core is free; never starved
//! outright (nice 19 would leave it ≈ 1.5 % while every core is busy, which would hold up a
//! cancelled job's exit on a loaded machine).

use std::sync::OnceLock;

/// Runs `f` on a refinement thread and waits for it; parallel iterators inside `f` stay on
/// the refinement threads. Callers pass work whose result does not depend on the number of threads
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
            .num_threads(
                std::thread::available_parallelism()
                    .map(usize::from)
                    .unwrap_or(1),
            )
            .thread_name(|i| format!("samplescope-refine-{i}"))
            .start_handler(|_| lower_priority())
            .build()
            .ok()
    })
    .as_ref()
}

/// The refinement threads' nice value.
pub const NICE: i32 = 10;

/// [`NICE`] for the calling thread (Linux keeps a nice value per thread).
#[cfg(all(target_os = "linux", target_env = "gnu"))]
fn lower_priority() {
    // SAFETY: setpriority takes no pointers; PRIO_PROCESS with who = 0 changes only the calling
    // thread's nice value on Linux. A failure leaves the priority as it was, which is harmless.
    unsafe {
        libc::setpriority(libc::PRIO_PROCESS, 0, NICE);
    }
}

#[cfg(not(all(target_os = "linux", target_env = "gnu")))]
fn lower_priority() {}

#[cfg(test)]
mod tests {
    /// The work runs on a refinement thread, its parallel iterators on the refinement pool,
    /// and gives its value.
    #[test]
    fn runs_on_the_refinement_threads() {
        let (name, threads, sum) = super::run(|| {
            use rayon::prelude::*;
            (
                std::thread::current().name().map(str::to_string),
                rayon::current_num_threads(),
                (0..1000u64).into_par_iter().sum::<u64>(),
            )
        });
        assert!(name.unwrap().starts_with("samplescope-refine-"));
        let cores = std::thread::available_parallelism().map_or(1, usize::from);
        assert_eq!(threads, cores);
        assert_eq!(sum, 499_500);
    }

    /// The thread's nice value is NICE where the system keeps one per thread (and the caller's
    /// is untouched).
    #[cfg(all(target_os = "linux", target_env = "gnu"))]
    #[test]
    fn the_refinement_thread_has_the_lowest_priority() {
        // SAFETY: getpriority takes no pointers; errno is not consulted (neither value is -1).
        let get = || unsafe { libc::getpriority(libc::PRIO_PROCESS, 0) };
        let mine = get();
        assert_eq!(super::run(get), super::NICE);
        assert_eq!(get(), mine);
    }
}
