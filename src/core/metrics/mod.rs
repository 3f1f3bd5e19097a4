//! Point-set statistics: minimum distance, star and L2-star discrepancy, t-value of nets, and
//! PSA's spectral and spatial statistics ([`psa`]: RDF, effective Nyquist frequency,
//! oscillations, bond-orientational order).
//!
//! Every function is a pure function of a slice of points and returns
//! `Result<_, `[`MetricsError`]`>`; the long ones take a [`Cancel`] token and check it inside
//! their loops. [`statistics`] runs them all and records the wall time of every stage.
//!
//! # Conventions
//!
//! - **Domain.** Points are `f64` pairs ([`DVec2`]) in the unit square **[0,1)²** (crate
//!   convention). A non-finite coordinate or one outside [0,1) is an error naming the point's
//!   index ([`MetricsError::NonFinite`], [`MetricsError::OutOfRange`]); nothing is clamped.
//!   The 1D functions take values in the closed interval `[0,1]` (the classical setting of the
//!   1D formula, where the lecture's example `x_i = i/N` has `x_N = 1`).
//! - **Distances are toroidal** (periodic): `d(p,q)² = Σ_k min(|p_k−q_k|, 1−|p_k−q_k|)²`.
//! - **Hexagonal normalisation.** N discs on the unit torus are packed best by the hexagonal
//!   lattice, whose nearest-neighbour distance is `d_hex(N) = √(2 / (√3·N))`. Normalised
//!   distances are `d / d_hex(N)`. PSA (Heck, Schlömer, Deussen 2013) reports minimum distances
//!   multiplied by `√(√3·N / 2)`, which is exactly `1 / d_hex(N)`: our normalised values are
//!   PSA's (and Lagae & Dutré's relative radius ρ). 1 is the hexagonal packing,
//!   `√(√3/2) ≈ 0.93` a square grid; the minimum distance of white noise tends to 0 as N grows.
//! - **Star discrepancy** (the lecture's `D*_N`):
//!   `D*_N(P) = sup_{(a,b) ∈ [0,1]²} | #{x_i ∈ [0,a)×[0,b)} / N − a·b |`.
//!   The supremum is approached either by an *open* box `[0,a)×[0,b)` holding too few points
//!   (`a·b − A_open/N`, attained at `a, b` ∈ {point coordinates} ∪ {1}) or by a *closed* box
//!   `[0,a]×[0,b]` holding too many (`A_closed/N − a·b`, the limit of half-open boxes shrinking
//!   onto `a, b` ∈ {point coordinates}). [`StarDiscrepancy`] reports which kind, so a GUI can
//!   draw the worst anchored box. Computed exactly (no sampling of boxes): see [`star`].
//! - **L2-star discrepancy** `T_N = ( ∫_{[0,1]²} (A([0,a)×[0,b))/N − a·b)² da db )^½`, by
//!   Warnock's closed form (see [`l2`]).
//! - **t-value.** For `N = b^m` points, the smallest `t` such that every elementary interval
//!   `[i·b^−k, (i+1)·b^−k) × [j·b^−(m−t−k), (j+1)·b^−(m−t−k))` (all `0 ≤ k ≤ m−t`) holds exactly
//!   `b^t` points. Intervals are half-open, so a point on a boundary belongs to the upper cell;
//!   membership is decided exactly for the `f64` values given (see [`tvalue`]).
//!
//! # Functions, references and costs
//!
//! | statistic | fast | reference (tests, benches) |
//! |---|---|---|
//! | min distance, mean NN | [`min_distance`]: grid, O(N) expected | [`min_distance_naive`]: all pairs, O(N²) |
//! | star discrepancy, 2D | [`star_discrepancy`]: sweep, O(N²) | [`star_discrepancy_brute_force`]: all critical boxes, O(N³) |
//! | star discrepancy, 1D | [`star_discrepancy_1d`]: closed form, O(N log N) | [`star_discrepancy_1d_brute_force`]: O(N²) |
//! | L2-star discrepancy | [`l2_star_discrepancy`]: Fenwick tree, O(N log N) | [`l2_star_discrepancy_naive`]: double sum, O(N²) |
//! | t-value | [`t_value`]: digit counting, O(N m log m) | (tests: every interval, exact integers) |
//! | RDF | [`rdf`]: all pairs, parallel, O(N²) | [`psa::rdf_naive`]: serial double loop |
//! | PSA radial power | [`psa::radial_power_from_rdf`]: fast J₀, window cut, parallel | [`psa::radial_power_from_rdf_naive`]: exact J₀, every sample |
//! | bond-orientational order | [`bond_orientational_order`]: toroidal Delaunay, O(N log N) | (tests: lattices in closed form, PSA's values) |
//!
//! # Accuracy
//! Star discrepancies are exact up to one rounding of `count/N − a·b` (counts are integers).
//! The L2-star sums are accumulated with error-free transformations (double-double, `dd.rs`),
//! so the fast and the naive algorithms agree to ~1e-13 relative even for low-discrepancy
//! sets, where Warnock's three terms (≈ 0.1) cancel to `T² ≈ 10⁻⁸`.
//!
//! # References
//! - H. Niederreiter, *Random Number Generation and Quasi-Monte Carlo Methods*, SIAM 1992
//!   (Thm 2.6: 1D closed form; Def. 4.1: (t,m,s)-nets).
//! - T. T. Warnock, *Computational investigations of low-discrepancy point sets*, 1972.
//! - H. Niederreiter, *Discrepancy and convex programming*, Ann. Mat. Pura Appl. 1972, and
//!   M. Gnewuch, A. Srivastav, C. Winzen, *Finding optimal volume subintervals with k points and
//!   calculating the star discrepancy are NP-hard problems*, J. Complexity 2009, §2 (the
//!   critical-box lemma used here).
//! - D. Dobkin, D. Eppstein, D. Mitchell, *Computing the discrepancy with applications to
//!   supersampling patterns*, ACM TOG 1996 (an O(N log² N) alternative, not used: the O(N²)
//!   sweep meets our speed targets and is far simpler to verify).
//! - D. Heck, T. Schlömer, O. Deussen, *Blue noise sampling with controlled aliasing*, ACM TOG
//!   2013 (PSA's normalisation of distances).

