//! The reconstruction filters of [`crate::core::filter`] as reconstruction kernels.

use super::ReconKernel;
use crate::core::filter::{Filter2D, Mode2D};
use glam::DVec2;

impl ReconKernel for Filter2D {
    fn support(&self) -> f64 {
        Filter2D::support(self)
    }

    fn weight(&self, d: DVec2) -> f64 {
        Filter2D::weight(self, d)
    }

    /// Separable filters splat with 2(2r+1) factor evaluations per sample.
    fn factor(&self, x: f64) -> Option<f64> {
        match self.mode {
            Mode2D::Separable => Some(self.filter.eval(x)),
            Mode2D::Radial => None,
        }
    }

    /// The 1D filter's [`crate::core::filter::Kernel::eval_many`] (the Gaussian's
    /// one-exponential form, within `EVAL_MANY_ABS_ERROR` of `eval`); zeros when radial.
    fn factors(&self, xs: &mut [f64]) {
        match self.mode {
            Mode2D::Separable => self.filter.kernel().eval_many(xs),
            Mode2D::Radial => xs.fill(0.0),
        }
    }

    /// ∫∫h₂ / ∫∫|h₂| by the filter library's quadrature; 0 for a filter that cannot
    /// reconstruct ([`Filter2D::reconstruction_refusal`]), which the reconstruction refuses.
    fn dc_fraction(&self) -> f64 {
        if self.reconstruction_refusal().is_some() {
            return 0.0;
        }
        self.integral2() / self.abs_integral2()
    }
}

/// A filter whose splat evaluates each separable factor on its own through
/// [`crate::core::filter::Kernel::eval`] (the trait's default [`ReconKernel::factors`]), not
/// through the filter's faster `eval_many`: the exact splat that the fast factors are tested
/// and benchmarked against.
#[derive(Debug, Clone, Copy)]
pub struct ExactFactors(pub Filter2D);

impl ReconKernel for ExactFactors {
    fn support(&self) -> f64 {
        ReconKernel::support(&self.0)
    }
    fn weight(&self, d: DVec2) -> f64 {
        ReconKernel::weight(&self.0, d)
    }
    fn factor(&self, x: f64) -> Option<f64> {
        self.0.factor(x)
    }
    fn dc_fraction(&self) -> f64 {
        self.0.dc_fraction()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::filter::Filter;

    #[test]
    fn separable_factor_agrees_with_the_2d_weight() {
        let f = Filter2D::separable(Filter::default());
        for &(x, y) in &[(0.0, 0.0), (0.3, -1.2), (1.9, 0.5), (2.5, 0.0)] {
            let w = ReconKernel::weight(&f, DVec2::new(x, y));
            let p = f.factor(x).unwrap() * f.factor(y).unwrap();
            assert!((w - p).abs() <= 1e-15, "{x} {y}: {w} vs {p}");
        }
        assert!(Filter2D::radial(Filter::default()).factor(0.1).is_none());
    }

    /// The default scene's reconstruction (4096 random samples of a chirp onto 512², the
    /// Gaussian σ = ½, r = 2 with its edge subtracted) with the Gaussian's one-exponential
    /// factors against the exact splat: each weight moves by at most δ = EVAL_MANY_ABS_ERROR
    /// (4.4·10⁻¹⁶) times a factor ≤ 1, so a pixel Σw·v/Σw moves by at most 2δ·Σ|v|/Σw ≈ 2δ ×
    /// the ≈ 16 samples in reach / Σw (≥ 0.3 here): held to 10⁻¹³. The tent (no fast form)
    /// and a Gaussian with σ ≳ r (the exact form kept) give the same bits.
    #[test]
    fn fast_factors_reconstruct_within_their_bound_of_the_exact_splat() {
        use crate::core::cancel::Cancel;
        use crate::core::recon::reconstruct_scattered;
        let mut rng = crate::core::rng::Rng::new(1);
        let pts: Vec<DVec2> = (0..4096)
            .map(|_| DVec2::new(rng.next_f64(), rng.next_f64()))
            .collect();
        let vals: Vec<f64> = pts
            .iter()
            .map(|p| (std::f64::consts::PI * 64.0 * p.length_squared()).cos())
            .collect();
        let run = |k: &dyn ReconKernel| {
            reconstruct_scattered(&pts, &vals, 512, k, &Cancel::never())
                .expect("reconstructs")
                .pixels
        };
        let gauss = |sigma: f64| {
            Filter2D::separable(Filter::Gaussian(crate::core::filter::Gaussian {
                sigma,
                radius: 2.0,
                subtract_edge: true,
            }))
        };
        let (fast, exact) = (run(&gauss(0.5)), run(&ExactFactors(gauss(0.5))));
        let worst = fast
            .iter()
            .zip(&exact)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        assert!(worst <= 1e-13, "{worst}");
        assert!(worst > 0.0, "the fast form was not used");
        for f in [
            gauss(3.0),
            Filter2D::separable(Filter::from_name("tent").unwrap()),
        ] {
            let (a, b) = (run(&f), run(&ExactFactors(f)));
            assert!(a.iter().zip(&b).all(|(x, y)| x.to_bits() == y.to_bits()));
        }
    }

    #[test]
    fn dc_fraction_is_the_ratio_of_the_integrals() {
        // Catmull–Rom: ∫h = 1, each negative lobe −1/24, so ∫|h| = 7/6 and ρ = (6/7)².
        let cr = Filter2D::separable(Filter::from_name("catmull-rom").unwrap());
        assert!(
            (cr.dc_fraction() - 36.0 / 49.0).abs() < 1e-9,
            "{}",
            cr.dc_fraction()
        );
        // The trait's default midpoint rule agrees with the library's quadrature.
        struct Plain(Filter2D);
        impl ReconKernel for Plain {
            fn support(&self) -> f64 {
                ReconKernel::support(&self.0)
            }
            fn weight(&self, d: DVec2) -> f64 {
                ReconKernel::weight(&self.0, d)
            }
        }
        for f in [
            cr,
            Filter2D::separable(Filter::from_name("lanczos").unwrap()),
        ] {
            let (a, b) = (f.dc_fraction(), Plain(f).dc_fraction());
            assert!((a - b).abs() < 1e-3, "{a} vs {b}");
        }
        let gauss = Filter2D::separable(Filter::from_name("gaussian").unwrap());
        assert!((gauss.dc_fraction() - 1.0).abs() < 1e-12);
        // Band-pass and cosc cannot reconstruct, nor a radial sinc cut at radius 4
        // (2π∫₀⁴ sinc(s) s ds = 2(1 − cos 4π)/π = 0).
        for f in [
            Filter2D::separable(Filter::from_name("band-pass").unwrap()),
            Filter2D::separable(Filter::from_name("cosc").unwrap()),
            Filter2D::separable(Filter::from_name("high-pass").unwrap()),
            Filter2D::radial(Filter::from_name("sinc").unwrap()),
        ] {
            assert_eq!(f.dc_fraction(), 0.0, "{f:?}");
            assert!(f.reconstruction_refusal().is_some(), "{f:?}");
        }
    }
}
