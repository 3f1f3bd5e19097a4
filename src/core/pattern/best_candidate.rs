//! Mitchell's best-candidate sampling.
use super::*;

pub fn best_candidate(
    p: &BestCandidate,
    n: usize,
    seed: u64,
    cancel: &Cancel,
) -> Result<Vec<DVec2>, PatternError> {
    let _ = (p, n, seed, cancel);
    unimplemented!()
}
