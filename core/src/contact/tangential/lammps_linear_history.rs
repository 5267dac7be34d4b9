//! LAMMPS's `pair granular` tangential model `linear_history k_t x_γ,t μ` (scene law
//! `lammps_linear_history`), reproduced operation for operation from LAMMPS 22 Jul
//! 2025 (update 4), src/GRANULAR/gran_sub_mod_tangential.cpp
//! `GranSubModTangentialLinearHistory::calculate_forces`, with the normal damping's
//! prefactor from gran_sub_mod_damping.cpp and F_s from granular_model.cpp. tamp's
//! notation: `normal` n from the partner to particle i, v_t the tangential velocity of
//! i's contact point relative to the partner's (spins included), F_n the total normal
//! force, elastic plus damping. Per step:
//!
//! ```text
//!   γ_t = x_γ,t η_n            (η_n: the normal damping's coefficient this step,
//!                               F_n,damp = η_n dδ/dt; 0 without damping)
//!   F_s = μ |F_n|              (`set_fncrit`: Fncrit = |F_n,elastic + F_n,damp|)
//!   if k_t |h·n| > 1e-10 F_s:  h ← (h − (h·n) n) · |h| / |h − (h·n) n|
//!                              (turned into the contact plane, length kept)
//!   h ← h + v_t Δt
//!   F_t = −k_t h − γ_t v_t
//!   if |F_t| > F_s and |h| ≠ 0:  F_t ← F_t F_s/|F_t|,  h ← −(F_t + γ_t v_t)/k_t
//!   if |F_t| > F_s and |h| = 0:  F_t ← 0
//! ```
//!
//! So it is a Cundall–Strack spring with a tangential dashpot that follows the normal
//! damping (the dashpot counts in the Coulomb test, and the spring keeps only the
//! elastic part of the force on the cone), with Coulomb's limit on |F_n| (friction
//! acts while the damped normal force pulls at the end of a contact) and the history
//! turned only above the threshold. tamp's `cundall_strack` instead caps at
//! μ·max(F_n, 0), turns every step and has no dashpot. The history h (m) starts at
//! zero when a contact forms and is dropped when it ends, as in tamp. The lever arms
//! are the scene's (`contact.lever_arm`; `lammps` for LAMMPS's). Parameters: k_t
//! (N/m), x_γ,t (dimensionless), μ from the material pair, and `history`: this rule,
//! or one of the two classic ones (`classic_step`): `pair granular`'s
//! `linear_history_classic` and `pair_style gran/hooke/history`'s. docs/lammps.md has
//! the measured agreement.

use super::lammps_mindlin::{onto_the_cone, turn_above_threshold};
use super::{TangentialInput, TangentialLaw, TangentialModel};
use crate::contact::lammps::NoLammpsModel;
use crate::contact::model::Roles;
use crate::contact::registry::{self, TangentialExample};
use crate::error::Errors;
use crate::particles::Vec3;

/// `{"law": "lammps_linear_history", "stiffness": k_t, "x_gamma_t": x, "friction": μ}`,
/// with `"history"` naming which of LAMMPS's shear histories.
#[derive(Clone, Copy, Debug, PartialEq, serde::Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct LammpsLinearHistory {
    /// k_t, N/m.
    pub stiffness: f64,
    /// x_γ,t: the tangential dashpot over the normal one, γ_t = x_γ,t η_n.
    pub x_gamma_t: f64,
    /// Which of LAMMPS's rules keeps the history.
    #[serde(default, skip_serializing_if = "LammpsHistory::is_default")]
    pub history: LammpsHistory,
}

/// The shear histories LAMMPS keeps with a linear spring.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Deserialize, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum LammpsHistory {
    /// `pair granular`'s `linear_history`: turned into the contact plane above a
    /// threshold, length kept.
    #[default]
    LinearHistory,
    /// `pair granular`'s `linear_history_classic` (`classic_step`): grown, then
    /// projected every step without keeping its length, the spring k_t a.
    LinearHistoryClassic,
    /// `pair_style gran/hooke/history` (pair_gran_hooke_history.cpp): the classic rule
    /// with the spring k_t itself.
    GranHookeHistory,
}

