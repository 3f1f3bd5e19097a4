//! A size-bounded, checksummed on-disk cache for computed node results.
//!
//! [`DiskCache`] maps `(kind, key)` — a short kind name such as `"reference"` and a 32-byte key
//! (typically a hash of everything the result depends on) — to an opaque byte payload. It keeps
//! expensive results (reference images) across runs of the program. It knows nothing about what
//! the bytes mean; [`ImagePayload`] is a small encoding for one reference image.
//!
//! # Location
//!
//! [`DiskCache::default_dir`] is `$SAMPLESCOPE_CACHE_DIR` when that is set (and not empty), else
//! the platform's cache directory joined with `samplescope/v1`:
//!
//! | platform | directory |
//! | --- | --- |
//! | Linux | `$XDG_CACHE_HOME/samplescope/v1`, or `~/.cache/samplescope/v1` |
//! | macOS | `~/Library/Caches/samplescope/v1` |
//! | Windows | `%LOCALAPPDATA%\samplescope\v1` |
//!
//! # File format
//!
//! One file per entry, named `<kind>-<key as 64 lowercase hex digits>.bin`. All integers are
//! little-endian:
//!
//! | bytes | field |
//! | --- | --- |
//! | 8 | magic `SSCACHE1` |
//! | 4 | format version, `u32` ([`FORMAT_VERSION`]) |
//! | 32 | the key |
//! | 4 | length of the kind, `u32` |
//! | n | the kind, ASCII |
//! | 8 | payload length, `u64` |
//! | len | the payload |
//! | 32 | BLAKE3 hash of every byte before it |
//!
//! So an entry's file is [`entry_overhead`]`(kind)` = 88 + `kind.len()` bytes longer than its
//! payload. Kinds are 1 to 64 characters out of `a-z`, `0-9`, `_` and `-` (they are part of a
//! file name, and a case-insensitive file system must not fold two kinds together).
//!
//! # Guarantees
//!
//! - **Never trusts a bad file.** [`DiskCache::get`] returns the payload only when the magic,
//!   version, key, kind, payload length, file length and checksum all match. Any mismatch gives
//!   `None` and the file is deleted: a corrupt file, a truncated one, or a *foreign* one (a
//!   valid entry renamed or copied to another key's or kind's name).
//! - **Bounded reads.** `get` reads at most the header-declared length plus the fixed overhead
//!   (through [`Read::take`]), and rejects a declared payload longer than `max_bytes` or one that
//!   does not agree with the file's length before allocating anything for it, so a huge, sparse
//!   or endless file cannot cause a large allocation.
//! - **Atomic writes.** [`DiskCache::put`] writes the whole entry to a temporary file in the
//!   same directory and renames it over the entry's name. A reader, or a second process writing
//!   the same key, sees either the old complete file or the new complete one, never a part.
//!   There is no fsync: after a power loss a file may hold garbage, which the checksum catches.
//! - **Size bound.** After each `put`, the least recently used entries (oldest modification
//!   time; `get` sets it to now) are deleted until the entry files add up to at most
//!   `max_bytes`. An entry whose file would be larger than `max_bytes` on its own is not stored
//!   (`put` returns `Ok`). With several processes the bound holds once each one's `put` returns.
//! - **Leftovers.** Temporary files left by a crash are deleted by [`DiskCache::open`] (those
//!   not written to for [`STALE_TEMP_AGE`], so a concurrent writer's file is left alone).
//! - **Only its own files.** `open`, `put`, [`DiskCache::total_bytes`] and
//!   [`DiskCache::clear`] touch only file names of the two shapes above; anything else in the
//!   directory is ignored.
//!
//! A race between a reader finding a damaged file and a writer replacing it can at worst delete
//! the writer's fresh entry: a lost cache entry, never a wrong payload.

use crate::core::cancel::Cancel;
use crate::core::output::Partial;
use std::fs::{self, File, OpenOptions};
use std::io::{self, ErrorKind, Read, Write};
use std::path::{Path, PathBuf};
use std::time::{Duration, SystemTime};

/// The first eight bytes of every entry file.
pub const MAGIC: [u8; 8] = *b"SSCACHE1";
/// The format version written after [`MAGIC`]; files of another version are rejected.
/// Version 2: the image payload no longer stores the accuracy text (it is derived).
pub const FORMAT_VERSION: u32 = 2;
/// The longest kind name, in bytes.
pub const MAX_KIND_LEN: usize = 64;
/// A temporary file not modified for this long is taken for a crash's leftover by
/// [`DiskCache::open`] and [`DiskCache::clear`].
pub const STALE_TEMP_AGE: Duration = Duration::from_secs(120);

/// Magic, version, key and kind length: the bytes before the kind.
const FIXED_PREFIX: usize = 8 + 4 + 32 + 4;
/// Payload length field and the trailing hash.
const FIXED_SUFFIX: usize = 8 + 32;
const TEMP_PREFIX: &str = ".sscache-";
const TEMP_SUFFIX: &str = ".tmp";
const ENTRY_SUFFIX: &str = ".bin";
const HEX_KEY_LEN: usize = 64;

/// Bytes an entry's file holds beyond its payload: 88 + `kind.len()`.
pub fn entry_overhead(kind: &str) -> u64 {
    (FIXED_PREFIX + kind.len() + FIXED_SUFFIX) as u64
}

/// What went wrong opening or writing a [`DiskCache`]; each names the path concerned.
#[derive(Debug, thiserror::Error)]
pub enum DiskCacheError {
    /// The cache directory does not exist and cannot be created (or is not a directory).
    #[error("cannot create cache directory {}: {source}", path.display())]
    CreateDir { path: PathBuf, source: io::Error },
    /// The cache directory exists but no file can be created in it.
    #[error("cache directory {} is not writable: {source}", path.display())]
    NotWritable { path: PathBuf, source: io::Error },
    /// The cache directory cannot be listed.
    #[error("cannot list cache directory {}: {source}", path.display())]
    ReadDir { path: PathBuf, source: io::Error },
    /// Writing an entry's temporary file failed (it has been removed).
    #[error("cannot write cache file {}: {source}", path.display())]
    Write { path: PathBuf, source: io::Error },
    /// Renaming the temporary file to the entry's name failed (it has been removed).
    #[error("cannot rename {} to {}: {source}", from.display(), to.display())]
    Rename {
        from: PathBuf,
        to: PathBuf,
        source: io::Error,
    },
    /// Deleting a file (by eviction or [`DiskCache::clear`]) failed.
    #[error("cannot delete cache file {}: {source}", path.display())]
    Remove { path: PathBuf, source: io::Error },
    /// The kind is not 1 to 64 characters out of `a-z`, `0-9`, `_`, `-`.
    #[error("invalid cache kind {kind:?} (want 1 to 64 characters out of a-z, 0-9, '_', '-') for cache directory {}", dir.display())]
    InvalidKind { kind: String, dir: PathBuf },
}

