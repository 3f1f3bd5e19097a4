//! The periodogram image (log10 P through a colour map) with its colour bar; and the same
//! image without its bar ([`SpectrumWithoutBar`]), which a composite of locked scales draws
//! beside one shared bar ([`SharedBar`]).

use super::draw::{
    bar_axis, draw_err, empty, ordered_range, present, Frame, ImageSpec, BAR_PART, MARGIN, X_LABEL,
};
use super::{context_metadata, Area, Figure};
use crate::export::ExportError;
use crate::model::{Colormap, ColumnData, FigureContext, FigureKind};
use plotters::prelude::*;
use std::fmt::Write as _;

/// The periodogram figure.
pub(super) struct Spectrum;

const KIND: FigureKind = FigureKind::Spectrum;

/// The description of the colour bar: the quantity, and where white noise (E[P] = 1) sits.
const BAR_DESC: &str = "log₁₀ P   (white noise: 0)";

/// Draws the periodogram image into `body`, with its colour bar when `bar`.
fn draw_periodogram(f: &mut Frame<'_, '_>, body: &Area<'_>, bar: bool) -> Result<(), ExportError> {
    let s = present(KIND, f.data.spectrum.data())?;
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
            bar: bar.then_some(BAR_DESC),
        },
    )
}

impl Figure for Spectrum {
    fn kind(&self) -> FigureKind {
        KIND
    }

    fn base_size(&self) -> (u32, u32) {
        (590, 510)
    }

    fn title(&self, ctx: &FigureContext, _data: &ColumnData) -> String {
        format!("periodogram, {}", ctx.column_caption())
    }

    fn panel_title(&self, _ctx: &FigureContext, _data: &ColumnData) -> String {
        "periodogram".to_string()
    }

    fn has_data(&self, data: &ColumnData) -> bool {
        data.spectrum.is_ready()
    }

    fn check(&self, data: &ColumnData) -> Result<(), ExportError> {
        let s = present(KIND, data.spectrum.data())?;
        if s.image.width == 0 || s.image.height == 0 {
            return Err(empty(KIND, "the periodogram image is empty"));
        }
        Ok(())
    }

    fn draw(&self, f: &mut Frame<'_, '_>, body: &Area<'_>) -> Result<(), ExportError> {
        draw_periodogram(f, body, true)
    }

    fn csv(&self, data: &ColumnData) -> Result<String, ExportError> {
        let s = present(KIND, data.spectrum.data())?;
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
        if let Some(s) = data.spectrum.data() {
            let (lo, hi) = ctx.spectrum_range.unwrap_or(s.auto_range);
            m.push(("colour range".into(), format!("log10 P in [{lo}, {hi}]")));
        }
        m
    }
}

/// The periodogram figure without its colour bar: [`BAR_PART`] narrower, the same square
/// image, title, data, CSV and metadata. Composites draw it where every column shares one
/// colour range, beside one [`SharedBar`].
pub(super) struct SpectrumWithoutBar;

impl Figure for SpectrumWithoutBar {
    fn kind(&self) -> FigureKind {
        KIND
    }

    fn base_size(&self) -> (u32, u32) {
        let (w, h) = Spectrum.base_size();
        (w - BAR_PART, h)
    }

    fn title(&self, ctx: &FigureContext, data: &ColumnData) -> String {
        Spectrum.title(ctx, data)
    }

    fn panel_title(&self, ctx: &FigureContext, data: &ColumnData) -> String {
        Spectrum.panel_title(ctx, data)
    }

    fn has_data(&self, data: &ColumnData) -> bool {
        Spectrum.has_data(data)
    }

    fn check(&self, data: &ColumnData) -> Result<(), ExportError> {
        Spectrum.check(data)
    }

    fn draw(&self, f: &mut Frame<'_, '_>, body: &Area<'_>) -> Result<(), ExportError> {
        draw_periodogram(f, body, false)
    }

    fn csv(&self, data: &ColumnData) -> Result<String, ExportError> {
        Spectrum.csv(data)
    }

    fn metadata(&self, ctx: &FigureContext, data: &ColumnData) -> Vec<(String, String)> {
        Spectrum.metadata(ctx, data)
    }
}

/// The one colour bar of periodograms drawn with a shared range `lo..hi` through `colormap`:
/// [`BAR_PART`] wide and as high as the periodogram figure, its bar level with their images
/// (the same margins and label areas as the bar of [`Spectrum`]); its title band says
/// "all columns".
pub(super) struct SharedBar {
    pub lo: f64,
    pub hi: f64,
    pub colormap: Colormap,
}

impl Figure for SharedBar {
    fn kind(&self) -> FigureKind {
        KIND
    }

    fn base_size(&self) -> (u32, u32) {
        (BAR_PART, Spectrum.base_size().1)
    }

    fn title(&self, _ctx: &FigureContext, _data: &ColumnData) -> String {
        "all columns".into()
    }

    fn has_data(&self, _data: &ColumnData) -> bool {
        true
    }

    fn check(&self, _data: &ColumnData) -> Result<(), ExportError> {
        Ok(())
    }

    fn draw(&self, f: &mut Frame<'_, '_>, body: &Area<'_>) -> Result<(), ExportError> {
        let look = f.look;
        let de = |e| draw_err(KIND, e);
        let mut bar = ChartBuilder::on(body)
            .margin_top(look.u(MARGIN))
            .margin_bottom(look.u(MARGIN))
            .margin_left(look.u(14))
            .margin_right(look.u(4))
            .x_label_area_size(look.u(X_LABEL))
            .right_y_label_area_size(look.u(68))
            .build_cartesian_2d(0.0..1.0, self.lo..self.hi)
            .map_err(de)?;
        // The gradient as 256 bands, lowest value at the bottom.
        let steps = 256usize;
        let span = self.hi - self.lo;
        bar.draw_series((0..steps).map(|i| {
            let (a, b) = (i as f64 / steps as f64, (i + 1) as f64 / steps as f64);
            let [r, g, bl] = self.colormap.eval((a + b) / 2.0);
            Rectangle::new(
                [(0.0, self.lo + a * span), (1.0, self.lo + b * span)],
                RGBColor(r, g, bl).filled(),
            )
        }))
        .map_err(de)?;
        bar_axis(&mut bar, BAR_DESC, look, KIND)
    }

    fn csv(&self, _data: &ColumnData) -> Result<String, ExportError> {
        Ok(format!("lo,hi\n{},{}\n", self.lo, self.hi))
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
            spectrum: crate::model::Slot::from(Arc::new(SpectrumData {
                image,
                auto_range: (0.0, 1.0),
                raps: vec![],
                anisotropy: vec![],
                stages: vec![],
                power: Arc::new(crate::core::spectrum::Spectrum {
                    m: 2,
                    power: vec![10.0, 100.0, 1000.0, 10000.0],
                    n_points: 4,
                    realizations: 1,
                    dc: crate::core::spectrum::DcMode::Show,
                }),
            })),
            ..Default::default()
        };
        let csv = Spectrum.csv(&d).unwrap();
        assert_eq!(csv, "kx,ky,log10_power\n-1,-1,3\n0,-1,4\n-1,0,1\n0,0,2\n");
        let e = super::super::raps::Raps.csv(&d).unwrap_err().to_string();
        assert!(e.contains("raps") && e.contains("empty"), "{e}");
    }
}
