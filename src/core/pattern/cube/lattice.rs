//! Lattices in d dimensions: Roberts' R_d Kronecker sequence and rank-1 lattices whose
//! generating vector comes from the fast component-by-component (CBC) construction.
//!
//! ## R_d (`kronecker`)
//!
//! x_i = frac(s + i·α), α_k = φ_d^−(k+1), k = 0..D, φ_d the real root > 1 of x^(D+1) = x + 1
//! (M. Roberts 2018, "The unreasonable effectiveness of quasirandom sequences"): the golden
//! ratio for D = 1, the plastic number for D = 2. Offsets s = (offset_x, offset_y, ½, ½, …).
//! As the 2D R2 (`lattice::kronecker`): φ_d by Newton's method in f64, then a = 1/φ_d refined
//! in 128-bit fixed point by two Newton steps on a^(D+1) + a^D = 1, α_k = a^(k+1) by repeated
//! 256-bit-product truncation, and each point the exact u128 sum S + i·A mod 2¹²⁸ converted once
//! to f64. Each α_k is within (k + 8)·2⁻¹²⁸ of a's power (truncations) and a within 2⁻¹²⁰ of
//! 1/φ_d (checked by the residual in the tests), so a coordinate is within 2⁻⁹⁰ of the exact
//! frac(s + i·α) for i < 2²⁵: the f64 is correctly rounded but in rare ties. At D = 2 the
//! arithmetic is the 2D one step for step, so R_2 is the 2D R2 bit for bit (tested).
//!
//! ## Rank-1 lattices (`rank1`)
//!
//! x_i = frac(i·z / N + Δ), i = 0..N, with the generating vector z ∈ ℤ^D:
//! - `g ≠ 0`: the Korobov vector z = (1, g, g², …) mod N (at D = 2 the 2D `rank1`'s lattice);
//! - `g = 0` and D ≠ 2: the CBC vector minimising the worst-case error P_α (α = 2) of the
//!   weighted Korobov space with product weights γ_j = 0.9^j, j = 1..D:
//!   P₂(z) = −1 + (1/N) Σ_k Π_j (1 + γ_j ω({k z_j / N})), ω(x) = 2π² (x² − x + 1/6)
//!   (Sloan & Reztsov 2002; Nuyens & Cools 2006, "Fast algorithms for component-by-component
//!   construction of rank-1 lattice rules in shift-invariant reproducing kernel Hilbert
//!   spaces", Math. Comp. 75). z_1 = 1; z_s minimises Σ_k p_{s−1}(k) ω({k z_s/N}) over the
//!   candidates, p_{s−1}(k) the product over the chosen components (the smallest z_s among the
//!   sums within 10⁻⁹ of the minimum: the criterion has exact ties, `choose`).
//!   **Prime N**: the fast CBC — the candidates z = g^a and the nodes k = g^b (g a primitive
//!   root) turn the N − 1 sums into one cyclic correlation of length N − 1, computed by FFT
//!   (rustfft): O(D·N log N). **Other N**: the naive CBC over the units z (gcd(z, N) = 1),
//!   O(N²·D), allowed while N²·D ≤ 2³² (a few seconds; e.g. N ≤ 11585 at D = 32); beyond it
//!   the error names the nearest primes. [`cbc_naive`] is the naive CBC for any N, the
//!   reference of the tests.
//! - `g = 0` and D = 2: the 2D `rank1` (the generator with the largest minimum distance), so
//!   that dims = 2 stays the 2D pattern; the CBC vector is a different lattice there.
//! - `z` given (a list of D integers in 1..N, `--set z=1,433,229`): that vector, for every D
//!   (also D = 2, where the 2D pattern takes it too); `g` must then be 0.
//! - `shift`: Δ uniform from `Rng::new(seed)`, dimension 0 first (the 2D rotation at D = 2);
//!   else Δ = 0.
use crate::core::pattern::lattice::{mul_hi_u128, to_fixed, TWO_POW_M128};
use crate::core::pattern::radical_inverse::is_prime;
use crate::core::pattern::{clamp_unit, Cancel, Kronecker, PatternError, Rank1, MAX_N};
use crate::core::rng::Rng;
use rustfft::num_complex::Complex64;

/// The pattern names in errors.
const RANK1: &str = "rank1";

