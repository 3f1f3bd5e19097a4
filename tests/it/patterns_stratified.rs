//! Stratified patterns and the hexagonal lattice, through the public API (`Pattern::generate`).
//!
//! Exact combinatorial checks (one point per stratum / row / column), closed forms (grid values,
//! jitter variance a²/12, hex spacing), a naive brute-force minimum distance, and determinism.
//! Every random test uses fixed seeds.

use glam::DVec2;
use samplescope::core::pattern::hex::{hex_aspect_error, hex_spacing};
use samplescope::core::pattern::stratified::{lhs_points, lhs_table};
use samplescope::core::pattern::{
    CorrelatedMultiJitter, Grid, Hex, Jitter, Lhs, MultiJitter, NRooks, Pattern, PatternError,
    Random, MAX_N,
};

fn gen(p: Pattern, n: usize, seed: u64) -> Vec<DVec2> {
    let pts = p
        .generate(n, seed)
        .unwrap_or_else(|e| panic!("{}: {e}", p.name()));
    assert_eq!(pts.len(), n, "{} n = {n}", p.name());
    pts
}

fn assert_in_unit_square(name: &str, pts: &[DVec2]) {
    for (k, p) in pts.iter().enumerate() {
        assert!(
            (0.0..1.0).contains(&p.x) && (0.0..1.0).contains(&p.y),
            "{name}: point {k} = {p:?} outside [0,1)²"
        );
    }
}

/// Cell index of `v` among `k` equal cells of [0,1).
fn cell(v: f64, k: usize) -> usize {
    ((v * k as f64).floor() as usize).min(k - 1)
}

/// Asserts exactly one point in every column and every row of the n × n fine grid.
fn assert_n_rooks(name: &str, pts: &[DVec2]) {
    let n = pts.len();
    let mut col = vec![0u32; n];
    let mut row = vec![0u32; n];
    for p in pts {
        col[cell(p.x, n)] += 1;
        row[cell(p.y, n)] += 1;
    }
    assert!(col.iter().all(|&c| c == 1), "{name}: fine columns {col:?}");
    assert!(row.iter().all(|&c| c == 1), "{name}: fine rows {row:?}");
}

/// Asserts point k lies in coarse cell (k mod cols, k div cols) of the cols × rows grid.
fn assert_one_per_coarse_cell(name: &str, pts: &[DVec2], cols: usize, rows: usize) {
    assert_eq!(pts.len(), cols * rows);
    for (k, p) in pts.iter().enumerate() {
        assert_eq!(
            (cell(p.x, cols), cell(p.y, rows)),
            (k % cols, k / cols),
            "{name}: point {k} = {p:?} not in its cell of {cols}x{rows}"
        );
    }
}

// ---------------------------------------------------------------- grid

#[test]
fn grid_exact_values_3x2() {
    let pts = gen(Pattern::Grid(Grid { cols: 3 }), 6, 0);
    let want = [
        (1.0 / 6.0, 0.25),
        (0.5, 0.25),
        (5.0 / 6.0, 0.25),
        (1.0 / 6.0, 0.75),
        (0.5, 0.75),
        (5.0 / 6.0, 0.75),
    ];
    for (p, w) in pts.iter().zip(want) {
        assert_eq!((p.x, p.y), w);
    }
}

#[test]
fn grid_auto_cols_is_divisor_nearest_sqrt() {
    // n = 12: cols 3, rows 4 (x = 1/6, 1/2, 5/6; y = 1/8, 3/8, 5/8, 7/8).
    let pts = gen(Pattern::Grid(Grid { cols: 0 }), 12, 0);
    assert_eq!(pts[4], DVec2::new(0.5, 0.375));
    assert_eq!(pts[11], DVec2::new(5.0 / 6.0, 0.875));
    // Prime n = 7: one column of 7 rows.
    let pts = gen(Pattern::Grid(Grid { cols: 0 }), 7, 0);
    assert!(pts.iter().all(|p| p.x == 0.5));
    assert_eq!(pts[3].y, 0.5);
    // n = 1: the centre.
    assert_eq!(
        gen(Pattern::Grid(Grid::default()), 1, 0),
        [DVec2::splat(0.5)]
    );
}

