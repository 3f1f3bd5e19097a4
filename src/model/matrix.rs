//! The projection matrix of a column: the first K dimensions of its points as a triangle of
//! small scatter plots, one cell per pair i < j, each with the pair's row of the projection
//! table (`core::metrics::cube::projections`); and the one picture of it (cells tinted by a
//! measure through a colour map, the points darkened over the tint) that the GUI shows and the
//! figure saves.
//!
//! Layout: cell (i, j) sits at grid column i and grid row K − 1 − j (row 0 at the top holds
//! j = K − 1): x is dimension i, y dimension j, so the triangle fills the upper left of a
//! (K − 1) × (K − 1) grid, as on axes where y grows upwards.
//!
//! The picture is drawn at the pixel size it is shown at ([`MatrixData::picture_sized`]: the
//! figure's plotting area, the panel's size on screen), never resampled afterwards: the gaps
//! between cells are a whole number of pixels, the same everywhere, and scale with the cells
//! (1/24 of a cell, at least one pixel: [`MatrixAxis`]). At its natural size (48-pixel cells)
//! the gaps are [`MATRIX_GAP`] pixels.

use super::Colormap;
use crate::core::metrics::cube::{ProjectionMeasure, ProjectionRow};

/// Pixels of a cell's side in the node's coverage images.
pub const MATRIX_CELL: usize = 48;
/// Pixels between two cells of the picture at its natural size ([`MATRIX_CELL`]-pixel cells);
/// at other sizes the gap keeps this share of a cell's pitch (cell plus gap), rounded to
/// whole pixels, at least one.
pub const MATRIX_GAP: usize = 2;

/// Where the cells of one side of the picture fall: cell k covers the pixels
/// `start(k) .. start(k) + len(k)` with `start(k) = round(k (side + gap) / g)`, so every gap is
/// exactly `gap` pixels and the cells differ by at most one pixel.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct MatrixAxis {
    /// The picture's side in pixels.
    pub side: usize,
    /// Pixels between two cells.
    pub gap: usize,
    /// Cells along the side.
    pub cells: usize,
}

impl MatrixAxis {
    /// The layout of `cells` cells over `side` pixels (the gap [`MATRIX_GAP`]/(cell + gap) of
    /// the pitch, at least one pixel; none for a single cell).
    pub fn new(cells: usize, side: usize) -> Self {
        let share = MATRIX_GAP as f64 / (MATRIX_CELL + MATRIX_GAP) as f64;
        let gap = if cells > 1 {
            ((side as f64 / cells as f64 * share).round() as usize).max(1)
        } else {
            0
        };
        MatrixAxis { side, gap, cells }
    }

    /// The side of `cells` cells of [`MATRIX_CELL`] pixels [`MATRIX_GAP`] apart.
    pub fn natural_side(cells: usize) -> usize {
        cells * MATRIX_CELL + cells.saturating_sub(1) * MATRIX_GAP
    }

    /// The first pixel of cell `k` (`k = cells`: one gap past the end).
    fn edge(&self, k: usize) -> usize {
        if self.cells == 0 {
            return 0;
        }
        (k * (self.side + self.gap) + self.cells / 2) / self.cells
    }

    /// Cell `k`'s first pixel and width.
    pub fn span(&self, k: usize) -> (usize, usize) {
        let (a, b) = (self.edge(k), self.edge(k + 1));
        (a, b.saturating_sub(a + self.gap))
    }

    /// The cell holding pixel `x`, if any (none in a gap or past the end).
    pub fn cell_at(&self, x: usize) -> Option<usize> {
        if self.cells == 0 || x >= self.side {
            return None;
        }
        let k = ((x * self.cells) / (self.side + self.gap)).min(self.cells - 1);
        // Rounding may put x in the cell before or after the estimate.
        (k.saturating_sub(1)..=(k + 1).min(self.cells - 1)).find(|&c| {
            let (a, w) = self.span(c);
            (a..a + w).contains(&x)
        })
    }
}

/// One cell: the pair, its measured row (when measured: rows come in while the node runs), and
/// the coverage of its scatter plot.
#[derive(Debug, Clone)]
pub struct MatrixCell {
    /// The dimensions `[i, j]`, i < j.
    pub pair: [usize; 2],
    /// The pair's projection-table row, once measured.
    pub row: Option<ProjectionRow>,
    /// [`MATRIX_CELL`]² coverage values (0 empty … 255 covered), row 0 at the top (x_j near 1).
    pub coverage: Vec<u8>,
}

/// The projection matrix of a column (the `Matrix` node's data).
#[derive(Debug, Clone)]
pub struct MatrixData {
    /// K: the dimensions shown (the cells are the pairs of 0..K).
    pub k: usize,
    /// The points' dimension D (K ≤ D).
    pub dims: usize,
    /// The number of points.
    pub n: usize,
    /// The cells, pairs in order (0,1), (0,2), … (K−2, K−1).
    pub cells: Vec<MatrixCell>,
}

