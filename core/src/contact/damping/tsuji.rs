//! LAMMPS's `damping tsuji`, as tamp's `critical_fraction` (scene kind `tsuji`).
//! Equations as LAMMPS 22 Jul 2025 (update 4) evaluates them,
//! src/GRANULAR/gran_sub_mod_damping.cpp (`GranSubModDampingTsuji::init` and
//! `::calculate_forces`), in tamp's notation (δ > 0 overlap, m* = m_i m_j/(m_i + m_j)):
//!
//!   d = 1.2728 − 4.2783 e + 11.087 e² − 22.348 e³ + 27.467 e⁴ − 18.022 e⁵ + 4.8218 e⁶
//!       (Marshall 2009, J. Comput. Phys. 228, eq 53: a fit to Tsuji et al. 1992's α(e)
//!       for Hertz contacts; e is the `damp` coefficient of the normal model)
//!   η = d √(m* F_n/δ),  F_d = η dδ/dt   (F_n the elastic normal force)
//!
//! d is not exactly the damping that gives restitution e: LAMMPS's own fit (the
//! rebound it gives is measured by the case `hertz_dashpot_forms`). LAMMPS releases after 22 Jul 2025 multiply d by √2
//! ("for effective mass convention (as in Tsuji 1992)"); this law is the 22 Jul 2025
//! one, which the recorded LAMMPS runs check.
//!
//! F_n/δ is the secant stiffness of the normal law: (2/3) k_n for Hertz (k_n = 2E*a, its
//! tangent stiffness), k_n for a linear spring. So η = ξ · 2√(m* k_n) with
//! ξ = d √(F_n/(δ k_n)) / 2 (contact/lammps.rs), constant over the contact: tamp runs
//! the law as that `critical_fraction`, once the scene is built.
//! Normal laws: `hertz` (LAMMPS `hertz/material`) and `linear` (`hooke`); LAMMPS does
//! not allow tsuji with a cohesive normal model either.

use super::CriticalFraction;
use crate::contact::lammps::{LammpsDamping, LammpsNormal, NoLammpsModel};
use crate::contact::model::Roles;
use crate::contact::normal::NormalLaw;
use crate::error::Errors;

/// The damping kind `tsuji`: LAMMPS's `damping tsuji` with the normal model's `damp`
/// coefficient `restitution`.
#[derive(Clone, Copy, Debug, PartialEq, serde::Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct Tsuji {
    /// The restitution coefficient e Marshall's fit reads, in [0, 1].
    pub restitution: f64,
}

impl Tsuji {
    /// The damping `kind` in the scene file.
    pub const NAME: &str = "tsuji";

    /// The dashpot it is beside `normal`, or why LAMMPS's tsuji is not defined there.
    pub fn with(&self, normal: &NormalLaw) -> Result<CriticalFraction, String> {
        let model = normal
            .lammps()
            .map_err(|_| unsupported_law(normal.name()))?;
        Ok(CriticalFraction {
            xi: model.critical_fraction(tsuji_coefficient(self.restitution)),
        })
    }

    /// The rules of `restitution`, and that LAMMPS defines tsuji beside the scene's normal
    /// law; `path` is where the scene holds the damping role.
    pub fn check(&self, path: &str, roles: Roles, e: &mut Errors) {
        let restitution = self.restitution;
        if !(0.0..=1.0).contains(&restitution) {
            e.push(
                format!("{path}.restitution"),
                format!("must be in [0, 1] (the range of Marshall's fit), got {restitution}"),
            );
        }
        if let Err(rule) = self.with(roles.normal) {
            e.push(format!("{path}.kind"), rule);
        }
    }

    /// `damping tsuji` with e in the normal model's damp slot.
    pub fn lammps(&self, _: LammpsNormal) -> Result<LammpsDamping, NoLammpsModel> {
        Ok(LammpsDamping {
            keyword: "tsuji",
            coefficient: self.restitution,
        })
    }
}

/// Why `tsuji` is refused with the normal law `law`.
pub fn unsupported_law(law: &str) -> String {
    format!(
        "'tsuji' is defined beside contact.normal.law 'hertz' (LAMMPS hertz/material) or 'linear' (hooke), not '{law}'"
    )
}

/// d(e) of Marshall 2009 eq 53, in LAMMPS's order of evaluation (`square`, `cube` and
/// `powint`, which multiplies by repeated squaring), so that d is LAMMPS's to the bit.
pub fn tsuji_coefficient(e: f64) -> f64 {
    let e2 = e * e;
    let e4 = e2 * e2;
    let mut d = 1.2728 - 4.2783 * e + 11.087 * e2;
    d += -22.348 * (e * e * e) + 27.467 * e4;
    d += -18.022 * (e * e4) + 4.8218 * (e2 * e4);
    d
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::normal::{Hertz, Linear, Storakers};

    #[test]
    fn the_fit_at_its_ends() {
        // d(0) is the constant term; d(1) sums the coefficients, 3e-4 (nearly no damping).
        assert_eq!(tsuji_coefficient(0.0), 1.2728);
        let sum: f64 = 1.2728 - 4.2783 + 11.087 - 22.348 + 27.467 - 18.022 + 4.8218;
        assert!((tsuji_coefficient(1.0) - sum).abs() < 1e-14);
    }

    #[test]
    fn xi_is_half_d_times_the_root_of_the_secant_over_tangent_stiffness() {
        let t = Tsuji { restitution: 0.5 };
        let d = tsuji_coefficient(0.5);
        let hertz = t.with(&NormalLaw::Hertz(Hertz {})).unwrap().xi;
        assert!((hertz - d / 6f64.sqrt()).abs() < 1e-15 * d);
        let linear = t
            .with(&NormalLaw::Linear(Linear { stiffness: 1e6 }))
            .unwrap()
            .xi;
        assert!((linear - d / 2.0).abs() < 1e-15 * d);
    }

    #[test]
    fn refused_beside_a_law_lammps_has_no_tsuji_for() {
        let t = Tsuji { restitution: 0.5 };
        let err = t
            .with(&NormalLaw::Storakers(Storakers::default()))
            .unwrap_err();
        assert!(err.contains("'storakers'"), "{err}");
    }
}
