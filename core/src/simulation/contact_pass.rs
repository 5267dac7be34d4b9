//! A pass over the contacts specialised to the scene: its laws as types, so the
//! compiler builds one loop per combination of laws and a scene pays only for the laws
//! it names. The force loop is such a pass. Whether spins enter, and through which
//! lever arms, is a value fixed for the run (`Spins`) that the loop branches on per
//! contact: as types they compiled every law's loop three times, each a copy of the
//! law's whole evaluation, for a few multiplications per contact (docs/performance.md,
//! "Compile time"). This is the one place that maps the scene's settings onto the pass.

use crate::contact::ContactLaw;
use crate::contact::lever_arm::LeverArm;
use crate::contact::model::{
    CohesionModel, Composed, DampingModel, LawVisitor, NormalModel, TangentialModel,
};

/// A computation over the contacts, written once for any laws (`N`, `D`, `T`, `C`)
/// and spins.
pub(super) trait ContactPass {
    type Output;
    fn run<N, D, T, C>(self, law: &Composed<N, D, T, C>, spins: Spins) -> Self::Output
    where
        N: NormalModel,
        D: DampingModel,
        T: TangentialModel,
        C: CohesionModel;
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
    fn visit<N: NormalModel, D: DampingModel, T: TangentialModel, C: CohesionModel>(
        self,
        law: Composed<N, D, T, C>,
    ) -> P::Output {
        self.0.run(&law, self.1)
    }
}
