//! Low-discrepancy sequences: the lecture's tables, hand-computed values, exact rational
//! references, the (0,m,2)-net property of the Sobol' sequence, validation and determinism.

use glam::DVec2;
use samplescope::core::params::Params;
use samplescope::core::pattern::lowdisc::{self, owen_scramble, sobol_point_u32};
use samplescope::core::pattern::radical_inverse::{
    folded_radical_inverse, radical_inverse, radical_inverse_table, try_radical_inverse, PRIMES,
};
use samplescope::core::pattern::sphere::{pattern_to_sphere, square_to_sphere};
use samplescope::core::pattern::{
    Halton, HaltonZaremba, Hammersley, HammersleyZaremba, Pattern, PatternError, Scramble, Sobol,
    VanDerCorput, MAX_N, ONE_MINUS_EPSILON,
};
use samplescope::core::rng::{derive_seed, Rng};

// ---------------------------------------------------------------------------------------------
// Independent references
// ---------------------------------------------------------------------------------------------

/// num/den (0 ≤ num < den < 2¹²⁶) correctly rounded to f64: binary long division until the
/// quotient q has 127 significant bits (value = q · 2^−e), then one rounding in the u128 → f64
/// conversion, with a sticky bit standing for a non-zero remainder.
fn ratio_to_f64(num: u128, den: u128) -> f64 {
    assert!(num < den && den < 1 << 126);
    if num == 0 {
        return 0.0;
    }
    let (mut r, mut q, mut e) = (num, 0u128, 0i32);
    while q < 1 << 126 {
        r <<= 1;
        q <<= 1;
        e += 1;
        if r >= den {
            r -= den;
            q |= 1;
        }
    }
    let sticky = u128::from(r != 0);
    ((q | sticky) as f64) * 2f64.powi(-e)
}

/// Φ_b(n) as the exact rational Σ a_i b^{k−i} / b^k (u128), digit by digit.
fn radical_inverse_exact(n: u64, b: u32) -> (u128, u128) {
    let b = u128::from(b);
    let (mut num, mut den, mut m) = (0u128, 1u128, u128::from(n));
    while m > 0 {
        num = num * b + m % b;
        den *= b;
        m /= b;
    }
    (num, den)
}

/// Φ⁺_b(n) as an exact rational: the folded digits d_i = (a_i + i − 1) mod b for i = 1..=M, with
/// M the first multiple of b ≥ the length of n, then the periodic tail 0.(0 1 2 … b−1)_b repeated,
/// worth P/(b^b − 1) with P = Σ_{j=1}^{b} (j−1) b^{b−j}. So Φ⁺ = (N_M (b^b − 1) + P) / (b^M (b^b − 1)).
fn folded_exact(n: u64, b: u32) -> (u128, u128) {
    let bb = u128::from(b);
    let mut len = 0u32;
    let mut m = n;
    while m > 0 {
        len += 1;
        m /= u64::from(b);
    }
    let big_m = len.div_ceil(b).max(1) * b;
    let (mut num, mut den, mut rest) = (0u128, 1u128, u128::from(n));
    for i in 1..=big_m {
        let a = rest % bb;
        rest /= bb;
        num = num * bb + (a + u128::from(i - 1)) % bb;
        den *= bb;
    }
    let period = bb.pow(b) - 1;
    let p: u128 = (1..=b).fold(0, |acc, j| acc * bb + u128::from(j - 1));
    (num * period + p, den * period)
}

/// Distance in units in the last place.
fn ulps(a: f64, b: f64) -> u64 {
    (a.to_bits() as i64 - b.to_bits() as i64).unsigned_abs()
}

/// Random n with every magnitude represented: 64 random bits shifted right by 0..64.
fn random_indices(seed: u64, count: usize) -> Vec<u64> {
    let mut rng = Rng::new(seed);
    (0..count)
        .map(|_| rng.next_u64() >> rng.below(64))
        .collect()
}

