//! Exact star discrepancy in 2D (O(N²) sweep, O(N³) brute-force reference) and in 1D (the
//! lecture's closed form, O(N²) brute-force reference).
//!
//! # Definition and critical boxes
//! `D*_N(P) = sup_{0≤a,b≤1} |A(a,b)/N − a·b|`, `A(a,b) = #{i : x_i < a, y_i < b}` (anchored
//! half-open boxes `[0,a)×[0,b)`). Split the supremum by the sign of the local discrepancy:
//!
//! - *too few points*: `a·b − A(a,b)/N`. Between consecutive critical values the count is
//!   constant and the volume grows with `a` and `b`, so the supremum is attained (a maximum) at
//!   `a ∈ X̄ = {x_i} ∪ {1}`, `b ∈ Ȳ = {y_i} ∪ {1}` with the **open** count
//!   `A_open(a,b) = #{x_i < a, y_i < b}`;
//! - *too many points*: `A(a,b)/N − a·b`. The count is left-constant and jumps just after a
//!   point coordinate, so the supremum is the limit `a ↓ x_k`, `b ↓ y_l`: the **closed** box
//!   `[0,a]×[0,b]` with `A_closed(a,b) = #{x_i ≤ a, y_i ≤ b}`, `a ∈ {x_i}`, `b ∈ {y_i}` (or 1).
//!
//! Hence `D*_N = max( max_{X̄×Ȳ} (ab − A_open/N), max_{X̄×Ȳ} (A_closed/N − ab) )` (Niederreiter
//! 1972; Gnewuch, Srivastav, Winzen 2009, §2). Closed boxes with a coordinate equal to 1 are
//! harmless limits (every point has coordinates < 1).
//!
//! # Sweep, O(N²)
//! Sort the distinct x values `v_1 < … < v_K` and the distinct y values `w_1 < … < w_{M−1}`,
//! with `w_M = 1`. Sweep `k = 1..K`: insert the points with `x = v_k` into the counts
//! `Q[s] = #{inserted, y ≤ w_s}` (a range increment), then one pass over `s` evaluates both
//! the closed boxes at `a = v_k` (`Q[s]/N − v_k·w_s`) and the open boxes at the *next*
//! critical `a = v_{k+1}` (or 1), whose open count `#{x < v_{k+1}, y < w_{s+1}}` is exactly
//! `Q[s]`: `v_{k+1}·w_{s+1} − Q[s]/N`. The open boxes at `a = v_1` hold no point; their best is
//! `[0,v_1)×[0,1)`, worth `v_1`. Both passes are branch-free and vectorise.

use glam::DVec2;
use serde::Serialize;

use super::{validate, Cancel, MetricsError};

/// [`star_discrepancy`] accepts at most this many points (O(N²): ~30 s at this size).
pub const STAR_EXACT_MAX_N: usize = 1 << 18;

/// [`star_discrepancy_brute_force`] accepts at most this many points (O(N³)).
pub const STAR_BRUTE_FORCE_MAX_N: usize = 1024;

/// The exact star discrepancy of a 2D point set and the anchored box that attains it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct StarDiscrepancy {
    /// `D*_N ∈ [1/(2N), 1]`: the supremum of the local discrepancy `|A/N − ab|`.
    pub value: f64,
    /// Upper corner `(a, b)` of the worst anchored box.
    pub worst_box: (f64, f64),
    /// `false`: the open box `[0,a)×[0,b)` holds too few points (`value = ab − count/N`);
    /// `true`: the closed box `[0,a]×[0,b]` holds too many (`value = count/N − ab`, the limit
    /// of half-open boxes shrinking onto it).
    pub closed: bool,
    /// Number of points in that box (open or closed as stated by `closed`).
    pub points_inside: usize,
}

/// Exact 2D star discrepancy `D*_N` by the O(N²) sweep described in the module docs, with
/// the worst anchored box. Memory O(N). Checks `cancel` once per distinct x value.
///
/// Ties between boxes of equal discrepancy are resolved deterministically (the first found
/// in sweep order), so the box is a pure function of the input.
///
/// Errors: empty or invalid points, more than [`STAR_EXACT_MAX_N`] points, cancellation.
pub fn star_discrepancy(
    points: &[DVec2],
    cancel: &Cancel,
) -> Result<StarDiscrepancy, MetricsError> {
    validate(points)?;
    let n = points.len();
    if n > STAR_EXACT_MAX_N {
        return Err(MetricsError::TooManyPoints {
            what: "star_discrepancy",
            n,
            max: STAR_EXACT_MAX_N,
            cost: "O(N²)",
        });
    }
    let (pts, ys, best) = prepare(points);
    sweep_dispatch(&pts, &ys, 1.0 / n as f64, cancel, best)
}

