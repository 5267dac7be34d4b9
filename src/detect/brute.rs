//! The reference broad phase: every pair is tested. O(N²); exists so the fast
//! detectors can be checked against it.

use crate::particles::Vec3;

/// All pairs (i < j) whose surfaces are closer than `margin`, in lexicographic order.
pub fn candidate_pairs(position: &[Vec3], radius: &[f64], margin: f64) -> Vec<(u32, u32)> {
    let mut pairs = Vec::new();
    for i in 0..position.len() {
        for j in i + 1..position.len() {
            let reach = radius[i] + radius[j] + margin;
            if (position[i] - position[j]).norm_squared() < reach * reach {
                pairs.push((i as u32, j as u32));
            }
        }
    }
    pairs
}
