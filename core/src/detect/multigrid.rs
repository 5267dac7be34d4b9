//! Multigrid broad phase after He, Dong & Zhou 2007 (Phys. Rev. E 75, 036710): one
//! grid level per particle size class, each particle stored only in the level whose
//! cell edge matches its own size, so no level has cells much larger than its
//! particles and the cost stays O(N) whatever the size ratio.
//!
//! Size classes. With `s = 2r + margin` (the reach of a particle paired with one of
//! its own size) and `s_min` the smallest, class `k` holds the particles with
//! `s_min·2^(k−1) < s ≤ s_min·2^k`: cell edges double from one class to the next.
//! Only occupied classes get a level, so a bidisperse mix has two levels whatever
//! its size ratio. A level's cell edge is the largest `s` in it, the linked-cell
//! edge for that class alone.
//!
//! Search. A particle looks for partners in its own level and in every coarser
//! level, in the cells overlapping the cube of half-width `r + R_level + margin`
//! around it — at most 3 per axis, since a coarse cell edge exceeds
//! `r_small + R_big + margin` (`grid.rs` gives the details and the periodic wrap).
//! Searching the other way, from a big particle down into a fine level, would visit
//! about `(R_big/r_small)³` mostly empty fine cells per big particle. Each
//! cross-level pair is therefore found once, by its smaller member; same-level pairs
//! as in linked cells. Per particle the work is at most 27 cells times the number of
//! occupied levels from its own up — at most about log₂ of the size ratio — and in
//! a dense packing each coarse cell holds O(1) particles of its level.

use super::grid::{self, Level, MAX_CELLS, counting_sort};
use crate::particles::Vec3;
use crate::space::Space;

/// Classes beyond this are merged into the coarsest one, bounding the number of
/// levels for absurd size ratios (2^40); merging only costs speed, never pairs.
const MAX_CLASS: usize = 40;

/// All pairs (i < j) whose surfaces are closer than `margin` through the nearest
/// periodic image, in lexicographic order. Radii and margin must be ≥ 0.
pub fn candidate_pairs(
    position: &[Vec3],
    radius: &[f64],
    margin: f64,
    space: &Space,
) -> Vec<(u32, u32)> {
    if position.len() < 2 {
        return Vec::new();
    }
    let size: Vec<f64> = radius.iter().map(|r| 2.0 * r + margin).collect();
    let s_max = size.iter().cloned().fold(0.0, f64::max);
    if s_max <= 0.0 {
        // Zero reach everywhere: |d|² < 0 never holds.
        return Vec::new();
    }
    let s_min = size.iter().cloned().fold(f64::INFINITY, f64::min);
    let base = s_min.max(s_max * 0.5f64.powi(MAX_CLASS as i32));
    let class: Vec<usize> = size
        .iter()
        .map(|&s| {
            if s <= base {
                0
            } else {
                ((s / base).log2().ceil() as usize).min(MAX_CLASS)
            }
        })
        .collect();

    // Sorting the particle ids by class gives each level's members in id order.
    let (start, member) = counting_sort(&class, MAX_CLASS + 1);
    let mut class_size = [0.0f64; MAX_CLASS + 1];
    for (&k, &s) in class.iter().zip(&size) {
        class_size[k] = class_size[k].max(s);
    }

    let occupied: Vec<usize> = (0..=MAX_CLASS)
        .filter(|&k| start[k + 1] > start[k])
        .collect();
    // The memory cap is shared between levels; coarse levels need few cells anyway.
    let max_cells = MAX_CELLS / occupied.len();
    let levels: Vec<Level> = occupied
        .iter()
        .map(|&k| {
            Level::build(
                &member[start[k]..start[k + 1]],
                position,
                radius,
                class_size[k],
                space,
                max_cells,
            )
        })
        .collect();
    grid::pairs(&levels, margin, space)
}