/// A directory of checksummed cache entries whose files add up to at most `max_bytes`.
///
/// See the [module documentation](self) for the file format and the guarantees.
#[derive(Debug, Clone)]
pub struct DiskCache {
    dir: PathBuf,
    max_bytes: u64,
}

impl DiskCache {
    /// The directory to use: `$SAMPLESCOPE_CACHE_DIR` if set and not empty, else
    /// `dirs::cache_dir()/samplescope/v1` — `$XDG_CACHE_HOME/samplescope/v1` or
    /// `~/.cache/samplescope/v1` on Linux, `~/Library/Caches/samplescope/v1` on macOS,
    /// `%LOCALAPPDATA%\samplescope\v1` on Windows. `None` if no directory can be found.
    pub fn default_dir() -> Option<PathBuf> {
        default_dir_from(std::env::var_os("SAMPLESCOPE_CACHE_DIR"), dirs::cache_dir)
    }

    /// Opens (creating it and its parents if needed) the cache in `dir`, bounded to `max_bytes`
    /// of entry files. Checks that a file can be created there and deletes stale temporary
    /// files. Entries already there are kept; the bound is enforced at the next [`put`](Self::put).
    pub fn open(dir: PathBuf, max_bytes: u64) -> Result<DiskCache, DiskCacheError> {
        if let Err(source) = fs::create_dir_all(&dir) {
            return Err(DiskCacheError::CreateDir { path: dir, source });
        }
        match fs::metadata(&dir) {
            Ok(m) if m.is_dir() => {}
            Ok(_) => {
                let source = io::Error::new(ErrorKind::AlreadyExists, "not a directory");
                return Err(DiskCacheError::CreateDir { path: dir, source });
            }
            Err(source) => return Err(DiskCacheError::CreateDir { path: dir, source }),
        }
        let cache = DiskCache { dir, max_bytes };
        // A file can be created there (the probe is removed when dropped).
        match cache.create_partial(&cache.dir.join("probe")) {
            Ok(probe) => drop(probe),
            Err(source) => {
                return Err(DiskCacheError::NotWritable {
                    path: cache.dir,
                    source,
                })
            }
        }
        cache.remove_stale_temps()?;
        Ok(cache)
    }

    /// The cache's directory.
    pub fn dir(&self) -> &Path {
        &self.dir
    }

    /// The bound on the entry files' total size, in bytes.
    pub fn max_bytes(&self) -> u64 {
        self.max_bytes
    }

    /// The payload stored for `(kind, key)`, or `None` when there is none or the file is
    /// corrupt, truncated or foreign (such a file is deleted). A hit marks the entry as
    /// recently used (sets its modification time to now).
    pub fn get(&self, kind: &str, key: &[u8; 32]) -> Option<Vec<u8>> {
        if !valid_kind(kind) {
            return None;
        }
        let path = self.entry_path(kind, key);
        let meta = fs::symlink_metadata(&path).ok()?;
        if !meta.is_file() {
            // A link, a pipe or a directory under an entry's name: never ours.
            remove_non_file(&path, &meta);
            return None;
        }
        let file = File::open(&path).ok()?;
        match read_entry(&file, kind, key, self.max_bytes) {
            Ok(payload) => {
                touch(&file, &path);
                Some(payload)
            }
            Err(ReadFailure::Bad) => {
                drop(file);
                let _ = fs::remove_file(&path);
                None
            }
            Err(ReadFailure::Io) => None,
        }
    }

    /// Stores `payload` for `(kind, key)`, replacing any entry there, then deletes the least
    /// recently used entries until the total is at most `max_bytes`.
    ///
    /// The entry is written to a temporary file in the cache directory and renamed into place,
    /// so no reader ever sees a partial file. If the entry's file (payload plus
    /// [`entry_overhead`]) would be larger than `max_bytes`, nothing is stored and the result
    /// is `Ok(())`. An eviction error is returned after the entry was stored.
    pub fn put(&self, kind: &str, key: &[u8; 32], payload: &[u8]) -> Result<(), DiskCacheError> {
        if !valid_kind(kind) {
            return Err(DiskCacheError::InvalidKind {
                kind: kind.to_owned(),
                dir: self.dir.clone(),
            });
        }
        let size = entry_overhead(kind).saturating_add(payload.len() as u64);
        if size > self.max_bytes {
            return Ok(());
        }
        let path = self.entry_path(kind, key);
        // The shared partial-file writer (removed on failure, on drop and on a signal).
        let mut partial =
            self.create_partial(&path)
                .map_err(|source| DiskCacheError::NotWritable {
                    path: self.dir.clone(),
                    source,
                })?;
        let temp = partial.path().to_path_buf();
        if let Err(source) = write_entry(partial.writer(), kind, key, payload) {
            return Err(DiskCacheError::Write { path: temp, source });
        }
        if let Err(e) = partial.commit(&Cancel::never()) {
            let source = e.unwrap_or_else(|| io::Error::other("cancelled"));
            return Err(DiskCacheError::Rename {
                from: temp,
                to: path,
                source,
            });
        }
        self.evict(&path)
    }

    /// The total size in bytes of the entry files now in the directory (0 if it can't be read).
    pub fn total_bytes(&self) -> u64 {
        self.entries()
            .map(|es| es.iter().map(|e| e.len).sum())
            .unwrap_or(0)
    }

    /// Deletes every entry, and stale temporary files. Other files in the directory are kept.
    pub fn clear(&self) -> Result<(), DiskCacheError> {
        for e in self.entries()? {
            remove_entry_file(&e.path)?;
        }
        self.remove_stale_temps()
    }

    fn entry_path(&self, kind: &str, key: &[u8; 32]) -> PathBuf {
        self.dir.join(format!("{kind}-{}{ENTRY_SUFFIX}", hex(key)))
    }

    /// A new, empty temporary file with a name no other writer uses, to be renamed onto
    /// `target` ([`Partial::create_unique`]).
    fn create_partial(&self, target: &Path) -> io::Result<Partial> {
        Partial::create_unique(&self.dir, TEMP_PREFIX, TEMP_SUFFIX, target.to_path_buf())
    }

    /// Lists the directory: entry files (with size and modification time), calling `temp` on
    /// each temporary file.
    fn scan(
        &self,
        mut temp: impl FnMut(&Path, &fs::Metadata),
    ) -> Result<Vec<Entry>, DiskCacheError> {
        let read_dir = fs::read_dir(&self.dir).map_err(|source| DiskCacheError::ReadDir {
            path: self.dir.clone(),
            source,
        })?;
        let mut entries = Vec::new();
        for item in read_dir {
            let item = item.map_err(|source| DiskCacheError::ReadDir {
                path: self.dir.clone(),
                source,
            })?;
            let name = item.file_name();
            let Some(name) = name.to_str() else { continue };
            let is_entry = is_entry_name(name);
            if !is_entry && !is_temp_name(name) {
                continue;
            }
            let Ok(meta) = item.metadata() else { continue };
            let path = item.path();
            if is_entry {
                entries.push(Entry {
                    path,
                    len: meta.len(),
                    modified: meta.modified().unwrap_or(SystemTime::UNIX_EPOCH),
                });
            } else if meta.is_file() {
                temp(&path, &meta);
            }
        }
        Ok(entries)
    }

