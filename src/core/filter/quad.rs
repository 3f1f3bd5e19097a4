//! Numerical quadrature for the filter module: Gauss–Legendre rules and an adaptive
//! Gauss–Legendre integrator.
//!
//! - [`GaussLegendre::new`]`(n)` computes the n-point rule on \[−1, 1\] by Newton's method on the
//!   Legendre polynomial P_n (three-term recurrence), to full double precision. It integrates
//!   polynomials of degree ≤ 2n − 1 exactly.
//! - [`adaptive`] integrates f over a list of panels (the caller puts every point where f is not
//!   smooth on a panel boundary). Each panel's 16-point value is compared with the sum over its
//!   two halves; the panel with the largest difference is bisected (globally adaptive, as
//!   QUADPACK's QAG) until the summed differences are below the tolerance, with at most
//!   [`MAX_SPLITS`] bisections and [`MAX_DEPTH`] levels, so the cost is bounded even when
//!   rounding noise exceeds the tolerance. The tolerance is *relative to ∫|f|*, estimated on the
//!   initial panels (never below the caller's absolute floor), so results are accurate to about
//!   `rel_tol·∫|f|` (the reported `error` is the sum of |whole − halves|, a conservative
//!   estimate for Gauss rules: the returned halves are far more accurate).
//! - [`adaptive_rule`] runs the same refinement on f and returns the accepted panels' nodes and
//!   weights, so that ∫ f(x) g(x) dx for many smooth g (e.g. e^{−2πiωx} for all ω up to a bound
//!   that the panel widths resolve) costs one sum each.

use std::sync::OnceLock;

/// Deepest bisection of an initial panel (2⁻⁴⁰ of its width).
pub const MAX_DEPTH: u32 = 40;

/// An n-point Gauss–Legendre rule on \[−1, 1\].
#[derive(Debug, Clone)]
pub struct GaussLegendre {
    /// Nodes in increasing order.
    pub nodes: Vec<f64>,
    /// Positive weights summing to 2.
    pub weights: Vec<f64>,
}

impl GaussLegendre {
    /// The n-point rule (n ≥ 1): nodes are the zeros of P_n, found by Newton's method from
    /// cos(π(i − ¼)/(n + ½)); weights w_i = 2/((1 − x_i²) P_n'(x_i)²).
    pub fn new(n: usize) -> Self {
        let n = n.max(1);
        let mut nodes = vec![0.0; n];
        let mut weights = vec![0.0; n];
        let nf = n as f64;
        for i in 0..n.div_ceil(2) {
            let mut x = (std::f64::consts::PI * (i as f64 + 0.75) / (nf + 0.5)).cos();
            let mut dp = 1.0;
            for _ in 0..100 {
                // P_n(x) and P_n'(x) by the three-term recurrence.
                let (mut p0, mut p1) = (1.0, x);
                for k in 2..=n {
                    let kf = k as f64;
                    let p2 = ((2.0 * kf - 1.0) * x * p1 - (kf - 1.0) * p0) / kf;
                    p0 = p1;
                    p1 = p2;
                }
                // P_n' = n (x P_n − P_{n−1}) / (x² − 1).
                dp = nf * (x * p1 - p0) / (x * x - 1.0);
                let dx = p1 / dp;
                x -= dx;
                if dx.abs() < 1e-16 {
                    break;
                }
            }
            nodes[i] = -x;
            nodes[n - 1 - i] = x;
            let w = 2.0 / ((1.0 - x * x) * dp * dp);
            weights[i] = w;
            weights[n - 1 - i] = w;
        }
        if n % 2 == 1 {
            nodes[n / 2] = 0.0;
        }
        GaussLegendre { nodes, weights }
    }

    /// ∫_a^b f(x) dx by this rule.
    #[inline]
    pub fn integrate<F: FnMut(f64) -> f64>(&self, f: &mut F, a: f64, b: f64) -> f64 {
        let c = 0.5 * (a + b);
        let h = 0.5 * (b - a);
        let mut s = 0.0;
        for (x, w) in self.nodes.iter().zip(&self.weights) {
            s += w * f(c + h * x);
        }
        s * h
    }
}

/// The 16-point rule, computed once.
pub fn gl16() -> &'static GaussLegendre {
    static RULE: OnceLock<GaussLegendre> = OnceLock::new();
    RULE.get_or_init(|| GaussLegendre::new(16))
}

/// The 8-point rule, computed once.
pub fn gl8() -> &'static GaussLegendre {
    static RULE: OnceLock<GaussLegendre> = OnceLock::new();
    RULE.get_or_init(|| GaussLegendre::new(8))
}

/// A quadrature result with its error estimate.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Integral {
    /// The estimate of ∫ f.
    pub value: f64,
    /// Estimated absolute error (sum over panels of |whole − halves|).
    pub error: f64,
}

/// Most initial panels of one integration ([`panels`] widens them beyond this count): bounds
/// the cost of integrands oscillating faster than the caller can resolve (e.g. H(ω) for
/// |ω| ≳ [`MAX_PANELS`]/(2·length) cycles per unit), at the price of accuracy there.
pub const MAX_PANELS: usize = 1 << 16;

