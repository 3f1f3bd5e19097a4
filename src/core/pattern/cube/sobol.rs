//! Sobol' points in up to 1024 dimensions with Joe & Kuo's direction numbers
//! (new-joe-kuo-6.21201), identical to `scipy.stats.qmc.Sobol(d, scramble=False)` including the
//! point order, with per-dimension random-digit or Owen scrambling and Burley's hash-based
//! shuffling of the index.
//!
//! **Directions.** Dimension 0 is the van der Corput sequence in base 2 (m_k = 1). Dimension
//! j ≥ 1 is row d = j + 1 of Joe & Kuo's table (`assets/sobol/new-joe-kuo-6.21201-1024.txt`,
//! its origin and licence in its header; parsed once, at first use): a primitive polynomial of
//! degree s with inner coefficients c_1 … c_{s−1} (the bits of `a`), initial odd m_1 … m_s, and
//! for k > s the recurrence m_k = 2c_1 m_{k−1} ⊕ 2²c_2 m_{k−2} ⊕ … ⊕ 2^{s−1}c_{s−1} m_{k−s+1} ⊕
//! 2^s m_{k−s} ⊕ m_{k−s} (Bratley & Fox 1988; Joe & Kuo 2008). The direction numbers are
//! V_k = m_k · 2^{32−k}, k = 1..=32: 32-bit points, a coordinate v · 2⁻³². Dimensions 0 and 1
//! are the 2D `sobol`'s (x + 1 is Joe & Kuo's d = 2), and SciPy's 30-bit points are the top 30
//! bits of these (V₃₂ = 4·V₃₀ for k ≤ 30), so the values agree exactly for n ≤ 2³⁰.
//!
//! **Order.** Gray-code order (Antonov & Saleev 1979), point j = the natural-order point of
//! index g(i) = i ⊕ (i ≫ 1), i = skip + j, as SciPy, Joe & Kuo and the 2D `sobol`. Each point
//! is its predecessor with one direction number XORed per dimension: O(D) per point, in
//! parallel chunks of 4096 points that start from their first point computed directly (the
//! output does not depend on the thread count). [`sobol_naive`] computes every point from its
//! index through the generator matrices (O(32·D) per point), the reference of the tests and
//! the benchmark.
//!
//! **Scrambling** (per dimension; the 2D `sobol`'s at D = 2, bit for bit):
//! - `random-digit`: dimension d XORed with the d-th 32-bit word of `Rng::new(seed)`;
//! - `owen`: [`owen_scramble`] with the seed `derive_seed(seed, d)`;
//! - `owen-shuffled`: `owen` applied to the point whose sequence position is
//!   `owen_scramble(skip + j, derive_seed(seed, SHUFFLE_STREAM))` (Burley 2020, "Practical
//!   hash-based Owen scrambling", JCGT 9(4): the index's nested uniform scramble). Each index
//!   bit then depends only on itself and the bits above it, so the first 2^m points are one
//!   aligned block of 2^m sequence positions (the high bits are fixed by the seed), visited in
//!   a random nested order: every 2^m prefix is the (t,m,s)-net the plain block is, and the
//!   order within it is random, which is what pbrt-v4 and Burley use to decorrelate
//!   dimensions and pixels.
//!
//! Every scramble is a bijection on the leading m digits of each coordinate, so each aligned
//! 2^m block stays a (t,m,s)-net in every set of dimensions where the plain one is (tested).
use crate::core::pattern::lowdisc::{check_sobol, owen_scramble};
use crate::core::pattern::{Cancel, PatternError, Scramble, Sobol};
use crate::core::rng::{derive_seed, Rng};
use rayon::prelude::*;
use std::sync::OnceLock;

/// The table of direction numbers (Joe & Kuo, dimensions 2..=1024 in their numbering).
const TABLE: &str = include_str!("../../../../assets/sobol/new-joe-kuo-6.21201-1024.txt");

/// The most dimensions of [`sobol`]: the rows of the table plus dimension 0.
pub const SOBOL_MAX_DIMS: usize = 1024;

/// The stream index of the shuffle's seed (`derive_seed(seed, SHUFFLE_STREAM)`), apart from
/// the per-dimension streams 0..dims.
pub const SHUFFLE_STREAM: u64 = u64::MAX;

/// Points per parallel chunk (and per cancel check).
const CHUNK: usize = 4096;

/// 2⁻³², exactly.
const TWO_POW_M32: f64 = 1.0 / 4_294_967_296.0;

