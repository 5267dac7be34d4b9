//! The loading axis of the two scalar tangential laws with loading/unloading memory
//! (Mindlin–Deresiewicz, Walton–Braun). Both were derived for a tangential load
//! along one line; tamp applies their scalar rule along a loading axis ê:
//!
//! - during virgin loading ê follows the force; once the load reverses ê is frozen
//!   (rotated with the contact plane), so unloading may take the force through zero
//!   to the other side, as the 1D laws require;
//! - the displacement increment along ê drives the scalar law; its component across
//!   ê turns the force with the same current tangent stiffness.
//!
//! For collinear loading (every closed form, the oblique impact) this is exactly the
//! published law; for loading that changes direction it is one reasonable extension
//! among several (Thornton & Yin 1991 discuss the non-uniqueness).

use super::cundall_strack::rotate_into_plane;
use super::incremental::cap_to_cone;
use crate::contact::model::ContactState;
use crate::particles::Vec3;
use serde::{Deserialize, Serialize};
use std::ops::ControlFlow;

/// Loading state of the scalar tangential laws (Zhong eq 20, k = 0, 1, 2).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum TangentialBranch {
    /// k = 0: first loading from a virgin contact.
    #[default]
    Loading,
    /// k = 1: unloading from the turning point.
    Unloading,
    /// k = 2: reloading after an unloading.
    Reloading,
}

/// What a scalar-axis law (Mindlin–Deresiewicz, Walton–Braun) keeps per contact.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct ScalarAxisState {
    /// The tangential force F_t in the contact plane, N.
    pub tangential: Vec3,
    /// Force at the last turning point, N (Mindlin–Deresiewicz F^k, Walton–Braun F*).
    pub turning_force: f64,
    /// Normal force at the previous step, N (its increment ΔF_n drives Mindlin–Deresiewicz).
    pub previous_normal_force: f64,
    /// Loading branch k: first loading, unloading or reloading.
    pub branch: TangentialBranch,
    /// Unit loading axis.
    pub axis: Vec3,
}

impl ScalarAxisState {
    /// Forget the tangential state (force, axis, branch, turning point) while the
    /// bodies stay in contact; the previous normal force is kept.
    pub fn forget_tangential(&mut self) {
        *self = ScalarAxisState {
            previous_normal_force: self.previous_normal_force,
            ..ScalarAxisState::default()
        };
    }
}

impl ContactState for ScalarAxisState {
    fn tangential(&self) -> Vec3 {
        self.tangential
    }
}

/// Displacement increment split on the axis: (ê, along, across).
pub struct AxisIncrement {
    /// Unit loading axis ê in the current contact plane.
    pub axis: Vec3,
    /// Stored force along ê, N (signed).
    pub force_along: f64,
    /// Displacement increment along ê, m (signed).
    pub along: f64,
    /// Part of the displacement increment across ê, m.
    pub across: Vec3,
}

/// Rotate the stored force and axis into the current plane and split the increment
/// the force follows (−v_t Δt) on the axis. `Break` is a force to return at once:
/// zero, with the tangential state forgotten, when there is no friction cone
/// (`limit` = μN ≤ 0); the stored force on the cone when there is neither a force
/// nor a displacement to define an axis.
pub fn split(
    history: &mut ScalarAxisState,
    normal: &Vec3,
    tangential_velocity: &Vec3,
    dt: f64,
    limit: f64,
) -> ControlFlow<Vec3, AxisIncrement> {
    if limit <= 0.0 {
        history.forget_tangential();
        return ControlFlow::Break(Vec3::zeros());
    }
    history.tangential = rotate_into_plane(history.tangential, normal);
    let increment = -tangential_velocity * dt;
    let mut axis = rotate_into_plane(history.axis, normal);
    if axis.norm_squared() == 0.0 {
        let n = increment.norm();
        if n == 0.0 {
            return ControlFlow::Break(cap_to_cone(history.tangential, 1.0, limit));
        }
        axis = increment / n;
    }
    let along = increment.dot(&axis);
    ControlFlow::Continue(AxisIncrement {
        axis,
        force_along: history.tangential.dot(&axis),
        along,
        across: increment - axis * along,
    })
}

/// Store the new force (capped to the cone) and the axis for the next step: the
/// axis follows the force during first loading and stays frozen afterwards.
pub fn finish(history: &mut ScalarAxisState, force: Vec3, axis: Vec3, limit: f64) -> Vec3 {
    history.tangential = cap_to_cone(force, 1.0, limit);
    history.axis =
        if history.branch == TangentialBranch::Loading && history.tangential.norm_squared() > 0.0 {
            history.tangential.normalize()
        } else {
            axis
        };
    history.tangential
}