/// Splits each interval `[breaks[i], breaks[i+1]]` into equal panels no wider than `max_width`
/// (widened if needed so that there are at most [`MAX_PANELS`] in all).
///
/// `breaks` must be sorted; empty or non-finite intervals are skipped. Returns the panels.
pub fn panels(breaks: &[f64], max_width: f64) -> Vec<(f64, f64)> {
    let total: f64 = breaks
        .windows(2)
        .filter(|w| w[1] > w[0] && w[0].is_finite() && w[1].is_finite())
        .map(|w| w[1] - w[0])
        .sum();
    let intervals = breaks.len().saturating_sub(1);
    let mut width = max_width;
    if !(width.is_finite() && width > 0.0) {
        width = f64::INFINITY;
    }
    let budget = MAX_PANELS.saturating_sub(intervals).max(1) as f64;
    if total / width > budget {
        width = total / budget;
    }
    let mut out = Vec::new();
    for w in breaks.windows(2) {
        let (a, b) = (w[0], w[1]);
        if b <= a || !a.is_finite() || !b.is_finite() {
            continue;
        }
        let n = if width.is_finite() {
            ((b - a) / width).ceil().max(1.0) as usize
        } else {
            1
        };
        for i in 0..n {
            let lo = a + (b - a) * i as f64 / n as f64;
            let hi = if i + 1 == n {
                b
            } else {
                a + (b - a) * (i + 1) as f64 / n as f64
            };
            out.push((lo, hi));
        }
    }
    out
}

/// Adaptive Gauss–Legendre integration of f over `breaks[0]..breaks[last]`, with f smooth inside
/// each interval of `breaks`, initial panels no wider than `max_width`, and tolerance
/// `rel_tol·∫|f|` (∫|f| estimated on the initial panels; `abs_floor` is the smallest absolute
/// tolerance used, to stop refining a function that is zero to rounding).
pub fn adaptive<F: FnMut(f64) -> f64>(
    f: &mut F,
    breaks: &[f64],
    max_width: f64,
    rel_tol: f64,
    abs_floor: f64,
) -> Integral {
    let mut out = Integral::default();
    adaptive_visit(
        f,
        breaks,
        max_width,
        rel_tol,
        abs_floor,
        &mut |_, _, v, e| {
            out.value += v;
            out.error += e;
        },
    );
    out
}

/// Nodes and weights (16-point rule on each accepted panel) of an adaptive integration of f:
/// the rule Σ w_q g(x_q) then approximates ∫ g over the same range for any g that is as smooth
/// as f on the scale of the panels. The 16-point rule integrates cos(κx) over a panel holding
/// one full period with error ≈ 2·10⁻²⁹ relative to the panel width (Gauss error term
/// 2^{33}(16!)⁴/(33·(32!)³)·(π)^{32}), two periods ≈ 10⁻¹⁹.
pub fn adaptive_rule<F: FnMut(f64) -> f64>(
    f: &mut F,
    breaks: &[f64],
    max_width: f64,
    rel_tol: f64,
    abs_floor: f64,
) -> Vec<(f64, f64)> {
    let mut accepted = Vec::new();
    adaptive_visit(
        f,
        breaks,
        max_width,
        rel_tol,
        abs_floor,
        &mut |a, b, _, _| {
            accepted.push((a, b));
        },
    );
    let rule = gl16();
    let mut out = Vec::with_capacity(accepted.len() * 16);
    for (a, b) in accepted {
        let c = 0.5 * (a + b);
        let h = 0.5 * (b - a);
        for (x, w) in rule.nodes.iter().zip(&rule.weights) {
            out.push((c + h * x, w * h));
        }
    }
    out
}

/// A panel of the global adaptive scheme: `value` is the sum of the 16-point rule on its two
/// halves, `error` = |value − 16-point rule on the whole panel|.
#[derive(Debug, Clone, Copy)]
struct Panel {
    a: f64,
    b: f64,
    left: f64,
    right: f64,
    error: f64,
    depth: u32,
}

impl Panel {
    fn value(&self) -> f64 {
        self.left + self.right
    }
}

/// Orders panels by error for the max-heap.
struct ByError(Panel);

