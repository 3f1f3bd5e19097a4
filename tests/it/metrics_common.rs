//! Point sets shared by the metrics tests, built here (not by the pattern module) so the
//! tests do not depend on the samplers they are meant to measure.
#![allow(dead_code)]

use glam::DVec2;
use samplescope::core::rng::Rng;

/// `n` uniform random points (fixed seed).
pub fn random(n: usize, seed: u64) -> Vec<DVec2> {
    let mut r = Rng::new(seed);
    (0..n)
        .map(|_| DVec2::new(r.next_f64(), r.next_f64()))
        .collect()
}

/// Van der Corput Φ₂(i) on 32 bits: bit reversal of i, divided by 2³².
pub fn phi2(i: u32) -> f64 {
    i.reverse_bits() as f64 / 4_294_967_296.0
}

/// Hammersley in base 2: (i/N, Φ₂(i)), i = 0..N.
pub fn hammersley2(n: usize) -> Vec<DVec2> {
    (0..n)
        .map(|i| DVec2::new(i as f64 / n as f64, phi2(i as u32)))
        .collect()
}

/// Second dimension of the unscrambled Sobol' sequence (primitive polynomial x + 1):
/// direction numbers v_1 = 2³¹, v_k = v_{k−1} XOR (v_{k−1} >> 1); x_i = XOR of v_k over the
/// set bits k of i (bit k−1 of i, the direct — not Gray-code — ordering).
pub fn sobol_dim1(i: u32) -> f64 {
    let mut v = 1u32 << 31;
    let mut x = 0u32;
    let mut bits = i;
    while bits != 0 {
        if bits & 1 == 1 {
            x ^= v;
        }
        v ^= v >> 1;
        bits >>= 1;
    }
    x as f64 / 4_294_967_296.0
}

/// The first n points of the unscrambled Sobol' (0,2)-sequence: (Φ₂(i), sobol_dim1(i)).
pub fn sobol(n: usize) -> Vec<DVec2> {
    (0..n as u32)
        .map(|i| DVec2::new(phi2(i), sobol_dim1(i)))
        .collect()
}

/// Jittered k×k grid.
pub fn jittered(k: usize, seed: u64) -> Vec<DVec2> {
    let mut r = Rng::new(seed);
    let mut v = Vec::with_capacity(k * k);
    for j in 0..k {
        for i in 0..k {
            v.push(DVec2::new(
                (i as f64 + r.next_f64()) / k as f64,
                (j as f64 + r.next_f64()) / k as f64,
            ));
        }
    }
    v
}

/// Cell centres of a k×k grid.
pub fn grid(k: usize) -> Vec<DVec2> {
    let mut v = Vec::with_capacity(k * k);
    for j in 0..k {
        for i in 0..k {
            v.push(DVec2::new(
                (i as f64 + 0.5) / k as f64,
                (j as f64 + 0.5) / k as f64,
            ));
        }
    }
    v
}
