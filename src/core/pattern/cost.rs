//! What generating n points of each pattern costs (work, seconds, bytes): one arm per pattern
//! and no fallback, so a pattern without a cost does not compile. Rates and method: the
//! module docs of [`crate::core::budget`].

use crate::core::budget::{cpu, touch, Estimate, Unit, REFERENCE_CORES};
use crate::core::format::significant;
use crate::core::pattern::poisson::{default_radius, max_radius};
use crate::core::pattern::{self, Pattern};

/// One best-candidate candidate while the search structures fit in cache (two random numbers,
/// one raster proposal and its distance; measured 7–9 ns at N = 16384 and 14 ns at N = 40000
/// on the loaded reference machine, against 17 and 29 ns before the f32 raster and the
/// neighbours' proposals).
pub const BC_CANDIDATE_NS: f64 = 10.0;
/// Points at which a best-candidate candidate costs twice [`BC_CANDIDATE_NS`] (the raster
/// and grid outgrow the caches).
pub const BC_CACHE_POINTS: f64 = 250_000.0;
/// Per placed point of best candidate (the rebuilt rasters and grids, the exact search of each
/// new best candidate: about ln i of them in step i; measured 0.44 ms per 256-point pattern
/// of `recon --spp 256 --pattern best-candidate`, of which 0.26 ms candidates).
pub(crate) const BC_POINT_NS: f64 = 800.0;
/// One dart of dart throwing (3×3 cells of the grid searched), while the grid fits in cache.
pub const DART_NS: f64 = 170.0;
/// One Bridson annulus try (about 1.7 draws of the rejection sampler, a 5×5 cell search).
pub const BRIDSON_TRY_NS: f64 = 70.0;
/// One point of the simple patterns (grid, random, jitter, hex, the sequences).
pub(crate) const POINT_NS: f64 = 30.0;
/// One pmj02 point (the strata bookkeeping of Pharr 2019).
pub(crate) const PMJ02_POINT_NS: f64 = 300.0;
/// One pmj02bn candidate (a draw and a nearest-neighbour query on the grid).
pub(crate) const PMJ02BN_CANDIDATE_NS: f64 = 250.0;
/// One generator of the rank-1 search for g = 0 (a 2D lattice reduction, ~log₂ N steps).
pub(crate) const RANK1_GENERATOR_NS: f64 = 25.0;
/// One Owen-scrambled Halton point (0.36 s for 2^20 points in bases 2, 3; 0.8 s in 17, 19).
pub(crate) const HALTON_OWEN_POINT_NS: f64 = 800.0;
/// One Lloyd point update (its share of the triangulation of ~n + 16√n points, its cell's
/// centroid).
/// (measured 22–31 ms for 1024 points × 50 iterations).
pub(crate) const LLOYD_UPDATE_NS: f64 = 1_000.0;
/// One SOT point-slice: the projection of a point on a direction, its bucket, its share of
/// the insertion pass, its quantile and displacement (O(n) per slice; measured 11 ns of CPU
/// at n = 1024 on the loaded 2-core machine after the branch-free bucket loop, 17 ns before
/// in the same run; benches/optimize.rs).
pub(crate) const SOT_UPDATE_NS: f64 = 10.0;
/// One GBN point update (the vectorised Gaussian kernel over a cell block of ~256 candidates,
/// ~113 of them within 6σ; measured 0.83 µs of CPU at n = 1024 under load, against 2.2 µs
/// with libm's exp per pair; benches/optimize.rs).
pub(crate) const GBN_UPDATE_NS: f64 = 800.0;
/// One point of the shuffling patterns (N-rooks, multi-jitter, correlated multi-jitter).
pub(crate) const SHUFFLE_POINT_NS: f64 = 150.0;
/// One call of a pattern (checks, allocation): matters for per-pixel patterns.
pub(crate) const PATTERN_CALL_NS: f64 = 200.0;

