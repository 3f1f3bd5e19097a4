//! Point-set spectral analysis: periodograms (exact DFT and a type-1 NUFFT), averages over
//! realizations, the radially averaged power spectrum (RAPS), anisotropy, and the pair
//! correlation function g(r).
//!
//! Pure computation: never imports egui, eframe or wgpu.
//!
//! # Conventions
//!
//! - **Points** live in the unit torus [0,1)² as `f64` ([`glam::DVec2`]). Every routine
//!   checks them: a coordinate that is not finite or lies outside [0, 1) is an error
//!   ([`SpectrumError::InvalidPoint`], naming its index), never clamped.
//! - **Periodogram.** For N points x_j and an integer frequency vector k = (kx, ky),
//!
//!   P(k) = |Σ_j exp(−2πi k·x_j)|² / N.
//!
//!   White noise (N i.i.d. uniform points) has E[P(k)] = 1 and Var[P(k)] = 1 − 1/N for k ≠ 0,
//!   and P(0) = N always. P(−k) = P(k) because the points are real.
//! - **Grid.** A spectrum of size M holds the M×M frequencies kx, ky ∈ [k_min, k_min + M − 1]
//!   with k_min = −⌊M/2⌋: for even M that is [−M/2, M/2) (one more negative frequency than
//!   positive, as in an FFT), for odd M it is the symmetric −(M−1)/2 ..= (M−1)/2. Storage is
//!   row-major, `power[iy·M + ix]` with kx = ix + k_min, ky = iy + k_min (rows are ky, x grows
//!   to the right), so DC sits at the centre index (⌊M/2⌋, ⌊M/2⌋). M is in
//!   [`MIN_SIZE`]..=[`MAX_SIZE`].
//! - **Averages** over K realizations are plain means of P; realization r is generated from
//!   [`crate::core::rng::derive_seed`]`(seed, r)`, and the sum runs in realization order, so the
//!   result is bit-for-bit the same for any number of threads.
//! - **Determinism.** Every routine sums in a fixed order (never in thread-arrival order), so
//!   the same input gives the same bits on every run and for any number of threads. Across
//!   platforms the bits can differ only through the system's `sin`, `cos` and `exp` (last-ulp
//!   differences of libm), well below every tolerance.
//! - **DC.** [`DcMode`] only affects display ([`Spectrum::to_display_image`]); `power` always
//!   holds the true P(0) = N (mean N over realizations). RAPS and anisotropy always exclude DC.
//! - **Error metric.** Accuracy is the relative ℓ2 error over all frequencies except DC,
//!   ‖P̃ − P‖₂ / ‖P‖₂ ([`relative_l2_error`]); DC is excluded because P(0) = N would otherwise
//!   dominate the norm and hide errors everywhere else.
//!
//! # Methods
//!
//! | function | cost | use |
//! |---|---|---|
//! | [`periodogram_naive`] | N·M² sin/cos | reference for tests only |
//! | [`periodogram_exact`] | N·M²/2 complex multiply-adds (phasor recurrences) | exact, small N·M² |
//! | [`periodogram_nufft`] / [`NufftPlan`] | N·w² + (σM)² log(σM) | everyday, tolerance 1e-2..1e-12 |
//!
//! [`average_periodogram`] averages K realizations with either method and returns a
//! [`SpectrumReport`] with the time of every stage and the measured error.
//! [`radial_average`] gives RAPS over annuli of width 1 (annulus b holds |k| ∈ [b − ½, b + ½),
//! b ≥ 1, only annuli that the square grid contains completely) and PSA's anisotropy
//! 10·log10(variance/mean²) per annulus; [`pair_correlation`] gives g(r) on the torus (cell
//! list; [`pair_correlation_naive`] is the all-pairs reference, N ≤ 16 384).

pub mod average;
pub mod cost;
pub mod dft;
pub mod nufft;
pub mod pair;
pub mod quadrature;
pub mod radial;

pub use average::{
    analyze_points, average_periodogram, average_periodogram_progressive,
    average_periodogram_staged, DcMode, ErrorCheck, Method, PendingCheck, SpectrumReport,
    SpectrumRequest, DEFAULT_ERROR_CHECK_BUDGET,
};
pub use dft::{exact_field_few_rows, exact_field_rows, periodogram_exact, periodogram_naive};
pub use nufft::{
    es_kernel, kernel_params, kernel_transform, periodogram_nufft, upsampled_size, KernelParams,
    NufftPlan, NufftTimes, MAX_TOLERANCE, MIN_TOLERANCE,
};
pub use pair::{pair_correlation, pair_correlation_naive, PairCorrelation};
pub use quadrature::gauss_legendre;
pub use radial::{radial_average, RadialBin};