pub mod cost;
pub mod cube;
mod dd;
mod hankel;
pub mod l2;
pub mod mindist;
mod pairs;
pub mod psa;
pub mod star;
pub mod tvalue;

use std::time::{Duration, Instant};

use glam::DVec2;
use serde::Serialize;

pub use crate::core::cancel::{Cancel, Cancelled};
pub use l2::{l2_star_discrepancy, l2_star_discrepancy_naive, L2_NAIVE_MAX_N};
pub use mindist::{
    hex_distance, min_distance, min_distance_naive, MinDistance, MIN_DISTANCE_NAIVE_MAX_N,
};
pub use psa::{
    bond_orientational_order, effective_nyquist, oscillations, psa_statistics, radial_power, rdf,
    PsaStatistics, RadialPower, Rdf, PSA_MAX_N, PSA_MIN_N,
};
pub use star::{
    star_discrepancy, star_discrepancy_1d, star_discrepancy_1d_brute_force,
    star_discrepancy_brute_force, StarDiscrepancy, STAR_BRUTE_FORCE_MAX_N, STAR_EXACT_MAX_N,
};
pub use tvalue::{net_prefixes, t_value, ElementaryViolation, NetPrefixes, PrefixCheck, TValue};

/// Why a statistic could not be computed. Every variant names the offending input.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum MetricsError {
    /// The point set is empty.
    #[error("the point set is empty: at least 1 point is needed")]
    Empty,
    /// Too few points for the statistic (e.g. a minimum distance needs two).
    #[error("{what} needs at least {min} points, got n = {n}")]
    TooFewPoints {
        what: &'static str,
        n: usize,
        min: usize,
    },
    /// More points than the routine accepts (its cost grows too fast to finish).
    #[error("{what} accepts at most {max} points (it costs {cost}), got n = {n}")]
    TooManyPoints {
        what: &'static str,
        n: usize,
        max: usize,
        cost: &'static str,
    },
    /// A coordinate is NaN or infinite.
    #[error(
        "point {index} = ({x}, {y}) is not finite: coordinates must be finite numbers in [0, 1)"
    )]
    NonFinite { index: usize, x: f64, y: f64 },
    /// A coordinate lies outside [0, 1).
    #[error(
        "point {index} = ({x}, {y}) lies outside the unit square: coordinates must be in [0, 1)"
    )]
    OutOfRange { index: usize, x: f64, y: f64 },
    /// A 1D value is NaN, infinite or outside [0, 1].
    #[error("value {index} = {}: 1D values must be finite numbers in [0, 1]", crate::core::params::fmt_num(*.value))]
    ValueOutOfRange { index: usize, value: f64 },
    /// The number of points is not a power of the base (t-values are defined for N = b^m).
    #[error("n = {n} is not a power of base {base}: a t-value needs n = base^m points")]
    NotPowerOfBase { n: usize, base: u32 },
    /// The base of a net is below 2.
    #[error("base = {base}: must be an integer ≥ 2")]
    InvalidBase { base: u32 },
    /// An RDF binning outside the accepted range.
    #[error(
        "RDF bins = {bins}, r_max = {r_max}: need 1 ≤ bins ≤ {max_bins} and 0 < r_max ≤ 0.5 \
         (annuli beyond 0.5 are not whole circles on the unit torus)"
    )]
    InvalidRdfRange {
        bins: usize,
        r_max: f64,
        max_bins: usize,
    },
    /// A frequency sampling outside the accepted range.
    #[error("frequency bins = {bins}, nu_max = {nu_max}: need 1 ≤ bins ≤ {max_bins} and a positive nu_max")]
    InvalidFrequencyRange {
        bins: usize,
        nu_max: f64,
        max_bins: usize,
    },
    /// More dimensions than the measure accepts.
    #[error("{what} accepts at most {max} dimensions ({why}), got dims = {dims}")]
    TooManyDims {
        what: &'static str,
        dims: usize,
        max: usize,
        why: &'static str,
    },
    /// Fewer dimensions than the measure needs.
    #[error("{what} needs at least {min} dimensions, got dims = {dims}")]
    TooFewDims {
        what: &'static str,
        dims: usize,
        min: usize,
    },
    /// A d-dimensional point set is not in [0,1)^d, or a projection is not in it.
    #[error(transparent)]
    Cube(#[from] crate::core::cube::CubeError),
    /// The computation was cancelled.
    #[error("cancelled")]
    Cancelled,
}

