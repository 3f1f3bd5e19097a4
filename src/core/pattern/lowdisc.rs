//! Low-discrepancy sequences and point sets: van der Corput, Halton, Hammersley, their folded
//! (Zaremba) twins, and the Sobol' (0,2)-sequence with optional scrambling.
//!
//! ## Conventions
//!
//! - Indices start at 0 (Φ_b(0) = 0 is the first van der Corput point). Halton and Sobol' start
//!   at index `skip`; point j of the output has index i = skip + j.
//! - Bases are primes in 2..=7919 (the first 1000 primes, [`PRIMES`](super::radical_inverse::PRIMES)).
//!   A non-prime base is an error: the Halton construction needs pairwise coprime bases, and the
//!   parameter is documented as "a prime".
//! - Every coordinate lies in [0, 1 − 2⁻⁵³] (see [`radical_inverse`](super::radical_inverse::radical_inverse)).
//! - Sobol' points are 32-bit: a coordinate is an integer v ∈ [0, 2³²) read as v · 2⁻³², which is
//!   exact in f64 and < 1 by construction.
//!
//! References: J. H. Halton 1960 (Numer. Math. 2); J. M. Hammersley 1960; I. M. Sobol' 1967
//! (USSR Comput. Math. Math. Phys. 7); I. A. Antonov & V. M. Saleev 1979 (Gray-code order);
//! T. Kollig & A. Keller 2002 (folded radical inverse, random digit scrambling); S. Laine &
//! T. Karras 2011, "Stratified sampling for stochastic transparency" (hash-based nested
//! scrambling); B. Burley 2020, "Practical hash-based Owen scrambling" (JCGT 9(4)).
use super::radical_inverse::{
    is_prime, FoldedRadicalInverseIter, RadicalInverseIter, MAX_PRIME_BASE,
};
use super::*;
use crate::core::rng::{derive_seed, Rng};

/// `base` if it is a prime in 2..=7919, else [`PatternError::InvalidParam`] naming
/// `pattern.field`, e.g. `halton.base_x = 4: must be a prime in 2..=7919`.
pub fn check_prime_base(
    pattern: &'static str,
    field: &'static str,
    base: u32,
) -> Result<u32, PatternError> {
    if base <= MAX_PRIME_BASE && is_prime(u64::from(base)) {
        Ok(base)
    } else {
        Err(PatternError::InvalidParam {
            pattern,
            field,
            value: base.to_string(),
            allowed: format!("a prime in 2..={MAX_PRIME_BASE}"),
        })
    }
}

/// Both Halton bases prime, and distinct: with equal bases the two coordinates are the same
/// number, so every point lies on the diagonal x = y (the Halton construction needs coprime bases).
pub(super) fn check_halton_bases(
    pattern: &'static str,
    base_x: u32,
    base_y: u32,
) -> Result<(u32, u32), PatternError> {
    let bx = check_prime_base(pattern, "base_x", base_x)?;
    let by = check_prime_base(pattern, "base_y", base_y)?;
    if bx == by {
        return Err(PatternError::InvalidParam {
            pattern,
            field: "base_y",
            value: base_y.to_string(),
            allowed: format!(
                "a prime in 2..={MAX_PRIME_BASE} different from base_x = {base_x} \
                 (equal bases make x = y: every point would lie on the diagonal)"
            ),
        });
    }
    Ok((bx, by))
}

/// The van der Corput sequence drawn as 2D points: x_i = Φ_b(i), y_i = ½, i = 0..n.
///
/// Φ_b is the radical inverse ([`radical_inverse`](super::radical_inverse::radical_inverse), evaluated
/// incrementally by [`RadicalInverseIter`]); base 2 gives 0, ½, ¼, ¾, ⅛, ⅝, ⅜, … (the
/// lecture's table). Star discrepancy O(log N / N).
///
/// Errors: `n` outside 1..=[`MAX_N`]; `base` not a prime ≤ 7919.
pub fn van_der_corput(p: &VanDerCorput, n: usize) -> Result<Vec<DVec2>, PatternError> {
    check_n(n, MAX_N)?;
    let b = check_prime_base(VanDerCorput::NAME, "base", p.base)?;
    Ok(RadicalInverseIter::new(0, b)
        .take(n)
        .map(|x| DVec2::new(x, 0.5))
        .collect())
}

