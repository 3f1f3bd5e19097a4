//! What every subcommand shares: the cost budget checked before any work, the progress bar
//! of long commands, Ctrl-C, and output files that never appear half-written.
//!
//! - **Budget.** A command lists the estimates of everything it will compute
//!   ([`samplescope::core::budget`]) and calls [`Session::admit`] before starting: beyond the
//!   budget (`--budget SECONDS`, `--budget-memory GIB`; defaults 60 s and 4 GiB) it is refused
//!   at once with status 2, naming the operation, its estimate and the limit. `--estimate`
//!   prints the estimates and exits without computing.
//! - **Progress.** When the estimate is over [`PROGRESS_SECONDS`] a bar with the stage and
//!   the ETA is drawn on standard error if it is a terminal (never into pipes or files). The
//!   bar advances with the elapsed time within a stage, capped at the stage's estimate, and
//!   jumps to the true position when the next stage starts.
//! - **Ctrl-C** (and SIGTERM) sets the flag of the session's [`Cancel`] token, which every hot
//!   loop of the core checks; the command then stops, the file being written (if any) is
//!   removed, and the program exits with status 130. A second Ctrl-C ends it at once.
//! - **Files** are written to a hidden `.NAME.partial` beside the target and renamed into
//!   place ([`write_output`]), so an interrupted or failed write leaves no partial file.

use super::CliError;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use samplescope::core::budget::{self, Budget, Estimate};
use samplescope::core::cancel::Cancel;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// Commands estimated to take longer than this show a progress bar (on a terminal).
pub const PROGRESS_SECONDS: f64 = 2.0;

/// The budget flags, global to every subcommand.
#[derive(clap::Args, Debug, Clone)]
pub struct BudgetArgs {
    /// Refuse work estimated to take longer than this many seconds (on the reference 2-core
    /// machine; default 60).
    #[arg(long, global = true, value_name = "SECONDS", value_parser = positive)]
    pub budget: Option<f64>,
    /// Refuse work estimated to need more than this many GiB of memory (default 4).
    #[arg(long = "budget-memory", global = true, value_name = "GIB", value_parser = positive)]
    pub budget_memory: Option<f64>,
    /// Print the estimated work, time and memory of every stage, then exit without computing.
    #[arg(long, global = true)]
    pub estimate: bool,
}

fn positive(text: &str) -> Result<f64, String> {
    text.trim()
        .parse::<f64>()
        .ok()
        .filter(|v| v.is_finite() && *v > 0.0)
        .ok_or_else(|| format!("{text}: must be a positive number"))
}

/// The budget, the cancellation token and the progress display of one command.
pub struct Session {
    /// The limits work is checked against.
    pub budget: Budget,
    /// Cancelled by Ctrl-C; every computation of the command takes it.
    pub cancel: Cancel,
    /// The flag under `cancel`, which the signal handlers set.
    flag: Arc<AtomicBool>,
    estimate_only: bool,
    /// The first budget flag given on the command line, if any (refused where no work is
    /// estimated: `--list`).
    budget_flag: Option<&'static str>,
}

impl Session {
    /// A session with the limits of `args` and a fresh token (see [`Session::stop_on_ctrl_c`]).
    pub fn new(args: &BudgetArgs) -> Self {
        let flag = Arc::new(AtomicBool::new(false));
        let defaults = Budget::default();
        Session {
            budget: Budget {
                seconds: args.budget.unwrap_or(defaults.seconds),
                bytes: args
                    .budget_memory
                    .map_or(defaults.bytes, |g| g * (1u64 << 30) as f64),
            },
            flag: flag.clone(),
            cancel: Cancel::from_flag(flag),
            estimate_only: args.estimate,
            budget_flag: if args.estimate {
                Some("--estimate")
            } else if args.budget.is_some() {
                Some("--budget")
            } else if args.budget_memory.is_some() {
                Some("--budget-memory")
            } else {
                None
            },
        }
    }

    /// Refuses `--estimate`, `--budget` and `--budget-memory` for `what` (e.g. `--list`), which
    /// computes nothing: they would have no effect.
    pub fn refuse_budget_flags(&self, what: &str) -> Result<(), CliError> {
        match self.budget_flag {
            Some(flag) => Err(CliError::Usage(format!(
                "{flag} cannot be used with {what}: {what} computes nothing, so {flag} would have \
                 no effect"
            ))),
            None => Ok(()),
        }
    }

    /// From now on Ctrl-C and SIGTERM trip the session's token; a second one ends the process
    /// with status 130. (Only subcommands call this: the GUI keeps the default handlers.)
    pub fn stop_on_ctrl_c(&self) {
        for signal in [signal_hook::consts::SIGINT, signal_hook::consts::SIGTERM] {
            // Failing to install a handler only loses the clean stop: the default handler
            // still ends the process.
            let _ =
                signal_hook::flag::register_conditional_shutdown(signal, 130, self.flag.clone());
            let _ = signal_hook::flag::register(signal, self.flag.clone());
        }
    }

    /// Checks `plan` against the budget before any work. `Ok(Some(progress))`: go ahead,
    /// announcing each stage to `progress`; `Ok(None)`: `--estimate` printed the plan, stop;
    /// over the budget: [`CliError::Budget`].
    pub fn admit(&self, plan: Vec<Estimate>) -> Result<Option<Progress>, CliError> {
        if self.estimate_only {
            super::out!("{}", estimate_text(&plan))?;
            return Ok(None);
        }
        self.budget.check(&plan).map_err(|e| {
            let flag = match e {
                budget::OverBudget::Time { .. } => "--budget SECONDS",
                budget::OverBudget::Memory { .. } => "--budget-memory GIB",
            };
            CliError::Budget(format!("{e} (raise it with {flag})"))
        })?;
        Ok(Some(Progress::new(plan)))
    }
}

