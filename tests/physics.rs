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
    let f = b.sim.particles.force[0];
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
            if b.sim.particles.velocity[0].z > 0.0 && b.sim.contact_count() == 0 {
                break;
            }
        }
        b.sim.particles.velocity[0].z / 0.1
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
