//! Special functions used by the reconstruction filters, each accurate to a few ulps in `f64`
//! over the whole finite range (no NaN or infinity for finite arguments unless the true value
//! overflows).
//!
//! | function | definition | method |
//! |---|---|---|
//! | [`sin_pi`], [`cos_pi`] | sin(πx), cos(πx) | x reduced mod 2 *exactly* (IEEE `fmod`), then folded to \[−½, ½\] with exact (Sterbenz) subtractions, so that `sin_pi(n) = 0` and `cos_pi(n + ½) = 0` exactly for every integer n and every finite x works |
//! | [`sinc`] | sin(πx)/(πx), sinc(0) = 1 | Taylor 1 − u/6 + u²/120 (u = (πx)²) for \|x\| < 10⁻⁴, else `sin_pi(x)/(πx)` |
//! | [`cosc`] | d/dx sinc(x) = (πx cos πx − sin πx)/(πx²) = cos(πx)/x − sin(πx)/(πx²) | odd Taylor series for \|x\| < 0.14 (the closed form cancels catastrophically there), else (cos πx − sinc x)/x |
//! | [`sinc_d2`] | d²/dx² sinc(x) = −π² sinc(x) − 2 cosc(x)/x | even Taylor series for \|x\| < 0.25 |
//! | [`bessel_i0`], [`bessel_i1_over_x`] | modified Bessel I₀(x), I₁(x)/x | power series (all terms positive: no cancellation) |
//! | [`bessel_j0`] | Bessel J₀(x) | power series (\|x\| ≤ 2), Miller's backward recurrence normalised by J₀ + 2ΣJ₂ₖ = 1 (\|x\| ≤ 25), Hankel's asymptotic expansion beyond |
//! | [`sine_integral`] | Si(x) = ∫₀ˣ sin t / t dt | power series (\|x\| ≤ 4), else Si(x) = π/2 + Im E₁(ix) with E₁ from its continued fraction (modified Lentz) |
//! | [`erf`] | (2/√π)∫₀ˣ e^{−t²} dt | the positive series (2/√π) e^{−x²} Σ 2ⁿx^{2n+1}/(2n+1)!! for \|x\| ≤ 6, ±1 beyond |
//!
//! References: Abramowitz & Stegun, *Handbook of Mathematical Functions* (1964), §§ 5.1–5.2
//! (sine integral, E₁ continued fraction 5.1.22), 7.1.6 (erf series), 9.1.10, 9.1.27, 9.2.5
//! (J₀ series, recurrence, asymptotics), 9.6.10 (I₀ series); Julia `Base.Math.cosc` for the
//! Taylor switch of cosc at |x| ≈ 0.14; pbrt-v4 `Sinc` zero handling.

use rustfft::num_complex::Complex64;
use std::f64::consts::{FRAC_PI_2, PI};

/// sin(πx) for every finite x, exact at integers (returns ±0).
///
/// The argument is reduced first: `x % 2` is exact in IEEE arithmetic, and the folds
/// y − 2, 1 − y are exact by Sterbenz's lemma, so only one rounding (π·y, |y| ≤ ½) remains.
/// Non-finite x gives NaN, like `f64::sin`.
pub fn sin_pi(x: f64) -> f64 {
    if !x.is_finite() {
        return f64::NAN;
    }
    let mut y = x % 2.0; // exact, in (−2, 2)
    if y > 1.0 {
        y -= 2.0;
    } else if y < -1.0 {
        y += 2.0;
    }
    // y ∈ [−1, 1]; sin(πy) = sin(π(1 − y)).
    if y > 0.5 {
        y = 1.0 - y;
    } else if y < -0.5 {
        y = -1.0 - y;
    }
    (PI * y).sin()
}

