//! Patterns in d dimensions: [`Pattern::generate_cube`] (n points in [0,1)^d as a
//! [`CubePoints`]), [`Pattern::max_dims`] and the checks of `dims`, one file per family of
//! d-dimensional generators beside the 2D ones.
//!
//! | family | module | patterns (max dims) |
//! |---|---|---|
//! | stratified | [`stratified`] | random, lhs (Latin hypercube), grid (n a D-th power) — 1024 |
//! | Sobol' | [`sobol`] | sobol (Joe & Kuo new-joe-kuo-6.21201; none, random-digit, owen, owen-shuffled) — 1024 |
//! | radical inverse | [`halton`] | halton (the first D primes; none, permute, owen), hammersley — 1024 |
//! | lattices | [`lattice`] | kronecker (Roberts' R_d), rank1 (fast CBC, Korobov) — 1024 |
//! | padding | [`padded`] | padded (any 2D pattern per dimension pair, shuffled across pairs) — 1024 |
//!
//! Every other pattern is 2D only (`max_dims` = 2). **dims = 2 is the 2D pattern**: for every
//! pattern `generate_cube(n, 2, …)` is [`Pattern::generate_with`]'s points, bit for bit, so the
//! 2D path never changes. Where a pattern's d-dimensional construction at D = 2 is the same
//! construction, a test checks the two agree (random, lhs, grid, sobol, halton, hammersley,
//! padded); where it is not, the module says why (rank1: the 2D `g = 0` picks the generator with
//! the largest minimum distance, the d-dimensional one the CBC vector; kronecker: the same R2 up
//! to the last bit of α).
//!
//! Limits: `dims` in 1..=[`MAX_DIMS`], `n · dims` ≤ [`MAX_COORDS`], `n` ≤ [`MAX_N`]; each
//! pattern's own rules on `n` (grid: a D-th power; rank1: prime or small for the CBC vector).

pub mod halton;
pub mod lattice;
pub mod padded;
pub mod sobol;
pub mod stratified;

use super::*;
use crate::core::cube::{CubeError, CubePoints, MAX_COORDS, MAX_DIMS};

/// The patterns with a d-dimensional form, as `max_dims` lists them (the one list the error of
/// a 2D-only pattern and `points --list` print).
pub const CUBE_PATTERNS: &str =
    "random, lhs, grid, sobol, halton, hammersley, kronecker, rank1, padded";

impl Pattern {
    /// The most dimensions [`Pattern::generate_cube`] takes: [`MAX_DIMS`] for the patterns with
    /// a d-dimensional definition ([`CUBE_PATTERNS`]), 2 for the 2D-only ones.
    pub fn max_dims(&self) -> usize {
        match self {
            Pattern::Random(_)
            | Pattern::Lhs(_)
            | Pattern::Grid(_)
            | Pattern::Sobol(_)
            | Pattern::Halton(_)
            | Pattern::Hammersley(_)
            | Pattern::Kronecker(_)
            | Pattern::Rank1(_)
            | Pattern::Padded(_) => MAX_DIMS,
            _ => 2,
        }
    }

    /// Whether `dims` is one this pattern is defined in: 1..=`max_dims` for a d-dimensional
    /// pattern, exactly 2 for a 2D-only one.
    pub fn check_dims(&self, dims: usize) -> Result<(), PatternError> {
        let max = self.max_dims();
        if max == 2 {
            if dims == 2 {
                return Ok(());
            }
            return Err(PatternError::InvalidDims {
                pattern: self.name(),
                dims,
                max,
                allowed: format!(
                    "must be 2 ({} is defined in 2 dimensions only; the patterns defined in d \
                     dimensions are {CUBE_PATTERNS})",
                    self.name()
                ),
            });
        }
        if dims == 0 || dims > max {
            return Err(PatternError::InvalidDims {
                pattern: self.name(),
                dims,
                max,
                allowed: format!("must be an integer in 1..={max}"),
            });
        }
        Ok(())
    }

    /// Checks that `n` points in `dims` dimensions can be generated, without generating them
    /// (as [`Pattern::validate`], which is what dims = 2 checks): `dims`, `n · dims` ≤
    /// [`MAX_COORDS`], the parameters, and the pattern's own rules on `n` in `dims` dimensions.
    pub fn validate_cube(&self, n: usize, dims: usize) -> Result<(), PatternError> {
        self.check_dims(dims)?;
        if dims == 2 {
            return self.validate(n);
        }
        check_n(n, MAX_N)?;
        check_coords(n, dims)?;
        use crate::core::params::Params;
        self.check_params()?;
        match self {
            Pattern::Random(_) => Ok(()),
            Pattern::Lhs(p) => stratified::check_lhs(p, n, dims),
            Pattern::Grid(p) => stratified::check_grid(p, n, dims).map(drop),
            Pattern::Sobol(p) => lowdisc::check_sobol(p, n),
            Pattern::Halton(p) => halton::check_halton(p, n, dims),
            Pattern::Hammersley(p) => halton::check_hammersley(p, n, dims),
            Pattern::Kronecker(p) => lattice::check_kronecker(p, n, dims),
            Pattern::Rank1(p) => lattice::check_rank1(p, n, dims),
            Pattern::Padded(p) => padded::check_padded(p, n),
            _ => unreachable!("check_dims refused dims ≠ 2 for a 2D-only pattern"),
        }
    }

