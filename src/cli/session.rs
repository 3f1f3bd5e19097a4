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
//! - **Signals.** SIGINT (Ctrl-C) and SIGTERM (what `timeout`, systemd and job schedulers send)
//!   set the flag of the session's [`Cancel`] token, which every hot loop of the core checks;
//!   the command then stops, the file being written (if any) is removed, and the program exits
//!   with status 130 after SIGINT, 143 after SIGTERM (128 + the first signal's number). What
//!   cannot look at the flag — a read blocked on a FIFO that never writes, a figure being
//!   drawn — is ended by a watchdog thread: [`GRACE`] after the first signal, or at once on a
//!   second one, it removes every partial file being written and exits with the same status.
//! - **Files** go through [`samplescope::core::output`]: a hidden `.NAME.partial` beside the
//!   target renamed into place ([`write_output`]), links followed, streams written through;
//!   every output of a command is checked before any work ([`check_outputs`]).

use super::CliError;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use samplescope::core::budget::{self, Budget, Estimate};
use samplescope::core::cancel::Cancel;
use samplescope::core::output::{self, OutputError};
use std::path::Path;
use std::sync::atomic::{AtomicBool, AtomicI32, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// Commands estimated to take longer than this show a progress bar (on a terminal).
pub const PROGRESS_SECONDS: f64 = 2.0;

/// How long after the first SIGINT or SIGTERM the command may take to stop by itself before
/// the watchdog ends the process.
pub const GRACE: Duration = Duration::from_millis(1000);

/// Signals received (SIGINT, SIGTERM), and the first one's number (0 before any).
static SIGNALS: AtomicUsize = AtomicUsize::new(0);
static FIRST_SIGNAL: AtomicI32 = AtomicI32::new(0);

/// The exit status after an interruption: 128 + the first signal's number (130 for SIGINT,
/// 143 for SIGTERM); 130 when the command was cancelled otherwise.
pub fn interrupted_status() -> u8 {
    match FIRST_SIGNAL.load(Ordering::SeqCst) {
        s @ 1..=127 => 128 + s as u8,
        _ => 130,
    }
}

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

    /// From now on SIGINT (Ctrl-C) and SIGTERM trip the session's token, and a watchdog ends
    /// the process [`GRACE`] after the first one (at once after a second) if the command has
    /// not stopped by then. (Only subcommands call this: the GUI keeps the default handlers.)
    pub fn stop_on_ctrl_c(&self) {
        for signal in [signal_hook::consts::SIGINT, signal_hook::consts::SIGTERM] {
            let flag = self.flag.clone();
            let handler = move || {
                // Atomic stores only: all a signal handler may do.
                let _ =
                    FIRST_SIGNAL.compare_exchange(0, signal, Ordering::SeqCst, Ordering::SeqCst);
                SIGNALS.fetch_add(1, Ordering::SeqCst);
                flag.store(true, Ordering::SeqCst);
            };
            // SAFETY: the handler only performs atomic operations, which are async-signal-safe.
            // Failing to install it only loses the clean stop: the default handler still ends
            // the process.
            let _ = unsafe { signal_hook::low_level::register(signal, handler) };
        }
        let _ = std::thread::Builder::new()
            .name("signal watchdog".into())
            .spawn(|| {
                let mut first: Option<Instant> = None;
                loop {
                    std::thread::sleep(Duration::from_millis(20));
                    let n = SIGNALS.load(Ordering::SeqCst);
                    if n == 0 {
                        continue;
                    }
                    let since = *first.get_or_insert_with(Instant::now);
                    if n >= 2 || since.elapsed() >= GRACE {
                        output::abandon(i32::from(interrupted_status()));
                    }
                }
            });
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
    /// Of stages that run together ([`Progress::concurrent`]): the estimated milliseconds of
    /// those that have finished.
    finished: f64,
}

impl Position {
    fn within(&self) -> f64 {
        match self.done {
            Some(f) => f * self.stage,
            None => (self.started.elapsed().as_secs_f64() * 1e3)
                .max(self.finished)
                .min(self.stage),
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
            finished: 0.0,
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
                finished: 0.0,
            };
        }
        if let (Some(bar), Some(e)) = (&self.bar, self.plan.get(i)) {
            bar.set_position(before as u64);
            bar.set_message(e.operation.clone());
        }
    }

    /// The stages `stages` of the plan start together (the nodes the engine evaluates at the
    /// same time; the stages before them are done): the bar advances with the elapsed time
    /// over their summed estimates, and at least by the estimates of those reported
    /// [`Progress::finished`].
    pub fn concurrent(&self, stages: std::ops::Range<usize>) {
        let ms = |e: &Estimate| e.seconds * 1e3;
        let before: f64 = self.plan.iter().take(stages.start).map(ms).sum();
        let span = self.plan.get(stages.clone()).unwrap_or_default();
        if let Ok(mut p) = self.position.lock() {
            *p = Position {
                before,
                stage: span.iter().map(ms).sum(),
                started: Instant::now(),
                done: None,
                finished: 0.0,
            };
        }
        if let Some(bar) = &self.bar {
            bar.set_position(before as u64);
            // Named by the longest of them.
            let longest = span.iter().max_by(|a, b| a.seconds.total_cmp(&b.seconds));
            bar.set_message(match (longest, span.len()) {
                (None, _) => String::new(),
                (Some(one), 1) => one.operation.clone(),
                (Some(one), k) => format!("{} and {} more at once", one.operation, k - 1),
            });
        }
    }

    /// One of the stages that run together finished; `seconds` is its estimate.
    pub fn finished(&self, seconds: f64) {
        if let Ok(mut p) = self.position.lock() {
            p.finished += seconds * 1e3;
        }
    }
}