/// cos(πx) for every finite x, exact at integers (±1) and half-integers (0).
///
/// Same exact reduction as [`sin_pi`]. Non-finite x gives NaN.
pub fn cos_pi(x: f64) -> f64 {
    if !x.is_finite() {
        return f64::NAN;
    }
    let mut y = x.abs() % 2.0; // exact, in [0, 2)
    if y > 1.0 {
        y = 2.0 - y; // cos(π(2 − y)) = cos(πy)
    }
    // y ∈ [0, 1]
    if y <= 0.25 {
        (PI * y).cos()
    } else if y < 0.75 {
        (PI * (0.5 - y)).sin()
    } else {
        -(PI * (1.0 - y)).cos()
    }
}

/// Normalised sinc: sinc(x) = sin(πx)/(πx), with sinc(0) = 1 exactly.
///
/// Its Fourier transform is the unit box on |ω| ≤ ½ (ω in cycles per unit of x). For
/// |x| < 10⁻⁴ the Taylor polynomial 1 − u/6 + u²/120, u = (πx)², is exact to below half an
/// ulp (the next term is u³/5040 < 10⁻²⁴). Finite for every finite x (sinc(1e300) = 0).
pub fn sinc(x: f64) -> f64 {
    if x.abs() < 1e-4 {
        let u = (PI * x) * (PI * x);
        1.0 - u / 6.0 + u * u / 120.0
    } else {
        sin_pi(x) / (PI * x)
    }
}

/// Taylor coefficients of cosc: cosc(x) = π·(πx)·Σ_{k≥1} c_k u^{k−1}, u = (πx)²,
/// c_k = (−1)^k 2k/(2k+1)!.
const COSC_TAYLOR: [f64; 9] = [
    -2.0 / 6.0,
    4.0 / 120.0,
    -6.0 / 5040.0,
    8.0 / 362_880.0,
    -10.0 / 39_916_800.0,
    12.0 / 6_227_020_800.0,
    -14.0 / 1_307_674_368_000.0,
    16.0 / 355_687_428_096_000.0,
    -18.0 / 121_645_100_408_832_000.0,
];

/// Below this |x|, [`cosc`] uses its Taylor series (as Julia's `cosc` does).
pub const COSC_TAYLOR_SWITCH: f64 = 0.14;

/// The derivative of the normalised sinc (the lecture's Cosc):
/// cosc(x) = d/dx sinc(x) = cos(πx)/x − sin(πx)/(πx²) = (πx cos πx − sin πx)/(πx²).
///
/// cosc(0) = 0, cosc(1) = −1, cosc is odd, and its Fourier transform is 2πiω on |ω| < ½.
/// For |x| < 0.14 the closed form subtracts two nearly equal numbers; there the odd Taylor
/// series π·(πx)·Σ (−1)^k 2k (πx)^{2k−2}/(2k+1)! (9 terms, truncation < 10⁻²¹ relative) is
/// used. Elsewhere (cos πx − sinc x)/x, which never overflows (cosc(1e300) = 1e-300).
pub fn cosc(x: f64) -> f64 {
    if x.abs() < COSC_TAYLOR_SWITCH {
        let t = PI * x;
        let u = t * t;
        let mut s = 0.0;
        for c in COSC_TAYLOR.iter().rev() {
            s = s * u + c;
        }
        PI * t * s
    } else {
        (cos_pi(x) - sinc(x)) / x
    }
}

/// Taylor coefficients of sinc'': sinc''(x) = π²·Σ_{k≥1} d_k u^{k−1}, u = (πx)²,
/// d_k = (−1)^k 2k(2k−1)/(2k+1)!.
const SINC_D2_TAYLOR: [f64; 11] = [
    -2.0 / 6.0,
    12.0 / 120.0,
    -30.0 / 5040.0,
    56.0 / 362_880.0,
    -90.0 / 39_916_800.0,
    132.0 / 6_227_020_800.0,
    -182.0 / 1_307_674_368_000.0,
    240.0 / 355_687_428_096_000.0,
    -306.0 / 121_645_100_408_832_000.0,
    380.0 / 51_090_942_171_709_440_000.0,
    -462.0 / 25_852_016_738_884_976_640_000.0,
];