#[test]
fn grid_cols_not_dividing_n_is_error() {
    let err = Pattern::Grid(Grid { cols: 3 }).generate(10, 0).unwrap_err();
    assert!(
        matches!(&err, PatternError::InvalidParam { pattern: "grid", field: "cols", value, .. } if value == "3"),
        "{err:?}"
    );
    assert!(err.to_string().contains("divisor of n = 10"), "{err}");
}

// ---------------------------------------------------------------- random

#[test]
fn random_is_uniform_chi_square() {
    // 20_000 points in 10 × 10 bins: chi-square with 99 dof, 99.9% quantile 148.23.
    let pts = gen(Pattern::Random(Random {}), 20_000, 11);
    let mut bins = [0u32; 100];
    for p in &pts {
        bins[cell(p.y, 10) * 10 + cell(p.x, 10)] += 1;
    }
    let e = 200.0;
    let chi: f64 = bins.iter().map(|&c| (c as f64 - e).powi(2) / e).sum();
    assert!(chi < 148.23, "chi-square {chi}");
}

#[test]
fn random_is_progressive_prefix() {
    let a = gen(Pattern::Random(Random {}), 10, 4);
    let b = gen(Pattern::Random(Random {}), 25, 4);
    assert_eq!(a[..], b[..10]);
}

// ---------------------------------------------------------------- jitter

#[test]
fn jitter_exactly_one_point_per_stratum() {
    for (n, cols) in [
        (12, 3),
        (12, 4),
        (35, 5),
        (64, 0),
        (7, 7),
        (7, 1),
        (1, 0),
        (1000, 25),
    ] {
        for seed in [1, 2, 3] {
            let p = Jitter { cols, amount: 1.0 };
            let pts = gen(Pattern::Jitter(p), n, seed);
            let c = if cols == 0 {
                samplescope::core::pattern::divisor_near_sqrt(n)
            } else {
                cols as usize
            };
            assert_one_per_coarse_cell("jitter", &pts, c, n / c);
        }
    }
}

#[test]
fn jitter_amount_zero_is_grid_exactly() {
    for (n, cols) in [(12, 3), (30, 0), (49, 7)] {
        let j = gen(Pattern::Jitter(Jitter { cols, amount: 0.0 }), n, 99);
        let g = gen(Pattern::Grid(Grid { cols }), n, 0);
        assert!(j
            .iter()
            .zip(&g)
            .all(|(a, b)| a.x.to_bits() == b.x.to_bits() && a.y.to_bits() == b.y.to_bits()));
    }
}

/// Offsets from the cell centres in cell units, (dx, dy) ∈ [−½, ½)².
fn jitter_offsets(pts: &[DVec2], cols: usize, rows: usize) -> Vec<DVec2> {
    pts.iter()
        .enumerate()
        .map(|(k, p)| {
            DVec2::new(
                p.x * cols as f64 - ((k % cols) as f64 + 0.5),
                p.y * rows as f64 - ((k / cols) as f64 + 0.5),
            )
        })
        .collect()
}

#[test]
fn jitter_amount_half_stays_within_quarter_cell() {
    let (n, cols, rows) = (400, 20, 20);
    let pts = gen(
        Pattern::Jitter(Jitter {
            cols: 20,
            amount: 0.5,
        }),
        n,
        5,
    );
    let off = jitter_offsets(&pts, cols, rows);
    let max = off
        .iter()
        .fold(0.0f64, |m, d| m.max(d.x.abs()).max(d.y.abs()));
    // Within ±¼ cell (tolerance 1e-12 cell for rounding), and the bound is nearly reached.
    assert!(max <= 0.25 + 1e-12, "max offset {max}");
    assert!(max > 0.24, "max offset {max}");
}

