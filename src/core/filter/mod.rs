//! Reconstruction filters (placeholder while the module is written).
pub mod special;
