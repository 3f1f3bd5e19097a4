//! The periodogram image (log10 P through a colour map) with its colour bar.

use super::draw::{empty, ordered_range, present, Frame, ImageSpec};
use super::{context_metadata, Area, Figure};
use crate::export::ExportError;
use crate::model::{ColumnData, FigureContext, PanelKind};
use std::fmt::Write as _;

/// The periodogram figure.
pub(super) struct Spectrum;

const KIND: PanelKind = PanelKind::Spectrum;

impl Figure for Spectrum {
    fn kind(&self) -> PanelKind {
        KIND
    }

    fn base_size(&self) -> (u32, u32) {
        (590, 510)
    }

    fn title(&self, ctx: &FigureContext, _data: &ColumnData) -> String {
        format!("periodogram, {}", ctx.column_caption())
    }

    fn has_data(&self, data: &ColumnData) -> bool {
        data.spectrum.is_some()
    }

    fn check(&self, data: &ColumnData) -> Result<(), ExportError> {
        let s = present(KIND, data.spectrum.as_ref())?;
        if s.image.width == 0 || s.image.height == 0 {
            return Err(empty(KIND, "the periodogram image is empty"));
        }
        Ok(())
    }

    fn draw(&self, f: &mut Frame<'_, '_>, body: &Area<'_>) -> Result<(), ExportError> {
        let s = present(KIND, f.data.spectrum.as_ref())?;
        let (lo, hi) = ordered_range(f.ctx.spectrum_range.unwrap_or(s.auto_range));
        let m = s.image.width as f64;
        let k0 = -((s.image.width / 2) as f64);
        let ky0 = -((s.image.height / 2) as f64);
        let kh = s.image.height as f64;
        let colormap = f.ctx.spectrum_colormap;
        f.image(
            body,
            KIND,
            ImageSpec {
                image: &s.image,
                x: (k0 - 0.5)..(k0 + m - 0.5),
                y: (ky0 - 0.5)..(ky0 + kh - 0.5),
                x_desc: "kx (cycles per unit)",
                y_desc: "ky",
                integer_ticks: true,
                lo,
                hi,
                colormap,
                bar: Some("log10 P"),
            },
        )
    }

    fn csv(&self, data: &ColumnData) -> Result<String, ExportError> {
        let s = present(KIND, data.spectrum.as_ref())?;
        let im = &s.image;
        if im.width == 0 || im.height == 0 {
            return Err(empty(KIND, "the periodogram image is empty"));
        }
        // Row 0 of the display image is the highest ky; k_min = −⌊M/2⌋.
        let kx0 = -((im.width / 2) as i64);
        let ky0 = -((im.height / 2) as i64);
        let mut out = String::from("kx,ky,log10_power\n");
        for r in (0..im.height).rev() {
            let ky = (im.height - 1 - r) as i64 + ky0;
            for c in 0..im.width {
                let _ = writeln!(
                    out,
                    "{},{ky},{}",
                    c as i64 + kx0,
                    im.values[r * im.width + c]
                );
            }
        }
        Ok(out)
    }

    /// The context and the colour range drawn.
    fn metadata(&self, ctx: &FigureContext, data: &ColumnData) -> Vec<(String, String)> {
        let mut m = context_metadata(ctx);
        if let Some(s) = &data.spectrum {
            let (lo, hi) = ctx.spectrum_range.unwrap_or(s.auto_range);
            m.push(("colour range".into(), format!("log10 P in [{lo}, {hi}]")));
        }
        m
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{ImageData, SpectrumData};
    use std::sync::Arc;

    #[test]
    fn spectrum_rows_run_from_lowest_ky_with_centred_frequencies() {
        // 2×2 display image: row 0 is ky = 0 (the highest), row 1 is ky = −1.
        let image = ImageData::new(2, 2, vec![1.0, 2.0, 3.0, 4.0]);
        let d = ColumnData {
            spectrum: Some(Arc::new(SpectrumData {
                image,
                auto_range: (0.0, 1.0),
                raps: vec![],
                anisotropy: vec![],
                stages: vec![],
            })),
            ..Default::default()
        };
        let csv = Spectrum.csv(&d).unwrap();
        assert_eq!(csv, "kx,ky,log10_power\n-1,-1,3\n0,-1,4\n-1,0,1\n0,0,2\n");
        let e = super::super::raps::Raps.csv(&d).unwrap_err().to_string();
        assert!(e.contains("raps") && e.contains("empty"), "{e}");
    }
}
