//! Property tests over random scenes: a few spheres with radii ratios up to 100,
//! Young's moduli from 1e6 to 4e11 Pa, densities from 1e3 to 2e4 kg/m³, thrown at each
//! other in open space (no walls, no gravity) under a random contact law. Whatever the
//! draw: every value stays finite, linear and angular momentum are conserved (the
//! contact forces are equal and opposite and their torques use lever arms that add up
//! to the centre distance), a dissipative law never gains energy, and numbering the
//! particles the other way round gives the same motion.

use proptest::prelude::*;
use serde_json::{Value, json};
use tamp::particles::Vec3;
use tamp::scene;
use tamp::simulation::Simulation;

#[derive(Clone, Debug)]
struct Draw {
    /// Per sphere: radius as a fraction of the largest (1e-2..1, so ratios up to 100),
    /// lateral offset from the chain's axis in units of its radius, velocity direction.
    spheres: Vec<(f64, [f64; 2], [f64; 3])>,
    youngs_modulus: f64,
    density: f64,
    law: usize,
    xi: f64,
}

const LAWS: [&str; 4] = ["hertz", "hertz+mindlin", "linear+cundall", "hertz+coulomb"];
const R_MAX: f64 = 1e-3;
/// Up to 0.1 m/s, and less where a draw is too soft for it (`speed`).
const SPEED: f64 = 0.1;

/// The draw's speed: at most `SPEED`, and low enough that the heaviest sphere, met at
/// the largest relative speed the chain can have (2.6 × the speed), presses a
/// contact with the smallest sphere to at most a tenth of its radius. Without the
/// cap a soft draw (E = 1 MPa) pinches a 10 µm sphere between two of 0.5–0.8 mm
/// until the overlap passes half its radius and the run stops at the overlap
/// guard: physics outside the law's range, not a numerical failure (found in CI).
fn speed(d: &Draw) -> f64 {
    let radius = |f: f64| f * R_MAX;
    let smallest = d
        .spheres
        .iter()
        .map(|s| radius(s.0))
        .fold(f64::INFINITY, f64::min);
    let largest = d.spheres.iter().map(|s| radius(s.0)).fold(0.0, f64::max);
    let heaviest = d.density * 4.0 / 3.0 * std::f64::consts::PI * largest.powi(3);
    let overlap = 0.1 * smallest;
    let v = match LAWS[d.law] {
        // ½ m v² = ½ k δ², k = E R_MAX (scene_of).
        "linear+cundall" => overlap * (d.youngs_modulus * R_MAX / heaviest).sqrt(),
        // Hertz: δ_max = (15 m v² / (16 E* √R*))^(2/5), R* ≤ the smallest radius.
        _ => {
            let e_star = d.youngs_modulus / (2.0 * (1.0 - 0.3f64 * 0.3));
            (16.0 * e_star * smallest.sqrt() * overlap.powf(2.5) / (15.0 * heaviest)).sqrt()
        }
    };
    SPEED.min(v / 2.6)
}

fn draw() -> impl Strategy<Value = Draw> {
    let sphere = (
        0.01f64..1.0,
        prop::array::uniform2(-0.5f64..0.5),
        prop::array::uniform3(-0.3f64..0.3),
    );
    (
        prop::collection::vec(sphere, 2..7),
        6.0f64..11.6, // log10 E
        3.0f64..4.3,  // log10 ρ
        0..LAWS.len(),
        0.05f64..0.9,
    )
        .prop_map(|(spheres, le, lr, law, xi)| Draw {
            spheres,
            youngs_modulus: 10f64.powf(le),
            density: 10f64.powf(lr),
            law,
            xi,
        })
}