#[test]
fn jitter_offset_variance_is_amount_squared_over_12() {
    // Offset a·(u − ½): variance a²/12. 10_000 points: the sample mean of d² has standard
    // deviation a²·√(1/180)/100 ≈ 7.5e-4·a²; tolerance 5e-3·a² (≈ 6.7σ).
    for a in [1.0, 0.5] {
        let pts = gen(
            Pattern::Jitter(Jitter {
                cols: 100,
                amount: a,
            }),
            10_000,
            8,
        );
        let off = jitter_offsets(&pts, 100, 100);
        let vx = off.iter().map(|d| d.x * d.x).sum::<f64>() / off.len() as f64;
        let vy = off.iter().map(|d| d.y * d.y).sum::<f64>() / off.len() as f64;
        let want = a * a / 12.0;
        assert!(
            (vx - want).abs() < 5e-3 * a * a,
            "a = {a}: var x {vx} vs {want}"
        );
        assert!(
            (vy - want).abs() < 5e-3 * a * a,
            "a = {a}: var y {vy} vs {want}"
        );
    }
}

#[test]
fn jitter_bad_amount_and_cols_are_errors() {
    for a in [f64::NAN, -0.1, 1.5, f64::INFINITY] {
        let err = Pattern::Jitter(Jitter { cols: 0, amount: a })
            .generate(16, 0)
            .unwrap_err();
        assert!(
            matches!(
                err,
                PatternError::InvalidParam {
                    pattern: "jitter",
                    field: "amount",
                    ..
                }
            ),
            "{a}: {err:?}"
        );
    }
    let err = Pattern::Jitter(Jitter {
        cols: 5,
        amount: 1.0,
    })
    .generate(16, 0)
    .unwrap_err();
    assert!(matches!(
        err,
        PatternError::InvalidParam { field: "cols", .. }
    ));
}

// ---------------------------------------------------------------- N-rooks

#[test]
fn nrooks_one_point_per_row_and_column() {
    for n in [1, 2, 10, 97, 256, 1000] {
        for seed in [0, 1, 42] {
            let pts = gen(Pattern::NRooks(NRooks { amount: 1.0 }), n, seed);
            assert_n_rooks("nrooks", &pts);
        }
    }
}

#[test]
fn nrooks_shuffles_the_diagonal() {
    // After the per-dimension shuffles, x and y cells agree only by chance (≈ 1 of n expected).
    let n = 200;
    let pts = gen(Pattern::NRooks(NRooks { amount: 1.0 }), n, 3);
    let same = pts.iter().filter(|p| cell(p.x, n) == cell(p.y, n)).count();
    assert!(same < 10, "{same} points still on the diagonal");
}

#[test]
fn nrooks_amount_zero_gives_cell_centres() {
    let n = 50;
    let pts = gen(Pattern::NRooks(NRooks { amount: 0.0 }), n, 6);
    for p in &pts {
        for v in [p.x, p.y] {
            let c = cell(v, n) as f64;
            assert_eq!(v, (c + 0.5) / n as f64);
        }
    }
    assert_n_rooks("nrooks a=0", &pts);
}

// ---------------------------------------------------------------- LHS

#[test]
fn lhs_table_k3_n10_is_a_permutation_per_row_like_the_lecture() {
    // The lecture's table: k = 3 rows, n = 10 columns, entries 1..=10, each row a permutation.
    let t = lhs_table(10, 3, 2024).unwrap();
    assert_eq!(t.len(), 3);
    for row in &t {
        assert_eq!(row.len(), 10);
        let mut s = row.clone();
        s.sort_unstable();
        assert_eq!(s, (1..=10).collect::<Vec<_>>());
    }
    // Independent permutations per dimension.
    assert_ne!(t[0], t[1]);
    assert_ne!(t[1], t[2]);
}