use crate::core::cancel::Cancelled;
use glam::DVec2;

/// Smallest spectrum size M.
pub const MIN_SIZE: usize = 2;
/// Largest spectrum size M (4096² frequencies, 128 MiB of `f64`).
pub const MAX_SIZE: usize = 4096;
/// Largest number of realizations K in an average.
pub const MAX_REALIZATIONS: usize = 1024;
/// Powers below this are shown as `log10(LOG_FLOOR)` by [`Spectrum::to_log_image`]
/// (exact zeros occur, e.g. for grid-aligned points).
pub const LOG_FLOOR: f64 = 1e-10;

/// Why a spectrum could not be computed. Every variant names the offending field and what is allowed.
#[derive(Debug, thiserror::Error)]
pub enum SpectrumError {
    /// The spectrum size M is out of range.
    #[error("size m = {m}: must be an integer in {min}..={max}")]
    InvalidSize { m: usize, min: usize, max: usize },
    /// The NUFFT tolerance is NaN or out of range.
    #[error("tolerance = {}: must be a number in [{min:e}, {max:e}]", crate::core::params::fmt_num(*.value))]
    InvalidTolerance { value: f64, min: f64, max: f64 },
    /// The number of realizations K is out of range.
    #[error("realizations K = {k}: must be an integer in 1..={max}")]
    InvalidRealizations { k: usize, max: usize },
    /// No points were given (a periodogram divides by N).
    #[error("empty point set: at least one point is needed")]
    EmptyPointSet,
    /// A point is not finite or lies outside [0, 1)².
    #[error("point {index} = ({x}, {y}): coordinates must be finite and in [0, 1)")]
    InvalidPoint { index: usize, x: f64, y: f64 },
    /// Another parameter (pair-correlation bin width, radius, point count) is out of range.
    #[error("{field} = {value}: must be {allowed}")]
    InvalidParam {
        field: &'static str,
        value: String,
        allowed: String,
    },
    /// The point generator of an average failed.
    #[error("realization {realization}: point generator failed: {source}")]
    Generator {
        realization: usize,
        #[source]
        source: Box<dyn std::error::Error + Send + Sync>,
    },
    /// The computation was cancelled.
    #[error("cancelled")]
    Cancelled,
}

impl From<Cancelled> for SpectrumError {
    fn from(_: Cancelled) -> Self {
        SpectrumError::Cancelled
    }
}

/// Checks `MIN_SIZE ≤ m ≤ MAX_SIZE`.
pub fn check_size(m: usize) -> Result<(), SpectrumError> {
    if !(MIN_SIZE..=MAX_SIZE).contains(&m) {
        return Err(SpectrumError::InvalidSize {
            m,
            min: MIN_SIZE,
            max: MAX_SIZE,
        });
    }
    Ok(())
}

/// Checks that the set is non-empty and every coordinate is finite and in [0, 1).
pub fn check_points(points: &[DVec2]) -> Result<(), SpectrumError> {
    if points.is_empty() {
        return Err(SpectrumError::EmptyPointSet);
    }
    for (index, p) in points.iter().enumerate() {
        let ok = |v: f64| v.is_finite() && (0.0..1.0).contains(&v);
        if !ok(p.x) || !ok(p.y) {
            return Err(SpectrumError::InvalidPoint {
                index,
                x: p.x,
                y: p.y,
            });
        }
    }
    Ok(())
}

/// The lowest frequency of a size-`m` grid, k_min = −⌊m/2⌋ (see the module docs).
#[inline]
pub fn k_min(m: usize) -> i64 {
    -((m / 2) as i64)
}

/// PSA's default spectrum size for N points: 10·√N/2 frequencies on each side of DC, i.e.
/// M = 10·√N rounded to the nearest even integer (640 for N = 4096), then limited to
/// [`MIN_SIZE`]..=[`MAX_SIZE`] (N > 167 772 would ask for more than 4096).
/// Reference: PSA, Heck, Schlömer & Deussen, "Blue noise sampling with controlled
/// aliasing", ACM TOG 2013 (tool nodag/psa).
pub fn psa_default_size(n: usize) -> usize {
    let half = (5.0 * (n as f64).sqrt()).round() as usize;
    (2 * half).clamp(MIN_SIZE, MAX_SIZE)
}

