//! Rank-1 lattices (Fibonacci, Korobov) and the R2 Kronecker sequence.
//!
//! ## Rank-1 lattices
//!
//! A Korobov (rank-1) lattice of N points with generator g is x_i = (i/N, frac(i·g/N)),
//! i = 0..N (Korobov 1959; Sloan & Joe 1994, "Lattice Methods for Multiple Integration"). It is
//! the intersection of the unit torus with the lattice L spanned by (1/N, g/N) and (0, 1): the
//! set is closed under addition mod 1 (x_i + x_j ≡ x_{(i+j) mod N}). In integer units (times N)
//! L = {(a, b) ∈ ℤ² : b ≡ g·a (mod N)}, a lattice of determinant N.
//!
//! - [`fibonacci`]: N = F_k (a Fibonacci number), g = F_{k−1} (Niederreiter 1992, §5; the
//!   Fibonacci lattice of Zaremba 1966). Its points lie close to a hexagonal arrangement.
//! - [`rank1`]: any N ≥ 2 and g ∈ 1..N; g = 0 picks [`best_generator`].
//!
//! **Exactness.** The numerators i and i·g mod N are exact integers (updated by one addition
//! and one conditional subtraction per point, in u64), and each coordinate is the correctly
//! rounded quotient of two integers below 2²⁴ — the f64 nearest to the exact rational. With
//! `shift` (a Cranley–Patterson rotation, Cranley & Patterson 1976) a seeded uniform vector
//! u = (u_x, u_y) from [`Rng`]`::new(seed)` (u_x first) is added mod 1 in f64 (one rounding per
//! coordinate, plus the subtraction of 1, which is exact). Without `shift` the seed is unused.
//! Cost O(N), one allocation.
//!
//! **Minimum distance.** The minimum toroidal distance between two distinct lattice points is
//! the length of the shortest nonzero vector of L: every difference x_i − x_j is a lattice vector,
//! and the torus periods (integer vectors, length ≥ 1) are never shorter than (1, g − N)/N.
//! [`lattice_min_distance`] finds it by Lagrange–Gauss reduction of the basis (0, N), (1, g) in
//! exact integers (Lagrange 1773; Gauss 1801; see Nguyen & Vallée, "The LLL Algorithm", ch. 2):
//! O(log N) steps, each one rounded integer division.
//!
//! **Best generator.** [`best_generator`] searches g ∈ 1..=⌊N/2⌋ with gcd(g, N) = 1 (g and N − g
//! give mirror images, so the upper half is redundant; coprime g make both projections N-rooks
//! stratified, the usual rank-1 requirement — a non-coprime g can have a larger minimum distance,
//! e.g. N = 4, g = 2 gives 0.5 against 0.354 for g = 1, but its y coordinates take only
//! N / gcd(g, N) values). It maximises the exact integer squared length of the shortest vector,
//! smallest g on ties. Cost: N/2 gcds and reductions, O(N log N) in all — measured
//! (opt-level 1, one thread) 2.4 ms for N = 2¹⁶, 0.10 s for N = 2²⁰, 1.4 s for N = 2²⁴
//! ([`MAX_N`] = [`MAX_BEST_GENERATOR_N`], the documented bound); the search checks its cancel
//! token every 2¹⁶ generators ([`best_generator_with`], [`rank1_with`]).
//!
//! ## The R2 sequence
//!
//! [`kronecker`]: x_i = frac(s + i·α), α = (1/φ₂, 1/φ₂²), with φ₂ ≈ 1.3247 the plastic number,
//! the real root of x³ = x + 1 (M. Roberts 2018, "The unreasonable effectiveness of quasirandom
//! sequences"). It is the 2D analogue of the golden-ratio sequence; every prefix is well spread
//! (progressive), the default offset is s = (½, ½).
//!
//! φ₂ is found by Newton's method in f64 ([`plastic_number`]). For large i an f64 α is not
//! enough (an error of 2⁻⁵⁴ in α becomes 2⁻³⁰ at i = 2²⁴), so α is refined to a 128-bit
//! fixed-point fraction A (two Newton steps on a³ + a² = 1 in integer arithmetic, from the f64
//! value; α₂ = α₁²), the offset is truncated to 128 bits, and the point is the u128 sum
//! S + i·A mod 2¹²⁸ (exact modular arithmetic), converted once to f64.
//!
//! **Error bound.** |A/2¹²⁸ − α| ≤ 2⁻¹²⁵ per coordinate (the fixed-point residual is checked in
//! the tests), so the fixed-point value is within i·2⁻¹²⁵ + 2⁻¹²⁸ < 2⁻¹⁰⁰ of frac(s + i·α) for
//! i < 2²⁴; the conversion to f64 rounds to nearest. The output is therefore within half an ulp
//! (plus 2⁻¹⁰⁰) of the exact value, at most 2⁻⁵⁴ + 2⁻¹⁰⁰ absolute; a value that would round to
//! 1.0 is clamped to 1 − 2⁻⁵³. Cost O(N): one u128 addition and one conversion per coordinate.
use super::*;
use crate::core::rng::Rng;

/// Pattern name of [`fibonacci`] in errors.
pub const FIBONACCI_NAME: &str = "fibonacci";
/// Pattern name of [`rank1`] in errors.
pub const RANK1_NAME: &str = "rank1";
/// Pattern name of [`kronecker`] in errors.
pub const KRONECKER_NAME: &str = "kronecker";

