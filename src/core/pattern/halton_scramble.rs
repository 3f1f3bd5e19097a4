//! Scrambled Halton points: random digit permutations and nested uniform (Owen) scrambling of
//! the radical inverses.
//!
//! ## Construction
//!
//! Point j has index i = skip + j with base-b digits a_1, a_2, … (least significant first,
//! [`radical_inverse`](super::radical_inverse)). Each coordinate is a scrambled radical inverse
//!
//! Φ^π_b(i) = Σ_{k=1}^{K} π_k(a_k) b^{−k},
//!
//! with K the largest number of digits such that b^K ≤ 2⁵³ (53 for base 2, 33 for base 3, 4 for
//! base 7919). Every one of the K digits is permuted, also the zeros beyond the length of i (so a
//! point's trailing digits are not all 0 — as pbrt-v4, which continues until the digit weight
//! underflows); the digits past K weigh less than b^−K ≤ b·2⁻⁵³ and are dropped. The integer
//! R = Σ π_k(a_k) b^{K−k} < b^K ≤ 2⁵³ is exact, and the coordinate is the correctly rounded
//! quotient R / b^K (one f64 division, as in [`RadicalInverseIter`]), so the value is a
//! correctly rounded rational and lies in [0, 1 − 2⁻⁵³]. Indices are below 2³³ + 2²⁴ (skip is
//! 32-bit, n ≤ 2²⁴) < 2⁴⁰ < b^K for every base ≤ 7919, so all digits of i are inside the K.
//!
//! - [`HaltonScramble::None`]: π_k = identity; exactly the bits of
//!   [`halton`](super::lowdisc::halton) (the same [`RadicalInverseIter`]).
//! - [`HaltonScramble::Permute`]: one uniformly random permutation of 0..b per digit position k
//!   and per dimension, independent of the other digits (random digit permutations: Braaten &
//!   Weller 1979; Faure 1992; pbrt-v4's `PermuteDigits`, Pharr, Jakob & Humphreys 2023, §8.6.2).
//!   Dimension d (0 = x, 1 = y) draws its K permutations, digit position 1 first, by
//!   Fisher–Yates from [`Rng`]`::new(derive_seed(seed, d))`. The table costs K·b entries per
//!   dimension (at most 4·7919); evaluation is incremental, O(1) amortised per coordinate.
//! - [`HaltonScramble::Owen`]: nested uniform scrambling (Owen 1995, "Randomly permuted
//!   (t,m,s)-nets and (t,s)-sequences"; pbrt-v4's `OwenScrambledRadicalInverse`): the
//!   permutation applied to digit k depends on the digits before it — it is the permutation of
//!   the node (k, a_1 … a_{k−1}) of the b-ary tree. The node's permutation is keyed by
//!   `derive_seed(derive_seed(derive_seed(seed, d), k − 1), p)` with p = a_1 + a_2 b + … +
//!   a_{k−1} b^{k−2} = i mod b^{k−1} (distinct for distinct nodes of a level), and evaluated
//!   without a table by [`node_permute`]. O(K) per coordinate: K hashes and K digit
//!   permutations (53 for base 2).
//!
//! **Node permutations** ([`node_permute`]). Base 2: the digit is flipped iff the key's top bit is
//! set. Bases ≤ 16: the key, read as a 64-bit fraction, is expanded in the mixed radix
//! (b, b−1, …, 2) (multiply-high digit extraction) to drive a Fisher–Yates shuffle, so every
//! permutation of 0..b has probability b!/2⁶⁴ ± 2⁻⁶⁴·b! — uniform to within 10⁻⁶ relative.
//! Larger bases: a keyed bijection of the w-bit integers (w = bits of b − 1: a 6-round
//! unbalanced Feistel network whose round functions are `splitmix64` of the round key and the
//! low half, round keys drawn from the node key by `splitmix64`) restricted to 0..b by cycle
//! walking (Black & Rogaway 2002, "Ciphers with arbitrary finite domains"; Kensler 2013,
//! "Correlated multi-jittered sampling", uses the same device): always a permutation (tested for
//! every key tried), terminating after at most 2^w − b + 1 < b steps, fewer than 2 on average.
//! Pairs (π(0), π(1)) pass a chi-square test against uniform over the b(b − 1) ordered pairs
//! (b = 17, 31, 61; measured up to 257). The tests use no other definition of "random
//! permutation", so this is a pseudo-random, not an exactly uniform, choice for b > 16.
//!
//! **Cost.** None and Permute: a few ns per point. Owen: K hashes per coordinate (86 per point
//! for bases 2 and 3), computed in parallel chunks of 4096 points (rayon; the output does not
//! depend on the thread count). Measured at opt-level 1 on 2 cores, N = 2²⁰: 0.36 s for bases
//! (2, 3), 0.8 s for (17, 19) (cycle-walked Feistel), 0.13 s for (7919, 7907); None and Permute
//! 6–16 ms. N = 2²⁴ costs 16× that.
//!
//! **Stratification.** Both scramblings map the first k digits of the index bijectively onto the
//! first k digits of the value (Permute: digit by digit; Owen: each digit through its node's
//! permutation), so every property of plain Halton stated on digit prefixes survives: any
//! b^k consecutive indices put one point in each interval [m/b^k, (m+1)/b^k) of their
//! coordinate, and any n = b_x^a·b_y^c consecutive indices put one point in each elementary box
//! b_x^−a × b_y^−c (Chinese remainder theorem on i mod b_x^a, i mod b_y^c). Rounding cannot move a
//! point out of its interval: R / b^K is at least 1/b^K ≥ 2⁻⁵³ below the next boundary, more than
//! half an ulp.
use super::radical_inverse::RadicalInverseIter;
use super::*;
use crate::core::rng::{derive_seed, splitmix64, Rng};
use rayon::prelude::*;

