//! Resuming a run: a stored `State` put back into a simulation built from the same
//! scene. The model comes from the scene, the state from the checkpoint, and nothing
//! is recomputed, so the run goes on bit for bit as if it had never stopped (see
//! `state` for why).

use super::state::Contacts;
use super::{Simulation, State};
use crate::error::{Result, TampError};

impl Simulation {
    /// Go on from `state`, captured from a run of this simulation's scene, in place of
    /// this simulation's own. Refuses (exit 2) a state that cannot belong to the
    /// scene: a mismatch would otherwise surface as an index out of bounds in the
    /// middle of the run.
    pub fn resume(&mut self, mut state: State) -> Result<()> {
        self.check_fits(&state)?;
        let mut typed = self.model.new_contact_states(state.particles.len());
        match std::mem::replace(&mut state.contacts, Contacts::Read(serde_json::Value::Null)) {
            Contacts::Read(json) => typed.load_json(json).map_err(|e| {
                TampError::input(
                    "checkpoint.contacts",
                    format!("does not hold the states of the scene's contact laws: {e}"),
                )
            })?,
            Contacts::Typed(store) if store.as_any().type_id() == typed.as_any().type_id() => {
                typed = store
            }
            Contacts::Typed(_) => {
                return Err(TampError::input(
                    "checkpoint.contacts",
                    "holds the states of other contact laws than the scene's",
                ));
            }
        }
        if !typed.fits(
            state.neighbors.pairs.len(),
            state.particles.len(),
            self.model.walls.len(),
        ) {
            let rule = if typed.is_kept() {
                "lacks a state for each contact, which the scene's contact laws keep"
            } else {
                "holds contact states, but the scene's contact laws keep none"
            };
            return Err(TampError::input("checkpoint.contacts", rule));
        }
        state.contacts = Contacts::Typed(typed);
        self.state = state;
        self.refresh_smallest_radius();
        Ok(())
    }

    /// The shape of `state` against this simulation: walls and sources, the particle
    /// count (those built plus those poured since), and a growth stage's radii.
    fn check_fits(&self, state: &State) -> Result<()> {
        let refuse =
            |field: &str, rule: String| Err(TampError::input(format!("checkpoint.{field}"), rule));
        match (&state.mdr, self.model.law.normal.mdr()) {
            (Some(m), Some(_)) if m.len() != state.particles.len() => {
                return refuse(
                    "mdr",
                    format!(
                        "holds the mdr state of {} particles, the checkpoint {}",
                        m.len(),
                        state.particles.len()
                    ),
                );
            }
            (None, Some(_)) => {
                return refuse(
                    "mdr",
                    "is missing; the scene's normal law 'mdr' keeps a state per particle".into(),
                );
            }
            (Some(_), None) => {
                return refuse(
                    "mdr",
                    "holds an mdr state, but the scene's normal law is not 'mdr'".into(),
                );
            }
            _ => {}
        }
        let walls = self.model.walls.len();
        if state.walls.len() != walls || state.wall_force.len() != walls {
            return refuse(
                "walls",
                format!("has {} walls, the scene {walls}", state.walls.len()),
            );
        }
        let sources = &self.state.sources;
        if state.sources.len() != sources.len() {
            return refuse(
                "sources",
                format!(
                    "has {} pouring sources, the scene {}",
                    state.sources.len(),
                    sources.len()
                ),
            );
        }
        let mut poured = 0;
        for (k, (saved, built)) in state.sources.iter().zip(sources).enumerate() {
            if saved.remaining > built.remaining {
                return refuse(
                    &format!("sources[{k}].remaining"),
                    format!(
                        "{} particles still to pour, more than the {} of the scene",
                        saved.remaining, built.remaining
                    ),
                );
            }
            poured += built.remaining - saved.remaining;
        }
        let p = &state.particles;
        let n = p.len();
        if n != self.state.particles.len() + poured {
            return refuse(
                "particles",
                format!(
                    "holds {n} particles, but the scene builds {} and its sources have poured {poured} since",
                    self.state.particles.len()
                ),
            );
        }
        let lengths = [
            p.velocity.len(),
            p.omega.len(),
            p.force.len(),
            p.torque.len(),
            p.radius.len(),
            p.mass.len(),
            p.inertia.len(),
            p.material.len(),
            p.prescribed.len(),
            p.id.len(),
        ];
        if lengths.iter().any(|&l| l != n) {
            return refuse(
                "particles",
                format!("its arrays must all hold {n} entries, got {lengths:?}"),
            );
        }
        let nb = &state.neighbors;
        if nb.reference_position.len() != nb.reference_radius.len() {
            return refuse(
                "neighbors",
                "reference positions and radii differ in number".to_string(),
            );
        }
        if state.target_radius.len() != self.state.target_radius.len() {
            return refuse(
                "target_radius",
                format!(
                    "has {} target radii, the scene's growth stage {}",
                    state.target_radius.len(),
                    self.state.target_radius.len()
                ),
            );
        }
        Ok(())
    }
}
