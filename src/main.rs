//! The `samplescope` command line.

use samplescope::cli;

use clap::{Parser, Subcommand};
use std::process::ExitCode;

/// samplescope: an explorer of signals and sampling for image synthesis.
#[derive(Parser, Debug)]
#[command(name = "samplescope", version, about, long_about = None)]
struct Cli {
    /// Scene file (RON) to open in the GUI (default: the built-in default scene).
    #[arg(long, global = false)]
    scene: Option<std::path::PathBuf>,
    /// Point file (CSV or `x y` text with an optional header or count line, pmj-cpp's
    /// `(x, y),` rows, NumPy .npy, PSA .rps) shown in column 1 instead of its pattern.
    #[arg(long, global = false)]
    points: Option<std::path::PathBuf>,
    /// With --points: map the points' bounding box onto [0,1)² (aspect kept) instead of
    /// rejecting points outside.
    #[arg(long, global = false, requires = "points")]
    normalize: bool,
    /// Start the GUI in lecture mode (light theme, large text, pictures filling the window)
    /// with the controls hidden (F9 shows them), full screen where the window system allows.
    #[arg(long, global = false)]
    lecture: bool,
    #[command(flatten)]
    budget: cli::session::BudgetArgs,
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Generate a sample pattern and write it as CSV (`x,y`).
    Points(cli::points::PointsArgs),
    /// Quality metrics and frequency response of a reconstruction filter.
    Filter(cli::filter::FilterArgs),
    /// Statistics, discrepancies, t-value and spectrum of a pattern or a point file.
    Analyze(cli::analyze::AnalyzeArgs),
    /// Sample a test signal with a pattern, reconstruct it, and report RMSE, PSNR and time.
    Recon(cli::recon::ReconArgs),
    /// Write every figure of a scene (PNG, SVG, CSV, composites) with no window and no GPU.
    Render(cli::render::RenderArgs),
    /// Integration error of a pattern on an integrand with a known integral as N grows: MSE
    /// per N over realizations and its log-log slope.
    Converge(cli::converge::ConvergeArgs),
}

/// glibc's malloc, with one-shot commands' large buffers on huge pages (`engine::allocator`).
#[global_allocator]
static ALLOCATOR: samplescope::engine::allocator::Allocator =
    samplescope::engine::allocator::Allocator;

fn main() -> ExitCode {
    // One-shot commands: peaks that match the budget's estimates (`engine::allocator`).
    samplescope::engine::allocator::release_large_buffers();
    let cli = match Cli::try_parse() {
        Ok(c) => c,
        Err(e) if e.use_stderr() => {
            let _ = e.print();
            return ExitCode::from(2);
        }
        // --help and --version: their text is the output, so a failed write is a failure
        // (`--help > /dev/full`), as for every other output; a closed pipe ends quietly.
        Err(e) => {
            use std::io::Write as _;
            let written = e.print().and_then(|()| std::io::stdout().flush());
            return match written.map_err(cli::CliError::Output) {
                Err(e) if !e.is_broken_pipe() => {
                    eprintln!("error: {e}");
                    ExitCode::from(e.exit_code())
                }
                _ => ExitCode::SUCCESS,
            };
        }
    };
    // --scene, --points and --lecture open the GUI: with a subcommand they would have no effect.
    if let (Some(_), Some(flag)) = (
        &cli.command,
        [
            (cli.scene.is_some(), "--scene"),
            (cli.points.is_some(), "--points"),
            (cli.lecture, "--lecture"),
        ]
        .into_iter()
        .find_map(|(given, flag)| given.then_some(flag)),
    ) {
        eprintln!(
            "error: {flag} is an option of the GUI (no subcommand), so with a subcommand it \
             would have no effect (give `render SCENE.ron` or `analyze --points FILE` instead)"
        );
        return ExitCode::from(2);
    }
    if cli.command.is_none() {
        // The GUI: a slider change reuses the pages the last one freed (`engine::allocator`).
        samplescope::engine::allocator::keep_freed_buffers();
    }
    let session = cli::session::Session::new(&cli.budget);
    if cli.command.is_some() {
        session.stop_on_ctrl_c();
    }
    let result = match cli.command {
        Some(Command::Points(args)) => cli::points::run(&args, &session),
        Some(Command::Filter(args)) => cli::filter::run(&args, &session),
        Some(Command::Analyze(args)) => cli::analyze::run(&args, &session),
        Some(Command::Recon(args)) => cli::recon::run(&args, &session),
        Some(Command::Render(args)) => cli::render::run(&args, &session),
        Some(Command::Converge(args)) => cli::converge::run(&args, &session),
        None => cli::gui::run(cli.scene, cli.points, cli.normalize, cli.lecture),
    };
    // Results are line-buffered: a failure of the last flush is a failed write too.
    let result = result.and_then(|()| {
        use std::io::Write as _;
        std::io::stdout().flush().map_err(cli::CliError::Output)
    });
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) if e.is_broken_pipe() => ExitCode::SUCCESS,
        // Whatever error a computation stopped by a signal returned, it was the interruption:
        // 130 after SIGINT, 143 after SIGTERM.
        Err(_) if session.cancel.is_cancelled() => {
            eprintln!("interrupted");
            ExitCode::from(cli::session::interrupted_status())
        }
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(e.exit_code())
        }
    }
}
