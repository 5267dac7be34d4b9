//! Hard cases: scenes at the edges of what the integrator and the contact laws must
//! survive. Each test states what it proves; none may end in a NaN.

// NiAl's Poisson ratio 0.318 (Rojek 2016 Table 2) is a material constant, not 1/π.
#![allow(clippy::approx_constant)]

mod common;

use serde_json::{Value, json};
use tamp::contact::normal::storakers::StorakersHistory;
use tamp::contact::normal::{NormalLaw, NormalModel, Storakers};
use tamp::error::TampError;
use tamp::particles::Vec3;
use tamp::scene;
use tamp::simulation::Simulation;

use common::built;

fn all_finite(sim: &Simulation) -> bool {
    let p = &sim.state().particles;
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
    let before = (sim.state().particles.velocity[1] - sim.state().particles.velocity[0]).x;
    sim.run_with(b.steps, |_| {}).expect("stable");
    let after = (sim.state().particles.velocity[1] - sim.state().particles.velocity[0]).x;
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
        assert!(
            all_finite(&sim),
            "non-finite state at step {}",
            sim.state().step
        );
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
        let start = sim.state().particles.translational_kinetic_energy();
        let mut most = start;
        sim.run_with(b.steps, |s| {
            most = most.max(s.state().particles.translational_kinetic_energy() + s.stored_energy());
        })
        .expect("stable");
        assert!(all_finite(&sim));
        assert!(
            most <= start * (1.0 + 1e-9),
            "ξ = {xi}: energy rose to {most} from {start}"
        );
        let rel = (sim.state().particles.velocity[1] - sim.state().particles.velocity[0]).x;
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
        let x = sim.state().particles.position[i];
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
    let start: Vec<f64> = sim.state().particles.position.iter().map(|x| x.z).collect();
    sim.run_with(b.steps, |_| {}).expect("stable");
    assert!(all_finite(&sim));
    for (i, (x, z0)) in sim
        .state()
        .particles
        .position
        .iter()
        .zip(&start)
        .enumerate()
    {
        assert!(x.z <= z0 + 1e-6, "sphere {i} rose from {z0} to {}", x.z);
    }
}

/// Glass spheres of the rotating-pair test: R = 1 mm, held at δ = 1e-3 R.
const PAIR_R: f64 = 1e-3;
const PAIR_OVERLAP: f64 = 1e-6;

/// Two glass spheres (E = 100 MPa, ν = 0.25) overlapping by `PAIR_OVERLAP` along x,
/// centred on the origin, both driven (`prescribed_velocity`, steered by the test).
fn rotating_pair(tangential: Value) -> Value {
    let half = PAIR_R - 0.5 * PAIR_OVERLAP;
    json!({
        "materials": [{"name": "glass", "density": 2500, "youngs_modulus": 1e8, "poisson_ratio": 0.25}],
        "contact": {"normal": {"law": "hertz"}, "tangential": tangential},
        "particles": [
            {"position": [half, 0, 0], "radius": PAIR_R, "material": "glass", "prescribed_velocity": [0, 0, 0]},
            {"position": [-half, 0, 0], "radius": PAIR_R, "material": "glass", "prescribed_velocity": [0, 0, 0]}
        ],
        "rotation": {},
        // The test spins the driven spheres itself, which the energy book (it has no
        // prescribed spin) cannot account for: its check would stop a correct run.
        "stability": {"initial_overlap_tolerance": 0.01, "max_energy_growth": 1e300},
        "time_step": {"fixed": 1e-6},
        "run": {"steps": 1}
    })
}

/// One step that brings the pair's centres onto the circle of diameter 2R − δ at angle
/// `theta` about z (the chord velocity of the step), with both spheres spinning at
/// `spin` about z.
fn step_pair_to(sim: &mut Simulation, theta: f64, spin: f64) {
    let half = PAIR_R - 0.5 * PAIR_OVERLAP;
    let e = Vec3::new(theta.cos(), theta.sin(), 0.0);
    for (i, side) in [(0, 1.0), (1, -1.0)] {
        let v = (e * (side * half) - sim.state().particles.position[i]) / sim.dt();
        sim.prescribe(i, v);
        sim.set_spin(i, Vec3::z() * spin);
    }
    sim.step().expect("driven pair");
}

