//! A small, portable, deterministic random number generator.
//!
//! samplescope promises the same bits for the same `(parameters, seed)` on every platform and
//! every run, so it does not depend on a third-party RNG whose stream may change between
//! versions. [`Rng`] is xoshiro256** (Blackman & Vigna 2018) seeded through SplitMix64.

/// SplitMix64 step: a bijective 64-bit mixer, also used to derive child seeds.
#[inline]
pub fn splitmix64(state: &mut u64) -> u64 {
    *state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
    let mut z = *state;
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// Derives the seed of child stream `index` from `seed` (e.g. realization r of an average,
/// or pixel p of a supersampled image). Distinct `(seed, index)` pairs give unrelated streams.
#[inline]
pub fn derive_seed(seed: u64, index: u64) -> u64 {
    let mut s = seed ^ index.wrapping_mul(0xD1B5_4A32_D192_ED03);
    splitmix64(&mut s);
    splitmix64(&mut s)
}

/// The value [`Rng::next_f64`] makes of 64 random bits: their top 53 as k · 2⁻⁵³ ∈ [0, 1).
#[inline(always)]
pub fn unit_f64(bits: u64) -> f64 {
    (bits >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
}

/// xoshiro256** generator.
#[derive(Clone, Debug)]
pub struct Rng {
    s: [u64; 4],
}

impl Rng {
    /// A generator whose whole stream is a function of `seed`.
    pub fn new(seed: u64) -> Self {
        let mut sm = seed;
        let s = [
            splitmix64(&mut sm),
            splitmix64(&mut sm),
            splitmix64(&mut sm),
            splitmix64(&mut sm),
        ];
        Rng { s }
    }

    /// Next 64 random bits.
    #[inline]
    pub fn next_u64(&mut self) -> u64 {
        let result = self.s[1].wrapping_mul(5).rotate_left(7).wrapping_mul(9);
        self.advance();
        result
    }

    /// The state update of xoshiro256** (one step of the stream).
    #[inline(always)]
    fn advance(&mut self) {
        let t = self.s[1] << 17;
        self.s[2] ^= self.s[0];
        self.s[3] ^= self.s[1];
        self.s[1] ^= self.s[2];
        self.s[0] ^= self.s[3];
        self.s[2] ^= t;
        self.s[3] = self.s[3].rotate_left(45);
    }

    /// Next 32 random bits.
    #[inline]
    pub fn next_u32(&mut self) -> u32 {
        (self.next_u64() >> 32) as u32
    }

    /// Uniform in [0, 1) with 53 random bits: k · 2⁻⁵³, k ∈ [0, 2⁵³). Never returns 1.0.
    #[inline]
    pub fn next_f64(&mut self) -> f64 {
        unit_f64(self.next_u64())
    }

    /// Advances the stream by `count` values without producing them (the state updates of
    /// [`Rng::next_u64`] alone): afterwards the generator is where `count` calls would leave it.
    #[inline]
    pub fn skip(&mut self, count: u64) {
        for _ in 0..count {
            self.advance();
        }
    }

    /// Uniform integer in [0, bound) without modulo bias (Lemire 2019). `bound` must be > 0.
    #[inline]
    pub fn below(&mut self, bound: u64) -> u64 {
        debug_assert!(bound > 0);
        let mut m = (self.next_u64() as u128) * (bound as u128);
        let mut low = m as u64;
        if low < bound {
            let threshold = bound.wrapping_neg() % bound;
            while low < threshold {
                m = (self.next_u64() as u128) * (bound as u128);
                low = m as u64;
            }
        }
        (m >> 64) as u64
    }

    /// Fisher–Yates shuffle in place.
    pub fn shuffle<T>(&mut self, items: &mut [T]) {
        for i in (1..items.len()).rev() {
            let j = self.below(i as u64 + 1) as usize;
            items.swap(i, j);
        }
    }

    /// A uniformly random permutation of 0..n.
    pub fn permutation(&mut self, n: usize) -> Vec<usize> {
        let mut p: Vec<usize> = (0..n).collect();
        self.shuffle(&mut p);
        p
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn same_seed_same_stream_and_f64_in_unit_interval() {
        let mut a = Rng::new(7);
        let mut b = Rng::new(7);
        for _ in 0..1000 {
            let x = a.next_f64();
            assert_eq!(x.to_bits(), b.next_f64().to_bits());
            assert!((0.0..1.0).contains(&x));
        }
    }

    #[test]
    fn skip_lands_where_the_values_would_and_unit_f64_is_next_f64() {
        for count in [0u64, 1, 2, 7, 1000] {
            let mut a = Rng::new(5);
            let mut b = Rng::new(5);
            for _ in 0..count {
                a.next_u64();
            }
            b.skip(count);
            assert_eq!(a.next_u64(), b.next_u64(), "count {count}");
        }
        let (mut a, mut b) = (Rng::new(9), Rng::new(9));
        for _ in 0..100 {
            assert_eq!(a.next_f64().to_bits(), unit_f64(b.next_u64()).to_bits());
        }
    }

    #[test]
    fn below_is_uniform_chi_square() {
        // 10 bins, 100_000 draws: chi-square with 9 dof; 99.9% quantile is 27.88.
        let mut r = Rng::new(1);
        let mut bins = [0u32; 10];
        for _ in 0..100_000 {
            bins[r.below(10) as usize] += 1;
        }
        let e = 10_000.0;
        let chi: f64 = bins.iter().map(|&c| (c as f64 - e).powi(2) / e).sum();
        assert!(chi < 27.88, "chi-square {chi}");
    }

    #[test]
    fn permutation_is_a_permutation() {
        let mut r = Rng::new(3);
        let mut p = r.permutation(1000);
        p.sort_unstable();
        assert!(p.iter().enumerate().all(|(i, &v)| i == v));
    }
}
