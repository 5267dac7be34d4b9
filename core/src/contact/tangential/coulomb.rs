//! Coulomb sliding friction (Zhong 2009 model VII, eq 22).
//!
//!   F_t = −μ max(F_n, 0) v_t/|v_t|,  and 0 when v_t = 0
//!
//! (the cap takes only a compressive normal force: a contact pulled by cohesion has no
//! friction).
//!
//! Pure kinetic friction, no spring: the force always opposes the slip velocity,
//! so it dissipates at every instant and cannot hold a contact at rest against a
//! tangential load (it chatters about v_t = 0 instead). Use it for flows that slide,
//! not for static packings. No history. No stiffness enters the time step.

use super::{TangentialInput, TangentialLaw, TangentialModel};
use crate::contact::registry::{self, TangentialExample};

use crate::particles::Vec3;

/// Kinetic friction force −μ max(F_n, 0) v_t/|v_t| on particle i, N; zero when v_t = 0.
#[inline]
pub fn coulomb_force(tangential_velocity: &Vec3, friction: f64, normal_force: f64) -> Vec3 {
    let speed = tangential_velocity.norm();
    if speed == 0.0 {
        return Vec3::zeros();
    }
    -tangential_velocity * (friction * normal_force.max(0.0) / speed)
}

/// Zhong model VII: sliding friction only, no spring.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct Coulomb {}

impl TangentialModel for Coulomb {
    type State = ();

    fn name(&self) -> &'static str {
        "coulomb"
    }

    /// F = −μF_n v̂_t whatever the speed (Zhong eq 22).
    fn examples() -> Vec<TangentialExample> {
        [registry::sticking_input(), registry::sliding_input()]
            .map(|input| TangentialExample {
                law: TangentialLaw::Coulomb(Coulomb {}),
                input,
                force: registry::sliding_force(&input),
            })
            .to_vec()
    }

    #[inline(always)]
    fn force(&self, input: &TangentialInput, _: &mut ()) -> Vec3 {
        coulomb_force(
            &input.tangential_velocity,
            input.friction,
            input.normal_force,
        )
    }

    fn stiffness(&self, _: &TangentialInput) -> f64 {
        0.0
    }

    fn energy(&self, _: &TangentialInput, _: &()) -> f64 {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn opposes_slip_with_magnitude_mu_fn() {
        let f = coulomb_force(&Vec3::new(3.0, 4.0, 0.0), 0.5, 10.0);
        assert!((f - Vec3::new(-3.0, -4.0, 0.0)).norm() < 1e-14);
        assert_eq!(coulomb_force(&Vec3::zeros(), 0.5, 10.0), Vec3::zeros());
    }
}
