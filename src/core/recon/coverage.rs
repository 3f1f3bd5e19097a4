//! Exact area coverage: the box-prefiltered image of half-planes and convex polygons.
//!
//! The coverage of a pixel is the fraction of its square inside the shape. It is computed by
//! clipping the pixel square against each bounding half-plane of the shape
//! (Sutherland & Hodgman 1974, "Reentrant polygon clipping") and taking the area of the clipped
//! polygon with the shoelace formula A = ½ Σₖ (xₖ y₍ₖ₊₁₎ − x₍ₖ₊₁₎ yₖ). Both are exact up to
//! rounding (≈ 10⁻¹⁵ of the pixel area when done, as here, in pixel-local coordinates).

use glam::DVec2;

/// Clips the polygon `subject` against the half-plane {p : a·p ≥ b} (one Sutherland–Hodgman
/// stage), writing the result to `out` (cleared first). Points on the line are kept.
pub fn clip_half_plane(subject: &[DVec2], a: DVec2, b: f64, out: &mut Vec<DVec2>) {
    out.clear();
    let n = subject.len();
    if n == 0 {
        return;
    }
    for k in 0..n {
        let p = subject[k];
        let q = subject[(k + 1) % n];
        let sp = a.dot(p) - b;
        let sq = a.dot(q) - b;
        let p_in = sp >= 0.0;
        let q_in = sq >= 0.0;
        if p_in {
            out.push(p);
        }
        if p_in != q_in {
            // The edge crosses the line: sp and sq have opposite signs, so sp − sq ≠ 0.
            let t = sp / (sp - sq);
            out.push(p + (q - p) * t);
        }
    }
}

/// The signed shoelace area ½ Σ (xₖ y₍ₖ₊₁₎ − x₍ₖ₊₁₎ yₖ): positive for counter-clockwise
/// vertices (in a y-up frame).
pub fn polygon_area(poly: &[DVec2]) -> f64 {
    let n = poly.len();
    if n < 3 {
        return 0.0;
    }
    let mut s = 0.0;
    for k in 0..n {
        s += poly[k].perp_dot(poly[(k + 1) % n]);
    }
    0.5 * s
}

/// The half-planes {p : aₖ·p ≥ bₖ} whose intersection is the convex counter-clockwise polygon
/// `poly`: aₖ = perp(vₖ₊₁ − vₖ) = (−eᵧ, eₓ), bₖ = aₖ·vₖ.
pub fn half_planes(poly: &[DVec2]) -> Vec<(DVec2, f64)> {
    let n = poly.len();
    (0..n)
        .map(|k| {
            let e = poly[(k + 1) % n] - poly[k];
            let a = DVec2::new(-e.y, e.x);
            (a, a.dot(poly[k]))
        })
        .collect()
}

/// The unit square \[0,1\]² as a counter-clockwise polygon.
pub const UNIT_SQUARE: [DVec2; 4] = [
    DVec2::new(0.0, 0.0),
    DVec2::new(1.0, 0.0),
    DVec2::new(1.0, 1.0),
    DVec2::new(0.0, 1.0),
];

/// Fraction of the unit square \[0,1\]² inside the intersection of the half-planes
/// {p : aₖ·p ≥ bₖ} (exact up to rounding; in [0, 1]).
///
/// Planes that contain all four corners are skipped and a plane that excludes all four gives
/// 0 at once, so only pixels crossed by an edge are clipped.
pub fn unit_square_coverage(planes: &[(DVec2, f64)]) -> f64 {
    let mut cutting: Vec<(DVec2, f64)> = Vec::new();
    for &(n, c) in planes {
        let (lo, hi) = corner_range(n, c);
        if hi < 0.0 {
            return 0.0;
        }
        if lo < 0.0 {
            cutting.push((n, c));
        }
    }
    if cutting.is_empty() {
        return 1.0;
    }
    let mut a: Vec<DVec2> = UNIT_SQUARE.to_vec();
    let mut b: Vec<DVec2> = Vec::with_capacity(8);
    for &(n, c) in &cutting {
        clip_half_plane(&a, n, c, &mut b);
        std::mem::swap(&mut a, &mut b);
        if a.is_empty() {
            return 0.0;
        }
    }
    polygon_area(&a).clamp(0.0, 1.0)
}

/// min and max of n·q − c over the corners q of the unit square.
#[inline]
fn corner_range(n: DVec2, c: f64) -> (f64, f64) {
    let lo = n.x.min(0.0) + n.y.min(0.0) - c;
    let hi = n.x.max(0.0) + n.y.max(0.0) - c;
    (lo, hi)
}

/// Coverage of pixel (i, j) of a W×W image by the intersection of half-planes given in image
/// coordinates ({p : a·p ≥ b}, p ∈ [0,1)²).
///
/// The planes are moved to pixel-local coordinates q = p·W − (i, j), where the pixel is \[0,1\]²:
/// a·p ≥ b ⇔ a·q ≥ b·W − a·(i, j).
pub fn pixel_coverage(planes: &[(DVec2, f64)], i: usize, j: usize, w: usize) -> f64 {
    let origin = DVec2::new(i as f64, j as f64);
    let wf = w as f64;
    let local: Vec<(DVec2, f64)> = planes
        .iter()
        .map(|&(a, b)| (a, b * wf - a.dot(origin)))
        .collect();
    unit_square_coverage(&local)
}
