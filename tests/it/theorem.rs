//! The 1D sampling-theorem view: closed-form transforms against numeric Fourier integrals
//! (composite Simpson, written here independently of the crate's quadrature), the scaling and
//! shift properties, Poisson summation, ideal reconstruction, the pre-/post-aliasing split,
//! Parseval between the spectral and the spatial error, edge cases, typed errors, and the
//! compute graph evaluating the view only while its panel is shown.

use samplescope::core::cancel::Cancel;
use samplescope::core::filter::{
    BoxFilter, Cosc, Filter, LowPass, Mitchell, Sinc, Tent, Window, WindowedSinc,
};
use samplescope::core::params::ParamError;
use samplescope::core::signal::theorem::{
    aliasing_errors, compute_view, merged_lines, samples, PairKind, Reconstructor, Signal1D,
    TheoremError, TheoremSettings, TransformPair, ERROR_BAND,
};
use samplescope::core::signal::theorem::{
    Box1D, Cosines1D, Gaussian1D, PulseTrain1D, Sinc1D, SincSquared1D, Tent1D,
};
use samplescope::engine::Evaluator;
use samplescope::scene::graph::NodeKind;
use samplescope::scene::{Scene, BUILTIN};
use std::f64::consts::PI;

/// Composite Simpson's rule with `n` (even) intervals on [a, b].
fn simpson(f: impl Fn(f64) -> f64, a: f64, b: f64, n: usize) -> f64 {
    let n = n + n % 2;
    let h = (b - a) / n as f64;
    let mut s = f(a) + f(b);
    for i in 1..n {
        let x = a + h * i as f64;
        s += if i % 2 == 1 { 4.0 } else { 2.0 } * f(x);
    }
    s * h / 3.0
}

/// ∫ f(x) e^{−2πiωx} dx over [a, b] by Simpson: (Re, Im).
fn fourier(f: impl Fn(f64) -> f64, omega: f64, a: f64, b: f64, n: usize) -> (f64, f64) {
    let re = simpson(|x| f(x) * (2.0 * PI * omega * x).cos(), a, b, n);
    let im = simpson(|x| -f(x) * (2.0 * PI * omega * x).sin(), a, b, n);
    (re, im)
}

const OMEGAS: [f64; 9] = [0.0, 0.1, 0.37, 0.5, 1.0, 1.3, 2.71, 4.0, 7.9];

#[test]
fn closed_form_transforms_match_numeric_fourier_integrals() {
    // Compact support or fast decay: forward transform over the support (Simpson, 2·10⁵
    // intervals; the box integrates its smooth inside, so the error is O(h⁴)). Tolerance 1e-9.
    let cases = [
        (Signal1D::Box(Box1D { width: 0.8 }), 0.4),
        (Signal1D::Tent(Tent1D { radius: 1.3 }), 1.3),
        (Signal1D::Gaussian(Gaussian1D { sigma: 0.35 }), 0.35 * 12.0),
    ];
    for (s, half) in cases {
        // Stop 1e-12 short of the box's jumps, where f takes the mid-value ½.
        let half = half - 1e-12;
        for w in OMEGAS {
            let (re, im) = fourier(|x| s.eval(x), w, -half, half, 200_000);
            // The tent has kinks at 0: integrate each half separately.
            let re = if let Signal1D::Tent(Tent1D { .. }) = s {
                fourier(|x| s.eval(x), w, -half, 0.0, 100_000).0
                    + fourier(|x| s.eval(x), w, 0.0, half, 100_000).0
            } else {
                re
            };
            let f = s.transform(w);
            assert!((re - f).abs() < 1e-9, "{} ω={w}: {re} vs {f}", s.name());
            assert!(im.abs() < 1e-9, "{} ω={w}: Im {im}", s.name());
        }
    }
    // Band-limited: f(x) = ∫_{−B}^{B} F(ω) e^{2πiωx} dω (the inverse transform over the band).
    for s in [
        Signal1D::Sinc(Sinc1D { bandwidth: 1.7 }),
        Signal1D::SincSquared(SincSquared1D { bandwidth: 0.9 }),
    ] {
        // Stop 1e-12 short of ±B, where the sinc's F takes the mid-value.
        let b = s.bandwidth().unwrap() - 1e-12;
        for x in [0.0, 0.13, 0.5, 1.0, 2.2, 7.3] {
            let halves = simpson(
                |w| s.transform(w) * (2.0 * PI * w * x).cos(),
                -b,
                0.0,
                100_000,
            ) + simpson(
                |w| s.transform(w) * (2.0 * PI * w * x).cos(),
                0.0,
                b,
                100_000,
            );
            assert!(
                (halves - s.eval(x)).abs() < 1e-9,
                "{} x={x}: {halves} vs {}",
                s.name(),
                s.eval(x)
            );
        }
    }
    // Lines: the cosines are their lines; the pulse train's Fourier coefficients
    // c_m = (1/p)∫_{−p/2}^{p/2} f(x) e^{−2πimx/p} dx (numeric over the pulse) equal d sinc(md).
    let c = Signal1D::Cosines(Cosines1D { bandwidth: 1.3 });
    let (lines, dropped) = c.lines();
    assert_eq!(dropped, 0.0);
    for x in [0.0, 0.3, 1.7, -4.2] {
        let sum: f64 = lines
            .iter()
            .map(|&(nu, a)| a * (2.0 * PI * nu * x).cos())
            .sum();
        assert!((sum - c.eval(x)).abs() < 1e-13);
    }
    let p = Signal1D::PulseTrain(PulseTrain1D {
        period: 1.5,
        duty: 0.3,
    });
    let (lines, dropped) = p.lines();
    assert!(dropped <= 2.0 / (PI * PI * 1024.0) + 1e-15);
    for m in 0..6i64 {
        let edge = 0.5 * 0.3 * 1.5;
        let (re, _) = fourier(|_| 1.0, m as f64 / 1.5, -edge, edge, 20_000);
        let coeff = re / 1.5;
        let line = lines
            .iter()
            .find(|(nu, _)| (nu - m as f64 / 1.5).abs() < 1e-12)
            .unwrap();
        assert!(
            (line.1 - coeff).abs() < 1e-10,
            "m={m}: {} vs {coeff}",
            line.1
        );
    }
}

