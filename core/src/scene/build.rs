//! Assemble a `Simulation` from a validated scene, from the topics' builds (the
//! material and pair tables, the walls, the space, the particles and sources): only
//! the roles the scene names are built; random placement uses the scene's seed.

use super::schema::*;
use crate::accuracy::step::{COST_PER_PARTICLE_STEP, DEFAULT_ACCURACY, STABILITY_ALPHA};
use crate::detect::{Detection, locality};
use crate::error::{Result, TampError};
use crate::growth::Growth;
use crate::material::Material;
use crate::particles::Vec3;
use crate::simulation::{Model, Simulation, VelocityChange};

/// A built scene: the simulation ready to step, and what its build found.
pub struct BuiltScene {
    /// The simulation at t = 0, first forces computed.
    pub sim: Simulation,
    /// α · Δt_cr (Rojek eqs 26–29), when it can be estimated.
    pub dt_estimate: Option<f64>,
    /// Steps the run lasts (its maximum, with `run.until`).
    pub steps: u64,
    /// Warnings for stderr and `summary.json`.
    pub warnings: Vec<String>,
    /// How the step was chosen, when tamp chose it from an accuracy or an implied
    /// characteristic velocity: printed to stderr by `tamp run`.
    pub notes: Vec<String>,
    /// What `time_step.accuracy` (stated or the default) chose, when it set the step.
    pub accuracy: Option<crate::accuracy::step::Choice>,
}

pub(super) fn v3(a: &[f64; 3]) -> Vec3 {
    Vec3::new(a[0], a[1], a[2])
}

/// Rules on what the inputs make together, checked once the scene is built: every
/// particle's mass and inertia, the step, and the speeds and energies the run can
/// reach (its initial speeds and the characteristic velocity, plus |g| times its
/// duration) stay inside the range of a double, with a margin of 10⁶ for sums over
/// many particles and steps. Otherwise some output would be inf or NaN.
fn check_range(scene: &Scene, sim: &Simulation, dt: f64, steps: f64) -> Result<()> {
    const MARGIN: f64 = 1e-6 * f64::MAX;
    let p = &sim.state.particles;
    for i in 0..p.len() {
        let (m, inertia) = (p.mass[i], p.inertia[i]);
        if !(m > 0.0 && m.is_finite() && inertia > 0.0 && inertia.is_finite()) {
            let k = p.material[i];
            return Err(TampError::input(
                format!("materials[{k}].density"),
                format!(
                    "gives particle {} (radius {:e} m) a mass of {m:e} kg and a moment of inertia of {inertia:e} kg m²: outside the range of a double",
                    p.id[i], p.radius[i]
                ),
            ));
        }
    }
    if !(dt > 0.0 && dt.is_finite()) {
        return Err(TampError::input(
            "time_step",
            format!("gives a step of {:e} s: it must be > 0 and finite", dt),
        ));
    }
    let duration = steps * dt;
    let fall = scene
        .gravity
        .map_or(0.0, |g| Vec3::new(g[0], g[1], g[2]).norm() * duration);
    let moving = p.velocity.iter().map(|v| v.norm()).fold(
        scene.time_step.characteristic_velocity.unwrap_or(0.0),
        f64::max,
    );
    let total_mass: f64 = p.mass.iter().sum();
    let energy = total_mass * (moving + fall).powi(2);
    if !energy.is_finite() || energy >= MARGIN {
        let (path, what) = if fall > moving {
            ("gravity", format!("|g| times the run's {duration:e} s"))
        } else {
            ("particles", "the fastest initial velocity".to_string())
        };
        return Err(TampError::input(
            path,
            format!(
                "gives speeds of {:e} m/s ({what}) and kinetic energies of {energy:e} J for {total_mass:e} kg of particles: beyond the range of a double (1e-6 of its largest value)",
                moving + fall
            ),
        ));
    }
    Ok(())
}

