//! Error-free transformations, double-double arithmetic and `sin(πx)`, `cos(πx)` with exact
//! argument reduction.
//!
//! The zone plate's phase π K |p − c|² reaches 10⁸ π and more; evaluated naively in `f64` its
//! absolute error is about K|p − c|²·2⁻⁵³·π (3·10⁻⁸ at K|p − c|² = 10⁸), which is visible
//! after the `sin`. Here the phase is carried in units of π (so that the reduction "mod 2π"
//! becomes "mod 2", an exact operation on binary floating point) and as a double-double
//! (an unevaluated sum `hi + lo`, about 106 significant bits):
//!
//! - [`two_sum`] (Knuth 1969) and [`two_prod`] (Dekker 1971, Veltkamp splitting; no FMA needed,
//!   so the bits are the same on every platform) return a result and its exact rounding error;
//! - [`DoubleDouble`] adds and multiplies with relative error ≲ 4·2⁻¹⁰⁶ (Dekker 1971;
//!   Joldes, Muller, Popescu 2017, "Tight and rigorous error bounds for basic building blocks
//!   of double-word arithmetic");
//! - [`rem2`] reduces a double-double modulo 2 into [−1, 1]: `hi % 2` and `lo % 2` are exact
//!   (IEEE `fmod` is exact), their sum is rounded once (|error| ≤ 2⁻⁵¹);
//! - [`sin_pi`] / [`cos_pi`] reduce `x mod 2` exactly, fold into [0, ¼] by exact symmetries
//!   (1 − r and ½ − r are exact by Sterbenz's lemma) and evaluate a Taylor polynomial of
//!   sin(πr) or cos(πr) on |r| ≤ ¼ (truncation error < 5·10⁻¹⁷). `sin_pi(n) = 0` exactly for
//!   every integer n, `sin_pi(n + ½) = ±1` exactly, unlike `(PI * x).sin()`.
//!
//! Only `+`, `−`, `×` and `%` are used, so every function here gives the same bits on every
//! IEEE-754 platform (no dependence on the C library's `sin`).

/// `s + e = a + b` exactly, with `s = fl(a + b)` (Knuth's TwoSum, 6 flops, any ordering).
#[inline]
pub fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    let e = (a - (s - bb)) + (b - bb);
    (s, e)
}

/// `s + e = a + b` exactly, requires `|a| ≥ |b|` or `a = 0` (Dekker's FastTwoSum).
#[inline]
pub fn fast_two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let e = b - (s - a);
    (s, e)
}

/// Veltkamp's splitting constant 2²⁷ + 1.
const SPLITTER: f64 = 134_217_729.0;

/// Splits `a` into `hi + lo` with both halves fitting in 26 bits (exact for |a| < 2⁹⁹⁶).
#[inline]
fn split(a: f64) -> (f64, f64) {
    let t = SPLITTER * a;
    let hi = t - (t - a);
    (hi, a - hi)
}

/// `p + e = a · b` exactly, with `p = fl(a · b)` (Dekker's TwoProduct; exact unless
/// `|a|`, `|b|` exceed 2⁹⁹⁶ or the product underflows).
#[inline]
pub fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    let (ah, al) = split(a);
    let (bh, bl) = split(b);
    let e = ((ah * bh - p) + ah * bl + al * bh) + al * bl;
    (p, e)
}

/// An unevaluated sum `hi + lo` with `|lo| ≤ ulp(hi)/2`: about 106 significant bits.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DoubleDouble {
    /// Leading part, `fl(hi + lo)`.
    pub hi: f64,
    /// Trailing part.
    pub lo: f64,
}

impl DoubleDouble {
    /// The exact value `x`.
    #[inline]
    pub fn from_f64(x: f64) -> Self {
        DoubleDouble { hi: x, lo: 0.0 }
    }

    /// `a − b` exactly.
    #[inline]
    pub fn diff(a: f64, b: f64) -> Self {
        let (hi, lo) = two_sum(a, -b);
        DoubleDouble { hi, lo }
    }

    /// `a · b` exactly.
    #[inline]
    pub fn prod(a: f64, b: f64) -> Self {
        let (hi, lo) = two_prod(a, b);
        DoubleDouble { hi, lo }
    }

    /// `self · b` for an `f64` b, relative error ≤ 3·2⁻¹⁰⁶.
    #[inline]
    pub fn mul_f64(self, b: f64) -> Self {
        let (p, e) = two_prod(self.hi, b);
        let e = e + self.lo * b;
        let (hi, lo) = fast_two_sum(p, e);
        DoubleDouble { hi, lo }
    }