#[test]
fn energies_match_parseval_in_both_domains() {
    // Spatial ∫f² for compact/fast-decaying signals, spectral ∫F² for band-limited ones.
    let spatial = [
        (Signal1D::Box(Box1D { width: 0.8 }), 0.4),
        (Signal1D::Tent(Tent1D { radius: 1.3 }), 1.3),
        (Signal1D::Gaussian(Gaussian1D { sigma: 0.35 }), 5.0),
    ];
    for (s, half) in spatial {
        let half = half - 1e-12;
        let e = simpson(|x| s.eval(x).powi(2), -half, 0.0, 100_000)
            + simpson(|x| s.eval(x).powi(2), 0.0, half, 100_000);
        assert!((e - s.energy()).abs() < 1e-10, "{}: {e}", s.name());
    }
    for s in [
        Signal1D::Sinc(Sinc1D { bandwidth: 1.7 }),
        Signal1D::SincSquared(SincSquared1D { bandwidth: 0.9 }),
    ] {
        let b = s.bandwidth().unwrap() - 1e-12;
        let e = 2.0 * simpson(|w| s.transform(w).powi(2), 0.0, b, 100_000);
        assert!((e - s.energy()).abs() < 1e-10, "{}: {e}", s.name());
    }
    // Mean powers over one common period (Simpson, periodic integrand).
    let c = Signal1D::Cosines(Cosines1D { bandwidth: 1.0 });
    let m = simpson(|x| c.eval(x).powi(2), 0.0, 4.0, 200_000) / 4.0;
    assert!((m - c.energy()).abs() < 1e-12, "{m}");
    let p = Signal1D::PulseTrain(PulseTrain1D {
        period: 2.0,
        duty: 0.3,
    });
    assert_eq!(p.energy(), 0.3);
}

fn numeric_pair(p: &TransformPair, w: f64) -> (f64, f64) {
    let a = p.scale.abs();
    let s = p.shift;
    match p.kind {
        // Integrate over the support with its kinks/jumps as break points.
        // Stop 1e-12 short of the jumps, where the box takes the mid-value ½.
        PairKind::Box => fourier(
            |x| p.eval(x),
            w,
            s - 0.5 / a + 1e-12,
            s + 0.5 / a - 1e-12,
            100_000,
        ),
        PairKind::Tent => {
            let l = fourier(|x| p.eval(x), w, s - 1.0 / a, s, 100_000);
            let r = fourier(|x| p.eval(x), w, s, s + 1.0 / a, 100_000);
            (l.0 + r.0, l.1 + r.1)
        }
        _ => fourier(|x| p.eval(x), w, s - 8.0 / a, s + 8.0 / a, 200_000),
    }
}

