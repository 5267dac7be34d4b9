//! Mindlin–Deresiewicz tangential law with micro-slip and loading history (Zhong
//! 2009 model VI, eqs 19–21; Thornton & Yin 1991, Powder Technol. 65, 153; Di Renzo
//! & Di Maio 2004). Along the loading axis (`scalar_axis.rs`), with the signed
//! tangential force F, normal force N and its increment ΔN over the step:
//!
//!   ΔF = 8 G* a θ_k Δs + (−1)^k μ ΔN (1 − θ_k),   a = √(R* δ)          (eq 19)
//!   θ_0³ = 1 − (F + μΔN)/(μN)                       first loading, k = 0  (eq 20)
//!   θ_1³ = 1 − (F¹ − F + 2μΔN)/(2μN)                unloading,     k = 1
//!   θ_2³ = 1 − (F − F² + 2μΔN)/(2μN)                reloading,     k = 2
//!   θ_k = 1 when |8 G* a Δs| < μ|ΔN|; turning points move as F^k ← F^k − (−1)^k μΔN
//!
//! Under constant N first loading integrates to Mindlin's curve
//! F = μN[1 − (1 − 2k₀s/(3μN))^{3/2}], k₀ = 8G*a, reaching μN at s = 3μN/(2k₀), and
//! unloading follows Masing's rule F = F¹ − 2μN[1 − (1 − k₀(s¹−s)/(3μN))^{3/2}].
//! Zhong eq 21 prints G* = Σ (2 − ν)/G without the reciprocal; we use Rojek's eq 13
//! (docs/paper-discrepancies.md). θ³ is clamped to [0, 1] and |F| to μN.
//! History: force vector, axis, branch k, turning point F^k, previous N.
//! Stiffness for the time step: k₀ = 8 G* a (θ = 1, the largest).

use super::incremental::spring_energy;
use super::mindlin_no_slip::MindlinNoSlip;
use super::{TangentialInput, TangentialLaw, TangentialModel};
use crate::contact::model::Needs;
use crate::contact::registry::{self, TangentialExample};

use super::scalar_axis::{ScalarAxisState, TangentialBranch};
use super::scalar_axis::{finish, split};
use crate::particles::Vec3;
use std::ops::ControlFlow;

/// One step of eq 19 along the loading axis, with initial stiffness k₀ = 8G*a
/// (`initial_stiffness`, N/m). Returns the tangential force on particle i, N.
#[inline]
pub fn mindlin_deresiewicz_force(
    history: &mut ScalarAxisState,
    normal: &Vec3,
    tangential_velocity: &Vec3,
    dt: f64,
    initial_stiffness: f64,
    friction: f64,
    normal_force: f64,
) -> Vec3 {
    let n = normal_force.max(0.0);
    let dn = n - history.previous_normal_force;
    history.previous_normal_force = n;
    let mu_n = friction * n;
    let step = match split(history, normal, tangential_velocity, dt, mu_n) {
        ControlFlow::Continue(step) => step,
        ControlFlow::Break(force) => return force,
    };
    let f = step.force_along;
    use TangentialBranch::*;
    match history.branch {
        Loading | Reloading if step.along < 0.0 => {
            history.branch = Unloading;
            history.turning_force = f;
        }
        Unloading if step.along > 0.0 => {
            history.branch = Reloading;
            history.turning_force = f;
        }
        _ => {}
    }
    let mu_dn = friction * dn;
    let theta = if (initial_stiffness * step.along).abs() < mu_dn.abs() {
        1.0
    } else {
        let cube = match history.branch {
            Loading => 1.0 - (f + mu_dn) / mu_n,
            Unloading => 1.0 - (history.turning_force - f + 2.0 * mu_dn) / (2.0 * mu_n),
            Reloading => 1.0 - (f - history.turning_force + 2.0 * mu_dn) / (2.0 * mu_n),
        };
        cube.clamp(0.0, 1.0).cbrt()
    };
    let sign = if history.branch == Unloading {
        -1.0
    } else {
        1.0
    };
    let along = initial_stiffness * theta * step.along + sign * mu_dn * (1.0 - theta);
    match history.branch {
        Unloading => history.turning_force += mu_dn,
        Reloading => history.turning_force -= mu_dn,
        Loading => {}
    }
    let force = history.tangential + step.axis * along + step.across * (initial_stiffness * theta);
    finish(history, force, step.axis, mu_n)
}

