//! Sample patterns in the unit square: every 2D pattern the lecture teaches.
//!
//! A pattern is a small `Copy` parameter struct; [`Pattern`] is the enum that dispatches over
//! them, and [`Pattern::generate`] is the one entry point: `n` points in [0,1)², as `f64`
//! ([`glam::DVec2`]), a pure function of `(parameters, n, seed)`.
//!
//! | family | module | patterns |
//! |---|---|---|
//! | stratified | [`stratified`] | grid, random, jitter, nrooks, lhs, multijitter, cmj |
//! | lattice | [`hex`] | hex |
//! | blue noise | [`poisson`], [`best_candidate`] | poisson-dart, poisson-bridson, best-candidate |
//! | low discrepancy | [`lowdisc`], [`radical_inverse`], [`halton_scramble`] | van-der-corput, halton (plain, permuted or Owen-scrambled digits), hammersley, halton-zaremba, hammersley-zaremba, sobol |
//! | progressive multi-jittered | [`pmj`] | pmj02, pmj02bn |
//! | lattices | [`lattice`] | fibonacci, rank1 (Korobov, best generator), kronecker (R2) |
//! | optimised blue noise | [`optimize`] | lloyd (CVT on the torus), sot (sliced optimal transport), gbn (Gaussian blue noise) |
//!
//! [`sphere`] maps any 2D pattern onto the unit sphere.
//!
//! Every coordinate is clamped to at most `1 − 2⁻⁵³` ([`ONE_MINUS_EPSILON`]) so no value can
//! round to 1.0. Sequences are indexed from i = 0.

pub mod best_candidate;
pub mod cost;
pub mod cube;
pub mod halton_scramble;
pub mod hex;
pub mod lattice;
pub mod lowdisc;
pub mod optimize;
pub mod pmj;
pub mod poisson;
pub mod radical_inverse;
pub mod sphere;
pub mod stratified;

use crate::core::family::{family, UnknownName};
use crate::core::params::{declare_params, ChoiceParam, ParamError};
use crate::core::progress::{no_progress, OnProgress};
use glam::DVec2;
use serde::{Deserialize, Serialize};

pub use crate::core::cancel::{Cancel, Cancelled};

/// The largest f64 below 1: `1 − 2⁻⁵³`.
pub const ONE_MINUS_EPSILON: f64 = 1.0 - f64::EPSILON / 2.0;

/// The largest number of points any pattern generates (2²⁴ ≈ 16.8 M points, 268 MB as f64 pairs).
pub const MAX_N: usize = 1 << 24;

/// Why a pattern could not be generated. Every variant names the offending field and what is allowed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PatternError {
    /// `n` is zero or larger than [`MAX_N`] (or the pattern's own limit).
    #[error("n = {n}: must be an integer in 1..={max}{why}")]
    InvalidN {
        n: usize,
        max: usize,
        /// Extra explanation, starting with "; " (may be empty).
        why: String,
    },
    /// `n` is in range but not a value this pattern can take (an odd n for hex, a number that
    /// is not a Fibonacci number for the Fibonacci lattice).
    #[error("{pattern}: n = {n}: must be {allowed}")]
    UnsupportedN {
        pattern: &'static str,
        n: usize,
        allowed: String,
    },
    /// The pattern name is not known.
    #[error(transparent)]
    UnknownPattern(#[from] UnknownName),
    /// The parameter key is not known for this pattern.
    #[error("{pattern}: unknown parameter '{key}': allowed parameters are [{allowed}]")]
    UnknownParam {
        pattern: &'static str,
        key: String,
        allowed: String,
    },
    /// A parameter value is out of range or malformed.
    #[error("{pattern}.{field} = {value}: must be {allowed}")]
    InvalidParam {
        pattern: &'static str,
        field: &'static str,
        value: String,
        allowed: String,
    },
    /// A Poisson-disk radius too large for `n` points on the unit torus.
    #[error("{pattern}.radius = {}: {n} points need radius ≤ {} (hexagonal packing bound √(2/(√3·n)))", crate::core::params::fmt_num(*.radius), crate::core::params::fmt_num(*.max))]
    RadiusTooLarge {
        pattern: &'static str,
        radius: f64,
        n: usize,
        max: f64,
    },
    /// Fewer points than asked were placed (dart throwing gave up after `max_misses`,
    /// Bridson's maximal set at `radius` holds fewer than n): `note` says how many and names
    /// the parameter that prevents the rest.
    #[error("{pattern}: {note}")]
    TooFew {
        pattern: &'static str,
        placed: usize,
        requested: usize,
        note: String,
    },
    /// `dims` outside what the pattern is defined for ([`Pattern::max_dims`]; 2D-only patterns
    /// take dims = 2 alone): `allowed` says what is, and for a 2D-only pattern names the
    /// patterns that have a d-dimensional form.
    #[error("{pattern}: dims = {dims}: {allowed}")]
    InvalidDims {
        pattern: &'static str,
        dims: usize,
        max: usize,
        allowed: String,
    },
    /// The computation was cancelled.
    #[error("cancelled")]
    Cancelled,
}