/// The contact normal (from sphere 1 to sphere 0), and the normal and tangential
/// parts of the force on sphere 0, which only the contact loads.
fn pair_force(sim: &Simulation) -> (Vec3, f64, Vec3) {
    let p = &sim.state().particles;
    let n = (p.position[0] - p.position[1]).normalize();
    let f = p.force[0];
    let f_n = f.dot(&n);
    (n, f_n, f - n * f_n)
}

/// A sticking contact whose normal turns by 90°, for every tangential law that keeps a
/// history. Two spheres at constant overlap are driven as one rigid body about z:
/// centres on a circle, both spinning at the orbit rate, so their contact points move
/// together. tamp has no prescribed spin, so the test sets the spins of the driven
/// spheres itself (they are never integrated). The pair first turns 90° from a fresh
/// contact; then a short orbit without spin (the contact points slip by d·θ) loads the
/// tangential state to about half the cone, pointing along the direction of travel;
/// then the pair turns another 90°. That direction of travel is where the normal
/// ends up, so a state left where it was would appear whole in the normal force.
///
/// At every step: the stored state (spring or force) lies in the current tangent
/// plane; the normal force stays the Hertz force of the constant overlap; |F_t| ≤ μ F_n;
/// everything is finite. During the rigid turns F_t is objective: from a fresh contact
/// it stays near zero, and a loaded state turns with the pair and keeps its length.
///
/// Tolerances: the driver moves the centres along chords while the spins turn at the
/// exact rate Δθ/Δt, so the contact points slip by d(Δθ − sin Δθ) ≈ dΔθ³/6 a step,
/// d(π/2)Δθ²/6 = 2e-11 m over a quarter turn (Δθ = π/16000, d = 2 mm): the
/// first-order kinematics of a rate law, 5e-5 of the cone and 1e-4 of the loaded
/// spring. `liggghts_history` projects the shear without restoring its length, as
/// LIGGGHTS does, which shortens it by (cos Δθ)^N ≈ 1 − πΔθ/4 = 1 − 1.5e-4 over the
/// turn more.
#[test]
fn contact_normal_turning_90_degrees_while_sticking() {
    let mu = 0.5;
    let laws = [
        json!({"law": "cundall_strack", "friction": mu, "stiffness": 2000}),
        json!({"law": "mindlin_no_slip", "friction": mu}),
        json!({"law": "mindlin_deresiewicz", "friction": mu}),
        json!({"law": "walton_braun", "friction": mu, "stiffness": 2000}),
        json!({"law": "storakers", "friction": mu, "beta": 1.0}),
        json!({"law": "liggghts_history", "friction": mu}),
    ];
    let quarter = std::f64::consts::FRAC_PI_2;
    let turn_steps = 8000;
    let d_theta = quarter / turn_steps as f64;
    let preload_steps = 50;
    // Orbit without spin: the contact points slip by d·θ, about half of μF_n/k_t.
    let preload_angle = 1e-4;
    for law in laws {
        let name = law["law"].as_str().unwrap().to_string();
        let mut sim = built(&rotating_pair(law)).sim;
        let spin = d_theta / sim.dt();
        let (_, f_n0, _) = pair_force(&sim);
        let check = |sim: &Simulation, what: &str| {
            assert!(all_finite(sim), "{name} {what}: non-finite state");
            let (n, f_n, f_t) = pair_force(sim);
            assert!(
                (f_n - f_n0).abs() <= 1e-9 * f_n0,
                "{name} {what}: normal force {f_n} instead of {f_n0}"
            );
            assert!(
                f_t.norm() <= mu * f_n * (1.0 + 1e-12),
                "{name} {what}: |F_t| {} above the cone {}",
                f_t.norm(),
                mu * f_n
            );
            let stored = sim.contact_tangential(0, 1).expect("history");
            assert!(
                stored.dot(&n).abs() <= 1e-9 * stored.norm(),
                "{name} {what}: stored state {stored:?} leaves the plane of {n:?}"
            );
            f_t
        };
        let mut worst_fresh: f64 = 0.0;
        for k in 1..=turn_steps {
            step_pair_to(&mut sim, k as f64 * d_theta, spin);
            let f_t = check(&sim, "fresh turn");
            worst_fresh = worst_fresh.max(f_t.norm() / (mu * f_n0));
        }
        for k in 1..=preload_steps {
            let theta = quarter + preload_angle * k as f64 / preload_steps as f64;
            step_pair_to(&mut sim, theta, 0.0);
            check(&sim, "preload");
        }
        let start = quarter + preload_angle;
        let f_t0 = check(&sim, "loaded");
        let mut worst_turned: f64 = 0.0;
        for k in 1..=turn_steps {
            let turned = k as f64 * d_theta;
            step_pair_to(&mut sim, start + turned, spin);
            let f_t = check(&sim, "loaded turn");
            let (s, c) = turned.sin_cos();
            let expected = Vec3::new(c * f_t0.x - s * f_t0.y, s * f_t0.x + c * f_t0.y, f_t0.z);
            worst_turned = worst_turned.max((f_t - expected).norm() / f_t0.norm());
        }
        // Measured: 5.1e-5 to 6.1e-5 of the cone from a fresh contact; 1.0e-4 to 1.1e-4
        // of the loaded spring, 2.6e-4 for liggghts_history.
        assert!(
            worst_fresh < 3e-4,
            "{name}: fresh contact reached {worst_fresh:e} of the cone"
        );
        assert!(
            worst_turned < 5e-4,
            "{name}: the loaded spring did not turn with the pair ({worst_turned:e})"
        );
        // The spring really was loaded and still sticks.
        let loaded = f_t0.norm() / (mu * f_n0);
        assert!((0.3..0.9).contains(&loaded), "{name}: preload {loaded}");
    }
}