/// The cost of `pattern.generate(n, ·)`: (amount, unit, CPU seconds of one call, peak bytes).
/// Serial: every pattern generates on one thread.
pub(crate) fn pattern_cost(p: &Pattern, n: usize) -> (f64, Unit, f64, f64) {
    let nf = n as f64;
    let points_bytes = 16.0 * nf;
    let call = cpu(PATTERN_CALL_NS);
    match p {
        Pattern::BestCandidate(b) => {
            let c = best_candidate_candidates(b.m, n);
            let ns = BC_CANDIDATE_NS * (1.0 + nf / BC_CACHE_POINTS);
            // The last rebuild (at the largest power of two below n) and the one before it
            // are alive together: grid cells and raster pixels (24 bytes each, 8 per point).
            let last = if n > 2 {
                (1usize << (usize::BITS - 1 - (n - 1).leading_zeros())) as f64
            } else {
                1.0
            };
            let accel = 1.5 * last * (8.0 * 24.0 + 2.0 * 4.0);
            let bytes = points_bytes + 4.0 * nf + accel;
            let secs = c * cpu(ns) + nf * cpu(BC_POINT_NS) + call + touch(bytes);
            (c, Unit::Candidates, secs, bytes)
        }
        Pattern::PoissonDart(d) => {
            let r = resolved_radius(d.radius, n);
            let darts = dart_darts(r, n, d.max_misses);
            let g = (1.0 / (r * (1.0 + 1e-6)))
                .floor()
                .min((2.0 * nf).sqrt().ceil())
                .max(1.0);
            let bytes = points_bytes + 4.0 * nf + 4.0 * g * g;
            let secs = darts * cpu(DART_NS * (1.0 + nf / 1e6)) + call + touch(bytes);
            (darts, Unit::Darts, secs, bytes)
        }
        Pattern::PoissonBridson(b) => {
            let r = resolved_radius(b.radius, n).max(pattern::poisson::bridson_min_radius());
            let (tries, maximal) = bridson_tries(r, b.k);
            let g = (std::f64::consts::SQRT_2 * (1.0 + 1e-6) / r)
                .ceil()
                .max(1.0)
                + 4.0;
            let bytes = 20.0 * maximal + 4.0 * g * g;
            let secs = tries * cpu(BRIDSON_TRY_NS) + call + touch(bytes);
            (tries, Unit::Tries, secs, bytes)
        }
        Pattern::Lhs(l) => {
            let dims = f64::from(l.dims.max(1));
            let bytes = points_bytes + 4.0 * nf * dims;
            let secs = nf * dims * cpu(POINT_NS) + call + touch(bytes);
            (nf, Unit::Points, secs, bytes)
        }
        Pattern::Pmj02(_) => {
            let bytes = points_bytes + 24.0 * nf;
            (
                nf,
                Unit::Points,
                nf * cpu(PMJ02_POINT_NS) + call + touch(bytes),
                bytes,
            )
        }
        Pattern::Pmj02bn(p) => {
            let c = nf * f64::from(p.candidates.max(1));
            let bytes = points_bytes + 40.0 * nf;
            let secs = nf * cpu(PMJ02_POINT_NS) + c * cpu(PMJ02BN_CANDIDATE_NS) + call;
            (c, Unit::Candidates, secs + touch(bytes), bytes)
        }
        Pattern::Rank1(r) if r.g == 0 && r.z.is_empty() => {
            let generators = (nf / 2.0).max(1.0);
            let secs = generators * nf.max(2.0).log2() * cpu(RANK1_GENERATOR_NS)
                + nf * cpu(POINT_NS)
                + call;
            (
                generators,
                Unit::Candidates,
                secs + touch(points_bytes),
                points_bytes,
            )
        }
        Pattern::Halton(h) if h.scramble == pattern::halton_scramble::HaltonScramble::Owen => {
            // One hashed node permutation per digit of both coordinates.
            let secs = nf * cpu(HALTON_OWEN_POINT_NS) + call + touch(points_bytes);
            (nf, Unit::Points, secs, points_bytes)
        }
        Pattern::Lloyd(l) => {
            let updates = nf * f64::from(l.iterations);
            // Per vertex of the replicated points (~n + 16√n): its copy (16 bytes), delaunator's
            // triangles and halfedges (2 triangles × 2 × 24) and hull arrays (40), the
            // circumcentres (2 × 24), the fan sums (34) and the cells (32): 266 bytes.
            let bytes = points_bytes + 266.0 * (nf + 16.0 * nf.sqrt());
            let secs = updates * cpu(LLOYD_UPDATE_NS) + call + touch(bytes);
            (updates, Unit::PointUpdates, secs, bytes)
        }
        Pattern::Sot(s) => {
            let updates = nf * f64::from(s.iterations) * f64::from(s.directions);
            // The points, velocities and quantile levels (40 bytes a point), and for each of
            // the 8 chunks of directions an accumulator (16) and a slice's buffers (32).
            let bytes = nf * (40.0 + 8.0 * 48.0);
            let secs = updates * cpu(SOT_UPDATE_NS) / REFERENCE_CORES + call;
            (updates, Unit::PointUpdates, secs + touch(bytes), bytes)
        }
        Pattern::Gbn(g) => {
            let updates = nf * f64::from(g.iterations);
            // Points, velocities, gradients, the per-point sums (24) and the grid's copies.
            let bytes = points_bytes * 5.0 + 8.0 * nf;
            let secs = updates * cpu(GBN_UPDATE_NS) / REFERENCE_CORES + call + touch(bytes);
            (updates, Unit::PointUpdates, secs, bytes)
        }
        Pattern::Padded(p) => {
            // One pair: the base pattern, then its shuffle.
            let base = pattern::cube::padded::base_pattern(p.base);
            let (amount, unit, secs, bytes) = pattern_cost(&base, n);
            let shuffle = 8.0 * nf + points_bytes;
            (
                amount,
                unit,
                secs + nf * cpu(SHUFFLE_POINT_NS) + touch(shuffle),
                bytes + shuffle,
            )
        }
        Pattern::NRooks(_) | Pattern::MultiJitter(_) | Pattern::CorrelatedMultiJitter(_) => {
            let bytes = points_bytes + 8.0 * nf;
            (
                nf,
                Unit::Points,
                nf * cpu(SHUFFLE_POINT_NS) + call + touch(bytes),
                bytes,
            )
        }
        // The simple patterns: one cheap step per point.
        Pattern::Grid(_)
        | Pattern::Random(_)
        | Pattern::Jitter(_)
        | Pattern::Hex(_)
        | Pattern::VanDerCorput(_)
        | Pattern::Halton(_)
        | Pattern::Hammersley(_)
        | Pattern::HaltonZaremba(_)
        | Pattern::HammersleyZaremba(_)
        | Pattern::Sobol(_)
        | Pattern::Fibonacci(_)
        | Pattern::Rank1(_)
        | Pattern::Kronecker(_) => (
            nf,
            Unit::Points,
            nf * cpu(POINT_NS) + call + touch(points_bytes),
            points_bytes,
        ),
    }
}