impl From<ParamError> for PatternError {
    fn from(e: ParamError) -> Self {
        match e {
            ParamError::Unknown {
                owner,
                key,
                allowed,
            } => PatternError::UnknownParam {
                pattern: owner,
                key,
                allowed,
            },
            ParamError::Invalid {
                owner,
                field,
                value,
                allowed,
            } => PatternError::InvalidParam {
                pattern: owner,
                field,
                value,
                allowed,
            },
        }
    }
}

impl From<Cancelled> for PatternError {
    fn from(_: Cancelled) -> Self {
        PatternError::Cancelled
    }
}

/// Checks `1 ≤ n ≤ max`.
pub fn check_n(n: usize, max: usize) -> Result<(), PatternError> {
    if n == 0 || n > max {
        return Err(PatternError::InvalidN {
            n,
            max,
            why: String::new(),
        });
    }
    Ok(())
}

/// The result of a generation: the points, and a note when fewer than requested were placed.
#[derive(Debug, Clone, PartialEq)]
pub struct Generated {
    /// The points, in generation order (progressive patterns: every prefix is usable).
    pub points: Vec<DVec2>,
    /// How many points were asked for.
    pub requested: usize,
    /// Why fewer points than requested were placed (e.g. dart throwing gave up after its miss bound).
    pub note: Option<String>,
}

impl Generated {
    /// The points if all `requested` were placed, else [`PatternError::TooFew`] naming
    /// `pattern` and the parameter that stopped it (from the note).
    pub fn require_all(self, pattern: &'static str) -> Result<Vec<DVec2>, PatternError> {
        if self.points.len() >= self.requested {
            return Ok(self.points);
        }
        Err(PatternError::TooFew {
            pattern,
            placed: self.points.len(),
            requested: self.requested,
            note: self.note.unwrap_or_else(|| {
                format!("placed {} of {} points", self.points.len(), self.requested)
            }),
        })
    }

    /// All requested points, no note.
    pub fn complete(points: Vec<DVec2>) -> Self {
        let requested = points.len();
        Generated {
            points,
            requested,
            note: None,
        }
    }
}

/// Scrambling of the Sobol' (0,2)-sequence.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Scramble {
    /// The plain sequence.
    #[default]
    None,
    /// Random digit scrambling: XOR of every coordinate with one random 32-bit word per dimension.
    RandomDigit,
    /// Nested uniform (Owen) scrambling, hash-based (Laine–Karras 2011, Burley 2020).
    Owen,
    /// Owen scrambling of the points and of their index: Burley's (2020) hash-based shuffling,
    /// every 2^m prefix a randomly chosen aligned block in random order (`cube::sobol`).
    OwenShuffled,
}

impl ChoiceParam for Scramble {
    const OPTIONS: &'static [&'static str] = &["none", "random-digit", "owen", "owen-shuffled"];
    fn index(self) -> usize {
        self as usize
    }
    fn from_index(index: usize) -> Self {
        [
            Scramble::None,
            Scramble::RandomDigit,
            Scramble::Owen,
            Scramble::OwenShuffled,
        ][index]
    }
}

