//! The documented range of every scene value that has no descriptor: N, the columns, texts
//! (patterns, signals, filters, integrands, the spectrum, reconstruction — `recon.mode`'s spp
//! and grid included —, theorem and integration settings have descriptors,
//! [`crate::core::params`]).
//! [`Scene::validate`] enforces them and the GUI's widgets span exactly them, so no widget
//! can clamp a value a scene file may hold.

use std::ops::RangeInclusive;

/// Largest per-column elementary-interval exponent k (2^24 strata per axis).
pub const MAX_ELEMENTARY_K: u32 = 24;
/// Most columns a scene may have.
pub const MAX_COLUMNS: usize = 8;
/// Most points per column in a scene (interactive use).
pub const MAX_SCENE_N: usize = 1 << 20;

/// Points per column (`n`).
pub const N: RangeInclusive<usize> = 1..=MAX_SCENE_N;
/// Number of columns.
pub const COLUMNS: RangeInclusive<usize> = 1..=MAX_COLUMNS;
/// A column's elementary-interval exponent k (further bounded by N = 2^m: k ≤ m).
pub const ELEMENTARY_K: RangeInclusive<u32> = 0..=MAX_ELEMENTARY_K;
/// Characters of the scene's `title` (drawn above the comparison, in every figure's
/// metadata).
pub const TITLE_CHARS: usize = 256;
/// Characters of the scene's `notes`.
pub const NOTES_CHARS: usize = 4096;
/// Characters of a column's `label`.
pub const LABEL_CHARS: usize = 128;
/// Characters of an imported point file's `path` and `source`.
pub const PATH_CHARS: usize = 4096;