impl Progress {
    /// The current stage's routine reports its steps (an optimiser's iterations): the bar
    /// follows them instead of the estimated time.
    pub fn follow<T: ?Sized>(&self, report: samplescope::core::progress::Progress<'_, T>) {
        if report.total == 0 {
            return;
        }
        if let Ok(mut p) = self.position.lock() {
            p.done = Some(report.fraction());
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

/// Writes `bytes` to `path` whole or not at all ([`output::write_atomic`]: through a partial
/// file renamed when complete and not cancelled, links followed, streams and `-` written
/// through).
pub fn write_output(path: &Path, bytes: &[u8], cancel: &Cancel) -> Result<(), CliError> {
    output::write_atomic(path, bytes, cancel).map_err(CliError::from)
}

/// Checks every output a command was given (`(flag, path)`, unset ones skipped) before any
/// work: exit 1 if one cannot be written (a missing or unwritable directory, a directory, a
/// dangling link), 2 if two name the same file.
pub fn check_outputs(outputs: &[(&str, Option<&str>)]) -> Result<(), CliError> {
    let given: Vec<(&str, &Path)> = outputs
        .iter()
        .filter_map(|(flag, p)| p.map(|p| (*flag, Path::new(p))))
        .collect();
    output::check_outputs(&given).map_err(CliError::from)
}

impl From<OutputError> for CliError {
    fn from(e: OutputError) -> Self {
        match e {
            OutputError::Cancelled => CliError::Cancelled,
            OutputError::Io { path, source } => CliError::Io { path, source },
            e if e.is_conflict() => CliError::Usage(e.to_string()),
            e => CliError::Environment(e.to_string()),
        }
    }
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
            finished: 0.0,
        };
        // Without steps the elapsed time is used, at most the stage's estimate.
        assert_eq!(p.within(), 1000.0);
        p.done = Some(0.25);
        assert_eq!(p.within(), 250.0);
    }

    #[test]
    fn stages_that_run_together_advance_by_time_and_by_the_ones_finished() {
        let mut p = Position {
            before: 0.0,
            stage: 1000.0,
            started: Instant::now(),
            done: None,
            finished: 0.0,
        };
        assert!(p.within() < 100.0);
        // A finished stage moves the bar by its estimate even before that much time passed.
        p.finished = 600.0;
        assert_eq!(p.within(), 600.0);
        // Never past the span, however many report.
        p.finished = 1500.0;
        assert_eq!(p.within(), 1000.0);
        p.started = Instant::now() - Duration::from_secs(10);
        p.finished = 0.0;
        assert_eq!(p.within(), 1000.0);
    }
}