declare_params! {
    /// Cell centres of a `cols × (n / cols)` grid.
    Grid = "grid", "regular grid, cell centres ((i+½)/cols, (j+½)/rows)" {
        cols: int(0, 0, MAX_N, "columns; 0 = auto (the divisor of n nearest √n); must divide n"),
    }
}
declare_params! {
    /// White noise: n independent uniform points.
    Random = "random", "white noise: independent uniform points" {}
}
declare_params! {
    /// Jittered (stratified) sampling on a `cols × rows` grid of strata.
    Jitter = "jitter", "one point per cell of a cols × rows grid, offset from the centre by amount·(u−½) cell widths" {
        cols: int(0, 0, MAX_N, "strata columns; 0 = auto (the divisor of n nearest √n); must divide n"),
        amount: float(1.0, 0.0, 1.0, "jitter amount: 0 = cell centres, 0.5 = ±¼ cell, 1 = anywhere in the cell"),
    }
}
declare_params! {
    /// N-rooks (2D Latin hypercube).
    NRooks = "nrooks", "N-rooks: jittered diagonal, columns shuffled per dimension (one point per row and column)" {
        amount: float(1.0, 0.0, 1.0, "jitter amount within the cell: 0 = centres, 1 = anywhere"),
    }
}
declare_params! {
    /// Latin hypercube sampling in `dims` dimensions, projected to two of them.
    Lhs = "lhs", "Latin hypercube in k dims: one random permutation per dimension; shows the projection (x_dim, y_dim)" {
        dims: int(3, 1, 64, "number of dimensions k"),
        x_dim: int(0, 0, 63, "dimension shown on x (0-based, < dims)"),
        y_dim: int(1, 0, 63, "dimension shown on y (0-based, < dims)"),
        amount: float(1.0, 0.0, 1.0, "jitter amount within the cell: 0 = centres, 1 = anywhere"),
    }
    check(p) {
        let dims = p.dims;
        let below = |field: &'static str, v: u32| ParamError::Invalid {
            owner: Lhs::NAME,
            field,
            value: v.to_string(),
            allowed: format!("an integer in 0..={} (below dims = {dims})", dims.saturating_sub(1)),
        };
        if p.x_dim >= dims {
            return Err(below("x_dim", p.x_dim));
        }
        if p.y_dim >= dims {
            return Err(below("y_dim", p.y_dim));
        }
        if dims >= 2 && p.x_dim == p.y_dim {
            return Err(ParamError::Invalid {
                owner: Lhs::NAME,
                field: "y_dim",
                value: p.y_dim.to_string(),
                allowed: format!(
                    "an integer in 0..={} different from x_dim = {}",
                    dims - 1,
                    p.x_dim
                ),
            });
        }
        Ok(())
    }
}
declare_params! {
    /// Multi-jittered sampling (Chiu, Shirley, Wang 1994).
    MultiJitter = "multijitter", "multi-jitter (Chiu–Shirley–Wang 1994): jittered and N-rooks at once, shuffled canonical arrangement" {
        cols: int(0, 0, MAX_N, "columns; 0 = auto (the divisor of n nearest √n); must divide n"),
    }
}
declare_params! {
    /// Correlated multi-jittered sampling (Kensler 2013).
    CorrelatedMultiJitter = "cmj", "correlated multi-jitter (Kensler 2013): one shuffle per row/column of the canonical arrangement" {
        cols: int(0, 0, MAX_N, "columns; 0 = auto (the divisor of n nearest √n); must divide n"),
    }
}
declare_params! {
    /// Hexagonal lattice fitted to the unit torus.
    Hex = "hex", "hexagonal lattice (rows offset by half a spacing) fitted to the torus, optional jitter" {
        rows: int(0, 0, MAX_N, "rows; 0 = auto (the even divisor of n closest to the equilateral aspect); must divide n"),
        amount: float(0.0, 0.0, 1.0, "jitter amount: 0 = exact lattice, 1 = anywhere in the point's cell"),
    }
}
declare_params! {
    /// Dart throwing as in the lecture's pseudo-code, on the torus.
    PoissonDart = "poisson-dart", "dart throwing (lecture pseudo-code): reject darts closer than radius to any accepted point (toroidal)" {
        radius: float(0.0, 0.0, 1.0, "minimum toroidal distance between points; 0 = auto (0.65 × the hexagonal packing distance for n)"),
        max_misses: int(100_000, 1, 100_000_000, "give up after this many consecutive rejected darts"),
    }
}
declare_params! {
    /// Bridson's fast Poisson-disk sampling on the torus.
    PoissonBridson = "poisson-bridson", "Bridson 2007 Poisson disk on the torus: k annulus candidates per active point, randomly thinned to n" {
        radius: float(0.0, 0.0, 1.0, "minimum toroidal distance between points; 0 = auto (0.65 × the hexagonal packing distance for n)"),
        k: int(30, 1, 1000, "candidates tried around each active point"),
    }
}
declare_params! {
    /// Mitchell's best-candidate sampling on the torus.
    BestCandidate = "best-candidate", "Mitchell 1991 best candidate on the torus: point i keeps the farthest of m·i candidates; progressive" {
        m: int(1, 1, 1000, "candidate multiplier: point i draws m·i candidates (at least 1)"),
    }
}
declare_params! {
    /// The van der Corput sequence Φ_b(i), drawn on the line y = ½.
    VanDerCorput = "van-der-corput", "1D van der Corput sequence x_i = Φ_b(i), drawn at y = ½" {
        base: int(2, 2, 7919, "base b (a prime ≤ 7919, the 1000th prime)"),
    }
    check(p) {
        prime_param(VanDerCorput::NAME, "base", p.base)
    }
}
declare_params! {
    /// The Halton sequence (Φ_{b1}(i), Φ_{b2}(i)).
    Halton = "halton", "Halton sequence x_i = (Φ_bx(i), Φ_by(i)), i = skip, skip+1, …" {
        base_x: int(2, 2, 7919, "base of x (a prime ≤ 7919)"),
        base_y: int(3, 2, 7919, "base of y (a prime ≤ 7919)"),
        skip: int(0, 0, u32::MAX, "index of the first point"),
        scramble: choice(halton_scramble::HaltonScramble, "none | permute (random digit permutations per digit position, pbrt-v4) | owen (nested uniform scrambling in each base)"),
    }
    check(p) {
        halton_bases(Halton::NAME, p.base_x, p.base_y)
    }
}
declare_params! {
    /// The Hammersley point set (i/N, Φ_{p1}(i)).
    Hammersley = "hammersley", "Hammersley set x_i = (i/N, Φ_p1(i))" {
        p1: int(2, 2, 7919, "base p1 of y (a prime ≤ 7919; the lecture shows 2, 3, 5, 7, 11)"),
    }
    check(p) {
        prime_param(Hammersley::NAME, "p1", p.p1)
    }
}
declare_params! {
    /// Halton with the folded radical inverse.
    HaltonZaremba = "halton-zaremba", "Halton–Zaremba: Halton with the folded radical inverse Σ((a_k+k−1) mod b) b^(−k)" {
        base_x: int(2, 2, 7919, "base of x (a prime ≤ 7919)"),
        base_y: int(3, 2, 7919, "base of y (a prime ≤ 7919)"),
        skip: int(0, 0, u32::MAX, "index of the first point"),
    }
    check(p) {
        halton_bases(HaltonZaremba::NAME, p.base_x, p.base_y)
    }
}
declare_params! {
    /// Hammersley with the folded radical inverse.
    HammersleyZaremba = "hammersley-zaremba", "Hammersley–Zaremba: (i/N, folded Φ_p1(i))" {
        p1: int(2, 2, 7919, "base p1 of y (a prime ≤ 7919)"),
    }
    check(p) {
        prime_param(HammersleyZaremba::NAME, "p1", p.p1)
    }
}
declare_params! {
    /// The (0,2)-sequence of the first two Sobol' dimensions.
    Sobol = "sobol", "Sobol' (0,2)-sequence (first two dimensions), optionally scrambled" {
        scramble: choice(Scramble, "none | random-digit (XOR) | owen (nested uniform, hash-based) | owen-shuffled (owen, and the index Owen-scrambled: Burley 2020's hash-based shuffling)"),
        skip: int(0, 0, u32::MAX, "index of the first point (a multiple of 2^m keeps the (0,m,2)-net property)"),
    }
}
declare_params! {
    /// Progressive multi-jittered (0,2) sequence (Christensen, Kensler, Kilpatrick 2018).
    Pmj02 = "pmj02", "progressive multi-jittered (0,2) sequence (Christensen et al. 2018, Pharr 2019): every 2^k prefix is a (0,k,2)-net" {}
}
declare_params! {
    /// PMJ02 with the blue-noise choice among valid candidates.
    Pmj02bn = "pmj02bn", "pmj02 with blue noise: each point the farthest of `candidates` valid candidates; still a (0,k,2)-net at every 2^k prefix" {
        candidates: int(10, 1, pmj::MAX_CANDIDATES, "valid candidates tried per point (1 = pmj02)"),
    }
}
declare_params! {
    /// The rank-1 Fibonacci lattice.
    Fibonacci = "fibonacci", "Fibonacci lattice x_i = (i/F_k, frac(i·F_(k−1)/F_k)); N must be a Fibonacci number" {
        shift: flag(false, "Cranley–Patterson rotation by a seeded uniform shift (mod 1)"),
    }
}
declare_params! {
    /// Korobov rank-1 lattice.
    Rank1 = "rank1", "Korobov lattice x_i = (i/N, frac(i·g/N)); g = 0 picks the generator with the largest minimum distance" {
        g: int(0, 0, MAX_N, "generator g in 1..N−1 (g coprime to N gives N distinct rows); 0 = the best coprime g (largest toroidal minimum distance, each g ≤ N/2 by 2D lattice reduction: O(N log N), 0.1 s at N = 2^20)"),
        shift: flag(false, "Cranley–Patterson rotation by a seeded uniform shift (mod 1)"),
        /// The generating vector given as a list (empty: from `g`).
        #[serde(skip_serializing_if = "crate::core::params::IntList::is_empty")]
        z: int_list(1, MAX_N - 1, "the generating vector z given as a list, one integer in 1..N per dimension (x_i = frac(i·z/N)); empty = from g (set g = 0 with a list)"),
    }
    check(p) {
        // A list and a Korobov generator would both name the vector.
        if p.g != 0 && !p.z.is_empty() {
            return Err(ParamError::Invalid {
                owner: Rank1::NAME,
                field: "z",
                value: p.z.value().short(),
                allowed: format!(
                    "left out when g ≠ 0 (g = {} sets the Korobov vector (1, g, g², …)); set g = 0 to give z",
                    p.g
                ),
            });
        }
        Ok(())
    }
}
declare_params! {
    /// The R2 sequence (Roberts 2018).
    Kronecker = "kronecker", "R2 sequence x_i = frac(s + i·α), α = (1/φ₂, 1/φ₂²), φ₂ the plastic number (Roberts 2018); progressive" {
        offset_x: below(0.5, 0.0, 1.0, "offset s_x in [0, 1)"),
        offset_y: below(0.5, 0.0, 1.0, "offset s_y in [0, 1)"),
    }
}
declare_params! {
    /// Centroidal Voronoi tessellation by Lloyd relaxation on the torus.
    Lloyd = "lloyd", "Lloyd relaxation on the torus from white noise: each step moves every point to the centroid of its exact Voronoi cell" {
        iterations: int(optimize::LLOYD_DEFAULT_ITERATIONS, 0, optimize::LLOYD_MAX_ITERATIONS, "relaxation steps"),
    }
}
declare_params! {
    /// Sliced optimal transport sampling (Paulin et al. 2020).
    Sot = "sot", "sliced optimal transport (Paulin et al. 2020): 1D transport to the exact projections of the uniform square along random directions" {
        iterations: int(optimize::SOT_DEFAULT_ITERATIONS, 0, optimize::SOT_MAX_ITERATIONS, "steps"),
        directions: int(optimize::SOT_DEFAULT_DIRECTIONS, 1, optimize::SOT_MAX_DIRECTIONS, "random directions per step"),
    }
}
declare_params! {
    /// Gaussian blue noise (Ahmed, Ren, Wonka 2022).
    Gbn = "gbn", "Gaussian blue noise (Ahmed, Ren, Wonka 2022): gradient descent on Σ exp(−d²/2σ²) over toroidal pairs" {
        iterations: int(optimize::GBN_DEFAULT_ITERATIONS, 0, optimize::GBN_MAX_ITERATIONS, "gradient steps"),
        sigma: float(0.0, 0.0, 1.0, "kernel width σ in mean spacings 1/√n; 0 = the default (1)"),
    }
}

