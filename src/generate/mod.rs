//! Building blocks for generating initial particle packings: radius distributions,
//! 3D ballistic deposition by steepest descent, and measurements on the result.
//! See docs/generation.md.

pub mod ballistic;
pub mod distribution;
mod grid;
pub mod measure;