/// Two NiAl spheres (Rojek 2016 Table 2, R = 10 µm, σ_Y = 800 MPa) under Storåkers with
/// m = 0, exactly touching at t = 0 (δ = 0, no contact yet), driven together at a
/// relative 1e-4 m/s: with Δt = 1e-11 s the overlap grows by 1e-15 m a step.
fn storakers_m0_pair(min_with_hertz: bool) -> Value {
    json!({
        "materials": [{"name": "NiAl", "density": 5910, "youngs_modulus": 183e9, "poisson_ratio": 0.318,
                       "hollomon": {"exponent": 0.0, "yield_stress": 800e6}}],
        "contact": {"normal": {"law": "storakers", "min_with_hertz": min_with_hertz}},
        "particles": [
            {"position": [-10e-6, 0, 0], "radius": 10e-6, "material": "NiAl", "prescribed_velocity": [0.5e-4, 0, 0]},
            {"position": [10e-6, 0, 0], "radius": 10e-6, "material": "NiAl", "prescribed_velocity": [-0.5e-4, 0, 0]}
        ],
        // The law as published gives back more than it took below the Hertz crossover
        // (docs/models/storakers.md); the driven pair is about forces, not the book.
        "stability": {"max_energy_growth": 1e6},
        "time_step": {"fixed": 1e-11},
        "run": {"steps": 3000}
    })
}

