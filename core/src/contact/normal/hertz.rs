//! Hertz elastic normal law (Rojek 2016 eqs 2, 9; Zhong 2009 model II, eqs 10–13).
//!
//!   F_n^e = 4/3 E* √R* δ^{3/2}                 (eq 2; Rojek writes h = −δ)
//!   k_n   = dF/dδ = 2 E* √(R* δ) = ∛(6 R* E*² F)  (eqs 9–10)
//!   U     = 8/15 E* √R* δ^{5/2}
//!
//! E* from Rojek eq 3, R* from eq 4 (`crate::material`). No history.
//! A head-on collision at approach speed v has the closed forms (Johnson 1985 §11.4):
//!   δ_max = (15 m* v² / (16 E* √R*))^{2/5}
//!   t_c   = 3.2180655 (m*/k̃)^{2/5} v^{−1/5},  k̃ = 4/3 E* √R*
//! Zhong eq 13 prints the constant as 3.21 (0.25 % low; docs/paper-discrepancies.md).
//! LIGGGHTS keyword: `model hertz`.

use super::NormalLaw;
use super::{NormalModel, NormalResponse};
use crate::contact::damping::Damping;
use crate::contact::damping::liggghts::LiggghtsModel;
use crate::contact::lammps::{LammpsNormal, NoLammpsModel};
use crate::contact::model::{LiggghtsDeck, LiggghtsRefusal, LiggghtsScene, Needs};
use crate::contact::registry::{self, NormalExample};
use crate::material::PairProperties;

/// Hertz elastic normal force F_n = 4/3 E* √R* δ^{3/2}, N (eq 2).
pub fn hertz_force(overlap: f64, effective_radius: f64, effective_modulus: f64) -> f64 {
    4.0 / 3.0 * effective_modulus * (effective_radius * overlap).sqrt() * overlap
}

/// Hertz tangent stiffness k_n = dF/dδ = 2 E* √(R* δ), N/m (eq 9).
pub fn hertz_stiffness(overlap: f64, effective_radius: f64, effective_modulus: f64) -> f64 {
    2.0 * effective_modulus * (effective_radius * overlap).sqrt()
}

/// Elastic energy stored at overlap δ, U = 8/15 E* √R* δ^{5/2}, J.
pub fn hertz_energy(overlap: f64, effective_radius: f64, effective_modulus: f64) -> f64 {
    8.0 / 15.0 * effective_modulus * effective_radius.sqrt() * overlap.powf(2.5)
}

/// Inverse of eq 2: the overlap at which the Hertz force equals `force`.
pub fn hertz_overlap_at_force(force: f64, effective_radius: f64, effective_modulus: f64) -> f64 {
    (force / (4.0 / 3.0 * effective_modulus * effective_radius.sqrt())).powf(2.0 / 3.0)
}

/// Largest overlap δ_max of an undamped head-on collision at approach speed v, m.
pub fn hertz_max_overlap(
    effective_mass: f64,
    approach_speed: f64,
    effective_radius: f64,
    effective_modulus: f64,
) -> f64 {
    (15.0 * effective_mass * approach_speed.powi(2)
        / (16.0 * effective_modulus * effective_radius.sqrt()))
    .powf(0.4)
}

/// Exact constant of the elastic Hertz contact duration,
/// 2·√π·Γ(7/5)/Γ(9/10)·(5/4)^{2/5} (derived in docs/paper-discrepancies.md §2), to
/// double precision: the test `duration_constant_is_the_gamma_expression` recomputes it.
pub const HERTZ_DURATION_CONSTANT: f64 = 3.218_065_459_719_043_5;

/// Duration t_c of an undamped head-on collision at approach speed v, s.
pub fn hertz_contact_duration(
    effective_mass: f64,
    approach_speed: f64,
    effective_radius: f64,
    effective_modulus: f64,
) -> f64 {
    let k_tilde = 4.0 / 3.0 * effective_modulus * effective_radius.sqrt();
    HERTZ_DURATION_CONSTANT * (effective_mass / k_tilde).powf(0.4) * approach_speed.powf(-0.2)
}

/// The Hertz law (no parameters: E* and R* come from the pair).
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct Hertz {}

impl NormalModel for Hertz {
    type State = ();

