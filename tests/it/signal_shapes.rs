//! Checkerboard projection, grating phase against exact integer arithmetic, and the 1D signals'
//! Nyquist behaviour.

use glam::DVec2;
use samplescope::core::rng::Rng;
use samplescope::core::signal::{
    cos_pi, sin_pi, Checkerboard, Chirp, Grating, Polygon, Signal, StepEdge,
};

#[test]
fn checkerboard_projects_ground_points_like_a_pinhole() {
    // A ground point (X, Y) is seen at u = X/Y, v = height/Y (focal length 1); ground_checks
    // must return it rotated by tilt and scaled by checks.
    let c = Checkerboard {
        checks: 3.0,
        height: 1.7,
        horizon: 0.3,
        tilt: 35.0,
    };
    let mut rng = Rng::new(4);
    let (s, co) = (sin_pi(35.0 / 180.0), cos_pi(35.0 / 180.0));
    for _ in 0..1000 {
        let big_y = 2.5 + 40.0 * rng.next_f64();
        let big_x = (rng.next_f64() - 0.5) * big_y; // keep |u| < ½
        let p = DVec2::new(0.5 + big_x / big_y, c.horizon + c.height / big_y);
        let g = c.ground_checks(p).expect("below the horizon");
        let want = DVec2::new(
            3.0 * (big_x * co + big_y * s),
            3.0 * (-big_x * s + big_y * co),
        );
        assert!((g - want).length() < 1e-11 * want.length(), "{g} vs {want}");
    }
}

#[test]
fn checkerboard_row_alternates_at_predicted_boundaries() {
    // tilt 0, checks 2, height 1, horizon 0.2, row y = 0.65: v = 0.45, Y = 1/0.45, so
    // s·X = 2u/0.45 and the checks change colour every Δu = 0.225; sample mid-check.
    let c = Checkerboard {
        checks: 2.0,
        height: 1.0,
        horizon: 0.2,
        tilt: 0.0,
    };
    let y = 0.65;
    let row_parity = ((2.0f64 / 0.45).floor() as i64).rem_euclid(2);
    for k in -2i64..2 {
        let u = (k as f64 + 0.5) * 0.225;
        let v = c.eval(DVec2::new(0.5 + u, y));
        let parity = (k + row_parity).rem_euclid(2);
        assert_eq!(v, if parity == 0 { 1.0 } else { 0.0 }, "k = {k}");
    }
}

#[test]
fn checkerboard_far_field_and_sky_are_the_mean() {
    let c = Checkerboard::default();
    // One ulp below the horizon the ground is ~10^16 checks away: beyond 2^40 → ½.
    let y = c.horizon + f64::EPSILON;
    assert_eq!(c.eval(DVec2::new(0.3, y)), Checkerboard::SKY);
    assert_eq!(c.eval(DVec2::new(0.3, 0.0)), Checkerboard::SKY);
}

#[test]
fn grating_phase_exact_against_integer_arithmetic() {
    // angle 0, integer f, x = i/W with W = 2^12: phase/π = 2 f i / W mod 2 exactly.
    let w: u64 = 4096;
    let mut rng = Rng::new(8);
    for f in [3u64, 1000, 999_983] {
        let g = Signal::Grating(Grating {
            frequency: f as f64,
            angle: 0.0,
            phase: 0.0,
        });
        let mut worst: f64 = 0.0;
        for _ in 0..5000 {
            let i = rng.below(w);
            let r = (2 * f as u128 * i as u128) % (2 * w as u128);
            let t = r as f64 / w as f64;
            let truth = 0.5 * (1.0 + (std::f64::consts::PI * t).sin());
            let got = g.eval(DVec2::new(i as f64 / w as f64, rng.next_f64()));
            worst = worst.max((got - truth).abs());
        }
        assert!(worst < 1e-13, "f = {f}: {worst:e}");
    }
}

#[test]
fn grating_axis_angles_are_exact() {
    // angle 90: varies along y only; quarter period gives exactly 1.
    let g = Grating {
        frequency: 4.0,
        angle: 90.0,
        phase: 0.0,
    };
    assert_eq!(g.eval(DVec2::new(0.3, 1.0 / 16.0)), 1.0);
    assert_eq!(g.eval(DVec2::new(0.9, 1.0 / 16.0)), 1.0);
    assert_eq!(g.eval(DVec2::new(0.9, 3.0 / 16.0)), 0.0);
}

#[test]
fn step_edge_and_polygon_sides() {
    let s = StepEdge {
        angle: 0.0,
        offset: 0.1,
    };
    assert_eq!(s.eval(DVec2::new(0.61, 0.2)), 1.0);
    assert_eq!(s.eval(DVec2::new(0.59, 0.2)), 0.0);
    let p = Polygon::default();
    assert_eq!(p.eval(DVec2::splat(0.5)), 1.0);
    assert_eq!(p.eval(DVec2::new(0.02, 0.02)), 0.0);
    // Every vertex lies on the polygon (boundary included).
    for v in p.vertices() {
        let inward = (DVec2::splat(0.5) - v) * 1e-9;
        assert_eq!(p.eval(v + inward), 1.0);
    }
}

#[test]
fn chirp_instantaneous_frequency_from_zero_crossings() {
    // Zero crossings of sin(2π(f0 x + (f1−f0)x²/2)) are ½ cycle apart: around x the spacing is
    // 1/(2·f(x)). Count crossings in [0.45, 0.55] and compare with ∫ 2 f(x) dx.
    let c = Chirp {
        f0: 10.0,
        f1: 200.0,
    };
    let n = 200_000;
    let (a, b) = (0.45, 0.55);
    let mut crossings = 0;
    let mut prev = c.eval1(a) - 0.5;
    for k in 1..=n {
        let v = c.eval1(a + (b - a) * k as f64 / n as f64) - 0.5;
        if (v > 0.0) != (prev > 0.0) {
            crossings += 1;
        }
        prev = v;
    }
    let expected = 2.0 * (c.f0 * (b - a) + (c.f1 - c.f0) * (b * b - a * a) / 2.0);
    assert!(
        (crossings as f64 - expected).abs() <= 1.0,
        "{crossings} vs {expected}"
    );
    assert_eq!(c.frequency_at(0.5), 105.0);
}
