//! PSA's windowed Hankel transform of an RDF (the sums behind
//! [`super::psa::radial_power_from_rdf`]) in O(m log m) instead of O(m²) J₀ evaluations, with
//! the same J₀ (Abramowitz & Stegun 9.4.1/9.4.3, [`j0_fast`]) and the direct sum kept as the
//! reference ([`power_direct`]).
//!
//! For frequency k and RDF sample j the argument is x = C·k·j, C = 2π·Δν·Δr, and the sum is
//! S_k = Σ_j a_j J₀(C·k·j) with a_j = (g_j − 1)·r_j·w(r_j) (trapezoid weights included). For all
//! frequencies whose window is the long one (every k with L(ν_k) = ½ r_max: all but the first
//! ≈ 8·bins·√N/(4·ν_max)), a_j does not depend on k, and:
//!
//! - **x ≤ 3** (j ≤ J(k), A&S 9.4.1: J₀ = Σ_q s_q (x/3)^{2q}, a polynomial of degree 6 in
//!   (x/3)²): S_k's part is Σ_q s_q (Ck/3)^{2q} Σ_{j ≤ J(k)} a_j j^{2q}, seven prefix sums
//!   over j read at J(k): O(1) per frequency.
//! - **x > 3** (A&S 9.4.3: J₀ = f₀(t) cos(x − π/4 + θ₁(t))/√x, t = 3/x, f₀ and θ₁
//!   polynomials): J₀ = Re[x^{−½} F(t) e^{i(x − π/4)}] with F(t) = f₀(t)·e^{iθ₁(t)}, an entire
//!   function whose Taylor series Σ_p F_p t^p ([`taylor_f`]) is cut where its tail over
//!   0 ≤ t ≤ 1 is below 10⁻¹⁵ (23 terms). Since t = 3/(C·k·j) and x^{−½} factor into a
//!   function of k times one of j, over a block of frequencies k ∈ [K₀, K₁) and the samples
//!   j > J(K₀) the part is Re[e^{−iπ/4}(Ck)^{−½} Σ_p F_p (3/(Ck))^p Σ_j a_j j^{−½−p} e^{iCkj}],
//!   and each inner sum over j, for all k of the block at once, is a chirp-z transform
//!   (Bluestein: kj = (k² + j² − (k − j)²)/2, one FFT convolution). The samples between J(k)
//!   and J(K₀) are summed directly. Blocks grow geometrically (K₁ = 4·K₀), so there are
//!   ≈ log₄ m of them, each with 23 convolutions of length ≈ m/2 + K₁.
//!
//! The other frequencies (short or growing window) are summed directly, as is every frequency
//! when there are too few for the transform to pay. The result differs from the direct sum
//! only by rounding: the truncated series (< 10⁻¹⁵ relative to |F|), the FFT's (≈ 10⁻¹⁵
//! relative to Σ|a_j|/√x) and the phases' (C·k·j ≤ π·ν_max·r_max rounded once, where the direct
//! sum rounds (2πν)·r); the tests bound the difference of P by 10⁻¹⁰ and of the statistics by
//! 10⁻⁹.

use std::f64::consts::{FRAC_PI_4, TAU};

use rayon::prelude::*;
use rustfft::num_complex::Complex64;
use rustfft::FftPlanner;

use super::psa::{last_term, window, window_length};
use super::{Cancel, MetricsError};

/// A&S 9.4.1: J₀(x) = Σ_q J0_SMALL[q]·(x/3)^{2q} for |x| ≤ 3 (error < 5·10⁻⁸).
const J0_SMALL: [f64; 7] = [
    1.0,
    -2.249_999_7,
    1.265_620_8,
    -0.316_386_6,
    0.044_447_9,
    -0.003_944_4,
    0.000_210_0,
];
/// A&S 9.4.3: f₀(t) = Σ_p J0_F0[p]·t^p, t = 3/|x|.
const J0_F0: [f64; 7] = [
    0.797_884_56,
    -0.000_000_77,
    -0.005_527_40,
    -0.000_095_12,
    0.001_372_37,
    -0.000_728_05,
    0.000_144_76,
];
/// A&S 9.4.3: θ₀ = |x| − π/4 + Σ_p J0_THETA[p]·t^p (J0_THETA[0] = 0).
const J0_THETA: [f64; 7] = [
    0.0,
    -0.041_663_97,
    -0.000_039_54,
    0.002_625_73,
    -0.000_541_25,
    -0.000_293_33,
    0.000_135_58,
];

