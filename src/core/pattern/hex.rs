//! Hexagonal lattice on the torus.
use super::*;

pub fn hex(p: &Hex, n: usize, seed: u64) -> Result<Vec<DVec2>, PatternError> {
    let _ = (p, n, seed);
    unimplemented!()
}