/// The step against the initial speeds: refused (exit 2) when it already carries a
/// particle farther than `stability.max_step_fraction` of the smallest radius, so that
/// contacts would be stepped over (the run stops on the same rule later, exit 3);
/// a warning when a particle starts faster than the characteristic velocity the step
/// was sized for.
fn check_speeds(scene: &Scene, sim: &Simulation) -> Result<Vec<String>> {
    let p = &sim.state.particles;
    // A prescribed velocity that comes later counts as the particle's speed.
    let later = |i: usize| {
        sim.model
            .velocity_changes
            .iter()
            .filter(|c| c.id == p.id[i])
            .map(|c| c.velocity.norm())
            .fold(0.0, f64::max)
    };
    let Some((i, speed)) = (0..p.len())
        .map(|i| (i, p.velocity[i].norm().max(later(i))))
        .max_by(|a, b| a.1.total_cmp(&b.1))
    else {
        return Ok(Vec::new());
    };
    // Paths and messages name the particle as the scene does, whatever its index.
    let (k, id) = (p.id[i] as usize - 1, p.id[i]);
    let path = match (k < scene.particles.len(), p.prescribed[i]) {
        (true, false) => format!("particles[{k}].velocity"),
        (true, true) => format!("particles[{k}].prescribed_velocity"),
        (false, _) => "insert".to_string(),
    };
    let smallest = sim.smallest_radius();
    let fraction = sim.model.limits.max_step_fraction;
    if speed * sim.state.dt > fraction * smallest {
        return Err(TampError::input(
            path,
            format!(
                "{speed:e} m/s moves particle {id} {:.3e} m in one step of {:.3e} s, more than {fraction} of the smallest radius {smallest:e} m (stability.max_step_fraction), so contacts would be stepped over: raise time_step.characteristic_velocity to this speed or give a smaller time_step.fixed",
                speed * sim.state.dt,
                sim.state.dt
            ),
        ));
    }
    let mut warnings = Vec::new();
    if let Some(v) = scene.time_step.characteristic_velocity
        && speed > v
    {
        warnings.push(format!(
            "{path}: particle {id} starts at {speed:e} m/s, faster than time_step.characteristic_velocity = {v:e} m/s, the impact speed the step was sized for"
        ));
    }
    Ok(warnings)
}

/// The run's step count `steps` at the step `dt`, refused (exit 2, naming the fields that set it) beyond
/// `run::MAX_STEPS` or when its predicted wall time exceeds `run.max_wall_time`.
fn check_length(scene: &Scene, sim: &Simulation, dt: f64, steps: f64) -> Result<()> {
    let step_source = if scene.time_step.fixed.is_some() {
        "time_step.fixed"
    } else {
        "chosen from time_step"
    };
    let (path, said) = match scene.run.duration {
        Some(d) if scene.run.steps.is_none() => (
            "run.duration",
            format!("{d:e} s at a step of {dt:e} s ({step_source})"),
        ),
        _ => ("run.steps", "the run".to_string()),
    };
    if steps.is_nan() || steps > super::run::MAX_STEPS {
        return Err(TampError::input(
            path,
            format!(
                "{said} is {steps:e} steps, more than 2^53 = {:e}: beyond it the times n·Δt are not all distinct doubles",
                super::run::MAX_STEPS
            ),
        ));
    }
    let bodies = (sim.state.particles.len() + sim.state.still_to_pour()).max(1);
    let predicted = steps * bodies as f64 * COST_PER_PARTICLE_STEP;
    let limit = scene
        .run
        .max_wall_time
        .unwrap_or(super::run::DEFAULT_MAX_WALL_TIME);
    if predicted > limit {
        return Err(TampError::input(
            path,
            format!(
                "{said} is {steps:e} steps of {bodies} particles, predicted to take {predicted:.3e} s of wall time ({COST_PER_PARTICLE_STEP:e} s per particle-step), more than run.max_wall_time = {limit:e} s; raise run.max_wall_time if the run is meant to be this long"
            ),
        ));
    }
    Ok(())
}

/// The scene's `prescribed_velocity_changes` at the step `dt` puts them on (step 0 for
/// an infinite `dt`: the velocities alone, before the step is chosen).
fn velocity_changes(scene: &Scene, dt: f64) -> Result<Vec<VelocityChange>> {
    let steps = if dt.is_finite() {
        super::particles::velocity_change_steps(scene, dt)?
    } else {
        let all = scene.particles.iter().enumerate().flat_map(|(k, p)| {
            p.prescribed_velocity_changes
                .iter()
                .map(move |c| (0, k, v3(&c.velocity)))
        });
        all.collect()
    };
    Ok(steps
        .into_iter()
        .map(|(step, k, velocity)| VelocityChange {
            step,
            // Explicit particles are placed first: particles[k] has id k + 1.
            id: k as u64 + 1,
            velocity,
        })
        .collect())
}

