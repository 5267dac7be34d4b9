//! Closed forms for LAMMPS's `linear_history` and `linear_nohistory` (tamp laws
//! `lammps_linear_history`, `lammps_linear_nohistory`): a sphere hits a flat wall
//! obliquely, fast enough along it that it slides throughout the contact. The friction
//! is then μ|F_n| against the slip at every step, so (with LAMMPS's lever arm R at a
//! wall, `contact.lever_arm` = `lammps`, and I = 2/5 m R²)
//!   Δv_t = μ ∫|F_n| dt / m,   ω R = (5/2) Δv_t,
//! whatever the tangential stiffness and dashpot (rigid-body impulse theory for gross
//! sliding, e.g. Brach 1991). Without a pulling normal force ∫|F_n| dt = m (1 + e) v_n.

use serde_json::{Value, json};
use tamp::contact::normal::linear::LinearCollision;
use tamp::scene;

/// A steel sphere (R = 1 mm) 1 µm above a steel plane, launched at (v_t, 0, −v_n),
/// with the given contact; run until it has left the wall: (Δv_t, ω R, v_n out).
fn slide(contact: Value, v_t: f64, v_n: f64, dt: f64) -> (f64, f64, f64) {
    let s = json!({
        "name": "sliding",
        "materials": [{"name": "steel", "density": 7800, "youngs_modulus": 2e11, "poisson_ratio": 0.3}],
        "contact": contact,
        "particles": [{"position": [0, 0, 0.001001], "radius": 0.001, "material": "steel", "velocity": [v_t, 0, -v_n]}],
        "walls": [{"material": "steel", "shape": {"kind": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}}],
        "rotation": {},
        "time_step": {"fixed": dt},
        "run": {"steps": 1}
    });
    let mut sim = scene::build(&scene::parse(&s.to_string()).unwrap())
        .unwrap()
        .sim;
    let mut touched = false;
    for _ in 0..10_000_000 {
        sim.step().unwrap();
        let touching = sim.contact_count() > 0;
        if touched && !touching {
            let p = &sim.state().particles;
            return (
                v_t - p.velocity[0].x,
                p.omega[0].y * p.radius[0],
                p.velocity[0].z,
            );
        }
        touched |= touching;
    }
    panic!("the sphere did not leave the wall");
}

/// Undamped Hertz (no pulling phase): Δv_t = μ (1 + e) v_n with e measured, for two
/// tangential stiffnesses ten times apart. The spring reaches the cone at the first
/// step of contact (k_t v_t Δt ≫ μ F_n there), so only round-off remains: 1e-9.
#[test]
fn linear_history_slides_at_the_rigid_body_limit_whatever_its_stiffness() {
    let (mu, v_t, v_n) = (0.3, 0.5, 0.1);
    for stiffness in [2e6, 2e7] {
        let contact = json!({
            "normal": {"law": "hertz"},
            "tangential": {"law": "lammps_linear_history", "stiffness": stiffness, "x_gamma_t": 0.5, "friction": mu},
            "lever_arm": "lammps"
        });
        let (dv, omega_r, v_out) = slide(contact, v_t, v_n, 1e-8);
        let e = v_out / v_n;
        let want = mu * (1.0 + e) * v_n;
        assert!(
            (dv / want - 1.0).abs() < 1e-9,
            "k_t {stiffness}: Δv_t {dv} vs {want}"
        );
        assert!(
            (omega_r / (2.5 * dv) - 1.0).abs() < 1e-9,
            "k_t {stiffness}: ωR {omega_r} vs {}",
            2.5 * dv
        );
    }
}

/// Hooke with a constant dashpot: the contact is the damped oscillator
/// δ(t) = (v_n/ω) e^{−βt} sin ωt (β = γ_n/2m, ω = √(k/m − β²)) until δ = 0 at t = π/ω.
/// Its force F_n = −m δ̈ turns pulling at ω t_s = π − atan(2βω/(ω² − β²)) (δ̈ = 0), where
/// the separation speed is largest, s = −δ̇(t_s); so
///   ∫|F_n| dt / m = (v_n + s) + (s − v_out),   v_out = v_n e^{−βπ/ω},
/// and LAMMPS's Coulomb limit on |F_n| gives Δv_t = μ (v_n + 2s − v_out). The dashpot
/// γ_t = 20 γ_n keeps γ_t|v_t| above μ|F_n| throughout (sliding). The force jumps at
/// first touch (to γ_n v_n) and at separation, each sampled within one step: a
/// relative error of at most γ_n Δt/m = 2βΔt (1.5e-5 here).
#[test]
fn linear_nohistory_slides_with_lammps_coulomb_limit_on_the_pulling_force() {
    let (mu, v_t, v_n, dt) = (0.3, 0.5, 0.1, 1e-9);
    let (k, gamma) = (2e6, 0.5);
    let mass = 7800.0 * 4.0 / 3.0 * std::f64::consts::PI * 1e-9;
    let contact = json!({
        "normal": {"law": "linear", "stiffness": k},
        "damping": {"kind": "constant", "gamma_n": gamma},
        "tangential": {"law": "lammps_linear_nohistory", "x_gamma_t": 20.0, "friction": mu},
        "lever_arm": "lammps"
    });
    let (dv, omega_r, v_out) = slide(contact, v_t, v_n, dt);
    let c = LinearCollision::new(k, mass, gamma);
    let (beta, omega) = (c.beta, c.damped_frequency());
    let t_s = (std::f64::consts::PI - (2.0 * beta * omega / (omega * omega - beta * beta)).atan())
        / omega;
    let s = -v_n * (-beta * t_s).exp() * ((omega * t_s).cos() - beta / omega * (omega * t_s).sin());
    let out = v_n * c.restitution();
    let want = mu * (v_n + 2.0 * s - out);
    let tolerance = 2.0 * beta * dt;
    assert!(
        (v_out / out - 1.0).abs() < tolerance,
        "v_out {v_out} vs {out}"
    );
    assert!((dv / want - 1.0).abs() < tolerance, "Δv_t {dv} vs {want}");
    // (1 + e) v_n alone misses the pulling phase by more than the tolerance.
    assert!((dv / (mu * (v_n + out)) - 1.0).abs() > 10.0 * tolerance);
    assert!(
        (omega_r / (2.5 * dv) - 1.0).abs() < 1e-9,
        "ωR {omega_r} vs {}",
        2.5 * dv
    );
}
