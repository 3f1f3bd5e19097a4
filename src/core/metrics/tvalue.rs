//! t-value of a 2D point set of `b^m` points in base `b`.
//!
//! A `(t, m, 2)`-net in base b (Niederreiter 1992, Def. 4.1; the lecture's "(t,m,d) nets") is a
//! set of `b^m` points such that every elementary interval
//! `E = [i·b^−kx, (i+1)·b^−kx) × [j·b^−ky, (j+1)·b^−ky)`, `kx + ky = m − t`,
//! of volume `b^(t−m)` holds exactly `b^t` points. A `(t,m,2)`-net is also a `(t+1,m,2)`-net
//! (each coarser interval is a union of b finer ones), so the **t-value** — the smallest such
//! t — is found by bisection over `t ∈ [0, m]` (`t = m` always holds: one interval, the square).
//!
//! **Exact membership.** Each coordinate is mapped once to its m-digit integer
//! `X = ⌊x·b^m⌋`, computed exactly for the f64 value given: for bases that are powers of two
//! the product is exact; otherwise the rounded product is corrected by an exact comparison
//! (`x·b^m = p + e` by Dekker's two-product). Then `⌊x·b^kx⌋ = ⌊X / b^(m−kx)⌋`. Intervals are
//! half-open, so a point on a boundary belongs to the upper interval. Note that non-dyadic
//! boundaries such as 1/3 are not representable: `fl(1/3) < 1/3` lies in `[0, 1/3)`.
//!
//! Cost: O(N·m) per tested t, O(N·m·log m) in all; memory O(N).

use glam::DVec2;
use serde::Serialize;

use super::dd::two_prod;
use super::{validate, Cancel, MetricsError, CANCEL_STRIDE};

/// The t-value of a net, with a witness that `t − 1` fails.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct TValue {
    /// The base b.
    pub base: u32,
    /// `N = b^m`.
    pub m: u32,
    /// The smallest t (0 ≤ t ≤ m) for which the set is a (t, m, 2)-net in base b.
    pub t: u32,
    /// For t > 0: an elementary interval of volume `b^(t−1−m)` that does not hold `b^(t−1)`
    /// points, i.e. why the set is not a (t−1, m, 2)-net. `None` when t = 0.
    pub violation: Option<ElementaryViolation>,
}

/// An elementary interval `[cx·b^−kx, (cx+1)·b^−kx) × [cy·b^−ky, (cy+1)·b^−ky)` whose count
/// differs from the `b^t` a (t, m, 2)-net requires.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct ElementaryViolation {
    /// The t that was tested (`kx + ky = m − t`).
    pub t: u32,
    /// The interval is `b^−kx` wide.
    pub kx: u32,
    /// The interval is `b^−ky` tall.
    pub ky: u32,
    /// Cell indices `(cx, cy)`.
    pub cell: (u64, u64),
    /// Points it holds.
    pub count: usize,
    /// Points it should hold: `b^t`.
    pub expected: usize,
}

/// `⌊x·s⌋` exactly, for `0 ≤ x < 1` and `s` a positive integer below 2⁵³ (exact in f64).
pub(crate) fn exact_floor_scaled(x: f64, s: f64, s_is_pow2: bool) -> u64 {
    let q = x * s;
    let mut c = q.floor();
    if !s_is_pow2 && c > 0.0 {
        // Rounding is monotone, so fl(x·s) ≥ k whenever x·s ≥ k: `c` can only be one too
        // large (when x·s lies just below the integer c). Compare x·s = p + e with c exactly.
        let (p, e) = two_prod(x, s);
        if p < c || (p == c && e < 0.0) {
            c -= 1.0;
        }
    }
    c as u64
}

/// Checks the (t, m, 2)-net property; returns the first violated elementary interval, in
/// order of `kx` then cell index `cx·b^ky + cy`.
fn violation_at(
    digits: &[(u64, u64)],
    pow: &[u64],
    m: u32,
    t: u32,
    cancel: &Cancel,
) -> Result<Option<ElementaryViolation>, MetricsError> {
    let expected = pow[t as usize];
    let cells = pow[(m - t) as usize] as usize;
    let mut counts = vec![0u64; cells];
    for kx in 0..=(m - t) {
        let ky = m - t - kx;
        let div_x = pow[(m - kx) as usize];
        let div_y = pow[(m - ky) as usize];
        let rows = pow[ky as usize];
        counts.fill(0);
        for (i, &(x, y)) in digits.iter().enumerate() {
            if i % CANCEL_STRIDE == 0 {
                cancel.check()?;
            }
            counts[((x / div_x) * rows + y / div_y) as usize] += 1;
        }
        if let Some(c) = counts.iter().position(|&c| c != expected) {
            return Ok(Some(ElementaryViolation {
                t,
                kx,
                ky,
                cell: (c as u64 / rows, c as u64 % rows),
                count: counts[c] as usize,
                expected: expected as usize,
            }));
        }
    }
    Ok(None)
}

