//! The GUI's start (no subcommand): its arguments are checked before a window is asked for, so
//! a bad scene or point file is reported (status 2, or 1 when an existing file cannot be
//! read: the README's "Exit status") whether or not there is a display, and "no display" only
//! comes for arguments that would open. A build without the `gui` feature says so instead.

use super::CliError;
use std::path::PathBuf;

/// Opens the window on `scene` (or the default scene) with `points` (and `--normalize`) in
/// column 1, after checking them; `lecture`: in lecture mode with the controls hidden.
#[cfg(feature = "gui")]
pub fn run(
    scene: Option<PathBuf>,
    points: Option<PathBuf>,
    normalize: bool,
    lecture: bool,
) -> Result<(), CliError> {
    check_inputs(scene.as_deref(), points.as_deref(), normalize)?;
    samplescope::ui::run(samplescope::ui::Start {
        scene,
        points: points.map(|p| (p, normalize)),
        lecture,
    })
    .map_err(CliError::Gui)
}

/// Without the `gui` feature there is no window: one line, bad input (status 2).
#[cfg(not(feature = "gui"))]
pub fn run(
    scene: Option<PathBuf>,
    points: Option<PathBuf>,
    normalize: bool,
    lecture: bool,
) -> Result<(), CliError> {
    let _ = (scene, points, normalize, lecture);
    Err(CliError::Usage(
        "this build of samplescope has no GUI (built without the cargo feature `gui`): give a \
         subcommand (see --help)"
            .into(),
    ))
}

/// Loads and validates `--scene` and `--points` as the window would.
#[cfg(feature = "gui")]
fn check_inputs(
    scene: Option<&std::path::Path>,
    points: Option<&std::path::Path>,
    normalize: bool,
) -> Result<(), CliError> {
    use samplescope::core::pointset::{read_points, OutOfRange, PointsFileError};
    use samplescope::scene::{Scene, MAX_SCENE_N};
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