// ---------------------------------------------------------------------------------------------
// Radical inverse
// ---------------------------------------------------------------------------------------------

#[test]
fn van_der_corput_table_matches_lecture() {
    // Lecture, "Van Der Corput Sequence": i | binary form of i | radical inverse | x_i.
    let want = [
        (0, "0", "0.0", 0.0),
        (1, "1", "0.1", 0.5),
        (2, "10", "0.01", 0.25),
        (3, "11", "0.11", 0.75),
        (4, "100", "0.001", 0.125),
        (5, "101", "0.101", 0.625),
        (6, "110", "0.011", 0.375),
    ];
    let table = radical_inverse_table(2, 7).unwrap();
    assert_eq!(table.len(), 7);
    for (row, &(i, bin, rev, x)) in table.iter().zip(&want) {
        assert_eq!(row.i, i);
        assert_eq!(row.digits_string(), bin);
        assert_eq!(row.reversed_string(), rev);
        assert_eq!(row.value, x);
    }
    let pts = Pattern::VanDerCorput(VanDerCorput { base: 2 })
        .generate(7, 0)
        .unwrap();
    for (p, &(_, _, _, x)) in pts.iter().zip(&want) {
        assert_eq!(*p, DVec2::new(x, 0.5));
    }
}

#[test]
fn radical_inverse_u64_max_edge_below_one_for_all_1000_primes() {
    assert_eq!(PRIMES.len(), 1000);
    assert_eq!(PRIMES[999], 7919);
    for &b in PRIMES.iter() {
        let x = radical_inverse(u64::MAX, b);
        assert!((0.0..1.0).contains(&x), "base {b}: {x}");
        assert!(x <= ONE_MINUS_EPSILON);
        let f = folded_radical_inverse(u64::MAX, b);
        assert!((0.0..1.0).contains(&f), "folded base {b}: {f}");
    }
    // In base 2 the exact value 1 − 2⁻⁶⁴ rounds to 1.0 and must be clamped.
    assert_eq!(radical_inverse(u64::MAX, 2), ONE_MINUS_EPSILON);
}

#[test]
fn radical_inverse_matches_exact_rational_within_2_ulp() {
    // Reference: the exact rational num/den (u128), correctly rounded. The implementation is
    // correctly rounded (0 ulp) in base 2 and whenever num, den ≤ 2⁵³; within 2 ulp otherwise.
    let mut bases: Vec<u32> = vec![2, 3, 5, 7, 11, 13, 97, 251, 4093, 7919];
    let mut rng = Rng::new(2024);
    bases.extend((0..20).map(|_| PRIMES[rng.below(1000) as usize]));
    let mut worst = 0;
    for &b in &bases {
        for n in random_indices(u64::from(b), 2000) {
            let (num, den) = radical_inverse_exact(n, b);
            let want = ratio_to_f64(num, den).min(ONE_MINUS_EPSILON);
            let got = radical_inverse(n, b);
            let e = ulps(got, want);
            worst = worst.max(e);
            if b == 2 || (num <= 1 << 53 && den <= 1 << 53) {
                assert_eq!(got, want, "b={b} n={n}: not correctly rounded");
            }
            assert!(e <= 2, "b={b} n={n}: {got} vs {want} ({e} ulp)");
        }
    }
    println!("radical_inverse worst error: {worst} ulp");
}

#[test]
fn try_radical_inverse_rejects_base_0_and_1() {
    for b in [0, 1] {
        match try_radical_inverse(3, b) {
            Err(PatternError::InvalidParam { field, .. }) => assert_eq!(field, "base"),
            other => panic!("base {b}: {other:?}"),
        }
    }
    assert_eq!(try_radical_inverse(5, 3), Ok(radical_inverse(5, 3)));
}