#[test]
fn pair_transforms_obey_scaling_and_shift_properties_numerically() {
    for kind in [PairKind::Box, PairKind::Tent, PairKind::Gaussian] {
        let base = TransformPair {
            kind,
            scale: 1.0,
            shift: 0.0,
        };
        for (a, s) in [(0.5, 0.0), (2.0, 0.3), (-1.5, -1.2), (3.0, 2.5)] {
            let p = TransformPair {
                kind,
                scale: a,
                shift: s,
            };
            p.validate().unwrap();
            for w in [0.0, 0.2, 0.77, 1.5, 3.1] {
                // Closed form against the numeric transform of p (tolerance 1e-9).
                let (re, im) = numeric_pair(&p, w);
                let v = p.transform(w);
                assert!(
                    (re - v.re).abs() < 1e-9 && (im - v.im).abs() < 1e-9,
                    "{kind:?} a={a} s={s} ω={w}: ({re},{im}) vs {v}"
                );
                // The properties on numeric transforms alone: P(ω) = e^{−2πiωs} G(ω/a)/|a|.
                let (gr, gi) = numeric_pair(&base, w / a);
                let (c, sn) = ((2.0 * PI * w * s).cos(), -(2.0 * PI * w * s).sin());
                let pr = (c * gr - sn * gi) / a.abs();
                let pi = (c * gi + sn * gr) / a.abs();
                assert!(
                    (re - pr).abs() < 1e-9 && (im - pi).abs() < 1e-9,
                    "{kind:?} a={a} s={s} ω={w}: property"
                );
            }
        }
    }
}

#[test]
fn shah_impulses_satisfy_parseval_with_a_gaussian_test_function() {
    // ∫ p φ = ∫ P conj(Φ) with φ(x) = e^{−πx²}, Φ(ω) = e^{−πω²}:
    // Σ_n φ(s + n/|a|)/|a| = Σ_m e^{−2πim|a|s} Φ(m|a|). Tolerance 1e-12.
    for (a, s) in [(1.0, 0.0), (0.7, 0.25), (2.5, -0.4), (-1.3, 1.1)] {
        let p = TransformPair {
            kind: PairKind::Shah,
            scale: a,
            shift: s,
        };
        let (xs, ws) = p.impulses(40.0, 40.0);
        let lhs: f64 = xs.iter().map(|[x, w]| w * (-PI * x * x).exp()).sum();
        let (mut re, mut im) = (0.0, 0.0);
        for (w, c) in &ws {
            re += c.re * (-PI * w * w).exp();
            im += c.im * (-PI * w * w).exp();
        }
        assert!((lhs - re).abs() < 1e-12, "a={a} s={s}: {lhs} vs {re}");
        assert!(im.abs() < 1e-12, "a={a} s={s}: Im {im}");
        // Spacing 1/|a| in x with weight 1/|a|; spacing |a| in ω with unit magnitude.
        assert!((xs[1][0] - xs[0][0] - 1.0 / a.abs()).abs() < 1e-12);
        assert!((xs[0][1] - 1.0 / a.abs()).abs() < 1e-15);
        assert!(ws.iter().all(|(_, c)| (c.norm() - 1.0).abs() < 1e-14));
    }
}

#[test]
fn replica_sum_matches_poisson_sample_sum() {
    // P(ω) = Σ_k F(ω − k f_s) = T Σ_n f(nT) e^{−2πiωnT}.
    // Gaussian: the crate sums replicas; compare with the direct sample sum (|n| ≤ 2000,
    // remainder below e^{−(2000T)²/2σ²}). Tolerance 1e-13 (relative to F(0)).
    let g = Signal1D::Gaussian(Gaussian1D { sigma: 0.4 });
    for rate in [1.0, 2.5, 7.0] {
        let t = 1.0 / rate;
        for w in [0.0, 0.3, 0.5 * rate, 1.9, 5.5] {
            let direct: f64 = (-2000i64..=2000)
                .map(|n| t * g.eval(n as f64 * t) * (2.0 * PI * w * n as f64 * t).cos())
                .sum();
            let (p, a) = g.periodized(w, rate);
            assert!(
                (p - direct).abs() < 1e-13,
                "rate {rate} ω {w}: {p} vs {direct}"
            );
            assert!((a - (p - g.transform(w))).abs() < 1e-13);
        }
    }
    // Tent: the crate uses the finite sample sum; compare with the replica sum over
    // |k| ≤ K = 2·10⁵, whose tail is ≤ 2 Σ_{k>K} 1/(π²w(k f_s − |ω|)²) ≤ 2/(π²w f_s²(K − 1 − |ω|/f_s)).
    let tent = Signal1D::Tent(Tent1D { radius: 0.9 });
    let k_max = 200_000i64;
    for rate in [1.0, 2.5, 7.0] {
        for w in [0.0, 0.3, 0.5 * rate, 1.9, 5.5] {
            let replica: f64 = (-k_max..=k_max).map(|k| tent.replica(k, w, rate)).sum();
            let tail = 2.0 / (PI * PI * 0.9 * rate * rate * (k_max as f64 - 1.0 - w / rate));
            let (p, _) = tent.periodized(w, rate);
            assert!(
                (p - replica).abs() <= tail + 1e-12,
                "rate {rate} ω {w}: {p} vs {replica} (tail {tail:e})"
            );
        }
    }
    // Sinc²: the crate sums the finitely many replicas; compare with the sample sum over
    // |n| ≤ N = 10⁶, remainder ≤ 2T Σ_{n>N} 1/(πB nT)² ≤ 2/(π²B²T N).
    let s2 = Signal1D::SincSquared(SincSquared1D { bandwidth: 1.0 });
    let n_max = 1_000_000i64;
    for rate in [1.5, 3.0] {
        let t = 1.0 / rate;
        for w in [0.0, 0.2, 0.6, 1.1] {
            let direct: f64 = t * s2.eval(0.0)
                + 2.0
                    * (1..=n_max)
                        .map(|n| t * s2.eval(n as f64 * t) * (2.0 * PI * w * n as f64 * t).cos())
                        .sum::<f64>();
            let tail = 2.0 / (PI * PI * t * n_max as f64);
            let (p, _) = s2.periodized(w, rate);
            assert!((p - direct).abs() <= tail + 1e-12, "rate {rate} ω {w}");
        }
    }
}

