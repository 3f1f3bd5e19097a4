//! Test integrands on [0,1]² with exact integrals, and their random families.
//!
//! | integrand | f(x, y) | ∫∫ f over [0,1]² | random instance ([`Integrand::randomized`]) |
//! |---|---|---|---|
//! | `disk` | 1 where (x−cx)² + (y−cy)² ≤ r² | area of the disk ∩ square ([`disk_rect_area`]) | cx, cy ~ U[0.2, 0.8], r ~ U[0.1, 0.4] |
//! | `gaussian` | exp(−‖x − c‖²/(2σ²)) | Π_axis σ√(π/2)·(erf((1−c)/(σ√2)) + erf(c/(σ√2))) | cx, cy ~ U[0, 1], σ ~ U[0.05, 0.3] |
//! | `heaviside` | 1 where n·(x − p) ≥ 0, n = (cos θ, sin θ) | area of the half-plane ∩ square ([`half_plane_square_area`]) | px, py ~ U[0, 1], θ ~ U[0°, 360°) |
//! | `bilinear` | x·y | 1/4 | no parameters: the instance itself |
//! | `cosines` | ½(1 + cos 2πax)·½(1 + cos 2πby) | ¼(1 + sinc 2a)(1 + sinc 2b), sinc t = sin πt/(πt) | a, b ~ U[0.5, 8] |
//!
//! The random families follow the integrand databases of UTK (Bonneel et al. 2019): each
//! realization of a study integrates a new instance, so that the error measures a sampler on
//! the family rather than on one lucky placement of an edge. A random instance draws its
//! parameters from [`Rng::next_f64`] in the order of the table's column (x before y).
//!
//! Every parameter set is a [`declare_params!`] struct, so `--integrand-set key=value` goes
//! through [`Params::set`] with its checks, and [`Integrand`] dispatches over them
//! ([`family!`](crate::core::family::family)) like [`crate::core::pattern::Pattern`] does.
//!
//! The family also holds Genz's six d-dimensional integrands ([`super::genz`]: `genz-…`);
//! [`Integrand::genz`] gives their parameters, [`Integrand::is_planar`] tells the five 2D
//! integrands apart. On [0,1]² ([`Integrand::eval`], [`Integrand::integral`]) a Genz
//! integrand is its D = 2 instance.

use super::genz::{
    Genz, GenzContinuous, GenzCornerPeak, GenzDiscontinuous, GenzFamily, GenzGaussian, GenzKind,
    GenzOscillatory, GenzProductPeak,
};
use crate::core::family::family;
use crate::core::filter::special::{cos_pi, erf, erfc, sin_pi, sinc};
use crate::core::params::{declare_params, ParamError};
use crate::core::rng::Rng;
use glam::DVec2;

use std::f64::consts::PI;

declare_params! {
    /// The indicator of a disk, cut by the square's edges.
    Disk = "disk", "indicator of the disk (x−cx)² + (y−cy)² ≤ r²; its integral is the area of the disk cut by the square's edges" {
        cx: float(0.5, -1.0, 2.0, "centre x (the disk may reach over the square's edges)"),
        cy: float(0.5, -1.0, 2.0, "centre y"),
        r: positive(0.3, 2.0, "radius"),
    }
}
declare_params! {
    /// An isotropic Gaussian bump.
    Gaussian = "gaussian", "Gaussian bump exp(−|x−c|²/(2σ²)), integrated over the square by erf" {
        cx: float(0.5, -1.0, 2.0, "centre x"),
        cy: float(0.5, -1.0, 2.0, "centre y"),
        sigma: positive(0.15, 10.0, "standard deviation σ"),
    }
}
declare_params! {
    /// The indicator of a half-plane through p with normal angle θ.
    Heaviside = "heaviside", "indicator of the half-plane n·(x − p) ≥ 0, n = (cos θ, sin θ): a straight edge through p" {
        px: float(0.5, -1.0, 2.0, "x of a point p on the edge"),
        py: float(0.5, -1.0, 2.0, "y of a point p on the edge"),
        theta: float(30.0, 0.0, 360.0, "angle of the normal n in degrees (0 = the side x ≥ px)"),
    }
}
declare_params! {
    /// The product x·y.
    Bilinear = "bilinear", "bilinear x·y (smooth, integral 1/4)" {}
}
declare_params! {
    /// A smooth separable product of raised cosines.
    Cosines = "cosines", "raised cosines ½(1 + cos 2πax)·½(1 + cos 2πby) (smooth, periodic for integer a, b)" {
        a: float(2.25, 0.0, 256.0, "frequency a along x (cycles per unit)"),
        b: float(1.75, 0.0, 256.0, "frequency b along y (cycles per unit)"),
    }
}

