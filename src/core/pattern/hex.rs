//! Hexagonal lattice on the torus.
//!
//! The lecture's aside: "Cartesian is NOT the optimal way to divide up space uniformly …
//! hexagonal is optimal in 2D". This module fits a hexagonal lattice to the unit torus so that
//! it tiles periodically (its spectrum has no seam).
//!
//! ## Construction
//!
//! `n = rows · cols` points; horizontal spacing `a = 1/cols`, row spacing `h = 1/rows`. Point
//! `k = j·cols + i` (row `j`, column `i`) sits at
//!
//! `x = ((i + ½ + ½·[j odd]) mod cols) / cols`,   `y = (j + ½) / rows`,
//!
//! so odd rows are shifted by half a spacing. The shift alternates, so the lattice wraps
//! vertically only when `rows` is **even** (row `rows − 1` must be odd to neighbour row 0):
//! `n` must be even and `rows` an even divisor of it. The lattice is equilateral (every point has
//! six neighbours at distance `a`) when `h = a·√3/2`, i.e. `cols/rows = √3/2`; a rational torus
//! fit can only approach that ([`hex_aspect_error`]).
//!
//! With `amount > 0` each point is jittered uniformly in its `a × h` cell:
//! `x += a·amount·(u − ½)`, `y += h·amount·(v − ½)` (wrapped on the torus), `u, v` drawn from
//! [`Rng`]`::new(seed)` in the order `u_0, v_0, u_1, …`. With `amount = 0` the seed is unused.
use super::*;
use crate::core::rng::Rng;

/// How far a `rows × cols` torus lattice is from equilateral: `|ln(h / (a·√3/2))|` with
/// `a = 1/cols`, `h = 1/rows`, i.e. `|ln(2·cols / (√3·rows))|`.
///
/// 0 means equilateral triangles; `ln 2 ≈ 0.693` means rows twice (or half) as far apart as in the
/// equilateral lattice with the same horizontal spacing. Symmetric in stretching and squashing.
/// Returns `+∞` when `rows` or `cols` is 0 (a degenerate lattice).
pub fn hex_aspect_error(rows: usize, cols: usize) -> f64 {
    if rows == 0 || cols == 0 {
        return f64::INFINITY;
    }
    (2.0 * cols as f64 / (3f64.sqrt() * rows as f64)).ln().abs()
}

/// Resolves the `rows` parameter of [`Hex`] for `n` points into `(rows, cols)`, `rows · cols = n`.
///
/// `rows = 0` (auto) picks the even divisor of `n` with the smallest [`hex_aspect_error`] (ties:
/// the fewer rows). An explicit `rows` must be an even divisor of `n`.
///
/// Errors: `n` outside `1..=MAX_N`; `n` odd ([`PatternError::UnsupportedN`]: no even row count
/// exists); `rows` not an even divisor of `n` ([`PatternError::InvalidParam`] on `rows`, listing
/// the allowed values).
pub fn hex_shape(rows: u32, n: usize) -> Result<(usize, usize), PatternError> {
    check_n(n, MAX_N)?;
    if n % 2 != 0 {
        return Err(PatternError::UnsupportedN {
            pattern: "hex",
            n,
            allowed: format!(
                "an even integer in 2..={MAX_N} (hex needs an even number of rows: the \
                 half-spacing shift of odd rows must wrap on the torus)"
            ),
        });
    }
    let even_divisors = even_divisors(n);
    if rows == 0 {
        let mut best = (f64::INFINITY, 0usize);
        for &r in &even_divisors {
            let e = hex_aspect_error(r, n / r);
            if e < best.0 {
                best = (e, r);
            }
        }
        // n even: 2 divides n, so there is at least one candidate with finite error.
        return Ok((best.1, n / best.1));
    }
    let r = rows as usize;
    if r % 2 != 0 || n % r != 0 {
        let list = if even_divisors.len() <= 32 {
            format!(
                ": {}",
                even_divisors
                    .iter()
                    .map(|d| d.to_string())
                    .collect::<Vec<_>>()
                    .join(", ")
            )
        } else {
            String::new()
        };
        return Err(PatternError::InvalidParam {
            pattern: Hex::NAME,
            field: "rows",
            value: rows.to_string(),
            allowed: format!("0 (auto) or an even divisor of n = {n}{list}"),
        });
    }
    Ok((r, n / r))
}

