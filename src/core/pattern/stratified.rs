//! Stratified patterns: grid, random, jitter, N-rooks, Latin hypercube, multi-jitter,
//! correlated multi-jitter.
//!
//! ## Conventions
//!
//! - **Strata.** A `cols × rows` grid of strata (cells) has cell `(i, j)` = `[i/cols, (i+1)/cols) ×
//!   [j/rows, (j+1)/rows)`, `i` the column (x), `j` the row (y). `cols` = 0 means "auto": the
//!   divisor of `n` nearest √n, not above it ([`divisor_near_sqrt`]); an explicit `cols` must divide `n`.
//! - **Order.** Patterns with one point per coarse cell (grid, jitter, multi-jitter, correlated
//!   multi-jitter) return point `k` in cell `(k mod cols, k div cols)`: row-major, row 0 at y = 0.
//!   N-rooks and LHS return sample `i` as the lecture's column `i` of its permutation table.
//! - **Jitter amount.** A jittered coordinate in a cell of width `w` with lower edge `c` is
//!   `c + w·(½ + a·(u − ½))`, `u` uniform in [0,1): an offset uniform in ±a/2 cell widths around the
//!   cell centre. `a = 0` gives cell centres, `a = 1` "anywhere in the cell" (classic jitter, Cook
//!   1986), `a = 0.5` a perturbation range half a cell wide (±¼ cell), which is how the issue reads
//!   the lecture's "perturb the samples up to ½ width or height".
//! - **Fine grid.** With `n` points, the "N-rooks" property means exactly one point in every column
//!   `[c/n, (c+1)/n)` and every row `[r/n, (r+1)/n)` of the `n × n` fine grid.
//! - **Randomness.** Everything is drawn from [`Rng`] seeded with `seed` (LHS: one derived stream per
//!   dimension, see [`lhs_table`]), so the same `(parameters, n, seed)` gives the same bits.
//! - Every coordinate passes through [`clamp_unit`], so none can round to 1.0.
use super::*;
use crate::core::rng::{derive_seed, Rng};

/// The largest number of table entries (`n · dims`) [`lhs_table`] and [`lhs_points`] build: 2²⁵,
/// the memory of the largest 2D pattern ([`MAX_N`] points × 2 coordinates).
pub const LHS_MAX_VALUES: usize = 1 << 25;

/// Largest dimension count of [`lhs_table`] and [`lhs_points`] (the `Lhs.dims` parameter's range).
pub const LHS_MAX_DIMS: usize = 64;

/// The jittered position within a cell, in cell units: `½ + a·(u − ½)` ∈ [0, 1) for a ∈ [0, 1].
#[inline]
fn offset(amount: f64, u: f64) -> f64 {
    0.5 + amount * (u - 0.5)
}

/// Checks a jitter amount: finite and in [0, 1].
pub(super) fn check_amount(pattern: &'static str, amount: f64) -> Result<(), PatternError> {
    if amount.is_finite() && (0.0..=1.0).contains(&amount) {
        Ok(())
    } else {
        Err(PatternError::InvalidParam {
            pattern,
            field: "amount",
            value: crate::core::params::fmt_num(amount),
            allowed: "a finite number in [0, 1]".into(),
        })
    }
}

/// A uniformly random permutation of `0..n` as `u32` (half the memory of `usize` indices).
/// `n` must be at most 2³², which [`MAX_N`] guarantees.
fn permutation_u32(rng: &mut Rng, n: usize) -> Vec<u32> {
    debug_assert!(n <= u32::MAX as usize + 1);
    let mut p: Vec<u32> = (0..n).map(|i| i as u32).collect();
    rng.shuffle(&mut p);
    p
}

/// Regular grid: the cell centres `x_k = ((i + ½)/cols, (j + ½)/rows)`, `k = j·cols + i`.
///
/// `(cols, rows)` from [`resolve_cols`] (`cols = 0`: the divisor of `n` nearest √n). Deterministic.
///
/// Errors: `n` outside `1..=MAX_N`; `cols` not dividing `n`.
pub fn grid(p: &Grid, n: usize) -> Result<Vec<DVec2>, PatternError> {
    check_n(n, MAX_N)?;
    let (cols, rows) = resolve_cols(Grid::NAME, p.cols, n)?;
    let (w, h) = (cols as f64, rows as f64);
    let mut pts = Vec::with_capacity(n);
    for j in 0..rows {
        let y = clamp_unit((j as f64 + 0.5) / h);
        for i in 0..cols {
            pts.push(DVec2::new(clamp_unit((i as f64 + 0.5) / w), y));
        }
    }
    Ok(pts)
}