/// The 2D pattern a `padded` pattern repeats in every dimension pair (`cube::padded`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum PadBase {
    /// Progressive multi-jittered (0,2).
    #[default]
    Pmj02,
    /// PMJ02 with blue noise.
    Pmj02bn,
    /// Owen-scrambled Sobol' (0,2).
    Sobol,
    /// Owen-scrambled Halton (2, 3).
    Halton,
    /// Jittered.
    Jitter,
    /// Multi-jittered.
    MultiJitter,
    /// Correlated multi-jittered.
    Cmj,
    /// White noise.
    Random,
    /// Mitchell's best candidate.
    BestCandidate,
}

impl ChoiceParam for PadBase {
    const OPTIONS: &'static [&'static str] = &[
        "pmj02",
        "pmj02bn",
        "sobol",
        "halton",
        "jitter",
        "multijitter",
        "cmj",
        "random",
        "best-candidate",
    ];
    fn index(self) -> usize {
        self as usize
    }
    fn from_index(index: usize) -> Self {
        [
            PadBase::Pmj02,
            PadBase::Pmj02bn,
            PadBase::Sobol,
            PadBase::Halton,
            PadBase::Jitter,
            PadBase::MultiJitter,
            PadBase::Cmj,
            PadBase::Random,
            PadBase::BestCandidate,
        ][index]
    }
}

