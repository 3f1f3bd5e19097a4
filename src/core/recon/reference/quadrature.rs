//! Composite Gauss–Legendre pixel means of the quadratic-phase sinusoids behind the zone-plate
//! and chirp references (the method and its error bound are in the parent module's docs).
//!
//! One axis at a time: in the pixel coordinate X = W·x (pixel interval i is X ∈ [i, i+1]) the
//! phase in units of π is a quadratic a₂ξ² + a₁ξ with ξ = X − shift, carried in double-double
//! and reduced exactly ([`rem2`]), as the signals do. Each pixel interval is split into m equal
//! subintervals so that the local frequency times the subinterval length is at most
//! [`MAX_CYCLES`] cycles, and each subinterval gets the [`FINE_NODES`]-point rule (returned)
//! and the [`COARSE_NODES`]-point rule (the check).

use super::super::{check_cancel, ReconError};
use crate::core::cancel::Cancel;
use crate::core::signal::exact::{cos_pi, rem2, sin_pi, DoubleDouble};
use rayon::prelude::*;

/// n: nodes of the returned (fine) rule per subinterval.
pub(super) const FINE_NODES: usize = 20;
/// Nodes of the check (coarse) rule, on the same subintervals.
pub(super) const COARSE_NODES: usize = 16;
/// q: the most cycles of the local frequency over one subinterval.
pub(super) const MAX_CYCLES: f64 = 1.25;
/// T: bound on the truncation error of the fine rule for the mean over one subinterval, from
/// the Bernstein-ellipse bound (parent module docs) at ρ = 4.5: 6.85·10⁻¹⁸.
pub(super) const TRUNCATION_BOUND: f64 = 7e-18;
/// Integrand evaluations (one phase, one `sin_pi`, one `cos_pi`) per subinterval.
pub(super) const EVALS_PER_SUBINTERVAL: u128 = (FINE_NODES + COARSE_NODES) as u128;
/// The unit roundoff 2⁻⁵³.
pub(super) const U: f64 = f64::EPSILON / 2.0;
/// Bound on the absolute error of [`sin_pi`] and [`cos_pi`].
const SIN_PI_ERROR: f64 = 3e-16;

/// 16-point Gauss–Legendre nodes on [0, 1], ascending.
const GL16_NODES: [f64; 16] = [
    0.005299532504175033,
    0.02771248846338371,
    0.06718439880608412,
    0.12229779582249849,
    0.19106187779867811,
    0.2709916111713863,
    0.35919822461037054,
    0.4524937450811813,
    0.5475062549188188,
    0.6408017753896295,
    0.7290083888286137,
    0.8089381222013219,
    0.8777022041775016,
    0.9328156011939158,
    0.9722875115366163,
    0.994700467495825,
];
/// 16-point Gauss–Legendre weights on [0, 1] (they sum to 1).
const GL16_WEIGHTS: [f64; 16] = [
    0.013576229705877048,
    0.031126761969323947,
    0.04757925584124639,
    0.06231448562776694,
    0.07479799440828837,
    0.08457825969750127,
    0.09130170752246179,
    0.09472530522753425,
    0.09472530522753425,
    0.09130170752246179,
    0.08457825969750127,
    0.07479799440828837,
    0.06231448562776694,
    0.04757925584124639,
    0.031126761969323947,
    0.013576229705877048,
];
/// 20-point Gauss–Legendre nodes on [0, 1], ascending.
const GL20_NODES: [f64; 20] = [
    0.0034357004074525377,
    0.018014036361043106,
    0.04388278587433705,
    0.0804415140888906,
    0.1268340467699246,
    0.1819731596367425,
    0.24456649902458646,
    0.3131469556422902,
    0.38610707442917747,
    0.46173673943325133,
    0.5382632605667487,
    0.6138929255708225,
    0.6868530443577098,
    0.7554335009754135,
    0.8180268403632576,
    0.8731659532300754,
    0.9195584859111094,
    0.956117214125663,
    0.9819859636389568,
    0.9965642995925474,
];
/// 20-point Gauss–Legendre weights on [0, 1] (they sum to 1).
const GL20_WEIGHTS: [f64; 20] = [
    0.008807003569576059,
    0.02030071490019347,
    0.031336024167054534,
    0.04163837078835238,
    0.05096505990862022,
    0.059097265980759206,
    0.06584431922458832,
    0.07104805465919102,
    0.07458649323630187,
    0.07637669356536292,
    0.07637669356536292,
    0.07458649323630187,
    0.07104805465919102,
    0.06584431922458832,
    0.059097265980759206,
    0.05096505990862022,
    0.04163837078835238,
    0.031336024167054534,
    0.02030071490019347,
    0.008807003569576059,
];

