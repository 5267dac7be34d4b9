//! The screening of contacts through a third particle (Zunker et al. 2025; LAMMPS's
//! `FixGranularMDR::calculate_contact_penalty`). When particles i, j, k overlap
//! pairwise, the contact across the longest of the three centre distances passes
//! through the third particle, the "central" one; it is given the penalty
//!   p += 1/(1 + e^{−50(α/π − 1/2)}),
//! with α the angle at the central particle between the directions to the other two,
//! and its force is weighed by w = max(1 − p, 0). A contact seen nearly straight
//! through the centre (α → π) loses its force; one at a right angle keeps half.

use crate::particles::Vec3;
use std::f64::consts::PI;

/// The penalty one triplet adds to the contact opposite the angle `alpha` (rad).
pub fn screening(alpha: f64) -> f64 {
    1.0 / (1.0 + (-50.0 * (alpha / PI - 0.5)).exp())
}

/// The weight of a contact with penalty `p`.
pub fn weight(p: f64) -> f64 {
    (1.0 - p).max(0.0)
}

/// One step's screening over a neighbour list `pairs` (sorted, i < j): every triplet of
/// pairwise overlapping particles i < j < k whose partners j and k both follow i in the
/// list (LAMMPS's serial half list, seen from its first particle), in the list's order.
/// `add(c, p)` adds the penalty p to pair c of the list, the contact opposite the
/// central particle (across the longest of the three centre distances).
/// `separation(a, b)` is x_b − x_a (the nearest image), `radius` the particles' radii.
pub fn screen(
    pairs: &[(u32, u32)],
    separation: impl Fn(usize, usize) -> Vec3,
    radius: &[f64],
    mut add: impl FnMut(usize, f64),
) {
    let between = |a: usize, b: usize| {
        let d = separation(a, b);
        let dist = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
        (d, dist, 1.0 / dist, radius[a] + radius[b] - dist)
    };
    let dot = |a: Vec3, b: Vec3| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let index = |a: usize, b: usize| {
        let key = (a.min(b) as u32, a.max(b) as u32);
        pairs.binary_search(&key).ok()
    };
    for (first, i) in pairs
        .chunk_by(|x, y| x.0 == y.0)
        .map(|run| (run, run[0].0 as usize))
    {
        for (jj, &(_, j)) in first.iter().enumerate() {
            let j = j as usize;
            let (d_ij, r_ij, inv_ij, o_ij) = between(i, j);
            if o_ij < 0.0 {
                continue;
            }
            for &(_, k) in &first[jj + 1..] {
                let k = k as usize;
                let (d_ik, r_ik, inv_ik, o_ik) = between(i, k);
                if o_ik < 0.0 {
                    continue;
                }
                let (d_jk, r_jk, inv_jk, o_jk) = between(j, k);
                if o_jk < 0.0 {
                    continue;
                }
                let r_max = r_ij.max(r_ik.max(r_jk));
                let (alpha, (a, b)) = if r_ij == r_max {
                    (dot(-(d_ik * inv_ik), -(d_jk * inv_jk)).acos(), (i, j))
                } else if r_ik == r_max {
                    (dot(-(d_ij * inv_ij), d_jk * inv_jk).acos(), (i, k))
                } else {
                    (dot(d_ij * inv_ij, d_ik * inv_ik).acos(), (j, k))
                };
                if let Some(c) = index(a, b) {
                    add(c, screening(alpha));
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn straight_through_loses_the_force() {
        assert!((screening(PI / 2.0) - 0.5).abs() < 1e-15);
        assert!(weight(screening(PI)) < 1e-10);
        assert!(weight(screening(PI / 3.0)) > 0.9997);
    }
}