    fn entries(&self) -> Result<Vec<Entry>, DiskCacheError> {
        self.scan(|_, _| {})
    }

    fn remove_stale_temps(&self) -> Result<(), DiskCacheError> {
        let now = SystemTime::now();
        let mut stale = Vec::new();
        self.scan(|path, meta| {
            let modified = meta.modified().unwrap_or(SystemTime::UNIX_EPOCH);
            let age = now.duration_since(modified).unwrap_or(Duration::ZERO);
            if age >= STALE_TEMP_AGE {
                stale.push(path.to_path_buf());
            }
        })?;
        for path in stale {
            remove_entry_file(&path)?;
        }
        Ok(())
    }

    /// Deletes the least recently used entries, sparing `keep`, until the total fits.
    fn evict(&self, keep: &Path) -> Result<(), DiskCacheError> {
        let mut entries = self.entries()?;
        let mut total: u64 = entries.iter().map(|e| e.len).sum();
        if total <= self.max_bytes {
            return Ok(());
        }
        entries.sort_by(|a, b| (a.modified, &a.path).cmp(&(b.modified, &b.path)));
        for e in entries {
            if total <= self.max_bytes {
                break;
            }
            if e.path == keep {
                continue;
            }
            remove_entry_file(&e.path)?;
            total -= e.len;
        }
        Ok(())
    }
}

struct Entry {
    path: PathBuf,
    len: u64,
    modified: SystemTime,
}

enum ReadFailure {
    /// The file is not a valid entry for this kind and key: delete it.
    Bad,
    /// Reading failed for another reason (permissions, I/O): leave the file alone.
    Io,
}

impl From<io::Error> for ReadFailure {
    fn from(e: io::Error) -> ReadFailure {
        if e.kind() == ErrorKind::UnexpectedEof {
            ReadFailure::Bad
        } else {
            ReadFailure::Io
        }
    }
}

fn read_entry(
    file: &File,
    kind: &str,
    key: &[u8; 32],
    max_bytes: u64,
) -> Result<Vec<u8>, ReadFailure> {
    // The header as it must be for this kind; nothing beyond it is read before it checks out.
    let prefix_len = FIXED_PREFIX + kind.len() + 8;
    let mut prefix = Vec::with_capacity(prefix_len);
    file.take(prefix_len as u64).read_to_end(&mut prefix)?;
    if prefix.len() != prefix_len
        || prefix[0..8] != MAGIC
        || prefix[8..12] != FORMAT_VERSION.to_le_bytes()
        || prefix[12..44] != key[..]
        || prefix[44..48] != (kind.len() as u32).to_le_bytes()
        || &prefix[48..48 + kind.len()] != kind.as_bytes()
    {
        return Err(ReadFailure::Bad);
    }
    let declared = u64::from_le_bytes(prefix[prefix_len - 8..].try_into().expect("8 bytes"));
    if declared > max_bytes {
        return Err(ReadFailure::Bad);
    }
    let expected_len = (prefix_len as u64)
        .checked_add(declared)
        .and_then(|n| n.checked_add(32))
        .ok_or(ReadFailure::Bad)?;
    if file.metadata()?.len() != expected_len {
        return Err(ReadFailure::Bad);
    }
    let declared = usize::try_from(declared).map_err(|_| ReadFailure::Bad)?;
    let mut payload = Vec::new();
    payload
        .try_reserve_exact(declared)
        .map_err(|_| ReadFailure::Io)?;
    file.take(declared as u64).read_to_end(&mut payload)?;
    if payload.len() != declared {
        return Err(ReadFailure::Bad);
    }
    let mut hash = [0u8; 32];
    let mut reader = file.take(32 + 1);
    reader.read_exact(&mut hash)?;
    if reader.read(&mut [0u8; 1])? != 0 {
        return Err(ReadFailure::Bad); // grew past the declared length
    }
    let mut hasher = blake3::Hasher::new();
    hasher.update(&prefix);
    hasher.update(&payload);
    if hasher.finalize().as_bytes() != &hash {
        return Err(ReadFailure::Bad);
    }
    Ok(payload)
}

fn write_entry(w: &mut impl Write, kind: &str, key: &[u8; 32], payload: &[u8]) -> io::Result<()> {
    let mut header = Vec::with_capacity(FIXED_PREFIX + kind.len() + 8);
    header.extend_from_slice(&MAGIC);
    header.extend_from_slice(&FORMAT_VERSION.to_le_bytes());
    header.extend_from_slice(key);
    header.extend_from_slice(&(kind.len() as u32).to_le_bytes());
    header.extend_from_slice(kind.as_bytes());
    header.extend_from_slice(&(payload.len() as u64).to_le_bytes());
    let mut hasher = blake3::Hasher::new();
    hasher.update(&header);
    hasher.update(payload);
    w.write_all(&header)?;
    w.write_all(payload)?;
    w.write_all(hasher.finalize().as_bytes())?;
    w.flush()
}

/// Marks an entry as just used. Best effort: a read-only cache still serves hits.
fn touch(file: &File, path: &Path) {
    let now = SystemTime::now();
    if file.set_modified(now).is_err() {
        // Some platforms (Windows) need a handle with write access to set times.
        if let Ok(f) = OpenOptions::new().write(true).open(path) {
            let _ = f.set_modified(now);
        }
    }
}

/// Deletes a link, pipe or other non-file under an entry's name (what a link points to is left
/// alone); a directory only if it is empty.
fn remove_non_file(path: &Path, meta: &fs::Metadata) {
    if meta.is_dir() {
        let _ = fs::remove_dir(path);
    } else {
        let _ = fs::remove_file(path);
    }
}

/// Deletes a file; one already gone (another process got there first) is fine.
fn remove_entry_file(path: &Path) -> Result<(), DiskCacheError> {
    match fs::remove_file(path) {
        Ok(()) => Ok(()),
        Err(e) if e.kind() == ErrorKind::NotFound => Ok(()),
        Err(source) => Err(DiskCacheError::Remove {
            path: path.to_path_buf(),
            source,
        }),
    }
}

fn default_dir_from(
    env: Option<std::ffi::OsString>,
    cache_dir: impl FnOnce() -> Option<PathBuf>,
) -> Option<PathBuf> {
    match env {
        Some(dir) if !dir.is_empty() => Some(PathBuf::from(dir)),
        _ => cache_dir().map(|d| d.join("samplescope").join("v1")),
    }
}