/// The largest N for which [`rank1`] searches the best generator (g = 0): [`MAX_N`], where the
/// O(N log N) search takes about 1.4 s single-threaded (0.1 s at N = 2²⁰).
pub const MAX_BEST_GENERATOR_N: usize = MAX_N;

/// The default R2 offset s = (½, ½) (Roberts 2018).
pub const R2_DEFAULT_OFFSET: DVec2 = DVec2::new(0.5, 0.5);

/// The Fibonacci numbers F_2 = 1, F_3 = 2, F_4 = 3, … up to the first one above [`MAX_N`]
/// (F_37 = 24 157 817), ascending.
fn fibonacci_numbers() -> Vec<u64> {
    let mut f = vec![1u64, 2];
    while *f.last().unwrap_or(&0) <= MAX_N as u64 {
        let k = f.len();
        f.push(f[k - 1] + f[k - 2]);
    }
    f
}

/// `Some(F_{k−1})` if `n = F_k ≥ 2` (F_1 = F_2 = 1), else `None`.
pub fn fibonacci_predecessor(n: usize) -> Option<usize> {
    let f = fibonacci_numbers();
    let k = f.iter().position(|&x| x == n as u64)?;
    if k == 0 {
        None
    } else {
        Some(f[k - 1] as usize)
    }
}

/// The Fibonacci lattice x_i = (i/F_k, frac(i·F_{k−1}/F_k)), i = 0..F_k, n = F_k ≥ 2 (see the
/// module docs); with `shift`, Cranley–Patterson rotated by a uniform vector drawn from `seed`.
///
/// Errors: `n` not a Fibonacci number in 2..=[`MAX_N`] ([`PatternError::InvalidN`], naming the
/// nearest Fibonacci numbers below and above).
pub fn fibonacci(n: usize, shift: bool, seed: u64) -> Result<Vec<DVec2>, PatternError> {
    let g = match fibonacci_predecessor(n) {
        Some(g) if n <= MAX_N => g,
        _ => return Err(fibonacci_error(n)),
    };
    Ok(korobov(n as u64, g as u64, shift, seed))
}

/// The `InvalidN` for an `n` that is not a Fibonacci number in 2..=MAX_N.
fn fibonacci_error(n: usize) -> PatternError {
    let allowed: Vec<u64> = fibonacci_numbers()
        .into_iter()
        .filter(|&x| (2..=MAX_N as u64).contains(&x))
        .collect();
    let below = allowed.iter().copied().filter(|&x| x < n as u64).max();
    let above = allowed.iter().copied().find(|&x| x > n as u64);
    let allowed = match (below, above) {
        (None, _) => {
            "a Fibonacci number F_k ≥ 2 (the Fibonacci lattice needs N = F_k): the smallest is 2"
                .to_string()
        }
        (Some(b), Some(a)) => {
            format!("a Fibonacci number F_k (the Fibonacci lattice needs N = F_k): nearest are {b} and {a}")
        }
        (Some(b), None) => {
            format!("a Fibonacci number F_k ≤ {MAX_N} (the Fibonacci lattice needs N = F_k): the largest is {b}")
        }
    };
    if n == 0 || n > MAX_N {
        return PatternError::InvalidN {
            n,
            max: MAX_N,
            why: format!("; {allowed}"),
        };
    }
    PatternError::UnsupportedN {
        pattern: FIBONACCI_NAME,
        n,
        allowed,
    }
}

/// The checks of [`rank1`]: `n` in 2..=[`MAX_N`] and `g` below `n`.
pub(super) fn check_rank1(n: usize, g: u32) -> Result<(), PatternError> {
    check_n(n, MAX_N)?;
    if n < 2 {
        return Err(PatternError::UnsupportedN {
            pattern: RANK1_NAME,
            n,
            allowed: format!(
                "an integer in 2..={MAX_N} (a rank-1 lattice needs a generator in 1..N)"
            ),
        });
    }
    if g != 0 && g as usize >= n {
        return Err(PatternError::InvalidParam {
            pattern: RANK1_NAME,
            field: "g",
            value: g.to_string(),
            allowed: format!(
                "0 (auto: the generator maximising the minimum distance) or an integer in 1..={} \
                 (below n = {n})",
                n - 1
            ),
        });
    }
    Ok(())
}

/// The checks of [`fibonacci`]: `n` a Fibonacci number in 2..=[`MAX_N`].
pub(super) fn check_fibonacci(n: usize) -> Result<(), PatternError> {
    match fibonacci_predecessor(n) {
        Some(_) if n <= MAX_N => Ok(()),
        _ => Err(fibonacci_error(n)),
    }
}

/// The checks of [`kronecker`]: `n` and both offsets finite in [0, 1).
pub(super) fn check_kronecker(n: usize, offset: DVec2) -> Result<(), PatternError> {
    check_n(n, MAX_N)?;
    for (field, v) in [("offset_x", offset.x), ("offset_y", offset.y)] {
        if !(v.is_finite() && (0.0..1.0).contains(&v)) {
            return Err(PatternError::InvalidParam {
                pattern: KRONECKER_NAME,
                field,
                value: crate::core::params::fmt_num(v),
                allowed: "a finite number in [0, 1)".into(),
            });
        }
    }
    Ok(())
}

