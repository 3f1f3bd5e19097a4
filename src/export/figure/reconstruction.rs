//! The reconstructed signal (grey, 0..1).

use super::csv::image_rows;
use super::draw::{empty, present, Frame, ImageSpec};
use super::{Area, Figure};
use crate::export::ExportError;
use crate::model::{Colormap, ColumnData, FigureContext, FigureKind, ImageData};

/// The reconstruction figure.
pub(super) struct Reconstruction;

const KIND: FigureKind = FigureKind::Reconstruction;

/// The spec of an image of the unit square through `colormap` over [lo, hi] (the
/// reconstruction, reference and error figures).
pub(super) fn unit_square_image<'a>(
    image: &'a ImageData,
    lo: f64,
    hi: f64,
    colormap: Colormap,
    bar: Option<&'a str>,
) -> ImageSpec<'a> {
    ImageSpec {
        image,
        x: 0.0..1.0,
        y: 0.0..1.0,
        x_desc: "x",
        y_desc: "y",
        integer_ticks: false,
        lo,
        hi,
        colormap,
        bar,
    }
}

/// Refuses an image without pixels.
pub(super) fn check_image(image: &ImageData, kind: FigureKind) -> Result<(), ExportError> {
    if image.width == 0 || image.height == 0 {
        return Err(empty(kind, "the image is empty"));
    }
    Ok(())
}

impl Figure for Reconstruction {
    fn kind(&self) -> FigureKind {
        KIND
    }

    fn base_size(&self) -> (u32, u32) {
        (480, 510)
    }

    fn title(&self, ctx: &FigureContext, _data: &ColumnData) -> String {
        format!("reconstruction, {}", ctx.column_caption())
    }

    fn panel_title(&self, _ctx: &FigureContext, _data: &ColumnData) -> String {
        "reconstruction".to_string()
    }

    fn has_data(&self, data: &ColumnData) -> bool {
        data.reconstruction.is_ready()
    }

    fn check(&self, data: &ColumnData) -> Result<(), ExportError> {
        check_image(&present(KIND, data.reconstruction.data())?.image, KIND)
    }

    fn draw(&self, f: &mut Frame<'_, '_>, body: &Area<'_>) -> Result<(), ExportError> {
        let r = present(KIND, f.data.reconstruction.data())?;
        let spec = unit_square_image(&r.image, 0.0, 1.0, Colormap::Greys, None);
        f.image(body, KIND, spec)
    }

    fn csv(&self, data: &ColumnData) -> Result<String, ExportError> {
        image_rows(&present(KIND, data.reconstruction.data())?.image, KIND)
    }
}
