//! Hard cases (issue 8): scenes at the edges of what the integrator and the contact
//! laws must survive. Each test states what it proves; none may end in a NaN.

// NiAl's Poisson ratio 0.318 (Rojek 2016 Table 2) is a material constant, not 1/π.
#![allow(clippy::approx_constant)]

use serde_json::{Value, json};
use tamp::error::TampError;
use tamp::scene;
use tamp::simulation::Simulation;

fn built(v: &Value) -> scene::BuiltScene {
    let s = scene::parse(&v.to_string()).expect("valid scene");
    scene::build(&s).expect("builds")
}

fn all_finite(sim: &Simulation) -> bool {
    let p = &sim.particles;
    (0..p.len()).all(|i| {
        p.position[i].iter().all(|c| c.is_finite())
            && p.velocity[i].iter().all(|c| c.is_finite())
            && p.omega[i].iter().all(|c| c.is_finite())
    })
}

/// Two NiAl spheres (Rojek 2016 Table 2: E = 183 GPa, ν = 0.318, ρ = 5910 kg/m³,
/// R = 10 µm) meeting head-on at relative speed `speed` from a 0.1 µm gap; at 0.2 m/s
/// they touch after 0.5 µs and the Hertz contact lasts about 0.08 µs.
fn nial_pair(speed: f64, damping: Value, time_step: Value) -> Value {
    json!({
        "materials": [{"name": "NiAl", "density": 5910, "youngs_modulus": 183e9, "poisson_ratio": 0.318}],
        "contact": {"normal": {"law": "hertz"}, "damping": damping},
        "particles": [
            {"position": [-10.05e-6, 0, 0], "radius": 10e-6, "material": "NiAl", "velocity": [speed / 2.0, 0, 0]},
            {"position": [10.05e-6, 0, 0], "radius": 10e-6, "material": "NiAl", "velocity": [-speed / 2.0, 0, 0]}
        ],
        "time_step": time_step,
        "run": {"duration": 1e-6}
    })
}

/// Relative speed after the run, over the relative speed before.
fn restitution_after(v: &Value) -> (f64, Simulation) {
    let b = built(v);
    let mut sim = b.sim;
    let before = (sim.particles.velocity[1] - sim.particles.velocity[0]).x;
    sim.run_with(b.steps, |_| {}).expect("stable");
    let after = (sim.particles.velocity[1] - sim.particles.velocity[0]).x;
    (-after / before, sim)
}

/// A time step ten times the critical one (Rojek eq 26 without the safety factor) on
/// micrometre NiAl spheres at Rojek's loading speed must stop the run with the step
/// and the particle or contact named, before any non-finite value appears.
#[test]
fn ten_times_the_critical_step_stops_with_a_diagnostic_not_nan() {
    let probe = built(&nial_pair(
        0.2,
        json!({"kind": "critical_fraction", "xi": 0.9}),
        json!({"alpha": 1.0, "characteristic_velocity": 0.2}),
    ));
    let critical = probe
        .dt_estimate
        .expect("hertz with a characteristic velocity");
    let scene = nial_pair(
        0.2,
        json!({"kind": "critical_fraction", "xi": 0.9}),
        json!({"fixed": 10.0 * critical}),
    );
    let b = built(&scene);
    let mut sim = b.sim;
    let mut error = None;
    for _ in 0..10_000 {
        if let Err(e) = sim.step() {
            error = Some(e);
            break;
        }
        assert!(all_finite(&sim), "non-finite state at step {}", sim.step);
    }
    match error {
        Some(TampError::Unstable { step, what, .. }) => {
            assert!(step > 0, "{what}");
            assert!(
                what.contains("particle") || what.contains("contact"),
                "{what}"
            );
        }
        other => panic!("expected an instability, got {other:?}"),
    }
    assert!(all_finite(&sim), "the state left behind is finite");
}

/// The same pair at α = 0.1 (Rojek's choice) is stable, and with ξ = 0.9 (Rojek's
/// die-compaction damping) it loses almost all of its relative speed.
#[test]
fn nial_micrometre_pair_at_the_paper_loading_is_stable() {
    let (e, sim) = restitution_after(&nial_pair(
        0.2,
        json!({"kind": "critical_fraction", "xi": 0.9}),
        json!({"alpha": 0.1, "characteristic_velocity": 0.2}),
    ));
    assert!(all_finite(&sim));
    assert!((0.0..0.05).contains(&e), "restitution {e}");
}

/// Restitution at LIGGGHTS's limits: e = 1 returns the impact speed (no damping), and
/// e just above 0.05 returns about that. The tolerance is velocity Verlet's error at
/// the non-smooth entry and exit of the contact, first order in dt: measured 7.4e-5 at
/// e = 1 with α = 0.05.
#[test]
fn restitution_limits_one_and_nearly_zero() {
    let time_step = json!({"alpha": 0.05, "characteristic_velocity": 0.2});
    let (e, _) = restitution_after(&nial_pair(
        0.2,
        json!({"kind": "liggghts_restitution", "restitution": 1.0}),
        time_step.clone(),
    ));
    assert!((e - 1.0).abs() < 1e-3, "e = 1 gave {e}");
    let (e, _) = restitution_after(&nial_pair(
        0.2,
        json!({"kind": "liggghts_restitution", "restitution": 0.051}),
        time_step,
    ));
    assert!((e - 0.051).abs() < 0.005, "e = 0.051 gave {e}");
}

