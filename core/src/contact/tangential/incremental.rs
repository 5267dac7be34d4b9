//! The incremental tangential force shared by the stiffness-based laws of Rojek 2016
//! (eq 11) — Mindlin no-slip and Storåkers' proportional stiffness:
//!
//!   F_t ← R(F_t) − k_t v_t Δt,  then |F_t| ≤ μ max(F_n, 0)   (eqs 11, 14)
//!
//! R rotates the stored force into the current contact plane with its magnitude
//! kept (as for the Cundall–Strack spring). The force itself is the history, so a
//! stiffness that changes with the overlap changes only the increments: unloading
//! at a lower stiffness than loading leaves a residual force, as in the paper's
//! formulation (unlike a total-spring law F_t = −k_t(δ) ξ_s).

use super::TangentialInput;
use super::cundall_strack::rotate_into_plane;
use crate::particles::Vec3;

/// Scale `force` back onto the friction cone |F_t| ≤ μ F_n if it lies outside.
#[inline]
pub fn cap_to_cone(force: Vec3, friction: f64, normal_force: f64) -> Vec3 {
    let limit = friction * normal_force.max(0.0);
    let magnitude = force.norm();
    if magnitude > limit {
        if magnitude > 0.0 {
            force * (limit / magnitude)
        } else {
            force
        }
    } else {
        force
    }
}

/// `incremental_force` of a law of stiffness `stiffness` at the contact `input`.
#[inline(always)]
pub fn incremental_step(force: &mut Vec3, input: &TangentialInput, stiffness: f64) -> Vec3 {
    incremental_force(
        force,
        &input.normal,
        &input.tangential_velocity,
        input.dt,
        stiffness,
        input.friction,
        input.normal_force,
    )
}

/// One step of Rojek's eq 11 on the stored force: rotate it into the plane normal to
/// `normal`, add −k_t v_t Δt, cap it to μ max(F_n, 0). Returns the new tangential
/// force on particle i, N, which is also the new state.
#[inline]
pub fn incremental_force(
    force: &mut Vec3,
    normal: &Vec3,
    tangential_velocity: &Vec3,
    dt: f64,
    stiffness: f64,
    friction: f64,
    normal_force: f64,
) -> Vec3 {
    let trial = rotate_into_plane(*force, normal) - tangential_velocity * (stiffness * dt);
    *force = cap_to_cone(trial, friction, normal_force);
    *force
}

/// Energy of a tangential force F held by a spring of stiffness k: ½|F|²/k (zero
/// without a spring).
pub fn spring_energy(force: &Vec3, stiffness: f64) -> f64 {
    if stiffness > 0.0 {
        0.5 * force.norm_squared() / stiffness
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sticks_elastically_then_slides_on_the_cone() {
        let n = Vec3::z();
        let mut f = Vec3::zeros();
        let v = Vec3::new(1.0, 0.0, 0.0);
        incremental_force(&mut f, &n, &v, 1e-3, 1e3, 0.5, 10.0);
        assert!((f.x + 1.0).abs() < 1e-14);
        for _ in 0..10 {
            incremental_force(&mut f, &n, &v, 1e-3, 1e3, 0.5, 10.0);
        }
        assert!((f.norm() - 5.0).abs() < 1e-14);
    }
}
