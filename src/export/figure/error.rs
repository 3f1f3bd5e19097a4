//! |reconstruction − reference| (inferno, 0..max) with its colour bar; RMSE and PSNR in the
//! title.

use super::csv::image_rows;
use super::draw::{present, Frame};
use super::reconstruction::{check_image, unit_square_image};
use super::{Area, Figure};
use crate::export::ExportError;
use crate::model::{Colormap, ColumnData, FigureContext, FigureKind};

/// The error figure.
pub(super) struct Error;

const KIND: FigureKind = FigureKind::Error;

impl Figure for Error {
    fn kind(&self) -> FigureKind {
        KIND
    }

    fn base_size(&self) -> (u32, u32) {
        (590, 510)
    }

    fn title(&self, _ctx: &FigureContext, data: &ColumnData) -> String {
        match data.error.data() {
            Some(e) => format!("error, RMSE {:.4}, PSNR {:.2} dB", e.rmse, e.psnr),
            None => "error".to_string(),
        }
    }

    fn has_data(&self, data: &ColumnData) -> bool {
        data.error.is_ready()
    }

    fn check(&self, data: &ColumnData) -> Result<(), ExportError> {
        check_image(&present(KIND, data.error.data())?.image, KIND)
    }

    fn draw(&self, f: &mut Frame<'_, '_>, body: &Area<'_>) -> Result<(), ExportError> {
        let r = present(KIND, f.data.error.data())?;
        let spec = unit_square_image(
            &r.image,
            0.0,
            r.max_error.max(1e-6) as f64,
            Colormap::Inferno,
            Some("|reconstruction − reference|"),
        );
        f.image(body, KIND, spec)
    }

    fn csv(&self, data: &ColumnData) -> Result<String, ExportError> {
        image_rows(&present(KIND, data.error.data())?.image, KIND)
    }
}
