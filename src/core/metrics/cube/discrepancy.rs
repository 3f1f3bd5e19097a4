//! The five L2-type discrepancies of a point set in [0,1)^d: L2-star, centred (CD),
//! wrap-around (WD), mixture (MD) and symmetric (SD), each the same number
//! `scipy.stats.qmc.discrepancy` gives where scipy has it.
//!
//! Every one is `A(d) − (c₁/N) Σ_i Π_k g(x_ik) + (c₂/N²) Σ_i Σ_j Π_k h(x_ik, x_jk)`:
//!
//! | measure | A(d) | c₁ | g(x) | c₂ | h(a, b) | reported |
//! |---|---|---|---|---|---|---|
//! | L2-star (Warnock 1972) | 3^−d | 2^(1−d) | 1 − x² | 1 | 1 − max(a, b) | the root T = √(…) |
//! | CD (Hickernell 1998) | (13/12)^d | 2 | 1 + ½\|x−½\| − ½\|x−½\|² | 1 | 1 + ½\|a−½\| + ½\|b−½\| − ½\|a−b\| | the square CD² |
//! | WD (Hickernell 1998) | −(4/3)^d | 0 | — | 1 | 3/2 − \|a−b\| + \|a−b\|² | the square WD² |
//! | MD (Zhou, Fang, Ning 2013) | (19/12)^d | 2 | 5/3 − ¼\|x−½\| − ¼\|x−½\|² | 1 | 15/8 − ¼\|a−½\| − ¼\|b−½\| − ¾\|a−b\| + ½\|a−b\|² | the square MD² |
//! | SD (Hickernell 1998) | (4/3)^d | 2 | 1 + 2x − 2x² | 2^d | 1 − \|a−b\| | the square SD² |
//!
//! **What is reported follows scipy** (1.17, `scipy.stats.qmc.discrepancy`): its `L2-star`
//! takes the square root (Warnock's T_N, the same number as the 2D
//! [`crate::core::metrics::l2_star_discrepancy`] at d = 2), while its `CD`, `WD` and `MD`
//! return the right-hand sides of Zhou et al.'s equations 9, 10 and 18, the *squared*
//! discrepancies. scipy has no symmetric discrepancy; SD is reported squared like CD, WD and
//! MD (Fang, Li, Sudjianto, *Design and Modeling for Computer Experiments*, 2006, eq. 3.8 form).
//!
//! # Three ways to the same number
//! - [`discrepancy_naive`]: scipy's loops literally (`workers = 1`): the factors evaluated in
//!   scipy's order, every sum a plain f64 running sum, the constants as scipy writes them
//!   (`pow`). It reproduces scipy's value to a few units in the last place and is the reference
//!   of the fast path's *formula*.
//! - [`discrepancy_reference`]: every factor, product and sum in double-double (~106 bits),
//!   the constants exact to that precision: the reference of the fast path's *accuracy*
//!   (tests compare it with an mpmath evaluation of the same formula).
//! - [`discrepancy`] / [`discrepancies`], the fast path: h is symmetric, so the double sum is
//!   `Σ_i h_ii + 2 Σ_{i<j} h_ij` (half the pairs); rows run in parallel on rayon's pool in
//!   batches (cancel checked and progress reported between batches); each pair's product is
//!   an f64 product of f64 factors (as scipy's; their constants 1, ½, ¼, ¾, 3/2, 15/8 are
//!   exact in f64), but every sum (per row, then over the rows in row order, so the result
//!   does not depend on the number of threads) is a double-double sum, the single sum (O(N·d))
//!   is in double-double throughout (its constant 5/3 is not exact in f64), and the constant
//!   A(d) is a double-double power.
//!
//! # Accuracy
//! Every factor and every term of the two sums is positive (h ≥ 1 for CD, > 0 for the others),
//! so the sums themselves lose nothing; the loss is in the final `A − t₁ + t₂`, where the
//! three terms are up to κ = (|A| + t₁ + t₂)/|value| times the result (κ ≈ 10²–10⁴ for the
//! low-discrepancy sets of the tests). The fast path's error is the rounding of each product
//! (≤ (2d + 4) ulps relative per term, random in sign) times κ; scipy's adds the error of its
//! plain running sum over N² terms. The tests bound both against the mpmath reference.
//!
//! **Range.** The terms leave f64's range above [`DISCREPANCY_MAX_DIMS`] dimensions (3^−d
//! underflows from d = 647, 2^d overflows from d = 1024): the functions refuse more
//! dimensions ([`MetricsError::TooManyDims`]) instead of returning 0, ∞ or NaN.

