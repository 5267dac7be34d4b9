//! Every boundary kind, with a particle bouncing off it and a particle resting on it.
//!
//! Bounce: a sphere (linear spring k, no damping, no gravity) hits the surface along
//! its normal at speed v. The wall counts as infinitely massive with R* = R whatever
//! its curvature, so the closed forms of a linear impact hold for every shape:
//! the largest overlap is v·√(m/k) and the sphere leaves with speed v along the
//! reversed normal (energy conserved). Resting: the same sphere with critical
//! damping under gravity settles at the overlap m·g/k on an upward-facing surface.

use serde_json::{Value, json};
use tamp::particles::Vec3;
use tamp::scene;
use tamp::simulation::Simulation;

const R: f64 = 0.001;
const K: f64 = 1e3;
const RHO: f64 = 2500.0;
const V: f64 = 0.1;

fn mass() -> f64 {
    RHO * 4.0 / 3.0 * std::f64::consts::PI * R.powi(3)
}

fn build(shape: Value, motion: Value, particle: Value, extra: Value) -> scene::BuiltScene {
    let mut s = json!({
        "materials": [{"name": "m", "density": RHO}],
        "contact": {"normal": {"law": "linear", "stiffness": K}},
        "particles": [particle],
        "walls": [{"name": "w", "material": "m", "shape": shape, "motion": motion}],
        "time_step": {"alpha": 0.005},
        "run": {"steps": 1}
    });
    for (k, v) in extra.as_object().unwrap() {
        s[k] = v.clone();
    }
    scene::build(&scene::parse(&s.to_string()).unwrap()).unwrap()
}

/// Step until a contact has begun and ended (or a step budget runs out), calling
/// `during` after every step still in or before contact. Returns the largest
/// overlap seen, m, and whether any contact happened.
fn through_impact(b: &mut scene::BuiltScene, mut during: impl FnMut(&Simulation)) -> (f64, bool) {
    let mut largest = 0.0f64;
    let mut touched = false;
    for _ in 0..2_000_000 {
        b.sim.step().unwrap();
        largest = largest.max(b.sim.state().max_overlap_ratio * R);
        let in_contact = b.sim.contact_count() > 0;
        touched |= in_contact;
        if touched && !in_contact {
            break;
        }
        during(&b.sim);
    }
    (largest, touched)
}

/// Shoot a sphere from `start` along −`normal` (the surface's normal at the impact
/// point) and check the closed-form impact.
fn bounce(shape: Value, start: [f64; 3], normal: [f64; 3]) {
    let n = Vec3::from(normal).normalize();
    let v0 = -n * V;
    let mut b = build(
        shape,
        json!({"kind": "fixed"}),
        json!({"position": start, "radius": R, "material": "m", "velocity": [v0.x, v0.y, v0.z]}),
        json!({}),
    );
    let (max_overlap, touched) = through_impact(&mut b, |_| {});
    assert!(touched, "the sphere never reached the surface");
    let expected = V * (mass() / K).sqrt();
    assert!(
        (max_overlap / expected - 1.0).abs() < 2e-3,
        "largest overlap {max_overlap:e}, closed form {expected:e}"
    );
    let v = b.sim.state().particles.velocity[0];
    assert!(
        (v - n * V).norm() < 2e-3 * V,
        "rebound velocity {v:?}, expected {:?}",
        n * V
    );
}

/// A sphere placed touching an upward-facing surface at `at` settles at δ = m g / k.
fn rest(shape: Value, at: [f64; 3]) {
    let mut b = build(
        shape,
        json!({"kind": "fixed"}),
        json!({"position": at, "radius": R, "material": "m"}),
        json!({"gravity": [0, 0, -9.81], "contact": {"normal": {"law": "linear", "stiffness": K},
               "damping": {"kind": "critical_fraction", "xi": 1.0}}}),
    );
    for _ in 0..200_000 {
        b.sim.step().unwrap();
    }
    let expected = mass() * 9.81 / K;
    let overlap = R - (b.sim.state().particles.position[0].z - (at[2] - R));
    assert!(
        (overlap / expected - 1.0).abs() < 1e-6,
        "resting overlap {overlap:e}, expected m g / k = {expected:e}"
    );
    assert!(b.sim.state().particles.velocity[0].norm() < 1e-9);
}

#[test]
fn plane() {
    let shape = json!({"kind": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]});
    bounce(shape.clone(), [0.0, 0.0, 1.5 * R], [0.0, 0.0, 1.0]);
    let tilted = json!({"kind": "plane", "point": [0, 0, 0], "normal": [1, 2, 3]});
    let n = Vec3::new(1.0, 2.0, 3.0).normalize() * 1.5 * R;
    bounce(tilted, [n.x, n.y, n.z], [1.0, 2.0, 3.0]);
    rest(shape, [0.0, 0.0, R]);
}