/// Second derivative of the normalised sinc: sinc''(x) = cosc'(x) = −π² sinc(x) − 2 cosc(x)/x,
/// with sinc''(0) = −π²/3. Even Taylor series π² Σ (−1)^k 2k(2k−1)(πx)^{2k−2}/(2k+1)! for
/// |x| < 0.25 (11 terms), closed form elsewhere. Finite for every finite x.
pub fn sinc_d2(x: f64) -> f64 {
    if x.abs() < 0.25 {
        let t = PI * x;
        let u = t * t;
        let mut s = 0.0;
        for c in SINC_D2_TAYLOR.iter().rev() {
            s = s * u + c;
        }
        PI * PI * s
    } else {
        -PI * PI * sinc(x) - 2.0 * cosc(x) / x
    }
}

/// Modified Bessel function of the first kind of order 0:
/// I₀(x) = Σ_{k≥0} (x/2)^{2k} / (k!)² (A&S 9.6.10).
///
/// Every term is positive, so the sum is accurate to a few ulps; it is summed until a term no
/// longer changes it. Overflows to +∞ for |x| > ~713 (the true value exceeds f64::MAX); NaN in,
/// NaN out.
pub fn bessel_i0(x: f64) -> f64 {
    if x.is_nan() {
        return f64::NAN;
    }
    let ax = x.abs();
    if ax > 713.0 {
        return f64::INFINITY;
    }
    let q = 0.25 * ax * ax;
    let mut term = 1.0;
    let mut sum = 1.0;
    let mut k = 1.0;
    loop {
        term *= q / (k * k);
        let next = sum + term;
        if next == sum {
            break;
        }
        sum = next;
        k += 1.0;
    }
    sum
}

/// I₁(x)/x = Σ_{k≥0} (x/2)^{2k} / (2·k!(k+1)!), the regular form used by the derivative of the
/// Kaiser window (equals ½ at x = 0). Positive series like [`bessel_i0`]; +∞ for |x| > ~713.
pub fn bessel_i1_over_x(x: f64) -> f64 {
    if x.is_nan() {
        return f64::NAN;
    }
    let ax = x.abs();
    if ax > 713.0 {
        return f64::INFINITY;
    }
    let q = 0.25 * ax * ax;
    let mut term = 0.5;
    let mut sum = 0.5;
    let mut k = 1.0;
    loop {
        term *= q / (k * (k + 1.0));
        let next = sum + term;
        if next == sum {
            break;
        }
        sum = next;
        k += 1.0;
    }
    sum
}

/// Bessel function of the first kind of order 0, J₀(x) = (1/π)∫₀^π cos(x sin θ) dθ.
///
/// |x| ≤ 2: power series Σ (−1)^k (x²/4)^k/(k!)² (A&S 9.1.10). |x| ≤ 25: Miller's backward
/// recurrence J_{k−1} = (2k/x)J_k − J_{k+1} from k = ⌊x⌋ + 40, normalised with
/// J₀ + 2Σ_{k≥1} J_{2k} = 1 (A&S 9.1.27, 9.1.46). Beyond: Hankel's asymptotic expansion
/// J₀(x) = √(2/(πx)) (P cos χ − Q sin χ), χ = x − π/4 (A&S 9.2.5), summed until the terms stop
/// decreasing (the smallest term is ≈ e^{−2x} < 10⁻²¹). Absolute error ≈ 10⁻¹⁶.
pub fn bessel_j0(x: f64) -> f64 {
    if x.is_nan() {
        return f64::NAN;
    }
    let ax = x.abs();
    if ax.is_infinite() {
        return 0.0;
    }
    if ax <= 2.0 {
        let q = -0.25 * ax * ax;
        let mut term = 1.0;
        let mut sum = 1.0;
        let mut k = 1.0;
        loop {
            term *= q / (k * k);
            let next = sum + term;
            if next == sum {
                break;
            }
            sum = next;
            k += 1.0;
        }
        sum
    } else if ax <= 25.0 {
        // Backward recurrence from an even start index far above x.
        let mut n = ax as usize + 40;
        if n % 2 == 1 {
            n += 1;
        }
        let mut j_next = 0.0; // J_{k+1}
        let mut j = 1e-30; // J_k, k = n
        let mut norm = 0.0; // 2 Σ J_{2k}, k ≥ 1, in the same (arbitrary) scale
        let mut j0 = 0.0;
        for k in (1..=n).rev() {
            if k % 2 == 0 {
                norm += 2.0 * j;
            }
            let j_prev = (2.0 * k as f64 / ax) * j - j_next;
            j_next = j;
            j = j_prev;
            if j.abs() > 1e250 {
                j *= 1e-250;
                j_next *= 1e-250;
                norm *= 1e-250;
            }
            if k == 1 {
                j0 = j;
            }
        }
        j0 / (j0 + norm)
    } else {
        let (p, q) = hankel_pq(ax);
        let (s, c) = ax.sin_cos();
        // cos(x − π/4) = (cos x + sin x)/√2, sin(x − π/4) = (sin x − cos x)/√2.
        let cos_chi = (c + s) * std::f64::consts::FRAC_1_SQRT_2;
        let sin_chi = (s - c) * std::f64::consts::FRAC_1_SQRT_2;
        (2.0 / (PI * ax)).sqrt() * (p * cos_chi - q * sin_chi)
    }
}