#[test]
fn folded_radical_inverse_matches_hand_computed_values() {
    // Derivations (digits a_i least significant first, folded digit d_i = (a_i + i − 1) mod b,
    // the digits of n beyond its length are 0 and are folded too):
    // base 2: n=0: 0.010101…₂ = 1/3; n=1: 0.1 1010…₂ = 1/2 + 1/3 = 5/6;
    //   n=2 (a=0,1): 0.00 0101…₂ = (1/4)(1/3) = 1/12; n=3 (a=1,1): 1/2 + 1/12 = 7/12;
    //   n=4 (a=0,0,1): 0.011 1010…₂ = 3/8 + 1/12 = 11/24; n=5 (a=1,0,1): 7/8 + 1/12 = 23/24.
    // base 3: the periodic tails 0.(012)₃ = 5/26, 0.(120)₃ = 15/26, 0.(201)₃ = 19/26:
    //   n=0: 5/26; n=1: 1/3 + (1/3)(15/26) = 41/78; n=2: 2/3 + 15/78 = 67/78;
    //   n=3 (a=0,1): d=0,2 then 0.(201): 2/9 + 19/234 = 71/234; n=4 (a=1,1): 1/3 + 71/234 = 149/234;
    //   n=5 (a=2,1): 2/3 + 71/234 = 227/234.
    // base 5: tails 0.(01234)₅ = 194/3124 = 97/1562, 0.(12340)₅ = 970/3124 = 485/1562,
    //   0.(23401)₅ = 1726/3124 = 863/1562: n=0: 97/1562; n=1: 1/5 + 485/7810 = 2047/7810;
    //   n=2: 2/5 + 485/7810 = 3609/7810; n=7 (a=2,1): d=2,2: 2/5 + 2/25 + 863/39050 = 19607/39050.
    let table: [(u32, u64, u64, u64); 16] = [
        (2, 0, 1, 3),
        (2, 1, 5, 6),
        (2, 2, 1, 12),
        (2, 3, 7, 12),
        (2, 4, 11, 24),
        (2, 5, 23, 24),
        (3, 0, 5, 26),
        (3, 1, 41, 78),
        (3, 2, 67, 78),
        (3, 3, 71, 234),
        (3, 4, 149, 234),
        (3, 5, 227, 234),
        (5, 0, 97, 1562),
        (5, 1, 2047, 7810),
        (5, 2, 3609, 7810),
        (5, 7, 19607, 39050),
    ];
    for &(b, n, p, q) in &table {
        let want = p as f64 / q as f64; // correctly rounded p/q
        let got = folded_radical_inverse(n, b);
        assert!(
            ulps(got, want) <= 3,
            "base {b}, n = {n}: {got} vs {p}/{q} = {want}"
        );
        // The reference itself agrees with the hand values exactly (as rationals).
        let (num, den) = folded_exact(n, b);
        assert_eq!(
            num * u128::from(q),
            den * u128::from(p),
            "reference, base {b}, n = {n}"
        );
    }
}

#[test]
fn folded_radical_inverse_matches_exact_periodic_series_within_3_ulp() {
    let mut worst = 0;
    for b in [2u32, 3, 5, 7, 11] {
        for n in random_indices(100 + u64::from(b), 2000)
            .into_iter()
            .chain([0, 1, u64::MAX])
        {
            let (num, den) = folded_exact(n, b);
            let want = ratio_to_f64(num, den).min(ONE_MINUS_EPSILON);
            let got = folded_radical_inverse(n, b);
            let e = ulps(got, want);
            worst = worst.max(e);
            assert!(e <= 3, "b={b} n={n}: {got} vs {want} ({e} ulp)");
        }
    }
    println!("folded_radical_inverse worst error: {worst} ulp");
}

// ---------------------------------------------------------------------------------------------
// Halton, Hammersley and their folded twins
// ---------------------------------------------------------------------------------------------