#[test]
fn lhs_points_one_per_cell_per_dimension_and_match_table() {
    for (n, dims, seed) in [
        (10, 3, 2024),
        (10, 3, 7),
        (37, 5, 1),
        (3, 64, 9),
        (5, 1, 0),
        (500, 4, 3),
    ] {
        let t = lhs_table(n, dims, seed).unwrap();
        let pts = lhs_points(n, dims, 1.0, seed).unwrap();
        assert_eq!(pts.len(), n);
        for d in 0..dims {
            let mut count = vec![0u32; n];
            for (i, s) in pts.iter().enumerate() {
                assert_eq!(s.len(), dims);
                assert!((0.0..1.0).contains(&s[d]));
                let c = cell(s[d], n);
                count[c] += 1;
                // "s^i_d is from the t[d][i]-th cell of dimension d" (1-based).
                assert_eq!(c + 1, t[d][i], "n={n} dims={dims} d={d} i={i}");
            }
            assert!(count.iter().all(|&c| c == 1), "dim {d}: {count:?}");
        }
    }
}

#[test]
fn lhs_projection_equals_points_bitwise() {
    let (n, seed) = (64, 17);
    let pts = lhs_points(n, 4, 0.7, seed).unwrap();
    for (xd, yd) in [(0, 1), (2, 0), (3, 1)] {
        let p = Lhs {
            dims: 4,
            x_dim: xd,
            y_dim: yd,
            amount: 0.7,
        };
        let proj = gen(Pattern::Lhs(p), n, seed);
        for (q, s) in proj.iter().zip(&pts) {
            assert_eq!(q.x.to_bits(), s[xd as usize].to_bits());
            assert_eq!(q.y.to_bits(), s[yd as usize].to_bits());
        }
        assert_n_rooks("lhs projection", &proj);
    }
}

#[test]
fn lhs_amount_zero_gives_cell_centres() {
    let pts = lhs_points(8, 2, 0.0, 5).unwrap();
    let t = lhs_table(8, 2, 5).unwrap();
    for (i, s) in pts.iter().enumerate() {
        for d in 0..2 {
            assert_eq!(s[d], (t[d][i] as f64 - 0.5) / 8.0);
        }
    }
}

#[test]
fn lhs_one_dimension_lies_on_the_diagonal() {
    let p = Lhs {
        dims: 1,
        x_dim: 0,
        y_dim: 0,
        amount: 1.0,
    };
    let pts = gen(Pattern::Lhs(p), 20, 1);
    assert!(pts.iter().all(|q| q.x == q.y));
    assert_n_rooks("lhs dims=1", &pts);
}

#[test]
fn lhs_bad_dims_are_errors() {
    let bad = |dims, x_dim, y_dim| {
        Pattern::Lhs(Lhs {
            dims,
            x_dim,
            y_dim,
            amount: 1.0,
        })
        .generate(10, 0)
        .unwrap_err()
    };
    let e = bad(3, 3, 1);
    assert!(
        matches!(&e, PatternError::InvalidParam { pattern: "lhs", field: "x_dim", allowed, .. } if allowed.contains("0..=2")),
        "{e:?}"
    );
    let e = bad(3, 0, 5);
    assert!(
        matches!(&e, PatternError::InvalidParam { field: "y_dim", .. }),
        "{e:?}"
    );
    let e = bad(3, 1, 1);
    assert!(
        matches!(&e, PatternError::InvalidParam { field: "y_dim", allowed, .. } if allowed.contains("different from x_dim")),
        "{e:?}"
    );
    let e = bad(1, 0, 1);
    assert!(
        matches!(&e, PatternError::InvalidParam { field: "y_dim", .. }),
        "{e:?}"
    );
    let e = bad(0, 0, 0);
    assert!(
        matches!(&e, PatternError::InvalidParam { field: "dims", .. }),
        "{e:?}"
    );
}

// ---------------------------------------------------------------- multi-jitter, CMJ

const MJ_SHAPES: [(usize, u32, usize); 7] = [
    // (n, cols parameter, resolved cols)
    (16, 0, 4),
    (12, 3, 3),
    (12, 4, 4),
    (30, 5, 5),
    (7, 1, 1),
    (7, 7, 7),
    (400, 0, 20),
];