/// The Korobov lattice x_i = (i/N, frac(i·g/N)), i = 0..N (module docs); `g = 0` uses
/// [`best_generator`]. With `shift`, Cranley–Patterson rotated by a uniform vector from `seed`.
///
/// Errors: `n` outside 2..=[`MAX_N`] ([`PatternError::InvalidN`]); `g ≥ n`
/// ([`PatternError::InvalidParam`] on `rank1.g`).
pub fn rank1(n: usize, g: u32, shift: bool, seed: u64) -> Result<Vec<DVec2>, PatternError> {
    rank1_with(n, g, shift, seed, &Cancel::never())
}

/// As [`rank1`], with a cancel token checked during the generator search (g = 0).
pub fn rank1_with(
    n: usize,
    g: u32,
    shift: bool,
    seed: u64,
    cancel: &Cancel,
) -> Result<Vec<DVec2>, PatternError> {
    check_rank1(n, g)?;
    let g = if g == 0 {
        best_generator_with(n, cancel)?
    } else {
        g
    };
    Ok(korobov(n as u64, u64::from(g), shift, seed))
}

/// The N points (i/N, (i·g mod N)/N), optionally rotated. `2 ≤ n ≤ MAX_N`, `1 ≤ g < n`.
fn korobov(n: u64, g: u64, shift: bool, seed: u64) -> Vec<DVec2> {
    let u = if shift {
        let mut rng = Rng::new(seed);
        let ux = rng.next_f64();
        DVec2::new(ux, rng.next_f64())
    } else {
        DVec2::ZERO
    };
    let nf = n as f64;
    let mut out = Vec::with_capacity(n as usize);
    let mut y: u64 = 0; // i·g mod n, exactly
    for i in 0..n {
        let p = DVec2::new(i as f64 / nf, y as f64 / nf);
        out.push(if shift {
            DVec2::new(rotate(p.x, u.x), rotate(p.y, u.y))
        } else {
            p
        });
        y += g;
        if y >= n {
            y -= n;
        }
    }
    out
}

/// (x + u) mod 1 for x, u ∈ [0, 1), in [0, 1 − 2⁻⁵³].
#[inline]
fn rotate(x: f64, u: f64) -> f64 {
    let s = x + u;
    clamp_unit(if s >= 1.0 { s - 1.0 } else { s })
}

/// Squared length of the shortest nonzero vector of {(a, b) ∈ ℤ² : b ≡ g·a (mod n)}, by
/// Lagrange–Gauss reduction of the basis (0, n), (1, g mod n). Exact; `2 ≤ n ≤ 2⁶²`.
fn shortest_vector_sq(n: u64, g: u64) -> u128 {
    let n = n as i128;
    let mut g = (g as i128) % n;
    if 2 * g > n {
        g -= n; // centred representative: |g| ≤ n/2
    }
    let norm = |v: (i128, i128)| v.0 * v.0 + v.1 * v.1;
    let mut u = (1i128, g);
    let mut v = (0i128, n);
    if norm(u) > norm(v) {
        std::mem::swap(&mut u, &mut v);
    }
    loop {
        // v −= m·u with m the integer nearest ⟨u, v⟩ / |u|²; then u is shortest iff |v| ≥ |u|.
        let uu = norm(u);
        let dot = u.0 * v.0 + u.1 * v.1;
        let m = (2 * dot + uu).div_euclid(2 * uu);
        v = (v.0 - m * u.0, v.1 - m * u.1);
        if norm(v) >= uu {
            return uu as u128;
        }
        std::mem::swap(&mut u, &mut v);
    }
}

/// The same as [`shortest_vector_sq`] in i64, for the search (n ≤ 2³⁰: norms ≤ n² ≤ 2⁶⁰, and
/// |2⟨u,v⟩ + |u|²| ≤ 3·2⁶⁰ < 2⁶³). Kept bit-for-bit equal to the i128 version (tested).
fn shortest_vector_sq_i64(n: u64, g: u64) -> u64 {
    debug_assert!(n <= 1 << 30);
    let n = n as i64;
    let mut g = (g as i64) % n;
    if 2 * g > n {
        g -= n;
    }
    let norm = |v: (i64, i64)| v.0 * v.0 + v.1 * v.1;
    let mut u = (1i64, g);
    let mut v = (0i64, n);
    if norm(u) > norm(v) {
        std::mem::swap(&mut u, &mut v);
    }
    loop {
        let uu = norm(u);
        let dot = u.0 * v.0 + u.1 * v.1;
        let m = (2 * dot + uu).div_euclid(2 * uu);
        v = (v.0 - m * u.0, v.1 - m * u.1);
        if norm(v) >= uu {
            return uu as u64;
        }
        std::mem::swap(&mut u, &mut v);
    }
}

/// The minimum toroidal distance between two distinct points of the rank-1 lattice
/// (i/n, frac(i·g/n)), i = 0..n: the length of its shortest vector (module docs), computed
/// exactly in integers and returned as √(len²)/n. `g` is taken mod n (g ≡ 0 gives the points on
/// the line y = 0, distance 1/n).
///
/// Returns +∞ for n < 2 (no two distinct points) and NaN for n > 2⁶² (outside the exact
/// integer range).
pub fn lattice_min_distance(n: usize, g: u32) -> f64 {
    if n < 2 {
        return f64::INFINITY;
    }
    if n as u64 > 1 << 62 {
        return f64::NAN;
    }
    (shortest_vector_sq(n as u64, u64::from(g)) as f64).sqrt() / n as f64
}

