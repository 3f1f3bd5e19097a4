//! Quality metrics and 2D filters against closed forms: smoothing and post-aliasing of the box,
//! tent, Gaussian and ideal filters (via Si and erf), ringing of Mitchell, sinc and cosc, the
//! anisotropy of separable ideal low-pass filters, and the numeric Hankel transform against the
//! Gaussian (separable = radial).

use glam::DVec2;
use samplescope::core::cancel::Cancel;
use samplescope::core::filter::kernels::{HighPass, LowPass};
use samplescope::core::filter::special::{erf, sine_integral};
use samplescope::core::filter::{
    BoxFilter, Cosc, Filter, Filter2D, FilterError, Gaussian, Mitchell, Mode2D, Sinc, Tent, Window,
};
use samplescope::core::rng::Rng;
use std::f64::consts::PI;

fn separable(f: Filter) -> Filter2D {
    Filter2D::new(f, Mode2D::Separable).expect("valid")
}

fn radial(f: Filter) -> Filter2D {
    Filter2D::new(f, Mode2D::Radial).expect("valid")
}

/// ∫₀^X sinc²(ω) dω = Si(2πX)/π − sin²(πX)/(π²X).
fn int_sinc2(x: f64) -> f64 {
    sine_integral(2.0 * PI * x) / PI - (PI * x).sin().powi(2) / (PI * PI * x)
}

fn wide_gaussian() -> Filter {
    Filter::Gaussian(Gaussian {
        sigma: 0.5,
        radius: 8.0,
        subtract_edge: false,
    })
}

#[test]
fn ideal_low_pass_at_nyquist_has_no_smoothing_no_post_aliasing_no_anisotropy() {
    let m = separable(Filter::LowPass(LowPass {
        cutoff: 0.5,
        radius: 16.0,
    }))
    .metrics()
    .unwrap();
    assert!(m.smoothing.abs() < 1e-12, "{m:?}");
    assert_eq!(m.post_aliasing, 0.0);
    assert_eq!(m.anisotropy, 0.0);
    // The truncated sinc kernel still rings (Gibbs): about 9% for a long kernel.
    assert!(m.ringing > 0.08 && m.ringing < 0.1, "{m:?}");
}

#[test]
fn ideal_low_pass_below_nyquist_smooths_by_one_minus_twice_the_cutoff() {
    let m = separable(Filter::LowPass(LowPass {
        cutoff: 0.25,
        radius: 8.0,
    }))
    .metrics()
    .unwrap();
    assert!((m.smoothing - 0.5).abs() < 1e-12, "{m:?}");
    assert_eq!(m.post_aliasing, 0.0);
}

#[test]
fn ideal_high_pass_post_aliasing_is_the_energy_fraction_above_nyquist() {
    // |H|² = 1 on [c, ω_max]: fraction (4 − ½)/(4 − c).
    let m = separable(Filter::HighPass(HighPass {
        cutoff: 0.25,
        radius: 8.0,
    }))
    .metrics()
    .unwrap();
    assert!((m.post_aliasing - 3.5 / 3.75).abs() < 1e-12, "{m:?}");
    // Smoothing relative to the pass-band gain 1: half the baseband [0, ½] is blocked.
    assert!((m.smoothing - 0.5).abs() < 1e-12);
}

#[test]
fn anisotropy_of_a_separable_ideal_low_pass_counts_passing_angles() {
    // H(ωx)H(ωy) = 1 iff both |ωx|, |ωy| < 0.3. At ρ = 13.5/32 only the diagonal θ = π/4 of the
    // 17 angles in [0, π/4] passes (cos θ < 0.3/ρ = 0.711 only for θ > 0.779); larger sampled
    // radii (≥ 14.5/32 > 0.3√2) pass nothing and are skipped. (max − min)/mean = 1/(1/17) = 17.
    let m = separable(Filter::LowPass(LowPass {
        cutoff: 0.3,
        radius: 8.0,
    }))
    .metrics()
    .unwrap();
    assert!((m.anisotropy - 17.0).abs() < 1e-12, "{m:?}");
}

