//! filter (see crate docs).
