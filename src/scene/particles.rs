//! Where a scene's particles come from: `particles` (each given explicitly),
//! `insert` (random sequential insertion into a box, at once or poured on a schedule)
//! and `deposit` (ballistic deposition onto a floor).
//!
//! ```json
//! "insert": [{"count": 500, "radius": {"min": 4e-4, "max": 6e-4}, "material": "glass",
//!             "region": {"lower": [0, 0, 0.01], "upper": [0.02, 0.02, 0.05]}}]
//! ```

use super::materials::MaterialNames;
use super::schema::Scene;
use crate::error::Errors;
use crate::generate::distribution::SizeDistribution;
use serde::{Deserialize, Serialize};

/// One particle given explicitly.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct ParticleSpec {
    /// Centre, m.
    pub position: [f64; 3],
    /// m
    pub radius: f64,
    /// The name of its material (not rigid).
    pub material: String,
    /// Initial velocity, m/s; absent means at rest.
    #[serde(default)]
    pub velocity: Option<[f64; 3]>,
    /// Initial angular velocity, rad/s; needs `rotation`.
    #[serde(default)]
    pub omega: Option<[f64; 3]>,
    /// When set, the particle moves at this velocity whatever the forces (m/s).
    #[serde(default)]
    pub prescribed_velocity: Option<[f64; 3]>,
}

/// Random sequential insertion of `count` non-overlapping spheres into a box.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct InsertSpec {
    /// How many particles.
    pub count: usize,
    /// Their radii: one value, a uniform range or a size distribution.
    pub radius: RadiusSpec,
    /// The name of their material (not rigid).
    pub material: String,
    /// Axis-aligned box the particles must lie inside (whole spheres), m.
    pub region: BoxRegion,
    /// Speed of each particle in a uniformly random direction, m/s.
    #[serde(default)]
    pub speed: f64,
    /// Magnitude of each particle's spin in a random direction, rad/s.
    #[serde(default)]
    pub spin: f64,
    /// Random positions tried for one particle before the insertion gives up.
    #[serde(default = "default_attempts")]
    pub max_attempts: usize,
    /// Absent: all particles are placed at t = 0.
    #[serde(default)]
    pub schedule: Option<ScheduleSpec>,
}

fn default_attempts() -> usize {
    100_000
}

/// A radius as the scene gives it: one value (m), `{"min", "max"}` or a size law.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(untagged)]
pub enum RadiusSpec {
    /// Every particle this radius, m.
    Fixed(f64),
    /// Uniform in [min, max].
    Uniform(UniformRadius),
    /// Any `generate::distribution::SizeDistribution`, tagged by `law`.
    Law(SizeDistribution),
}

impl RadiusSpec {
    /// The radius as the distribution it is sampled from.
    pub fn distribution(&self) -> SizeDistribution {
        match self {
            RadiusSpec::Fixed(radius) => SizeDistribution::Mono { radius: *radius },
            RadiusSpec::Uniform(UniformRadius { min, max }) => SizeDistribution::Uniform {
                min: *min,
                max: *max,
            },
            RadiusSpec::Law(law) => law.clone(),
        }
    }
}

/// Pouring: instead of all at t = 0, insert `per_event` particles every `every`
/// seconds from `start` on, until `count` are in.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct ScheduleSpec {
    /// Time of the first insertion, s.
    #[serde(default)]
    pub start: f64,
    /// Time between insertions, s.
    pub every: f64,
    /// Particles per insertion.
    pub per_event: usize,
}

/// 3D ballistic deposition (steepest descent) of `count` spheres dropped over a
/// rectangular footprint onto the plane z = `floor`.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct DepositSpec {
    /// How many particles.
    pub count: usize,
    /// Their radii.
    pub radius: RadiusSpec,
    /// The name of their material (not rigid).
    pub material: String,
    /// [x, y] corners of the footprint, m.
    pub footprint: [[f64; 2]; 2],
    /// Height of the floor they settle on, m.
    pub floor: f64,
}

/// Radii uniformly distributed in [min, max], m.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct UniformRadius {
    /// m
    pub min: f64,
    /// m
    pub max: f64,
}

/// An axis-aligned box, m.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct BoxRegion {
    /// The corner of smallest coordinates.
    pub lower: [f64; 3],
    /// The corner of largest coordinates.
    pub upper: [f64; 3],
}