use rayon::prelude::*;

use super::super::dd::Dd;
use super::{check_cube, pair_batches};
use crate::core::cube::CubePoints;
use crate::core::metrics::{Cancel, MetricsError};
use crate::core::progress::{OnProgress, Progress};
use serde::Serialize;

/// The most dimensions the discrepancies accept (see the module docs' "Range").
pub const DISCREPANCY_MAX_DIMS: usize = 512;

/// One of the five discrepancies.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
pub enum Discrepancy {
    /// Warnock's L2-star discrepancy T_N (the root).
    L2Star,
    /// Hickernell's centred L2 discrepancy, squared.
    Centered,
    /// Hickernell's wrap-around L2 discrepancy, squared.
    WrapAround,
    /// Zhou, Fang and Ning's mixture discrepancy, squared.
    Mixture,
    /// Hickernell's symmetric L2 discrepancy, squared.
    Symmetric,
}

impl Discrepancy {
    /// All five, in the order they are reported.
    pub const ALL: [Discrepancy; 5] = [
        Discrepancy::L2Star,
        Discrepancy::Centered,
        Discrepancy::WrapAround,
        Discrepancy::Mixture,
        Discrepancy::Symmetric,
    ];

    /// The key of `analyze --json`.
    pub fn key(self) -> &'static str {
        match self {
            Discrepancy::L2Star => "l2_star_discrepancy",
            Discrepancy::Centered => "centered_discrepancy",
            Discrepancy::WrapAround => "wraparound_discrepancy",
            Discrepancy::Mixture => "mixture_discrepancy",
            Discrepancy::Symmetric => "symmetric_discrepancy",
        }
    }

    /// The name printed by `analyze`, saying whether it is the square.
    pub fn label(self) -> &'static str {
        match self {
            Discrepancy::L2Star => "L2-star discrepancy",
            Discrepancy::Centered => "centred discrepancy CD² (squared)",
            Discrepancy::WrapAround => "wrap-around discrepancy WD² (squared)",
            Discrepancy::Mixture => "mixture discrepancy MD² (squared)",
            Discrepancy::Symmetric => "symmetric discrepancy SD² (squared)",
        }
    }

    /// scipy's `method` name, `None` for SD (scipy has none).
    pub fn scipy_method(self) -> Option<&'static str> {
        match self {
            Discrepancy::L2Star => Some("L2-star"),
            Discrepancy::Centered => Some("CD"),
            Discrepancy::WrapAround => Some("WD"),
            Discrepancy::Mixture => Some("MD"),
            Discrepancy::Symmetric => None,
        }
    }
}

/// The five discrepancies of one point set.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Discrepancies {
    /// Warnock's T_N (the root, as scipy's `L2-star`).
    pub l2_star: f64,
    /// CD² (squared, as scipy's `CD`).
    pub centered: f64,
    /// WD² (squared, as scipy's `WD`).
    pub wraparound: f64,
    /// MD² (squared, as scipy's `MD`).
    pub mixture: f64,
    /// SD² (squared, like the other three).
    pub symmetric: f64,
}

impl Discrepancies {
    /// The value of one of them.
    pub fn get(&self, which: Discrepancy) -> f64 {
        match which {
            Discrepancy::L2Star => self.l2_star,
            Discrepancy::Centered => self.centered,
            Discrepancy::WrapAround => self.wraparound,
            Discrepancy::Mixture => self.mixture,
            Discrepancy::Symmetric => self.symmetric,
        }
    }
}

/// The arithmetic the formulas are written in once: f64 (scipy's and the fast path's) and
/// double-double (the reference).
pub(crate) trait Real: Copy {
    /// An f64 taken exactly.
    fn lit(v: f64) -> Self;
    /// p/q: rounded once in f64 (as scipy's literal `5.0 / 3.0`), to ~106 bits in Dd.
    fn ratio(p: f64, q: f64) -> Self;
    fn add(self, o: Self) -> Self;
    fn sub(self, o: Self) -> Self;
    fn mul(self, o: Self) -> Self;
    fn abs(self) -> Self;
    fn max(self, o: Self) -> Self;
}