/// c₀ + t(c₁ + t(c₂ + …)), innermost first.
#[inline]
fn horner(c: &[f64], t: f64) -> f64 {
    c.iter().rev().fold(0.0, |acc, &v| v + t * acc)
}

/// J₀(x) by Abramowitz & Stegun 9.4.1 (|x| ≤ 3, error < 5·10⁻⁸) and 9.4.3 (|x| > 3,
/// √x·error < 2·10⁻⁸ in amplitude and 7·10⁻⁸ in phase).
#[inline]
pub(crate) fn j0_fast(x: f64) -> f64 {
    let ax = x.abs();
    if ax <= 3.0 {
        let t = (ax / 3.0) * (ax / 3.0);
        1.0 + t * horner(&J0_SMALL[1..], t)
    } else {
        let t = 3.0 / ax;
        let theta = ax - FRAC_PI_4 + t * horner(&J0_THETA[1..], t);
        horner(&J0_F0, t) * theta.cos() / ax.sqrt()
    }
}

/// Terms of F's Taylor series computed (far beyond the ones kept).
const TAYLOR_MAX: usize = 40;
/// The tail of F's series left out, at most this over 0 ≤ t ≤ 1 (relative to |F| ≈ 0.8).
const TAYLOR_TAIL: f64 = 1e-15;

fn cmul(a: &[Complex64], b: &[Complex64]) -> Vec<Complex64> {
    let mut c = vec![Complex64::new(0.0, 0.0); TAYLOR_MAX + 1];
    for (i, x) in a.iter().enumerate() {
        for (j, y) in b.iter().enumerate().take(TAYLOR_MAX + 1 - i) {
            c[i + j] += x * y;
        }
    }
    c
}

/// The Taylor coefficients F_p of F(t) = f₀(t)·exp(iθ₁(t)) (module docs), cut after the
/// first p whose tail Σ_{q>p} |F_q| is below [`TAYLOR_TAIL`].
pub(crate) fn taylor_f() -> Vec<Complex64> {
    let theta: Vec<Complex64> = J0_THETA.iter().map(|&v| Complex64::new(0.0, v)).collect();
    // exp(iθ₁) = Σ_n (iθ₁)^n / n!; θ₁ has no constant term, so (iθ₁)^n starts at t^n.
    let mut e = vec![Complex64::new(0.0, 0.0); TAYLOR_MAX + 1];
    let mut term = vec![Complex64::new(0.0, 0.0); TAYLOR_MAX + 1];
    term[0] = Complex64::new(1.0, 0.0);
    for n in 0..=TAYLOR_MAX {
        for (a, b) in e.iter_mut().zip(&term) {
            *a += b;
        }
        term = cmul(&term, &theta);
        term.iter_mut().for_each(|v| *v /= (n + 1) as f64);
    }
    let f0: Vec<Complex64> = J0_F0.iter().map(|&v| Complex64::new(v, 0.0)).collect();
    let mut f = cmul(&f0, &e);
    let mut tail = 0.0;
    let mut keep = f.len();
    for p in (0..f.len()).rev() {
        tail += f[p].norm();
        if tail >= TAYLOR_TAIL {
            keep = p + 1;
            break;
        }
    }
    f.truncate(keep);
    f
}

/// The fewest frequencies with the long window for which the fast path is taken.
const FAST_MIN_FREQUENCIES: usize = 64;
/// Block growth: K₁ = BLOCK_RATIO·K₀.
const BLOCK_RATIO: usize = 4;

/// What the transform of one RDF needs: N, r_max, its bin count m, g_j for j ≤ the last
/// sample any window reaches ([`samples_used`]), and the frequencies (`bins` up to `nu_max`).
pub(crate) struct Transform<'a> {
    pub n: usize,
    pub r_max: f64,
    pub m: usize,
    pub g: &'a [f64],
    pub bins: usize,
    pub nu_max: f64,
}

/// The RDF samples the transform reads: j = 0 … the last under the longest window, ½·r_max.
pub(crate) fn samples_used(m: usize, r_max: f64) -> usize {
    last_term(0.5 * r_max, r_max / m as f64, m) + 1
}