/// The 32 direction numbers V_1..V_32 of one dimension (index k − 1).
pub type Directions = [u32; 32];

/// The direction numbers of a dimension from its polynomial's degree `s`, inner coefficients
/// `a` and initial `m` (`m.len() == s`; s = 0 is dimension 0, every m_k = 1).
pub fn direction_numbers(s: usize, a: u32, m: &[u32]) -> Directions {
    let mut mk = [0u64; 33]; // mk[k] = m_k, 1-based
    for k in 1..=32 {
        mk[k] = if s == 0 {
            1
        } else if k <= s {
            u64::from(m[k - 1])
        } else {
            let mut v = mk[k - s] ^ (mk[k - s] << s);
            for i in 1..s {
                if (a >> (s - 1 - i)) & 1 == 1 {
                    v ^= mk[k - i] << i;
                }
            }
            v
        };
    }
    let mut out = [0u32; 32];
    for k in 1..=32 {
        out[k - 1] = (mk[k] << (32 - k)) as u32;
    }
    out
}

/// Parses the table's rows `d s a m_1 … m_s` (d = 2, 3, … in order; `#` lines and the
/// column header skipped) into direction numbers, dimension 0 first.
fn parse_table(text: &str) -> Result<Vec<Directions>, String> {
    let mut dims = vec![direction_numbers(0, 0, &[])];
    for (line_no, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') || line.starts_with('d') {
            continue;
        }
        let bad = |what: &str| format!("line {}: {what}: {line}", line_no + 1);
        let fields: Vec<u32> = line
            .split_whitespace()
            .map(|f| f.parse().map_err(|_| bad("not an integer")))
            .collect::<Result<_, _>>()?;
        let [d, s, a, m @ ..] = fields.as_slice() else {
            return Err(bad("fewer than 3 fields"));
        };
        let s = *s as usize;
        if *d as usize != dims.len() + 1 || m.len() != s || s == 0 || s > 31 {
            return Err(bad("expected d = previous + 1 and s initial numbers"));
        }
        if m.iter()
            .enumerate()
            .any(|(k, &mk)| mk % 2 == 0 || mk >= 2 << k)
        {
            return Err(bad("m_k must be odd and below 2^k"));
        }
        dims.push(direction_numbers(s, *a, m));
    }
    Ok(dims)
}

/// The direction numbers of dimensions 0..[`SOBOL_MAX_DIMS`], parsed at first use.
pub fn directions() -> &'static [Directions] {
    static DIRS: OnceLock<Vec<Directions>> = OnceLock::new();
    DIRS.get_or_init(|| {
        let dims = parse_table(TABLE).expect("the shipped Sobol' table parses");
        assert_eq!(
            dims.len(),
            SOBOL_MAX_DIMS,
            "the shipped table has 1024 dimensions"
        );
        dims
    })
}

/// The unscrambled 32-bit Sobol' point with natural index `a`, by the generator matrices:
/// x_d = ⊕_{k: bit k of a is 1} V^{(d)}_{k+1} (the direct definition).
pub fn point_u32(a: u32, out: &mut [u32]) {
    let dirs = directions();
    out.fill(0);
    let mut bits = a;
    while bits != 0 {
        let k = bits.trailing_zeros() as usize;
        bits &= bits - 1;
        for (x, v) in out.iter_mut().zip(dirs) {
            *x ^= v[k];
        }
    }
}

/// The per-dimension scramble of a 32-bit coordinate.
#[derive(Clone)]
enum Finish {
    None,
    Xor(Vec<u32>),
    Owen(Vec<u64>),
}

impl Finish {
    fn new(scramble: Scramble, dims: usize, seed: u64) -> Self {
        match scramble {
            Scramble::None => Finish::None,
            Scramble::RandomDigit => {
                let mut rng = Rng::new(seed);
                Finish::Xor((0..dims).map(|_| rng.next_u32()).collect())
            }
            Scramble::Owen | Scramble::OwenShuffled => {
                Finish::Owen((0..dims as u64).map(|d| derive_seed(seed, d)).collect())
            }
        }
    }

    #[inline]
    fn write(&self, x: &[u32], out: &mut [f64]) {
        match self {
            Finish::None => {
                for (o, &v) in out.iter_mut().zip(x) {
                    *o = f64::from(v) * TWO_POW_M32;
                }
            }
            Finish::Xor(w) => {
                for ((o, &v), &w) in out.iter_mut().zip(x).zip(w) {
                    *o = f64::from(v ^ w) * TWO_POW_M32;
                }
            }
            Finish::Owen(s) => {
                for ((o, &v), &s) in out.iter_mut().zip(x).zip(s) {
                    *o = f64::from(owen_scramble(v, s)) * TWO_POW_M32;
                }
            }
        }
    }
}