#[test]
fn box_smoothing_and_post_aliasing_match_sine_integral_closed_forms() {
    // Box r = ½: H = sinc(ω) ≥ 0 on [0, ½]: smoothing = 1 − 2 Si(π/2)/π;
    // post-aliasing = (I(4) − I(½))/I(4) with I(X) = ∫₀^X sinc².
    let m = separable(Filter::Box(BoxFilter { radius: 0.5 }))
        .metrics()
        .unwrap();
    let smoothing = 1.0 - 2.0 * sine_integral(PI / 2.0) / PI;
    let post = (int_sinc2(4.0) - int_sinc2(0.5)) / int_sinc2(4.0);
    assert!(
        (m.smoothing - smoothing).abs() < 1e-12,
        "{} vs {smoothing}",
        m.smoothing
    );
    assert!(
        (m.post_aliasing - post).abs() < 1e-12,
        "{} vs {post}",
        m.post_aliasing
    );
    assert_eq!(m.ringing, 0.0);
    // Tent r = 1: H = sinc², smoothing = 1 − 2 I(½).
    let m = separable(Filter::Tent(Tent { radius: 1.0 }))
        .metrics()
        .unwrap();
    assert!((m.smoothing - (1.0 - 2.0 * int_sinc2(0.5))).abs() < 1e-12);
    assert!(m.ringing < 1e-15);
}

#[test]
fn gaussian_metrics_match_erf_closed_forms() {
    // |H|/H(0) = e^{−aω²}, a = 2π²σ²: smoothing = 1 − 2·(√π/(2√a)) erf(√a/2);
    // |H|² ∝ e^{−2aω²}: post = (erf(√(2a)·4) − erf(√(2a)/2))/erf(√(2a)·4).
    let sigma: f64 = 0.5;
    let a = 2.0 * PI * PI * sigma * sigma;
    let smoothing = 1.0 - 2.0 * (PI.sqrt() / (2.0 * a.sqrt())) * erf(a.sqrt() / 2.0);
    let b = (2.0 * a).sqrt();
    let post = (erf(4.0 * b) - erf(0.5 * b)) / erf(4.0 * b);
    for f2 in [separable(wide_gaussian()), radial(wide_gaussian())] {
        let m = f2.metrics().unwrap();
        assert!(
            (m.smoothing - smoothing).abs() < 1e-10,
            "{:?}: {} vs {smoothing}",
            f2.mode,
            m.smoothing
        );
        assert!(
            (m.post_aliasing - post).abs() < 1e-10,
            "{:?}: {} vs {post}",
            f2.mode,
            m.post_aliasing
        );
        assert!(m.ringing < 1e-12, "{m:?}");
        // The separable Gaussian is isotropic: the product e^{−a(ωx²+ωy²)} depends on |ω| only.
        assert!(m.anisotropy < 1e-12, "{m:?}");
    }
}

/// −∫_{u0}^{2} k(u) du for the Mitchell cubic's outer piece, u0 its zero in [1, 2).
fn mitchell_overshoot(b: f64, c: f64) -> f64 {
    let q = [
        (8.0 * b + 24.0 * c) / 6.0,
        (-12.0 * b - 48.0 * c) / 6.0,
        (6.0 * b + 30.0 * c) / 6.0,
        (-b - 6.0 * c) / 6.0,
    ];
    let k = |u: f64| q[0] + q[1] * u + q[2] * u * u + q[3] * u * u * u;
    let anti =
        |u: f64| q[0] * u + q[1] * u * u / 2.0 + q[2] * u.powi(3) / 3.0 + q[3] * u.powi(4) / 4.0;
    // k(1) = B/6 ≥ 0 and k < 0 just below 2 when C > B/2... find the sign change by bisection.
    let (mut lo, mut hi) = (1.0, 2.0 - 1e-9);
    if k(lo) < 0.0 {
        return 0.0;
    }
    for _ in 0..200 {
        let m = 0.5 * (lo + hi);
        if k(m) > 0.0 {
            lo = m;
        } else {
            hi = m;
        }
    }
    (-(anti(2.0) - anti(lo))).max(0.0)
}

#[test]
fn mitchell_ringing_matches_the_area_of_its_negative_lobe() {
    for (b, c) in [(0.0, 0.5), (1.0 / 3.0, 1.0 / 3.0), (0.2, 0.7), (1.0, 0.0)] {
        for radius in [2.0, 3.0] {
            let m = separable(Filter::Mitchell(Mitchell { b, c, radius }))
                .metrics()
                .unwrap();
            let want = mitchell_overshoot(b, c);
            assert!(
                (m.overshoot - want).abs() < 1e-10,
                "B={b} C={c} r={radius}: {} vs {want}",
                m.overshoot
            );
            assert!((m.undershoot - want).abs() < 1e-10);
            assert_eq!(m.ringing, m.overshoot.max(m.undershoot));
        }
    }
    // Catmull–Rom: exactly 1/24.
    let m = separable(Filter::Mitchell(Mitchell::catmull_rom()))
        .metrics()
        .unwrap();
    assert!((m.ringing - 1.0 / 24.0).abs() < 1e-12);
    let m = separable(Filter::Mitchell(Mitchell::b_spline()))
        .metrics()
        .unwrap();
    assert!(m.ringing < 1e-14);
}

