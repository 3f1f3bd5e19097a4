//! Why a scene could not be loaded ([`SceneError`]) and where in its text ([`Location`]).

use super::ron_path;

/// Why a scene could not be loaded.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SceneError {
    /// The RON text is malformed or names an unknown field; `line`/`column` are 1-based.
    #[error("{source_name}:{line}:{column}: {message}")]
    Parse {
        source_name: String,
        line: usize,
        column: usize,
        message: String,
    },
    /// The scene parsed but a value is out of range; `location` is where the field (or the
    /// innermost part of its path that is written) stands in the text, when known.
    #[error("{source_name}{location}: {field} = {value}: must be {allowed}")]
    Invalid {
        source_name: String,
        location: Location,
        field: String,
        value: String,
        allowed: String,
    },
    /// The file is not there (or is a directory), or is not a scene's text: not UTF-8, a
    /// NUL byte, too large. Bad input, as a malformed scene is.
    #[error("{path}: {message}")]
    File { path: String, message: String },
    /// An existing file could not be read (permissions, a device error): the environment.
    #[error("{path}: {message}")]
    Io { path: String, message: String },
    /// A column's point file could not be read or holds a bad point (the error names the line).
    #[error("{source_name}: columns[{column}].points: {path}: {error}")]
    Points {
        source_name: String,
        column: usize,
        path: String,
        error: crate::core::pointset::PointsFileError,
    },
}

/// A 1-based line and column in a scene's text (displayed as `:line:column`, or nothing when
/// unknown, e.g. for a scene built in code).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Location(pub Option<(usize, usize)>);

impl std::fmt::Display for Location {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.0 {
            Some((line, column)) => write!(f, ":{line}:{column}"),
            None => Ok(()),
        }
    }
}

impl SceneError {
    /// Whether the environment is at fault (exit status 1: an existing file could not be
    /// read), rather than the input (status 2: a file that is not there, not text, malformed
    /// or out of range). A column's point file follows the same rule.
    pub fn is_environment(&self) -> bool {
        match self {
            SceneError::Io { .. } => true,
            SceneError::Points {
                error: crate::core::pointset::PointsFileError::Io { path, .. },
                ..
            } => std::fs::metadata(path).is_ok_and(|m| m.is_file()),
            _ => false,
        }
    }

    /// The error with the location of its field in `text` (for [`SceneError::Invalid`]).
    pub fn located_in(mut self, text: &str) -> Self {
        if let SceneError::Invalid {
            location, field, ..
        } = &mut self
        {
            *location = Location(ron_path::locate(text, field));
        }
        self
    }
}
