//! The identities of the panels: what the GUI shows, `render` writes and a figure draws.

/// One panel of a column (one figure each).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum PanelKind {
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

impl PanelKind {
    /// Every kind, in the order `render` writes them.
    pub const ALL: [PanelKind; 15] = [
        PanelKind::Pattern,
        PanelKind::Sphere,
        PanelKind::Spectrum,
        PanelKind::Raps,
        PanelKind::Reconstruction,
        PanelKind::Reference,
        PanelKind::Error,
        PanelKind::Kernel,
        PanelKind::Response,
        PanelKind::Convergence,
        PanelKind::TheoremSignal,
        PanelKind::TheoremSpectrum,
        PanelKind::TheoremReconstructed,
        PanelKind::TheoremPair,
        PanelKind::Integration,
    ];

    /// The figures of the 1D sampling-theorem panel.
    pub const THEOREM: [PanelKind; 4] = [
        PanelKind::TheoremSignal,
        PanelKind::TheoremSpectrum,
        PanelKind::TheoremReconstructed,
        PanelKind::TheoremPair,
    ];

    /// The kinds a composite may hold, in its order: one per panel as the GUI first shows it
    /// (pattern, sphere, periodogram, reconstruction, kernel and response), then the theorem's
    /// signal, spectrum and reconstructed spectrum (not the transform pair).
    pub const COMPOSITE: [PanelKind; 9] = [
        PanelKind::Pattern,
        PanelKind::Sphere,
        PanelKind::Spectrum,
        PanelKind::Reconstruction,
        PanelKind::Kernel,
        PanelKind::Response,
        PanelKind::TheoremSignal,
        PanelKind::TheoremSpectrum,
        PanelKind::TheoremReconstructed,
    ];

    /// Whether this is a figure of the 1D sampling-theorem panel: its data does not depend
    /// on the column and exists for column 0 only.
    pub fn is_theorem(self) -> bool {
        PanelKind::THEOREM.contains(&self)
    }

    /// Name used in file names, menus and metadata.
    pub fn name(self) -> &'static str {
        match self {
            PanelKind::Pattern => "pattern",
            PanelKind::Sphere => "sphere",
            PanelKind::Spectrum => "spectrum",
            PanelKind::Raps => "raps",
            PanelKind::Reconstruction => "reconstruction",
            PanelKind::Reference => "reference",
            PanelKind::Error => "error",
            PanelKind::Kernel => "kernel",
            PanelKind::Response => "response",
            PanelKind::Convergence => "convergence",
            PanelKind::TheoremSignal => "theorem-signal",
            PanelKind::TheoremSpectrum => "theorem-spectrum",
            PanelKind::TheoremReconstructed => "theorem-reconstructed",
            PanelKind::TheoremPair => "theorem-pair",
            PanelKind::Integration => "integration",
        }
    }
}