impl Real for f64 {
    #[inline(always)]
    fn lit(v: f64) -> Self {
        v
    }
    #[inline(always)]
    fn ratio(p: f64, q: f64) -> Self {
        p / q
    }
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        self + o
    }
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        self - o
    }
    #[inline(always)]
    fn mul(self, o: Self) -> Self {
        self * o
    }
    #[inline(always)]
    fn abs(self) -> Self {
        f64::abs(self)
    }
    #[inline(always)]
    fn max(self, o: Self) -> Self {
        // scipy's C++ `max(a, b)`: `a < b ? b : a`.
        if self < o {
            o
        } else {
            self
        }
    }
}

impl Real for Dd {
    fn lit(v: f64) -> Self {
        Dd::from_f64(v)
    }
    fn ratio(p: f64, q: f64) -> Self {
        Dd::from_f64(p).div_f64(q)
    }
    fn add(self, o: Self) -> Self {
        Dd::add(self, o)
    }
    fn sub(self, o: Self) -> Self {
        Dd::add(self, o.neg())
    }
    fn mul(self, o: Self) -> Self {
        Dd::mul(self, o)
    }
    fn abs(self) -> Self {
        if self.hi < 0.0 || (self.hi == 0.0 && self.lo < 0.0) {
            self.neg()
        } else {
            self
        }
    }
    fn max(self, o: Self) -> Self {
        if (self.hi, self.lo) < (o.hi, o.lo) {
            o
        } else {
            self
        }
    }
}

/// g and h of each measure, in scipy's order of evaluation (left to right as its Cython
/// source writes them; `u**2` as `u·u`).
#[inline(always)]
fn point_factor<R: Real>(which: Discrepancy, x: R) -> R {
    let half = R::lit(0.5);
    match which {
        Discrepancy::L2Star => R::lit(1.0).sub(x.mul(x)),
        Discrepancy::Centered => {
            let u = x.sub(half).abs();
            R::lit(1.0).add(half.mul(u)).sub(half.mul(u.mul(u)))
        }
        Discrepancy::WrapAround => R::lit(1.0), // c₁ = 0: never summed
        Discrepancy::Mixture => {
            let u = x.sub(half).abs();
            let q = R::lit(0.25);
            R::ratio(5.0, 3.0).sub(q.mul(u)).sub(q.mul(u.mul(u)))
        }
        Discrepancy::Symmetric => {
            let two = R::lit(2.0);
            R::lit(1.0).add(two.mul(x)).sub(two.mul(x.mul(x)))
        }
    }
}

#[inline(always)]
fn pair_factor<R: Real>(which: Discrepancy, a: R, b: R) -> R {
    let half = R::lit(0.5);
    match which {
        Discrepancy::L2Star => R::lit(1.0).sub(a.max(b)),
        Discrepancy::Centered => R::lit(1.0)
            .add(half.mul(a.sub(half).abs()))
            .add(half.mul(b.sub(half).abs()))
            .sub(half.mul(a.sub(b).abs())),
        Discrepancy::WrapAround => {
            let t = a.sub(b).abs();
            R::lit(1.5).sub(t).add(t.mul(t))
        }
        Discrepancy::Mixture => {
            let t = a.sub(b).abs();
            let q = R::lit(0.25);
            R::ratio(15.0, 8.0)
                .sub(q.mul(a.sub(half).abs()))
                .sub(q.mul(b.sub(half).abs()))
                .sub(R::ratio(3.0, 4.0).mul(t))
                .add(half.mul(t.mul(t)))
        }
        Discrepancy::Symmetric => R::lit(1.0).sub(a.sub(b).abs()),
    }
}

/// Whether the single sum appears (c₁ ≠ 0).
fn has_point_sum(which: Discrepancy) -> bool {
    which != Discrepancy::WrapAround
}

