//! LAMMPS's `pair granular` tangential model `linear_nohistory x_γ,t μ` (scene law
//! `lammps_linear_nohistory`), reproduced operation for operation from LAMMPS 22 Jul
//! 2025 (update 4), src/GRANULAR/gran_sub_mod_tangential.cpp
//! `GranSubModTangentialLinearNoHistory::calculate_forces` ("classic pair gran/hooke
//! (no history)"), with the normal damping's prefactor from gran_sub_mod_damping.cpp
//! and F_s from granular_model.cpp. tamp's notation as in `lammps_linear_history`:
//!
//! ```text
//!   γ_t = x_γ,t η_n      (η_n: the normal damping's coefficient this step,
//!                         F_n,damp = η_n dδ/dt; 0 without damping)
//!   F_s = μ |F_n|        (F_n elastic + damping)
//!   F_t = −min(F_s, γ_t |v_t|) v_t / |v_t|     (0 when v_t = 0)
//! ```
//!
//! A viscous friction without a spring (so without a stiffness and without memory): it
//! is Haff & Werner's law (`haff_werner`, F_t = −min(γ_s|v_t|, μF_n) v̂_t) with
//! γ_s = x_γ,t η_n following the normal damping through the contact, and Coulomb's
//! limit on |F_n|. Without normal damping it gives no force at all (which is how
//! `tamp export-lammps` writes a frictionless scene: `linear_nohistory 0 0`). The lever
//! arms are the scene's (`contact.lever_arm`; `lammps` for LAMMPS's). Parameters: x_γ,t
//! (dimensionless), μ from the material pair. docs/lammps.md has the measured
//! agreement.

use super::{TangentialInput, TangentialLaw, TangentialModel};
use crate::contact::lammps::NoLammpsModel;
use crate::contact::model::Roles;
use crate::contact::registry::{self, TangentialExample};
use crate::error::Errors;
use crate::particles::Vec3;

/// `{"law": "lammps_linear_nohistory", "x_gamma_t": x, "friction": μ}`.
#[derive(Clone, Copy, Debug, PartialEq, serde::Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct LammpsLinearNohistory {
    /// x_γ,t: the tangential dashpot over the normal one, γ_t = x_γ,t η_n.
    pub x_gamma_t: f64,
}

impl TangentialModel for LammpsLinearNohistory {
    type State = ();

    fn name(&self) -> &'static str {
        "lammps_linear_nohistory"
    }

    /// The dashpot −x_γ,t η_n v_t below the cone; Coulomb's −μ|F_n| v̂_t above it.
    fn examples() -> Vec<TangentialExample> {
        let law = TangentialLaw::LammpsLinearNohistory(LammpsLinearNohistory { x_gamma_t: 0.5 });
        let (stick, slide) = registry::damped_inputs(2.0);
        vec![
            // 0.5·2·0.01 = 0.01 N < μ F_n = 1.2 N.
            TangentialExample {
                law,
                input: stick,
                force: -stick.tangential_velocity * (0.5 * 2.0),
            },
            // 0.5·2·1 = 1 N < 1.2 N: still the dashpot; with η_n = 200, the cone.
            TangentialExample {
                law,
                input: slide,
                force: -slide.tangential_velocity * (0.5 * 2.0),
            },
            TangentialExample {
                law,
                input: TangentialInput {
                    normal_damping: 200.0,
                    ..slide
                },
                force: registry::sliding_force(&slide),
            },
        ]
    }

    fn check(&self, path: &str, _: Roles, e: &mut Errors) {
        e.non_negative(format!("{path}.x_gamma_t"), self.x_gamma_t);
    }

    fn lammps(&self) -> Result<String, NoLammpsModel> {
        Ok(format!(
            "linear_nohistory {} {{mu}}",
            crate::decimal::g(self.x_gamma_t)
        ))
    }

    #[inline(always)]
    fn force(&self, input: &TangentialInput, _: &mut ()) -> Vec3 {
        let damping = self.x_gamma_t * input.normal_damping;
        let limit = input.normal_force.abs() * input.friction;
        let speed = input.tangential_velocity.norm();
        let viscous = damping * speed;
        // LAMMPS's MIN(F_s, γ_t|v_t|)/|v_t|, in its order.
        let per_speed = if speed != 0.0 {
            (if limit < viscous { limit } else { viscous }) / speed
        } else {
            0.0
        };
        input.tangential_velocity * -per_speed
    }

    fn stiffness(&self, _: &TangentialInput) -> f64 {
        0.0
    }

    fn energy(&self, _: &TangentialInput, _: &()) -> f64 {
        0.0
    }

    fn dashpot_over_normal(&self) -> f64 {
        self.x_gamma_t
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_dashpot_follows_the_normal_damping_and_stops_at_the_cone() {
        let law = LammpsLinearNohistory { x_gamma_t: 0.5 };
        let v = Vec3::new(3.0, 4.0, 0.0);
        let at = |normal_force: f64, normal_damping: f64| {
            law.force(
                &TangentialInput {
                    tangential_velocity: v,
                    normal_force,
                    normal_damping,
                    ..registry::sticking_input()
                },
                &mut (),
            )
        };
        // γ_t |v| = 0.5·2·5 = 5 N below μ|F_n| = 0.4·100 N: the dashpot.
        approx::assert_relative_eq!(at(100.0, 2.0).x, -3.0, max_relative = 1e-15);
        // Above μ|F_n| = 0.4·|−5| = 2 N (a pulling normal force counts): the cone.
        approx::assert_relative_eq!(at(-5.0, 2.0).norm(), 2.0, max_relative = 1e-15);
        // No normal damping, no force; no slip, no force.
        assert_eq!(at(100.0, 0.0), Vec3::zeros());
        let still = TangentialInput {
            tangential_velocity: Vec3::zeros(),
            normal_damping: 2.0,
            ..registry::sticking_input()
        };
        assert_eq!(law.force(&still, &mut ()), Vec3::zeros());
    }

    #[test]
    fn names_its_lammps_keyword_and_coefficient() {
        let law = LammpsLinearNohistory { x_gamma_t: 0.5 };
        assert_eq!(law.lammps().unwrap(), "linear_nohistory 5e-1 {mu}");
    }
}
