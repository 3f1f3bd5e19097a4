//! Radical inverse, folded radical inverse, and the primes used as their bases.
//!
//! ## Conventions
//!
//! An integer `n ≥ 0` written in base `b` has digits `a_1, a_2, …` (least significant first):
//! `n = a_1 b⁰ + a_2 b¹ + a_3 b² + …`. Its **radical inverse** mirrors the digits about the
//! radix point (the lecture's "Pseudo-Random Sequences" slide):
//!
//! Φ_b(n) = 0.a_1 a_2 a_3 … (base b) = Σ_{i≥1} a_i b^{−i}.
//!
//! The **folded radical inverse** (Hammersley–Zaremba / Halton–Zaremba; Kollig & Keller,
//! "Efficient multidimensional sampling", Eurographics 2002) offsets digit i by i − 1 before
//! mirroring, and — because the digits beyond the length of `n` are zeros that are offset too —
//! is an infinite series:
//!
//! Φ⁺_b(n) = Σ_{i≥1} ((a_i + i − 1) mod b) b^{−i}.
//!
//! Sequences are indexed from 0 (Φ_b(0) = 0). Every value is clamped to at most
//! [`ONE_MINUS_EPSILON`] = 1 − 2⁻⁵³ so that no rounding can produce 1.0.
//!
//! Bases: any integer `b ≥ 2` works for the radical inverses themselves; the sequences in
//! [`super::lowdisc`] use the primes of [`PRIMES`] (the first 1000 primes, 2 ..= 7919).

use super::{PatternError, ONE_MINUS_EPSILON};

/// How many primes [`PRIMES`] holds.
pub const PRIME_COUNT: usize = 1000;

/// Sieve bound for [`PRIMES`]: the 1000th prime is below it. Checked at compile time: if the
/// bound were too small the constant evaluation of [`PRIMES`] would fail to compile.
const SIEVE_LIMIT: usize = 8000;

/// The first [`PRIME_COUNT`] primes, ascending: `PRIMES[0] = 2`, …, `PRIMES[999] = 7919`.
///
/// Computed at compile time by a sieve of Eratosthenes (`first_primes`), not typed in.
pub const PRIMES: [u32; PRIME_COUNT] = first_primes();

/// The largest base the sequences accept: the 1000th prime, 7919.
pub const MAX_PRIME_BASE: u32 = PRIMES[PRIME_COUNT - 1];

/// Sieve of Eratosthenes on `0..SIEVE_LIMIT`, evaluated at compile time, returning the first
/// [`PRIME_COUNT`] primes. Fails to compile (const-evaluation error) if the sieve bound is too small.
const fn first_primes() -> [u32; PRIME_COUNT] {
    let mut composite = [false; SIEVE_LIMIT];
    let mut p = 2;
    while p * p < SIEVE_LIMIT {
        if !composite[p] {
            let mut m = p * p;
            while m < SIEVE_LIMIT {
                composite[m] = true;
                m += p;
            }
        }
        p += 1;
    }
    let mut out = [0u32; PRIME_COUNT];
    let mut count = 0;
    let mut k = 2;
    while k < SIEVE_LIMIT && count < PRIME_COUNT {
        if !composite[k] {
            out[count] = k as u32;
            count += 1;
        }
        k += 1;
    }
    assert!(
        count == PRIME_COUNT,
        "SIEVE_LIMIT too small for PRIME_COUNT primes"
    );
    out
}

/// `a · b mod m` without overflow (u128 intermediate).
#[inline]
fn mul_mod(a: u64, b: u64, m: u64) -> u64 {
    ((a as u128 * b as u128) % m as u128) as u64
}

/// `a^e mod m` by square-and-multiply.
fn pow_mod(mut a: u64, mut e: u64, m: u64) -> u64 {
    let mut r = 1 % m;
    a %= m;
    while e > 0 {
        if e & 1 == 1 {
            r = mul_mod(r, a, m);
        }
        a = mul_mod(a, a, m);
        e >>= 1;
    }
    r
}