#[test]
fn ideal_sinc_reconstruction_recovers_band_limited_signal_above_nyquist() {
    // sinc²(Bx), B = 1, sampled at f_s = 3 > 2B. Shannon: Σ f(nT) sinc(x/T − n) = f(x); the
    // kernel truncated at r leaves out Σ_{|u−n|>r} f(nT) sinc(u − n), bounded here term by
    // term by |f(nT)|/(π|u − n|), summed over |n| ≤ 10⁶ (the rest is below 10⁻¹²). The result
    // is divided by H(0) = ∫h: 1 for the ideal low-pass, Si(πr)·2/π for the truncated sinc,
    // which adds |f(x)|·|1/H(0) − 1| to the bound.
    let s = Signal1D::SincSquared(SincSquared1D { bandwidth: 1.0 });
    let rate = 3.0;
    for filter in [
        Filter::LowPass(LowPass {
            cutoff: 0.5,
            radius: 64.0,
        }),
        Filter::Sinc(Sinc { radius: 64.0 }),
    ] {
        let rec = Reconstructor::new(filter, rate, 10.0).unwrap();
        let r = filter.radius();
        let h0 = filter.response(0.0).re;
        for i in 0..=30 {
            let x = -3.0 + 0.2 * i as f64 + 0.0123;
            let u = x * rate;
            let bound: f64 = (-1_000_000i64..=1_000_000)
                .filter(|&n| (u - n as f64).abs() > r)
                .map(|n| s.eval(n as f64 / rate).abs() / (PI * (u - n as f64).abs()))
                .sum::<f64>()
                / h0
                + s.eval(x).abs() * (1.0 / h0 - 1.0).abs()
                + 1e-12;
            let err = (rec.reconstruct(&s, x) - s.eval(x)).abs();
            assert!(
                err <= bound,
                "{} x={x}: error {err:e} > bound {bound:e}",
                filter.name()
            );
            // The ideal low-pass (H(0) = 1): truncation only, below 1e-4 here. The truncated
            // sinc's own DC gain H(0) ≈ 0.998 dominates its bound (≈ 2e-3 near x = 0).
            if matches!(filter, Filter::LowPass(_)) {
                assert!(err < 1e-4, "{} x={x}: {err:e}", filter.name());
            }
        }
    }
}

fn ideal() -> Filter {
    Filter::LowPass(LowPass {
        cutoff: 0.5,
        radius: 16.0,
    })
}

#[test]
fn pre_aliasing_is_zero_above_nyquist_and_positive_below() {
    for s in [
        Signal1D::Sinc(Sinc1D { bandwidth: 1.0 }),
        Signal1D::SincSquared(SincSquared1D { bandwidth: 1.0 }),
        Signal1D::Cosines(Cosines1D { bandwidth: 1.0 }),
    ] {
        let above = aliasing_errors(&s, 2.5, ideal()).unwrap();
        assert!(above.pre_aliasing <= 1e-15, "{}: {above:?}", s.name());
        // The ideal filter: no post-aliasing, no smoothing, nothing lost, total ≈ 0.
        assert!(above.post_aliasing <= 1e-15, "{}: {above:?}", s.name());
        assert!(above.smoothing <= 1e-15, "{}: {above:?}", s.name());
        assert!(above.total <= 1e-12, "{}: {above:?}", s.name());
        let below = aliasing_errors(&s, 1.5, ideal()).unwrap();
        assert!(
            below.relative(below.pre_aliasing) > 1e-3,
            "{}: {below:?}",
            s.name()
        );
    }
    // Closed form for sinc(2Bx) at B < f_s < 2B: in |ω| < f_s/2 the replicas k = ±1 cover
    // f_s − B < |ω| < f_s/2 at height 1/(2B): pre = 2(B − f_s/2)/(4B²).
    for (b, fs) in [(1.0, 1.5), (1.0, 1.2), (2.0, 3.1)] {
        let e = aliasing_errors(&Signal1D::Sinc(Sinc1D { bandwidth: b }), fs, ideal()).unwrap();
        let exact = 2.0 * (b - 0.5 * fs) / (4.0 * b * b);
        assert!((e.pre_aliasing - exact).abs() < 1e-9, "{e:?} vs {exact}");
    }
    // A cosine at exactly f_s/2 is not sampled above the Nyquist rate: it pre-aliases.
    let at = aliasing_errors(
        &Signal1D::Cosines(Cosines1D { bandwidth: 1.0 }),
        2.0,
        ideal(),
    )
    .unwrap();
    assert!(at.pre_aliasing > 1e-3, "{at:?}");
    // Not band-limited: pre-aliasing at every rate; with the ideal filter the error is exactly
    // pre-aliasing plus the lost band (to the quadrature tolerance).
    for s in [
        Signal1D::Box(Box1D { width: 1.0 }),
        Signal1D::Tent(Tent1D { radius: 1.0 }),
        Signal1D::Gaussian(Gaussian1D { sigma: 0.3 }),
    ] {
        let e = aliasing_errors(&s, 4.0, ideal()).unwrap();
        assert!(e.pre_aliasing > 0.0, "{}: {e:?}", s.name());
        assert!(e.post_aliasing <= 1e-15, "{}: {e:?}", s.name());
        let sum = e.pre_aliasing + e.lost;
        assert!(
            (e.total - sum).abs() <= 1e-7 * e.signal_energy,
            "{}: {e:?}",
            s.name()
        );
    }
}

