//! Output files, written whole or not at all: the one writer every command, the GUI's figure
//! saver and the disk cache use.
//!
//! - **Regular files** are written to a hidden `.NAME.partial` beside the file and renamed
//!   onto it when complete ([`write_atomic`]); a failure or a cancellation removes the partial
//!   file, and so does a signal ([`abandon`] removes every partial file still registered).
//! - **Symbolic links are followed** to their target: the partial file is written beside the
//!   resolved target and renamed onto it, so the link stays a link (as `cp` writes through a
//!   link). A link whose target does not exist (a dangling link) is refused, as `cp` refuses
//!   it ("not writing through dangling symlink"): create the target or remove the link.
//! - **Anything that is not a regular file** is written straight through, with no partial file
//!   and no rename: a pipe or FIFO, a character device (`/dev/null`, a terminal), an open
//!   descriptor (`/dev/stdout`, `/dev/stderr`, `/dev/fd/N`, `/proc/self/fd/N`), and `-`,
//!   standard output. A descriptor that is a regular file (`> f.csv`) is appended to at its
//!   end, as the shell's own writes would be.
//! - [`check_outputs`] checks every output of a command before any work: its directory exists
//!   and can be written, it is not a directory, no link is dangling, and no two outputs are the
//!   same file (compared after following links, and by inode for hard links).

use crate::core::cancel::Cancel;
use std::fs::{self, File, OpenOptions};
use std::io::{self, BufWriter, Write};
use std::path::{Component, Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Mutex, MutexGuard};

/// Links followed at most before a path is refused (Linux's own limit).
pub const MAX_LINK_HOPS: usize = 40;

/// Why an output cannot be written.
#[derive(Debug, thiserror::Error)]
pub enum OutputError {
    /// Writing, creating or renaming failed; `path` is the output as given.
    #[error("{path}: {source}")]
    Io { path: String, source: io::Error },
    /// The output is a symbolic link whose target does not exist.
    #[error(
        "{path}: a symbolic link to {target}, which does not exist: not writing through a \
         dangling link (create the target or remove the link)"
    )]
    Dangling { path: String, target: String },
    /// The output is a directory.
    #[error("{path}: is a directory (expected a file name)")]
    Directory { path: String },
    /// Two outputs of one command are the same file (the second would replace the first).
    #[error("{first} and {second} name the same file ({path}): give each output its own file")]
    Same {
        first: String,
        second: String,
        path: String,
    },
    /// The command was cancelled before the output was complete.
    #[error("cancelled")]
    Cancelled,
}

impl OutputError {
    /// Whether this is a conflict between the command's own arguments (two outputs the same
    /// file), rather than the file system refusing a write.
    pub fn is_conflict(&self) -> bool {
        matches!(self, OutputError::Same { .. })
    }
}

/// Where an output path leads, links followed.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Target {
    /// Standard output: `-`, `/dev/stdout`, `/dev/fd/1`, `/proc/self/fd/1`.
    Stdout,
    /// Not a regular file (a pipe or FIFO, a device, an open descriptor): written as it is.
    Stream(PathBuf),
    /// A regular file at this path (existing or not), every link of the last component
    /// followed; written through a partial file beside it.
    File(PathBuf),
}

/// The descriptor number an fd path names (`/dev/stdout` → 1, `/dev/fd/3`, `/proc/self/fd/3`,
/// `/proc/thread-self/fd/3`, `/proc/<pid>/fd/3`), or `None` for any other path.
pub fn descriptor(path: &Path) -> Option<u32> {
    let parts: Vec<&str> = path
        .components()
        .filter_map(|c| match c {
            Component::Normal(s) => s.to_str(),
            _ => None,
        })
        .collect();
    if !path.is_absolute() {
        return None;
    }
    match parts.as_slice() {
        ["dev", "stdin"] => Some(0),
        ["dev", "stdout"] => Some(1),
        ["dev", "stderr"] => Some(2),
        ["dev", "fd", n] => n.parse().ok(),
        ["proc", pid, "fd", n]
            if *pid == "self"
                || *pid == "thread-self"
                || pid.parse::<u32>().is_ok_and(|p| p == std::process::id()) =>
        {
            n.parse().ok()
        }
        _ => None,
    }
}