#[test]
fn halton_2_3_first_points_are_hand_computed() {
    // i = 3 = 10₃ → 0.01₃ = 1/9; i = 4 = 11₃ → 4/9; i = 5 = 12₃ → 2/3 + 1/9 = 7/9.
    let want = [
        (0, 1, 0, 1),
        (1, 2, 1, 3),
        (1, 4, 2, 3),
        (3, 4, 1, 9),
        (1, 8, 4, 9),
        (5, 8, 7, 9),
    ];
    let pts = lowdisc::halton(&Halton::default(), 6).unwrap();
    for (j, (p, &(a, b, c, d))) in pts.iter().zip(&want).enumerate() {
        // Both coordinates are correctly rounded quotients.
        assert_eq!(
            *p,
            DVec2::new(a as f64 / b as f64, c as f64 / d as f64),
            "i = {j}"
        );
    }
    let skipped = lowdisc::halton(
        &Halton {
            skip: 3,
            ..Halton::default()
        },
        3,
    )
    .unwrap();
    assert_eq!(skipped.as_slice(), &pts[3..6]);
}

#[test]
fn halton_and_hammersley_equal_radical_inverse_bit_for_bit() {
    let h = Halton {
        base_x: 7907,
        base_y: 3,
        skip: 4_000_000_000,
        ..Halton::default()
    };
    let pts = lowdisc::halton(&h, 5000).unwrap();
    for (j, p) in pts.iter().enumerate() {
        let i = u64::from(h.skip) + j as u64;
        assert_eq!(p.x.to_bits(), radical_inverse(i, 7907).to_bits());
        assert_eq!(p.y.to_bits(), radical_inverse(i, 3).to_bits());
    }
    let pts = lowdisc::hammersley(&Hammersley { p1: 5 }, 5000).unwrap();
    for (i, p) in pts.iter().enumerate() {
        assert_eq!(p.y.to_bits(), radical_inverse(i as u64, 5).to_bits());
    }
}

#[test]
fn hammersley_8_points_p1_3_are_hand_computed() {
    // x = i/8; y = Φ₃(i): 0, 1/3, 2/3, 1/9, 4/9, 7/9, 2/9 (6 = 20₃), 5/9 (7 = 21₃).
    let y = [
        (0, 1),
        (1, 3),
        (2, 3),
        (1, 9),
        (4, 9),
        (7, 9),
        (2, 9),
        (5, 9),
    ];
    let pts = lowdisc::hammersley(&Hammersley { p1: 3 }, 8).unwrap();
    assert_eq!(pts.len(), 8);
    for (i, (p, &(a, b))) in pts.iter().zip(&y).enumerate() {
        assert_eq!(
            *p,
            DVec2::new(i as f64 / 8.0, a as f64 / b as f64),
            "i = {i}"
        );
    }
}

#[test]
fn zaremba_twins_use_the_folded_inverse() {
    let hz = lowdisc::halton_zaremba(&HaltonZaremba::default(), 64).unwrap();
    let mz = lowdisc::hammersley_zaremba(&HammersleyZaremba { p1: 5 }, 64).unwrap();
    for i in 0..64u64 {
        let j = i as usize;
        assert_eq!(hz[j].x, folded_radical_inverse(i, 2));
        assert_eq!(hz[j].y, folded_radical_inverse(i, 3));
        assert_eq!(
            mz[j],
            DVec2::new(i as f64 / 64.0, folded_radical_inverse(i, 5))
        );
    }
    // Hand values: Halton–Zaremba (2,3) starts at (1/3, 5/26).
    assert!(ulps(hz[0].x, 1.0 / 3.0) <= 3 && ulps(hz[0].y, 5.0 / 26.0) <= 3);
}