    /// `self / b` for an `f64` b ≠ 0, relative error ≲ 4·2⁻¹⁰⁶ (long division: q₁ = hi/b, the
    /// remainder `self − q₁·b` formed exactly with [`two_prod`], q₂ = remainder/b).
    #[inline]
    pub fn div_f64(self, b: f64) -> Self {
        let q1 = self.hi / b;
        let (p, e) = two_prod(q1, b);
        // hi − p is exact (Sterbenz: p is within a rounding of hi).
        let r = ((self.hi - p) - e) + self.lo;
        let (hi, lo) = fast_two_sum(q1, r / b);
        DoubleDouble { hi, lo }
    }

    /// The nearest `f64` (to within one rounding).
    #[inline]
    pub fn to_f64(self) -> f64 {
        self.hi + self.lo
    }
}

impl std::ops::Neg for DoubleDouble {
    type Output = DoubleDouble;

    /// `−self`, exact.
    #[inline]
    fn neg(self) -> Self {
        DoubleDouble {
            hi: -self.hi,
            lo: -self.lo,
        }
    }
}

impl std::ops::Add for DoubleDouble {
    type Output = DoubleDouble;

    /// `self + other`, relative error ≤ 3·2⁻¹⁰⁶ (accurate double-word addition).
    #[inline]
    fn add(self, other: Self) -> Self {
        let (s, e) = two_sum(self.hi, other.hi);
        let (t, f) = two_sum(self.lo, other.lo);
        let (s, e) = fast_two_sum(s, e + t);
        let (hi, lo) = fast_two_sum(s, e + f);
        DoubleDouble { hi, lo }
    }
}

impl std::ops::Mul for DoubleDouble {
    type Output = DoubleDouble;

    /// `self · other`, relative error ≤ 5·2⁻¹⁰⁶.
    #[inline]
    fn mul(self, other: Self) -> Self {
        let (p, e) = two_prod(self.hi, other.hi);
        let e = e + (self.hi * other.lo + self.lo * other.hi);
        let (hi, lo) = fast_two_sum(p, e);
        DoubleDouble { hi, lo }
    }
}

/// Reduces `r` (any finite `f64`) modulo 2 into [−1, 1], exactly.
///
/// `r % 2` is exact (IEEE remainder truncated toward zero, |result| < 2); adding or
/// subtracting 2 from a value in (1, 2) is exact by Sterbenz's lemma.
#[inline]
pub fn rem2_f64(r: f64) -> f64 {
    let mut r = r % 2.0;
    if r > 1.0 {
        r -= 2.0;
    } else if r < -1.0 {
        r += 2.0;
    }
    r
}

/// `(x.hi + x.lo) mod 2`, as an `f64` in [−1, 1].
///
/// Both parts are reduced exactly; their sum (|sum| < 4) is rounded once, so the absolute
/// error is at most 2⁻⁵¹ ≈ 4.4·10⁻¹⁶ whatever the magnitude of `x`.
#[inline]
pub fn rem2(x: DoubleDouble) -> f64 {
    rem2_f64((x.hi % 2.0) + (x.lo % 2.0))
}

/// Taylor coefficients of sin(πr) = Σ S_k r^(2k+1): S_k = (−1)^k π^(2k+1)/(2k+1)!
/// (17 significant digits from a 40-digit mpmath evaluation; the compiler rounds them).
#[allow(clippy::excessive_precision)]
const SIN_PI_COEFFS: [f64; 8] = [
    std::f64::consts::PI,
    -5.167_712_780_049_970,
    2.550_164_039_877_345_4,
    -0.599_264_529_320_792_1,
    0.082_145_886_611_128_23,
    -0.007_370_430_945_714_351,
    0.000_466_302_805_767_612_56,
    -0.000_021_915_353_447_830_216,
];

/// Taylor coefficients of cos(πr) = Σ C_k r^(2k): C_k = (−1)^k π^(2k)/(2k)!.
#[allow(clippy::excessive_precision)]
const COS_PI_COEFFS: [f64; 9] = [
    1.0,
    -4.934_802_200_544_679,
    4.058_712_126_416_768,
    -1.335_262_768_854_589_5,
    0.235_330_630_358_893_2,
    -0.025_806_891_390_014_06,
    0.001_929_574_309_403_923,
    -0.000_104_638_104_924_845_71,
    0.000_004_303_069_587_032_947,
];

/// sin(πr) for |r| ≤ ¼ (Horner in r²).
#[inline]
fn sin_pi_kernel(r: f64) -> f64 {
    let z = r * r;
    let mut p = SIN_PI_COEFFS[7];
    for &c in SIN_PI_COEFFS[..7].iter().rev() {
        p = p * z + c;
    }
    p * r
}