/// The largest N²·D of the naive CBC (composite N).
pub const NAIVE_CBC_WORK: u128 = 1 << 32;

/// The checks of [`kronecker`]: the offsets (as the 2D pattern).
pub(super) fn check_kronecker(p: &Kronecker, n: usize, _dims: usize) -> Result<(), PatternError> {
    crate::core::pattern::lattice::check_kronecker(n, glam::DVec2::new(p.offset_x, p.offset_y))
}

/// φ_d, the real root > 1 of x^(D+1) = x + 1, by Newton's method from min(1.5, 1 + 2/D)
/// (right of the root, where the iteration decreases monotonically), stopped when a step no
/// longer decreases x. At D = 2 the same operations as `lattice::plastic_number`.
pub fn phi(dims: usize) -> f64 {
    let d = dims as f64;
    let mut x = if dims == 1 {
        2.0
    } else {
        1.5f64.min(1.0 + 2.0 / d)
    };
    for _ in 0..10_000 {
        let mut pd1 = 1.0; // x^(D−1)
        for _ in 1..dims {
            pd1 *= x;
        }
        let pd = if dims == 1 { x } else { pd1 * x }; // x^D
        let p = pd * x; // x^(D+1)
        let next = x - (p - x - 1.0) / ((d + 1.0) * x * pd1 - 1.0);
        if next >= x {
            break;
        }
        x = next;
    }
    x
}

/// α_k = φ_d^−(k+1), k = 0..dims, as 128-bit fixed-point fractions (module docs).
pub fn alpha_fixed(dims: usize) -> Vec<u128> {
    let d = dims as f64;
    let a = 1.0 / phi(dims);
    // a^(D−1) in f64, for the derivative (D+1)a^D + D a^(D−1) = ((D+1)a)·a^(D−1) + D·a^(D−1).
    let mut ad1 = 1.0;
    for _ in 1..dims {
        ad1 *= a;
    }
    let deriv = (d + 1.0) * a * ad1 + d * ad1;
    let mut fixed = (a * 2f64.powi(128)) as u128;
    for _ in 0..2 {
        // Powers p_1 = a, p_k = ⌊p_{k−1}·a⌋ in fixed point; residual a^(D+1) + a^D − 1.
        let mut p = fixed;
        let mut pd = fixed;
        for k in 2..=dims + 1 {
            p = mul_hi_u128(p, fixed);
            if k == dims {
                pd = p;
            }
        }
        let residual = p.wrapping_add(pd) as i128;
        let step = (residual as f64 / deriv).round() as i128;
        fixed = (fixed as i128 - step) as u128;
    }
    let mut out = Vec::with_capacity(dims);
    let mut p = fixed;
    out.push(p);
    for _ in 1..dims {
        p = mul_hi_u128(p, fixed);
        out.push(p);
    }
    out
}

/// The R_d points x_i = frac(s + i·α), i = 0..n, row-major.
pub fn kronecker(p: &Kronecker, n: usize, dims: usize) -> Result<Vec<f64>, PatternError> {
    let alpha = alpha_fixed(dims);
    let mut x: Vec<u128> = (0..dims)
        .map(|k| {
            to_fixed(match k {
                0 => p.offset_x,
                1 => p.offset_y,
                _ => 0.5,
            })
        })
        .collect();
    let mut out = Vec::with_capacity(n * dims);
    for _ in 0..n {
        for (v, a) in x.iter_mut().zip(&alpha) {
            out.push(clamp_unit(*v as f64 * TWO_POW_M128));
            *v = v.wrapping_add(*a);
        }
    }
    Ok(out)
}

/// The product weight γ_j of dimension j (1-based): 0.9^j.
pub fn weight(j: usize) -> f64 {
    0.9f64.powi(j as i32)
}

/// ω(x) = 2π² (x² − x + 1/6) = 2π² B₂(x), the kernel of the Korobov space with α = 2.
#[inline]
fn omega(x: f64) -> f64 {
    2.0 * std::f64::consts::PI * std::f64::consts::PI * (x * x - x + 1.0 / 6.0)
}

