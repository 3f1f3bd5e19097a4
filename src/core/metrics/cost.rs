//! What the point-set statistics cost: distances, discrepancies, t-value, PSA's, the RDF and
//! the net check (work, seconds, bytes). Rates and method: [`crate::core::budget`].

use crate::core::budget::{cpu, parallel, touch, Estimate, Unit, REFERENCE_CORES};

/// One cell of the star-discrepancy sweep (vectorised, serial).
pub(crate) const STAR_CELL_NS: f64 = 0.65;
/// Per point: the minimum distance (grid search), the t-value digits per (m·log₂ m).
pub(crate) const MIN_DISTANCE_NS: f64 = 400.0;
pub(crate) const L2_NS: f64 = 80.0;
/// One pair of an RDF the pair loop visits: a toroidal distance and, within the radius, its
/// square root and bin (parallel).
pub const PAIR_NS: f64 = 2.0;
/// One term of PSA's RDF-to-power transform summed directly: J₀, the window and a
/// multiply-add (parallel).
pub const PSA_TERM_NS: f64 = 10.0;
/// Per unit of L·log₂ L of the transform's FFTs of length L (parallel).
pub const PSA_FFT_NS: f64 = 0.3;
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

/// PSA's statistics of `n` points ([`crate::core::metrics::psa_statistics`]): the RDF's pairs
/// closer than ¼ by a cell grid, the transform's directly summed J₀ terms and FFTs
/// ([`crate::core::metrics::psa::radial_power_work`]), and a toroidal Delaunay triangulation
/// of ≈ N + 16√N points. Nothing above [`crate::core::metrics::PSA_MAX_N`] points (not
/// computed there).
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
    let m = psa::spectral_bins(n) as f64;
    let (pairs, terms, fft) = psa::radial_power_work(n);
    let tri = nf + 16.0 * nf.sqrt();
    // Per-chunk histograms of the ≈ m/2 bins used, the prefix sums (7 rows), the FFT buffers
    // (23 rows of up to ≈ 2m complex values), the triangulation.
    let bytes = 8.0 * m * (rayon_chunks() + 8.0) + 16.0 * 23.0 * 2.0 * m + 200.0 * tri;
    Estimate::new(
        format!("PSA statistics of {n} points ({m} RDF bins)"),
        pairs,
        Unit::Pairs,
        parallel(pairs * PAIR_NS + terms * PSA_TERM_NS + fft * PSA_FFT_NS)
            + cpu(tri * DELAUNAY_POINT_NS),
        bytes,
    )
}

/// Per-chunk histograms of the RDF (4 per thread of the reference machine).
pub(crate) fn rayon_chunks() -> f64 {
    4.0 * REFERENCE_CORES
}

/// A radial distribution function of `n` points over `bins` bins up to `r_max`
/// ([`crate::core::metrics::rdf`]: the pairs its cell grid visits).
pub fn rdf(n: usize, bins: usize, r_max: f64) -> Estimate {
    let pairs = crate::core::metrics::psa::rdf_work(n, r_max);
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