/// Whether `n` is prime, for every `u64`.
///
/// Trial division by the primes up to 37, then the deterministic Miller–Rabin test with the
/// witnesses {2, 3, 5, …, 37}, which is exact for all n < 3.3·10²⁴ ⊃ u64 (Sorenson & Webster 2015,
/// "Strong pseudoprimes to twelve prime bases", Math. Comp. 86).
pub fn is_prime(n: u64) -> bool {
    const WITNESSES: [u64; 12] = [2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37];
    if n < 2 {
        return false;
    }
    for &p in &WITNESSES {
        if n % p == 0 {
            return n == p;
        }
    }
    // n odd, > 37: n − 1 = d · 2^s with d odd.
    let s = (n - 1).trailing_zeros();
    let d = (n - 1) >> s;
    'witness: for &a in &WITNESSES {
        let mut x = pow_mod(a, d, n);
        if x == 1 || x == n - 1 {
            continue;
        }
        for _ in 1..s {
            x = mul_mod(x, x, n);
            if x == n - 1 {
                continue 'witness;
            }
        }
        return false;
    }
    true
}

/// Position of the prime `p` in [`PRIMES`] (`prime_index(2) = Some(0)`, `prime_index(7919) =
/// Some(999)`); `None` if `p` is not one of the first 1000 primes.
pub fn prime_index(p: u32) -> Option<usize> {
    PRIMES.binary_search(&p).ok()
}

/// Φ₂(n): the base-2 radical inverse by bit reversal, `reverse_bits(n) · 2⁻⁶⁴`, correctly
/// rounded to f64 (one rounding, in the u64 → f64 conversion) and clamped below 1.
#[inline]
pub fn radical_inverse_base2(n: u64) -> f64 {
    ((n.reverse_bits() as f64) * TWO_POW_M64).min(ONE_MINUS_EPSILON)
}

/// 2⁻⁶⁴, exactly.
const TWO_POW_M64: f64 = 1.0 / 18_446_744_073_709_551_616.0;

/// The radical inverse Φ_b(n) = Σ_{i≥1} a_i b^{−i} of `n = Σ a_i b^{i−1}` (lecture, "Pseudo-Random
/// Sequences"; Halton 1960), in [0, 1 − 2⁻⁵³].
///
/// Method (after pbrt-v4 `RadicalInverse`, re-derived): the digits are reversed into an integer
/// accumulator `r = a_1 b^{k−1} + … + a_k` while `r < ⌊(2⁶⁴−1)/b⌋ − b`, the bound below which
/// `r·b + a` cannot overflow a `u64`. Then Φ_b(n) = (r + Φ_b(m)) / b^k, where `m = ⌊n / b^k⌋`
/// is what is left of `n` (at most about b, so one or two digits for the bases ≤ 7919 used here,
/// summed in f64) and b^k is kept exactly as a `u128` (b^k ≤ b·n < 2⁹⁶).
///
/// Indices below 2³² (all that the sequences use) take a 32-bit path: the same digits, with
/// 32-bit divisions and b^k ≤ b·n < 2⁶⁴ held in a `u64`.
///
/// Accuracy: when `r < 2⁵³` and `b^k ≤ 2⁵³` (e.g. every n < 3³³ in base 3) the result is the
/// correctly rounded value of the exact rational r / b^k (one rounding, in the division). In
/// general it is within 2 ulp. Base 2 takes the bit-reversal fast path
/// ([`radical_inverse_base2`]) and is always correctly rounded.
///
/// `base` must be ≥ 2 (checked only by `debug_assert!`; use [`try_radical_inverse`] for
/// unchecked input). Callers validate their bases once, up front.
#[inline]
pub fn radical_inverse(n: u64, base: u32) -> f64 {
    debug_assert!(base >= 2, "radical_inverse: base {base} < 2");
    if base == 2 {
        return radical_inverse_base2(n);
    }
    let b = u64::from(base.max(2));
    if let Ok(small) = u32::try_from(n) {
        // n < 2³²: 32-bit divisions, and b^k ≤ b·n < 2⁶⁴ fits a u64 (so does r < b^k).
        let mut rest = small;
        let mut reversed: u64 = 0;
        let mut denom: u64 = 1;
        while rest > 0 {
            let next = rest / base;
            reversed = reversed * b + u64::from(rest - next * base);
            denom *= b;
            rest = next;
        }
        return (reversed as f64 / denom as f64).min(ONE_MINUS_EPSILON);
    }
    let limit = u64::MAX / b - b;
    let mut rest = n;
    let mut reversed: u64 = 0;
    let mut denom: u128 = 1;
    while rest > 0 && reversed < limit {
        let next = rest / b;
        let digit = rest - next * b;
        reversed = reversed * b + digit;
        denom *= u128::from(b);
        rest = next;
    }
    let mut numer = reversed as f64;
    if rest > 0 {
        numer += radical_inverse_f64_sum(rest, b);
    }
    (numer / denom as f64).min(ONE_MINUS_EPSILON)
}

