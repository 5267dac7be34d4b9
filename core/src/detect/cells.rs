//! Linked-cell broad phase: particles are binned into cubic cells of edge
//! ≥ 2 R_max + margin, so each particle's partners lie in its own or the 26
//! neighbouring cells (wrapping round periodic axes) — in fact in those of them
//! within r + R_max + margin, fewer than 27 for a small particle. O(N) for narrow size
//! distributions; for wide ones the cell size is set by the largest particle and the
//! cost grows with the size ratio (the multigrid detector of He, Dong & Zhou 2007,
//! `multigrid.rs`, removes that dependence). The grid itself is `grid.rs` with a
//! single level.

use super::grid::{self, Level, MAX_CELLS};
use crate::particles::Vec3;
use crate::space::Space;

/// All pairs (i < j) whose surfaces are closer than `margin` through the nearest
/// periodic image, in lexicographic order. Positions along a periodic axis are read
/// modulo the period, so they need not be wrapped.
pub fn candidate_pairs_in(
    position: &[Vec3],
    radius: &[f64],
    margin: f64,
    space: &Space,
) -> Vec<(u32, u32)> {
    if position.len() < 2 {
        return Vec::new();
    }
    let r_max = radius.iter().cloned().fold(0.0, f64::max);
    let everyone: Vec<u32> = (0..position.len() as u32).collect();
    let level = Level::build(
        &everyone,
        position,
        radius,
        2.0 * r_max + margin,
        space,
        MAX_CELLS,
    );
    grid::pairs(&[level], margin, space)
}