/// The pattern name errors start with (the Halton pattern, whose `scramble` this is).
pub const NAME: &str = "halton";

/// Scrambling of the Halton sequence's radical inverses.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum HaltonScramble {
    /// The plain sequence.
    #[default]
    None,
    /// One random permutation of the digits 0..b per digit position (and dimension).
    Permute,
    /// Nested uniform (Owen) scrambling: the permutation of a digit depends on the digits
    /// before it.
    Owen,
}

impl ChoiceParam for HaltonScramble {
    const OPTIONS: &'static [&'static str] = &["none", "permute", "owen"];
    fn index(self) -> usize {
        self as usize
    }
    fn from_index(index: usize) -> Self {
        [
            HaltonScramble::None,
            HaltonScramble::Permute,
            HaltonScramble::Owen,
        ][index]
    }
}

/// Scrambled Halton points x_j = (Φ^π_{bx}(i), Φ^π_{by}(i)), i = skip + j, j = 0..n (module
/// docs). `None` gives exactly [`halton`](super::lowdisc::halton); `Permute` and `Owen` are pure
/// functions of `(bases, skip, scramble, n, seed)`. Progressive.
///
/// Errors: `n` outside 1..=[`MAX_N`]; a base not a prime ≤ 7919; `base_x == base_y`
/// ([`PatternError::InvalidParam`] naming `halton.base_x` / `halton.base_y`).
pub fn scrambled_halton(
    base_x: u32,
    base_y: u32,
    skip: u32,
    scramble: HaltonScramble,
    n: usize,
    seed: u64,
) -> Result<Vec<DVec2>, PatternError> {
    scrambled_halton_with(base_x, base_y, skip, scramble, n, seed, &Cancel::never())
}

/// As [`scrambled_halton`], checking `cancel` every 4096 points.
pub fn scrambled_halton_with(
    base_x: u32,
    base_y: u32,
    skip: u32,
    scramble: HaltonScramble,
    n: usize,
    seed: u64,
    cancel: &Cancel,
) -> Result<Vec<DVec2>, PatternError> {
    check_n(n, MAX_N)?;
    // The same rule and wording as `lowdisc::halton`.
    let (bx, by) = super::lowdisc::check_halton_bases(NAME, base_x, base_y)?;
    let start = u64::from(skip);
    match scramble {
        HaltonScramble::None => fill(
            n,
            cancel,
            RadicalInverseIter::new(start, bx),
            RadicalInverseIter::new(start, by),
        ),
        HaltonScramble::Permute => fill(
            n,
            cancel,
            PermuteIter::new(start, DigitPermutations::random(bx, derive_seed(seed, 0))),
            PermuteIter::new(start, DigitPermutations::random(by, derive_seed(seed, 1))),
        ),
        HaltonScramble::Owen => owen_points(bx, by, start, n, seed, cancel),
    }
}

/// The `Permute` stream Φ^π_b(start), Φ^π_b(start + 1), … of one dimension whose
/// permutations are drawn from `Rng::new(seed)` (the d-dimensional Halton's, `cube::halton`,
/// with seed `derive_seed(seed, d)` as here).
pub(super) fn permuted_stream(start: u64, base: u32, seed: u64) -> impl Iterator<Item = f64> {
    PermuteIter::new(start, DigitPermutations::random(base, seed))
}

