//! LIGGGHTS's normal damping from a coefficient of restitution, as tamp's
//! `critical_fraction` (scene kind `liggghts_restitution`). Equations as LIGGGHTS-PUBLIC
//! 3.8.0 evaluates them (release commit 84ba3d7, SI units), written in tamp's notation:
//! δ > 0 overlap, m* = m_i m_j/(m_i + m_j), R* = R_i R_j/(R_i + R_j), and
//! 1/E* = (1 − ν_i²)/E_i + (1 − ν_j²)/E_j (global_properties.cpp l. 432).
//!
//!   β   = ln e / √(ln²e + π²)   (≤ 0; global_properties.cpp l. 516, 539)
//!   `model hertz` (normal_model_hertz.h l. 231–237):
//!       S_n = 2E*√(R*δ),  γ_n = −2√(5/6) β √(S_n m*)
//!   `model hooke` (normal_model_hooke.h l. 269–274), V = `characteristicVelocity`:
//!       k_n = (16/15) √R* E* (15 m* V² / (16 √R* E*))^{1/5}   (independent of δ)
//!       γ_n = √(4 m* k_n ln²e / (ln²e + π²))
//!   both: F_n = k δ + γ_n dδ/dt, not clipped (`limitForce off`, the 3.8 default).
//!   e must satisfy 0.05 < e ≤ 1 (global_properties.cpp l. 488–489).
//!
//! tamp's `critical_fraction` is c_n = ξ · 2√(m* k), with k the normal law's tangent
//! stiffness: 2E*√(R*δ) = S_n for `hertz` (hertz.rs), k_n for `linear`. So
//!   hertz:  ξ = √(5/6) |ln e| / √(ln²e + π²) = −√(5/6) β
//!   linear: ξ =        |ln e| / √(ln²e + π²) = −β
//! and c_n equals LIGGGHTS's γ_n at every overlap. The linear law stands in for
//! `model hooke` when its stiffness is the k_n above (`hooke_stiffness`); LIGGGHTS's
//! other normal models (`hooke/stiffness`, `hertz/stiffness`) take their damping from
//! other inputs, and tamp's other laws have no LIGGGHTS counterpart.
//! See docs/liggghts.md for the full parameter mapping.

use super::CriticalFraction;
use crate::contact::lammps::{LammpsDamping, LammpsNormal, NoLammpsModel};
use crate::contact::model::Roles;
use crate::contact::normal::NormalLaw;
use crate::error::Errors;

/// √(5/6), the constant LIGGGHTS hard-codes in `model hertz`.
pub const SQRT_FIVE_SIXTHS: f64 = 0.912_870_929_175_276_9;

/// The LIGGGHTS model a tamp normal law reproduces.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum LiggghtsModel {
    /// `model hertz` = tamp `hertz`.
    #[default]
    Hertz,
    /// `model hooke` = tamp `linear` with k_n from `hooke_stiffness`.
    Hooke,
}

impl LiggghtsModel {
    /// The keyword in `pair_style gran model …`.
    pub fn keyword(&self) -> &'static str {
        match self {
            LiggghtsModel::Hertz => "hertz",
            LiggghtsModel::Hooke => "hooke",
        }
    }

    /// ξ of tamp's `critical_fraction` that reproduces LIGGGHTS's γ_n for restitution `e`.
    pub fn critical_fraction(&self, e: f64) -> f64 {
        match self {
            LiggghtsModel::Hertz => -SQRT_FIVE_SIXTHS * beta(e),
            LiggghtsModel::Hooke => -beta(e),
        }
    }
}

/// The damping kind `liggghts_restitution`: LIGGGHTS's restitution coefficient e. It
/// is not a dashpot of its own: the force loop runs it as the `CriticalFraction` ξ
/// that the scene's normal law gives (`critical_fraction`).
#[derive(Clone, Copy, Debug, PartialEq, serde::Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct LiggghtsRestitution {
    /// Coefficient of restitution e LIGGGHTS is given, in (0.05, 1].
    pub restitution: f64,
}