/// White noise ("Poisson" in the lecture): `n` independent uniform points `(u_{2k}, u_{2k+1})`
/// from one [`Rng`] stream, so every prefix of the output is itself white noise (progressive).
///
/// Expected periodogram E[P(k)] = 1 for every k ≠ 0.
pub fn random(n: usize, seed: u64) -> Vec<DVec2> {
    let mut rng = Rng::new(seed);
    (0..n)
        .map(|_| {
            let x = rng.next_f64();
            let y = rng.next_f64();
            DVec2::new(clamp_unit(x), clamp_unit(y))
        })
        .collect()
}

/// Jittered (stratified) sampling (Cook 1986, "Stochastic sampling in computer graphics"):
/// one point in each cell of a `cols × rows` grid,
///
/// `x_k = ((i + ½ + a(u − ½))/cols, (j + ½ + a(v − ½))/rows)`, `k = j·cols + i`,
///
/// with `a = p.amount` and `u, v` uniform in [0,1) drawn in the order `u_0, v_0, u_1, v_1, …`.
/// `a = 0` reproduces [`grid`] bit for bit (and ignores the seed); `a = 1` puts the point anywhere
/// in its cell.
///
/// Errors: `n` outside `1..=MAX_N`; `cols` not dividing `n`; `amount` not a finite number in [0, 1].
pub fn jitter(p: &Jitter, n: usize, seed: u64) -> Result<Vec<DVec2>, PatternError> {
    check_n(n, MAX_N)?;
    check_amount(Jitter::NAME, p.amount)?;
    let (cols, rows) = resolve_cols(Jitter::NAME, p.cols, n)?;
    let (w, h) = (cols as f64, rows as f64);
    let a = p.amount;
    let mut rng = Rng::new(seed);
    let mut pts = Vec::with_capacity(n);
    for j in 0..rows {
        for i in 0..cols {
            let u = rng.next_f64();
            let v = rng.next_f64();
            pts.push(DVec2::new(
                clamp_unit((i as f64 + offset(a, u)) / w),
                clamp_unit((j as f64 + offset(a, v)) / h),
            ));
        }
    }
    Ok(pts)
}

/// N-rooks sampling (Shirley 1991), i.e. the 2D Latin hypercube, exactly as the lecture builds it:
/// a jittered sample in each diagonal cell `(c, c)` of the `n × n` grid, then an independent
/// random shuffle of the cell indices in each dimension:
///
/// `x_c = ((π_x(c) + ½ + a(u_c − ½))/n, (π_y(c) + ½ + a(v_c − ½))/n)`, `c = 0 … n−1`,
///
/// `π_x, π_y` independent uniform permutations of `0..n`, `a = p.amount`. Exactly one point lies in
/// every column and every row of the `n × n` grid; each projection is a 1D jittered pattern.
/// Draw order: `u_0, v_0, …, u_{n−1}, v_{n−1}`, then `π_x`, then `π_y` (Fisher–Yates).
///
/// This infallible form is what [`Pattern::generate`] calls, after checking `n`. It does not
/// re-validate its input: `n` outside `1..=MAX_N` gives no points, and an `amount` outside [0, 1]
/// is clamped into it (NaN counts as 1, the default). [`try_nrooks`] reports both as errors.
pub fn nrooks(p: &NRooks, n: usize, seed: u64) -> Vec<DVec2> {
    if n == 0 || n > MAX_N {
        return Vec::new();
    }
    let amount = if p.amount.is_nan() {
        1.0
    } else {
        p.amount.clamp(0.0, 1.0)
    };
    nrooks_points(n, amount, seed)
}

