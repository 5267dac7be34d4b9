//! Physics regressions found in review: each test states what it protects.

mod common;

use serde_json::json;
use tamp::scene;

fn build(v: serde_json::Value) -> scene::BuiltScene {
    common::built(&v)
}

/// A sphere resting on a floor while sliding at t = 0: the first force evaluation
/// must not advance the tangential spring (it once ran with a 1 s placeholder step
/// and started every such contact on the friction cone).
#[test]
fn initial_contact_starts_with_an_unloaded_spring() {
    let b = build(json!({
        "materials": [{"name": "m", "density": 2500, "youngs_modulus": 1e7, "poisson_ratio": 0.3}],
        "contact": {"normal": {"law": "hertz"},
                    "tangential": {"law": "cundall_strack", "stiffness": 100, "friction": 0.5}},
        "particles": [{"position": [0, 0, 0.000999], "radius": 0.001, "material": "m", "velocity": [0.1, 0, 0]}],
        "walls": [{ "material": "m", "shape": {"kind": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}}],
        "stability": {"initial_overlap_tolerance": 0.01},
        "time_step": {"alpha": 0.1, "characteristic_velocity": 0.1},
        "run": {"steps": 1}
    }));
    let f = b.sim.state().particles.force[0];
    assert_eq!(
        f.x, 0.0,
        "tangential force at t = 0 must be zero, got {f:?}"
    );
    assert!(b.sim.dissipated_energy().abs() < 1e-15);
}

/// A free sphere bouncing off a prescribed (immovable) sphere must see the same
/// damping as against a wall: the prescribed body counts as infinite mass.
#[test]
fn prescribed_partner_damps_like_a_wall() {
    let restitution = |target: serde_json::Value, walls: serde_json::Value| {
        let mut particles = vec![
            json!({"position": [0, 0, 0.0011], "radius": 0.001, "material": "m", "velocity": [0, 0, -0.1]}),
        ];
        if !target.is_null() {
            particles.push(target);
        }
        let mut b = build(json!({
            "materials": [{"name": "m", "density": 2500, "youngs_modulus": 1e7, "poisson_ratio": 0.3}],
            "contact": {"normal": {"law": "linear", "stiffness": 1e4}, "damping": {"kind": "critical_fraction", "xi": 0.2}},
            "particles": particles, "walls": walls,
            "time_step": {"alpha": 0.01}, "run": {"steps": 1}
        }));
        for _ in 0..200_000 {
            b.sim.step().unwrap();
            if b.sim.state().particles.velocity[0].z > 0.0 && b.sim.contact_count() == 0 {
                break;
            }
        }
        b.sim.state().particles.velocity[0].z / 0.1
    };
    let against_wall = restitution(
        serde_json::Value::Null,
        json!([{ "material": "m", "shape": {"kind": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}}]),
    );
    let against_driven = restitution(
        json!({"position": [0, 0, -0.001], "radius": 0.001, "material": "m", "prescribed_velocity": [0, 0, 0]}),
        json!([]),
    );
    assert!(
        (against_wall - against_driven).abs() < 1e-3,
        "wall {against_wall}, driven sphere {against_driven}"
    );
}

/// LAMMPS's tangential dashpot γ_t = x_γ,t c_n damps the tangential mode, which then
/// limits the critical step by Rojek eq 28 with its own damping ratio: one free sphere
/// (R = 1 mm, ρ = 2500, L = 1 + mR²/I = 7/2), `linear` k_n = 1e4 N/m with a `constant`
/// dashpot c_n = 0.1 N·s/m, `lammps_linear_history` k_t = 1e4 N/m (L k_t > k_n: the
/// tangential mode is the stiffest); x_γ,t = 5 gives ξ_t = L x_γ,t c_n / (2√(L k_t m))
/// = 1.45 and a step 2.9 times shorter than with x_γ,t = 0, whose estimate keeps the
/// normal damping's ξ = c_n/(2√(L k_t m)).
#[test]
fn lammps_tangential_dashpots_count_in_the_critical_step() {
    let estimate = |x_gamma_t: f64| {
        free_sphere_step_estimate(json!({"kind": "constant", "gamma_n": 0.1}), x_gamma_t)
    };
    let m = 2500.0 * 4.0 / 3.0 * std::f64::consts::PI * 1e-9;
    let k = 3.5 * 1e4;
    let omega = (k / m).sqrt();
    let eq_28 = |xi: f64| 2.0 / omega * ((1.0 + xi * xi).sqrt() - xi);
    let critical = 2.0 * (k * m).sqrt();
    let undamped_tangential = estimate(0.0);
    let damped_tangential = estimate(5.0);
    approx::assert_relative_eq!(
        undamped_tangential,
        eq_28(0.1 / critical),
        max_relative = 1e-12
    );
    approx::assert_relative_eq!(
        damped_tangential,
        eq_28(3.5 * 5.0 * 0.1 / critical),
        max_relative = 1e-12
    );
    assert!(damped_tangential < undamped_tangential / 2.5);
}