/// Sobol' points j = 0..n with indices skip + j in `dims` ≤ [`SOBOL_MAX_DIMS`] dimensions,
/// row-major (module docs). Errors: `n`, `skip` as the 2D `sobol`; cancelled.
pub fn sobol(
    p: &Sobol,
    n: usize,
    dims: usize,
    seed: u64,
    cancel: &Cancel,
) -> Result<Vec<f64>, PatternError> {
    check_sobol(p, n)?;
    let dirs = &directions()[..dims];
    let finish = Finish::new(p.scramble, dims, seed);
    let shuffle = (p.scramble == Scramble::OwenShuffled).then(|| derive_seed(seed, SHUFFLE_STREAM));
    let mut out = vec![0.0f64; n * dims];
    out.par_chunks_mut(CHUNK * dims)
        .enumerate()
        .try_for_each(|(c, chunk)| {
            cancel.check()?;
            let first = u64::from(p.skip) + (c * CHUNK) as u64;
            let mut x = vec![0u32; dims];
            if let Some(s) = shuffle {
                for (j, row) in chunk.chunks_exact_mut(dims).enumerate() {
                    let pos = owen_scramble((first + j as u64) as u32, s);
                    point_u32(pos ^ (pos >> 1), &mut x);
                    finish.write(&x, row);
                }
                return Ok(());
            }
            let i0 = first as u32;
            point_u32(i0 ^ (i0 >> 1), &mut x);
            for (j, row) in chunk.chunks_exact_mut(dims).enumerate() {
                if j > 0 {
                    // i ≥ 1, so trailing_zeros < 32.
                    let k = ((first + j as u64) as u32).trailing_zeros() as usize & 31;
                    for (v, d) in x.iter_mut().zip(dirs) {
                        *v ^= d[k];
                    }
                }
                finish.write(&x, row);
            }
            Ok::<(), crate::core::cancel::Cancelled>(())
        })?;
    Ok(out)
}

/// The plain (unscrambled) points of [`sobol`] one by one from their Gray-code index through
/// all 32 columns of the generator matrices, O(32·D) per point, one thread: the naive
/// reference [`sobol`] is tested and benchmarked against.
pub fn sobol_naive(skip: u32, n: usize, dims: usize) -> Vec<f64> {
    let dirs = &directions()[..dims];
    let mut out = Vec::with_capacity(n * dims);
    for j in 0..n as u64 {
        let i = (u64::from(skip) + j) as u32;
        let g = i ^ (i >> 1);
        for d in dirs {
            let mut x = 0u32;
            for (k, v) in d.iter().enumerate() {
                if (g >> k) & 1 == 1 {
                    x ^= v;
                }
            }
            out.push(f64::from(x) * TWO_POW_M32);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_table_parses_and_starts_with_joe_and_kuo_s_rows() {
        let d = directions();
        assert_eq!(d.len(), 1024);
        // Dimension 1 (d = 2, x + 1): m = 1, 3, 5, 15, …; dimension 2 (d = 3, x² + x + 1,
        // m = 1, 3): m = 1, 3, 1, 5?  Checked by the recurrence against the 2D table.
        let m = |dim: usize, k: usize| d[dim][k - 1] >> (32 - k);
        assert_eq!(
            (1..=6).map(|k| m(1, k)).collect::<Vec<_>>(),
            [1, 3, 5, 15, 17, 51]
        );
        assert_eq!((1..=4).map(|k| m(0, k)).collect::<Vec<_>>(), [1, 1, 1, 1]);
        // d = 3: s = 2, a = 1, m = 1 3; m_3 = 2·m_2 ⊕ 4·m_1 ⊕ m_1 = 6 ⊕ 4 ⊕ 1 = 3.
        assert_eq!((1..=3).map(|k| m(2, k)).collect::<Vec<_>>(), [1, 3, 3]);
    }

    #[test]
    fn malformed_rows_are_refused_with_their_line() {
        assert!(parse_table("2 1 0 2").unwrap_err().contains("odd"));
        assert!(parse_table("3 1 0 1")
            .unwrap_err()
            .contains("d = previous + 1"));
        assert!(parse_table("2 1 x 1")
            .unwrap_err()
            .contains("not an integer"));
    }
}
