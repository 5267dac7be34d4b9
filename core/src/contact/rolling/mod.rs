//! Rolling resistance: a torque against the relative rolling of two bodies in contact,
//! one law per file. It is not a role of its own in the force loop: a scene's rolling
//! law joins its tangential law (`WithRolling<T>`), whose state then keeps the rolling
//! displacement beside the sliding history (`RollingState`). A scene without rolling
//! keeps the tangential family's own state and code, so it pays nothing for it
//! (`TangentialModel::ROLLS` is false and the torque's code compiles to nothing).

pub mod sds;

use crate::contact::lammps::NoLammpsModel;
use crate::contact::model::{ContactState, Needs, Roles, TangentialModel};
use crate::contact::registry::TangentialExample;
use crate::contact::tangential::TangentialInput;
use crate::decimal::g;
use crate::error::Errors;
use crate::particles::Vec3;
pub use sds::{RollingInput, Sds};

/// The scene's rolling law, read as `{"law": "<name>", <its parameters>}`.
#[derive(Clone, Copy, Debug, PartialEq, serde::Deserialize, serde::Serialize)]
#[serde(tag = "law", rename_all = "snake_case")]
pub enum RollingLaw {
    /// LAMMPS 22 Jul 2025 `rolling sds`.
    Sds(Sds),
}

impl RollingLaw {
    /// The `law` of the scene file.
    pub fn name(&self) -> &'static str {
        match self {
            RollingLaw::Sds(_) => "sds",
        }
    }

    /// The rules of its own parameters; `path` is where the scene holds it.
    pub fn check(&self, path: &str, errors: &mut Errors) {
        match self {
            RollingLaw::Sds(law) => law.check(path, errors),
        }
    }

    /// Its words in LAMMPS's `pair granular` (`tamp export-lammps`): `rolling sds k γ μ`.
    pub fn lammps(&self) -> String {
        match self {
            RollingLaw::Sds(s) => format!(
                "rolling sds {} {} {}",
                g(s.stiffness),
                g(s.damping),
                g(s.friction)
            ),
        }
    }

    #[inline(always)]
    fn force(&self, input: &RollingInput, xi: &mut Vec3) -> Vec3 {
        match self {
            RollingLaw::Sds(law) => law.force(input, xi),
        }
    }

    fn energy(&self, xi: &Vec3) -> f64 {
        match self {
            RollingLaw::Sds(law) => law.energy(xi),
        }
    }

    fn stiffness(&self) -> f64 {
        match self {
            RollingLaw::Sds(law) => law.stiffness,
        }
    }
}

/// A contact's sliding history and its rolling displacement ξ, m.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct RollingState<S> {
    /// The tangential law's state.
    pub sliding: S,
    /// The rolling displacement ξ, m.
    pub rolling: Vec3,
}

impl<S: ContactState> ContactState for RollingState<S> {
    fn tangential(&self) -> Vec3 {
        self.sliding.tangential()
    }
}

/// A tangential law `T` with rolling resistance: every call of the tangential role
/// goes to `T`, and `rolling` gives the resistance.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WithRolling<T> {
    /// The tangential law.
    pub sliding: T,
    /// The rolling law.
    pub rolling: RollingLaw,
}

impl<T: TangentialModel> TangentialModel for WithRolling<T> {
    type State = RollingState<T::State>;
    const ACTIVE: bool = T::ACTIVE;
    const ROLLS: bool = true;

    fn name(&self) -> &'static str {
        self.sliding.name()
    }
    fn needs(&self) -> Needs {
        self.sliding.needs()
    }
    fn check(&self, path: &str, roles: Roles, errors: &mut Errors) {
        self.sliding.check(path, roles, errors)
    }
    fn lammps(&self) -> Result<String, NoLammpsModel> {
        self.sliding.lammps()
    }
    fn bind(&mut self, roles: Roles) {
        self.sliding.bind(roles)
    }
    fn examples() -> Vec<TangentialExample> {
        Vec::new()
    }
    #[inline(always)]
    fn force(&self, input: &TangentialInput, state: &mut Self::State) -> Vec3 {
        self.sliding.force(input, &mut state.sliding)
    }
    #[inline(always)]
    fn rolling(&self, input: &RollingInput, state: &mut Self::State) -> Vec3 {
        self.rolling.force(input, &mut state.rolling)
    }
    /// The sliding law's and the rolling spring's k_r: the critical time step counts
    /// them with the lever factor 1 + mR²/I of the tangential mode, which bounds the
    /// rolling mode's mR*²/I.
    fn stiffness(&self, input: &TangentialInput) -> f64 {
        self.sliding.stiffness(input) + self.rolling.stiffness()
    }
    /// The sliding law's energy and the rolling spring's.
    fn energy(&self, input: &TangentialInput, state: &Self::State) -> f64 {
        self.sliding.energy(input, &state.sliding) + self.rolling.energy(&state.rolling)
    }
    fn stiffness_before_contact(&self, impact_stiffness: f64) -> f64 {
        self.sliding.stiffness_before_contact(impact_stiffness) + self.rolling.stiffness()
    }
    fn viscous_coefficient(&self) -> Option<f64> {
        self.sliding.viscous_coefficient()
    }
    fn dashpot_over_normal(&self) -> f64 {
        self.sliding.dashpot_over_normal()
    }
}