/// A servo lid holds a target force on a sphere sitting on a floor (no gravity):
/// in equilibrium the sphere's reaction on the lid equals the target and both
/// contacts carry it, so each overlap is F/k. The gain respects the loop's stability
/// limits (docs in boundary/motion.rs): gain·c = 0.29 and gain·k·Δt = 0.01.
#[test]
fn servo_holds_its_target_force() {
    let target = 1e-4;
    let s = json!({
        "materials": [{"name": "m", "density": RHO}],
        "contact": {"normal": {"law": "linear", "stiffness": K},
                    "damping": {"kind": "critical_fraction", "xi": 0.7}},
        "particles": [{"position": [0, 0, R], "radius": R, "material": "m"}],
        "walls": [
            {"name": "floor", "material": "m", "shape": {"kind": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}},
            {"name": "lid", "material": "m", "shape": {"kind": "plane", "point": [0, 0, 2.01e-3], "normal": [0, 0, -1]},
             "motion": {"kind": "servo", "direction": [0, 0, -1], "force": target, "gain": 2.0, "max_speed": 0.01}}
        ],
        "time_step": {"alpha": 0.05},
        "run": {"steps": 1}
    });
    let mut b = scene::build(&scene::parse(&s.to_string()).unwrap()).unwrap();
    let steps = (0.5 / b.sim.dt()) as usize;
    for _ in 0..steps {
        b.sim.step().unwrap();
    }
    let reaction = b.sim.state().wall_force[1].z;
    assert!(
        (reaction / target - 1.0).abs() < 1e-6,
        "lid reaction {reaction:e}, target {target:e}"
    );
    let floor_overlap = R - b.sim.state().particles.position[0].z;
    assert!((floor_overlap * K / target - 1.0).abs() < 1e-6);
    assert!(b.sim.dissipated_energy() >= 0.0);
}

/// A floor oscillating as z = A sin ωt with A ω² < g carries a resting sphere along;
/// ω is far below the contact frequency √(k/m), so the overlap follows the quasi-static
/// m (g + z̈)/k.
#[test]
fn displacement_motion_carries_a_resting_sphere() {
    let (a, w) = (1e-5, 2.0 * std::f64::consts::PI * 20.0);
    let mut b = build(
        json!({"kind": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}),
        json!({"kind": "displacement", "x": "0.0", "y": "0.0", "z": format!("{a} * math::sin({w} * t)")}),
        json!({"position": [0, 0, R - mass() * 9.81 / K], "radius": R, "material": "m"}),
        json!({"gravity": [0, 0, -9.81], "contact": {"normal": {"law": "linear", "stiffness": K},
               "damping": {"kind": "critical_fraction", "xi": 1.0}},
               "stability": {"initial_overlap_tolerance": 1e-3}}),
    );
    let steps = (0.2 / b.sim.dt()) as usize;
    let mut worst = 0.0f64;
    for _ in 0..steps {
        b.sim.step().unwrap();
        let t = b.sim.state().time;
        if t < 0.05 {
            continue; // the start-up transient of the damped contact
        }
        let floor = a * (w * t).sin();
        let expected = mass() * (9.81 - a * w * w * (w * t).sin()) / K;
        let overlap = R - (b.sim.state().particles.position[0].z - floor);
        worst = worst.max((overlap - expected).abs() / expected);
    }
    assert!(
        worst < 1e-2,
        "overlap deviates from quasi-static by {worst:e}"
    );
    assert!(b.sim.dissipated_energy() >= -1e-15);
}

#[test]
fn open_box() {
    let shape = json!({"kind": "box", "lower": [-0.01, -0.01, -0.01], "upper": [0.01, 0.01, 0.01], "open": ["+z"]});
    bounce(shape.clone(), [0.01 - 1.5 * R, 0.0, 0.0], [-1.0, 0.0, 0.0]);
    bounce(shape.clone(), [0.0, -0.01 + 1.5 * R, 0.0], [0.0, 1.0, 0.0]);
    rest(shape, [0.0, 0.0, -0.01 + R]);
}

#[test]
fn cylinder_inner_wall() {
    let shape = json!({"kind": "cylinder", "origin": [0, 0, 0], "axis": [0, 0, 1], "radius": 0.01, "bottom": -0.01, "top": 0.01});
    bounce(shape.clone(), [0.01 - 1.5 * R, 0.0, 0.0], [-1.0, 0.0, 0.0]);
    let s = std::f64::consts::FRAC_1_SQRT_2;
    let at = 0.01 - 1.5 * R;
    bounce(shape, [at * s, at * s, 0.003], [-1.0, -1.0, 0.0]);
}

/// Inner surface of a 45° cone, hit along its inward normal (−1, 0, 1)/√2.
#[test]
fn cone_inner_wall() {
    let shape = json!({"kind": "cone", "origin": [0, 0, 0], "axis": [0, 0, 1],
                       "bottom": 0.0, "bottom_radius": 0.005, "top": 0.01, "top_radius": 0.015});
    let s = std::f64::consts::FRAC_1_SQRT_2;
    bounce(
        shape,
        [0.01 - 1.5 * R * s, 0.0, 0.005 + 1.5 * R * s],
        [-1.0, 0.0, 1.0],
    );
}

