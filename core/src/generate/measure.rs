//! Checks of a generated packing that the general measures (`crate::measure`) do
//! not make: the contact pairs with their relative gaps (to see that no two spheres
//! overlap), and whether every deposited sphere was stably supported when placed.
//! Solid fractions come from `measure::packing_fraction`.

use crate::detect::cells;
use crate::particles::Vec3;
use crate::space::Space;

/// Pairs (i, j), i < j, whose centre distance is at most (rᵢ + rⱼ)(1 + gap), each
/// with its signed relative gap |xᵢ − xⱼ|/(rᵢ + rⱼ) − 1, sorted by (i, j).
pub fn contact_pairs(
    positions: &[Vec3],
    radii: &[f64],
    space: &Space,
    gap: f64,
) -> Vec<(usize, usize, f64)> {
    // |d| ≤ (rᵢ + rⱼ)(1 + gap) lies within the margin 2 r_max gap of touching.
    let r_max = radii.iter().copied().fold(0.0, f64::max);
    cells::candidate_pairs_in(
        positions,
        radii,
        2.0 * r_max * gap.max(0.0) * (1.0 + 1e-12),
        space,
    )
    .into_iter()
    .filter_map(|(i, j)| {
        let (i, j) = (i as usize, j as usize);
        let relative =
            space.displacement(&positions[i], &positions[j]).norm() / (radii[i] + radii[j]) - 1.0;
        (relative <= gap).then_some((i, j, relative))
    })
    .collect()
}

/// Spheres, in deposition order, that were not stably supported when placed:
/// neither on the floor (z − r = floor) nor with the vertical projection of the
/// centre inside (or on) the triangle of the contact points of three earlier
/// spheres. Contacts are pairs within relative gap `gap`; the triangle test allows
/// the same relative slack. An empty result is the deposition criterion of
/// `ballistic::deposit` checked from the positions alone.
pub fn unsupported(
    positions: &[Vec3],
    radii: &[f64],
    space: &Space,
    floor: f64,
    gap: f64,
) -> Vec<usize> {
    let mut earlier: Vec<Vec<usize>> = vec![Vec::new(); positions.len()];
    for (i, j, _) in contact_pairs(positions, radii, space, gap) {
        earlier[j].push(i); // i < j: i was there first
    }
    let mut out = Vec::new();
    for (j, below) in earlier.iter().enumerate() {
        let p = &positions[j];
        if (p[2] - radii[j] - floor).abs() <= gap * radii[j] {
            continue;
        }
        // Contact points relative to the centre.
        let points: Vec<Vec3> = below
            .iter()
            .map(|&i| space.displacement(&positions[i], p) * (radii[j] / (radii[i] + radii[j])))
            .collect();
        let mut stable = false;
        for a in 0..points.len() {
            for b in a + 1..points.len() {
                for c in b + 1..points.len() {
                    stable |= encloses_origin(&points[a], &points[b], &points[c], gap);
                }
            }
        }
        if !stable {
            out.push(j);
        }
    }
    out
}

/// Whether the xy triangle a, b, c contains the origin, by the signs of the three
/// sub-triangle areas (barycentric coordinates), with relative slack `gap`.
fn encloses_origin(a: &Vec3, b: &Vec3, c: &Vec3, gap: f64) -> bool {
    let cross = |u: &Vec3, v: &Vec3| u[0] * v[1] - u[1] * v[0];
    let parts = [cross(a, b), cross(b, c), cross(c, a)];
    let area: f64 = parts.iter().sum();
    area != 0.0 && parts.iter().all(|s| s * area.signum() >= -gap * area.abs())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn simple_cubic_lattice_bonds() {
        // Unit spheres (r = ½) on a cubic lattice of spacing 1: each touches six.
        let (mut positions, mut radii) = (Vec::new(), Vec::new());
        for i in 0..4 {
            for j in 0..4 {
                for k in 0..10 {
                    positions.push(Vec3::new(i as f64, j as f64, k as f64));
                    radii.push(0.5);
                }
            }
        }
        let space = Space {
            periodic: [Some((-0.5, 4.0)), Some((-0.5, 4.0)), None],
        };
        let pairs = contact_pairs(&positions, &radii, &space, 1e-9);
        // Periodic in x, y: 3 bonds per sphere except the 16 missing vertical ones.
        assert_eq!(pairs.len(), 3 * 160 - 16);
    }
}
