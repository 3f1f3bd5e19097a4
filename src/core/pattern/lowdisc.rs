//! Low-discrepancy sequences.
use super::*;

pub fn van_der_corput(p: &VanDerCorput, n: usize) -> Result<Vec<DVec2>, PatternError> {
    let _ = (p, n);
    unimplemented!()
}
pub fn halton(p: &Halton, n: usize) -> Result<Vec<DVec2>, PatternError> {
    let _ = (p, n);
    unimplemented!()
}
pub fn hammersley(p: &Hammersley, n: usize) -> Result<Vec<DVec2>, PatternError> {
    let _ = (p, n);
    unimplemented!()
}
pub fn halton_zaremba(p: &HaltonZaremba, n: usize) -> Result<Vec<DVec2>, PatternError> {
    let _ = (p, n);
    unimplemented!()
}
pub fn hammersley_zaremba(p: &HammersleyZaremba, n: usize) -> Result<Vec<DVec2>, PatternError> {
    let _ = (p, n);
    unimplemented!()
}
pub fn sobol(p: &Sobol, n: usize, seed: u64) -> Result<Vec<DVec2>, PatternError> {
    let _ = (p, n, seed);
    unimplemented!()
}
