//! PSA's statistics: radial distribution function, the radial power spectrum derived from it,
//! effective Nyquist frequency, oscillations, and bond-orientational order.
//!
//! These are the measures of D. Heck, T. Schlömer, O. Deussen, *Blue noise sampling with
//! controlled aliasing*, ACM TOG 32(3):25, 2013, as their tool `psa` computes and prints them
//! (github.com/nodag/psa, commit b042eea7f1dde5b428a225929fb949b8403e82c1: `src/statistics.cpp`
//! `SpectralStatistics`, `RDFtoRP`, `EffectiveNyquist`, `OscillationsMetric`;
//! `src/point.cpp` `PointSet::RDF`; `src/delaunay.cpp` `Delaunay::GetStatistics`). Written
//! here from those definitions; `tests/data/psa/README.md` says how PSA's own values, which
//! the tests compare against, were obtained.
//!
//! Distances are toroidal (the crate convention, and PSA's); frequencies ν are in cycles per
//! unit length (integer-frequency units, as the periodogram's k). N is the number of points.
//!
//! # Radial distribution function ([`rdf`])
//!
//! A histogram of the toroidal distances of all N(N−1)/2 pairs over `bins` bins of width
//! Δr = r_max/bins, bin i = [iΔr, (i+1)Δr), divided by the count a uniform density would put
//! there:
//!
//! g_i = count_i / ( N(N−1)/2 · π Δr² (2i+1) ),
//!
//! (π Δr²(2i+1) is the area of the annulus). White noise has E[g_i] = 1. r_max ≤ ½ keeps
//! every annulus a whole circle on the torus. PSA's `--rdf` plot uses N/8 bins up to 8 d_hex
//! ([`psa_rdf_range`], d_hex = [`hex_distance`]); its spectral statistics use ⌊100√N⌋ bins up
//! to ½ ([`spectral_bins`]).
//!
//! # Radial power spectrum from the RDF ([`radial_power_from_rdf`])
//!
//! For an isotropic point pattern of N points on unit area the radial power spectrum is the
//! Hankel transform of g − 1 (Heck et al. 2013):
//!
//! P(ν) = 1 + 2πN ∫₀^{r_max} (g(r) − 1) J₀(2πνr) r w_ν(r) dr,
//!
//! with PSA's taper w_ν(r) = 0.43 + 0.5 cos(πr/L) + 0.08 cos(2πr/L) for r ≤ L and 0 beyond
//! (a Blackman window, with PSA's 0.43 for Blackman's 0.42), whose length grows with the
//! frequency: L = r_max · clamp(4ν/√N, 0.2, 0.5). Like PSA, the integral is the trapezoid
//! rule on the bin samples g_i taken at r_i = iΔr (the lower bin edge), and the result is
//! |·| (P is a power, and the windowed estimate can dip below zero). The frequencies are
//! ν_k = kΔν, k = 0 … bins − 1, Δν = ν_max/bins; PSA's spectral statistics use the same bin
//! count as the RDF and ν_max = N/2 ([`radial_power`]). J₀ is Abramowitz & Stegun 9.4.1 and
//! 9.4.3 (absolute error < 10⁻⁷, checked against [`bessel_j0`] in the tests). The sum is
//! evaluated in O(m log m) ([`super::hankel`]: prefix sums for J₀'s power series, chirp-z
//! transforms for its asymptotic series); [`radial_power_from_rdf_direct`] sums it term by
//! term with the same J₀ (the reference: equal up to rounding, ≈ 10⁻¹⁴), and
//! [`radial_power_from_rdf_naive`] with the exact J₀ and no shortcut.
//!
//! The windows are at most ½·r_max long, so the statistics read the RDF up to r = ¼ only:
//! [`radial_power`] counts just the pairs closer than that.
//!
//! PSA derives its statistics from this transform, not from a periodogram on the integer
//! frequency grid (`src/core/spectrum/`), because they need the spectrum on a continuous,
//! finely sampled frequency axis up to many times the Nyquist frequency.
//!
//! # Effective Nyquist frequency ([`effective_nyquist`])
//!
//! With the mean power over the disc of radius ν_k, C_k = (2/ν_k²) Σ_{l ≤ k} P(ν_l) ν_l Δν
//! (a rectangle rule, as PSA's), search upward from ν = √N/2 for the first ν_i with
//! C_i > 0.5; the effective Nyquist frequency is half the largest ν_j ≤ ν_i (j ≥ 1) with
//! C_j < 0.1 (PSA's thresholds): a sampling pattern has almost no power below ν_j, so it
//! represents frequencies up to ν_j/2 nearly free of aliasing. It is reported, as PSA prints
//! it, relative to the Nyquist frequency √N/2 of a √N × √N grid: **ν_eff = (ν_j/2)/(√N/2) =
//! ν_j/√N**. 0 when no such pair exists (white noise, or Poisson disk with a small radius:
//! their disc means never fall below 0.1). The value moves in steps of Δν/√N (0.005 for
//! PSA's bins at N = 1024).
//!
//! # Oscillations ([`oscillations`])
//!
//! Let ν_osc be the first frequency where P reaches 0.98 (if it never does: where P is
//! largest), ν₁ = min(ν_osc + 10·√N/2, ν_max). Oscillations = 10 · RMS of P − 1 over the
//! annulus ν_osc ≤ |ν| ≤ ν₁ of the plane:
//!
//! oscillations = 10 · ( 2π ∫_{ν_osc}^{ν₁} (P(ν) − 1)² ν dν / (π(ν₁² − ν_osc²)) )^{1/2},
//!
//! the integral by the trapezoid rule on the samples k₀ … k₁ with k₀ = ν_osc/Δν and
//! k₁ = ⌊ν₁/Δν⌋ + 1 (clamped to the last sample), as PSA's. (PSA's loop drops sample k₁ − 1
//! when k₁ − k₀ is even; we do not: 3·10⁻⁴ relative on the N = 954 set of the tests.)
//!
//! # Bond-orientational order ([`bond_orientational_order`])
//!
//! For point i with Delaunay neighbours q_1 … q_m in angular order, let θ_k be the direction
//! of the edge q_k − q_{k+1} (cyclic) between consecutive neighbours, and
//! s_i = Σ_k exp(6iθ_k). Then
//!
//! BOO = Σ_i |s_i| / Σ_i m_i,
//!
//! which is PSA's definition: the mean of |ψ₆(i)| = |s_i|/m_i weighted by the neighbour count
//! m_i, with the directions of the edges of the neighbour ring. (The textbook ψ₆ uses the
//! bond directions p_i → q_k and a plain mean; both give the same value for every lattice,
//! e.g. 1 for the hexagonal lattice and 1/3 for a square lattice with one diagonal per cell,
//! but differ on irregular sets.) The triangulation is toroidal, as PSA's: the points and
//! their periodic copies in a band [−w, 1 + w]² are triangulated ([`crate::core::torus::delaunay`]:
//! `delaunator`, then made unique on cocircular points by CGAL's symbolic perturbation, which
//! PSA's CGAL triangulation uses, so that a square grid gives exactly 1/3 as PSA does); w starts at
//! PSA's 4/√N and doubles (up to 2, with copies p + (a, b), a, b ∈ −2…2) until every
//! triangle around an original point has its circumdisc's bounding box inside the band, which
//! makes it a Delaunay triangle of the infinite periodic set (`pattern/optimize.rs` gives the
//! argument). A point the triangulator drops as a (near-)duplicate of another counts with that
//! point's neighbours, as in PSA (CGAL returns the existing vertex for a duplicate).
//!
//! # Costs
//!
//! [`psa_statistics`]: the RDF's pairs closer than ¼ by a cell grid (≈ πN²/32 pairs, plus the
//! grid's margin; parallel); the transform, a few hundred thousand J₀ terms summed directly and
//! ≈ 4 blocks × 47 FFTs of length ≤ 2m (parallel), instead of ≈ m²/2 = 5000·N J₀ terms; a
//! triangulation of about N + 16√N points (serial, run beside the RDF and the transform;
//! [`radial_power_work`] counts them for the budget). The pairs still grow as N², so
//! N ≤ [`PSA_MAX_N`].