/// The even divisors of `n`, ascending (O(√n)).
fn even_divisors(n: usize) -> Vec<usize> {
    let mut small = Vec::new();
    let mut large = Vec::new();
    let mut d = 1;
    while d * d <= n {
        if n % d == 0 {
            small.push(d);
            if d * d != n {
                large.push(n / d);
            }
        }
        d += 1;
    }
    small
        .into_iter()
        .chain(large.into_iter().rev())
        .filter(|d| d % 2 == 0)
        .collect()
}

/// The shortest toroidal distance between two distinct points of the (unjittered) `rows × cols`
/// hexagonal lattice on the unit torus.
///
/// The lattice vectors are `((k₁ + k₂/2)·a, k₂·h)`; the shortest ones are `(a, 0)`, `(0, 2h)` and
/// `(a/2, h)`, except those that are periods of the torus (they join a point to itself):
/// `(a, 0)` when `cols = 1`, `(0, 2h)` when `rows = 2`. Hence
///
/// `d_min = min(a [cols ≥ 2], 2h [rows ≥ 4], √(a²/4 + h²))`,   `a = 1/cols`, `h = 1/rows`.
///
/// Errors: `rows` not even and ≥ 2 (field `rows`), `cols` = 0 (field `cols`).
pub fn hex_spacing(rows: usize, cols: usize) -> Result<f64, PatternError> {
    if rows < 2 || rows % 2 != 0 {
        return Err(PatternError::InvalidParam {
            pattern: Hex::NAME,
            field: "rows",
            value: rows.to_string(),
            allowed: "an even integer ≥ 2".into(),
        });
    }
    if cols == 0 {
        return Err(PatternError::InvalidParam {
            pattern: Hex::NAME,
            field: "cols",
            value: cols.to_string(),
            allowed: "an integer ≥ 1".into(),
        });
    }
    let a = 1.0 / cols as f64;
    let h = 1.0 / rows as f64;
    let mut d = (0.5 * a).hypot(h);
    if cols >= 2 {
        d = d.min(a);
    }
    if rows >= 4 {
        d = d.min(2.0 * h);
    }
    Ok(d)
}

/// The checks of [`hex`]: `n`, `amount` and `rows`; the lattice's (rows, columns).
pub(super) fn check_hex(p: &Hex, n: usize) -> Result<(usize, usize), PatternError> {
    check_n(n, MAX_N)?;
    if !(p.amount.is_finite() && (0.0..=1.0).contains(&p.amount)) {
        return Err(PatternError::InvalidParam {
            pattern: Hex::NAME,
            field: "amount",
            value: crate::core::params::fmt_num(p.amount),
            allowed: "a finite number in [0, 1]".into(),
        });
    }
    hex_shape(p.rows, n)
}

