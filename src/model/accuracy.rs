//! The accuracy a node reached, as typed data: panels and figures print it (its `Display` is
//! the text under a panel) and can read its numbers (the error left, the tolerance asked).

use crate::core::recon::ReferenceMethod;

/// What a node's result is accurate to, or how far a refining node has got.
#[derive(Debug, Clone, PartialEq)]
pub enum Accuracy {
    /// Fast spectrum: measured relative ℓ² error against the exact DFT on `frequencies`
    /// frequencies, with the tolerance asked.
    SpectrumMeasured {
        relative_l2: f64,
        asked: f64,
        frequencies: usize,
    },
    /// Fast spectrum without a measured error: only the tolerance asked.
    SpectrumAsked { tolerance: f64 },
    /// Fast spectrum shown while its error is being measured (the final result then carries
    /// [`Accuracy::SpectrumMeasured`]).
    SpectrumMeasuring { asked: f64 },
    /// The exact DFT.
    ExactDft,
    /// A partial spectrum: the mean of `done` of `of` realizations (relative noise 1/√done).
    Realizations { done: usize, of: usize },
    /// Imported points have one realization although the scene asks for `asked`.
    ImportedOneRealization {
        asked: usize,
        spectrum: Box<Accuracy>,
    },
    /// A reference image whose own error is bounded by `bound`.
    ReferenceBound { bound: f64 },
    /// A reference image whose own RMS error is estimated as `rms`.
    ReferenceRms { rms: f64 },
    /// A supersampled preview at `spp` of the final `of` samples per pixel.
    Preview { spp: usize, of: usize, noise: f64 },
    /// A reconstruction where `pixels` pixels received no filter weight.
    ZeroWeightPixels { pixels: usize },
    /// A partial convergence curve: `done` of `of` spp levels.
    ConvergenceLevels { done: usize, of: usize },
    /// The 1D theorem view: errors integrated over |ω| ≤ band; the rest is bounded by `tail`.
    TheoremBand { band: f64, tail: f64 },
    /// An iterative pattern (Lloyd, SOT, GBN) part way: `done` of `of` iterations.
    Iterations { done: usize, of: usize },
    /// The projection matrix part way: `done` of `of` pairs measured.
    Pairs { done: usize, of: usize },
    /// Points read from a file, not generated (`source` names it).
    Imported { source: String },
    /// The error image against the reference: RMSE, PSNR (dB) and the share of the error's
    /// energy at frequencies up to W/8 cycles per image (white noise ≈ 4.9 %).
    Error {
        rmse: f64,
        psnr: f64,
        low_frequency: Option<f64>,
    },
}

impl Accuracy {
    /// The accuracy of a reference image computed by `method` with `error_estimate`.
    pub fn reference(method: ReferenceMethod, error_estimate: Option<f64>) -> Option<Accuracy> {
        error_estimate.map(|e| {
            if method.estimate_is_bound() {
                Accuracy::ReferenceBound { bound: e }
            } else {
                Accuracy::ReferenceRms { rms: e }
            }
        })
    }

    /// The error the result is known to have (measured or bounded), where there is one.
    pub fn error(&self) -> Option<f64> {
        match self {
            Accuracy::SpectrumMeasured { relative_l2, .. } => Some(*relative_l2),
            Accuracy::ExactDft => Some(0.0),
            Accuracy::ImportedOneRealization { spectrum, .. } => spectrum.error(),
            Accuracy::ReferenceBound { bound } => Some(*bound),
            Accuracy::ReferenceRms { rms } => Some(*rms),
            Accuracy::TheoremBand { tail, .. } => Some(*tail),
            Accuracy::Error { rmse, .. } => Some(*rmse),
            _ => None,
        }
    }
}

impl std::fmt::Display for Accuracy {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Accuracy::SpectrumMeasured {
                relative_l2,
                asked,
                frequencies,
            } => write!(
                f,
                "rel. L2 error {relative_l2:.1e} (asked {asked:.0e}, {frequencies} freq.)"
            ),
            Accuracy::SpectrumAsked { tolerance } => write!(f, "asked {tolerance:.0e}"),
            Accuracy::SpectrumMeasuring { asked } => {
                write!(f, "asked {asked:.0e}, measuring the error…")
            }
            Accuracy::ExactDft => f.write_str("exact DFT"),
            Accuracy::Realizations { done, of } => write!(
                f,
                "mean of {done} of {of} realizations, rel. noise ≈ {:.2}",
                1.0 / (*done as f64).sqrt()
            ),
            Accuracy::ImportedOneRealization { asked, spectrum } => write!(
                f,
                "imported points: one realization (K = 1, scene asks {asked}); {spectrum}"
            ),
            Accuracy::ReferenceBound { bound } => write!(f, "own error ≤ {bound:.1e}"),
            Accuracy::ReferenceRms { rms } => write!(f, "own RMS error ≈ {rms:.1e}"),
            Accuracy::Preview { spp, of, noise } => write!(
                f,
                "preview at {spp} of {of} spp: noise ≳ {noise}× the final's"
            ),
            Accuracy::ZeroWeightPixels { pixels } => write!(f, "{pixels} zero-weight pixels"),
            Accuracy::ConvergenceLevels { done, of } => write!(f, "{done} of {of} spp levels"),
            Accuracy::TheoremBand { band, tail } => {
                write!(f, "band ±{band:.3} cycles/unit, tail ≤ {tail:.1e}")
            }
            Accuracy::Iterations { done, of } => write!(f, "iteration {done} of {of}"),
            Accuracy::Pairs { done, of } => write!(f, "{done} of {of} pairs measured"),
            Accuracy::Imported { source } => write!(f, "imported from {source}"),
            Accuracy::Error {
                rmse,
                psnr,
                low_frequency,
            } => {
                write!(f, "RMSE {rmse:.4}, PSNR {psnr:.2} dB")?;
                match low_frequency {
                    Some(l) => write!(f, ", low-frequency error {:.1} %", 100.0 * l),
                    None => Ok(()),
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn texts_are_the_panel_captions() {
        let cases = [
            (
                Accuracy::SpectrumMeasured {
                    relative_l2: 3.14e-8,
                    asked: 1e-6,
                    frequencies: 512,
                },
                "rel. L2 error 3.1e-8 (asked 1e-6, 512 freq.)",
            ),
            (
                Accuracy::SpectrumMeasuring { asked: 1e-6 },
                "asked 1e-6, measuring the error…",
            ),
            (Accuracy::ExactDft, "exact DFT"),
            (
                Accuracy::Realizations { done: 4, of: 16 },
                "mean of 4 of 16 realizations, rel. noise ≈ 0.50",
            ),
            (
                Accuracy::ImportedOneRealization {
                    asked: 8,
                    spectrum: Box::new(Accuracy::ExactDft),
                },
                "imported points: one realization (K = 1, scene asks 8); exact DFT",
            ),
            (
                Accuracy::ReferenceBound { bound: 1e-14 },
                "own error ≤ 1.0e-14",
            ),
            (
                Accuracy::TheoremBand {
                    band: 32.0,
                    tail: 2.5e-9,
                },
                "band ±32.000 cycles/unit, tail ≤ 2.5e-9",
            ),
            (
                Accuracy::Iterations { done: 12, of: 50 },
                "iteration 12 of 50",
            ),
        ];
        for (a, want) in cases {
            assert_eq!(a.to_string(), want);
        }
        assert_eq!(Accuracy::ReferenceRms { rms: 0.5 }.error(), Some(0.5));
        assert_eq!(Accuracy::Realizations { done: 1, of: 2 }.error(), None);
    }
}