impl LammpsHistory {
    fn is_default(&self) -> bool {
        *self == LammpsHistory::LinearHistory
    }
}

impl LammpsLinearHistory {
    /// The spring's stiffness now: k_t, or k_t a (a = √(R* δ)) for `pair granular`'s
    /// classic history.
    fn spring(&self, input: &TangentialInput) -> f64 {
        match self.history {
            LammpsHistory::LinearHistoryClassic => {
                self.stiffness * (input.overlap * input.effective_radius).sqrt()
            }
            _ => self.stiffness,
        }
    }
}

/// The classic shear history, operation for operation as LAMMPS 22 Jul 2025 keeps it
/// in `linear_history_classic` (`GranSubModTangentialLinearHistoryClassic::
/// calculate_forces`) and in `pair_style gran/hooke/history`
/// (`PairGranHookeHistory::compute`), `spring` being the spring's stiffness:
///
/// ```text
///   h ← h + v_t Δt;  s = |h|;  h ← h − (h·n) n    (projected, length not kept)
///   F_t = −spring h − γ_t v_t
///   if |F_t| > F_s and s ≠ 0:  F_t ← F_t F_s/|F_t|,  h ← −(F_t + γ_t v_t)/k_t
///   if |F_t| > F_s and s = 0:  F_t ← 0
/// ```
///
/// `gran/hooke/history`'s spring is k_t. The 22 Jul 2025 release sets
/// `contact_radius_flag = 1` for `linear_history_classic`, so there the spring is k_t
/// times the contact radius a = √(R* δ), with the hooke normal law too, while the
/// cone's reset divides by k_t alone: in SI units a is micrometres, and the spring is
/// that many times softer than the style whose behaviour the model's comment names
/// (docs/lammps.md).
#[inline(always)]
fn classic_step(h: &mut Vec3, input: &TangentialInput, k: f64, spring: f64, damping: f64) -> Vec3 {
    let limit = input.normal_force.abs() * input.friction;
    *h += input.tangential_velocity * input.dt;
    let magnitude = h.norm();
    *h -= input.normal * h.dot(&input.normal);
    let dashpot = input.tangential_velocity * -damping;
    let mut f = *h * -spring + dashpot;
    onto_the_cone(&mut f, h, dashpot, limit, -1.0 / k, Some(magnitude));
    f
}

impl TangentialModel for LammpsLinearHistory {
    type State = Vec3;