#[test]
fn folded_hammersley_has_lower_star_discrepancy_on_average() {
    // Lecture: folding "improves discrepancy". Exact 2D star discrepancy of small sets (O(N³)
    // over the grid of point coordinates), averaged over N = 16..=64 for p1 = 2 and 3.
    fn star_discrepancy(pts: &[DVec2]) -> f64 {
        let n = pts.len() as f64;
        let mut xs: Vec<f64> = pts.iter().map(|p| p.x).chain([1.0]).collect();
        let mut ys: Vec<f64> = pts.iter().map(|p| p.y).chain([1.0]).collect();
        xs.sort_by(f64::total_cmp);
        ys.sort_by(f64::total_cmp);
        let mut d: f64 = 0.0;
        for &x in &xs {
            for &y in &ys {
                let open = pts.iter().filter(|p| p.x < x && p.y < y).count() as f64;
                let closed = pts.iter().filter(|p| p.x <= x && p.y <= y).count() as f64;
                d = d.max(x * y - open / n).max(closed / n - x * y);
            }
        }
        d
    }
    for p1 in [2u32, 3] {
        let (mut plain, mut folded) = (0.0, 0.0);
        for n in 16..=64 {
            plain += star_discrepancy(&lowdisc::hammersley(&Hammersley { p1 }, n).unwrap());
            folded += star_discrepancy(
                &lowdisc::hammersley_zaremba(&HammersleyZaremba { p1 }, n).unwrap(),
            );
        }
        assert!(
            folded < plain,
            "p1 = {p1}: folded {folded} vs plain {plain}"
        );
    }
}

// ---------------------------------------------------------------------------------------------
// Sobol'
// ---------------------------------------------------------------------------------------------

fn sobol_pts(scramble: Scramble, skip: u32, n: usize, seed: u64) -> Vec<DVec2> {
    lowdisc::sobol(&Sobol { scramble, skip }, n, seed).unwrap()
}

#[test]
fn sobol_unscrambled_first_points_are_the_known_sequence() {
    // Gray-code order, as produced by Joe & Kuo's generator and SciPy's qmc.Sobol(scramble=False).
    let want = [
        (0.0, 0.0),
        (0.5, 0.5),
        (0.75, 0.25),
        (0.25, 0.75),
        (0.375, 0.375),
        (0.875, 0.875),
        (0.625, 0.125),
        (0.125, 0.625),
        (0.1875, 0.3125),
        (0.6875, 0.8125),
    ];
    let pts = sobol_pts(Scramble::None, 0, want.len(), 0);
    for (p, &(x, y)) in pts.iter().zip(&want) {
        assert_eq!(*p, DVec2::new(x, y));
    }
}

#[test]
fn sobol_is_the_gray_code_permutation_of_the_matrix_reference() {
    let to_f = |v: u32| v as f64 / 4_294_967_296.0;
    for skip in [0u32, 1, 4095, 123_456_789, u32::MAX - 999] {
        let pts = sobol_pts(Scramble::None, skip, 1000, 0);
        for (j, p) in pts.iter().enumerate() {
            let i = skip + j as u32;
            let [x, y] = sobol_point_u32(i ^ (i >> 1));
            assert_eq!(*p, DVec2::new(to_f(x), to_f(y)), "skip {skip}, j {j}");
        }
    }
}

/// Every aligned block of 2^m points, m = 0..=max_m, has exactly one point in every elementary
/// interval [a 2^−k, (a+1) 2^−k) × [c 2^−(m−k), (c+1) 2^−(m−k)), k = 0..=m.
fn assert_02_sequence(pts: &[DVec2], max_m: u32, what: &str) {
    for m in 0..=max_m {
        let size = 1usize << m;
        let mut counts = vec![0u8; size];
        for (block, chunk) in pts.chunks_exact(size).enumerate() {
            for k in 0..=m {
                counts.iter_mut().for_each(|c| *c = 0);
                for p in chunk {
                    let a = (p.x * (1u64 << k) as f64) as usize;
                    let c = (p.y * (1u64 << (m - k)) as f64) as usize;
                    counts[(a << (m - k)) | c] += 1;
                }
                assert!(
                    counts.iter().all(|&c| c == 1),
                    "{what}: block {block} of 2^{m} points, intervals 2^-{k} x 2^-{}",
                    m - k
                );
            }
        }
    }
}

