//! The contacts of a step as records (`Simulation::step_recording_contacts`): the
//! force loop's geometry and laws on copies of the stored states, so nothing advances.

use super::Simulation;
use super::contact_pass::Spins;
use super::force_loop::{Bodies, carried_state, pair_geometry, resolve, wall_geometry};
use crate::contact::model::{
    CohesionModel, Composed, DampingModel, LawVisitor, NormalModel, StateOf, TangentialModel,
};
use crate::contact::record::{ContactRecord, Partner};
use crate::contact::states::ContactStates;

/// `Simulation::contact_records` for the scene's laws as types.
struct Records<'a>(&'a Simulation);

impl LawVisitor for Records<'_> {
    type Output = Vec<ContactRecord>;
    fn visit<N: NormalModel, D: DampingModel, T: TangentialModel, C: CohesionModel>(
        self,
        law: Composed<N, D, T, C>,
    ) -> Vec<ContactRecord> {
        self.0.contact_records_with(&law)
    }
}

impl Simulation {
    /// The contacts the force loop is about to evaluate, with the forces it will apply:
    /// every pair within reach of the law and every wall contact, each evaluated by the
    /// same geometry and law code as in `compute_forces_with`, on a copy of its stored
    /// state, so nothing is advanced. Contacts the force loop will refuse (overlap
    /// limit, non-finite force) are left out: that loop reports them.
    pub(super) fn contact_records(&self) -> Vec<ContactRecord> {
        self.model.law.visit(Records(self))
    }

    fn contact_records_with<N, D, T, C>(&self, law: &Composed<N, D, T, C>) -> Vec<ContactRecord>
    where
        N: NormalModel,
        D: DampingModel,
        T: TangentialModel,
        C: CohesionModel,
    {
        let kept = ContactStates::<StateOf<N, T>>::KEPT;
        let spins = Spins::of(&self.model.law, self.model.rotation);
        let states = self.states_as::<StateOf<N, T>>();
        let p = &self.state.particles;
        let n = p.len();
        let bodies = Bodies {
            velocity: &p.velocity[..n],
            omega: &p.omega[..n],
            radius: &p.radius[..n],
            mass: &p.mass[..n],
            prescribed: &p.prescribed[..n],
        };
        let (dt, max_fraction) = (self.state.dt, self.model.limits.max_overlap_fraction);
        let law_reach = law.cohesion.reach();
        let image = self.model.detection.space.minimum_image();
        let mut out = Vec::new();
        for (k, &(i, j)) in self.state.neighbors.pairs.iter().enumerate() {
            let (i, j) = (i as usize, j as usize);
            let d = image.displacement(&p.position[i], &p.position[j]);
            let reach = p.radius[i] + p.radius[j];
            let dist2 = d.norm_squared();
            if dist2 >= (reach + law_reach).powi(2) || dist2 == 0.0 {
                continue;
            }
            let dist = dist2.sqrt();
            let overlap = reach - dist;
            let ratio = overlap / p.radius[i].min(p.radius[j]);
            let (g, arm_i, _) = pair_geometry(&bodies, spins, i, j, d, dist, overlap);
            let pair = self.model.pair_table.get(p.material[i], p.material[j]);
            let mut state = if kept {
                states.pairs[k]
            } else {
                Default::default()
            };
            if let Ok((_, f)) = resolve(law, &g, ratio, max_fraction, pair, &mut state, dt) {
                out.push(ContactRecord {
                    i,
                    partner: Partner::Particle(j),
                    centre: p.position[i],
                    other_end: p.position[i] - d,
                    point: p.position[i] - g.normal * arm_i.torque,
                    normal: g.normal,
                    normal_force: f.normal,
                    tangential_force: f.tangential,
                    overlap,
                });
            }
        }
        let mut found = Vec::new();
        let walls = self.model.walls.iter().zip(&self.state.walls);
        for (w, (wall, pose)) in walls.enumerate() {
            for i in 0..n {
                found.clear();
                wall.contacts(pose, &p.position[i], p.radius[i], law_reach, &mut found);
                for contact in &found {
                    let ratio = contact.overlap / p.radius[i];
                    let (g, arm) = wall_geometry(p, spins, i, contact, wall, pose);
                    let pair = self.model.pair_table.get(p.material[i], wall.material);
                    let mut state = if kept {
                        carried_state(&states.walls[w][i], contact.facet)
                    } else {
                        Default::default()
                    };
                    if let Ok((_, f)) = resolve(law, &g, ratio, max_fraction, pair, &mut state, dt)
                    {
                        let point = p.position[i] - g.normal * arm.torque;
                        out.push(ContactRecord {
                            i,
                            partner: Partner::Wall(w),
                            centre: p.position[i],
                            other_end: point,
                            point,
                            normal: g.normal,
                            normal_force: f.normal,
                            tangential_force: f.tangential,
                            overlap: contact.overlap,
                        });
                    }
                }
            }
        }
        out
    }
}
