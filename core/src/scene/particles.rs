//! Where a scene's particles come from: `particles` (each given explicitly),
//! `insert` (random sequential insertion into a box, at once or poured on a schedule)
//! and `deposit` (ballistic deposition onto a floor).
//!
//! ```json
//! "insert": [{"count": 500, "radius": {"min": 4e-4, "max": 6e-4}, "material": "glass",
//!             "region": {"lower": [0, 0, 0.01], "upper": [0.02, 0.02, 0.05]}}]
//! ```

use super::build::v3;
use super::materials::MaterialNames;
use super::schema::Scene;
use crate::boundary::Boundary;
use crate::error::{Errors, Result, TampError};
use crate::generate::distribution::SizeDistribution;
use crate::generate::pour::Source;
use crate::generate::rsi::{InsertionBox, Placed};
use crate::generate::{ballistic, random_unit};
use crate::material::Material;
use crate::particles::{Motion, Particles, Vec3};
use crate::progress::Progress;
use crate::space::Space;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
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
    /// Later prescribed velocities, each from its time on (needs `prescribed_velocity`).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub prescribed_velocity_changes: Vec<VelocityChangeSpec>,
}

/// A prescribed particle's new velocity from a time on: a displacement-controlled
/// loading that turns back (load, unload, reload).
#[derive(Clone, Debug, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct VelocityChangeSpec {
    /// From this time on (the step nearest it at the scene's time step), s.
    pub time: f64,
    /// The velocity from then on, m/s.
    pub velocity: [f64; 3],
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
#[derive(Clone, Debug, Serialize)]
#[serde(untagged)]
pub enum RadiusSpec {
    /// Every particle this radius, m.
    Fixed(f64),
    /// Uniform in [min, max].
    Uniform(UniformRadius),
    /// Any `generate::distribution::SizeDistribution`, tagged by `law`.
    Law(SizeDistribution),
}

/// Read by its shape (a number, an object with `law`, another object), so that an
/// error names what is wrong inside the form given; serde's untagged reading only says
/// that no form matched.
impl<'de> Deserialize<'de> for RadiusSpec {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        use serde::de::Error;
        let value = serde_json::Value::deserialize(d)?;
        let read = match &value {
            serde_json::Value::Number(_) => serde_json::from_value(value).map(RadiusSpec::Fixed),
            serde_json::Value::Object(o) if o.contains_key("law") => {
                serde_json::from_value(value).map(RadiusSpec::Law)
            }
            serde_json::Value::Object(_) => serde_json::from_value(value).map(RadiusSpec::Uniform),
            _ => {
                return Err(D::Error::custom(
                    "must be a radius (m), {\"min\", \"max\"} or a size law {\"law\": …}",
                ));
            }
        };
        read.map_err(D::Error::custom)
    }
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

/// A particle's `prescribed_velocity_changes`: only with `prescribed_velocity`, at
/// positive, finite, increasing times, with finite velocities. That no two changes
/// fall on one step is checked once the step is known (`velocity_change_steps`).
fn validate_velocity_changes(p: &ParticleSpec, path: &str, e: &mut Errors) {
    if p.prescribed_velocity_changes.is_empty() {
        return;
    }
    if p.prescribed_velocity.is_none() {
        e.push(
            format!("{path}.prescribed_velocity_changes"),
            "needs prescribed_velocity: only a prescribed particle's velocity can be changed",
        );
    }
    let mut before = 0.0;
    for (c, change) in p.prescribed_velocity_changes.iter().enumerate() {
        let at = format!("{path}.prescribed_velocity_changes[{c}]");
        if !(change.time > before && change.time.is_finite()) {
            e.push(
                format!("{at}.time"),
                format!(
                    "must be finite and later than {before:e} s (the start, or the change before), got {:e}",
                    change.time
                ),
            );
        }
        before = change.time;
        e.finite3(format!("{at}.velocity"), &change.velocity);
    }
}