/// P₀(x), Q₀(x) of Hankel's asymptotic expansion: a_k = a_{k−1}·(−(2k−1)²)/(8k), a₀ = 1;
/// P = Σ_{k even} (−1)^{k/2} a_k/x^k, Q = Σ_{k odd} (−1)^{(k−1)/2} a_k/x^k.
fn hankel_pq(x: f64) -> (f64, f64) {
    let mut p = 1.0;
    let mut q = 0.0;
    let mut a = 1.0; // a_k / x^k
    let mut last = f64::INFINITY;
    for k in 1..200 {
        let kf = k as f64;
        a *= -((2.0 * kf - 1.0) * (2.0 * kf - 1.0)) / (8.0 * kf * x);
        let t = a.abs();
        if t >= last || t < 1e-18 {
            break;
        }
        last = t;
        // (−1)^{⌊k/2⌋} sign pattern of A&S 9.2.9/9.2.10.
        let sign = if (k / 2) % 2 == 0 { 1.0 } else { -1.0 };
        if k % 2 == 0 {
            p += sign * a;
        } else {
            q += sign * a;
        }
    }
    (p, q)
}

/// The sine integral Si(x) = ∫₀ˣ sin(t)/t dt (odd; Si(±∞) = ±π/2; maximum Si(π) ≈ 1.8519).
///
/// |x| ≤ 4: power series Σ (−1)^k x^{2k+1}/((2k+1)(2k+1)!) (A&S 5.2.14). Otherwise
/// Si(x) = π/2 + Im E₁(ix) where E₁(z) = e^{−z}/(z + 1 − 1²/(z + 3 − 2²/(z + 5 − …)))
/// (A&S 5.1.22, 5.2.23) is evaluated with the modified Lentz algorithm to relative 10⁻¹⁶.
/// Absolute error ≈ 10⁻¹⁵. Si(±∞) = ±π/2; NaN in, NaN out.
pub fn sine_integral(x: f64) -> f64 {
    if x.is_nan() {
        return f64::NAN;
    }
    if x < 0.0 {
        return -sine_integral(-x);
    }
    if x > 1e6 {
        // Si(x) = π/2 − f(x) cos x − g(x) sin x with f ≈ 1/x − 2/x³, g ≈ 1/x² − 6/x⁴; the omitted
        // terms are below 10⁻¹⁷ here (and the continued fraction's complex arithmetic would
        // overflow for x ≳ 1e150).
        if x.is_infinite() {
            return FRAC_PI_2;
        }
        let (s, c) = x.sin_cos();
        let r = 1.0 / x;
        return FRAC_PI_2 - c * r * (1.0 - 2.0 * r * r) - s * r * r * (1.0 - 6.0 * r * r);
    }
    if x <= 4.0 {
        let q = -x * x;
        let mut t = x; // (−1)^k x^{2k+1}/(2k+1)!
        let mut sum = x;
        let mut k = 1.0;
        loop {
            t *= q / ((2.0 * k) * (2.0 * k + 1.0));
            let term = t / (2.0 * k + 1.0);
            let next = sum + term;
            if next == sum {
                break;
            }
            sum = next;
            k += 1.0;
        }
        sum
    } else {
        let z = Complex64::new(0.0, x);
        let tiny = 1e-300;
        let b0 = z + 1.0;
        let mut f = b0;
        let mut c = b0;
        let mut d = Complex64::new(0.0, 0.0);
        for k in 1..100_000u32 {
            let kf = k as f64;
            let a = -kf * kf;
            let b = z + (2.0 * kf + 1.0);
            d = b + d * a;
            if d.norm() < tiny {
                d = Complex64::new(tiny, 0.0);
            }
            c = b + a / c;
            if c.norm() < tiny {
                c = Complex64::new(tiny, 0.0);
            }
            d = d.inv();
            let delta = c * d;
            f *= delta;
            if (delta - 1.0).norm() < 1e-16 {
                break;
            }
        }
        let (s, co) = x.sin_cos();
        let e1 = Complex64::new(co, -s) / f;
        FRAC_PI_2 + e1.im
    }
}

