//! Declarative scenes (RON files) and the compute graph they drive.
//!
//! A scene says what is shown: the columns (one sample pattern each, with its seed), the
//! shared settings (N, signal, filter, reconstruction, spectrum), the visible panels and the
//! effects that are on. The [`graph`] turns a scene into the list of nodes that the visible
//! panels need; nothing else is computed.

pub mod animation;
mod builtin;
pub mod compute;
pub mod cost;
mod error;
pub mod figure;
pub mod graph;
pub mod import;
pub mod integration;
pub mod limits;
mod load;
pub mod motion;
pub mod node;
pub mod panels;
pub mod ron_path;
mod settings;
mod validate;

pub use animation::{Animates, AnimationSettings};
pub use builtin::BUILTIN;
pub use error::{Location, SceneError};
pub use limits::{MAX_COLUMNS, MAX_ELEMENTARY_K, MAX_SCENE_N};
pub use load::{MAX_SCENE_BYTES, RON_NESTING};
pub use panels::Panels;
pub use settings::{
    Column, Effects, MatrixSettings, PixelSampling, ReconMode, ReconSettings, Scene,
    SpectrumSettings, DEFAULT_DIMS, DEFAULT_GRID, DEFAULT_PROJECT, DEFAULT_SPP, MATRIX_MAX_DIMS,
};

pub use import::ImportedPoints;
pub use integration::IntegrationSettings;
pub use motion::Motion;
