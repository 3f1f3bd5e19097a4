//! L2-star discrepancy by Warnock's closed form.
//!
//! `T_N² = ∫_{[0,1]²} (A([0,a)×[0,b))/N − a·b)² da db`
//! `     = 1/9 − (2/N) Σ_i Π_d (1 − x_{id}²)/2 + (1/N²) Σ_i Σ_j Π_d (1 − max(x_{id}, x_{jd}))`
//! (Warnock 1972; expand the square and integrate each indicator product). In 2D the middle
//! term is `(1/(2N)) Σ_i (1 − x_i²)(1 − y_i²)`.
//!
//! # Cancellation
//! For a good point set `T_N² ≈ 10⁻⁸` while the three terms are ≈ 0.1: eight digits cancel.
//! Both algorithms therefore accumulate every sum in double-double (`dd.rs`) and form
//! `1 − x²` exactly, so the result is accurate to ~1e-15 relative given the f64 inputs
//! (`1 − x` and `1 − max(…)` are rounded to f64, which is exact whenever x is a multiple of
//! 2⁻⁵³, as every pattern of this crate produces). The result is `√max(0, T_N²)`.
//!
//! # Fast double sum, O(N log N)
//! With `u = 1 − x`, `w = 1 − y`: `1 − max(x_i, x_j) = min(u_i, u_j)`, so the double sum is
//! `S = Σ_i u_i w_i + 2 Σ_{i<j} min(u_i,u_j) min(w_i,w_j)`. Sort by x ascending: for `i < j`,
//! `min(u_i, u_j) = u_j` (ties give equal u, so any order works), hence
//! `S = Σ_i u_i w_i + 2 Σ_j u_j · ( Σ_{i<j, w_i ≤ w_j} w_i + w_j · #{i<j : w_i > w_j} )`,
//! where the inner sum and count come from a Fenwick tree over the ranks of w.

use glam::DVec2;

use super::dd::Dd;
use super::{validate, Cancel, MetricsError, CANCEL_STRIDE};

/// [`l2_star_discrepancy_naive`] accepts at most this many points (N² terms).
pub const L2_NAIVE_MAX_N: usize = 1 << 16;

/// `(1/(2N)) Σ_i (1 − x_i²)(1 − y_i²)`, in double-double with `1 − x²` formed exactly.
fn linear_term(points: &[DVec2]) -> Dd {
    let one_minus_sq = |v: f64| Dd::from_f64(1.0).add(Dd::from_prod(v, v).neg());
    let mut sum = Dd::ZERO;
    for p in points {
        sum = sum.add(one_minus_sq(p.x).mul(one_minus_sq(p.y)));
    }
    sum.div_f64(2.0 * points.len() as f64)
}

/// `√max(0, 1/9 − linear + S/N²)`.
fn finish(points: &[DVec2], s: Dd) -> f64 {
    let n = points.len() as f64;
    let ninth = Dd::from_f64(1.0).div_f64(9.0);
    let t2 = ninth
        .add(linear_term(points).neg())
        .add(s.div_f64(n).div_f64(n))
        .to_f64();
    t2.max(0.0).sqrt()
}

/// L2-star discrepancy `T_N` by Warnock's formula with the literal O(N²) double sum
/// `Σ_i Σ_j (1 − max(x_i,x_j))(1 − max(y_i,y_j))` (each product rounded once, summed in
/// double-double). The reference for [`l2_star_discrepancy`].
///
/// Errors: empty or invalid points, more than [`L2_NAIVE_MAX_N`] points, cancellation.
pub fn l2_star_discrepancy_naive(points: &[DVec2], cancel: &Cancel) -> Result<f64, MetricsError> {
    validate(points)?;
    let n = points.len();
    if n > L2_NAIVE_MAX_N {
        return Err(MetricsError::TooManyPoints {
            what: "l2_star_discrepancy_naive",
            n,
            max: L2_NAIVE_MAX_N,
            cost: "O(N²)",
        });
    }
    let mut s = Dd::ZERO;
    for (i, p) in points.iter().enumerate() {
        if i % 256 == 0 {
            cancel.check()?;
        }
        for q in points {
            s = s.add_f64((1.0 - p.x.max(q.x)) * (1.0 - p.y.max(q.y)));
        }
    }
    Ok(finish(points, s))
}

/// Fenwick (binary indexed) tree of double-double sums and counts over ranks.
struct Fenwick {
    sum: Vec<Dd>,
    count: Vec<u32>,
}

impl Fenwick {
    fn new(len: usize) -> Self {
        Fenwick {
            sum: vec![Dd::ZERO; len + 1],
            count: vec![0; len + 1],
        }
    }
    /// Adds `value` at `rank` (0-based).
    fn insert(&mut self, rank: usize, value: f64) {
        let mut k = rank + 1;
        while k < self.sum.len() {
            self.sum[k] = self.sum[k].add_f64(value);
            self.count[k] += 1;
            k += k & k.wrapping_neg();
        }
    }
    /// Sum and count over ranks `0..=rank`.
    fn prefix(&self, rank: usize) -> (Dd, u64) {
        let mut k = rank + 1;
        let mut s = Dd::ZERO;
        let mut c = 0u64;
        while k > 0 {
            s = s.add(self.sum[k]);
            c += self.count[k] as u64;
            k &= k - 1;
        }
        (s, c)
    }
}

/// L2-star discrepancy `T_N` (Warnock's closed form, see the module docs) in O(N log N):
/// sort by x, then a Fenwick tree over the ranks of `1 − y` yields every
/// `Σ_{i<j} min(1−y_i, 1−y_j)`. Memory O(N). Agrees with [`l2_star_discrepancy_naive`] to
/// ~1e-13 relative; ~1 ms at N = 4096.
///
/// Errors: empty or invalid points, cancellation.
pub fn l2_star_discrepancy(points: &[DVec2], cancel: &Cancel) -> Result<f64, MetricsError> {
    validate(points)?;
    // (u, w) = (1 − x, 1 − y), sorted by x ascending (u descending).
    let mut uw: Vec<(f64, f64, f64)> = points.iter().map(|p| (p.x, 1.0 - p.x, 1.0 - p.y)).collect();
    uw.sort_unstable_by(|a, b| a.0.total_cmp(&b.0));
    // Ranks of w among the distinct values.
    let mut ws: Vec<f64> = uw.iter().map(|t| t.2).collect();
    ws.sort_unstable_by(f64::total_cmp);
    ws.dedup();
    let mut tree = Fenwick::new(ws.len());

    let mut diag = Dd::ZERO;
    let mut cross = Dd::ZERO;
    for (j, &(_, u, w)) in uw.iter().enumerate() {
        if j % CANCEL_STRIDE == 0 {
            cancel.check()?;
        }
        diag = diag.add(Dd::from_prod(u, w));
        let r = ws.partition_point(|&v| v < w);
        let (sum_le, count_le) = tree.prefix(r);
        let count_gt = j as u64 - count_le;
        let inner = sum_le.add(Dd::from_prod(w, count_gt as f64));
        cross = cross.add(inner.mul_f64(u));
        tree.insert(r, w);
    }
    Ok(finish(points, diag.add(cross.mul_f64(2.0))))
}
