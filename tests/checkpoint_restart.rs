//! Restart checkpoints: a captured state survives its text bit for bit; a run killed and
//! resumed from its checkpoint ends bit for bit as the uninterrupted run, through the
//! library and through `tamp run --resume`; a checkpoint of another scene or particle
//! count is refused.

mod common;

use serde_json::{Value, json};
use std::path::{Path, PathBuf};
use std::process::Stdio;
use std::time::{Duration, Instant};
use tamp::particles::Vec3;
use tamp::simulation::Simulation;
use tamp::simulation::State;

/// A die with a lid coming down: 300 spinning frictional spheres (Mindlin–Deresiewicz,
/// so contacts keep tangential history, with each other and with the walls) fly about
/// under gravity while 30 more are poured in from above (the first 470 steps); the lid
/// then compacts them (some 500 contacts at step 8000).
fn die_scene(steps: u64, checkpoint_every: u64) -> Value {
    json!({
        "name": "checkpointed die",
        "seed": 3,
        "materials": [{"name": "glass", "density": 2500, "youngs_modulus": 6e7, "poisson_ratio": 0.25}],
        "contact": {
            "normal": {"law": "hertz"},
            "damping": {"kind": "critical_fraction", "xi": 0.3},
            "tangential": {"law": "mindlin_deresiewicz", "friction": 0.4}
        },
        "insert": [
            {"count": 300, "material": "glass", "radius": {"min": 0.0004, "max": 0.0005},
             "region": {"lower": [-0.004, -0.004, 0.0], "upper": [0.004, 0.004, 0.008]},
             "speed": 0.5, "spin": 200},
            {"count": 30, "material": "glass", "radius": {"min": 0.0004, "max": 0.0005},
             "region": {"lower": [-0.004, -0.004, 0.008], "upper": [0.004, 0.004, 0.0095]},
             "speed": 0.5, "schedule": {"start": 0.0, "every": 0.0002, "per_event": 4}}
        ],
        "walls": [
            {"name": "die", "material": "glass",
             "shape": {"kind": "box", "lower": [-0.004, -0.004, 0.0], "upper": [0.004, 0.004, 0.03],
                       "open": ["+z"]}},
            {"name": "lid", "material": "glass",
             "shape": {"kind": "plane", "point": [0, 0, 0.0096], "normal": [0, 0, -1]},
             "motion": {"kind": "displacement", "x": "0.0", "y": "0.0", "z": "-0.2 * t"}}
        ],
        "gravity": [0, 0, -9.81],
        "rotation": {},
        "time_step": {"alpha": 0.2, "characteristic_velocity": 1.0},
        "run": {"steps": steps},
        "output": {"series_every": 50, "trajectory_every": 1000, "vtk_every": 2000,
                   "checkpoint_every": checkpoint_every}
    })
}

fn build(scene: &Value) -> Simulation {
    common::built(scene).sim
}

fn steps(sim: &mut Simulation, n: u64) {
    for _ in 0..n {
        sim.step().unwrap();
    }
}

fn bits(v: &[Vec3]) -> Vec<u64> {
    v.iter()
        .flat_map(|x| x.iter().map(|c| c.to_bits()))
        .collect()
}

/// Two spheres on a floor with friction and a pouring source: every kind of state.
fn poured_scene(extra_particle: bool) -> Simulation {
    build(&poured_scene_value(extra_particle))
}