/// Sorts the (validated, non-empty) points for the sweep: returns the points as
/// `(x, rank of y)` sorted by x, the distinct y values followed by 1, and the best open box
/// at `a = x_min`.
#[allow(clippy::type_complexity)]
fn prepare(points: &[DVec2]) -> (Vec<(f64, usize)>, Vec<f64>, StarDiscrepancy) {
    // Distinct y values (+0.0 folds a -0.0 into 0.0), then the sentinel 1.
    let mut ys: Vec<f64> = points.iter().map(|p| p.y + 0.0).collect();
    ys.sort_unstable_by(f64::total_cmp);
    ys.dedup();
    ys.push(1.0);
    let m = ys.len();

    // Points sorted by x, each with the rank of its y.
    let mut pts: Vec<(f64, usize)> = points
        .iter()
        .map(|p| {
            let y = p.y + 0.0;
            // `ys` holds every y exactly, so the search always succeeds.
            let r = ys[..m - 1].partition_point(|&w| w < y);
            debug_assert!(ys[r] == y);
            (p.x + 0.0, r)
        })
        .collect();
    pts.sort_unstable_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));

    // Open boxes at a = x_min hold no point: the best is [0, x_min) × [0, 1).
    let best = StarDiscrepancy {
        value: pts[0].0,
        worst_box: (pts[0].0, 1.0),
        closed: false,
        points_inside: 0,
    };
    (pts, ys, best)
}

/// Runs [`sweep`] compiled for AVX2 when the CPU has it (4 f64 lanes instead of SSE2's 2).
/// Both versions execute the same IEEE operations in the same order (Rust never contracts
/// a·b − c into an FMA), so they return identical bits.
fn sweep_dispatch(
    pts: &[(f64, usize)],
    ys: &[f64],
    inv_n: f64,
    cancel: &Cancel,
    best: StarDiscrepancy,
) -> Result<StarDiscrepancy, MetricsError> {
    #[cfg(target_arch = "x86_64")]
    {
        if std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: `sweep_avx2` only requires AVX2, which the CPU was just checked to have.
            return unsafe { sweep_avx2(pts, ys, inv_n, cancel, best) };
        }
    }
    sweep(pts, ys, inv_n, cancel, best)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn sweep_avx2(
    pts: &[(f64, usize)],
    ys: &[f64],
    inv_n: f64,
    cancel: &Cancel,
    best: StarDiscrepancy,
) -> Result<StarDiscrepancy, MetricsError> {
    sweep(pts, ys, inv_n, cancel, best)
}

/// The sweep over the distinct x values (module docs): `pts` sorted by x with the rank of
/// each y in `ys` (distinct y values, then 1); `best` holds the open box at a = x_min.
#[inline(always)]
fn sweep(
    pts: &[(f64, usize)],
    ys: &[f64],
    inv_n: f64,
    cancel: &Cancel,
    mut best: StarDiscrepancy,
) -> Result<StarDiscrepancy, MetricsError> {
    let n = pts.len();
    let m = ys.len();
    let mut q = vec![0.0f64; m];
    let mut k = 0;
    while k < n {
        cancel.check()?;
        let a = pts[k].0;
        while k < n && pts[k].0 == a {
            for c in &mut q[pts[k].1..] {
                *c += 1.0;
            }
            k += 1;
        }
        let a_next = if k < n { pts[k].0 } else { 1.0 };

        let (closed_max, open_max) = row_maxima(&q, ys, inv_n, a, a_next);
        // Open box [0, a_next) × [0, w_0): no point inside.
        let open_first = a_next * ys[0];
        if open_first > best.value {
            best = StarDiscrepancy {
                value: open_first,
                worst_box: (a_next, ys[0]),
                closed: false,
                points_inside: 0,
            };
        }
        if closed_max > best.value {
            // Same expression, same operation order as in `row_maxima`: same bits.
            let s = (0..m).find(|&s| q[s] * inv_n - a * ys[s] == closed_max);
            debug_assert!(s.is_some());
            let s = s.unwrap_or(0);
            best = StarDiscrepancy {
                value: closed_max,
                worst_box: (a, ys[s]),
                closed: true,
                points_inside: q[s] as usize,
            };
        }
        if open_max > best.value {
            let s = (0..m - 1).find(|&s| a_next * ys[s + 1] - q[s] * inv_n == open_max);
            debug_assert!(s.is_some());
            let s = s.unwrap_or(0);
            best = StarDiscrepancy {
                value: open_max,
                worst_box: (a_next, ys[s + 1]),
                closed: false,
                points_inside: q[s] as usize,
            };
        }
    }
    Ok(best)
}