/// Follows `path` to what it names: standard output, a stream, or a regular file (existing or
/// to be created). A dangling link and a directory are errors; a path that cannot be examined
/// (a permission error on its directory) is taken as a file, so the write reports the error.
pub fn resolve(path: &Path) -> Result<Target, OutputError> {
    let shown = || path.display().to_string();
    if path.as_os_str() == "-" {
        return Ok(Target::Stdout);
    }
    let mut cur = path.to_path_buf();
    let mut via_link = false;
    for _ in 0..=MAX_LINK_HOPS {
        if let Some(fd) = descriptor(&cur) {
            return Ok(if fd == 1 {
                Target::Stdout
            } else {
                Target::Stream(cur)
            });
        }
        let meta = match fs::symlink_metadata(&cur) {
            Ok(m) => m,
            Err(e) if e.kind() == io::ErrorKind::NotFound && via_link => {
                return Err(OutputError::Dangling {
                    path: shown(),
                    target: cur.display().to_string(),
                })
            }
            Err(_) => return Ok(Target::File(cur)),
        };
        let kind = meta.file_type();
        if kind.is_symlink() {
            let to = fs::read_link(&cur).map_err(|source| OutputError::Io {
                path: shown(),
                source,
            })?;
            cur = match cur.parent() {
                Some(dir) if to.is_relative() => dir.join(to),
                _ => to,
            };
            via_link = true;
            continue;
        }
        if kind.is_dir() {
            return Err(OutputError::Directory { path: shown() });
        }
        if kind.is_file() {
            return Ok(Target::File(cur));
        }
        return Ok(Target::Stream(cur));
    }
    Err(OutputError::Io {
        path: shown(),
        source: io::Error::other(format!("more than {MAX_LINK_HOPS} symbolic links in a row")),
    })
}

/// The hidden file beside `path` that [`write_atomic`] writes first.
pub fn partial_path(path: &Path) -> PathBuf {
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    path.with_file_name(format!(".{name}.partial"))
}

/// The partial files being written now, removed by [`abandon`].
static PARTIALS: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

fn partials() -> MutexGuard<'static, Vec<PathBuf>> {
    PARTIALS.lock().unwrap_or_else(|e| e.into_inner())
}

/// Ends the process with `status` after removing every partial file being written (for a
/// watchdog after a signal, when the command did not stop by itself). No output is renamed
/// into place after this is called.
pub fn abandon(status: i32) -> ! {
    let list = partials();
    for p in list.iter() {
        let _ = fs::remove_file(p);
    }
    // The lock stays held: a writer about to rename its partial file waits for the exit.
    let _ = io::stderr().write_all(b"interrupted\n");
    std::process::exit(status)
}

/// A file being written beside its target, renamed onto it by [`Partial::commit`] and removed
/// if dropped before (or by [`abandon`] on a signal).
pub struct Partial {
    temp: PathBuf,
    target: PathBuf,
    file: Option<BufWriter<File>>,
}

impl Partial {
    /// Creates `temp` (which must not exist) to be renamed onto `target` later.
    pub fn create_new(temp: PathBuf, target: PathBuf) -> io::Result<Partial> {
        Self::open(temp, target, true)
    }

    /// Creates a new file in `dir` named `{prefix}{pid}-{n}{suffix}`, a name no other thread
    /// or process writing there uses, to be renamed onto `target`: for a directory several
    /// processes write the same targets in (the disk cache), where the fixed
    /// [`partial_path`] beside the target could be another writer's.
    pub fn create_unique(
        dir: &Path,
        prefix: &str,
        suffix: &str,
        target: PathBuf,
    ) -> io::Result<Partial> {
        static NEXT: AtomicU64 = AtomicU64::new(0);
        let pid = std::process::id();
        let mut last = None;
        for _ in 0..64 {
            let n = NEXT.fetch_add(1, Ordering::Relaxed);
            let temp = dir.join(format!("{prefix}{pid}-{n}{suffix}"));
            match Self::create_new(temp, target.clone()) {
                Ok(p) => return Ok(p),
                Err(e) if e.kind() == io::ErrorKind::AlreadyExists => last = Some(e),
                Err(e) => return Err(e),
            }
        }
        Err(last.unwrap_or_else(|| io::Error::other("no free temporary file name")))
    }

