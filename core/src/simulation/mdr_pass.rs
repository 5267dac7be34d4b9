//! MDR's pass at the start of the force computation, before any contact force
//! (LAMMPS's `fix GRANULAR/MDR` `pre_force`): the particles' update from the last
//! step's sums (volumes, free surface, the apparent radius, which becomes the
//! particle's radius), the screening penalty of every contact, and each particle's
//! mean surface displacement. Only a scene with the MDR law runs it: the force loop
//! calls it behind `NormalModel::mdr`, which is `None` for every other law.
//!
//! Order as in LAMMPS: penalties over the list's pairs (each triplet of pairwise
//! overlapping particles seen from its first particle's partners, in the list's
//! order), then the pairs' shares of the mean surface displacement, then the walls'.

use super::Simulation;
use super::force_loop::carried_state;
use super::narrow_phase::NarrowPhase;
use crate::contact::mdr::{Mdr, PairSides, bulk, penalty};
use crate::contact::model::{NormalModel, StateOf, TangentialModel};
use crate::particles::Vec3;

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
        let position = narrow.position;
        let radius = narrow.radius;
        let image = narrow.image;
        let between = |a: usize, b: usize| {
            let d = image.displacement(&position[b], &position[a]);
            let dist = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
            (d, dist, 1.0 / dist, radius[a] + radius[b] - dist)
        };
        let dot = |a: Vec3, b: Vec3| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        let index = |a: usize, b: usize| {
            let key = (a.min(b) as u32, a.max(b) as u32);
            pairs.binary_search(&key).ok()
        };
        let mut first = 0;
        while first < pairs.len() {
            let i = pairs[first].0;
            let mut last = first;
            while last < pairs.len() && pairs[last].0 == i {
                last += 1;
            }
            for jj in first..last {
                let j = pairs[jj].1 as usize;
                let i = i as usize;
                let (d_ij, r_ij, inv_ij, o_ij) = between(i, j);
                if o_ij < 0.0 {
                    continue;
                }
                for &(_, k) in &pairs[jj + 1..last] {
                    let k = k as usize;
                    let (d_ik, r_ik, inv_ik, o_ik) = between(i, k);
                    if o_ik < 0.0 {
                        continue;
                    }
                    let (d_jk, r_jk, inv_jk, o_jk) = between(j, k);
                    if o_jk < 0.0 {
                        continue;
                    }
                    let r_max = r_ij.max(r_ik.max(r_jk));
                    let (alpha, (a, b)) = if r_ij == r_max {
                        (dot(-(d_ik * inv_ik), -(d_jk * inv_jk)).acos(), (i, j))
                    } else if r_ik == r_max {
                        (dot(-(d_ij * inv_ij), d_jk * inv_jk).acos(), (i, k))
                    } else {
                        (dot(d_ij * inv_ij, d_ik * inv_ik).acos(), (j, k))
                    };
                    if let Some(c) =
                        index(a, b).and_then(|c| N::mdr_contact(&mut states.pairs[c].normal))
                    {
                        c.penalty += penalty::screening(alpha);
                    }
                }
            }
            first = last;
        }

        // The mean surface displacement: pairs, then walls.
        for (k, &(i, j)) in pairs.iter().enumerate() {
            let (i, j) = (i as usize, j as usize);
            let d = image.displacement(&position[i], &position[j]);
            let rsq = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
            let radsum = radius[i] + radius[j];
            let state = &mut states.pairs[k];
            if rsq < radsum * radsum {
                if let Some(c) = N::mdr_contact(&mut state.normal) {
                    let sides = PairSides::of(i, j, id[i], id[j]);
                    bulk::add_pair(c, radsum - rsq.sqrt(), sides.0, particles);
                }
            } else {
                *state = StateOf::<N, T>::default();
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