family! {
    /// Every integrand, as a small parameter struct per variant (`kind` in serde forms).
    Integrand = "integrand", "integrands" {
        Disk(Disk) = "disk",
        Gaussian(Gaussian) = "gaussian",
        Heaviside(Heaviside) = "heaviside",
        Bilinear(Bilinear) = "bilinear",
        Cosines(Cosines) = "cosines",
        GenzOscillatory(GenzOscillatory) = "genz-oscillatory",
        GenzProductPeak(GenzProductPeak) = "genz-product-peak",
        GenzCornerPeak(GenzCornerPeak) = "genz-corner-peak",
        GenzGaussian(GenzGaussian) = "genz-gaussian",
        GenzContinuous(GenzContinuous) = "genz-continuous",
        GenzDiscontinuous(GenzDiscontinuous) = "genz-discontinuous",
    }
}

impl Default for Integrand {
    fn default() -> Self {
        Integrand::Disk(Disk::default())
    }
}

impl Integrand {
    /// f(p). Any finite p is allowed (the study only asks inside [0,1)²). A Genz integrand is
    /// its D = 2 instance (NaN when it has none: a list of another length than 1 or 2).
    pub fn eval(&self, p: DVec2) -> f64 {
        Prepared::new(self).map_or(f64::NAN, |f| f.eval(p))
    }

    /// A Genz integrand's family and parameters; `None` for the 2D integrands.
    pub fn genz(&self) -> Option<GenzFamily> {
        match self {
            Integrand::GenzOscillatory(g) => Some(g.family()),
            Integrand::GenzProductPeak(g) => Some(g.family()),
            Integrand::GenzCornerPeak(g) => Some(g.family()),
            Integrand::GenzGaussian(g) => Some(g.family()),
            Integrand::GenzContinuous(g) => Some(g.family()),
            Integrand::GenzDiscontinuous(g) => Some(g.family()),
            Integrand::Disk(_)
            | Integrand::Gaussian(_)
            | Integrand::Heaviside(_)
            | Integrand::Bilinear(_)
            | Integrand::Cosines(_) => None,
        }
    }

    /// The integrand of a Genz family's parameters.
    pub fn from_genz(f: &GenzFamily) -> Integrand {
        match f.kind {
            GenzKind::Oscillatory => Integrand::GenzOscillatory(GenzOscillatory {
                a: f.a,
                u: f.u.as_slice()[0],
            }),
            GenzKind::ProductPeak => Integrand::GenzProductPeak(GenzProductPeak { a: f.a, u: f.u }),
            GenzKind::CornerPeak => Integrand::GenzCornerPeak(GenzCornerPeak { a: f.a }),
            GenzKind::Gaussian => Integrand::GenzGaussian(GenzGaussian { a: f.a, u: f.u }),
            GenzKind::Continuous => Integrand::GenzContinuous(GenzContinuous { a: f.a, u: f.u }),
            GenzKind::Discontinuous => {
                Integrand::GenzDiscontinuous(GenzDiscontinuous { a: f.a, u: f.u })
            }
        }
    }

    /// Whether f is one of the 2D integrands (defined on [0,1]² only); the Genz integrands are
    /// defined in any dimension.
    pub fn is_planar(&self) -> bool {
        self.genz().is_none()
    }

    /// A Genz integrand made ready for `dims` dimensions ([`Genz::new`]: its lists' lengths
    /// and range checked, errors naming the field); `None` for the 2D integrands.
    pub fn in_dims(&self, dims: usize) -> Option<Result<Genz, ParamError>> {
        self.genz().map(|f| Genz::new(&f, dims))
    }