    fn open(temp: PathBuf, target: PathBuf, new: bool) -> io::Result<Partial> {
        partials().push(temp.clone());
        let mut o = OpenOptions::new();
        o.write(true);
        if new {
            o.create_new(true);
        } else {
            o.create(true).truncate(true);
        }
        match o.open(&temp) {
            Ok(f) => Ok(Partial {
                temp,
                target,
                file: Some(BufWriter::new(f)),
            }),
            Err(e) => {
                unregister(&temp);
                Err(e)
            }
        }
    }

    /// The temporary file's path.
    pub fn path(&self) -> &Path {
        &self.temp
    }

    /// Where the file is written.
    pub fn writer(&mut self) -> &mut BufWriter<File> {
        self.file.as_mut().expect("open until committed")
    }

    /// Flushes the file and renames it onto its target, unless `cancel` was cancelled (then it
    /// is removed). `Err(None)`: cancelled.
    pub fn commit(mut self, cancel: &Cancel) -> Result<(), Option<io::Error>> {
        let file = self.file.take().expect("open until committed");
        if let Err(e) = file.into_inner().map_err(|e| e.into_error()) {
            return Err(Some(e));
        }
        // A signal's watchdog holds the list's lock while it removes the files and exits, so
        // nothing is renamed into place once it has started.
        let mut list = partials();
        if cancel.is_cancelled() {
            return Err(None);
        }
        let done = fs::rename(&self.temp, &self.target);
        if done.is_ok() {
            list.retain(|p| p != &self.temp);
        }
        drop(list);
        done.map_err(Some)
    }
}

fn unregister(temp: &Path) {
    partials().retain(|p| p != temp);
}

impl Drop for Partial {
    fn drop(&mut self) {
        let list = partials();
        if list.iter().any(|p| p == &self.temp) {
            drop(list);
            self.file = None;
            let _ = fs::remove_file(&self.temp);
            unregister(&self.temp);
        }
    }
}

/// Writes `bytes` to `path` whole or not at all (see the module's rules): links followed,
/// streams written through, regular files through a partial file renamed when complete and not
/// cancelled.
pub fn write_atomic(path: &Path, bytes: &[u8], cancel: &Cancel) -> Result<(), OutputError> {
    write_atomic_with(path, cancel, |w| w.write_all(bytes))
}

/// Like [`write_atomic`], with the content written by `fill`.
pub fn write_atomic_with(
    path: &Path,
    cancel: &Cancel,
    fill: impl FnOnce(&mut dyn Write) -> io::Result<()>,
) -> Result<(), OutputError> {
    if cancel.is_cancelled() {
        return Err(OutputError::Cancelled);
    }
    let io = |source| OutputError::Io {
        path: path.display().to_string(),
        source,
    };
    match resolve(path)? {
        Target::Stdout => {
            let mut out = io::stdout().lock();
            fill(&mut out).and_then(|()| out.flush()).map_err(io)
        }
        Target::Stream(p) => {
            // Appending: a descriptor that is a regular file (`> f.csv`) is written at its end,
            // as the shell's own writes are; a pipe or a device ignores it.
            let mut f = OpenOptions::new().append(true).open(&p).map_err(io)?;
            fill(&mut f).and_then(|()| f.flush()).map_err(io)
        }
        Target::File(target) => {
            // A file replaced keeps its permissions.
            let mode = fs::metadata(&target).ok().map(|m| m.permissions());
            let mut partial = Partial::open(partial_path(&target), target, false).map_err(io)?;
            fill(partial.writer()).map_err(io)?;
            if let Some(mode) = mode {
                let _ = fs::set_permissions(partial.path(), mode);
            }
            partial.commit(cancel).map_err(|e| match e {
                Some(e) => io(e),
                None => OutputError::Cancelled,
            })
        }
    }
}

