//! Poisson-disk patterns: dart throwing and Bridson.
use super::*;

pub fn dart(
    p: &PoissonDart,
    n: usize,
    seed: u64,
    cancel: &Cancel,
) -> Result<Generated, PatternError> {
    let _ = (p, n, seed, cancel);
    unimplemented!()
}
pub fn bridson(
    p: &PoissonBridson,
    n: usize,
    seed: u64,
    cancel: &Cancel,
) -> Result<Generated, PatternError> {
    let _ = (p, n, seed, cancel);
    unimplemented!()
}
