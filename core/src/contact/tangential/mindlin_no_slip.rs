//! Mindlin–Deresiewicz no-slip tangential law, "H-MDNs" (Rojek 2016 eqs 11–14; Di
//! Renzo & Di Maio 2004). Incremental (`incremental.rs`) with the tangent stiffness
//! of the no-slip solution,
//!
//!   k_t = 8 G* √(R* δ) = 8 G* a          (eq 12; a = √(R* δ) the contact radius)
//!   1/G* = (2 − ν_i)/G_i + (2 − ν_j)/G_j  (eq 13)
//!   |F_t| ≤ μ max(F_n, 0)                (eq 14 writes μ|F_n|; tamp's laws cap at the
//!                                         compressive normal force, contact/model.rs)
//!
//! Micro-slip inside the contact is ignored (that is the full Mindlin–Deresiewicz
//! law, `mindlin_deresiewicz.rs`). History: the tangential force vector (N).
//! Stiffness for the time step: k_t at the current overlap.

use super::incremental::{incremental_step, spring_energy};
use super::{TangentialInput, TangentialLaw, TangentialModel};
use crate::contact::model::Needs;
use crate::contact::registry::{self, TangentialExample};
use crate::particles::Vec3;

/// No-slip tangential stiffness k_t = 8 G* √(R* δ), N/m (eq 12).
pub fn mindlin_no_slip_stiffness(
    overlap: f64,
    effective_radius: f64,
    effective_shear_modulus: f64,
) -> f64 {
    8.0 * effective_shear_modulus * (effective_radius * overlap).sqrt()
}

/// Rojek eqs 11–14 (H-MDNs). State: the incremental tangential force, N.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct MindlinNoSlip {}

impl TangentialModel for MindlinNoSlip {
    type State = Vec3;

    fn name(&self) -> &'static str {
        "mindlin_no_slip"
    }

    /// F = −8G*√(R*δ) v_t Δt from rest (Rojek eqs 11–13); sliding: −μF_n v̂_t.
    fn examples() -> Vec<TangentialExample> {
        let law = TangentialLaw::MindlinNoSlip(MindlinNoSlip {});
        registry::spring_examples(law, registry::mindlin_stiffness())
    }

    fn needs(&self) -> Needs {
        Needs {
            elastic: Some(" (G*, Rojek eq 13)"),
            ..Needs::default()
        }
    }

    #[inline(always)]
    fn force(&self, input: &TangentialInput, force: &mut Vec3) -> Vec3 {
        incremental_step(force, input, self.stiffness(input))
    }

    fn stiffness(&self, input: &TangentialInput) -> f64 {
        mindlin_no_slip_stiffness(
            input.overlap,
            input.effective_radius,
            input.effective_shear_modulus,
        )
    }

    fn energy(&self, input: &TangentialInput, force: &Vec3) -> f64 {
        spring_energy(force, self.stiffness(input))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ratio_to_hertz_normal_stiffness_is_4g_over_e() {
        // k_t/k_n = 8G*a/(2E*a) = 4G*/E*; for equal materials with ν = 0.3 this is
        // 4·(E/(2·2.6·1.7))/(E/(2·0.91)) = 0.8235 (the familiar 2(1−ν)/(2−ν)).
        let (r, d, nu): (f64, f64, f64) = (1e-3, 1e-6, 0.3);
        let e_star = 1.0 / (2.0 * (1.0 - nu * nu));
        let g_star = 1.0 / (2.0 * 2.0 * (1.0 + nu) * (2.0 - nu));
        let k_n = 2.0 * e_star * (r * d).sqrt();
        let ratio = mindlin_no_slip_stiffness(d, r, g_star) / k_n;
        assert!((ratio - 2.0 * (1.0 - nu) / (2.0 - nu)).abs() < 1e-12);
    }
}
