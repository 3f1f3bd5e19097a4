//! Double-double arithmetic: error-free transformations for accurate sums.
//!
//! A [`Dd`] is an unevaluated sum `hi + lo` with `|lo| ≤ ulp(hi)/2`, carrying ~106 bits.
//! `two_sum` (Knuth) and `two_prod` (Dekker/Veltkamp splitting, no FMA needed) are exact:
//! `a + b = s + e` and `a · b = p + e` in real arithmetic (barring overflow/underflow).
//! Reference: T. J. Dekker, *A floating-point technique for extending the available
//! precision*, Numer. Math. 1971; Hida, Li, Bailey, *Library for double-double and
//! quad-double arithmetic*, 2007.

/// `a + b = s + e` exactly.
#[inline]
pub(crate) fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    let e = (a - (s - bb)) + (b - bb);
    (s, e)
}

/// `a + b = s + e` exactly, provided `|a| ≥ |b|` (or `a == 0`).
#[inline]
fn fast_two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let e = b - (s - a);
    (s, e)
}

/// Veltkamp split: `a = hi + lo` with both halves holding at most 26 significant bits.
#[inline]
fn split(a: f64) -> (f64, f64) {
    const FACTOR: f64 = 134_217_729.0; // 2^27 + 1
    let c = FACTOR * a;
    let hi = c - (c - a);
    (hi, a - hi)
}

/// `a · b = p + e` exactly (Dekker), for |a|, |b| well inside the f64 range.
#[inline]
pub(crate) fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    let (ah, al) = split(a);
    let (bh, bl) = split(b);
    let e = ((ah * bh - p) + ah * bl + al * bh) + al * bl;
    (p, e)
}

/// A double-double number `hi + lo`.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(crate) struct Dd {
    pub hi: f64,
    pub lo: f64,
}

impl Dd {
    pub const ZERO: Dd = Dd { hi: 0.0, lo: 0.0 };

    #[inline]
    pub fn from_f64(x: f64) -> Dd {
        Dd { hi: x, lo: 0.0 }
    }

    /// The exact product `a · b` as a double-double.
    #[inline]
    pub fn from_prod(a: f64, b: f64) -> Dd {
        let (hi, lo) = two_prod(a, b);
        Dd { hi, lo }
    }

    /// `self + b`.
    #[inline]
    pub fn add_f64(self, b: f64) -> Dd {
        let (s, e) = two_sum(self.hi, b);
        let (hi, lo) = fast_two_sum(s, e + self.lo);
        Dd { hi, lo }
    }

    /// `self + o` (Hida–Li–Bailey "sloppy" addition is not enough under cancellation, so this
    /// is the accurate variant).
    #[inline]
    pub fn add(self, o: Dd) -> Dd {
        let (s, e) = two_sum(self.hi, o.hi);
        let (t, f) = two_sum(self.lo, o.lo);
        let (s, e) = fast_two_sum(s, e + t);
        let (hi, lo) = fast_two_sum(s, e + f);
        Dd { hi, lo }
    }

    #[inline]
    pub fn neg(self) -> Dd {
        Dd {
            hi: -self.hi,
            lo: -self.lo,
        }
    }

    /// `self · b`.
    #[inline]
    pub fn mul_f64(self, b: f64) -> Dd {
        let (p, e) = two_prod(self.hi, b);
        let (hi, lo) = fast_two_sum(p, e + self.lo * b);
        Dd { hi, lo }
    }

    /// `self · o`.
    #[inline]
    pub fn mul(self, o: Dd) -> Dd {
        let (p, e) = two_prod(self.hi, o.hi);
        let (hi, lo) = fast_two_sum(p, e + (self.hi * o.lo + self.lo * o.hi));
        Dd { hi, lo }
    }

    /// `self / b`.
    #[inline]
    pub fn div_f64(self, b: f64) -> Dd {
        let q1 = self.hi / b;
        let (p, e) = two_prod(q1, b);
        let r = ((self.hi - p) - e + self.lo) / b;
        let (hi, lo) = fast_two_sum(q1, r);
        Dd { hi, lo }
    }

    /// Rounded to the nearest f64.
    #[inline]
    pub fn to_f64(self) -> f64 {
        self.hi + self.lo
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::rng::Rng;

    #[test]
    fn two_prod_is_exact_on_dyadic_values() {
        // Products of 26-bit integers scaled by powers of two are exact in f64; products of
        // 53-bit ones are not, and p + e must recover them exactly (checked in u128).
        let mut r = Rng::new(11);
        for _ in 0..1000 {
            let a = (r.next_u64() >> 11) as f64; // 53-bit integer
            let b = (r.next_u64() >> 11) as f64;
            let (p, e) = two_prod(a, b);
            let exact = (a as u128) * (b as u128);
            let got = p as i128 + e as i128;
            assert_eq!(got as u128, exact);
        }
    }

    #[test]
    fn sum_of_many_tenths_is_accurate() {
        // Σ_{k<10^5} 0.1 in double-double equals 10^5 · fl(0.1) to ~1e-25 relative.
        let mut acc = Dd::ZERO;
        for _ in 0..100_000 {
            acc = acc.add_f64(0.1);
        }
        let exact = Dd::from_prod(0.1, 100_000.0);
        let diff = acc.add(exact.neg());
        assert!(diff.to_f64().abs() < 1e-20, "{diff:?}");
    }

    #[test]
    fn division_by_nine_recovers_one_ninth() {
        let ninth = Dd::from_f64(1.0).div_f64(9.0);
        let back = ninth.mul_f64(9.0).add_f64(-1.0);
        assert!(back.to_f64().abs() < 1e-30, "{back:?}");
    }
}