/// The t-value of `points` as a net in base `base`: the smallest t such that every
/// elementary interval of volume `b^(t−m)` (all shapes `b^−k × b^−(m−t−k)`) holds exactly
/// `b^t` points, with `N = b^m`. See the module docs for exact boundary handling.
///
/// Errors: `base < 2`; empty or invalid points; N not a power of `base`
/// ([`MetricsError::NotPowerOfBase`]); cancellation.
pub fn t_value(points: &[DVec2], base: u32, cancel: &Cancel) -> Result<TValue, MetricsError> {
    if base < 2 {
        return Err(MetricsError::InvalidBase { base });
    }
    validate(points)?;
    let n = points.len();
    let b = base as u64;
    // pow[k] = b^k for k = 0..=m, with b^m = n.
    let mut pow = vec![1u64];
    while (*pow.last().unwrap_or(&1) as usize) < n {
        match pow.last().and_then(|p| p.checked_mul(b)) {
            Some(p) => pow.push(p),
            None => break,
        }
    }
    let m = pow.len() as u32 - 1;
    if pow[m as usize] != n as u64 {
        return Err(MetricsError::NotPowerOfBase { n, base });
    }
    let s = n as f64; // b^m ≤ N is exact in f64 (N points fit in memory, N < 2⁵³)
    let pow2 = base.is_power_of_two();
    let digits: Vec<(u64, u64)> = points
        .iter()
        .map(|p| {
            (
                exact_floor_scaled(p.x, s, pow2),
                exact_floor_scaled(p.y, s, pow2),
            )
        })
        .collect();

    // Bisection: smallest t in [0, m] with no violation (t = m never fails).
    let (mut lo, mut hi) = (0u32, m);
    while lo < hi {
        let mid = (lo + hi) / 2;
        if violation_at(&digits, &pow, m, mid, cancel)?.is_none() {
            hi = mid;
        } else {
            lo = mid + 1;
        }
    }
    let t = lo;
    let violation = if t > 0 {
        violation_at(&digits, &pow, m, t - 1, cancel)?
    } else {
        None
    };
    Ok(TValue {
        base,
        m,
        t,
        violation,
    })
}

/// One power-of-two prefix `points[..2^k]` checked as a (0, k, 2)-net in base 2.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct PrefixCheck {
    /// The prefix length `2^k`.
    pub n: usize,
    /// `k`.
    pub k: u32,
    /// Whether every elementary interval of area `2^−k` (all shapes `2^−kx × 2^−(k−kx)`) holds
    /// exactly one of the prefix's points.
    pub is_net: bool,
}

/// The (0, k, 2)-net check of every power-of-two prefix of a sequence (what a progressive
/// (0,2)-sequence such as Sobol' or pmj02, with or without Owen scrambling, must pass).
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct NetPrefixes {
    /// Every prefix `2^k ≤ N`, k = 0, 1, …, in order.
    pub prefixes: Vec<PrefixCheck>,
    /// The first prefix that is not a net and its first wrong interval (in order of `kx`, then
    /// column, then row): `violation.t = 0`, `expected = 1`, `cell = (column, row)` counted from
    /// the origin.
    pub first_failure: Option<(PrefixCheck, ElementaryViolation)>,
}

/// Checks every power-of-two prefix `points[..2^k]` (`2^k ≤ N`) for the (0, k, 2)-net property
/// in base 2: every elementary interval `[c·2^−kx, (c+1)·2^−kx) × [r·2^−ky, (r+1)·2^−ky)` with
/// `kx + ky = k` holds exactly one point. Exact for every f64 in [0, 1) (`⌊x·2^k⌋` is exact in
/// base 2). N need not be a power of two: the prefixes are checked up to the largest `2^k ≤ N`.
/// Cost O(N log N) in all (the prefixes' sizes sum to below 2N).
///
/// Errors: empty or invalid points; cancellation.
pub fn net_prefixes(points: &[DVec2], cancel: &Cancel) -> Result<NetPrefixes, MetricsError> {
    validate(points)?;
    let top = usize::BITS - 1 - points.len().leading_zeros(); // ⌊log2 N⌋
    let pow: Vec<u64> = (0..=top).map(|k| 1u64 << k).collect();
    let s = (1u64 << top) as f64;
    // ⌊x·2^top⌋, then ⌊x·2^k⌋ = that >> (top − k).
    let fine: Vec<(u64, u64)> = points[..1 << top]
        .iter()
        .map(|p| {
            (
                exact_floor_scaled(p.x, s, true),
                exact_floor_scaled(p.y, s, true),
            )
        })
        .collect();
    let mut prefixes = Vec::with_capacity(top as usize + 1);
    let mut first_failure = None;
    let mut digits = Vec::with_capacity(fine.len());
    for k in 0..=top {
        let n = 1usize << k;
        let shift = top - k;
        digits.clear();
        digits.extend(fine[..n].iter().map(|&(x, y)| (x >> shift, y >> shift)));
        let violation = violation_at(&digits, &pow, k, 0, cancel)?;
        let check = PrefixCheck {
            n,
            k,
            is_net: violation.is_none(),
        };
        if let (true, Some(v)) = (first_failure.is_none(), violation) {
            first_failure = Some((check, v));
        }
        prefixes.push(check);
    }
    Ok(NetPrefixes {
        prefixes,
        first_failure,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exact_floor_at_non_dyadic_boundaries() {
        // fl(1/3) < 1/3, so ⌊fl(1/3)·3⌋ = 0 although the rounded product is exactly 1.0.
        let third = 1.0 / 3.0;
        assert_eq!(third * 3.0, 1.0);
        assert_eq!(exact_floor_scaled(third, 3.0, false), 0);
        // fl(2/3) < 2/3 too, while fl(fl(2/3)·3) = 2.0: the cell is 1.
        assert_eq!((2.0 / 3.0) * 3.0, 2.0);
        assert_eq!(exact_floor_scaled(2.0 / 3.0, 3.0, false), 1);
        // Exactly representable boundary in base 2: the upper cell.
        assert_eq!(exact_floor_scaled(0.5, 2.0, true), 1);
        assert_eq!(exact_floor_scaled(0.1, 10.0, false), 1); // fl(0.1) > 0.1
    }
}