/// [`nrooks`] with its input checked: `n` in `1..=MAX_N`, `amount` a finite number in [0, 1].
pub fn try_nrooks(p: &NRooks, n: usize, seed: u64) -> Result<Vec<DVec2>, PatternError> {
    check_n(n, MAX_N)?;
    check_amount(NRooks::NAME, p.amount)?;
    Ok(nrooks_points(n, p.amount, seed))
}

fn nrooks_points(n: usize, a: f64, seed: u64) -> Vec<DVec2> {
    let mut rng = Rng::new(seed);
    // Jittered diagonal: cell (c, c), position within the cell.
    let jit: Vec<(f64, f64)> = (0..n)
        .map(|_| {
            let u = rng.next_f64();
            let v = rng.next_f64();
            (offset(a, u), offset(a, v))
        })
        .collect();
    let px = permutation_u32(&mut rng, n);
    let py = permutation_u32(&mut rng, n);
    let w = n as f64;
    jit.iter()
        .zip(px.iter().zip(&py))
        .map(|(&(ox, oy), (&cx, &cy))| {
            DVec2::new(
                clamp_unit((cx as f64 + ox) / w),
                clamp_unit((cy as f64 + oy) / w),
            )
        })
        .collect()
}

/// Checks `dims` and the table size `n · dims` of [`lhs_table`] / [`lhs_points`].
fn check_lhs_size(n: usize, dims: usize) -> Result<(), PatternError> {
    check_n(n, MAX_N)?;
    if dims == 0 || dims > LHS_MAX_DIMS {
        return Err(PatternError::InvalidParam {
            pattern: Lhs::NAME,
            field: "dims",
            value: dims.to_string(),
            allowed: format!("an integer in 1..={LHS_MAX_DIMS}"),
        });
    }
    let max = LHS_MAX_VALUES / dims;
    if n > max {
        return Err(PatternError::InvalidN {
            n,
            max,
            why: format!(
                "; a {dims}-dimensional Latin hypercube stores n·dims values, at most {LHS_MAX_VALUES}"
            ),
        });
    }
    Ok(())
}

/// The random streams of LHS dimension `d`: its permutation and its jitter.
///
/// Dimension `d` draws its permutation from `Rng::new(derive_seed(seed, 2d))` and its jitter from
/// `Rng::new(derive_seed(seed, 2d + 1))`, so one dimension can be generated without the others,
/// and the first k dimensions of a (k+1)-dimensional hypercube are those of the k-dimensional one.
fn lhs_dim_perm(n: usize, d: usize, seed: u64) -> Vec<u32> {
    let mut rng = Rng::new(derive_seed(seed, 2 * d as u64));
    permutation_u32(&mut rng, n)
}

/// Coordinates of LHS dimension `d` for all `n` samples: `(π_d(i) + ½ + a(u_{d,i} − ½))/n`.
pub(super) fn lhs_dim_coords(n: usize, d: usize, a: f64, seed: u64) -> Vec<f64> {
    let perm = lhs_dim_perm(n, d, seed);
    let mut rng = Rng::new(derive_seed(seed, 2 * d as u64 + 1));
    let w = n as f64;
    perm.iter()
        .map(|&c| clamp_unit((c as f64 + offset(a, rng.next_f64())) / w))
        .collect()
}

/// The permutation table of a Latin hypercube of `n` samples in `dims` dimensions, laid out as the
/// lecture's `k = 3, n = 10` table: row `d` is dimension `d`, column `i` is sample `i`, and the
/// entry is the **1-based** cell `π_d(i) + 1` of sample `i` along dimension `d` (each row is a
/// permutation of `1..=n`; "s³₁ is from the 8-th cell from dimension 1" reads `table[0][2] = 8`).
///
/// Row `d` is a Fisher–Yates permutation drawn from `Rng::new(derive_seed(seed, 2d))`, the same
/// one [`lhs_points`] and [`lhs`] use for the same `seed`.
///
/// Errors: `n` outside `1..=MAX_N`; `dims` outside `1..=64`; `n · dims` > [`LHS_MAX_VALUES`].
pub fn lhs_table(n: usize, dims: usize, seed: u64) -> Result<Vec<Vec<usize>>, PatternError> {
    check_lhs_size(n, dims)?;
    Ok((0..dims)
        .map(|d| {
            lhs_dim_perm(n, d, seed)
                .into_iter()
                .map(|c| c as usize + 1)
                .collect()
        })
        .collect())
}

