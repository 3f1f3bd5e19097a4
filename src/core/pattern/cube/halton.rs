//! Halton and Hammersley points in up to 1024 dimensions: the radical inverses in the first D
//! primes (2, 3, 5, …, 8161), plain or scrambled per base.
//!
//! - **Halton**: x_j[d] = Φ_{p_d}(i), i = skip + j, p_d the (d+1)-th prime; the same values as
//!   `scipy.stats.qmc.Halton(D, scramble=False)` in the same order, each correctly rounded
//!   (the exact rational R / b^K, [`RadicalInverseIter`]). SciPy sums the digits in floating
//!   point (a rounding per digit), so its values differ from the correctly rounded ones by up to
//!   2 ulp in about a third of the coordinates (base 2 is exact in both); the tests compare with
//!   SciPy to 2 ulp and with the exact rationals bit for bit.
//! - **Scrambles** per base, those of the 2D `halton` (`halton_scramble`): `permute` (one random
//!   digit permutation per digit position, dimension d from `derive_seed(seed, d)`) and `owen`
//!   (nested uniform scrambling, dimension d seeded `derive_seed(seed, d)`). Both keep every
//!   stratification of plain Halton on digit prefixes.
//! - **Hammersley**: x_i = (i/N, Φ_2(i), Φ_3(i), …, Φ_{p_{D−2}}(i)), i = 0..N.
//!
//! At D = 2 these are the 2D patterns with their default bases (2, 3; p1 = 2), bit for bit. In
//! d dimensions the bases are always the first D primes: the 2D bases (`base_x`, `base_y`,
//! `p1`) choose the pair a 2D pattern shows and must keep their defaults when dims ≠ 2.
//!
//! Parallel chunks of 4096 points, each starting its D streams at its first index: the output
//! does not depend on the thread count.
use super::first_primes;
use crate::core::pattern::halton_scramble::{owen_stream, permuted_stream, HaltonScramble};
use crate::core::pattern::radical_inverse::RadicalInverseIter;
use crate::core::pattern::{clamp_unit, Cancel, Halton, Hammersley, PatternError};
use crate::core::rng::derive_seed;
use rayon::prelude::*;

/// Points per parallel chunk (and per cancel check).
const CHUNK: usize = 4096;

/// The first D primes, the bases of dimensions 0..D.
pub fn bases(dims: usize) -> Vec<u32> {
    first_primes(dims)
}

/// A 2D base left at a non-default value while dims ≠ 2.
fn fixed_base(
    pattern: &'static str,
    field: &'static str,
    value: u32,
    default: u32,
    dims: usize,
) -> Result<(), PatternError> {
    if value == default {
        return Ok(());
    }
    Err(PatternError::InvalidParam {
        pattern,
        field,
        value: value.to_string(),
        allowed: format!(
            "{default} with dims = {dims}: in d dimensions the bases are the first {dims} primes \
             ({field} chooses a base of the 2D pattern only)"
        ),
    })
}

/// The checks of the d-dimensional [`halton`]: default bases, `skip + n` within 2³³ + 2²⁴.
pub(super) fn check_halton(p: &Halton, _n: usize, dims: usize) -> Result<(), PatternError> {
    let d = Halton::default();
    fixed_base(Halton::NAME, "base_x", p.base_x, d.base_x, dims)?;
    fixed_base(Halton::NAME, "base_y", p.base_y, d.base_y, dims)
}

/// The checks of the d-dimensional [`hammersley`]: the default `p1`.
pub(super) fn check_hammersley(p: &Hammersley, _n: usize, dims: usize) -> Result<(), PatternError> {
    fixed_base(Hammersley::NAME, "p1", p.p1, Hammersley::default().p1, dims)
}

/// The stream of dimension d's coordinates from index `start`.
fn stream(
    scramble: HaltonScramble,
    start: u64,
    base: u32,
    seed: u64,
    d: usize,
) -> Box<dyn Iterator<Item = f64>> {
    match scramble {
        HaltonScramble::None => Box::new(RadicalInverseIter::new(start, base)),
        HaltonScramble::Permute => {
            Box::new(permuted_stream(start, base, derive_seed(seed, d as u64)))
        }
        HaltonScramble::Owen => Box::new(owen_stream(start, base, derive_seed(seed, d as u64))),
    }
}

/// Fills row-major `n × dims` coordinates in parallel chunks; `column(first, d)` gives
/// dimension d's values from point index `first` on.
fn fill_columns<I: Iterator<Item = f64>>(
    n: usize,
    dims: usize,
    cancel: &Cancel,
    column: impl Fn(usize, usize) -> I + Sync,
) -> Result<Vec<f64>, PatternError> {
    let mut out = vec![0.0f64; n * dims];
    out.par_chunks_mut(CHUNK * dims)
        .enumerate()
        .try_for_each(|(c, chunk)| {
            cancel.check()?;
            let first = c * CHUNK;
            for d in 0..dims {
                for (row, v) in chunk.chunks_exact_mut(dims).zip(column(first, d)) {
                    row[d] = v;
                }
            }
            Ok::<(), crate::core::cancel::Cancelled>(())
        })?;
    Ok(out)
}

/// Halton points j = 0..n, index skip + j, in the first `dims` primes, scrambled per
/// `p.scramble` (module docs).
pub fn halton(
    p: &Halton,
    n: usize,
    dims: usize,
    seed: u64,
    cancel: &Cancel,
) -> Result<Vec<f64>, PatternError> {
    let bases = bases(dims);
    let skip = u64::from(p.skip);
    fill_columns(n, dims, cancel, |first, d| {
        stream(p.scramble, skip + first as u64, bases[d], seed, d)
    })
}

/// Hammersley points (i/N, Φ_2(i), …, Φ_{p_{D−2}}(i)), i = 0..N.
pub fn hammersley(n: usize, dims: usize, cancel: &Cancel) -> Result<Vec<f64>, PatternError> {
    let bases = bases(dims.saturating_sub(1).max(1));
    let nf = n as f64;
    fill_columns(n, dims, cancel, |first, d| {
        let it: Box<dyn Iterator<Item = f64>> = if d == 0 {
            Box::new((first..).map(move |i| clamp_unit(i as f64 / nf)))
        } else {
            Box::new(RadicalInverseIter::new(first as u64, bases[d - 1]))
        };
        it
    })
}

/// Halton points computed one coordinate at a time by the radical inverse's definition
/// ([`crate::core::pattern::radical_inverse::radical_inverse`], O(log_b i) divisions each), one
/// thread: the naive reference of the tests and the benchmark.
pub fn halton_naive(skip: u32, n: usize, dims: usize) -> Vec<f64> {
    let bases = bases(dims);
    let mut out = Vec::with_capacity(n * dims);
    for j in 0..n as u64 {
        let i = u64::from(skip) + j;
        for &b in &bases {
            out.push(crate::core::pattern::radical_inverse::radical_inverse(i, b));
        }
    }
    out
}