    fn name(&self) -> &'static str {
        "lammps_linear_history"
    }

    /// From rest, one step, sticking: F = −k_t v_t Δt − x_γ,t η_n v_t; sliding:
    /// Coulomb's −μ|F_n| v̂_t (the dashpot inside the cone).
    fn examples() -> Vec<TangentialExample> {
        let eta = 2.0;
        let (stick, slide) = registry::damped_inputs(eta);
        let v = stick.tangential_velocity;
        // pair granular's classic spring is k_t a: its k_t is chosen so that k_t a =
        // 1e6 N/m here.
        let a = (stick.overlap * stick.effective_radius).sqrt();
        [
            (LammpsHistory::LinearHistory, 1e6),
            (LammpsHistory::LinearHistoryClassic, 1e6 / a),
            (LammpsHistory::GranHookeHistory, 1e6),
        ]
        .into_iter()
        .flat_map(|(history, stiffness)| {
            let law = LammpsLinearHistory {
                stiffness,
                x_gamma_t: 0.5,
                history,
            };
            let tangential = TangentialLaw::LammpsLinearHistory(law);
            let spring = law.spring(&stick);
            [
                TangentialExample {
                    law: tangential,
                    input: stick,
                    force: -v * (spring * stick.dt) - v * (0.5 * eta),
                },
                TangentialExample {
                    law: tangential,
                    input: slide,
                    force: registry::sliding_force(&slide),
                },
            ]
        })
        .collect()
    }

    /// k_t > 0 (LAMMPS takes k_t = 0, then divides by it on the cone), x_γ,t ≥ 0.
    fn check(&self, path: &str, _: Roles, e: &mut Errors) {
        e.positive(format!("{path}.stiffness"), self.stiffness);
        e.non_negative(format!("{path}.x_gamma_t"), self.x_gamma_t);
    }

    fn lammps(&self) -> Result<String, NoLammpsModel> {
        let keyword = match self.history {
            LammpsHistory::LinearHistory => "linear_history",
            LammpsHistory::LinearHistoryClassic => "linear_history_classic",
            LammpsHistory::GranHookeHistory => {
                return Err(NoLammpsModel(
                    "pair granular has no tangential model with gran/hooke/history's unscaled spring (tamp export-lammps writes a scene with this history as pair_style gran/hooke/history, where that style can say the rest)".into(),
                ));
            }
        };
        Ok(format!(
            "{keyword} {} {} {{mu}}",
            crate::decimal::g(self.stiffness),
            crate::decimal::g(self.x_gamma_t)
        ))
    }

    #[inline(always)]
    fn force(&self, input: &TangentialInput, h: &mut Vec3) -> Vec3 {
        let k = self.stiffness;
        let damping = self.x_gamma_t * input.normal_damping;
        if self.history != LammpsHistory::LinearHistory {
            return classic_step(h, input, k, self.spring(input), damping);
        }
        let limit = input.normal_force.abs() * input.friction;
        turn_above_threshold(h, &input.normal, k, limit);
        *h += input.tangential_velocity * input.dt;
        let dashpot = input.tangential_velocity * -damping;
        let mut f = *h * -k + dashpot;
        onto_the_cone(&mut f, h, dashpot, limit, -1.0 / k, None);
        f
    }

    /// k_t, or k_t a for `pair granular`'s classic history.
    fn stiffness(&self, input: &TangentialInput) -> f64 {
        self.spring(input)
    }

    /// ½ k |h|² with the spring's k (k_t, or k_t a for `pair granular`'s classic
    /// history).
    fn energy(&self, input: &TangentialInput, h: &Vec3) -> f64 {
        0.5 * self.spring(input) * h.norm_squared()
    }

    fn stiffness_before_contact(&self, _: f64) -> f64 {
        self.stiffness
    }

    fn dashpot_over_normal(&self) -> f64 {
        self.x_gamma_t
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn law() -> LammpsLinearHistory {
        LammpsLinearHistory {
            stiffness: 1e4,
            x_gamma_t: 0.5,
            history: LammpsHistory::LinearHistory,
        }
    }

    fn input(v: Vec3, normal_force: f64, normal_damping: f64) -> TangentialInput {
        TangentialInput {
            normal: Vec3::z(),
            tangential_velocity: v,
            dt: 1e-3,
            friction: 0.5,
            normal_force,
            normal_damping,
            ..registry::sticking_input()
        }
    }

    #[test]
    fn on_the_cone_the_spring_keeps_only_the_elastic_part() {
        // k h = 1e4·(3, 4)e-3 = (30, 40) N, γ_t v = 0.5·1·(3, 4) = (1.5, 2) N: |F| = 52.5 N
        // > μ|F_n| = 0.5·20 = 10 N, so F = −10 v̂ = (−6, −8) N and
        // h = −(F + γ_t v)/k = (4.5, 6)e-4 m.
        let mut h = Vec3::zeros();
        let f = law().force(&input(Vec3::new(3.0, 4.0, 0.0), -20.0, 1.0), &mut h);
        approx::assert_relative_eq!(f.x, -6.0, max_relative = 1e-14);
        approx::assert_relative_eq!(f.y, -8.0, max_relative = 1e-14);
        approx::assert_relative_eq!(h.x, 4.5e-4, max_relative = 1e-13);
        approx::assert_relative_eq!(h.y, 6e-4, max_relative = 1e-13);
    }

    #[test]
    fn the_history_is_turned_only_above_the_threshold() {
        // A history tilted out of the plane by 1e-12 rad keeps its normal component:
        // k|h·n| = 1e4·1e-3·1e-12 = 1e-11 N is below 1e-10 F_s = 5e-9 N (F_s = 0.5·100 N,
        // above the spring's 10 N); tilted by 1e-3 it is turned into the plane with its
        // length kept.
        for (tilt, turned) in [(1e-12, false), (1e-3, true)] {
            let mut h = Vec3::new(1e-3, 0.0, 1e-3 * tilt);
            let length = h.norm();
            law().force(&input(Vec3::zeros(), 100.0, 0.0), &mut h);
            assert_eq!(h.z == 0.0, turned, "tilt {tilt}");
            approx::assert_relative_eq!(h.norm(), length, max_relative = 1e-14);
        }
    }

    /// The classic history is projected every step, its length not kept: a history
    /// tilted by 1e-12 rad, which `linear_history` leaves alone, loses its normal
    /// component and with it its length (by cos of the tilt); so does one tilted by 0.6,
    /// which `linear_history` turns at full length.
    #[test]
    fn the_classic_history_is_projected_every_step_and_shrinks() {
        let classic = LammpsLinearHistory {
            history: LammpsHistory::LinearHistoryClassic,
            ..law()
        };
        for tilt in [1e-12, 0.6f64] {
            let mut h = Vec3::new(1e-3 * tilt.cos(), 0.0, 1e-3 * tilt.sin());
            classic.force(&input(Vec3::zeros(), 100.0, 0.0), &mut h);
            assert_eq!(h.z, 0.0, "tilt {tilt}");
            approx::assert_relative_eq!(h.x, 1e-3 * tilt.cos(), max_relative = 1e-15);
        }
        // The history grows before it is projected: a velocity along n is removed; the
        // spring is k_t times the contact radius a = √(R* δ).
        let mut h = Vec3::new(1e-4, 0.0, 0.0);
        let along_n = input(Vec3::new(0.0, 0.0, 1.0), 100.0, 0.0);
        let f = classic.force(&along_n, &mut h);
        assert_eq!(h, Vec3::new(1e-4, 0.0, 0.0));
        let a = (along_n.overlap * along_n.effective_radius).sqrt();
        assert_eq!(f, Vec3::new(-(1e4 * a) * 1e-4, 0.0, 0.0));
        // On the cone the history is reset with 1/k_t, not 1/(k_t a).
        let mut h = Vec3::new(1.0, 0.0, 0.0);
        let f = classic.force(&input(Vec3::zeros(), 1e-6, 0.0), &mut h);
        approx::assert_relative_eq!(f.x, -0.5e-6, max_relative = 1e-15);
        approx::assert_relative_eq!(h.x, 0.5e-6 / 1e4, max_relative = 1e-15);
    }

    #[test]
    fn names_its_lammps_keyword_and_coefficients() {
        assert_eq!(law().lammps().unwrap(), "linear_history 1e4 5e-1 {mu}");
        let classic = LammpsLinearHistory {
            history: LammpsHistory::LinearHistoryClassic,
            ..law()
        };
        assert_eq!(
            classic.lammps().unwrap(),
            "linear_history_classic 1e4 5e-1 {mu}"
        );
        let gran = LammpsLinearHistory {
            history: LammpsHistory::GranHookeHistory,
            ..law()
        };
        assert!(gran.lammps().is_err());
    }

    /// `gran/hooke/history` keeps the classic rule with the spring k_t itself: the same
    /// growth and projection, F = −k_t h, and the same reset on the cone.
    #[test]
    fn the_gran_history_is_the_classic_rule_with_an_unscaled_spring() {
        let gran = LammpsLinearHistory {
            history: LammpsHistory::GranHookeHistory,
            ..law()
        };
        let mut h = Vec3::new(1e-4, 0.0, 2e-5);
        let f = gran.force(&input(Vec3::new(0.0, 0.0, 1.0), 100.0, 0.0), &mut h);
        assert_eq!(h, Vec3::new(1e-4, 0.0, 0.0));
        assert_eq!(f, Vec3::new(-1e4 * 1e-4, 0.0, 0.0));
        let mut h = Vec3::new(1.0, 0.0, 0.0);
        let f = gran.force(&input(Vec3::zeros(), 1e-6, 0.0), &mut h);
        approx::assert_relative_eq!(f.x, -0.5e-6, max_relative = 1e-15);
        approx::assert_relative_eq!(h.x, 0.5e-6 / 1e4, max_relative = 1e-15);
    }
}