/// Φ_b(m) by direct f64 summation Σ a_i b^{−i}; used only for the few leftover digits.
fn radical_inverse_f64_sum(mut m: u64, b: u64) -> f64 {
    let inv = 1.0 / b as f64;
    let mut weight = inv;
    let mut sum = 0.0;
    while m > 0 {
        let next = m / b;
        sum += (m - next * b) as f64 * weight;
        weight *= inv;
        m = next;
    }
    sum
}

/// [`radical_inverse`] with the base checked: `base < 2` is an
/// [`PatternError::InvalidParam`] naming `radical-inverse.base`.
pub fn try_radical_inverse(n: u64, base: u32) -> Result<f64, PatternError> {
    check_base(base)?;
    Ok(radical_inverse(n, base))
}

/// The run Φ_b(start), Φ_b(start + 1), … of radical inverses, computed incrementally and
/// bit-identical to [`radical_inverse`] (the sequences' fast path).
///
/// With K = ⌊53 / log₂ b⌋ digits, so that b^K ≤ 2⁵³, every i < b^K has Φ_b(i) = R(i) / b^K with
/// the integer R(i) = Σ_{j=1}^{K} a_j b^{K−j} < 2⁵³. Adding 1 to i adds b^{K−1} to R and, for each
/// carry out of digit j, subtracts b·b^{K−j} and adds b^{K−j−1}: amortised 1 + 1/(b − 1) integer
/// steps per index, no division. R and b^K are exact in f64, so the quotient R / b^K is the
/// correctly rounded value — the same bits as [`radical_inverse`], whose numerator and
/// denominator are then also exact. Past b^K (never reached by the sequences' 33-bit indices) the
/// iterator calls [`radical_inverse`] for each index.
#[derive(Debug, Clone)]
pub struct RadicalInverseIter {
    base: u32,
    /// The next index to yield.
    next: u64,
    /// Digits a_1 … a_K of `next`, least significant first.
    digits: [u32; 64],
    /// weights[j] = b^{K−1−j}: the weight of digit a_{j+1} in R.
    weights: [u64; 64],
    /// K, the number of digits tracked.
    k: usize,
    /// R(next).
    r: u64,
    /// b^K as f64 (exact).
    denom: f64,
    /// `next` ≥ b^K: fall back to [`radical_inverse`].
    overflow: bool,
}

impl RadicalInverseIter {
    /// The run starting at Φ_b(start). `base` must be ≥ 2 (`debug_assert!`; callers validate).
    pub fn new(start: u64, base: u32) -> Self {
        debug_assert!(base >= 2, "RadicalInverseIter: base {base} < 2");
        let b = u64::from(base.max(2));
        let (k, pow) = digits_within_2_pow_53(b);
        let mut weights = [0u64; 64];
        let mut w = 1u64;
        for j in (0..k).rev() {
            weights[j] = w;
            w *= b;
        }
        let mut it = RadicalInverseIter {
            base,
            next: start,
            digits: [0; 64],
            weights,
            k,
            r: 0,
            denom: pow as f64,
            overflow: start >= pow,
        };
        let mut rest = start;
        for (digit, &w) in it.digits.iter_mut().zip(&weights).take(k) {
            let d = rest % b;
            *digit = d as u32;
            it.r += d * w;
            rest /= b;
        }
        it
    }
}

impl Iterator for RadicalInverseIter {
    type Item = f64;

    #[inline]
    fn next(&mut self) -> Option<f64> {
        let i = self.next;
        self.next = i.wrapping_add(1);
        if self.overflow {
            return Some(radical_inverse(i, self.base));
        }
        let value = (self.r as f64 / self.denom).min(ONE_MINUS_EPSILON);
        // Increment the digits of i (and R) to those of i + 1.
        let mut j = 0;
        loop {
            self.digits[j] += 1;
            self.r += self.weights[j];
            if self.digits[j] < self.base {
                break;
            }
            self.digits[j] = 0;
            self.r -= u64::from(self.base) * self.weights[j];
            j += 1;
            if j == self.k {
                self.overflow = true;
                break;
            }
        }
        Some(value)
    }
}

/// `base ≥ 2`, else an error naming the field.
fn check_base(base: u32) -> Result<(), PatternError> {
    if base < 2 {
        return Err(PatternError::InvalidParam {
            pattern: "radical-inverse",
            field: "base",
            value: base.to_string(),
            allowed: format!("an integer in 2..={}", u32::MAX),
        });
    }
    Ok(())
}