/// The simulation a validated scene describes, its time step chosen, and what the
/// choice printed.
pub fn build(scene: &Scene) -> Result<BuiltScene> {
    super::memory::check(scene, None)?;
    let materials: Vec<Material> = super::materials::build(&scene.materials);
    let material_id = |name: &str| {
        materials
            .iter()
            .position(|m| m.name == name)
            .expect("validated material name")
    };

    let pair_table = super::contact::pair_table(&scene.contact, &materials, &material_id);

    let walls = super::walls::build(&scene.walls, &material_id, &scene.base_dir)?;
    let space = super::physics::space(scene.periodic.as_ref());

    let (mut particles, sources) =
        super::particles::place(scene, &materials, &material_id, &walls, &space)?;

    let law = scene.contact.law();
    // Particles still to be poured count: the skin must suit the smallest of them.
    let r_min = particles
        .radius
        .iter()
        .cloned()
        .chain(
            sources
                .iter()
                .map(|s| s.radius.min_radius())
                .filter(|&r| r > 0.0),
        )
        .fold(f64::INFINITY, f64::min);
    super::physics::check_period(
        &space,
        &particles,
        &sources,
        &law,
        scene.broad_phase.skin_fraction * r_min,
    )?;
    let detector = scene.broad_phase.kind.detector();
    if scene.broad_phase.sort {
        let r_max = particles.largest_radius();
        let edge = 2.0 * r_max + scene.broad_phase.skin_fraction * r_min;
        particles.permute(&locality::cell_order(&particles.position, edge));
    }
    let detection = Detection {
        detector,
        skin: scene.broad_phase.skin_fraction * r_min,
        reach: law.reach(),
        space,
    };
    // A growth stage starts from the initial fraction of every radius; the
    // simulation is built at that size so no force is ever computed at full size.
    let target_radius = particles.radius.clone();
    if let Some(g) = &scene.growth {
        particles
            .radius
            .iter_mut()
            .for_each(|r| *r *= g.initial_fraction);
    }
    let mut model = Model {
        materials,
        pair_table,
        law,
        gravity: scene.gravity.map(|g| v3(&g)),
        rotation: scene.rotation.is_some(),
        inertia_scale: super::physics::inertia_scale(scene.rotation.as_ref()),
        inertia_radius: scene
            .rotation
            .as_ref()
            .map_or(Default::default(), |r| r.inertia_radius),
        walls,
        sources,
        growth: None,
        detection,
        limits: scene.stability.limits(),
        velocity_changes: Vec::new(),
    };
    // The later velocities, which the step is sized for too; their steps follow from it.
    model.velocity_changes = velocity_changes(scene, f64::INFINITY)?;
    let mut sim = Simulation::new(model, particles)?;
    if let Some(g) = &scene.growth {
        let growth = Growth {
            duration: g.duration,
            initial_fraction: g.initial_fraction,
        };
        sim.set_growth(growth, target_radius);
    }
    let ts = &scene.time_step;
    let mut warnings = Vec::new();
    let mut notes = Vec::new();
    let model = crate::accuracy::model::for_law(&sim.model.law);
    let accuracy = match (ts.accuracy, ts.stated(), model) {
        (Some(a), _, _) => Some(a),
        (None, false, Some(_)) => Some(DEFAULT_ACCURACY),
        (None, false, None) => {
            notes.push(format!(
                "time step: the scene states none and its contact law has no error model (docs/accuracy-cost.md), so alpha = {DEFAULT_ALPHA} (Rojek eq 26)"
            ));
            None
        }
        (None, true, _) => None,
    };
    // The characteristic velocity: the scene's, else the one its motions imply —
    // always for an accuracy, otherwise only where the step needs one and has none.
    let implied = || {
        let v = crate::accuracy::velocity::implied(&sim);
        (v.speed > 0.0).then(|| {
            (
                v.speed,
                format!("characteristic velocity {:.4e} m/s: {}", v.speed, v.source),
            )
        })
    };
    // The accuracy's step; a default accuracy the scene's laws or motions cannot
    // serve gives way to alpha, an explicit one is an input error.
    let mut by_accuracy = None;
    if let Some(a) = accuracy {
        let (v, said) = match ts.characteristic_velocity {
            Some(v) => (
                v,
                format!("characteristic velocity {v:e} m/s (the scene's)"),
            ),
            None => implied().unwrap_or((0.0, "no characteristic velocity: nothing moves".into())),
        };
        let critical = sim.critical_time_step((v > 0.0).then_some(v));
        match crate::accuracy::step::choose(&sim, a, v, critical) {
            Ok(choice) => by_accuracy = Some((a, choice, said, critical)),
            Err(rule) if ts.accuracy.is_none() => notes.push(format!(
                "time step: the default accuracy {a:e} does not apply ({rule}), so alpha = {DEFAULT_ALPHA} (Rojek eq 26)"
            )),
            Err(rule) => return Err(TampError::input("time_step.accuracy", rule)),
        }
    }
    let (dt_estimate, dt, chosen) = if let Some((a, choice, said, critical)) = by_accuracy {
        let dt_estimate = critical.map(|c| ts.alpha() * c);
        (dt_estimate, choice.dt, Some((a, choice, said)))
    } else {
        let mut dt_estimate = sim
            .critical_time_step(ts.characteristic_velocity)
            .map(|dt| ts.alpha() * dt);
        if dt_estimate.is_none()
            && ts.fixed.is_none()
            && ts.characteristic_velocity.is_none()
            && let Some((v, said)) = implied()
        {
            dt_estimate = sim.critical_time_step(Some(v)).map(|dt| ts.alpha() * dt);
            notes.push(format!("time step: {said}"));
        }
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
            (None, None) if ts.characteristic_velocity.is_some() => {
                return Err(TampError::input(
                    "materials",
                    "give no finite critical time step (Rojek eqs 26–29): check every youngs_modulus and density, or give time_step.fixed",
                ));
            }
            (None, None) => {
                return Err(TampError::input(
                    "time_step.characteristic_velocity",
                    "is required when time_step.fixed is absent, the normal law's stiffness depends on the overlap and nothing in the scene moves",
                ));
            }
        };
        (dt_estimate, dt, None)
    };
    let planned = match (scene.run.steps, scene.run.duration) {
        (Some(s), _) => s as f64,
        (None, Some(d)) => (d / dt).ceil(),
        (None, None) => unreachable!("validated"),
    };
    if dt > 0.0 && dt.is_finite() {
        check_length(scene, &sim, dt, planned)?;
    }
    check_range(scene, &sim, dt, planned)?;
    let steps = planned as u64;
    if let Some((a, choice, said)) = &chosen {
        let (a, choice) = (*a, *choice);
        let bodies = sim.state.particles.len() + sim.state.still_to_pour();
        notes.push(format!(
            "time step: accuracy {a:e}{} ({} error model): dt = {:.4e} s, {:.1} steps per contact (shortest contact {:.4e} s; {said}){}; predicted cost {steps} steps, about {:.2e} s of wall time ({bodies} particles at {:.1e} s per particle-step)",
            if ts.accuracy.is_none() { " (the default: the scene states no step)" } else { "" },
            choice.model.law,
            choice.dt,
            choice.steps_per_contact(),
            choice.contact_duration,
            if choice.stability_bound {
                format!(", bounded by stability at alpha = {STABILITY_ALPHA} (the accuracy alone allows a larger step)")
            } else {
                String::new()
            },
            steps as f64 * bodies.max(1) as f64 * COST_PER_PARTICLE_STEP,
            COST_PER_PARTICLE_STEP,
        ));
    }
    sim.set_time_step(dt)?;
    sim.model.velocity_changes = velocity_changes(scene, dt)?;
    super::memory::check(scene, Some(steps))?;
    warnings.extend(check_speeds(scene, &sim)?);
    Ok(BuiltScene {
        sim,
        dt_estimate,
        steps,
        warnings,
        notes,
        accuracy: chosen.map(|(_, choice, _)| choice),
    })
}
