//! Periodograms ready to display.

use super::ImageData;

/// A periodogram ready to display.
#[derive(Debug, Clone)]
pub struct SpectrumData {
    /// log10 P, row 0 = highest ky.
    pub image: ImageData,
    /// A display range from the data (2nd and 99.8th percentile of log10 P).
    pub auto_range: (f32, f32),
    /// Radially averaged power spectrum: (|k|, P).
    pub raps: Vec<[f64; 2]>,
    /// Anisotropy in dB: (|k|, A).
    pub anisotropy: Vec<[f64; 2]>,
    /// Wall time per stage (ms).
    pub stages: Vec<(String, f64)>,
    /// The periodogram itself (P at every frequency, DC with its true value): what
    /// `samplescope analyze` writes as CSV and averages over files.
    pub power: std::sync::Arc<crate::core::spectrum::Spectrum>,
}

/// Most decades of log10 P one shared colour range spans below its top.
pub const SHARED_DECADES: f32 = 4.0;

/// A range narrower than this (in decades) is degenerate: nearly every frequency has the same
/// power (a lattice: P = 0, shown at the display floor, except at its dual lattice's peaks).
const DEGENERATE: f32 = 0.01;

/// One colour range for the periodograms of several columns, from their automatic ranges
/// (log10 P): the union of the ranges that are not degenerate, its bottom raised to at most
/// [`SHARED_DECADES`] below its top. A lattice's range (its 2nd and 99.8th percentiles both on
/// the display floor, 10⁻¹⁰) would otherwise stretch the shared bar over ten decades and
/// leave every other column's periodogram in a few colours; with the rule, the lattice's
/// zeros show at the bottom colour and its peaks at the top, as in its own figure. When every
/// range is degenerate, their union. `None` for no ranges.
pub fn shared_spectrum_range(ranges: &[(f32, f32)]) -> Option<(f32, f32)> {
    let finite: Vec<(f32, f32)> = ranges
        .iter()
        .copied()
        .filter(|(lo, hi)| lo.is_finite() && hi.is_finite())
        .collect();
    let wide: Vec<(f32, f32)> = finite
        .iter()
        .copied()
        .filter(|(lo, hi)| hi - lo >= DEGENERATE)
        .collect();
    let pick = if wide.is_empty() { &finite } else { &wide };
    let (lo, hi) = pick
        .iter()
        .copied()
        .reduce(|(lo, hi), r| (lo.min(r.0), hi.max(r.1)))?;
    Some((lo.max(hi - SHARED_DECADES), hi))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shared_range_is_the_union_of_the_columns_ranges() {
        assert_eq!(
            shared_spectrum_range(&[(-1.8, 0.7), (-1.2, 1.1)]),
            Some((-1.8, 1.1))
        );
        assert_eq!(shared_spectrum_range(&[]), None);
    }

    #[test]
    fn a_lattice_at_the_display_floor_does_not_stretch_the_shared_range() {
        // Fibonacci and rank-1 lattices: both percentiles on the 1e-10 floor.
        let lattice = (-10.0, -10.0 + 1e-3);
        let r = shared_spectrum_range(&[lattice, lattice, (-1.5, 1.6), (-2.0, 0.4)]).unwrap();
        assert_eq!(r, (-2.0, 1.6));
        // All lattices: their own union.
        assert_eq!(shared_spectrum_range(&[lattice, lattice]), Some(lattice));
    }

    #[test]
    fn the_shared_range_spans_at_most_four_decades_and_ignores_nan() {
        let r = shared_spectrum_range(&[(-9.0, 0.5), (-1.0, 3.0), (f32::NAN, 1.0)]).unwrap();
        assert_eq!(r, (3.0 - SHARED_DECADES, 3.0));
    }
}