/// The worst-case error P₂(z) of the rank-1 rule with N points and generating vector z, product
/// weights [`weight`]: −1 + (1/N) Σ_k Π_j (1 + γ_j ω({k z_j/N})). O(N·D).
pub fn worst_case_error(n: usize, z: &[u64]) -> f64 {
    let nn = n as u64;
    let mut sum = 0.0;
    for k in 0..nn {
        let mut prod = 1.0;
        for (j, &zj) in z.iter().enumerate() {
            prod *= 1.0 + weight(j + 1) * omega(((k * zj) % nn) as f64 / n as f64);
        }
        sum += prod;
    }
    sum / n as f64 - 1.0
}

/// Greatest common divisor.
fn gcd(mut a: u64, mut b: u64) -> u64 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

/// The naive CBC vector for any N ≥ 2 (module docs): for each component, every unit z in
/// 1..N tried against every node k, O(N²·D). The reference of the fast one.
pub fn cbc_naive(n: usize, dims: usize, cancel: &Cancel) -> Result<Vec<u64>, PatternError> {
    let nn = n as u64;
    let mut prod = vec![1.0f64; n]; // p(k), k = 0..N
    let mut z = Vec::with_capacity(dims);
    for s in 1..=dims {
        let gamma = weight(s);
        let zs = if s == 1 {
            1
        } else {
            let mut sums = Vec::with_capacity(n);
            for cand in 1..nn {
                if gcd(cand, nn) != 1 {
                    continue;
                }
                if cand % 1024 == 0 {
                    cancel.check()?;
                }
                let e: f64 = (1..nn)
                    .map(|k| prod[k as usize] * omega(((k * cand) % nn) as f64 / n as f64))
                    .sum();
                sums.push((cand, e));
            }
            choose(&sums)
        };
        for (k, p) in prod.iter_mut().enumerate() {
            *p *= 1.0 + gamma * omega(((k as u64 * zs) % nn) as f64 / n as f64);
        }
        z.push(zs);
    }
    Ok(z)
}

/// The CBC choice among (candidate z, its sum): the smallest z whose sum is within 10⁻⁹
/// (relative) of the smallest sum. The criterion has exact ties — z, N − z, z⁻¹ and −z⁻¹ give
/// the same sum at the second component, z and N − z at every one — which rounding would
/// otherwise break differently in the fast and the naive sums (and the greedy construction
/// then goes different ways); the tolerance is far above their rounding (10⁻¹³) and far below
/// the gaps between distinct candidates.
fn choose(sums: &[(u64, f64)]) -> u64 {
    let min = sums.iter().map(|s| s.1).fold(f64::INFINITY, f64::min);
    let tol = 1e-9 * min.abs();
    sums.iter()
        .filter(|s| s.1 <= min + tol)
        .map(|s| s.0)
        .min()
        .expect("at least one candidate")
}

/// b^e mod m.
fn pow_mod(mut b: u64, mut e: u64, m: u64) -> u64 {
    let mut r = 1u64;
    b %= m;
    while e > 0 {
        if e & 1 == 1 {
            r = (u128::from(r) * u128::from(b) % u128::from(m)) as u64;
        }
        b = (u128::from(b) * u128::from(b) % u128::from(m)) as u64;
        e >>= 1;
    }
    r
}

/// The smallest primitive root of the prime p.
pub fn primitive_root(p: u64) -> u64 {
    if p == 2 {
        return 1;
    }
    let mut factors = Vec::new();
    let mut m = p - 1;
    let mut f = 2;
    while f * f <= m {
        if m % f == 0 {
            factors.push(f);
            while m % f == 0 {
                m /= f;
            }
        }
        f += 1;
    }
    if m > 1 {
        factors.push(m);
    }
    (2..p)
        .find(|&g| factors.iter().all(|&q| pow_mod(g, (p - 1) / q, p) != 1))
        .expect("a prime has a primitive root")
}

