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
}
