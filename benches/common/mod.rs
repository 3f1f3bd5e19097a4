//! Timing helpers shared by the benches that print a table of medians beside criterion's
//! numbers (`patterns`, `pmj`, `optimize`, `converge`, `cube`): wall and CPU clocks, medians, and
//! criterion's benchmark filter. Each bench includes this module with `mod common;`.
#![allow(dead_code)]

use std::time::Instant;

/// Medians in ms: wall time and this thread's CPU time.
#[derive(Clone, Copy)]
pub struct Timing {
    pub wall: f64,
    pub cpu: f64,
}

/// CPU time of the calling thread in ms (`clock_gettime(CLOCK_THREAD_CPUTIME_ID)`), NaN where
/// unavailable. On a shared machine it excludes the time the thread waited for a core.
#[cfg(target_os = "linux")]
pub fn thread_cpu_ms() -> f64 {
    #[repr(C)]
    struct Timespec {
        tv_sec: i64,
        tv_nsec: i64,
    }
    extern "C" {
        fn clock_gettime(clock: i32, tp: *mut Timespec) -> i32;
    }
    const CLOCK_THREAD_CPUTIME_ID: i32 = 3;
    let mut t = Timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: `t` is a valid, writable timespec; the clock id is Linux's thread CPU clock.
    let rc = unsafe { clock_gettime(CLOCK_THREAD_CPUTIME_ID, &mut t) };
    if rc != 0 {
        return f64::NAN;
    }
    t.tv_sec as f64 * 1e3 + t.tv_nsec as f64 * 1e-6
}

#[cfg(not(target_os = "linux"))]
pub fn thread_cpu_ms() -> f64 {
    f64::NAN
}

/// CPU time of the whole process in ms (`clock_gettime(CLOCK_PROCESS_CPUTIME_ID)`), NaN where
/// unavailable: the study runs on rayon's threads, so a thread clock would miss most of it.
#[cfg(target_os = "linux")]
pub fn process_cpu_ms() -> f64 {
    #[repr(C)]
    struct Timespec {
        tv_sec: i64,
        tv_nsec: i64,
    }
    extern "C" {
        fn clock_gettime(clock: i32, tp: *mut Timespec) -> i32;
    }
    const CLOCK_PROCESS_CPUTIME_ID: i32 = 2;
    let mut t = Timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: `t` is a valid, writable timespec; the clock id is Linux's process CPU clock.
    let rc = unsafe { clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &mut t) };
    if rc != 0 {
        return f64::NAN;
    }
    t.tv_sec as f64 * 1e3 + t.tv_nsec as f64 * 1e-6
}

#[cfg(not(target_os = "linux"))]
pub fn process_cpu_ms() -> f64 {
    f64::NAN
}

/// Wall and CPU time in ms of one run (for references that take seconds).
pub fn once_ms(f: impl FnOnce()) -> Timing {
    let (c0, start) = (thread_cpu_ms(), Instant::now());
    f();
    Timing {
        wall: start.elapsed().as_secs_f64() * 1e3,
        cpu: thread_cpu_ms() - c0,
    }
}

/// Median wall and CPU times in ms of `reps` runs (after one warm-up run), CPU time from
/// `clock` ([`thread_cpu_ms`] or [`process_cpu_ms`]).
pub fn median_ms_with(clock: fn() -> f64, reps: usize, mut f: impl FnMut()) -> Timing {
    f();
    let mut wall = Vec::with_capacity(reps);
    let mut cpu = Vec::with_capacity(reps);
    for _ in 0..reps {
        let (c0, start) = (clock(), Instant::now());
        f();
        wall.push(start.elapsed().as_secs_f64() * 1e3);
        cpu.push(clock() - c0);
    }
    wall.sort_by(f64::total_cmp);
    cpu.sort_by(f64::total_cmp);
    Timing {
        wall: wall[reps / 2],
        cpu: cpu[reps / 2],
    }
}

/// Median wall and thread-CPU times in ms of `reps` runs (after one warm-up run).
pub fn median_ms(reps: usize, f: impl FnMut()) -> Timing {
    median_ms_with(thread_cpu_ms, reps, f)
}

/// The benchmark filter given on the command line (criterion's first positional argument), if any.
pub fn filter() -> Option<String> {
    const WITH_VALUE: &[&str] = &[
        "--warm-up-time",
        "--measurement-time",
        "--sample-size",
        "--save-baseline",
        "-s",
        "--baseline",
        "-b",
        "--baseline-lenient",
        "--load-baseline",
        "--output-format",
        "--plotting-backend",
        "--color",
        "-c",
        "--significance-level",
        "--confidence-level",
        "--nresamples",
        "--noise-threshold",
        "--profile-time",
        "--format",
    ];
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        if WITH_VALUE.contains(&a.as_str()) {
            args.next();
        } else if !a.starts_with('-') {
            return Some(a);
        }
    }
    None
}

/// Whether benchmark `id` passes the filter (substring match, criterion's rule).
pub fn selected(id: &str) -> bool {
    filter().is_none_or(|f| id.contains(&f))
}

/// "w ms wall / c ms cpu".
pub fn both(t: Timing) -> String {
    format!("{:.3} ms wall / {:.3} ms cpu", t.wall, t.cpu)
}