declare_params! {
    /// A 2D pattern padded to d dimensions (pbrt-v4's padded samplers).
    Padded = "padded", "pbrt-v4's padding: each dimension pair an independent randomized copy of the 2D base pattern, shuffled (its own random order); in 2D one shuffled copy" {
        base: choice(PadBase, "the 2D pattern of every pair: pmj02 | pmj02bn | sobol (Owen) | halton (Owen) | jitter | multijitter | cmj | random | best-candidate"),
    }
}

/// A radical-inverse base: a prime in 2..=7919 (the range of its descriptor holds every
/// integer; primality is checked with the set, so `--set`, scene files and the GUI refuse a
/// composite base before any generation, with the words of the generators).
fn prime_param(owner: &'static str, field: &'static str, base: u32) -> Result<(), ParamError> {
    lowdisc::check_prime_base(owner, field, base)
        .map(drop)
        .map_err(|e| param_error(owner, e))
}

/// Both Halton bases prime and different (equal bases put every point on the diagonal).
fn halton_bases(owner: &'static str, base_x: u32, base_y: u32) -> Result<(), ParamError> {
    lowdisc::check_halton_bases(owner, base_x, base_y)
        .map(drop)
        .map_err(|e| param_error(owner, e))
}

/// A generator's parameter error as a [`ParamError`] of `owner`.
fn param_error(owner: &'static str, e: PatternError) -> ParamError {
    match e {
        PatternError::InvalidParam {
            field,
            value,
            allowed,
            ..
        } => ParamError::Invalid {
            owner,
            field,
            value,
            allowed,
        },
        other => ParamError::Invalid {
            owner,
            field: "",
            value: String::new(),
            allowed: other.to_string(),
        },
    }
}

family! {
    /// Every sample pattern, as a small parameter struct per variant. In scene files the
    /// `kind` is the pattern's one name, the same as on the command line and in the GUI.
    /// `Rank1` holds its generating vector inline (`IntList`, 4 KiB, so that every parameter
    /// set stays `Copy`): a pattern is copied per column and per scene, never in a hot loop.
    #[allow(clippy::large_enum_variant)]
    Pattern = "pattern", "patterns" {
        Grid(Grid) = "grid",
        Random(Random) = "random",
        Jitter(Jitter) = "jitter",
        NRooks(NRooks) = "nrooks",
        Lhs(Lhs) = "lhs",
        MultiJitter(MultiJitter) = "multijitter",
        CorrelatedMultiJitter(CorrelatedMultiJitter) = "cmj",
        Hex(Hex) = "hex",
        PoissonDart(PoissonDart) = "poisson-dart",
        PoissonBridson(PoissonBridson) = "poisson-bridson",
        BestCandidate(BestCandidate) = "best-candidate",
        VanDerCorput(VanDerCorput) = "van-der-corput",
        Halton(Halton) = "halton",
        Hammersley(Hammersley) = "hammersley",
        HaltonZaremba(HaltonZaremba) = "halton-zaremba",
        HammersleyZaremba(HammersleyZaremba) = "hammersley-zaremba",
        Sobol(Sobol) = "sobol",
        Pmj02(Pmj02) = "pmj02",
        Pmj02bn(Pmj02bn) = "pmj02bn",
        Fibonacci(Fibonacci) = "fibonacci",
        Rank1(Rank1) = "rank1",
        Kronecker(Kronecker) = "kronecker",
        Lloyd(Lloyd) = "lloyd",
        Sot(Sot) = "sot",
        Gbn(Gbn) = "gbn",
        Padded(Padded) = "padded",
    }
}

