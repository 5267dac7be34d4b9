//! Packing (solid) fraction of a region:
//!
//!   φ = Σ_i Σ_images V(ball_i ∩ region) / V(region),
//!
//! with V(ball ∩ region) exact (`Region::intersection_volume`).
//!
//! * **Overlaps.** Particles in a compacted bed overlap. The sum counts each lens of
//!   overlap twice, which is what mass conservation asks for: the overlap stands for
//!   material pushed elsewhere, so φ is the mass-based relative density
//!   Σ m_i / (ρ_s V), not the volume of the union of the balls (which would fall as
//!   the powder is compressed). This is the usual DEM convention and the one behind
//!   relative densities quoted against experiment (Rojek et al. 2016 §5).
//! * **Periodic axes.** The bed is the infinite periodic tiling of the particles, and
//!   every image x_i + n L ê_k that meets the region counts. There is no restriction
//!   on where the region lies or how long it is: a region longer than L simply meets
//!   more images, as it would in the tiled bed. Positions need not be wrapped.
//! * **Slabs.** A slab is unbounded across its axis, so its volume is infinite. In a
//!   bed periodic along both lateral axes it is measured per periodic cell instead:
//!   every particle counts once laterally (V(ball ∩ slab) does not depend on the
//!   lateral position) and V = (hi − lo) L_a L_b. A slab with a non-periodic lateral
//!   axis is refused.
//! * **Cost.** Images are enumerated only along periodic axes and only for the range
//!   of n whose bounding box meets the region's; a ball whose bounding box misses the
//!   region costs a few comparisons.

use crate::error::{Result, TampError};
use crate::measure::region::Region;
use crate::particles::Vec3;
use crate::space::Space;

/// Σ V(ball ∩ region) over particles and their periodic images, and the volume it is
/// divided by (the periodic cell's share for a slab).
pub fn solid_volume(
    positions: &[Vec3],
    radii: &[f64],
    region: &Region,
    space: &Space,
) -> Result<(f64, f64)> {
    if positions.len() != radii.len() {
        return Err(TampError::input(
            "radii",
            format!(
                "one radius per position expected, got {} radii for {} positions",
                radii.len(),
                positions.len()
            ),
        ));
    }
    if let Some(defect) = region.defect() {
        return Err(TampError::input("region", defect));
    }
    if let Region::Slab { axis, lo, hi } = *region {
        let cell_area = lateral_cell_area(space, axis).map_err(|k| {
            TampError::input(
                "region",
                format!(
                    "a slab normal to axis {axis} has infinite volume unless axis {k} \
                     is periodic; use a box or a cylinder"
                ),
            )
        })?;
        let along = Space {
            periodic: {
                let mut p = [None; 3];
                p[axis] = space.periodic[axis];
                p
            },
        };
        let solid = sum_over_images(positions, radii, region, &along);
        return Ok((solid, (hi - lo) * cell_area));
    }
    Ok((
        sum_over_images(positions, radii, region, space),
        region.volume(),
    ))
}

/// Area of the periodic cell across `axis`: the product of the periods of the two
/// other axes, or `Err(k)` with the first of them that is not periodic (then the
/// cell, and any slab across `axis`, is unbounded).
pub(crate) fn lateral_cell_area(space: &Space, axis: usize) -> std::result::Result<f64, usize> {
    (0..3).filter(|&k| k != axis).try_fold(1.0, |area, k| {
        space.periodic[k].map(|(_, length)| area * length).ok_or(k)
    })
}

/// φ = Σ V(ball ∩ region) / V(region); see the module comment for overlaps, periodic
/// images and slabs.
pub fn packing_fraction(
    positions: &[Vec3],
    radii: &[f64],
    region: &Region,
    space: &Space,
) -> Result<f64> {
    let (solid, volume) = solid_volume(positions, radii, region, space)?;
    Ok(solid / volume)
}