#[test]
fn truncated_sinc_ringing_matches_sine_integral() {
    // S(x) = (Si(πx) + Si(πR))/(2 Si(πR)), maximal at x = 1 where Si(π) is the global maximum.
    for r in [2.0, 4.5, 8.0, 31.0] {
        let m = separable(Filter::Sinc(Sinc { radius: r }))
            .metrics()
            .unwrap();
        let want = (sine_integral(PI) - sine_integral(PI * r)) / (2.0 * sine_integral(PI * r));
        assert!(
            (m.overshoot - want).abs() < 1e-10,
            "R = {r}: {} vs {want}",
            m.overshoot
        );
        assert!((m.undershoot - want).abs() < 1e-10);
    }
}

#[test]
fn cosc_ringing_is_the_first_sinc_side_lobe() {
    // ∫_{−4}^{x} cosc = sinc(x) − sinc(−4) = sinc(x): a bump of peak 1 whose deepest negative
    // excursion is sinc at the first zero of cosc (tan πx = πx, x ≈ 1.4303).
    let g = |x: f64| PI * x * (PI * x).cos() - (PI * x).sin();
    let (mut lo, mut hi) = (1.2, 1.6);
    for _ in 0..200 {
        let m = 0.5 * (lo + hi);
        if g(m) * g(lo) > 0.0 {
            lo = m;
        } else {
            hi = m;
        }
    }
    let want = -(PI * lo).sin() / (PI * lo);
    let f = Filter::Cosc(Cosc {
        radius: 4.0,
        window: Window::Rect,
    });
    let m = separable(f).metrics().unwrap();
    assert!(
        (m.undershoot - want).abs() < 1e-10,
        "{} vs {want}",
        m.undershoot
    );
    assert_eq!(m.overshoot, 0.0);
    // Its smoothing is measured against the ideal differentiator 2πω: small for a long kernel.
    let long = Filter::Cosc(Cosc {
        radius: 32.0,
        window: Window::Hann,
    });
    let m = separable(long).metrics().unwrap();
    assert!(m.smoothing.abs() < 0.05, "{m:?}");
}

#[test]
fn radial_positive_kernels_do_not_ring_and_are_isotropic() {
    for f in [
        Filter::Box(BoxFilter { radius: 0.7 }),
        Filter::Tent(Tent { radius: 1.5 }),
        Filter::Mitchell(Mitchell::b_spline()),
        Filter::Gaussian(Gaussian::default()),
    ] {
        let m = radial(f).metrics().unwrap();
        assert!(m.ringing < 1e-9, "{f:?}: {m:?}");
        assert_eq!(m.anisotropy, 0.0);
        let s = separable(f).metrics().unwrap();
        assert!(
            s.anisotropy > 0.0,
            "{f:?}: separable should be anisotropic: {s:?}"
        );
    }
}

#[test]
fn hankel_transform_of_the_radial_gaussian_matches_the_separable_closed_form() {
    // g(x)g(y) = g(|p|): the numeric Hankel transform must equal G(ωx)G(ωy), G = σ√(2π)e^{−2π²σ²ω²}.
    let f = wide_gaussian();
    let Filter::Gaussian(g) = f else {
        unreachable!()
    };
    let rad = radial(f);
    let sep = separable(f);
    let mut rng = Rng::new(7);
    let h00 = g.response_untruncated(0.0).powi(2);
    for i in 0..200 {
        let w = if i < 10 {
            DVec2::new(0.1 * i as f64, 0.0)
        } else {
            DVec2::new(rng.next_f64() * 3.0 - 1.5, rng.next_f64() * 3.0 - 1.5)
        };
        let want = g.response_untruncated(w.x) * g.response_untruncated(w.y);
        let r = rad.response2(w);
        assert!(
            (r.re - want).abs() <= 1e-9 * h00 && r.im == 0.0,
            "ω = {w}: {} vs {want}",
            r.re
        );
        assert!((sep.response2(w).re - want).abs() <= 1e-9 * h00);
    }
    // The precomputed rule agrees with the adaptive transform.
    let rule = rad.hankel_rule(3.0);
    for i in 0..=30 {
        let rho = 0.1 * i as f64;
        assert!((rule.eval(rho) - rad.radial_response(rho)).abs() < 1e-12);
    }
}