/// cos(πr) for |r| ≤ ¼ (Horner in r²).
#[inline]
fn cos_pi_kernel(r: f64) -> f64 {
    let z = r * r;
    let mut p = COS_PI_COEFFS[8];
    for &c in COS_PI_COEFFS[..8].iter().rev() {
        p = p * z + c;
    }
    p
}

/// sin(πx) with exact reduction of x modulo 2.
///
/// Absolute error ≤ 3·10⁻¹⁶ for every finite x (x itself is taken as exact); `sin_pi(n) = ±0`
/// for integers n and `sin_pi(n + ½) = ±1` exactly. Returns NaN for a non-finite x.
pub fn sin_pi(x: f64) -> f64 {
    if !x.is_finite() {
        return f64::NAN;
    }
    let r = rem2_f64(x);
    let (r, negative) = if r < 0.0 { (-r, true) } else { (r, false) };
    // sin(π r) = sin(π (1 − r)); 1 − r is exact for r ∈ [½, 1].
    let r = if r > 0.5 { 1.0 - r } else { r };
    let v = if r <= 0.25 {
        sin_pi_kernel(r)
    } else {
        // sin(π r) = cos(π (½ − r)); ½ − r is exact for r ∈ [¼, ½].
        cos_pi_kernel(0.5 - r)
    };
    if negative {
        -v
    } else {
        v
    }
}

/// cos(πx) with exact reduction of x modulo 2.
///
/// Absolute error ≤ 3·10⁻¹⁶ for every finite x; `cos_pi(n + ½) = 0` and `cos_pi(n) = ±1`
/// exactly. Returns NaN for a non-finite x.
pub fn cos_pi(x: f64) -> f64 {
    if !x.is_finite() {
        return f64::NAN;
    }
    // cos is even: fold to r ∈ [0, 1].
    let r = rem2_f64(x).abs();
    // cos(π r) = −cos(π (1 − r)).
    let (r, negative) = if r > 0.5 { (1.0 - r, true) } else { (r, false) };
    let v = if r <= 0.25 {
        cos_pi_kernel(r)
    } else {
        // cos(π r) = sin(π (½ − r)).
        sin_pi_kernel(0.5 - r)
    };
    if negative {
        -v
    } else {
        v
    }
}