/// The folded radical inverse Φ⁺_b(n) = Σ_{i≥1} ((a_i + i − 1) mod b) b^{−i}, in [0, 1 − 2⁻⁵³]
/// (Hammersley–Zaremba; lecture slide "Folded Radical Inverse"; Kollig & Keller 2002). The digits
/// a_i of n beyond its length are 0, so the series goes on with the digits (i − 1) mod b: e.g.
/// Φ⁺₂(0) = 0.010101…₂ = 1/3 and Φ⁺₃(0) = 0.012012…₃ = 5/26.
///
/// **Stopping rule** (of the series summation `folded_series`): let z be the position of the
/// first non-zero folded digit (z ≤ len(n) + 2, because beyond n only every b-th digit is 0), so
/// Φ⁺ ≥ b^{−z}. Digits are summed up to position L, the first with b^{L−z} ≥ 2⁶⁰. The omitted
/// tail is < b^{−L} ≤ 2⁻⁶⁰·Φ⁺, under 1/128 of an ulp: no further digit can change the f64 (up to
/// the rounding of the digits summed). For base 2 that is 60 digits past z; for base 7919, 6.
///
/// **Method.** With K = ⌊53 / log₂ b⌋ (so b^K ≤ 2⁵³), an index n < b^K has no digits beyond K, so
/// Φ⁺_b(n) = (F(n) + C) / b^K, where F(n) = Σ_{i=1}^{K} ((a_i + i − 1) mod b) b^{K−i} is an exact
/// integer < 2⁵³ and C = Σ_{m≥1} ((K + m − 1) mod b) b^{−m} is the index-independent tail, summed
/// by `folded_series`. Larger n are summed by `folded_series` directly. Either way the result
/// is within 3 ulp of the exact series ([`FoldedRadicalInverseIter`] gives the same bits,
/// incrementally). Base 2 has a bit-level fast path: the first 64 folded digits are the bits of
/// n ⊕ 0xAAAA…AA (bit i−1 flipped when i − 1 is odd), the digits beyond are 0101…, worth 2⁻⁶⁴/3,
/// so Φ⁺₂(n) = (reverse_bits(n ⊕ 0xAA…A) + 1/3)·2⁻⁶⁴.
///
/// `base` must be ≥ 2 (`debug_assert!`; see [`try_folded_radical_inverse`]).
pub fn folded_radical_inverse(n: u64, base: u32) -> f64 {
    debug_assert!(base >= 2, "folded_radical_inverse: base {base} < 2");
    if base == 2 {
        let bits = (n ^ 0xAAAA_AAAA_AAAA_AAAA).reverse_bits();
        return ((bits as f64 + 1.0 / 3.0) * TWO_POW_M64).min(ONE_MINUS_EPSILON);
    }
    let b = u64::from(base.max(2));
    let (k, pow) = digits_within_2_pow_53(b);
    if n >= pow {
        return folded_series(n, b, 0);
    }
    let mut rest = n;
    let mut folded: u64 = 0;
    let mut offset: u64 = 0;
    for _ in 0..k {
        let next = rest / b;
        let mut d = rest - next * b + offset;
        if d >= b {
            d -= b;
        }
        folded = folded * b + d;
        rest = next;
        offset += 1;
        if offset == b {
            offset = 0;
        }
    }
    folded_from_parts(folded, folded_series(0, b, k as u64 % b), pow)
}

/// (F + C) / b^K, clamped below 1: the common last step of [`folded_radical_inverse`] and
/// [`FoldedRadicalInverseIter`] (same expression, same bits).
#[inline]
fn folded_from_parts(folded: u64, tail: f64, pow: u64) -> f64 {
    ((folded as f64 + tail) / pow as f64).min(ONE_MINUS_EPSILON)
}

/// K = the largest k with b^k ≤ 2⁵³, and b^K (b ≥ 2; K ≥ 1 for b ≤ 2³²).
fn digits_within_2_pow_53(b: u64) -> (usize, u64) {
    let mut k = 0;
    let mut pow: u64 = 1;
    while pow <= (1u64 << 53) / b {
        pow *= b;
        k += 1;
    }
    (k, pow)
}

