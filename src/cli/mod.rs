//! Subcommands of the `samplescope` binary. Each returns a [`CliError`]: bad input exits with
//! status 2 and one line naming the field and what is allowed; I/O failures exit with 1.

pub mod analyze;
pub mod filter;
pub mod points;
pub mod recon;
pub mod render;

use samplescope::core::filter::FilterError;
use samplescope::core::pattern::{Pattern, PatternError};

/// An error of a subcommand.
#[derive(Debug, thiserror::Error)]
pub enum CliError {
    /// Bad input from the user (exit status 2).
    #[error("{0}")]
    Usage(String),
    /// A pattern could not be generated from the given parameters (exit status 2).
    #[error("{0}")]
    Pattern(#[from] PatternError),
    /// A filter could not be built or evaluated from the given parameters (exit status 2).
    #[error("{0}")]
    Filter(#[from] FilterError),
    /// The window could not be opened (exit status 1).
    #[error("cannot open the window: {0}")]
    Gui(String),
    /// Reading or writing a file failed (exit status 1).
    #[error("{path}: {source}")]
    Io {
        path: String,
        source: std::io::Error,
    },
}

impl CliError {
    /// The process exit status for this error.
    pub fn exit_code(&self) -> u8 {
        match self {
            CliError::Io { .. } | CliError::Gui(_) => 1,
            _ => 2,
        }
    }
}

/// Builds a pattern from its name and `key=value` settings.
pub fn pattern_from_args(name: &str, settings: &[String]) -> Result<Pattern, CliError> {
    let mut pattern = Pattern::from_name(name)?;
    for s in settings {
        let (k, v) = s.split_once('=').ok_or_else(|| {
            CliError::Usage(format!(
                "--set {s}: expected key=value (see `samplescope points --list`)"
            ))
        })?;
        pattern.set(k.trim(), v)?;
    }
    Ok(pattern)
}

/// Parses `-n`, accepting only a positive integer that fits in memory.
pub fn parse_n(text: &str) -> Result<usize, String> {
    let max = samplescope::core::pattern::MAX_N;
    text.trim()
        .parse::<usize>()
        .ok()
        .filter(|&n| (1..=max).contains(&n))
        .ok_or_else(|| format!("n = {text}: must be an integer in 1..={max}"))
}