use glam::DVec2;
use serde::Serialize;
use std::f64::consts::{PI, TAU};

use super::hankel;
use super::pairs::{self, bin_of};
use super::{hex_distance, validate, Cancel, MetricsError, CANCEL_STRIDE};
use crate::core::filter::special::bessel_j0;
use crate::core::torus;
use crate::core::torus::{circumcircle, circumdisc_in_band};

/// The fewest points the PSA statistics accept (an RDF needs a pair).
pub const PSA_MIN_N: usize = 2;
/// The most points the PSA statistics accept: their RDF visits the pairs closer than ¼
/// (≈ 0.12·N², ≈ 5·10⁸ at this N, a few seconds on two cores).
pub const PSA_MAX_N: usize = 65_536;
/// The most bins an RDF or radial power curve may have.
pub const RDF_MAX_BINS: usize = 1 << 24;

/// PSA's thresholds of the effective Nyquist frequency (disc mean power).
const NYQUIST_LOW: f64 = 0.1;
const NYQUIST_HIGH: f64 = 0.5;
/// Where the oscillations' annulus starts: the first ν with P ≥ this.
const OSCILLATIONS_START: f64 = 0.98;
/// The annulus' width in units of √N/2.
const OSCILLATIONS_WIDTH: f64 = 10.0;

/// PSA's statistics of one point set, normalised as PSA prints them.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PsaStatistics {
    /// Effective Nyquist frequency relative to the Nyquist frequency √N/2 of a √N × √N grid
    /// (1 = as high as the grid's; 0 when the pattern has noticeable power at all frequencies).
    pub effective_nyquist: f64,
    /// 10 × the RMS of P − 1 over the annulus above where P first reaches 0.98 (dimensionless;
    /// 0 for a flat spectrum, large for lattice-like peaks).
    pub oscillations: f64,
    /// Bond-orientational order in [0, 1] (1 = hexagonal lattice).
    pub bond_orientational_order: f64,
}

/// A radial distribution function: g over `bins` bins of width `r_max / bins` from r = 0.
#[derive(Debug, Clone, PartialEq)]
pub struct Rdf {
    n: usize,
    r_max: f64,
    values: Vec<f64>,
}

impl Rdf {
    /// Number of points it was computed from.
    pub fn n(&self) -> usize {
        self.n
    }
    /// Upper end of the last bin (units of the unit square).
    pub fn r_max(&self) -> f64 {
        self.r_max
    }
    /// Bin width Δr.
    pub fn bin_width(&self) -> f64 {
        self.r_max / self.values.len() as f64
    }
    /// g_i of bin i = [iΔr, (i+1)Δr).
    pub fn values(&self) -> &[f64] {
        &self.values
    }
}

/// A radial power spectrum P(ν_k) at ν_k = kΔν, k = 0 … len − 1 (cycles per unit length).
#[derive(Debug, Clone, PartialEq)]
pub struct RadialPower {
    n: usize,
    nu_max: f64,
    values: Vec<f64>,
}

impl RadialPower {
    /// Number of points it was computed from.
    pub fn n(&self) -> usize {
        self.n
    }
    /// Frequency step Δν.
    pub fn bin_width(&self) -> f64 {
        self.nu_max / self.values.len() as f64
    }
    /// Frequency of sample k.
    pub fn frequency(&self, k: usize) -> f64 {
        k as f64 * self.bin_width()
    }
    /// P(ν_k).
    pub fn values(&self) -> &[f64] {
        &self.values
    }
}

/// Checks the point count and the points.
fn validate_psa(points: &[DVec2], what: &'static str) -> Result<(), MetricsError> {
    let n = points.len();
    if n > PSA_MAX_N {
        return Err(MetricsError::TooManyPoints {
            what,
            n,
            max: PSA_MAX_N,
            cost: "O(N²) pairs closer than ¼",
        });
    }
    if n < PSA_MIN_N {
        return Err(MetricsError::TooFewPoints {
            what,
            n,
            min: PSA_MIN_N,
        });
    }
    validate(points)
}

fn validate_range(bins: usize, r_max: f64) -> Result<(), MetricsError> {
    if bins == 0 || bins > RDF_MAX_BINS || !(r_max > 0.0 && r_max <= 0.5) {
        return Err(MetricsError::InvalidRdfRange {
            bins,
            r_max,
            max_bins: RDF_MAX_BINS,
        });
    }
    Ok(())
}

/// g_i from the pair counts of bins of width `dr` (bins 0 … counts.len() − 1; fewer than
/// the RDF's bins when only its first bins are needed).
fn normalise(n: usize, dr: f64, counts: &[u64]) -> Vec<f64> {
    let pairs = (n as f64) * (n as f64 - 1.0) / 2.0;
    counts
        .iter()
        .enumerate()
        .map(|(i, &c)| c as f64 / (pairs * PI * dr * dr * (2 * i + 1) as f64))
        .collect()
}