/// The damping ratio of LAMMPS's mass-scaled dashpots in the critical step
/// (docs/models/damping.md): `mass_velocity` c = η_n0 m, `viscoelastic` c = η_n0 m R
/// (the particle's radius bounding the contact radius) for a free sphere. With η_n0
/// chosen so that c equals the `constant` dashpot 0.1 N·s/m, all three give the same
/// estimate: Rojek eq 28 with ξ = c/(2√(k m)) on the stiffest mode (the tangential
/// one, L k_t = 3.5e4 N/m, as in the test above).
#[test]
fn mass_scaled_dashpots_count_in_the_critical_step() {
    let m = 2500.0 * 4.0 / 3.0 * std::f64::consts::PI * 1e-9;
    let estimate = |damping: serde_json::Value| free_sphere_step_estimate(damping, 0.0);
    let k = 3.5 * 1e4;
    let xi = 0.1 / (2.0 * (k * m).sqrt());
    let eq_28 = 2.0 / (k / m).sqrt() * ((1.0 + xi * xi).sqrt() - xi);
    for damping in [
        json!({"kind": "constant", "gamma_n": 0.1}),
        json!({"kind": "mass_velocity", "eta_n0": 0.1 / m}),
        json!({"kind": "viscoelastic", "eta_n0": 0.1 / (m * 0.001)}),
    ] {
        approx::assert_relative_eq!(estimate(damping.clone()), eq_28, max_relative = 1e-12);
    }
}

/// The critical-step estimate (α = 1) of one free sphere (R = 1 mm, ρ = 2500) with
/// `linear` k_n = 1e4 N/m, the dashpot `damping` and `lammps_linear_history` k_t =
/// 1e4 N/m with its tangential dashpot x_γ,t.
fn free_sphere_step_estimate(damping: serde_json::Value, x_gamma_t: f64) -> f64 {
    build(json!({
        "materials": [{"name": "m", "density": 2500, "youngs_modulus": 1e7, "poisson_ratio": 0.3}],
        "contact": {
            "normal": {"law": "linear", "stiffness": 1e4},
            "damping": damping,
            "tangential": {"law": "lammps_linear_history", "stiffness": 1e4, "x_gamma_t": x_gamma_t, "friction": 0.3},
            "lever_arm": "lammps"
        },
        "particles": [{"position": [0, 0, 0], "radius": 0.001, "material": "m"}],
        "rotation": {},
        "time_step": {"alpha": 1.0}, "run": {"steps": 1}
    }))
    .dt_estimate
    .expect("a linear law has a stiffness")
}

/// A prescribed velocity that changes during the run: the particle moves at the old
/// velocity through the step the change falls on and at the new one after it, and the
/// kinetic energy the change gives it is counted as the prescribing body's work, so
/// the energy book stays balanced (nothing is dissipated without contacts).
#[test]
fn prescribed_velocity_changes_at_its_step_and_keeps_the_energy_book() {
    let dt = 1e-6;
    let mut b = build(json!({
        "materials": [{"name": "m", "density": 2500, "youngs_modulus": 1e7, "poisson_ratio": 0.3}],
        "contact": {"normal": {"law": "hertz"}},
        "particles": [{"position": [0, 0, 0], "radius": 0.001, "material": "m",
                       "prescribed_velocity": [0.1, 0, 0],
                       "prescribed_velocity_changes": [
                           {"time": 10e-6, "velocity": [-0.3, 0, 0]},
                           {"time": 25e-6, "velocity": [0, 0.2, 0]}]}],
        "time_step": {"fixed": dt},
        "run": {"steps": 40}
    }));
    let sim = &mut b.sim;
    let mut x = Vec::new();
    for _ in 0..40 {
        sim.step().unwrap();
        x.push(sim.state().particles.position[0]);
    }
    let expect = |n: f64| {
        let [a, c] = [n.min(10.0), (n.min(25.0) - 10.0).max(0.0)];
        [0.1 * a * dt - 0.3 * c * dt, 0.2 * (n - 25.0).max(0.0) * dt]
    };
    for (k, p) in x.iter().enumerate() {
        let [ex, ey] = expect(k as f64 + 1.0);
        assert!(
            (p.x - ex).abs() < 1e-15 && (p.y - ey).abs() < 1e-15,
            "step {}: at {p:?}, expected x {ex:e}, y {ey:e}",
            k + 1
        );
    }
    let kinetic = sim.kinetic_energy();
    let mass = 2500.0 * 4.0 / 3.0 * std::f64::consts::PI * 1e-9;
    assert!((kinetic - 0.5 * mass * 0.04).abs() < 1e-12 * kinetic);
    assert!(
        sim.dissipated_energy().abs() < 1e-12 * kinetic,
        "dissipated {:e} J of {kinetic:e} J",
        sim.dissipated_energy()
    );
}