fn valid_kind(kind: &str) -> bool {
    (1..=MAX_KIND_LEN).contains(&kind.len())
        && kind
            .bytes()
            .all(|b| b.is_ascii_lowercase() || b.is_ascii_digit() || b == b'_' || b == b'-')
}

fn hex(key: &[u8; 32]) -> String {
    const DIGITS: &[u8; 16] = b"0123456789abcdef";
    let mut s = String::with_capacity(HEX_KEY_LEN);
    for b in key {
        s.push(DIGITS[(b >> 4) as usize] as char);
        s.push(DIGITS[(b & 15) as usize] as char);
    }
    s
}

/// `<kind>-<64 lowercase hex>.bin` with a valid kind.
fn is_entry_name(name: &str) -> bool {
    let Some(stem) = name.strip_suffix(ENTRY_SUFFIX) else {
        return false;
    };
    if stem.len() < HEX_KEY_LEN + 2 || !stem.is_char_boundary(stem.len() - HEX_KEY_LEN - 1) {
        return false;
    }
    let (kind, rest) = stem.split_at(stem.len() - HEX_KEY_LEN - 1);
    let Some(hex_key) = rest.strip_prefix('-') else {
        return false;
    };
    valid_kind(kind)
        && hex_key
            .bytes()
            .all(|b| b.is_ascii_digit() || (b'a'..=b'f').contains(&b))
}

fn is_temp_name(name: &str) -> bool {
    name.starts_with(TEMP_PREFIX) && name.ends_with(TEMP_SUFFIX)
}

/// One reference image as a cache payload: a `width × height` grid of `f64` values (row-major)
/// with how it was computed.
///
/// Encoding, little-endian, with nothing after it:
///
/// | bytes | field |
/// | --- | --- |
/// | 4 | `width`, `u32` |
/// | 4 | `height`, `u32` |
/// | 8 · width · height | `values`, `f64` bit patterns (NaNs kept bit for bit) |
/// | 1, then 8 if 1 | `error_estimate`: 0 = `None`; 1 = `Some`, then the `f64` |
/// | 4 + n | `method`: length `u32`, then n bytes of UTF-8 |
///
/// The accuracy shown for the image is not stored: it is a function of the method and the
/// error estimate (`model::Accuracy::reference`).
#[derive(Debug, Clone, PartialEq)]
pub struct ImagePayload {
    pub width: u32,
    pub height: u32,
    /// Row-major, exactly `width * height` values.
    pub values: Vec<f64>,
    pub error_estimate: Option<f64>,
    pub method: String,
}

impl ImagePayload {
    /// The encoding described on [`ImagePayload`].
    ///
    /// # Panics
    ///
    /// If `values.len()` is not `width * height`, or a string is 4 GiB or longer.
    pub fn to_bytes(&self) -> Vec<u8> {
        assert_eq!(
            Some(self.values.len()),
            (self.width as usize).checked_mul(self.height as usize),
            "ImagePayload: values.len() must be width * height ({} x {})",
            self.width,
            self.height
        );
        let mut out = Vec::with_capacity(8 + 8 * self.values.len() + 9 + 4 + self.method.len());
        out.extend_from_slice(&self.width.to_le_bytes());
        out.extend_from_slice(&self.height.to_le_bytes());
        for v in &self.values {
            out.extend_from_slice(&v.to_le_bytes());
        }
        match self.error_estimate {
            None => out.push(0),
            Some(e) => {
                out.push(1);
                out.extend_from_slice(&e.to_le_bytes());
            }
        }
        put_str(&mut out, &self.method);
        out
    }

    /// Decodes [`to_bytes`](Self::to_bytes)'s encoding. `None` unless the lengths agree exactly
    /// (8 · width · height value bytes, computed without overflow; string lengths; no trailing
    /// bytes), the option tags are 0 or 1 and the strings are UTF-8. Allocates only what the
    /// input actually holds.
    pub fn from_bytes(b: &[u8]) -> Option<ImagePayload> {
        let mut r = Reader(b);
        let width = u32::from_le_bytes(r.array()?);
        let height = u32::from_le_bytes(r.array()?);
        let count = (width as usize).checked_mul(height as usize)?;
        let raw = r.take(count.checked_mul(8)?)?;
        let values = raw
            .chunks_exact(8)
            .map(|c| f64::from_le_bytes(c.try_into().expect("8 bytes")))
            .collect();
        let error_estimate = match r.array::<1>()?[0] {
            0 => None,
            1 => Some(f64::from_le_bytes(r.array()?)),
            _ => return None,
        };
        let method = r.string()?;
        if !r.0.is_empty() {
            return None;
        }
        Some(ImagePayload {
            width,
            height,
            values,
            error_estimate,
            method,
        })
    }
}

fn put_str(out: &mut Vec<u8>, s: &str) {
    let len = u32::try_from(s.len()).expect("ImagePayload: string shorter than 4 GiB");
    out.extend_from_slice(&len.to_le_bytes());
    out.extend_from_slice(s.as_bytes());
}

/// A cursor over a byte slice whose reads fail instead of running past the end.
struct Reader<'a>(&'a [u8]);