/// `A(d) − (c₁/N)·s₁ + (c₂/N²)·s₂` exactly as scipy writes it (f64, `pow`), the root for
/// L2-star.
fn combine_scipy(which: Discrepancy, d: usize, n: usize, s1: f64, s2: f64) -> f64 {
    let df = d as f64;
    let nf = n as f64;
    let inv_n2 = 1.0 / (nf * nf);
    match which {
        Discrepancy::L2Star => {
            let one_div_n = 1.0 / nf;
            (3f64.powf(-df) - one_div_n * 2f64.powf(1.0 - df) * s1 + inv_n2 * s2).sqrt()
        }
        Discrepancy::Centered => (13.0f64 / 12.0).powf(df) - 2.0 / nf * s1 + inv_n2 * s2,
        Discrepancy::WrapAround => -(4.0f64 / 3.0).powf(df) + inv_n2 * s2,
        Discrepancy::Mixture => {
            let a = (19.0f64 / 12.0).powf(df);
            let t1 = 2.0 / nf * s1;
            let t2 = inv_n2 * s2;
            a - t1 + t2
        }
        Discrepancy::Symmetric => {
            (4.0f64 / 3.0).powf(df) - 2.0 / nf * s1 + 2f64.powf(df) * inv_n2 * s2
        }
    }
}

/// `r^d` in double-double by repeated squaring.
fn dd_pow(r: Dd, d: usize) -> Dd {
    let (mut acc, mut base, mut e) = (Dd::from_f64(1.0), r, d);
    while e > 0 {
        if e & 1 == 1 {
            acc = acc.mul(base);
        }
        base = base.mul(base);
        e >>= 1;
    }
    acc
}

/// `A(d)`, `c₁` and `c₂` in double-double.
fn constants_dd(which: Discrepancy, d: usize) -> (Dd, Dd, Dd) {
    let one = Dd::from_f64(1.0);
    let two_d = || dd_pow(Dd::from_f64(2.0), d);
    match which {
        Discrepancy::L2Star => (
            dd_pow(Dd::ratio(1.0, 3.0), d),
            dd_pow(Dd::from_f64(0.5), d).mul_f64(2.0),
            one,
        ),
        Discrepancy::Centered => (dd_pow(Dd::ratio(13.0, 12.0), d), Dd::from_f64(2.0), one),
        Discrepancy::WrapAround => (dd_pow(Dd::ratio(4.0, 3.0), d).neg(), Dd::ZERO, one),
        Discrepancy::Mixture => (dd_pow(Dd::ratio(19.0, 12.0), d), Dd::from_f64(2.0), one),
        Discrepancy::Symmetric => (dd_pow(Dd::ratio(4.0, 3.0), d), Dd::from_f64(2.0), two_d()),
    }
}

/// `A − (c₁/N)·s₁ + (c₂/N²)·s₂` in double-double, rounded once (the root for L2-star, of
/// max(0, ·): the exact value is never negative).
fn combine_dd(which: Discrepancy, d: usize, n: usize, s1: Dd, s2: Dd) -> f64 {
    let (a, c1, c2) = constants_dd(which, d);
    let nf = n as f64;
    let v = a
        .sub(c1.mul(s1).div_f64(nf))
        .add(c2.mul(s2).div_f64(nf).div_f64(nf))
        .to_f64();
    if which == Discrepancy::L2Star {
        v.max(0.0).sqrt()
    } else {
        v
    }
}

/// The checks every discrepancy makes: a non-empty set in [0,1)^d, at most
/// [`DISCREPANCY_MAX_DIMS`] dimensions.
fn check(points: &CubePoints) -> Result<(), MetricsError> {
    check_cube(points)?;
    if points.dims() > DISCREPANCY_MAX_DIMS {
        return Err(MetricsError::TooManyDims {
            what: "the L2 discrepancies",
            dims: points.dims(),
            max: DISCREPANCY_MAX_DIMS,
            why: "their terms 3^-d and 2^d leave the range of f64",
        });
    }
    Ok(())
}

/// [`discrepancy_naive`] and [`discrepancy_reference`] accept at most this many points.
pub const DISCREPANCY_NAIVE_MAX_N: usize = 1 << 14;

fn check_naive(points: &CubePoints, what: &'static str) -> Result<(), MetricsError> {
    check(points)?;
    if points.n() > DISCREPANCY_NAIVE_MAX_N {
        return Err(MetricsError::TooManyPoints {
            what,
            n: points.n(),
            max: DISCREPANCY_NAIVE_MAX_N,
            cost: "O(N²·d)",
        });
    }
    Ok(())
}

