//! Dashpots whose coefficient does not follow the normal law's stiffness, as LAMMPS
//! 22 Jul 2025 (update 4) evaluates them, src/GRANULAR/gran_sub_mod_damping.cpp
//! (`GranSubModDampingVelocity`, `…MassVelocity`, `…Viscoelastic`, `::calculate_forces`),
//! in tamp's notation (δ > 0 overlap, R* and m* as for every law, F_d = η_n dδ/dt):
//!
//!   `constant`       η_n = γ_n                      (Zhong 2009 eq 6; LAMMPS `velocity`)
//!   `mass_velocity`  η_n = η_n0 · m*                (LAMMPS `mass_velocity`, η_n0 in 1/s)
//!   `viscoelastic`   η_n = η_n0 · m* · a, a = √(δR*) (LAMMPS `viscoelastic`, η_n0 in
//!                                                    1/(m·s))
//!
//! a is the Hertz contact radius, which LAMMPS's `hertz/material` and `hooke` both
//! report (`calculate_contact_radius`, √(δR*)); tamp uses the same a beside every
//! normal law. Beside `hertz` the viscoelastic dashpot is Kuwabara and Kono's
//! (normal/kuwabara_kono.rs) with A = η_n0 m*/(2E*), without that law's clamp of the
//! total force at zero: like every damping kind here, it may pull at the end of a
//! contact, as LAMMPS's default `limit_damping` off.
//!
//! The three are one type whose form is chosen at run time, as every damping kind is
//! (`Dashpot`): a predictable branch per contact costs less than a compiled force loop
//! per kind (docs/performance.md, "Compile time").
//!
//! For the critical time step the damping ratio ξ = η_n/(2√(m k)) of the viscoelastic
//! form needs a contact radius before any contact: tamp takes the body's radius R, a
//! bound of a = √(δR*) while δ ≤ R* (a larger ξ, so a shorter, safe step).

use super::critical_damping;
use crate::contact::lammps::{LammpsDamping, LammpsNormal, NoLammpsModel};
use crate::contact::model::{DampingModel, Roles};
use crate::error::Errors;

/// `constant`: c_n = γ_n, Zhong eq 6 (N·s/m).
#[derive(Clone, Copy, Debug, PartialEq, serde::Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct Constant {
    /// Normal damping coefficient γ_n ≥ 0, N·s/m.
    pub gamma_n: f64,
}

/// `mass_velocity`: c_n = η_n0 · m* (η_n0 in 1/s).
#[derive(Clone, Copy, Debug, PartialEq, serde::Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct MassVelocity {
    /// η_n0 ≥ 0, 1/s: the damping coefficient per unit effective mass.
    pub eta_n0: f64,
}

/// `viscoelastic`: c_n = η_n0 · m* · √(δR*) (η_n0 in 1/(m·s)).
#[derive(Clone, Copy, Debug, PartialEq, serde::Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct Viscoelastic {
    /// η_n0 ≥ 0, 1/(m·s): the damping coefficient per unit effective mass and unit
    /// contact radius.
    pub eta_n0: f64,
}

/// The compiled form of the three kinds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Viscous {
    /// c_n = γ_n.
    Constant(Constant),
    /// c_n = η_n0 · m*.
    MassVelocity(MassVelocity),
    /// c_n = η_n0 · m* · √(δR*).
    Viscoelastic(Viscoelastic),
}

impl DampingModel for Viscous {
    fn name(&self) -> &'static str {
        match self {
            Viscous::Constant(_) => "constant",
            Viscous::MassVelocity(_) => "mass_velocity",
            Viscous::Viscoelastic(_) => "viscoelastic",
        }
    }
    fn check(&self, path: &str, _: Roles, e: &mut Errors) {
        match self {
            Viscous::Constant(c) => e.non_negative(format!("{path}.gamma_n"), c.gamma_n),
            Viscous::MassVelocity(d) => e.non_negative(format!("{path}.eta_n0"), d.eta_n0),
            Viscous::Viscoelastic(d) => e.non_negative(format!("{path}.eta_n0"), d.eta_n0),
        }
    }
    /// In LAMMPS's order of multiplication: (η_n0 · m*) · a.
    #[inline(always)]
    fn coefficient(
        &self,
        effective_mass: f64,
        _: f64,
        contact_radius: impl FnOnce() -> f64,
    ) -> f64 {
        match self {
            Viscous::Constant(c) => c.gamma_n,
            Viscous::MassVelocity(d) => d.eta_n0 * effective_mass,
            Viscous::Viscoelastic(d) => d.eta_n0 * effective_mass * contact_radius(),
        }
    }
    fn ratio(&self, effective_mass: f64, stiffness: f64, contact_radius: f64) -> f64 {
        self.coefficient(effective_mass, stiffness, || contact_radius)
            / critical_damping(effective_mass, stiffness)
    }
}