impl Transform<'_> {
    fn dr(&self) -> f64 {
        self.r_max / self.m as f64
    }
    fn dnu(&self) -> f64 {
        self.nu_max / self.bins as f64
    }
    fn power(&self, sum: f64) -> f64 {
        (1.0 + TAU * self.n as f64 * self.dr() * sum).abs()
    }
}

/// The direct sums S_k of frequencies `ks` (today's loop: a J₀ per term; the windows of the
/// two clamped lengths tabulated).
fn direct_sums(
    t: &Transform,
    ks: std::ops::Range<usize>,
    cancel: &Cancel,
) -> Result<Vec<f64>, MetricsError> {
    let m = t.m;
    let dr = t.dr();
    let dnu = t.dnu();
    let used = t.g.len();
    // The window is the same for all frequencies where L(ν) is clamped (all but a few).
    let taper = |len: f64| -> Vec<f64> { (0..used).map(|j| window(j as f64 * dr, len)).collect() };
    let (short, long) = (0.2 * t.r_max, 0.5 * t.r_max);
    let (w_short, w_long) = (taper(short), taper(long));
    ks.into_par_iter()
        .with_min_len(8)
        .map(|k| {
            cancel.check()?;
            let nu = k as f64 * dnu;
            let len = window_length(nu, t.n, t.r_max);
            let u = TAU * nu;
            // Samples beyond L have a zero window; j = 0 has r = 0.
            let last = last_term(len, dr, m);
            let w_at = |j: usize| {
                if len == short {
                    w_short[j]
                } else if len == long {
                    w_long[j]
                } else {
                    window(j as f64 * dr, len)
                }
            };
            let mut sum = 0.0;
            for j in 1..=last {
                let r = j as f64 * dr;
                let f = (t.g[j] - 1.0) * j0_fast(u * r) * r * w_at(j);
                sum += if j == m - 1 { 0.5 * f } else { f };
            }
            Ok(sum)
        })
        .collect()
}

/// P(ν_k) for k = 0 … bins − 1 by the direct sum over the samples (the reference of the fast
/// path, and today's arithmetic term for term).
pub(crate) fn power_direct(t: &Transform, cancel: &Cancel) -> Result<Vec<f64>, MetricsError> {
    Ok(direct_sums(t, 0..t.bins, cancel)?
        .into_iter()
        .map(|s| t.power(s))
        .collect())
}

/// The smallest 2^a·3^b ≥ `n` (a length rustfft transforms fast).
fn fft_length(n: usize) -> usize {
    let mut best = n.next_power_of_two();
    let mut p3 = 1;
    while p3 < best {
        let mut v = p3;
        while v < n {
            v *= 2;
        }
        best = best.min(v);
        p3 *= 3;
    }
    best
}

/// The fast path's layout for one transform's sizes (it depends on N, the bins and the
/// ranges only, not on the RDF): the frequencies summed directly, J(k), the blocks. The cost
/// estimate reads the same layout.
pub(crate) struct Plan {
    dr: f64,
    dnu: f64,
    /// The first frequency with the long window (all of them when there is no fast path).
    k_long: usize,
    /// The last RDF sample under the long window.
    last: usize,
    /// J(k) for k = k_long … bins − 1.
    js: Vec<usize>,
    /// Index (into `js`) of the first frequency with J(k) < last.
    first: usize,
    /// Blocks [b0, b1) of indices into `js`.
    blocks: Vec<(usize, usize)>,
}

impl Plan {
    pub(crate) fn new(n: usize, r_max: f64, m: usize, bins: usize, nu_max: f64) -> Plan {
        let dr = r_max / m as f64;
        let dnu = nu_max / bins as f64;
        let long = 0.5 * r_max;
        let last = last_term(long, dr, m);
        // Frequencies with the long window: a suffix (L(ν) grows with ν up to its clamp).
        let (mut lo, mut hi) = (0, bins);
        while lo < hi {
            let mid = lo + (hi - lo) / 2;
            if window_length(mid as f64 * dnu, n, r_max) != long {
                lo = mid + 1;
            } else {
                hi = mid;
            }
        }
        let mut plan = Plan {
            dr,
            dnu,
            k_long: lo,
            last,
            js: Vec::new(),
            first: 0,
            blocks: Vec::new(),
        };
        if bins - plan.k_long < FAST_MIN_FREQUENCIES || last < 2 {
            plan.k_long = bins;
            return plan;
        }
        plan.js = (plan.k_long..bins)
            .map(|k| plan.small_count(plan.u(k)))
            .collect();
        plan.first = plan.js.partition_point(|&j| j >= last);
        let mut b0 = plan.first;
        while b0 < plan.js.len() {
            let k0 = plan.k_long + b0;
            let b1 = (k0 * BLOCK_RATIO - plan.k_long).clamp(b0 + 1, plan.js.len());
            plan.blocks.push((b0, b1));
            b0 = b1;
        }
        plan
    }

