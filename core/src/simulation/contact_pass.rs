//! A pass over the contacts specialised to the scene: its laws, its lever-arm
//! convention and whether spins enter, all as types, so the compiler builds one loop
//! per combination and a scene pays only for what it enables. The force loop is such
//! a pass. The contact records, which only read contacts, take the laws as types but
//! choose the lever arms at run time (`Variant`): compiled once per law instead of
//! three times, since every variant of a law is a copy of its whole evaluation. This
//! is the one place that maps the scene's settings onto those variants.

use super::force_loop::{Bodies, pair_geometry, wall_geometry};
use crate::boundary::{Boundary, shape::ShapeContact};
use crate::contact::lever_arm::Arms;
use crate::contact::lever_arm::{Lammps, LeverArm, LeverArms, MidOverlap};
use crate::contact::model::{
    CohesionModel, Composed, DampingModel, LawVisitor, NormalModel, TangentialModel,
};
use crate::contact::{ContactGeometry, ContactLaw};
use crate::particles::{Particles, Vec3};
use std::marker::PhantomData;

/// A computation over the contacts, written once for any laws (`N`, `D`, `T`, `C`),
/// lever arms `A` and rotation `ROT`.
pub(super) trait ContactPass {
    type Output;
    fn run<N, D, T, C, A, const ROT: bool>(self, law: &Composed<N, D, T, C>) -> Self::Output
    where
        N: NormalModel,
        D: DampingModel,
        T: TangentialModel,
        C: CohesionModel,
        A: LeverArms;
}

/// The force loop's variants: without spins no lever arm enters the forces, so one
/// variant serves both conventions.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Variant {
    SpinMidOverlap,
    SpinLammps,
    NoSpin,
}

impl Variant {
    pub(super) fn of(law: &ContactLaw, rotation: bool) -> Variant {
        match (rotation, law.lever_arm) {
            (true, LeverArm::MidOverlap) => Variant::SpinMidOverlap,
            (true, LeverArm::Lammps) => Variant::SpinLammps,
            (false, _) => Variant::NoSpin,
        }
    }

    /// `force_loop::pair_geometry` of this variant, chosen at run time: for passes
    /// that read contacts rather than step them (the contact records), which need
    /// not be compiled once per variant.
    #[inline]
    pub(super) fn pair_geometry(
        self,
        b: &Bodies,
        i: usize,
        j: usize,
        d: Vec3,
        dist: f64,
        overlap: f64,
    ) -> (ContactGeometry, Arms, Arms) {
        match self {
            Variant::SpinMidOverlap => pair_geometry::<MidOverlap, true>(b, i, j, d, dist, overlap),
            Variant::SpinLammps => pair_geometry::<Lammps, true>(b, i, j, d, dist, overlap),
            Variant::NoSpin => pair_geometry::<MidOverlap, false>(b, i, j, d, dist, overlap),
        }
    }

    /// `force_loop::wall_geometry` of this variant, chosen at run time.
    #[inline]
    pub(super) fn wall_geometry(
        self,
        p: &Particles,
        i: usize,
        c: &ShapeContact,
        wall: &Boundary,
    ) -> (ContactGeometry, Arms) {
        match self {
            Variant::SpinMidOverlap => wall_geometry::<MidOverlap, true>(p, i, c, wall),
            Variant::SpinLammps => wall_geometry::<Lammps, true>(p, i, c, wall),
            Variant::NoSpin => wall_geometry::<MidOverlap, false>(p, i, c, wall),
        }
    }
}

/// Run `pass` specialised to `law` and `rotation`.
pub(super) fn specialised<P: ContactPass>(law: ContactLaw, rotation: bool, pass: P) -> P::Output {
    match Variant::of(&law, rotation) {
        Variant::SpinMidOverlap => law.visit(Typed::<P, MidOverlap, true>(pass, PhantomData)),
        Variant::SpinLammps => law.visit(Typed::<P, Lammps, true>(pass, PhantomData)),
        Variant::NoSpin => law.visit(Typed::<P, MidOverlap, false>(pass, PhantomData)),
    }
}

/// `pass` with its lever arms and rotation fixed, waiting for the laws' types.
struct Typed<P, A, const ROT: bool>(P, PhantomData<A>);

impl<P: ContactPass, A: LeverArms, const ROT: bool> LawVisitor for Typed<P, A, ROT> {
    type Output = P::Output;
    fn visit<N: NormalModel, D: DampingModel, T: TangentialModel, C: CohesionModel>(
        self,
        law: Composed<N, D, T, C>,
    ) -> P::Output {
        self.0.run::<N, D, T, C, A, ROT>(&law)
    }
}
