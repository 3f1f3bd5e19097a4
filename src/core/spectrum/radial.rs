//! Radially averaged power spectrum (RAPS) and anisotropy.
//!
//! Annulus b (b = 1, 2, …) holds the frequencies with |k| ∈ [b − ½, b + ½), i.e. b = round(|k|);
//! |k|² is an integer, so no frequency lies on a boundary ((b + ½)² is never an integer). DC
//! (b = 0) is excluded. Only complete annuli are returned: b ≤ ⌊M/2⌋ − 1 for even M (the grid
//! stops at kx = M/2 − 1) and b ≤ (M − 1)/2 for odd M; beyond, the square grid cuts the annulus
//! and the statistics would be biased by which directions remain.
//!
//! Anisotropy (Lagae & Dutré 2008; PSA, Heck et al. 2013): the variance of P over the annulus
//! divided by the squared mean, in decibels, 10·log10(σ²/μ²). The variance is the population
//! variance (1/count) of the values on the annulus. White noise has P ~ Exp(1) at every k ≠ 0,
//! so σ²/μ² ≈ 1 → 0 dB for one periodogram and ≈ 1/K → −10·log10 K dB for a mean of K;
//! an isotropic spectrum approaches that floor, a directional one rises above it.

use super::{check_size, Spectrum, SpectrumError};

/// One annulus of the radial average.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RadialBin {
    /// Nominal radius b (integer-frequency units): the annulus is |k| ∈ [b − ½, b + ½).
    pub radius: f64,
    /// Mean of P over the annulus.
    pub mean_power: f64,
    /// Number of frequencies on the annulus.
    pub count: usize,
    /// 10·log10(variance / mean²): −∞ when P is constant on the annulus, NaN when the mean is 0.
    pub anisotropy_db: f64,
}

/// RAPS and anisotropy of `spectrum` over the complete annuli b = 1, …, b_max of width 1
/// (see the module docs); empty for M = 2 (one frequency on each side of DC is no annulus).
///
/// # Errors
/// [`SpectrumError::InvalidParam`] naming `power` when `power.len() ≠ m²` (a hand-built
/// [`Spectrum`]); [`SpectrumError::InvalidSize`] when m is out of range.
pub fn radial_average(spectrum: &Spectrum) -> Result<Vec<RadialBin>, SpectrumError> {
    let m = spectrum.m;
    check_size(m)?;
    if spectrum.power.len() != m * m {
        return Err(SpectrumError::InvalidParam {
            field: "power",
            value: format!("{} values", spectrum.power.len()),
            allowed: format!("m² = {} values", m * m),
        });
    }
    let b_max = if m % 2 == 0 { m / 2 - 1 } else { (m - 1) / 2 };
    if b_max == 0 {
        return Ok(Vec::new());
    }
    let c = (m / 2) as i64;
    // Annulus index of every frequency inside the largest complete annulus.
    let bin_of = |ix: usize, iy: usize| -> Option<usize> {
        let (kx, ky) = (ix as i64 - c, iy as i64 - c);
        // round(√r²) as ⌊√r² + ½⌋: equal for every integer r², whose root is at least
        // 1/(8(b + 1)) from any b + ½ (far above the rounding of the sum), and without the
        // library call `round` is without SSE4.1.
        let b = (((kx * kx + ky * ky) as f64).sqrt() + 0.5) as usize;
        (1..=b_max).contains(&b).then(|| b - 1)
    };
    let mut sum = vec![0.0f64; b_max];
    let mut count = vec![0usize; b_max];
    for iy in 0..m {
        for ix in 0..m {
            if let Some(b) = bin_of(ix, iy) {
                sum[b] += spectrum.power[iy * m + ix];
                count[b] += 1;
            }
        }
    }
    let mean: Vec<f64> = sum.iter().zip(&count).map(|(s, &n)| s / n as f64).collect();
    let mut squares = vec![0.0f64; b_max];
    for iy in 0..m {
        for ix in 0..m {
            if let Some(b) = bin_of(ix, iy) {
                let d = spectrum.power[iy * m + ix] - mean[b];
                squares[b] += d * d;
            }
        }
    }
    Ok((0..b_max)
        .map(|b| {
            let variance = squares[b] / count[b] as f64;
            RadialBin {
                radius: (b + 1) as f64,
                mean_power: mean[b],
                count: count[b],
                anisotropy_db: 10.0 * (variance / (mean[b] * mean[b])).log10(),
            }
        })
        .collect())
}

#[cfg(test)]
mod tests {
    /// The annulus rule ⌊√r² + ½⌋ equals round(√r²) for every |k|² on the largest grid
    /// (M = 4096: |k|² ≤ 2·2048²).
    #[test]
    fn half_up_truncation_equals_round_for_every_integer_square_radius() {
        for r2 in 0..=2 * 2048u64 * 2048 {
            let x = (r2 as f64).sqrt();
            assert_eq!((x + 0.5) as usize, x.round() as usize, "|k|² = {r2}");
        }
    }
}