/// Latin hypercube sampling (McKay, Beckman & Conover 1979) in `dims` dimensions, as the lecture's
/// "LHS or N-Rooks in k-D": each dimension is divided into `n` cells, each dimension gets its own
/// random permutation `π_d`, and sample `i` is jittered in the cells the permutations assign:
///
/// `s_i[d] = (π_d(i) + ½ + a(u_{d,i} − ½)) / n`,   `i = 0 … n−1`, `d = 0 … dims−1`,
///
/// `π_d(i) + 1` being the entry of [`lhs_table`] (same seed, same table), `u_{d,i}` uniform in
/// [0,1) from dimension `d`'s jitter stream `Rng::new(derive_seed(seed, 2d + 1))`, `a = amount`
/// (0 = cell centres, 1 = anywhere in the cell). Returns `n` samples of `dims` coordinates each.
///
/// Errors: as [`lhs_table`], and `amount` not a finite number in [0, 1].
pub fn lhs_points(
    n: usize,
    dims: usize,
    amount: f64,
    seed: u64,
) -> Result<Vec<Vec<f64>>, PatternError> {
    check_lhs_size(n, dims)?;
    check_amount(Lhs::NAME, amount)?;
    let coords: Vec<Vec<f64>> = (0..dims)
        .map(|d| lhs_dim_coords(n, d, amount, seed))
        .collect();
    Ok((0..n)
        .map(|i| coords.iter().map(|c| c[i]).collect())
        .collect())
}

/// The checks of [`lhs`]: `n`, `dims`, `x_dim`, `y_dim` and `amount`.
pub(super) fn check_lhs(p: &Lhs, n: usize) -> Result<(), PatternError> {
    check_n(n, MAX_N)?;
    let dims = p.dims as usize;
    if dims == 0 || dims > LHS_MAX_DIMS {
        return Err(PatternError::InvalidParam {
            pattern: Lhs::NAME,
            field: "dims",
            value: p.dims.to_string(),
            allowed: format!("an integer in 1..={LHS_MAX_DIMS}"),
        });
    }
    let dim_range = |field: &'static str, v: u32| PatternError::InvalidParam {
        pattern: Lhs::NAME,
        field,
        value: v.to_string(),
        allowed: format!("an integer in 0..={} (below dims = {dims})", dims - 1),
    };
    if p.x_dim as usize >= dims {
        return Err(dim_range("x_dim", p.x_dim));
    }
    if p.y_dim as usize >= dims {
        return Err(dim_range("y_dim", p.y_dim));
    }
    if dims >= 2 && p.x_dim == p.y_dim {
        return Err(PatternError::InvalidParam {
            pattern: Lhs::NAME,
            field: "y_dim",
            value: p.y_dim.to_string(),
            allowed: format!(
                "an integer in 0..={} different from x_dim = {}",
                dims - 1,
                p.x_dim
            ),
        });
    }
    check_amount(Lhs::NAME, p.amount)
}

/// The 2D projection `(s_i[x_dim], s_i[y_dim])` of the `dims`-dimensional Latin hypercube of
/// [`lhs_points`] (same seed, same bits). Only the two shown dimensions are generated, so the cost
/// is O(n) whatever `dims`.
///
/// `x_dim` and `y_dim` must be distinct and below `dims`; the one exception is `dims = 1`, where
/// `x_dim = y_dim = 0` shows the single dimension against itself (all points on the diagonal).
///
/// Errors: `n` outside `1..=MAX_N`; `dims` outside `1..=64`; `x_dim` or `y_dim` ≥ `dims`;
/// `x_dim = y_dim` with `dims ≥ 2`; `amount` not a finite number in [0, 1].
pub fn lhs(p: &Lhs, n: usize, seed: u64) -> Result<Vec<DVec2>, PatternError> {
    check_lhs(p, n)?;
    let xs = lhs_dim_coords(n, p.x_dim as usize, p.amount, seed);
    let ys = if p.y_dim == p.x_dim {
        xs.clone()
    } else {
        lhs_dim_coords(n, p.y_dim as usize, p.amount, seed)
    };
    Ok(xs
        .into_iter()
        .zip(ys)
        .map(|(x, y)| DVec2::new(x, y))
        .collect())
}