impl From<Cancelled> for MetricsError {
    fn from(_: Cancelled) -> Self {
        MetricsError::Cancelled
    }
}

/// Checks that the set is non-empty and every point is finite and inside [0,1)².
pub(crate) fn validate(points: &[DVec2]) -> Result<(), MetricsError> {
    if points.is_empty() {
        return Err(MetricsError::Empty);
    }
    for (index, p) in points.iter().enumerate() {
        if !p.x.is_finite() || !p.y.is_finite() {
            return Err(MetricsError::NonFinite {
                index,
                x: p.x,
                y: p.y,
            });
        }
        if !(0.0..1.0).contains(&p.x) || !(0.0..1.0).contains(&p.y) {
            return Err(MetricsError::OutOfRange {
                index,
                x: p.x,
                y: p.y,
            });
        }
    }
    Ok(())
}

/// How many loop iterations run between two cancellation checks.
pub(crate) const CANCEL_STRIDE: usize = 4096;

/// The exact star discrepancy is skipped by [`statistics`] above this many points (its cost
/// is O(N²): about 2 s at N = 65 536 on one core).
pub const STATISTICS_STAR_MAX_N: usize = 65_536;

/// Every statistic of one point set, with the wall time of each stage (for the CLI and GUI).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Statistics {
    /// Number of points.
    pub n: usize,
    /// Toroidal minimum and mean nearest-neighbour distance; `None` when N < 2.
    pub min_distance: Option<MinDistance>,
    /// Why `min_distance` is `None`.
    pub min_distance_skipped: Option<String>,
    /// Exact star discrepancy; `None` when N > [`STATISTICS_STAR_MAX_N`].
    pub star: Option<StarDiscrepancy>,
    /// Why `star` is `None`.
    pub star_skipped: Option<String>,
    /// L2-star discrepancy (Warnock), always computed (O(N log N)).
    pub l2_star: f64,
    /// t-value in base 2; `None` when N is not a power of 2.
    pub t_value: Option<TValue>,
    /// Why `t_value` is `None`.
    pub t_value_skipped: Option<String>,
    /// Wall time of each stage that ran, in order.
    pub timings: Vec<(&'static str, Duration)>,
}