#[test]
fn multijitter_is_jittered_and_n_rooks() {
    for (n, cols, c) in MJ_SHAPES {
        for seed in [0, 5, 77] {
            let pts = gen(Pattern::MultiJitter(MultiJitter { cols }), n, seed);
            assert_n_rooks("multijitter", &pts);
            assert_one_per_coarse_cell("multijitter", &pts, c, n / c);
        }
    }
}

#[test]
fn cmj_is_jittered_and_n_rooks() {
    for (n, cols, c) in MJ_SHAPES {
        for seed in [0, 5, 77] {
            let pts = gen(
                Pattern::CorrelatedMultiJitter(CorrelatedMultiJitter { cols }),
                n,
                seed,
            );
            assert_n_rooks("cmj", &pts);
            assert_one_per_coarse_cell("cmj", &pts, c, n / c);
        }
    }
}

/// Sub-column of point k within its coarse column: fine column − i·rows ∈ 0..rows; and sub-row.
fn sub_cells(pts: &[DVec2], cols: usize, rows: usize) -> Vec<(usize, usize)> {
    let n = pts.len();
    pts.iter()
        .enumerate()
        .map(|(k, p)| {
            let (i, j) = (k % cols, k / cols);
            (cell(p.x, n) - i * rows, cell(p.y, n) - j * cols)
        })
        .collect()
}

/// Whether every coarse column has the same sub-column order (x depends on the row only) and
/// every coarse row the same sub-row order.
fn is_correlated(pts: &[DVec2], cols: usize, rows: usize) -> bool {
    let s = sub_cells(pts, cols, rows);
    (0..rows).all(|j| (0..cols).all(|i| s[j * cols + i].0 == s[j * cols].0))
        && (0..cols).all(|i| (0..rows).all(|j| s[j * cols + i].1 == s[i].1))
}

#[test]
fn cmj_uses_one_shuffle_per_dimension_kensler() {
    // Kensler's formula: x = (i + (π_y(j) + u)/rows)/cols, y = (j + (π_x(i) + v)/cols)/rows.
    for (n, cols) in [(64, 8), (12, 3), (60, 6)] {
        let rows = n / cols;
        for seed in [1, 2] {
            let pts = gen(
                Pattern::CorrelatedMultiJitter(CorrelatedMultiJitter { cols: cols as u32 }),
                n,
                seed,
            );
            assert!(is_correlated(&pts, cols, rows), "n={n} seed={seed}");
            // The recovered π_y (row j's sub-column) and π_x are permutations.
            let s = sub_cells(&pts, cols, rows);
            let mut py: Vec<usize> = (0..rows).map(|j| s[j * cols].0).collect();
            let mut px: Vec<usize> = (0..cols).map(|i| s[i].1).collect();
            py.sort_unstable();
            px.sort_unstable();
            assert_eq!(py, (0..rows).collect::<Vec<_>>());
            assert_eq!(px, (0..cols).collect::<Vec<_>>());
        }
    }
}

#[test]
fn multijitter_shuffles_are_independent_per_column() {
    // Plain multi-jitter shuffles every column and row independently: not correlated.
    let pts = gen(Pattern::MultiJitter(MultiJitter { cols: 8 }), 64, 1);
    assert!(!is_correlated(&pts, 8, 8));
}

#[test]
fn multijitter_and_cmj_cols_not_dividing_n_are_errors() {
    for p in [
        Pattern::MultiJitter(MultiJitter { cols: 7 }),
        Pattern::CorrelatedMultiJitter(CorrelatedMultiJitter { cols: 7 }),
    ] {
        let e = p.generate(30, 0).unwrap_err();
        assert!(
            matches!(&e, PatternError::InvalidParam { field: "cols", .. }),
            "{}: {e:?}",
            p.name()
        );
    }
}

// ---------------------------------------------------------------- hex

/// Naive O(n²) minimum toroidal distance.
fn brute_min_toroidal(pts: &[DVec2]) -> f64 {
    let mut best = f64::INFINITY;
    for (k, p) in pts.iter().enumerate() {
        for q in &pts[k + 1..] {
            let mut d = (*p - *q).abs();
            d.x = d.x.min(1.0 - d.x);
            d.y = d.y.min(1.0 - d.y);
            best = best.min(d.length());
        }
    }
    best
}

