//! Prescribed velocities that change during a run: a displacement-controlled loading
//! that turns back, as LAMMPS users do with `fix move` between `run`s (load to a
//! turning point, unload, reload; Rojek 2016 §3.3).
//!
//! A change due at step n takes effect before step n + 1 starts: the drift from
//! t_n to t_n+1 is made at the new velocity, and the frame written at step n still
//! shows the old one. The prescribing body does the work of the jump in kinetic
//! energy, ½m(v_new² − v_old²), which the energy book counts as external work; the
//! power −F·v the next step's trapezoidal rule starts from is the new velocity's.

use super::Simulation;
use crate::particles::Vec3;

/// One particle's new prescribed velocity from a step on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VelocityChange {
    /// The step after which the new velocity applies.
    pub step: u64,
    /// The particle's id (its place in the scene's `particles`, 1-based): ids follow
    /// a particle when the broad phase reorders the arrays.
    pub id: u64,
    /// m/s
    pub velocity: Vec3,
}

impl Simulation {
    /// Apply the changes due at the present step (`Model::velocity_changes`, sorted by
    /// step).
    pub(super) fn change_prescribed_velocities(&mut self) {
        let step = self.state.step;
        let changes = &self.model.velocity_changes;
        let from = changes.partition_point(|c| c.step < step);
        let due = changes[from..].iter().take_while(|c| c.step == step);
        let mut work = 0.0;
        let mut any = false;
        for change in due {
            let p = &mut self.state.particles;
            let i =
                p.id.iter()
                    .position(|&id| id == change.id)
                    .expect("a change names a particle of the scene");
            work +=
                0.5 * p.mass[i] * (change.velocity.norm_squared() - p.velocity[i].norm_squared());
            p.velocity[i] = change.velocity;
            any = true;
        }
        if any {
            let power = self.prescribed_power();
            let book = &mut self.state.energy;
            book.external_work += work;
            book.external_work_scale += work.abs();
            book.external_power = power;
        }
    }
}
