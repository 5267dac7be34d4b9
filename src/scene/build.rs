//! Assemble a `Simulation` from a validated scene: only the roles the scene names
//! are built; random insertion uses the scene's seed.

use super::schema::*;
use crate::contact::{
    ContactLaw, damping::Damping, normal::NormalLaw, tangential::TangentialLaw,
    van_der_waals::VanDerWaals,
};
use crate::detect::{Detector, NeighborList};
use crate::error::{Result, TampError};
use crate::material::{Hollomon, Material, PairTable};
use crate::particles::{Motion, Particles, Vec3};
use crate::simulation::{Simulation, StabilityLimits};
use crate::walls::PlaneWall;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;

pub struct BuiltScene {
    pub sim: Simulation,
    /// α · Δt_cr (Rojek eqs 26–29), when it can be estimated.
    pub dt_estimate: Option<f64>,
    pub steps: u64,
    pub warnings: Vec<String>,
}

fn v3(a: &[f64; 3]) -> Vec3 {
    Vec3::new(a[0], a[1], a[2])
}

pub fn contact_law(spec: &ContactSpec) -> ContactLaw {
    ContactLaw {
        normal: match spec.normal {
            NormalSpec::Linear { stiffness } => NormalLaw::Linear { stiffness },
            NormalSpec::Hertz {} => NormalLaw::Hertz,
            NormalSpec::KuwabaraKono { dissipation_time } => {
                NormalLaw::KuwabaraKono { dissipation_time }
            }
            NormalSpec::WaltonBraun {
                loading_stiffness,
                unloading_stiffness,
            } => NormalLaw::WaltonBraun {
                loading_stiffness,
                unloading_stiffness,
            },
            NormalSpec::Hysteretic {
                stiffness,
                hysteresis,
            } => NormalLaw::Hysteretic {
                stiffness,
                hysteresis,
            },
            NormalSpec::Storakers { min_with_hertz } => NormalLaw::Storakers { min_with_hertz },
        },
        damping: spec.damping.as_ref().map(|d| match *d {
            DampingSpec::CriticalFraction { xi } => Damping::CriticalFraction { xi },
            DampingSpec::Constant { gamma_n } => Damping::Constant { gamma_n },
        }),
        tangential: spec.tangential.as_ref().map(|t| {
            let parameter = t.stiffness.or(t.damping).or(t.beta).unwrap_or(0.0);
            match t.law {
                TangentialLawName::MindlinDeresiewicz => TangentialLaw::MindlinDeresiewicz,
                TangentialLawName::Coulomb => TangentialLaw::Coulomb,
                TangentialLawName::HaffWerner => TangentialLaw::HaffWerner { damping: parameter },
                TangentialLawName::CundallStrack => TangentialLaw::CundallStrack {
                    stiffness: parameter,
                },
                TangentialLawName::WaltonBraun => TangentialLaw::WaltonBraun {
                    stiffness: parameter,
                },
                TangentialLawName::MindlinNoSlip => TangentialLaw::MindlinNoSlip,
                TangentialLawName::Storakers => TangentialLaw::Storakers { beta: parameter },
            }
        }),
        cohesion: spec.cohesion.as_ref().map(|c| match *c {
            CohesionSpec::VanDerWaals {
                hamaker,
                min_separation,
                cutoff,
            } => VanDerWaals {
                hamaker,
                min_separation,
                cutoff,
            },
        }),
    }
}

fn random_unit(rng: &mut ChaCha8Rng) -> Vec3 {
    loop {
        let v = Vec3::new(
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
        );
        let n2 = v.norm_squared();
        if n2 > 1e-6 && n2 <= 1.0 {
            return v / n2.sqrt();
        }
    }
}