    /// 2π·ν_k.
    fn u(&self, k: usize) -> f64 {
        TAU * (k as f64 * self.dnu)
    }

    /// J(k): the samples j ≤ last with x = u·r_j ≤ 3, by the direct sum's own arithmetic.
    fn small_count(&self, u: f64) -> usize {
        let (last, dr) = (self.last, self.dr);
        let x = |j: usize| u * (j as f64 * dr);
        let mut j = if u > 0.0 {
            ((3.0 / (u * dr)).floor().min(last as f64)) as usize
        } else {
            last
        };
        while j < last && x(j + 1) <= 3.0 {
            j += 1;
        }
        while j > 0 && x(j) > 3.0 {
            j -= 1;
        }
        j
    }

    /// The block of frequency index `i` (into `js`, i ≥ first).
    fn block_of(&self, i: usize) -> (usize, usize) {
        self.blocks[self.blocks.partition_point(|&(_, b1)| b1 <= i)]
    }

    /// (j0, lk, lj, fft length) of a block's chirp-z transforms; `None` when it has no samples
    /// beyond J(K₀).
    fn convolution(&self, (b0, b1): (usize, usize)) -> Option<(usize, usize, usize, usize)> {
        let j0 = self.js[b0] + 1;
        if j0 > self.last {
            return None;
        }
        let (lk, lj) = (b1 - b0, self.last + 1 - j0);
        Some((j0, lk, lj, fft_length(lk + lj - 1)))
    }

    /// The J₀ terms summed one by one: the frequencies before `k_long` over their windows, and
    /// J(k) < j ≤ J(K₀) in each block.
    pub(crate) fn direct_terms(&self, n: usize, r_max: f64, m: usize) -> f64 {
        let head: usize = (0..self.k_long)
            .map(|k| last_term(window_length(k as f64 * self.dnu, n, r_max), self.dr, m))
            .sum();
        let blocks: usize = (self.first..self.js.len())
            .map(|i| self.js[self.block_of(i).0] - self.js[i])
            .sum();
        (head + blocks) as f64
    }

    /// The FFTs' work, Σ L·log₂ L over every FFT of length L (per block: the kernel's, and a
    /// forward and an inverse one for each of the series' terms).
    pub(crate) fn fft_work(&self) -> f64 {
        let terms = taylor_f().len() as f64;
        self.blocks
            .iter()
            .filter_map(|&b| self.convolution(b))
            .map(|(_, _, _, len)| (1.0 + 2.0 * terms) * len as f64 * (len as f64).log2())
            .sum()
    }
}

/// P(ν_k) for k = 0 … bins − 1, the fast path (module docs); equal to [`power_direct`] up to
/// rounding.
pub(crate) fn power(t: &Transform, cancel: &Cancel) -> Result<Vec<f64>, MetricsError> {
    let plan = Plan::new(t.n, t.r_max, t.m, t.bins, t.nu_max);
    if plan.k_long == t.bins {
        return power_direct(t, cancel);
    }
    let mut sums = direct_sums(t, 0..plan.k_long, cancel)?;
    sums.extend(long_window_sums(t, &plan, cancel)?);
    Ok(sums.into_iter().map(|s| t.power(s)).collect())
}