/// The phase/π of one axis as a function of the pixel coordinate: a₂ξ² + a₁ξ, ξ = X − shift.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct QuadraticPhase {
    a2: DoubleDouble,
    a1: DoubleDouble,
    shift: DoubleDouble,
}

impl QuadraticPhase {
    /// One axis of the zone plate: K(x − c)² = (K/W²)(X − cW)² (cW exact, K/W² to ~2⁻¹⁰⁴).
    pub(super) fn zone_plate_axis(k: f64, c: f64, w: usize) -> Self {
        let wf = w as f64;
        QuadraticPhase {
            a2: DoubleDouble::from_f64(k).div_f64(wf * wf),
            a1: DoubleDouble::from_f64(0.0),
            shift: DoubleDouble::prod(c, wf),
        }
    }

    /// The chirp: 2f₀x + (f₁ − f₀)x² = (2f₀/W)X + ((f₁ − f₀)/W²)X².
    pub(super) fn chirp(f0: f64, f1: f64, w: usize) -> Self {
        let wf = w as f64;
        QuadraticPhase {
            a2: DoubleDouble::diff(f1, f0).div_f64(wf * wf),
            a1: DoubleDouble::from_f64(2.0 * f0).div_f64(wf),
            shift: DoubleDouble::from_f64(0.0),
        }
    }

    /// phase/π at ξ, reduced modulo 2 into [−1, 1].
    #[inline]
    fn phase(&self, xi: DoubleDouble) -> f64 {
        let mut t = (xi * xi) * self.a2;
        if self.a1.hi != 0.0 {
            t = t + xi * self.a1;
        }
        rem2(t)
    }

    /// ξ at the left end of pixel interval i.
    fn start(&self, i: usize) -> DoubleDouble {
        DoubleDouble::from_f64(i as f64) + (-self.shift)
    }

    /// Local frequency in cycles per pixel at ξ: ½|d(phase/π)/dξ| = |a₂ξ + a₁/2| (`f64`).
    fn cycles_per_pixel(&self, xi: f64) -> f64 {
        (self.a2.hi * xi + 0.5 * self.a1.hi).abs()
    }

    /// m for pixel interval i: ⌈F/q⌉ (at least 1), F the largest local frequency on the
    /// interval in cycles per pixel; the frequency is linear in ξ, so F is taken at an end. F
    /// is formed in `f64` (relative error ≲ 10⁻¹⁵, which moves T by a negligible amount).
    pub(super) fn subintervals(&self, i: usize) -> u64 {
        let a = self.start(i).to_f64();
        let f = self.cycles_per_pixel(a).max(self.cycles_per_pixel(a + 1.0));
        // `as` saturates; a huge m is refused by the work check before any evaluation.
        ((f / MAX_CYCLES).ceil() as u64).max(1)
    }

    /// An upper bound on |phase/π| over pixel interval i (for the rounding bound).
    fn max_abs_phase(&self, i: usize) -> f64 {
        let a = self.start(i).to_f64();
        let r = a.abs().max((a + 1.0).abs());
        (self.a2.hi.abs() * r * r + self.a1.hi.abs() * r) * (1.0 + 1e-9)
    }
}

