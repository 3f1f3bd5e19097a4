//! recon (see crate docs).