/// Independent accumulators of the row reduction: enough to hide the latency of `max`
/// (16 lanes = four AVX2 registers per maximum; measured ~35% faster than 4 lanes).
const LANES: usize = 16;

/// One row of the sweep: `max_s (Q[s]/N − a·w_s)` over `s < M` (closed boxes) and
/// `max_s (a'·w_{s+1} − Q[s]/N)` over `s < M−1` (open boxes), branch-free over [`LANES`]
/// independent lanes so the compiler vectorises the reduction.
#[inline(always)]
fn row_maxima(q: &[f64], ys: &[f64], inv_n: f64, a: f64, a_next: f64) -> (f64, f64) {
    let m = q.len();
    let body = m - 1;
    let mut cl = [f64::NEG_INFINITY; LANES];
    let mut op = [f64::NEG_INFINITY; LANES];
    let q0 = &q[..body];
    let w0 = &ys[..body];
    let w1 = &ys[1..m];
    let mut qc = q0.chunks_exact(LANES);
    let mut w0c = w0.chunks_exact(LANES);
    let mut w1c = w1.chunks_exact(LANES);
    for ((qq, ww0), ww1) in (&mut qc).zip(&mut w0c).zip(&mut w1c) {
        for l in 0..LANES {
            let f = qq[l] * inv_n;
            let vc = f - a * ww0[l];
            let vo = a_next * ww1[l] - f;
            cl[l] = if vc > cl[l] { vc } else { cl[l] };
            op[l] = if vo > op[l] { vo } else { op[l] };
        }
    }
    let mut closed = cl.iter().fold(f64::NEG_INFINITY, |x, &y| x.max(y));
    let mut open = op.iter().fold(f64::NEG_INFINITY, |x, &y| x.max(y));
    for ((&qq, &ww0), &ww1) in qc
        .remainder()
        .iter()
        .zip(w0c.remainder())
        .zip(w1c.remainder())
    {
        let f = qq * inv_n;
        closed = closed.max(f - a * ww0);
        open = open.max(a_next * ww1 - f);
    }
    // The last row of Q (b = 1) only forms a closed box.
    closed = closed.max(q[body] * inv_n - a * ys[body]);
    (closed, open)
}

/// Exact 2D star discrepancy by brute force over every critical box: for all
/// `(a, b) ∈ ({x_i} ∪ {1}) × ({y_i} ∪ {1})` count the points of the open box `[0,a)×[0,b)`
/// and of the closed box `[0,a]×[0,b]` by scanning the whole set, O(N³). The reference for
/// [`star_discrepancy`]; ties resolved by the first box in (a, b) scan order.
///
/// Errors: empty or invalid points, more than [`STAR_BRUTE_FORCE_MAX_N`] points,
/// cancellation.
pub fn star_discrepancy_brute_force(
    points: &[DVec2],
    cancel: &Cancel,
) -> Result<StarDiscrepancy, MetricsError> {
    validate(points)?;
    let n = points.len();
    if n > STAR_BRUTE_FORCE_MAX_N {
        return Err(MetricsError::TooManyPoints {
            what: "star_discrepancy_brute_force",
            n,
            max: STAR_BRUTE_FORCE_MAX_N,
            cost: "O(N³)",
        });
    }
    let nf = n as f64;
    let xs: Vec<f64> = points.iter().map(|p| p.x).chain([1.0]).collect();
    let ys: Vec<f64> = points.iter().map(|p| p.y).chain([1.0]).collect();
    let mut best = StarDiscrepancy {
        value: f64::NEG_INFINITY,
        worst_box: (0.0, 0.0),
        closed: false,
        points_inside: 0,
    };
    for &a in &xs {
        cancel.check()?;
        for &b in &ys {
            let open = points.iter().filter(|p| p.x < a && p.y < b).count();
            let closed = points.iter().filter(|p| p.x <= a && p.y <= b).count();
            let v_open = a * b - open as f64 / nf;
            let v_closed = closed as f64 / nf - a * b;
            if v_open > best.value {
                best = StarDiscrepancy {
                    value: v_open,
                    worst_box: (a, b),
                    closed: false,
                    points_inside: open,
                };
            }
            if v_closed > best.value {
                best = StarDiscrepancy {
                    value: v_closed,
                    worst_box: (a, b),
                    closed: true,
                    points_inside: closed,
                };
            }
        }
    }
    Ok(best)
}

