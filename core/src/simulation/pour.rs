//! Pouring: the particles sources insert during a run (`generate::pour`).

use super::Simulation;
use crate::boundary::Boundary;
use crate::error::Result;
use crate::generate::rsi::Placed;
use crate::particles::{Motion, Vec3};

impl Simulation {
    /// Insert the due batch of every pouring source (see `generate::pour`).
    pub(super) fn pour(&mut self) -> Result<()> {
        let t = self.time;
        let mut sources = std::mem::take(&mut self.sources);
        for src in sources.iter_mut().filter(|s| s.is_due(t)) {
            src.next += src.every;
            // One grid per event, O(N), so that each of its draws is O(1).
            let mut placed = Placed::with(
                &self.neighbors.space,
                &self.particles.position,
                &self.particles.radius,
                src.radius.max_radius(),
            );
            for _ in 0..src.per_event.min(src.remaining) {
                let r = *src
                    .pending_radius
                    .get_or_insert_with(|| src.radius.sample(&mut src.rng));
                let walls = &self.walls;
                let clear = |x: &Vec3, r: f64| Boundary::clear_of_all(walls, x, r);
                let Some(x) =
                    placed.place(r, &src.region, &clear, 1.0, &mut src.rng, src.max_attempts)
                else {
                    break; // no room now: this sphere waits for the next event
                };
                src.pending_radius = None;
                src.remaining -= 1;
                let velocity = crate::generate::random_unit(&mut src.rng) * src.speed;
                let omega = crate::generate::random_unit(&mut src.rng) * src.spin;
                let density = self.materials[src.material].particle_density();
                self.particles.push(
                    x,
                    velocity,
                    omega,
                    r,
                    density,
                    src.material,
                    self.inertia_scale,
                    Motion::Free,
                );
                let i = self.particles.len() - 1;
                self.states.add_particle();
                let brought = 0.5 * self.particles.mass[i] * velocity.norm_squared()
                    + 0.5 * self.particles.inertia[i] * omega.norm_squared();
                self.external_work += brought;
                self.external_work_scale += brought;
            }
        }
        self.sources = sources;
        self.refresh_smallest_radius();
        // The neighbour list sees the new length and rebuilds; forces for the new
        // particles are computed at the next step.
        Ok(())
    }
}
