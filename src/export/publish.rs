//! The one publishing path: a [`Publication`] (a scene's figures as plain data), a [`Target`]
//! (one panel's figure, a column, the comparison, or everything), formats, scale and aspect
//! become named files. `samplescope render`, the GUI's Save menus and shortcuts, and the
//! image outputs of `recon` and `analyze` all publish through [`publish`]; the GUI's clipboard
//! copies through [`picture`]. Nothing here writes: the caller writes the files through the
//! one writer, `core::output`.

use super::figure::{
    column_file, column_file_name, column_rgba, comparison_file, comparison_file_name,
    comparison_rgba, comparison_size, figure, panel_csv, panel_file, panel_file_name, panel_rgba,
    Aspect, FileFormat, MAX_COMPOSITE_PIXELS,
};
use super::ExportError;
use crate::core::cancel::Cancel;
use crate::model::{ColumnData, FigureContext, FigureKind, Publication};

/// What is published.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Target {
    /// One figure of one column.
    Panel { column: usize, kind: FigureKind },
    /// A column's composite (its figures side by side).
    Column { column: usize },
    /// Every column, one row each.
    Comparison,
    /// What `render` writes: every column's figures (each format), every column's composite
    /// that has figures, and the comparison (pictures only; left out when too large).
    All,
}

/// A format of the published files.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Format {
    /// A picture: PNG, SVG or PDF.
    Picture(FileFormat),
    /// The figure's data (per figure only: a composite is a picture).
    Csv,
}

/// What [`publish`] made: the files in order, and the comparison it left out of
/// [`Target::All`] because it would exceed [`MAX_COMPOSITE_PIXELS`].
#[derive(Debug, Default)]
pub struct Published {
    /// (file name, bytes), in the order they were made.
    pub files: Vec<(String, Vec<u8>)>,
    /// (width, height) in pixels of the comparison left out of [`Target::All`].
    pub comparison_too_large: Option<(u64, u64)>,
}

/// The files of `target` in each of `formats` at `scale` (composites laid out to fill a frame
/// of `aspect`), named as `render` names them. A figure without data is an error naming it;
/// `cancel` is looked at between files ([`ExportError::Cancelled`]).
pub fn publish(
    p: &Publication,
    target: Target,
    formats: &[Format],
    scale: u32,
    aspect: Aspect,
    cancel: &Cancel,
) -> Result<Published, ExportError> {
    let mut out = Published::default();
    let mut add = |name: String, bytes: Vec<u8>| {
        // Between figures: drawing one does not look at the token.
        if cancel.is_cancelled() {
            return Err(ExportError::Cancelled);
        }
        out.files.push((name, bytes));
        Ok(())
    };
    let pictures: Vec<FileFormat> = formats
        .iter()
        .filter_map(|f| match f {
            Format::Picture(p) => Some(*p),
            Format::Csv => None,
        })
        .collect();
    match target {
        Target::Panel { column, kind } => {
            let (ctx, data) = column_of(p, column)?;
            check_data(kind, column, data)?;
            for &f in formats {
                let (name, bytes) = figure_file(kind, ctx, data, scale, f)?;
                add(name, bytes)?;
            }
        }
        Target::Column { column } => {
            let (ctx, data) = column_of(p, column)?;
            no_csv_only("column", &pictures)?;
            for &f in &pictures {
                let kinds = &p.composites[column];
                let bytes = column_file(kinds, ctx, data, scale, aspect, f)?;
                add(column_file_name(ctx, scale, f), bytes)?;
            }
        }
        Target::Comparison => {
            no_csv_only("comparison", &pictures)?;
            for &f in &pictures {
                let bytes = comparison_file(&p.comparison, &p.columns, scale, aspect, f)?;
                add(comparison_file_name(&p.name, p.n, scale, f), bytes)?;
            }
        }
        Target::All => {
            for (c, (ctx, data)) in p.columns.iter().enumerate() {
                for &kind in &p.figures[c] {
                    for &f in formats {
                        let (name, bytes) = figure_file(kind, ctx, data, scale, f)?;
                        add(name, bytes)?;
                    }
                }
                let own = &p.composites[c];
                if own.is_empty() {
                    continue;
                }
                for &f in &pictures {
                    let bytes = column_file(own, ctx, data, scale, aspect, f)?;
                    add(column_file_name(ctx, scale, f), bytes)?;
                }
            }
            let (w, h) = comparison_size(&p.comparison, &p.columns, scale, aspect);
            if !p.comparison.is_empty() && !pictures.is_empty() && w * h > MAX_COMPOSITE_PIXELS {
                out.comparison_too_large = Some((w, h));
            } else if !p.comparison.is_empty() {
                for &f in &pictures {
                    let bytes = comparison_file(&p.comparison, &p.columns, scale, aspect, f)?;
                    add(comparison_file_name(&p.name, p.n, scale, f), bytes)?;
                }
            }
        }
    }
    Ok(out)
}

