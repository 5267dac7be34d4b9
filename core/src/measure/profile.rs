//! Porosity profiles near walls: the wall effect, the looser packing within a few
//! particle diameters of a container wall (Rojek et al. 2016 §5 cite it as the reason
//! for measuring density in an RVE away from the walls).
//!
//! * **Plane wall** normal to coordinate axis k at x_k = w, bed on one side. Layer j
//!   is the part of a domain (the container's interior) between the distances
//!   [j t, (j + 1) t) from the wall:
//!   `φ_j = Σ_i V(ball_i ∩ domain ∩ {j t ≤ ±(x_k − w) < (j + 1) t}) / V_j`,
//!   each layer being itself a region — a box, a laterally periodic slab, or a
//!   cylinder whose axis is along k — so every term is exact.
//! * **Cylindrical wall** of radius R: shell j is the annulus of radii
//!   [R − (j + 1) t, R − j t) (the innermost clipped at 0) over the cylinder's height:
//!   `φ_j = (S(R − j t) − S(R − (j + 1) t)) / (π ((R − j t)² − (R − (j + 1) t)²) H)`
//!   with `S(ρ) = Σ_i V(ball_i ∩ coaxial cylinder of radius ρ)`, exact as a
//!   difference of exact cylinder volumes.
//!
//! Porosity is 1 − φ. Overlaps and periodic images are counted as in
//! `packing::packing_fraction`.

use crate::error::{Result, TampError};
use crate::measure::packing::solid_volume;
use crate::measure::region::Region;
use crate::particles::Vec3;
use crate::space::Space;
use std::f64::consts::PI;

/// One layer or shell of a profile; `near` and `far` are its distances from the wall.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Layer {
    /// Distance of its wall-side face from the wall, m.
    pub near: f64,
    /// Distance of its far face from the wall, m.
    pub far: f64,
    /// Volume of the layer, m³.
    pub volume: f64,
    /// Solid fraction φ_j: volume of solid in the layer over its volume.
    pub solid_fraction: f64,
}

impl Layer {
    /// Porosity 1 − φ_j of the layer.
    pub fn porosity(&self) -> f64 {
        1.0 - self.solid_fraction
    }
}

/// Layers parallel to a plane wall normal to a coordinate axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlaneProfile {
    /// The container's interior whose layers are measured: a box, a slab normal to
    /// `axis` (laterally periodic beds) or a cylinder with its axis along `axis`.
    pub domain: Region,
    /// Coordinate axis k normal to the wall (0 = x, 1 = y, 2 = z).
    pub axis: usize,
    /// Coordinate of the wall along `axis`.
    pub wall: f64,
    /// Whether the bed lies on the positive side of the wall.
    pub positive_side: bool,
    /// Thickness t of each layer, m.
    pub thickness: f64,
    /// Number of layers, counted from the wall.
    pub layers: usize,
}

/// Solid fraction φ_j of each layer of `spec`, nearest the wall first. Errors (naming
/// the field) on a bad axis, layer count or thickness, an invalid domain, or layers
/// reaching outside the domain.
pub fn plane_wall_profile(
    positions: &[Vec3],
    radii: &[f64],
    space: &Space,
    spec: &PlaneProfile,
) -> Result<Vec<Layer>> {
    let k = spec.axis;
    if k > 2 {
        return Err(TampError::input(
            "axis",
            format!("must be 0, 1 or 2, got {k}"),
        ));
    }
    check_layers(spec.thickness, spec.layers)?;
    if let Some(defect) = spec.domain.defect() {
        return Err(TampError::input("domain", defect));
    }
    let (lo, hi) = extent_along(&spec.domain, k)?;
    let depth = spec.thickness * spec.layers as f64;
    let sign = if spec.positive_side { 1.0 } else { -1.0 };
    let (a, b) = {
        let far = spec.wall + sign * depth;
        (spec.wall.min(far), spec.wall.max(far))
    };
    // The last layer may stop a rounding error short of the domain's face.
    let slack = 1e-12 * (hi - lo);
    if a < lo - slack || b > hi + slack {
        return Err(TampError::input(
            "layers",
            format!(
                "{} layers of {} from the wall at {} reach [{a}, {b}] along axis {k}, \
                 outside the domain's [{lo}, {hi}]",
                spec.layers, spec.thickness, spec.wall
            ),
        ));
    }
    (0..spec.layers)
        .map(|j| {
            let near = j as f64 * spec.thickness;
            let far = near + spec.thickness;
            let (x1, x2) = (spec.wall + sign * near, spec.wall + sign * far);
            let region = slice(&spec.domain, k, x1.min(x2).max(lo), x1.max(x2).min(hi))?;
            let (solid, volume) = solid_volume(positions, radii, &region, space)?;
            Ok(Layer {
                near,
                far,
                volume,
                solid_fraction: solid / volume,
            })
        })
        .collect()
}