/// The fast CBC vector for prime N (module docs): per component one FFT correlation of length
/// N − 1 (rustfft), O(D·N log N).
pub fn cbc_fast(n: usize, dims: usize, cancel: &Cancel) -> Result<Vec<u64>, PatternError> {
    let nn = n as u64;
    debug_assert!(is_prime(nn));
    if n == 2 {
        return Ok(vec![1; dims]);
    }
    let m = n - 1;
    let g = primitive_root(nn);
    // perm[b] = g^b mod N: the nodes and candidates in the order of the group.
    let mut perm = Vec::with_capacity(m);
    let mut v = 1u64;
    for _ in 0..m {
        perm.push(v);
        v = v * g % nn;
    }
    let mut planner = rustfft::FftPlanner::<f64>::new();
    let fwd = planner.plan_fft_forward(m);
    let inv = planner.plan_fft_inverse(m);
    // FFT of W[c] = ω(g^c / N).
    let mut w_hat: Vec<Complex64> = perm
        .iter()
        .map(|&r| Complex64::new(omega(r as f64 / n as f64), 0.0))
        .collect();
    fwd.process(&mut w_hat);
    let mut prod = vec![1.0f64; m]; // p(g^b)
    let mut z = Vec::with_capacity(dims);
    let mut buf = vec![Complex64::new(0.0, 0.0); m];
    for s in 1..=dims {
        cancel.check()?;
        let gamma = weight(s);
        let zs = if s == 1 {
            1
        } else {
            // c[a] = Σ_b P[b] W[a + b] = Σ_b R[b] W[a − b], R[b] = P[−b mod m]: a cyclic
            // convolution, FFT(c) = FFT(R) · FFT(W).
            for (b, o) in buf.iter_mut().enumerate() {
                *o = Complex64::new(prod[(m - b) % m], 0.0);
            }
            fwd.process(&mut buf);
            for (o, w) in buf.iter_mut().zip(&w_hat) {
                *o *= w;
            }
            inv.process(&mut buf);
            let sums: Vec<(u64, f64)> = (0..m).map(|a| (perm[a], buf[a].re)).collect();
            choose(&sums)
        };
        for (b, p) in prod.iter_mut().enumerate() {
            *p *= 1.0 + gamma * omega((perm[b] * zs % nn) as f64 / n as f64);
        }
        z.push(zs);
    }
    Ok(z)
}

/// The nearest primes below and above n, for messages.
fn nearest_primes(n: usize) -> (u64, u64) {
    let below = (2..n as u64).rev().find(|&p| is_prime(p)).unwrap_or(2);
    let above = (n as u64 + 1..)
        .find(|&p| is_prime(p))
        .expect("primes never end");
    (below, above)
}

/// The checks of [`rank1`]: the 2D checks (n ≥ 2, g < n), and for the CBC vector (g = 0,
/// dims ≠ 2) a prime n or N²·D within [`NAIVE_CBC_WORK`].
pub(super) fn check_rank1(p: &Rank1, n: usize, dims: usize) -> Result<(), PatternError> {
    crate::core::pattern::lattice::check_rank1(n, p.g)?;
    check_z(p, n, dims)?;
    if p.g == 0
        && p.z.is_empty()
        && !is_prime(n as u64)
        && (n as u128).pow(2) * dims as u128 > NAIVE_CBC_WORK
    {
        let (below, above) = nearest_primes(n);
        return Err(PatternError::UnsupportedN {
            pattern: RANK1,
            n,
            allowed: format!(
                "a prime for the fast CBC vector in {dims} dimensions (nearest: {below} and \
                 {above}), or small enough for the naive CBC (N²·D ≤ 2^32), or set g for a \
                 Korobov vector"
            ),
        });
    }
    debug_assert!(n <= MAX_N);
    Ok(())
}

/// The checks of a generating vector given as a list (`rank1.z`; none when it is empty):
/// exactly `dims` entries, each in 1..n. The descriptor checks each entry against the largest
/// N only; this is the check against the N and D being generated.
pub(crate) fn check_z(p: &Rank1, n: usize, dims: usize) -> Result<(), PatternError> {
    let z = p.z.as_slice();
    if z.is_empty() {
        return Ok(());
    }
    let invalid = |value: String, allowed: String| PatternError::InvalidParam {
        pattern: RANK1,
        field: "z",
        value,
        allowed,
    };
    if z.len() != dims {
        return Err(invalid(
            p.z.value().short(),
            format!(
                "a list of exactly {dims} integers (one per dimension, dims = {dims}), each in \
                 1..={} (below n = {n}); it has {}",
                n.saturating_sub(1),
                z.len()
            ),
        ));
    }
    if let Some((j, &v)) = z
        .iter()
        .enumerate()
        .find(|(_, &v)| v == 0 || v as usize >= n)
    {
        return Err(invalid(
            p.z.value().short(),
            format!(
                "a list of integers in 1..={} (below n = {n}); entry {j} is {v}",
                n.saturating_sub(1)
            ),
        ));
    }
    Ok(())
}

