//! The MDR law's parameters and the moduli it derives from them.
//!
//! Inputs (LAMMPS's `mdr E ν Y γ ψ_b η` in this order): Young's modulus E and
//! Poisson's ratio ν of the particles' material, the yield stress Y, the effective
//! surface energy γ (0 for no adhesion), the free-surface fraction ψ_b below which the
//! bulk response acts, and the damping coefficient η with its form.
//! Derived: G = E/(2(1 + ν)), κ = E/(3(1 − 2ν)), E* = E/(1 − ν²).

use super::damping::MdrDamping;
use crate::error::Errors;

/// The MDR law of one material (particles and walls share it, as in LAMMPS).
#[derive(Clone, Copy, Debug, PartialEq, serde::Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct Mdr {
    /// Young's modulus E, Pa.
    pub youngs_modulus: f64,
    /// Poisson's ratio ν.
    pub poisson_ratio: f64,
    /// Yield stress Y, Pa.
    pub yield_stress: f64,
    /// Effective surface energy γ, J/m² (0: no adhesion).
    #[serde(default)]
    pub surface_energy: f64,
    /// Effective surface energy between a particle and a wall, J/m²; absent: γ. LAMMPS
    /// gives every wall fix its own `mdr` coefficients; its tableting example makes
    /// the walls non-adhesive this way.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub wall_surface_energy: Option<f64>,
    /// Free-surface fraction ψ_b below which the bulk response acts.
    pub bulk_trigger: f64,
    /// The normal dashpot.
    pub damping: MdrDamping,
}

/// The moduli MDR derives from E and ν, computed once per law.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Moduli {
    /// Shear modulus G, Pa.
    pub shear: f64,
    /// Bulk modulus κ, Pa.
    pub bulk: f64,
    /// Plane-strain modulus E* = E/(1 − ν²) of one sphere on a rigid flat, Pa.
    pub plane_strain: f64,
}

impl Mdr {
    /// G, κ and E*, in LAMMPS's arithmetic.
    pub fn moduli(&self) -> Moduli {
        Moduli {
            shear: self.shear_modulus(),
            bulk: self.bulk_modulus(),
            plane_strain: self.plane_strain_modulus(),
        }
    }

    /// The law of a particle–wall contact: γ is the wall's.
    pub fn at_wall(&self) -> Mdr {
        Mdr {
            surface_energy: self.wall_surface_energy.unwrap_or(self.surface_energy),
            ..*self
        }
    }

    /// Shear modulus G, Pa.
    pub fn shear_modulus(&self) -> f64 {
        self.youngs_modulus / (2.0 * (1.0 + self.poisson_ratio))
    }

    /// Bulk modulus κ, Pa.
    pub fn bulk_modulus(&self) -> f64 {
        self.youngs_modulus / (3.0 * (1.0 - 2.0 * self.poisson_ratio))
    }

    /// Plane-strain modulus E* = E/(1 − ν²) of one sphere on a rigid flat, Pa.
    pub fn plane_strain_modulus(&self) -> f64 {
        self.youngs_modulus / (1.0 - self.poisson_ratio * self.poisson_ratio)
    }

    /// The rules of the parameters (those LAMMPS enforces, with ν < 1/2 strictly since
    /// κ is finite only then); `path` is where the scene holds the law.
    pub fn check(&self, path: &str, errors: &mut Errors) {
        errors.positive(format!("{path}.youngs_modulus"), self.youngs_modulus);
        let nu = self.poisson_ratio;
        if !(0.0..0.5).contains(&nu) {
            errors.push(
                format!("{path}.poisson_ratio"),
                format!("must be >= 0 and < 0.5 (the bulk modulus is infinite at 0.5), got {nu}"),
            );
        }
        errors.non_negative(format!("{path}.yield_stress"), self.yield_stress);
        errors.non_negative(format!("{path}.surface_energy"), self.surface_energy);
        if let Some(gamma) = self.wall_surface_energy {
            errors.non_negative(format!("{path}.wall_surface_energy"), gamma);
        }
        let psi_b = self.bulk_trigger;
        if !(0.0..=1.0).contains(&psi_b) {
            errors.push(
                format!("{path}.bulk_trigger"),
                format!("must lie in [0, 1], got {psi_b}"),
            );
        }
        self.damping.check(&format!("{path}.damping"), errors);
    }
}
