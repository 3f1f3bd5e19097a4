//! Published discrepancy values of the unscrambled Sobol' points (UTK documentation).
//!
//! Source: UTK, github.com/utk-team/utk, `sources-doc/discrepancy_star_disc.md` and
//! `sources-doc/discrepancy_l2_disc.md` ("Deterministic sampler" sections), which list the
//! output of `StarDiscrepancy_fromfile_2dd` / `L2Discrepancy_fromfile_2dd` on `sobol_1024.dat`
//! and `sobol_4096.dat`:
//!
//! | N    | star (L∞) discrepancy | L2 discrepancy |
//! |------|-----------------------|----------------|
//! | 1024 | 0.00429916            | 0.000867928    |
//! | 4096 | 0.00132918            | 0.000234269    |
//!
//! UTK's `L2Discrepancy.hpp` evaluates Warnock's formula (1/N² ΣΣ Π(1 − max) − (2^{1−d}/N)
//! Σ Π(1 − x²) + 3^{−d}), i.e. the L2-star discrepancy; its star discrepancy is an exact
//! O(N²) grid evaluation. The variant: the first N points (i = 0 … N−1, direct order) of the
//! unscrambled Sobol' sequence, first two dimensions — dimension 0 is the van der Corput
//! sequence Φ₂(i), dimension 1 uses the primitive polynomial x + 1 (direction numbers
//! v_k = v_{k−1} XOR (v_{k−1} >> 1), v_1 = 2⁻¹). These dimensions are the same in every
//! Sobol' direction-number table (Joe–Kuo, Bratley–Fox). The points are built in
//! `metrics_common` (32-bit integers / 2³², exact in f64). Both discrepancies are symmetric
//! under swapping x and y, so the dimension order does not matter.
//!
//! The values are published to 6 significant digits: the tolerance is half a unit in the
//! last published digit.

use crate::metrics_common;

use metrics_common::sobol;
use samplescope::core::cancel::Cancel;
use samplescope::core::metrics::{l2_star_discrepancy, star_discrepancy};

fn check(name: &str, got: f64, published: f64, half_ulp: f64) {
    assert!(
        (got - published).abs() <= half_ulp,
        "{name}: computed {got:.10e}, published {published:e} (±{half_ulp:e})"
    );
}

#[test]
fn sobol_1024_matches_utk() {
    let pts = sobol(1024);
    let c = Cancel::never();
    check(
        "star 1024",
        star_discrepancy(&pts, &c).unwrap().value,
        0.004_299_16,
        5e-9,
    );
    check(
        "L2 1024",
        l2_star_discrepancy(&pts, &c).unwrap(),
        0.000_867_928,
        5e-10,
    );
}

#[test]
fn sobol_4096_matches_utk() {
    let pts = sobol(4096);
    let c = Cancel::never();
    check(
        "star 4096",
        star_discrepancy(&pts, &c).unwrap().value,
        0.001_329_18,
        5e-9,
    );
    check(
        "L2 4096",
        l2_star_discrepancy(&pts, &c).unwrap(),
        0.000_234_269,
        5e-10,
    );
}
