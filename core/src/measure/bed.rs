//! Bulk packing fraction of a settled, laterally periodic bed: all the solid over
//! the volume of the bed, φ_bulk = Σ_i V_i / (A H), with A the periodic cell's area
//! and H the height of the bed's free surface above the floor.
//!
//! Why a bulk measure: in a mixture whose small spheres can pass through the gaps
//! between the large ones (size ratio 10: the gap in a triangle of touching large
//! spheres has radius (2/√3 − 1) R_b = 0.155 R_b > R_s), the small spheres drain to
//! the bottom while the bed settles. A region in the interior then sees a
//! composition that depends on where it is, and only the whole bed has the nominal
//! composition whose packing fraction Zhong et al. 2009 §6.1 (Fig 4) report.
//!
//! The surface. A bed of spheres has no sharp top: the solid fraction falls to
//! zero over about one large diameter, and near the floor and the top it is layered.
//! H is placed as a Gibbs dividing surface against the bed just beneath the top:
//! with z_top the highest top of a sphere that touches another one or the floor (a
//! sphere ejected from the bed, still in flight when the run ends, is not the bed's
//! top: it touches nothing), d the largest diameter and z_ref = z_top − 2d,
//! φ_ref is the solid fraction of the slab [z_ref − d, z_ref] (one diameter thick,
//! which averages the layering out) and
//!
//!   H = z_ref + V(solid above z_ref) / (A φ_ref),
//!
//! the height at which the solid above z_ref, packed at φ_ref, would end flat. A
//! bed that settles into a different composition at its top (a layer of excess
//! small spheres, or large ones the small ones drained out of) is judged against
//! its own top layer. The bed must be at least 3d deep.
//!
//! The interior fraction. The floor orders the spheres next to it into a looser
//! layer about one large diameter thick, and the top diameter is loose too. The
//! interior fraction is the solid fraction of the slab [floor + d, floor + H − d],
//! away from both, as the Scott case measures; a bed at least 3d deep leaves it at
//! least about one diameter thick.
//!
//! Each slab's solid is exact: Σ_i V(ball_i ∩ slab) from spherical caps
//! (`Region::Slab`), every particle counted once per periodic cell.

use crate::error::{Result, TampError};
use crate::measure::packing::lateral_cell_area;
use crate::measure::region::{Region, ball_volume};
use crate::particles::Vec3;
use crate::space::Space;

/// Packing measures of a settled bed: its surface height H and its bulk, surface-layer
/// and interior solid fractions φ.
#[derive(Clone, Debug, PartialEq)]
pub struct Bed {
    /// Height of the free surface above the floor (H).
    pub height: f64,
    /// φ_ref: solid fraction of the one-diameter slab beneath the top layer.
    pub surface_fraction: f64,
    /// Σ V_i / (A H).
    pub bulk_fraction: f64,
    /// Solid fraction of the slab from one largest diameter above the floor to one
    /// below the surface.
    pub interior_fraction: f64,
}