/// Auto rows by brute force: the even divisor with the smallest |ln(2 cols / (√3 rows))|.
fn auto_rows_reference(n: usize) -> usize {
    (1..=n)
        .filter(|r| r % 2 == 0 && n % r == 0)
        .min_by(|&a, &b| {
            let e = |r: usize| (2.0 * (n / r) as f64 / (3f64.sqrt() * r as f64)).ln().abs();
            e(a).total_cmp(&e(b))
        })
        .unwrap()
}

#[test]
fn hex_min_distance_equals_lattice_spacing() {
    for n in [8, 12, 24, 50, 56, 98, 200, 256, 1000] {
        let pts = gen(Pattern::Hex(Hex::default()), n, 0);
        let rows = auto_rows_reference(n);
        let cols = n / rows;
        let a = 1.0 / cols as f64;
        let h = 1.0 / rows as f64;
        // Near-equilateral auto shapes: nearest neighbours at a (same row) or √(a²/4 + h²).
        let want = a.min((0.5 * a).hypot(h));
        let got = brute_min_toroidal(&pts);
        assert!((got - want).abs() < 1e-12, "n={n}: {got} vs {want}");
        assert!((hex_spacing(rows, cols).unwrap() - want).abs() < 1e-12);
        assert!(got > 0.0, "n={n}: points not distinct");
        assert_in_unit_square("hex", &pts);
    }
}

#[test]
fn hex_points_are_distinct_and_the_lattice_formula() {
    // n = 56: 8 rows of 7 (2·7/(√3·8) ≈ 1.0104, the closest to equilateral).
    let pts = gen(Pattern::Hex(Hex::default()), 56, 0);
    assert_eq!(pts[0], DVec2::new(1.0 / 14.0, 1.0 / 16.0));
    assert_eq!(pts[7], DVec2::new(2.0 / 14.0, 3.0 / 16.0)); // row 1 shifted by ½ spacing
    assert_eq!(pts[13], DVec2::new(0.0, 3.0 / 16.0)); // wrapped: (6 + ½ + ½)/7 = 1 ≡ 0
    let mut keys: Vec<(u64, u64)> = pts.iter().map(|p| (p.x.to_bits(), p.y.to_bits())).collect();
    keys.sort_unstable();
    keys.dedup();
    assert_eq!(keys.len(), 56);
}

#[test]
fn hex_auto_rows_is_closest_to_equilateral() {
    for n in [2, 4, 6, 8, 18, 56, 96, 120, 1024, 4096] {
        let rows = auto_rows_reference(n);
        let pts = gen(Pattern::Hex(Hex::default()), n, 0);
        // The number of distinct y values is the row count.
        let mut ys: Vec<u64> = pts.iter().map(|p| p.y.to_bits()).collect();
        ys.sort_unstable();
        ys.dedup();
        assert_eq!(ys.len(), rows, "n = {n}");
    }
    // n = 56 → 8 rows; aspect error ln(14/(8√3)) ≈ 0.0103.
    assert_eq!(auto_rows_reference(56), 8);
    assert!((hex_aspect_error(8, 7) - 0.010_309_643_601_367_893).abs() < 1e-14);
}

#[test]
fn hex_jitter_stays_within_half_amount_of_a_cell() {
    let (n, amount) = (96, 0.5);
    let lattice = gen(
        Pattern::Hex(Hex {
            rows: 0,
            amount: 0.0,
        }),
        n,
        0,
    );
    let jit = gen(Pattern::Hex(Hex { rows: 0, amount }), n, 3);
    let rows = auto_rows_reference(n);
    let cols = n / rows;
    let mut max = DVec2::ZERO;
    for (p, q) in lattice.iter().zip(&jit) {
        let mut d = (*p - *q).abs();
        d.x = d.x.min(1.0 - d.x) * cols as f64;
        d.y = d.y.min(1.0 - d.y) * rows as f64;
        max = max.max(d);
    }
    assert!(
        max.x <= amount / 2.0 + 1e-12 && max.y <= amount / 2.0 + 1e-12,
        "{max:?}"
    );
    assert!(max.x > 0.2 && max.y > 0.2, "{max:?}");
    assert_in_unit_square("hex jitter", &jit);
}

