//! The GUI's arguments, checked before a window is asked for: a bad scene or point file is
//! reported (status 2, or 1 when an existing file cannot be read: the README's "Exit status")
//! whether or not there is a display, and "no display" only comes for arguments that would
//! open.

use super::CliError;
use samplescope::core::pointset::{read_points, OutOfRange, PointsFileError};
use samplescope::scene::{Scene, MAX_SCENE_N};
use std::path::Path;

/// Loads and validates `--scene` and `--points` as the window would.
pub fn check_inputs(
    scene: Option<&Path>,
    points: Option<&Path>,
    normalize: bool,
) -> Result<(), CliError> {
    if let Some(path) = scene {
        Scene::load(path).map_err(super::scene_error)?;
    }
    if let Some(path) = points {
        let shown = path.display().to_string();
        let file = super::open_input(path)?;
        let mode = if normalize {
            OutOfRange::NormalizeToBoundingBox
        } else {
            OutOfRange::Reject
        };
        let pts = read_points(std::io::BufReader::new(file), mode).map_err(|e| match e {
            PointsFileError::Io { message, .. } => CliError::Io {
                path: shown.clone(),
                source: std::io::Error::other(message),
            },
            e => CliError::Usage(format!("--points {shown}: {e}")),
        })?;
        if pts.len() > MAX_SCENE_N {
            return Err(CliError::Usage(format!(
                "--points {shown}: {} points; a column shows at most {MAX_SCENE_N}",
                pts.len()
            )));
        }
    }
    Ok(())
}