/// Critical and over-critical damping (ξ = 1, ξ = 1.5): the pair never gains energy
/// and the state stays finite; the spheres end nearly at rest relative to each other.
#[test]
fn critical_and_overcritical_damping_stay_passive() {
    for xi in [1.0, 1.5] {
        let v = nial_pair(
            0.2,
            json!({"kind": "critical_fraction", "xi": xi}),
            json!({"alpha": 0.1, "characteristic_velocity": 0.2}),
        );
        let b = built(&v);
        let mut sim = b.sim;
        let start = sim.particles.translational_kinetic_energy();
        let mut most = start;
        sim.run_with(b.steps, |s| {
            most = most.max(s.particles.translational_kinetic_energy() + s.stored_energy());
        })
        .expect("stable");
        assert!(all_finite(&sim));
        assert!(
            most <= start * (1.0 + 1e-9),
            "ξ = {xi}: energy rose to {most} from {start}"
        );
        let rel = (sim.particles.velocity[1] - sim.particles.velocity[0]).x;
        assert!(rel.abs() < 0.1 * 0.2, "ξ = {xi}: relative speed {rel} left");
    }
}

/// A sphere placed exactly on the floor (zero overlap) and one straddling the upper
/// face of a periodic axis: both settle under gravity, the second is wrapped into
/// [lo, hi) and meets its partner's image, nothing is lost or non-finite. A centre
/// exactly on the upper face is refused at build, naming the axis.
#[test]
fn sphere_exactly_on_a_wall_and_on_a_periodic_face() {
    let v = json!({
        "materials": [{"name": "glass", "density": 2500, "youngs_modulus": 1e8, "poisson_ratio": 0.25}],
        "contact": {"normal": {"law": "hertz"}, "damping": {"kind": "critical_fraction", "xi": 0.3}},
        "particles": [
            {"position": [0.005, 0.005, 0.001], "radius": 0.001, "material": "glass"},
            {"position": [0.0095, 0.002, 0.004], "radius": 0.001, "material": "glass"}
        ],
        "walls": [{"name": "floor", "material": "glass", "shape": {"kind": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}}],
        "periodic": {"x": [0.0, 0.01], "y": [0.0, 0.01]},
        "gravity": [0, 0, -9.81],
        "time_step": {"alpha": 0.2, "characteristic_velocity": 1.0},
        "run": {"duration": 0.05}
    });
    let mut on_face = v.clone();
    on_face["particles"][1]["position"][0] = json!(0.01);
    let Err(refused) = scene::build(&scene::parse(&on_face.to_string()).unwrap()) else {
        panic!("a centre exactly on the upper periodic face must be refused");
    };
    assert!(refused.to_string().contains("periodic.x"), "{refused}");
    assert_eq!(refused.exit_code(), 2);
    let b = built(&v);
    let mut sim = b.sim;
    sim.run_with(b.steps, |_| {}).expect("stable");
    assert!(all_finite(&sim));
    for i in 0..2 {
        let x = sim.particles.position[i];
        assert!(
            (0.0..0.01).contains(&x.x) && (0.0..0.01).contains(&x.y),
            "{x:?}"
        );
        // Resting on the floor: the centre about one radius up.
        assert!((x.z - 0.001).abs() < 2e-5, "sphere {i} at {x:?}");
    }
}

/// Size ratio 100 in one bed: large spheres (R = 5 mm) and small ones (R = 50 µm)
/// dropped together onto a floor, found by the multigrid broad phase, with the time
/// step set by the small ones. The run stays finite and the small spheres end
/// below where they started (nothing is launched).
#[test]
fn size_ratio_100_in_one_bed() {
    let v = json!({
        "seed": 7,
        "materials": [{"name": "glass", "density": 2500, "youngs_modulus": 1e7, "poisson_ratio": 0.25}],
        "contact": {"normal": {"law": "hertz"}, "damping": {"kind": "critical_fraction", "xi": 0.5}},
        "insert": [
            {"count": 4, "radius": 0.005, "material": "glass", "region": {"lower": [0, 0, 0], "upper": [0.03, 0.03, 0.02]}},
            {"count": 300, "radius": 5e-5, "material": "glass", "region": {"lower": [0, 0, 0], "upper": [0.03, 0.03, 0.02]}}
        ],
        "walls": [{"name": "floor", "material": "glass", "shape": {"kind": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}}],
        "periodic": {"x": [0.0, 0.03], "y": [0.0, 0.03]},
        "gravity": [0, 0, -9.81],
        "time_step": {"alpha": 0.2, "characteristic_velocity": 1.0},
        "broad_phase": {"kind": "multigrid"},
        "run": {"steps": 4000}
    });
    let b = built(&v);
    let mut sim = b.sim;
    let start: Vec<f64> = sim.particles.position.iter().map(|x| x.z).collect();
    sim.run_with(b.steps, |_| {}).expect("stable");
    assert!(all_finite(&sim));
    for (i, (x, z0)) in sim.particles.position.iter().zip(&start).enumerate() {
        assert!(x.z <= z0 + 1e-6, "sphere {i} rose from {z0} to {}", x.z);
    }
}