/// What two outputs are compared by: the resolved path, and the inode of an existing file.
struct Identity {
    path: Option<PathBuf>,
    inode: Option<(u64, u64)>,
}

impl Identity {
    fn of(target: &Target) -> Identity {
        match target {
            Target::Stdout => Identity {
                path: Some(PathBuf::from("-")),
                inode: None,
            },
            Target::Stream(p) | Target::File(p) => {
                let meta = fs::metadata(p).ok();
                // Devices may take any number of outputs (`/dev/null` twice is fine).
                if meta.as_ref().is_some_and(is_device) {
                    return Identity {
                        path: None,
                        inode: None,
                    };
                }
                let path = match (p.parent(), p.file_name()) {
                    (Some(dir), Some(name)) => {
                        let dir = if dir.as_os_str().is_empty() {
                            Path::new(".")
                        } else {
                            dir
                        };
                        Some(fs::canonicalize(dir).map_or_else(|_| p.clone(), |d| d.join(name)))
                    }
                    _ => Some(p.clone()),
                };
                Identity {
                    path,
                    inode: meta.as_ref().and_then(inode),
                }
            }
        }
    }

    fn same(&self, other: &Identity) -> bool {
        (self.path.is_some() && self.path == other.path)
            || (self.inode.is_some() && self.inode == other.inode)
    }
}

#[cfg(unix)]
fn is_device(m: &fs::Metadata) -> bool {
    use std::os::unix::fs::FileTypeExt;
    m.file_type().is_char_device() || m.file_type().is_block_device()
}

#[cfg(not(unix))]
fn is_device(_: &fs::Metadata) -> bool {
    false
}

#[cfg(unix)]
fn inode(m: &fs::Metadata) -> Option<(u64, u64)> {
    use std::os::unix::fs::MetadataExt;
    Some((m.dev(), m.ino()))
}

#[cfg(not(unix))]
fn inode(_: &fs::Metadata) -> Option<(u64, u64)> {
    None
}

/// Checks the outputs of a command before it starts: each `(flag, path)` (the flag names it in
/// the error, e.g. `--raps`) must be writable — a regular file's directory exists and a file
/// can be created there (tried with its partial file, removed at once), a stream or descriptor
/// exists — and no two may be the same file. Nothing is left behind.
pub fn check_outputs(outputs: &[(&str, &Path)]) -> Result<(), OutputError> {
    let mut seen: Vec<(String, Identity)> = Vec::with_capacity(outputs.len());
    for &(flag, path) in outputs {
        let named = format!("{flag} {}", path.display());
        let io = |source| OutputError::Io {
            path: named.clone(),
            source,
        };
        let target = resolve(path).map_err(|e| match e {
            OutputError::Dangling { target, .. } => OutputError::Dangling {
                path: named.clone(),
                target,
            },
            OutputError::Directory { .. } => OutputError::Directory {
                path: named.clone(),
            },
            OutputError::Io { source, .. } => io(source),
            other => other,
        })?;
        match &target {
            Target::Stdout => {}
            Target::Stream(p) => {
                fs::metadata(p).map_err(io)?;
            }
            Target::File(p) => probe(p).map_err(io)?,
        }
        let id = Identity::of(&target);
        if let Some((first, _)) = seen.iter().find(|(_, other)| other.same(&id)) {
            return Err(OutputError::Same {
                first: first.clone(),
                second: named,
                path: match &target {
                    Target::Stdout => "standard output".into(),
                    Target::Stream(p) | Target::File(p) => p.display().to_string(),
                },
            });
        }
        seen.push((named, id));
    }
    Ok(())
}