/// The rules of `particles`, `insert` and `deposit`, and that the scene has at least
/// one particle.
pub fn validate(scene: &Scene, names: &MaterialNames, e: &mut Errors) {
    for (k, p) in scene.particles.iter().enumerate() {
        e.finite3(format!("particles[{k}].position"), &p.position);
        e.positive(format!("particles[{k}].radius"), p.radius);
        names.check_particle_material(e, format!("particles[{k}].material"), &p.material);
        if p.prescribed_velocity.is_some() && (p.velocity.is_some() || p.omega.is_some()) {
            e.push(
                format!("particles[{k}].prescribed_velocity"),
                "cannot be combined with velocity or omega: a prescribed particle moves at exactly this velocity and does not spin",
            );
        }
        if p.omega.is_some() && scene.rotation.is_none() {
            e.push(
                format!("particles[{k}].omega"),
                "needs \"rotation\" in the scene: without it spins never change",
            );
        }
        for (field, v) in [
            ("velocity", &p.velocity),
            ("omega", &p.omega),
            ("prescribed_velocity", &p.prescribed_velocity),
        ] {
            if let Some(v) = v {
                e.finite3(format!("particles[{k}].{field}"), v);
            }
        }
    }
    for (k, ins) in scene.insert.iter().enumerate() {
        let path = format!("insert[{k}]");
        names.check_particle_material(e, format!("{path}.material"), &ins.material);
        let r_max = match ins.radius {
            RadiusSpec::Fixed(r) => {
                e.positive(format!("{path}.radius"), r);
                r
            }
            RadiusSpec::Uniform(UniformRadius { min, max }) => {
                e.positive(format!("{path}.radius.min"), min);
                if !(max >= min && max.is_finite()) {
                    e.push(
                        format!("{path}.radius.max"),
                        format!("must be >= radius.min ({min:e}), got {max:e}"),
                    );
                }
                max
            }
            RadiusSpec::Law(_) => radius_law_max(e, &format!("{path}.radius"), &ins.radius),
        };
        if let Some(sch) = &ins.schedule {
            e.non_negative(format!("{path}.schedule.start"), sch.start);
            e.positive(format!("{path}.schedule.every"), sch.every);
            if sch.per_event == 0 {
                e.push(format!("{path}.schedule.per_event"), "must be >= 1, got 0");
            }
            if scene.growth.is_some() {
                e.push(
                    format!("{path}.schedule"),
                    "cannot be combined with growth: poured particles would arrive during or after the growth stage at full size",
                );
            }
        }
        e.finite3(format!("{path}.region.lower"), &ins.region.lower);
        e.finite3(format!("{path}.region.upper"), &ins.region.upper);
        for a in 0..3 {
            if ins.region.upper[a] - ins.region.lower[a] < 2.0 * r_max {
                e.push(
                    format!("{path}.region.upper[{a}]"),
                    format!("the region must be at least one particle diameter ({:e} m) wide along every axis", 2.0 * r_max),
                );
                break;
            }
        }
        e.non_negative(format!("{path}.speed"), ins.speed);
        e.non_negative(format!("{path}.spin"), ins.spin);
        if ins.spin > 0.0 && scene.rotation.is_none() {
            e.push(
                format!("{path}.spin"),
                "needs \"rotation\" in the scene: without it spins never change",
            );
        }
        if ins.max_attempts == 0 {
            e.push(format!("{path}.max_attempts"), "must be >= 1, got 0");
        }
    }
    for (k, dep) in scene.deposit.iter().enumerate() {
        let path = format!("deposit[{k}]");
        names.check_particle_material(e, format!("{path}.material"), &dep.material);
        radius_law_max(e, &format!("{path}.radius"), &dep.radius);
        let [lo, hi] = dep.footprint;
        if !(lo.iter().chain(&hi).all(|c| c.is_finite()) && hi[0] > lo[0] && hi[1] > lo[1]) {
            e.push(
                format!("{path}.footprint"),
                format!(
                    "must be [[x_lo, y_lo], [x_hi, y_hi]] with hi > lo, finite, got {:?}",
                    dep.footprint
                ),
            );
        }
        if !dep.floor.is_finite() {
            e.push(format!("{path}.floor"), "must be finite");
        }
    }
    if scene.particles.is_empty()
        && scene.insert.iter().all(|i| i.count == 0)
        && scene.deposit.iter().all(|d| d.count == 0)
    {
        e.push(
            "particles",
            "the scene must contain at least one particle (particles or insert)",
        );
    }
}

/// Check a radius given as a distribution; returns its largest radius (0 when invalid).
fn radius_law_max(e: &mut Errors, path: &str, radius: &RadiusSpec) -> f64 {
    let d = radius.distribution();
    if let Err(rule) = d.validate() {
        e.push(path, rule);
        return 0.0;
    }
    let r_max = d.max_radius();
    if !r_max.is_finite() {
        e.push(
            format!("{path}.max"),
            "is required: placing particles needs a largest radius",
        );
        return 0.0;
    }
    r_max
}
