//! One DEM run: state, the step loop, and its safeguards.
//!
//! Each step: half kick → drift (walls move too) → neighbour-list check → forces
//! (pairs, walls, gravity) → half kick. Only the effects the scene enabled run:
//! friction off selects a force loop without tangential code, rotation, damping and
//! cohesion are branches fixed for the run, gravity and walls are skipped when absent.
//!
//! Energy book: E_mech = kinetic (translation + spin) + energy stored in contact
//! springs. External work W is the work of gravity and of prescribed bodies (moving
//! walls, driven particles). Dissipation D = E_mech(0) + W − E_mech ≥ 0 for every law
//! tamp has; a clearly negative D means the integration is adding energy (unstable).
//!
//! A run is its `Model` (what the scene fixes: materials, laws, walls' shapes and
//! motion laws, sources, detection, safeguards), its `State` (what the step changes,
//! and what a checkpoint stores) and a private `Workspace` (scratch).
//!
//! This file holds the step; its parts live beside it: `force_loop` (every contact's
//! force), `contact_pass` (the force loop specialised to the scene's laws and
//! rotation), `records` (a step's contacts as output), `energy` (the energy
//! book and its check), `critical_step` (Rojek's critical time step), `growth_stage`
//! and `pour` (particles growing or entering during a run), `contacts` (queries on the
//! current contacts).

use crate::boundary::BoundaryMotion;
use crate::contact::mdr::MdrParticles;
use crate::contact::record::ContactRecord;
use crate::detect::NeighborList;
use crate::error::{Result, TampError};
use crate::integrate;
use crate::particles::{Particles, Vec3};

use contact_pass::specialised;
use energy::EnergyBook;
use force_loop::ForceLoop;
use state::Contacts;
use workspace::Workspace;

pub use limits::StabilityLimits;
pub use model::Model;
pub use state::State;
pub use velocity_changes::VelocityChange;

mod contact_pass;
mod contacts;
mod critical_step;
mod energy;
mod force_loop;
mod growth_stage;
mod limits;
mod mdr_pass;
mod model;
mod narrow_phase;
mod pour;
mod records;
mod resume;
mod state;
mod velocity_changes;
mod workspace;

/// One DEM run: its model, its state, and the step's scratch. Outside the core both
/// are read-only (`model`, `state`): the step keeps invariants across them (contact
/// states typed by the laws and indexed by the neighbour list, wall poses and forces
/// one per wall, the energy book, the time step), so they change only through the
/// step and the few setters below.
#[derive(Clone, Debug)]
pub struct Simulation {
    /// What the scene fixes; the step only reads it.
    pub(crate) model: Model,
    /// What the step changes; a checkpoint stores it.
    pub(crate) state: State,
    work: Workspace,
}

impl Simulation {
    /// What the scene fixes.
    pub fn model(&self) -> &Model {
        &self.model
    }

    /// What the step changes.
    pub fn state(&self) -> &State {
        &self.state
    }

    /// Set particle `i`'s velocity, m/s, between steps (an initial condition no scene
    /// states, or a kick).
    pub fn set_velocity(&mut self, i: usize, velocity: Vec3) {
        self.state.particles.velocity[i] = velocity;
    }

    /// From the next step on, particle `i` moves at `velocity`, m/s, whatever the force
    /// (as a scene's `prescribed_velocity`, which this changes between steps).
    pub fn prescribe(&mut self, i: usize, velocity: Vec3) {
        self.state.particles.prescribe(i, velocity);
    }

    /// Set particle `i`'s spin, rad/s, between steps.
    pub fn set_spin(&mut self, i: usize, omega: Vec3) {
        self.state.particles.omega[i] = omega;
    }

    /// From the next step on, wall `w` moves by `motion`, starting from where it is: a
    /// process's next stage (a punch released from its load and withdrawn at a speed).
    /// A `Velocity` motion goes on from the present displacement; a `Displacement`
    /// motion's expressions are of the run's time t, so they must meet the present
    /// displacement at the present time.
    pub fn set_wall_motion(&mut self, w: usize, motion: BoundaryMotion) {
        self.model.walls[w].motion = motion;
    }