/// sinc_π(x) = sin(πx)/(πx), with sinc_π(0) = 1 (the normalised sinc of the lecture).
///
/// No cancellation: for small |x| `sin_pi(x)` is accurate to a relative 10⁻¹⁶, so the
/// quotient is too.
pub fn sinc_pi(x: f64) -> f64 {
    if x == 0.0 {
        1.0
    } else {
        sin_pi(x) / (std::f64::consts::PI * x)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::rng::Rng;

    #[test]
    fn two_prod_is_exact_on_small_integers_times_powers_of_two() {
        // (2^27 + 1)^2 = 2^54 + 2^28 + 1 is not representable; the error term holds the 1.
        let a = 134_217_729.0;
        let (p, e) = two_prod(a, a);
        assert_eq!(p, 18_014_398_777_917_440.0);
        assert_eq!(e, 1.0);
    }

    #[test]
    fn two_sum_recovers_lost_low_bits() {
        let (s, e) = two_sum(1.0, 1e-17);
        assert_eq!(s, 1.0);
        assert_eq!(e, 1e-17);
    }

    #[test]
    fn sin_pi_matches_std_sin_on_small_arguments() {
        // For |x| ≤ 4, (PI * x).sin() has error ≤ ~4·2⁻⁵³·4π, so 1e-14 is a fair tolerance.
        let mut rng = Rng::new(11);
        for _ in 0..20_000 {
            let x = (rng.next_f64() - 0.5) * 8.0;
            let a = sin_pi(x);
            let b = (std::f64::consts::PI * x).sin();
            assert!((a - b).abs() < 1e-14, "sin_pi({x}) = {a}, std {b}");
            let a = cos_pi(x);
            let b = (std::f64::consts::PI * x).cos();
            assert!((a - b).abs() < 1e-14, "cos_pi({x}) = {a}, std {b}");
        }
    }

    #[test]
    fn sin_pi_exact_at_integers_and_half_integers() {
        for n in [-1e15, -3.0, -1.0, 0.0, 1.0, 2.0, 7.0, 1e15, 2f64.powi(60)] {
            assert_eq!(sin_pi(n), 0.0, "sin_pi({n})");
            // n + ½ is representable only for |n| < 2⁵².
            if n.abs() < 2f64.powi(52) {
                assert_eq!(cos_pi(n + 0.5), 0.0, "cos_pi({n} + ½)");
            }
        }
        assert_eq!(sin_pi(0.5), 1.0);
        assert_eq!(sin_pi(-0.5), -1.0);
        assert_eq!(sin_pi(2.5), 1.0);
        assert_eq!(cos_pi(0.0), 1.0);
        assert_eq!(cos_pi(1.0), -1.0);
        assert_eq!(cos_pi(-3.0), -1.0);
    }

    #[test]
    fn sin_pi_known_values_table() {
        // sin(π/6) = ½, sin(π/4) = √2/2, sin(π/3) = √3/2: 1 ulp-ish tolerance 2e-16.
        assert!((sin_pi(1.0 / 6.0) - 0.5).abs() < 2e-16);
        assert!((sin_pi(0.25) - std::f64::consts::FRAC_1_SQRT_2).abs() < 2e-16);
        assert!((sin_pi(1.0 / 3.0) - 3f64.sqrt() / 2.0).abs() < 2e-16);
        assert!((cos_pi(1.0 / 3.0) - 0.5).abs() < 2e-16);
    }

    #[test]
    fn sin_pi_large_argument_reduced_exactly() {
        // x = 2^40 + 0.25 is exact in f64; sin(πx) = sin(π/4).
        let x = 2f64.powi(40) + 0.25;
        assert!((sin_pi(x) - std::f64::consts::FRAC_1_SQRT_2).abs() < 2e-16);
        // The naive evaluation loses ~2^40·2^-53·π ≈ 4e-4.
        let naive = (std::f64::consts::PI * x).sin();
        assert!((naive - std::f64::consts::FRAC_1_SQRT_2).abs() > 1e-6);
    }

    #[test]
    fn sin_pi_non_finite_is_nan() {
        assert!(sin_pi(f64::NAN).is_nan());
        assert!(sin_pi(f64::INFINITY).is_nan());
        assert!(cos_pi(f64::NEG_INFINITY).is_nan());
    }

    #[test]
    fn sinc_pi_zero_and_small_arguments() {
        assert_eq!(sinc_pi(0.0), 1.0);
        // Walk up from the smallest subnormal: sinc stays within a few ulps of 1 − (πx)²/6.
        let mut x = f64::from_bits(1);
        while x < 1e-4 {
            let s = sinc_pi(x);
            let t = 1.0 - (std::f64::consts::PI * x).powi(2) / 6.0;
            assert!((s - t).abs() < 5e-16, "sinc_pi({x}) = {s}");
            x *= 3.7;
        }
        assert!(sinc_pi(1.0).abs() < 1e-17);
        assert!((sinc_pi(0.5) - 2.0 / std::f64::consts::PI).abs() < 2e-16);
    }

    #[test]
    fn rem2_of_double_double_keeps_low_part() {
        // 2^60 + 0.5 (not representable in one f64) ≡ 0.5 (mod 2).
        let x = DoubleDouble {
            hi: 2f64.powi(60),
            lo: 0.5,
        };
        assert_eq!(rem2(x), 0.5);
        let y = DoubleDouble { hi: 3.0, lo: -0.25 };
        assert_eq!(rem2(y), 0.75);
    }

    #[test]
    fn double_double_div_f64_is_a_double_double_accurate_quotient() {
        // 1/3 = hi + lo to ~2⁻¹⁰⁶: 3·(hi + lo) − 1 must vanish to double-double accuracy.
        let q = DoubleDouble::from_f64(1.0).div_f64(3.0);
        let back = q.mul_f64(3.0) + DoubleDouble::from_f64(-1.0);
        assert!(back.to_f64().abs() < 1e-31, "{back:?}");
        assert!(q.lo != 0.0);
        // An exact quotient stays exact; a double-double numerator keeps its low part.
        let x = DoubleDouble { hi: 6.0, lo: 3e-17 };
        let y = x.div_f64(2.0);
        assert_eq!((y.hi, y.lo), (3.0, 1.5e-17));
        // (2⁶⁰ + 5)/7 against exact integer arithmetic: 7·q must give back the numerator.
        let n = DoubleDouble {
            hi: 2f64.powi(60),
            lo: 5.0,
        };
        let q = n.div_f64(7.0);
        let r = q.mul_f64(7.0) + (-n);
        assert!(r.to_f64().abs() < 1e-12, "{r:?}");
        assert_eq!((-q).hi, -q.hi);
    }

    #[test]
    fn double_double_mul_matches_exact_integer_product() {
        // (2^30 + 3)·(2^30 + 5) = 2^60 + 8·2^30 + 15, exact in i128.
        let a = DoubleDouble::from_f64((1u64 << 30) as f64 + 3.0);
        let b = DoubleDouble::from_f64((1u64 << 30) as f64 + 5.0);
        let p = a * b;
        let exact: i128 = ((1i128 << 30) + 3) * ((1i128 << 30) + 5);
        let got = p.hi as i128 + p.lo as i128;
        assert_eq!(got, exact);
    }
}