#[test]
fn response_images_radial_gaussian_equals_separable_and_box_equals_sinc_product() {
    let size = 24;
    let omega_max = 1.5;
    let a = radial(wide_gaussian())
        .response_image(size, omega_max)
        .unwrap();
    let b = separable(wide_gaussian())
        .response_image(size, omega_max)
        .unwrap();
    assert_eq!(a.len(), size * size);
    let c = size / 2;
    assert!(
        (a[c * size + c] - 1.0).abs() < 1e-14,
        "DC pixel {}",
        a[c * size + c]
    );
    for (i, (x, y)) in a.iter().zip(&b).enumerate() {
        assert!((x - y).abs() < 1e-9, "pixel {i}: {x} vs {y}");
    }
    // Box r = ½: |H(ω)|/H(0) = |sinc(ω)|; pixel (i, j) at ω = ((i − c)Δ, (j − c)Δ), Δ = 2ω_max/size.
    let img = separable(Filter::Box(BoxFilter { radius: 0.5 }))
        .response_image(size, omega_max)
        .unwrap();
    let d = 2.0 * omega_max / size as f64;
    let sinc = |w: f64| {
        if w == 0.0 {
            1.0
        } else {
            (PI * w).sin() / (PI * w)
        }
    };
    for j in 0..size {
        for i in 0..size {
            let (wx, wy) = ((i as f64 - c as f64) * d, (j as f64 - c as f64) * d);
            let want = (sinc(wx) * sinc(wy)).abs();
            assert!((img[j * size + i] - want).abs() < 1e-14, "({i}, {j})");
        }
    }
    assert_eq!(
        separable(wide_gaussian()).response_image(1, 1.0).unwrap(),
        vec![1.0]
    );
}

#[test]
fn response_image_arguments_are_validated() {
    let f = separable(Filter::default());
    for size in [0, 4097] {
        assert!(matches!(
            f.response_image(size, 1.0),
            Err(FilterError::InvalidArgument { field: "size", .. })
        ));
    }
    for w in [0.0, -1.0, f64::NAN, f64::INFINITY, 65.0] {
        assert!(matches!(
            f.response_image(8, w),
            Err(FilterError::InvalidArgument {
                field: "omega_max",
                ..
            })
        ));
        assert!(f.metrics_with(w, &Cancel::never()).is_err());
    }
}

#[test]
fn radial_mode_is_rejected_for_odd_and_dirac_kernels() {
    for f in [
        Filter::Cosc(Cosc::default()),
        Filter::HighPass(HighPass::default()),
    ] {
        let e = Filter2D::new(f, Mode2D::Radial).unwrap_err();
        assert!(matches!(e, FilterError::RadialUnsupported { .. }), "{e}");
        assert!(e.to_string().contains("separable"));
        assert!(Filter2D::new(f, Mode2D::Separable).is_ok());
    }
    let bad = Filter::Box(BoxFilter { radius: -1.0 });
    assert!(matches!(
        Filter2D::new(bad, Mode2D::Separable),
        Err(FilterError::InvalidParam {
            field: "radius",
            ..
        })
    ));
    assert!(Mode2D::from_name("diagonal").is_err());
    assert_eq!(Mode2D::from_name("Radial"), Ok(Mode2D::Radial));
}

#[test]
fn weights_support_and_2d_integrals() {
    let b = separable(Filter::Box(BoxFilter { radius: 0.5 }));
    assert_eq!(b.support(), 0.5);
    assert_eq!(b.weight(DVec2::new(0.4, -0.4)), 1.0);
    assert_eq!(b.weight(DVec2::new(0.6, 0.0)), 0.0);
    let t = radial(Filter::Tent(Tent { radius: 1.0 }));
    assert_eq!(t.weight(DVec2::new(0.6, 0.8)), 0.0);
    assert!((t.weight(DVec2::new(0.3, 0.4)) - 0.5).abs() < 1e-15);
    assert_eq!(t.weight(DVec2::new(0.9, 0.9)), 0.0);
    // ∫∫: disk πr², cone πr²/3, separable (∫h)².
    let r: f64 = 1.3;
    assert!((radial(Filter::Box(BoxFilter { radius: r })).integral2() - PI * r * r).abs() < 1e-12);
    assert!(
        (radial(Filter::Tent(Tent { radius: r })).integral2() - PI * r * r / 3.0).abs() < 1e-12
    );
    let m = Filter::Mitchell(Mitchell::default());
    assert!((separable(m).integral2() - 1.0).abs() < 1e-15);
    // H₂(0) of a radial filter is its integral.
    let g = radial(Filter::Gaussian(Gaussian::default()));
    assert!((g.radial_response(0.0) - g.integral2()).abs() < 1e-13);
}

