//! Hysteretic linear law (Zhong 2009 model V, eqs 17–18).
//!
//!   F_n = k_n δ (1 + γ sgn(dδ/dt)),  0 ≤ γ < 1
//!
//! Zhong writes F_dn = −γ_n sgn(ξ̇) F_cn with ξ̇ the normal relative velocity
//! (negative on approach); in our convention dδ/dt > 0 on approach, hence the plus.
//! The contact is stiffer while loading, k(1 + γ), than while unloading, k(1 − γ),
//! so a head-on collision has e = √((1 − γ)/(1 + γ)) whatever the speed, and with
//! Zhong's γ_n = 0.7 (Tables 1–2) e = 0.420. γ is dimensionless.
//! No history. Stiffness for the time step: k(1 + γ).
//! Recoverable (stored) energy: ½ k (1 − γ) δ², released along the unloading branch.

use super::NormalLaw;
use super::{NormalModel, NormalResponse};
use crate::contact::registry::{self, NormalExample};
use crate::error::Errors;
use crate::material::PairProperties;

/// Hysteretic force k_n δ (1 + γ sgn(dδ/dt)), N: stiffer while the overlap grows.
pub fn hysteretic_force(overlap: f64, overlap_rate: f64, stiffness: f64, hysteresis: f64) -> f64 {
    let factor = if overlap_rate > 0.0 {
        1.0 + hysteresis
    } else if overlap_rate < 0.0 {
        1.0 - hysteresis
    } else {
        1.0
    };
    stiffness * overlap * factor
}

/// Closed-form restitution of a head-on collision.
pub fn hysteretic_restitution(hysteresis: f64) -> f64 {
    ((1.0 - hysteresis) / (1.0 + hysteresis)).sqrt()
}

/// Zhong model V; k_n in N/m, γ dimensionless in [0, 1).
#[derive(Clone, Copy, Debug, PartialEq, serde::Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct Hysteretic {
    /// Base normal stiffness k_n, N/m.
    pub stiffness: f64,
    /// Hysteresis factor γ, dimensionless, in [0, 1).
    pub hysteresis: f64,
}

impl NormalModel for Hysteretic {
    type State = ();
    const OWN_DISSIPATION: bool = true;

    fn name(&self) -> &'static str {
        "hysteretic"
    }

    /// Loading (dδ/dt > 0): F = k_n (1 + γ) δ (Zhong eq 17).
    fn examples() -> Vec<NormalExample> {
        let law = NormalLaw::Hysteretic(Hysteretic {
            stiffness: 1e7,
            hysteresis: 0.5,
        });
        registry::loading_examples(law, |overlap| 1e7 * 1.5 * overlap)
    }

    fn check(&self, path: &str, e: &mut Errors) {
        e.positive(format!("{path}.stiffness"), self.stiffness);
        if !(self.hysteresis >= 0.0 && self.hysteresis < 1.0) {
            e.push(
                format!("{path}.hysteresis"),
                format!("must be in [0, 1), got {}", self.hysteresis),
            );
        }
    }

    #[inline(always)]
    fn response(
        &self,
        overlap: f64,
        rate: f64,
        _: f64,
        _: &PairProperties,
        _: &mut (),
    ) -> NormalResponse {
        NormalResponse {
            force: hysteretic_force(overlap, rate, self.stiffness, self.hysteresis),
            stiffness: self.stiffness * (1.0 + self.hysteresis),
        }
    }

    fn stiffness(&self, _: f64, _: f64, _: &PairProperties, _: &()) -> f64 {
        self.stiffness * (1.0 + self.hysteresis)
    }

    fn energy(&self, overlap: f64, _: f64, _: &PairProperties, _: &()) -> f64 {
        0.5 * self.stiffness * (1.0 - self.hysteresis) * overlap * overlap
    }

    fn impact_stiffness(&self, _: f64, _: f64, _: f64, _: &PairProperties) -> f64 {
        self.stiffness * (1.0 + self.hysteresis)
    }

    fn stiffness_depends_on_speed(&self) -> bool {
        false
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn loading_is_stiffer_than_unloading() {
        assert_eq!(hysteretic_force(1e-3, 1.0, 1e6, 0.7), 1e3 * 1.7);
        assert!((hysteretic_force(1e-3, -1.0, 1e6, 0.7) - 300.0).abs() < 1e-9);
        assert!((hysteretic_restitution(0.7) - 0.420_084).abs() < 1e-6);
    }
}