    /// Put wall `w`, at rest, at `displacement` from its rest frame between steps: a
    /// process taking a punch away once nothing touches it. Contacts it had are left
    /// to the next step, which finds them gone.
    pub fn place_wall(&mut self, w: usize, displacement: Vec3) {
        self.state.walls[w].displacement = displacement;
        self.state.walls[w].velocity = Vec3::zeros();
    }

    /// A run at t = 0 of `model` with `particles`: builds the neighbour list and the
    /// forces at t = 0 and opens the energy book. The run has no time step until
    /// `set_time_step` gives it one. Fails when a contact at t = 0 is already
    /// unstable (coincident centres, an overlap beyond the limit).
    pub fn new(model: Model, particles: Particles) -> Result<Self> {
        let mut contacts = model.new_contact_states(particles.len());
        let mut neighbors = NeighborList::default();
        neighbors.rebuild(
            &model.detection,
            &particles.position,
            &particles.radius,
            &mut *contacts,
        );
        let state = State {
            time: 0.0,
            step: 0,
            // Forces at t = 0 are evaluated with a zero step, so no tangential spring
            // is advanced before the first real step.
            dt: 0.0,
            neighbors,
            contacts: Contacts::Typed(contacts),
            walls: model.walls.iter().map(|w| w.initial_pose()).collect(),
            wall_force: vec![Vec3::zeros(); model.walls.len()],
            energy: EnergyBook::default(),
            max_overlap_ratio: 0.0,
            target_radius: Vec::new(),
            sources: model.sources.iter().map(|s| s.initial_state()).collect(),
            mdr: model
                .law
                .normal
                .mdr()
                .map(|_| MdrParticles::new(&particles.radius)),
            particles,
        };
        let mut sim = Simulation {
            model,
            state,
            work: Workspace::default(),
        };
        sim.compute_forces()?;
        sim.restart_energy_book();
        sim.refresh_smallest_radius();
        Ok(sim)
    }

    /// The time step Δt, s (0 until `set_time_step`).
    pub fn dt(&self) -> f64 {
        self.state.dt
    }

    /// Step on with Δt = `dt` from now: the scene's estimate, or a process's new one
    /// (a pressing re-estimates it as the specimen stiffens). A step that is not
    /// positive and finite stops the run (exit 3); the build refuses such an estimate
    /// earlier, as bad input naming `time_step`.
    pub fn set_time_step(&mut self, dt: f64) -> Result<()> {
        if !(dt > 0.0 && dt.is_finite()) {
            return Err(self.unstable(format!(
                "the time step became {dt:e} s; a step must be positive and finite"
            )));
        }
        self.state.dt = dt;
        Ok(())
    }

    /// Advance one time step Δt (velocity-Verlet half kick, drift, forces, half kick).
    /// Fails, naming the step and the cause, when the run turns unstable (a stability
    /// limit broken, a non-finite state).
    pub fn step(&mut self) -> Result<()> {
        self.advance(None)
    }

    /// One step, and the contacts whose forces it applied (pairs and walls). They come
    /// from `contact_records`, a read-only pass over the contacts made just before the
    /// step's force loop, so the force loop itself records nothing and a scene that
    /// asks for no contacts pays nothing for them.
    pub fn step_recording_contacts(&mut self) -> Result<Vec<ContactRecord>> {
        let mut records = Vec::new();
        self.advance(Some(&mut records))?;
        Ok(records)
    }