impl<'a> Reader<'a> {
    fn take(&mut self, n: usize) -> Option<&'a [u8]> {
        if n > self.0.len() {
            return None;
        }
        let (head, tail) = self.0.split_at(n);
        self.0 = tail;
        Some(head)
    }

    fn array<const N: usize>(&mut self) -> Option<[u8; N]> {
        self.take(N).map(|s| s.try_into().expect("N bytes"))
    }

    fn string(&mut self) -> Option<String> {
        let len = usize::try_from(u32::from_le_bytes(self.array()?)).ok()?;
        let bytes = self.take(len)?;
        std::str::from_utf8(bytes).ok().map(str::to_owned)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::atomic::{AtomicU64, Ordering};
    use std::sync::Arc;

    /// A unique directory under the system temp dir, deleted on drop.
    struct TempDir(PathBuf);

    impl TempDir {
        fn new(name: &str) -> TempDir {
            static N: AtomicU64 = AtomicU64::new(0);
            let nanos = SystemTime::now()
                .duration_since(SystemTime::UNIX_EPOCH)
                .map_or(0, |d| d.as_nanos());
            let dir = std::env::temp_dir().join(format!(
                "samplescope-disk-cache-{name}-{}-{}-{nanos}",
                std::process::id(),
                N.fetch_add(1, Ordering::Relaxed)
            ));
            TempDir(dir)
        }

        fn path(&self) -> &Path {
            &self.0
        }
    }

    impl Drop for TempDir {
        fn drop(&mut self) {
            let _ = fs::remove_dir_all(&self.0);
        }
    }

    fn key(n: u8) -> [u8; 32] {
        let mut k = [0u8; 32];
        for (i, b) in k.iter_mut().enumerate() {
            *b = n.wrapping_mul(31).wrapping_add(i as u8);
        }
        k
    }

    fn payload(len: usize, seed: u8) -> Vec<u8> {
        (0..len)
            .map(|i| (i as u8).wrapping_mul(7).wrapping_add(seed))
            .collect()
    }

    fn set_age(path: &Path, age: Duration) {
        let f = OpenOptions::new().write(true).open(path).unwrap();
        f.set_modified(SystemTime::now() - age).unwrap();
    }

    /// Every file name in the directory, sorted.
    fn names(dir: &Path) -> Vec<String> {
        let mut v: Vec<String> = fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().into_string().unwrap())
            .collect();
        v.sort();
        v
    }

    #[test]
    fn round_trip() {
        let tmp = TempDir::new("round-trip");
        let cache = DiskCache::open(tmp.path().join("a/b"), 1 << 20).unwrap();
        assert!(
            tmp.path().join("a/b").is_dir(),
            "open creates the directory"
        );
        assert_eq!(cache.get("reference", &key(1)), None);
        for (i, len) in [0usize, 1, 100, 70_000].into_iter().enumerate() {
            let p = payload(len, i as u8);
            cache.put("reference", &key(i as u8), &p).unwrap();
            assert_eq!(
                cache.get("reference", &key(i as u8)).as_deref(),
                Some(&p[..])
            );
        }
        // Same key, other kind: separate entries.
        cache.put("other_kind-2", &key(1), b"x").unwrap();
        assert_eq!(cache.get("other_kind-2", &key(1)).unwrap(), b"x");
        assert_eq!(cache.get("reference", &key(1)).unwrap(), payload(1, 1));
        // Replacing an entry.
        cache.put("reference", &key(1), b"new").unwrap();
        assert_eq!(cache.get("reference", &key(1)).unwrap(), b"new");
        let name = format!("reference-{}.bin", hex(&key(1)));
        assert!(
            names(cache.dir()).contains(&name),
            "{:?}",
            names(cache.dir())
        );
        let expected: u64 = [0u64, 100, 70_000, 3]
            .iter()
            .map(|n| n + entry_overhead("reference"))
            .sum::<u64>()
            + 1
            + entry_overhead("other_kind-2");
        assert_eq!(cache.total_bytes(), expected);
        // Reopening finds the entries.
        let again = DiskCache::open(cache.dir().to_path_buf(), 1 << 20).unwrap();
        assert_eq!(again.get("reference", &key(2)).unwrap(), payload(100, 2));
    }

    #[test]
    fn file_layout_is_as_documented() {
        let tmp = TempDir::new("layout");
        let cache = DiskCache::open(tmp.path().to_path_buf(), 1 << 20).unwrap();
        cache.put("ref", &key(9), b"hello").unwrap();
        let bytes = fs::read(cache.entry_path("ref", &key(9))).unwrap();
        assert_eq!(bytes.len() as u64, 5 + entry_overhead("ref"));
        assert_eq!(&bytes[0..8], b"SSCACHE1");
        assert_eq!(&bytes[8..12], &2u32.to_le_bytes());
        assert_eq!(&bytes[12..44], &key(9));
        assert_eq!(&bytes[44..48], &3u32.to_le_bytes());
        assert_eq!(&bytes[48..51], b"ref");
        assert_eq!(&bytes[51..59], &5u64.to_le_bytes());
        assert_eq!(&bytes[59..64], b"hello");
        assert_eq!(&bytes[64..], blake3::hash(&bytes[..64]).as_bytes());
    }

    #[test]
    fn flipped_byte_anywhere_is_rejected_and_removed() {
        let tmp = TempDir::new("flip");
        let cache = DiskCache::open(tmp.path().to_path_buf(), 1 << 20).unwrap();
        let p = payload(40, 3);
        cache.put("reference", &key(3), &p).unwrap();
        let path = cache.entry_path("reference", &key(3));
        let good = fs::read(&path).unwrap();
        for i in 0..good.len() {
            for mask in [0x01u8, 0x80] {
                let mut bad = good.clone();
                bad[i] ^= mask;
                fs::write(&path, &bad).unwrap();
                assert_eq!(
                    cache.get("reference", &key(3)),
                    None,
                    "byte {i} ^ {mask:#x}"
                );
                assert!(!path.exists(), "byte {i}: the corrupt file is deleted");
            }
        }
        fs::write(&path, &good).unwrap();
        assert_eq!(cache.get("reference", &key(3)).unwrap(), p);
    }

    #[test]
    fn truncated_or_extended_file_is_rejected() {
        let tmp = TempDir::new("truncate");
        let cache = DiskCache::open(tmp.path().to_path_buf(), 1 << 20).unwrap();
        cache.put("reference", &key(4), &payload(30, 4)).unwrap();
        let path = cache.entry_path("reference", &key(4));
        let good = fs::read(&path).unwrap();
        for len in 0..good.len() {
            fs::write(&path, &good[..len]).unwrap();
            assert_eq!(cache.get("reference", &key(4)), None, "truncated to {len}");
            assert!(!path.exists(), "truncated to {len}: deleted");
        }
        let mut longer = good.clone();
        longer.push(0);
        fs::write(&path, &longer).unwrap();
        assert_eq!(cache.get("reference", &key(4)), None, "a trailing byte");
        assert!(!path.exists());
    }

    #[test]
    fn file_under_another_name_is_foreign() {
        let tmp = TempDir::new("foreign");
        let cache = DiskCache::open(tmp.path().to_path_buf(), 1 << 20).unwrap();
        cache.put("reference", &key(5), b"five").unwrap();
        let source = cache.entry_path("reference", &key(5));
        // Another key's name.
        let other_key = cache.entry_path("reference", &key(6));
        fs::copy(&source, &other_key).unwrap();
        assert_eq!(cache.get("reference", &key(6)), None);
        assert!(!other_key.exists(), "a foreign file is deleted");
        // Another kind's name, same length and not.
        for kind in ["referencf", "ref"] {
            let other_kind = cache.entry_path(kind, &key(5));
            fs::copy(&source, &other_kind).unwrap();
            assert_eq!(cache.get(kind, &key(5)), None, "{kind}");
            assert!(!other_kind.exists());
        }
        assert_eq!(cache.get("reference", &key(5)).unwrap(), b"five");
    }

    /// A header that checks out but declares 1 TB of payload.
    fn huge_header(kind: &str, key: &[u8; 32]) -> Vec<u8> {
        let mut h = Vec::new();
        h.extend_from_slice(&MAGIC);
        h.extend_from_slice(&FORMAT_VERSION.to_le_bytes());
        h.extend_from_slice(key);
        h.extend_from_slice(&(kind.len() as u32).to_le_bytes());
        h.extend_from_slice(kind.as_bytes());
        h.extend_from_slice(&1_000_000_000_000u64.to_le_bytes());
        h.extend_from_slice(&[0u8; 64]);
        h
    }

    #[test]
    fn declared_terabyte_payload_is_rejected_without_allocating() {
        let tmp = TempDir::new("huge");
        // Longer than max_bytes: rejected on the length field.
        let small = DiskCache::open(tmp.path().to_path_buf(), 1 << 20).unwrap();
        let path = small.entry_path("reference", &key(7));
        fs::write(&path, huge_header("reference", &key(7))).unwrap();
        assert_eq!(small.get("reference", &key(7)), None);
        assert!(!path.exists());
        // Within an unbounded max_bytes: rejected as it disagrees with the file's length
        // (allocating 1 TB first would abort the test process).
        let unbounded = DiskCache::open(tmp.path().to_path_buf(), u64::MAX).unwrap();
        fs::write(&path, huge_header("reference", &key(7))).unwrap();
        assert_eq!(unbounded.get("reference", &key(7)), None);
        assert!(!path.exists());
        // u64::MAX declared: the length arithmetic must not overflow.
        let mut h = huge_header("reference", &key(7));
        let at = FIXED_PREFIX + "reference".len();
        h[at..at + 8].copy_from_slice(&u64::MAX.to_le_bytes());
        fs::write(&path, &h).unwrap();
        assert_eq!(unbounded.get("reference", &key(7)), None);
        assert!(!path.exists());
    }

    #[test]
    fn eviction_keeps_total_within_bound() {
        let tmp = TempDir::new("evict-bound");
        let max = 4_000;
        let cache = DiskCache::open(tmp.path().to_path_buf(), max).unwrap();
        for i in 0..50u8 {
            let len = (i as usize * 337) % 1_500;
            let p = payload(len, i);
            cache.put("reference", &key(i), &p).unwrap();
            let total = cache.total_bytes();
            assert!(total <= max, "after put {i}: {total} > {max}");
            assert_eq!(
                cache.get("reference", &key(i)).unwrap(),
                p,
                "the newest entry is kept"
            );
        }
        assert!(cache.total_bytes() > 0);
    }

    #[test]
    fn eviction_removes_least_recently_used_first() {
        let tmp = TempDir::new("evict-lru");
        let kind = "reference";
        let size = 100 + entry_overhead(kind);
        // Room for exactly three entries.
        let cache = DiskCache::open(tmp.path().to_path_buf(), 3 * size).unwrap();
        for n in 1..=3 {
            cache.put(kind, &key(n), &payload(100, n)).unwrap();
        }
        // Written an hour, 30 minutes and 10 minutes ago: 1 is the oldest.
        for (n, minutes) in [(1, 60), (2, 30), (3, 10)] {
            set_age(
                &cache.entry_path(kind, &key(n)),
                Duration::from_secs(60 * minutes),
            );
        }
        // Reading 1 makes it the most recently used; 2 is now the least.
        assert!(cache.get(kind, &key(1)).is_some());
        cache.put(kind, &key(4), &payload(100, 4)).unwrap();
        assert_eq!(cache.total_bytes(), 3 * size);
        assert!(
            !cache.entry_path(kind, &key(2)).exists(),
            "2 was least recently used"
        );
        for n in [1, 3, 4] {
            assert_eq!(
                cache.get(kind, &key(n)).unwrap(),
                payload(100, n),
                "{n} kept"
            );
        }
        // Make 3 the least recently used: it goes next.
        set_age(&cache.entry_path(kind, &key(3)), Duration::from_secs(60));
        cache.put(kind, &key(5), &payload(100, 5)).unwrap();
        assert!(!cache.entry_path(kind, &key(3)).exists());
        assert!(cache.entry_path(kind, &key(1)).exists());
        // A bigger entry evicts as many as it needs.
        cache.put(kind, &key(6), &payload(150, 6)).unwrap();
        assert!(cache.total_bytes() <= 3 * size);
        assert!(cache.get(kind, &key(6)).is_some());
    }

    #[test]
    fn the_entry_just_put_is_never_evicted() {
        // Entries dated in the future (a skewed clock, a shared network drive) look newer than
        // the one being put; eviction still keeps the new one.
        let tmp = TempDir::new("evict-keep");
        let size = 50 + entry_overhead("reference");
        let cache = DiskCache::open(tmp.path().to_path_buf(), 2 * size).unwrap();
        for n in 1..=2 {
            cache.put("reference", &key(n), &payload(50, n)).unwrap();
            let f = OpenOptions::new()
                .write(true)
                .open(cache.entry_path("reference", &key(n)));
            f.unwrap()
                .set_modified(SystemTime::now() + Duration::from_secs(3_600))
                .unwrap();
        }
        cache.put("reference", &key(3), &payload(50, 3)).unwrap();
        assert_eq!(cache.get("reference", &key(3)).unwrap(), payload(50, 3));
        assert_eq!(cache.total_bytes(), 2 * size);
    }

    #[test]
    fn entry_longer_than_max_bytes_of_a_smaller_cache_is_rejected() {
        let tmp = TempDir::new("shrunk");
        let big = DiskCache::open(tmp.path().to_path_buf(), 10_000).unwrap();
        big.put("reference", &key(1), &payload(5_000, 1)).unwrap();
        let small = DiskCache::open(tmp.path().to_path_buf(), 1_000).unwrap();
        assert_eq!(small.get("reference", &key(1)), None);
        assert_eq!(small.total_bytes(), 0, "it is deleted");
    }

    #[test]
    fn payload_larger_than_max_bytes_is_not_stored() {
        let tmp = TempDir::new("oversized");
        let max = 1_000;
        let cache = DiskCache::open(tmp.path().to_path_buf(), max).unwrap();
        cache.put("reference", &key(1), b"small").unwrap();
        let before = cache.total_bytes();
        cache.put("reference", &key(2), &payload(1_001, 2)).unwrap();
        assert_eq!(cache.get("reference", &key(2)), None);
        assert_eq!(
            cache.total_bytes(),
            before,
            "nothing stored, nothing evicted"
        );
        assert!(cache.get("reference", &key(1)).is_some());
        // One byte too big with the overhead counted, and exactly fitting.
        let fits = (max - entry_overhead("reference")) as usize;
        cache
            .put("reference", &key(3), &payload(fits + 1, 3))
            .unwrap();
        assert_eq!(cache.get("reference", &key(3)), None);
        cache.put("reference", &key(4), &payload(fits, 4)).unwrap();
        assert_eq!(cache.get("reference", &key(4)).unwrap(), payload(fits, 4));
        assert_eq!(cache.total_bytes(), max);
        // A cache of size 0 stores nothing.
        let zero = DiskCache::open(tmp.path().join("zero"), 0).unwrap();
        zero.put("reference", &key(5), b"").unwrap();
        assert_eq!(zero.total_bytes(), 0);
        assert!(names(zero.dir()).is_empty());
    }

    #[test]
    fn leftover_temp_files_are_removed_on_open() {
        let tmp = TempDir::new("leftover");
        let dir = tmp.path().to_path_buf();
        let cache = DiskCache::open(dir.clone(), 1 << 20).unwrap();
        cache.put("reference", &key(1), b"kept").unwrap();
        let stale = dir.join(".sscache-99999-0.tmp");
        let fresh = dir.join(".sscache-99999-1.tmp");
        let unrelated = dir.join("notes.txt");
        for p in [&stale, &fresh, &unrelated] {
            fs::write(p, b"partial").unwrap();
        }
        set_age(&stale, STALE_TEMP_AGE + Duration::from_secs(60));
        set_age(&unrelated, Duration::from_secs(86_400));
        let cache = DiskCache::open(dir.clone(), 1 << 20).unwrap();
        assert!(!stale.exists(), "a crash's leftover is removed");
        assert!(
            fresh.exists(),
            "a temp file being written by another process is left alone"
        );
        assert!(
            unrelated.exists(),
            "files that aren't the cache's are never touched"
        );
        assert_eq!(cache.get("reference", &key(1)).unwrap(), b"kept");
        assert_eq!(
            cache.total_bytes(),
            4 + entry_overhead("reference"),
            "temp files don't count"
        );
        // No temp file of open's own write probe or of put is left behind.
        cache.put("reference", &key(2), b"x").unwrap();
        let temps: Vec<_> = names(&dir)
            .into_iter()
            .filter(|n| n.ends_with(".tmp"))
            .collect();
        assert_eq!(temps, vec![".sscache-99999-1.tmp".to_string()]);
    }

    #[test]
    fn directory_that_cannot_be_created_is_a_typed_error() {
        let tmp = TempDir::new("bad-dir");
        fs::create_dir_all(tmp.path()).unwrap();
        let file = tmp.path().join("a-file");
        fs::write(&file, b"not a directory").unwrap();
        // Parent is a regular file.
        let under_file = file.join("cache");
        let e = DiskCache::open(under_file.clone(), 1 << 20).unwrap_err();
        assert!(
            e.to_string().contains(&under_file.display().to_string()),
            "{e}"
        );
        match e {
            DiskCacheError::CreateDir { path, .. } => assert_eq!(path, under_file),
            other => panic!("expected CreateDir, got {other:?}"),
        }
        // The path itself is a regular file.
        match DiskCache::open(file.clone(), 1 << 20) {
            Err(DiskCacheError::CreateDir { path, .. }) => assert_eq!(path, file),
            other => panic!("expected CreateDir, got {other:?}"),
        }
    }

    #[cfg(unix)]
    #[test]
    fn unwritable_directory_is_a_typed_error() {
        use std::os::unix::fs::PermissionsExt;
        let tmp = TempDir::new("read-only");
        let dir = tmp.path().join("ro");
        fs::create_dir_all(&dir).unwrap();
        fs::set_permissions(&dir, fs::Permissions::from_mode(0o555)).unwrap();
        // Root ignores permission bits; then there is nothing to check.
        let writable_anyway = File::create(dir.join("probe")).is_ok();
        let result = DiskCache::open(dir.clone(), 1 << 20);
        fs::set_permissions(&dir, fs::Permissions::from_mode(0o755)).unwrap();
        if !writable_anyway {
            match result {
                Err(DiskCacheError::NotWritable { path, .. }) => assert_eq!(path, dir),
                other => panic!("expected NotWritable, got {other:?}"),
            }
        }
    }

    #[test]
    fn invalid_kinds_are_refused() {
        let tmp = TempDir::new("kind");
        let cache = DiskCache::open(tmp.path().to_path_buf(), 1 << 20).unwrap();
        let long = "k".repeat(MAX_KIND_LEN + 1);
        for kind in [
            "",
            "../up",
            "a/b",
            "Upper",
            "dot.ted",
            "spa ce",
            "é",
            long.as_str(),
        ] {
            match cache.put(kind, &key(1), b"x") {
                Err(DiskCacheError::InvalidKind { kind: k, .. }) => assert_eq!(k, kind),
                other => panic!("{kind:?}: expected InvalidKind, got {other:?}"),
            }
            assert_eq!(cache.get(kind, &key(1)), None);
        }
        let longest = "k".repeat(MAX_KIND_LEN);
        cache.put(&longest, &key(1), b"x").unwrap();
        assert_eq!(cache.get(&longest, &key(1)).unwrap(), b"x");
        assert!(names(cache.dir()).iter().all(|n| is_entry_name(n)));
    }

    #[test]
    fn clear_removes_entries_only() {
        let tmp = TempDir::new("clear");
        let cache = DiskCache::open(tmp.path().to_path_buf(), 1 << 20).unwrap();
        for n in 0..5 {
            cache.put("reference", &key(n), &payload(10, n)).unwrap();
        }
        let unrelated = cache.dir().join("keep-me.bin");
        fs::write(&unrelated, b"user file").unwrap();
        cache.clear().unwrap();
        assert_eq!(cache.total_bytes(), 0);
        assert_eq!(cache.get("reference", &key(0)), None);
        assert_eq!(names(cache.dir()), vec!["keep-me.bin".to_string()]);
    }

    #[test]
    fn non_entry_under_an_entry_name_is_ignored_and_removed() {
        let tmp = TempDir::new("not-a-file");
        let cache = DiskCache::open(tmp.path().to_path_buf(), 1 << 20).unwrap();
        let path = cache.entry_path("reference", &key(1));
        fs::create_dir_all(&path).unwrap();
        assert_eq!(cache.get("reference", &key(1)), None);
        assert!(!path.exists());
        cache.put("reference", &key(1), b"ok").unwrap();
        assert_eq!(cache.get("reference", &key(1)).unwrap(), b"ok");
    }

    #[cfg(unix)]
    #[test]
    fn link_under_an_entry_name_is_removed_but_not_its_target() {
        let tmp = TempDir::new("link");
        let cache = DiskCache::open(tmp.path().join("cache"), 1 << 20).unwrap();
        cache.put("reference", &key(1), b"one").unwrap();
        // Even a link to a valid entry of the same key is not trusted.
        let target = tmp.path().join("elsewhere.bin");
        fs::copy(cache.entry_path("reference", &key(1)), &target).unwrap();
        let link = cache.entry_path("reference", &key(1));
        fs::remove_file(&link).unwrap();
        std::os::unix::fs::symlink(&target, &link).unwrap();
        assert_eq!(cache.get("reference", &key(1)), None);
        assert!(fs::symlink_metadata(&link).is_err(), "the link is deleted");
        assert!(target.exists(), "what it pointed to is not");
    }

    #[test]
    fn concurrent_writers_of_one_key_never_expose_a_corrupt_file() {
        let tmp = TempDir::new("concurrent");
        let dir = tmp.path().to_path_buf();
        DiskCache::open(dir.clone(), 1 << 24).unwrap();
        let payloads: Arc<Vec<Vec<u8>>> = Arc::new(
            (0..4)
                .map(|w| payload(20_000 + 1_000 * w, w as u8))
                .collect(),
        );
        std::thread::scope(|s| {
            for w in 0..4 {
                let dir = dir.clone();
                let payloads = Arc::clone(&payloads);
                // Each writer its own handle, as separate processes would have.
                s.spawn(move || {
                    let cache = DiskCache::open(dir, 1 << 24).unwrap();
                    for _ in 0..30 {
                        cache.put("reference", &key(1), &payloads[w]).unwrap();
                    }
                });
            }
            let payloads = Arc::clone(&payloads);
            let dir = dir.clone();
            s.spawn(move || {
                let cache = DiskCache::open(dir, 1 << 24).unwrap();
                for _ in 0..200 {
                    if let Some(p) = cache.get("reference", &key(1)) {
                        assert!(payloads.contains(&p), "a torn or mixed payload was read");
                    }
                }
            });
        });
        let cache = DiskCache::open(dir.clone(), 1 << 24).unwrap();
        let last = cache
            .get("reference", &key(1))
            .expect("a complete entry is left");
        assert!(payloads.contains(&last));
        assert!(
            names(&dir).iter().all(|n| is_entry_name(n)),
            "{:?}",
            names(&dir)
        );
    }

    #[test]
    fn default_dir_prefers_the_environment() {
        let platform = || Some(PathBuf::from("/home/u/.cache"));
        assert_eq!(
            default_dir_from(Some("/tmp/mine".into()), platform),
            Some(PathBuf::from("/tmp/mine"))
        );
        assert_eq!(
            default_dir_from(None, platform),
            Some(PathBuf::from("/home/u/.cache/samplescope/v1"))
        );
        assert_eq!(
            default_dir_from(Some("".into()), platform),
            Some(PathBuf::from("/home/u/.cache/samplescope/v1")),
            "an empty variable counts as unset"
        );
        assert_eq!(default_dir_from(None, || None), None);
        if let Some(d) = DiskCache::default_dir() {
            assert!(d.is_absolute() || std::env::var_os("SAMPLESCOPE_CACHE_DIR").is_some());
        }
    }

    #[test]
    fn entry_names_are_recognised_exactly() {
        let h = hex(&key(1));
        assert!(is_entry_name(&format!("reference-{h}.bin")));
        assert!(is_entry_name(&format!("a-b-{h}.bin")));
        assert!(!is_entry_name(&format!("-{h}.bin")));
        assert!(!is_entry_name(&format!("reference-{h}.tmp")));
        assert!(!is_entry_name(&format!(
            "reference-{}.bin",
            h.to_uppercase()
        )));
        assert!(!is_entry_name(&format!("reference_{h}.bin")));
        assert!(!is_entry_name(&format!("reference-{}.bin", &h[1..])));
        assert!(!is_entry_name("é-é.bin"));
        assert!(is_temp_name(".sscache-1-2.tmp"));
        assert!(!is_temp_name("sscache-1-2.tmp"));
    }

    fn image() -> ImagePayload {
        ImagePayload {
            width: 3,
            height: 2,
            values: vec![
                0.0,
                -1.5,
                f64::from_bits(0x7ff8_0000_0000_1234),
                f64::INFINITY,
                1e-42,
                7.25,
            ],
            error_estimate: Some(1.0e-4),
            method: "supersampled 64² — box".to_string(),
        }
    }

    fn same_bits(a: &ImagePayload, b: &ImagePayload) -> bool {
        a.width == b.width
            && a.height == b.height
            && a.values.len() == b.values.len()
            && a.values
                .iter()
                .zip(&b.values)
                .all(|(x, y)| x.to_bits() == y.to_bits())
            && a.error_estimate.map(f64::to_bits) == b.error_estimate.map(f64::to_bits)
            && a.method == b.method
    }

    #[test]
    fn image_payload_round_trip() {
        let full = image();
        let back = ImagePayload::from_bytes(&full.to_bytes()).unwrap();
        assert!(same_bits(&full, &back), "{back:?}");
        let bare = ImagePayload {
            width: 0,
            height: 5,
            values: vec![],
            error_estimate: None,
            method: String::new(),
        };
        assert_eq!(ImagePayload::from_bytes(&bare.to_bytes()).unwrap(), bare);
        // Layout: little-endian width and height, then the values.
        let b = full.to_bytes();
        assert_eq!(&b[0..4], &3u32.to_le_bytes());
        assert_eq!(&b[4..8], &2u32.to_le_bytes());
        assert_eq!(&b[8..16], &0.0f64.to_le_bytes());
        assert_eq!(&b[16..24], &(-1.5f64).to_le_bytes());
        assert_eq!(b[56], 1);
        assert_eq!(&b[57..65], &1.0e-4f64.to_le_bytes());
    }

    #[test]
    fn image_payload_rejects_bad_input() {
        let good = image().to_bytes();
        for len in 0..good.len() {
            assert_eq!(
                ImagePayload::from_bytes(&good[..len]),
                None,
                "truncated to {len}"
            );
        }
        let mut longer = good.clone();
        longer.push(0);
        assert_eq!(ImagePayload::from_bytes(&longer), None, "a trailing byte");
        // Width × height larger than the input (and than memory): no allocation, None.
        for (w, h) in [(u32::MAX, u32::MAX), (65_536, 65_536), (4, 2)] {
            let mut b = good.clone();
            b[0..4].copy_from_slice(&w.to_le_bytes());
            b[4..8].copy_from_slice(&h.to_le_bytes());
            assert_eq!(ImagePayload::from_bytes(&b), None, "{w} x {h}");
        }
        // An option tag other than 0 or 1.
        let mut b = good.clone();
        b[56] = 2;
        assert_eq!(ImagePayload::from_bytes(&b), None);
        // Invalid UTF-8 in the method.
        let mut bad = image();
        bad.method = "ab".to_string();
        let mut b = bad.to_bytes();
        let at = 8 + 48 + 9 + 4;
        assert_eq!(&b[at..at + 2], b"ab");
        b[at] = 0xff;
        assert_eq!(ImagePayload::from_bytes(&b), None);
        // A string length past the end.
        let mut b = good.clone();
        b[65..69].copy_from_slice(&u32::MAX.to_le_bytes());
        assert_eq!(ImagePayload::from_bytes(&b), None);
    }

    #[test]
    #[should_panic(expected = "width * height")]
    fn image_payload_with_wrong_value_count_panics() {
        let mut bad = image();
        bad.values.pop();
        bad.to_bytes();
    }

    #[test]
    fn image_payload_through_the_cache() {
        let tmp = TempDir::new("image");
        let cache = DiskCache::open(tmp.path().to_path_buf(), 1 << 20).unwrap();
        let img = image();
        cache.put("reference", &key(8), &img.to_bytes()).unwrap();
        let back = ImagePayload::from_bytes(&cache.get("reference", &key(8)).unwrap()).unwrap();
        assert!(same_bits(&img, &back));
    }
}