/// gcd by Euclid's algorithm.
fn gcd(mut a: u64, mut b: u64) -> u64 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

/// The generator g ∈ 1..=⌊N/2⌋, coprime to N, whose rank-1 lattice has the largest minimum
/// toroidal distance ([`lattice_min_distance`]); the smallest such g on ties. See the module docs
/// for the search and its cost.
///
/// Returns 0 (no generator) for n < 2 and for n > [`MAX_BEST_GENERATOR_N`] (not searched).
pub fn best_generator(n: usize) -> u32 {
    best_generator_with(n, &Cancel::never()).unwrap_or(0)
}

/// As [`best_generator`], checking `cancel` every 2¹⁶ generators.
///
/// Errors: [`PatternError::Cancelled`]; `n` outside 2..=[`MAX_BEST_GENERATOR_N`]
/// ([`PatternError::InvalidN`]).
pub fn best_generator_with(n: usize, cancel: &Cancel) -> Result<u32, PatternError> {
    if !(2..=MAX_BEST_GENERATOR_N).contains(&n) {
        return Err(PatternError::InvalidN {
            n,
            max: MAX_BEST_GENERATOR_N,
            why: "; the best-generator search needs N ≥ 2".into(),
        });
    }
    let nn = n as u64;
    let mut best = (0u64, 1u64); // (squared length, g)
    for g in 1..=nn / 2 {
        if g % (1 << 16) == 0 {
            cancel.check()?;
        }
        if gcd(nn, g) != 1 {
            continue;
        }
        let len = shortest_vector_sq_i64(nn, g);
        if len > best.0 {
            best = (len, g);
        }
    }
    Ok(best.1 as u32)
}

/// The plastic number φ₂ ≈ 1.324718, the real root of x³ = x + 1, by Newton's method in f64
/// from x₀ = 1.5 (where the iteration is monotone: f is convex on x > 0), stopped when a step
/// no longer decreases x (at most 64 steps; 6 in practice).
pub fn plastic_number() -> f64 {
    let mut x = 1.5f64;
    for _ in 0..64 {
        let next = x - (x * x * x - x - 1.0) / (3.0 * x * x - 1.0);
        if next >= x {
            break;
        }
        x = next;
    }
    x
}

/// The R2 generator α = (1/φ₂, 1/φ₂²) in f64 (nearest to the 128-bit values the sequence uses).
pub fn r2_alpha() -> DVec2 {
    let [a1, a2] = r2_alpha_fixed();
    DVec2::new(a1 as f64 * TWO_POW_M128, a2 as f64 * TWO_POW_M128)
}

/// 2⁻¹²⁸, exactly.
pub(super) const TWO_POW_M128: f64 = 1.0 / 340_282_366_920_938_463_463_374_607_431_768_211_456.0;

/// ⌊a·b / 2¹²⁸⌋ (the high half of the 256-bit product), exactly.
pub(super) fn mul_hi_u128(a: u128, b: u128) -> u128 {
    const M: u128 = u64::MAX as u128;
    let (a1, a0) = (a >> 64, a & M);
    let (b1, b0) = (b >> 64, b & M);
    let p00 = a0 * b0;
    let p01 = a0 * b1;
    let p10 = a1 * b0;
    let p11 = a1 * b1;
    let mid = (p00 >> 64) + (p01 & M) + (p10 & M);
    p11 + (p01 >> 64) + (p10 >> 64) + (mid >> 64)
}

/// α = (1/φ₂, 1/φ₂²) as 128-bit fixed-point fractions A = α·2¹²⁸: α₁ = 1/φ₂ is the root of
/// a³ + a² = 1 (divide φ³ = φ + 1 by φ³); from the f64 value, two Newton steps with the residual
/// a³ + a² − 1 evaluated in fixed point (two truncated 256-bit products) and the derivative
/// 3a² + 2a in f64. Then A₂ = ⌊A₁² / 2¹²⁸⌋. Each is within 2⁻¹²⁵ of the exact value (tested).
fn r2_alpha_fixed() -> [u128; 2] {
    let a = 1.0 / plastic_number();
    let deriv = 3.0 * a * a + 2.0 * a;
    let mut fixed = (a * 2f64.powi(128)) as u128;
    for _ in 0..2 {
        let sq = mul_hi_u128(fixed, fixed);
        let cube = mul_hi_u128(sq, fixed);
        // a³ + a² − 1 in units of 2⁻¹²⁸: the sum is near 2¹²⁸, so the wrapped value is small.
        let residual = cube.wrapping_add(sq) as i128;
        let step = (residual as f64 / deriv).round() as i128;
        fixed = (fixed as i128 - step) as u128;
    }
    [fixed, mul_hi_u128(fixed, fixed)]
}

/// `s` as a 128-bit fixed-point fraction ⌊s·2¹²⁸⌋ (s ∈ [0, 1)).
pub(super) fn to_fixed(s: f64) -> u128 {
    (s * 2f64.powi(128)) as u128
}