/// The series Σ_{i≥1} ((a_i + r + i − 1) mod b) b^{−i} (digits a_i of n, then 0), with the
/// stopping rule of [`folded_radical_inverse`]: r = 0 gives Φ⁺_b(n); n = 0 gives the tail C_b(r).
/// The folded digits from the first non-zero one (position z) to position L are accumulated
/// exactly as an integer F (Horner, u128: F < b^{L−z+1} < 2⁶⁰·b²), so the sum is
/// F / b^{L−z+1} / b^{z−1} with both powers exact in u128 (b^{z−1} ≤ b^{len(n)+1} < 2⁹⁰).
fn folded_series(n: u64, b: u64, r: u64) -> f64 {
    let b128 = u128::from(b);
    // The significant part must reach b^(L−z) ≥ 2^60, i.e. b^(L−z+1) ≥ 2^60 · b.
    let enough: u128 = (1u128 << 60) * b128;
    let mut rest = n;
    let mut offset: u64 = r % b; // (r + i − 1) mod b for the current position i
    let mut lead: u128 = 1; // b^(z−1): one factor per leading zero digit
    let mut folded: u128 = 0; // F
    let mut scale: u128 = 1; // b^(number of digits in F)
    while scale < enough {
        let next = rest / b;
        let a = rest - next * b;
        rest = next;
        let mut d = a + offset;
        if d >= b {
            d -= b;
        }
        offset += 1;
        if offset == b {
            offset = 0;
        }
        if folded == 0 && d == 0 {
            lead *= b128;
        } else {
            folded = folded * b128 + u128::from(d);
            scale *= b128;
        }
    }
    ((folded as f64 / scale as f64) / lead as f64).min(ONE_MINUS_EPSILON)
}

/// The run Φ⁺_b(start), Φ⁺_b(start + 1), … of folded radical inverses, computed incrementally
/// and bit-identical to [`folded_radical_inverse`].
///
/// Keeps the K digits a_i of the index and the integer F = Σ_{i=1}^{K} ((a_i + i − 1) mod b)
/// b^{K−i} (see [`folded_radical_inverse`]). Adding 1 to the index increments every digit of the
/// carry chain by 1 mod b, and so each of their folded digits: F changes by +b^{K−i}, or by
/// −(b − 1)·b^{K−i} where the folded digit wraps from b − 1 to 0. The tail C is computed once.
/// Base 2, and indices ≥ b^K, use [`folded_radical_inverse`] per index.
#[derive(Debug, Clone)]
pub struct FoldedRadicalInverseIter {
    base: u32,
    next: u64,
    /// Digits a_1 … a_K of `next`, least significant first.
    digits: [u32; 64],
    /// Folded digits (a_i + i − 1) mod b.
    folded_digits: [u32; 64],
    /// weights[j] = b^{K−1−j}.
    weights: [u64; 64],
    k: usize,
    /// F(next).
    folded: u64,
    /// The tail C.
    tail: f64,
    /// b^K.
    pow: u64,
    /// Per-index fallback (base 2, or `next` ≥ b^K).
    per_index: bool,
}

impl FoldedRadicalInverseIter {
    /// The run starting at Φ⁺_b(start). `base` must be ≥ 2 (`debug_assert!`; callers validate).
    pub fn new(start: u64, base: u32) -> Self {
        debug_assert!(base >= 2, "FoldedRadicalInverseIter: base {base} < 2");
        let b = u64::from(base.max(2));
        let (k, pow) = digits_within_2_pow_53(b);
        let mut it = FoldedRadicalInverseIter {
            base,
            next: start,
            digits: [0; 64],
            folded_digits: [0; 64],
            weights: [0; 64],
            k,
            folded: 0,
            tail: 0.0,
            pow,
            per_index: base == 2 || start >= pow,
        };
        if it.per_index {
            return it;
        }
        it.tail = folded_series(0, b, k as u64 % b);
        let mut w = 1u64;
        for j in (0..k).rev() {
            it.weights[j] = w;
            w *= b;
        }
        let mut rest = start;
        for j in 0..k {
            let a = rest % b;
            rest /= b;
            let f = (a + j as u64 % b) % b;
            it.digits[j] = a as u32;
            it.folded_digits[j] = f as u32;
            it.folded += f * it.weights[j];
        }
        it
    }
}

impl Iterator for FoldedRadicalInverseIter {
    type Item = f64;

