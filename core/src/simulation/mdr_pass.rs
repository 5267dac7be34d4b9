//! MDR's pass at the start of the force computation, before any contact force
//! (LAMMPS's `fix GRANULAR/MDR` `pre_force`): the particles' update from the last
//! step's sums (volumes, free surface, the apparent radius, which becomes the
//! particle's radius, and its moment of inertia with `rotation.inertia_radius`
//! `current`), the screening penalty of every contact, and each particle's
//! mean surface displacement. Only a scene with the MDR law runs it: the force loop
//! calls it behind `NormalModel::mdr`, which is `None` for every other law.
//!
//! Order as in LAMMPS: penalties over the list's pairs (each triplet of pairwise
//! overlapping particles seen from its first particle's partners, in the list's
//! order), then the pairs' shares of the mean surface displacement, then the walls'.

use super::Simulation;
use super::force_loop::carried_state;
use super::narrow_phase::NarrowPhase;
use crate::contact::ContactGeometry;
use crate::contact::mdr::contact::MdrForce;
use crate::contact::mdr::parameters::Moduli;
use crate::contact::mdr::{Mdr, MdrParticles, PairSides, WallSide, bulk, penalty};
use crate::contact::model::{NormalModel, StateOf, TangentialModel};
use crate::particles::InertiaRadius;

impl Simulation {
    /// MDR's start of a step, for the scene's laws `N` (whose normal law is `mdr`) and
    /// `T`. At t = 0 (no step under way) there is nothing to do: the particles are as
    /// `MdrParticles::new` set them up, as LAMMPS's set-up leaves them.
    pub(super) fn mdr_begin_step<N, T>(&mut self, mdr: &Mdr)
    where
        N: NormalModel,
        T: TangentialModel,
    {
        if !self.work.stepping {
            return;
        }
        let particles = self
            .state
            .mdr
            .as_mut()
            .expect("an MDR scene's state holds its particles' MDR state");
        particles.begin_step(mdr.bulk_trigger);
        let p = &mut self.state.particles;
        let n = p.len();
        p.radius[..n].copy_from_slice(&particles.radius[..n]);
        // With `"inertia_radius": "current"` the spins turn with the apparent radius's
        // moment of inertia, 2/5 m R², as LAMMPS's fix nve/sphere takes it.
        if self.model.inertia_radius == InertiaRadius::Current {
            let scale = self.model.inertia_scale;
            for i in 0..n {
                p.inertia[i] = scale * 0.4 * p.mass[i] * p.radius[i] * p.radius[i];
            }
        }

        let states = self.state.contacts.typed_mut::<StateOf<N, T>>();
        let narrow = NarrowPhase {
            image: self.model.detection.space.minimum_image(),
            pairs: &self.state.neighbors.pairs[..],
            position: &p.position[..n],
            radius: &p.radius[..n],
        };
        let pairs = narrow.pairs;
        let id = &p.id[..n];

        // The penalties: cleared, then one share per triplet.
        for s in states.pairs[..pairs.len()].iter_mut() {
            if let Some(c) = N::mdr_contact(&mut s.normal) {
                c.penalty = 0.0;
            }
        }
        let (position, radius, image) = (narrow.position, narrow.radius, narrow.image);
        penalty::screen(
            pairs,
            |a, b| image.displacement(&position[b], &position[a]),
            radius,
            |c, p| {
                if let Some(c) = N::mdr_contact(&mut states.pairs[c].normal) {
                    c.penalty += p;
                }
            },
        );

        // The mean surface displacement: pairs, then walls.
        for (k, &(i, j)) in pairs.iter().enumerate() {
            let (i, j) = (i as usize, j as usize);
            let d = image.displacement(&position[i], &position[j]);
            let rsq = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
            let radsum = radius[i] + radius[j];
            // A pair apart has its state reset by the force loop.
            if rsq < radsum * radsum
                && let Some(c) = N::mdr_contact(&mut states.pairs[k].normal)
            {
                let sides = PairSides::of(i, j, id[i], id[j]);
                bulk::add_pair(c, radsum - rsq.sqrt(), sides.0, particles);
            }
        }
        let mut found = std::mem::take(&mut self.work.found);
        let (walls, poses) = (&self.model.walls[..], &self.state.walls[..]);
        let _ = narrow.wall_contacts(walls, poses, 0.0, &mut found, |w, _, _, i, found| {
            for contact in found {
                let mut kept = carried_state(&states.walls[w][i], contact.facet);
                if let Some(c) = N::mdr_contact(&mut kept.normal) {
                    bulk::add_wall(c, contact.overlap, i, particles);
                }
            }
            Ok::<(), ()>(())
        });
        self.work.found = found;
    }
}

/// MDR's contacts in a pass over the contacts (the force loop, the records): the law,
/// its moduli and the particles' state, and whether the evaluations advance the
/// histories and the particles' sums.
pub(super) struct MdrStep<'a> {
    pub law: &'a Mdr,
    /// The law of a wall contact (`Mdr::at_wall`).
    pub wall_law: Mdr,
    pub moduli: Moduli,
    pub particles: &'a mut MdrParticles,
    pub update: bool,
}

impl<'a> MdrStep<'a> {
    /// The step's MDR part, for a scene whose law is `law` and whose state holds
    /// `particles`; `None` for every other law.
    pub fn of(
        law: Option<&'a Mdr>,
        particles: Option<&'a mut MdrParticles>,
        update: bool,
    ) -> Option<Self> {
        law.zip(particles).map(|(law, particles)| MdrStep {
            law,
            wall_law: law.at_wall(),
            moduli: law.moduli(),
            particles,
            update,
        })
    }

    /// The normal force of the pair (i, j), ids `id`, at `overlap` with the contact's
    /// geometry `g`, `normal` its normal state; `None` if that is another law's.
    pub fn pair<N: NormalModel>(
        &mut self,
        normal: &mut N::State,
        overlap: f64,
        (i, j): (usize, usize),
        id: &[u64],
        g: &ContactGeometry,
    ) -> Option<MdrForce> {
        N::mdr_contact(normal).map(|c| {
            c.pair(
                self.law,
                &self.moduli,
                overlap,
                PairSides::of(i, j, id[i], id[j]),
                self.particles,
                g.normal,
                g.effective_mass,
                self.update,
            )
        })
    }

    /// The normal force of particle `i`'s wall contact at `overlap`, as `pair`.
    pub fn wall<N: NormalModel>(
        &mut self,
        normal: &mut N::State,
        overlap: f64,
        i: usize,
        g: &ContactGeometry,
    ) -> Option<MdrForce> {
        N::mdr_contact(normal).map(|c| {
            c.wall(
                &self.wall_law,
                &self.moduli,
                overlap,
                WallSide(i),
                self.particles,
                g.normal,
                g.effective_mass,
                self.update,
            )
        })
    }
}