#[test]
fn sobol_every_aligned_block_is_a_0m2_net_for_all_scramblings() {
    let n = 1 << 13;
    for scramble in [Scramble::None, Scramble::RandomDigit, Scramble::Owen] {
        for seed in [0u64, 7, 0xFEED_F00D] {
            let pts = sobol_pts(scramble, 0, n, seed);
            assert_02_sequence(&pts, 12, &format!("{scramble:?} seed {seed}"));
        }
        // A skip that is a multiple of 2^12 keeps every block of ≤ 2^12 points aligned.
        let pts = sobol_pts(scramble, 5 << 12, n, 3);
        assert_02_sequence(&pts, 12, &format!("{scramble:?} skip 5·2^12"));
    }
}

#[test]
fn sobol_scramblings_differ_and_depend_on_the_seed() {
    let plain = sobol_pts(Scramble::None, 0, 256, 1);
    let rd = sobol_pts(Scramble::RandomDigit, 0, 256, 1);
    let owen = sobol_pts(Scramble::Owen, 0, 256, 1);
    assert_ne!(plain, rd);
    assert_ne!(plain, owen);
    assert_ne!(rd, owen);
    assert_ne!(owen, sobol_pts(Scramble::Owen, 0, 256, 2));
    assert_ne!(rd, sobol_pts(Scramble::RandomDigit, 0, 256, 2));
    // The unscrambled sequence ignores the seed.
    assert_eq!(plain, sobol_pts(Scramble::None, 0, 256, 99));
    // Random digit scrambling is an XOR with one word per dimension from Rng::new(seed).
    let mut rng = Rng::new(1);
    let (wx, wy) = (rng.next_u32(), rng.next_u32());
    let scale = 4_294_967_296.0;
    for (p, q) in plain.iter().zip(&rd) {
        assert_eq!(((p.x * scale) as u32) ^ wx, (q.x * scale) as u32);
        assert_eq!(((p.y * scale) as u32) ^ wy, (q.y * scale) as u32);
    }
}

#[test]
fn sobol_owen_is_owen_scramble_of_each_coordinate_with_derived_seeds() {
    let scale = 4_294_967_296.0;
    for (skip, seed) in [(0u32, 1u64), (12_345, 99), (u32::MAX - 499, 7)] {
        let plain = sobol_pts(Scramble::None, skip, 500, seed);
        let owen = sobol_pts(Scramble::Owen, skip, 500, seed);
        let (sx, sy) = (derive_seed(seed, 0), derive_seed(seed, 1));
        for (p, q) in plain.iter().zip(&owen) {
            assert_eq!(
                owen_scramble((p.x * scale) as u32, sx),
                (q.x * scale) as u32
            );
            assert_eq!(
                owen_scramble((p.y * scale) as u32, sy),
                (q.y * scale) as u32
            );
        }
    }
}

#[test]
fn sobol_skip_overflow_edge_is_an_error() {
    // The last index skip + n − 1 must fit in 32 bits.
    let ok = lowdisc::sobol(
        &Sobol {
            scramble: Scramble::None,
            skip: u32::MAX,
        },
        1,
        0,
    )
    .unwrap();
    assert_eq!(ok.len(), 1);
    let e = lowdisc::sobol(
        &Sobol {
            scramble: Scramble::Owen,
            skip: u32::MAX,
        },
        2,
        0,
    )
    .unwrap_err();
    match &e {
        PatternError::InvalidParam { pattern, field, .. } => {
            assert_eq!((*pattern, *field), ("sobol", "skip"));
        }
        other => panic!("{other:?}"),
    }
    assert!(e
        .to_string()
        .starts_with("sobol.skip = 4294967295: must be an integer in 0..=4294967294"));
}