/// S_k for the frequencies k_long … bins − 1, whose window is the long one (module docs).
fn long_window_sums(t: &Transform, plan: &Plan, cancel: &Cancel) -> Result<Vec<f64>, MetricsError> {
    let m = t.m;
    let (dr, last, js) = (plan.dr, plan.last, &plan.js);
    let long = 0.5 * t.r_max;
    // a_j = (g_j − 1)·r_j·w(r_j), with the trapezoid's half weight on the last RDF sample.
    let a: Vec<f64> = (0..=last)
        .map(|j| {
            if j == 0 {
                return 0.0;
            }
            let r = j as f64 * dr;
            let f = (t.g[j] - 1.0) * r * window(r, long);
            if j == m - 1 {
                0.5 * f
            } else {
                f
            }
        })
        .collect();
    let k_of = |i: usize| plan.k_long + i;
    // Prefix sums Σ_{j ≤ J} a_j j^{2q} of the small-argument part.
    let q_max = J0_SMALL.len();
    let mut prefix = vec![vec![0.0; last + 1]; q_max];
    for (q, row) in prefix.iter_mut().enumerate() {
        let mut acc = 0.0;
        for j in 1..=last {
            acc += a[j] * ((j * j) as f64).powi(q as i32);
            row[j] = acc;
        }
    }
    let mut sums: Vec<f64> = js
        .iter()
        .enumerate()
        .map(|(i, &jk)| {
            let x3 = plan.u(k_of(i)) * dr / 3.0;
            let c = x3 * x3;
            (0..q_max)
                .rev()
                .fold(0.0, |acc, q| J0_SMALL[q] * prefix[q][jk] + c * acc)
        })
        .collect();
    // Direct terms J(k) < j ≤ J(K₀) of each block.
    let direct: Vec<f64> = (plan.first..js.len())
        .into_par_iter()
        .with_min_len(16)
        .map(|i| {
            cancel.check()?;
            let j_top = js[plan.block_of(i).0];
            let u = plan.u(k_of(i));
            Ok((js[i] + 1..=j_top)
                .map(|j| a[j] * j0_fast(u * (j as f64 * dr)))
                .sum::<f64>())
        })
        .collect::<Result<_, MetricsError>>()?;
    for (s, d) in sums[plan.first..].iter_mut().zip(&direct) {
        *s += d;
    }
    let f = taylor_f();
    let c = TAU * plan.dnu * dr;
    let mut planner = FftPlanner::<f64>::new();
    // The blocks' buffers, made once at the largest block's length and reused (fresh buffers
    // of this size are page faults): the chirp, the inputs, and one row per power p.
    let convolutions: Vec<_> = plan
        .blocks
        .iter()
        .filter_map(|&b| plan.convolution(b).map(|conv| (b, conv)))
        .collect();
    let max_len = convolutions
        .iter()
        .map(|(_, (.., len))| *len)
        .max()
        .unwrap_or(0);
    let max_lj = convolutions
        .iter()
        .map(|(_, (_, _, lj, _))| *lj)
        .max()
        .unwrap_or(0);
    let mut kernel: Vec<Complex64> = Vec::with_capacity(max_len);
    let mut inputs: Vec<Complex64> = Vec::with_capacity(f.len() * max_lj);
    let mut outs: Vec<Complex64> = Vec::with_capacity(f.len() * max_len);
    for &((b0, _), (j0, lk, lj, len)) in &convolutions {
        cancel.check()?;
        let k0 = k_of(b0);
        let fwd = planner.plan_fft_forward(len);
        let inv = planner.plan_fft_inverse(len);
        let scratch_len = fwd
            .get_inplace_scratch_len()
            .max(inv.get_inplace_scratch_len());
        let cis = |half_turns: f64| {
            let (s, co) = (0.5 * c * half_turns).sin_cos();
            Complex64::new(co, s)
        };
        // The chirp e^{−iC d²/2} at d = κ − ι ∈ (−lj, lk).
        kernel.clear();
        kernel.resize(len, Complex64::new(0.0, 0.0));
        for (d, h) in kernel.iter_mut().enumerate().take(lk) {
            *h = cis(-((d * d) as f64));
        }
        for d in 1..lj {
            kernel[len - d] = cis(-((d * d) as f64));
        }
        fwd.process_with_scratch(
            &mut kernel,
            &mut vec![Complex64::new(0.0, 0.0); scratch_len],
        );
        // The inputs a_j j^{−½} z_j^p e^{iC(K₀ι + ι²/2)}, j = j0 + ι, z_j = j0/j, one row
        // per power p.
        inputs.clear();
        inputs.resize(f.len() * lj, Complex64::new(0.0, 0.0));
        for i in 0..lj {
            let j = j0 + i;
            let z = j0 as f64 / j as f64;
            let mut v = cis((2 * k0 * i + i * i) as f64) * (a[j] / (j as f64).sqrt());
            for p in 0..f.len() {
                inputs[p * lj + i] = v;
                v *= z;
            }
        }
        // Row p: the chirp-z transform of input row p, its first lk values kept.
        outs.clear();
        outs.resize(f.len() * len, Complex64::new(0.0, 0.0));
        let (kernel, inputs) = (&kernel, &inputs);
        outs.par_chunks_mut(len).enumerate().try_for_each_init(
            || vec![Complex64::new(0.0, 0.0); scratch_len],
            |scratch, (p, buf)| {
                cancel.check()?;
                buf[..lj].copy_from_slice(&inputs[p * lj..(p + 1) * lj]);
                fwd.process_with_scratch(buf, scratch);
                for (x, h) in buf.iter_mut().zip(kernel) {
                    *x *= h;
                }
                inv.process_with_scratch(buf, scratch);
                let scale = 1.0 / len as f64;
                buf[..lk].iter_mut().for_each(|x| *x *= scale);
                Ok::<(), MetricsError>(())
            },
        )?;
        let rot = Complex64::new(FRAC_PI_4.cos(), -FRAC_PI_4.sin());
        for kappa in 0..lk {
            let ck = plan.u(k0 + kappa) * dr;
            let y = 3.0 / (ck * j0 as f64);
            let mut acc = Complex64::new(0.0, 0.0);
            for p in (0..f.len()).rev() {
                acc = acc * y + f[p] * outs[p * len + kappa];
            }
            let phase = cis((2 * (k0 * j0 + j0 * kappa) + kappa * kappa) as f64);
            sums[b0 + kappa] += (rot * phase * acc).re / ck.sqrt();
        }
    }
    Ok(sums)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// F(t) = f₀(t)·e^{iθ₁(t)} from the A&S polynomials.
    fn f_exact(t: f64) -> Complex64 {
        let theta = t * horner(&J0_THETA[1..], t);
        Complex64::new(theta.cos(), theta.sin()) * horner(&J0_F0, t)
    }

    #[test]
    fn the_taylor_series_of_f_matches_f_to_1e_15_on_the_unit_interval() {
        let f = taylor_f();
        assert!(f.len() <= 25, "{} terms", f.len());
        for i in 0..=1000 {
            let t = i as f64 / 1000.0;
            let series = f
                .iter()
                .rev()
                .fold(Complex64::new(0.0, 0.0), |a, &c| a * t + c);
            let err = (series - f_exact(t)).norm();
            assert!(err < 2e-15, "t = {t}: {err:e}");
        }
    }

    #[test]
    fn j0_by_the_series_matches_j0_fast_to_1e_14_plus_the_phase_rounding() {
        // Re[x^{−½} F(3/x) e^{i(x − π/4)}] is what the chirp-z path sums, for 3 < x ≤ π·N/2·½
        // (the largest argument at N = 2^16: 2π·ν_max·L_max = 2π·32768·¼).
        let f = taylor_f();
        let mut x = 3.0 + 1e-9;
        let mut worst: f64 = 0.0;
        while x < 51_472.0 {
            let t = 3.0 / x;
            let series = f
                .iter()
                .rev()
                .fold(Complex64::new(0.0, 0.0), |a, &c| a * t + c);
            let (s, c) = (x - FRAC_PI_4).sin_cos();
            let j0 = (series * Complex64::new(c, s)).re / x.sqrt();
            // Relative to the amplitude 0.8/√x, beyond the rounding of the phase x − π/4 (a few
            // ulp of x, in both).
            let allowed = 1e-14 + 4.0 * f64::EPSILON * x;
            worst = worst.max((j0 - j0_fast(x)).abs() * x.sqrt() / allowed);
            x *= 1.000_37;
        }
        assert!(worst <= 1.0, "max √x·|ΔJ₀| / (1e-14 + 4εx) = {worst}");
    }

    #[test]
    fn fft_lengths_are_3_smooth_and_long_enough() {
        for n in 1..3000 {
            let l = fft_length(n);
            assert!(l >= n);
            let mut r = l;
            while r % 2 == 0 {
                r /= 2;
            }
            while r % 3 == 0 {
                r /= 3;
            }
            assert_eq!(r, 1, "{n} → {l}");
            assert!(l < 2 * n.max(1), "{n} → {l}");
        }
    }
}