impl LiggghtsRestitution {
    /// The damping `kind` in the scene file.
    pub const NAME: &str = "liggghts_restitution";

    /// The dashpot it is beside `normal`, or why LIGGGHTS has none.
    pub fn with(&self, normal: &NormalLaw) -> Result<CriticalFraction, String> {
        match normal.liggghts() {
            Some(model) => Ok(CriticalFraction {
                xi: model.critical_fraction(self.restitution),
            }),
            None => Err(unsupported_law(normal.name())),
        }
    }

    /// The rules of `restitution`, and that the scene's normal law has a LIGGGHTS model
    /// with this damping; `path` is where the scene holds the damping role.
    pub fn check(&self, path: &str, roles: Roles, e: &mut Errors) {
        let restitution = self.restitution;
        if !restitution_is_valid(restitution) {
            e.push(
                format!("{path}.restitution"),
                format!("must be > 0.05 and <= 1 (LIGGGHTS's own rule), got {restitution}"),
            );
        }
        if let Err(rule) = self.with(roles.normal) {
            e.push(format!("{path}.restitution"), rule);
        }
    }
}

impl LiggghtsRestitution {
    /// LAMMPS's `damping coeff_restitution` with e in the normal model's damp slot: the
    /// same γ_n as LIGGGHTS for both normal models (`CriticalFraction::lammps` has
    /// the algebra), so the same e.
    pub fn lammps(&self, _: LammpsNormal) -> Result<LammpsDamping, NoLammpsModel> {
        Ok(LammpsDamping {
            keyword: "coeff_restitution",
            coefficient: self.restitution,
        })
    }
}

/// Why `liggghts_restitution` is refused with the normal law `law`.
pub fn unsupported_law(law: &str) -> String {
    format!(
        "has no LIGGGHTS definition with contact.normal.law '{law}': LIGGGHTS derives the damping from a restitution coefficient only for 'hertz' (model hertz) and 'linear' (model hooke)"
    )
}

/// LIGGGHTS's rule for `coefficientRestitution`.
pub fn restitution_is_valid(e: f64) -> bool {
    e > 0.05 && e <= 1.0
}

/// e from a β in (−1, 0]: inverts β = ln e / √(ln²e + π²).
pub fn restitution_from_beta(beta: f64) -> f64 {
    (beta * std::f64::consts::PI / (1.0 - beta * beta).sqrt()).exp()
}

/// β = ln e / √(ln²e + π²) (LIGGGHTS `betaeff`), in (−1, 0].
pub fn beta(e: f64) -> f64 {
    let ln_e = e.ln();
    ln_e / (ln_e * ln_e + std::f64::consts::PI.powi(2)).sqrt()
}