/// Computes every statistic of `points`: minimum distance and mean nearest-neighbour distance
/// (toroidal, with hexagonal normalisation), exact star discrepancy (skipped above
/// [`STATISTICS_STAR_MAX_N`] points, with the reason recorded), L2-star discrepancy, and the
/// t-value in base 2 when N is a power of 2.
///
/// Errors: an empty set, a non-finite or out-of-range point, cancellation. Skipped stages
/// are not errors.
pub fn statistics(points: &[DVec2], cancel: &Cancel) -> Result<Statistics, MetricsError> {
    validate(points)?;
    let n = points.len();
    let mut timings = Vec::with_capacity(4);

    /// A stage's value and wall time.
    fn timed<T>(
        f: impl FnOnce() -> Result<T, MetricsError>,
    ) -> Result<(T, Duration), MetricsError> {
        let t0 = Instant::now();
        f().map(|v| (v, t0.elapsed()))
    }
    // The exact star discrepancy (serial, the longest stage) runs beside the other three:
    // the same values as one after the other; an error is reported in the stages' order.
    let (star, (md, l2, tv)) = rayon::join(
        || (n <= STATISTICS_STAR_MAX_N).then(|| timed(|| star_discrepancy(points, cancel))),
        || {
            let md = (n >= 2).then(|| timed(|| min_distance(points, cancel)));
            let l2 = timed(|| l2_star_discrepancy(points, cancel));
            let tv = n
                .is_power_of_two()
                .then(|| timed(|| tvalue::t_value(points, 2, cancel)));
            (md, l2, tv)
        },
    );

    /// A stage that ran (its value; its wall time added to `timings` under `name`) or was
    /// skipped (`why`).
    fn stage<T>(
        ran: Option<Result<(T, Duration), MetricsError>>,
        name: &'static str,
        timings: &mut Vec<(&'static str, Duration)>,
        why: impl FnOnce() -> String,
    ) -> Result<(Option<T>, Option<String>), MetricsError> {
        match ran {
            Some(r) => {
                let (v, d) = r?;
                timings.push((name, d));
                Ok((Some(v), None))
            }
            None => Ok((None, Some(why()))),
        }
    }
    let (min_distance, min_distance_skipped) = stage(md, "min distance", &mut timings, || {
        format!("a minimum distance needs at least 2 points, got n = {n}")
    })?;
    let (star, star_skipped) = stage(star, "star discrepancy", &mut timings, || {
        format!(
            "exact star discrepancy skipped: n = {n} > {STATISTICS_STAR_MAX_N} (its cost is O(N²))"
        )
    })?;
    let (l2_star, d) = l2?;
    timings.push(("L2-star discrepancy", d));
    let (t_value, t_value_skipped) = stage(tv, "t-value", &mut timings, || {
        format!("t-value skipped: n = {n} is not a power of 2 (nets in base 2 have 2^m points)")
    })?;

    Ok(Statistics {
        n,
        min_distance,
        min_distance_skipped,
        star,
        star_skipped,
        l2_star,
        t_value,
        t_value_skipped,
        timings,
    })
}
