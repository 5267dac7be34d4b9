//! Cundall–Strack tangential spring with a Coulomb limit (Zhong 2009 model IX,
//! eqs 24–25; Cundall & Strack 1979).
//!
//!   ξ_s = ∫ v_t dt since first touch        (eq 25, kept as a 3-vector)
//!   F_t = −k_s ξ_s,  |F_t| ≤ μ F_n            (eq 24)
//!
//! On gross sliding the spring is shortened to ξ_s = −F_t/k_s so that it sits on the
//! friction cone. Before each increment the stored spring is rotated into the current
//! tangent plane with its length kept, so a rigid rotation of the contact pair
//! produces no spurious force. F_n is the total normal force (elastic + damping),
//! clamped at zero: a damped contact pulling its bodies together near separation
//! carries no friction (LIGGGHTS's `tangential history` uses |F_n| instead;
//! docs/models/cundall_strack.md).
//! History: the spring vector ξ_s (m). Parameters: k_s (N/m), μ from the material pair.

use super::{TangentialInput, TangentialLaw, TangentialModel};
use crate::contact::model::Roles;
use crate::contact::registry::{self, TangentialExample};
use crate::error::Errors;

use super::incremental::cap_to_cone;
use crate::particles::Vec3;

/// Rotate the stored spring into the plane normal to `normal`, keeping its length.
#[inline]
pub fn rotate_into_plane(spring: Vec3, normal: &Vec3) -> Vec3 {
    let len = spring.norm();
    if len == 0.0 {
        return spring;
    }
    let projected = spring - normal * normal.dot(&spring);
    let plen = projected.norm();
    if plen == 0.0 {
        Vec3::zeros()
    } else {
        projected * (len / plen)
    }
}

/// One update of the spring and the resulting tangential force on particle i.
#[inline(always)]
pub fn cundall_strack_force(
    spring: &mut Vec3,
    normal: &Vec3,
    tangential_velocity: &Vec3,
    dt: f64,
    stiffness: f64,
    friction: f64,
    normal_force: f64,
) -> Vec3 {
    *spring = rotate_into_plane(*spring, normal) + tangential_velocity * dt;
    let trial = -*spring * stiffness;
    let force = cap_to_cone(trial, friction, normal_force);
    if force != trial {
        // Gross sliding: shorten the spring so that it sits on the cone.
        *spring = -force / stiffness;
    }
    force
}

/// Zhong model IX; k_s in N/m. State: the spring elongation ξ_s, m.
#[derive(Clone, Copy, Debug, PartialEq, serde::Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct CundallStrack {
    /// Tangential spring stiffness k_s, N/m.
    pub stiffness: f64,
}

impl TangentialModel for CundallStrack {
    type State = Vec3;

    fn name(&self) -> &'static str {
        "cundall_strack"
    }

    /// F = −k_s v_t Δt from rest (Zhong eq 24); sliding: −μF_n v̂_t (eq 25).
    fn examples() -> Vec<TangentialExample> {
        let law = TangentialLaw::CundallStrack(CundallStrack { stiffness: 1e6 });
        registry::spring_examples(law, 1e6)
    }

    fn check(&self, path: &str, _: Roles, e: &mut Errors) {
        e.positive(format!("{path}.stiffness"), self.stiffness);
    }

    #[inline(always)]
    fn force(&self, input: &TangentialInput, spring: &mut Vec3) -> Vec3 {
        cundall_strack_force(
            spring,
            &input.normal,
            &input.tangential_velocity,
            input.dt,
            self.stiffness,
            input.friction,
            input.normal_force,
        )
    }

    fn stiffness(&self, _: &TangentialInput) -> f64 {
        self.stiffness
    }

    /// ½ k_s |ξ_s|².
    fn energy(&self, _: &TangentialInput, spring: &Vec3) -> f64 {
        0.5 * self.stiffness * spring.norm_squared()
    }

    fn stiffness_before_contact(&self, _: f64) -> f64 {
        self.stiffness
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn force_never_leaves_friction_cone() {
        let n = Vec3::z();
        let mut s = Vec3::zeros();
        for k in 0..100 {
            let v = Vec3::new(0.3 * k as f64, -0.1, 0.0);
            let f = cundall_strack_force(&mut s, &n, &v, 1e-3, 1e5, 0.4, 10.0);
            assert!(f.norm() <= 0.4 * 10.0 * (1.0 + 1e-12));
            assert!(f.dot(&n).abs() < 1e-12);
        }
    }

    #[test]
    fn rotation_keeps_spring_length_and_tangency() {
        let s = Vec3::new(1.0, 0.0, 0.5);
        let n = Vec3::new(0.0, 1.0, 1.0).normalize();
        let r = rotate_into_plane(s, &n);
        approx::assert_relative_eq!(r.norm(), s.norm(), max_relative = 1e-14);
        assert!(r.dot(&n).abs() < 1e-14);
    }

    #[test]
    fn sticking_spring_is_elastic() {
        let n = Vec3::z();
        let mut s = Vec3::zeros();
        let f = cundall_strack_force(&mut s, &n, &Vec3::new(1.0, 0.0, 0.0), 1e-3, 1e4, 0.5, 100.0);
        approx::assert_relative_eq!(f.x, -10.0, max_relative = 1e-14);
    }
}
