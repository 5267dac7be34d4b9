//! The resolved scene an external engine is given: a tamp scene in which nothing is
//! left to tamp's generators or estimates. Every particle is explicit (inserted and
//! deposited ones placed), the step is `time_step.fixed` and the length `run.steps`,
//! every default is written out, `output` says what to record, and `resolved_from`
//! keeps the original scene's name and hash. A growth stage stays, with each particle at
//! its final radius: the stage is a rule of the run (every radius a known function of
//! time), not a generator. `tamp run` on it runs the same steps as on the original
//! scene, bit for bit.

use super::Refusal;
use crate::scene::schema::{OutputSpec, ParticleSpec, ResolvedFrom, RunSpec, TimeStepSpec};
use crate::scene::{self, Scene};
use crate::verify::recording::{RecordSpec, Recording};

/// A resolved scene and what reading its recording needs.
#[derive(Clone, Debug)]
pub struct Resolved {
    pub scene: Scene,
    /// SHA-256 of the resolved scene's JSON text, hex.
    pub sha256: String,
    /// The resolved scene as written for the engine.
    pub json: String,
    pub particles: usize,
    pub dt: f64,
    pub steps: u64,
    pub spec: RecordSpec,
}

impl Resolved {
    /// The recording an engine wrote into `file` for this run, from its rows keyed by
    /// (step, id): checked against the particles, steps and frames the run asked for.
    pub fn recording(
        &self,
        file: &std::path::Path,
        rows: &std::collections::BTreeMap<(u64, u64), crate::compare::State>,
    ) -> crate::error::Result<Recording> {
        Recording::from_rows(
            &file.display().to_string(),
            rows,
            self.particles,
            self.dt,
            self.steps,
            self.spec,
        )
    }
}