/// Storåkers with a perfectly plastic material (Hollomon m = 0) at vanishing overlap.
/// m = 0 is inside the accepted range [0, 1) and nothing in the law is singular there:
/// the virgin branch is linear, F_p = C δ with C = 6π c² σ0* R* (eq 16 at m = 0,
/// c² = 1.43), so its tangent k_p = C is a constant, not a δ^{−1/2} that would blow up
/// at first touch. With `min_with_hertz` the small-overlap branch is Hertz, whose
/// tangent 2E*√(R*δ) tends to 0 instead.
///
/// Proves, for both variants: the scene is accepted; at δ from 1e-300 m to 1e-9 m the
/// force, the tangent, the stored energy and the unloading branch are finite and
/// nonnegative, with F/δ = C to 1e-12 on the pure law; a driven pair whose overlap
/// grows by 1e-15 m a step has, from its first contact step on, the force of the law
/// and a finite positive critical step — constant 2√(m/C) = 3.03e-8 s on the pure law,
/// 2.6e-6 s at δ = 1e-15 m with the Hertz cap (the Hertz tangent that small; only a
/// `characteristic_velocity` brings in the impact stiffness); and a free pair meeting
/// at 1e-6 m/s from touching runs finite.
///
/// The surprise: that free pair on the pure law stops at the first energy check (exit
/// 3, "mechanical energy grew … 0.99 of the energy scale"), with a finite state. Not a
/// time step problem, whatever the message suggests: below the Hertz crossover
/// (δ_x = 1.26e-7 m here) the Hertz unloading curve through (δ_max, Cδ_max) stores about
/// twice the work the linear loading took (docs/models/storakers.md: the ratio tends to
/// 2 + m/2 as δ_max → 0), and the book sees that as energy created. The capped law is
/// elastic there and returns the approach speed.
///
/// Tolerances: F against the closed forms 1e-9 relative (the same overlap, computed
/// twice from the same positions); the estimate against 2√(m/C) 1e-12.
#[test]
fn storakers_perfectly_plastic_at_vanishing_overlap() {
    let r_eff: f64 = 5e-6;
    let mass = 5910.0 * 4.0 / 3.0 * std::f64::consts::PI * 1e-15;
    let e_eff = 183e9 / (2.0 * (1.0 - 0.318f64.powi(2)));
    let hertz_k = 4.0 / 3.0 * e_eff * r_eff.sqrt();
    // Eq 16 at m = 0; σ0* of two equal materials is σ0 = σ_Y.
    let c = 6.0 * std::f64::consts::PI * 1.43 * 800e6 * r_eff;
    for cap in [false, true] {
        let b = built(&storakers_m0_pair(cap));
        assert!(
            b.dt_estimate.is_none(),
            "no contact, no characteristic velocity"
        );
        let mut sim = b.sim;
        let pair = *sim.model().pair_table.get(0, 0);
        let law = Storakers {
            min_with_hertz: cap,
        };
        assert_eq!(sim.model().law.normal, NormalLaw::Storakers(law));
        for d in [1e-300, 1e-200, 1e-100, 1e-15, 1e-12, 1e-9] {
            let virgin = law.response(d, 0.0, r_eff, &pair, &mut StorakersHistory::default());
            let k_n = law.time_step_stiffness(d, r_eff, &pair, &StorakersHistory::default());
            let stored = law.energy(d, r_eff, &pair, &StorakersHistory::default());
            let unloading = law.response(0.5 * d, 0.0, r_eff, &pair, &mut StorakersHistory::new(d));
            for (what, v) in [
                ("force", virgin.force),
                ("stiffness", virgin.stiffness),
                ("stored energy", stored),
                ("unloading force", unloading.force),
                ("unloading stiffness", unloading.stiffness),
            ] {
                assert!(
                    v.is_finite() && v >= 0.0,
                    "cap {cap}, δ = {d:e}: {what} {v:e}"
                );
            }
            assert!(k_n > 0.0, "cap {cap}, δ = {d:e}: zero tangent");
            assert!(
                virgin.force <= c * d * (1.0 + 1e-12),
                "cap {cap}, δ = {d:e}: above the plastic line"
            );
            if !cap {
                assert!((virgin.force / d / c - 1.0).abs() < 1e-12, "δ = {d:e}");
                assert!((k_n / c - 1.0).abs() < 1e-12, "δ = {d:e}");
            }
        }
        let mut previous_dt = f64::INFINITY;
        for _ in 0..b.steps {
            sim.step().expect("driven pair");
            assert!(all_finite(&sim));
            let d = sim.overlap(0, 1);
            assert!(
                d > 0.0 && d < 1e-11,
                "overlap {d:e} at step {}",
                sim.state().step
            );
            // Compression: the force on the left sphere points left.
            let f = -sim.state().particles.force[0].x;
            let law = if cap { hertz_k * d.powf(1.5) } else { c * d };
            assert!(
                (f / law - 1.0).abs() < 1e-9,
                "step {}: F {f:e}, law {law:e}",
                sim.state().step
            );
            let dt = sim
                .critical_time_step(None)
                .expect("a contact gives a stiffness");
            assert!(
                dt.is_finite() && dt > 0.0,
                "step {}: Δt_cr {dt:e}",
                sim.state().step
            );
            if cap {
                assert!(dt <= previous_dt, "the Hertz tangent only grows");
                previous_dt = dt;
            } else {
                assert!(
                    (dt / (2.0 * (mass / c).sqrt()) - 1.0).abs() < 1e-12,
                    "{dt:e}"
                );
            }
        }
        // The same pair set free, meeting at 1e-6 m/s: the first contact step overlaps
        // by less than v Δt (measured 2.1e-16 m pure, 5.1e-15 m capped).
        let v = 1e-6;
        let mut free = storakers_m0_pair(cap);
        for (k, side) in [(0, 1.0), (1, -1.0)] {
            let p = free["particles"][k].as_object_mut().unwrap();
            p.remove("prescribed_velocity");
            p.insert("velocity".into(), json!([side * v / 2.0, 0, 0]));
        }
        free["stability"] = json!({});
        free["time_step"] = json!({"alpha": 0.01, "characteristic_velocity": v});
        free["run"] = json!({"duration": 2e-6});
        let b = built(&free);
        let mut sim = b.sim;
        let mut first = None;
        let result = sim.run_with(b.steps, |s| {
            let d = s.overlap(0, 1);
            if d > 0.0 && first.is_none() {
                first = Some(d);
            }
        });
        assert!(all_finite(&sim), "cap {cap}: non-finite state");
        assert!(first.unwrap() < 1e-14, "first overlap {:?}", first);
        if cap {
            result.expect("the capped law is elastic Hertz here");
            let e = (sim.state().particles.velocity[1] - sim.state().particles.velocity[0]).x / v;
            // Measured 1 + 1.6e-6: velocity Verlet over an elastic contact at α = 0.01.
            assert!((e - 1.0).abs() < 1e-4, "restitution {e}");
        } else {
            match result {
                Err(TampError::Unstable { what, .. }) => {
                    assert!(what.contains("mechanical energy grew"), "{what}")
                }
                other => panic!("expected the energy check to stop the pure law, got {other:?}"),
            }
        }
    }
}

