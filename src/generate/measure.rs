//! Measurements on generated packings: contacts and the solid fraction of a slab.
//!
//! Slab solid fraction: each sphere (centre height c, radius r) contributes its
//! exact volume between the planes z_lo and z_hi,
//!   V = ∫ π (r² − (z − c)²) dz over [max(z_lo, c − r), min(z_hi, c + r)],
//! with antiderivative π (r² t − t³/3), t = z − c (sum of spherical caps), so the
//! fraction has no boundary bias from spheres cut by the slab faces:
//!   φ = Σ V / (A (z_hi − z_lo)),  A the footprint area.

use super::grid::CellGrid;
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
    if positions.is_empty() {
        return Vec::new();
    }
    let r_max = radii.iter().copied().fold(0.0, f64::max);
    let reach = 2.0 * r_max * (1.0 + gap);
    let z_min = positions.iter().map(|p| p[2]).fold(f64::INFINITY, f64::min);
    let mut grid = CellGrid::new(space, reach, z_min);
    for (i, p) in positions.iter().enumerate() {
        grid.insert(p, i);
    }
    let mut out = Vec::new();
    let mut ids = Vec::new();
    for (i, p) in positions.iter().enumerate() {
        grid.near(p, reach, &mut ids);
        for &j in &ids {
            if j <= i {
                continue;
            }
            let sum = radii[i] + radii[j];
            let relative = space.displacement(p, &positions[j]).norm() / sum - 1.0;
            if relative <= gap {
                out.push((i, j, relative));
            }
        }
    }
    out.sort_by_key(|&(i, j, _)| (i, j));
    out
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

/// Volume of a sphere (centre height c, radius r) between the planes z_lo < z_hi.
pub fn sphere_volume_between(c: f64, r: f64, z_lo: f64, z_hi: f64) -> f64 {
    let lo = (z_lo - c).max(-r);
    let hi = (z_hi - c).min(r);
    if hi <= lo {
        return 0.0;
    }
    let f = |t: f64| std::f64::consts::PI * (r * r * t - t * t * t / 3.0);
    f(hi) - f(lo)
}

/// Solid fraction of the slab z_lo < z < z_hi over a footprint of the given area.
pub fn slab_solid_fraction(
    positions: &[Vec3],
    radii: &[f64],
    area: f64,
    z_lo: f64,
    z_hi: f64,
) -> f64 {
    let solid: f64 = positions
        .iter()
        .zip(radii)
        .map(|(p, r)| sphere_volume_between(p[2], *r, z_lo, z_hi))
        .sum();
    solid / (area * (z_hi - z_lo))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn caps_sum_to_the_sphere() {
        let r = 0.7;
        let whole = 4.0 / 3.0 * std::f64::consts::PI * r * r * r;
        assert!((sphere_volume_between(1.0, r, -5.0, 5.0) - whole).abs() < 1e-14);
        // Cut through the centre: two hemispheres.
        let half = sphere_volume_between(1.0, r, -5.0, 1.0);
        assert!((half - 0.5 * whole).abs() < 1e-14);
        // Cap of height h: π h² (3r − h)/3.
        let h = 0.2;
        let cap = sphere_volume_between(1.0, r, 1.0 + r - h, 9.0);
        assert!((cap - std::f64::consts::PI * h * h * (3.0 * r - h) / 3.0).abs() < 1e-14);
        assert_eq!(sphere_volume_between(1.0, r, 2.0, 3.0), 0.0);
    }

    #[test]
    fn simple_cubic_fraction_is_pi_over_six() {
        // Unit spheres (r = ½) on a cubic lattice of spacing 1: φ = π/6 in any slab
        // whose thickness is a whole number of periods, wherever it is cut.
        let (mut positions, mut radii) = (Vec::new(), Vec::new());
        for i in 0..4 {
            for j in 0..4 {
                for k in 0..10 {
                    positions.push(Vec3::new(i as f64, j as f64, k as f64));
                    radii.push(0.5);
                }
            }
        }
        let phi = slab_solid_fraction(&positions, &radii, 16.0, 2.3, 7.3);
        assert!((phi - std::f64::consts::PI / 6.0).abs() < 1e-13, "{phi}");
        let space = Space {
            periodic: [Some((-0.5, 4.0)), Some((-0.5, 4.0)), None],
        };
        let pairs = contact_pairs(&positions, &radii, &space, 1e-9);
        // Periodic in x, y: 3 bonds per sphere except the 16 missing vertical ones.
        assert_eq!(pairs.len(), 3 * 160 - 16);
    }
}