/// The Halton sequence x_j = (Φ_{bx}(i), Φ_{by}(i)), i = skip + j, j = 0..n (Halton 1960).
///
/// Every prefix is well distributed (star discrepancy O((log N)² / N)); large bases show
/// correlated stripes (the lecture's "Prime numbers" figure).
///
/// Errors: `n` outside 1..=[`MAX_N`]; a base not a prime ≤ 7919; `base_x == base_y`.
pub fn halton(p: &Halton, n: usize) -> Result<Vec<DVec2>, PatternError> {
    check_n(n, MAX_N)?;
    let (bx, by) = check_halton_bases(Halton::NAME, p.base_x, p.base_y)?;
    let skip = u64::from(p.skip);
    Ok(RadicalInverseIter::new(skip, bx)
        .zip(RadicalInverseIter::new(skip, by))
        .take(n)
        .map(|(x, y)| DVec2::new(x, y))
        .collect())
}

/// The Hammersley point set x_i = (i/N, Φ_{p1}(i)), i = 0..N, N = n (Hammersley 1960).
///
/// N must be known in advance (not progressive); as p1 grows the set becomes regular and
/// aliases (the lecture's p1 = 2, 3, 5, 7, 11 figure).
///
/// Errors: `n` outside 1..=[`MAX_N`]; `p1` not a prime ≤ 7919.
pub fn hammersley(p: &Hammersley, n: usize) -> Result<Vec<DVec2>, PatternError> {
    check_n(n, MAX_N)?;
    let b = check_prime_base(Hammersley::NAME, "p1", p.p1)?;
    let nf = n as f64;
    Ok(RadicalInverseIter::new(0, b)
        .take(n)
        .enumerate()
        .map(|(i, y)| DVec2::new(clamp_unit(i as f64 / nf), y))
        .collect())
}

/// Halton–Zaremba: x_j = (Φ⁺_{bx}(i), Φ⁺_{by}(i)), i = skip + j, with the folded radical inverse
/// Φ⁺_b(n) = Σ_{k≥1} ((a_k + k − 1) mod b) b^{−k} ([`folded_radical_inverse`](super::radical_inverse::folded_radical_inverse); Kollig & Keller 2002,
/// evaluated incrementally by [`FoldedRadicalInverseIter`]).
///
/// Note that Φ⁺ sums the offset digits beyond the length of i too, so the first point is not
/// the origin: Φ⁺₂(0) = 1/3, Φ⁺₃(0) = 5/26.
///
/// Errors: as [`halton`].
pub fn halton_zaremba(p: &HaltonZaremba, n: usize) -> Result<Vec<DVec2>, PatternError> {
    check_n(n, MAX_N)?;
    let (bx, by) = check_halton_bases(HaltonZaremba::NAME, p.base_x, p.base_y)?;
    let skip = u64::from(p.skip);
    Ok(FoldedRadicalInverseIter::new(skip, bx)
        .zip(FoldedRadicalInverseIter::new(skip, by))
        .take(n)
        .map(|(x, y)| DVec2::new(x, y))
        .collect())
}

/// Hammersley–Zaremba: x_i = (i/N, Φ⁺_{p1}(i)), i = 0..N, with the folded radical inverse
/// ([`FoldedRadicalInverseIter`]).
///
/// Errors: as [`hammersley`].
pub fn hammersley_zaremba(p: &HammersleyZaremba, n: usize) -> Result<Vec<DVec2>, PatternError> {
    check_n(n, MAX_N)?;
    let b = check_prime_base(HammersleyZaremba::NAME, "p1", p.p1)?;
    let nf = n as f64;
    Ok(FoldedRadicalInverseIter::new(0, b)
        .take(n)
        .enumerate()
        .map(|(i, y)| DVec2::new(clamp_unit(i as f64 / nf), y))
        .collect())
}

/// Direction numbers of Sobol' dimension 0 as 32-bit integers: V_k = 2^(32−k), k = 1..=32
/// (the identity generator matrix: the van der Corput sequence in base 2).
const SOBOL_DIR_0: [u32; 32] = sobol_directions(false);

