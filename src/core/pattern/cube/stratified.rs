//! The stratified patterns in d dimensions: white noise, the Latin hypercube and the regular
//! grid of n = k^D points. Each is the 2D construction with more coordinates per point, so at
//! D = 2 it gives the 2D pattern's bits (tested).
use crate::core::pattern::stratified::lhs_dim_coords;
use crate::core::pattern::{clamp_unit, Grid, Lhs, PatternError};
use crate::core::rng::Rng;

/// White noise: n·dims uniform coordinates from one [`Rng`] stream, row-major (point 0's
/// coordinates first), so every prefix is white noise and D = 2 is the 2D `random`.
pub fn random(n: usize, dims: usize, seed: u64) -> Vec<f64> {
    let mut rng = Rng::new(seed);
    (0..n * dims).map(|_| clamp_unit(rng.next_f64())).collect()
}

/// The Latin hypercube in `dims` dimensions (McKay, Beckman & Conover 1979), the same
/// construction as [`crate::core::pattern::stratified::lhs_points`]: dimension d is
/// `(π_d(i) + ½ + a(u_{d,i} − ½)) / n` with its permutation and jitter from the streams
/// `derive_seed(seed, 2d)` and `derive_seed(seed, 2d + 1)`. So the first k dimensions of a
/// D-dimensional hypercube are the k-dimensional one, and the 2D `lhs`'s projection (x_dim,
/// y_dim) is dimensions x_dim and y_dim of it. Defining property: every 1D projection has one
/// point in each of the n intervals [c/n, (c+1)/n).
pub fn lhs(amount: f64, n: usize, dims: usize, seed: u64) -> Vec<f64> {
    let columns: Vec<Vec<f64>> = (0..dims)
        .map(|d| lhs_dim_coords(n, d, amount, seed))
        .collect();
    let mut out = Vec::with_capacity(n * dims);
    for i in 0..n {
        out.extend(columns.iter().map(|c| c[i]));
    }
    out
}

/// The checks of the d-dimensional [`lhs`]: its `amount` (the 2D `dims`, `x_dim` and `y_dim`
/// choose the projection the 2D pattern shows and do not apply in d dimensions).
pub(super) fn check_lhs(p: &Lhs, _n: usize, _dims: usize) -> Result<(), PatternError> {
    crate::core::pattern::stratified::check_amount(Lhs::NAME, p.amount)
}

/// k with k^dims = n, or [`PatternError::UnsupportedN`] naming the two nearest D-th powers.
/// The 2D grid's `cols` applies to dims = 2 only; in d dimensions it must be 0 (auto) or k.
pub(super) fn check_grid(p: &Grid, n: usize, dims: usize) -> Result<usize, PatternError> {
    let k = integer_root(n, dims);
    if pow_sat(k, dims) != n {
        let above = pow_sat(k + 1, dims);
        return Err(PatternError::UnsupportedN {
            pattern: Grid::NAME,
            n,
            allowed: format!(
                "k^{dims} for an integer k in {dims} dimensions (nearest: {} and {})",
                pow_sat(k, dims),
                above
            ),
        });
    }
    if p.cols != 0 && p.cols as usize != k {
        return Err(PatternError::InvalidParam {
            pattern: Grid::NAME,
            field: "cols",
            value: p.cols.to_string(),
            allowed: format!("0 (auto) or {k} (n = {n} is {k}^{dims}) in {dims} dimensions"),
        });
    }
    Ok(k)
}

/// ⌊n^(1/d)⌋ exactly (an f64 guess corrected by integer powers).
fn integer_root(n: usize, d: usize) -> usize {
    if d == 1 {
        return n;
    }
    let mut k = (n as f64).powf(1.0 / d as f64).round() as usize;
    while k > 0 && pow_sat(k, d) > n {
        k -= 1;
    }
    while pow_sat(k + 1, d) <= n {
        k += 1;
    }
    k
}

/// k^d, saturating at `usize::MAX`.
fn pow_sat(k: usize, d: usize) -> usize {
    let mut p = 1usize;
    for _ in 0..d {
        p = p.saturating_mul(k);
    }
    p
}

/// The regular grid of n = k^dims cell centres, x_i[d] = (c_d + ½)/k where c_0, c_1, … are the
/// base-k digits of i (dimension 0 fastest, as the 2D grid's x). Deterministic.
pub fn grid(p: &Grid, n: usize, dims: usize) -> Result<Vec<f64>, PatternError> {
    let k = check_grid(p, n, dims)?;
    let centres: Vec<f64> = (0..k)
        .map(|c| clamp_unit((c as f64 + 0.5) / k as f64))
        .collect();
    let mut out = Vec::with_capacity(n * dims);
    for i in 0..n {
        let mut rest = i;
        for _ in 0..dims {
            out.push(centres[rest % k]);
            rest /= k;
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn integer_roots_are_exact() {
        for d in 1..=12 {
            for k in 1..=20usize {
                let n = pow_sat(k, d);
                if n > 1 << 40 {
                    continue;
                }
                assert_eq!(integer_root(n, d), k, "{k}^{d}");
                if n > 1 {
                    assert_eq!(integer_root(n - 1, d), k - 1, "{k}^{d} − 1");
                }
            }
        }
    }
}
