//! signal (see crate docs).