    /// `n` points in [0,1)^dims, row-major; a pure function of `(self, n, dims, seed)` (the
    /// thread count never changes a bit). dims = 2 is exactly [`Pattern::generate_with`]'s
    /// points (all n, else [`PatternError::TooFew`]). Errors: as [`Pattern::validate_cube`];
    /// [`PatternError::Cancelled`].
    pub fn generate_cube(
        &self,
        n: usize,
        dims: usize,
        seed: u64,
        cancel: &Cancel,
    ) -> Result<CubePoints, PatternError> {
        self.validate_cube(n, dims)?;
        if dims == 2 {
            let points = self
                .generate_with(n, seed, cancel)?
                .require_all(self.name())?;
            return Ok(CubePoints::from_2d(&points));
        }
        let coords = self.cube_coords(n, dims, seed, cancel)?;
        CubePoints::new(dims, coords).map_err(|e| cube_error(self.name(), e))
    }

    /// The 2D projection `(x_i, x_j)` of [`Pattern::generate_cube`]'s `n` points in `dims`
    /// dimensions (what `points --dims D --project i,j` writes, and what a scene's column with
    /// `dims` and `project` shows). Errors: as [`Pattern::generate_cube`], and a pair that is
    /// not two different dimensions below `dims` ([`PatternError::InvalidParam`] naming
    /// `project`).
    pub fn generate_projected(
        &self,
        n: usize,
        dims: usize,
        (i, j): (usize, usize),
        seed: u64,
        cancel: &Cancel,
    ) -> Result<Vec<DVec2>, PatternError> {
        if i >= dims || j >= dims || i == j {
            return Err(PatternError::InvalidParam {
                pattern: self.name(),
                field: "project",
                value: format!("({i}, {j})"),
                allowed: format!(
                    "two different dimensions in 0..={} (dims = {dims})",
                    dims.saturating_sub(1)
                ),
            });
        }
        let points = self.generate_cube(n, dims, seed, cancel)?;
        points.project(i, j).map_err(|e| cube_error(self.name(), e))
    }

    /// The d-dimensional construction itself, for any dims the pattern takes (also 2: the
    /// tests compare it with the 2D path). Row-major coordinates.
    pub fn cube_coords(
        &self,
        n: usize,
        dims: usize,
        seed: u64,
        cancel: &Cancel,
    ) -> Result<Vec<f64>, PatternError> {
        match self {
            Pattern::Random(_) => Ok(stratified::random(n, dims, seed)),
            Pattern::Lhs(p) => Ok(stratified::lhs(p.amount, n, dims, seed)),
            Pattern::Grid(p) => stratified::grid(p, n, dims),
            Pattern::Sobol(p) => sobol::sobol(p, n, dims, seed, cancel),
            Pattern::Halton(p) => halton::halton(p, n, dims, seed, cancel),
            Pattern::Hammersley(_) => halton::hammersley(n, dims, cancel),
            Pattern::Kronecker(p) => lattice::kronecker(p, n, dims),
            Pattern::Rank1(p) => lattice::rank1(p, n, dims, seed, cancel),
            Pattern::Padded(p) => padded::padded(p, n, dims, seed, cancel),
            _ => Err(PatternError::InvalidDims {
                pattern: self.name(),
                dims,
                max: 2,
                allowed: "must be 2".into(),
            }),
        }
    }
}

/// `n · dims` ≤ [`MAX_COORDS`], as [`PatternError::InvalidN`] naming the largest n for `dims`.
pub fn check_coords(n: usize, dims: usize) -> Result<(), PatternError> {
    if n.checked_mul(dims).is_none_or(|c| c > MAX_COORDS) {
        return Err(PatternError::InvalidN {
            n,
            max: MAX_COORDS / dims,
            why: format!(
                "; {dims} dimensions hold at most {MAX_COORDS} coordinates (n · dims ≤ 2^25)"
            ),
        });
    }
    Ok(())
}

/// A [`CubeError`] of a generator's output as a pattern error (a generator never makes one:
/// every coordinate is clamped into [0, 1)).
fn cube_error(pattern: &'static str, e: CubeError) -> PatternError {
    match e {
        CubeError::InvalidDims { dims, max } => PatternError::InvalidDims {
            pattern,
            dims,
            max,
            allowed: format!("must be an integer in 1..={max}"),
        },
        other => PatternError::InvalidParam {
            pattern,
            field: "points",
            value: String::new(),
            allowed: other.to_string(),
        },
    }
}

/// The first `count` primes, ascending (a sieve; the 1024th prime is 8161).
pub fn first_primes(count: usize) -> Vec<u32> {
    let mut limit = 16usize;
    loop {
        let mut composite = vec![false; limit + 1];
        let mut primes = Vec::with_capacity(count);
        for i in 2..=limit {
            if composite[i] {
                continue;
            }
            primes.push(i as u32);
            if primes.len() == count {
                return primes;
            }
            let mut j = i * i;
            while j <= limit {
                composite[j] = true;
                j += i;
            }
        }
        limit *= 2;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn first_primes_agree_with_the_table_of_the_2d_bases() {
        let p = first_primes(1024);
        assert_eq!(&p[..1000], &radical_inverse::PRIMES[..]);
        assert_eq!(p[1023], 8161);
        assert!(p[1000..]
            .iter()
            .all(|&q| radical_inverse::is_prime(u64::from(q))));
    }
}