#[test]
fn post_aliasing_of_box_exceeds_tent_exceeds_windowed_sinc() {
    let boxf = Filter::Box(BoxFilter { radius: 0.5 });
    let tent = Filter::Tent(Tent { radius: 1.0 });
    let lanczos = Filter::WindowedSinc(WindowedSinc {
        radius: 3.0,
        window: Window::Lanczos,
    });
    for (s, rate) in [
        (Signal1D::Gaussian(Gaussian1D { sigma: 0.4 }), 4.0),
        (Signal1D::Sinc(Sinc1D { bandwidth: 1.0 }), 3.0),
        (Signal1D::Cosines(Cosines1D { bandwidth: 1.0 }), 3.0),
        (Signal1D::Tent(Tent1D { radius: 1.0 }), 5.0),
    ] {
        let p: Vec<f64> = [boxf, tent, lanczos]
            .iter()
            .map(|f| aliasing_errors(&s, rate, *f).unwrap().post_aliasing)
            .collect();
        assert!(
            p[0] > p[1] && p[1] > p[2] && p[2] > 0.0,
            "{}: {p:?}",
            s.name()
        );
    }
}

#[test]
fn total_error_matches_the_spatial_error_parseval() {
    // ∫|F_r − F|² dω (spectral, crate) against ∫|f_r − f|² dx (spatial, Simpson on a fine grid
    // through the reconstruction). Gaussian: both decay fast; tolerance 1e-6 relative.
    let g = Signal1D::Gaussian(Gaussian1D { sigma: 0.4 });
    for (rate, filter) in [
        (3.0, Filter::Tent(Tent { radius: 1.0 })),
        (2.0, Filter::Mitchell(Mitchell::default())),
        (
            4.0,
            Filter::WindowedSinc(WindowedSinc {
                radius: 3.0,
                window: Window::Lanczos,
            }),
        ),
    ] {
        let e = aliasing_errors(&g, rate, filter).unwrap();
        let rec = Reconstructor::new(filter, rate, ERROR_BAND * rate).unwrap();
        // Break at every sample (kinks of f_r for the tent and Mitchell).
        let l = 8.0;
        let mut spatial = 0.0;
        let n = (2.0 * l * rate) as i64;
        for i in 0..n {
            let a = -l + i as f64 / rate;
            spatial += simpson(
                |x| (rec.reconstruct(&g, x) - g.eval(x)).powi(2),
                a,
                a + 1.0 / rate,
                64,
            );
        }
        assert!(
            (spatial - e.total).abs() <= 1e-6 * e.signal_energy + e.tail_bound,
            "{}: spatial {spatial:e} vs spectral {:e}",
            filter.name(),
            e.total
        );
    }
    // Cosines at B = 1, f_s = 2.5: every line is a multiple of ¼, so f_r − f has period 4 and
    // its mean square is the total power. The lines the filter passes beyond ±Ω (not in the
    // crate's sum) are added up here: Σ_ν Σ_{|ν + k f_s| > Ω} |G(ν + k f_s) c_ν|², |k| ≤ 10⁴
    // (the tent's G = sinc² leaves < 1e-12 beyond).
    let c = Signal1D::Cosines(Cosines1D { bandwidth: 1.0 });
    let tent = Filter::Tent(Tent { radius: 1.0 });
    let e = aliasing_errors(&c, 2.5, tent).unwrap();
    let rec = Reconstructor::new(tent, 2.5, ERROR_BAND * 2.5).unwrap();
    let mut spatial = 0.0;
    for i in 0..10 {
        let a = i as f64 * 0.4;
        spatial += simpson(
            |x| (rec.reconstruct(&c, x) - c.eval(x)).powi(2),
            a,
            a + 0.4,
            512,
        );
    }
    spatial /= 4.0;
    let band = ERROR_BAND * 2.5;
    let (lines, _) = c.lines();
    let mut outside = 0.0;
    for &(nu, amp) in &lines {
        for k in -10_000i64..=10_000 {
            let w = nu + k as f64 * 2.5;
            if w.abs() > band {
                outside += (rec.gain(w) * amp).powi(2);
            }
        }
    }
    assert!(
        (spatial - e.total - outside).abs() <= 1e-9 * e.signal_energy,
        "spatial {spatial:e} vs lines {:e}",
        e.total
    );
    // Coincident replicas merge: at f_s = 2, the line at B = 1 meets the k = −1 replica of −1.
    let m = merged_lines(&c, 2.0, 4.0);
    let at1 = m.iter().find(|l| (l.omega - 1.0).abs() < 1e-12).unwrap();
    assert!((at1.total - 0.2).abs() < 1e-15 && (at1.original - 0.1).abs() < 1e-15);
}

