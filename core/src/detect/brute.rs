//! The reference broad phase: every pair is tested. O(N²); exists so the fast
//! detectors can be checked against it.

use crate::particles::Vec3;
use crate::space::Space;

/// All pairs (i < j) whose surfaces are closer than `margin` (through the nearest
/// periodic image), in lexicographic order.
pub fn candidate_pairs(
    position: &[Vec3],
    radius: &[f64],
    margin: f64,
    space: &Space,
) -> Vec<(u32, u32)> {
    let mut pairs = Vec::new();
    for i in 0..position.len() {
        for j in i + 1..position.len() {
            let reach = radius[i] + radius[j] + margin;
            if space
                .displacement(&position[i], &position[j])
                .norm_squared()
                < reach * reach
            {
                pairs.push((i as u32, j as u32));
            }
        }
    }
    pairs
}