/// PSA's binning of its `--rdf` output: N/8 bins (at least 1) up to 8 d_hex(N) (at most ½,
/// where the annuli stop being whole circles on the torus; PSA does not clamp).
pub fn psa_rdf_range(n: usize) -> (usize, f64) {
    ((n / 8).max(1), (8.0 * hex_distance(n.max(1))).min(0.5))
}

/// The bins of PSA's spectral statistics: ⌊100√N⌋ RDF bins up to r = ½, and as many
/// frequency samples up to ν = N/2.
pub fn spectral_bins(n: usize) -> usize {
    (100.0 * (n as f64).sqrt()) as usize
}

/// The work of [`radial_power`] for N points (the budget's counts): the pairs its cell grid
/// visits (those closer than ¼, the longest window, and the grid's margin: ≈ 0.12·N² for
/// N ≥ 1000), the J₀ terms it sums one by one, and its FFTs' Σ L·log₂ L.
pub fn radial_power_work(n: usize) -> (f64, f64, f64) {
    let m = spectral_bins(n);
    if m == 0 || n < PSA_MIN_N {
        return (0.0, 0.0, 0.0);
    }
    let r_max = 0.5;
    let used = hankel::samples_used(m, r_max);
    let pairs = pairs::visited_pairs(n, used as f64 * (r_max / m as f64));
    let plan = hankel::Plan::new(n, r_max, m, m, 0.5 * n as f64);
    (pairs, plan.direct_terms(n, r_max, m), plan.fft_work())
}

/// The pairs [`rdf`] visits for N points up to `r_max` (the budget's count).
pub fn rdf_work(n: usize, r_max: f64) -> f64 {
    pairs::visited_pairs(n, r_max)
}

/// The last RDF sample of the transform at window length `len`.
#[inline]
pub(super) fn last_term(len: f64, dr: f64, m: usize) -> usize {
    ((len / dr).floor() as usize).min(m - 1)
}

/// The radial distribution function of `points` (toroidal, see the module docs) over `bins`
/// bins up to `r_max` ∈ (0, ½]: the pairs closer than `r_max` by a cell grid (O(N·k) for k
/// points within `r_max`; all N(N−1)/2 pairs when `r_max` is too large for a grid), in
/// parallel; the counts, hence the values, do not depend on the number of threads and equal
/// [`rdf_naive`]'s bin for bin.
///
/// Errors: fewer than 2 or more than [`PSA_MAX_N`] points, an invalid point, `bins` = 0 or
/// above [`RDF_MAX_BINS`], `r_max` outside (0, ½], cancellation.
pub fn rdf(
    points: &[DVec2],
    bins: usize,
    r_max: f64,
    cancel: &Cancel,
) -> Result<Rdf, MetricsError> {
    validate_psa(points, "a radial distribution function")?;
    validate_range(bins, r_max)?;
    let n = points.len();
    let dr = r_max / bins as f64;
    let counts = pairs::pair_counts(points, bins, dr, cancel)?;
    Ok(Rdf {
        n,
        r_max,
        values: normalise(n, dr, &counts),
    })
}

/// [`rdf`] by a plain serial double loop (the reference of the tests).
pub fn rdf_naive(
    points: &[DVec2],
    bins: usize,
    r_max: f64,
    cancel: &Cancel,
) -> Result<Rdf, MetricsError> {
    validate_psa(points, "a radial distribution function")?;
    validate_range(bins, r_max)?;
    let n = points.len();
    let dr = r_max / bins as f64;
    let mut counts = vec![0u64; bins];
    for i in 0..n {
        if i % 64 == 0 {
            cancel.check()?;
        }
        for j in i + 1..n {
            if let Some(b) = bin_of(
                torus::distance_squared(points[i], points[j], 1.0).sqrt(),
                dr,
                bins,
            ) {
                counts[b] += 1;
            }
        }
    }
    Ok(Rdf {
        n,
        r_max,
        values: normalise(n, dr, &counts),
    })
}

/// PSA's taper (module docs) at r for window length `len`; 0 beyond.
#[inline]
pub(super) fn window(r: f64, len: f64) -> f64 {
    if r > len {
        0.0
    } else {
        0.43 + 0.5 * (PI * r / len).cos() + 0.08 * (TAU * r / len).cos()
    }
}

/// The window length L(ν) = r_max · clamp(4ν/√N, 0.2, 0.5).
#[inline]
pub(super) fn window_length(nu: f64, n: usize, r_max: f64) -> f64 {
    r_max * (4.0 * nu / (n as f64).sqrt()).clamp(0.2, 0.5)
}

fn validate_spectrum(bins: usize, nu_max: f64) -> Result<(), MetricsError> {
    if bins == 0 || bins > RDF_MAX_BINS || !(nu_max.is_finite() && nu_max > 0.0) {
        return Err(MetricsError::InvalidFrequencyRange {
            bins,
            nu_max,
            max_bins: RDF_MAX_BINS,
        });
    }
    Ok(())
}

/// The radial power spectrum P(ν_k), ν_k = k·ν_max/bins, from an RDF by PSA's windowed
/// Hankel transform (module docs), evaluated fast ([`super::hankel`]: chirp-z transforms of
/// J₀'s asymptotic series and prefix sums of its power series, O(m log m)); equal to
/// [`radial_power_from_rdf_direct`] up to rounding (≈ 10⁻¹² here). Parallel; the result does
/// not depend on the number of threads.
///
/// Errors: `bins` = 0 or above [`RDF_MAX_BINS`], `nu_max` not a positive number, cancellation.
pub fn radial_power_from_rdf(
    rdf: &Rdf,
    bins: usize,
    nu_max: f64,
    cancel: &Cancel,
) -> Result<RadialPower, MetricsError> {
    validate_spectrum(bins, nu_max)?;
    let t = rdf_transform(rdf, bins, nu_max);
    Ok(RadialPower {
        n: rdf.n,
        nu_max,
        values: hankel::power(&t, cancel)?,
    })
}

fn rdf_transform(rdf: &Rdf, bins: usize, nu_max: f64) -> hankel::Transform<'_> {
    hankel::Transform {
        n: rdf.n,
        r_max: rdf.r_max,
        m: rdf.values.len(),
        g: &rdf.values,
        bins,
        nu_max,
    }
}

