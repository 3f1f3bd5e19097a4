//! `render(scene, out_dir, …)`: every figure of a scene written into a directory, as
//! `samplescope render` writes them (`cli::render::render`: through `core::output`, so an
//! interrupted call leaves no file half-written).

use super::run;
use crate::cli::render::{render as render_scene, Format, RenderArgs};
use crate::export::figure::Aspect;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use std::path::PathBuf;

/// Writes every figure of a scene into ``out_dir`` (created if missing): the list of files
/// written, in order.
///
/// ``scene`` is the path of a scene file (RON, str or os.PathLike) or the RON text of a scene
/// (its figures named ``scene_…``). ``formats``: any of ``"png"``, ``"svg"``, ``"pdf"``,
/// ``"csv"`` (default png, svg, csv); ``scale`` 1..=4; ``aspect`` ``"W:H"`` (the composites'
/// frame, default 16:9); ``no_cache`` computes reference images even if the disk cache has
/// them. These are ``samplescope render``'s ``--format``, ``--scale``, ``--aspect`` and
/// ``--no-cache``, checked the same way; the same scene gives byte-identical files. Releases
/// the GIL; Ctrl-C raises KeyboardInterrupt and leaves no partial file.
#[pyfunction]
#[pyo3(signature = (scene, out_dir, formats = None, *, scale = None, aspect = None, no_cache = false, budget = None, budget_memory = None))]
#[allow(clippy::too_many_arguments)]
fn render(
    py: Python<'_>,
    scene: &Bound<'_, PyAny>,
    out_dir: PathBuf,
    formats: Option<Vec<String>>,
    scale: Option<u32>,
    aspect: Option<&str>,
    no_cache: bool,
    budget: Option<f64>,
    budget_memory: Option<f64>,
) -> PyResult<Vec<PathBuf>> {
    // A path (str or os.PathLike) of an existing file, else RON text.
    let (path, text) = match scene.extract::<PathBuf>() {
        Ok(p) if p.is_file() => (p, None),
        Ok(p) => {
            let s = p.to_string_lossy().into_owned();
            if !s.contains('(') {
                return Err(PyValueError::new_err(format!(
                    "scene = {s}: no such file (give the path of a scene file or a scene's RON text)"
                )));
            }
            (PathBuf::from("scene.ron"), Some(s))
        }
        Err(_) => {
            return Err(PyValueError::new_err(
                "scene: expected the path of a scene file or a scene's RON text",
            ))
        }
    };
    let format = match formats {
        None => vec![Format::Png, Format::Svg, Format::Csv],
        Some(list) => list
            .iter()
            .map(|f| match f.as_str() {
                "png" => Ok(Format::Png),
                "svg" => Ok(Format::Svg),
                "pdf" => Ok(Format::Pdf),
                "csv" => Ok(Format::Csv),
                other => Err(PyValueError::new_err(format!(
                    "formats: {other}: must be png, svg, pdf or csv"
                ))),
            })
            .collect::<PyResult<Vec<_>>>()?,
    };
    if format.is_empty() {
        return Err(PyValueError::new_err(
            "formats: empty: give at least one of png, svg, pdf, csv",
        ));
    }
    let aspect = match aspect {
        Some(a) => Some(
            a.parse::<Aspect>()
                .map_err(|e| PyValueError::new_err(format!("aspect = {a}: {e}")))?,
        ),
        None => None,
    };
    let args = RenderArgs {
        scene: path,
        out: out_dir,
        scale,
        format,
        aspect,
        no_cache,
        frames: None,
        fps: None,
    };
    let session = run::session(budget, budget_memory)?;
    run::run(py, session, move |session| {
        let mut written = Vec::new();
        render_scene(&args, text.as_deref(), session, &mut |p| {
            written.push(p.to_path_buf());
            Ok(())
        })?;
        Ok(written)
    })
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(render, m)?)
}