fn validate_1d(xs: &[f64]) -> Result<(), MetricsError> {
    if xs.is_empty() {
        return Err(MetricsError::Empty);
    }
    for (index, &value) in xs.iter().enumerate() {
        if !(0.0..=1.0).contains(&value) {
            return Err(MetricsError::ValueOutOfRange { index, value });
        }
    }
    Ok(())
}

/// 1D star discrepancy by the lecture's closed form (Niederreiter 1992, Thm 2.6): for the
/// sorted values `x_(1) ≤ … ≤ x_(N)` in `[0,1]`,
///
/// `D*_N = 1/(2N) + max_{1≤i≤N} | x_(i) − (2i−1)/(2N) |`,
///
/// where `D*_N = sup_{0<a≤1} |#{x_i < a}/N − a|`. O(N log N) (the sort).
/// Lecture examples: `x_i = i/N → 1/N`; `x_i = (i−½)/N → 1/(2N)` (the optimum).
///
/// Errors: empty input, a value that is not a finite number in [0, 1].
pub fn star_discrepancy_1d(xs: &[f64]) -> Result<f64, MetricsError> {
    validate_1d(xs)?;
    let mut s = xs.to_vec();
    s.sort_unstable_by(f64::total_cmp);
    let n = s.len() as f64;
    let worst = s
        .iter()
        .enumerate()
        .map(|(k, &x)| (x - (2.0 * (k + 1) as f64 - 1.0) / (2.0 * n)).abs())
        .fold(0.0, f64::max);
    Ok(1.0 / (2.0 * n) + worst)
}

/// 1D star discrepancy by brute force over the critical points: for every
/// `a ∈ {x_i} ∪ {1}`, `a − #{x < a}/N` (open interval, too few) and `#{x ≤ a}/N − a` (the
/// closed limit, too many), counting by a full scan: O(N²). The reference for
/// [`star_discrepancy_1d`].
///
/// Errors: empty input, a value that is not a finite number in [0, 1].
pub fn star_discrepancy_1d_brute_force(xs: &[f64]) -> Result<f64, MetricsError> {
    validate_1d(xs)?;
    let n = xs.len() as f64;
    let mut best = 0.0f64;
    for &a in xs.iter().chain([1.0].iter()) {
        let open = xs.iter().filter(|&&x| x < a).count() as f64;
        let closed = xs.iter().filter(|&&x| x <= a).count() as f64;
        best = best.max(a - open / n).max(closed / n - a);
    }
    Ok(best)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::rng::Rng;

    #[test]
    #[cfg(target_arch = "x86_64")]
    fn avx2_and_generic_sweeps_give_identical_bits() {
        if !std::arch::is_x86_feature_detected!("avx2") {
            return; // nothing to compare on this CPU
        }
        let mut r = Rng::new(1);
        for n in [1usize, 2, 17, 100, 1000] {
            let pts: Vec<DVec2> = (0..n)
                .map(|_| DVec2::new(r.next_f64(), r.below(64) as f64 / 64.0))
                .collect();
            let (p, ys, best) = prepare(&pts);
            let c = Cancel::never();
            let inv_n = 1.0 / n as f64;
            let generic = sweep(&p, &ys, inv_n, &c, best).unwrap();
            // SAFETY: AVX2 support was checked above.
            let avx2 = unsafe { sweep_avx2(&p, &ys, inv_n, &c, best) }.unwrap();
            assert_eq!(generic.value.to_bits(), avx2.value.to_bits());
            assert_eq!(generic, avx2);
        }
    }
}
