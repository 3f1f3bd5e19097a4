//! Integration error of sample patterns: Monte Carlo and quasi-Monte Carlo estimates of
//! integrals over [0,1]² — or [0,1]^D with Genz's integrands — whose exact values are known, and
//! how their mean squared error falls with the number of samples N.
//!
//! The estimate of I = ∫∫ f is the mean of f over the N points of a pattern. Its error depends
//! on the pattern and on f: for uniform random points MSE = Var(f)/N (slope −1 on a log–log
//! plot); jittered sampling of a function with edges gives N^(−1.5) and of a smooth function
//! N^(−2); Owen-scrambled (0,2)-sequences give N^(−1.5) on edges and N^(−3) (up to logs) on
//! smooth functions (Owen 1997; Pilleboue et al. 2015; Öztireli 2016).
//!
//! - [`integrands`]: the test integrands (disk, Gaussian, Heaviside edge, bilinear, raised
//!   cosines) with closed-form integrals and random families ([`Integrand`]).
//! - [`genz`]: Genz's six d-dimensional families (oscillatory, product peak, corner peak,
//!   Gaussian, continuous, discontinuous) with closed-form integrals on [0,1]^D, the corner
//!   peak's evaluated stably, and Genz's random instances ([`Genz`], [`GenzFamily`]).
//! - [`study`]: the study itself: estimates over many realizations for a list of N, the MSE,
//!   its standard error, variance and squared bias per N, and the log–log slope
//!   ([`run_study`], [`StudyRequest`], [`Study`]), with its cost estimate ([`estimate`]).

pub mod genz;
pub mod integrands;
pub mod study;

pub use genz::{corner_peak_integral, Genz, GenzFamily, GenzKind};
pub use integrands::{
    disk_rect_area, half_plane_square_area, Bilinear, Cosines, Disk, Gaussian, Heaviside, Integrand,
};
pub use study::{
    check_request, estimate, log_log_fit, run_study, run_study_naive, Study, StudyError,
    StudyRequest, StudyRow, StudyTimings, MAX_NS, MAX_REALIZATIONS, MAX_STUDY_N,
};
