//! A few simple [`ReconKernel`]s for the reconstruction tests and benchmarks: independent
//! references beside the filter library.
//!
//! This is not the filter library (that is `core::filter`, which implements [`ReconKernel`] for
//! its own filters); these are the minimum needed to exercise reconstruction: box, tent and
//! Gaussian (separable), a radial cone (not separable), and the Lanczos windowed sinc of the
//! lecture's "reconstructed to 512×512 using windowed sinc". All are in filter units
//! (sample spacings or pixels) and vanish outside |dₓ|, |d_y| < support.

use glam::DVec2;
use samplescope::core::recon::ReconKernel;
use samplescope::core::signal::sinc_pi;

/// Box: h(x) = 1 for |x| < r, else 0 (the open interval the [`ReconKernel`] contract asks for;
/// with r = ½ a sample exactly halfway between two pixel centres reaches neither).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BoxKernel {
    /// Half-width r.
    pub radius: f64,
}

impl ReconKernel for BoxKernel {
    fn support(&self) -> f64 {
        self.radius
    }
    fn weight(&self, d: DVec2) -> f64 {
        self.h(d.x) * self.h(d.y)
    }
    fn factor(&self, x: f64) -> Option<f64> {
        Some(self.h(x))
    }
}

impl BoxKernel {
    #[inline]
    fn h(&self, x: f64) -> f64 {
        if x.abs() < self.radius {
            1.0
        } else {
            0.0
        }
    }
}

/// Tent (linear interpolation): h(x) = max(0, 1 − |x|/r), separable.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TentKernel {
    /// Radius r (1 = linear interpolation between samples).
    pub radius: f64,
}

impl TentKernel {
    /// Written with the reciprocal so that, inlined into a loop, the division is hoisted.
    #[inline]
    fn h(&self, x: f64) -> f64 {
        let inv = 1.0 / self.radius;
        (1.0 - x.abs() * inv).max(0.0)
    }
}

impl ReconKernel for TentKernel {
    fn support(&self) -> f64 {
        self.radius
    }
    fn weight(&self, d: DVec2) -> f64 {
        self.h(d.x) * self.h(d.y)
    }
    fn factor(&self, x: f64) -> Option<f64> {
        Some(self.h(x))
    }
}

/// Truncated Gaussian, shifted to reach 0 at the radius (as pbrt does):
/// h(x) = max(0, exp(−x²/(2σ²)) − exp(−r²/(2σ²))), separable.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GaussianKernel {
    /// Standard deviation σ.
    pub sigma: f64,
    /// Truncation radius r.
    pub radius: f64,
}

impl GaussianKernel {
    #[inline]
    fn h(&self, x: f64) -> f64 {
        if x.abs() >= self.radius {
            return 0.0;
        }
        let s2 = 2.0 * self.sigma * self.sigma;
        ((-x * x / s2).exp() - (-self.radius * self.radius / s2).exp()).max(0.0)
    }
}

impl ReconKernel for GaussianKernel {
    fn support(&self) -> f64 {
        self.radius
    }
    fn weight(&self, d: DVec2) -> f64 {
        self.h(d.x) * self.h(d.y)
    }
    fn factor(&self, x: f64) -> Option<f64> {
        Some(self.h(x))
    }
}

/// Radial cone w(d) = max(0, 1 − |d|/r): not separable (exercises the general 2D path).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ConeKernel {
    /// Radius r.
    pub radius: f64,
}

impl ReconKernel for ConeKernel {
    fn support(&self) -> f64 {
        self.radius
    }
    fn weight(&self, d: DVec2) -> f64 {
        (1.0 - d.length() / self.radius).max(0.0)
    }
}

/// Lanczos windowed sinc: h(x) = sinc(x)·sinc(x/a) for |x| < a, else 0 (sinc(x) = sin πx/(πx)),
/// separable. Its negative lobes make the total weight able to cancel.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LanczosKernel {
    /// Number of lobes a (the support radius).
    pub a: f64,
}

impl LanczosKernel {
    #[inline]
    fn h(&self, x: f64) -> f64 {
        if x.abs() >= self.a {
            0.0
        } else {
            sinc_pi(x) * sinc_pi(x / self.a)
        }
    }
}

impl ReconKernel for LanczosKernel {
    fn support(&self) -> f64 {
        self.a
    }
    fn weight(&self, d: DVec2) -> f64 {
        self.h(d.x) * self.h(d.y)
    }
    fn factor(&self, x: f64) -> Option<f64> {
        Some(self.h(x))
    }
}

/// Hides the separable factor of a kernel, forcing the general 2D path (for tests).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NonSeparable<K>(pub K);

impl<K: ReconKernel> ReconKernel for NonSeparable<K> {
    fn support(&self) -> f64 {
        self.0.support()
    }
    fn weight(&self, d: DVec2) -> f64 {
        self.0.weight(d)
    }
}