/// The name and cost-setting parameters of a pattern, e.g. "best-candidate n = 200000, m = 1".
pub(crate) fn pattern_label(p: &Pattern, n: usize) -> String {
    match p {
        Pattern::BestCandidate(b) => format!("best-candidate n = {n}, m = {}", b.m),
        Pattern::PoissonDart(d) => format!(
            "poisson-dart n = {n}, radius = {}, max_misses = {}",
            significant(resolved_radius(d.radius, n), 6),
            d.max_misses
        ),
        Pattern::PoissonBridson(b) => format!(
            "poisson-bridson n = {n}, radius = {}, k = {}",
            significant(resolved_radius(b.radius, n), 6),
            b.k
        ),
        Pattern::Pmj02bn(p) => format!("pmj02bn n = {n}, candidates = {}", p.candidates),
        Pattern::Rank1(r) if r.g == 0 && r.z.is_empty() => {
            format!("rank1 n = {n}, g = 0 (generator search)")
        }
        Pattern::Lloyd(l) => format!("lloyd n = {n}, iterations = {}", l.iterations),
        Pattern::Sot(s) => format!(
            "sot n = {n}, iterations = {}, directions = {}",
            s.iterations, s.directions
        ),
        Pattern::Gbn(g) => format!("gbn n = {n}, iterations = {}", g.iterations),
        Pattern::Padded(p) => format!(
            "padded n = {n}, base = {}",
            pattern_label(&pattern::cube::padded::base_pattern(p.base), n)
        ),
        // Patterns whose cost depends on n alone.
        other @ (Pattern::Grid(_)
        | Pattern::Random(_)
        | Pattern::Jitter(_)
        | Pattern::NRooks(_)
        | Pattern::Lhs(_)
        | Pattern::MultiJitter(_)
        | Pattern::CorrelatedMultiJitter(_)
        | Pattern::Hex(_)
        | Pattern::VanDerCorput(_)
        | Pattern::Halton(_)
        | Pattern::Hammersley(_)
        | Pattern::HaltonZaremba(_)
        | Pattern::HammersleyZaremba(_)
        | Pattern::Sobol(_)
        | Pattern::Pmj02(_)
        | Pattern::Fibonacci(_)
        | Pattern::Rank1(_)
        | Pattern::Kronecker(_)) => format!("{} n = {n}", other.name()),
    }
}

