//! Tangential stiffness of the Storåkers contact (Rojek 2016 eq 21, after Olsson &
//! Larsson 2013): the incremental law of eq 11 (`incremental.rs`) with
//!
//!   k_t = β k_n
//!
//! where k_n is the current tangent stiffness of the normal law (eq 22 while
//! loading plastically, eq 20 while unloading) and β = 0.5–5 per Olsson & Larsson.
//! Used with any normal law, it ties the tangential spring to that law's stiffness.
//! History: the tangential force vector (N). Stiffness for the time step: β k_n.

use super::incremental::{incremental_step, spring_energy};
use super::{TangentialInput, TangentialLaw, TangentialModel};
use crate::contact::model::Roles;
use crate::contact::registry::{self, TangentialExample};
use crate::error::Errors;
use crate::particles::Vec3;

/// Tangential stiffness k_t = β k_n, N/m (eq 21).
pub fn storakers_tangential_stiffness(beta: f64, normal_stiffness: f64) -> f64 {
    beta * normal_stiffness
}

/// Rojek eq 21: k_t = β k_n. State: the incremental tangential force, N.
#[derive(Clone, Copy, Debug, PartialEq, serde::Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct Storakers {
    /// Ratio β = k_t/k_n of tangential to normal stiffness, dimensionless.
    pub beta: f64,
}

impl TangentialModel for Storakers {
    type State = Vec3;

    fn name(&self) -> &'static str {
        "storakers"
    }

    /// F = −β k_n v_t Δt from rest (Rojek eq 21, β = 1); sliding: −μF_n v̂_t.
    fn examples() -> Vec<TangentialExample> {
        let law = TangentialLaw::Storakers(Storakers { beta: 1.0 });
        registry::spring_examples(law, registry::sticking_input().normal_stiffness)
    }

    fn check(&self, path: &str, _: Roles, e: &mut Errors) {
        e.positive(format!("{path}.beta"), self.beta);
    }

    #[inline(always)]
    fn force(&self, input: &TangentialInput, force: &mut Vec3) -> Vec3 {
        incremental_step(force, input, self.stiffness(input))
    }

    fn stiffness(&self, input: &TangentialInput) -> f64 {
        storakers_tangential_stiffness(self.beta, input.normal_stiffness)
    }

    fn energy(&self, input: &TangentialInput, force: &Vec3) -> f64 {
        spring_energy(force, self.stiffness(input))
    }
}
