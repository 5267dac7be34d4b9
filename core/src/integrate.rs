//! Velocity Verlet (the central-difference scheme of Rojek 2016 §3.1 written with
//! whole-step velocities):
//!   v_{n+½} = v_n + ½Δt F_n/m,   x_{n+1} = x_n + Δt v_{n+½},
//!   F_{n+1} = F(x_{n+1}, v_{n+½}),   v_{n+1} = v_{n+½} + ½Δt F_{n+1}/m.
//! Velocity-dependent forces (damping, friction) see the half-step velocity, as in
//! LIGGGHTS. Spins follow the same kicks with torque/I; spheres need no orientation.
//! Prescribed particles keep their velocity and are only drifted.

use crate::particles::{Particles, Vec3};
use crate::space::Space;

/// Half kick of the free particles' velocities, and of their spins when rotation is
/// on (one pass over the particles); prescribed particles keep their velocity.
pub fn kick(p: &mut Particles, half_dt: f64, rotation: bool) {
    for i in 0..p.len() {
        if !p.prescribed[i] {
            p.velocity[i] += p.force[i] * (half_dt / p.mass[i]);
            if rotation {
                p.omega[i] += p.torque[i] * (half_dt / p.inertia[i]);
            }
        }
    }
}

/// Drift every particle by Δt v (v the half-step velocity of free particles, the
/// prescribed one of the others). Returns the work gravity does over the drift on the
/// free particles, Σ m_i g·Δx_i, J (0 without gravity).
pub fn drift(p: &mut Particles, dt: f64, gravity: Option<&Vec3>) -> f64 {
    let mut work = 0.0;
    for i in 0..p.len() {
        let dx = p.velocity[i] * dt;
        if let (Some(g), false) = (gravity, p.prescribed[i]) {
            work += p.mass[i] * g.dot(&dx);
        }
        p.position[i] += dx;
    }
    work
}

/// The first particle with a non-finite position, velocity or spin.
pub fn first_non_finite(p: &Particles) -> Option<usize> {
    (0..p.len()).find(|&i| {
        !(p.position[i].iter().all(|c| c.is_finite())
            && p.velocity[i].iter().all(|c| c.is_finite())
            && p.omega[i].iter().all(|c| c.is_finite()))
    })
}

/// What `kick_and_check` saw at the end of a step.
#[derive(Clone, Copy, Debug)]
pub struct Kicked {
    /// Whether every position, velocity and spin is finite.
    pub finite: bool,
    /// Power the contact forces take from the prescribed particles, −Σ F·v over
    /// them in index order (the particles' part of `Simulation::prescribed_power`).
    pub driven_power: f64,
}

/// What `kick_drift_wrap` saw of the drift.
#[derive(Clone, Copy, Debug)]
pub struct Drifted {
    /// Work of gravity over the drift, J.
    pub gravity_work: f64,
    /// The particle that moved farthest, and |Δx|² of its move, m².
    pub farthest: (usize, f64),
}

/// The first half kick, the drift and the periodic wrap of a step in one pass over
/// the particles: for each, `kick`, then `drift`, then `Space::wrap`, the same
/// operations as the three passes one after the other. Returns the work of gravity
/// over the drift, summed in index order as `drift` sums it, and the longest move.
pub fn kick_drift_wrap(
    p: &mut Particles,
    half_dt: f64,
    dt: f64,
    rotation: bool,
    gravity: Option<&Vec3>,
    space: &Space,
) -> Drifted {
    let n = p.len();
    let periodic = space.is_periodic();
    let (position, velocity, omega) = (
        &mut p.position[..n],
        &mut p.velocity[..n],
        &mut p.omega[..n],
    );
    let (force, torque, mass, inertia, prescribed) = (
        &p.force[..n],
        &p.torque[..n],
        &p.mass[..n],
        &p.inertia[..n],
        &p.prescribed[..n],
    );
    let mut work = 0.0;
    let mut farthest = (0, 0.0);
    for i in 0..n {
        if !prescribed[i] {
            velocity[i] += force[i] * (half_dt / mass[i]);
            if rotation {
                omega[i] += torque[i] * (half_dt / inertia[i]);
            }
        }
        let dx = velocity[i] * dt;
        let moved = dx.norm_squared();
        if moved > farthest.1 {
            farthest = (i, moved);
        }
        if let (Some(g), false) = (gravity, prescribed[i]) {
            work += mass[i] * g.dot(&dx);
        }
        position[i] += dx;
        if periodic {
            space.wrap(&mut position[i]);
        }
    }
    Drifted {
        gravity_work: work,
        farthest,
    }
}

/// The second half kick of a step (`kick`) in one pass with the checks that follow
/// it: whether every position, velocity and spin is finite (`first_non_finite`
/// finds which one is not), and the power of the contact forces on the prescribed
/// particles.
pub fn kick_and_check(p: &mut Particles, half_dt: f64, rotation: bool) -> Kicked {
    let n = p.len();
    let (velocity, omega) = (&mut p.velocity[..n], &mut p.omega[..n]);
    let (position, force, torque, mass, inertia, prescribed) = (
        &p.position[..n],
        &p.force[..n],
        &p.torque[..n],
        &p.mass[..n],
        &p.inertia[..n],
        &p.prescribed[..n],
    );
    let mut finite = true;
    // `Sum` of f64 starts from −0.0; so does this sum, term by term the same.
    let mut driven_power = -0.0;
    for i in 0..n {
        if prescribed[i] {
            driven_power += -force[i].dot(&velocity[i]);
        } else {
            velocity[i] += force[i] * (half_dt / mass[i]);
            if rotation {
                omega[i] += torque[i] * (half_dt / inertia[i]);
            }
        }
        // `&`, not `&&`: no branch per component.
        for v in [&position[i], &velocity[i], &omega[i]] {
            finite &= v.x.is_finite() & v.y.is_finite() & v.z.is_finite();
        }
    }
    Kicked {
        finite,
        driven_power,
    }
}