/// A funnel: the 45° cone and the outlet tube below it.
#[test]
fn funnel() {
    let shape = json!({"kind": "funnel", "origin": [0, 0, 0], "axis": [0, 0, 1],
                       "outlet_radius": 0.003, "outlet_bottom": -0.01, "outlet_top": 0.0,
                       "top_radius": 0.013, "top": 0.01});
    let s = std::f64::consts::FRAC_1_SQRT_2;
    bounce(
        shape.clone(),
        [0.008 - 1.5 * R * s, 0.0, 0.005 + 1.5 * R * s],
        [-1.0, 0.0, 1.0],
    );
    bounce(shape, [0.003 - 1.5 * R, 0.0, -0.005], [-1.0, 0.0, 0.0]);
}

/// z = 0.1 x + 0.2 y sampled on a grid (exact for a plane), hit along its normal;
/// a flat grid of heights to rest on.
#[test]
fn height_field() {
    let tilted = json!({"kind": "height_field", "x_range": [-0.01, 0.01], "y_range": [-0.01, 0.01],
                        "expression": "0.1 * x + 0.2 * y", "cells": [4, 4]});
    let n = Vec3::new(-0.1, -0.2, 1.0).normalize() * 1.5 * R;
    bounce(tilted, [n.x, n.y, n.z], [-0.1, -0.2, 1.0]);
    let flat = json!({"kind": "height_field", "x_range": [-0.01, 0.01], "y_range": [-0.01, 0.01],
                      "grid": [[0.0, 0.0, 0.0], [0.0, 0.0, 0.0]]});
    rest(flat, [0.001, 0.002, R]);
}

/// Meshes: a square polygon (two triangles) hit exactly over their shared diagonal,
/// where a double-counted contact would halve the largest overlap's closed form by √2;
/// the same square read from an STL file to rest on.
#[test]
fn mesh_polygons_and_stl() {
    let square = json!({"kind": "mesh", "polygons": [[[-0.01, -0.01, 0], [0.01, -0.01, 0], [0.01, 0.01, 0], [-0.01, 0.01, 0]]]});
    bounce(square, [0.002, 0.002, 1.5 * R], [0.0, 0.0, 1.0]);
    let stl = json!({"kind": "mesh", "stl": "tests/scenes/square.stl"});
    bounce(stl.clone(), [-0.003, -0.003, 1.5 * R], [0.0, 0.0, 1.0]);
    rest(stl, [0.0, 0.0, R]);
}

/// A motion expression that stops being finite stops the run with a diagnostic
/// naming the wall, instead of losing the wall and writing NaN work.
#[test]
fn non_finite_motion_stops_the_run() {
    let mut b = build(
        json!({"kind": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}),
        json!({"kind": "displacement", "x": "0.0", "y": "0.0", "z": "0.001 * math::sqrt(0.0 - math::sin(1000.0 * t))"}),
        json!({"position": [0, 0, 0.5], "radius": R, "material": "m"}),
        json!({"time_step": {"fixed": 1e-4}}),
    );
    let err = (0..100).try_for_each(|_| b.sim.step()).unwrap_err();
    let msg = err.to_string();
    assert!(
        msg.contains("wall 'w'") && msg.contains("non-finite"),
        "{msg}"
    );
    assert_eq!(err.exit_code(), 3);
}

/// Periodic faces: two equal spheres leave the box through opposite faces and meet
/// through them. An elastic head-on collision of equal masses swaps the velocities,
/// exactly as in open space, and the largest overlap is the closed form
/// v_rel·√(m*/k) with v_rel = 2v and m* = m/2; positions stay inside the period.
#[test]
fn periodic_faces_collide_through_the_boundary() {
    let l = 0.01;
    let s = json!({
        "materials": [{"name": "m", "density": RHO}],
        "contact": {"normal": {"law": "linear", "stiffness": K}},
        "particles": [
            {"position": [0.5 * l - 1.2 * R, 0, 0], "radius": R, "material": "m", "velocity": [-V, 0, 0]},
            {"position": [-0.5 * l + 1.2 * R, 0, 0], "radius": R, "material": "m", "velocity": [V, 0, 0]}
        ],
        "periodic": {"x": [-0.5 * l, 0.5 * l]},
        "time_step": {"alpha": 0.005},
        "run": {"steps": 1}
    });
    let mut b = scene::build(&scene::parse(&s.to_string()).unwrap()).unwrap();
    let (worst, touched) = through_impact(&mut b, |sim| {
        assert!(
            sim.state()
                .particles
                .position
                .iter()
                .all(|x| x.x >= -0.5 * l && x.x < 0.5 * l)
        );
    });
    assert!(touched, "the spheres never met through the periodic faces");
    let v = &b.sim.state().particles.velocity;
    assert!(
        (v[0].x - V).abs() < 2e-3 * V && (v[1].x + V).abs() < 2e-3 * V,
        "{v:?}"
    );
    let closed_form = 2.0 * V * (0.5 * mass() / K).sqrt();
    assert!(
        (worst / closed_form - 1.0).abs() < 2e-3,
        "largest overlap {worst:e}, closed form {closed_form:e}"
    );
}
