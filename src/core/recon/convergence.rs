//! Convergence of supersampling: RMSE against the box-prefiltered reference as the number of
//! samples per pixel grows — the data of a log–log convergence plot.
//!
//! For jittered sampling of a signal with edges the RMSE falls like spp^(−3/4); for uniform
//! random sampling like spp^(−1/2) (Mitchell 1996, "Consequences of stratified sampling in
//! graphics"). Use a box kernel of radius ½ for the curve to converge to zero: other pixel
//! filters converge to their own filtered image, not to the box-filtered reference.

use super::reference::{reference_image_with, ReferenceMethod, ReferenceOptions};
use super::supersample::{supersample, SampleProvider};
use super::{check_size, error_report, ReconError, ReconKernel, MAX_SPP};
use crate::core::cancel::Cancel;
use crate::core::progress::{no_progress, OnProgress, Progress};
use crate::core::signal::Signal;
use std::time::Duration;

/// The default spp list of a convergence plot.
pub const DEFAULT_SPP_LIST: [usize; 5] = [1, 4, 16, 64, 256];

/// One point of a convergence curve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ConvergencePoint {
    /// Samples per pixel.
    pub spp: usize,
    /// RMSE against the reference.
    pub rmse: f64,
    /// PSNR (dB, peak 1).
    pub psnr: f64,
    /// Wall time of the supersampled image.
    pub time: Duration,
}

/// A convergence curve and what it was measured against.
#[derive(Debug, Clone, PartialEq)]
pub struct ConvergenceCurve {
    /// One point per requested spp, in the given order.
    pub points: Vec<ConvergencePoint>,
    /// How the reference was computed.
    pub reference_method: ReferenceMethod,
    /// The reference's own estimated RMS error (`None` when exact): RMSEs below it are not
    /// meaningful.
    pub reference_error: Option<f64>,
    /// Wall time of the reference.
    pub reference_time: Duration,
}

/// RMSE, PSNR and time of [`supersample`] for each spp in `spp_list`, against
/// [`reference_image_with`] (default options) of the same signal and size.
pub fn convergence_curve<K, P>(
    signal: &Signal,
    provider: &P,
    spp_list: &[usize],
    w: usize,
    kernel: &K,
    cancel: &Cancel,
) -> Result<ConvergenceCurve, ReconError>
where
    K: ReconKernel + ?Sized,
    P: SampleProvider + ?Sized,
{
    convergence_curve_progressive(
        signal,
        provider,
        spp_list,
        w,
        kernel,
        cancel,
        &mut no_progress,
    )
}

/// [`convergence_curve`], handing out the curve so far: `progress` ([`crate::core::progress`])
/// gets level k of the `spp_list.len()` levels after each, with the curve's first k points
/// (after the last level: all of them, the returned curve's). Same result, bit for bit.
pub fn convergence_curve_progressive<K, P>(
    signal: &Signal,
    provider: &P,
    spp_list: &[usize],
    w: usize,
    kernel: &K,
    cancel: &Cancel,
    progress: &mut OnProgress<'_, [ConvergencePoint]>,
) -> Result<ConvergenceCurve, ReconError>
where
    K: ReconKernel + ?Sized,
    P: SampleProvider + ?Sized,
{
    check_size("spp_list.len()", spp_list.len(), 1, 64)?;
    for &spp in spp_list {
        check_size("spp", spp, 1, MAX_SPP)?;
    }
    let reference = reference_image_with(signal, w, &ReferenceOptions::default(), cancel)?;
    let mut points = Vec::with_capacity(spp_list.len());
    for &spp in spp_list {
        let r = supersample(signal, w, spp, provider, kernel, cancel)?;
        let e = error_report(&r, &reference.pixels)?;
        points.push(ConvergencePoint {
            spp,
            rmse: e.rmse,
            psnr: e.psnr,
            time: r.wall_time,
        });
        progress(Progress::with(points.len(), spp_list.len(), &points));
    }
    Ok(ConvergenceCurve {
        points,
        reference_method: reference.method,
        reference_error: reference.error_estimate,
        reference_time: reference.wall_time,
    })
}