/// One discrepancy by scipy's loops (`workers = 1`) literally: every factor in scipy's
/// order, plain f64 running sums over i then j (L2-star: a running sum per row, then over
/// the rows, as scipy's `l2_star_loop`), the constants by `pow`. Reproduces scipy's value to a
/// few ulps; the formula reference of [`discrepancy`].
///
/// Errors: empty or invalid points, more than [`DISCREPANCY_MAX_DIMS`] dimensions or
/// [`DISCREPANCY_NAIVE_MAX_N`] points, cancellation.
pub fn discrepancy_naive(
    points: &CubePoints,
    which: Discrepancy,
    cancel: &Cancel,
) -> Result<f64, MetricsError> {
    check_naive(points, "discrepancy_naive")?;
    let (n, d) = (points.n(), points.dims());
    let mut s1 = 0.0;
    if has_point_sum(which) {
        for p in points.rows() {
            let mut prod = 1.0;
            for &x in p {
                prod *= point_factor(which, x);
            }
            s1 += prod;
        }
    }
    let mut s2 = 0.0;
    for (i, p) in points.rows().enumerate() {
        if i % 64 == 0 {
            cancel.check()?;
        }
        let mut row = 0.0;
        for q in points.rows() {
            let mut prod = 1.0;
            for k in 0..d {
                prod *= pair_factor(which, p[k], q[k]);
            }
            if which == Discrepancy::L2Star {
                row += prod;
            } else {
                s2 += prod;
            }
        }
        if which == Discrepancy::L2Star {
            s2 += row;
        }
    }
    Ok(combine_scipy(which, d, n, s1, s2))
}

/// One discrepancy with every factor, product and sum in double-double and exact constants:
/// the accuracy reference of [`discrepancy`] (the literal double sum over all i, j).
///
/// Errors: as [`discrepancy_naive`].
pub fn discrepancy_reference(
    points: &CubePoints,
    which: Discrepancy,
    cancel: &Cancel,
) -> Result<f64, MetricsError> {
    check_naive(points, "discrepancy_reference")?;
    let (n, d) = (points.n(), points.dims());
    let s1 = point_sum_dd(points, which);
    let mut s2 = Dd::ZERO;
    for (i, p) in points.rows().enumerate() {
        if i % 16 == 0 {
            cancel.check()?;
        }
        for q in points.rows() {
            let mut prod = Dd::from_f64(1.0);
            for k in 0..d {
                prod = prod.mul(pair_factor(which, Dd::from_f64(p[k]), Dd::from_f64(q[k])));
            }
            s2 = s2.add(prod);
        }
    }
    Ok(combine_dd(which, d, n, s1, s2))
}

/// `Σ_i Π_k g(x_ik)`, every factor, product and sum in double-double (O(N·d): the fast path
/// and the reference share it). In f64 the constant 5/3 of MD's g would be rounded in every
/// factor, an error of the same sign in all N terms that the final cancellation magnifies
/// (8·10⁻¹² relative for a lattice of 1021 points in 8 dimensions).
fn point_sum_dd(points: &CubePoints, which: Discrepancy) -> Dd {
    let mut s1 = Dd::ZERO;
    if has_point_sum(which) {
        for p in points.rows() {
            let mut prod = Dd::from_f64(1.0);
            for &x in p {
                prod = prod.mul(point_factor(which, Dd::from_f64(x)));
            }
            s1 = s1.add(prod);
        }
    }
    s1
}

/// `Σ_j Π_k h(x_ik, x_jk)` over `j ≥ i`, the diagonal once and the rest twice, in
/// double-double (the products in f64).
#[inline(always)]
fn row_sum(which: Discrepancy, coords: &[f64], d: usize, i: usize) -> Dd {
    let p = &coords[i * d..(i + 1) * d];
    let mut diag = 1.0;
    for &x in p {
        diag *= pair_factor(which, x, x);
    }
    let mut off = Dd::ZERO;
    for q in coords[(i + 1) * d..].chunks_exact(d) {
        let mut prod = 1.0;
        for k in 0..d {
            prod *= pair_factor(which, p[k], q[k]);
        }
        off = off.add_f64(prod);
    }
    off.mul_f64(2.0).add_f64(diag)
}

/// Dispatches `row_sum` on a measure known at compile time (the match leaves the hot loop).
fn row_sum_of(which: Discrepancy, coords: &[f64], d: usize, i: usize) -> Dd {
    match which {
        Discrepancy::L2Star => row_sum(Discrepancy::L2Star, coords, d, i),
        Discrepancy::Centered => row_sum(Discrepancy::Centered, coords, d, i),
        Discrepancy::WrapAround => row_sum(Discrepancy::WrapAround, coords, d, i),
        Discrepancy::Mixture => row_sum(Discrepancy::Mixture, coords, d, i),
        Discrepancy::Symmetric => row_sum(Discrepancy::Symmetric, coords, d, i),
    }
}