    #[inline]
    fn next(&mut self) -> Option<f64> {
        let i = self.next;
        self.next = i.wrapping_add(1);
        if self.per_index {
            return Some(folded_radical_inverse(i, self.base));
        }
        let value = folded_from_parts(self.folded, self.tail, self.pow);
        let b = self.base;
        let mut j = 0;
        loop {
            let w = self.weights[j];
            if self.folded_digits[j] == b - 1 {
                self.folded_digits[j] = 0;
                self.folded -= u64::from(b - 1) * w;
            } else {
                self.folded_digits[j] += 1;
                self.folded += w;
            }
            self.digits[j] += 1;
            if self.digits[j] < b {
                break;
            }
            self.digits[j] = 0;
            j += 1;
            if j == self.k {
                self.per_index = true;
                break;
            }
        }
        Some(value)
    }
}

/// [`folded_radical_inverse`] with the base checked (`base < 2` is an error naming the field).
pub fn try_folded_radical_inverse(n: u64, base: u32) -> Result<f64, PatternError> {
    check_base(base)?;
    Ok(folded_radical_inverse(n, base))
}

/// The largest base [`radical_inverse_table`] accepts, so that every digit is one character
/// (`0-9a-z`).
pub const MAX_TABLE_BASE: u32 = 36;

/// The most rows [`radical_inverse_table`] builds.
pub const MAX_TABLE_ROWS: usize = 1 << 16;

/// One row of the lecture's van der Corput table: `i`, `i` written in base b, the mirrored digits
/// after the radix point, and the value Φ_b(i).
#[derive(Debug, Clone, PartialEq)]
pub struct RadicalInverseRow {
    /// The index i.
    pub i: u64,
    /// The digits of i in base b, most significant first, as written (`i = 0` is `[0]`).
    pub digits: Vec<u8>,
    /// The digits after the radix point of Φ_b(i): `digits` reversed (a_1 first).
    pub reversed: Vec<u8>,
    /// Φ_b(i) = [`radical_inverse`]`(i, b)`.
    pub value: f64,
}

impl RadicalInverseRow {
    /// The index in base b, e.g. `"110"` for i = 6, b = 2.
    pub fn digits_string(&self) -> String {
        format_digits(&self.digits)
    }

    /// The mirrored fraction in base b, e.g. `"0.011"` for i = 6, b = 2.
    pub fn reversed_string(&self) -> String {
        format!("0.{}", format_digits(&self.reversed))
    }
}

/// Writes base-b digits (each < 36) as text, one character per digit: `0-9` then `a-z`
/// (`[1, 0, 1]` → `"101"`, `[15, 0]` → `"f0"`). A digit ≥ 36, which no table row contains, is
/// written as `?`.
pub fn format_digits(digits: &[u8]) -> String {
    digits
        .iter()
        .map(|&d| char::from_digit(u32::from(d), 36).unwrap_or('?'))
        .collect()
}

/// The digits of `i` in base `b`, most significant first (`[0]` for 0).
fn digits_msb_first(mut i: u64, b: u64) -> Vec<u8> {
    let mut d = Vec::new();
    loop {
        // A digit is < b ≤ MAX_TABLE_BASE, so it fits in a u8.
        d.push((i % b) as u8);
        i /= b;
        if i == 0 {
            break;
        }
    }
    d.reverse();
    d
}

