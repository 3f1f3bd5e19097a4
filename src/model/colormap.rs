//! The colour maps of float images, on screen (the shader's lookup table and the CPU
//! fallback) and in figures and PNGs, and the one CPU colorizer.

use serde::{Deserialize, Serialize};

/// A colour map for float images. Its serde names (`Viridis`, `Inferno`, `Greys`) are part of
/// the GUI's persisted state.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
pub enum Colormap {
    /// Perceptually uniform (matplotlib's viridis, from the `colorous` crate).
    #[default]
    Viridis,
    /// Perceptually uniform, high contrast (matplotlib's inferno).
    Inferno,
    /// Grey ramp, for images of signals.
    Greys,
}

impl Colormap {
    /// Every colour map.
    pub const ALL: [Colormap; 3] = [Colormap::Viridis, Colormap::Inferno, Colormap::Greys];

    /// Display name.
    pub fn name(self) -> &'static str {
        match self {
            Colormap::Viridis => "viridis",
            Colormap::Inferno => "inferno",
            Colormap::Greys => "greys",
        }
    }

    /// The sRGB colour at t ∈ [0, 1] (clamped; NaN maps to 0).
    pub fn eval(self, t: f64) -> [u8; 3] {
        let t = if t.is_nan() { 0.0 } else { t.clamp(0.0, 1.0) };
        let c = match self {
            Colormap::Viridis => colorous::VIRIDIS.eval_continuous(t),
            Colormap::Inferno => colorous::INFERNO.eval_continuous(t),
            Colormap::Greys => {
                let g = (t * 255.0).round() as u8;
                colorous::Color { r: g, g, b: g }
            }
        };
        [c.r, c.g, c.b]
    }

    /// 256 sRGBA entries, entry i = [`Colormap::eval`] at i/255 (the GPU's lookup table).
    pub fn lut(self) -> [[u8; 4]; 256] {
        let mut out = [[0u8; 4]; 256];
        for (i, o) in out.iter_mut().enumerate() {
            let [r, g, b] = self.eval(i as f64 / 255.0);
            *o = [r, g, b, 255];
        }
        out
    }
}

/// Maps `values` through `colormap`, [lo, hi] → [0, 1] (values outside clamped, NaN to the
/// first colour; a range with hi ≤ lo is taken as [lo, lo + 1]): 8-bit RGB, three bytes per
/// value, in the values' order.
pub fn colorize<T: Copy + Into<f64>>(
    values: &[T],
    lo: f64,
    hi: f64,
    colormap: Colormap,
) -> Vec<u8> {
    let span = if hi > lo { hi - lo } else { 1.0 };
    let mut rgb = Vec::with_capacity(values.len() * 3);
    for &v in values {
        rgb.extend_from_slice(&colormap.eval((v.into() - lo) / span));
    }
    rgb
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ends_nan_and_clamping() {
        let rgb = colorize(
            &[0.0f32, 1.0, 0.5, f32::NAN, 7.0],
            0.0,
            1.0,
            Colormap::Greys,
        );
        assert_eq!(
            rgb,
            vec![0, 0, 0, 255, 255, 255, 128, 128, 128, 0, 0, 0, 255, 255, 255]
        );
        assert_eq!(Colormap::Viridis.eval(0.0), [68, 1, 84]);
        assert_eq!(
            Colormap::Viridis.lut()[255][..3],
            Colormap::Viridis.eval(1.0)
        );
    }

    #[test]
    fn serde_names_of_the_persisted_gui_colormap_stay() {
        for (c, name) in [
            (Colormap::Viridis, "Viridis"),
            (Colormap::Inferno, "Inferno"),
            (Colormap::Greys, "Greys"),
        ] {
            assert_eq!(ron::to_string(&c).unwrap(), name);
            assert_eq!(ron::from_str::<Colormap>(name).unwrap(), c);
        }
    }
}