    /// `step`; with `records`, also the contacts of the step (`step_recording_contacts`).
    fn advance(&mut self, records: Option<&mut Vec<ContactRecord>>) -> Result<()> {
        if !self.model.velocity_changes.is_empty() {
            self.change_prescribed_velocities();
        }
        let dt = self.state.dt;
        let growing = self.is_growing();
        let gravity = self.active_gravity();
        let space = self.model.detection.space;
        self.work.stepping = true;
        // Half kick, drift and periodic wrap, in one pass over the particles.
        let drifted = integrate::kick_drift_wrap(
            &mut self.state.particles,
            0.5 * dt,
            dt,
            self.model.rotation,
            gravity.as_ref(),
            &space,
        );
        let gravity_work = drifted.gravity_work;
        let (i, moved2) = drifted.farthest;
        let fraction = self.model.limits.max_step_fraction;
        if moved2 > (fraction * self.work.smallest_radius).powi(2) {
            return Err(self.unstable(format!(
                "particle {} moved {:.3e} m in one step (speed {:.3e} m/s), more than {fraction} of the smallest radius {:.3e} m (stability.max_step_fraction): it could pass through a contact unseen; the step is too large for this speed",
                self.state.particles.id[i],
                moved2.sqrt(),
                self.state.particles.velocity[i].norm(),
                self.work.smallest_radius
            )));
        }
        if let Some(growth) = self.model.growth.filter(|_| growing) {
            let f = growth.fraction(self.state.time + dt);
            for (r, target) in self
                .state
                .particles
                .radius
                .iter_mut()
                .zip(&self.state.target_radius)
            {
                *r = target * f;
            }
        }
        let walls = self.model.walls.iter().zip(&mut self.state.walls);
        for ((wall, pose), force) in walls.zip(&self.state.wall_force) {
            if let Err(what) = wall.advance(pose, self.state.time, dt, force) {
                return Err(self.unstable(what));
            }
        }
        let State {
            particles,
            neighbors,
            contacts,
            ..
        } = &mut self.state;
        neighbors.update(
            &self.model.detection,
            &particles.position,
            &particles.radius,
            contacts.store_mut(),
        );
        if let Some(records) = records {
            *records = self.contact_records();
        }
        self.compute_forces()?;
        self.work.stepping = false;
        // Half kick, the finiteness check and the prescribed particles' power, in
        // one pass.
        let kicked =
            integrate::kick_and_check(&mut self.state.particles, 0.5 * dt, self.model.rotation);
        self.state.step += 1;
        self.state.time += dt;
        if growing && !self.is_growing() {
            self.restart_energy_book();
        }
        let poured = self.state.sources.iter().any(|s| s.is_due(self.state.time));
        if poured {
            self.pour()?;
        }
        // A pour added particles the pass above did not see: check them all again.
        if (!kicked.finite || poured)
            && let Some(i) = integrate::first_non_finite(&self.state.particles)
        {
            return Err(self.unstable(format!(
                "particle {} has a non-finite position, velocity or spin",
                self.state.particles.id[i]
            )));
        }
        // Trapezoidal work of prescribed bodies, exact for gravity.
        let power = if poured {
            self.prescribed_power()
        } else {
            kicked.driven_power + self.walls_power()
        };
        let step_work = 0.5 * dt * (self.state.energy.external_power + power) + gravity_work;
        self.state.energy.external_power = power;
        self.state.energy.external_work += step_work;
        self.state.energy.external_work_scale += step_work.abs();
        if self.model.limits.check_every > 0
            && self
                .state
                .step
                .is_multiple_of(self.model.limits.check_every)
            && !self.is_growing()
        {
            self.check_energy()?;
        }
        Ok(())
    }

    /// Run `steps` steps, calling `observe` after each.
    pub fn run_with(&mut self, steps: u64, mut observe: impl FnMut(&Simulation)) -> Result<()> {
        for _ in 0..steps {
            self.step()?;
            observe(self);
        }
        self.check_energy_at_end()
    }

    /// The energy check of a run's last steps, which a run shorter than
    /// `check_every`, or ending between two checks, would otherwise never make.
    pub fn check_energy_at_end(&self) -> Result<()> {
        if self.model.limits.check_every > 0
            && !self
                .state
                .step
                .is_multiple_of(self.model.limits.check_every)
            && !self.is_growing()
        {
            self.check_energy()
        } else {
            Ok(())
        }
    }

    /// The run's stop, at the step that produced `what`: while a step is under way
    /// (its drift done, `self.state.step` not yet counted) that is the next step.
    fn unstable(&self, what: String) -> TampError {
        let (step, time) = if self.work.stepping {
            (self.state.step + 1, self.state.time + self.state.dt)
        } else {
            (self.state.step, self.state.time)
        };
        TampError::Unstable { step, time, what }
    }

    fn compute_forces(&mut self) -> Result<()> {
        specialised(self.model.law, self.model.rotation, ForceLoop(self))
    }
}