/// The lecture's van der Corput table for base `base` and `i = 0..count`: each row holds i, its
/// base-b digits, the mirrored digits `0.a_1 a_2 …` and Φ_b(i). For base 2 the first rows are
/// `0 | 0 | 0.0 | 0`, `1 | 1 | 0.1 | 0.5`, `2 | 10 | 0.01 | 0.25`, `3 | 11 | 0.11 | 0.75`, …
///
/// Errors: `base` outside `2..=36` (digits must be single characters) or `count` outside
/// `1..=65536`.
pub fn radical_inverse_table(
    base: u32,
    count: usize,
) -> Result<Vec<RadicalInverseRow>, PatternError> {
    if !(2..=MAX_TABLE_BASE).contains(&base) {
        return Err(PatternError::InvalidParam {
            pattern: "radical-inverse-table",
            field: "base",
            value: base.to_string(),
            allowed: format!("an integer in 2..={MAX_TABLE_BASE} (one character per digit)"),
        });
    }
    if count == 0 || count > MAX_TABLE_ROWS {
        return Err(PatternError::InvalidN {
            n: count,
            max: MAX_TABLE_ROWS,
            why: "; the number of table rows".to_string(),
        });
    }
    Ok((0..count as u64)
        .map(|i| {
            let digits = digits_msb_first(i, u64::from(base));
            let mut reversed = digits.clone();
            reversed.reverse();
            RadicalInverseRow {
                i,
                digits,
                reversed,
                value: radical_inverse(i, base),
            }
        })
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Naive trial division by every d in 2..n with d² ≤ n.
    fn trial_division(n: u64) -> bool {
        n >= 2 && (2..).take_while(|d| d * d <= n).all(|d| n % d != 0)
    }

    #[test]
    fn primes_match_trial_division_and_end_at_7919() {
        let naive: Vec<u32> = (2u64..)
            .filter(|&n| trial_division(n))
            .take(PRIME_COUNT)
            .map(|n| n as u32)
            .collect();
        assert_eq!(naive.as_slice(), PRIMES.as_slice());
        assert_eq!(PRIMES[0], 2);
        assert_eq!(PRIMES[999], 7919);
        assert_eq!(MAX_PRIME_BASE, 7919);
    }

    #[test]
    fn is_prime_matches_trial_division_below_100000() {
        for n in 0..100_000u64 {
            assert_eq!(is_prime(n), trial_division(n), "n = {n}");
        }
    }

    #[test]
    fn is_prime_edge_large_primes_and_strong_pseudoprimes() {
        // Known primes: the Mersenne prime 2^61 − 1 and the largest u64 prime 2^64 − 59.
        assert!(is_prime((1 << 61) - 1));
        assert!(is_prime(u64::MAX - 58));
        assert!(is_prime(4_294_967_291)); // largest prime below 2^32
                                          // Composites: Carmichael 561; 3215031751 is a strong pseudoprime to bases 2, 3, 5, 7;
                                          // 3825123056546413051 to bases 2..=23 (Sorenson–Webster); 2^64 − 1; a square of a prime.
        for c in [
            561u64,
            3_215_031_751,
            3_825_123_056_546_413_051,
            u64::MAX,
            4_294_967_291 * 3,
            65_521 * 65_521,
        ] {
            assert!(!is_prime(c), "{c} reported prime");
        }
    }

    #[test]
    fn prime_index_round_trips() {
        for (k, &p) in PRIMES.iter().enumerate() {
            assert_eq!(prime_index(p), Some(k));
        }
        assert_eq!(prime_index(4), None);
        assert_eq!(prime_index(7921), None); // 89², beyond the table anyway
        assert_eq!(prime_index(7927), None); // the 1001st prime
    }

    #[test]
    fn try_radical_inverse_base_below_2_is_an_error() {
        for base in [0, 1] {
            let e = try_radical_inverse(5, base).unwrap_err();
            assert!(e.to_string().contains("radical-inverse.base"), "{e}");
            assert!(try_folded_radical_inverse(5, base).is_err());
        }
        assert_eq!(try_radical_inverse(3, 2), Ok(0.75));
    }

    #[test]
    fn radical_inverse_huge_base_edge_matches_digit_sum() {
        // Bases far beyond the table, where the accumulator stops after a digit or two.
        for &b in &[65_537u32, 1 << 31, u32::MAX] {
            for &n in &[u64::MAX, 1 << 63, 123_456_789_012_345_678] {
                let got = radical_inverse(n, b);
                let want = radical_inverse_f64_sum(n, u64::from(b));
                assert!((got - want).abs() <= 1e-15 * want, "b={b} n={n}");
                assert!(got < 1.0);
            }
        }
    }

    #[test]
    fn folded_base2_fast_path_matches_general_path_and_digit_series() {
        // The bit-level fast path against the general loop run with b = 2, and against the
        // series summed digit by digit (200 digits, far past double precision). Tolerance 4 ulp.
        let mut rng = crate::core::rng::Rng::new(11);
        let fixed = [0u64, 1, 2, 5, 1000, u64::MAX, 0xAAAA_AAAA_AAAA_AAAA];
        let random: Vec<u64> = (0..200).map(|_| rng.next_u64() >> rng.below(64)).collect();
        for &n in fixed.iter().chain(&random) {
            let general = folded_series(n, 2, 0);
            let fast = folded_radical_inverse(n, 2);
            assert!((general - fast).abs() <= 4.0 * f64::EPSILON * fast, "n={n}");
            let mut sum = 0.0f64;
            let mut w = 0.5;
            for i in 1..=200u32 {
                let a = if i <= 64 { (n >> (i - 1)) & 1 } else { 0 };
                sum += ((a + u64::from(i - 1)) % 2) as f64 * w;
                w *= 0.5;
            }
            let got = folded_radical_inverse(n, 2);
            assert!((got - sum).abs() <= 4.0 * f64::EPSILON * sum, "n={n}");
        }
    }

    #[test]
    fn iterator_is_bit_identical_to_radical_inverse_across_digit_overflow_edge() {
        // Starts near 0, near a carry into a new digit, and just below b^K where the iterator
        // switches to the per-index fallback (K = 53, 33, 4 for b = 2, 3, 7919).
        let cases: [(u32, u64); 8] = [
            (2, 0),
            (2, (1 << 53) - 100),
            (3, 0),
            (3, 3u64.pow(33) - 100),
            (5, 5u64.pow(7) - 3),
            (7919, 0),
            (7919, 7919u64.pow(4) - 100),
            (7907, u64::from(u32::MAX) - 50),
        ];
        for (b, start) in cases {
            for (j, x) in RadicalInverseIter::new(start, b).take(300).enumerate() {
                let i = start + j as u64;
                assert_eq!(x.to_bits(), radical_inverse(i, b).to_bits(), "b={b} i={i}");
            }
        }
        let mut rng = crate::core::rng::Rng::new(8);
        for _ in 0..200 {
            let b = PRIMES[rng.below(PRIME_COUNT as u64) as usize];
            let start = rng.next_u64() >> rng.below(64);
            for (j, x) in RadicalInverseIter::new(start, b).take(20).enumerate() {
                let i = start.wrapping_add(j as u64);
                assert_eq!(x.to_bits(), radical_inverse(i, b).to_bits(), "b={b} i={i}");
            }
        }
    }

    #[test]
    fn folded_iterator_is_bit_identical_across_digit_overflow_edge() {
        // K = 33, 15, 4 for b = 3, 11, 7919: starts just below b^K cross into the fallback.
        let cases: [(u32, u64); 8] = [
            (2, 0),
            (3, 0),
            (3, 3u64.pow(33) - 100),
            (5, 5u64.pow(7) - 3),
            (11, 11u64.pow(15) - 100),
            (7919, 0),
            (7919, 7919u64.pow(4) - 100),
            (7907, u64::from(u32::MAX) - 50),
        ];
        for (b, start) in cases {
            for (j, x) in FoldedRadicalInverseIter::new(start, b)
                .take(300)
                .enumerate()
            {
                let i = start + j as u64;
                let want = folded_radical_inverse(i, b);
                assert_eq!(x.to_bits(), want.to_bits(), "b={b} i={i}");
            }
        }
        let mut rng = crate::core::rng::Rng::new(9);
        for _ in 0..200 {
            let b = PRIMES[rng.below(PRIME_COUNT as u64) as usize];
            let start = rng.next_u64() >> rng.below(64);
            for (j, x) in FoldedRadicalInverseIter::new(start, b).take(20).enumerate() {
                let i = start.wrapping_add(j as u64);
                let want = folded_radical_inverse(i, b);
                assert_eq!(x.to_bits(), want.to_bits(), "b={b} i={i}");
            }
        }
    }

    #[test]
    fn folded_split_form_agrees_with_direct_series() {
        // (F + C)/b^K against the series summed directly, for indices below b^K: within 3 ulp.
        let mut rng = crate::core::rng::Rng::new(10);
        for _ in 0..2000 {
            let b = PRIMES[1 + rng.below(PRIME_COUNT as u64 - 1) as usize];
            let (_, pow) = digits_within_2_pow_53(u64::from(b));
            let n = rng.below(pow) >> rng.below(50);
            let split = folded_radical_inverse(n, b);
            let direct = folded_series(n, u64::from(b), 0);
            let ulps = (split.to_bits() as i64 - direct.to_bits() as i64).unsigned_abs();
            assert!(ulps <= 3, "b={b} n={n}: {split} vs {direct}");
        }
    }

    #[test]
    fn format_digits_uses_alphanumerics() {
        assert_eq!(format_digits(&[1, 0, 1]), "101");
        assert_eq!(format_digits(&[15, 0, 35]), "f0z");
        assert_eq!(format_digits(&[36]), "?");
    }

    #[test]
    fn table_rejects_bad_base_and_count() {
        assert!(radical_inverse_table(1, 4).is_err());
        assert!(radical_inverse_table(37, 4).is_err());
        assert!(radical_inverse_table(2, 0).is_err());
        assert!(radical_inverse_table(2, MAX_TABLE_ROWS + 1).is_err());
        let t = radical_inverse_table(16, 256).unwrap();
        assert_eq!(t[255].digits_string(), "ff");
        assert_eq!(t[255].reversed_string(), "0.ff");
    }
}