/// Multi-jittered sampling (Chiu, Shirley & Wang 1994, "Multi-jittered sampling", Graphics Gems IV):
/// jittered in the `cols × rows` grid *and* N-rooks in the `n × n` fine grid, `n = cols·rows`.
///
/// Canonical arrangement: coarse cell `(i, j)` holds the point in fine column `i·rows + j` and fine
/// row `j·cols + i`. Then, for every coarse column `i`, the fine-column indices of its `rows`
/// points are shuffled among themselves (an independent permutation `σ_i` of `0..rows`), and for
/// every coarse row `j` the fine-row indices of its `cols` points (independent `τ_j` of `0..cols`):
///
/// `x_{ij} = (i·rows + σ_i(j) + u_{ij}) / n`,   `y_{ij} = (j·cols + τ_j(i) + v_{ij}) / n`,
///
/// point `k = j·cols + i`. Shuffling within a coarse column keeps every x inside that column
/// (jittered property) and keeps the set of fine columns (N-rooks property); likewise for y.
/// These are the swap loops of the paper (as written out by Kensler 2013, listing 2) in
/// permutation form. Draw order: `σ_0, u_{0·}, σ_1, u_{1·}, …` (column by column, `u` down the
/// column), then `τ_0, v_{·0}, τ_1, …` (row by row).
///
/// Errors: `n` outside `1..=MAX_N`; `cols` not dividing `n`.
pub fn multijitter(p: &MultiJitter, n: usize, seed: u64) -> Result<Vec<DVec2>, PatternError> {
    check_n(n, MAX_N)?;
    let (cols, rows) = resolve_cols(MultiJitter::NAME, p.cols, n)?;
    let mut rng = Rng::new(seed);
    let nf = n as f64;
    let mut pts = vec![DVec2::ZERO; n];
    let mut perm: Vec<u32> = (0..rows as u32).collect();
    for i in 0..cols {
        rng.shuffle(&mut perm);
        for (j, &s) in perm.iter().enumerate() {
            let u = rng.next_f64();
            pts[j * cols + i].x = clamp_unit(((i * rows + s as usize) as f64 + u) / nf);
        }
    }
    let mut perm: Vec<u32> = (0..cols as u32).collect();
    for j in 0..rows {
        rng.shuffle(&mut perm);
        for (i, &s) in perm.iter().enumerate() {
            let v = rng.next_f64();
            pts[j * cols + i].y = clamp_unit(((j * cols + s as usize) as f64 + v) / nf);
        }
    }
    Ok(pts)
}