impl Default for Pattern {
    fn default() -> Self {
        Pattern::Jitter(Jitter::default())
    }
}

impl Pattern {
    /// Whether the pattern uses its seed (deterministic ones ignore it). A scrambled pattern
    /// (Sobol' or Halton with a scramble) draws its scramble from the seed, so it is random;
    /// unscrambled it is deterministic.
    pub fn is_random(&self) -> bool {
        !matches!(
            self,
            Pattern::Grid(_)
                | Pattern::VanDerCorput(_)
                | Pattern::Hammersley(_)
                | Pattern::HaltonZaremba(_)
                | Pattern::HammersleyZaremba(_)
                | Pattern::Kronecker(_)
        ) && !matches!(self, Pattern::Sobol(s) if s.scramble == Scramble::None)
            && !matches!(self, Pattern::Halton(h) if h.scramble == halton_scramble::HaltonScramble::None)
            && !matches!(self, Pattern::Fibonacci(f) if !f.shift)
            && !matches!(self, Pattern::Rank1(r) if !r.shift)
            && !matches!(self, Pattern::Jitter(j) if j.amount == 0.0)
            && !matches!(self, Pattern::Hex(h) if h.amount == 0.0)
    }

    /// The one-line refusal of a `seed` given explicitly (as `flag`: `--seed`, `seed`) for a
    /// pattern that is deterministic with these parameters: it draws no random numbers, so the
    /// seed would have no effect. `None` when the pattern uses its seed.
    pub fn seed_refusal(&self, seed: u64, flag: &str) -> Option<String> {
        (!self.is_random()).then(|| {
            format!(
                "{flag} {seed}: {} with these parameters is deterministic (it draws no random \
                 numbers), so {flag} would have no effect; leave it out",
                self.name()
            )
        })
    }

    /// Whether every prefix of the output is itself a good pattern (sequences, best candidate).
    pub fn is_progressive(&self) -> bool {
        matches!(
            self,
            Pattern::Random(_)
                | Pattern::BestCandidate(_)
                | Pattern::VanDerCorput(_)
                | Pattern::Halton(_)
                | Pattern::HaltonZaremba(_)
                | Pattern::Sobol(_)
                | Pattern::Pmj02(_)
                | Pattern::Pmj02bn(_)
                | Pattern::Kronecker(_)
        )
    }

    /// Whether the points come in an order whose prefixes mean something, so that showing the
    /// first k of N points plays the construction: the progressive patterns (the first k
    /// points are the k-point run) and dart throwing (the first k darts accepted, at the
    /// N-point radius).
    pub fn plays_in_order(&self) -> bool {
        self.is_progressive() || matches!(self, Pattern::PoissonDart(_))
    }

    /// `n` points in [0,1)²; a pure function of `(self, n, seed)`.
    ///
    /// Exactly `n` points or an error: a pattern that places fewer (dart throwing that gives
    /// up, [`Pattern::may_place_fewer`]) is [`PatternError::TooFew`]. Use
    /// [`Pattern::generate_with`] to keep the points placed.
    pub fn generate(&self, n: usize, seed: u64) -> Result<Vec<DVec2>, PatternError> {
        self.generate_with(n, seed, &Cancel::never())?
            .require_all(self.name())
    }

    /// Whether the pattern can place fewer points than asked (its [`Generated`] then has a
    /// note): dart throwing stops after `max_misses` consecutive misses, and Bridson's maximal
    /// set at a given radius may hold fewer than n points. Every other pattern places exactly
    /// n points or refuses n.
    pub fn may_place_fewer(&self) -> bool {
        matches!(self, Pattern::PoissonDart(_) | Pattern::PoissonBridson(_))
    }

    /// As [`Pattern::generate`], cancellable, and reporting how many points were placed.
    pub fn generate_with(
        &self,
        n: usize,
        seed: u64,
        cancel: &Cancel,
    ) -> Result<Generated, PatternError> {
        self.generate_observed(n, seed, cancel, &mut no_progress)
    }

