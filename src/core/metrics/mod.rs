//! metrics (see crate docs).
