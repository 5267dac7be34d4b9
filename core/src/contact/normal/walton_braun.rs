//! Walton–Braun normal law: linear loading, stiffer linear unloading with a
//! permanent set (Zhong 2009 model IV, eq 16; Walton & Braun 1986, J. Rheol. 30, 949).
//!
//!   loading (δ = δ_max, the virgin branch):  F = k₁ δ
//!   unloading and reloading (δ < δ_max):     F = max(0, k₂ (δ − δ₀)),  δ₀ = δ_max (1 − k₁/k₂)
//!
//! Zhong writes the branch choice with the sign of dδ/dt; we choose it by the memory
//! δ_max instead, which is Walton & Braun's original rule: reloading after a partial
//! unloading climbs the k₂ line until it meets the k₁ line at δ_max, so the law is
//! path-independent between turning points and never creates energy. A head-on
//! collision has e = √(k₁/k₂) exactly, whatever the speed. Requires k₂ ≥ k₁.
//! History: δ_max (m). Stiffness for the time step: k₂ on every contact, since a
//! loading contact turns onto the k₂ branch the step its overlap stops growing.
//! Recoverable (stored) energy: ½ k₂ (δ − δ₀)² while δ > δ₀.

use super::NormalLaw;
use super::{NormalModel, NormalResponse, PeakOverlap};
use crate::contact::damping::Damping;
use crate::contact::registry::{self, NormalExample};
use crate::error::Errors;
use crate::material::PairProperties;

/// Force and tangent stiffness at `overlap` given the largest overlap so far.
pub fn walton_braun_response(
    overlap: f64,
    max_overlap: f64,
    loading_stiffness: f64,
    unloading_stiffness: f64,
) -> (f64, f64) {
    if overlap >= max_overlap {
        (loading_stiffness * overlap, loading_stiffness)
    } else {
        let set = max_overlap * (1.0 - loading_stiffness / unloading_stiffness);
        if overlap > set {
            (unloading_stiffness * (overlap - set), unloading_stiffness)
        } else {
            (0.0, unloading_stiffness)
        }
    }
}

/// Energy recoverable by unloading from `overlap`, ½ k₂ (δ − δ₀)², J, with δ₀ the
/// permanent set of the largest overlap reached (this one included).
pub fn walton_braun_energy(
    overlap: f64,
    max_overlap: f64,
    loading_stiffness: f64,
    unloading_stiffness: f64,
) -> f64 {
    let set = max_overlap.max(overlap) * (1.0 - loading_stiffness / unloading_stiffness);
    0.5 * unloading_stiffness * (overlap - set).max(0.0).powi(2)
}

/// Zhong model IV; k₁ loading, k₂ unloading, N/m.
#[derive(Clone, Copy, Debug, PartialEq, serde::Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct WaltonBraun {
    /// Loading stiffness k₁ of the virgin branch, N/m.
    pub loading_stiffness: f64,
    /// Unloading and reloading stiffness k₂ ≥ k₁, N/m.
    pub unloading_stiffness: f64,
}

impl NormalModel for WaltonBraun {
    type State = PeakOverlap;

    fn name(&self) -> &'static str {
        "walton_braun"
    }

    /// Loading branch: F = k₁ δ (Zhong eq 16).
    fn examples() -> Vec<NormalExample> {
        let law = NormalLaw::WaltonBraun(WaltonBraun {
            loading_stiffness: 1e7,
            unloading_stiffness: 3e7,
        });
        registry::loading_examples(law, |overlap| 1e7 * overlap)
    }

    fn check(&self, path: &str, e: &mut Errors) {
        let (loading, unloading) = (self.loading_stiffness, self.unloading_stiffness);
        e.positive(format!("{path}.loading_stiffness"), loading);
        if !(unloading >= loading && unloading.is_finite()) {
            e.push(
                format!("{path}.unloading_stiffness"),
                format!(
                    "must be >= loading_stiffness ({loading:e}) and finite: unloading is the stiffer branch, got {unloading:e}"
                ),
            );
        }
    }

    #[inline(always)]
    fn response(
        &self,
        overlap: f64,
        _: f64,
        _: f64,
        _: &PairProperties,
        state: &mut PeakOverlap,
    ) -> NormalResponse {
        state.max_overlap = state.max_overlap.max(overlap);
        let (force, stiffness) = walton_braun_response(
            overlap,
            state.max_overlap,
            self.loading_stiffness,
            self.unloading_stiffness,
        );
        NormalResponse { force, stiffness }
    }

    fn stiffness(&self, overlap: f64, _: f64, _: &PairProperties, state: &PeakOverlap) -> f64 {
        walton_braun_response(
            overlap,
            state.max_overlap.max(overlap),
            self.loading_stiffness,
            self.unloading_stiffness,
        )
        .1
    }

    /// The current branch's tangent, and for a contact on the loading branch also the
    /// unloading branch it turns onto the step its overlap stops growing. Without the
    /// second, a dense bed estimated while loading under-resolves its first unloading
    /// (the stable-α study, docs/accuracy-cost.md).
    fn time_step_stiffness(
        &self,
        overlap: f64,
        r: f64,
        pair: &PairProperties,
        state: &PeakOverlap,
    ) -> f64 {
        let current = self.stiffness(overlap, r, pair, state);
        let turning = if overlap > 0.0 {
            self.unloading_stiffness
        } else {
            0.0
        };
        current.max(turning)
    }

    fn energy(&self, overlap: f64, _: f64, _: &PairProperties, state: &PeakOverlap) -> f64 {
        walton_braun_energy(
            overlap,
            state.max_overlap,
            self.loading_stiffness,
            self.unloading_stiffness,
        )
    }

    fn impact_stiffness(&self, _: f64, _: f64, _: f64, _: &PairProperties) -> f64 {
        self.unloading_stiffness
    }

    fn stiffness_depends_on_speed(&self) -> bool {
        false
    }

    fn error_model(&self, damping: Option<&Damping>) -> Option<&'static str> {
        damping.is_none().then_some("walton_braun")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn unloading_line_meets_loading_line_at_the_turning_point() {
        let (k1, k2, dm) = (1e5, 4e5, 1e-4);
        let (f_load, _) = walton_braun_response(dm, dm, k1, k2);
        let (f_unload, _) = walton_braun_response(dm * (1.0 - 1e-12), dm, k1, k2);
        assert_relative_eq!(f_load, f_unload, max_relative = 1e-9);
        // permanent set: zero force at δ₀ = δ_max (1 − k1/k2)
        assert_eq!(walton_braun_response(0.75 * dm, dm, k1, k2).0, 0.0);
    }
}