#[test]
fn hex_odd_n_is_refused_saying_n_must_be_even() {
    let e = Pattern::Hex(Hex::default()).generate(15, 0).unwrap_err();
    assert!(
        matches!(e, PatternError::UnsupportedN { n: 15, .. }),
        "{e:?}"
    );
    assert_eq!(
        e.to_string(),
        "hex: n = 15: must be an even integer in 2..=16777216 (hex needs an even number of \
         rows: the half-spacing shift of odd rows must wrap on the torus)"
    );
}

#[test]
fn hex_bad_rows_are_errors() {
    for rows in [3, 5, 8] {
        let e = Pattern::Hex(Hex { rows, amount: 0.0 })
            .generate(12, 0)
            .unwrap_err();
        match &e {
            PatternError::InvalidParam {
                pattern: "hex",
                field: "rows",
                allowed,
                ..
            } => assert!(allowed.contains("2, 4, 6, 12"), "{allowed}"),
            _ => panic!("rows = {rows}: {e:?}"),
        }
    }
    let e = Pattern::Hex(Hex {
        rows: 0,
        amount: f64::NAN,
    })
    .generate(12, 0)
    .unwrap_err();
    assert!(matches!(
        e,
        PatternError::InvalidParam {
            field: "amount",
            ..
        }
    ));
}

// ---------------------------------------------------------------- all patterns

fn stratified_patterns() -> Vec<Pattern> {
    vec![
        Pattern::Grid(Grid::default()),
        Pattern::Random(Random {}),
        Pattern::Jitter(Jitter::default()),
        Pattern::Jitter(Jitter {
            cols: 0,
            amount: 0.0,
        }),
        Pattern::NRooks(NRooks::default()),
        Pattern::Lhs(Lhs::default()),
        Pattern::MultiJitter(MultiJitter::default()),
        Pattern::CorrelatedMultiJitter(CorrelatedMultiJitter::default()),
        Pattern::Hex(Hex::default()),
        Pattern::Hex(Hex {
            rows: 0,
            amount: 1.0,
        }),
    ]
}

#[test]
fn determinism_same_seed_same_bits_different_seed_differs() {
    for p in stratified_patterns() {
        let n = 144;
        let a = gen(p, n, 12345);
        let b = gen(p, n, 12345);
        let c = gen(p, n, 12346);
        let bits = |v: &[DVec2]| -> Vec<(u64, u64)> {
            v.iter().map(|q| (q.x.to_bits(), q.y.to_bits())).collect()
        };
        assert_eq!(bits(&a), bits(&b), "{}", p.name());
        if p.is_random() {
            assert_ne!(bits(&a), bits(&c), "{} ignores its seed", p.name());
        } else {
            assert_eq!(bits(&a), bits(&c), "{} is deterministic", p.name());
        }
    }
}

#[test]
fn all_outputs_in_unit_square() {
    for p in stratified_patterns() {
        for n in [2, 4, 36, 90, 1024] {
            for seed in [0, u64::MAX] {
                assert_in_unit_square(p.name(), &gen(p, n, seed));
            }
        }
    }
}

#[test]
fn n_zero_and_too_large_are_invalid_n() {
    for p in stratified_patterns() {
        for n in [0, MAX_N + 1] {
            assert!(
                matches!(p.generate(n, 0), Err(PatternError::InvalidN { .. })),
                "{} n = {n}",
                p.name()
            );
        }
    }
}

#[test]
fn n_one_is_fine_except_hex() {
    for p in stratified_patterns() {
        let r = p.generate(1, 0);
        if matches!(p, Pattern::Hex(_)) {
            assert!(matches!(r, Err(PatternError::UnsupportedN { n: 1, .. })));
        } else {
            assert_eq!(r.unwrap().len(), 1, "{}", p.name());
        }
    }
}
