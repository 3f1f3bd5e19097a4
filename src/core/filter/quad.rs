//! Numerical quadrature for the filter module: Gauss–Legendre rules and an adaptive
//! Gauss–Legendre integrator.
//!
//! - [`GaussLegendre::new`]`(n)` computes the n-point rule on \[−1, 1\] by Newton's method on the
//!   Legendre polynomial P_n (three-term recurrence), to full double precision. It integrates
//!   polynomials of degree ≤ 2n − 1 exactly.
//! - [`adaptive`] integrates f over a list of panels (the caller puts every point where f is not
//!   smooth on a panel boundary). Each panel is compared with the sum over its two halves
//!   (16-point rule on each); panels whose difference exceeds their share of the tolerance are
//!   bisected, up to [`MAX_DEPTH`] times. The tolerance is *relative to ∫|f|*, estimated on the
//!   initial panels, so results are accurate to about `rel_tol·∫|f|` (the reported `error` is the
//!   sum of the |whole − halves| differences, a conservative estimate for Gauss rules).
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

/// Splits each interval `[breaks[i], breaks[i+1]]` into equal panels no wider than `max_width`.
///
/// `breaks` must be sorted; empty intervals are skipped. Returns the panel boundaries.
pub fn panels(breaks: &[f64], max_width: f64) -> Vec<(f64, f64)> {
    let mut out = Vec::new();
    for w in breaks.windows(2) {
        let (a, b) = (w[0], w[1]);
        if b <= a || !a.is_finite() || !b.is_finite() {
            continue;
        }
        let n = if max_width.is_finite() && max_width > 0.0 {
            ((b - a) / max_width).ceil().clamp(1.0, 1e6) as usize
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

/// Nodes and weights of the accepted panels of an adaptive integration of f: the rule
/// Σ w_q g(x_q) then approximates ∫ g over the same range for any g that is as smooth as f on
/// the scale of the panels.
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
    let mut out = Vec::with_capacity(accepted.len() * 32);
    for (a, b) in accepted {
        let m = 0.5 * (a + b);
        for (lo, hi) in [(a, m), (m, b)] {
            let c = 0.5 * (lo + hi);
            let h = 0.5 * (hi - lo);
            for (x, w) in rule.nodes.iter().zip(&rule.weights) {
                out.push((c + h * x, w * h));
            }
        }
    }
    out
}

/// Runs the refinement and calls `accept(a, b, value, error)` for every accepted panel (the
/// value is the two-halves estimate).
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
    let total_width: f64 = ps.iter().map(|(a, b)| b - a).sum();
    let mut wholes = Vec::with_capacity(ps.len());
    let mut scale = 0.0;
    for &(a, b) in &ps {
        wholes.push(rule.integrate(f, a, b));
        scale += rule.integrate(&mut |x| f(x).abs(), a, b);
    }
    let tol_total = (rel_tol * scale).max(abs_floor);
    for (&(a, b), &whole) in ps.iter().zip(&wholes) {
        let tol = tol_total * (b - a) / total_width;
        refine(f, rule, a, b, whole, tol, 0, accept);
    }
}

#[allow(clippy::too_many_arguments)]
fn refine<F: FnMut(f64) -> f64, A: FnMut(f64, f64, f64, f64)>(
    f: &mut F,
    rule: &GaussLegendre,
    a: f64,
    b: f64,
    whole: f64,
    tol: f64,
    depth: u32,
    accept: &mut A,
) {
    let m = 0.5 * (a + b);
    let left = rule.integrate(f, a, m);
    let right = rule.integrate(f, m, b);
    let err = (left + right - whole).abs();
    if err <= tol || depth >= MAX_DEPTH || m <= a || m >= b || !err.is_finite() {
        accept(a, b, left + right, err);
        return;
    }
    refine(f, rule, a, m, left, 0.5 * tol, depth + 1, accept);
    refine(f, rule, m, b, right, 0.5 * tol, depth + 1, accept);
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