/// Direction numbers of Sobol' dimension 1: primitive polynomial x + 1 (degree s = 1, no inner
/// coefficients), initial m_1 = 1, recurrence m_k = 2 m_{k−1} ⊕ m_{k−1}, giving m = 1, 3, 5,
/// 15, 17, 51, 85, 255, …; V_k = m_k · 2^(32−k). The generator matrix is Pascal's triangle mod 2.
const SOBOL_DIR_1: [u32; 32] = sobol_directions(true);

/// Computes the 32 direction numbers V_1..V_32 (stored at indices 0..32) of dimension 0
/// (`pascal = false`: m_k = 1) or dimension 1 (`pascal = true`: m_k = 2 m_{k−1} ⊕ m_{k−1}).
const fn sobol_directions(pascal: bool) -> [u32; 32] {
    let mut v = [0u32; 32];
    let mut m: u64 = 1;
    let mut k = 1;
    while k <= 32 {
        v[k - 1] = (m << (32 - k)) as u32;
        if pascal {
            m ^= m << 1;
        }
        k += 1;
    }
    v
}

/// The unscrambled 32-bit Sobol' point with *natural* index `a`: the generator-matrix product
/// x_d = ⊕_{k: bit k of a is 1} V^{(d)}_{k+1}, d = 0, 1 (Sobol' 1967). Dimension 0 equals
/// `a.reverse_bits()`. This is the direct reference; [`sobol`] visits these points in Gray-code
/// order.
pub fn sobol_point_u32(a: u32) -> [u32; 2] {
    let mut x = 0u32;
    let mut y = 0u32;
    for k in 0..32 {
        // mask = all ones if bit k of a is set: branch-free.
        let mask = 0u32.wrapping_sub((a >> k) & 1);
        x ^= SOBOL_DIR_0[k] & mask;
        y ^= SOBOL_DIR_1[k] & mask;
    }
    [x, y]
}

/// The Laine–Karras style nested permutation of a *bit-reversed* 32-bit value (Laine & Karras
/// 2011; Burley 2020, §3), written for samplescope.
///
/// In the reversed word, bit 0 is the most significant binary digit of the coordinate. Each step
/// below changes bit k by an amount that depends only on bits < k (and the seed): adding a
/// constant (carries only move up), multiplying by an odd number, and `x ^= x · c` with c even
/// (bit k of x·c depends on bits < k only). So output digit k = input digit k ⊕ f_k(digits < k,
/// seed): a nested uniform (Owen) scramble whose per-node flips f_k are drawn from a hash rather
/// than stored. The seed enters twice — an additive offset (low 32 bits) and an odd multiplier
/// (high 32 bits) — so that the first digits' flips are seed-dependent; the even multipliers
/// spread every digit into all higher ones.
#[inline]
fn nested_scramble_reversed(mut x: u32, seed: u64) -> u32 {
    let s0 = seed as u32;
    let s1 = (seed >> 32) as u32;
    x = x.wrapping_add(s0);
    x ^= x.wrapping_mul(0x9b9b_1324);
    x = x.wrapping_mul(s1 | 1);
    x ^= x.wrapping_mul(0xd1a6_e55e);
    x = x.wrapping_add(s1);
    x ^= x.wrapping_mul(0xc55a_45f8);
    x ^= x.wrapping_mul(0x566b_f9d6);
    x
}

/// Hash-based Owen (nested uniform) scrambling of a 32-bit binary fraction v·2⁻³², fast form:
/// reverse the bits, apply the nested permutation `nested_scramble_reversed`, reverse back
/// (Burley 2020, "Practical hash-based Owen scrambling"). Digit k of the result is digit k of
/// `v` XOR a pseudo-random bit that depends only on `seed` and the digits above k, so the map is
/// a bijection that preserves every (0,m,2)-net.
#[inline]
pub fn owen_scramble(v: u32, seed: u64) -> u32 {
    nested_scramble_reversed(v.reverse_bits(), seed).reverse_bits()
}

/// Owen scrambling by its definition, one hashed coin per tree node (Owen 1995): digit k (from
/// the most significant) of `v` is flipped iff bit 0 of `derive_seed(seed ⊕ k·φ, prefix)` is 1,
/// where `prefix` is the k digits above it. 32 hashes per value: the slow reference for tests
/// and benchmarks (a different random scramble from [`owen_scramble`], with the same structure).
pub fn owen_scramble_reference(v: u32, seed: u64) -> u32 {
    let mut out = v;
    for k in 0..32u32 {
        let prefix = u64::from(v) >> (32 - k); // the k most significant digits (0 for k = 0)
        let node_seed = seed ^ u64::from(k).wrapping_mul(0x9E37_79B9_7F4A_7C15);
        let flip = (derive_seed(node_seed, prefix) & 1) as u32;
        out ^= flip << (31 - k);
    }
    out
}

