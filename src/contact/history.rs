//! What a contact remembers between steps. One record per potential contact, kept
//! only when the scene's law needs memory (`ContactLaw::has_history`), and reset to
//! the default when the bodies separate: like LIGGGHTS and Yade, tamp forgets a
//! contact once it opens, including any permanent set.

use crate::particles::Vec3;
use serde::{Deserialize, Serialize};

/// Loading state of the Mindlin–Deresiewicz tangential law (Zhong eq 20, k = 0, 1, 2).
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

#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct ContactHistory {
    /// Tangential state vector in the contact plane: the spring elongation ξ_s (m) for
    /// Cundall–Strack, the tangential force F_t (N) for the incremental laws.
    pub tangential: Vec3,
    /// Largest overlap reached on the loading branch, m (Walton–Braun normal, Storåkers).
    pub max_overlap: f64,
    /// Force at the last turning point, N (Mindlin–Deresiewicz F^k, Walton–Braun F*).
    pub turning_force: f64,
    /// Normal force at the previous step, N (its increment ΔF_n drives Mindlin–Deresiewicz).
    pub previous_normal_force: f64,
    pub branch: TangentialBranch,
    /// Unit loading axis of the scalar tangential laws (Mindlin–Deresiewicz, Walton–Braun).
    pub axis: Vec3,
}

impl ContactHistory {
    /// Forget the tangential state (force, axis, branch, turning point) while the
    /// bodies stay in contact; δ_max and the previous normal force record the normal
    /// force and are kept.
    pub fn forget_tangential(&mut self) {
        *self = ContactHistory {
            max_overlap: self.max_overlap,
            previous_normal_force: self.previous_normal_force,
            ..ContactHistory::default()
        };
    }
}