impl MatrixData {
    /// The cell of pair (i, j), i < j < K.
    pub fn cell(&self, i: usize, j: usize) -> Option<&MatrixCell> {
        self.cells.iter().find(|c| c.pair == [i, j])
    }

    /// The grid's side in cells (K − 1).
    pub fn grid(&self) -> usize {
        self.k.saturating_sub(1)
    }

    /// The cell at grid column `gx` and grid row `gy` (row 0 at the top), if the triangle has
    /// one there.
    pub fn cell_at_grid(&self, gx: usize, gy: usize) -> Option<&MatrixCell> {
        let g = self.grid();
        if gx >= g || gy >= g {
            return None;
        }
        let (i, j) = (gx, g - gy);
        (i < j).then(|| self.cell(i, j)).flatten()
    }

    /// The grid position (column, row) of pair (i, j).
    pub fn grid_of(&self, [i, j]: [usize; 2]) -> (usize, usize) {
        (i, self.grid() - j)
    }

    /// The picture's side at its natural size ([`MATRIX_CELL`]-pixel cells).
    pub fn natural_side(&self) -> usize {
        MatrixAxis::natural_side(self.grid())
    }

    /// The pixel rectangle (x, y, width, height) of pair (i, j)'s cell in the picture of
    /// `width` × `height` pixels.
    pub fn cell_rect(&self, pair: [usize; 2], (width, height): (usize, usize)) -> [usize; 4] {
        let (gx, gy) = self.grid_of(pair);
        let g = self.grid();
        let (x, w) = MatrixAxis::new(g, width).span(gx);
        let (y, h) = MatrixAxis::new(g, height).span(gy);
        [x, y, w, h]
    }

    /// The cell under pixel (x, y) of the picture of `width` × `height` pixels, if any (none in
    /// a gap or outside the triangle).
    pub fn cell_at_pixel(
        &self,
        (x, y): (usize, usize),
        (width, height): (usize, usize),
    ) -> Option<&MatrixCell> {
        let g = self.grid();
        let gx = MatrixAxis::new(g, width).cell_at(x)?;
        let gy = MatrixAxis::new(g, height).cell_at(y)?;
        self.cell_at_grid(gx, gy)
    }

    /// Whether every cell is measured.
    pub fn complete(&self) -> bool {
        self.cells.iter().all(|c| c.row.is_some())
    }

