//! Padded sampling as pbrt-v4 does it (its `PaddedSobolSampler`, and the padding of its
//! stratified and PMJ02 samplers): a 2D pattern padded to d dimensions.
//!
//! Dimension pair k (dimensions 2k, 2k + 1; an odd D's last pair keeps its x) is an
//! independent randomized copy of the 2D `base` pattern — generated with the seed
//! `derive_seed(seed, 2k)` — whose points are shuffled by a uniformly random permutation drawn
//! from `Rng::new(derive_seed(seed, 2k + 1))`. Each pair is therefore exactly the base
//! pattern (a PMJ02 pair is a (0,m,2)-net, a jittered pair one point per stratum), while the
//! independent orders decorrelate the pairs: point i's coordinates in pair k and pair l come
//! from unrelated base points. Shuffling loses the progressive prefixes of a sequence (as in
//! pbrt, where the permutation runs over a pixel's samples). In 2D the pattern is pair 0: one
//! shuffled copy. The pairs are generated in parallel; each is a pure function of its seeds.
//!
//! The base patterns are used with their default parameters, randomized: `sobol` with Owen
//! scrambling, `halton` with Owen scrambling.
use crate::core::pattern::{
    BestCandidate, Cancel, CorrelatedMultiJitter, Halton, Jitter, MultiJitter, PadBase, Padded,
    Pattern, PatternError, Pmj02, Pmj02bn, Random, Scramble, Sobol,
};
use crate::core::rng::{derive_seed, Rng};
use glam::DVec2;
use rayon::prelude::*;

/// The 2D pattern of every pair.
pub fn base_pattern(base: PadBase) -> Pattern {
    match base {
        PadBase::Pmj02 => Pattern::Pmj02(Pmj02::default()),
        PadBase::Pmj02bn => Pattern::Pmj02bn(Pmj02bn::default()),
        PadBase::Sobol => Pattern::Sobol(Sobol {
            scramble: Scramble::Owen,
            ..Sobol::default()
        }),
        PadBase::Halton => Pattern::Halton(Halton {
            scramble: crate::core::pattern::halton_scramble::HaltonScramble::Owen,
            ..Halton::default()
        }),
        PadBase::Jitter => Pattern::Jitter(Jitter::default()),
        PadBase::MultiJitter => Pattern::MultiJitter(MultiJitter::default()),
        PadBase::Cmj => Pattern::CorrelatedMultiJitter(CorrelatedMultiJitter::default()),
        PadBase::Random => Pattern::Random(Random::default()),
        PadBase::BestCandidate => Pattern::BestCandidate(BestCandidate::default()),
    }
}

/// The checks of [`padded`]: the base pattern's for n.
pub(crate) fn check_padded(p: &Padded, n: usize) -> Result<(), PatternError> {
    base_pattern(p.base).validate(n)
}

/// Pair k's points: the base pattern with seed `derive_seed(seed, 2k)`, shuffled by the
/// permutation of `derive_seed(seed, 2k + 1)`.
fn pair(
    base: &Pattern,
    n: usize,
    k: usize,
    seed: u64,
    cancel: &Cancel,
) -> Result<Vec<DVec2>, PatternError> {
    let pts = base
        .generate_with(n, derive_seed(seed, 2 * k as u64), cancel)?
        .require_all(base.name())?;
    let perm = Rng::new(derive_seed(seed, 2 * k as u64 + 1)).permutation(n);
    Ok(perm.into_iter().map(|i| pts[i]).collect())
}

/// The padded points in `dims` dimensions, row-major (module docs).
pub fn padded(
    p: &Padded,
    n: usize,
    dims: usize,
    seed: u64,
    cancel: &Cancel,
) -> Result<Vec<f64>, PatternError> {
    check_padded(p, n)?;
    let base = base_pattern(p.base);
    let pairs: Vec<Vec<DVec2>> = (0..dims.div_ceil(2))
        .into_par_iter()
        .map(|k| pair(&base, n, k, seed, cancel))
        .collect::<Result<_, _>>()?;
    let mut out = Vec::with_capacity(n * dims);
    out.resize(n * dims, 0.0);
    for (d, column) in (0..dims).zip((0..).map(|d: usize| &pairs[d / 2])) {
        for (row, q) in out.chunks_exact_mut(dims).zip(column) {
            row[d] = if d % 2 == 0 { q.x } else { q.y };
        }
    }
    Ok(out)
}

/// The 2D pattern: pair 0.
pub fn padded_2d(
    p: &Padded,
    n: usize,
    seed: u64,
    cancel: &Cancel,
) -> Result<Vec<DVec2>, PatternError> {
    check_padded(p, n)?;
    pair(&base_pattern(p.base), n, 0, seed, cancel)
}