/// [`radial_power_from_rdf`] by the direct sum: one J₀ (the same A&S approximation) per
/// frequency and RDF sample within the window, O(m²) (the reference of the fast path).
pub fn radial_power_from_rdf_direct(
    rdf: &Rdf,
    bins: usize,
    nu_max: f64,
    cancel: &Cancel,
) -> Result<RadialPower, MetricsError> {
    validate_spectrum(bins, nu_max)?;
    let t = rdf_transform(rdf, bins, nu_max);
    Ok(RadialPower {
        n: rdf.n,
        nu_max,
        values: hankel::power_direct(&t, cancel)?,
    })
}

/// [`radial_power_from_rdf`] by the plain trapezoid sum over all RDF samples with the exact
/// J₀ ([`bessel_j0`]) and the window evaluated everywhere (the reference of the tests).
pub fn radial_power_from_rdf_naive(
    rdf: &Rdf,
    bins: usize,
    nu_max: f64,
) -> Result<RadialPower, MetricsError> {
    validate_spectrum(bins, nu_max)?;
    let m = rdf.values.len();
    let dr = rdf.bin_width();
    let values = (0..bins)
        .map(|k| {
            let nu = k as f64 * nu_max / bins as f64;
            let len = window_length(nu, rdf.n, rdf.r_max);
            let f = |j: usize| {
                let r = j as f64 * dr;
                (rdf.values[j] - 1.0) * bessel_j0(TAU * nu * r) * r * window(r, len)
            };
            let mut t = 0.5 * (f(0) + f(m - 1));
            for j in 1..m.saturating_sub(1) {
                t += f(j);
            }
            (1.0 + TAU * rdf.n as f64 * dr * t).abs()
        })
        .collect();
    Ok(RadialPower {
        n: rdf.n,
        nu_max,
        values,
    })
}

/// PSA's radial power spectrum of `points`: the RDF with [`spectral_bins`] bins up to ½ (only
/// the bins up to ¼ counted, all the windows reach), its transform at as many frequencies up
/// to N/2.
///
/// Errors: as [`rdf`].
pub fn radial_power(points: &[DVec2], cancel: &Cancel) -> Result<RadialPower, MetricsError> {
    validate_psa(points, "a radial distribution function")?;
    let n = points.len();
    let m = spectral_bins(n).max(1);
    let r_max = 0.5;
    validate_range(m, r_max)?;
    // Only the RDF samples a window reaches (r ≤ ¼): the pairs closer than that.
    let dr = r_max / m as f64;
    let used = hankel::samples_used(m, r_max);
    let g = normalise(n, dr, &pairs::pair_counts(points, used, dr, cancel)?);
    let nu_max = 0.5 * n as f64;
    let t = hankel::Transform {
        n,
        r_max,
        m,
        g: &g,
        bins: m,
        nu_max,
    };
    Ok(RadialPower {
        n,
        nu_max,
        values: hankel::power(&t, cancel)?,
    })
}

/// [`radial_power`] by the references: the RDF over all pairs ([`rdf_naive`]) and the direct
/// transform ([`radial_power_from_rdf_direct`]).
pub fn radial_power_direct(points: &[DVec2], cancel: &Cancel) -> Result<RadialPower, MetricsError> {
    let n = points.len();
    let bins = spectral_bins(n).max(1);
    let g = rdf_naive(points, bins, 0.5, cancel)?;
    radial_power_from_rdf_direct(&g, bins, 0.5 * n as f64, cancel)
}

/// The effective Nyquist frequency of a radial power spectrum, relative to √N/2 (module
/// docs); 0 when the disc mean never falls below 0.1 before rising above 0.5.
pub fn effective_nyquist(rp: &RadialPower) -> f64 {
    let p = &rp.values;
    let dnu = rp.bin_width();
    let sqrt_n = (rp.n as f64).sqrt();
    // Disc means C_k and, for each k, the last j ≤ k (j ≥ 1) with C_j < 0.1.
    let mut cum = 0.0;
    let mut last_low: Option<usize> = None;
    let start = (0.5 * sqrt_n / dnu) as usize;
    for (k, &pk) in p.iter().enumerate() {
        let nu = k as f64 * dnu;
        cum += pk * dnu * 2.0 * nu;
        if k == 0 {
            continue;
        }
        let mean = cum / (nu * nu);
        if mean < NYQUIST_LOW {
            last_low = Some(k);
        }
        if k >= start && mean > NYQUIST_HIGH {
            if let Some(j) = last_low {
                return j as f64 * dnu / sqrt_n;
            }
        }
    }
    0.0
}

/// The oscillations metric of a radial power spectrum (module docs).
pub fn oscillations(rp: &RadialPower) -> f64 {
    let p = &rp.values;
    let dnu = rp.bin_width();
    let nu_top = rp.nu_max;
    // First sample reaching the threshold, else the (first) maximum.
    let k0 = p
        .iter()
        .position(|&v| v >= OSCILLATIONS_START)
        .unwrap_or_else(|| {
            p.iter()
                .enumerate()
                .fold((0, f64::NEG_INFINITY), |(bk, bv), (k, &v)| {
                    if v > bv {
                        (k, v)
                    } else {
                        (bk, bv)
                    }
                })
                .0
        });
    let nu0 = k0 as f64 * dnu;
    let nu1 = (nu0 + OSCILLATIONS_WIDTH * 0.5 * (rp.n as f64).sqrt()).min(nu_top);
    let k1 = ((nu1 / dnu) as usize + 1).min(p.len() - 1);
    let f = |k: usize| {
        let d = p[k] - 1.0;
        d * d * k as f64 * dnu
    };
    let integral = if k1 > k0 {
        dnu * (0.5 * (f(k0) + f(k1)) + (k0 + 1..k1).map(f).sum::<f64>())
    } else {
        0.0
    };
    let ring = PI * (nu1 * nu1 - nu0 * nu0);
    if ring > 0.0 {
        10.0 * (TAU * integral / ring).sqrt()
    } else {
        0.0
    }
}

/// exp(6iθ) of the direction θ of `d`, as (cos 6θ, sin 6θ); 0 for d = 0.
#[inline]
fn six_fold(d: DVec2) -> DVec2 {
    let len = d.length();
    if len == 0.0 || !len.is_finite() {
        return DVec2::ZERO;
    }
    let z = d / len;
    let z2 = DVec2::new(z.x * z.x - z.y * z.y, 2.0 * z.x * z.y);
    let z3 = DVec2::new(z2.x * z.x - z2.y * z.y, z2.x * z.y + z2.y * z.x);
    DVec2::new(z3.x * z3.x - z3.y * z3.y, 2.0 * z3.x * z3.y)
}

/// Widest band of periodic copies.
const MAX_BAND: f64 = 2.0;