impl PartialEq for ByError {
    fn eq(&self, other: &Self) -> bool {
        self.0.error.total_cmp(&other.0.error).is_eq()
    }
}
impl Eq for ByError {}
impl PartialOrd for ByError {
    fn partial_cmp(&self, other: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}
impl Ord for ByError {
    fn cmp(&self, other: &Self) -> std::cmp::Ordering {
        self.0.error.total_cmp(&other.0.error)
    }
}

/// Most bisections of one adaptive integration (each costs 64 evaluations); beyond it the
/// current estimate is returned with its (larger) error estimate.
pub const MAX_SPLITS: usize = 2000;

/// Global adaptive refinement (QUADPACK QAG style): the panel with the largest error estimate
/// is bisected until the total estimate is below the tolerance, the panel is 2⁻⁴⁰ of its initial
/// width, or [`MAX_SPLITS`] bisections were made. Calls `accept(a, b, value, error)` for every
/// final panel.
fn adaptive_visit<F: FnMut(f64) -> f64, A: FnMut(f64, f64, f64, f64)>(
    f: &mut F,
    breaks: &[f64],
    max_width: f64,
    rel_tol: f64,
    abs_floor: f64,
    accept: &mut A,
) {
    let rule = gl16();
    let ps = panels(breaks, max_width);
    if ps.is_empty() {
        return;
    }
    let make = |f: &mut F, a: f64, b: f64, whole: f64, depth: u32| {
        let m = 0.5 * (a + b);
        let left = rule.integrate(f, a, m);
        let right = rule.integrate(f, m, b);
        let error = (left + right - whole).abs();
        Panel {
            a,
            b,
            left,
            right,
            error: if error.is_finite() {
                error
            } else {
                f64::INFINITY
            },
            depth,
        }
    };
    let mut heap = std::collections::BinaryHeap::with_capacity(ps.len() + 2 * MAX_SPLITS);
    let mut scale = 0.0;
    let mut total_error = 0.0;
    for &(a, b) in &ps {
        let whole = rule.integrate(f, a, b);
        scale += rule.integrate(&mut |x| f(x).abs(), a, b);
        let p = make(f, a, b, whole, 0);
        total_error += p.error;
        heap.push(ByError(p));
    }
    let tol = (rel_tol * scale).max(abs_floor);
    let mut done = Vec::new();
    let mut splits = 0;
    while total_error > tol && splits < MAX_SPLITS {
        let Some(ByError(p)) = heap.pop() else {
            break;
        };
        let m = 0.5 * (p.a + p.b);
        if p.depth >= MAX_DEPTH || m <= p.a || m >= p.b || !p.error.is_finite() {
            done.push(p);
            if !p.error.is_finite() {
                break;
            }
            continue;
        }
        let l = make(f, p.a, m, p.left, p.depth + 1);
        let r = make(f, m, p.b, p.right, p.depth + 1);
        total_error += l.error + r.error - p.error;
        heap.push(ByError(l));
        heap.push(ByError(r));
        splits += 1;
    }
    done.extend(heap.into_iter().map(|ByError(p)| p));
    done.sort_by(|x, y| x.a.total_cmp(&y.a));
    for p in done {
        accept(p.a, p.b, p.value(), p.error);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gauss_legendre_weights_sum_to_two_and_integrate_polynomials_exactly() {
        for n in [1usize, 2, 5, 8, 16] {
            let r = GaussLegendre::new(n);
            let sum: f64 = r.weights.iter().sum();
            assert!((sum - 2.0).abs() < 1e-14, "n = {n}");
            // ∫_{-1}^{1} x^k = 2/(k+1) for even k, 0 for odd k; exact for k ≤ 2n − 1.
            for k in 0..2 * n {
                let got = r.integrate(&mut |x: f64| x.powi(k as i32), -1.0, 1.0);
                let want = if k % 2 == 0 {
                    2.0 / (k as f64 + 1.0)
                } else {
                    0.0
                };
                assert!((got - want).abs() < 1e-14, "n = {n}, k = {k}");
            }
        }
        // Published 2-point rule: ±1/√3, weights 1.
        let r = GaussLegendre::new(2);
        assert!(
            (r.nodes[1] - 1.0 / 3f64.sqrt()).abs() < 3e-16,
            "{}",
            r.nodes[1]
        );
        assert!((r.weights[0] - 1.0).abs() < 1e-15);
    }

    #[test]
    fn adaptive_integrates_oscillatory_and_peaked_functions() {
        // ∫_0^10 cos(7x) dx = sin(70)/7.
        let got = adaptive(&mut |x: f64| (7.0 * x).cos(), &[0.0, 10.0], 0.5, 1e-14, 0.0);
        assert!((got.value - 70f64.sin() / 7.0).abs() < 1e-13);
        // ∫_0^1 1/(1e-4 + x²) dx = atan(100)/0.01 (a sharp peak at 0).
        let got = adaptive(
            &mut |x: f64| 1.0 / (1e-4 + x * x),
            &[0.0, 1.0],
            1.0,
            1e-13,
            0.0,
        );
        assert!((got.value - 100f64.atan() / 0.01).abs() < 1e-9, "{got:?}");
    }

    #[test]
    fn adaptive_rule_reproduces_integrals_of_modulated_functions() {
        let f = |x: f64| (-x * x).exp();
        let rule = adaptive_rule(&mut |x| f(x), &[0.0, 8.0], 0.25, 1e-14, 0.0);
        // ∫_0^8 e^{−x²} cos(2x) dx ≈ (√π/2) e^{−1} (the tail beyond 8 is < 1e-28).
        let s: f64 = rule.iter().map(|(x, w)| w * f(*x) * (2.0 * x).cos()).sum();
        let want = std::f64::consts::PI.sqrt() / 2.0 * (-1f64).exp();
        assert!((s - want).abs() < 1e-14);
    }
}