/// The `Owen` stream Φ^Owen_b(start), Φ^Owen_b(start + 1), … of one dimension with seed
/// `seed` (`derive_seed(seed, d)` for dimension d, as here).
pub(super) fn owen_stream(start: u64, base: u32, seed: u64) -> impl Iterator<Item = f64> {
    let mut it = OwenIter::new(start, base, seed);
    std::iter::from_fn(move || Some(it.value()))
}

/// Points per parallel chunk of [`owen_points`] (and per cancel check).
const OWEN_CHUNK: usize = 4096;

/// The Owen-scrambled points, in parallel chunks of [`OWEN_CHUNK`] indices (each chunk starts
/// its own [`OwenIter`] at its first index, so the output does not depend on the thread count).
fn owen_points(
    bx: u32,
    by: u32,
    start: u64,
    n: usize,
    seed: u64,
    cancel: &Cancel,
) -> Result<Vec<DVec2>, PatternError> {
    let (sx, sy) = (derive_seed(seed, 0), derive_seed(seed, 1));
    let mut out = vec![DVec2::ZERO; n];
    out.par_chunks_mut(OWEN_CHUNK)
        .enumerate()
        .try_for_each(|(c, chunk)| {
            cancel.check()?;
            let first = start + (c * OWEN_CHUNK) as u64;
            let mut x = OwenIter::new(first, bx, sx);
            let mut y = OwenIter::new(first, by, sy);
            for p in chunk.iter_mut() {
                *p = DVec2::new(x.value(), y.value());
            }
            Ok::<(), Cancelled>(())
        })?;
    Ok(out)
}

/// The first n pairs of the two coordinate streams as points, checking `cancel` every 4096.
fn fill(
    n: usize,
    cancel: &Cancel,
    x: impl Iterator<Item = f64>,
    y: impl Iterator<Item = f64>,
) -> Result<Vec<DVec2>, PatternError> {
    let mut out = Vec::with_capacity(n);
    for (j, (x, y)) in x.zip(y).take(n).enumerate() {
        if j % 4096 == 0 {
            cancel.check()?;
        }
        out.push(DVec2::new(x, y));
    }
    Ok(out)
}

/// K = the largest k with b^k ≤ 2⁵³, and b^K (b ≥ 2).
fn precision(b: u32) -> (usize, u64) {
    let b = u64::from(b);
    let mut k = 0;
    let mut pow = 1u64;
    while pow <= (1u64 << 53) / b {
        pow *= b;
        k += 1;
    }
    (k, pow)
}

/// The K base-b digits of an index, least significant first, with increment.
#[derive(Debug, Clone)]
struct Digits {
    base: u32,
    k: usize,
    d: [u32; 64],
}

impl Digits {
    fn new(mut index: u64, base: u32, k: usize) -> Self {
        let mut d = [0u32; 64];
        for digit in d.iter_mut().take(k) {
            *digit = (index % u64::from(base)) as u32;
            index /= u64::from(base);
        }
        debug_assert_eq!(index, 0, "index ≥ b^K");
        Digits { base, k, d }
    }
}

/// Per-dimension digit permutations: `table[k·b + v]` = π_{k+1}(v), k = 0..K.
#[derive(Debug, Clone)]
struct DigitPermutations {
    base: u32,
    k: usize,
    table: Vec<u32>,
}

impl DigitPermutations {
    /// K uniformly random permutations of 0..b, digit position 1 first, from `Rng::new(seed)`.
    fn random(base: u32, seed: u64) -> Self {
        let (k, _) = precision(base);
        let mut rng = Rng::new(seed);
        let mut table = Vec::with_capacity(k * base as usize);
        for _ in 0..k {
            table.extend(rng.permutation(base as usize).into_iter().map(|v| v as u32));
        }
        DigitPermutations { base, k, table }
    }

    #[inline]
    fn get(&self, position: usize, digit: u32) -> u64 {
        u64::from(self.table[position * self.base as usize + digit as usize])
    }
}

/// Φ^π_b(start), Φ^π_b(start + 1), … with per-position permutations, incremental: R is updated
/// only at the digits the increment changes (amortised 1 + 1/(b − 1) per index).
#[derive(Debug, Clone)]
struct PermuteIter {
    perms: DigitPermutations,
    digits: Digits,
    /// weights[k] = b^{K−1−k}.
    weights: [u64; 64],
    r: u64,
    denom: f64,
}

