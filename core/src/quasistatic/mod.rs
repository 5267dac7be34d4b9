//! The 2D quasi-static network model of Redanz & Fleck (2001): circular cylinders of
//! unit depth whose contacts flatten plastically, compacted by prescribing a
//! macroscopic strain and solving for static equilibrium increment by increment.
//!
//! This is a second, independent way of computing compaction next to the explicit 3D
//! DEM of `simulation`: no masses, no time step, an implicit network solve. It shares
//! nothing with the explicit loop (docs/architecture.md).

pub mod affine_yield;
pub mod compaction;
pub mod network;
pub mod packing;
pub mod yield_probe;

pub use packing::{CylinderPacking, Vec2};
