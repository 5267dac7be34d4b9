//! Pouring: the particles sources insert during a run (`generate::pour`).

use super::Simulation;
use crate::boundary::Boundary;
use crate::error::Result;
use crate::generate::pour::Source;
use crate::generate::rsi::Placed;
use crate::particles::{Motion, Vec3};

impl Simulation {
    /// The sources with particles still to pour.
    pub fn pouring_sources(&self) -> impl Iterator<Item = &Source> + '_ {
        let sources = self.model.sources.iter().zip(&self.state.sources);
        sources.filter(|(_, at)| at.remaining > 0).map(|(s, _)| s)
    }

    /// Insert the due batch of every pouring source (see `generate::pour`).
    pub(super) fn pour(&mut self) -> Result<()> {
        let Simulation { model, state, .. } = self;
        let t = state.time;
        for (src, at) in model.sources.iter().zip(&mut state.sources) {
            if !at.is_due(t) {
                continue;
            }
            at.next += src.every;
            // One grid per event, O(N), so that each of its draws is O(1).
            let mut placed = Placed::with(
                &model.detection.space,
                &state.particles.position,
                &state.particles.radius,
                src.radius.max_radius(),
            );
            for _ in 0..src.per_event.min(at.remaining) {
                let r = *at
                    .pending_radius
                    .get_or_insert_with(|| src.radius.sample(&mut at.rng));
                let (walls, poses) = (&model.walls, &state.walls);
                let clear = |x: &Vec3, r: f64| Boundary::clear_of_all(walls, poses, x, r);
                let Some(x) =
                    placed.place(r, &src.region, &clear, 1.0, &mut at.rng, src.max_attempts)
                else {
                    break; // no room now: this sphere waits for the next event
                };
                at.pending_radius = None;
                at.remaining -= 1;
                let velocity = crate::generate::random_unit(&mut at.rng) * src.speed;
                let omega = crate::generate::random_unit(&mut at.rng) * src.spin;
                let density = model.materials[src.material].particle_density();
                let p = &mut state.particles;
                p.push(
                    x,
                    velocity,
                    omega,
                    r,
                    density,
                    src.material,
                    model.inertia_scale,
                    Motion::Free,
                );
                let i = p.len() - 1;
                state.contacts.store_mut().add_particle();
                if let Some(mdr) = &mut state.mdr {
                    mdr.push(r);
                }
                let brought = 0.5 * p.mass[i] * velocity.norm_squared()
                    + 0.5 * p.inertia[i] * omega.norm_squared();
                state.energy.external_work += brought;
                state.energy.external_work_scale += brought;
            }
        }
        self.refresh_smallest_radius();
        // The neighbour list sees the new length and rebuilds; forces for the new
        // particles are computed at the next step.
        Ok(())
    }
}