// ---------------------------------------------------------------------------------------------
// Validation, determinism, range
// ---------------------------------------------------------------------------------------------

#[test]
fn non_prime_base_is_an_error_naming_the_field() {
    let e = lowdisc::halton(
        &Halton {
            base_x: 4,
            ..Halton::default()
        },
        8,
    )
    .unwrap_err();
    assert_eq!(
        e.to_string(),
        "halton.base_x = 4: must be a prime in 2..=7919"
    );
    let cases: Vec<(Result<Vec<DVec2>, PatternError>, &str)> = vec![
        (
            lowdisc::van_der_corput(&VanDerCorput { base: 1 }, 8),
            "van-der-corput.base = 1",
        ),
        (
            lowdisc::van_der_corput(&VanDerCorput { base: 0 }, 8),
            "van-der-corput.base = 0",
        ),
        (
            lowdisc::halton(
                &Halton {
                    base_y: 9,
                    ..Halton::default()
                },
                8,
            ),
            "halton.base_y = 9",
        ),
        (
            lowdisc::hammersley(&Hammersley { p1: 7927 }, 8),
            "hammersley.p1 = 7927",
        ),
        (
            lowdisc::halton_zaremba(
                &HaltonZaremba {
                    base_x: 15,
                    ..HaltonZaremba::default()
                },
                8,
            ),
            "halton-zaremba.base_x = 15",
        ),
        (
            lowdisc::hammersley_zaremba(&HammersleyZaremba { p1: 7921 }, 8),
            "hammersley-zaremba.p1 = 7921",
        ),
    ];
    for (r, prefix) in cases {
        let msg = r.unwrap_err().to_string();
        assert!(msg.starts_with(prefix), "{msg}");
        assert!(msg.contains("must be a prime in 2..=7919"), "{msg}");
    }
    // Through the dispatcher's text interface a base out of range or not prime is refused
    // when it is set, with the generators' words.
    let mut p = Pattern::from_name("halton").unwrap();
    assert!(p.set("base_x", "8000").is_err());
    let e = p.set("base_x", "6").unwrap_err().to_string();
    assert_eq!(e, "halton.base_x = 6: must be a prime in 2..=7919");
    assert!(p.generate(4, 0).is_ok());
}

#[test]
fn halton_equal_bases_are_rejected() {
    for r in [
        lowdisc::halton(
            &Halton {
                base_x: 5,
                base_y: 5,
                skip: 0,
                ..Halton::default()
            },
            8,
        ),
        lowdisc::halton_zaremba(
            &HaltonZaremba {
                base_x: 5,
                base_y: 5,
                skip: 0,
            },
            8,
        ),
    ] {
        let msg = r.unwrap_err().to_string();
        assert!(
            msg.contains("base_y = 5") && msg.contains("different from base_x"),
            "{msg}"
        );
    }
}

#[test]
fn n_zero_and_above_max_n_are_errors() {
    for n in [0, MAX_N + 1] {
        assert!(matches!(
            lowdisc::van_der_corput(&VanDerCorput::default(), n),
            Err(PatternError::InvalidN { .. })
        ));
        assert!(lowdisc::halton(&Halton::default(), n).is_err());
        assert!(lowdisc::hammersley(&Hammersley::default(), n).is_err());
        assert!(lowdisc::halton_zaremba(&HaltonZaremba::default(), n).is_err());
        assert!(lowdisc::hammersley_zaremba(&HammersleyZaremba::default(), n).is_err());
        assert!(lowdisc::sobol(&Sobol::default(), n, 0).is_err());
    }
}

