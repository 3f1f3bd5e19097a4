//! Pure computation: never imports egui, eframe or wgpu.

pub mod budget;
pub mod cancel;
pub mod cube;
pub mod family;
pub mod filter;
pub mod format;
pub mod integration;
pub mod metrics;
pub mod output;
pub mod params;
pub mod pattern;
pub mod pointset;
pub mod progress;
pub mod recon;
pub mod rng;
pub mod signal;
pub mod spectrum;
pub mod torus;