pub fn build(scene: &Scene) -> Result<BuiltScene> {
    let materials: Vec<Material> = scene
        .materials
        .iter()
        .map(|m| Material {
            name: m.name.clone(),
            density: m.density,
            youngs_modulus: m.youngs_modulus,
            poisson_ratio: m.poisson_ratio,
            hollomon: m.hollomon.as_ref().map(|h| match h.strength {
                Some(strength) => Hollomon {
                    strength,
                    exponent: h.exponent,
                },
                None => Hollomon::through_yield_point(
                    h.yield_stress.unwrap_or(0.0),
                    m.youngs_modulus.unwrap_or(0.0),
                    h.exponent,
                ),
            }),
        })
        .collect();
    let material_id = |name: &str| {
        materials
            .iter()
            .position(|m| m.name == name)
            .expect("validated material name")
    };

    let (default_friction, overrides): (f64, Vec<(usize, usize, f64)>) =
        match &scene.contact.tangential {
            Some(TangentialSpec {
                friction,
                friction_pairs,
                ..
            }) => (
                *friction,
                friction_pairs
                    .iter()
                    .map(|fp| {
                        (
                            material_id(&fp.materials[0]),
                            material_id(&fp.materials[1]),
                            fp.friction,
                        )
                    })
                    .collect(),
            ),
            None => (0.0, Vec::new()),
        };
    let pair_table = PairTable::new(&materials, |a, b| {
        overrides
            .iter()
            .find(|&&(x, y, _)| (x, y) == (a, b) || (y, x) == (a, b))
            .map_or(default_friction, |o| o.2)
    });

    let walls: Vec<PlaneWall> = scene
        .walls
        .iter()
        .enumerate()
        .map(|(k, w)| {
            let WallSpec::Plane {
                point,
                normal,
                material,
                velocity,
                ..
            } = w;
            PlaneWall {
                name: w.name(k),
                point: v3(point),
                normal: v3(normal).normalize(),
                material: material_id(material),
                velocity: velocity.map_or(Vec3::zeros(), |v| v3(&v)),
            }
        })
        .collect();

    let inertia_scale = scene.rotation.as_ref().map_or(1.0, |r| r.inertia_scale);
    let mut particles = Particles::default();
    for p in &scene.particles {
        let m = material_id(&p.material);
        let motion = p
            .prescribed_velocity
            .map_or(Motion::Free, |v| Motion::Prescribed(v3(&v)));
        particles.push(
            v3(&p.position),
            p.velocity.map_or(Vec3::zeros(), |v| v3(&v)),
            p.omega.map_or(Vec3::zeros(), |v| v3(&v)),
            p.radius,
            materials[m].density,
            m,
            inertia_scale,
            motion,
        );
    }
    check_initial_overlaps(
        &particles,
        &walls,
        scene.stability.initial_overlap_tolerance,
    )?;

    let mut rng = ChaCha8Rng::seed_from_u64(scene.seed);
    for (k, ins) in scene.insert.iter().enumerate() {
        insert_random(
            &mut particles,
            &walls,
            ins,
            k,
            material_id(&ins.material),
            &materials,
            inertia_scale,
            &mut rng,
        )?;
    }

    let law = contact_law(&scene.contact);
    let r_min = particles
        .radius
        .iter()
        .cloned()
        .fold(f64::INFINITY, f64::min);
    let detector = match scene.broad_phase.kind {
        DetectorSpec::Brute => Detector::Brute,
        DetectorSpec::Cells => Detector::Cells,
        DetectorSpec::Multigrid => Detector::Multigrid,
    };
    let neighbors = NeighborList::new(
        detector,
        scene.broad_phase.skin_fraction * r_min,
        law.reach(),
        law.has_history(),
        crate::space::Space::open(),
    );
    let limits = StabilityLimits {
        max_overlap_fraction: scene.stability.max_overlap_fraction,
        max_energy_growth: scene.stability.max_energy_growth,
        check_every: scene.stability.check_every,
    };
    let mut sim = Simulation::new(
        particles,
        walls,
        materials,
        pair_table,
        law,
        scene.gravity.map(|g| v3(&g)),
        scene.rotation.is_some(),
        1.0, // replaced below once the estimate is known
        neighbors,
        limits,
    )?;

    let ts = &scene.time_step;
    let dt_estimate = sim
        .critical_time_step(ts.characteristic_velocity)
        .map(|dt| ts.alpha * dt);
    let mut warnings = Vec::new();
    let dt = match (ts.fixed, dt_estimate) {
        (Some(fixed), Some(est)) => {
            if fixed > est {
                warnings.push(format!(
                    "time_step.fixed = {fixed:e} s exceeds alpha * critical time step = {est:e} s (Rojek eq 26); the run may be unstable"
                ));
            }
            fixed
        }
        (Some(fixed), None) => fixed,
        (None, Some(est)) => est,
        (None, None) => {
            return Err(TampError::input(
                "time_step.characteristic_velocity",
                "is required when time_step.fixed is absent and the normal law's stiffness depends on the overlap",
            ));
        }
    };
    sim.dt = dt;
    let steps = match (scene.run.steps, scene.run.duration) {
        (Some(s), _) => s,
        (None, Some(d)) => (d / dt).ceil() as u64,
        (None, None) => unreachable!("validated"),
    };
    Ok(BuiltScene {
        sim,
        dt_estimate,
        steps,
        warnings,
    })
}