/// Relative ℓ2 error ‖approx − exact‖₂ / ‖exact‖₂ of two periodograms of the same size,
/// over all frequencies except DC when `exclude_dc` (the crate's accuracy metric excludes it).
/// Returns 0 when both are identical, +∞ when `exact` is zero and `approx` is not, and NaN
/// when the sizes differ.
pub fn relative_l2_error(approx: &Spectrum, exact: &Spectrum, exclude_dc: bool) -> f64 {
    if approx.m != exact.m || approx.power.len() != exact.power.len() {
        return f64::NAN;
    }
    let dc = exact.dc_index();
    let (mut num, mut den) = (0.0f64, 0.0f64);
    for (i, (a, e)) in approx.power.iter().zip(&exact.power).enumerate() {
        if exclude_dc && i == dc {
            continue;
        }
        num += (a - e) * (a - e);
        den += e * e;
    }
    ratio_of_norms(num, den)
}

/// √(num/den) with 0/0 = 0 and x/0 = ∞.
pub(crate) fn ratio_of_norms(num: f64, den: f64) -> f64 {
    if num == 0.0 {
        0.0
    } else if den == 0.0 {
        f64::INFINITY
    } else {
        (num / den).sqrt()
    }
}

/// A periodogram (or an average of K periodograms) on an M×M grid of integer frequencies,
/// row-major with DC at the centre index (see the module docs for the index convention).
#[derive(Debug, Clone, PartialEq)]
pub struct Spectrum {
    /// Grid size M (frequencies per axis).
    pub m: usize,
    /// P(k) at `iy·m + ix`, kx = ix + k_min, ky = iy + k_min, k_min = −⌊m/2⌋.
    pub power: Vec<f64>,
    /// Points per realization (the smallest count if realizations differ).
    pub n_points: usize,
    /// Number of periodograms averaged (1 for a single periodogram).
    pub realizations: usize,
    /// How displays treat DC (the data always hold the true value).
    pub dc: DcMode,
}

impl Spectrum {
    /// A spectrum from a row-major power array of length m² (checked in debug builds).
    pub(crate) fn from_power(m: usize, power: Vec<f64>, n_points: usize) -> Self {
        debug_assert_eq!(power.len(), m * m);
        Spectrum {
            m,
            power,
            n_points,
            realizations: 1,
            dc: DcMode::Show,
        }
    }

    /// The frequency of column/row index `i`: i + k_min.
    #[inline]
    pub fn frequency(&self, i: usize) -> i64 {
        i as i64 + k_min(self.m)
    }

    /// The index of frequency `k` along an axis, if it is on the grid.
    #[inline]
    pub fn index_of(&self, k: i64) -> Option<usize> {
        let i = k - k_min(self.m);
        (0..self.m as i64).contains(&i).then_some(i as usize)
    }

    /// P(kx, ky), if the frequency is on the grid.
    pub fn at(&self, kx: i64, ky: i64) -> Option<f64> {
        let ix = self.index_of(kx)?;
        let iy = self.index_of(ky)?;
        self.power.get(iy * self.m + ix).copied()
    }

    /// Index of DC in `power`: (⌊m/2⌋, ⌊m/2⌋).
    #[inline]
    pub fn dc_index(&self) -> usize {
        (self.m / 2) * self.m + self.m / 2
    }

    /// log10 P(k) as `f32`, row-major like `power`, for display. Powers below [`LOG_FLOOR`]
    /// (including exact zeros) map to log10(LOG_FLOOR) = −10. When `dc_masked`, the DC pixel is
    /// painted with the mean power of its 8 neighbours (toroidal wrap on the grid) so that
    /// P(0) = N neither dominates the colour scale nor leaves a hole (a hand-built spectrum whose
    /// `power` is not m² long is converted without masking).
    pub fn to_log_image(&self, dc_masked: bool) -> Vec<f32> {
        use rayon::prelude::*;
        let to_log = |p: f64| p.max(LOG_FLOOR).log10() as f32;
        let mut image: Vec<f32> = self.power.par_iter().map(|&p| to_log(p)).collect();
        if dc_masked && self.power.len() == self.m * self.m {
            let m = self.m;
            let c = m / 2;
            let mut sum = 0.0;
            for dy in [m - 1, 0, 1] {
                for dx in [m - 1, 0, 1] {
                    if dx == 0 && dy == 0 {
                        continue;
                    }
                    sum += self.power[((c + dy) % m) * m + (c + dx) % m];
                }
            }
            image[self.dc_index()] = to_log(sum / 8.0);
        }
        image
    }