/// The hexagonal lattice of the module docs: `rows` from [`hex_shape`] (0 = the even divisor of
/// `n` closest to equilateral), optionally jittered by `amount` within each point's `a × h` cell.
///
/// Errors: `n` outside `1..=MAX_N` or odd; `rows` not 0 or an even divisor of `n`; `amount` not a
/// finite number in [0, 1].
pub fn hex(p: &Hex, n: usize, seed: u64) -> Result<Vec<DVec2>, PatternError> {
    let (rows, cols) = check_hex(p, n)?;
    // x = (2i + 1 + [j odd]) / (2 cols), wrapped: one exact integer numerator, one division.
    let (x_den, y_den) = (2.0 * cols as f64, 2.0 * rows as f64);
    let mut rng = (p.amount > 0.0).then(|| Rng::new(seed));
    let mut pts = Vec::with_capacity(n);
    for j in 0..rows {
        let y0 = (2 * j + 1) as f64 / y_den;
        for i in 0..cols {
            let x0 = ((2 * i + 1 + (j & 1)) % (2 * cols)) as f64 / x_den;
            let pt = match rng.as_mut() {
                None => DVec2::new(x0, y0),
                Some(rng) => {
                    let u = rng.next_f64();
                    let v = rng.next_f64();
                    DVec2::new(
                        (x0 + p.amount * (u - 0.5) / cols as f64).rem_euclid(1.0),
                        (y0 + p.amount * (v - 0.5) / rows as f64).rem_euclid(1.0),
                    )
                }
            };
            pts.push(DVec2::new(clamp_unit(pt.x), clamp_unit(pt.y)));
        }
    }
    Ok(pts)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Naive reference: every even d in 1..=n dividing n.
    fn even_divisors_naive(n: usize) -> Vec<usize> {
        (1..=n).filter(|d| n % d == 0 && d % 2 == 0).collect()
    }

    #[test]
    fn even_divisors_match_naive() {
        for n in 1..=400 {
            assert_eq!(even_divisors(n), even_divisors_naive(n), "n = {n}");
        }
    }

    /// Naive reference: min over all pairs of the toroidal distance of the unjittered lattice.
    fn brute_min_distance(rows: usize, cols: usize) -> f64 {
        let n = rows * cols;
        let pts = hex(
            &Hex {
                rows: rows as u32,
                amount: 0.0,
            },
            n,
            0,
        )
        .unwrap();
        let mut best = f64::INFINITY;
        for (k, p) in pts.iter().enumerate() {
            for q in &pts[k + 1..] {
                let mut d = (*p - *q).abs();
                d.x = d.x.min(1.0 - d.x);
                d.y = d.y.min(1.0 - d.y);
                best = best.min(d.length());
            }
        }
        best
    }

    #[test]
    fn hex_spacing_matches_brute_force_on_degenerate_shapes() {
        // Includes cols = 1 (no horizontal neighbour), rows = 2 (row j+2 is row j), tall and flat.
        for (rows, cols) in [
            (2, 1),
            (2, 2),
            (2, 7),
            (4, 1),
            (16, 1),
            (20, 2),
            (2, 30),
            (6, 5),
            (8, 7),
            (10, 10),
        ] {
            let want = brute_min_distance(rows, cols);
            let got = hex_spacing(rows, cols).unwrap();
            assert!((got - want).abs() < 1e-12, "{rows}x{cols}: {got} vs {want}");
        }
    }

    #[test]
    fn hex_spacing_rejects_odd_rows_and_zero_cols() {
        assert!(matches!(
            hex_spacing(3, 4),
            Err(PatternError::InvalidParam { field: "rows", .. })
        ));
        assert!(matches!(
            hex_spacing(0, 4),
            Err(PatternError::InvalidParam { field: "rows", .. })
        ));
        assert!(matches!(
            hex_spacing(4, 0),
            Err(PatternError::InvalidParam { field: "cols", .. })
        ));
    }

    #[test]
    fn hex_aspect_error_closed_form() {
        // 8 rows × 7 cols: 2·7/(√3·8) = 1.010362971081845; ln of it = 0.0103097…
        let e = hex_aspect_error(8, 7);
        assert!((e - (14.0 / (8.0 * 3f64.sqrt())).ln()).abs() < 1e-15);
        assert!((e - 0.010_309_7).abs() < 1e-6, "{e}");
        // 2 × 2: ln(2/√3) = ln 2 − ½ ln 3.
        let want = 2f64.ln() - 0.5 * 3f64.ln();
        assert!((hex_aspect_error(2, 2) - want).abs() < 1e-15);
        assert_eq!(hex_aspect_error(0, 3), f64::INFINITY);
        assert_eq!(hex_aspect_error(3, 0), f64::INFINITY);
    }
}
