//! Building blocks for generating initial particle packings: radius distributions
//! and 3D ballistic deposition by steepest descent. See docs/generation.md.

pub mod distribution;