/// The means of sin(π·phase) and cos(π·phase) over the W pixel intervals of one axis.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct AxisMeans {
    /// σᵢ: mean of sin(π·phase) over pixel interval i (fine rule).
    pub sin: Vec<f64>,
    /// γᵢ: mean of cos(π·phase) over pixel interval i (fine rule).
    pub cos: Vec<f64>,
    /// e = maxᵢ (δᵢ + T + ρᵢ): a bound on |σᵢ − σ̄ᵢ| and |γᵢ − γ̄ᵢ| for every i (δᵢ the
    /// fine–coarse difference, T [`TRUNCATION_BOUND`], ρᵢ the rounding bound).
    pub err: f64,
    /// maxᵢ (|σᵢ| + |γᵢ|).
    pub mag: f64,
    /// maxᵢ δᵢ (reported for tests and diagnostics).
    pub delta: f64,
}

/// m for every pixel interval of one axis, and the total integrand evaluations.
pub(super) fn plan(phase: &QuadraticPhase, w: usize) -> (Vec<u64>, u128) {
    let m: Vec<u64> = (0..w).map(|i| phase.subintervals(i)).collect();
    let work = m.iter().map(|&m| m as u128).sum::<u128>() * EVALS_PER_SUBINTERVAL;
    (m, work)
}

/// Σₖ wₖ (sin, cos)(π·phase(left + offsetₖ)) for one subinterval.
#[inline]
fn rule<const N: usize>(
    phase: &QuadraticPhase,
    left: DoubleDouble,
    offsets: &[f64; N],
    weights: &[f64; N],
) -> (f64, f64) {
    let (mut s, mut c) = (0.0, 0.0);
    for (&o, &wk) in offsets.iter().zip(weights) {
        let t = phase.phase(left + DoubleDouble::from_f64(o));
        s += wk * sin_pi(t);
        c += wk * cos_pi(t);
    }
    (s, c)
}

/// One pixel interval: (σ, γ, δ, ρ).
fn interval(
    phase: &QuadraticPhase,
    i: usize,
    m: u64,
    cancel: &Cancel,
) -> Result<(f64, f64, f64, f64), ReconError> {
    let mf = m as f64;
    let fine_off = GL20_NODES.map(|t| t / mf);
    let coarse_off = GL16_NODES.map(|t| t / mf);
    let a = phase.start(i);
    let zero = DoubleDouble::from_f64(0.0);
    let (mut sf, mut cf, mut sc, mut cc) = (zero, zero, zero, zero);
    for s in 0..m {
        if s % 4096 == 4095 {
            check_cancel(cancel)?;
        }
        let left = if s == 0 {
            a
        } else {
            a + DoubleDouble::from_f64(s as f64).div_f64(mf)
        };
        let (s1, c1) = rule(phase, left, &fine_off, &GL20_WEIGHTS);
        let (s2, c2) = rule(phase, left, &coarse_off, &GL16_WEIGHTS);
        sf = sf + DoubleDouble::from_f64(s1);
        cf = cf + DoubleDouble::from_f64(c1);
        sc = sc + DoubleDouble::from_f64(s2);
        cc = cc + DoubleDouble::from_f64(c2);
    }
    let (sf, cf) = (sf.to_f64() / mf, cf.to_f64() / mf);
    let (sc, cc) = (sc.to_f64() / mf, cc.to_f64() / mf);
    let delta = (sf - sc).abs().max((cf - cc).abs());
    // ρ (parent module docs): integrand error (sin_pi/cos_pi; rem2's rounding, the node
    // positions and the double-double phase, all times π) plus the sums and the weights.
    let integrand = SIN_PI_ERROR
        + std::f64::consts::PI
            * (2f64.powi(-51) + 4.0 * MAX_CYCLES * U + 2f64.powi(-100) * phase.max_abs_phase(i));
    let rounding = integrand + (FINE_NODES + 4) as f64 * U + mf * 2f64.powi(-104);
    Ok((sf, cf, delta, rounding))
}

