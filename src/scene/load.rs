//! Reading and writing scene text: RON parsing, bounded file reads, point files resolved.

use super::{Location, Scene, SceneError};

/// The deepest nesting RON reads (its default recursion limit): deeper text is refused with
/// one line at the place it goes too deep.
pub const RON_NESTING: usize = 128;

/// The largest scene file read (inline points included): 256 MiB.
pub const MAX_SCENE_BYTES: u64 = 256 << 20;

/// Why [`read_text_limited`] failed.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum ReadTextError {
    /// Reading failed (the environment's fault).
    Io(String),
    /// The bytes are not a text file of the allowed size (the input's fault).
    NotText(String),
}

/// Reads UTF-8 text of at most `max` bytes from `reader`, block by block: the first block
/// holding a NUL byte or bytes that are not UTF-8 ends the read with the byte offset.
pub(crate) fn read_text_limited(
    mut reader: impl std::io::Read,
    max: u64,
) -> Result<String, ReadTextError> {
    use ReadTextError::{Io, NotText};
    let mut bytes: Vec<u8> = Vec::new();
    let mut block = vec![0u8; 64 * 1024];
    // Bytes before `checked` are known to be UTF-8 (a character may span two blocks).
    let mut checked = 0usize;
    loop {
        let n = match reader.read(&mut block) {
            Ok(0) => break,
            Ok(n) => n,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(Io(e.to_string())),
        };
        if bytes.len() as u64 + n as u64 > max {
            return Err(NotText(format!(
                "larger than {max} bytes: scene files are read up to that size"
            )));
        }
        if let Some(i) = block[..n].iter().position(|&b| b == 0) {
            return Err(NotText(format!(
                "byte {} is a NUL byte: not a scene file (RON text)",
                bytes.len() + i
            )));
        }
        bytes.extend_from_slice(&block[..n]);
        match std::str::from_utf8(&bytes[checked..]) {
            Ok(_) => checked = bytes.len(),
            Err(e) if e.error_len().is_none() => checked += e.valid_up_to(),
            Err(e) => {
                return Err(NotText(format!(
                    "byte {} is not UTF-8 text: not a scene file (RON text)",
                    checked + e.valid_up_to()
                )))
            }
        }
    }
    String::from_utf8(bytes).map_err(|e| {
        NotText(format!(
            "byte {} is not UTF-8 text: the file ends inside a character",
            e.utf8_error().valid_up_to()
        ))
    })
}

impl Scene {
    /// Parses and validates a scene from RON text; `source_name` appears in errors. Point
    /// files named by columns are read relative to the current directory.
    pub fn from_ron(text: &str, source_name: &str) -> Result<Scene, SceneError> {
        Scene::from_ron_in(text, source_name, None)
    }

    /// As [`Scene::from_ron`], reading the columns' point files relative to `base_dir`.
    pub fn from_ron_in(
        text: &str,
        source_name: &str,
        base_dir: Option<&std::path::Path>,
    ) -> Result<Scene, SceneError> {
        // A byte-order mark (as some Windows editors write) is not part of the text.
        let text = text.strip_prefix('\u{feff}').unwrap_or(text);
        let mut scene: Scene = ron::from_str(text).map_err(|e| SceneError::Parse {
            source_name: source_name.to_string(),
            line: e.span.start.line,
            column: e.span.start.col,
            message: match e.code {
                ron::Error::ExceededRecursionLimit => format!(
                    "nested more than {RON_NESTING} levels deep: a scene nests a few levels \
                     (scene, columns, pattern); look for brackets that are never closed"
                ),
                // RON writes names with dashes as raw identifiers (`r#n-rooks`); show them as
                // they are written in a scene.
                code => code.to_string().replace("`r#", "`"),
            },
        })?;
        for (ci, col) in scene.columns.iter().enumerate() {
            if let Some(imp) = col.points.as_ref().filter(|p| !p.path.is_empty()) {
                if !imp.points.is_empty() {
                    let err = SceneError::Invalid {
                        source_name: source_name.to_string(),
                        location: Location::default(),
                        field: format!("columns[{ci}].points"),
                        value: format!(
                            "path {:?} and {} inline points",
                            imp.path,
                            imp.points.len()
                        ),
                        allowed:
                            "either a `path` (read when the scene loads) or inline `points` (with \
                                  `source` naming where they came from), not both"
                                .into(),
                    };
                    return Err(err.located_in(text));
                }
            }
        }
        scene.resolve_points(source_name, base_dir)?;
        scene
            .validate(source_name)
            .map_err(|e| e.located_in(text))?;
        Ok(scene)
    }

    /// Reads every column's point file that is not loaded yet (see [`ImportedPoints::resolve`]).
    pub fn resolve_points(
        &mut self,
        source_name: &str,
        base_dir: Option<&std::path::Path>,
    ) -> Result<(), SceneError> {
        for (ci, col) in self.columns.iter_mut().enumerate() {
            if let Some(imp) = &mut col.points {
                imp.resolve(base_dir).map_err(|error| SceneError::Points {
                    source_name: source_name.to_string(),
                    column: ci,
                    path: imp.path.clone(),
                    error,
                })?;
            }
        }
        Ok(())
    }

    /// Reads a scene file: at most [`MAX_SCENE_BYTES`], UTF-8 text without NUL bytes, checked
    /// as it is read, so a binary or endless file (`/dev/zero`, `/dev/urandom`) is refused
    /// after its first block.
    pub fn load(path: &std::path::Path) -> Result<Scene, SceneError> {
        let io = |message: String| SceneError::Io {
            path: path.display().to_string(),
            message,
        };
        let bad = |message: String| SceneError::File {
            path: path.display().to_string(),
            message,
        };
        let file = std::fs::File::open(path).map_err(|e| {
            use std::io::ErrorKind as K;
            match e.kind() {
                K::NotFound | K::NotADirectory | K::IsADirectory | K::InvalidFilename => {
                    bad(e.to_string())
                }
                _ => io(e.to_string()),
            }
        })?;
        if file.metadata().is_ok_and(|m| m.is_dir()) {
            return Err(bad("is a directory, not a scene file".into()));
        }
        let text = read_text_limited(file, MAX_SCENE_BYTES).map_err(|e| match e {
            ReadTextError::Io(m) => io(m),
            ReadTextError::NotText(m) => bad(m),
        })?;
        Scene::from_ron_in(&text, &path.display().to_string(), path.parent())
    }

    /// The scene as RON text.
    /// Imported points are written inline (with their file as `source`), so the saved scene
    /// does not depend on the point file and loads as it was.
    pub fn to_ron(&self) -> String {
        let mut scene = self.clone();
        for col in &mut scene.columns {
            if let Some(imp) = &mut col.points {
                *imp = imp.inline();
            }
        }
        ron::ser::to_string_pretty(&scene, ron::ser::PrettyConfig::default()).unwrap_or_default()
    }
}