fn poured_scene_value(extra_particle: bool) -> Value {
    let mut particles = vec![
        json!({"position": [0, 0, 0.001], "radius": 0.001, "material": "glass"}),
        json!({"position": [0.0015, 0, 0.0028], "radius": 0.001, "material": "glass"}),
    ];
    if extra_particle {
        particles
            .push(json!({"position": [0.005, 0, 0.002], "radius": 0.001, "material": "glass"}));
    }
    json!({
        "name": "checkpoint round trip",
        "materials": [{"name": "glass", "density": 2500, "youngs_modulus": 6e7, "poisson_ratio": 0.25}],
        "contact": {
            "normal": {"law": "hertz"},
            "damping": {"kind": "critical_fraction", "xi": 0.3},
            "tangential": {"law": "mindlin_deresiewicz", "friction": 0.4}
        },
        "particles": particles,
        "insert": [{
            "count": 3, "material": "glass", "radius": {"min": 0.0008, "max": 0.001},
            "region": {"lower": [-0.004, -0.004, 0.006], "upper": [0.004, 0.004, 0.010]},
            "schedule": {"start": 0.0, "every": 0.001, "per_event": 1}
        }],
        "walls": [{"name": "floor", "material": "glass",
                   "shape": {"kind": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}}],
        "gravity": [0, 0, -9.81],
        "rotation": {},
        "time_step": {"alpha": 0.2, "characteristic_velocity": 1.0},
        "run": {"steps": 1}
    })
}

/// The bits of every public double of a simulation's state, in a fixed order.
fn public_bits(sim: &Simulation) -> Vec<u64> {
    let p = &sim.state().particles;
    let mut out = bits(&p.position);
    for v in [
        &p.velocity,
        &p.omega,
        &p.force,
        &p.torque,
        &sim.state().wall_force,
    ] {
        out.extend(bits(v));
    }
    let scalars = p.radius.iter().chain(&p.mass).chain(&p.inertia);
    let dt = sim.dt();
    let scalars = scalars.chain(&sim.state().target_radius).chain([
        &dt,
        &sim.state().time,
        &sim.state().energy.external_work,
        &sim.state().max_overlap_ratio,
    ]);
    out.extend(scalars.map(|x| x.to_bits()));
    out
}

#[test]
fn captured_state_round_trips_bit_for_bit() {
    let mut sim = poured_scene(false);
    steps(&mut sim, 500);
    assert!(sim.state().particles.len() > 2, "the source has poured");
    // Doubles that a careless text format loses, put into the run through a restore
    // (the one way a whole state enters a run).
    let mut edited = sim.state().clone();
    edited.particles.position[0].y = -0.0;
    edited.particles.velocity[0].x = 0.1 + 0.2;
    edited.particles.omega[1] = Vec3::new(f64::from_bits(1), f64::MIN_POSITIVE / 3.0, -1e-310);
    edited.energy.external_work = -0.0;
    sim.resume(edited).unwrap();
    let state = sim.state().clone();
    let json = serde_json::to_string(&state).unwrap();
    let back: State = serde_json::from_str(&json).unwrap();
    assert_eq!(serde_json::to_string(&back).unwrap(), json);

    // Restored into a fresh build, every double is the captured one: the public ones
    // compared bit by bit, the rest (contact histories, sources, energy book) by the
    // text of a second capture.
    let mut fresh = poured_scene(false);
    fresh.resume(back).unwrap();
    assert_eq!(public_bits(&fresh), public_bits(&sim));
    assert_eq!(serde_json::to_string(&fresh.state()).unwrap(), json);
}

#[test]
fn restore_refuses_a_state_of_another_particle_count() {
    let state = poured_scene(false).state().clone();
    let err = poured_scene(true).resume(state).unwrap_err();
    assert_eq!(err.exit_code(), 2);
    assert!(
        err.to_string()
            .starts_with("checkpoint.particles: holds 2 particles, but the scene builds 3"),
        "{err}"
    );
}

/// `poured_scene` without friction: its contacts keep nothing.
fn frictionless_poured_scene() -> Simulation {
    let mut scene = poured_scene_value(false);
    scene["contact"]
        .as_object_mut()
        .unwrap()
        .remove("tangential");
    build(&scene)
}