/// Annular shells inward from the lateral wall of `die` (a cylinder).
pub fn cylinder_wall_profile(
    positions: &[Vec3],
    radii: &[f64],
    space: &Space,
    die: &Region,
    thickness: f64,
    shells: usize,
) -> Result<Vec<Layer>> {
    check_layers(thickness, shells)?;
    if let Some(defect) = die.defect() {
        return Err(TampError::input("die", defect));
    }
    let Region::Cylinder {
        base,
        axis,
        radius,
        height,
    } = *die
    else {
        return Err(TampError::input("die", "must be a cylinder"));
    };
    if (shells - 1) as f64 * thickness >= radius {
        return Err(TampError::input(
            "shells",
            format!("{shells} shells of {thickness} do not fit in a radius of {radius}"),
        ));
    }
    let solid_within = |rho: f64| -> Result<f64> {
        if rho <= 0.0 {
            return Ok(0.0);
        }
        let core = Region::Cylinder {
            base,
            axis,
            radius: rho,
            height,
        };
        Ok(solid_volume(positions, radii, &core, space)?.0)
    };
    let mut outer_solid = solid_within(radius)?;
    let mut shells_out = Vec::with_capacity(shells);
    for j in 0..shells {
        let near = j as f64 * thickness;
        let far = (near + thickness).min(radius);
        let (outer, inner) = (radius - near, radius - far);
        let inner_solid = solid_within(inner)?;
        let volume = PI * (outer - inner) * (outer + inner) * height;
        shells_out.push(Layer {
            near,
            far,
            volume,
            solid_fraction: (outer_solid - inner_solid) / volume,
        });
        outer_solid = inner_solid;
    }
    Ok(shells_out)
}

fn check_layers(thickness: f64, layers: usize) -> Result<()> {
    if !(thickness.is_finite() && thickness > 0.0) {
        return Err(TampError::input(
            "thickness",
            format!("must be positive, got {thickness}"),
        ));
    }
    if layers == 0 {
        return Err(TampError::input("layers", "at least one layer is needed"));
    }
    Ok(())
}

/// The domain's extent along coordinate axis k, for the shapes that can be sliced
/// normal to it.
fn extent_along(domain: &Region, k: usize) -> Result<(f64, f64)> {
    match *domain {
        Region::Box { lower, upper } => Ok((lower[k], upper[k])),
        Region::Slab { axis, lo, hi } if axis == k => Ok((lo, hi)),
        Region::Cylinder {
            base, axis, height, ..
        } => {
            let a = axis.normalize();
            // Parallel to within rounding: the slices must be cylinders again.
            if a[k].abs() < 1.0 - 1e-12 {
                return Err(TampError::input(
                    "domain",
                    format!("a cylinder sliced normal to axis {k} must have its axis along it"),
                ));
            }
            let top = base[k] + a[k] * height;
            Ok((base[k].min(top), base[k].max(top)))
        }
        _ => Err(TampError::input(
            "domain",
            format!("must be a box, a slab normal to axis {k} or a cylinder along it"),
        )),
    }
}

