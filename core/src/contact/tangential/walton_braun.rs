//! Walton–Braun tangential law (Zhong 2009 model X, eqs 26–27; Walton & Braun 1986).
//! Along the loading axis (`scalar_axis.rs`) with the signed force F:
//!
//!   ΔF = k̃ Δs                                            (eq 26)
//!   k̃ = k₀ ((μN − F)/(μN − F*))^{1/3}   while F increases (eq 27a)
//!   k̃ = k₀ ((μN + F)/(μN + F*))^{1/3}   while F decreases (eq 27b)
//!
//! F* starts at zero and takes the value of F whenever the direction of loading
//! reverses. Zhong prints a minus sign before k₀ in eq 27b, which with ΔF = k̃Δs
//! would make the force grow as the displacement reverses; the stiffness is positive
//! in Walton & Braun's law (docs/paper-discrepancies.md). Normal force changes are
//! neglected in the stiffness, as the model assumes. |F| ≤ μN.
//! History: force vector, axis, direction, F*. Stiffness for the time step: k₀.

use super::incremental::spring_energy;
use super::{TangentialInput, TangentialLaw, TangentialModel};
use crate::contact::model::Roles;
use crate::contact::registry::{self, TangentialExample};
use crate::error::Errors;

use super::scalar_axis::{ScalarAxisState, TangentialBranch};
use super::scalar_axis::{finish, split};
use crate::particles::Vec3;
use std::ops::ControlFlow;

/// One step of eqs 26–27 along the loading axis, with initial stiffness k₀
/// (`initial_stiffness`, N/m). Returns the tangential force on particle i, N.
#[inline]
pub fn walton_braun_tangential_force(
    history: &mut ScalarAxisState,
    normal: &Vec3,
    tangential_velocity: &Vec3,
    dt: f64,
    initial_stiffness: f64,
    friction: f64,
    normal_force: f64,
) -> Vec3 {
    let mu_n = friction * normal_force.max(0.0);
    let step = match split(history, normal, tangential_velocity, dt, mu_n) {
        ControlFlow::Continue(step) => step,
        ControlFlow::Break(force) => return force,
    };
    let f = step.force_along;
    let was_increasing = history.branch != TangentialBranch::Unloading;
    // A zero increment keeps the current direction (and F*).
    let increasing = if step.along == 0.0 {
        was_increasing
    } else {
        step.along > 0.0
    };
    if increasing != was_increasing {
        history.turning_force = f;
        history.branch = if increasing {
            TangentialBranch::Reloading
        } else {
            TangentialBranch::Unloading
        };
    }
    let f_star = history.turning_force;
    // At the turning point itself the ratio is 1 whatever F* (a reversal starts at k₀);
    // taken as such, F = F* = ±μN, where both sides of the quotient vanish, is not 0/0.
    let ratio = if f == f_star {
        1.0
    } else if increasing {
        (mu_n - f) / (mu_n - f_star)
    } else {
        (mu_n + f) / (mu_n + f_star)
    };
    let stiffness = initial_stiffness * ratio.clamp(0.0, 1.0).cbrt();
    let force = history.tangential + (step.axis * step.along + step.across) * stiffness;
    finish(history, force, step.axis, mu_n)
}

/// Zhong model X; k₀ in N/m. State: `ScalarAxisState`.
#[derive(Clone, Copy, Debug, PartialEq, serde::Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct WaltonBraun {
    /// Initial tangential stiffness k₀, N/m.
    pub stiffness: f64,
}

impl TangentialModel for WaltonBraun {
    type State = ScalarAxisState;

    fn name(&self) -> &'static str {
        "walton_braun"
    }

    /// From rest F* = F = 0, so k̃ = k₀ and F = −k₀ v_t Δt (eqs 26–27); sliding: −μF_n v̂_t.
    fn examples() -> Vec<TangentialExample> {
        let law = TangentialLaw::WaltonBraun(WaltonBraun { stiffness: 1e6 });
        registry::spring_examples(law, 1e6)
    }

    fn check(&self, path: &str, _: Roles, e: &mut Errors) {
        e.positive(format!("{path}.stiffness"), self.stiffness);
    }

    #[inline(always)]
    fn force(&self, input: &TangentialInput, state: &mut ScalarAxisState) -> Vec3 {
        walton_braun_tangential_force(
            state,
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

    fn energy(&self, _: &TangentialInput, state: &ScalarAxisState) -> f64 {
        spring_energy(&state.tangential, self.stiffness)
    }

    fn stiffness_before_contact(&self, _: f64) -> f64 {
        self.stiffness
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn first_loading_integrates_eq27a() {
        // dF/ds = k0 (1 − F/μN)^{1/3} ⇒ F = μN[1 − (1 − 2k0 s/(3μN))^{3/2}].
        let (k0, mu, n) = (1e6, 0.5, 4.0);
        let mut h = ScalarAxisState::default();
        let s_total = 0.8 * 3.0 * mu * n / (2.0 * k0);
        let steps = 50_000;
        let v = Vec3::new(-s_total / steps as f64, 0.0, 0.0);
        let mut f = Vec3::zeros();
        for _ in 0..steps {
            f = walton_braun_tangential_force(&mut h, &Vec3::z(), &v, 1.0, k0, mu, n);
        }
        let closed = mu * n * (1.0 - (1.0 - 2.0 * k0 * s_total / (3.0 * mu * n)).powf(1.5));
        assert_relative_eq!(f.x, closed, max_relative = 1e-3);
    }

    /// Reloading from a turning point on the Coulomb cone (F = F* = μN): eq 27a's
    /// quotient is 0/0 there. The force stays on the cone instead of turning NaN.
    #[test]
    fn reloading_at_the_cone_from_a_turning_point_on_it_stays_finite() {
        let (k0, mu, n) = (1e6, 0.5, 4.0);
        let mut h = ScalarAxisState {
            tangential: Vec3::new(mu * n, 0.0, 0.0),
            turning_force: mu * n,
            branch: TangentialBranch::Reloading,
            axis: Vec3::x(),
            ..ScalarAxisState::default()
        };
        let v = Vec3::new(-1e-9, 0.0, 0.0);
        let f = walton_braun_tangential_force(&mut h, &Vec3::z(), &v, 1.0, k0, mu, n);
        assert_eq!(f, Vec3::new(mu * n, 0.0, 0.0));
    }
}