#[test]
fn resume_refuses_the_contact_states_of_other_laws() {
    let mut sim = poured_scene(false);
    steps(&mut sim, 200);
    // Typed in memory: the states of Mindlin-Deresiewicz contacts into a frictionless run.
    let err = frictionless_poured_scene()
        .resume(sim.state().clone())
        .unwrap_err();
    assert_eq!(err.exit_code(), 2);
    assert!(
        err.to_string()
            .starts_with("checkpoint.contacts: holds the states of other contact laws"),
        "{err}"
    );
    // Read from JSON: they do not parse as the frictionless laws' (empty) states.
    let read: State = serde_json::from_str(&serde_json::to_string(&sim.state()).unwrap()).unwrap();
    let err = frictionless_poured_scene().resume(read).unwrap_err();
    assert_eq!(err.exit_code(), 2);
    assert!(
        err.to_string().starts_with("checkpoint.contacts: "),
        "{err}"
    );
}

/// The die scene run for 2000 steps at once, and run for 250, captured as text,
/// resumed in a simulation built afresh and run for the other 1750. It stops while the
/// source is still pouring, so its random generator goes on too.
fn whole_and_resumed(scene: &Value) -> (Simulation, Simulation) {
    let (n, m) = (250, 1750);
    let mut whole = build(scene);
    steps(&mut whole, n + m);
    let mut first = build(scene);
    steps(&mut first, n);
    assert!(first.state().sources[0].remaining > 0 && first.state().particles.len() > 300);
    let json = serde_json::to_string(&first.state()).unwrap();
    drop(first);
    let mut resumed = build(scene);
    resumed
        .resume(serde_json::from_str::<State>(&json).unwrap())
        .unwrap();
    steps(&mut resumed, m);
    (whole, resumed)
}

#[test]
fn restored_simulation_steps_on_bit_for_bit() {
    let (whole, resumed) = whole_and_resumed(&die_scene(1, 0));

    let (a, b) = (&whole.state().particles, &resumed.state().particles);
    assert_eq!(a.len(), 330, "the source has poured all");
    assert_eq!(bits(&a.position), bits(&b.position));
    assert_eq!(bits(&a.velocity), bits(&b.velocity));
    assert_eq!(bits(&a.omega), bits(&b.omega));
    assert_eq!(
        whole.state().neighbors.pairs,
        resumed.state().neighbors.pairs
    );
    let history = |s: &Simulation| format!("{:?}", s.contact_states());
    assert!(
        (0..whole.state().neighbors.pairs.len()).any(|k| whole
            .contact_states()
            .pair_tangential(k)
            .is_some_and(|t| t.norm() > 0.0)),
        "contacts carry tangential history"
    );
    assert_eq!(history(&whole), history(&resumed));
    // Everything else, wall histories and the energy book included: doubles print as
    // the shortest decimal that reads back to them, so equal text means equal bits.
    assert_eq!(
        serde_json::to_string(&whole.state()).unwrap(),
        serde_json::to_string(&resumed.state()).unwrap()
    );
}

use common::{run, tamp};

fn write_scene(dir: &Path, name: &str, scene: &Value) -> PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, scene.to_string()).unwrap();
    path
}

#[test]
fn killed_run_resumes_to_identical_outputs() {
    let total = 8000;
    let dir = tempfile::tempdir().unwrap();
    let scene = write_scene(dir.path(), "scene.json", &die_scene(total, 250));
    let (a, b) = (dir.path().join("a"), dir.path().join("b"));

    let o = run(&scene, &a, &[]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));

    let mut child = tamp()
        .args([
            "run",
            scene.to_str().unwrap(),
            "--out",
            b.to_str().unwrap(),
            "--quiet",
        ])
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let checkpoint = b.join("checkpoint.json");
    let started = Instant::now();
    while !checkpoint.exists() {
        assert!(started.elapsed() < Duration::from_secs(30), "no checkpoint");
        std::thread::sleep(Duration::from_millis(2));
    }
    child.kill().unwrap();
    child.wait().unwrap();
    assert!(!b.join("series.csv").exists(), "killed before the end");
    let saved: Value = serde_json::from_slice(&std::fs::read(&checkpoint).unwrap()).unwrap();
    let step = saved["state"]["sim"]["step"].as_u64().unwrap();
    assert!(step > 0 && step < total, "checkpoint at step {step}");

    let o = run(&scene, &b, &["--resume"]);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{stderr}");
    assert!(stderr.contains("resuming from step "), "{stderr}");

    let frames: Vec<String> = (0..=total / 2000)
        .map(|k| format!("vtk/frame_{k:06}.vtk"))
        .collect();
    let files = [
        "series.csv",
        "trajectory.csv",
        "quantities.csv",
        "summary.json",
    ];
    for file in files
        .iter()
        .copied()
        .chain(frames.iter().map(String::as_str))
    {
        let read = |d: &Path| std::fs::read(d.join(file)).unwrap();
        assert!(read(&a) == read(&b), "{file} differs after resuming");
    }
}