    fn name(&self) -> &'static str {
        "hertz"
    }

    /// F = (4/3) E* √R* δ^{3/2} (Rojek eq 2).
    fn examples() -> Vec<NormalExample> {
        let k = 4.0 / 3.0 * registry::EFFECTIVE_MODULUS * registry::EFFECTIVE_RADIUS.sqrt();
        registry::loading_examples(NormalLaw::Hertz(Hertz {}), |overlap| k * overlap.powf(1.5))
    }

    fn needs(&self) -> Needs {
        Needs {
            elastic: Some(""),
            ..Needs::default()
        }
    }

    fn liggghts(&self) -> Option<LiggghtsModel> {
        Some(LiggghtsModel::Hertz)
    }

    /// `hertz/material E damp ν`: F = (4/3)E* a δ, a = √(R*δ), the same E* mixing
    /// (contact/lammps.rs).
    fn lammps(&self) -> Result<LammpsNormal, NoLammpsModel> {
        Ok(LammpsNormal::HertzMaterial)
    }

    /// `model hertz`, damped by `coefficientRestitution` (no constant γ_n form).
    fn liggghts_deck(
        &self,
        scene: &LiggghtsScene,
    ) -> Option<Result<LiggghtsDeck, Vec<LiggghtsRefusal>>> {
        if let Some(Damping::Constant(_)) = scene.damping {
            return Some(Err(vec![(
                "contact.damping.kind".into(),
                "a constant gamma_n has no LIGGGHTS form with model hertz (use liggghts_restitution or critical_fraction)".into(),
            )]));
        }
        Some(Ok(LiggghtsDeck {
            model: "hertz",
            options: "",
            properties: vec![
                scene.coefficient_restitution(),
                scene.coefficient_friction(),
            ],
        }))
    }

    #[inline(always)]
    fn response(
        &self,
        overlap: f64,
        _: f64,
        r: f64,
        pair: &PairProperties,
        _: &mut (),
    ) -> NormalResponse {
        let e = pair.effective_modulus.unwrap_or(0.0);
        NormalResponse {
            force: hertz_force(overlap, r, e),
            stiffness: hertz_stiffness(overlap, r, e),
        }
    }

    fn stiffness(&self, overlap: f64, r: f64, pair: &PairProperties, _: &()) -> f64 {
        hertz_stiffness(overlap, r, pair.effective_modulus.unwrap_or(0.0))
    }

    fn energy(&self, overlap: f64, r: f64, pair: &PairProperties, _: &()) -> f64 {
        hertz_energy(overlap, r, pair.effective_modulus.unwrap_or(0.0))
    }

    /// The tangent stiffness at the largest overlap of a head-on impact.
    fn impact_stiffness(&self, mass: f64, speed: f64, r: f64, pair: &PairProperties) -> f64 {
        let e = pair.effective_modulus.unwrap_or(0.0);
        hertz_stiffness(hertz_max_overlap(mass, speed, r, e), r, e)
    }

    fn stiffness_depends_on_speed(&self) -> bool {
        true
    }

    fn error_model(&self, damping: Option<&Damping>) -> Option<&'static str> {
        match damping {
            None => Some("hertz"),
            // η_n0·m* is one constant γ_n for a given impact.
            Some(Damping::Constant(_) | Damping::MassVelocity(_)) => Some("hertz_constant_damped"),
            Some(
                Damping::CriticalFraction(_) | Damping::LiggghtsRestitution(_) | Damping::Tsuji(_),
            ) => Some("hertz_damped"),
            Some(Damping::Viscoelastic(_)) => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    const R: f64 = 5e-6;
    const E: f64 = 1e11;

    /// 2 (5/4)^{2/5} ∫₀¹ dx/√(1 − x^{5/2}) (twice the time to the turning point in the
    /// units of hertz_max_overlap), which is (4/5)(5/4)^{2/5} B(2/5, 1/2) and
    /// B(2/5, 1/2) = 2 ∫₀^{π/2} sin^{−1/5}θ dθ. With θ = t^{5/4} the integrand is bounded
    /// and Simpson's rule on 200 000 intervals gives it to about 1e-14.
    #[test]
    fn duration_constant_is_the_gamma_expression() {
        let end = std::f64::consts::FRAC_PI_2.powf(0.8);
        let f = |t: f64| {
            if t == 0.0 {
                1.25
            } else {
                1.25 * t.powf(0.25) * t.powf(1.25).sin().powf(-0.2)
            }
        };
        let simpson = crate::quadrature::simpson(f, 0.0, end, 200_000);
        let beta = 2.0 * simpson;
        let constant = 0.8 * 1.25f64.powf(0.4) * beta;
        assert_relative_eq!(constant, HERTZ_DURATION_CONSTANT, max_relative = 1e-12);
    }

    #[test]
    fn stiffness_matches_both_rojek_forms() {
        let d = 3e-9;
        let f = hertz_force(d, R, E);
        assert_relative_eq!(
            hertz_stiffness(d, R, E),
            (6.0 * R * E * E * f).cbrt(),
            max_relative = 1e-12
        );
    }

    #[test]
    fn stiffness_is_force_derivative() {
        let (d, h) = (3e-9, 1e-15);
        let fd = (hertz_force(d + h, R, E) - hertz_force(d - h, R, E)) / (2.0 * h);
        assert_relative_eq!(fd, hertz_stiffness(d, R, E), max_relative = 1e-6);
    }

    #[test]
    fn energy_derivative_is_force() {
        let (d, h) = (3e-9, 1e-15);
        let fd = (hertz_energy(d + h, R, E) - hertz_energy(d - h, R, E)) / (2.0 * h);
        assert_relative_eq!(fd, hertz_force(d, R, E), max_relative = 1e-6);
    }

    #[test]
    fn overlap_at_force_inverts_force() {
        let d = 2e-9;
        assert_relative_eq!(
            hertz_overlap_at_force(hertz_force(d, R, E), R, E),
            d,
            max_relative = 1e-12
        );
    }

    #[test]
    fn max_overlap_stores_all_kinetic_energy() {
        let (m, v) = (1e-11, 0.2);
        let d = hertz_max_overlap(m, v, R, E);
        assert_relative_eq!(hertz_energy(d, R, E), 0.5 * m * v * v, max_relative = 1e-12);
    }
}
