//! Tangential stiffness of the Storåkers contact (Rojek 2016 eq 21, after Olsson &
//! Larsson 2013): the incremental law of eq 11 (`incremental.rs`) with
//!
//!   k_t = β k_n
//!
//! where k_n is the current tangent stiffness of the normal law (eq 22 while
//! loading plastically, eq 20 while unloading) and β = 0.5–5 per Olsson & Larsson.
//! Used with any normal law, it ties the tangential spring to that law's stiffness.
//! History: the tangential force vector (N). Stiffness for the time step: β k_n.

use super::incremental::{incremental_force, spring_energy};
use super::{TangentialInput, TangentialModel};
use crate::particles::Vec3;

pub fn storakers_tangential_stiffness(beta: f64, normal_stiffness: f64) -> f64 {
    beta * normal_stiffness
}

/// Rojek eq 21: k_t = β k_n. State: the incremental tangential force, N.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Storakers {
    pub beta: f64,
}

impl TangentialModel for Storakers {
    type State = Vec3;

    #[inline(always)]
    fn force(&self, input: &TangentialInput, force: &mut Vec3) -> Vec3 {
        incremental_force(
            force,
            &input.normal,
            &input.tangential_velocity,
            input.dt,
            self.stiffness(input),
            input.friction,
            input.normal_force,
        )
    }

    fn stiffness(&self, input: &TangentialInput) -> f64 {
        storakers_tangential_stiffness(self.beta, input.normal_stiffness)
    }

    fn energy(&self, input: &TangentialInput, force: &Vec3) -> f64 {
        spring_energy(force, self.stiffness(input))
    }
}