#[test]
fn checkpoint_of_another_scene_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let one = write_scene(dir.path(), "one.json", &die_scene(100, 50));
    let o = run(&one, &out, &[]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));

    let other = write_scene(dir.path(), "other.json", &die_scene(200, 50));
    let o = run(&other, &out, &["--resume"]);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{stderr}");
    for scene in [&one, &other] {
        let sha = tamp::scene::sha256_hex(&std::fs::read(scene).unwrap());
        assert!(stderr.contains(&sha), "{stderr} does not name {sha}");
    }
}

#[test]
fn resume_needs_checkpoints() {
    let dir = tempfile::tempdir().unwrap();
    let scene = write_scene(dir.path(), "scene.json", &die_scene(10, 0));
    let o = run(&scene, &dir.path().join("out"), &["--resume"]);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("output.checkpoint_every: must be > 0"),
        "{stderr}"
    );
}

/// The MDR law keeps a state per particle (`State::mdr`: apparent radius, free
/// surface, volumes) beside its contacts' histories: the die of `die_scene` under MDR,
/// stopped while still pouring, resumes to the uninterrupted run's state bit for bit,
/// and its particles have grown.
#[test]
fn an_mdr_run_resumes_bit_for_bit() {
    let mut scene = die_scene(1, 0);
    scene["contact"] = json!({
        "normal": {"law": "mdr", "youngs_modulus": 6e7, "poisson_ratio": 0.25,
                   "yield_stress": 2e5, "surface_energy": 0.0, "bulk_trigger": 0.5,
                   "damping": {"coefficient": 0.5, "form": "stiffness"}},
        "tangential": {"law": "mindlin_deresiewicz", "friction": 0.4}
    });
    let (whole, resumed) = whole_and_resumed(&scene);
    let mdr = whole.state().mdr.as_ref().expect("an mdr state");
    assert_eq!(mdr.len(), 330, "the poured particles have their mdr state");
    assert!(
        mdr.radius
            .iter()
            .zip(&mdr.initial_radius)
            .any(|(r, r0)| r > r0),
        "some particle grew"
    );
    assert_eq!(
        serde_json::to_string(&whole.state()).unwrap(),
        serde_json::to_string(&resumed.state()).unwrap()
    );
}

/// A rolling resistance keeps its displacement ξ in each contact's state beside the
/// sliding history: the die of `die_scene` with LAMMPS's linear history and rolling sds,
/// stopped while still pouring, resumes to the uninterrupted run's state bit for bit,
/// and its contacts hold rolling displacements.
#[test]
fn a_rolling_run_resumes_bit_for_bit() {
    let mut scene = die_scene(1, 0);
    scene["contact"]["tangential"] = json!(
        {"law": "lammps_linear_history", "stiffness": 1e3, "x_gamma_t": 0.5, "friction": 0.4});
    scene["contact"]["rolling"] =
        json!({"law": "sds", "stiffness": 50.0, "damping": 0.0, "friction": 0.3});
    let (whole, resumed) = whole_and_resumed(&scene);
    let states = whole.contact_states().to_json();
    let rolling = states["pairs"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|s| {
            s["tangential"]["rolling"]
                .as_array()
                .unwrap()
                .iter()
                .any(|c| c.as_f64() != Some(0.0))
        })
        .count();
    assert!(rolling > 0, "contacts carry rolling displacements");
    assert_eq!(
        serde_json::to_string(&whole.state()).unwrap(),
        serde_json::to_string(&resumed.state()).unwrap()
    );
}
