//! spectrum (see crate docs).
