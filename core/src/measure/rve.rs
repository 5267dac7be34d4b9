//! Spherical representative volume element (RVE), Rojek et al. 2016 §5: the relative
//! density of a die-compacted specimen measured in a ball centred at the specimen's
//! centre, as large as possible but clear of the zone near the walls where the
//! packing is looser (the wall effect), instead of over the whole specimen.
//!
//!   φ_RVE = Σ_i V(ball_i ∩ B(c, R_RVE)) / (4/3 π R_RVE³),
//!
//! each term the exact lens volume (`Region::Sphere`). The largest radius that keeps
//! a clearance δ from a set of walls is
//!
//!   R_RVE = min_w d_w(c) − δ,
//!
//! with d_w the distance from c to wall w: |(c − p)·n̂| for a plane through p with
//! normal n, and R − |(c − b) − ((c − b)·â) â| for the inside of a cylindrical wall
//! of radius R about the axis through b along â.

use crate::boundary::shape::Plane;
use crate::error::{Result, TampError};
use crate::measure::packing::packing_fraction;
use crate::measure::region::Region;
use crate::particles::Vec3;
use crate::space::Space;

/// A wall the RVE must keep clear of.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum WallSurface {
    /// Plane through `point` with normal `normal` (either sign, any length).
    Plane {
        /// A point of the plane, m.
        point: Vec3,
        /// Normal of the plane; normalised on use.
        normal: Vec3,
    },
    /// The inside of an unbounded cylindrical wall (a die).
    Cylinder {
        /// A point on the cylinder's axis, m.
        point: Vec3,
        /// Direction â of the axis; normalised on use.
        axis: Vec3,
        /// Cylinder radius R, m.
        radius: f64,
    },
}

impl From<&Plane> for WallSurface {
    fn from(w: &Plane) -> Self {
        WallSurface::Plane {
            point: w.point,
            normal: w.normal,
        }
    }
}

impl WallSurface {
    /// Distance from `x` to the wall; for a cylinder, negative outside it.
    pub fn distance(&self, x: &Vec3) -> f64 {
        match *self {
            WallSurface::Plane { point, normal } => (x - point).dot(&normal.normalize()).abs(),
            WallSurface::Cylinder {
                point,
                axis,
                radius,
            } => {
                let a = axis.normalize();
                let d = x - point;
                radius - (d - a * d.dot(&a)).norm()
            }
        }
    }
}

/// Packing fraction in the ball of radius `radius` about `centre`.
pub fn rve_packing_fraction(
    positions: &[Vec3],
    radii: &[f64],
    space: &Space,
    centre: Vec3,
    radius: f64,
) -> Result<f64> {
    packing_fraction(positions, radii, &Region::Sphere { centre, radius }, space)
}

/// Largest RVE radius about `centre` that stays `clearance` away from every wall;
/// zero when no positive radius does (and infinite when there are no walls).
pub fn largest_rve_radius(centre: &Vec3, walls: &[WallSurface], clearance: f64) -> f64 {
    let nearest = walls
        .iter()
        .map(|w| w.distance(centre))
        .fold(f64::INFINITY, f64::min);
    (nearest - clearance).max(0.0)
}

/// The RVE of Rojek §5 for a specimen filling `specimen` (a cylinder: die radius and
/// the bed's height between punch faces; or a box): centred at its centre, with the
/// largest radius keeping `clearance` from its walls. An error when nothing is left.
pub fn specimen_centre_rve(specimen: &Region, clearance: f64) -> Result<Region> {
    if let Some(defect) = specimen.defect() {
        return Err(TampError::input("specimen", defect));
    }
    let (centre, walls) = match *specimen {
        Region::Cylinder {
            base,
            axis,
            radius,
            height,
        } => {
            let a = axis.normalize();
            (
                base + a * (0.5 * height),
                vec![
                    WallSurface::Cylinder {
                        point: base,
                        axis: a,
                        radius,
                    },
                    WallSurface::Plane {
                        point: base,
                        normal: a,
                    },
                    WallSurface::Plane {
                        point: base + a * height,
                        normal: a,
                    },
                ],
            )
        }
        Region::Box { lower, upper } => {
            let walls = (0..3)
                .flat_map(|k| {
                    let mut n = Vec3::zeros();
                    n[k] = 1.0;
                    [
                        WallSurface::Plane {
                            point: lower,
                            normal: n,
                        },
                        WallSurface::Plane {
                            point: upper,
                            normal: n,
                        },
                    ]
                })
                .collect();
            (0.5 * (lower + upper), walls)
        }
        _ => {
            return Err(TampError::input(
                "specimen",
                "the specimen must be a cylinder or a box",
            ));
        }
    };
    let radius = largest_rve_radius(&centre, &walls, clearance);
    if radius <= 0.0 {
        return Err(TampError::input(
            "clearance",
            format!("a clearance of {clearance} leaves no RVE inside the specimen"),
        ));
    }
    Ok(Region::Sphere { centre, radius })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::measure::region::ball_volume;

    /// The geometry of Rojek §5: a die of diameter 58 μm and a specimen of height
    /// H0 = 95 μm; a 2 μm clearance gives their RVE diameter of 54 μm.
    #[test]
    fn rojek_die_rve() {
        let um = 1e-6;
        let die = Region::Cylinder {
            base: Vec3::new(1.0, 2.0, 0.0) * um,
            axis: Vec3::z(),
            radius: 29.0 * um,
            height: 95.0 * um,
        };
        let Region::Sphere { centre, radius } = specimen_centre_rve(&die, 2.0 * um).unwrap() else {
            panic!("not a sphere")
        };
        assert!((2.0 * radius - 54.0 * um).abs() < 1e-18);
        assert!((centre - Vec3::new(1.0, 2.0, 47.5) * um).norm() < 1e-18);
        assert!(specimen_centre_rve(&die, 30.0 * um).is_err());
    }

    #[test]
    fn nearest_wall_sets_the_radius() {
        let floor = Plane {
            point: Vec3::zeros(),
            normal: Vec3::new(0.0, 0.0, 2.0),
        };
        let walls = [
            WallSurface::from(&floor),
            WallSurface::Cylinder {
                point: Vec3::zeros(),
                axis: Vec3::z(),
                radius: 1.0,
            },
        ];
        let c = Vec3::new(0.3, 0.4, 2.0);
        assert!((largest_rve_radius(&c, &walls, 0.1) - 0.4).abs() < 1e-15);
        assert!((largest_rve_radius(&Vec3::new(0.0, 0.0, 0.25), &walls, 0.1) - 0.15).abs() < 1e-15);
        assert_eq!(
            largest_rve_radius(&Vec3::new(2.0, 0.0, 5.0), &walls, 0.0),
            0.0
        );
    }

    #[test]
    fn rve_counts_lens_volumes() {
        // One ball fully inside, one cut through its centre by the RVE's surface.
        let x = vec![Vec3::zeros(), Vec3::new(1.0, 0.0, 0.0)];
        let r = vec![0.1, 0.1];
        let phi = rve_packing_fraction(&x, &r, &Space::open(), Vec3::zeros(), 1.0).unwrap();
        let lens = Region::Sphere {
            centre: Vec3::zeros(),
            radius: 1.0,
        }
        .intersection_volume(&x[1], 0.1);
        assert!((phi - (ball_volume(0.1) + lens) / ball_volume(1.0)).abs() < 1e-16);
        // Slightly under half the ball: the RVE's surface curves away from it.
        assert!(lens < 0.5 * ball_volume(0.1) && lens > 0.45 * ball_volume(0.1));
    }
}
