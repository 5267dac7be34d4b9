//! The contacts of a step as records (`Simulation::step_recording_contacts`): the
//! force loop's geometry and laws on copies of the stored states, so nothing advances.
//! MDR's contacts also need their particles' state after the pass that opens the force
//! loop (`mdr_pass.rs`): they are evaluated on a copy of the run that has made it.

use super::Simulation;
use super::contact_pass::Spins;
use super::force_loop::{Bodies, carried_state, pair_geometry, resolve, wall_geometry};
use super::mdr_pass::MdrStep;
use crate::contact::model::{Composed, LawVisitor, NormalModel, StateOf, TangentialModel};
use crate::contact::record::{ContactRecord, Partner};
use crate::contact::states::ContactStates;

/// `Simulation::contact_records` for the scene's laws as types.
struct Records<'a>(&'a Simulation);

impl LawVisitor for Records<'_> {
    type Output = Vec<ContactRecord>;
    fn visit<N: NormalModel, T: TangentialModel>(self, law: Composed<N, T>) -> Vec<ContactRecord> {
        self.0.contact_records_with(&law)
    }
}

impl Simulation {
    /// The contacts the force loop is about to evaluate, with the forces it will apply:
    /// every pair within reach of the law and every wall contact, each evaluated by the
    /// same geometry and law code as in `compute_forces_with`, on a copy of its stored
    /// state, so nothing is advanced. Contacts the force loop will refuse (overlap
    /// limit, non-finite force) are left out: that loop reports them. Between steps it
    /// evaluates the contacts at the present positions and velocities, each tangential
    /// spring one increment on from its stored state.
    pub fn contact_records(&self) -> Vec<ContactRecord> {
        self.model.law.visit(Records(self))
    }

    fn contact_records_with<N, T>(&self, law: &Composed<N, T>) -> Vec<ContactRecord>
    where
        N: NormalModel,
        T: TangentialModel,
    {
        match law.normal.mdr() {
            // MDR's forces need the pass before them, which changes the particles'
            // state: it runs on a copy of the run, as the force loop will run it.
            Some(m) => {
                let mut copy = self.clone();
                copy.mdr_begin_step::<N, T>(m);
                let mut particles = copy.state.mdr.take();
                let step = MdrStep::of(Some(m), particles.as_mut(), copy.work.stepping);
                copy.records_of(law, step)
            }
            None => self.records_of(law, None),
        }
    }

    /// The records of `contact_records_with`, each MDR contact evaluated with the
    /// particles' MDR state `mdr` (which the evaluations advance, as the force loop's do).
    fn records_of<N, T>(&self, law: &Composed<N, T>, mut mdr: Option<MdrStep>) -> Vec<ContactRecord>
    where
        N: NormalModel,
        T: TangentialModel,
    {
        let kept = ContactStates::<StateOf<N, T>>::KEPT;
        let spins = Spins::of(&self.model.law, self.model.rotation);
        let states = self.states_as::<StateOf<N, T>>();
        let p = &self.state.particles;
        let bodies = Bodies::of(p);
        let (dt, max_fraction) = (self.state.dt, self.model.limits.max_overlap_fraction);
        let law_reach = law.reach();
        let narrow = self.narrow_phase();
        let mut out = Vec::new();
        let mut near = Vec::new();
        narrow.pairs_within(law_reach, &mut near, |_| {});
        for &(k, d) in &near {
            let (i, j) = narrow.pair(k);
            let dist = d.norm_squared().sqrt();
            if dist == 0.0 {
                continue;
            }
            let overlap = p.radius[i] + p.radius[j] - dist;
            let ratio = overlap / p.radius[i].min(p.radius[j]);
            let (g, arm_i, _) = pair_geometry(&bodies, spins, i, j, d, dist, overlap);
            let pair = self.model.pair_table.get(p.material[i], p.material[j]);
            let mut state = if kept {
                states.pairs[k as usize]
            } else {
                Default::default()
            };
            let given = mdr
                .as_mut()
                .and_then(|m| m.pair::<N>(&mut state.normal, overlap, (i, j), &p.id, &g));
            let spin = p.omega[i] - p.omega[j];
            if let Ok((_, f)) = resolve(
                law,
                &g,
                ratio,
                max_fraction,
                pair,
                &mut state,
                dt,
                given,
                spin,
            ) {
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
        let (walls, poses) = (&self.model.walls[..], &self.state.walls[..]);
        let mut found = Vec::new();
        let Ok(()): Result<(), std::convert::Infallible> = narrow.wall_contacts(
            walls,
            poses,
            law_reach,
            &mut found,
            |w, wall, pose, i, found| {
                for contact in found {
                    let ratio = contact.overlap / p.radius[i];
                    let (g, arm) = wall_geometry(&bodies, spins, i, contact, wall, pose);
                    let pair = self.model.pair_table.get(p.material[i], wall.material);
                    let mut state = if kept {
                        carried_state(&states.walls[w][i], contact.facet)
                    } else {
                        Default::default()
                    };
                    let given = mdr
                        .as_mut()
                        .and_then(|m| m.wall::<N>(&mut state.normal, contact.overlap, i, &g));
                    if let Ok((_, f)) = resolve(
                        law,
                        &g,
                        ratio,
                        max_fraction,
                        pair,
                        &mut state,
                        dt,
                        given,
                        p.omega[i],
                    ) {
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
                Ok(())
            },
        );
        out
    }
}
