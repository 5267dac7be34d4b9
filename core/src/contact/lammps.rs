//! What each role's law is in LAMMPS's `pair_style granular` (LAMMPS 22 Jul 2025,
//! update 4, src/GRANULAR/gran_sub_mod_*.cpp and granular_model.cpp), for
//! `tamp export-lammps`. Each law declares its own LAMMPS model (`NormalModel::lammps`,
//! `Damping::lammps`, `TangentialModel::lammps`), or the reason LAMMPS has none; the
//! exporter only asks. docs/lammps.md has the full mapping.
//!
//! LAMMPS's normal models tamp reproduces (δ > 0 overlap, R* and m* as in tamp):
//!   `hertz/material E damp ν`: F = k a δ with k = (4/3)E*, a = √(R*δ) and
//!       1/E* = (1 − ν_i²)/E_i + (1 − ν_j²)/E_j (`mix_stiffnessE`, gran_sub_mod.cpp):
//!       tamp's `hertz`, F = (4/3)E*√R* δ^{3/2};
//!   `hooke k damp`: F = k δ: tamp's `linear`.
//! The damping models all give F_d = −η v_n (v_n < 0 approaching), η their
//! "prefactor" (gran_sub_mod_damping.cpp). Two of them scale with √(m* F/δ), the
//! secant stiffness F/δ of the normal model: (2/3)·2E*a for `hertz/material`, whose
//! tangent stiffness (tamp's k_n, contact/normal/hertz.rs) is 2E*a; k for `hooke`. So
//! η = d √(m* F/δ) is tamp's `critical_fraction` c_n = ξ · 2√(m* k_n) with
//! ξ = d √(F/(δ k_n)) / 2 (`LammpsNormal::critical_fraction`).

use std::fmt;

/// A normal law's model in `pair granular`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LammpsNormal {
    /// `hertz/material E damp ν` = tamp `hertz`.
    HertzMaterial,
    /// `hooke k damp` = tamp `linear` with k = its stiffness, N/m.
    Hooke {
        /// Normal spring stiffness k_n, N/m.
        stiffness: f64,
    },
    /// `mdr E ν Y γ ψ_b η` with `damping mdr 1|2` = tamp `mdr`: the law carries its
    /// own E, ν and dashpot.
    Mdr(crate::contact::mdr::Mdr),
}

impl LammpsNormal {
    /// The keyword after `pair_coeff i j`.
    pub fn keyword(&self) -> &'static str {
        match self {
            LammpsNormal::HertzMaterial => "hertz/material",
            LammpsNormal::Hooke { .. } => "hooke",
            LammpsNormal::Mdr(_) => "mdr",
        }
    }

    /// The secant stiffness F/δ over the tangent stiffness dF/dδ of the model: 2/3
    /// for Hertz (F ∝ δ^{3/2}) and for MDR's elastic branch, which is Hertz's at small
    /// overlap; 1 for a linear spring.
    pub fn secant_over_tangent(&self) -> f64 {
        match self {
            LammpsNormal::HertzMaterial | LammpsNormal::Mdr(_) => 2.0 / 3.0,
            LammpsNormal::Hooke { .. } => 1.0,
        }
    }

    /// ξ of tamp's `critical_fraction` equal to LAMMPS's η = d √(m* F/δ) (`tsuji`,
    /// `coeff_restitution`): ξ = d √(F/(δ k_n)) / 2.
    pub fn critical_fraction(&self, d: f64) -> f64 {
        0.5 * d * self.secant_over_tangent().sqrt()
    }
}

/// A damping law's model in `pair granular`: `damping <keyword>`, with `coefficient`
/// the normal model's `damp` slot it reads (γ for `velocity`, e for `tsuji` and
/// `coeff_restitution`, 0 for `none`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LammpsDamping {
    /// The word after `damping` (`velocity`, `coeff_restitution`, `tsuji`, …).
    pub keyword: &'static str,
    /// The value for the normal model's `damp` slot (its unit depends on `keyword`).
    pub coefficient: f64,
}

/// Why a law has no LAMMPS model (one line of `path: cannot export to LAMMPS: why`).
#[derive(Clone, Debug, PartialEq)]
pub struct NoLammpsModel(pub String);

impl fmt::Display for NoLammpsModel {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hertz_secant_stiffness_is_two_thirds_of_the_tangent_one() {
        // F = c δ^{3/2}: F/δ = c δ^{1/2}, dF/dδ = (3/2) c δ^{1/2}.
        let (c, delta) = (3.7e9_f64, 2.3e-6_f64);
        let secant = c * delta.powf(1.5) / delta;
        let tangent = 1.5 * c * delta.sqrt();
        let ratio = LammpsNormal::HertzMaterial.secant_over_tangent();
        assert!((secant / tangent - ratio).abs() < 1e-15);
    }
}