/// Glass spheres (R = 1 mm and 0.5 mm) whose centres are `offset` apart along x.
fn coincident_pair(offset: f64, stability: Value) -> Value {
    json!({
        "materials": [{"name": "glass", "density": 2500, "youngs_modulus": 1e8, "poisson_ratio": 0.25}],
        "contact": {"normal": {"law": "hertz"}},
        "particles": [
            {"position": [0, 0, 0], "radius": 1e-3, "material": "glass"},
            {"position": [offset, 0, 0], "radius": 0.5e-3, "material": "glass"}
        ],
        "stability": stability,
        "time_step": {"alpha": 0.1, "characteristic_velocity": 1.0},
        "run": {"duration": 1e-3}
    })
}

fn build_error(v: &Value) -> TampError {
    match scene::build(&scene::parse(&v.to_string()).expect("parses")) {
        Err(e) => e,
        Ok(_) => panic!("built: {v}"),
    }
}

/// Coincident and nearly coincident centres, as a careful LIGGGHTS or Yade user would
/// want them handled: two centres at one point have no contact normal (LIGGGHTS divides
/// by r = 0), so such a pair is refused at build as an input error (exit 2) naming both
/// particles — whatever `stability` allows, because no tolerance makes it a contact.
/// Centres 1e-300 m apart count as coincident: the squared distance underflows to 0,
/// exactly as the force loop would compute it.
///
/// Nearly coincident (1e-15 m, and 1e-160 m, whose squared distance is subnormal but
/// not 0): an overlap of 3 times the smaller radius is refused by the default initial
/// overlap tolerance, with the same naming. A user who raises both limits above it gets
/// what they asked for: the pair is pushed apart along the offset, finite, with its
/// momentum kept.
///
/// Driven through each other (both prescribed, so only the checks can stop them, with
/// the overlap limit above the (R_i + R_j)/R_min = 3 reached at coincidence), the pair stops at the step
/// its centres coincide (exit 3) with a message saying so. Before the build refused
/// them, a coincident pair under raised limits stopped the build with exit 3 and
/// "overlap … is 3.000 of the smaller radius (limit 3.5)", a limit it had not exceeded.
#[test]
fn coincident_and_nearly_coincident_centres() {
    let raised = json!({"initial_overlap_tolerance": 3.5, "max_overlap_fraction": 3.5, "max_step_fraction": 3.5});
    for offset in [0.0, 1e-300] {
        for stability in [json!({}), raised.clone()] {
            let e = build_error(&coincident_pair(offset, stability));
            assert_eq!(e.exit_code(), 2, "{e}");
            let text = e.to_string();
            assert!(text.starts_with("particles[1].position: "), "{text}");
            assert!(
                text.contains("particles[0]") && text.contains("contact normal"),
                "{text}"
            );
        }
    }
    let e = build_error(&coincident_pair(1e-15, json!({})));
    assert_eq!(e.exit_code(), 2, "{e}");
    let text = e.to_string();
    assert!(
        text.starts_with("particles[1].position: overlaps particles[0]"),
        "{text}"
    );
    for offset in [1e-15, 1e-160] {
        let b = built(&coincident_pair(offset, raised.clone()));
        let mut sim = b.sim;
        let start = sim.state().particles.linear_momentum();
        assert_eq!(start.norm(), 0.0);
        sim.run_with(b.steps, |s| assert!(all_finite(s)))
            .expect("raised limits");
        let p = &sim.state().particles;
        assert!(sim.overlap(0, 1) < 0.0, "still overlapping");
        assert!(p.velocity[1].x > 0.0 && p.velocity[0].x < 0.0);
        assert_eq!(p.velocity[0].yz().norm() + p.velocity[1].yz().norm(), 0.0);
        let scale = p.mass[1] * p.velocity[1].norm();
        assert!(p.linear_momentum().norm() <= 1e-12 * scale);
    }

    // Powers of two: 4096 steps of 2^-20 m take the small sphere from 2^-8 m exactly
    // onto the other centre.
    let mut through = coincident_pair(0.0, json!({"max_overlap_fraction": 3.5}));
    through["particles"][0]["prescribed_velocity"] = json!([0, 0, 0]);
    through["particles"][1]["position"] = json!([2f64.powi(-8), 0, 0]);
    through["particles"][1]["prescribed_velocity"] = json!([-1.0, 0, 0]);
    through["time_step"] = json!({"fixed": 2f64.powi(-20)});
    through["run"] = json!({"steps": 5000});
    let b = built(&through);
    let mut sim = b.sim;
    // The error names the step whose drift ended on the centre, the 4096th (it used to
    // name the 4095 steps completed before it).
    match sim.run_with(b.steps, |s| assert!(all_finite(s))) {
        Err(e @ TampError::Unstable { step: 4096, .. }) => {
            assert_eq!(e.exit_code(), 3);
            let text = e.to_string();
            assert!(text.contains("contact 1-2: the centres coincide"), "{text}");
        }
        other => panic!("expected a stop at the 4096th step, got {other:?}"),
    }
    assert!(all_finite(&sim));
}