/// Per original point: its neighbour ring (coordinates in the plane), or `None` when the
/// band is not shown sufficient (unless `accept`).
fn toroidal_rings(points: &[DVec2], w: f64, accept: bool) -> Option<Vec<Vec<DVec2>>> {
    use delaunator::{next_halfedge, EMPTY};
    let n = points.len();
    let all = crate::core::torus::with_periodic_copies(points, w, true);
    let tri = crate::core::torus::delaunay(&all);
    let at = |i: usize| DVec2::new(all[i].x, all[i].y);
    // One halfedge ending at each original point.
    let mut inedge = vec![EMPTY; n];
    for e in 0..tri.triangles.len() {
        let end = tri.triangles[next_halfedge(e)];
        if end < n && (inedge[end] == EMPTY || tri.halfedges[e] == EMPTY) {
            inedge[end] = e;
        }
    }
    let band_ok = |e: usize| {
        let t = e - e % 3;
        let (c, r2) = circumcircle(
            at(tri.triangles[t]),
            at(tri.triangles[t + 1]),
            at(tri.triangles[t + 2]),
        );
        circumdisc_in_band(c, r2, w)
    };
    let mut rings: Vec<Vec<DVec2>> = vec![Vec::new(); n];
    let mut dropped = Vec::new();
    for (i, ring) in rings.iter_mut().enumerate() {
        let start = inedge[i];
        if start == EMPTY {
            dropped.push(i);
            continue;
        }
        let mut e = start;
        loop {
            if !band_ok(e) && !accept {
                return None;
            }
            ring.push(at(tri.triangles[e]));
            let twin = tri.halfedges[next_halfedge(e)];
            if twin == EMPTY {
                if !accept {
                    return None;
                }
                break;
            }
            e = twin;
            if e == start || ring.len() > all.len() {
                break;
            }
        }
        // Neighbours relative to the point: copies of a dropped duplicate reuse them.
        let p = points[i];
        for q in ring.iter_mut() {
            *q -= p;
        }
    }
    // A point the triangulator dropped (a near-duplicate) takes the ring of the closest kept
    // point (rare: a linear search each).
    for i in dropped {
        let p = points[i];
        let best = (0..n).filter(|&j| inedge[j] != EMPTY).min_by(|&a, &b| {
            torus::distance_squared(p, points[a], 1.0)
                .total_cmp(&torus::distance_squared(p, points[b], 1.0))
        });
        if let Some(j) = best {
            rings[i] = rings[j].clone();
        }
    }
    Some(rings)
}

/// PSA's bond-orientational order of `points` on the torus (module docs), in [0, 1].
///
/// Errors: fewer than 2 or more than [`PSA_MAX_N`] points, an invalid point, cancellation.
pub fn bond_orientational_order(points: &[DVec2], cancel: &Cancel) -> Result<f64, MetricsError> {
    validate_psa(points, "a bond-orientational order")?;
    let n = points.len();
    let mut w = (4.0 / (n as f64).sqrt()).min(MAX_BAND);
    let rings = loop {
        cancel.check()?;
        let last = w >= MAX_BAND;
        if let Some(r) = toroidal_rings(points, w, last) {
            break r;
        }
        w = (2.0 * w).min(MAX_BAND);
    };
    let mut acc = 0.0;
    let mut count = 0usize;
    for (i, ring) in rings.iter().enumerate() {
        if i % CANCEL_STRIDE == 0 {
            cancel.check()?;
        }
        let m = ring.len();
        if m < 2 {
            continue;
        }
        let mut s = DVec2::ZERO;
        for k in 0..m {
            s += six_fold(ring[k] - ring[(k + 1) % m]);
        }
        acc += s.length();
        count += m;
    }
    Ok(if count > 0 { acc / count as f64 } else { 0.0 })
}