/// The part of `domain` with lo ≤ x_k ≤ hi (inside the domain's extent).
fn slice(domain: &Region, k: usize, lo: f64, hi: f64) -> Result<Region> {
    Ok(match *domain {
        Region::Box {
            mut lower,
            mut upper,
        } => {
            lower[k] = lo;
            upper[k] = hi;
            Region::Box { lower, upper }
        }
        Region::Slab { axis, .. } => Region::Slab { axis, lo, hi },
        Region::Cylinder {
            base, axis, radius, ..
        } => {
            let a = axis.normalize();
            let t1 = (lo - base[k]) / a[k];
            let t2 = (hi - base[k]) / a[k];
            Region::Cylinder {
                base: base + a * t1.min(t2),
                axis: a,
                radius,
                height: (t2 - t1).abs(),
            }
        }
        Region::Sphere { .. } => unreachable!("extent_along refuses spheres"),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::measure::packing::packing_fraction;
    use crate::measure::region::ball_volume;
    use rand::{RngExt, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    /// Simple cubic lattice (spacing 1, radius 1/2), periodic in x and y with period
    /// 4 and 6 layers in z from z = 0.5. Any layer one spacing thick, spanning the
    /// periodic cross-section, holds π/6 wherever it starts.
    #[test]
    fn whole_spacing_layers_in_a_lattice_hold_pi_over_six() {
        let mut x = Vec::new();
        for i in 0..4 {
            for j in 0..4 {
                for k in 0..6 {
                    x.push(Vec3::new(i as f64, j as f64, k as f64 + 0.5));
                }
            }
        }
        let r = vec![0.5; x.len()];
        let space = Space {
            periodic: [Some((0.0, 4.0)), Some((0.0, 4.0)), None],
        };
        let domains = [
            Region::Box {
                lower: Vec3::new(0.3, -1.1, 0.0),
                upper: Vec3::new(4.3, 2.9, 6.0),
            },
            Region::Slab {
                axis: 2,
                lo: 0.0,
                hi: 6.0,
            },
        ];
        for domain in domains {
            for (wall, positive_side) in [(0.0, true), (6.0, false), (0.37, true)] {
                let spec = PlaneProfile {
                    domain,
                    axis: 2,
                    wall,
                    positive_side,
                    thickness: 1.0,
                    layers: 5,
                };
                for layer in plane_wall_profile(&x, &r, &space, &spec).unwrap() {
                    assert!(
                        (layer.solid_fraction - PI / 6.0).abs() < 1e-13,
                        "{domain:?} {wall}: {layer:?}"
                    );
                    assert!((layer.volume - 16.0).abs() < 1e-12);
                }
            }
        }
    }

    fn random_bed(n: usize, seed: u64) -> (Vec<Vec3>, Vec<f64>) {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let x = (0..n)
            .map(|_| {
                Vec3::new(
                    rng.random_range(-1.0..1.0),
                    rng.random_range(-1.0..1.0),
                    rng.random_range(0.0..2.0),
                )
            })
            .collect();
        let r = (0..n).map(|_| rng.random_range(0.02..0.1)).collect();
        (x, r)
    }

    /// Layers tile the domain, so their volume-weighted mean is the domain's packing
    /// fraction — exactly, as every term is exact.
    #[test]
    fn layers_add_up_to_the_whole() {
        let (x, r) = random_bed(400, 3);
        let space = Space::open();
        let die = Region::Cylinder {
            base: Vec3::new(0.1, 0.0, 0.2),
            axis: Vec3::new(0.0, 0.0, -1.0),
            radius: 0.8,
            height: 0.2,
        };
        let whole = packing_fraction(&x, &r, &die, &space).unwrap();
        let spec = PlaneProfile {
            domain: die,
            axis: 2,
            wall: 0.0,
            positive_side: true,
            thickness: 0.02,
            layers: 10,
        };
        let mean = |layers: &[Layer]| {
            let v: f64 = layers.iter().map(|l| l.volume).sum();
            (
                layers
                    .iter()
                    .map(|l| l.solid_fraction * l.volume)
                    .sum::<f64>()
                    / v,
                v,
            )
        };
        let (m, v) = mean(&plane_wall_profile(&x, &r, &space, &spec).unwrap());
        assert!((v - die.volume()).abs() < 1e-14 * v);
        assert!((m - whole).abs() < 1e-13, "{m} {whole}");
        let shells = cylinder_wall_profile(&x, &r, &space, &die, 0.1, 8).unwrap();
        let (m, v) = mean(&shells);
        assert!((v - die.volume()).abs() < 1e-14 * v);
        assert!((m - whole).abs() < 1e-13, "{m} {whole}");
        // Too deep for the domain.
        let deep = PlaneProfile { layers: 11, ..spec };
        assert!(plane_wall_profile(&x, &r, &space, &deep).is_err());
    }

    /// One ball on the axis of a tall die: the solid inside radius ρ is the ball
    /// minus a napkin ring, 4/3 π (r³ − (r² − ρ²)^{3/2}) for ρ < r.
    #[test]
    fn shells_around_a_centred_ball_match_the_napkin_ring() {
        let r = 0.5;
        let die = Region::Cylinder {
            base: Vec3::new(0.0, 0.0, -1.0),
            axis: Vec3::z(),
            radius: 1.0,
            height: 2.0,
        };
        let within = |rho: f64| {
            if rho >= r {
                ball_volume(r)
            } else {
                4.0 / 3.0 * PI * (r.powi(3) - (r * r - rho * rho).powf(1.5))
            }
        };
        let shells =
            cylinder_wall_profile(&[Vec3::zeros()], &[r], &Space::open(), &die, 0.15, 7).unwrap();
        for s in shells {
            let (outer, inner) = (1.0 - s.near, 1.0 - s.far);
            let expected = (within(outer) - within(inner)) / s.volume;
            assert!(
                (s.solid_fraction - expected).abs() < 1e-14,
                "{s:?} {expected}"
            );
        }
    }
}