/// Zhong model VI. State: force, axis, branch, turning point and the previous
/// normal force (`ScalarAxisState`).
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct MindlinDeresiewicz {}

impl TangentialModel for MindlinDeresiewicz {
    type State = ScalarAxisState;

    fn name(&self) -> &'static str {
        "mindlin_deresiewicz"
    }

    /// First loading from rest with k Δs < μΔN: θ = 1, F = −8G*√(R*δ) v_t Δt (eq 19); sliding: −μF_n v̂_t.
    fn examples() -> Vec<TangentialExample> {
        let law = TangentialLaw::MindlinDeresiewicz(MindlinDeresiewicz {});
        registry::spring_examples(law, registry::mindlin_stiffness())
    }

    fn needs(&self) -> Needs {
        Needs {
            elastic: Some(" (G*, Rojek eq 13)"),
            ..Needs::default()
        }
    }

    #[inline(always)]
    fn force(&self, input: &TangentialInput, state: &mut ScalarAxisState) -> Vec3 {
        mindlin_deresiewicz_force(
            state,
            &input.normal,
            &input.tangential_velocity,
            input.dt,
            self.stiffness(input),
            input.friction,
            input.normal_force,
        )
    }

    /// The initial (θ = 1) stiffness, 8 G* a (Mindlin no-slip).
    fn stiffness(&self, input: &TangentialInput) -> f64 {
        MindlinNoSlip {}.stiffness(input)
    }

    fn energy(&self, input: &TangentialInput, state: &ScalarAxisState) -> f64 {
        spring_energy(&state.tangential, self.stiffness(input))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    const K0: f64 = 1e6;
    const MU: f64 = 0.4;
    const N: f64 = 10.0;

    /// Drive the contact along +x (force along −x) by `s` in `steps` increments.
    fn drive(h: &mut ScalarAxisState, s: f64, steps: usize) -> f64 {
        let v = Vec3::new(s / steps as f64, 0.0, 0.0);
        let mut f = Vec3::zeros();
        for _ in 0..steps {
            f = mindlin_deresiewicz_force(h, &Vec3::z(), &v, 1.0, K0, MU, N);
        }
        -f.x
    }

    fn virgin(s: f64) -> f64 {
        MU * N * (1.0 - (1.0 - 2.0 * K0 * s / (3.0 * MU * N)).max(0.0).powf(1.5))
    }

    #[test]
    fn first_loading_follows_mindlin_closed_form() {
        let mut h = ScalarAxisState {
            previous_normal_force: N,
            ..Default::default()
        };
        let s_slide = 3.0 * MU * N / (2.0 * K0);
        let mut s = 0.0;
        for k in 1..=5 {
            let ds = 0.18 * s_slide;
            let f = drive(&mut h, ds, 20_000);
            s += ds;
            assert_relative_eq!(f, virgin(s), max_relative = 2e-3);
            assert!(f <= MU * N * (1.0 + 1e-12), "step {k}");
        }
    }

    #[test]
    fn unloading_follows_masing() {
        let mut h = ScalarAxisState {
            previous_normal_force: N,
            ..Default::default()
        };
        let s1 = 0.7 * 3.0 * MU * N / (2.0 * K0);
        let f1 = drive(&mut h, s1, 40_000);
        let back = 0.5 * s1;
        let f = drive(&mut h, -back, 40_000);
        let masing = f1 - 2.0 * virgin(0.5 * back);
        assert_relative_eq!(f, masing, max_relative = 2e-3);
    }
}