#[test]
fn sinc_at_zero_and_tiny_x_is_finite() {
    let s = Signal1D::Sinc(Sinc1D { bandwidth: 1.0 });
    assert_eq!(s.eval(0.0), 1.0);
    for x in [1e-300, 5e-324, -1e-200, 1e-9, 1e-5] {
        let v = s.eval(x);
        assert!(v.is_finite() && (v - 1.0).abs() < 1e-8, "x={x}: {v}");
    }
    let sq = Signal1D::SincSquared(SincSquared1D { bandwidth: 1.0 });
    assert_eq!(sq.eval(0.0), 1.0);
    assert!(sq.eval(5e-324).is_finite());
    let rec = Reconstructor::new(ideal(), 3.0, 10.0).unwrap();
    for x in [0.0, 1e-300, 5e-324] {
        assert!(rec.reconstruct(&s, x).is_finite());
    }
    let b = TransformPair::default();
    assert_eq!(b.transform(0.0).re, 1.0);
    assert!(b.transform(1e-300).re.is_finite());
    let box1 = Signal1D::Box(Box1D { width: 1.0 });
    assert_eq!(box1.transform(0.0), 1.0);
    assert!((box1.transform(5e-324) - 1.0).abs() < 1e-15);
}

fn field_of(e: &TheoremError) -> String {
    match e {
        TheoremError::InvalidParam { field, .. } => field.to_string(),
        TheoremError::Filter(_) => "filter".into(),
        TheoremError::Param(ParamError::Invalid { owner, field, .. }) => format!("{owner}.{field}"),
        TheoremError::Param(p) => format!("? {p}"),
    }
}

#[test]
fn bad_input_gives_typed_errors_naming_field_and_range() {
    let base = TheoremSettings::default();
    let mut cases: Vec<(TheoremSettings, &str)> = Vec::new();
    for rate in [0.0, -1.0, f64::NAN, f64::INFINITY, 1e9] {
        cases.push((TheoremSettings { rate, ..base }, "rate"));
    }
    cases.push((
        TheoremSettings {
            rate: 1000.0,
            extent: 1000.0,
            ..base
        },
        "rate",
    ));
    // Too many samples across the signal's width (cost of the error integrals).
    cases.push((
        TheoremSettings {
            signal: Signal1D::Box(Box1D { width: 10.0 }),
            rate: 100.0,
            ..base
        },
        "rate",
    ));
    for extent in [0.0, f64::NAN, 1e7] {
        cases.push((TheoremSettings { extent, ..base }, "extent"));
    }
    for width in [0.0, -2.0, f64::NAN, 1e300] {
        cases.push((
            TheoremSettings {
                signal: Signal1D::Box(Box1D { width }),
                ..base
            },
            "signal.width",
        ));
    }
    cases.push((
        TheoremSettings {
            signal: Signal1D::PulseTrain(PulseTrain1D {
                period: 1.0,
                duty: 1.5,
            }),
            ..base
        },
        "signal.duty",
    ));
    cases.push((
        TheoremSettings {
            filter: Filter::Cosc(Cosc::default()),
            ..base
        },
        "filter",
    ));
    cases.push((
        TheoremSettings {
            filter: Filter::Tent(Tent { radius: -1.0 }),
            ..base
        },
        "filter",
    ));
    for scale in [0.0, f64::NAN, 1e6] {
        cases.push((
            TheoremSettings {
                pair: TransformPair { scale, ..base.pair },
                ..base
            },
            "pair.scale",
        ));
    }
    for vdc_rows in [0, 1 << 40] {
        cases.push((TheoremSettings { vdc_rows, ..base }, "vdc_rows"));
    }
    for (s, field) in cases {
        let e = compute_view(&s).expect_err(field);
        assert_eq!(field_of(&e), field, "{e}");
        let text = e.to_string();
        assert!(text.starts_with(&format!("theorem.{field}")), "{text}");
        if let TheoremError::InvalidParam { allowed, .. } = &e {
            assert!(!allowed.is_empty());
            assert!(text.contains("must be"), "{text}");
        }
        assert_eq!(s.validate().unwrap_err(), e);
    }
    assert!(matches!(
        samples(
            &Signal1D::Gaussian(Gaussian1D { sigma: 1.0 }),
            f64::NAN,
            1.0
        ),
        Err(TheoremError::InvalidParam { field: "rate", .. })
    ));
    assert!(matches!(
        aliasing_errors(
            &Signal1D::Gaussian(Gaussian1D { sigma: 1.0 }),
            -3.0,
            ideal()
        ),
        Err(TheoremError::InvalidParam { field: "rate", .. })
    ));
}