impl PermuteIter {
    fn new(start: u64, perms: DigitPermutations) -> Self {
        let k = perms.k;
        let pow = u64::from(perms.base).pow(k as u32);
        let digits = Digits::new(start, perms.base, k);
        let mut weights = [0u64; 64];
        let mut w = 1u64;
        for j in (0..k).rev() {
            weights[j] = w;
            w *= u64::from(perms.base);
        }
        let r = (0..k).map(|j| perms.get(j, digits.d[j]) * weights[j]).sum();
        PermuteIter {
            perms,
            digits,
            weights,
            r,
            denom: pow as f64,
        }
    }
}

impl PermuteIter {
    /// R of the current index (the value times b^K), then step to the next index.
    #[inline]
    fn next_numerator(&mut self) -> u64 {
        let value = self.r;
        let b = self.digits.base;
        for j in 0..self.digits.k {
            let old = self.digits.d[j];
            let new = if old + 1 == b { 0 } else { old + 1 };
            self.digits.d[j] = new;
            let w = self.weights[j];
            self.r = self.r + self.perms.get(j, new) * w - self.perms.get(j, old) * w;
            if new != 0 {
                break;
            }
        }
        value
    }
}

impl Iterator for PermuteIter {
    type Item = f64;

    #[inline]
    fn next(&mut self) -> Option<f64> {
        Some((self.next_numerator() as f64 / self.denom).min(ONE_MINUS_EPSILON))
    }
}

/// Φ^Owen_b(start), Φ^Owen_b(start + 1), …: per index, the K digits are passed through their
/// nodes' permutations, most significant output digit first.
#[derive(Debug, Clone)]
struct OwenIter {
    digits: Digits,
    /// level_seeds[k] = derive_seed(dimension seed, k): the seed of tree level k (digit k + 1).
    level_seeds: Vec<u64>,
    /// powers[k] = b^k.
    powers: [u64; 64],
    denom: f64,
}

impl OwenIter {
    fn new(start: u64, base: u32, seed: u64) -> Self {
        let (k, pow) = precision(base);
        let mut powers = [0u64; 64];
        let mut p = 1u64;
        for slot in powers.iter_mut().take(k) {
            *slot = p;
            p *= u64::from(base);
        }
        OwenIter {
            digits: Digits::new(start, base, k),
            level_seeds: (0..k as u64).map(|j| derive_seed(seed, j)).collect(),
            powers,
            denom: pow as f64,
        }
    }
}

impl OwenIter {
    /// R of the current index (the value times b^K), then step to the next index.
    #[inline]
    fn next_numerator(&mut self) -> u64 {
        let b = self.digits.base;
        let mut r = 0u64;
        let mut prefix = 0u64; // i mod b^k: the digits above digit k + 1
        for (k, &level_seed) in self.level_seeds.iter().enumerate() {
            let a = self.digits.d[k];
            let key = derive_seed(level_seed, prefix);
            r = r * u64::from(b) + u64::from(node_permute(a, b, key));
            prefix += u64::from(a) * self.powers[k];
        }
        for j in 0..self.digits.k {
            self.digits.d[j] += 1;
            if self.digits.d[j] < b {
                break;
            }
            self.digits.d[j] = 0;
        }
        r
    }
}

impl OwenIter {
    /// The value of the current index, then step to the next index.
    #[inline]
    fn value(&mut self) -> f64 {
        (self.next_numerator() as f64 / self.denom).min(ONE_MINUS_EPSILON)
    }
}

/// The largest base whose node permutations are drawn by the exact mixed-radix Fisher–Yates
/// shuffle (16! < 2⁴⁵, so the 64-bit key covers every permutation almost uniformly).
const MAX_SHUFFLE_BASE: u32 = 16;

/// π_key(v): the image of digit `v` under the pseudo-random permutation of 0..b selected by
/// `key` (module docs, "Node permutations"). `v < b`, `b ≥ 2`.
pub fn node_permute(v: u32, b: u32, key: u64) -> u32 {
    debug_assert!(v < b && b >= 2);
    if b == 2 {
        return v ^ (key >> 63) as u32;
    }
    if b <= MAX_SHUFFLE_BASE {
        return shuffle_permute(v, b, key);
    }
    let w = 32 - (b - 1).leading_zeros();
    let mut round_keys = [0u64; FEISTEL_ROUNDS];
    let mut state = key;
    for k in round_keys.iter_mut() {
        *k = splitmix64(&mut state);
    }
    let mut x = v;
    loop {
        x = keyed_bijection(x, w, &round_keys);
        if x < b {
            return x;
        }
    }
}