/// Generating `n` points of `pattern` ([`Pattern::generate_with`]).
pub fn pattern(p: &Pattern, n: usize) -> Estimate {
    let (amount, unit, secs, bytes) = pattern_cost(p, n);
    Estimate::new(pattern_label(p, n), amount, unit, secs, bytes)
}

/// Generating `n` points of `pattern` in `dims` dimensions ([`Pattern::generate_cube`]):
/// dims = 2 is [`pattern`]; otherwise the 2D cost per coordinate pair times dims / 2 (each
/// d-dimensional generator does per coordinate what the 2D one does per coordinate; the
/// padded pattern generates ⌈dims/2⌉ 2D sets), and the n·dims coordinates held.
pub fn pattern_cube(p: &Pattern, n: usize, dims: usize) -> Estimate {
    if dims == 2 {
        return pattern(p, n);
    }
    let (amount, unit, mut secs, bytes) = pattern_cost(p, n);
    if let Pattern::Rank1(r) = p {
        if r.g == 0 && r.z.is_empty() {
            // The CBC vector: per dimension an FFT of length N (prime N), or N² terms.
            let nf = n as f64;
            let per_dim = if pattern::radical_inverse::is_prime(n as u64) {
                nf * nf.log2().max(1.0) * 20.0
            } else {
                nf * nf * 4.0
            };
            secs = per_dim * dims as f64 * 1e-9;
        }
    }
    let scale = dims.div_ceil(2) as f64;
    let coords = 8.0 * n as f64 * dims as f64;
    Estimate::new(
        format!("{} in {dims} dimensions", pattern_label(p, n)),
        amount * scale,
        unit,
        secs * scale + touch(coords),
        bytes + coords,
    )
}

/// Candidates best candidate draws for n points: Σ_{i=1}^{n−1} m·i = m·n(n−1)/2.
pub fn best_candidate_candidates(m: u32, n: usize) -> f64 {
    let nf = n as f64;
    f64::from(m.max(1)) * nf * (nf - 1.0).max(0.0) / 2.0
}

/// The radius the Poisson-disk patterns use: 0 means the default for n; larger than the
/// packing bound is refused by the pattern, so it is capped there for the estimate.
pub(crate) fn resolved_radius(radius: f64, n: usize) -> f64 {
    if radius > 0.0 && radius.is_finite() {
        radius.min(max_radius(n))
    } else {
        default_radius(n)
    }
}