/// σ, γ and the error terms of every pixel interval of one axis (parallel over intervals,
/// cancellable per interval and every 4096 subintervals). `m` comes from [`plan`].
pub(super) fn axis_means(
    phase: &QuadraticPhase,
    m: &[u64],
    cancel: &Cancel,
) -> Result<AxisMeans, ReconError> {
    let v = m
        .par_iter()
        .enumerate()
        .map(|(i, &mi)| {
            check_cancel(cancel)?;
            interval(phase, i, mi, cancel)
        })
        .collect::<Result<Vec<_>, ReconError>>()?;
    let mut out = AxisMeans {
        sin: Vec::with_capacity(v.len()),
        cos: Vec::with_capacity(v.len()),
        err: 0.0,
        mag: 0.0,
        delta: 0.0,
    };
    for (s, c, delta, rho) in v {
        out.sin.push(s);
        out.cos.push(c);
        out.err = out.err.max(delta + TRUNCATION_BOUND + rho);
        out.mag = out.mag.max(s.abs() + c.abs());
        out.delta = out.delta.max(delta);
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rules_integrate_polynomials_exactly_and_weights_sum_to_one() {
        // N-point Gauss–Legendre is exact to degree 2N − 1: ∫₀¹ t^d dt = 1/(d + 1).
        fn check<const N: usize>(nodes: &[f64; N], weights: &[f64; N]) {
            for d in 0..2 * N {
                let q: f64 = nodes
                    .iter()
                    .zip(weights)
                    .map(|(&t, &w)| w * t.powi(d as i32))
                    .sum();
                let exact = 1.0 / (d + 1) as f64;
                assert!(
                    (q - exact).abs() < 1e-15,
                    "N = {N}, degree {d}: {q} vs {exact}"
                );
            }
            for (k, (&t, &w)) in nodes.iter().zip(weights).enumerate() {
                // Symmetric about ½.
                assert!((t + nodes[N - 1 - k] - 1.0).abs() < 1e-16);
                assert_eq!(w, weights[N - 1 - k]);
                assert!(t > 0.0 && t < 1.0 && w > 0.0);
            }
        }
        check(&GL16_NODES, &GL16_WEIGHTS);
        check(&GL20_NODES, &GL20_WEIGHTS);
    }

    #[test]
    fn truncation_bound_constant_is_the_bernstein_ellipse_bound() {
        // (32/15)·exp(π q a b)·ρ^(2 − 2n)/(ρ² − 1), a, b the semi-axes of E_ρ, at ρ = 4.5.
        let rho: f64 = 4.5;
        let (a, b) = ((rho + 1.0 / rho) / 2.0, (rho - 1.0 / rho) / 2.0);
        let n = FINE_NODES as i32;
        let bound =
            32.0 / 15.0 * (std::f64::consts::PI * MAX_CYCLES * a * b).exp() * rho.powi(2 - 2 * n)
                / (rho * rho - 1.0);
        assert!(
            bound <= TRUNCATION_BOUND && bound > 0.5 * TRUNCATION_BOUND,
            "{bound:e}"
        );
    }

    #[test]
    fn subintervals_follow_the_local_frequency() {
        // K = 1000, W = 10, c = ½: phase/π = 10(X − 5)², so the local frequency is |a₂ξ| =
        // 10|ξ| cycles per pixel: interval 9 (ξ ∈ [4, 5]) has F = 50 → ⌈50/1.25⌉ = 40.
        let p = QuadraticPhase::zone_plate_axis(1000.0, 0.5, 10);
        assert_eq!(p.subintervals(9), 40);
        assert_eq!(p.subintervals(0), 40);
        // Interval 5 (ξ ∈ [0, 1]): F = 10 → 8; K = 0: one subinterval.
        assert_eq!(p.subintervals(5), 8);
        assert_eq!(
            QuadraticPhase::zone_plate_axis(0.0, 0.5, 10).subintervals(3),
            1
        );
        // Chirp f₀ = 1, f₁ = 64 at W = 8: the last pixel ends at 64 cycles/unit = 8 per pixel.
        let c = QuadraticPhase::chirp(1.0, 64.0, 8);
        assert_eq!(c.subintervals(7), 7);
    }
}