/// An energy that overflows while every position and velocity is still finite (a sphere
/// at 1e200 m/s) never reaches an output: the series row ends the run (exit 3, naming
/// the column), and so does the energy check, whatever its sign conventions make of
/// inf − inf.
#[test]
fn an_overflowing_energy_ends_the_run_instead_of_reaching_an_output() {
    let mut scene = common::base();
    // The energy check at every step, and no bound on a step's move, so that the
    // energy check is what meets the overflow.
    scene["stability"] = serde_json::json!({"check_every": 1, "max_step_fraction": 1e300});
    let mut sim = built(&scene).sim;
    sim.set_velocity(0, Vec3::new(1e200, 0.0, 0.0));
    let mut series = tamp::output::series::Series::new(&[], &sim);
    match series.record(&sim) {
        Err(TampError::Unstable { what, .. }) => {
            assert!(what.contains("kinetic_energy is inf"), "{what}")
        }
        other => panic!("expected exit 3, got {other:?}"),
    }
    match sim.step() {
        Err(TampError::Unstable { what, .. }) => assert!(what.contains("energy"), "{what}"),
        other => panic!("expected exit 3, got {other:?}"),
    }
}

/// A step a process computes during a run (the pressing re-estimates it) that is not
/// positive and finite stops the run with exit 3 naming the step; it never becomes
/// the run's Δt.
#[test]
fn a_time_step_that_is_not_positive_and_finite_stops_the_run() {
    let mut sim = built(&common::base()).sim;
    let dt = sim.dt();
    sim.step().unwrap();
    for bad in [f64::NAN, 0.0, -dt, f64::INFINITY] {
        let err = sim.set_time_step(bad).unwrap_err();
        assert_eq!(err.exit_code(), 3, "{err}");
        match err {
            TampError::Unstable { step, what, .. } => {
                assert_eq!(step, 1);
                assert!(what.contains("the time step became"), "{what}");
            }
            other => panic!("expected exit 3, got {other:?}"),
        }
        assert_eq!(sim.dt(), dt);
    }
}