    /// The exact integral of f over [0,1]² (closed forms of the module table; a Genz
    /// integrand's D = 2 instance, NaN when it has none).
    pub fn integral(&self) -> f64 {
        let genz = |f: GenzFamily| Genz::new(&f, 2).map_or(f64::NAN, |g| g.integral());
        match self {
            Integrand::Disk(d) => {
                disk_rect_area(DVec2::new(d.cx, d.cy), d.r, DVec2::ZERO, DVec2::ONE)
            }
            Integrand::Gaussian(g) => gaussian_axis(g.cx, g.sigma) * gaussian_axis(g.cy, g.sigma),
            Integrand::Heaviside(h) => {
                half_plane_square_area(DVec2::new(h.px, h.py), normal(h.theta))
            }
            Integrand::Bilinear(_) => 0.25,
            Integrand::Cosines(c) => 0.25 * (1.0 + sinc(2.0 * c.a)) * (1.0 + sinc(2.0 * c.b)),
            Integrand::GenzOscillatory(g) => genz(g.family()),
            Integrand::GenzProductPeak(g) => genz(g.family()),
            Integrand::GenzCornerPeak(g) => genz(g.family()),
            Integrand::GenzGaussian(g) => genz(g.family()),
            Integrand::GenzContinuous(g) => genz(g.family()),
            Integrand::GenzDiscontinuous(g) => genz(g.family()),
        }
    }

    /// A new random instance of the same family, drawn from `rng` with the distributions of
    /// the module table (the integrand's own parameters are not used; `bilinear` has none and
    /// returns itself). A Genz integrand draws its D = 2 instance ([`Integrand::randomized_in`]).
    pub fn randomized(&self, rng: &mut Rng) -> Integrand {
        self.randomized_in(2, rng)
    }

    /// As [`Integrand::randomized`], a Genz integrand drawn in `dims` dimensions as Genz's test
    /// driver does ([`GenzFamily::randomized`]: u uniform, a normalised to Genz's difficulty);
    /// the 2D integrands ignore `dims`.
    pub fn randomized_in(&self, dims: usize, rng: &mut Rng) -> Integrand {
        if let Some(f) = self.genz() {
            return Integrand::from_genz(&GenzFamily::randomized(f.kind, dims, rng));
        }
        let mut u = |lo: f64, hi: f64| lo + (hi - lo) * rng.next_f64();
        match self {
            Integrand::Disk(_) => {
                let cx = u(0.2, 0.8);
                let cy = u(0.2, 0.8);
                let r = u(0.1, 0.4);
                Integrand::Disk(Disk { cx, cy, r })
            }
            Integrand::Gaussian(_) => {
                let cx = u(0.0, 1.0);
                let cy = u(0.0, 1.0);
                let sigma = u(0.05, 0.3);
                Integrand::Gaussian(Gaussian { cx, cy, sigma })
            }
            Integrand::Heaviside(_) => {
                let px = u(0.0, 1.0);
                let py = u(0.0, 1.0);
                let theta = u(0.0, 360.0);
                Integrand::Heaviside(Heaviside { px, py, theta })
            }
            Integrand::Bilinear(b) => Integrand::Bilinear(*b),
            Integrand::Cosines(_) => {
                let a = u(0.5, 8.0);
                let b = u(0.5, 8.0);
                Integrand::Cosines(Cosines { a, b })
            }
            genz => *genz,
        }
    }
}

/// The unit normal (cos θ, sin θ) of an angle in degrees, exact at multiples of 90°.
fn normal(theta_degrees: f64) -> DVec2 {
    let t = theta_degrees / 180.0;
    DVec2::new(cos_pi(t), sin_pi(t))
}

/// An integrand with its constants computed once, for the hot loop of a study.
/// [`Integrand::eval`] goes through it, so both give the same bits.
#[derive(Debug, Clone)]
pub(crate) enum Prepared {
    Disk {
        c: DVec2,
        r2: f64,
    },
    Gaussian {
        c: DVec2,
        k: f64,
    },
    Heaviside {
        p: DVec2,
        n: DVec2,
    },
    Bilinear,
    Cosines {
        a2: f64,
        b2: f64,
    },
    /// A Genz integrand's D = 2 instance.
    Genz(Genz),
}