/// Checks that `dir` (an output directory, `flag` naming it in the error) is a directory files
/// can be created in, or can be created as one: its nearest existing ancestor is a directory
/// that takes a new file (tried and removed at once). Nothing is created.
pub fn check_output_dir(flag: &str, dir: &Path) -> Result<(), OutputError> {
    let named = format!("{flag} {}", dir.display());
    let io = |source| OutputError::Io {
        path: named.clone(),
        source,
    };
    let mut cur = dir.to_path_buf();
    loop {
        match fs::metadata(&cur) {
            Ok(m) if m.is_dir() => {
                return probe(&cur.join(format!(".samplescope-probe-{}", std::process::id())))
                    .map_err(io)
            }
            Ok(_) => {
                return Err(io(io::Error::other(format!(
                    "{} is not a directory",
                    cur.display()
                ))))
            }
            Err(e) if e.kind() == io::ErrorKind::NotFound && cur != Path::new(".") => {
                if fs::symlink_metadata(&cur).is_ok() {
                    return Err(OutputError::Dangling {
                        path: named.clone(),
                        target: fs::read_link(&cur)
                            .map(|t| t.display().to_string())
                            .unwrap_or_default(),
                    });
                }
                match cur.parent() {
                    Some(p) if !p.as_os_str().is_empty() => cur = p.to_path_buf(),
                    _ => cur = PathBuf::from("."),
                }
            }
            Err(e) => return Err(io(e)),
        }
    }
}