    /// Checks that `n` points of this pattern can be generated, without generating them:
    /// every parameter against its descriptor and the constraints between them, `n` against
    /// the pattern's own rules (a Fibonacci number, a divisor for `cols`, an even `n` for hex,
    /// a radius the torus can hold). Cheap (at most O(√n)), so commands call it before
    /// printing an estimate or checking the budget; [`Pattern::generate_observed`] calls it
    /// first, and the generators return the same errors, so the two never disagree.
    ///
    /// Not checked (found only by generating): whether dart throwing or Bridson's method
    /// actually place all `n` points ([`Generated::require_all`]).
    pub fn validate(&self, n: usize) -> Result<(), PatternError> {
        use crate::core::params::Params;
        self.check_params()?;
        check_n(n, MAX_N)?;
        match self {
            Pattern::Grid(p) => resolve_cols(Grid::NAME, p.cols, n).map(drop),
            Pattern::Random(_) | Pattern::Pmj02(_) => Ok(()),
            Pattern::Jitter(p) => {
                stratified::check_amount(Jitter::NAME, p.amount)?;
                resolve_cols(Jitter::NAME, p.cols, n).map(drop)
            }
            Pattern::NRooks(p) => stratified::check_amount(NRooks::NAME, p.amount),
            Pattern::Lhs(p) => stratified::check_lhs(p, n),
            Pattern::MultiJitter(p) => resolve_cols(MultiJitter::NAME, p.cols, n).map(drop),
            Pattern::CorrelatedMultiJitter(p) => {
                resolve_cols(CorrelatedMultiJitter::NAME, p.cols, n).map(drop)
            }
            Pattern::Hex(p) => hex::check_hex(p, n).map(drop),
            Pattern::PoissonDart(p) => poisson::check_dart(p, n).map(drop),
            Pattern::PoissonBridson(p) => poisson::check_bridson(p, n).map(drop),
            Pattern::BestCandidate(p) => best_candidate::check_m(p).map(drop),
            Pattern::VanDerCorput(p) => {
                lowdisc::check_prime_base(VanDerCorput::NAME, "base", p.base).map(drop)
            }
            Pattern::Halton(p) => {
                lowdisc::check_halton_bases(Halton::NAME, p.base_x, p.base_y).map(drop)
            }
            Pattern::Hammersley(p) => {
                lowdisc::check_prime_base(Hammersley::NAME, "p1", p.p1).map(drop)
            }
            Pattern::HaltonZaremba(p) => {
                lowdisc::check_halton_bases(HaltonZaremba::NAME, p.base_x, p.base_y).map(drop)
            }
            Pattern::HammersleyZaremba(p) => {
                lowdisc::check_prime_base(HammersleyZaremba::NAME, "p1", p.p1).map(drop)
            }
            Pattern::Sobol(p) => lowdisc::check_sobol(p, n),
            Pattern::Pmj02bn(p) => pmj::check_candidates(p.candidates),
            Pattern::Fibonacci(_) => lattice::check_fibonacci(n),
            Pattern::Rank1(p) => {
                lattice::check_rank1(n, p.g)?;
                cube::lattice::check_z(p, n, 2)
            }
            Pattern::Kronecker(p) => {
                lattice::check_kronecker(n, DVec2::new(p.offset_x, p.offset_y))
            }
            Pattern::Lloyd(p) => optimize::check_lloyd(n, p.iterations),
            Pattern::Sot(p) => optimize::check_sot(n, p.iterations, p.directions),
            Pattern::Gbn(p) => optimize::check_gbn(n, p.iterations, p.sigma).map(drop),
            Pattern::Padded(p) => cube::padded::check_padded(p, n),
        }
    }

    /// Whether the pattern is made by an optimiser that refines a whole point set step by step
    /// (Lloyd, SOT, GBN), and so reports its steps from [`Pattern::generate_observed`].
    pub fn is_iterative(&self) -> bool {
        matches!(self, Pattern::Lloyd(_) | Pattern::Sot(_) | Pattern::Gbn(_))
    }

