//! The identities of the figures: what `render` writes, the GUI's Save menus list and a
//! `Figure` draws (a panel saves one or more of them).

/// One figure of a column (a panel saves one or more).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum FigureKind {
    /// The points in the unit square.
    Pattern,
    /// The points wrapped onto the sphere (cylinder wrap, radial projection): front and back
    /// orthographic views.
    Sphere,
    /// The periodogram image (log10 P through a colour map) with a colour bar.
    Spectrum,
    /// The radially averaged power spectrum as a line plot.
    Raps,
    /// The reconstructed signal (grey, 0..1).
    Reconstruction,
    /// The reference image of the signal (grey, 0..1).
    Reference,
    /// |reconstruction − reference| (inferno, 0..max) with a colour bar.
    Error,
    /// The filter kernel h(x).
    Kernel,
    /// The filter's frequency response |H(ω)| with the Nyquist line and the ideal low-pass.
    Response,
    /// RMSE against samples per pixel (log–log).
    Convergence,
    /// The 1D sampling theorem: f(x), the samples f(nT) as stems and the reconstruction
    /// f_r(x).
    TheoremSignal,
    /// The 1D sampling theorem: |F(ω)|, the replicas F(ω − k f_s) (one colour per k), the
    /// filter's gain |G(ω)| and the Nyquist lines ±f_s/2, with a legend beside the plot.
    TheoremSpectrum,
    /// The 1D sampling theorem: the reconstructed spectrum |F_r(ω)| against |F(ω)|.
    TheoremReconstructed,
    /// The theorem panel's transform pair p(x) = g(a(x − s)) and its transform P(ω) side by
    /// side (|P|, Re P and Im P; the shah as impulses).
    TheoremPair,
    /// The integration-error study: MSE against N (log–log) of every column on one plot, with
    /// standard-error bars, fitted slopes in the legend and guide lines N⁻¹ … N⁻³ (column 0
    /// only: the plot holds all columns).
    Integration,
}

impl FigureKind {
    /// Every kind, in the order `render` writes them.
    pub const ALL: [FigureKind; 15] = [
        FigureKind::Pattern,
        FigureKind::Sphere,
        FigureKind::Spectrum,
        FigureKind::Raps,
        FigureKind::Reconstruction,
        FigureKind::Reference,
        FigureKind::Error,
        FigureKind::Kernel,
        FigureKind::Response,
        FigureKind::Convergence,
        FigureKind::TheoremSignal,
        FigureKind::TheoremSpectrum,
        FigureKind::TheoremReconstructed,
        FigureKind::TheoremPair,
        FigureKind::Integration,
    ];

    /// The figures of the 1D sampling-theorem panel.
    pub const THEOREM: [FigureKind; 4] = [
        FigureKind::TheoremSignal,
        FigureKind::TheoremSpectrum,
        FigureKind::TheoremReconstructed,
        FigureKind::TheoremPair,
    ];

    /// The kinds a composite may hold, in its order: one per panel as the GUI first shows it
    /// (pattern, sphere, periodogram, reconstruction, kernel and response), then the theorem's
    /// signal, spectrum and reconstructed spectrum (not the transform pair).
    pub const COMPOSITE: [FigureKind; 9] = [
        FigureKind::Pattern,
        FigureKind::Sphere,
        FigureKind::Spectrum,
        FigureKind::Reconstruction,
        FigureKind::Kernel,
        FigureKind::Response,
        FigureKind::TheoremSignal,
        FigureKind::TheoremSpectrum,
        FigureKind::TheoremReconstructed,
    ];

    /// Whether this is a figure of the 1D sampling-theorem panel: its data does not depend
    /// on the column and exists for column 0 only.
    pub fn is_theorem(self) -> bool {
        FigureKind::THEOREM.contains(&self)
    }

    /// Name used in file names, menus and metadata.
    pub fn name(self) -> &'static str {
        match self {
            FigureKind::Pattern => "pattern",
            FigureKind::Sphere => "sphere",
            FigureKind::Spectrum => "spectrum",
            FigureKind::Raps => "raps",
            FigureKind::Reconstruction => "reconstruction",
            FigureKind::Reference => "reference",
            FigureKind::Error => "error",
            FigureKind::Kernel => "kernel",
            FigureKind::Response => "response",
            FigureKind::Convergence => "convergence",
            FigureKind::TheoremSignal => "theorem-signal",
            FigureKind::TheoremSpectrum => "theorem-spectrum",
            FigureKind::TheoremReconstructed => "theorem-reconstructed",
            FigureKind::TheoremPair => "theorem-pair",
            FigureKind::Integration => "integration",
        }
    }
}
