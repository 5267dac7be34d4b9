//! Kuwabara–Kono / Brilliantov viscoelastic Hertz law (Zhong 2009 model III, eq 15;
//! Kuwabara & Kono 1987; Brilliantov et al. 1996, Phys. Rev. E 53, 5382).
//!
//!   F_n = k̃ (δ^{3/2} + 3/2 A δ^{1/2} dδ/dt),  k̃ = 4/3 E* √R*,  F_n ≥ 0
//!
//! A (s) is the dissipation time of the material pair. The damping term grows with
//! the contact area, which makes the coefficient of restitution fall with impact
//! speed as 1 − e ≈ C₁ (3/2) A (k̃/m*)^{2/5} v^{1/5}, C₁ = 1.15344 (Schwager & Pöschel 2008,
//! Phys. Rev. E 78, 051304). The force is clamped at zero: the surfaces part when
//! the total force vanishes, before δ returns to zero, so the law never attracts.
//! Zhong's eq 15 gives A from the viscosities with (3η₂ − η₁) not squared, which
//! has units of 1/Pa; Brilliantov's original squares it (docs/paper-discrepancies.md).
//! No history. Stiffness for the time step: the Hertz tangent 2E*√(R*δ).

use super::NormalLaw;
use super::hertz::{Hertz, hertz_force, hertz_stiffness};
use super::{NormalModel, NormalResponse};
use crate::contact::damping::Damping;
use crate::contact::model::Needs;
use crate::contact::registry::{self, NormalExample};
use crate::error::Errors;
use crate::material::PairProperties;

/// Viscoelastic Hertz force k̃ (δ^{3/2} + 3/2 A δ^{1/2} dδ/dt), clamped at zero, N.
pub fn kuwabara_kono_force(
    overlap: f64,
    overlap_rate: f64,
    effective_radius: f64,
    effective_modulus: f64,
    dissipation_time: f64,
) -> f64 {
    let elastic = hertz_force(overlap, effective_radius, effective_modulus);
    // 3/2 A δ^{1/2} δ̇ k̃ = A k_n δ̇ with k_n = 2E*√(R*δ): the same tangent stiffness.
    let viscous = dissipation_time
        * hertz_stiffness(overlap, effective_radius, effective_modulus)
        * overlap_rate;
    (elastic + viscous).max(0.0)
}

/// Zhong model III; A is the dissipation time, s.
#[derive(Clone, Copy, Debug, PartialEq, serde::Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct KuwabaraKono {
    /// Dissipation time A ≥ 0 of the material pair, s.
    pub dissipation_time: f64,
}

impl NormalModel for KuwabaraKono {
    type State = ();
    const OWN_DISSIPATION: bool = true;

    fn name(&self) -> &'static str {
        "kuwabara_kono"
    }

    /// F = (4/3) E* √R* (δ^{3/2} + (3/2) A δ^{1/2} dδ/dt) (Zhong eq 15).
    fn examples() -> Vec<NormalExample> {
        let law = NormalLaw::KuwabaraKono(KuwabaraKono {
            dissipation_time: 1e-7,
        });
        let k = 4.0 / 3.0 * registry::EFFECTIVE_MODULUS * registry::EFFECTIVE_RADIUS.sqrt();
        let rate = registry::LOADING_RATE;
        registry::loading_examples(law, |overlap| {
            k * (overlap.powf(1.5) + 1.5 * 1e-7 * overlap.sqrt() * rate)
        })
    }

    fn needs(&self) -> Needs {
        Needs {
            elastic: Some(""),
            ..Needs::default()
        }
    }

    fn check(&self, path: &str, e: &mut Errors) {
        e.non_negative(format!("{path}.dissipation_time"), self.dissipation_time);
    }

    #[inline(always)]
    fn response(
        &self,
        overlap: f64,
        rate: f64,
        r: f64,
        pair: &PairProperties,
        _: &mut (),
    ) -> NormalResponse {
        let e = pair.effective_modulus.unwrap_or(0.0);
        NormalResponse {
            force: kuwabara_kono_force(overlap, rate, r, e, self.dissipation_time),
            stiffness: hertz_stiffness(overlap, r, e),
        }
    }

    /// The elastic (Hertz) part's tangent: the stored state has no rate.
    fn stiffness(&self, overlap: f64, r: f64, pair: &PairProperties, state: &()) -> f64 {
        Hertz {}.stiffness(overlap, r, pair, state)
    }

    fn energy(&self, overlap: f64, r: f64, pair: &PairProperties, state: &()) -> f64 {
        Hertz {}.energy(overlap, r, pair, state)
    }

    fn impact_stiffness(&self, mass: f64, speed: f64, r: f64, pair: &PairProperties) -> f64 {
        Hertz {}.impact_stiffness(mass, speed, r, pair)
    }

    fn stiffness_depends_on_speed(&self) -> bool {
        true
    }

    fn error_model(&self, damping: Option<&Damping>) -> Option<&'static str> {
        damping.is_none().then_some("kuwabara_kono")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn matches_eq15_term_by_term() {
        let (r, e, a): (f64, f64, f64) = (1e-3, 1e9, 1e-6);
        let k_tilde = 4.0 / 3.0 * e * r.sqrt();
        for (d, rate) in [(1e-6, 0.1), (3e-6, -0.01), (1e-5, 0.5)] {
            let direct = k_tilde * (d * f64::sqrt(d) + 1.5 * a * d.sqrt() * rate);
            assert_relative_eq!(
                kuwabara_kono_force(d, rate, r, e, a),
                direct.max(0.0),
                max_relative = 1e-13
            );
        }
    }

    #[test]
    fn never_attracts() {
        assert_eq!(kuwabara_kono_force(1e-9, -10.0, 1e-3, 1e9, 1e-5), 0.0);
    }
}