#[test]
fn abel_projection_and_derivative_gain_match_closed_forms() {
    use samplescope::core::filter::two_d::{abel_projection, derivative_gain};
    // Disk of radius r: m(x) = 2√(r² − x²).
    let disk = Filter::Box(BoxFilter { radius: 1.3 });
    for i in 0..=26 {
        let x = -1.3 + 0.1 * i as f64;
        let want = 2.0 * (1.3f64 * 1.3 - x * x).max(0.0).sqrt();
        assert!(
            (abel_projection(&disk, &[], x, 0.0) - want).abs() < 1e-9,
            "x = {x}"
        );
    }
    // Gaussian (negligible truncation): m(x) = σ√(2π) e^{−x²/2σ²}.
    let g = wide_gaussian();
    let breaks = g.kernel().breakpoints();
    for i in 0..=20 {
        let x = 0.15 * i as f64;
        let want = 0.5 * (2.0 * PI).sqrt() * (-x * x / 0.5).exp();
        assert!(
            (abel_projection(&g, &breaks, x, 0.0) - want).abs() < 1e-10,
            "x = {x}"
        );
    }
    // Truncated cosc at integer R: ∫x cosc = [x sinc]_{−R}^{R} − ∫sinc = −(2/π) Si(πR).
    for r in [2.0, 4.0, 9.0] {
        let f = Filter::Cosc(Cosc {
            radius: r,
            window: Window::Rect,
        });
        let want = 2.0 / PI * sine_integral(PI * r);
        assert!((derivative_gain(&f) - want).abs() < 1e-12, "R = {r}");
    }
}

#[test]
fn metrics_of_every_filter_are_finite_and_deterministic() {
    let mut all = Filter::all();
    all.extend(Filter::presets().into_iter().map(|(_, _, f)| f));
    for f in all {
        for mode in [Mode2D::Separable, Mode2D::Radial] {
            let Ok(f2) = Filter2D::new(f, mode) else {
                assert!(mode == Mode2D::Radial);
                continue;
            };
            let m = f2.metrics().unwrap();
            for v in [m.smoothing, m.post_aliasing, m.ringing, m.anisotropy] {
                assert!(v.is_finite(), "{f:?} {mode:?}: {m:?}");
            }
            assert!((0.0..=1.0).contains(&m.post_aliasing), "{m:?}");
            assert!(m.ringing >= 0.0 && m.anisotropy >= 0.0);
            assert_eq!(f2.metrics().unwrap(), m, "not deterministic");
        }
    }
}

#[test]
fn cancelled_metrics_and_images_return_cancelled() {
    let c = Cancel::new();
    c.cancel();
    let f = radial(Filter::Gaussian(Gaussian::default()));
    assert_eq!(f.metrics_with(4.0, &c), Err(FilterError::Cancelled));
    assert_eq!(
        f.response_image_with(64, 2.0, &c),
        Err(FilterError::Cancelled)
    );
}

#[test]
fn response_curves_are_normalised_and_phases_flip_at_sign_changes() {
    let f = Filter::Box(BoxFilter { radius: 0.5 });
    let curve = f.response_curve(2.0, 512).unwrap();
    assert_eq!(curve.samples.len(), 513);
    assert_eq!(curve.samples[0].magnitude, 1.0);
    // ω = 1: sinc(1) = 0; ω = 1.5: sinc < 0 → phase π.
    assert!(curve.samples[256].magnitude < 1e-15);
    assert_eq!(curve.samples[384].phase, PI);
    assert_eq!(curve.samples[100].phase, 0.0);
    // A zero-DC filter is left unnormalised; its response is imaginary (phase ±π/2).
    let c = Filter::Cosc(Cosc::default())
        .response_curve(2.0, 64)
        .unwrap();
    assert!(c.normalised_by.is_none());
    assert!(
        (c.samples[8].phase - PI / 2.0).abs() < 1e-15,
        "{:?}",
        c.samples[8]
    );
    assert!(f.response_curve(2.0, 0).is_err());
    // Radial profile of a radial Gaussian equals its 1D curve (g(|p|) separates).
    let p = radial(wide_gaussian()).response_profile(2.0, 64).unwrap();
    let q = separable(wide_gaussian())
        .response_profile(2.0, 64)
        .unwrap();
    for (a, b) in p.samples.iter().zip(&q.samples) {
        assert!((a.magnitude - b.magnitude).abs() < 1e-10);
    }
}