/// Correlated multi-jittered sampling (Kensler 2013, "Correlated Multi-Jittered Sampling", Pixar
/// Technical Memo 13-01): multi-jitter where the same shuffle is applied to every coarse column
/// (and every coarse row), which lowers the clumping of plain multi-jitter.
///
/// With `m = cols`, `r = rows`, `n = m·r`, one permutation `π_x` of `0..m` and one `π_y` of `0..r`,
/// sample `s` (coarse cell `i = s mod m`, `j = s div m`) is Kensler's final `cmj` formula
///
/// `x_s = (i + (π_y(j) + u_s)/r) / m = (i·r + π_y(j) + u_s) / n`,
/// `y_s = (j + (π_x(i) + v_s)/m) / r = (j·m + π_x(i) + v_s) / n`
///
/// (evaluated in the right-hand, single-division form). Kensler draws `π_x, π_y` with his
/// hash-based `permute(i, l, p)` and the jitter with `randfloat(s, p)`, so that sample `s` can be
/// computed alone; here both come from [`Rng`] instead: `π_x`, then `π_y` (Fisher–Yates), then
/// `u_0, v_0, u_1, v_1, …` in sample order. The distribution is the same (uniform permutations,
/// uniform jitter); the bits differ from his code. Jittered in the `m × r` grid and N-rooks in
/// the `n × n` grid; within every coarse column the sub-column order depends on the row only.
///
/// Errors: `n` outside `1..=MAX_N`; `cols` not dividing `n`.
pub fn correlated_multijitter(
    p: &CorrelatedMultiJitter,
    n: usize,
    seed: u64,
) -> Result<Vec<DVec2>, PatternError> {
    check_n(n, MAX_N)?;
    let (cols, rows) = resolve_cols(CorrelatedMultiJitter::NAME, p.cols, n)?;
    let mut rng = Rng::new(seed);
    let px = permutation_u32(&mut rng, cols);
    let py = permutation_u32(&mut rng, rows);
    let nf = n as f64;
    let mut pts = Vec::with_capacity(n);
    for (j, &sy) in py.iter().enumerate() {
        for (i, &sx) in px.iter().enumerate() {
            let u = rng.next_f64();
            let v = rng.next_f64();
            pts.push(DVec2::new(
                clamp_unit(((i * rows + sy as usize) as f64 + u) / nf),
                clamp_unit(((j * cols + sx as usize) as f64 + v) / nf),
            ));
        }
    }
    Ok(pts)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn offset_extremes_stay_inside_the_cell() {
        // u = 0 and the largest u < 1, at full amount: [0, 1) in cell units.
        assert_eq!(offset(1.0, 0.0), 0.0);
        assert!(offset(1.0, ONE_MINUS_EPSILON) < 1.0);
        assert_eq!(offset(0.0, 0.123), 0.5);
        assert_eq!(offset(0.5, 0.0), 0.25);
    }

    #[test]
    fn permutation_u32_matches_rng_permutation() {
        // Same Fisher–Yates draws as Rng::permutation (the reference), just narrower integers.
        let a = permutation_u32(&mut Rng::new(9), 257);
        let b = Rng::new(9).permutation(257);
        assert!(a.iter().zip(&b).all(|(&x, &y)| x as usize == y));
    }

    #[test]
    fn nrooks_infallible_form_on_out_of_range_input() {
        let p = NRooks { amount: 1.0 };
        assert!(nrooks(&p, 0, 1).is_empty());
        assert!(nrooks(&p, MAX_N + 1, 1).is_empty());
        // amount clamped to [0,1]; NaN is the default 1.
        let nan = nrooks(&NRooks { amount: f64::NAN }, 50, 3);
        assert_eq!(nan, nrooks(&NRooks { amount: 1.0 }, 50, 3));
        let big = nrooks(&NRooks { amount: 7.0 }, 50, 3);
        assert_eq!(big, nan);
        assert!(matches!(
            try_nrooks(&NRooks { amount: f64::NAN }, 50, 3),
            Err(PatternError::InvalidParam {
                field: "amount",
                ..
            })
        ));
        assert!(matches!(
            try_nrooks(&p, 0, 3),
            Err(PatternError::InvalidN { n: 0, .. })
        ));
        assert_eq!(try_nrooks(&p, 50, 3).unwrap(), nrooks(&p, 50, 3));
    }

    #[test]
    fn lhs_dimensions_are_shared_between_dim_counts() {
        // The first k rows of a (k+1)-dim table are the k-dim table (per-dimension streams).
        let t3 = lhs_table(12, 3, 5).unwrap();
        let t4 = lhs_table(12, 4, 5).unwrap();
        assert_eq!(&t4[..3], &t3[..]);
    }

    #[test]
    fn lhs_table_size_limit() {
        let max = LHS_MAX_VALUES / 64;
        assert!(matches!(
            lhs_table(max + 1, 64, 0),
            Err(PatternError::InvalidN { n, max: m, .. }) if n == max + 1 && m == max
        ));
        assert!(matches!(
            lhs_points(10, 0, 1.0, 0),
            Err(PatternError::InvalidParam { field: "dims", .. })
        ));
        assert!(matches!(
            lhs_points(10, 65, 1.0, 0),
            Err(PatternError::InvalidParam { field: "dims", .. })
        ));
        assert!(matches!(
            lhs_points(10, 3, -0.1, 0),
            Err(PatternError::InvalidParam {
                field: "amount",
                ..
            })
        ));
    }
}