/// The R2 sequence x_i = frac(s + i·α), α = (1/φ₂, 1/φ₂²), i = 0..n, s = `offset` (Roberts 2018;
/// default [`R2_DEFAULT_OFFSET`] = (½, ½)); progressive. See the module docs for the fixed-point
/// evaluation and its error bound (≤ 2⁻⁵⁴ + 2⁻¹⁰⁰ absolute).
///
/// Errors: `n` outside 1..=[`MAX_N`]; an offset component not finite or outside [0, 1)
/// ([`PatternError::InvalidParam`] on `kronecker.offset_x` / `offset_y`).
pub fn kronecker(n: usize, offset: DVec2) -> Result<Vec<DVec2>, PatternError> {
    check_kronecker(n, offset)?;
    let [ax, ay] = r2_alpha_fixed();
    let (mut x, mut y) = (to_fixed(offset.x), to_fixed(offset.y));
    let mut out = Vec::with_capacity(n);
    for _ in 0..n {
        out.push(fixed_point(x, y));
        x = x.wrapping_add(ax);
        y = y.wrapping_add(ay);
    }
    Ok(out)
}

/// The point with 128-bit fixed-point coordinates (x, y), each rounded to nearest and clamped.
#[inline]
fn fixed_point(x: u128, y: u128) -> DVec2 {
    DVec2::new(
        clamp_unit(x as f64 * TWO_POW_M128),
        clamp_unit(y as f64 * TWO_POW_M128),
    )
}

