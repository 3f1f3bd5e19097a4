//! Patterns in d dimensions (`Pattern::generate_cube`): SciPy's Sobol' and Halton bit for bit
//! (files from scripts/reference-scipy-qmc.py), every pattern × D ∈ {1, 2, 3, 8, 32}
//! (determinism across thread counts, the defining property, bad D refused with one line), the
//! 2D path unchanged at D = 2, and the `points --dims` / `--project` command line.

use crate::cli_points::samplescope;
use samplescope::core::cancel::Cancel;
use samplescope::core::cube::CubePoints;
use samplescope::core::params::Params;
use samplescope::core::pattern::cube::{halton, sobol};
use samplescope::core::pattern::halton_scramble::HaltonScramble;
use samplescope::core::pattern::radical_inverse::radical_inverse;
use samplescope::core::pattern::{Pattern, PatternError, Scramble};

const DIMS: [usize; 5] = [1, 2, 3, 8, 32];

fn pattern(name: &str, settings: &[(&str, &str)]) -> Pattern {
    let mut p = Pattern::from_name(name).unwrap();
    for (k, v) in settings {
        p.set_field(k, v).unwrap();
    }
    p
}

fn cube(p: &Pattern, n: usize, dims: usize, seed: u64) -> CubePoints {
    p.generate_cube(n, dims, seed, &Cancel::never())
        .unwrap_or_else(|e| panic!("{} n = {n} dims = {dims}: {e}", p.name()))
}