/// `scene` resolved, its output set to record `spec`; not expressible when a fixed list
/// of particles and steps cannot say what it does.
pub fn resolve(scene: &Scene, spec: RecordSpec) -> Result<Resolved, Refusal> {
    let refuse = |field: &str, why: &str| Err(Refusal::NotExpressible(format!("{field}: {why}")));
    let original = serde_json::to_vec(scene).expect("a scene serialises");
    let built = scene::build(scene)?;
    let sim = &built.sim;
    if sim.state().still_to_pour() > 0 {
        return refuse(
            "insert[].schedule",
            "particles poured during the run are not in the initial list",
        );
    }
    let p = &sim.state().particles;
    let mut order: Vec<usize> = (0..p.len()).collect();
    order.sort_by_key(|&i| p.id[i]);
    let particles = order
        .iter()
        .map(|&i| {
            let prescribed = p.prescribed[i];
            ParticleSpec {
                position: p.position[i].into(),
                // The final radius: a growth stage starts from its fraction of it.
                radius: match scene.growth {
                    Some(_) => sim.state().target_radius[i],
                    None => p.radius[i],
                },
                material: sim.model().materials[p.material[i]].name.clone(),
                velocity: (!prescribed).then(|| p.velocity[i].into()),
                omega: scene.rotation.is_some().then(|| p.omega[i].into()),
                prescribed_velocity: prescribed.then(|| p.velocity[i].into()),
                // Explicit particles come first, id k + 1 for particles[k].
                prescribed_velocity_changes: scene
                    .particles
                    .get(p.id[i] as usize - 1)
                    .map_or(Vec::new(), |s| s.prescribed_velocity_changes.clone()),
            }
        })
        .collect();
    let mut resolved = Scene {
        particles,
        insert: Vec::new(),
        deposit: Vec::new(),
        time_step: TimeStepSpec {
            fixed: Some(sim.dt()),
            ..TimeStepSpec::default()
        },
        run: RunSpec {
            steps: Some(built.steps),
            ..RunSpec::default()
        },
        output: OutputSpec {
            trajectory_every: spec.trajectory_every,
            trajectory_every_step_from: spec.every_step_from,
            forces: spec.forces,
            walls: spec.walls,
            ..OutputSpec::default()
        },
        resolved_from: Some(ResolvedFrom {
            name: scene.name.clone(),
            sha256: scene::sha256_hex(&original),
        }),
        ..scene.clone()
    };
    // The particles are in id order now: renumbering them again would change nothing.
    resolved.broad_phase.sort = false;
    let json = serde_json::to_string_pretty(&resolved).expect("a scene serialises") + "\n";
    Ok(Resolved {
        sha256: scene::sha256_hex(json.as_bytes()),
        json,
        particles: order.len(),
        dt: sim.dt(),
        steps: built.steps,
        spec,
        scene: resolved,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scene(json: &str) -> Scene {
        scene::parse(json).unwrap()
    }

    const INSERTED: &str = r#"{
        "name": "inserted", "seed": 3,
        "materials": [{"name": "glass", "density": 2500, "youngs_modulus": 1e7, "poisson_ratio": 0.3}],
        "contact": {"normal": {"law": "hertz"}},
        "insert": [{"count": 5, "radius": 1e-3, "material": "glass",
                    "region": {"lower": [0, 0, 0], "upper": [0.01, 0.01, 0.01]}, "speed": 0.1}],
        "gravity": [0, 0, -9.81],
        "time_step": {"alpha": 0.2, "characteristic_velocity": 0.5},
        "run": {"duration": 1e-3}
    }"#;

    #[test]
    fn a_resolved_scene_runs_the_same_steps_as_the_original() {
        let original = scene(INSERTED);
        let r = resolve(&original, RecordSpec::EVERY_STEP).unwrap();
        assert_eq!((r.particles, r.scene.insert.len()), (5, 0));
        let again = scene(&r.json);
        let (a, b) = (
            scene::build(&original).unwrap(),
            scene::build(&again).unwrap(),
        );
        assert_eq!((a.steps, a.sim.dt()), (b.steps, b.sim.dt()));
        let (mut a, mut b) = (a.sim, b.sim);
        for _ in 0..50 {
            a.step().unwrap();
            b.step().unwrap();
        }
        assert_eq!(a.state().particles.position, b.state().particles.position);
        assert_eq!(a.state().particles.velocity, b.state().particles.velocity);
        let from = again.resolved_from.expect("provenance kept");
        assert_eq!(from.name, "inserted");
        assert_eq!(from.sha256.len(), 64);
        assert_eq!(again.output.trajectory_every, 1);
    }

    #[test]
    fn a_growth_stage_resolves_to_the_final_radii_and_runs_the_same_steps() {
        let mut original = scene(INSERTED);
        original.growth = Some(crate::scene::schema::GrowthSpec {
            duration: 2e-4,
            initial_fraction: 0.5,
        });
        let r = resolve(&original, RecordSpec::EVERY_STEP).unwrap();
        assert!(r.scene.particles.iter().all(|p| p.radius == 1e-3));
        let growth = r.scene.growth.as_ref().expect("the growth stage kept");
        assert_eq!((growth.duration, growth.initial_fraction), (2e-4, 0.5));
        let (mut a, mut b) = (
            scene::build(&original).unwrap().sim,
            scene::build(&scene(&r.json)).unwrap().sim,
        );
        for _ in 0..400 {
            a.step().unwrap();
            b.step().unwrap();
        }
        assert!(!a.is_growing(), "the run must outlast the growth stage");
        assert_eq!(a.state().particles.radius, b.state().particles.radius);
        assert_eq!(a.state().particles.position, b.state().particles.position);
        assert_eq!(a.state().particles.velocity, b.state().particles.velocity);
    }

    #[test]
    fn what_a_fixed_list_of_particles_and_steps_cannot_say_is_named() {
        let mut s = scene(INSERTED);
        s.insert[0].schedule =
            Some(serde_json::from_str(r#"{"every": 1e-4, "per_event": 1}"#).unwrap());
        let Err(Refusal::NotExpressible(why)) = resolve(&s, RecordSpec::EVERY_STEP) else {
            panic!("a pouring schedule resolved")
        };
        assert!(why.starts_with("insert[].schedule:"), "{why}");
    }
}