/// PSA's effective Nyquist frequency, oscillations and bond-orientational order of `points`
/// (module docs), normalised as PSA prints them.
///
/// Errors: fewer than 2 or more than [`PSA_MAX_N`] points, a non-finite point or one outside
/// [0,1)², cancellation.
pub fn psa_statistics(points: &[DVec2], cancel: &Cancel) -> Result<PsaStatistics, MetricsError> {
    // The triangulation (serial) runs beside the RDF and its transform (parallel): on two
    // cores it fills the gaps of their loops instead of following them.
    let (rp, boo) = rayon::join(
        || radial_power(points, cancel),
        || bond_orientational_order(points, cancel),
    );
    let (rp, bond_orientational_order) = (rp?, boo?);
    Ok(PsaStatistics {
        effective_nyquist: effective_nyquist(&rp),
        oscillations: oscillations(&rp),
        bond_orientational_order,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::rng::Rng;

    fn white(n: usize, seed: u64) -> Vec<DVec2> {
        let mut rng = Rng::new(seed);
        (0..n)
            .map(|_| {
                let x = rng.next_f64();
                DVec2::new(x, rng.next_f64())
            })
            .collect()
    }

    /// The lattice {i·u + j·v} mod 1, u = (1/c, 0), v = (shift/c, 1/r), i < c, j < r, where
    /// row j is shifted by (j·shift mod 1) cells.
    fn lattice(c: usize, r: usize, shift: f64) -> (Vec<DVec2>, DVec2, DVec2) {
        let mut pts = Vec::with_capacity(c * r);
        for j in 0..r {
            let off = (j as f64 * shift).fract();
            for i in 0..c {
                pts.push(DVec2::new((i as f64 + off) / c as f64, j as f64 / r as f64));
            }
        }
        let u = DVec2::new(1.0 / c as f64, 0.0);
        let v = DVec2::new(shift / c as f64, 1.0 / r as f64);
        (pts, u, v)
    }

    /// BOO of a lattice whose Delaunay triangles are (0, u, v) and (u, v, u + v) (every angle
    /// of (0, u, v) acute): every neighbour ring is ±u, ±v, ±(v − u), so BOO =
    /// |e^{6iθ_u} + e^{6iθ_v} + e^{6iθ_{v−u}}| / 3.
    fn lattice_boo(u: DVec2, v: DVec2) -> f64 {
        let w = v - u;
        assert!(
            u.dot(v) > 0.0 && (-u).dot(w) > 0.0 && (-v).dot(-w) > 0.0,
            "not acute"
        );
        (six_fold(u) + six_fold(v) + six_fold(w)).length() / 3.0
    }

    #[test]
    fn j0_fast_matches_the_exact_bessel_function_to_1e_7() {
        let mut x = 0.0;
        let mut worst: f64 = 0.0;
        while x < 3000.0 {
            worst = worst.max((hankel::j0_fast(x) - bessel_j0(x)).abs());
            x += if x < 50.0 { 0.001 } else { 0.0731 };
        }
        assert!(worst < 1e-7, "max |J0 error| = {worst:e}");
        // Both sides of the switch at 3.
        assert!((hankel::j0_fast(3.0) - bessel_j0(3.0)).abs() < 1e-7);
        assert!((hankel::j0_fast(3.0 + 1e-12) - bessel_j0(3.0)).abs() < 1e-7);
    }

    /// Jittered points: one per cell of a k × k grid.
    fn jitter(k: usize, seed: u64) -> Vec<DVec2> {
        let mut rng = Rng::new(seed);
        let s = 1.0 / k as f64;
        (0..k * k)
            .map(|i| {
                let x = ((i % k) as f64 + rng.next_f64()) * s;
                DVec2::new(x, ((i / k) as f64 + rng.next_f64()) * s)
            })
            .collect()
    }

    /// Clusters of 20 points within 0.01 of 30 random centres (wrapped into [0,1)).
    fn clustered(seed: u64) -> Vec<DVec2> {
        let mut rng = Rng::new(seed);
        let wrap = |v: f64| {
            let w = v.rem_euclid(1.0);
            if w >= 1.0 {
                0.0
            } else {
                w
            }
        };
        let mut pts = Vec::new();
        for _ in 0..30 {
            let c = DVec2::new(rng.next_f64(), rng.next_f64());
            for _ in 0..20 {
                let d = DVec2::new(rng.next_f64() - 0.5, rng.next_f64() - 0.5) * 0.02;
                pts.push(DVec2::new(wrap(c.x + d.x), wrap(c.y + d.y)));
            }
        }
        pts
    }

    #[test]
    fn rdf_matches_the_naive_double_loop_bin_for_bin() {
        let c = Cancel::never();
        let below_one = 1.0 - f64::EPSILON / 2.0;
        // On the boundary and at the corners (0 and the largest value below 1), duplicates.
        let mut edge = white(300, 8);
        edge.extend([
            DVec2::ZERO,
            DVec2::new(below_one, 0.0),
            DVec2::new(0.0, below_one),
            DVec2::new(below_one, below_one),
            DVec2::new(0.5, 0.0),
            DVec2::new(0.5, below_one),
            DVec2::new(0.25, 0.25),
            DVec2::new(0.25, 0.25),
            DVec2::ZERO,
        ]);
        let (hex, _, _) = lattice(32, 32, 0.5);
        let sets: Vec<(&str, Vec<DVec2>)> = vec![
            ("random", white(700, 3)),
            ("jitter", jitter(40, 4)),
            ("clustered", clustered(5)),
            ("edge", edge),
            ("lattice", hex),
            ("two", vec![DVec2::new(0.1, 0.9), DVec2::new(0.95, 0.05)]),
            ("three", white(3, 6)),
            ("duplicates", vec![DVec2::new(0.3, 0.7); 5]),
        ];
        let n_psa = spectral_bins(1600);
        for (name, pts) in &sets {
            for (bins, r_max) in [
                (64, 0.5),
                (90, 0.2),
                (1, 0.5),
                (1000, 0.013),
                (200, 0.07),
                (n_psa, 0.5),
            ] {
                let fast = rdf(pts, bins, r_max, &c).unwrap();
                let naive = rdf_naive(pts, bins, r_max, &c).unwrap();
                assert_eq!(fast, naive, "{name}: bins = {bins}, r_max = {r_max}");
            }
            // PSA's own --rdf range.
            let (bins, r_max) = psa_rdf_range(pts.len());
            let fast = rdf(pts, bins, r_max, &c).unwrap();
            assert_eq!(fast, rdf_naive(pts, bins, r_max, &c).unwrap(), "{name}");
        }
    }

    #[test]
    fn rdf_of_white_noise_is_one_within_its_counting_error() {
        let n = 2048;
        let pts = white(n, 11);
        let g = rdf(&pts, 20, 0.5, &Cancel::never()).unwrap();
        let pairs = (n * (n - 1) / 2) as f64;
        let dr = g.bin_width();
        for (i, &v) in g.values().iter().enumerate() {
            let expected = pairs * PI * dr * dr * (2 * i + 1) as f64;
            let sigma = 1.0 / expected.sqrt();
            assert!((v - 1.0).abs() < 6.0 * sigma, "g[{i}] = {v}, ±{sigma}");
        }
    }

    #[test]
    fn rdf_of_a_lattice_is_zero_below_its_spacing() {
        let (pts, u, _) = lattice(32, 32, 0.5);
        let g = rdf(&pts, 64, 0.5, &Cancel::never()).unwrap();
        let dr = g.bin_width();
        // Lattice spacings: |u| = 1/32 and |v| = √(1/64² + 1/32²) ≈ 0.0349.
        for (i, &v) in g.values().iter().enumerate() {
            if (i + 1) as f64 * dr < u.length() * (1.0 - 1e-9) {
                assert_eq!(v, 0.0, "bin {i}");
            }
        }
    }

    #[test]
    fn radial_power_matches_the_naive_transform() {
        let c = Cancel::never();
        for (n, seed) in [(256, 5), (1000, 6)] {
            let pts = white(n, seed);
            let bins = spectral_bins(n);
            let g = rdf(&pts, bins, 0.5, &c).unwrap();
            let fast = radial_power_from_rdf(&g, bins, 0.5 * n as f64, &c).unwrap();
            let naive = radial_power_from_rdf_naive(&g, bins, 0.5 * n as f64).unwrap();
            let worst = fast
                .values()
                .iter()
                .zip(naive.values())
                .map(|(a, b)| (a - b).abs())
                .fold(0.0, f64::max);
            // J₀'s error (< 1e-7) times 2πN Σ|g − 1| r w Δr.
            assert!(worst < 1e-5, "n = {n}: max |ΔP| = {worst:e}");
        }
    }

    /// max |P_a − P_b| / max(1, |P_b|).
    fn worst_relative(a: &RadialPower, b: &RadialPower) -> f64 {
        assert_eq!(a.values().len(), b.values().len());
        a.values()
            .iter()
            .zip(b.values())
            .map(|(x, y)| (x - y).abs() / y.abs().max(1.0))
            .fold(0.0, f64::max)
    }

    #[test]
    fn the_fast_transform_matches_the_direct_sum_and_its_statistics() {
        let c = Cancel::never();
        let (hex, _, _) = lattice(32, 32, 0.5);
        let mut edge = jitter(20, 9);
        edge.extend([DVec2::ZERO, DVec2::new(1.0 - f64::EPSILON / 2.0, 0.5)]);
        let sets: Vec<(&str, Vec<DVec2>)> = vec![
            ("random", white(256, 5)),
            ("jitter", jitter(32, 7)),
            ("clustered", clustered(3)),
            ("lattice", hex),
            ("edge", edge),
            ("two", vec![DVec2::new(0.1, 0.9), DVec2::new(0.95, 0.05)]),
            ("three", white(3, 6)),
            ("duplicates", vec![DVec2::new(0.3, 0.7); 4]),
        ];
        for (name, pts) in &sets {
            let fast = radial_power(pts, &c).unwrap();
            let direct = radial_power_direct(pts, &c).unwrap();
            let worst = worst_relative(&fast, &direct);
            assert!(worst < 1e-10, "{name}: max |ΔP| = {worst:e}");
            let (nf, nd) = (effective_nyquist(&fast), effective_nyquist(&direct));
            let (of, od) = (oscillations(&fast), oscillations(&direct));
            assert!((nf - nd).abs() <= 1e-9, "{name}: ν_eff {nf} vs {nd}");
            assert!(
                (of - od).abs() <= 1e-9 * od.max(1.0),
                "{name}: {of} vs {od}"
            );
            // The same transform from the whole RDF (other bins: the public entry point).
            let g = rdf(pts, 500, 0.5, &c).unwrap();
            for (bins, nu_max) in [(700, 0.5 * pts.len() as f64), (300, 40.0), (90, 3.0)] {
                let fast = radial_power_from_rdf(&g, bins, nu_max, &c).unwrap();
                let direct = radial_power_from_rdf_direct(&g, bins, nu_max, &c).unwrap();
                let worst = worst_relative(&fast, &direct);
                assert!(worst < 1e-10, "{name}, {bins} to {nu_max}: {worst:e}");
            }
        }
    }

    #[test]
    fn radial_power_of_white_noise_averages_to_one() {
        let n = 1024;
        let pts = white(n, 9);
        let rp = radial_power(&pts, &Cancel::never()).unwrap();
        // Mean over 16 ≤ ν < 256 (beyond the lowest frequencies, where the window dominates).
        let sel: Vec<f64> = (0..rp.values().len())
            .filter(|&k| (16.0..256.0).contains(&rp.frequency(k)))
            .map(|k| rp.values()[k])
            .collect();
        let mean = sel.iter().sum::<f64>() / sel.len() as f64;
        assert!((mean - 1.0).abs() < 0.05, "mean P = {mean}");
    }

    #[test]
    fn effective_nyquist_of_a_step_spectrum_is_the_step() {
        // P = 0 below ν_c and 100 above: the disc mean exceeds 0.5 one sample after ν_c and
        // is below 0.1 up to ν_c, so ν_j is the last sample below ν_c.
        let n = 1024;
        let bins = 3200;
        let nu_max = 512.0;
        let dnu = nu_max / bins as f64;
        for nu_c in [8.0, 20.0, 30.05] {
            let values = (0..bins)
                .map(|k| if (k as f64) * dnu < nu_c { 0.0 } else { 100.0 })
                .collect();
            let rp = RadialPower { n, nu_max, values };
            let last = ((nu_c / dnu).ceil() - 1.0) * dnu;
            let got = effective_nyquist(&rp);
            assert!((got - last / 32.0).abs() < 1e-12, "ν_c = {nu_c}: {got}");
        }
        // A flat spectrum has no such frequency.
        let flat = RadialPower {
            n,
            nu_max,
            values: vec![1.0; bins],
        };
        assert_eq!(effective_nyquist(&flat), 0.0);
    }

    #[test]
    fn oscillations_of_a_constant_offset_are_ten_times_the_offset() {
        // P = 0 below ν_0 and 1 + a above: the RMS of P − 1 over the ring is a, up to the
        // trapezoid's ring ν_{k1}² − ν_0² (exact for the linear integrand) over ν₁² − ν_0².
        let n = 1024;
        let bins = 3200;
        let nu_max = 512.0;
        let dnu = nu_max / bins as f64;
        let a = 0.3;
        let k0 = 150;
        let values = (0..bins)
            .map(|k| if k < k0 { 0.0 } else { 1.0 + a })
            .collect();
        let rp = RadialPower { n, nu_max, values };
        let nu0 = k0 as f64 * dnu;
        let nu1 = nu0 + 10.0 * 16.0;
        let k1 = (nu1 / dnu) as usize + 1;
        let nuk1 = k1 as f64 * dnu;
        let want = 10.0 * a * ((nuk1 * nuk1 - nu0 * nu0) / (nu1 * nu1 - nu0 * nu0)).sqrt();
        let got = oscillations(&rp);
        assert!((got - want).abs() < 1e-12, "{got} vs {want}");
        assert!((got - 10.0 * a).abs() < 0.01 * 10.0 * a);
        let flat = RadialPower {
            n,
            nu_max,
            values: vec![1.0; bins],
        };
        assert_eq!(oscillations(&flat), 0.0);
    }

    #[test]
    fn bond_orientational_order_of_a_near_equilateral_lattice_is_one() {
        // 26 × 30 with alternate rows offset by half a cell: 2c/r = 1.7333 ≈ √3.
        let (pts, u, v) = lattice(26, 30, 0.5);
        let want = lattice_boo(u, v);
        assert!(want > 0.999_99);
        let got = bond_orientational_order(&pts, &Cancel::never()).unwrap();
        assert!((got - want).abs() < 1e-12, "{got} vs {want}");
    }

    #[test]
    fn bond_orientational_order_of_lattices_matches_the_closed_form() {
        // The stretched hex lattice of `hex` at N = 1024 (32 × 32; PSA prints 0.957333), a
        // square grid sheared by one cell over its height (so that each cell has one Delaunay
        // diagonal), and few points (N = 6: the widest band).
        for (c, r, shift) in [
            (32, 32, 0.5),
            (32, 32, 1.0 / 32.0),
            (3, 2, 0.5),
            (40, 20, 0.5),
        ] {
            let (pts, u, v) = lattice(c, r, shift);
            let want = lattice_boo(u, v);
            let got = bond_orientational_order(&pts, &Cancel::never()).unwrap();
            assert!(
                (got - want).abs() < 1e-12,
                "{c}×{r}, shift {shift}: {got} vs {want}"
            );
        }
        // The unsheared limit: directions 0°, 90°, 135° give |1 − 1 − i|/3 = 1/3.
        let square = six_fold(DVec2::X) + six_fold(DVec2::Y) + six_fold(DVec2::new(-1.0, 1.0));
        assert!((square.length() / 3.0 - 1.0 / 3.0).abs() < 1e-15);
    }

    #[test]
    fn bond_orientational_order_counts_a_duplicate_with_its_twin() {
        let (mut pts, u, v) = lattice(26, 30, 0.5);
        pts.push(pts[17]);
        let got = bond_orientational_order(&pts, &Cancel::never()).unwrap();
        assert!((got - lattice_boo(u, v)).abs() < 1e-12);
        // Two points, the smallest set: finite, in [0, 1].
        let two = [DVec2::new(0.1, 0.2), DVec2::new(0.6, 0.3)];
        let b = bond_orientational_order(&two, &Cancel::never()).unwrap();
        assert!((0.0..=1.0).contains(&b), "{b}");
    }

    #[test]
    fn white_noise_statistics_are_in_psa_s_range() {
        let s = psa_statistics(&white(1024, 1), &Cancel::never()).unwrap();
        assert_eq!(s.effective_nyquist, 0.0);
        assert!((0.2..0.4).contains(&s.oscillations), "{s:?}");
        assert!((0.3..0.45).contains(&s.bond_orientational_order), "{s:?}");
    }

    #[test]
    fn bad_input_is_a_typed_error() {
        let c = Cancel::never();
        let one = [DVec2::new(0.5, 0.5)];
        assert!(matches!(
            psa_statistics(&one, &c),
            Err(MetricsError::TooFewPoints { n: 1, .. })
        ));
        let nan = [DVec2::new(0.5, 0.5), DVec2::new(f64::NAN, 0.1)];
        assert!(matches!(
            psa_statistics(&nan, &c),
            Err(MetricsError::NonFinite { index: 1, .. })
        ));
        assert!(matches!(
            bond_orientational_order(&nan, &c),
            Err(MetricsError::NonFinite { index: 1, .. })
        ));
        let out = [DVec2::new(0.5, 0.5), DVec2::new(1.0, 0.1)];
        assert!(matches!(
            rdf(&out, 10, 0.5, &c),
            Err(MetricsError::OutOfRange { index: 1, .. })
        ));
        let pts = white(10, 1);
        for (bins, r_max) in [(0, 0.5), (10, 0.0), (10, 0.51), (10, f64::NAN)] {
            assert!(matches!(
                rdf(&pts, bins, r_max, &c),
                Err(MetricsError::InvalidRdfRange { .. })
            ));
        }
        let g = rdf(&pts, 10, 0.5, &c).unwrap();
        assert!(matches!(
            radial_power_from_rdf(&g, 10, f64::INFINITY, &c),
            Err(MetricsError::InvalidFrequencyRange { .. })
        ));
        let many = vec![DVec2::new(0.5, 0.5); PSA_MAX_N + 1];
        assert!(matches!(
            psa_statistics(&many, &c),
            Err(MetricsError::TooManyPoints { .. })
        ));
    }

    #[test]
    fn a_cancelled_token_stops_every_stage() {
        let c = Cancel::new();
        c.cancel();
        let pts = white(300, 2);
        assert_eq!(rdf(&pts, 10, 0.5, &c), Err(MetricsError::Cancelled));
        assert_eq!(
            bond_orientational_order(&pts, &c),
            Err(MetricsError::Cancelled)
        );
        let g = rdf(&pts, 10, 0.5, &Cancel::never()).unwrap();
        assert_eq!(
            radial_power_from_rdf(&g, 10, 150.0, &c),
            Err(MetricsError::Cancelled)
        );
        assert_eq!(psa_statistics(&pts, &c), Err(MetricsError::Cancelled));
    }

    #[test]
    fn radial_power_work_counts_the_terms_the_fast_path_sums() {
        for n in [2, 100, 1024, 4096] {
            let m = spectral_bins(n);
            let dr = 0.5 / m as f64;
            let dnu = 0.5 * n as f64 / m as f64;
            let long = 0.25;
            let last = ((long / dr).floor() as usize).min(m - 1);
            // Counted here from the definitions: the frequencies before the long window over
            // their windows, then per block [K₀, 4K₀) from the first k with J(k) < last, the
            // samples J(k) < j ≤ J(K₀), J(k) = #{j ≤ last: 2πν_k·r_j ≤ 3}.
            let len = |k: usize| window_length(k as f64 * dnu, n, 0.5);
            let k_long = (0..m).find(|&k| len(k) == long).unwrap_or(m);
            let jk = |k: usize| {
                (1..=last)
                    .filter(|&j| TAU * (k as f64 * dnu) * (j as f64 * dr) <= 3.0)
                    .count()
            };
            let mut counted: usize = (0..k_long)
                .map(|k| (1..m).filter(|&j| j as f64 * dr <= len(k)).count())
                .sum();
            let fast = m - k_long >= 64;
            if fast {
                let mut k0 = (k_long..m).find(|&k| jk(k) < last).unwrap_or(m);
                while k0 < m {
                    let k1 = (4 * k0).clamp(k0 + 1, m);
                    counted += (k0..k1).map(|k| jk(k0) - jk(k)).sum::<usize>();
                    k0 = k1;
                }
            } else {
                counted = (0..m)
                    .map(|k| (1..m).filter(|&j| j as f64 * dr <= len(k)).count())
                    .sum();
            }
            let (pairs, terms, fft) = radial_power_work(n);
            // Within one per frequency (j·Δr ≤ L and j ≤ ⌊L/Δr⌋ may differ by a rounding).
            assert!(
                (terms - counted as f64).abs() <= m as f64,
                "n = {n}: {terms} vs {counted}"
            );
            let all = (n * (n - 1) / 2) as f64;
            assert!(
                pairs <= all && pairs >= all * PI / 32.0 * 0.99 - 1.0,
                "n = {n}"
            );
            if n == 4096 {
                // The fast path: about 1% of the direct sum's m²/2 terms, and FFTs.
                assert!(terms < 0.02 * (m * m) as f64 / 2.0, "{terms}");
                assert!(fft > 0.0 && pairs < 0.3 * all, "{fft} {pairs}");
            }
        }
    }

    #[test]
    fn psa_rdf_range_follows_psa_s_config() {
        let (bins, r_max) = psa_rdf_range(1024);
        assert_eq!(bins, 128);
        assert!((r_max - 8.0 * hex_distance(1024)).abs() < 1e-15);
        assert_eq!(psa_rdf_range(3), (1, 0.5));
        assert_eq!(spectral_bins(1024), 3200);
        assert_eq!(spectral_bins(954), 3088);
    }
}