fn check_initial_overlaps(p: &Particles, walls: &[PlaneWall], tolerance: f64) -> Result<()> {
    let pairs = crate::detect::cells::candidate_pairs(&p.position, &p.radius, 0.0);
    let mut errors = Vec::new();
    for (i, j) in pairs {
        let (i, j) = (i as usize, j as usize);
        let overlap = p.radius[i] + p.radius[j] - (p.position[i] - p.position[j]).norm();
        let fraction = overlap / p.radius[i].min(p.radius[j]);
        if fraction > tolerance {
            errors.push(TampError::input(
                format!("particles[{j}].position"),
                format!(
                    "overlaps particles[{i}] by {overlap:.4e} m ({fraction:.3e} of the smaller radius); \
                     stability.initial_overlap_tolerance allows {tolerance:e}"
                ),
            ));
        }
    }
    for (k, wall) in walls.iter().enumerate() {
        for i in 0..p.len() {
            let overlap = p.radius[i] - wall.distance(&p.position[i]);
            if overlap / p.radius[i] > tolerance {
                errors.push(TampError::input(
                    format!("particles[{i}].position"),
                    format!(
                        "penetrates walls[{k}] ('{}') by {overlap:.4e} m; stability.initial_overlap_tolerance allows {tolerance:e} of the radius",
                        wall.name
                    ),
                ));
            }
        }
    }
    match errors.len() {
        0 => Ok(()),
        1 => Err(errors.pop().unwrap()),
        _ => Err(TampError::InputMany(errors)),
    }
}

/// Random sequential insertion: each new sphere is placed uniformly in the region
/// and kept if it overlaps no earlier sphere (brute-force check per trial).
#[allow(clippy::too_many_arguments)]
fn insert_random(
    particles: &mut Particles,
    walls: &[PlaneWall],
    ins: &InsertSpec,
    index: usize,
    material: usize,
    materials: &[Material],
    inertia_scale: f64,
    rng: &mut ChaCha8Rng,
) -> Result<()> {
    let (lo, hi) = (v3(&ins.region.lower), v3(&ins.region.upper));
    for placed in 0..ins.count {
        let r = match ins.radius {
            RadiusSpec::Fixed(r) => r,
            RadiusSpec::Uniform(UniformRadius { min, max }) => {
                if max > min {
                    rng.random_range(min..max)
                } else {
                    min
                }
            }
        };
        let mut attempts = 0;
        let position = loop {
            attempts += 1;
            if attempts > ins.max_attempts {
                return Err(TampError::input(
                    format!("insert[{index}].count"),
                    format!(
                        "placed only {placed} of {} particles in {} attempts; the region is too full",
                        ins.count, ins.max_attempts
                    ),
                ));
            }
            let x = Vec3::from_fn(|a, _| {
                let (from, to) = (lo[a] + r, hi[a] - r);
                if from < to {
                    rng.random_range(from..=to)
                } else {
                    0.5 * (lo[a] + hi[a])
                }
            });
            let free = particles
                .position
                .iter()
                .zip(&particles.radius)
                .all(|(q, rq)| (x - q).norm() >= r + rq)
                && walls.iter().all(|w| w.distance(&x) >= r);
            if free {
                break x;
            }
        };
        let velocity = random_unit(rng) * ins.speed;
        let omega = random_unit(rng) * ins.spin;
        particles.push(
            position,
            velocity,
            omega,
            r,
            materials[material].density,
            material,
            inertia_scale,
            Motion::Free,
        );
    }
    Ok(())
}
