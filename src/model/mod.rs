//! The plain data that views draw: images, point sets, spectra, curves, the per-node data
//! structs the compute graph fills, the identities of the figures ([`FigureKind`]), a column's
//! data as the panels and figures read it ([`ColumnData`]: each node's [`Slot`], its data
//! with its [`NodeStatus`], or its error), the plain figure context ([`FigureContext`]),
//! what one publication of a scene's figures draws ([`Publication`]),
//! and the shared display vocabulary (the one [`Colormap`] with its CPU colorizer, the
//! [`palette`], the dB conversion, the elementary-interval grid).
//!
//! Everything here is plain data or a pure function of it: `model` depends on [`crate::core`],
//! `glam`, `serde` and `colorous` only, never on the scene, the engine, egui or plotters
//! ([`FigureKind`] is expanded from the panel list, `scene::panels::panel_list!`, a macro that
//! carries only names).
//! The compute graph ([`crate::scene`]) fills these structs; the panels ([`crate::ui`]) and the
//! figures ([`crate::export`]) only read them.

mod accuracy;
mod colormap;
mod column;
mod context;
mod figure_kind;
mod filter;
mod image;
mod integration;
pub mod marks;
mod matrix;
pub mod palette;
mod points;
mod publication;
mod recon;
mod slot;
mod spectrum;

pub use accuracy::Accuracy;
pub use colormap::{colorize, Colormap};
pub use column::{ColumnData, InColumn};
pub use context::{sanitize, FigureContext, IMPORTED};
pub use figure_kind::FigureKind;
pub use filter::{amplitude_db, ResponseData, ResponseMetrics, DB_FLOOR};
pub use image::{next_version, ImageData};
pub use integration::{
    guide_line, IntegrationCurve, IntegrationData, IntegrationPlot, GUIDE_SLOPES,
};
pub use matrix::{coverage, MatrixAxis, MatrixCell, MatrixData, MATRIX_CELL, MATRIX_GAP};
pub use points::{
    drawn_strata, elementary_grid, PointsData, PsaData, SequenceData, StatsData, MAX_STRATA_LINES,
    STATS_PSA_MAX_N,
};
pub use publication::Publication;
pub use recon::{ConvergencePoint, ErrorData, ReconData, ReferenceData};
pub use slot::{NodeRow, NodeStatus, Slot};
pub use spectrum::{shared_spectrum_range, SpectrumData, SHARED_DECADES};

/// PSA's radial distribution function and the (0,k,2)-net check of power-of-two prefixes:
/// plain data computed by [`crate::core::metrics`].
pub use crate::core::metrics::{NetPrefixes, Rdf};
/// The 1D sampling-theorem view: plain data computed by [`crate::core::signal::theorem`].
pub use crate::core::signal::theorem::TheoremView;
