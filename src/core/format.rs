//! The one number formatter: how many digits a number is written with, in messages, labels and figures.
//!
//! **Significant digits** ([`significant`]; [`fmt_num`] with [`SIGNIFICANT`] = 6 is the
//! default of every message and label): the shortest decimal that reads back as the number
//! when it has at most that many significant digits (`0.1`, `5e-324`), else the number
//! rounded to that many (half to even on its exact binary value, as `format!` rounds), written
//! - plainly when the rounded value lies in 10⁻⁴ ≤ |x| < 10⁶ (`0.000123457`, `12.3457`,
//!   `123457`); an integer part with more digits than asked is written whole, never rounded
//!   (two digits of 512 are `512`);
//! - in scientific notation outside (`1.23457e8`, `1e-7`, `5e-324`), Rust's exponent form;
//! - with the trailing zeros of its fraction or mantissa dropped (`60`, `0.25`, `2e10`);
//! - zero as `0` (`-0` for −0), infinities and NaN as `inf`, `-inf`, `NaN`.
//!
//! [`plain`] is the same rounding always in plain notation (the axis tick labels: `0.02`,
//! `1000000`); [`decimals`] a fixed number of decimal places with trailing zeros dropped (the
//! lengths and coefficients of SVG and PDF text: `12.5`, `-0.25`, never `-0`).

/// The significant digits of [`fmt_num`]: every message and label.
pub const SIGNIFICANT: usize = 6;

/// A number for an error message or a label: [`significant`] with [`SIGNIFICANT`] digits
/// (123456789 is `1.23457e8`, 12.3456789 is `12.3457`, 5e-324 is `5e-324`).
pub fn fmt_num(v: f64) -> String {
    significant(v, SIGNIFICANT)
}

/// `x` rounded to `digits` (at least 1) significant digits, plain for 10⁻⁴ ≤ |x| < 10⁶ and
/// scientific outside (see the module docs).
pub fn significant(x: f64, digits: usize) -> String {
    write(x, digits, false)
}

/// `x` rounded to `digits` (at least 1) significant digits, always in plain notation (an
/// integer part is written whole): the axis tick labels (`plain(0.02, 1)` is `0.02`,
/// `plain(2e6, 1)` is `2000000`).
pub fn plain(x: f64, digits: usize) -> String {
    write(x, digits, true)
}

/// `x` with at most `places` decimals, trailing zeros dropped, and `0` for a value that rounds
/// to zero from below (`decimals(12.5, 2)` is `12.5`, `decimals(-0.001, 2)` is `0`).
pub fn decimals(x: f64, places: usize) -> String {
    let s = trim_fraction(format!("{x:.places$}"));
    if s == "-0" {
        "0".into()
    } else {
        s
    }
}

fn write(x: f64, digits: usize, always_plain: bool) -> String {
    if !x.is_finite() || x == 0.0 {
        return format!("{x}");
    }
    let digits = digits.max(1);
    // The shortest decimal that reads back as x when it has few enough digits (5e-324, not
    // 4.94066e-324), else x rounded; either way in scientific notation first, whose exponent
    // is the written value's magnitude (9.999996 to six digits is 1.00000e1).
    let shortest = format!("{x:e}");
    let shortest_digits = shortest
        .split('e')
        .next()
        .unwrap_or("")
        .chars()
        .filter(char::is_ascii_digit)
        .count();
    let exact = shortest_digits <= digits;
    let sci = if exact {
        shortest
    } else {
        format!("{:.*e}", digits - 1, x)
    };
    let (mantissa, exp) = sci.split_once('e').unwrap_or((&sci, "0"));
    let exp: i32 = exp.parse().unwrap_or(0);
    if always_plain || (-4..6).contains(&exp) {
        if exact {
            format!("{x}")
        } else {
            // Rounding at the mantissa's last place, 10^(exp − digits + 1); an integer part is
            // written whole.
            let places = (digits as i32 - 1 - exp).max(0) as usize;
            trim_fraction(format!("{x:.places$}"))
        }
    } else {
        format!("{}e{exp}", trim_fraction(mantissa.to_string()))
    }
}

/// Drops the trailing zeros of a fraction (and a bare point): `12.50` → `12.5`, `3.000` → `3`.
fn trim_fraction(s: String) -> String {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn six_significant_digits_table() {
        let cases: &[(f64, &str)] = &[
            (0.0, "0"),
            (-0.0, "-0"),
            (1.0, "1"),
            (-2.5, "-2.5"),
            (60.0, "60"),
            (0.25, "0.25"),
            (0.1 + 0.2, "0.3"),
            (12.345_678_9, "12.3457"),
            (123_456.7, "123457"),
            (999_999.4, "999999"),
            (999_999.7, "1e6"),
            (123_456_789.0, "1.23457e8"),
            (-123_456_789.0, "-1.23457e8"),
            (1e6, "1e6"),
            (2e10, "2e10"),
            (1e-4, "0.0001"),
            (0.000_123_456_789, "0.000123457"),
            (0.000_099_999_99, "0.0001"),
            (0.000_099_999_9, "9.99999e-5"),
            (1e-7, "1e-7"),
            (5e-324, "5e-324"),
            (f64::MAX, "1.79769e308"),
            (9.999_996, "10"),
            (9.999_994, "9.99999"),
            (f64::INFINITY, "inf"),
            (f64::NEG_INFINITY, "-inf"),
            (f64::NAN, "NaN"),
        ];
        for &(x, want) in cases {
            assert_eq!(fmt_num(x), want, "fmt_num({x:e})");
        }
    }

    #[test]
    fn fewer_digits_keep_the_integer_part_whole() {
        assert_eq!(significant(512.0, 2), "512");
        assert_eq!(significant(1.6, 2), "1.6");
        assert_eq!(significant(9.96, 2), "10");
        assert_eq!(significant(0.976_562_5, 2), "0.98");
        assert_eq!(significant(43.2, 2), "43");
        assert_eq!(significant(2e10, 2), "2e10");
        assert_eq!(significant(0.0, 2), "0");
        assert_eq!(significant(3.0, 0), "3");
    }

    #[test]
    fn plain_never_switches_to_scientific() {
        assert_eq!(plain(0.02, 1), "0.02");
        assert_eq!(plain(0.5, 1), "0.5");
        assert_eq!(plain(200.0, 1), "200");
        assert_eq!(plain(2e6, 1), "2000000");
        assert_eq!(plain(1e-5, 1), "0.00001");
        assert_eq!(plain(0.300_000_000_000_000_04, 1), "0.3");
    }

    #[test]
    fn decimals_are_short_and_signless_at_zero() {
        assert_eq!(decimals(12.0, 2), "12");
        assert_eq!(decimals(12.5, 2), "12.5");
        assert_eq!(decimals(-0.25, 2), "-0.25");
        assert_eq!(decimals(-0.001, 2), "0");
        assert_eq!(decimals(0.123_456, 5), "0.12346");
        assert_eq!(decimals(f64::from(0.1f32), 2), "0.1");
    }
}
