//! What the point-set statistics cost: distances, discrepancies, t-value, PSA's, the RDF and
//! the net check (work, seconds, bytes). Rates and method: [`crate::core::budget`].

use crate::core::budget::{cpu, parallel, touch, Estimate, Unit, REFERENCE_CORES};

/// One cell of the star-discrepancy sweep (vectorised, serial).
pub(crate) const STAR_CELL_NS: f64 = 0.65;
/// Per point: the minimum distance (grid search), the t-value digits per (m·log₂ m).
pub(crate) const MIN_DISTANCE_NS: f64 = 400.0;
pub(crate) const L2_NS: f64 = 80.0;
/// One pair of an RDF: a toroidal distance, its square root and bin (parallel).
pub const PAIR_NS: f64 = 2.0;
/// One term of PSA's RDF-to-power transform: J₀, the window and a multiply-add (parallel).
pub const PSA_TERM_NS: f64 = 10.0;
/// Per point of the toroidal Delaunay triangulation and its neighbour rings (serial).
pub(crate) const DELAUNAY_POINT_NS: f64 = 500.0;
pub(crate) const TVALUE_NS: f64 = 5.0;

/// Every statistic of `n` points ([`crate::core::metrics::statistics`]): the minimum
/// distance, the exact star discrepancy (N² sweep cells; skipped above
/// [`crate::core::metrics::STATISTICS_STAR_MAX_N`] points), the L2-star discrepancy
/// (N log N) and, for N = 2^m, the t-value (N·m·log₂ m).
pub fn statistics(n: usize) -> Estimate {
    let nf = n as f64;
    let star = if n <= crate::core::metrics::STATISTICS_STAR_MAX_N {
        nf * (nf + 1.0)
    } else {
        0.0
    };
    let log = nf.max(2.0).log2();
    let t = if n.is_power_of_two() && n > 1 {
        nf * log * log.log2().max(1.0)
    } else {
        0.0
    };
    let ns = nf * MIN_DISTANCE_NS + star * STAR_CELL_NS + nf * log * L2_NS + t * TVALUE_NS;
    let bytes = 64.0 * nf;
    Estimate::new(
        format!("statistics of {n} points"),
        star.max(nf),
        if star > 0.0 {
            Unit::Cells
        } else {
            Unit::Points
        },
        cpu(ns) + touch(bytes),
        bytes,
    )
}

/// The exact star discrepancy of `n` points alone ([`crate::core::metrics::star_discrepancy`]:
/// N(N+1) sweep cells), as the Python module's `discrepancy(points, "star")` computes it.
pub fn star_discrepancy(n: usize) -> Estimate {
    let nf = n as f64;
    let cells = nf * (nf + 1.0);
    Estimate::new(
        format!("star discrepancy of {n} points"),
        cells,
        Unit::Cells,
        cpu(cells * STAR_CELL_NS) + touch(32.0 * nf),
        32.0 * nf,
    )
}

/// PSA's statistics of `n` points ([`crate::core::metrics::psa_statistics`]): the RDF over
/// N(N−1)/2 pairs, its transform (≈ m²/2 terms for m = ⌊100√N⌋ RDF bins and frequencies),
/// and a toroidal Delaunay triangulation of ≈ N + 16√N points. Nothing above
/// [`crate::core::metrics::PSA_MAX_N`] points (not computed there).
pub fn psa_statistics(n: usize) -> Estimate {
    use crate::core::metrics::psa;
    if !(psa::PSA_MIN_N..=psa::PSA_MAX_N).contains(&n) {
        return Estimate::new(
            format!("PSA statistics of {n} points (skipped)"),
            0.0,
            Unit::Pairs,
            0.0,
            0.0,
        );
    }
    let nf = n as f64;
    let pairs = nf * (nf - 1.0) / 2.0;
    let m = psa::spectral_bins(n) as f64;
    let terms = psa::transform_terms(n);
    let tri = nf + 16.0 * nf.sqrt();
    let bytes = 8.0 * m * 2.0 * (rayon_chunks() + 2.0) + 200.0 * tri;
    Estimate::new(
        format!("PSA statistics of {n} points ({m} RDF bins)"),
        pairs,
        Unit::Pairs,
        parallel(pairs * PAIR_NS + terms * PSA_TERM_NS) + cpu(tri * DELAUNAY_POINT_NS),
        bytes,
    )
}

/// Per-chunk histograms of the RDF (4 per thread of the reference machine).
pub(crate) fn rayon_chunks() -> f64 {
    4.0 * REFERENCE_CORES
}

/// A radial distribution function of `n` points over `bins` bins ([`crate::core::metrics::rdf`]).
pub fn rdf(n: usize, bins: usize) -> Estimate {
    let nf = n as f64;
    let pairs = nf * (nf - 1.0).max(0.0) / 2.0;
    let bytes = 8.0 * bins as f64 * (rayon_chunks() + 1.0);
    Estimate::new(
        format!("RDF of {n} points ({bins} bins)"),
        pairs,
        Unit::Pairs,
        parallel(pairs * PAIR_NS) + touch(bytes),
        bytes,
    )
}

/// The (0, k, 2)-net check of every power-of-two prefix of `n` points
/// ([`crate::core::metrics::net_prefixes`]): Σₖ 2ᵏ·(k + 1) < 2N·(log₂ N + 1) cell counts.
pub fn net_prefixes(n: usize) -> Estimate {
    let nf = n as f64;
    let cells = 2.0 * nf * (nf.max(1.0).log2().floor() + 1.0);
    let bytes = 48.0 * nf;
    Estimate::new(
        format!("(0,k,2)-net check of the power-of-two prefixes of {n} points"),
        cells,
        Unit::Cells,
        cpu(cells * TVALUE_NS) + touch(bytes),
        bytes,
    )
}