impl Prepared {
    /// The integrand ready for [0,1]²; a Genz integrand without a D = 2 instance is the
    /// error of [`Genz::new`].
    pub(crate) fn new(integrand: &Integrand) -> Result<Self, ParamError> {
        let genz = |f: GenzFamily| Genz::new(&f, 2).map(Prepared::Genz);
        Ok(match integrand {
            Integrand::Disk(d) => Prepared::Disk {
                c: DVec2::new(d.cx, d.cy),
                r2: d.r * d.r,
            },
            Integrand::Gaussian(g) => Prepared::Gaussian {
                c: DVec2::new(g.cx, g.cy),
                k: 1.0 / (2.0 * g.sigma * g.sigma),
            },
            Integrand::Heaviside(h) => Prepared::Heaviside {
                p: DVec2::new(h.px, h.py),
                n: normal(h.theta),
            },
            Integrand::Bilinear(_) => Prepared::Bilinear,
            Integrand::Cosines(c) => Prepared::Cosines {
                a2: 2.0 * c.a,
                b2: 2.0 * c.b,
            },
            Integrand::GenzOscillatory(g) => genz(g.family())?,
            Integrand::GenzProductPeak(g) => genz(g.family())?,
            Integrand::GenzCornerPeak(g) => genz(g.family())?,
            Integrand::GenzGaussian(g) => genz(g.family())?,
            Integrand::GenzContinuous(g) => genz(g.family())?,
            Integrand::GenzDiscontinuous(g) => genz(g.family())?,
        })
    }

    #[inline]
    pub(crate) fn eval(&self, q: DVec2) -> f64 {
        match *self {
            Prepared::Disk { c, r2 } => {
                let (dx, dy) = (q.x - c.x, q.y - c.y);
                if dx * dx + dy * dy <= r2 {
                    1.0
                } else {
                    0.0
                }
            }
            Prepared::Gaussian { c, k } => {
                let (dx, dy) = (q.x - c.x, q.y - c.y);
                (-(dx * dx + dy * dy) * k).exp()
            }
            Prepared::Heaviside { p, n } => {
                if n.x * (q.x - p.x) + n.y * (q.y - p.y) >= 0.0 {
                    1.0
                } else {
                    0.0
                }
            }
            Prepared::Bilinear => q.x * q.y,
            Prepared::Cosines { a2, b2 } => {
                0.25 * (1.0 + cos_pi(a2 * q.x)) * (1.0 + cos_pi(b2 * q.y))
            }
            Prepared::Genz(ref g) => g.eval(&[q.x, q.y]),
        }
    }
}

/// erf(b) − erf(a) for a ≤ b without cancellation in the tails (through erfc there).
fn erf_difference(a: f64, b: f64) -> f64 {
    if a >= 0.0 {
        erfc(a) - erfc(b)
    } else if b <= 0.0 {
        erfc(-b) - erfc(-a)
    } else {
        erf(b) - erf(a)
    }
}

/// ∫₀¹ exp(−(x−c)²/(2σ²)) dx = σ√(π/2)·(erf((1−c)/(σ√2)) − erf(−c/(σ√2))).
fn gaussian_axis(c: f64, sigma: f64) -> f64 {
    let s = sigma * std::f64::consts::SQRT_2;
    sigma * (PI / 2.0).sqrt() * erf_difference(-c / s, (1.0 - c) / s)
}

