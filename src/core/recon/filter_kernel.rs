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

    /// ∫∫h₂ / ∫∫|h₂| by the filter library's quadrature; 0 for a filter that cannot
    /// reconstruct ([`Filter2D::reconstruction_refusal`]), which the reconstruction refuses.
    fn dc_fraction(&self) -> f64 {
        if self.reconstruction_refusal().is_some() {
            return 0.0;
        }
        self.integral2() / self.abs_integral2()
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