/// The `--estimate` table: one line per stage and the total.
pub fn estimate_text(plan: &[Estimate]) -> String {
    let mut s = String::new();
    for e in plan {
        s.push_str(&format!("{e}\n"));
    }
    s.push_str(&format!(
        "total: about {} here, {} at most\n",
        budget::format_seconds(budget::total_seconds(plan)),
        budget::format_bytes(budget::peak_bytes(plan))
    ));
    s
}

/// Where the bar stands: the estimated milliseconds before the current stage and in it, and
/// the share of the stage done when the stage reports it (else the elapsed time is used).
struct Position {
    before: f64,
    stage: f64,
    started: Instant,
    done: Option<f64>,
}

impl Position {
    fn within(&self) -> f64 {
        match self.done {
            Some(f) => f * self.stage,
            None => (self.started.elapsed().as_secs_f64() * 1e3).min(self.stage),
        }
    }
}

/// The progress bar of a command (hidden for short commands and when stderr is not a
/// terminal). Dropping it clears the bar.
pub struct Progress {
    plan: Vec<Estimate>,
    bar: Option<ProgressBar>,
    position: Arc<Mutex<Position>>,
    stop: Arc<AtomicBool>,
    ticker: Option<std::thread::JoinHandle<()>>,
}

impl Progress {
    fn new(plan: Vec<Estimate>) -> Self {
        let total = budget::total_seconds(&plan);
        let position = Arc::new(Mutex::new(Position {
            before: 0.0,
            stage: 0.0,
            started: Instant::now(),
            done: None,
        }));
        let stop = Arc::new(AtomicBool::new(false));
        let target = ProgressDrawTarget::stderr();
        let bar = (total > PROGRESS_SECONDS && !target.is_hidden()).then(|| {
            let bar = ProgressBar::with_draw_target(Some((total * 1e3) as u64), target);
            if let Ok(style) = ProgressStyle::with_template(
                "{spinner} [{elapsed_precise}] {wide_bar} {percent:>3}% ETA {eta:>4} {msg}",
            ) {
                bar.set_style(style);
            }
            bar
        });
        let ticker = bar.clone().map(|bar| {
            let (position, stop) = (position.clone(), stop.clone());
            std::thread::spawn(move || {
                while !stop.load(Ordering::Relaxed) {
                    if let Ok(p) = position.lock() {
                        bar.set_position((p.before + p.within()) as u64);
                    }
                    std::thread::sleep(Duration::from_millis(100));
                }
            })
        });
        Progress {
            plan,
            bar,
            position,
            stop,
            ticker,
        }
    }

    /// Stage `i` of the plan starts (the stages before it are done).
    pub fn stage(&self, i: usize) {
        let before: f64 = self.plan.iter().take(i).map(|e| e.seconds * 1e3).sum();
        let stage = self.plan.get(i).map_or(0.0, |e| e.seconds * 1e3);
        if let Ok(mut p) = self.position.lock() {
            *p = Position {
                before,
                stage,
                started: Instant::now(),
                done: None,
            };
        }
        if let (Some(bar), Some(e)) = (&self.bar, self.plan.get(i)) {
            bar.set_position(before as u64);
            bar.set_message(e.operation.clone());
        }
    }
}

impl Progress {
    /// The current stage reports that `done` of `of` of its steps are done (an optimiser's
    /// iterations): the bar follows them instead of the estimated time.
    pub fn steps_done(&self, done: usize, of: usize) {
        if of == 0 {
            return;
        }
        if let Ok(mut p) = self.position.lock() {
            p.done = Some((done as f64 / of as f64).min(1.0));
        }
    }
}

impl Drop for Progress {
    fn drop(&mut self) {
        self.stop.store(true, Ordering::Relaxed);
        if let Some(t) = self.ticker.take() {
            let _ = t.join();
        }
        if let Some(bar) = &self.bar {
            bar.finish_and_clear();
        }
    }
}

/// The hidden file beside `path` that [`write_output`] writes first.
pub fn partial_path(path: &Path) -> PathBuf {
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    path.with_file_name(format!(".{name}.partial"))
}

/// Writes `bytes` to `path` through [`partial_path`], renamed into place only when complete
/// and not cancelled; on any failure or cancellation the partial file is removed.
pub fn write_output(path: &Path, bytes: &[u8], cancel: &Cancel) -> Result<(), CliError> {
    if cancel.is_cancelled() {
        return Err(CliError::Cancelled);
    }
    let io = |source| CliError::Io {
        path: path.display().to_string(),
        source,
    };
    // A device or a pipe (`--out /dev/null`, `--out /dev/stdout`) is written as it is: it
    // holds no partial file, and renaming over it would replace it.
    if std::fs::metadata(path).is_ok_and(|m| !m.is_file() && !m.is_dir()) {
        return std::fs::write(path, bytes).map_err(io);
    }
    let partial = partial_path(path);
    if let Err(e) = std::fs::write(&partial, bytes) {
        let _ = std::fs::remove_file(&partial);
        return Err(io(e));
    }
    if cancel.is_cancelled() {
        let _ = std::fs::remove_file(&partial);
        return Err(CliError::Cancelled);
    }
    std::fs::rename(&partial, path).map_err(|e| {
        let _ = std::fs::remove_file(&partial);
        io(e)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_stage_that_reports_its_steps_moves_the_bar_by_them_not_by_the_clock() {
        let mut p = Position {
            before: 100.0,
            stage: 1000.0,
            started: Instant::now() - Duration::from_secs(10),
            done: None,
        };
        // Without steps the elapsed time is used, at most the stage's estimate.
        assert_eq!(p.within(), 1000.0);
        p.done = Some(0.25);
        assert_eq!(p.within(), 250.0);
    }
}
