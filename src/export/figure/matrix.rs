//! The projection matrix: the pairs of a column's first K dimensions as a triangle of scatter
//! plots tinted by the scene's measure (`model::MatrixData::picture_sized`, the picture the
//! panel shows, drawn at the plotting area's pixel size), dimension i across and j up, with the
//! measure's colour bar; its CSV is the pair table.

use super::draw::{empty, present, Frame, ImageSpec};
use super::{context_metadata, Area, Figure, Rgb};
use crate::export::ExportError;
use crate::model::{Colormap, ColumnData, FigureContext, FigureKind, ImageData};

/// The projection-matrix figure.
pub(super) struct Matrix;

const KIND: FigureKind = FigureKind::Matrix;

impl Figure for Matrix {
    fn kind(&self) -> FigureKind {
        KIND
    }

    fn base_size(&self) -> (u32, u32) {
        (590, 510)
    }

    fn title(&self, ctx: &FigureContext, data: &ColumnData) -> String {
        let k = data.matrix.data().map_or(0, |m| m.k);
        format!(
            "projection matrix of the first {k} dimensions, {}",
            ctx.column_caption()
        )
    }

    fn panel_title(&self, _ctx: &FigureContext, data: &ColumnData) -> String {
        let k = data.matrix.data().map_or(0, |m| m.k);
        format!("projection matrix, first {k} dimensions")
    }

    fn has_data(&self, data: &ColumnData) -> bool {
        data.matrix.is_ready()
    }

    fn check(&self, data: &ColumnData) -> Result<(), ExportError> {
        let m = present(KIND, data.matrix.data())?;
        if m.cells.is_empty() {
            return Err(empty(KIND, "the matrix has no pair of dimensions"));
        }
        Ok(())
    }

    fn draw(&self, f: &mut Frame<'_, '_>, body: &Area<'_>) -> Result<(), ExportError> {
        let m = present(KIND, f.data.matrix.data())?;
        let measure = f.ctx.matrix_measure;
        // The figures keep to one colour map: viridis, as the spectrum's default.
        let colormap = Colormap::Viridis;
        let g = m.grid();
        // The values behind the tints, one per grid cell (NaN outside the triangle).
        let values = ImageData::new(
            g,
            g,
            (0..g * g)
                .map(|k| {
                    m.cell_at_grid(k % g, k / g)
                        .and_then(|c| c.row)
                        .and_then(|r| r.value(measure))
                        .map_or(f32::NAN, |v| v as f32)
                })
                .collect(),
        );
        let (lo, hi) = m.range(measure).unwrap_or((0.0, 1.0));
        let bar = format!(
            "{}{}",
            measure.label(),
            if m.range(measure).is_none() {
                " (none: N not 2^m)"
            } else {
                ""
            }
        );
        let spec = ImageSpec {
            image: &values,
            x: -0.5..(g as f64 - 0.5),
            y: 0.5..(g as f64 + 0.5),
            x_desc: "dimension i",
            y_desc: "dimension j",
            integer_ticks: true,
            lo,
            hi,
            colormap,
            bar: Some(&bar),
        };
        // Drawn at the plotting area's pixel size, so that the gaps between cells are even
        // whole pixels at every scale (a fixed-size picture scaled to it would alias them).
        let rgb = |w: u32, h: u32| {
            let (w, h, data) = m.picture_sized(measure, colormap, (w as usize, h as usize));
            Rgb {
                width: w as u32,
                height: h as u32,
                data,
            }
        };
        f.picture(body, KIND, rgb, &spec)
    }

    fn csv(&self, data: &ColumnData) -> Result<String, ExportError> {
        self.check(data)?;
        Ok(present(KIND, data.matrix.data())?.csv())
    }

    /// The context, K and D, and the measure with its range.
    fn metadata(&self, ctx: &FigureContext, data: &ColumnData) -> Vec<(String, String)> {
        let mut md = context_metadata(ctx);
        if let Some(m) = data.matrix.data() {
            md.push(("dimensions".into(), format!("first {} of {}", m.k, m.dims)));
            let measure = ctx.matrix_measure;
            let range = m
                .range(measure)
                .map_or("none".into(), |(lo, hi)| format!("[{lo}, {hi}]"));
            md.push(("measure".into(), format!("{} in {range}", measure.label())));
        }
        md
    }
}