/// 2⁻³², exactly.
const TWO_POW_M32: f64 = 1.0 / 4_294_967_296.0;

/// [`SOBOL_DIR_0`] and [`SOBOL_DIR_1`] with their bits reversed: the direction numbers of the
/// bit-reversed coordinates, in which Owen scrambling works.
const SOBOL_DIR_REV: [[u32; 32]; 2] = reverse_directions();

const fn reverse_directions() -> [[u32; 32]; 2] {
    let mut r = [[0u32; 32]; 2];
    let mut k = 0;
    while k < 32 {
        r[0][k] = SOBOL_DIR_0[k].reverse_bits();
        r[1][k] = SOBOL_DIR_1[k].reverse_bits();
        k += 1;
    }
    r
}

/// The Sobol' points of indices `start ..= start + count − 1` in Gray-code order, each passed
/// through `finish`, which receives the two 32-bit coordinates — bit-reversed if `reversed` —
/// and returns them as plain (unreversed) integers. The inner loop is branch-free: one
/// `trailing_zeros` and two XORs per point, then `finish`. One allocation.
#[inline]
fn sobol_fill(
    start: u32,
    count: usize,
    reversed: bool,
    finish: impl Fn(u32, u32) -> (u32, u32),
) -> Vec<DVec2> {
    let mut out = Vec::with_capacity(count);
    let [mut x, mut y] = sobol_point_u32(start ^ (start >> 1));
    let (dir_x, dir_y) = if reversed {
        (x, y) = (x.reverse_bits(), y.reverse_bits());
        (&SOBOL_DIR_REV[0], &SOBOL_DIR_REV[1])
    } else {
        (&SOBOL_DIR_0, &SOBOL_DIR_1)
    };
    let to_point = |x: u32, y: u32| {
        let (fx, fy) = finish(x, y);
        DVec2::new(fx as f64 * TWO_POW_M32, fy as f64 * TWO_POW_M32)
    };
    out.push(to_point(x, y));
    // start + count − 1 ≤ u32::MAX was checked by the caller; i ≥ 1 so trailing_zeros < 32.
    let end = u64::from(start) + count as u64;
    for i in u64::from(start) + 1..end {
        let c = (i as u32).trailing_zeros() as usize & 31;
        x ^= dir_x[c];
        y ^= dir_y[c];
        out.push(to_point(x, y));
    }
    out
}

/// The checks of [`sobol`]: `n` and `skip + n − 1 ≤ 2³² − 1`.
pub(super) fn check_sobol(p: &Sobol, n: usize) -> Result<(), PatternError> {
    check_n(n, MAX_N)?;
    let last = u64::from(p.skip) + n as u64 - 1;
    if last > u64::from(u32::MAX) {
        return Err(PatternError::InvalidParam {
            pattern: Sobol::NAME,
            field: "skip",
            value: p.skip.to_string(),
            allowed: format!(
                "an integer in 0..={} for n = {n}: the last index skip + n − 1 must be ≤ 2³² − 1 \
                 (32-bit Sobol')",
                u64::from(u32::MAX) + 1 - n as u64
            ),
        });
    }
    Ok(())
}

