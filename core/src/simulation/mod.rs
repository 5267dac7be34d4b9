//! One DEM run: state, the step loop, and its safeguards.
//!
//! Each step: half kick → drift (walls move too) → neighbour-list check → forces
//! (pairs, walls, gravity) → half kick. Only the effects the scene enabled run:
//! rotation and friction select a monomorphised force loop, gravity and walls are
//! skipped when absent.
//!
//! Energy book: E_mech = kinetic (translation + spin) + energy stored in contact
//! springs. External work W is the work of gravity and of prescribed bodies (moving
//! walls, driven particles). Dissipation D = E_mech(0) + W − E_mech ≥ 0 for every law
//! tamp has; a clearly negative D means the integration is adding energy (unstable).
//!
//! This file holds the step; its parts live beside it: `force_loop` (every contact's
//! force), `contact_pass` (the force loop specialised to the scene's laws and
//! rotation), `records` (a step's contacts as output), `energy` (the energy
//! book and its check), `critical_step` (Rojek's critical time step), `growth_stage`
//! and `pour` (particles growing or entering during a run), `contacts` (queries on the
//! current contacts).

use crate::boundary::{Boundary, shape::ShapeContact};
use crate::contact::ContactLaw;
use crate::contact::record::ContactRecord;
use crate::contact::states::StateStore;
use crate::detect::NeighborList;
use crate::error::{Result, TampError};
use crate::generate::pour::Source;
use crate::growth::Growth;
use crate::integrate;
use crate::material::{Material, PairTable};
use crate::particles::{Particles, Vec3};

use contact_pass::specialised;
use contacts::NewStates;
use force_loop::ForceLoop;

mod contact_pass;
mod contacts;
mod critical_step;
mod energy;
mod force_loop;
mod growth_stage;
mod pour;
mod records;

/// Safeguards that stop a run as unstable: bounds on overlap, energy gain and
/// per-step motion.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StabilityLimits {
    /// Largest overlap allowed, as a fraction of the smaller radius of the contact.
    pub max_overlap_fraction: f64,
    /// Largest energy gain without external work, as a fraction of the energy scale.
    pub max_energy_growth: f64,
    /// Steps between energy checks.
    pub check_every: u64,
    /// Largest move of a particle in one step, as a fraction of the smallest radius.
    /// At 0.25, two particles approaching each other close by at most half that
    /// radius per step, so a contact is seen at an overlap the default overlap limit
    /// (0.5) still accepts, instead of being stepped over.
    pub max_step_fraction: f64,
}

impl Default for StabilityLimits {
    fn default() -> Self {
        StabilityLimits {
            max_overlap_fraction: 0.5,
            max_energy_growth: 0.5,
            check_every: 100,
            max_step_fraction: 0.25,
        }
    }
}

/// One DEM run: the particles, walls and contact law, the clock, the neighbour list,
/// the contact history and the energy book.
#[derive(Clone, Debug)]
pub struct Simulation {
    /// The particles' state arrays (position, velocity, spin, force, …).
    pub particles: Particles,
    /// Boundaries (walls, containers, meshes), each with its own shape, material and motion.
    pub walls: Vec<Boundary>,
    /// The scene's materials; particles and walls refer to them by index.
    pub materials: Vec<Material>,
    /// Contact parameters of each pair of materials (E*, G*, friction coefficient, …).
    pub pair_table: PairTable,
    /// The scene's contact law: its normal, damping, tangential and cohesion models and
    /// lever arm.
    pub law: ContactLaw,
    /// Gravitational acceleration g, m/s²; `None` without gravity.
    pub gravity: Option<Vec3>,
    /// Whether spins are integrated (torques act); off, particles only translate.
    pub rotation: bool,
    /// Time step Δt, s.
    pub dt: f64,
    /// Steps taken so far.
    pub step: u64,
    /// Simulated time t, s.
    pub time: f64,
    /// Verlet neighbour list with skin: the candidate pairs.
    pub neighbors: NeighborList,
    /// What each pair and wall contact keeps between steps, typed by the scene's
    /// laws (`contact::states`).
    pub(crate) states: Box<dyn StateStore>,
    /// Scratch list of the contacts of one particle with one boundary.
    scratch: Vec<ShapeContact>,
    /// Scratch list of the neighbour-list pairs within reach of the law at this
    /// step, with their separation: (index in the list, x_i − x_j).
    near: Vec<(u32, Vec3)>,
    /// Whether a step's drift is done and its count not yet taken (see `unstable`).
    stepping: bool,
    /// The smallest final radius of the particles present (`refresh_smallest_radius`).
    smallest_radius: f64,
    /// Force the particles exert on each wall at the current step, N.
    pub wall_force: Vec<Vec3>,
    /// The safeguards that stop an unstable run.
    pub limits: StabilityLimits,
    /// Work done on the particles by gravity and prescribed bodies since the start, J.
    pub external_work: f64,
    pub(crate) external_work_scale: f64,
    pub(crate) external_power: f64,
    pub(crate) initial_mechanical_energy: f64,
    /// Largest overlap / smaller radius seen so far.
    pub max_overlap_ratio: f64,
    /// Growth stage (Zhong 2009 §6.1): radii grow to `target_radius`, gravity off.
    pub growth: Option<Growth>,
    /// Per particle, the final radius R_i the growth stage grows to, m (empty without one).
    pub target_radius: Vec<f64>,
    /// Pouring sources (particles entering during the run).
    pub sources: Vec<Source>,
    /// Moment-of-inertia scale of new particles (`rotation.inertia_scale`).
    pub inertia_scale: f64,
}