/// Jamming coverage of random sequential adsorption of disks (Hinrichsen, Feder, Jøssang 1986).
pub(crate) const RSA_JAMMING: f64 = 0.5472;

/// Fraction of the torus still free for a new dart at disk coverage θ = i·π(r/2)²: the
/// Schaaf–Talbot approximant of random sequential adsorption,
/// Φ(θ) = (1 + 0.812x + 0.4258x² + 0.0716x³)(1 − x)³, x = θ/θ_J (exact to second order at low
/// coverage, the (θ_J − θ)³ law near jamming). P. Schaaf, J. Talbot, J. Chem. Phys. 91, 1989.
pub(crate) fn rsa_free_fraction(theta: f64) -> f64 {
    let x = theta / RSA_JAMMING;
    if x >= 1.0 {
        return 0.0;
    }
    (1.0 + x * (0.812 + x * (0.4258 + x * 0.0716))) * (1.0 - x).powi(3)
}

/// Expected darts of dart throwing with radius r for n points and the miss bound: point i
/// needs 1/Φ(θᵢ) darts on average ([`rsa_free_fraction`]), the run of misses reaches
/// `max_misses` with probability (1 − Φ)^max_misses at each point, and then the loop gives up
/// after those misses. Summed over 4096 blocks of points (no allocation).
pub fn dart_darts(r: f64, n: usize, max_misses: u32) -> f64 {
    let nf = n as f64;
    let per_point_area = std::f64::consts::PI * r * r / 4.0;
    let blocks = 4096.min(n.max(1));
    let size = nf / blocks as f64;
    let misses = f64::from(max_misses.max(1));
    let mut alive = 1.0; // probability that the loop has not given up yet
    let mut total = 0.0;
    for b in 0..blocks {
        let placed = (b as f64 + 0.5) * size;
        let phi = rsa_free_fraction(placed * per_point_area);
        // Per point: P(give up) = (1 − Φ)^M; darts until a hit or a give-up = (1 − (1 − Φ)^M)/Φ.
        let give_up = if phi > 0.0 {
            (misses * (-phi).ln_1p()).exp()
        } else {
            1.0
        };
        let darts = if phi > 0.0 {
            (1.0 - give_up) / phi
        } else {
            misses
        };
        // Points of this block reached before a give-up, each adding its darts; a give-up
        // adds its run of misses and ends the loop.
        // (1 − g)^size and its complement without cancellation (g is often below 1e−20).
        let log_keep = size * (-give_up).ln_1p();
        let keep = log_keep.exp();
        let lost = -log_keep.exp_m1();
        let reached = if give_up > 1e-300 {
            lost / give_up
        } else {
            size
        };
        total += alive * (reached * darts + lost * misses);
        alive *= keep;
        if alive < 1e-12 {
            break;
        }
    }
    total
}

/// Bridson's maximal set holds about 0.615/r² points (relative radius 0.73 at k = 30: module
/// docs of [`crate::core::pattern::poisson`]), at most the packing bound.
pub(crate) fn bridson_maximal(r: f64) -> f64 {
    (0.6153 / (r * r)).min(2.0 / (3f64.sqrt() * r * r)).max(1.0)
}

/// Expected annulus tries of Bridson's algorithm with radius r and k, and the size of its
/// maximal set. Each point leaves the active list after k failed tries and was found by a few
/// tries of another point's search: (1.19 + 1.5/k)·k tries per point of the set (fitted to the
/// loop counted by the tests: 1.22k at k = 30, 1.35k at k = 10, 1.43k at k = 5).
pub fn bridson_tries(r: f64, k: u32) -> (f64, f64) {
    let m = bridson_maximal(r);
    let k = f64::from(k.max(1));
    ((1.19 * k + 1.5) * m, m)
}