/// The error function erf(x) = (2/√π)∫₀ˣ e^{−t²} dt.
///
/// |x| < 2: erf(x) = (2/√π) e^{−x²} Σ_{n≥0} 2ⁿ x^{2n+1}/(1·3·…·(2n+1)) (A&S 7.1.6), a series of
/// positive terms (relative error a few ulps). |x| ≥ 2: 1 − [`erfc`]`(|x|)` with the sign of x.
pub fn erf(x: f64) -> f64 {
    if x.is_nan() {
        return f64::NAN;
    }
    let ax = x.abs();
    if ax >= 2.0 {
        return (1.0 - erfc(ax)).copysign(x);
    }
    let q = 2.0 * ax * ax;
    let mut term = ax;
    let mut sum = ax;
    let mut n = 1.0;
    loop {
        term *= q / (2.0 * n + 1.0);
        let next = sum + term;
        if next == sum {
            break;
        }
        sum = next;
        n += 1.0;
    }
    let v = (2.0 / PI.sqrt()) * (-ax * ax).exp() * sum;
    v.min(1.0).copysign(x)
}

/// The complementary error function erfc(x) = 1 − erf(x) = (2/√π)∫ₓ^∞ e^{−t²} dt, accurate to a
/// few ulps *relative* for x ≥ 2 (where 1 − erf would cancel).
///
/// x ≥ 2: the continued fraction erfc(x) = (e^{−x²}/√π)·1/(x + (1/2)/(x + 1/(x + (3/2)/(x + …))))
/// (A&S 7.1.14) by the modified Lentz algorithm; x < 2: 1 − [`erf`]`(x)`. erfc(+∞) = 0,
/// erfc(−∞) = 2; underflows to 0 for x > ~26.6.
pub fn erfc(x: f64) -> f64 {
    if x.is_nan() {
        return f64::NAN;
    }
    if x < 2.0 {
        return 1.0 - erf(x);
    }
    if x > 27.0 {
        return 0.0;
    }
    let tiny = 1e-300;
    let mut f = x;
    let mut c = x;
    let mut d = 0.0;
    for k in 1..10_000u32 {
        let a = 0.5 * k as f64;
        d = x + a * d;
        if d.abs() < tiny {
            d = tiny;
        }
        c = x + a / c;
        if c.abs() < tiny {
            c = tiny;
        }
        d = 1.0 / d;
        let delta = c * d;
        f *= delta;
        if (delta - 1.0).abs() < 1e-16 {
            break;
        }
    }
    (-x * x).exp() / (PI.sqrt() * f)
}

#[cfg(test)]
#[allow(clippy::excessive_precision)] // reference values are quoted to 20 digits (mpmath)
mod tests {
    use super::*;