impl Simulation {
    /// A run at t = 0 from its particles, walls, materials and law: builds the neighbour
    /// list and the forces at t = 0 and opens the energy book. Fails when a contact at
    /// t = 0 is already unstable (coincident centres, an overlap beyond the limit).
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        particles: Particles,
        walls: Vec<Boundary>,
        materials: Vec<Material>,
        pair_table: PairTable,
        law: ContactLaw,
        gravity: Option<Vec3>,
        rotation: bool,
        dt: f64,
        mut neighbors: NeighborList,
        limits: StabilityLimits,
    ) -> Result<Self> {
        let mut states = law.visit(NewStates {
            particles: particles.len(),
            boundaries: walls.len(),
        });
        neighbors.rebuild(&particles.position, &particles.radius, &mut *states);
        let mut sim = Simulation {
            wall_force: vec![Vec3::zeros(); walls.len()],
            particles,
            walls,
            materials,
            pair_table,
            law,
            gravity,
            rotation,
            dt,
            step: 0,
            time: 0.0,
            neighbors,
            states,
            scratch: Vec::new(),
            near: Vec::new(),
            stepping: false,
            smallest_radius: f64::INFINITY,
            limits,
            external_work: 0.0,
            external_work_scale: 0.0,
            external_power: 0.0,
            initial_mechanical_energy: 0.0,
            max_overlap_ratio: 0.0,
            growth: None,
            target_radius: Vec::new(),
            sources: Vec::new(),
            inertia_scale: 1.0,
        };
        // Forces at t = 0 with a zero step, so no tangential spring is advanced before
        // the first real step.
        sim.dt = 0.0;
        sim.compute_forces()?;
        sim.dt = dt;
        sim.external_power = sim.prescribed_power();
        sim.initial_mechanical_energy = sim.mechanical_energy();
        sim.refresh_smallest_radius();
        Ok(sim)
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
        let dt = self.dt;
        let growing = self.is_growing();
        let gravity = self.active_gravity();
        let space = self.neighbors.space;
        self.stepping = true;
        // Half kick, drift and periodic wrap, in one pass over the particles.
        let drifted = integrate::kick_drift_wrap(
            &mut self.particles,
            0.5 * dt,
            dt,
            self.rotation,
            gravity.as_ref(),
            &space,
        );
        let gravity_work = drifted.gravity_work;
        let (i, moved2) = drifted.farthest;
        let fraction = self.limits.max_step_fraction;
        if moved2 > (fraction * self.smallest_radius).powi(2) {
            return Err(self.unstable(format!(
                "particle {} moved {:.3e} m in one step (speed {:.3e} m/s), more than {fraction} of the smallest radius {:.3e} m (stability.max_step_fraction): it could pass through a contact unseen; the step is too large for this speed",
                self.particles.id[i],
                moved2.sqrt(),
                self.particles.velocity[i].norm(),
                self.smallest_radius
            )));
        }
        if let Some(growth) = self.growth.filter(|_| growing) {
            let f = growth.fraction(self.time + dt);
            for (r, target) in self.particles.radius.iter_mut().zip(&self.target_radius) {
                *r = target * f;
            }
        }
        for (wall, force) in self.walls.iter_mut().zip(&self.wall_force) {
            if let Err(what) = wall.advance(self.time, dt, force) {
                return Err(self.unstable(what));
            }
        }
        self.neighbors.update(
            &self.particles.position,
            &self.particles.radius,
            &mut *self.states,
        );
        if let Some(records) = records {
            *records = self.contact_records();
        }
        self.compute_forces()?;
        self.stepping = false;
        // Half kick, the finiteness check and the prescribed particles' power, in
        // one pass.
        let kicked = integrate::kick_and_check(&mut self.particles, 0.5 * dt, self.rotation);
        self.step += 1;
        self.time += dt;
        if growing && !self.is_growing() {
            self.restart_energy_book();
        }
        let poured = self.sources.iter().any(|s| s.is_due(self.time));
        if poured {
            self.pour()?;
        }
        // A pour added particles the pass above did not see: check them all again.
        if (!kicked.finite || poured)
            && let Some(i) = integrate::first_non_finite(&self.particles)
        {
            return Err(self.unstable(format!(
                "particle {} has a non-finite position, velocity or spin",
                self.particles.id[i]
            )));
        }
        // Trapezoidal work of prescribed bodies, exact for gravity.
        let power = if poured {
            self.prescribed_power()
        } else {
            kicked.driven_power + self.walls_power()
        };
        let step_work = 0.5 * dt * (self.external_power + power) + gravity_work;
        self.external_power = power;
        self.external_work += step_work;
        self.external_work_scale += step_work.abs();
        if self.limits.check_every > 0
            && self.step.is_multiple_of(self.limits.check_every)
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
        if self.limits.check_every > 0
            && !self.step.is_multiple_of(self.limits.check_every)
            && !self.is_growing()
        {
            self.check_energy()
        } else {
            Ok(())
        }
    }

    /// The run's stop, at the step that produced `what`: while a step is under way
    /// (its drift done, `self.step` not yet counted) that is the next step.
    fn unstable(&self, what: String) -> TampError {
        let (step, time) = if self.stepping {
            (self.step + 1, self.time + self.dt)
        } else {
            (self.step, self.time)
        };
        TampError::Unstable { step, time, what }
    }

    fn compute_forces(&mut self) -> Result<()> {
        specialised(self.law, self.rotation, ForceLoop(self))
    }
}
