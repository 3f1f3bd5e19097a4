//! The display state every panel shares (ranges, colour map, overlays, lecture mode), persisted
//! between runs, and the unit-square transform the panels draw with.

use crate::model::Colormap;
use eframe::egui::{Pos2, Rect};
use serde::{Deserialize, Serialize};

/// Which image the zone-plate panel shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
pub enum ZoneImage {
    /// The reconstruction from the samples.
    #[default]
    Reconstruction,
    /// The reference image of the signal.
    Reference,
    /// |reconstruction − reference|.
    Error,
    /// The error's periodogram (log₁₀ P, centred).
    ErrorSpectrum,
}

/// Display state shared by the panels (persisted between runs).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct ViewState {
    /// Same spectrum display range in every column.
    pub lock_scales: bool,
    /// Locked spectrum range, log10 P: lower end.
    pub spectrum_lo: f32,
    /// Locked spectrum range, log10 P: upper end.
    pub spectrum_hi: f32,
    /// Colour map of the spectrum and the 2D response.
    pub colormap: Colormap,
    /// The image of the zone-plate panel.
    pub zone_image: ZoneImage,
    /// Nearest-neighbour magnification of the zone plate.
    pub zoom: u32,
    /// |H| in dB instead of linear.
    pub response_db: bool,
    /// Overlay on the pattern panel: the strata.
    pub show_strata: bool,
    /// Overlay on the pattern panel: discs of the minimum distance.
    pub show_min_disc: bool,
    /// Overlay on the pattern panel: the box of the star discrepancy.
    pub show_star_box: bool,
    /// Elementary intervals b^k × b^(m−k) in base 2: `Some(k)`.
    pub elementary_k: Option<u32>,
    /// Show wall times next to the panels (off for reproducible figures and snapshots).
    pub show_timings: bool,
    /// Lecture mode: light projector theme, large text, pictures never smaller.
    pub lecture: bool,
    /// Zoom factor of everything in lecture mode (fonts, widgets, plots).
    pub lecture_scale: f32,
    /// The controls side panel is hidden (F9).
    pub controls_hidden: bool,
    /// Folder the figures are saved into.
    pub figure_dir: String,
    /// Scale of PNG figures saved by Ctrl+S (1..=3).
    pub figure_scale: u32,
}

impl Default for ViewState {
    fn default() -> Self {
        ViewState {
            lock_scales: true,
            spectrum_lo: -1.0,
            spectrum_hi: 1.0,
            colormap: Colormap::Viridis,
            zone_image: ZoneImage::Reconstruction,
            zoom: 1,
            response_db: false,
            show_strata: false,
            show_min_disc: false,
            show_star_box: false,
            elementary_k: None,
            show_timings: true,
            lecture: false,
            lecture_scale: LECTURE_SCALE_DEFAULT,
            controls_hidden: false,
            figure_dir: "figures".into(),
            figure_scale: 2,
        }
    }
}

/// Default zoom factor of lecture mode.
pub const LECTURE_SCALE_DEFAULT: f32 = 1.6;
/// Range of the lecture-mode zoom factor.
pub const LECTURE_SCALE_RANGE: std::ops::RangeInclusive<f32> = 1.0..=3.0;

/// `screen_from_unit`: maps the unit square (y up) onto `rect`.
pub fn screen_from_unit(rect: Rect, p: [f64; 2]) -> Pos2 {
    Pos2::new(
        rect.left() + p[0] as f32 * rect.width(),
        rect.bottom() - p[1] as f32 * rect.height(),
    )
}
