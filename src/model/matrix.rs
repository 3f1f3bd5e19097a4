//! The projection matrix of a column: the first K dimensions of its points as a triangle of
//! small scatter plots, one cell per pair i < j, each with the pair's row of the projection
//! table (`core::metrics::cube::projections`); and the one picture of it (cells tinted by a
//! measure through a colour map, the points darkened over the tint) that the GUI shows and the
//! figure saves.
//!
//! Layout: cell (i, j) sits at grid column i and grid row K − 1 − j (row 0 at the top holds
//! j = K − 1): x is dimension i, y dimension j, so the triangle fills the upper left of a
//! (K − 1) × (K − 1) grid, as on axes where y grows upwards.

use super::Colormap;
use crate::core::metrics::cube::{ProjectionMeasure, ProjectionRow};

/// Pixels of a cell's side in the node's coverage images.
pub const MATRIX_CELL: usize = 48;
/// Pixels between two cells of the picture.
pub const MATRIX_GAP: usize = 2;

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

    /// The picture's pixel rectangle (x, y, side) of pair (i, j)'s cell.
    pub fn cell_rect(&self, pair: [usize; 2]) -> (usize, usize, usize) {
        let (gx, gy) = self.grid_of(pair);
        let step = MATRIX_CELL + MATRIX_GAP;
        (gx * step, gy * step, MATRIX_CELL)
    }

    /// The cell under the picture's pixel (x, y), if any (none in a gap or outside the
    /// triangle).
    pub fn cell_at_pixel(&self, x: usize, y: usize) -> Option<&MatrixCell> {
        let step = MATRIX_CELL + MATRIX_GAP;
        if x % step >= MATRIX_CELL || y % step >= MATRIX_CELL {
            return None;
        }
        self.cell_at_grid(x / step, y / step)
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

    /// The picture: (width, height, RGB bytes) of the (K − 1)² grid of [`MATRIX_CELL`]-pixel
    /// cells [`MATRIX_GAP`] apart; each cell tinted by its `measure` through `colormap` over
    /// [`MatrixData::range`] (light grey while unmeasured or without a value), its points
    /// darkened over the tint; white outside the triangle.
    pub fn picture(
        &self,
        measure: ProjectionMeasure,
        colormap: Colormap,
    ) -> (usize, usize, Vec<u8>) {
        let g = self.grid();
        let side = g * MATRIX_CELL + g.saturating_sub(1) * MATRIX_GAP;
        let mut rgb = vec![255u8; side * side * 3];
        let range = self.range(measure);
        for cell in &self.cells {
            let tint = match (cell.row.and_then(|r| r.value(measure)), range) {
                (Some(v), Some((lo, hi))) => colormap.eval((v - lo) / (hi - lo)),
                _ => [210, 210, 210],
            };
            let (gx, gy) = self.grid_of(cell.pair);
            let (x0, y0) = (
                gx * (MATRIX_CELL + MATRIX_GAP),
                gy * (MATRIX_CELL + MATRIX_GAP),
            );
            for r in 0..MATRIX_CELL {
                for c in 0..MATRIX_CELL {
                    let a = cell.coverage[r * MATRIX_CELL + c] as u32;
                    let o = ((y0 + r) * side + x0 + c) * 3;
                    for (k, &t) in tint.iter().enumerate() {
                        // Points are near black over the tint: t·(1 − a) + 20·a.
                        rgb[o + k] = ((t as u32 * (255 - a) + 20 * a + 127) / 255) as u8;
                    }
                }
            }
        }
        (side, side, rgb)
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
        for c in &m.cells {
            let (gx, gy) = m.grid_of(c.pair);
            assert_eq!(m.cell_at_grid(gx, gy).unwrap().pair, c.pair);
            let (x, y, s) = m.cell_rect(c.pair);
            assert_eq!(m.cell_at_pixel(x, y).unwrap().pair, c.pair);
            assert_eq!(m.cell_at_pixel(x + s - 1, y + s - 1).unwrap().pair, c.pair);
            assert!(m.cell_at_pixel(x + s, y).is_none(), "the gap");
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

    #[test]
    fn coverage_darkens_the_pixel_of_each_point() {
        let c = coverage([(0.0, 0.0), (0.999, 0.999)].into_iter(), 2);
        let s = MATRIX_CELL;
        assert!(c[(s - 1) * s] > 200, "bottom left");
        assert!(c[s - 1] > 200, "top right");
        assert_eq!(c.iter().filter(|&&v| v > 0).count(), 2);
    }
}