    /// As [`Pattern::generate_with`]; an iterative pattern ([`Pattern::is_iterative`]) also
    /// reports its steps to `progress` ([`crate::core::progress`]), each with the points reached
    /// so far, which are a valid point set of the same size (what the GUI shows while it
    /// refines, and what drives the CLI's progress bar). The result does not depend on
    /// `progress`.
    pub fn generate_observed(
        &self,
        n: usize,
        seed: u64,
        cancel: &Cancel,
        progress: &mut OnProgress<'_, [DVec2]>,
    ) -> Result<Generated, PatternError> {
        self.validate(n)?;
        let points = match self {
            Pattern::Grid(p) => stratified::grid(p, n)?,
            Pattern::Random(_) => stratified::random(n, seed),
            Pattern::Jitter(p) => stratified::jitter(p, n, seed)?,
            Pattern::NRooks(p) => stratified::try_nrooks(p, n, seed)?,
            Pattern::Lhs(p) => stratified::lhs(p, n, seed)?,
            Pattern::MultiJitter(p) => stratified::multijitter(p, n, seed)?,
            Pattern::CorrelatedMultiJitter(p) => stratified::correlated_multijitter(p, n, seed)?,
            Pattern::Hex(p) => hex::hex(p, n, seed)?,
            Pattern::PoissonDart(p) => return poisson::dart(p, n, seed, cancel),
            Pattern::PoissonBridson(p) => return poisson::bridson(p, n, seed, cancel),
            Pattern::BestCandidate(p) => best_candidate::best_candidate(p, n, seed, cancel)?,
            Pattern::VanDerCorput(p) => lowdisc::van_der_corput(p, n)?,
            Pattern::Halton(p) if p.scramble == halton_scramble::HaltonScramble::None => {
                lowdisc::halton(p, n)?
            }
            Pattern::Halton(p) => halton_scramble::scrambled_halton_with(
                p.base_x, p.base_y, p.skip, p.scramble, n, seed, cancel,
            )?,
            Pattern::Hammersley(p) => lowdisc::hammersley(p, n)?,
            Pattern::HaltonZaremba(p) => lowdisc::halton_zaremba(p, n)?,
            Pattern::HammersleyZaremba(p) => lowdisc::hammersley_zaremba(p, n)?,
            Pattern::Sobol(p) => lowdisc::sobol(p, n, seed)?,
            Pattern::Pmj02(_) => pmj::pmj02(n, seed, cancel)?,
            Pattern::Pmj02bn(p) => pmj::pmj02bn(n, seed, p.candidates, cancel)?,
            Pattern::Fibonacci(p) => lattice::fibonacci(n, p.shift, seed)?,
            Pattern::Rank1(p) if !p.z.is_empty() => {
                cube::lattice::check_z(p, n, 2)?;
                let z: Vec<u64> = p.z.as_slice().iter().map(|&v| u64::from(v)).collect();
                let xy = cube::lattice::lattice_points(n, &z, p.shift, seed);
                xy.chunks_exact(2).map(|c| DVec2::new(c[0], c[1])).collect()
            }
            Pattern::Rank1(p) => lattice::rank1_with(n, p.g, p.shift, seed, cancel)?,
            Pattern::Kronecker(p) => lattice::kronecker(n, DVec2::new(p.offset_x, p.offset_y))?,
            Pattern::Lloyd(p) => optimize::lloyd(n, p.iterations, seed, cancel, progress)?,
            Pattern::Sot(p) => {
                optimize::sot(n, p.iterations, p.directions, seed, cancel, progress)?
            }
            Pattern::Gbn(p) => optimize::gbn(n, p.iterations, p.sigma, seed, cancel, progress)?,
            Pattern::Padded(p) => cube::padded::padded_2d(p, n, seed, cancel)?,
        };
        debug_assert!(points
            .iter()
            .all(|p| (0.0..1.0).contains(&p.x) && (0.0..1.0).contains(&p.y)));
        Ok(Generated::complete(points))
    }
}

/// Clamps a coordinate into [0, 1 − 2⁻⁵³].
#[inline]
pub fn clamp_unit(x: f64) -> f64 {
    x.clamp(0.0, ONE_MINUS_EPSILON)
}

/// The divisor of `n` nearest to √n, not above it (so `cols ≤ rows`). 1 for primes.
pub fn divisor_near_sqrt(n: usize) -> usize {
    let mut d = (n as f64).sqrt() as usize;
    while d > 1 && n % d != 0 {
        d -= 1;
    }
    d.max(1)
}

/// Resolves a `cols` parameter (0 = auto) into `(cols, rows)` with `cols·rows = n`.
impl Pattern {
    /// The grid of strata the pattern puts one point (jitter, multi-jitter: one per cell) or
    /// one point per row and column (N-rooks, Latin hypercube: an N × N grid) into, as
    /// (columns, rows), for n points; `None` for patterns that are not stratified on a grid
    /// (or whose grid does not divide n).
    pub fn strata(&self, n: usize) -> Option<(usize, usize)> {
        let cols = match self {
            Pattern::Jitter(j) => j.cols,
            Pattern::Grid(g) => g.cols,
            Pattern::MultiJitter(m) => m.cols,
            Pattern::CorrelatedMultiJitter(m) => m.cols,
            Pattern::NRooks(_) | Pattern::Lhs(_) => return (n > 0).then_some((n, n)),
            _ => return None,
        };
        resolve_cols(self.name(), cols, n).ok()
    }
}

pub fn resolve_cols(
    pattern: &'static str,
    cols: u32,
    n: usize,
) -> Result<(usize, usize), PatternError> {
    let c = if cols == 0 {
        divisor_near_sqrt(n)
    } else {
        cols as usize
    };
    if c == 0 || n % c != 0 {
        return Err(PatternError::InvalidParam {
            pattern,
            field: "cols",
            value: cols.to_string(),
            allowed: format!("0 (auto) or a divisor of n = {n}"),
        });
    }
    Ok((c, n / c))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn strata_are_the_grid_each_stratified_pattern_fills() {
        let jitter = |cols| {
            Pattern::Jitter(Jitter {
                cols,
                ..Default::default()
            })
        };
        assert_eq!(jitter(0).strata(4096), Some((64, 64)));
        assert_eq!(jitter(3).strata(16), None, "3 does not divide 16");
        assert_eq!(
            Pattern::NRooks(Default::default()).strata(10),
            Some((10, 10))
        );
        assert_eq!(Pattern::Lhs(Default::default()).strata(10), Some((10, 10)));
        assert_eq!(Pattern::Random(Default::default()).strata(16), None);
    }
}