    /// [`Spectrum::to_log_image`] with DC masked according to [`Spectrum::dc`].
    pub fn to_display_image(&self) -> Vec<f32> {
        self.to_log_image(self.dc == DcMode::Mask)
    }

    /// `(kx, ky, P)` for every frequency, in storage order (ky outer, kx inner), DC included
    /// with its true value whatever [`Spectrum::dc`] says.
    pub fn to_csv_rows(&self) -> Vec<(i64, i64, f64)> {
        let m = self.m;
        self.power
            .iter()
            .enumerate()
            .map(|(i, &p)| (self.frequency(i % m), self.frequency(i / m), p))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn psa_default_size_matches_psa_for_4096_points() {
        assert_eq!(psa_default_size(4096), 640);
        assert_eq!(psa_default_size(1024), 320);
        assert_eq!(psa_default_size(1), 10);
        assert_eq!(psa_default_size(0), MIN_SIZE);
        assert_eq!(psa_default_size(1 << 24), MAX_SIZE);
        // 10·√1000 = 316.2 → 316 (even).
        assert_eq!(psa_default_size(1000), 316);
    }

    #[test]
    fn index_convention_even_and_odd_sizes() {
        let even = Spectrum::from_power(4, vec![0.0; 16], 1);
        assert_eq!((even.frequency(0), even.frequency(3)), (-2, 1));
        assert_eq!(even.dc_index(), 2 * 4 + 2);
        assert_eq!(even.index_of(-3), None);
        assert_eq!(even.index_of(2), None);
        let odd = Spectrum::from_power(5, vec![0.0; 25], 1);
        assert_eq!((odd.frequency(0), odd.frequency(4)), (-2, 2));
        assert_eq!(odd.dc_index(), 2 * 5 + 2);
    }

    #[test]
    fn size_and_points_are_checked() {
        assert!(matches!(
            check_size(1),
            Err(SpectrumError::InvalidSize { m: 1, .. })
        ));
        assert!(matches!(
            check_size(4097),
            Err(SpectrumError::InvalidSize { m: 4097, .. })
        ));
        assert!(check_size(2).is_ok() && check_size(4096).is_ok());
        assert!(matches!(
            check_points(&[]),
            Err(SpectrumError::EmptyPointSet)
        ));
        let bad = [DVec2::new(0.5, 0.5), DVec2::new(1.0, 0.2)];
        assert!(matches!(
            check_points(&bad),
            Err(SpectrumError::InvalidPoint { index: 1, .. })
        ));
        let nan = [DVec2::new(f64::NAN, 0.5)];
        assert!(matches!(
            check_points(&nan),
            Err(SpectrumError::InvalidPoint { index: 0, .. })
        ));
        let neg = [DVec2::new(0.5, -0.0), DVec2::new(-1e-300, 0.5)];
        assert!(matches!(
            check_points(&neg),
            Err(SpectrumError::InvalidPoint { index: 1, .. })
        ));
    }

    #[test]
    fn log_image_and_csv_rows() {
        let mut power = vec![1.0; 16];
        power[10] = 100.0; // DC of m = 4
        power[0] = 0.0;
        let s = Spectrum::from_power(4, power, 100);
        let img = s.to_log_image(false);
        assert_eq!(img[10], 2.0);
        assert_eq!(img[0], -10.0);
        assert_eq!(img[1], 0.0);
        let masked = s.to_log_image(true);
        // Neighbours of (2,2) on the 4×4 torus: all 1.0 (index 0 is not a neighbour).
        assert_eq!(masked[10], 0.0);
        let rows = s.to_csv_rows();
        assert_eq!(rows.len(), 16);
        assert_eq!(rows[0], (-2, -2, 0.0));
        assert_eq!(rows[10], (0, 0, 100.0));
        assert_eq!(rows[15], (1, 1, 1.0));
    }

    #[test]
    fn relative_l2_error_excludes_dc_when_asked() {
        let a = Spectrum::from_power(2, vec![1.0, 1.0, 1.0, 5.0], 5);
        let b = Spectrum::from_power(2, vec![1.0, 1.0, 1.0, 4.0], 4);
        assert_eq!(a.dc_index(), 3);
        assert_eq!(relative_l2_error(&a, &b, true), 0.0);
        let e = relative_l2_error(&a, &b, false);
        assert!((e - (1.0f64 / 19.0).sqrt()).abs() < 1e-15);
    }
}