impl Viscous {
    /// LAMMPS's `damping velocity`, `mass_velocity` or `viscoelastic` with η_n0 (γ_n
    /// for `velocity`) in the normal model's damp slot, beside any normal model tamp
    /// exports.
    pub fn lammps(&self, _: LammpsNormal) -> Result<LammpsDamping, NoLammpsModel> {
        let (keyword, coefficient) = match *self {
            Viscous::Constant(Constant { gamma_n }) => ("velocity", gamma_n),
            Viscous::MassVelocity(MassVelocity { eta_n0 }) => ("mass_velocity", eta_n0),
            Viscous::Viscoelastic(Viscoelastic { eta_n0 }) => ("viscoelastic", eta_n0),
        };
        Ok(LammpsDamping {
            keyword,
            coefficient,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const M: f64 = 3.0e-5;
    const K: f64 = 2.0e6;

    #[test]
    fn each_form_gives_its_coefficient() {
        let a = 4.0e-5;
        let never = || -> f64 { panic!("only the viscoelastic form reads the contact radius") };
        let c = Viscous::Constant(Constant { gamma_n: 0.5 });
        assert_eq!(c.coefficient(M, K, never), 0.5);
        let mv = Viscous::MassVelocity(MassVelocity { eta_n0: 1.5e4 });
        assert_eq!(mv.coefficient(M, K, never), 1.5e4 * M);
        let ve = Viscous::Viscoelastic(Viscoelastic { eta_n0: 2.0e8 });
        assert_eq!(ve.coefficient(M, K, || a), 2.0e8 * M * a);
    }

    #[test]
    fn the_ratio_is_the_coefficient_over_critical() {
        // ξ = η/(2√(m k)): for mass_velocity η_n0 √(m/k)/2, independent of a.
        let mv = Viscous::MassVelocity(MassVelocity { eta_n0: 1.5e4 });
        let expected = 1.5e4 * (M / K).sqrt() / 2.0;
        assert!((mv.ratio(M, K, 1.0) - expected).abs() < 1e-15 * expected);
        let ve = Viscous::Viscoelastic(Viscoelastic { eta_n0: 2.0e8 });
        let expected = 2.0e8 * M * 1e-3 / (2.0 * (M * K).sqrt());
        assert!((ve.ratio(M, K, 1e-3) - expected).abs() < 1e-15 * expected);
    }

    #[test]
    fn each_form_names_its_lammps_keyword() {
        let normal = LammpsNormal::HertzMaterial;
        for (law, keyword, coefficient) in [
            (
                Viscous::Constant(Constant { gamma_n: 0.5 }),
                "velocity",
                0.5,
            ),
            (
                Viscous::MassVelocity(MassVelocity { eta_n0: 7.0 }),
                "mass_velocity",
                7.0,
            ),
            (
                Viscous::Viscoelastic(Viscoelastic { eta_n0: 9.0 }),
                "viscoelastic",
                9.0,
            ),
        ] {
            let d = law.lammps(normal).unwrap();
            assert_eq!((d.keyword, d.coefficient), (keyword, coefficient));
        }
    }

    #[test]
    fn negative_coefficients_are_refused_by_path() {
        use crate::contact::normal::{NormalLaw, hertz::Hertz};
        let normal = NormalLaw::Hertz(Hertz {});
        let roles = Roles {
            normal: &normal,
            damping: None,
        };
        let mut e = Errors(Vec::new());
        Viscous::Viscoelastic(Viscoelastic { eta_n0: -1.0 }).check(
            "contact.damping",
            roles,
            &mut e,
        );
        assert_eq!(e.0.len(), 1);
        assert!(
            e.0[0].to_string().contains("contact.damping.eta_n0"),
            "{}",
            e.0[0]
        );
    }
}