#[test]
fn view_has_samples_replicas_and_the_van_der_corput_table() {
    let s = TheoremSettings {
        signal: Signal1D::Gaussian(Gaussian1D { sigma: 0.3 }),
        rate: 2.0,
        extent: 2.0,
        vdc_rows: 8,
        ..TheoremSettings::default()
    };
    let v = compute_view(&s).unwrap();
    // Samples at nT for |nT| ≤ extent: n = −4..=4.
    assert_eq!(v.samples.len(), 9);
    assert_eq!(v.samples[4], [0.0, 1.0]);
    assert_eq!(v.spectrum.replicas.len(), 6);
    // The replica k is F shifted by k f_s.
    let (k, r) = &v.spectrum.replicas[3];
    assert_eq!(*k, 1);
    for p in r.iter().step_by(97) {
        assert_eq!(p[1], s.signal.transform(p[0] - 2.0).abs());
    }
    // The table of the lecture: i, binary, reversed, value.
    let rows: Vec<(u64, String, String, f64)> = v
        .vdc
        .iter()
        .map(|r| (r.i, r.digits_string(), r.reversed_string(), r.value))
        .collect();
    assert_eq!(rows[0], (0, "0".into(), "0.0".into(), 0.0));
    assert_eq!(rows[1], (1, "1".into(), "0.1".into(), 0.5));
    assert_eq!(rows[6], (6, "110".into(), "0.011".into(), 0.375));
    assert_eq!(rows.len(), 8);
    // Line signals carry lines, not curves.
    let c = compute_view(&TheoremSettings {
        signal: Signal1D::Cosines(Cosines1D { bandwidth: 1.0 }),
        ..s
    })
    .unwrap();
    assert!(c.spectrum.original.is_empty() && !c.spectrum.lines.is_empty());
    assert!(c.errors.periodic);
}

fn quick(mut s: Scene) -> Scene {
    s.n = 256;
    s.recon.size = 64;
    s.spectrum.size = 32;
    s
}

#[test]
fn hidden_theorem_panel_computes_nothing() {
    let eval = Evaluator::default();
    let mut scene = quick(Scene::default());
    scene.columns.push(scene.columns[0].clone());
    scene.columns[1].seed = 9;
    scene.panels.theorem = false;
    let run = |scene: &Scene| {
        eval.evaluate(scene, &Cancel::new(), &mut |_, k, r| {
            if k == NodeKind::Theorem {
                assert!(r.value.is_ok(), "{:?}", r.value.as_ref().err());
            }
        })
    };
    run(&scene);
    assert_eq!(eval.count(NodeKind::Theorem), 0);
    scene.panels.theorem = true;
    run(&scene);
    // Column-independent: one evaluation for two columns.
    assert_eq!(eval.count(NodeKind::Theorem), 1);
    run(&scene);
    assert_eq!(eval.count(NodeKind::Theorem), 1);
    // Changing another column's pattern does not touch it; changing the rate does.
    scene.columns[1].seed = 10;
    run(&scene);
    assert_eq!(eval.count(NodeKind::Theorem), 1);
    scene.theorem.rate = 3.0;
    run(&scene);
    assert_eq!(eval.count(NodeKind::Theorem), 2);
    // Only the theorem panel: nothing else is computed.
    eval.reset_counts();
    scene.panels.pattern = false;
    scene.panels.spectrum = false;
    scene.panels.zoneplate = false;
    scene.panels.filter = false;
    scene.panels.cost = false;
    scene.panels.theorem = true;
    scene.theorem.rate = 5.0;
    run(&scene);
    for (k, n) in eval.counts() {
        assert_eq!(n, usize::from(k == NodeKind::Theorem), "{k:?}");
    }
}

