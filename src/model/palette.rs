//! The colours that name things, shared by the panels and the figures (sRGB).

/// The data line of a plot (matplotlib's first colour); also the samples f(nT).
pub const DATA: [u8; 3] = [31, 119, 180];
/// Reference lines (white noise, ideal low-pass, zero).
pub const GUIDE: [u8; 3] = [150, 150, 150];
/// The Nyquist lines.
pub const NYQUIST: [u8; 3] = [200, 60, 60];
/// The points of a pattern, and the signal's own spectrum (replica k = 0) in figures.
pub const INK: [u8; 3] = [20, 20, 30];
/// The strata grid under the points.
pub const STRATA: [u8; 3] = [190, 190, 190];
/// The elementary-interval grid under the points.
pub const INTERVALS: [u8; 3] = [120, 160, 220];
/// The reconstruction f_r and its spectrum.
pub const RECON: [u8; 3] = [230, 120, 20];
/// The replicas F(ω − k f_s) of the sampling theorem, k = −3..=3.
pub const REPLICAS: [[u8; 3]; 7] = [
    [148, 103, 189],
    [44, 160, 44],
    [255, 127, 14],
    [31, 119, 180],
    [214, 39, 40],
    [23, 190, 207],
    [188, 189, 34],
];

/// The colours of the columns where several share one plot (the integration study), in
/// column order (matplotlib's tab10).
pub const SERIES: [[u8; 3]; 8] = [
    [31, 119, 180],
    [255, 127, 14],
    [44, 160, 44],
    [214, 39, 40],
    [148, 103, 189],
    [140, 86, 75],
    [227, 119, 194],
    [23, 190, 207],
];

/// The colour of column `i` on a shared plot (repeating after eight).
pub fn series(i: usize) -> [u8; 3] {
    SERIES[i % SERIES.len()]
}

/// The colour of replica k (|k| > 3 take the colour of ±3; k = 0, the signal itself, is
/// usually drawn in the text colour or [`INK`] instead).
pub fn replica(k: i64) -> [u8; 3] {
    REPLICAS[(k + 3).clamp(0, 6) as usize]
}
