//! What a figure says about where its data came from.

use super::Colormap;

/// What a figure says about where its data came from: titles, metadata and file names, as
/// plain strings and numbers. The scene side builds it (`scene::figure::context`); the
/// display choices (`spectrum_range`, `spectrum_colormap`, `response_db`, `elementary_k`)
/// start at what the GUI first shows.
#[derive(Debug, Clone, PartialEq)]
pub struct FigureContext {
    /// The scene's title.
    pub scene_title: String,
    /// Short name of the scene for file names (e.g. its file stem `zone-plate-128-to-512`).
    pub scene_name: String,
    /// Index of the column in the scene.
    pub column: usize,
    /// The column's label (its pattern's name when it has none).
    pub column_title: String,
    /// File-name part naming the column: the pattern's name, then the label when it differs
    /// (sanitised), made unique within the scene.
    pub column_slug: String,
    /// The pattern's name (`imported` for a column showing points from a file).
    pub pattern: String,
    /// The pattern's parameters, `key=value` separated by spaces (for imported points the file
    /// name and whether the points were normalised).
    pub pattern_params: String,
    /// Number of points.
    pub n: usize,
    /// The column's seed.
    pub seed: u64,
    /// The test signal and its parameters (RON).
    pub signal: String,
    /// The reconstruction filter with its parameters and 2D mode (RON).
    pub filter: String,
    /// How the signal is sampled and the output size, e.g. `scattered, 512²`.
    pub recon: String,
    /// The periodogram's colour range in log10 P; `None` uses the data's own `auto_range`.
    pub spectrum_range: Option<(f32, f32)>,
    /// The periodogram's colour map.
    pub spectrum_colormap: Colormap,
    /// Plot |H| in dB instead of linear.
    pub response_db: bool,
    /// Draw the elementary intervals 2^k × 2^(m−k) (N = 2^m) under the points of the pattern
    /// figure with this k (the column's `elementary_k`; nothing is drawn when N is not a
    /// power of two; k above m is taken as m).
    pub elementary_k: Option<u32>,
    /// Draw the pattern's strata, (columns, rows), under its points (the column's `strata`,
    /// or the GUI's overlay; `scene::figure::strata` is the one rule, shared with the panel).
    pub strata: Option<(usize, usize)>,
    /// For a column in D > 2 dimensions (or a swapped pair), (i, j, D): its 2D figures show the
    /// projection (x_i, x_j) of its points in [0,1)^D; `None` for the 2D pattern itself.
    pub projection: Option<(usize, usize, usize)>,
    /// What tints the projection matrix's cells (the scene's `matrix.measure`).
    pub matrix_measure: crate::core::metrics::cube::ProjectionMeasure,
}

/// [`FigureContext::pattern`] of a column showing points from a file.
pub const IMPORTED: &str = "imported";

impl FigureContext {
    /// Whether the column's points come from its seed: false for imported points, whose
    /// captions then name no seed (the file's points have none).
    pub fn seeded(&self) -> bool {
        self.pattern != IMPORTED
    }

    /// "`sep`seed s" for a seeded column, nothing for imported points: the seed part of the
    /// captions.
    pub fn seed_part(&self, sep: &str) -> String {
        if self.seeded() {
            format!("{sep}seed {}", self.seed)
        } else {
            String::new()
        }
    }

    /// "label, N = n, seed s" (no seed for imported points): the column as the titles name it.
    pub fn column_caption(&self) -> String {
        let seed = self.seed_part(", ");
        match self.projection {
            None => format!("{}, N = {}{seed}", self.column_title, self.n),
            Some((i, j, d)) => format!(
                "{}, N = {}{seed}, x{i} × x{j} of D = {d}",
                self.column_title, self.n
            ),
        }
    }
}

/// Lower-case ASCII letters and digits; every other run of characters becomes one `-`;
/// at most 48 characters; never empty. What file names are made of.
pub fn sanitize(text: &str) -> String {
    let mut out = String::new();
    for c in text.chars() {
        if c.is_ascii_alphanumeric() {
            out.push(c.to_ascii_lowercase());
        } else if !out.ends_with('-') {
            out.push('-');
        }
    }
    let mut s = out.trim_matches('-').to_string();
    if s.len() > 48 {
        s.truncate(48);
        s = s.trim_end_matches('-').to_string();
    }
    if s.is_empty() {
        "untitled".into()
    } else {
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sanitize_keeps_ascii_alnum_and_collapses_the_rest() {
        assert_eq!(
            sanitize("Zone plate sampled at 128² → 512²"),
            "zone-plate-sampled-at-128-512"
        );
        assert_eq!(sanitize("  p1 = 11 "), "p1-11");
        assert_eq!(sanitize("²²"), "untitled");
        assert_eq!(sanitize(&"a".repeat(80)).len(), 48);
    }
}