/// The area of the disk of centre `c` and radius `r` inside the rectangle [lo, hi], in closed
/// form.
///
/// In coordinates centred on the disk, with h(x) = √(r² − x²), the area is
/// ∫ max(0, min(b₁, h) − max(b₀, −h)) dx over x ∈ [a₀, a₁] ∩ [−r, r]. The integrand changes
/// form only where h(x) = |b₀| or |b₁| (the rectangle's horizontal edges meet the circle); on
/// each piece between those points it is α·h(x) + β with α ∈ {0, 1, 2}, whose integral is
/// α·(H(v) − H(u)) + β·(v − u), H(x) = ½(x·h(x) + r²·asin(x/r)): the circular segments of the
/// edges, with their overlaps at the corners. Degenerate inputs (r ≤ 0, an empty rectangle)
/// give 0.
pub fn disk_rect_area(c: DVec2, r: f64, lo: DVec2, hi: DVec2) -> f64 {
    if r.is_nan() || r <= 0.0 {
        return 0.0;
    }
    let a0 = (lo.x - c.x).max(-r);
    let a1 = (hi.x - c.x).min(r);
    let (b0, b1) = (lo.y - c.y, hi.y - c.y);
    if a1.is_nan() || a0.is_nan() || a1 <= a0 || b1.is_nan() || b0.is_nan() || b1 <= b0 {
        return 0.0;
    }
    let r2 = r * r;
    let h = |x: f64| (r2 - x * x).max(0.0).sqrt();
    let primitive = |x: f64| 0.5 * (x * h(x) + r2 * (x / r).clamp(-1.0, 1.0).asin());
    let mut xs = [a0, a1, a1, a1, a1, a1];
    let mut len = 2;
    for b in [b0, b1] {
        if b.abs() < r {
            let s = (r2 - b * b).sqrt();
            for x in [-s, s] {
                if x > a0 && x < a1 {
                    xs[len] = x;
                    len += 1;
                }
            }
        }
    }
    let xs = &mut xs[..len];
    xs.sort_by(f64::total_cmp);
    let mut area = 0.0;
    for w in xs.windows(2) {
        let (u, v) = (w[0], w[1]);
        if v <= u {
            continue;
        }
        let hm = h(0.5 * (u + v));
        // Top: min(b1, h); bottom: max(b0, −h). Each is h (α = 1) or its edge (β).
        let (top_alpha, top_beta, top) = if hm <= b1 {
            (1.0, 0.0, hm)
        } else {
            (0.0, b1, b1)
        };
        let (bottom_alpha, bottom_beta, bottom) = if -hm >= b0 {
            (1.0, 0.0, -hm)
        } else {
            (0.0, -b0, b0)
        };
        if top - bottom <= 0.0 {
            continue;
        }
        let alpha = top_alpha + bottom_alpha;
        let beta = top_beta + bottom_beta;
        area += alpha * (primitive(v) - primitive(u)) + beta * (v - u);
    }
    area.max(0.0)
}

