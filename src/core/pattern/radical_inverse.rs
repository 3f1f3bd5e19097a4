//! Radical inverse and folded radical inverse.