/// A SciPy reference file: (first dimension, rows).
fn scipy_file(name: &str) -> (usize, Vec<Vec<f64>>) {
    let path = format!("{}/tests/data/scipy/{name}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let mut lines = text.lines().filter(|l| !l.starts_with('#'));
    let header = lines.next().unwrap();
    let first: usize = header.split(',').next().unwrap()[1..].parse().unwrap();
    let rows = lines
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    (first, rows)
}

#[test]
fn sobol_is_scipy_s_unscrambled_sobol_bit_for_bit() {
    let plain = Pattern::from_name("sobol").unwrap();
    for d in DIMS {
        let (_, rows) = scipy_file(&format!("sobol-d{d}.csv"));
        let ours = cube(&plain, rows.len(), d, 0);
        for (i, (row, want)) in ours.rows().zip(&rows).enumerate() {
            for (k, (a, b)) in row.iter().zip(want).enumerate() {
                assert_eq!(a.to_bits(), b.to_bits(), "d = {d}, point {i}, x{k}");
            }
        }
    }
    let (first, rows) = scipy_file("sobol-d1024-dims1000-1023.csv");
    let ours = cube(&plain, rows.len(), 1024, 0);
    for (i, (row, want)) in ours.rows().zip(&rows).enumerate() {
        for (k, b) in want.iter().enumerate() {
            assert_eq!(
                row[first + k].to_bits(),
                b.to_bits(),
                "point {i}, x{}",
                first + k
            );
        }
    }
}

/// Units in the last place between two doubles of the same sign.
fn ulps(a: f64, b: f64) -> u64 {
    (a.to_bits() as i64 - b.to_bits() as i64).unsigned_abs()
}

#[test]
fn halton_is_scipy_s_halton_to_2_ulp_and_correctly_rounded() {
    let plain = Pattern::from_name("halton").unwrap();
    let mut files: Vec<(String, usize)> = DIMS
        .iter()
        .map(|d| (format!("halton-d{d}.csv"), *d))
        .collect();
    files.push(("halton-d1024-dims1000-1023.csv".into(), 1024));
    let primes = samplescope::core::pattern::cube::first_primes(1024);
    let (mut differ, mut total) = (0, 0);
    for (name, d) in files {
        let (first, rows) = scipy_file(&name);
        let ours = cube(&plain, rows.len(), d, 0);
        for (i, (row, want)) in ours.rows().zip(&rows).enumerate() {
            for (k, b) in want.iter().enumerate() {
                let a = row[first + k];
                assert!(
                    ulps(a, *b) <= 2,
                    "{name}: point {i}, x{}: {a} vs SciPy {b}",
                    first + k
                );
                // The correctly rounded rational R / b^K of the radical inverse.
                assert_eq!(
                    a.to_bits(),
                    radical_inverse(i as u64, primes[first + k]).to_bits()
                );
                differ += usize::from(a != *b);
                total += 1;
            }
        }
    }
    // SciPy rounds per digit; base 2 agrees exactly, so some but not all coordinates differ.
    assert!(differ < total / 2, "{differ} of {total} differ");
}

/// Whether the 2^m points of `pts` (dims i, j) form a (t,m,2)-net: every elementary interval
/// of area 2^(t−m) holds 2^t points.
fn is_net(pts: &CubePoints, i: usize, j: usize, t: u32) -> bool {
    let n = pts.n();
    let m = n.trailing_zeros();
    assert_eq!(n, 1 << m);
    if t >= m {
        return true;
    }
    (0..=m - t).all(|a| {
        let b = m - t - a;
        let mut counts = vec![0u32; 1 << (m - t)];
        for p in pts.rows() {
            let cx = (p[i] * f64::from(1u32 << a)) as usize;
            let cy = (p[j] * f64::from(1u32 << b)) as usize;
            counts[(cx << b) | cy] += 1;
        }
        counts.iter().all(|&c| c == 1 << t)
    })
}

/// The t-value of the 2D projection (i, j) of the 2^m points.
fn t_value(pts: &CubePoints, i: usize, j: usize) -> u32 {
    (0..).find(|&t| is_net(pts, i, j, t)).unwrap()
}

/// The 2^m points of `pts` from `start`.
fn block(pts: &CubePoints, start: usize, len: usize) -> CubePoints {
    let d = pts.dims();
    CubePoints::new(d, pts.coords()[start * d..(start + len) * d].to_vec()).unwrap()
}

#[test]
fn sobol_fast_equals_the_naive_generator_matrices() {
    for d in DIMS {
        for skip in [0u32, 5, 4096] {
            let p = pattern("sobol", &[("skip", &skip.to_string())]);
            let n = 5000;
            let fast = p.cube_coords(n, d, 0, &Cancel::never()).unwrap();
            let naive = sobol::sobol_naive(skip, n, d);
            assert!(
                fast.iter()
                    .zip(&naive)
                    .all(|(a, b)| a.to_bits() == b.to_bits()),
                "d = {d} skip = {skip}"
            );
        }
    }
}

#[test]
fn scrambled_sobol_blocks_keep_the_t_values_of_the_plain_ones() {
    let d = 8;
    let plain = cube(&pattern("sobol", &[]), 512, d, 0);
    for scramble in ["random-digit", "owen", "owen-shuffled"] {
        for seed in [1u64, 7] {
            let s = cube(&pattern("sobol", &[("scramble", scramble)]), 512, d, seed);
            assert_ne!(s, plain);
            for (start, len) in [(0, 256), (256, 256), (0, 512), (128, 64)] {
                let (a, b) = (block(&plain, start, len), block(&s, start, len));
                for i in 0..d {
                    // (0,m,1): every 1D projection is stratified.
                    assert!(
                        is_net(&b, i, i, 0)
                            || t_value(&b, i, (i + 1) % d) == t_value(&a, i, (i + 1) % d)
                    );
                    for j in i + 1..d {
                        assert_eq!(
                            t_value(&b, i, j),
                            t_value(&a, i, j),
                            "{scramble} seed {seed}: block {start}+{len}, dims ({i}, {j})"
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn owen_shuffled_prefixes_are_one_aligned_block_in_a_random_order() {
    // Burley's shuffle: the first 2^m points are the Owen-scrambled points of the sequence
    // positions owen_scramble(j, shuffle seed), j < 2^m, which share their high bits (one
    // aligned block of 2^m positions) and visit its 2^m low parts in a random order.
    use samplescope::core::pattern::lowdisc::owen_scramble;
    use samplescope::core::rng::derive_seed;
    let (d, seed, m) = (3, 5u64, 8);
    let s = derive_seed(seed, sobol::SHUFFLE_STREAM);
    let pos: Vec<u32> = (0..1u32 << m).map(|j| owen_scramble(j, s)).collect();
    let high = pos[0] >> m;
    assert!(pos.iter().all(|p| p >> m == high), "one aligned block");
    let mut low: Vec<u32> = pos.iter().map(|p| p & ((1 << m) - 1)).collect();
    assert_ne!(low, (0..1 << m).collect::<Vec<_>>(), "in a shuffled order");
    low.sort_unstable();
    assert_eq!(
        low,
        (0..1 << m).collect::<Vec<_>>(),
        "every position of the block once"
    );
    let shuffled = cube(
        &pattern("sobol", &[("scramble", "owen-shuffled")]),
        1 << m,
        d,
        seed,
    );
    let skip = (high << m).to_string();
    let owen = cube(
        &pattern("sobol", &[("scramble", "owen"), ("skip", &skip)]),
        1 << m,
        d,
        seed,
    );
    for (j, row) in shuffled.rows().enumerate() {
        let k = (pos[j] & ((1 << m) - 1)) as usize;
        assert_eq!(row, owen.point(k), "point {j} is the block's position {k}");
    }
}

#[test]
fn halton_dimensions_are_stratified_in_their_bases() {
    for scramble in [
        HaltonScramble::None,
        HaltonScramble::Permute,
        HaltonScramble::Owen,
    ] {
        let name = ["none", "permute", "owen"][scramble as usize];
        let p = pattern("halton", &[("scramble", name)]);
        let d = 8;
        let primes = halton::bases(d);
        let pts = cube(&p, 2 * 19 * 19, d, 3);
        for (k, &b) in primes.iter().enumerate() {
            // Any b² consecutive indices put one point in each interval of width b^−2.
            let len = (b * b) as usize;
            let mut seen = vec![0u32; len];
            for v in pts.column(k).skip(len).take(len) {
                seen[(v * len as f64) as usize] += 1;
            }
            assert!(seen.iter().all(|&c| c == 1), "{name}: dim {k} base {b}");
        }
    }
    assert_eq!(
        halton::halton_naive(0, 3, 3),
        cube(&pattern("halton", &[]), 3, 3, 0).into_coords()
    );
}

#[test]
fn hammersley_is_i_over_n_then_the_radical_inverses() {
    let pts = cube(&pattern("hammersley", &[]), 100, 4, 0);
    for (i, row) in pts.rows().enumerate() {
        assert_eq!(row[0], i as f64 / 100.0);
        for (k, b) in [2u32, 3, 5].into_iter().enumerate() {
            assert_eq!(row[k + 1].to_bits(), radical_inverse(i as u64, b).to_bits());
        }
    }
}

#[test]
fn lhs_has_one_point_in_every_interval_of_every_dimension() {
    for d in DIMS {
        for amount in ["1", "0.5", "0"] {
            let n = 97;
            let pts = cube(&pattern("lhs", &[("amount", amount)]), n, d, 11);
            for k in 0..d {
                let mut seen = vec![false; n];
                for v in pts.column(k) {
                    let c = (v * n as f64) as usize;
                    assert!(!seen[c], "dims {d}, x{k}: two points in interval {c}");
                    seen[c] = true;
                }
            }
        }
    }
}

#[test]
fn grid_is_every_cell_centre_once() {
    for (d, k) in [(1usize, 7usize), (2, 5), (3, 4), (8, 2), (32, 1)] {
        let n = k.pow(d as u32);
        let pts = cube(&pattern("grid", &[]), n, d, 0);
        let mut cells: Vec<usize> = pts
            .rows()
            .map(|r| {
                r.iter()
                    .rev()
                    .fold(0, |acc, v| acc * k + (v * k as f64) as usize)
            })
            .collect();
        for r in pts.rows() {
            for v in r {
                let c = (v * k as f64).floor();
                assert_eq!(*v, (c + 0.5) / k as f64, "a cell centre");
            }
        }
        cells.sort_unstable();
        cells.dedup();
        assert_eq!(cells.len(), n, "dims {d}: every cell once");
    }
    let err = pattern("grid", &[])
        .generate_cube(10, 3, 0, &Cancel::never())
        .unwrap_err();
    assert_eq!(
        err.to_string(),
        "grid: n = 10: must be k^3 for an integer k in 3 dimensions (nearest: 8 and 27)"
    );
}

#[test]
fn random_is_uniform_per_dimension_and_progressive() {
    let p = pattern("random", &[]);
    let big = cube(&p, 4000, 8, 9);
    let small = cube(&p, 100, 8, 9);
    assert_eq!(small.coords(), &big.coords()[..800]);
    for k in 0..8 {
        let mean = big.column(k).sum::<f64>() / 4000.0;
        // σ of the mean = 1/√(12·4000) ≈ 0.0046; 5σ.
        assert!((mean - 0.5).abs() < 0.023, "x{k}: mean {mean}");
    }
}

/// The d-dimensional patterns and settings (n chosen so every one is defined).
fn cube_cases() -> Vec<(Pattern, usize)> {
    let mut v = vec![
        (pattern("random", &[]), 5000),
        (pattern("lhs", &[]), 5000),
        (pattern("hammersley", &[]), 5000),
        (pattern("kronecker", &[]), 5000),
        (pattern("rank1", &[]), 4999),
        (pattern("rank1", &[("shift", "true")]), 4999),
        (pattern("rank1", &[("g", "123")]), 5000),
        (pattern("padded", &[]), 5000),
        (pattern("padded", &[("base", "sobol")]), 5000),
        (pattern("padded", &[("base", "jitter")]), 5000),
    ];
    for s in ["none", "random-digit", "owen", "owen-shuffled"] {
        v.push((pattern("sobol", &[("scramble", s)]), 5000));
    }
    for s in ["none", "permute", "owen"] {
        v.push((pattern("halton", &[("scramble", s)]), 5000));
    }
    v
}

#[test]
fn every_pattern_in_every_dimension_count_is_deterministic_across_thread_counts() {
    for (p, n) in cube_cases() {
        for d in DIMS {
            let one = rayon::ThreadPoolBuilder::new()
                .num_threads(1)
                .build()
                .unwrap()
                .install(|| cube(&p, n, d, 42));
            let four = rayon::ThreadPoolBuilder::new()
                .num_threads(4)
                .build()
                .unwrap()
                .install(|| cube(&p, n, d, 42));
            assert_eq!(one, four, "{p:?} dims {d}");
            assert_eq!((one.n(), one.dims()), (n, d));
        }
    }
}

#[test]
fn dims_2_is_the_2d_pattern_and_the_d_dim_construction_agrees_with_it() {
    let mut cases = cube_cases();
    cases.push((pattern("grid", &[]), 0));
    cases.push((pattern("lhs", &[("amount", "0.5")]), 0));
    for (p, _) in cases {
        let cbc = matches!(&p, Pattern::Rank1(r) if r.g == 0);
        for (n, seed) in [(256usize, 0u64), (1000, 3)] {
            let two = p.generate(n, seed).unwrap();
            let via = cube(&p, n, 2, seed);
            assert_eq!(via.to_2d().unwrap(), two, "{p:?}");
            if matches!(p, Pattern::Grid(_)) && n != 256 {
                continue; // 1000 is not a square: the 2D grid is 40 × 25
            }
            if cbc {
                continue; // the 2D g = 0 is the largest-minimum-distance generator, not CBC
            }
            let construction = p.cube_coords(n, 2, seed, &Cancel::never()).unwrap();
            assert_eq!(
                CubePoints::new(2, construction).unwrap(),
                via,
                "{p:?} n = {n}"
            );
        }
    }
    // Every 2D-only pattern at dims = 2 is its 2D points.
    for p in Pattern::all() {
        if p.max_dims() == 2 && p.validate(64).is_ok() {
            let two = p.generate(64, 1).unwrap();
            assert_eq!(cube(&p, 64, 2, 1).to_2d().unwrap(), two, "{}", p.name());
        }
    }
    let _ = Scramble::Owen;
}

#[test]
fn bad_dims_are_refused_with_one_line_naming_the_limit() {
    for p in Pattern::all() {
        let max = p.max_dims();
        for dims in [0usize, max + 1, 3] {
            if max > 2 && dims == 3 {
                continue;
            }
            let e = p.generate_cube(16, dims, 0, &Cancel::never()).unwrap_err();
            let msg = e.to_string();
            assert!(matches!(e, PatternError::InvalidDims { .. }), "{msg}");
            assert!(!msg.contains('\n'), "{msg}");
            assert!(
                msg.starts_with(&format!("{}: dims = {dims}: ", p.name())),
                "{msg}"
            );
            if max == 2 {
                assert!(msg.contains("must be 2"), "{msg}");
                assert!(
                    msg.contains("sobol"),
                    "{msg}: names the d-dimensional patterns"
                );
            } else {
                assert!(msg.contains("1..=1024"), "{msg}");
            }
        }
    }
    let e = pattern("sobol", &[])
        .generate_cube(1 << 21, 32, 0, &Cancel::never())
        .unwrap_err();
    assert!(e.to_string().contains("1048576"), "{e}");
}

#[test]
fn points_dims_writes_one_column_per_dimension_and_projections() {
    let (header, rows) = crate::points_csv(&[
        "points",
        "sobol",
        "-n",
        "8",
        "--dims",
        "3",
        "--set",
        "scramble=owen",
        "--seed",
        "4",
    ]);
    assert_eq!(header, "x0,x1,x2");
    let want = cube(&pattern("sobol", &[("scramble", "owen")]), 8, 3, 4);
    let got: Vec<f64> = rows.concat();
    assert_eq!(got, want.coords());

    let out = samplescope(&[
        "points",
        "halton",
        "-n",
        "5",
        "--dims",
        "4",
        "--project",
        "3,1",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    let want = cube(&pattern("halton", &[]), 5, 4, 0)
        .project(3, 1)
        .unwrap();
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("x,y"));
    for (l, p) in lines.zip(&want) {
        assert_eq!(l, format!("{:?},{:?}", p.x, p.y));
    }
    // dims = 2 is today's output, byte for byte.
    let a = samplescope(&["points", "sobol", "-n", "16", "--dims", "2"]);
    let b = samplescope(&["points", "sobol", "-n", "16"]);
    assert_eq!(a.stdout, b.stdout);
}

#[test]
fn points_refuses_bad_dims_with_status_2_and_one_line() {
    let cases: &[(&[&str], &str)] = &[
        (
            &["points", "sobol", "-n", "4", "--dims", "1025"],
            "sobol: dims = 1025: must be an integer in 1..=1024",
        ),
        (
            &["points", "sobol", "-n", "4", "--dims", "0"],
            "sobol: dims = 0: must be an integer in 1..=1024",
        ),
        (
            &["points", "jitter", "-n", "4", "--dims", "3"],
            "jitter: dims = 3: must be 2",
        ),
        (
            &[
                "points",
                "sobol",
                "-n",
                "4",
                "--dims",
                "3",
                "--project",
                "0,3",
            ],
            "--project 0,3: must be two different dimensions i,j in 0..=2",
        ),
        (
            &[
                "points",
                "sobol",
                "-n",
                "4",
                "--dims",
                "3",
                "--project",
                "1,1",
            ],
            "--project 1,1",
        ),
        (
            &[
                "points", "halton", "-n", "4", "--dims", "3", "--set", "base_x=5",
            ],
            "halton.base_x = 5: must be 2 with dims = 3",
        ),
    ];
    for (args, want) in cases {
        let out = samplescope(args);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains(want), "{args:?}: {err}");
    }
}

#[test]
fn kronecker_r_d_is_roberts_sequence_and_r2_at_two_dimensions() {
    use samplescope::core::pattern::cube::lattice::{alpha_fixed, phi};
    for d in DIMS.into_iter().chain([1024]) {
        let f = phi(d);
        let lhs = f.powi(d as i32 + 1);
        assert!((lhs - f - 1.0).abs() < 1e-12 * lhs, "φ_{d}^(D+1) = φ + 1");
        for (k, a) in alpha_fixed(d).iter().enumerate().take(40) {
            let want = f.powi(-(k as i32 + 1));
            let got = *a as f64 / 2f64.powi(128);
            assert!(
                (got - want).abs() < 1e-13 * want,
                "dims {d}: α_{k} {got} vs {want}"
            );
        }
    }
    // Golden ratio at D = 1.
    assert!((phi(1) - (1.0 + 5f64.sqrt()) / 2.0).abs() < 1e-15);
    // Dimension d of point i is frac(½ + i·α_d) (to f64 accuracy).
    let pts = cube(&pattern("kronecker", &[]), 1000, 8, 0);
    let f = phi(8);
    for (i, row) in pts.rows().enumerate() {
        for (k, v) in row.iter().enumerate() {
            let want = (0.5 + i as f64 * f.powi(-(k as i32 + 1))).fract();
            assert!((v - want).abs() < 1e-9, "point {i}, x{k}");
        }
    }
}

#[test]
fn rank1_cbc_fast_is_as_good_as_the_naive_cbc_and_a_lattice() {
    use samplescope::core::pattern::cube::lattice::{cbc_fast, cbc_naive, worst_case_error};
    let never = Cancel::never();
    for (n, d) in [(31usize, 8usize), (101, 8), (257, 5), (1009, 3)] {
        let fast = cbc_fast(n, d, &never).unwrap();
        let naive = cbc_naive(n, d, &never).unwrap();
        let (pf, pn) = (worst_case_error(n, &fast), worst_case_error(n, &naive));
        if fast == naive {
            assert_eq!(pf.to_bits(), pn.to_bits());
        }
        assert!(pf <= pn * (1.0 + 1e-12), "n = {n}: fast {pf} > naive {pn}");
        // And far better than the trivial vector (1, 1, …, 1).
        assert!(pf < worst_case_error(n, &vec![1; d]), "n = {n}");
    }
    // The lattice: x_i + x_j ≡ x_{i+j} (mod 1), and every 1D projection is {k/N}.
    let n = 101;
    let pts = cube(&pattern("rank1", &[]), n, 8, 0);
    for k in 0..8 {
        let mut c: Vec<usize> = pts
            .column(k)
            .map(|v| (v * n as f64).round() as usize)
            .collect();
        c.sort_unstable();
        assert_eq!(c, (0..n).collect::<Vec<_>>(), "x{k} is stratified");
    }
    for (i, j) in [(3usize, 5usize), (40, 90), (100, 100)] {
        for k in 0..8 {
            let s = (pts.point(i)[k] + pts.point(j)[k]).fract();
            let t = pts.point((i + j) % n)[k];
            assert!((s - t).abs() < 1e-12 || (s - t).abs() > 1.0 - 1e-12);
        }
    }
    // A composite N too large for the naive CBC names the primes around it.
    let e = pattern("rank1", &[])
        .generate_cube(1 << 16, 3, 0, &never)
        .unwrap_err();
    assert!(e.to_string().contains("nearest: 65521 and 65537"), "{e}");
    // Composite N within the naive bound works, and a Korobov g is (1, g, g², …).
    assert!(pattern("rank1", &[])
        .generate_cube(1000, 3, 0, &never)
        .is_ok());
    let k = cube(&pattern("rank1", &[("g", "7")]), 100, 3, 0);
    assert_eq!(k.point(1), &[0.01, 0.07, 0.49]);
}

#[test]
fn padded_pairs_are_shuffled_copies_of_the_base_pattern() {
    use samplescope::core::rng::derive_seed;
    let seed = 9;
    let n = 256;
    for base in ["pmj02", "sobol", "jitter"] {
        let p = pattern("padded", &[("base", base)]);
        let pts = cube(&p, n, 7, seed);
        let base_p = samplescope::core::pattern::cube::padded::base_pattern(match &p {
            Pattern::Padded(q) => q.base,
            _ => unreachable!(),
        });
        let key = |x: f64, y: f64| (x.to_bits(), y.to_bits());
        let mut orders = Vec::new();
        for k in 0..3 {
            let want = base_p.generate(n, derive_seed(seed, 2 * k as u64)).unwrap();
            let mut w: Vec<_> = want.iter().map(|q| key(q.x, q.y)).collect();
            let mut g: Vec<_> = pts.rows().map(|r| key(r[2 * k], r[2 * k + 1])).collect();
            orders.push(g.clone());
            assert_ne!(g, w, "{base}: pair {k} is shuffled");
            g.sort();
            w.sort();
            assert_eq!(g, w, "{base}: pair {k} is the base pattern");
            if base != "jitter" {
                assert_eq!(
                    t_value(&pts, 2 * k, 2 * k + 1),
                    0,
                    "{base}: pair {k} a (0,8,2)-net"
                );
            }
        }
        // The odd last dimension is pair 3's x.
        let want = base_p.generate(n, derive_seed(seed, 6)).unwrap();
        let mut w: Vec<u64> = want.iter().map(|q| q.x.to_bits()).collect();
        let mut g: Vec<u64> = pts.column(6).map(f64::to_bits).collect();
        w.sort_unstable();
        g.sort_unstable();
        assert_eq!(g, w);
    }
}

#[test]
fn points_list_says_every_pattern_s_dimensions() {
    let out = samplescope(&["points", "--list"]);
    let text = String::from_utf8(out.stdout).unwrap();
    let section = &text[text
        .find("dimensions (--dims D")
        .expect("a dimensions section")..];
    for p in Pattern::all() {
        let want = if p.max_dims() == 2 {
            "2 only".to_string()
        } else {
            format!("1..={}", p.max_dims())
        };
        let line = section
            .lines()
            .find(|l| l.split_whitespace().next() == Some(p.name()))
            .unwrap_or_else(|| panic!("{} listed", p.name()));
        assert!(line.ends_with(&want), "{line}");
    }
}

#[test]
fn rank1_takes_its_generating_vector_as_a_list() {
    use samplescope::core::pattern::cube::lattice::generating_vector;
    let never = Cancel::never();
    let (n, d) = (4999usize, 8usize);
    // The CBC vector given as a list is the CBC lattice bit for bit (shifted or not).
    let cbc = generating_vector(
        &match pattern("rank1", &[]) {
            Pattern::Rank1(r) => r,
            _ => unreachable!(),
        },
        n,
        d,
        &never,
    )
    .unwrap();
    let list = cbc.iter().map(u64::to_string).collect::<Vec<_>>().join(",");
    for shift in ["false", "true"] {
        let given = cube(
            &pattern("rank1", &[("z", &list), ("shift", shift)]),
            n,
            d,
            7,
        );
        let auto = cube(&pattern("rank1", &[("shift", shift)]), n, d, 7);
        let bits = |c: &CubePoints| c.coords().iter().map(|v| v.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&given), bits(&auto), "shift = {shift}");
    }
    // At D = 2 the list (1, g) is the 2D Korobov lattice with generator g, bit for bit.
    for shift in ["false", "true"] {
        let given = pattern("rank1", &[("z", "[1, 377]"), ("shift", shift)])
            .generate(987, 5)
            .unwrap();
        let korobov = pattern("rank1", &[("g", "377"), ("shift", shift)])
            .generate(987, 5)
            .unwrap();
        let bits = |v: &[glam::DVec2]| {
            v.iter()
                .map(|p| (p.x.to_bits(), p.y.to_bits()))
                .collect::<Vec<_>>()
        };
        assert_eq!(bits(&given), bits(&korobov), "shift = {shift}");
    }
    // The list round-trips through the parameter text, JSON and the scene file (RON); one
    // not given is left out of all three, so scenes and outputs without it are unchanged.
    let p = pattern("rank1", &[("z", &list)]);
    assert!(
        p.params_text().ends_with(&format!("z=[{list}]")),
        "{}",
        p.params_text()
    );
    let mut again = pattern("rank1", &[]);
    again.set("z", &p.get("z").unwrap().to_string()).unwrap();
    assert_eq!(again, p);
    let json = serde_json::to_string(&p).unwrap();
    assert_eq!(serde_json::from_str::<Pattern>(&json).unwrap(), p, "{json}");
    let json_params = samplescope::core::params::params_json(&p);
    assert_eq!(json_params["z"], serde_json::json!(cbc));
    let ron_text = ron::to_string(&p).unwrap();
    assert_eq!(
        ron::from_str::<Pattern>(&ron_text).unwrap(),
        p,
        "{ron_text}"
    );
    let scene_text = std::fs::read_to_string(format!(
        "{}/assets/scenes/lattices-and-sequences.ron",
        env!("CARGO_MANIFEST_DIR")
    ))
    .unwrap()
    .replace(
        "(kind: \"rank1\", g: 0, shift: false)",
        "(kind: \"rank1\", g: 0, shift: false, z: [1, 610])",
    );
    let scene = samplescope::scene::Scene::from_ron(&scene_text, "z.ron").unwrap();
    assert_eq!(
        scene.columns[1].pattern,
        pattern("rank1", &[("z", "1,610")])
    );
    let saved = samplescope::scene::Scene::from_ron(&scene.to_ron(), "saved.ron").unwrap();
    assert_eq!(saved.columns[1].pattern, scene.columns[1].pattern);
    let plain = pattern("rank1", &[]);
    assert_eq!(plain.params_text(), "g=0 shift=false");
    assert!(!ron::to_string(&plain).unwrap().contains("z"));
    assert!(samplescope::core::params::params_json(&plain)
        .get("z")
        .is_none());
    // The CLI: `--set z=…` writes the CBC lattice's file.
    let args = |z: Option<&str>| {
        let mut a = vec!["points", "rank1", "-n", "4999", "--dims", "8"];
        if let Some(z) = z {
            a.extend(["--set", z]);
        }
        a.iter().map(|s| s.to_string()).collect::<Vec<_>>()
    };
    let zset = format!("z={list}");
    let run = |a: Vec<String>| {
        let refs: Vec<&str> = a.iter().map(String::as_str).collect();
        let o = samplescope(&refs);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        o.stdout
    };
    assert_eq!(run(args(Some(&zset))), run(args(None)));
}

#[test]
fn rank1_refuses_a_bad_generating_vector_with_one_line() {
    let cases: [(&[&str], &str); 7] = [
        (
            &["--dims", "3", "--set", "z=1,2"],
            "rank1.z = [1,2]: must be a list of exactly 3 integers (one per dimension, dims = 3), each in 1..=100 (below n = 101); it has 2",
        ),
        (
            &["--dims", "3", "--set", "z=1,2,101"],
            "rank1.z = [1,2,101]: must be a list of integers in 1..=100 (below n = 101); entry 2 is 101",
        ),
        (
            &["--set", "z=[1,7,3]"],
            "rank1.z = [1,7,3]: must be a list of exactly 2 integers",
        ),
        (
            &["--dims", "3", "--set", "z=0,2,3"],
            "rank1.z = 0,2,3: must be a list [a,b,…] of up to 1024 integers, one per dimension, each an integer in 1..=16777215 ([] = not given)",
        ),
        (
            &["--dims", "2", "--set", "z=1,2.5"],
            "rank1.z = 1,2.5: must be a list [a,b,…] of up to 1024 integers",
        ),
        (
            &["--dims", "2", "--set", "z=1,x"],
            "rank1.z = 1,x: must be a list",
        ),
        (
            &["--dims", "2", "--set", "z=1,5", "--set", "g=3"],
            "rank1.z = [1,5]: must be left out when g ≠ 0 (g = 3 sets the Korobov vector (1, g, g², …)); set g = 0 to give z",
        ),
    ];
    for (extra, want) in cases {
        let mut args = vec!["points", "rank1", "-n", "101"];
        args.extend(extra);
        let o = samplescope(&args);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert_eq!(err.trim().lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains(want), "{args:?}: {err}");
    }
}

/// The real root > 1 of x^(D+1) = x + 1 in 62-bit fixed point (x = X / 2^62), found by
/// bisection on the sign of x^(D+1) − x − 1 with integer arithmetic only: an independent
/// reference for `phi` (which uses Newton's method in f64). Each power is a truncated product,
/// so x^(D+1) is low by at most D units of 2^−62; the slope of x^(D+1) − x − 1 at the root is
/// (D+1)φ^D − 1 > D, so the root is within 2 units of 2^−62 (5·10⁻¹⁹).
fn phi_bisection(dims: usize) -> u64 {
    const ONE: u128 = 1 << 62;
    let above = |x: u64| {
        let mut p = x as u128;
        for _ in 0..dims {
            p = (p * x as u128) >> 62;
            if p >= 4 * ONE {
                return true; // x^(D+1) ≥ 4 > x + 1 for x < 2
            }
        }
        p >= x as u128 + ONE
    };
    let (mut lo, mut hi) = (ONE as u64, 2 * ONE as u64); // f(1) = −1 < 0 ≤ f(2)
    while hi - lo > 1 {
        let mid = lo + (hi - lo) / 2;
        if above(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    hi
}

#[test]
fn phi_d_and_alpha_match_an_independent_bisection_and_the_published_values() {
    use samplescope::core::pattern::cube::lattice::{alpha_fixed, phi};
    let ulp = |x: f64| f64::from_bits(x.to_bits() + 1) - x;
    // Published values, to more digits than an f64 holds: φ_1 the golden ratio, φ_2 the
    // plastic number, φ_3 (Roberts 2018).
    let published = [
        (1usize, "1.6180339887498948482045868343656381177"),
        (2, "1.3247179572447460259609088544780973407344"),
        (3, "1.2207440846057594753616853491088319144324"),
    ];
    for (d, text) in published {
        // phi in f64 within 2 ulps (Newton in f64 ends within one or two roundings of the root).
        let want: f64 = text.parse().unwrap();
        let f = phi(d);
        assert!(
            (f - want).abs() <= 2.0 * ulp(want),
            "φ_{d} = {f:e}, published {text}"
        );
        // The bisection within 3 units of 2^−62 of the published digits (19 of them: 10⁻¹⁹).
        let frac: u128 = text[2..21].parse().unwrap();
        let fixed = (1u128 << 62) + (frac << 62) / 10u128.pow(19);
        let b = phi_bisection(d) as u128;
        assert!(
            b.abs_diff(fixed) <= 3,
            "bisection φ_{d}: {b} vs {fixed} (2^-62 units)"
        );
    }
    for d in DIMS.into_iter().chain([4, 16, 100, 1024]) {
        let reference = phi_bisection(d);
        let r = reference as f64 / 2f64.powi(62);
        let f = phi(d);
        assert!(
            (f - r).abs() <= 2.0 * ulp(r),
            "dims {d}: φ {f:e} vs bisection {r:e}"
        );
        // a = 1/φ_d (2^−128 fixed point, refined beyond f64): a·φ = 1 within 8 units of
        // 2^−62 (a truncated to 62 bits: 1 unit; the bisection's root: 2 units times a < 1;
        // the product's truncation: 1 unit), i.e. a is 1/φ_d to 2·10⁻¹⁸.
        let a62 = (alpha_fixed(d)[0] >> 66) as u128;
        let product = (a62 * reference as u128) >> 62;
        let one = 1u128 << 62;
        assert!(
            product.abs_diff(one) <= 8,
            "dims {d}: a·φ = 1 + {} units of 2^-62",
            product as i128 - one as i128
        );
    }
}