/// The picture of `target` as (width, height, RGBA8 bytes, row 0 at the top) at `scale`, and
/// the name it would have as a file (without extension for a figure): for the clipboard.
/// [`Target::All`] is many pictures, not one: an error.
pub fn picture(
    p: &Publication,
    target: Target,
    scale: u32,
    aspect: Aspect,
) -> Result<(u32, u32, Vec<u8>, String), ExportError> {
    match target {
        Target::Panel { column, kind } => {
            let (ctx, data) = column_of(p, column)?;
            check_data(kind, column, data)?;
            let (w, h, rgba) = panel_rgba(kind, ctx, data, scale)?;
            Ok((w, h, rgba, panel_file_name(kind, ctx, None, "")))
        }
        Target::Column { column } => {
            let (ctx, data) = column_of(p, column)?;
            let (w, h, rgba) = column_rgba(&p.composites[column], ctx, data, scale, aspect)?;
            Ok((w, h, rgba, column_file_name(ctx, scale, FileFormat::Png)))
        }
        Target::Comparison => {
            let (w, h, rgba) = comparison_rgba(&p.comparison, &p.columns, scale, aspect)?;
            let name = comparison_file_name(&p.name, p.n, scale, FileFormat::Png);
            Ok((w, h, rgba, name))
        }
        Target::All => Err(ExportError::NotOnePicture),
    }
}

/// Figure `kind` of a column as a file in `format`.
fn figure_file(
    kind: FigureKind,
    ctx: &FigureContext,
    data: &ColumnData,
    scale: u32,
    format: Format,
) -> Result<(String, Vec<u8>), ExportError> {
    Ok(match format {
        Format::Picture(f) => (
            panel_file_name(kind, ctx, Some(scale), f.ext()),
            panel_file(kind, ctx, data, scale, f)?,
        ),
        Format::Csv => (
            panel_file_name(kind, ctx, None, "csv"),
            panel_csv(kind, ctx, data)?.into_bytes(),
        ),
    })
}

fn column_of(p: &Publication, column: usize) -> Result<(&FigureContext, &ColumnData), ExportError> {
    p.columns
        .get(column)
        .map(|(c, d)| (c, d))
        .ok_or(ExportError::OutOfRange {
            field: "column",
            value: column as i64,
            min: 0,
            max: p.columns.len() as i64 - 1,
        })
}

/// A figure asked for by itself must have its data (not computed yet, or not this column's).
fn check_data(kind: FigureKind, column: usize, data: &ColumnData) -> Result<(), ExportError> {
    if figure(kind).has_data(data) {
        Ok(())
    } else {
        Err(ExportError::EmptyData {
            figure: kind.name(),
            reason: format!("nothing computed yet for column {}", column + 1),
        })
    }
}

fn no_csv_only(what: &'static str, pictures: &[FileFormat]) -> Result<(), ExportError> {
    if pictures.is_empty() {
        Err(ExportError::NotAPicture { what })
    } else {
        Ok(())
    }
}