/// `model hooke`'s stiffness: the linear spring whose undamped maximum overlap at
/// impact speed V equals the elastic Hertz one, N/m.
pub fn hooke_stiffness(
    effective_mass: f64,
    effective_radius: f64,
    effective_modulus: f64,
    characteristic_velocity: f64,
) -> f64 {
    let sqrt_r = effective_radius.sqrt();
    16.0 / 15.0
        * sqrt_r
        * effective_modulus
        * (15.0 * effective_mass * characteristic_velocity.powi(2)
            / (16.0 * sqrt_r * effective_modulus))
            .powf(0.2)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::damping::{CriticalFraction, DampingModel};
    use crate::contact::normal::hertz::hertz_stiffness;
    use crate::contact::normal::{Hertz, Linear, NormalLaw, Storakers};
    use approx::assert_relative_eq;

    // The recorded LIGGGHTS scene: steel spheres, R = 1 mm, E = 2e11 Pa, ν = 0.3.
    const M_EFF: f64 = 1.633_628_179_866_692_5e-5;
    const R_EFF: f64 = 5e-4;
    const E_EFF: f64 = 2e11 / (2.0 * (1.0 - 0.09));

    /// LIGGGHTS's γ_n for `model hertz`, written as normal_model_hertz.h does.
    fn liggghts_hertz_gamma_n(e: f64, overlap: f64) -> f64 {
        let sqrtval = (R_EFF * overlap).sqrt();
        let sn = 2.0 * E_EFF * sqrtval;
        let ln_e = e.ln();
        let betaeff = ln_e / (ln_e.powf(2.0) + std::f64::consts::PI.powf(2.0)).sqrt();
        -2.0 * 0.912_870_929_175_276_9 * betaeff * (sn * M_EFF).sqrt()
    }

    /// LIGGGHTS's k_n and γ_n for `model hooke`, written as normal_model_hooke.h does.
    fn liggghts_hooke(e: f64, charvel: f64) -> (f64, f64) {
        let sqrtval = R_EFF.sqrt();
        let kn = 16.0 / 15.0
            * sqrtval
            * E_EFF
            * (15.0 * M_EFF * charvel * charvel / (16.0 * sqrtval * E_EFF)).powf(0.2);
        let l = e.ln();
        let gamman = (4.0 * M_EFF * kn * l * l / (l * l + std::f64::consts::PI.powi(2))).sqrt();
        (kn, gamman)
    }

    #[test]
    fn hertz_mapping_reproduces_liggghts_gamma_n() {
        for e in [0.06, 0.5, 0.9, 0.99, 1.0] {
            for overlap in [1e-9, 1.6e-6] {
                let xi = LiggghtsModel::Hertz.critical_fraction(e);
                let k = hertz_stiffness(overlap, R_EFF, E_EFF);
                let c = CriticalFraction { xi }.coefficient(M_EFF, k, || 0.0);
                let g = liggghts_hertz_gamma_n(e, overlap);
                assert!(
                    (c - g).abs() <= 1e-14 * g.abs().max(1e-300),
                    "e {e}: {c} vs {g}"
                );
            }
        }
    }

    #[test]
    fn hooke_mapping_reproduces_liggghts_gamma_n() {
        for e in [0.06, 0.5, 0.9, 0.99] {
            let (kn, gamman) = liggghts_hooke(e, 1.0);
            assert_relative_eq!(
                hooke_stiffness(M_EFF, R_EFF, E_EFF, 1.0),
                kn,
                max_relative = 1e-15
            );
            let xi = LiggghtsModel::Hooke.critical_fraction(e);
            let c = CriticalFraction { xi }.coefficient(M_EFF, kn, || 0.0);
            assert_relative_eq!(c, gamman, max_relative = 1e-14);
        }
    }

    #[test]
    fn research_values_of_beta_and_hooke_parameters() {
        // Printed in the LIGGGHTS research notes for this scene.
        assert_relative_eq!(beta(0.5), -0.215_453_762, max_relative = 1e-8);
        let kn = hooke_stiffness(M_EFF, R_EFF, E_EFF, 1.0);
        assert_relative_eq!(kn, 3.779_275_1e6, max_relative = 1e-7);
        let xi = LiggghtsModel::Hooke.critical_fraction(0.5);
        assert_relative_eq!(
            CriticalFraction { xi }.coefficient(M_EFF, kn, || 0.0),
            3.385_828_4,
            max_relative = 1e-7
        );
    }

    #[test]
    fn restitution_rule_is_liggghts_rule() {
        assert!(!restitution_is_valid(0.05));
        assert!(restitution_is_valid(0.050001));
        assert!(restitution_is_valid(1.0));
        assert!(!restitution_is_valid(1.0 + 1e-12));
        assert!(!restitution_is_valid(f64::NAN));
        assert_eq!(beta(1.0), 0.0);
    }

    #[test]
    fn only_hertz_and_linear_have_a_liggghts_model() {
        assert_eq!(
            NormalLaw::Hertz(Hertz {}).liggghts(),
            Some(LiggghtsModel::Hertz)
        );
        assert_eq!(
            NormalLaw::Linear(Linear { stiffness: 1.0 }).liggghts(),
            Some(LiggghtsModel::Hooke)
        );
        assert_eq!(
            NormalLaw::Storakers(Storakers {
                min_with_hertz: false
            })
            .liggghts(),
            None
        );
    }
}