fn all_lowdisc_patterns() -> Vec<Pattern> {
    let mut v = vec![
        Pattern::VanDerCorput(VanDerCorput { base: 2 }),
        Pattern::VanDerCorput(VanDerCorput { base: 7919 }),
        Pattern::Halton(Halton::default()),
        Pattern::Halton(Halton {
            base_x: 7907,
            base_y: 7919,
            skip: u32::MAX - 5000,
            ..Halton::default()
        }),
        Pattern::Hammersley(Hammersley { p1: 2 }),
        Pattern::Hammersley(Hammersley { p1: 11 }),
        Pattern::HaltonZaremba(HaltonZaremba::default()),
        Pattern::HaltonZaremba(HaltonZaremba {
            base_x: 7907,
            base_y: 7919,
            skip: u32::MAX,
        }),
        Pattern::HammersleyZaremba(HammersleyZaremba { p1: 3 }),
        Pattern::HammersleyZaremba(HammersleyZaremba { p1: 7919 }),
    ];
    for scramble in [Scramble::None, Scramble::RandomDigit, Scramble::Owen] {
        v.push(Pattern::Sobol(Sobol { scramble, skip: 0 }));
        v.push(Pattern::Sobol(Sobol {
            scramble,
            skip: u32::MAX - 4999,
        }));
    }
    v
}

#[test]
fn every_coordinate_is_in_the_half_open_unit_interval() {
    for p in all_lowdisc_patterns() {
        let pts = p.generate(5000, 17).unwrap();
        assert_eq!(pts.len(), 5000, "{p:?}");
        for q in &pts {
            assert!(
                (0.0..1.0).contains(&q.x) && (0.0..1.0).contains(&q.y),
                "{p:?}: {q:?}"
            );
        }
    }
}

#[test]
fn same_parameters_and_seed_give_the_same_bits() {
    for p in all_lowdisc_patterns() {
        let a = p.generate(777, 42).unwrap();
        let b = p.generate(777, 42).unwrap();
        let bits = |v: &[DVec2]| -> Vec<(u64, u64)> {
            v.iter().map(|q| (q.x.to_bits(), q.y.to_bits())).collect()
        };
        assert_eq!(bits(&a), bits(&b), "{p:?}");
        // Progressive sequences: a prefix of a longer run is the shorter run.
        if p.is_progressive() {
            let long = p.generate(1000, 42).unwrap();
            assert_eq!(bits(&long[..777]), bits(&a), "{p:?}");
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Sphere
// ---------------------------------------------------------------------------------------------

#[test]
fn sphere_points_have_unit_length() {
    let pts = sobol_pts(Scramble::Owen, 0, 1 << 14, 5);
    for q in pattern_to_sphere(&pts) {
        assert!((q.length() - 1.0).abs() < 1e-12, "{q:?}");
    }
}

#[test]
fn sphere_map_preserves_area_of_caps() {
    // Fine grid of cell centres on the square; the fraction landing in a cap of height h
    // must be the cap's area fraction (1 − h)/2 (Archimedes), within 1e-3.
    let g = 1000;
    let grid: Vec<DVec2> = (0..g * g)
        .map(|k| {
            DVec2::new(
                ((k % g) as f64 + 0.5) / g as f64,
                ((k / g) as f64 + 0.5) / g as f64,
            )
        })
        .collect();
    let sph = pattern_to_sphere(&grid);
    for h in [-0.9, -0.5, 0.0, 0.3, 0.77, 0.95] {
        let want = (1.0 - h) / 2.0;
        // Polar cap z > h, and caps around the x and y axes (these exercise φ and r as well).
        let fz = sph.iter().filter(|q| q.z > h).count() as f64 / grid.len() as f64;
        let fx = sph.iter().filter(|q| q.x > h).count() as f64 / grid.len() as f64;
        let fy = sph.iter().filter(|q| -q.y > h).count() as f64 / grid.len() as f64;
        for (axis, f) in [("z", fz), ("x", fx), ("-y", fy)] {
            assert!((f - want).abs() < 1e-3, "cap {axis} > {h}: {f} vs {want}");
        }
    }
    assert_eq!(square_to_sphere(DVec2::new(0.0, 0.0)).z, 1.0);
}