/// The bed resting on the floor `x_axis = floor`, periodic along the two other axes.
pub fn bulk_packing_fraction(
    positions: &[Vec3],
    radii: &[f64],
    space: &Space,
    axis: usize,
    floor: f64,
) -> Result<Bed> {
    if positions.len() != radii.len() || positions.is_empty() {
        return Err(TampError::input(
            "radii",
            format!(
                "one radius per position and at least one particle expected, got {} radii for {} positions",
                radii.len(),
                positions.len()
            ),
        ));
    }
    let area = lateral_cell_area(space, axis).map_err(|k| {
        TampError::input(
            "space",
            format!(
                "a bed's bulk fraction needs axis {k} periodic (the bed's area is its periodic cell)"
            ),
        )
    })?;
    let d = 2.0 * radii.iter().cloned().fold(0.0, f64::max);
    // Touching within a relative 1e-9, so that an exact stack counts as in contact.
    let touching = crate::detect::cells::candidate_pairs_in(positions, radii, 1e-9 * d, space);
    let on_floor =
        (0..positions.len()).filter(|&i| positions[i][axis] - radii[i] <= floor + 1e-9 * d);
    let top = touching
        .iter()
        .flat_map(|&(i, j)| [i as usize, j as usize])
        .chain(on_floor)
        .map(|i| positions[i][axis] + radii[i])
        .fold(f64::NEG_INFINITY, f64::max);
    if !top.is_finite() {
        return Err(TampError::input(
            "positions",
            "no sphere touches another or the floor: there is no bed to measure",
        ));
    }
    let z_ref = top - 2.0 * d;
    if z_ref - d < floor {
        return Err(TampError::input(
            "positions",
            format!(
                "the bed is {:.3e} deep, less than the 3 largest diameters ({:.3e}) its surface is judged over",
                top - floor,
                3.0 * d
            ),
        ));
    }
    let solid_in = |lo: f64, hi: f64| -> f64 {
        let slab = Region::Slab { axis, lo, hi };
        positions
            .iter()
            .zip(radii)
            .map(|(c, &r)| slab.intersection_volume(c, r))
            .sum()
    };
    let reference = solid_in(z_ref - d, z_ref) / (area * d);
    let above = solid_in(z_ref, top);
    let height = z_ref + above / (area * reference) - floor;
    let volume: f64 = radii.iter().map(|&r| ball_volume(r)).sum();
    let (lo, hi) = (floor + d, floor + height - d);
    Ok(Bed {
        height,
        surface_fraction: reference,
        bulk_fraction: volume / (area * height),
        interior_fraction: solid_in(lo, hi) / (area * (hi - lo)),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A simple cubic stack, n layers of spheres of radius R on a lateral period of
    /// 2R: the slab beneath the top layer, one period thick, holds exactly π/6, and
    /// the two top layers packed at π/6 end flat at the top of the stack, 2nR.
    #[test]
    fn simple_cubic_stack_ends_at_its_top() {
        let r = 1.0;
        let n = 8;
        let mut positions = Vec::new();
        for k in 0..n {
            for i in 0..3 {
                for j in 0..3 {
                    positions.push(Vec3::new(
                        (2 * i + 1) as f64 * r,
                        (2 * j + 1) as f64 * r,
                        (2 * k + 1) as f64 * r,
                    ));
                }
            }
        }
        let radii = vec![r; positions.len()];
        let space = Space {
            periodic: [Some((0.0, 6.0 * r)), Some((0.0, 6.0 * r)), None],
        };
        let bed = bulk_packing_fraction(&positions, &radii, &space, 2, 0.0).unwrap();
        let sixth = std::f64::consts::PI / 6.0;
        assert!((bed.surface_fraction - sixth).abs() < 1e-12, "{bed:?}");
        assert!((bed.height - 2.0 * n as f64 * r).abs() < 1e-12, "{bed:?}");
        assert!((bed.bulk_fraction - sixth).abs() < 1e-12, "{bed:?}");
        // [2R, 14R] holds six whole layers.
        assert!((bed.interior_fraction - sixth).abs() < 1e-12, "{bed:?}");
        // A sphere ejected high above the bed does not move its surface.
        let mut with_stray = positions.clone();
        with_stray.push(Vec3::new(3.0 * r, 3.0 * r, 40.0 * r));
        let stray_radii = vec![r; with_stray.len()];
        let stray = bulk_packing_fraction(&with_stray, &stray_radii, &space, 2, 0.0).unwrap();
        assert!((stray.height - bed.height).abs() < 1e-12, "{stray:?}");
        // Shifted by half a layer the reference slab still spans one period.
        let lifted: Vec<Vec3> = positions
            .iter()
            .map(|p| p + Vec3::new(0.0, 0.0, 0.5))
            .collect();
        let bed = bulk_packing_fraction(&lifted, &radii, &space, 2, 0.0).unwrap();
        assert!(
            (bed.height - (2.0 * n as f64 * r + 0.5)).abs() < 1e-12,
            "{bed:?}"
        );
    }

    #[test]
    fn refuses_an_open_side_and_a_shallow_bed() {
        let e = bulk_packing_fraction(&[Vec3::new(0.0, 0.0, 1.0)], &[1.0], &Space::open(), 2, 0.0)
            .unwrap_err();
        assert!(e.to_string().contains("periodic"), "{e}");
        let space = Space {
            periodic: [Some((0.0, 4.0)), Some((0.0, 4.0)), None],
        };
        let e =
            bulk_packing_fraction(&[Vec3::new(2.0, 2.0, 1.0)], &[1.0], &space, 2, 0.0).unwrap_err();
        assert!(e.to_string().contains("3 largest diameters"), "{e}");
    }
}