/// The step from which each `prescribed_velocity_changes` entry applies, the step
/// nearest its time at step `dt`, as (step, index k of `particles[k]`, velocity); exit 2
/// naming the entry when one falls on step 0 or on the step of the change before it.
pub fn velocity_change_steps(scene: &Scene, dt: f64) -> Result<Vec<(u64, usize, Vec3)>> {
    let mut steps = Vec::new();
    for (k, p) in scene.particles.iter().enumerate() {
        let mut before = 0;
        for (c, change) in p.prescribed_velocity_changes.iter().enumerate() {
            let step = (change.time / dt).round();
            if !(step >= 1.0 && step > before as f64 && step < u64::MAX as f64) {
                return Err(TampError::input(
                    format!("particles[{k}].prescribed_velocity_changes[{c}].time"),
                    format!(
                        "{:e} s is step {step} at the time step {dt:e} s, and each change needs a step of its own after step {before}",
                        change.time
                    ),
                ));
            }
            before = step as u64;
            steps.push((before, k, v3(&change.velocity)));
        }
    }
    steps.sort_by_key(|&(step, k, _)| (step, k));
    Ok(steps)
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
        validate_velocity_changes(p, &format!("particles[{k}]"), e);
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

/// The particles at t = 0 and the pouring sources, drawn from the scene's seed in
/// the file's order: explicit particles, deposits, then inserts (poured ones become
/// sources with their own seed). Explicit and deposited spheres must not overlap
/// each other or the walls beyond `stability.initial_overlap_tolerance`.
pub fn place(
    scene: &Scene,
    materials: &[Material],
    material_id: &dyn Fn(&str) -> usize,
    walls: &[Boundary],
    space: &Space,
) -> Result<(Particles, Vec<Source>)> {
    let inertia_scale = super::physics::inertia_scale(scene.rotation.as_ref());
    let mut particles = Particles::default();
    let count = scene.particles.len()
        + scene.insert.iter().map(|i| i.count).sum::<usize>()
        + scene.deposit.iter().map(|d| d.count).sum::<usize>();
    particles.try_reserve(count).map_err(|e| {
        TampError::input(
            "scene",
            format!(
                "memory for {count} particles could not be allocated ({e}); make the scene smaller"
            ),
        )
    })?;
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
            materials[m].particle_density(),
            m,
            inertia_scale,
            motion,
        );
    }
    let explicit = particles.len();

    let mut rng = ChaCha8Rng::seed_from_u64(scene.seed);
    // Spheres placed before a growth stage only need to be apart at their starting size.
    let placement_scale = scene.growth.as_ref().map_or(1.0, |g| g.initial_fraction);
    for (k, dep) in scene.deposit.iter().enumerate() {
        let law = dep.radius.distribution();
        let radii: Vec<f64> = (0..dep.count).map(|_| law.sample(&mut rng)).collect();
        let positions = ballistic::deposit(
            &radii,
            (dep.footprint[0], dep.footprint[1]),
            dep.floor,
            space,
            &mut rng,
        )
        .map_err(|rule| TampError::input(format!("deposit[{k}]"), rule))?;
        let m = material_id(&dep.material);
        for (x, r) in positions.into_iter().zip(radii) {
            particles.push(
                x,
                Vec3::zeros(),
                Vec3::zeros(),
                r,
                materials[m].particle_density(),
                m,
                inertia_scale,
                Motion::Free,
            );
        }
    }
    // Explicit and deposited spheres are placed without looking at each other or at
    // the walls; inserted ones are clear by construction, so they come after.
    check_initial_overlaps(
        &particles,
        explicit,
        walls,
        space,
        placement_scale,
        scene.stability.initial_overlap_tolerance,
    )?;
    let mut sources = Vec::new();
    for (k, ins) in scene.insert.iter().enumerate() {
        if let Some(sch) = &ins.schedule {
            sources.push(Source {
                region: insertion_box(&ins.region),
                radius: ins.radius.distribution(),
                material: material_id(&ins.material),
                speed: ins.speed,
                spin: ins.spin,
                start: sch.start,
                every: sch.every,
                per_event: sch.per_event,
                max_attempts: ins.max_attempts,
                count: ins.count,
                seed: scene.seed.wrapping_add(1 + k as u64),
            });
            continue;
        }
        insert_random(
            &mut particles,
            walls,
            space,
            placement_scale,
            ins,
            k,
            material_id(&ins.material),
            materials,
            inertia_scale,
            &mut rng,
        )?;
    }

    Ok((particles, sources))
}

fn insertion_box(region: &BoxRegion) -> InsertionBox {
    InsertionBox {
        lower: v3(&region.lower),
        upper: v3(&region.upper),
    }
}