/// The area of the half-plane {x : n·(x − p) ≥ 0} inside [0,1]²: the unit square clipped by
/// the plane (one Sutherland–Hodgman step), then the shoelace formula. `n` need not be unit;
/// n = 0 keeps the whole square.
pub fn half_plane_square_area(p: DVec2, n: DVec2) -> f64 {
    let square = [
        DVec2::new(0.0, 0.0),
        DVec2::new(1.0, 0.0),
        DVec2::new(1.0, 1.0),
        DVec2::new(0.0, 1.0),
    ];
    let side = |q: DVec2| n.x * (q.x - p.x) + n.y * (q.y - p.y);
    // A convex quadrilateral cut by a line has at most 5 vertices.
    let mut poly = [DVec2::ZERO; 8];
    let mut len = 0;
    for i in 0..4 {
        let (a, b) = (square[i], square[(i + 1) % 4]);
        let (da, db) = (side(a), side(b));
        if da >= 0.0 {
            poly[len] = a;
            len += 1;
        }
        if (da >= 0.0) != (db >= 0.0) {
            let t = da / (da - db);
            poly[len] = a + (b - a) * t;
            len += 1;
        }
    }
    let poly = &poly[..len];
    let mut twice = 0.0;
    for i in 0..len {
        let (a, b) = (poly[i], poly[(i + 1) % len]);
        twice += a.x * b.y - b.x * a.y;
    }
    (0.5 * twice).clamp(0.0, 1.0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::filter::quad::adaptive;
    use crate::core::params::Params;

    /// ∫₀¹ g over breakpoints where g is smooth: adaptive Gauss–Legendre, relative 1e−14.
    fn integrate_1d(g: &mut dyn FnMut(f64) -> f64, breaks: &[f64]) -> f64 {
        let mut b: Vec<f64> = breaks
            .iter()
            .copied()
            .filter(|x| (0.0..=1.0).contains(x))
            .chain([0.0, 1.0])
            .collect();
        b.sort_by(f64::total_cmp);
        b.dedup();
        adaptive(&mut |x| g(x), &b, 0.05, 1e-14, 1e-300).value
    }

    /// The disk's area by quadrature of its chord length inside the square: for each x the
    /// y-extent of the disk clamped to [0,1], integrated by adaptive Gauss–Legendre with
    /// breakpoints where the chord or its clamping has a kink.
    fn disk_quadrature(cx: f64, cy: f64, r: f64) -> f64 {
        let mut chord = |x: f64| {
            let d = r * r - (x - cx) * (x - cx);
            if d <= 0.0 {
                return 0.0;
            }
            let s = d.sqrt();
            ((cy + s).min(1.0) - (cy - s).max(0.0)).max(0.0)
        };
        let mut breaks = vec![cx - r, cx + r];
        for yb in [0.0, 1.0] {
            let d = r * r - (yb - cy) * (yb - cy);
            if d > 0.0 {
                breaks.extend([cx - d.sqrt(), cx + d.sqrt()]);
            }
        }
        integrate_1d(&mut chord, &breaks)
    }

    #[test]
    fn disk_area_matches_quadrature_for_centres_near_and_outside_the_edges() {
        // Inside, touching, over one edge, over a corner, centre outside, covering the square,
        // tangent cases and a disk that misses the square: |closed form − quadrature| ≤ 1e−12.
        let cases = [
            (0.5, 0.5, 0.3),
            (0.5, 0.5, 0.5),
            (0.1, 0.5, 0.3),
            (0.05, 0.93, 0.2),
            (-0.1, 0.4, 0.35),
            (1.2, -0.15, 0.4),
            (0.5, 0.5, 0.8),
            (0.5, 0.5, 1.5),
            (0.3, 0.0, 0.3),
            (0.0, 0.0, 1.0),
            (1.0, 1.0, 0.25),
            (1.5, 0.5, 0.4),
            (-0.2, 1.3, 0.5),
        ];
        for (cx, cy, r) in cases {
            let d = Integrand::Disk(Disk { cx, cy, r });
            let exact = d.integral();
            let quad = disk_quadrature(cx, cy, r);
            assert!(
                (exact - quad).abs() <= 1e-12,
                "disk ({cx}, {cy}, {r}): closed form {exact}, quadrature {quad}"
            );
        }
        // Known values: the whole disk, a half and a quarter, and the square itself.
        let area = |cx, cy, r| Integrand::Disk(Disk { cx, cy, r }).integral();
        assert!((area(0.5, 0.5, 0.3) - PI * 0.09).abs() < 1e-15);
        assert!((area(0.0, 0.5, 0.3) - PI * 0.09 / 2.0).abs() < 1e-15);
        assert!((area(1.0, 1.0, 0.3) - PI * 0.09 / 4.0).abs() < 1e-15);
        assert!((area(0.5, 0.5, 0.75) - 1.0).abs() < 1e-15);
        assert_eq!(area(1.5, 0.5, 0.4), 0.0);
        // A general rectangle: its quarter-disk corner.
        let q = disk_rect_area(DVec2::ZERO, 1.0, DVec2::ZERO, DVec2::splat(2.0));
        assert!((q - PI / 4.0).abs() < 1e-15);
    }

    #[test]
    fn disk_area_agrees_with_a_midpoint_count() {
        // 2048² cell centres counted inside the disk: for a curved edge the lattice count is
        // off by O(perimeter·h^{3/2}) ≈ 1e−5 at h = 1/2048 (Gauss circle problem); the
        // square's edges are cell boundaries. Tolerance 3e−5.
        let m = 2048;
        for (cx, cy, r) in [(0.13, 0.71, 0.31), (1.07, 0.52, 0.27)] {
            let mut count = 0u64;
            for j in 0..m {
                let y = (j as f64 + 0.5) / m as f64;
                for i in 0..m {
                    let x = (i as f64 + 0.5) / m as f64;
                    if (x - cx) * (x - cx) + (y - cy) * (y - cy) <= r * r {
                        count += 1;
                    }
                }
            }
            let mid = count as f64 / (m * m) as f64;
            let exact = Integrand::Disk(Disk { cx, cy, r }).integral();
            assert!(
                (mid - exact).abs() < 3e-5,
                "{cx},{cy},{r}: {mid} vs {exact}"
            );
        }
    }

    /// ∫∫ f by a 2D tensor product of the adaptive 1D rule (f smooth).
    fn smooth_quadrature(f: &Integrand) -> f64 {
        integrate_1d(
            &mut |x| integrate_1d(&mut |y| f.eval(DVec2::new(x, y)), &[]),
            &[],
        )
    }

    #[test]
    fn smooth_integrals_match_quadrature() {
        // Gaussians inside, near an edge, centred outside, narrow and wide; bilinear; cosines
        // at integer and non-integer frequencies: |closed form − quadrature| ≤ 1e−12.
        let cases = [
            Integrand::Gaussian(Gaussian::default()),
            Integrand::Gaussian(Gaussian {
                cx: 0.05,
                cy: 0.9,
                sigma: 0.1,
            }),
            Integrand::Gaussian(Gaussian {
                cx: -0.3,
                cy: 1.4,
                sigma: 0.2,
            }),
            Integrand::Gaussian(Gaussian {
                cx: 0.3,
                cy: 0.6,
                sigma: 0.03,
            }),
            Integrand::Gaussian(Gaussian {
                cx: 0.5,
                cy: 0.2,
                sigma: 3.0,
            }),
            Integrand::Bilinear(Bilinear::default()),
            Integrand::Cosines(Cosines::default()),
            Integrand::Cosines(Cosines { a: 3.0, b: 0.0 }),
            Integrand::Cosines(Cosines { a: 0.3, b: 7.7 }),
        ];
        for f in cases {
            let exact = f.integral();
            let quad = smooth_quadrature(&f);
            assert!(
                (exact - quad).abs() <= 1e-12,
                "{f:?}: closed form {exact}, quadrature {quad}"
            );
        }
        // The far tail: centre 1.5 outside, σ = 0.05 (10σ away): relative accuracy kept.
        let far = Integrand::Gaussian(Gaussian {
            cx: 1.5,
            cy: 0.5,
            sigma: 0.05,
        });
        let quad = smooth_quadrature(&far);
        assert!(quad > 0.0 && (far.integral() / quad - 1.0).abs() < 1e-9);
    }

    /// The half-plane's area by quadrature in x of the clamped y-extent: piecewise linear with
    /// kinks where the edge crosses y = 0 and y = 1 (a step at px for a vertical edge).
    fn heaviside_quadrature(px: f64, py: f64, theta: f64) -> f64 {
        let n = normal(theta);
        let mut extent = |x: f64| {
            // {y ∈ [0,1] : n.x (x − px) + n.y (y − py) ≥ 0}.
            let c = n.x * (x - px);
            if n.y == 0.0 {
                return if c >= 0.0 { 1.0 } else { 0.0 };
            }
            let y0 = py - c / n.y;
            if n.y > 0.0 {
                1.0 - y0.clamp(0.0, 1.0)
            } else {
                y0.clamp(0.0, 1.0)
            }
        };
        let mut breaks = vec![px];
        if n.x != 0.0 {
            for yb in [0.0, 1.0] {
                breaks.push(px - n.y * (yb - py) / n.x);
            }
        }
        integrate_1d(&mut extent, &breaks)
    }

    #[test]
    fn heaviside_area_matches_quadrature() {
        // Axis-aligned, diagonal through corners, general angles, edges missing the square:
        // |clipped polygon − quadrature| ≤ 1e−13.
        let cases = [
            (0.5, 0.5, 30.0),
            (0.3, 0.6, 0.0),
            (0.3, 0.6, 90.0),
            (0.3, 0.6, 180.0),
            (0.3, 0.6, 270.0),
            (0.0, 0.0, 45.0),
            (0.0, 1.0, 315.0),
            (0.2, 0.9, 117.0),
            (0.8, 0.1, 233.5),
            (-0.5, 0.5, 10.0),
            (1.7, 1.2, 200.0),
            (0.5, 0.5, 360.0),
        ];
        for (px, py, theta) in cases {
            let f = Integrand::Heaviside(Heaviside { px, py, theta });
            let exact = f.integral();
            let quad = heaviside_quadrature(px, py, theta);
            assert!(
                (exact - quad).abs() <= 1e-13,
                "heaviside ({px}, {py}, {theta}°): polygon {exact}, quadrature {quad}"
            );
        }
        let area = |px, py, theta| Integrand::Heaviside(Heaviside { px, py, theta }).integral();
        assert_eq!(area(0.3, 0.6, 0.0), 0.7);
        assert!((area(0.0, 0.0, 135.0) - 0.5).abs() < 1e-15);
        assert_eq!(area(-0.5, 0.5, 0.0), 1.0);
        assert_eq!(area(-0.5, 0.5, 180.0), 0.0);
    }

    #[test]
    fn eval_follows_the_definitions() {
        let d = Integrand::Disk(Disk::default());
        assert_eq!(d.eval(DVec2::new(0.5, 0.5)), 1.0);
        assert_eq!(d.eval(DVec2::new(0.5, 0.79)), 1.0);
        assert_eq!(d.eval(DVec2::new(0.5, 0.5 - 0.25)), 1.0); // 0.25² ≤ 0.3²
        assert_eq!(d.eval(DVec2::new(0.81, 0.5)), 0.0);
        let g = Integrand::Gaussian(Gaussian::default());
        let q = DVec2::new(0.6, 0.3);
        let want = (-((0.1f64).powi(2) + (0.2f64).powi(2)) / (2.0 * 0.15 * 0.15)).exp();
        assert!((g.eval(q) - want).abs() < 1e-15);
        let h = Integrand::Heaviside(Heaviside {
            px: 0.5,
            py: 0.5,
            theta: 90.0,
        });
        assert_eq!(h.eval(DVec2::new(0.1, 0.5)), 1.0); // on the edge
        assert_eq!(h.eval(DVec2::new(0.1, 0.49)), 0.0);
        assert_eq!(Integrand::Bilinear(Bilinear {}).eval(q), 0.6 * 0.3);
        let c = Integrand::Cosines(Cosines { a: 1.0, b: 2.0 });
        let want = 0.25 * (1.0 + (2.0 * PI * 0.6).cos()) * (1.0 + (4.0 * PI * 0.3).cos());
        assert!((c.eval(q) - want).abs() < 1e-15);
    }

    #[test]
    fn names_parameters_and_random_instances() {
        for f in Integrand::all() {
            assert_eq!(Integrand::from_name(f.name()).unwrap(), f);
            f.check_params().unwrap();
        }
        let err = Integrand::from_name("nosuch").unwrap_err().to_string();
        assert_eq!(
            err,
            "unknown integrand 'nosuch': allowed integrands are disk, gaussian, heaviside, bilinear, \
             cosines, genz-oscillatory, genz-product-peak, genz-corner-peak, genz-gaussian, \
             genz-continuous, genz-discontinuous"
        );
        let mut d = Integrand::from_name("Disk").unwrap();
        d.set("r", "0.1").unwrap();
        assert_eq!(
            d,
            Integrand::Disk(Disk {
                r: 0.1,
                ..Disk::default()
            })
        );
        let e = d.set("r", "0").unwrap_err().to_string();
        assert_eq!(e, "disk.r = 0: must be a finite number in (0, 2]");
        // Random instances stay inside their documented ranges and are valid sets.
        let mut rng = Rng::new(5);
        for f in Integrand::all() {
            for _ in 0..200 {
                let g = f.randomized(&mut rng);
                assert_eq!(g.name(), f.name());
                g.check_params().unwrap();
                match g {
                    Integrand::Disk(d) => assert!(
                        (0.2..0.8).contains(&d.cx)
                            && (0.2..0.8).contains(&d.cy)
                            && (0.1..0.4).contains(&d.r)
                    ),
                    Integrand::Gaussian(g) => assert!((0.05..0.3).contains(&g.sigma)),
                    Integrand::Heaviside(h) => assert!((0.0..360.0).contains(&h.theta)),
                    Integrand::Bilinear(_) => {}
                    Integrand::Cosines(c) => {
                        assert!((0.5..8.0).contains(&c.a) && (0.5..8.0).contains(&c.b))
                    }
                    // Drawn in D = 2 (the genz module tests Genz's normalisation in every D).
                    genz => {
                        let f = genz.genz().unwrap();
                        assert_eq!(f.a.as_slice().len(), 2);
                        assert!(genz.integral().is_finite());
                    }
                }
            }
        }
        // Serde form: tagged by kind, as scene files write patterns.
        let text = ron::to_string(&Integrand::Disk(Disk::default())).unwrap();
        let back: Integrand = ron::from_str(&text).unwrap();
        assert_eq!(back, Integrand::Disk(Disk::default()));
    }
}