    /// The smallest and largest value of `measure` over the measured cells, widened when
    /// empty (a t-value range starts at 0, the best); `None` when no cell has a value.
    pub fn range(&self, measure: ProjectionMeasure) -> Option<(f64, f64)> {
        let values = self
            .cells
            .iter()
            .filter_map(|c| c.row.and_then(|r| r.value(measure)));
        let (mut lo, mut hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
        if !lo.is_finite() {
            return None;
        }
        if measure == ProjectionMeasure::TValue {
            lo = 0.0;
            hi = hi.max(1.0);
        }
        if hi <= lo {
            let pad = if lo == 0.0 { 1e-3 } else { lo.abs() * 1e-3 };
            (lo, hi) = (lo - pad, hi + pad);
        }
        Some((lo, hi))
    }

    /// The picture at its natural size ([`Self::natural_side`]: [`MATRIX_CELL`]-pixel cells
    /// [`MATRIX_GAP`] apart): see [`Self::picture_sized`].
    pub fn picture(
        &self,
        measure: ProjectionMeasure,
        colormap: Colormap,
    ) -> (usize, usize, Vec<u8>) {
        let side = self.natural_side();
        self.picture_sized(measure, colormap, (side, side))
    }

    /// The picture: (width, height, RGB bytes) of the (K − 1)² grid of cells laid out over
    /// `width` × `height` pixels ([`MatrixAxis`]: even gaps of whole pixels); each cell tinted
    /// by its `measure` through `colormap` over [`MatrixData::range`] (light grey while
    /// unmeasured or without a value), its points darkened over the tint (the coverage image
    /// resampled to the cell: each pixel the darkest coverage it covers, so no point is lost
    /// when cells are smaller than [`MATRIX_CELL`]); white in the gaps and outside the
    /// triangle.
    pub fn picture_sized(
        &self,
        measure: ProjectionMeasure,
        colormap: Colormap,
        (width, height): (usize, usize),
    ) -> (usize, usize, Vec<u8>) {
        let (width, height) = (width.max(1), height.max(1));
        let mut rgb = vec![255u8; width * height * 3];
        let range = self.range(measure);
        // The source pixels [from(k, n), from(k + 1, n)) that destination pixel k of n covers.
        let from = |k: usize, n: usize| (k * MATRIX_CELL) / n.max(1);
        for cell in &self.cells {
            let tint = match (cell.row.and_then(|r| r.value(measure)), range) {
                (Some(v), Some((lo, hi))) => colormap.eval((v - lo) / (hi - lo)),
                _ => [210, 210, 210],
            };
            let [x0, y0, w, h] = self.cell_rect(cell.pair, (width, height));
            for r in 0..h {
                let rows = from(r, h)..from(r + 1, h).max(from(r, h) + 1);
                for c in 0..w {
                    let cols = from(c, w)..from(c + 1, w).max(from(c, w) + 1);
                    let a = rows
                        .clone()
                        .flat_map(|sr| cols.clone().map(move |sc| (sr, sc)))
                        .map(|(sr, sc)| cell.coverage[sr * MATRIX_CELL + sc])
                        .max()
                        .unwrap_or(0) as u32;
                    let o = ((y0 + r) * width + x0 + c) * 3;
                    for (k, &t) in tint.iter().enumerate() {
                        // Points are near black over the tint: t·(1 − a) + 20·a.
                        rgb[o + k] = ((t as u32 * (255 - a) + 20 * a + 127) / 255) as u8;
                    }
                }
            }
        }
        (width, height, rgb)
    }

    /// The table as CSV: `i,j,t_value,l2_star_discrepancy,min_distance`, pairs in order
    /// (empty fields where a value is missing).
    pub fn csv(&self) -> String {
        use std::fmt::Write as _;
        let mut out = String::from("i,j,t_value,l2_star_discrepancy,min_distance\n");
        for c in &self.cells {
            let [i, j] = c.pair;
            let (t, l2, md) = match c.row {
                Some(r) => (
                    r.t_value.map(|t| t.to_string()).unwrap_or_default(),
                    format!("{:?}", r.l2_star_discrepancy),
                    r.min_distance.map(|m| format!("{m:?}")).unwrap_or_default(),
                ),
                None => Default::default(),
            };
            let _ = writeln!(out, "{i},{j},{t},{l2},{md}");
        }
        out
    }
}

/// The coverage image of a cell: the 2D points `(x, y)` ([0,1)², y up) binned into
/// [`MATRIX_CELL`]² pixels (row 0 at the top), each pixel's count c shown as 255·(1 − e^(−λc))
/// with λ = max(1, pixels / n): a lone point is a dark pixel, a uniform dense set a mid grey.
pub fn coverage(points: impl Iterator<Item = (f64, f64)>, n: usize) -> Vec<u8> {
    let s = MATRIX_CELL;
    let mut counts = vec![0u32; s * s];
    for (x, y) in points {
        let c = ((x * s as f64) as usize).min(s - 1);
        let r = s - 1 - ((y * s as f64) as usize).min(s - 1);
        counts[r * s + c] += 1;
    }
    let lambda = ((s * s) as f64 / n.max(1) as f64).max(1.0) * 0.7;
    counts
        .iter()
        .map(|&c| (255.0 * (1.0 - (-lambda * c as f64).exp())).round() as u8)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn row(i: usize, j: usize, t: u32) -> ProjectionRow {
        ProjectionRow {
            dims: [i, j],
            t_value: Some(t),
            l2_star_discrepancy: 0.01 * (t + 1) as f64,
            min_distance: Some(0.1 / (t + 1) as f64),
        }
    }

    #[test]
    fn cells_sit_in_the_upper_left_triangle_and_the_picture_tints_them() {
        let k = 4;
        let cells = crate::core::metrics::cube::projections::pairs(k)
            .into_iter()
            .map(|[i, j]| MatrixCell {
                pair: [i, j],
                row: Some(row(i, j, (i + j) as u32)),
                coverage: vec![0; MATRIX_CELL * MATRIX_CELL],
            })
            .collect();
        let m = MatrixData {
            k,
            dims: 8,
            n: 16,
            cells,
        };
        // Row 0 holds j = 3 (i = 0, 1, 2), the last row j = 1 (i = 0 only).
        assert_eq!(m.cell_at_grid(0, 0).unwrap().pair, [0, 3]);
        assert_eq!(m.cell_at_grid(2, 0).unwrap().pair, [2, 3]);
        assert_eq!(m.cell_at_grid(0, 2).unwrap().pair, [0, 1]);
        assert!(m.cell_at_grid(1, 2).is_none() && m.cell_at_grid(3, 0).is_none());
        let natural = (m.natural_side(), m.natural_side());
        for c in &m.cells {
            let (gx, gy) = m.grid_of(c.pair);
            assert_eq!(m.cell_at_grid(gx, gy).unwrap().pair, c.pair);
            let [x, y, w, h] = m.cell_rect(c.pair, natural);
            assert_eq!((x, y, w, h), (gx * 50, gy * 50, MATRIX_CELL, MATRIX_CELL));
            assert_eq!(m.cell_at_pixel((x, y), natural).unwrap().pair, c.pair);
            let corner = (x + w - 1, y + h - 1);
            assert_eq!(m.cell_at_pixel(corner, natural).unwrap().pair, c.pair);
            assert!(m.cell_at_pixel((x + w, y), natural).is_none(), "the gap");
        }
        assert_eq!(m.range(ProjectionMeasure::TValue), Some((0.0, 5.0)));
        let (w, h, rgb) = m.picture(ProjectionMeasure::TValue, Colormap::Viridis);
        assert_eq!((w, h), (3 * MATRIX_CELL + 2 * MATRIX_GAP, w));
        let px = |x: usize, y: usize| [0, 1, 2].map(|k| rgb[(y * w + x) * 3 + k]);
        // Cell (0, 1) (t = 1) at the bottom left, cell (2, 3) (t = 5, the worst) top right of
        // the triangle; below the diagonal stays white.
        assert_eq!(px(1, h - 2), Colormap::Viridis.eval(0.2));
        assert_eq!(px(w - 2, 1), Colormap::Viridis.eval(1.0));
        assert_eq!(px(w - 2, h - 2), [255, 255, 255]);
        let csv = m.csv();
        assert!(csv.starts_with("i,j,t_value,l2_star_discrepancy,min_distance\n0,1,1,0.02,0.05\n"));
    }

    /// At any size the gaps are whole pixels, all equal, scaling with the cells (1/24 of a
    /// cell, at least 1), and the cells tile the side: what the picture draws is what
    /// `cell_at` finds.
    #[test]
    fn gaps_are_even_whole_pixels_at_any_size() {
        for g in [1, 2, 3, 7, 15] {
            let natural = MatrixAxis::new(g, MatrixAxis::natural_side(g));
            let want = if g > 1 { MATRIX_GAP } else { 0 };
            assert_eq!(natural.gap, want, "g = {g}");
            for side in [30, 97, 250, 333, 512, 748, 1000, 1497, 2000] {
                let a = MatrixAxis::new(g, side);
                let spans: Vec<(usize, usize)> = (0..g).map(|k| a.span(k)).collect();
                assert_eq!(spans[0].0, 0);
                let (last, w) = spans[g - 1];
                assert_eq!(last + w, side, "g = {g}, side = {side}");
                let gaps: Vec<usize> = spans.windows(2).map(|p| p[1].0 - p[0].0 - p[0].1).collect();
                assert!(gaps.iter().all(|&x| x == a.gap), "{gaps:?}");
                let widths: Vec<usize> = spans.iter().map(|s| s.1).collect();
                let (lo, hi) = (widths.iter().min().unwrap(), widths.iter().max().unwrap());
                assert!(hi - lo <= 1, "{widths:?}");
                if g > 1 {
                    // About 1/24 of a cell (2 px beside 48), at least one pixel.
                    let cell = widths[0] as f64;
                    assert!(
                        (a.gap as f64 - cell / 24.0).abs() <= 1.0,
                        "{} vs {cell}",
                        a.gap
                    );
                    assert!(a.gap >= 1);
                }
                for x in 0..side {
                    let inside = spans.iter().position(|&(s, w)| (s..s + w).contains(&x));
                    assert_eq!(a.cell_at(x), inside, "g = {g}, side = {side}, x = {x}");
                }
            }
        }
        // Twice the size, twice the gap.
        assert_eq!(
            MatrixAxis::new(15, 2 * 748).gap,
            2 * MatrixAxis::new(15, 748).gap
        );
    }

    #[test]
    fn a_smaller_picture_keeps_every_point() {
        let mut coverage = vec![0u8; MATRIX_CELL * MATRIX_CELL];
        coverage[17 * MATRIX_CELL + 31] = 255;
        let m = MatrixData {
            k: 2,
            dims: 2,
            n: 1,
            cells: vec![MatrixCell {
                pair: [0, 1],
                row: None,
                coverage,
            }],
        };
        for side in [10, 20, 48, 100] {
            let (_, _, rgb) =
                m.picture_sized(ProjectionMeasure::TValue, Colormap::Viridis, (side, side));
            let dark = rgb.chunks_exact(3).filter(|p| p[0] < 100).count();
            assert!(dark >= 1, "side {side}: the point is lost");
        }
    }

    #[test]
    fn coverage_darkens_the_pixel_of_each_point() {
        let c = coverage([(0.0, 0.0), (0.999, 0.999)].into_iter(), 2);
        let s = MATRIX_CELL;
        assert!(c[(s - 1) * s] > 200, "bottom left");
        assert!(c[s - 1] > 200, "top right");
        assert_eq!(c.iter().filter(|&&v| v > 0).count(), 2);
    }
}
