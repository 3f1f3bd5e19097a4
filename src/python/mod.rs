//! The Python extension module `samplescope`.