/// Initial overlaps among the explicit and deposited particles (through periodic
/// faces too) and with the walls, at the size they start with: `scale` of their
/// radius (a growth stage's initial fraction, else 1). The first `explicit` particles
/// are named by their `particles[k]` path, the rest as deposited particles.
fn check_initial_overlaps(
    p: &Particles,
    explicit: usize,
    walls: &[Boundary],
    space: &Space,
    scale: f64,
    tolerance: f64,
) -> Result<()> {
    let radius: Vec<f64> = p.radius.iter().map(|r| r * scale).collect();
    let path = |i: usize| {
        if i < explicit {
            format!("particles[{i}].position")
        } else {
            format!("deposit (particle {i})")
        }
    };
    let pairs = crate::detect::cells::candidate_pairs_in(&p.position, &radius, 0.0, space);
    let mut errors = Vec::new();
    for (i, j) in pairs {
        let (i, j) = (i as usize, j as usize);
        let distance = space
            .displacement(&p.position[i], &p.position[j])
            .norm_squared()
            .sqrt();
        // Two centres at distance zero (or so close that the squared distance
        // underflows, as the force loop computes it) leave the contact normal
        // undefined: no tolerance makes that a contact, so it is bad input whatever
        // the tolerance, not an instability of a run that never started.
        if distance == 0.0 {
            let other = path(i);
            let other = other.trim_end_matches(".position");
            let apart = space.displacement(&p.position[i], &p.position[j]).amax();
            let rule = if apart == 0.0 {
                format!("has the same centre as {other}: the contact normal is undefined")
            } else {
                format!(
                    "has its centre {apart:e} m from that of {other}, too close for a contact normal (the squared distance underflows)"
                )
            };
            errors.push(TampError::input(path(j), rule));
            continue;
        }
        let overlap = radius[i] + radius[j] - distance;
        let fraction = overlap / radius[i].min(radius[j]);
        if fraction > tolerance {
            errors.push(TampError::input(
                path(j),
                format!(
                    "overlaps {} by {overlap:.4e} m ({fraction:.3e} of the smaller radius); \
                     stability.initial_overlap_tolerance allows {tolerance:e}",
                    path(i).trim_end_matches(".position")
                ),
            ));
        }
    }
    for (k, wall) in walls.iter().enumerate() {
        for (i, (x, &r)) in p.position.iter().zip(&radius).enumerate() {
            let overlap = wall.deepest_overlap(&wall.initial_pose(), x, r);
            if overlap / r > tolerance {
                errors.push(TampError::input(
                    path(i),
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

/// Random sequential insertion of an `insert` block at t = 0 (`generate::rsi`).
#[allow(clippy::too_many_arguments)]
fn insert_random(
    particles: &mut Particles,
    walls: &[Boundary],
    space: &Space,
    placement_scale: f64,
    ins: &InsertSpec,
    index: usize,
    material: usize,
    materials: &[Material],
    inertia_scale: f64,
    rng: &mut ChaCha8Rng,
) -> Result<()> {
    let region = insertion_box(&ins.region);
    let law = ins.radius.distribution();
    let poses: Vec<_> = walls.iter().map(Boundary::initial_pose).collect();
    let clear = |x: &Vec3, r: f64| Boundary::clear_of_all(walls, &poses, x, r);
    let mut placed = Placed::with(
        space,
        &particles.position,
        &particles.radius,
        law.max_radius(),
    );
    let mut progress = Progress::new(&format!("insert[{index}]"), ins.count as u64, false);
    for count in 0..ins.count {
        let r = law.sample(rng);
        let position = placed
            .place(r, &region, &clear, placement_scale, rng, ins.max_attempts)
            .ok_or_else(|| {
                TampError::input(
                    format!("insert[{index}].count"),
                    format!(
                        "placed only {count} of {} particles in {} attempts; the region is too full",
                        ins.count, ins.max_attempts
                    ),
                )
            })?;
        if count % 1024 == 0 {
            progress.set(count as u64);
        }
        let velocity = random_unit(rng) * ins.speed;
        let omega = random_unit(rng) * ins.spin;
        particles.push(
            position,
            velocity,
            omega,
            r,
            materials[material].particle_density(),
            material,
            inertia_scale,
            Motion::Free,
        );
    }
    progress.finish();
    Ok(())
}
