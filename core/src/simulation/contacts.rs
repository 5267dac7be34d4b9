//! Queries on the contacts of the current state: which pairs and walls touch, the
//! stored contact states, overlaps and counts.

use super::Simulation;
use super::narrow_phase::NarrowPhase;
use crate::contact::model::{Composed, LawVisitor, NormalModel, StateOf, TangentialModel};
use crate::contact::states::{ContactStates, StateStore};
use crate::material::{PairProperties, effective_radius};
use crate::particles::Vec3;

/// An empty state store of the scene's laws' state type.
pub(super) struct NewStates {
    pub(super) particles: usize,
    pub(super) boundaries: usize,
}

impl LawVisitor for NewStates {
    type Output = Box<dyn StateStore>;
    fn visit<N: NormalModel, T: TangentialModel>(self, _: Composed<N, T>) -> Box<dyn StateStore> {
        Box::new(ContactStates::<StateOf<N, T>>::new(
            self.particles,
            self.boundaries,
        ))
    }
}

impl Simulation {
    /// The narrow phase of the current state (narrow_phase.rs).
    pub(super) fn narrow_phase(&self) -> NarrowPhase<'_> {
        let p = &self.state.particles;
        let n = p.len();
        NarrowPhase {
            image: self.model.detection.space.minimum_image(),
            pairs: &self.state.neighbors.pairs,
            position: &p.position[..n],
            radius: &p.radius[..n],
        }
    }

    /// Particle pairs closer than `beyond` to touching (overlap > −beyond):
    /// (neighbour-list index, i, j, overlap).
    pub(super) fn touching_pairs(
        &self,
        beyond: f64,
    ) -> impl Iterator<Item = (usize, usize, usize, f64)> + '_ {
        let narrow = self.narrow_phase();
        let mut near = Vec::new();
        narrow.pairs_within(beyond, &mut near, |_| {});
        near.into_iter().filter_map(move |(k, d)| {
            let (i, j) = narrow.pair(k);
            let overlap = narrow.radius[i] + narrow.radius[j] - d.norm();
            (overlap > -beyond).then_some((k as usize, i, j, overlap))
        })
    }

    /// Particle–boundary contacts closer than `beyond` to touching:
    /// (boundary, particle, facet, overlap).
    pub(super) fn touching_walls(&self, beyond: f64) -> Vec<(usize, usize, u32, f64)> {
        let (walls, poses) = (&self.model.walls[..], &self.state.walls[..]);
        let mut out = Vec::new();
        let Ok(()): Result<(), std::convert::Infallible> = self.narrow_phase().wall_contacts(
            walls,
            poses,
            beyond,
            &mut Vec::new(),
            |w, _, _, i, found| {
                out.extend(found.iter().map(|c| (w, i, c.facet, c.overlap)));
                Ok(())
            },
        );
        out
    }

    /// The material pair and effective radius R* of particles `i` and `j`.
    pub(super) fn pair_of(&self, i: usize, j: usize) -> (&PairProperties, f64) {
        let p = &self.state.particles;
        (
            self.model.pair_table.get(p.material[i], p.material[j]),
            effective_radius(p.radius[i], p.radius[j]),
        )
    }

    /// The material pair and effective radius R* of particle `i` against boundary `w`
    /// (R* by the boundary's curvature at the particle).
    pub(super) fn wall_pair_of(&self, w: usize, i: usize) -> (&PairProperties, f64) {
        let (p, wall, pose) = (
            &self.state.particles,
            &self.model.walls[w],
            &self.state.walls[w],
        );
        (
            self.model.pair_table.get(p.material[i], wall.material),
            wall.effective_radius(pose, &p.position[i], p.radius[i]),
        )
    }

    /// The state of the scene's laws, as the type `S` the force loop knows.
    pub(super) fn states_as<S: crate::contact::model::ContactState>(&self) -> &ContactStates<S> {
        self.state
            .contacts
            .store()
            .as_any()
            .downcast_ref::<ContactStates<S>>()
            .expect("the contact states were made for the scene's laws")
    }

    /// What the contacts keep between steps (read-only: for checkpoints, tests and
    /// diagnostics).
    pub fn contact_states(&self) -> &dyn StateStore {
        self.state.contacts.store()
    }

    /// The tangential spring or force of the contact between particles `i` and `j`
    /// (either order) after the last force evaluation; `None` when the pair is not in
    /// the neighbour list or the law keeps no state. For tests and diagnostics that
    /// follow one contact.
    pub fn contact_tangential(&self, i: usize, j: usize) -> Option<Vec3> {
        let key = (i.min(j) as u32, i.max(j) as u32);
        let k = self.state.neighbors.pairs.binary_search(&key).ok()?;
        self.state.contacts.store().pair_tangential(k)
    }

    /// Number of particle–particle and particle–wall contacts at the current positions.
    pub fn contact_count(&self) -> usize {
        self.touching_pairs(0.0).count() + self.touching_walls(0.0).len()
    }

    /// Overlap of two particles (negative when apart), m.
    pub fn overlap(&self, i: usize, j: usize) -> f64 {
        let p = &self.state.particles;
        let d = self
            .model
            .detection
            .space
            .displacement(&p.position[i], &p.position[j]);
        p.radius[i] + p.radius[j] - d.norm()
    }
}
