//! # samplescope
//!
//! A desktop explorer of signals and sampling for image synthesis: sample patterns, their
//! Fourier spectra, sampling and reconstruction of test signals, reconstruction filters in
//! the spatial and the frequency domain, and discrepancy.
//!
//! This library holds the computation (`core`) and the command line's subcommands (`cli`,
//! which the Python module calls too); the binary `samplescope` parses the command line and
//! runs them, or with no subcommand the GUI.
//!
//! ## Features
//! - `gui` (default): the GUI ([`ui`]: eframe, egui, wgpu, winit). Without it
//!   (`--no-default-features`) the library and the command line build with no GUI stack, and
//!   the binary says so when asked for a window.
//! - `python`: the Python extension module `samplescope` (`src/python/`, pyo3 and NumPy),
//!   built by maturin from `pyproject.toml` without `gui`.
//!
//! ## Conventions
//!
//! - **Domain.** Points live in the unit square [0,1)², stored as `f64` ([`glam::DVec2`]).
//!   Distances and spectra are toroidal (periodic) unless a function says otherwise. `f32` is
//!   used only for display textures. Point sets in d dimensions are [`core::cube::CubePoints`]
//!   (row-major coordinates in [0,1)^d, D ≤ 1024) from `Pattern::generate_cube` or a point file
//!   of D columns ([`core::pointset::read_cube_named`]), measured by [`core::metrics::cube`];
//!   any two dimensions project to a 2D point set that every 2D analysis takes. D = 2 is always
//!   the 2D path, bit for bit.
//! - **Clamping.** Every value meant to lie in [0,1) is clamped to at most `1 − 2⁻⁵³`
//!   ([`core::pattern::ONE_MINUS_EPSILON`]), so it can never round to 1.0.
//! - **Determinism.** Every randomized generator takes an explicit `seed: u64`; the same
//!   `(parameters, seed)` gives the same bits on every run and platform (the RNG is our own
//!   xoshiro256**, [`core::rng::Rng`]). Realization `r` of an average uses
//!   [`core::rng::derive_seed`]`(seed, r)`.
//! - **Sequences** are indexed from i = 0, as in the lecture's van der Corput table
//!   (Φ₂(0) = 0, Φ₂(1) = ½, Φ₂(2) = ¼, …). Halton uses bases 2, 3, 5, …; Hammersley is
//!   (i/N, Φ_{p1}(i)) with p1 selectable (default 2). The folded radical inverse is
//!   Φ_b(n) = Σ_{i≥1} ((a_i + i − 1) mod b) b^{−i}, summed until a digit no longer changes the f64.
//! - **Periodogram** of N points: P(k) = |Σ_j exp(−2πi k·x_j)|² / N for integer frequency
//!   vectors k, shown centred (DC in the middle). White noise has E[P(k)] = 1 for k ≠ 0 and
//!   P(0) = N. Averages over K realizations are plain means of P. The radially averaged power
//!   spectrum (RAPS) uses annuli of width 1 excluding DC; anisotropy is PSA's (variance over the
//!   annulus / squared mean, in dB).
//! - **Filters.** A kernel h(x) is given in units of the sample spacing, with a radius r
//!   (h = 0 for |x| > r). 2D filters are separable h(x)h(y) or radial h(|p|). Frequencies ω
//!   are in cycles per sample: Nyquist is 0.5.
//! - **Zone plate.** z(p) = ½(1 + sin(π K |p − c|²)) on the unit square, centre c (default
//!   (½, ½)). Its local frequency at radius ρ is K·ρ cycles per unit, so a W×W grid (Nyquist W/2)
//!   aliases beyond ρ = W/(2K). The phase is evaluated in `f64` and reduced exactly.
//! - **Reconstruction** is the normalised weighted sum Σ w(p − x_j) f(x_j) / Σ w(p − x_j). For N
//!   scattered samples the filter is scaled to the mean sample spacing 1/√N; for supersampling
//!   it is scaled to the output pixel. A pixel with zero total weight is reported, never divided by zero.
//! - **Poisson-disk radius.** `radius` is the minimum toroidal distance between two points
//!   (the lecture's pseudo-code rejects d < (2 r_p)², so `radius = 2 r_p`). N points fit on the
//!   unit torus only if radius ≤ √(2/(√3 N)), the hexagonal packing distance.
//!
//! ## Evaluation
//! A scene is planned into nodes by the node table of [`scene::graph`] (keys: BLAKE3 of the
//! node's kind, algorithm version, scene fields and input keys) and evaluated by [`engine`]:
//! in parallel, cancelled per node, coarse results first for slow nodes, every completed
//! result cached (memory bounded by bytes; reference images also on disk). Which nodes a
//! scene needs follows from the panels it shows ([`scene::panels`], one rule for the graph,
//! `render` and the GUI). Results are the plain data of [`model`], which the panels and the
//! figures of [`export`] only draw. See ARCHITECTURE.md.
//!
//! ## Errors
//! Bad input never panics: every fallible routine returns a typed error (e.g.
//! [`core::pattern::PatternError`]) that names the field and the allowed range. Long work takes a
//! [`core::cancel::Cancel`] token and stops promptly when it is cancelled.

// The subcommands name the crate `samplescope::…` as the binary does.
extern crate self as samplescope;

pub mod cli;
pub mod core;
pub mod engine;
pub mod export;
pub mod model;
#[cfg(feature = "python")]
mod python;
pub mod scene;
#[cfg(feature = "gui")]
pub mod ui;