    // Reference values computed with mpmath at 30 digits (mp.dps = 30).

    #[test]
    fn sin_pi_cos_pi_exact_at_integers_and_half_integers() {
        for n in [-7.0, -2.0, -1.0, 0.0, 1.0, 2.0, 3.0, 1e15, 1e300] {
            assert_eq!(sin_pi(n), 0.0, "sin_pi({n})");
        }
        for n in [-3.5, -0.5, 0.5, 1.5, 2.5, 1e15 + 0.5] {
            assert_eq!(cos_pi(n), 0.0, "cos_pi({n})");
        }
        assert_eq!(cos_pi(0.0), 1.0);
        assert_eq!(cos_pi(1.0), -1.0);
        assert_eq!(cos_pi(2.0), 1.0);
        assert_eq!(cos_pi(-3.0), -1.0);
        assert_eq!(sin_pi(0.5), 1.0);
        assert_eq!(sin_pi(-0.5), -1.0);
    }

    #[test]
    fn sin_pi_cos_pi_match_std_for_moderate_arguments() {
        // Reference: f64::sin(π x) is accurate for |x| ≤ 4 up to the rounding of π x (≤ 2e-15).
        let mut x = -4.0;
        while x <= 4.0 {
            assert!((sin_pi(x) - (PI * x).sin()).abs() < 4e-15, "sin_pi({x})");
            assert!((cos_pi(x) - (PI * x).cos()).abs() < 4e-15, "cos_pi({x})");
            x += 0.0137;
        }
    }

    #[test]
    fn sin_pi_large_argument_reduction() {
        // 2^51 + 0.5 is exactly representable: sin(π(2^51 + ½)) = sin(π/2) = 1 since 2^51 is even.
        let x = 2_251_799_813_685_248.5;
        assert_eq!(sin_pi(x), 1.0);
        assert_eq!(cos_pi(x), 0.0);
        // 2^51 + 1.5: sin = −1.
        assert_eq!(sin_pi(2_251_799_813_685_249.5), -1.0);
        // Naive sin(π x) is wrong in every digit there.
        assert!(((PI * x).sin() - 1.0).abs() > 1e-3);
    }

    #[test]
    fn sinc_reference_values() {
        let cases = [
            (0.5, 0.636_619_772_367_581_3),   // 2/π
            (0.25, 0.900_316_316_157_106_1),  // (√2/2)/(π/4)
            (1.5, -0.212_206_590_789_193_78), // −2/(3π)
            (1e-3, 0.999_998_355_066_744_9),
        ];
        for (x, want) in cases {
            assert!((sinc(x) - want).abs() < 2e-16, "sinc({x}) = {}", sinc(x));
        }
    }

    #[test]
    fn sinc_d2_matches_finite_difference_of_cosc() {
        // Reference: central difference of cosc (independent of the sinc'' series), h = 1e-5,
        // truncation error h²/6·|sinc⁗| ≲ 2e-9.
        let h = 1e-5;
        let mut x = -3.0;
        while x <= 3.0 {
            let fd = (cosc(x + h) - cosc(x - h)) / (2.0 * h);
            assert!((sinc_d2(x) - fd).abs() < 1e-8, "x = {x}");
            x += 0.0173;
        }
        assert!((sinc_d2(0.0) + PI * PI / 3.0).abs() < 1e-15);
    }

    #[test]
    fn bessel_i0_reference_values() {
        let cases = [
            (0.0, 1.0),
            (1.0, 1.266_065_877_752_008_4),
            (5.0, 27.239_871_823_604_45),
            (10.0, 2_815.716_628_466_254),
            (50.0, 2.932_553_783_849_336e20),
        ];
        for (x, want) in cases {
            let got = bessel_i0(x);
            assert!(((got - want) / want).abs() < 4e-16 * 8.0, "I0({x}) = {got}");
        }
        assert!(bessel_i0(1e300).is_infinite());
    }