/// Fisher–Yates on 0..b (b ≤ 16) with the swap targets j_m ∈ 0..=m, m = b−1 … 1, taken as the
/// mixed-radix digits of the fraction key/2⁶⁴ (j = ⌊key·(m+1)/2⁶⁴⌋, key ← key·(m+1) mod 2⁶⁴),
/// then the image of `v`.
#[inline]
fn shuffle_permute(v: u32, b: u32, mut key: u64) -> u32 {
    let mut a = [0u8; MAX_SHUFFLE_BASE as usize];
    for (i, slot) in a.iter_mut().enumerate().take(b as usize) {
        *slot = i as u8;
    }
    for m in (1..b as usize).rev() {
        let wide = u128::from(key) * (m as u128 + 1);
        let j = (wide >> 64) as usize;
        key = wide as u64;
        a.swap(m, j);
    }
    u32::from(a[v as usize])
}

/// Rounds of [`keyed_bijection`].
const FEISTEL_ROUNDS: usize = 6;

/// A bijection of 0..2^w (w ≥ 2) keyed by six round keys: an unbalanced Feistel network. The w
/// bits are split into a low part of `a` bits and a high part of w − a bits; round r XORs the
/// high part with F_r(low) = the top bits of `splitmix64(k_r ⊕ low)` and swaps the parts (so `a`
/// alternates between ⌊w/2⌋ and ⌈w/2⌉). Any round function gives a bijection; 6 rounds of a
/// hashed one make the permutation statistically close to uniform (tested on pairs of images).
#[inline]
fn keyed_bijection(mut x: u32, w: u32, round_keys: &[u64; FEISTEL_ROUNDS]) -> u32 {
    let mut a = w / 2;
    for &round_key in round_keys {
        let hi_bits = w - a;
        let low = x & ((1u32 << a) - 1);
        let high = x >> a;
        let mut state = round_key ^ u64::from(low);
        let f = (splitmix64(&mut state) >> (64 - hi_bits)) as u32;
        x = (low << hi_bits) | (high ^ f);
        a = hi_bits;
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::pattern::lowdisc::halton;
    use crate::core::pattern::Halton;

    const BASES: [(u32, u32); 4] = [(2, 3), (3, 2), (5, 7), (7, 5)];

    fn bits(p: &[DVec2]) -> Vec<(u64, u64)> {
        p.iter().map(|p| (p.x.to_bits(), p.y.to_bits())).collect()
    }

    /// Index of the interval [m/q, (m+1)/q) holding x, with the boundaries as the correctly
    /// rounded f64 of m/q (the only representable boundaries): the number of them ≤ x.
    fn interval(x: f64, q: u64) -> u64 {
        let (mut lo, mut hi) = (0u64, q); // boundary lo ≤ x < boundary hi (m = 0 is 0.0)
        while hi - lo > 1 {
            let mid = (lo + hi) / 2;
            if mid as f64 / q as f64 <= x {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        lo
    }

    #[test]
    fn none_is_exactly_halton() {
        for (bx, by) in [(2, 3), (3, 5), (7919, 7907), (11, 2)] {
            for skip in [0u32, 1, 1000, u32::MAX - 5000] {
                let want = halton(
                    &Halton {
                        base_x: bx,
                        base_y: by,
                        skip,
                        ..Halton::default()
                    },
                    5000,
                )
                .unwrap();
                let got = scrambled_halton(bx, by, skip, HaltonScramble::None, 5000, 9).unwrap();
                assert_eq!(bits(&got), bits(&want), "bases {bx},{by} skip {skip}");
            }
        }
    }

    #[test]
    fn identity_permutations_reproduce_the_radical_inverse() {
        for b in [2u32, 3, 5, 7919] {
            let (k, _) = precision(b);
            let ident = DigitPermutations {
                base: b,
                k,
                table: (0..k).flat_map(|_| 0..b).collect(),
            };
            for start in [0u64, 12345, u64::from(u32::MAX)] {
                let a: Vec<u64> = PermuteIter::new(start, ident.clone())
                    .take(3000)
                    .map(f64::to_bits)
                    .collect();
                let want: Vec<u64> = RadicalInverseIter::new(start, b)
                    .take(3000)
                    .map(f64::to_bits)
                    .collect();
                assert_eq!(a, want, "b={b} start={start}");
            }
        }
    }

    /// Digit-by-digit reference for `Permute`: digits by division, R summed in u128.
    fn permute_reference(i: u64, perms: &DigitPermutations) -> f64 {
        let b = u64::from(perms.base);
        let mut rest = i;
        let mut r: u128 = 0;
        let mut denom: u128 = 1;
        for k in 0..perms.k {
            let a = (rest % b) as u32;
            rest /= b;
            r = r * u128::from(b) + u128::from(perms.get(k, a));
            denom *= u128::from(b);
        }
        (r as f64 / denom as f64).min(ONE_MINUS_EPSILON)
    }

    #[test]
    fn permute_incremental_matches_digit_by_digit_reference() {
        for b in [2u32, 3, 13, 7919] {
            let perms = DigitPermutations::random(b, derive_seed(4, u64::from(b)));
            for start in [0u64, 999, u64::from(u32::MAX) - 10] {
                for (j, x) in PermuteIter::new(start, perms.clone())
                    .take(2000)
                    .enumerate()
                {
                    let i = start + j as u64;
                    let want = permute_reference(i, &perms);
                    assert_eq!(x.to_bits(), want.to_bits(), "b={b} i={i}");
                }
            }
        }
    }

    #[test]
    fn digit_permutations_are_permutations() {
        for b in [2u32, 3, 5, 7, 11, 101, 7919] {
            let p = DigitPermutations::random(b, 77);
            assert_eq!(p.table.len(), p.k * b as usize);
            for k in 0..p.k {
                let mut row: Vec<u32> = (0..b).map(|v| p.get(k, v) as u32).collect();
                row.sort_unstable();
                assert!(row.iter().copied().eq(0..b), "b={b} position {k}");
            }
        }
        // Node permutations: every key gives a bijection of 0..b.
        let mut rng = Rng::new(5);
        for b in [2u32, 3, 5, 7, 11, 13, 16, 17, 31, 127, 257, 1009, 7919] {
            for _ in 0..if b > 1000 { 20 } else { 200 } {
                let key = rng.next_u64();
                let mut img: Vec<u32> = (0..b).map(|v| node_permute(v, b, key)).collect();
                img.sort_unstable();
                assert!(img.iter().copied().eq(0..b), "b={b} key={key:#x}");
            }
        }
    }

    /// Tree-walk reference for `Owen`: the index's digits by division; for each level k the node
    /// is named by its prefix digits a_1 … a_{k−1}, its whole permutation table is drawn
    /// explicitly from the node hash and checked to be a permutation, then applied to a_k;
    /// R is summed in u128.
    fn owen_reference(i: u64, b: u32, dim_seed: u64) -> f64 {
        let (k_max, _) = precision(b);
        let mut digits = Vec::new();
        let mut rest = i;
        for _ in 0..k_max {
            digits.push((rest % u64::from(b)) as u32);
            rest /= u64::from(b);
        }
        let mut r: u128 = 0;
        let mut denom: u128 = 1;
        for k in 0..k_max {
            // The node: level k, prefix a_1 … a_k (0-based digits 0..k) as the integer Σ a_j b^j.
            let prefix = digits[..k]
                .iter()
                .rev()
                .fold(0u64, |acc, &a| acc * u64::from(b) + u64::from(a));
            let node_key = derive_seed(derive_seed(dim_seed, k as u64), prefix);
            let table: Vec<u32> = (0..b).map(|v| node_permute(v, b, node_key)).collect();
            let mut sorted = table.clone();
            sorted.sort_unstable();
            assert!(sorted.iter().copied().eq(0..b));
            r = r * u128::from(b) + u128::from(table[digits[k] as usize]);
            denom *= u128::from(b);
        }
        (r as f64 / denom as f64).min(ONE_MINUS_EPSILON)
    }

    #[test]
    fn owen_fast_path_matches_tree_walk_reference_bit_for_bit() {
        for b in [2u32, 3, 5, 7, 17, 7919] {
            let seed = derive_seed(123, u64::from(b));
            for start in [0u64, 4321, u64::from(u32::MAX) - 3] {
                let count = if b > 1000 { 50 } else { 400 };
                let mut it = OwenIter::new(start, b, seed);
                for j in 0..count {
                    let x = it.value();
                    let i = start + j as u64;
                    assert_eq!(
                        x.to_bits(),
                        owen_reference(i, b, seed).to_bits(),
                        "b={b} i={i}"
                    );
                }
            }
        }
    }

    #[test]
    fn scrambles_stratify_each_coordinate() {
        for scramble in [HaltonScramble::Permute, HaltonScramble::Owen] {
            for (bx, by) in BASES {
                for skip in [0u32, 17] {
                    for k in 1..=3u32 {
                        for (b, coord) in [(bx, 0usize), (by, 1)] {
                            let q = u64::from(b).pow(k);
                            let pts =
                                scrambled_halton(bx, by, skip, scramble, q as usize, 3).unwrap();
                            let mut seen = vec![false; q as usize];
                            for p in &pts {
                                let v = if coord == 0 { p.x } else { p.y };
                                let m = interval(v, q) as usize;
                                assert!(!seen[m], "{scramble:?} b={b} k={k} skip={skip}: twice");
                                seen[m] = true;
                            }
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn scrambles_keep_the_halton_elementary_boxes() {
        // n = bx^a · by^c consecutive indices: one point per box bx^−a × by^−c.
        for scramble in [
            HaltonScramble::None,
            HaltonScramble::Permute,
            HaltonScramble::Owen,
        ] {
            for (bx, by, a, c) in [
                (2u32, 3u32, 3u32, 2u32),
                (2, 3, 5, 3),
                (3, 2, 2, 4),
                (5, 7, 2, 1),
                (7, 5, 1, 2),
            ] {
                let (qx, qy) = (u64::from(bx).pow(a), u64::from(by).pow(c));
                let n = (qx * qy) as usize;
                for skip in [0u32, 1000] {
                    let pts = scrambled_halton(bx, by, skip, scramble, n, 8).unwrap();
                    let mut seen = vec![false; n];
                    for p in &pts {
                        let cell = (interval(p.x, qx) * qy + interval(p.y, qy)) as usize;
                        assert!(!seen[cell], "{scramble:?} {bx}^{a}×{by}^{c} skip {skip}");
                        seen[cell] = true;
                    }
                }
            }
        }
    }

    #[test]
    fn scrambling_is_deterministic_and_seed_sensitive() {
        for scramble in [HaltonScramble::Permute, HaltonScramble::Owen] {
            let a = scrambled_halton(2, 3, 0, scramble, 1000, 1).unwrap();
            let b = scrambled_halton(2, 3, 0, scramble, 1000, 1).unwrap();
            let c = scrambled_halton(2, 3, 0, scramble, 1000, 2).unwrap();
            assert_eq!(bits(&a), bits(&b));
            let same = a.iter().zip(&c).filter(|(p, q)| p == q).count();
            assert!(
                same <= 5,
                "{scramble:?}: {same} of 1000 points unchanged by the seed"
            );
            let plain = scrambled_halton(2, 3, 0, HaltonScramble::None, 1000, 1).unwrap();
            assert_ne!(bits(&a), bits(&plain));
            assert!(a
                .iter()
                .all(|p| (0.0..1.0).contains(&p.x) && (0.0..1.0).contains(&p.y)));
            // Progressive and consistent with skip: a prefix, and a shifted window.
            let short = scrambled_halton(2, 3, 0, scramble, 100, 1).unwrap();
            assert_eq!(bits(&short), bits(&a[..100]));
            let shifted = scrambled_halton(2, 3, 10, scramble, 90, 1).unwrap();
            assert_eq!(bits(&shifted), bits(&a[10..100]));
        }
        // None ignores the seed.
        let x = scrambled_halton(2, 3, 0, HaltonScramble::None, 50, 1).unwrap();
        let y = scrambled_halton(2, 3, 0, HaltonScramble::None, 50, 2).unwrap();
        assert_eq!(bits(&x), bits(&y));
    }

    #[test]
    fn owen_is_nested_and_permute_is_not() {
        // Owen: indices with the same first k digits share the first k output digits, and the
        // output digit k+1 differs when the input digit k+1 does. Read on R = value·b^K.
        let b = 3u32;
        let (k_max, _) = precision(b);
        let digit =
            |r: u64, k: usize| (r / u64::from(b).pow((k_max - 1 - k) as u32)) % u64::from(b);
        let mut it = OwenIter::new(0, b, 99);
        let xs: Vec<u64> = (0..729).map(|_| it.next_numerator()).collect();
        for i in 0..729usize {
            for j in i + 1..729 {
                let mut shared = 0; // number of equal low-order index digits
                let (mut x, mut y) = (i, j);
                while x % 3 == y % 3 {
                    shared += 1;
                    x /= 3;
                    y /= 3;
                }
                for k in 0..shared {
                    assert_eq!(digit(xs[i], k), digit(xs[j], k), "i={i} j={j} k={k}");
                }
                assert_ne!(digit(xs[i], shared), digit(xs[j], shared), "i={i} j={j}");
            }
        }
        // Owen's digit-2 permutation varies with digit 1; Permute's does not. Over 200 seeds,
        // count seeds where indices 0 and 1 (digit 1 differs, digit 2 = 0) map digit 2 alike.
        let mut owen_differ = 0;
        for s in 0..200u64 {
            let mut o = OwenIter::new(0, b, s);
            let v = [o.next_numerator(), o.next_numerator()];
            owen_differ += (digit(v[0], 1) != digit(v[1], 1)) as u32;
            let mut q = PermuteIter::new(0, DigitPermutations::random(b, s));
            let p = [q.next_numerator(), q.next_numerator()];
            assert_eq!(
                digit(p[0], 1),
                digit(p[1], 1),
                "permute: digit 2 depends on digit 1"
            );
        }
        // Independent nodes: P(differ) = 2/3, σ = 0.033 over 200 seeds.
        assert!(
            (100..=165).contains(&owen_differ),
            "owen_differ = {owen_differ}"
        );
    }

    #[test]
    fn node_permutations_are_uniform() {
        // b = 3 and 5: every one of the b! permutations, chi-square against uniform.
        // 99.9 % quantiles: 20.5 (5 dof), 173.6 (119 dof).
        for (b, trials, limit) in [(3u32, 60_000u64, 20.5), (5, 120_000, 173.6)] {
            let mut counts = std::collections::HashMap::new();
            for t in 0..trials {
                let key = derive_seed(2024, t);
                let perm: Vec<u32> = (0..b).map(|v| node_permute(v, b, key)).collect();
                *counts.entry(perm).or_insert(0u64) += 1;
            }
            let cells: u64 = (1..=u64::from(b)).product();
            assert_eq!(
                counts.len() as u64,
                cells,
                "b={b}: not every permutation occurs"
            );
            let e = trials as f64 / cells as f64;
            let chi: f64 = counts.values().map(|&c| (c as f64 - e).powi(2) / e).sum();
            assert!(chi < limit, "b={b}: chi-square {chi}");
        }
        // Larger bases (cycle-walked bijection for b > 16): the pair (π(0), π(1)) over all
        // b(b−1) ordered pairs of distinct values, chi-square; 99.9 % quantiles by the
        // Wilson–Hilferty approximation, computed below.
        for b in [17u32, 31, 61] {
            let cells = u64::from(b * (b - 1));
            let trials = 50 * cells;
            let mut counts = vec![0u64; (b * b) as usize];
            for t in 0..trials {
                let key = derive_seed(7, t);
                let (p0, p1) = (node_permute(0, b, key), node_permute(1, b, key));
                counts[(p0 * b + p1) as usize] += 1;
            }
            let e = trials as f64 / cells as f64;
            let chi: f64 = (0..b * b)
                .filter(|c| c / b != c % b)
                .map(|c| (counts[c as usize] as f64 - e).powi(2) / e)
                .sum();
            let dof = cells as f64 - 1.0;
            let z = 3.09; // 99.9 %
            let q = dof * (1.0 - 2.0 / (9.0 * dof) + z * (2.0 / (9.0 * dof)).sqrt()).powi(3);
            assert!(chi < q, "b={b}: chi-square {chi} ≥ {q}");
        }
    }

    #[test]
    fn rejects_bad_bases_and_n() {
        let e = scrambled_halton(4, 3, 0, HaltonScramble::Owen, 10, 0).unwrap_err();
        assert!(e.to_string().contains("halton.base_x = 4"), "{e}");
        let e = scrambled_halton(2, 7927, 0, HaltonScramble::Permute, 10, 0).unwrap_err();
        assert!(e.to_string().contains("halton.base_y"), "{e}");
        let e = scrambled_halton(5, 5, 0, HaltonScramble::Owen, 10, 0).unwrap_err();
        let want = halton(
            &Halton {
                base_x: 5,
                base_y: 5,
                ..Halton::default()
            },
            10,
        )
        .unwrap_err();
        assert_eq!(e, want, "same error as halton");
        assert!(scrambled_halton(2, 3, 0, HaltonScramble::None, 0, 0).is_err());
        assert!(scrambled_halton(2, 3, 0, HaltonScramble::Owen, MAX_N + 1, 0).is_err());
        let c = Cancel::new();
        c.cancel();
        assert_eq!(
            scrambled_halton_with(2, 3, 0, HaltonScramble::Owen, 10, 0, &c),
            Err(PatternError::Cancelled)
        );
    }

    #[test]
    fn choice_param_names_round_trip() {
        for (i, name) in HaltonScramble::OPTIONS.iter().enumerate() {
            let s = HaltonScramble::from_index(i);
            assert_eq!(s.name(), *name);
            assert_eq!(HaltonScramble::from_name(name), Some(s));
            let json = serde_json::to_string(&s).unwrap();
            assert_eq!(json, format!("\"{name}\""));
        }
        assert_eq!(HaltonScramble::default(), HaltonScramble::None);
    }
}