/// Spheres meeting head-on far faster than the characteristic velocity their step was
/// sized for could pass through each other with exit 0. Here the step is 0.70 µs, so at
/// 400 m/s each sphere moves 0.28 mm a step, beyond a quarter of its 1 mm radius (at
/// 300 m/s, 0.21 mm, the contact is still seen). A step that would carry a particle
/// more than a quarter of the smallest radius is refused at build (exit 2) when the
/// initial speeds already do it, with a warning whenever they exceed the characteristic
/// velocity; a particle that reaches such a speed during the run (here: a fall of 1 s
/// under a strong gravity) stops it with exit 3 naming the particle and the step.
#[test]
fn a_step_that_could_tunnel_through_a_contact_is_refused() {
    let pair = |speed: f64| {
        json!({
            "materials": [{"name": "s", "density": 7800, "youngs_modulus": 2e11, "poisson_ratio": 0.3}],
            "contact": {"normal": {"law": "hertz"}},
            "particles": [
                {"position": [-0.0011, 0, 0], "radius": 0.001, "material": "s", "velocity": [speed, 0, 0]},
                {"position": [0.0011, 0, 0], "radius": 0.001, "material": "s", "velocity": [-speed, 0, 0]}
            ],
            "time_step": {"alpha": 0.2, "characteristic_velocity": 1.0},
            "run": {"duration": 1e-4}
        })
    };
    let s = scene::parse(&pair(400.0).to_string()).unwrap();
    let e = scene::build(&s).err().expect("refused");
    assert_eq!(e.exit_code(), 2, "{e}");
    assert!(
        e.to_string().contains("].velocity: 4e2 m/s moves particle"),
        "{e}"
    );
    let b = built(&pair(2.0));
    assert!(
        b.warnings
            .iter()
            .any(|w| w.contains("characteristic_velocity")),
        "{:?}",
        b.warnings
    );
    let mut falling = pair(0.0);
    falling["particles"][1]["position"] = json!([0.5, 0, 0]);
    falling["gravity"] = json!([0, 0, -1e4]);
    falling["run"] = json!({"duration": 1.0});
    let b = built(&falling);
    let mut sim = b.sim;
    match sim.run_with(b.steps, |_| {}) {
        Err(e @ TampError::Unstable { .. }) => {
            let text = e.to_string();
            assert!(
                text.contains("particle") && text.contains("smallest radius"),
                "{text}"
            );
        }
        other => panic!("expected exit 3, got {other:?}"),
    }
}