/// The Sobol' (0,2)-sequence: the first two Sobol' dimensions, 32-bit, points with indices
/// i = skip + j, j = 0..n, optionally scrambled (Sobol' 1967).
///
/// - **Dimensions.** Dimension 0 is the base-2 van der Corput sequence (bit reversal);
///   dimension 1 uses the primitive polynomial x + 1 (direction numbers m_k = 2m_{k−1} ⊕ m_{k−1},
///   Pascal's matrix mod 2). Together they form a (0,2)-sequence: every aligned block of 2^m
///   points (indices k·2^m ..< (k+1)·2^m) is a (0,m,2)-net — one point in each elementary
///   interval of area 2^−m.
/// - **Order.** Points are generated in Gray-code order (Antonov & Saleev 1979), as in Joe & Kuo's
///   reference generator, SciPy and MATLAB: point i is the natural-order point with index
///   g(i) = i ⊕ (i ≫ 1) ([`sobol_point_u32`]). The first points are (0,0), (½,½), (¾,¼), (¼,¾),
///   (⅜,⅜), (⅞,⅞), (⅝,⅛), (⅛,⅝). Gray order permutes aligned blocks of 2^m among themselves,
///   so the net property above holds unchanged.
/// - **Scrambling** ([`Scramble`]): `None`; `RandomDigit` XORs each dimension's 32-bit integer with
///   a word drawn from `Rng::new(seed)` (x first, then y) — a digital shift (Kollig & Keller 2002);
///   `Owen` applies [`owen_scramble`] with the per-dimension seeds `derive_seed(seed, 0)` and
///   `derive_seed(seed, 1)`. Both keep the (0,m,2)-net property of every aligned block.
///
/// Errors: `n` outside 1..=[`MAX_N`]; `skip + n − 1 > 2³² − 1` (indices are 32-bit).
pub fn sobol(p: &Sobol, n: usize, seed: u64) -> Result<Vec<DVec2>, PatternError> {
    check_sobol(p, n)?;
    let start = p.skip;
    Ok(match p.scramble {
        Scramble::None => sobol_fill(start, n, false, |x, y| (x, y)),
        Scramble::RandomDigit => {
            let mut rng = Rng::new(seed);
            let wx = rng.next_u32();
            let wy = rng.next_u32();
            sobol_fill(start, n, false, |x, y| (x ^ wx, y ^ wy))
        }
        Scramble::OwenShuffled => {
            let coords = super::cube::sobol::sobol(p, n, 2, seed, &Cancel::never())?;
            coords
                .chunks_exact(2)
                .map(|c| DVec2::new(c[0], c[1]))
                .collect()
        }
        Scramble::Owen => {
            // owen_scramble(v) = reverse(nested(reverse(v))): the sequence is stepped in the
            // reversed domain, so only the final reversal remains per coordinate.
            let sx = derive_seed(seed, 0);
            let sy = derive_seed(seed, 1);
            sobol_fill(start, n, true, |xr, yr| {
                (
                    nested_scramble_reversed(xr, sx).reverse_bits(),
                    nested_scramble_reversed(yr, sy).reverse_bits(),
                )
            })
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sobol_direction_numbers_are_pascal_mod_2() {
        // m_k from the recurrence, checked against the binomial definition: bit j of m_k is
        // C(k−1, j) mod 2 (row k−1 of Pascal's triangle, read as a binary number).
        for k in 1..=32usize {
            let mut m: u64 = 0;
            for j in 0..k {
                // C(k−1, j) mod 2 = 1 iff j & (k−1) == j (Lucas' theorem).
                if j & (k - 1) == j {
                    m |= 1 << j;
                }
            }
            assert_eq!(u64::from(SOBOL_DIR_1[k - 1]), m << (32 - k), "k = {k}");
            assert_eq!(SOBOL_DIR_0[k - 1], 1u32 << (32 - k));
        }
        // The first m_k as published (Joe & Kuo, dimension 2 of new-joe-kuo-6.21201).
        let m: Vec<u32> = (1..=8).map(|k| SOBOL_DIR_1[k - 1] >> (32 - k)).collect();
        assert_eq!(m, vec![1, 3, 5, 15, 17, 51, 85, 255]);
    }

    #[test]
    fn sobol_point_dimension0_is_bit_reversal() {
        let mut rng = Rng::new(5);
        for _ in 0..1000 {
            let a = rng.next_u32();
            assert_eq!(sobol_point_u32(a)[0], a.reverse_bits());
        }
    }

    /// Checks that `f` is a nested scramble: images of v and w agree on the digits above the
    /// first digit where v and w differ, and differ at that digit.
    fn assert_nested(f: impl Fn(u32) -> u32) {
        let mut rng = Rng::new(99);
        for _ in 0..20_000 {
            let v = rng.next_u32();
            let k = rng.below(32) as u32; // first differing digit, from the top
            let keep = if k == 0 { 0 } else { u32::MAX << (32 - k) };
            let w = (v & keep) | (rng.next_u32() & !keep);
            let w = w & !(1 << (31 - k)) | (!v & (1 << (31 - k)));
            let (fv, fw) = (f(v), f(w));
            assert_eq!(
                fv & keep,
                fw & keep,
                "prefix changed: v={v:#x} w={w:#x} k={k}"
            );
            assert_ne!(
                (fv ^ fw) & (1 << (31 - k)),
                0,
                "digit {k} not a bijection: v={v:#x} w={w:#x}"
            );
        }
    }

    #[test]
    fn owen_scramble_fast_and_reference_are_nested_bijections() {
        for seed in [0u64, 1, 0xDEAD_BEEF, u64::MAX] {
            assert_nested(|v| owen_scramble(v, seed));
            assert_nested(|v| owen_scramble_reference(v, seed));
        }
    }

    /// For digit levels k = 0..12 and a few nodes per level, across 4096 seeds: each node's flip
    /// is a fair coin, and the flips of two sibling nodes agree half the time (independent),
    /// as for an ideal Owen scramble. 4096 trials: σ = 1/128, the band ±0.05 is 6.4σ.
    fn assert_fair_independent_flips(f: impl Fn(u32, u64) -> u32) {
        let trials = 4096u64;
        for k in 0..12u32 {
            for node in 0..4u32 {
                // Prefix of k digits (node pattern), digit k = 0, the rest 0: v and its sibling.
                let prefix = if k == 0 {
                    0
                } else {
                    (node.wrapping_mul(0x9E37_79B9) & ((1u32 << k) - 1)) << (32 - k)
                };
                let sibling = prefix ^ if k == 0 { 0 } else { 1 << (32 - k) };
                let bit = 1u32 << (31 - k);
                let mut flips = 0u64;
                let mut agree = 0u64;
                for s in 0..trials {
                    let seed = derive_seed(12345, s);
                    let a = (f(prefix, seed) ^ prefix) & bit != 0;
                    let b = (f(sibling, seed) ^ sibling) & bit != 0;
                    flips += a as u64;
                    agree += (a == b) as u64;
                }
                let pf = flips as f64 / trials as f64;
                assert!(
                    (pf - 0.5).abs() < 0.05,
                    "level {k} node {node}: flip rate {pf}"
                );
                if k > 0 {
                    let pa = agree as f64 / trials as f64;
                    assert!((pa - 0.5).abs() < 0.05, "level {k}: sibling agreement {pa}");
                }
            }
        }
    }

    /// Within a single seed, the flips of the 2^k nodes of level k (k = 8, 10, 12) must look like
    /// independent fair coins, as in a true Owen scramble: their mean is ½, a node agrees with its
    /// neighbour (next node in reversed-digit order) half the time, and with its child at level
    /// k + 1 half the time. Per seed and level, σ ≤ 1/32; the band ±0.15 is ≥ 4.8σ. (A plain
    /// additive scramble x + seed — carries only — fails this: its flips are a threshold function.)
    fn assert_flips_independent_within_seed(f: impl Fn(u32, u64) -> u32) {
        for s in 0..48u64 {
            let seed = derive_seed(777, s);
            for k in [8u32, 10, 12] {
                let nodes = 1u32 << k;
                let flip = |level: u32, r: u32| {
                    // r holds the prefix digits in reversed order: v = its top `level` digits.
                    let v = r.reverse_bits();
                    (f(v, seed) ^ v) >> (31 - level) & 1
                };
                let (mut ones, mut agree_next, mut agree_child) = (0u32, 0u32, 0u32);
                for r in 0..nodes {
                    let here = flip(k, r);
                    ones += here;
                    agree_next += (here == flip(k, (r + 1) % nodes)) as u32;
                    agree_child += (here == flip(k + 1, r)) as u32;
                }
                for (what, count) in [("mean", ones), ("next", agree_next), ("child", agree_child)]
                {
                    let frac = f64::from(count) / f64::from(nodes);
                    assert!(
                        (frac - 0.5).abs() < 0.15,
                        "seed {s} level {k}: {what} {frac}"
                    );
                }
            }
        }
    }

    #[test]
    fn owen_scramble_flips_are_independent_within_one_seed() {
        assert_flips_independent_within_seed(owen_scramble);
        assert_flips_independent_within_seed(owen_scramble_reference);
    }

    #[test]
    fn owen_scramble_flips_are_fair_and_independent() {
        assert_fair_independent_flips(owen_scramble);
        assert_fair_independent_flips(owen_scramble_reference);
    }
}