/// Whether a file can be created beside `target`: its directory exists, is a directory, and
/// takes a new file (its partial file, created and removed at once).
fn probe(target: &Path) -> io::Result<()> {
    let dir = match target.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    match fs::metadata(dir) {
        Ok(m) if m.is_dir() => {}
        Ok(_) => {
            return Err(io::Error::other(format!(
                "{} is not a directory",
                dir.display()
            )))
        }
        Err(e) if e.kind() == io::ErrorKind::NotFound => {
            return Err(io::Error::other(format!(
                "directory {} does not exist",
                dir.display()
            )))
        }
        Err(e) => return Err(e),
    }
    let temp = partial_path(target);
    match OpenOptions::new().write(true).create_new(true).open(&temp) {
        Ok(f) => {
            drop(f);
            let _ = fs::remove_file(&temp);
            Ok(())
        }
        // A partial file of another writer: the directory takes files.
        Err(e) if e.kind() == io::ErrorKind::AlreadyExists => Ok(()),
        Err(e) => Err(io::Error::new(
            e.kind(),
            format!("cannot create a file in {}: {e}", dir.display()),
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn dir(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("ss-output-{name}-{}", std::process::id()));
        let _ = fs::remove_dir_all(&d);
        fs::create_dir_all(&d).unwrap();
        d
    }

    #[test]
    fn unique_partials_have_distinct_names_and_vanish_unless_committed() {
        let d = dir("unique");
        let target = d.join("entry.bin");
        let a = Partial::create_unique(&d, ".t-", ".tmp", target.clone()).unwrap();
        let mut b = Partial::create_unique(&d, ".t-", ".tmp", target.clone()).unwrap();
        assert_ne!(a.path(), b.path());
        let name = b.path().file_name().unwrap().to_string_lossy().into_owned();
        assert!(name.starts_with(".t-") && name.ends_with(".tmp"), "{name}");
        let a_path = a.path().to_path_buf();
        drop(a);
        assert!(!a_path.exists(), "a dropped partial file is removed");
        b.writer().write_all(b"whole").unwrap();
        let b_path = b.path().to_path_buf();
        b.commit(&Cancel::never()).unwrap();
        assert!(!b_path.exists());
        assert_eq!(fs::read(&target).unwrap(), b"whole");
        let _ = fs::remove_dir_all(&d);
    }

    #[test]
    fn descriptors_are_recognised_by_path() {
        assert_eq!(descriptor(Path::new("/dev/stdout")), Some(1));
        assert_eq!(descriptor(Path::new("/dev/fd/3")), Some(3));
        assert_eq!(descriptor(Path::new("/proc/self/fd/1")), Some(1));
        let own = format!("/proc/{}/fd/2", std::process::id());
        assert_eq!(descriptor(Path::new(&own)), Some(2));
        assert_eq!(descriptor(Path::new("/proc/self/fdinfo/1")), None);
        assert_eq!(descriptor(Path::new("dev/stdout")), None);
        assert_eq!(descriptor(Path::new("/tmp/x")), None);
    }

    #[cfg(unix)]
    #[test]
    fn links_are_followed_and_kept() {
        let d = dir("links");
        let target = d.join("t.csv");
        fs::write(&target, b"old").unwrap();
        std::os::unix::fs::symlink("t.csv", d.join("l1")).unwrap();
        std::os::unix::fs::symlink(d.join("l1"), d.join("l2")).unwrap();
        write_atomic(&d.join("l2"), b"new", &Cancel::never()).unwrap();
        assert_eq!(fs::read(&target).unwrap(), b"new");
        for l in ["l1", "l2"] {
            assert!(fs::symlink_metadata(d.join(l))
                .unwrap()
                .file_type()
                .is_symlink());
        }
        std::os::unix::fs::symlink("missing.csv", d.join("dangling")).unwrap();
        let e = write_atomic(&d.join("dangling"), b"x", &Cancel::never()).unwrap_err();
        assert!(matches!(e, OutputError::Dangling { .. }), "{e}");
        assert!(!d.join("missing.csv").exists());
        std::os::unix::fs::symlink("loop", d.join("loop")).unwrap();
        assert!(write_atomic(&d.join("loop"), b"x", &Cancel::never()).is_err());
        let left: Vec<_> = fs::read_dir(&d)
            .unwrap()
            .filter_map(|e| e.ok())
            .filter(|e| e.file_name().to_string_lossy().ends_with(".partial"))
            .collect();
        assert!(left.is_empty(), "{left:?}");
        fs::remove_dir_all(&d).unwrap();
    }

    #[test]
    fn a_cancelled_write_leaves_nothing() {
        let d = dir("cancel");
        let c = Cancel::new();
        let e = write_atomic_with(&d.join("a.csv"), &c, |w| {
            c.cancel();
            w.write_all(b"x")
        })
        .unwrap_err();
        assert!(matches!(e, OutputError::Cancelled));
        assert_eq!(fs::read_dir(&d).unwrap().count(), 0);
        fs::remove_dir_all(&d).unwrap();
    }

    #[cfg(unix)]
    #[test]
    fn outputs_are_checked_for_directories_duplicates_and_links() {
        let d = dir("check");
        let a = d.join("a.csv");
        std::os::unix::fs::symlink("a.csv", d.join("la")).unwrap();
        let ok = check_outputs(&[("--x", &a), ("--y", &d.join("b.csv"))]);
        assert!(ok.is_ok(), "{ok:?}");
        let e = check_outputs(&[("--x", &a), ("--y", &d.join(".").join("a.csv"))]).unwrap_err();
        assert!(e.is_conflict(), "{e}");
        // A link and the file it will create are the same output too.
        fs::write(&a, b"").unwrap();
        let e = check_outputs(&[("--x", &a), ("--y", &d.join("la"))]).unwrap_err();
        assert!(
            e.to_string().contains("--x") && e.to_string().contains("--y"),
            "{e}"
        );
        fs::hard_link(&a, d.join("h.csv")).unwrap();
        assert!(check_outputs(&[("--x", &a), ("--y", &d.join("h.csv"))]).is_err());
        let e = check_outputs(&[("--x", &d)]).unwrap_err();
        assert!(matches!(e, OutputError::Directory { .. }), "{e}");
        let e = check_outputs(&[("--x", &d.join("no/such/dir.csv"))]).unwrap_err();
        assert!(e.to_string().starts_with("--x "), "{e}");
        let null = Path::new("/dev/null");
        assert!(check_outputs(&[("--x", null), ("--y", null)]).is_ok());
        assert!(
            check_outputs(&[("--x", Path::new("-")), ("--y", Path::new("/dev/stdout"))]).is_err()
        );
        // Nothing probed is left behind.
        let mut names: Vec<String> = fs::read_dir(&d)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        names.sort();
        assert_eq!(names, ["a.csv", "h.csv", "la"]);
        fs::remove_dir_all(&d).unwrap();
    }
}
