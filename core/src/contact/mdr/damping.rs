//! The normal dashpot LAMMPS offers with MDR (`damping mdr 1|2`, its only damping for
//! this law): F_d = −η_eff v_n, v_n the normal relative velocity (negative on approach).
//!
//!   - `stiffness` (`damping mdr 1`): η_eff = η √(2 m* E* a_d), with a_d the sum of the
//!     two sides' contact radii for a pair (E* of one sphere), and for a wall half the
//!     side's radius with E*/2: √(m* E* a/2);
//!   - `velocity` (`damping mdr 2`): η_eff = η while the contact has a radius, else 0.
//!
//! The scale is the one computed by the same step's normal force (`MdrContact`).

use crate::error::Errors;

/// The dashpot's coefficient η and its form.
#[derive(Clone, Copy, Debug, PartialEq, serde::Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct MdrDamping {
    /// η: dimensionless for `stiffness`, N·s/m for `velocity`.
    pub coefficient: f64,
    /// Which scale multiplies η.
    pub form: MdrDampingForm,
}

/// LAMMPS's damping type of `damping mdr`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Deserialize, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum MdrDampingForm {
    /// `damping mdr 1`: η √(2 m* E* a).
    Stiffness,
    /// `damping mdr 2`: η.
    Velocity,
}

impl MdrDamping {
    /// The dashpot's coefficient for a contact whose stored scale is `scale`
    /// (√(2 m* E* a), zero when the contact has no radius), N·s/m.
    pub fn coefficient(&self, scale: f64) -> f64 {
        match self.form {
            MdrDampingForm::Stiffness => self.coefficient * scale,
            MdrDampingForm::Velocity => {
                if scale == 0.0 {
                    0.0
                } else {
                    self.coefficient
                }
            }
        }
    }

    /// The rule of η.
    pub fn check(&self, path: &str, errors: &mut Errors) {
        errors.non_negative(format!("{path}.coefficient"), self.coefficient);
    }
}
