//! Stratified patterns: grid, random, jitter, N-rooks, Latin hypercube, multi-jitter, correlated multi-jitter.
use super::*;

pub fn grid(p: &Grid, n: usize) -> Result<Vec<DVec2>, PatternError> {
    let _ = (p, n);
    unimplemented!()
}
pub fn random(n: usize, seed: u64) -> Vec<DVec2> {
    let _ = (n, seed);
    unimplemented!()
}
pub fn jitter(p: &Jitter, n: usize, seed: u64) -> Result<Vec<DVec2>, PatternError> {
    let _ = (p, n, seed);
    unimplemented!()
}
pub fn nrooks(p: &NRooks, n: usize, seed: u64) -> Vec<DVec2> {
    let _ = (p, n, seed);
    unimplemented!()
}
pub fn lhs(p: &Lhs, n: usize, seed: u64) -> Result<Vec<DVec2>, PatternError> {
    let _ = (p, n, seed);
    unimplemented!()
}
pub fn multijitter(p: &MultiJitter, n: usize, seed: u64) -> Result<Vec<DVec2>, PatternError> {
    let _ = (p, n, seed);
    unimplemented!()
}
pub fn correlated_multijitter(
    p: &CorrelatedMultiJitter,
    n: usize,
    seed: u64,
) -> Result<Vec<DVec2>, PatternError> {
    let _ = (p, n, seed);
    unimplemented!()
}
