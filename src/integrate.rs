//! Velocity Verlet (the central-difference scheme of Rojek 2016 §3.1 written with
//! whole-step velocities):
//!   v_{n+½} = v_n + ½Δt F_n/m,   x_{n+1} = x_n + Δt v_{n+½},
//!   F_{n+1} = F(x_{n+1}, v_{n+½}),   v_{n+1} = v_{n+½} + ½Δt F_{n+1}/m.
//! Velocity-dependent forces (damping, friction) see the half-step velocity, as in
//! LIGGGHTS. Spins follow the same kicks with torque/I; spheres need no orientation.
//! Prescribed particles keep their velocity and are only drifted.

use crate::particles::{Particles, Vec3};

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