/// The scene of a draw: the spheres in a chain along x, each 0.1 % of its radius
/// from the one before and offset sideways (so contacts are oblique), all moving
/// towards the chain's middle at about 0.1 m/s; particles listed in `order`.
fn scene_of(d: &Draw, order: &[usize]) -> Value {
    let n = d.spheres.len();
    // Each sphere goes as far left as it can while clearing every earlier one by
    // 0.1 % of the radii's sum, so it nearly touches at least one of them.
    let mut centres: Vec<[f64; 3]> = Vec::with_capacity(n);
    let mut x: f64 = 0.0;
    for (k, (f, off, _)) in d.spheres.iter().enumerate() {
        let r = f * R_MAX;
        let (y, z) = (off[0] * r, off[1] * r);
        let mut at = if k == 0 { 0.0 } else { f64::NEG_INFINITY };
        for (j, c) in centres.iter().enumerate() {
            let reach = (d.spheres[j].0 * R_MAX + r) * 1.001;
            let lateral2 = (y - c[1]).powi(2) + (z - c[2]).powi(2);
            at = at.max(c[0] + (reach * reach - lateral2).max(0.0).sqrt());
        }
        x = x.max(at);
        centres.push([at, y, z]);
    }
    let middle = x / 2.0;
    let speed = speed(d);
    let mut particles = Vec::new();
    for &k in order {
        let (f, _, dir) = d.spheres[k];
        let c = centres[k];
        let towards = if c[0] < middle { 1.0 } else { -1.0 };
        particles.push(json!({
            "position": c,
            "radius": f * R_MAX,
            "material": "m",
            "velocity": [(towards + dir[0]) * speed, dir[1] * speed, dir[2] * speed]
        }));
    }
    let (normal, tangential) = match LAWS[d.law] {
        "hertz" => (json!({"law": "hertz"}), Value::Null),
        "hertz+mindlin" => (
            json!({"law": "hertz"}),
            json!({"law": "mindlin_deresiewicz", "friction": 0.4}),
        ),
        "linear+cundall" => (
            json!({"law": "linear", "stiffness": d.youngs_modulus * R_MAX}),
            json!({"law": "cundall_strack", "friction": 0.4, "stiffness": 0.8 * d.youngs_modulus * R_MAX}),
        ),
        _ => (
            json!({"law": "hertz"}),
            json!({"law": "coulomb", "friction": 0.4}),
        ),
    };
    let mut contact =
        json!({"normal": normal, "damping": {"kind": "critical_fraction", "xi": d.xi}});
    if !tangential.is_null() {
        contact["tangential"] = tangential;
    }
    json!({
        "materials": [{"name": "m", "density": d.density, "youngs_modulus": d.youngs_modulus, "poisson_ratio": 0.3}],
        "contact": contact,
        "particles": particles,
        "rotation": {},
        "time_step": {"alpha": 0.1, "characteristic_velocity": 0.2},
        "run": {"steps": 3000}
    })
}

fn run(v: &Value) -> Simulation {
    let s = scene::parse(&v.to_string()).expect("valid scene");
    let b = scene::build(&s).expect("builds");
    let mut sim = b.sim;
    sim.run_with(b.steps, |_| {}).expect("stable");
    sim
}

fn momenta(sim: &Simulation) -> (Vec3, Vec3, f64) {
    let p = &sim.state().particles;
    let mut linear = Vec3::zeros();
    let mut angular = Vec3::zeros();
    let mut scale = 0.0;
    for i in 0..p.len() {
        let mv = p.velocity[i] * p.mass[i];
        linear += mv;
        angular += p.position[i].cross(&mv) + p.omega[i] * p.inertia[i];
        scale += mv.norm() * (p.position[i].norm() + p.radius[i]);
    }
    (linear, angular, scale)
}

