//! The tangential laws grouped by what a contact keeps between steps: nothing
//! (`Stateless`), one 3-vector (`Spring`: an elongation or an incremental force), a
//! scalar history along one axis (`ScalarAxis`), or LAMMPS's Mindlin history
//! (`lammps_mindlin`, a family of its own). The force loop is compiled once per family
//! and per normal law, and takes the law within a family by a branch fixed for the
//! run: the state's shape is what the loop's storage and code depend on, while which
//! law of a shape runs is a branch the processor predicts every time. Compiling every
//! law as its own type multiplied the build time by the number of laws, for a speed
//! the branch matches (docs/performance.md, "Compile time").

use super::lammps_linear_history::LammpsLinearHistory;
use super::lammps_linear_nohistory::LammpsLinearNohistory;
use super::scalar_axis::ScalarAxisState;
use super::storakers::Storakers;
use super::walton_braun::WaltonBraun;
use super::{
    Coulomb, CundallStrack, HaffWerner, LiggghtsHistory, MindlinDeresiewicz, MindlinNoSlip,
    TangentialInput, TangentialModel,
};
use crate::contact::lammps::NoLammpsModel;
use crate::contact::model::{Needs, Roles};
use crate::contact::registry::TangentialExample;
use crate::error::Errors;
use crate::particles::Vec3;

/// A family: an enum of the laws that keep `$state`, implementing `TangentialModel`
/// by passing every call to the law it holds.
macro_rules! family {
    ($(#[$doc:meta])* $family:ident, $state:ty, { $($(#[$vdoc:meta])* $law:ident($ty:ty)),+ $(,)? }) => {
        $(#[$doc])*
        #[derive(Clone, Copy, Debug, PartialEq)]
        pub enum $family {
            $($(#[$vdoc])* $law($ty)),+
        }

        impl TangentialModel for $family {
            type State = $state;
            fn name(&self) -> &'static str {
                match self { $($family::$law(t) => t.name()),+ }
            }
            fn needs(&self) -> Needs {
                match self { $($family::$law(t) => t.needs()),+ }
            }
            fn check(&self, path: &str, roles: Roles, errors: &mut Errors) {
                match self { $($family::$law(t) => t.check(path, roles, errors)),+ }
            }
            fn lammps(&self) -> Result<String, NoLammpsModel> {
                match self { $($family::$law(t) => t.lammps()),+ }
            }
            fn bind(&mut self, roles: Roles) {
                match self { $($family::$law(t) => t.bind(roles)),+ }
            }
            fn examples() -> Vec<TangentialExample> {
                [$(<$ty>::examples()),+].concat()
            }
            #[inline(always)]
            fn force(&self, input: &TangentialInput, state: &mut $state) -> Vec3 {
                match self { $($family::$law(t) => t.force(input, state)),+ }
            }
            fn stiffness(&self, input: &TangentialInput) -> f64 {
                match self { $($family::$law(t) => t.stiffness(input)),+ }
            }
            fn energy(&self, input: &TangentialInput, state: &$state) -> f64 {
                match self { $($family::$law(t) => t.energy(input, state)),+ }
            }
            fn stiffness_before_contact(&self, impact_stiffness: f64) -> f64 {
                match self { $($family::$law(t) => t.stiffness_before_contact(impact_stiffness)),+ }
            }
            fn viscous_coefficient(&self) -> Option<f64> {
                match self { $($family::$law(t) => t.viscous_coefficient()),+ }
            }
            fn dashpot_over_normal(&self) -> f64 {
                match self { $($family::$law(t) => t.dashpot_over_normal()),+ }
            }
        }
    };
}

family!(
    /// The laws that keep nothing: the force follows the contact's present motion.
    Stateless, (), {
        /// Zhong model VII.
        Coulomb(Coulomb),
        /// Zhong model VIII.
        HaffWerner(HaffWerner),
        /// LAMMPS's `linear_nohistory`.
        LammpsLinearNohistory(LammpsLinearNohistory),
    }
);

family!(
    /// The laws that keep one 3-vector: a spring's elongation or an incremental force.
    Spring, Vec3, {
        /// Zhong model IX.
        CundallStrack(CundallStrack),
        /// Rojek eqs 11–14.
        MindlinNoSlip(MindlinNoSlip),
        /// Rojek eq 21.
        Storakers(Storakers),
        /// LIGGGHTS 3.8 `tangential history`.
        LiggghtsHistory(LiggghtsHistory),
        /// LAMMPS's `linear_history`.
        LammpsLinearHistory(LammpsLinearHistory),
    }
);

impl Spring {
    /// The law as a member of this family, if it keeps one 3-vector.
    pub fn of(law: super::TangentialLaw) -> Option<Spring> {
        use super::TangentialLaw as L;
        match law {
            L::CundallStrack(l) => Some(Spring::CundallStrack(l)),
            L::MindlinNoSlip(l) => Some(Spring::MindlinNoSlip(l)),
            L::Storakers(l) => Some(Spring::Storakers(l)),
            L::LiggghtsHistory(l) => Some(Spring::LiggghtsHistory(l)),
            L::LammpsLinearHistory(l) => Some(Spring::LammpsLinearHistory(l)),
            _ => None,
        }
    }
}

family!(
    /// The one-dimensional history laws acting along the slip direction.
    ScalarAxis, ScalarAxisState, {
        /// Zhong model VI.
        MindlinDeresiewicz(MindlinDeresiewicz),
        /// Zhong model X.
        WaltonBraun(WaltonBraun),
    }
);

/// `each_family!(law, t => expr)`: `expr` with `t` bound to the scene's tangential law
/// as its family's type (`lammps_mindlin` is its own family), for every variant of
/// `TangentialLaw` (an exhaustive match).
#[macro_export]
macro_rules! each_family {
    ($law:expr, $t:ident => $body:expr) => {{
        use $crate::contact::tangential::TangentialLaw as L;
        use $crate::contact::tangential::families::{ScalarAxis, Spring, Stateless};
        match $law {
            L::Coulomb(l) => {
                let $t = Stateless::Coulomb(l);
                $body
            }
            L::HaffWerner(l) => {
                let $t = Stateless::HaffWerner(l);
                $body
            }
            L::LammpsLinearNohistory(l) => {
                let $t = Stateless::LammpsLinearNohistory(l);
                $body
            }
            L::CundallStrack(l) => {
                let $t = Spring::CundallStrack(l);
                $body
            }
            L::MindlinNoSlip(l) => {
                let $t = Spring::MindlinNoSlip(l);
                $body
            }
            L::Storakers(l) => {
                let $t = Spring::Storakers(l);
                $body
            }
            L::LiggghtsHistory(l) => {
                let $t = Spring::LiggghtsHistory(l);
                $body
            }
            L::LammpsLinearHistory(l) => {
                let $t = Spring::LammpsLinearHistory(l);
                $body
            }
            L::MindlinDeresiewicz(l) => {
                let $t = ScalarAxis::MindlinDeresiewicz(l);
                $body
            }
            L::WaltonBraun(l) => {
                let $t = ScalarAxis::WaltonBraun(l);
                $body
            }
            L::LammpsMindlin($t) => $body,
        }
    }};
}