/// R2 point i directly: S + i·A mod 2¹²⁸ (the same exact value [`kronecker`] reaches by
/// repeated addition).
#[cfg(test)]
fn r2_point(i: u64, offset: DVec2) -> DVec2 {
    let [ax, ay] = r2_alpha_fixed();
    let i = u128::from(i);
    fixed_point(
        to_fixed(offset.x).wrapping_add(i.wrapping_mul(ax)),
        to_fixed(offset.y).wrapping_add(i.wrapping_mul(ay)),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn bits(p: DVec2) -> (u64, u64) {
        (p.x.to_bits(), p.y.to_bits())
    }

    /// Integer coordinates (round(x·N), round(y·N)) of a lattice point, checking that the point
    /// is exactly the correctly rounded k/N (so x·N "is an integer" in the only sense f64 allows).
    fn integer_coords(p: DVec2, n: usize) -> (u64, u64) {
        let nf = n as f64;
        let kx = (p.x * nf).round();
        let ky = (p.y * nf).round();
        assert_eq!(p.x.to_bits(), (kx / nf).to_bits(), "x = {} not k/N", p.x);
        assert_eq!(p.y.to_bits(), (ky / nf).to_bits(), "y = {} not k/N", p.y);
        (kx as u64, ky as u64)
    }

    /// Squared toroidal distance between all pairs, brute force, in integer units; the minimum.
    fn brute_min_sq(n: u64, g: u64) -> u64 {
        let pts: Vec<(u64, u64)> = (0..n).map(|i| (i, i * g % n)).collect();
        let mut best = u64::MAX;
        for i in 0..pts.len() {
            for j in i + 1..pts.len() {
                let dx = pts[i].0.abs_diff(pts[j].0);
                let dy = pts[i].1.abs_diff(pts[j].1);
                let (dx, dy) = (dx.min(n - dx), dy.min(n - dy));
                best = best.min(dx * dx + dy * dy);
            }
        }
        best
    }

    #[test]
    fn rank1_points_are_exact_and_closed_under_addition() {
        for (n, g) in [
            (2usize, 1u32),
            (7, 3),
            (64, 19),
            (100, 30),
            (377, 233),
            (1000, 7),
        ] {
            let pts = rank1(n, g, false, 0).unwrap();
            assert_eq!(pts.len(), n);
            let k: Vec<(u64, u64)> = pts.iter().map(|&p| integer_coords(p, n)).collect();
            let nn = n as u64;
            for (i, &(kx, ky)) in k.iter().enumerate() {
                assert_eq!(
                    (kx, ky),
                    (i as u64, i as u64 * u64::from(g) % nn),
                    "n={n} i={i}"
                );
            }
            // x_i + x_j ≡ x_{(i+j) mod N}: all pairs for small N, a stride for larger.
            let step = (n / 60).max(1);
            for i in (0..n).step_by(step) {
                for j in (0..n).step_by(step) {
                    let s = ((k[i].0 + k[j].0) % nn, (k[i].1 + k[j].1) % nn);
                    assert_eq!(s, k[(i + j) % n], "n={n} i={i} j={j}");
                }
            }
        }
    }

    #[test]
    fn fibonacci_lattice_has_generator_f_k_minus_1() {
        let fib = fibonacci_numbers();
        assert_eq!(&fib[..8], &[1, 2, 3, 5, 8, 13, 21, 34]);
        for w in fib.windows(3) {
            assert_eq!(w[2], w[0] + w[1]);
        }
        for &(n, g) in &[
            (2usize, 1u64),
            (3, 2),
            (13, 8),
            (89, 55),
            (987, 610),
            (10946, 6765),
        ] {
            let pts = fibonacci(n, false, 0).unwrap();
            assert_eq!(integer_coords(pts[1], n), (1, g), "n={n}");
            let want = rank1(n, g as u32, false, 0).unwrap();
            assert!(pts.iter().zip(&want).all(|(a, b)| bits(*a) == bits(*b)));
        }
        // The largest allowed, F_36, and exact i·F_{k−1} mod F_k at the far end.
        let n = 14_930_352usize;
        assert_eq!(fibonacci_predecessor(n), Some(9_227_465));
        assert_eq!(fibonacci_predecessor(24_157_817), Some(14_930_352)); // (beyond MAX_N)
        assert!(fibonacci(24_157_817, false, 0).is_err());
    }

    #[test]
    fn fibonacci_rejects_non_fibonacci_n_naming_neighbours() {
        let e = fibonacci(1000, false, 0).unwrap_err();
        assert!(
            e.to_string()
                .contains("the Fibonacci lattice needs N = F_k): nearest are 987 and 1597"),
            "{e}"
        );
        assert!(matches!(e, PatternError::UnsupportedN { n: 1000, .. }));
        for n in [0usize, 1] {
            let e = fibonacci(n, false, 0).unwrap_err();
            assert!(e.to_string().contains("the smallest is 2"), "{e}");
        }
        let e = fibonacci(15_000_000, false, 0).unwrap_err();
        assert!(e.to_string().contains("the largest is 14930352"), "{e}");
        let e = fibonacci(usize::MAX, false, 0).unwrap_err();
        assert!(e.to_string().contains("the largest is 14930352"), "{e}");
        assert!(fibonacci(4, false, 0)
            .unwrap_err()
            .to_string()
            .contains("nearest are 3 and 5"));
    }

    #[test]
    fn rank1_rejects_bad_g_and_n() {
        let e = rank1(10, 10, false, 0).unwrap_err();
        assert!(
            matches!(
                e,
                PatternError::InvalidParam {
                    pattern: "rank1",
                    field: "g",
                    ..
                }
            ),
            "{e}"
        );
        assert!(e.to_string().contains("1..=9"), "{e}");
        assert!(rank1(10, u32::MAX, false, 0).is_err());
        assert!(matches!(
            rank1(1, 0, false, 0),
            Err(PatternError::UnsupportedN { n: 1, .. })
        ));
        assert!(rank1(0, 1, false, 0).is_err());
        assert!(rank1(MAX_N + 1, 1, false, 0).is_err());
        assert_eq!(best_generator(0), 0);
        assert_eq!(best_generator(1), 0);
        assert_eq!(best_generator(MAX_N + 1), 0);
        assert_eq!(best_generator(2), 1);
    }

    #[test]
    fn shift_is_a_seeded_rotation_mod_1() {
        let plain = fibonacci(233, false, 0).unwrap();
        let a = fibonacci(233, true, 5).unwrap();
        let b = fibonacci(233, true, 5).unwrap();
        let c = fibonacci(233, true, 6).unwrap();
        assert_eq!(a, b);
        assert_ne!(a, c);
        assert_eq!(
            fibonacci(233, false, 1).unwrap(),
            plain,
            "seed unused without shift"
        );
        let mut rng = Rng::new(5);
        let u = DVec2::new(rng.next_f64(), rng.next_f64());
        for (p, q) in plain.iter().zip(&a) {
            assert!((0.0..1.0).contains(&q.x) && (0.0..1.0).contains(&q.y));
            for (x, y, s) in [(p.x, q.x, u.x), (p.y, q.y, u.y)] {
                let d = (y - x - s).rem_euclid(1.0);
                assert!(d.min(1.0 - d) < 1e-15, "not rotated by u: {x} {y} {s}");
            }
        }
    }

    #[test]
    fn shortest_vector_equals_brute_force_min_distance() {
        // Random (N, g), N ≤ 1500: every pair of points, exact integers.
        let mut rng = Rng::new(42);
        for _ in 0..40 {
            let n = 2 + rng.below(1500);
            let g = rng.below(n);
            let want = brute_min_sq(n, g);
            assert_eq!(shortest_vector_sq(n, g), u128::from(want), "n={n} g={g}");
            assert_eq!(shortest_vector_sq_i64(n, g), want, "n={n} g={g}");
            let d = lattice_min_distance(n as usize, g as u32);
            assert!((d - (want as f64).sqrt() / n as f64).abs() <= 1e-15);
        }
        // Large N against the O(N) brute force over the difference set {x_k : k ≠ 0}.
        for _ in 0..4 {
            let n = (1 << 20) + rng.below(1 << 20);
            let g = 1 + rng.below(n - 1);
            let mut want = u64::MAX;
            for k in 1..n {
                let (dx, dy) = (k, k * g % n);
                let (dx, dy) = (dx.min(n - dx), dy.min(n - dy));
                want = want.min(dx * dx + dy * dy);
            }
            assert_eq!(shortest_vector_sq(n, g), u128::from(want), "n={n} g={g}");
            assert_eq!(shortest_vector_sq_i64(n, g), want, "n={n} g={g}");
        }
        assert_eq!(lattice_min_distance(1, 0), f64::INFINITY);
        assert!(lattice_min_distance(usize::MAX, 3).is_nan());
        // The i128 path at N = 2⁶²: g = 1 is the diagonal, shortest vector (1, 1).
        assert_eq!(shortest_vector_sq(1 << 62, 1), 2);
    }

    #[test]
    fn best_generator_matches_brute_force_search_up_to_200() {
        for n in 2..=200u64 {
            let mut best = 0u64;
            for g in 1..n {
                if gcd(n, g) == 1 {
                    best = best.max(brute_min_sq(n, g));
                }
            }
            let g = best_generator(n as usize);
            assert!(g >= 1 && u64::from(g) <= n / 2 && gcd(n, u64::from(g)) == 1);
            assert_eq!(brute_min_sq(n, u64::from(g)), best, "n={n} g={g}");
        }
    }

    #[test]
    fn best_lattice_obeys_hermite_bound_and_fibonacci_is_near_optimal() {
        // Hermite: in 2D, λ₁² ≤ (2/√3)·det, det = 1/N, with equality only for the hexagonal
        // lattice. The best rank-1 lattices come within 10 % of it: measured d/d_hex = 0.9135
        // (N = 55), 0.9306 (89), 0.9370 (144), 0.9774 (233), 0.9490 (500), 0.9707 (1000),
        // 0.9821 (4096); required ≥ 0.91.
        for n in [55usize, 89, 144, 233, 500, 1000, 4096] {
            let d = lattice_min_distance(n, best_generator(n));
            let hex = (2.0 / (3f64.sqrt() * n as f64)).sqrt();
            assert!(d <= hex * (1.0 + 1e-12), "n={n}: {d} > {hex}");
            assert!(d >= 0.91 * hex, "n={n}: {d} vs {hex}");
        }
        // Fibonacci lattices against the best generator: measured ratios 1 (89: the search
        // finds g = 34 = 89 − 55, the mirror image), 0.9363 (144: shortest vector (8, −8)),
        // 0.9522 (233); required ≥ 0.93.
        for (n, g) in [(89usize, 55u32), (144, 89), (233, 144)] {
            let ratio = lattice_min_distance(n, g) / lattice_min_distance(n, best_generator(n));
            assert!((0.93..=1.0).contains(&ratio), "F = {n}: ratio {ratio}");
        }
        assert_eq!(best_generator(89), 34);
    }

    #[test]
    fn best_generator_is_cancellable() {
        let c = Cancel::new();
        c.cancel();
        assert_eq!(
            best_generator_with(1 << 20, &c),
            Err(PatternError::Cancelled)
        );
        assert_eq!(
            rank1_with(1 << 20, 0, false, 0, &c),
            Err(PatternError::Cancelled)
        );
    }

    #[test]
    fn plastic_number_newton_matches_cubic_and_closed_form() {
        let p = plastic_number();
        assert!((p * p * p - p - 1.0).abs() <= 1e-15, "{p}");
        // Cardano: ρ = ∛((9 + √69)/18) + ∛((9 − √69)/18).
        let r69 = 69f64.sqrt();
        let closed = ((9.0 + r69) / 18.0).cbrt() + ((9.0 - r69) / 18.0).cbrt();
        assert!((p - closed).abs() <= 4.0 * f64::EPSILON, "{p} vs {closed}");
        assert!((p - 1.324_717_957_244_746).abs() <= 2.0 * f64::EPSILON);
    }

    #[test]
    fn mul_hi_is_the_high_half_of_the_product() {
        let mut rng = Rng::new(3);
        for _ in 0..1000 {
            let x = (u128::from(rng.next_u64()) << 64) | u128::from(rng.next_u64());
            let k = 1 + rng.below(127) as u32;
            assert_eq!(mul_hi_u128(x, 1u128 << k), x >> (128 - k));
            // (a·2⁶⁴)(b·2⁶⁴) / 2¹²⁸ = a·b for a, b < 2⁶⁴.
            let (a, b) = (rng.next_u64() as u128, rng.next_u64() as u128);
            assert_eq!(mul_hi_u128(a << 64, b << 64), a * b);
            assert_eq!(mul_hi_u128(x, a << 64), mul_hi_u128(a << 64, x));
        }
        assert_eq!(mul_hi_u128(u128::MAX, u128::MAX), u128::MAX - 1);
    }

    /// ⌊α₁·2⁶⁴⌋ by bisection on a³ + a² < 1 with exact 192-bit integer comparisons
    /// (a = A/2⁶⁴, so the test is A³ + A²·2⁶⁴ < 2¹⁹²): independent of Newton and of f64.
    fn alpha1_64_by_bisection() -> u64 {
        let below_root = |a: u64| -> bool {
            let a = u128::from(a);
            let sq = a * a; // < 2¹²⁸
            let (lo, hi) = (sq & u128::from(u64::MAX), sq >> 64);
            let p1 = lo * a; // low part of sq·a
            let p2 = hi * a; // high part, weight 2⁶⁴
                             // A³ = p2·2⁶⁴ + p1; the top 128 bits (weight 2⁶⁴) plus A²: overflow ⟺ ≥ 2¹⁹².
            let top = p2.checked_add(p1 >> 64).and_then(|t| t.checked_add(sq));
            top.is_some()
        };
        let (mut lo, mut hi) = (0u64, u64::MAX); // below_root(lo), !below_root(hi)
        assert!(below_root(lo) && !below_root(hi));
        while hi - lo > 1 {
            let mid = lo + (hi - lo) / 2;
            if below_root(mid) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        lo
    }

    #[test]
    fn fixed_point_alpha_solves_the_cubic_to_125_bits() {
        let [a1, a2] = r2_alpha_fixed();
        // Residual a³ + a² − 1 in units of 2⁻¹²⁸ (truncated products: |error| ≤ 3 units); the
        // derivative is ≈ 3.22, so |A − α·2¹²⁸| ≤ (|residual| + 3)/3.2 + 1.
        let sq = mul_hi_u128(a1, a1);
        let residual = (mul_hi_u128(sq, a1).wrapping_add(sq) as i128).abs();
        assert!(residual <= 8, "residual {residual}");
        assert_eq!(a2, sq);
        // The top 64 bits agree with the exact bisection.
        let want = alpha1_64_by_bisection();
        assert_eq!((a1 >> 64) as u64, want);
        let alpha = r2_alpha();
        let p = plastic_number();
        assert!((alpha.x - 1.0 / p).abs() <= f64::EPSILON);
        assert!((alpha.y - 1.0 / (p * p)).abs() <= f64::EPSILON);
        // The defining identity α₁³ + α₁² = 1 in f64.
        assert!((alpha.x.powi(3) + alpha.x.powi(2) - 1.0).abs() < 1e-15);
    }

    /// (s + i·α) mod 1 with a 64-bit-fraction α from the bisection (α₂ = ⌊A₁²/2⁶⁴⌋) in u128
    /// arithmetic: error ≤ i·3·2⁻⁶⁴ + 2⁻⁶⁴.
    fn r2_reference(i: u64, s: DVec2, a1: u64) -> DVec2 {
        let a1 = u128::from(a1);
        let a2 = (a1 * a1) >> 64;
        let m = 1u128 << 64;
        let f = |s: f64, a: u128| {
            let s = (s * 2f64.powi(64)) as u128;
            let v = (s + u128::from(i) * a) % m;
            v as f64 / m as f64
        };
        DVec2::new(f(s.x, a1), f(s.y, a2))
    }

    fn circle_dist(a: f64, b: f64) -> f64 {
        let d = (a - b).rem_euclid(1.0);
        d.min(1.0 - d)
    }

    #[test]
    fn kronecker_matches_fixed_point_reference_up_to_2_pow_24() {
        let s = R2_DEFAULT_OFFSET;
        let n = 1 << 16;
        let pts = kronecker(n, s).unwrap();
        assert_eq!(pts[0], DVec2::new(0.5, 0.5));
        let a1 = alpha1_64_by_bisection();
        let mut rng = Rng::new(17);
        let large: Vec<u64> = (0..2000)
            .map(|_| rng.below(1 << 24))
            .chain([(1 << 24) - 1, 1 << 24, (1 << 23) + 1])
            .collect();
        for i in (0..n as u64).chain(large) {
            let got = if (i as usize) < n {
                pts[i as usize]
            } else {
                r2_point(i, s)
            };
            if (i as usize) < n {
                assert_eq!(bits(got), bits(r2_point(i, s)), "incremental != direct");
            }
            let want = r2_reference(i, s, a1);
            // Reference error i·3·2⁻⁶⁴ + 2⁻⁶⁴, ours ≤ 2⁻⁵⁴ + 2⁻¹⁰⁰, plus f64 rounding of the
            // reference (2⁻⁵⁴).
            let tol = (i as f64 * 3.0 + 1.0) * 2f64.powi(-64) + 2f64.powi(-53);
            assert!(
                circle_dist(got.x, want.x) <= tol,
                "i={i}: x {} vs {}",
                got.x,
                want.x
            );
            assert!(
                circle_dist(got.y, want.y) <= tol,
                "i={i}: y {} vs {}",
                got.y,
                want.y
            );
        }
    }

    #[test]
    fn kronecker_is_progressive_and_steps_by_alpha() {
        let s = DVec2::new(0.125, 0.75);
        let long = kronecker(5000, s).unwrap();
        let short = kronecker(1234, s).unwrap();
        assert_eq!(&long[..1234], &short[..]);
        let a = r2_alpha();
        for w in long.windows(2) {
            assert!(circle_dist(w[1].x - w[0].x, a.x) <= 2.0 * f64::EPSILON);
            assert!(circle_dist(w[1].y - w[0].y, a.y) <= 2.0 * f64::EPSILON);
            assert!((0.0..1.0).contains(&w[1].x) && (0.0..1.0).contains(&w[1].y));
        }
        // Zero offset: x_0 is the origin, x_1 = α.
        let z = kronecker(2, DVec2::ZERO).unwrap();
        assert_eq!(z[0], DVec2::ZERO);
        assert_eq!(z[1], a);
    }

    #[test]
    fn kronecker_rejects_bad_offset_and_n() {
        for (bad, field) in [
            (DVec2::new(1.0, 0.5), "offset_x"),
            (DVec2::new(-0.1, 0.5), "offset_x"),
            (DVec2::new(0.5, f64::NAN), "offset_y"),
            (DVec2::new(0.5, f64::INFINITY), "offset_y"),
        ] {
            let e = kronecker(10, bad).unwrap_err();
            assert!(
                matches!(e, PatternError::InvalidParam { pattern: "kronecker", field: f, .. } if f == field),
                "{e}"
            );
        }
        assert!(kronecker(0, R2_DEFAULT_OFFSET).is_err());
        assert!(kronecker(MAX_N + 1, R2_DEFAULT_OFFSET).is_err());
        let edge = kronecker(3, DVec2::new(super::ONE_MINUS_EPSILON, 0.0)).unwrap();
        assert!(edge.iter().all(|p| p.x < 1.0 && p.y < 1.0));
    }
}