#[test]
fn theorem_scenes_load_show_the_panel_and_separate_the_errors() {
    for name in ["sampling-theorem.ron", "pre-aliasing-vs-post-aliasing.ron"] {
        let (_, text) = BUILTIN.iter().find(|(n, _)| *n == name).expect(name);
        let scene = Scene::from_ron(text, name).unwrap();
        assert!(scene.panels.theorem, "{name}");
        assert!(!scene.notes.is_empty());
        let v = compute_view(&scene.theorem).unwrap();
        assert!(v.errors.pre_aliasing > 0.0, "{name}: {:?}", v.errors);
        assert!(v.errors.post_aliasing > 0.0, "{name}: {:?}", v.errors);
    }
    // A scene without a theorem section stays valid and gets the defaults.
    let s = Scene::from_ron("(title: \"x\")", "x.ron").unwrap();
    assert_eq!(s.theorem, TheoremSettings::default());
    assert!(!s.panels.theorem);
    // Out-of-range values are reported with the field.
    let bad = "(title: \"x\", theorem: (rate: -1.0))";
    let e = Scene::from_ron(bad, "bad.ron").unwrap_err().to_string();
    assert!(e.contains("theorem.rate"), "{e}");
}

/// The panel driven through its labels (no rendering: accesskit only, no GPU needed).
#[test]
fn panel_controls_edit_the_settings_and_show_both_errors() {
    use egui_kittest::kittest::Queryable;
    use samplescope::scene::graph::{NodeResult, NodeValue};
    use samplescope::ui::figures::FigureRequests;
    use samplescope::ui::panels::theorem::TheoremPanel;
    use samplescope::ui::panels::{Panel, PanelCx};
    use samplescope::ui::results::{ColumnResults, Shown};
    use samplescope::ui::view::ViewState;
    use samplescope::ui::widgets::image::ImageView;
    use std::sync::Arc;

    /// The panel and what the app would lend it.
    struct State {
        panel: TheoremPanel,
        scene: Scene,
        data: Vec<samplescope::model::ColumnData>,
        view: ViewState,
        images: ImageView,
        figures: FigureRequests,
        evaluator: Evaluator,
    }
    let scene = Scene::default();
    assert_eq!(scene.theorem, TheoremSettings::default());
    let view = compute_view(&scene.theorem).unwrap();
    let result = Arc::new(NodeResult {
        value: Ok(NodeValue::Theorem(Arc::new(view))),
        wall: std::time::Duration::ZERO,
        accuracy: None,
    });
    let shown = Shown {
        result,
        scene: Arc::new(scene.clone()),
        generation: 1,
        progress: None,
    };
    let state = State {
        panel: TheoremPanel::default(),
        scene,
        data: vec![samplescope::scene::figure::column_data(
            &ColumnResults::from([(NodeKind::Theorem, shown)]),
        )],
        view: ViewState::default(),
        images: ImageView::new(false),
        figures: FigureRequests::default(),
        evaluator: Evaluator::default(),
    };
    let mut h = egui_kittest::Harness::builder()
        .with_size(eframe::egui::Vec2::new(1400.0, 900.0))
        .build_ui_state(
            |ui, s: &mut State| {
                let mut cx = PanelCx {
                    scene: &mut s.scene,
                    column: 0,
                    data: &s.data,
                    view: &mut s.view,
                    images: &mut s.images,
                    figures: &mut s.figures,
                    evaluator: &s.evaluator,
                    cell: Default::default(),
                };
                s.panel.ui(ui, &mut cx);
            },
            state,
        );
    h.run();
    // The two aliasing errors side by side, and the controls by their labels.
    for label in ["pre-aliasing", "post-aliasing", "smoothing"] {
        h.get_by_label(label);
    }
    use eframe::egui::accesskit::Role;
    for label in [
        "sampling rate f_s",
        "signal radius",
        "scale |a|",
        "shift s",
        "van der Corput rows n",
    ] {
        h.get_by_role_and_label(Role::Slider, label);
    }
    h.get_by_role_and_label(Role::ComboBox, "Signal");
    h.get_by_role_and_label(Role::ComboBox, "Reconstruction filter");
    h.get_by_role_and_label(Role::ComboBox, "Pair");
    // The table shows row i = 6 of the lecture: 110 → 0.011.
    h.get_by_label("0.011");
    // Controls edit the settings (the engine recomputes from them).
    h.get_by_label("Show Re/Im of the transform")
        .click_accesskit();
    h.run();
    assert!(h.state().panel.pair_re_im);
    assert_eq!(h.state().scene.theorem, TheoremSettings::default());
    h.get_by_role_and_label(Role::ComboBox, "Signal")
        .click_accesskit();
    h.run();
    h.get_by_label("gaussian").click_accesskit();
    h.run();
    assert_eq!(
        h.state().scene.theorem.signal,
        Signal1D::Gaussian(Gaussian1D { sigma: 0.3 })
    );
}