proptest! {
    // A fixed seed: CI must judge the same draws every time (a new failure found by
    // exploring with PROPTEST_RNG_SEED goes into the regression file or a named test).
    #![proptest_config(ProptestConfig {
        cases: 64,
        rng_seed: proptest::test_runner::RngSeed::Fixed(8),
        ..ProptestConfig::default()
    })]

    #[test]
    fn random_scenes_conserve_momentum_lose_energy_and_ignore_numbering(d in draw()) {
        let n = d.spheres.len();
        let forward: Vec<usize> = (0..n).collect();
        let backward: Vec<usize> = (0..n).rev().collect();
        let scene = scene_of(&d, &forward);
        let first = scene::build(&scene::parse(&scene.to_string()).unwrap()).unwrap();
        let p0 = momenta(&first.sim);
        let e0 = first.sim.state().particles.translational_kinetic_energy();
        let sim = run(&scene);
        let p = &sim.state().particles;
        prop_assert!((0..n).all(|i| p.position[i].iter().chain(p.velocity[i].iter()).chain(p.omega[i].iter()).all(|c| c.is_finite())));
        // The draw must have produced collisions, or it proves nothing.
        let exchanged = (0..n).any(|i| (p.velocity[i] - first.sim.state().particles.velocity[i]).norm() > 0.01 * speed(&d));
        prop_assume!(exchanged, "no collision within the run");
        let (lin, ang, _) = momenta(&sim);
        let lin_scale: f64 = (0..n).map(|i| p.mass[i] * 2.0 * speed(&d)).sum();
        prop_assert!((lin - p0.0).norm() <= 1e-12 * lin_scale, "linear momentum moved by {:e}", (lin - p0.0).norm());
        prop_assert!((ang - p0.1).norm() <= 1e-10 * p0.2.max(1e-30), "angular momentum moved by {:e} of {:e}", (ang - p0.1).norm(), p0.2);
        // Every law drawn dissipates (ξ > 0); velocity Verlet may add a first-order
        // error at the non-smooth entry and exit of each contact (7e-5 of the impact
        // energy at α = 0.05 for an undamped Hertz impact, tests/hard_cases.rs).
        let e1 = p.translational_kinetic_energy() + p.rotational_kinetic_energy() + sim.stored_energy();
        prop_assert!(e1 <= e0 * (1.0 + 1e-3), "energy rose from {e0:e} to {e1:e}");
        // Renumbered: the same motion, particle k of one run is particle n-1-k of the other.
        let other = run(&scene_of(&d, &backward));
        for i in 0..n {
            let j = n - 1 - i;
            let dx = (p.position[i] - other.state().particles.position[j]).norm();
            prop_assert!(dx <= 1e-9 * p.radius[i], "particle {i} differs by {dx:e} m when renumbered");
        }
    }
}

/// The draw CI's proptest shrank to on 2026-11-21 (before `speed` capped soft draws):
/// a 10 µm sphere between spheres of 0.46 and 0.79 mm, E = 1 MPa, Hertz + Mindlin.
#[test]
fn soft_pinch_found_in_ci_runs_within_the_overlap_guard() {
    let d = Draw {
        spheres: vec![
            (
                0.4597561942579398,
                [0.27292531116486635, -0.07723215866008712],
                [
                    -0.0272896490258215,
                    -0.2787361979646387,
                    -0.027437837860321727,
                ],
            ),
            (0.01, [0.0, 0.0], [0.0, 0.0, 0.0]),
            (0.06479751808584545, [0.0, 0.0], [0.0, 0.0, 0.0]),
            (0.788914868174379, [0.0, 0.0], [0.0, 0.0, 0.0]),
        ],
        youngs_modulus: 1e6,
        density: 1000.0,
        law: 1,
        xi: 0.05,
    };
    assert!(speed(&d) < SPEED);
    let sim = run(&scene_of(&d, &[0, 1, 2, 3]));
    assert!((0..4).all(|i| {
        sim.state().particles.velocity[i]
            .iter()
            .all(|c| c.is_finite())
    }));
}