fn sum_over_images(positions: &[Vec3], radii: &[f64], region: &Region, space: &Space) -> f64 {
    let (lo, hi) = region.bounding_box();
    let mut total = 0.0;
    for (c, &r) in positions.iter().zip(radii) {
        let mut range = [(0i64, 0i64); 3];
        let mut misses = false;
        for k in 0..3 {
            match space.periodic[k] {
                Some((_, length)) => {
                    let first = ((lo[k] - r - c[k]) / length).ceil();
                    let last = ((hi[k] + r - c[k]) / length).floor();
                    if first > last {
                        misses = true;
                        break;
                    }
                    range[k] = (first as i64, last as i64);
                }
                None => {
                    if c[k] + r < lo[k] || c[k] - r > hi[k] {
                        misses = true;
                        break;
                    }
                }
            }
        }
        if misses {
            continue;
        }
        let shift = |k: usize, n: i64| space.periodic[k].map_or(0.0, |(_, l)| n as f64 * l);
        for nx in range[0].0..=range[0].1 {
            for ny in range[1].0..=range[1].1 {
                for nz in range[2].0..=range[2].1 {
                    let image = c + Vec3::new(shift(0, nx), shift(1, ny), shift(2, nz));
                    total += region.intersection_volume(&image, r);
                }
            }
        }
    }
    total
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::measure::region::ball_volume;
    use std::f64::consts::PI;

    /// Simple cubic lattice, spacing a, radius a/2, in a periodic cell of n³ sites.
    fn simple_cubic(a: f64, n: usize) -> (Vec<Vec3>, Vec<f64>, Space) {
        let mut x = Vec::new();
        for i in 0..n {
            for j in 0..n {
                for k in 0..n {
                    x.push(Vec3::new(i as f64, j as f64, k as f64) * a);
                }
            }
        }
        let l = a * n as f64;
        let r = vec![0.5 * a; x.len()];
        (
            x,
            r,
            Space {
                periodic: [Some((0.0, l)); 3],
            },
        )
    }

    /// A box whose sides are whole multiples of the lattice spacing holds exactly
    /// π/6 of solid wherever it sits, also straddling the periodic faces, because it
    /// tiles the unit cell.
    #[test]
    fn whole_cell_boxes_in_a_periodic_lattice_hold_pi_over_six() {
        let a = 1e-3;
        let (x, r, space) = simple_cubic(a, 4);
        for offset in [
            Vec3::new(0.0, 0.0, 0.0),
            Vec3::new(0.37, 0.11, 0.93),
            Vec3::new(-1.3, 2.71, 3.5),
            Vec3::new(3.2, 3.9, -0.45),
        ] {
            let lower = offset * a;
            let upper = lower + Vec3::new(2.0, 3.0, 1.0) * a;
            let phi = packing_fraction(&x, &r, &Region::Box { lower, upper }, &space).unwrap();
            assert!((phi - PI / 6.0).abs() < 1e-13, "offset {offset:?}: {phi}");
        }
        // Longer than the periodic cell: still the tiled bed's value.
        let long = Region::Box {
            lower: Vec3::new(0.3, 0.2, 0.1) * a,
            upper: Vec3::new(6.3, 1.2, 1.1) * a,
        };
        assert!((packing_fraction(&x, &r, &long, &space).unwrap() - PI / 6.0).abs() < 1e-13);
        // A slab per periodic cell, any whole number of spacings thick.
        let slab = Region::Slab {
            axis: 2,
            lo: 0.77 * a,
            hi: 2.77 * a,
        };
        assert!((packing_fraction(&x, &r, &slab, &space).unwrap() - PI / 6.0).abs() < 1e-13);
    }

    #[test]
    fn unwrapped_positions_count_like_wrapped_ones() {
        let a = 1.0;
        let (mut x, r, space) = simple_cubic(a, 3);
        let region = Region::Sphere {
            centre: Vec3::new(0.1, 0.2, 2.9),
            radius: 1.3,
        };
        let wrapped = packing_fraction(&x, &r, &region, &space).unwrap();
        for (i, p) in x.iter_mut().enumerate() {
            *p += Vec3::new(3.0 * (i % 3) as f64, -6.0, 3.0 * (i % 2) as f64);
        }
        let unwrapped = packing_fraction(&x, &r, &region, &space).unwrap();
        assert!((wrapped - unwrapped).abs() < 1e-14);
        // A region straddling a periodic face, and the same moved by one period.
        let tilted = |shift: f64| Region::Cylinder {
            base: Vec3::new(-0.4 + shift, 1.1, 0.3),
            axis: Vec3::new(1.0, 1.0, 2.0),
            radius: 0.9,
            height: 1.7,
        };
        let here = packing_fraction(&x, &r, &tilted(0.0), &space).unwrap();
        let there = packing_fraction(&x, &r, &tilted(3.0), &space).unwrap();
        assert!(here > 0.3 && (here - there).abs() < 1e-14, "{here} {there}");
    }

    #[test]
    fn region_holding_every_ball_in_an_open_space() {
        let x = vec![Vec3::new(0.0, 0.0, 0.0), Vec3::new(0.5, 0.5, 0.5)];
        let r = vec![0.2, 0.3];
        let region = Region::Cylinder {
            base: Vec3::new(0.2, 0.2, -1.0),
            axis: Vec3::z(),
            radius: 2.0,
            height: 3.0,
        };
        let phi = packing_fraction(&x, &r, &region, &Space::open()).unwrap();
        let expected = (ball_volume(0.2) + ball_volume(0.3)) / (PI * 4.0 * 3.0);
        assert!((phi - expected).abs() < 1e-15);
    }

    #[test]
    fn refuses_what_it_cannot_measure() {
        let x = vec![Vec3::zeros()];
        let slab = Region::Slab {
            axis: 2,
            lo: 0.0,
            hi: 1.0,
        };
        assert!(packing_fraction(&x, &[1.0], &slab, &Space::open()).is_err());
        let empty = Region::Box {
            lower: Vec3::zeros(),
            upper: Vec3::new(1.0, 0.0, 1.0),
        };
        assert!(packing_fraction(&x, &[1.0], &empty, &Space::open()).is_err());
        let unit = Region::Box {
            lower: Vec3::zeros(),
            upper: Vec3::repeat(1.0),
        };
        assert!(packing_fraction(&x, &[], &unit, &Space::open()).is_err());
    }
}
