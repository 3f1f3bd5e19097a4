//! The reference image of the signal (grey, 0..1).

use super::csv::image_rows;
use super::draw::{present, Frame};
use super::reconstruction::{check_image, unit_square_image};
use super::{Area, Figure};
use crate::export::ExportError;
use crate::model::{Colormap, ColumnData, FigureContext, FigureKind};

/// The reference figure.
pub(super) struct Reference;

const KIND: FigureKind = FigureKind::Reference;

impl Figure for Reference {
    fn kind(&self) -> FigureKind {
        KIND
    }

    fn base_size(&self) -> (u32, u32) {
        (480, 510)
    }

    fn title(&self, _ctx: &FigureContext, _data: &ColumnData) -> String {
        "reference".to_string()
    }

    fn has_data(&self, data: &ColumnData) -> bool {
        data.reference.is_ready()
    }

    fn check(&self, data: &ColumnData) -> Result<(), ExportError> {
        check_image(&present(KIND, data.reference.data())?.image, KIND)
    }

    fn draw(&self, f: &mut Frame<'_, '_>, body: &Area<'_>) -> Result<(), ExportError> {
        let r = present(KIND, f.data.reference.data())?;
        let spec = unit_square_image(&r.image, 0.0, 1.0, Colormap::Greys, None);
        f.image(body, KIND, spec)
    }

    fn csv(&self, data: &ColumnData) -> Result<String, ExportError> {
        image_rows(&present(KIND, data.reference.data())?.image, KIND)
    }
}