/// The generating vector of [`rank1`] for `dims` ≠ 2 (module docs); the list `z` when given.
pub fn generating_vector(
    p: &Rank1,
    n: usize,
    dims: usize,
    cancel: &Cancel,
) -> Result<Vec<u64>, PatternError> {
    let nn = n as u64;
    if !p.z.is_empty() {
        check_z(p, n, dims)?;
        return Ok(p.z.as_slice().iter().map(|&v| u64::from(v)).collect());
    }
    if p.g != 0 {
        let g = u64::from(p.g);
        let mut z = Vec::with_capacity(dims);
        let mut v = 1 % nn;
        for _ in 0..dims {
            z.push(v);
            v = v * g % nn;
        }
        return Ok(z);
    }
    if is_prime(nn) {
        cbc_fast(n, dims, cancel)
    } else {
        cbc_naive(n, dims, cancel)
    }
}

/// The rank-1 lattice x_i = frac(i·z/N + Δ), i = 0..N, row-major (module docs).
pub fn rank1(
    p: &Rank1,
    n: usize,
    dims: usize,
    seed: u64,
    cancel: &Cancel,
) -> Result<Vec<f64>, PatternError> {
    let z = generating_vector(p, n, dims, cancel)?;
    Ok(lattice_points(n, &z, p.shift, seed))
}

/// The points of the rank-1 rule with vector `z`, optionally shifted (module docs).
pub fn lattice_points(n: usize, z: &[u64], shift: bool, seed: u64) -> Vec<f64> {
    let nn = n as u64;
    let nf = n as f64;
    let delta: Vec<f64> = if shift {
        let mut rng = Rng::new(seed);
        z.iter().map(|_| rng.next_f64()).collect()
    } else {
        vec![0.0; z.len()]
    };
    let mut num = vec![0u64; z.len()]; // i·z_j mod N, exactly
    let mut out = Vec::with_capacity(n * z.len());
    for _ in 0..n {
        for ((v, &zj), &u) in num.iter_mut().zip(z).zip(&delta) {
            let x = *v as f64 / nf;
            out.push(if shift {
                let s = x + u;
                clamp_unit(if s >= 1.0 { s - 1.0 } else { s })
            } else {
                x
            });
            *v += zj % nn;
            if *v >= nn {
                *v -= nn;
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn alpha_solves_a_to_the_d_plus_1_plus_a_to_the_d_equals_1_in_fixed_point() {
        for d in [1usize, 2, 3, 8, 32, 1024] {
            let a = alpha_fixed(d)[0];
            let mut p = a;
            let mut pd = a;
            for k in 2..=d + 1 {
                p = mul_hi_u128(p, a);
                if k == d {
                    pd = p;
                }
            }
            let residual = p.wrapping_add(pd) as i128;
            // Within 2⁻¹¹⁶ (the truncations of D + 1 products).
            assert!(
                residual.unsigned_abs() < 1 << 12,
                "dims {d}: residual {residual}"
            );
        }
    }

    #[test]
    fn fast_cbc_is_the_naive_cbc_up_to_reflections() {
        for (n, d) in [(31usize, 6usize), (1009, 3), (4999, 4)] {
            let never = Cancel::never();
            let fast = cbc_fast(n, d, &never).unwrap();
            let naive = cbc_naive(n, d, &never).unwrap();
            for (f, v) in fast.iter().zip(&naive) {
                // Equal, or the mirror N − z (an exact tie: ω(x) = ω(1 − x)).
                assert!(
                    f == v || f + v == n as u64,
                    "n = {n}: {fast:?} vs {naive:?}"
                );
            }
            let (pf, pn) = (worst_case_error(n, &fast), worst_case_error(n, &naive));
            assert!((pf - pn).abs() <= 1e-12 * pn, "n = {n}: {pf} vs {pn}");
        }
    }

    #[test]
    fn primitive_roots_generate_the_group() {
        for p in [3u64, 5, 7, 31, 101, 4999, 65537] {
            let g = primitive_root(p);
            let mut seen = vec![false; p as usize];
            let mut v = 1;
            for _ in 0..p - 1 {
                assert!(!seen[v as usize]);
                seen[v as usize] = true;
                v = v * g % p;
            }
        }
    }
}