/// Every registered law (`tamp::contact::registry`), alone and with every registered
/// tangential law, on one scene: three steel spheres of 1, 0.5 and 0.8 mm a few µm
/// apart thrown obliquely into each other at 0.1 m/s for 1 ms, with rotation and Hollomon constants (for
/// the laws that read them). Each combination scenes accept must stay finite,
/// conserve linear and angular momentum, and give the same motion when the particles
/// are numbered the other way round. No energy check: not every law is passive
/// (pure Storåkers gains energy below its threshold, see its unit tests; σ0 = 0.1 GPa
/// puts that threshold at 10 nm, so these impacts of a few µm run well beyond it and
/// the run's energy guard does not stop them).
#[test]
fn every_registered_law_conserves_momentum_and_ignores_numbering() {
    use tamp::contact::registry;
    let spheres = [
        ([0.0, 0.0, 0.0], 1e-3, [0.1, 0.02, 0.0]),
        ([1.46e-3, 0.35e-3, 0.0], 0.5e-3, [-0.1, 0.0, 0.03]),
        ([2.71e-3, 0.35e-3, 0.36e-3], 0.8e-3, [-0.12, -0.01, 0.0]),
    ];
    let scene = |normal: Value, tangential: Option<Value>, order: &[usize]| {
        let mut contact = json!({ "normal": normal });
        if let Some(t) = tangential {
            contact["tangential"] = t;
        }
        let particles: Vec<Value> = order
            .iter()
            .map(|&k| {
                let (position, radius, velocity) = spheres[k];
                json!({"position": position, "radius": radius, "material": "steel", "velocity": velocity})
            })
            .collect();
        json!({
            "materials": [{"name": "steel", "density": 7800, "youngs_modulus": 2e11, "poisson_ratio": 0.3,
                           "hollomon": {"exponent": 0.15, "strength": 1e8}}],
            "contact": contact,
            "particles": particles,
            "rotation": {},
            "time_step": {"alpha": 0.2, "characteristic_velocity": 0.2},
            "run": {"duration": 1e-3}
        })
    };
    let tangential: Vec<Option<Value>> = std::iter::once(None)
        .chain(registry::tangential_laws().into_iter().map(|t| {
            let mut v = serde_json::to_value(t).unwrap();
            v["friction"] = json!(0.4);
            Some(v)
        }))
        .collect();
    let mut checked = 0;
    for normal in registry::normal_laws() {
        for t in &tangential {
            let normal_json = serde_json::to_value(normal).unwrap();
            let forward = scene(normal_json.clone(), t.clone(), &[0, 1, 2]);
            // Combinations scenes refuse (liggghts_history beside a law LIGGGHTS lacks).
            let Ok(parsed) = scene::parse(&forward.to_string()) else {
                continue;
            };
            let label = format!(
                "{} + {:?}",
                normal.name(),
                t.as_ref().map(|t| t["law"].clone())
            );
            let first = scene::build(&parsed).unwrap().sim;
            let p0 = momenta(&first);
            let run = |v: &Value| {
                let b = scene::build(&scene::parse(&v.to_string()).unwrap()).unwrap();
                let mut sim = b.sim;
                sim.run_with(b.steps, |_| {})
                    .unwrap_or_else(|e| panic!("{label}: {e}"));
                sim
            };
            let sim = run(&forward);
            let p = &sim.state().particles;
            assert!(
                (0..3).all(|i| p.position[i]
                    .iter()
                    .chain(p.omega[i].iter())
                    .all(|c| c.is_finite())),
                "{label}: not finite"
            );
            assert!(
                (0..3).any(|i| (p.velocity[i] - first.state().particles.velocity[i]).norm() > 1e-3),
                "{label}: no collision"
            );
            let (lin, ang, _) = momenta(&sim);
            let lin_scale: f64 = (0..3).map(|i| p.mass[i] * 0.2).sum();
            assert!(
                (lin - p0.0).norm() <= 1e-12 * lin_scale,
                "{label}: linear momentum"
            );
            assert!(
                (ang - p0.1).norm() <= 1e-10 * p0.2,
                "{label}: angular momentum"
            );
            let other = run(&scene(normal_json, t.clone(), &[2, 1, 0]));
            for i in 0..3 {
                let dx = (p.position[i] - other.state().particles.position[2 - i]).norm();
                assert!(dx <= 1e-9 * p.radius[i], "{label}: renumbered, {dx:e} m");
            }
            checked += 1;
        }
    }
    let laws = registry::normal_laws().len() * tangential.len();
    assert!(
        checked * 10 >= laws * 8,
        "only {checked} of {laws} combinations were buildable"
    );
}