/// One discrepancy, fast: half the pairs (h is symmetric), rows in parallel, double-double
/// sums in row order (see the module docs). progress (`done` of `total` pairs) is called between
/// batches of rows. Agrees with [`discrepancy_reference`] to ~1e-14 relative for the test
/// sets (the error bound is in the module docs); N = 4096 in 32 dimensions takes ~0.3 s per
/// measure on 2 cores.
///
/// Errors: empty or invalid points, more than [`DISCREPANCY_MAX_DIMS`] dimensions,
/// cancellation.
pub fn discrepancy(
    points: &CubePoints,
    which: Discrepancy,
    cancel: &Cancel,
    progress: &mut OnProgress<'_, ()>,
) -> Result<f64, MetricsError> {
    check(points)?;
    let (n, d) = (points.n(), points.dims());
    let coords = points.coords();
    let s1 = point_sum_dd(points, which);
    let mut s2 = Dd::ZERO;
    let total = n * (n + 1) / 2;
    let mut done = 0;
    for rows in pair_batches(n) {
        cancel.check()?;
        let sums: Vec<Dd> = rows
            .clone()
            .into_par_iter()
            .map(|i| row_sum_of(which, coords, d, i))
            .collect();
        for s in sums {
            s2 = s2.add(s);
        }
        done += rows.map(|i| n - i).sum::<usize>();
        progress(Progress::at(done, total));
    }
    cancel.check()?;
    Ok(combine_dd(which, d, n, s1, s2))
}

/// All five discrepancies ([`discrepancy`] for each); progress (`done` of `total` pairs) counts
/// the pairs of all five.
///
/// Errors: as [`discrepancy`].
pub fn discrepancies(
    points: &CubePoints,
    cancel: &Cancel,
    progress: &mut OnProgress<'_, ()>,
) -> Result<Discrepancies, MetricsError> {
    check(points)?;
    let n = points.n();
    let per = n * (n + 1) / 2;
    let mut values = [0.0; 5];
    for (m, which) in Discrepancy::ALL.into_iter().enumerate() {
        values[m] = discrepancy(points, which, cancel, &mut |p: Progress<'_, ()>| {
            progress(Progress::at(m * per + p.done, 5 * per))
        })?;
    }
    let [l2_star, centered, wraparound, mixture, symmetric] = values;
    Ok(Discrepancies {
        l2_star,
        centered,
        wraparound,
        mixture,
        symmetric,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The f64 factors and the double-double ones agree (the generic formulas are one text).
    #[test]
    fn f64_and_dd_factors_agree_and_are_positive() {
        for which in Discrepancy::ALL {
            for &(a, b) in &[
                (0.0, 0.0),
                (0.1, 0.9),
                (0.5, 0.25),
                (0.999, 0.001),
                (0.3, 0.3),
            ] {
                let f = pair_factor(which, a, b);
                let g = pair_factor(which, Dd::from_f64(a), Dd::from_f64(b)).to_f64();
                assert!(f > 0.0 || which == Discrepancy::L2Star, "{which:?} {a} {b}");
                // Operands are at most 2: a few roundings of that size (1 − x² at x = 0.999
                // loses its relative accuracy to cancellation, not its absolute one).
                assert!((f - g).abs() <= 8.0 * f64::EPSILON, "{which:?}");
                let f = point_factor(which, a);
                let g = point_factor(which, Dd::from_f64(a)).to_f64();
                assert!((f - g).abs() <= 8.0 * f64::EPSILON, "{which:?}");
            }
        }
    }

    #[test]
    fn dd_powers_are_exact_for_dyadic_bases() {
        assert_eq!(dd_pow(Dd::from_f64(2.0), 10).to_f64(), 1024.0);
        assert_eq!(dd_pow(Dd::from_f64(0.5), 3).to_f64(), 0.125);
        let third = dd_pow(Dd::ratio(1.0, 3.0), 2).mul_f64(9.0).add_f64(-1.0);
        assert!(third.to_f64().abs() < 1e-30);
    }
}
