//! A pass over the contacts specialised to the scene: its normal law and tangential
//! family as types (contact/model.rs), so the compiler builds one loop per pair of them.
//! The force loop is such a pass. Whether spins enter, and through which lever arms, is
//! a value fixed for the run (`Spins`) that the loop branches on per contact, as are the
//! other roles: as types they multiplied the compiled loops, each a copy of the law's
//! whole evaluation, for a few operations per contact (docs/performance.md, "Compile
//! time"). This is the one place that maps the scene's settings onto the pass.

use crate::contact::ContactLaw;
use crate::contact::lever_arm::LeverArm;
use crate::contact::model::{Composed, LawVisitor, NormalModel, TangentialModel};

/// A computation over the contacts, written once for any laws (`N`, `D`, `T`, `C`)
/// and spins.
pub(super) trait ContactPass {
    type Output;
    fn run<N, T>(self, law: &Composed<N, T>, spins: Spins) -> Self::Output
    where
        N: NormalModel,
        T: TangentialModel;
}

/// How spins enter the contacts: whether they do (`on`: spins in the contact
/// velocity, torques from the tangential force), and through which lever arms.
/// Without spins no arm enters the forces; the contact records still place the
/// contact point with the `mid_overlap` arm then, whatever the scene's convention.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Spins {
    pub(super) on: bool,
    pub(super) arms: LeverArm,
}

impl Spins {
    pub(super) fn of(law: &ContactLaw, rotation: bool) -> Spins {
        Spins {
            on: rotation,
            arms: if rotation {
                law.lever_arm
            } else {
                LeverArm::MidOverlap
            },
        }
    }
}

/// Run `pass` specialised to `law`, with the spins of `rotation`.
pub(super) fn specialised<P: ContactPass>(law: ContactLaw, rotation: bool, pass: P) -> P::Output {
    law.visit(Typed(pass, Spins::of(&law, rotation)))
}

/// `pass` with its spins fixed, waiting for the laws' types.
struct Typed<P>(P, Spins);

impl<P: ContactPass> LawVisitor for Typed<P> {
    type Output = P::Output;
    fn visit<N: NormalModel, T: TangentialModel>(self, law: Composed<N, T>) -> P::Output {
        self.0.run(&law, self.1)
    }
}