    #[test]
    fn bessel_i1_over_x_reference_values() {
        // I1(1) = 0.565159103992485027, I1(10) = 2670.98830370125465.
        assert_eq!(bessel_i1_over_x(0.0), 0.5);
        assert!((bessel_i1_over_x(1.0) - 0.565_159_103_992_485).abs() < 1e-15);
        assert!((bessel_i1_over_x(10.0) - 267.098_830_370_125_47).abs() < 1e-12);
    }

    #[test]
    fn bessel_j0_reference_values() {
        let cases = [
            (0.0, 1.0),
            (1.0, 0.765_197_686_557_966_6),
            (2.0, 0.223_890_779_141_235_67),
            (2.404_825_557_695_773, -1.201_195_007_367_685_8e-16),
            (5.0, -0.177_596_771_314_338_3),
            (10.0, -0.245_935_764_451_348_34),
            (24.9, 0.083_245_968_353_015_68),
            (25.1, 0.108_275_671_499_949_29),
            (100.0, 0.019_985_850_304_223_122),
            (1000.0, 0.024_786_686_152_420_17),
        ];
        for (x, want) in cases {
            let got = bessel_j0(x);
            assert!((got - want).abs() < 3e-15, "J0({x}) = {got}, want {want}");
            assert_eq!(bessel_j0(-x), got);
        }
    }

    #[test]
    fn bessel_j0_matches_trapezoid_integral_representation() {
        // Reference: J0(x) = (1/π)∫₀^π cos(x sin θ) dθ by the trapezoid rule, which converges
        // exponentially for this periodic analytic integrand (m = 400 nodes for x ≤ 60).
        let m = 400;
        let mut x = 0.05;
        while x < 60.0 {
            let mut s = 0.5 * (1.0 + (x * PI.sin()).cos());
            for i in 1..m {
                let th = PI * i as f64 / m as f64;
                s += (x * th.sin()).cos();
            }
            let reference = s / m as f64;
            assert!((bessel_j0(x) - reference).abs() < 5e-15, "x = {x}");
            x += 0.731;
        }
    }

    #[test]
    fn sine_integral_reference_values() {
        let cases = [
            (0.5, 0.493_107_418_043_066_7),
            (1.0, 0.946_083_070_367_183),
            (PI, 1.851_937_051_982_466_2),
            (4.0, 1.758_203_138_949_053),
            (4.000_001, 1.758_202_949_748_371_2),
            (10.0, 1.658_347_594_218_874),
            (20.0, 1.548_241_701_043_439_9),
            (100.0, 1.562_225_466_889_056_3),
            (1e6, 1.570_795_390_043_119),
        ];
        for (x, want) in cases {
            let got = sine_integral(x);
            assert!((got - want).abs() < 2e-15, "Si({x}) = {got}, want {want}");
            assert_eq!(sine_integral(-x), -got);
        }
        assert_eq!(sine_integral(f64::INFINITY), FRAC_PI_2);
        assert!(sine_integral(1e300).is_finite());
    }

    #[test]
    fn erf_reference_values() {
        let cases = [
            (0.1, 0.112_462_916_018_284_9),
            (0.5, 0.520_499_877_813_046_5),
            (1.0, 0.842_700_792_949_714_9),
            (2.0, 0.995_322_265_018_952_7),
            (3.0, 0.999_977_909_503_001_4),
            (5.9, 0.999_999_999_999_999_9),
        ];
        for (x, want) in cases {
            let got = erf(x);
            assert!((got - want).abs() < 3e-16, "erf({x}) = {got}");
            assert_eq!(erf(-x), -got);
        }
        assert_eq!(erf(7.0), 1.0);
        // erfc(3) = 2.20904969985854413727e-5, erfc(10) = 2.08848758376254474700e-45.
        assert!((erfc(3.0) / 2.209_049_699_858_544e-5 - 1.0).abs() < 1e-15);
        assert!((erfc(10.0) / 2.088_487_583_762_544_7e-45 - 1.0).abs() < 1e-14);
        assert_eq!(erf(0.0), 0.0);
    }
}
