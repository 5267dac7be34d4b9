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

use crate::boundary::{Boundary, shape::ShapeContact};
use crate::contact::lever_arm::{Arms, Lammps, LeverArm, LeverArms, MidOverlap};
use crate::contact::model::{
    CohesionModel, Composed, DampingModel, LawVisitor, NormalModel, StateOf, TangentialModel,
};
use crate::contact::record::{ContactRecord, Partner};
use crate::contact::states::{ContactStates, StateStore};
use crate::contact::{ContactForce, ContactGeometry, ContactLaw};
use crate::detect::NeighborList;
use crate::error::{Result, TampError};
use crate::generate::pour::Source;
use crate::generate::rsi::Placed;
use crate::growth::Growth;
use crate::integrate;
use crate::material::PairProperties;
use crate::material::{Material, PairTable, effective_mass, effective_radius};
use crate::particles::{Motion, Particles, Vec3};
use crate::timestep::critical_time_step;
use std::marker::PhantomData;

/// Effective mass of a pair; a prescribed particle moves whatever the force, so it
/// counts as infinitely heavy, like a wall.
#[inline(always)]
fn contact_mass(mass: &[f64], prescribed: &[bool], i: usize, j: usize) -> f64 {
    match (prescribed[i], prescribed[j]) {
        (false, true) => mass[i],
        (true, false) => mass[j],
        _ => effective_mass(mass[i], mass[j]),
    }
}

/// Set every particle's force to its weight, zero plus m g for a free particle (the
/// same sum as zeroing the force and calling `add_weights`) and zero for a
/// prescribed one, in one pass.
fn set_weights(p: &mut Particles, g: Vec3) {
    let n = p.len();
    let (force, mass, prescribed) = (&mut p.force[..n], &p.mass[..n], &p.prescribed[..n]);
    for ((f, &m), &fixed) in force.iter_mut().zip(mass).zip(prescribed) {
        *f = if fixed {
            Vec3::zeros()
        } else {
            Vec3::zeros() + g * m
        };
    }
}

/// Add the weight m g of every free particle to its force.
fn add_weights(p: &mut Particles, g: Vec3) {
    for i in 0..p.len() {
        if !p.prescribed[i] {
            p.force[i] += g * p.mass[i];
        }
    }
}

/// What pair and wall contacts share once their geometry is known: the overlap
/// limit, the scene's laws, and a finite force. Returns the force on particle i
/// and its parts; the error says what went wrong, for the caller to place.
#[inline(always)]
fn resolve<N, D, T, C>(
    law: &Composed<N, D, T, C>,
    g: &ContactGeometry,
    ratio: f64,
    max_fraction: f64,
    pair: &PairProperties,
    state: &mut StateOf<N, T>,
    dt: f64,
) -> std::result::Result<(Vec3, ContactForce), String>
where
    N: NormalModel,
    D: DampingModel,
    T: TangentialModel,
    C: CohesionModel,
{
    let overlap = g.overlap;
    if ratio > max_fraction {
        return Err(format!(
            "overlap {overlap:.4e} m is {ratio:.3e} of the smaller radius (limit {max_fraction})"
        ));
    }
    let f = law.evaluate(g, pair, state, dt);
    let total = g.normal * f.normal + f.tangential;
    if !total.iter().all(|c| c.is_finite()) {
        return Err(format!(
            "non-finite contact force at overlap {overlap:.4e} m"
        ));
    }
    Ok((total, f))
}

/// Give this step's contacts of one particle with one wall (`found`) the states of
/// the same facets last step; a facet touched anew starts fresh.
#[inline(always)]
fn carry_facet_states<S: Copy + Default>(states: &mut Vec<(u32, S)>, found: &[ShapeContact]) {
    let same =
        states.len() == found.len() && states.iter().zip(found).all(|((f, _), c)| *f == c.facet);
    if !same {
        let previous = std::mem::take(states);
        states.extend(
            found
                .iter()
                .map(|c| (c.facet, carried_state(&previous, c.facet))),
        );
    }
}

/// The state facet `facet` had last step among one particle's contacts with one wall,
/// or a fresh one.
#[inline(always)]
fn carried_state<S: Copy + Default>(previous: &[(u32, S)], facet: u32) -> S {
    let kept = previous.iter().find(|(f, _)| *f == facet);
    kept.map_or_else(S::default, |(_, s)| *s)
}

/// The particle arrays a contact's geometry reads, as slices of one length.
struct Bodies<'a> {
    velocity: &'a [Vec3],
    omega: &'a [Vec3],
    radius: &'a [f64],
    mass: &'a [f64],
    prescribed: &'a [bool],
}

/// The geometry of the pair contact i–j at separation d = x_i − x_j (nearest image,
/// |d| = `dist` > 0, overlap δ = R_i + R_j − |d|), and the lever arms of i and j in
/// the convention `A`. `ROT`: spins enter the contact velocity.
#[inline(always)]
fn pair_geometry<A: LeverArms, const ROT: bool>(
    b: &Bodies,
    i: usize,
    j: usize,
    d: Vec3,
    dist: f64,
    overlap: f64,
) -> (ContactGeometry, Arms, Arms) {
    let normal = d / dist;
    let (arm_i, arm_j) = (A::pair(b.radius[i], overlap), A::pair(b.radius[j], overlap));
    let mut relative_velocity = b.velocity[i] - b.velocity[j];
    if ROT {
        relative_velocity -=
            b.omega[i].cross(&normal) * arm_i.velocity + b.omega[j].cross(&normal) * arm_j.velocity;
    }
    let g = ContactGeometry {
        normal,
        overlap,
        effective_radius: effective_radius(b.radius[i], b.radius[j]),
        effective_mass: contact_mass(b.mass, b.prescribed, i, j),
        relative_velocity,
    };
    (g, arm_i, arm_j)
}

/// The geometry of particle i's contact `c` with `wall`, and i's lever arms in the
/// convention `A`.
#[inline(always)]
fn wall_geometry<A: LeverArms, const ROT: bool>(
    p: &Particles,
    i: usize,
    c: &ShapeContact,
    wall: &Boundary,
) -> (ContactGeometry, Arms) {
    let (overlap, normal) = (c.overlap, c.normal);
    let arm = A::wall(p.radius[i], overlap);
    let mut relative_velocity = p.velocity[i] - wall.velocity;
    if ROT {
        relative_velocity -= p.omega[i].cross(&normal) * arm.velocity;
    }
    let g = ContactGeometry {
        normal,
        overlap,
        effective_radius: wall.effective_radius(&p.position[i], p.radius[i]),
        effective_mass: p.mass[i],
        relative_velocity,
    };
    (g, arm)
}

/// `Simulation::compute_forces` for the scene's laws and lever-arm convention as types.
struct ForceLoop<'a, A: LeverArms, const ROT: bool>(&'a mut Simulation, PhantomData<A>);

impl<A: LeverArms, const ROT: bool> LawVisitor for ForceLoop<'_, A, ROT> {
    type Output = Result<()>;
    fn visit<N: NormalModel, D: DampingModel, T: TangentialModel, C: CohesionModel>(
        self,
        law: Composed<N, D, T, C>,
    ) -> Result<()> {
        self.0.compute_forces_with::<N, D, T, C, A, ROT>(&law)
    }
}

/// An empty state store of the scene's laws' state type.
struct NewStates {
    particles: usize,
    boundaries: usize,
}

impl LawVisitor for NewStates {
    type Output = Box<dyn StateStore>;
    fn visit<N: NormalModel, D: DampingModel, T: TangentialModel, C: CohesionModel>(
        self,
        _: Composed<N, D, T, C>,
    ) -> Box<dyn StateStore> {
        Box::new(ContactStates::<StateOf<N, T>>::new(
            self.particles,
            self.boundaries,
        ))
    }
}

/// `Simulation::contact_records` for the scene's laws as types.
struct Records<'a, A: LeverArms, const ROT: bool>(&'a Simulation, PhantomData<A>);

impl<A: LeverArms, const ROT: bool> LawVisitor for Records<'_, A, ROT> {
    type Output = Vec<ContactRecord>;
    fn visit<N: NormalModel, D: DampingModel, T: TangentialModel, C: CohesionModel>(
        self,
        law: Composed<N, D, T, C>,
    ) -> Vec<ContactRecord> {
        self.0.contact_records_with::<N, D, T, C, A, ROT>(&law)
    }
}

/// `Simulation::stored_energy` for the scene's laws as types.
struct StoredEnergy<'a>(&'a Simulation);

impl LawVisitor for StoredEnergy<'_> {
    type Output = f64;
    fn visit<N: NormalModel, D: DampingModel, T: TangentialModel, C: CohesionModel>(
        self,
        law: Composed<N, D, T, C>,
    ) -> f64 {
        self.0.stored_energy_with(&law)
    }
}

/// `Simulation::critical_time_step` for the scene's laws as types.
struct CriticalStep<'a>(&'a Simulation, Option<f64>);

impl LawVisitor for CriticalStep<'_> {
    type Output = Option<f64>;
    fn visit<N: NormalModel, D: DampingModel, T: TangentialModel, C: CohesionModel>(
        self,
        law: Composed<N, D, T, C>,
    ) -> Option<f64> {
        self.0.critical_time_step_with(&law, self.1)
    }
}

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

#[derive(Clone, Debug)]
pub struct Simulation {
    pub particles: Particles,
    /// Boundaries (walls, containers, meshes), each with its own shape, material and motion.
    pub walls: Vec<Boundary>,
    pub materials: Vec<Material>,
    pub pair_table: PairTable,
    pub law: ContactLaw,
    pub gravity: Option<Vec3>,
    pub rotation: bool,
    pub dt: f64,
    pub step: u64,
    pub time: f64,
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
    pub target_radius: Vec<f64>,
    /// Pouring sources (particles entering during the run).
    pub sources: Vec<Source>,
    /// Moment-of-inertia scale of new particles (`rotation.inertia_scale`).
    pub inertia_scale: f64,
}

impl Simulation {
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

    /// Attach a growth stage to a simulation built with its particles at the starting
    /// size; `target_radius` are the final radii.
    pub fn set_growth(&mut self, growth: Growth, target_radius: Vec<f64>) {
        self.growth = Some(growth);
        self.target_radius = target_radius;
        self.refresh_smallest_radius();
        // The forces of `new` included the weights, which wait for the end of growth:
        // take them off again instead of evaluating every contact a second time.
        if let Some(g) = self.gravity.filter(|_| self.is_growing()) {
            add_weights(&mut self.particles, -g);
        }
        self.restart_energy_book();
    }

    /// Keep `smallest_radius` the smallest final radius present, after particles or
    /// their final radii change (build, growth, pouring).
    pub(crate) fn refresh_smallest_radius(&mut self) {
        self.smallest_radius = (0..self.particles.len())
            .map(|i| self.final_radius(i))
            .fold(f64::INFINITY, f64::min);
    }

    /// The smallest final radius of the particles present, m (∞ with none).
    pub fn smallest_radius(&self) -> f64 {
        self.smallest_radius
    }

    /// Radius particle i has at the end of any growth stage.
    fn final_radius(&self, i: usize) -> f64 {
        if self.growth.is_some() {
            self.target_radius[i]
        } else {
            self.particles.radius[i]
        }
    }

    pub fn is_growing(&self) -> bool {
        self.growth.is_some_and(|g| g.is_growing(self.time))
    }

    /// Gravity as it acts now: absent during a growth stage.
    pub fn active_gravity(&self) -> Option<Vec3> {
        if self.is_growing() {
            None
        } else {
            self.gravity
        }
    }

    /// Make the present state the reference of the energy book (W = 0, D = 0).
    fn restart_energy_book(&mut self) {
        self.external_work = 0.0;
        self.external_work_scale = 0.0;
        self.external_power = self.prescribed_power();
        self.initial_mechanical_energy = self.mechanical_energy();
    }

    /// Insert the due batch of every pouring source (see `generate::pour`).
    fn pour(&mut self) -> Result<()> {
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
        let law = self.law;
        // Without spins no lever arm enters the forces: one variant serves both.
        match (self.rotation, law.lever_arm) {
            (true, LeverArm::MidOverlap) => {
                law.visit(ForceLoop::<MidOverlap, true>(self, PhantomData))
            }
            (true, LeverArm::Lammps) => law.visit(ForceLoop::<Lammps, true>(self, PhantomData)),
            (false, _) => law.visit(ForceLoop::<MidOverlap, false>(self, PhantomData)),
        }
    }

    /// Contact, wall and body forces at the current positions, for the scene's laws
    /// as types. `ROT`: spins enter contact velocities and torques are accumulated,
    /// with the lever arms of the convention `A`.
    fn compute_forces_with<N, D, T, C, A: LeverArms, const ROT: bool>(
        &mut self,
        law: &Composed<N, D, T, C>,
    ) -> Result<()>
    where
        N: NormalModel,
        D: DampingModel,
        T: TangentialModel,
        C: CohesionModel,
    {
        let kept = ContactStates::<StateOf<N, T>>::KEPT;
        let gravity = self.active_gravity();
        let p = &mut self.particles;
        let n = p.len();
        // Forces start from the weights (or zero), torques from zero, in one pass.
        match gravity {
            Some(g) => set_weights(p, g),
            None => p.force.iter_mut().for_each(|f| *f = Vec3::zeros()),
        }
        if ROT {
            p.torque.iter_mut().for_each(|t| *t = Vec3::zeros());
        }
        let dt = self.dt;
        let max_fraction = self.limits.max_overlap_fraction;
        let mut worst = self.max_overlap_ratio;
        let torques = ROT && T::ACTIVE;
        let law_reach = law.cohesion.reach();
        let image = self.neighbors.space.minimum_image();
        let states = self
            .states
            .as_any_mut()
            .downcast_mut::<ContactStates<StateOf<N, T>>>()
            .expect("the contact states were made for the scene's laws");
        let mut fresh = StateOf::<N, T>::default();

        // The particle arrays as slices of one length n, so that one bounds check
        // per index covers them all, and none of them is re-read through `self`.
        let Particles {
            position,
            velocity,
            omega,
            force,
            torque,
            radius,
            mass,
            material,
            prescribed,
            ..
        } = p;
        let (position, velocity, omega, radius, mass, material, prescribed) = (
            &position[..n],
            &velocity[..n],
            &omega[..n],
            &radius[..n],
            &mass[..n],
            &material[..n],
            &prescribed[..n],
        );
        let (force, torque) = (&mut force[..n], &mut torque[..]);
        let bodies = Bodies {
            velocity,
            omega,
            radius,
            mass,
            prescribed,
        };
        let pairs = &self.neighbors.pairs[..];
        let pair_states: &mut [StateOf<N, T>] = if kept {
            &mut states.pairs[..pairs.len()]
        } else {
            &mut []
        };

        // Pass 1, over every pair of the list: the pairs within reach of their law,
        // with their separation; the state of every other pair is reset (it is apart).
        // Most pairs of a Verlet list are apart, and this loop is all they cost.
        let mut near = std::mem::take(&mut self.near);
        near.clear();
        for (k, &(i, j)) in pairs.iter().enumerate() {
            let (i, j) = (i as usize, j as usize);
            let d = image.displacement(&position[i], &position[j]);
            let reach = radius[i] + radius[j];
            if d.norm_squared() >= (reach + law_reach).powi(2) {
                if kept {
                    pair_states[k] = Default::default();
                }
            } else {
                near.push((k as u32, d));
            }
        }

        // Pass 2, over the pairs within reach, in the list's order (so forces are
        // summed in the same order as by one loop over the list).
        for &(k, d) in &near {
            let k = k as usize;
            let (i, j) = (pairs[k].0 as usize, pairs[k].1 as usize);
            let reach = radius[i] + radius[j];
            let dist2 = d.norm_squared();
            let dist = dist2.sqrt();
            let overlap = reach - dist;
            let ratio = overlap / radius[i].min(radius[j]);
            worst = worst.max(ratio);
            if dist == 0.0 {
                // The build refuses coincident centres, and a pair driven together
                // meets the overlap limit first unless it is at least (R_i + R_j)/R_min ≥ 2.
                self.near = near;
                return Err(self.unstable(format!(
                    "contact {}-{}: the centres coincide (overlap {overlap:.4e} m), so the contact normal is undefined",
                    self.particles.id[i], self.particles.id[j]
                )));
            }
            let (g, arm_i, arm_j) = pair_geometry::<A, ROT>(&bodies, i, j, d, dist, overlap);
            let normal = g.normal;
            let pair = self.pair_table.get(material[i], material[j]);
            let state = if kept {
                &mut pair_states[k]
            } else {
                &mut fresh
            };
            let (total, f) = match resolve(law, &g, ratio, max_fraction, pair, state, dt) {
                Ok(forces) => forces,
                Err(what) => {
                    self.near = near;
                    return Err(self.unstable(format!(
                        "contact {}-{}: {what}",
                        self.particles.id[i], self.particles.id[j]
                    )));
                }
            };
            force[i] += total;
            force[j] -= total;
            if torques {
                let t = -normal.cross(&f.tangential);
                torque[i] += t * arm_i.torque;
                torque[j] += t * arm_j.torque;
            }
        }
        self.near = near;
        let p = &mut self.particles;

        let mut found = std::mem::take(&mut self.scratch);
        for (w, wall) in self.walls.iter().enumerate() {
            let mut on_wall = Vec3::zeros();
            for i in 0..n {
                found.clear();
                wall.contacts(&p.position[i], p.radius[i], law_reach, &mut found);
                if kept {
                    // The states of the facets touched last step, carried to this
                    // step's contacts by facet.
                    carry_facet_states(&mut states.walls[w][i], &found);
                }
                for (c, contact) in found.iter().enumerate() {
                    let (facet, normal) = (contact.facet, contact.normal);
                    let ratio = contact.overlap / p.radius[i];
                    worst = worst.max(ratio);
                    let (g, arm) = wall_geometry::<A, ROT>(p, i, contact, wall);
                    let pair = self.pair_table.get(p.material[i], wall.material);
                    let state = if kept {
                        &mut states.walls[w][i][c].1
                    } else {
                        &mut fresh
                    };
                    let (total, f) = match resolve(law, &g, ratio, max_fraction, pair, state, dt) {
                        Ok(forces) => forces,
                        Err(what) => {
                            let what = format!(
                                "contact {}-wall '{}' (facet {facet}): {what}",
                                p.id[i], wall.name
                            );
                            return Err(self.unstable(what));
                        }
                    };
                    p.force[i] += total;
                    on_wall -= total;
                    if torques {
                        p.torque[i] += -normal.cross(&f.tangential) * arm.torque;
                    }
                }
            }
            self.wall_force[w] = on_wall;
        }
        self.scratch = found;
        self.max_overlap_ratio = worst;
        Ok(())
    }

    /// The contacts the force loop is about to evaluate, with the forces it will apply:
    /// every pair within reach of the law and every wall contact, each evaluated by the
    /// same geometry and law code as in `compute_forces_with`, on a copy of its stored
    /// state, so nothing is advanced. Contacts the force loop will refuse (overlap
    /// limit, non-finite force) are left out: that loop reports them.
    fn contact_records(&self) -> Vec<ContactRecord> {
        let law = self.law;
        match (self.rotation, law.lever_arm) {
            (true, LeverArm::MidOverlap) => {
                law.visit(Records::<MidOverlap, true>(self, PhantomData))
            }
            (true, LeverArm::Lammps) => law.visit(Records::<Lammps, true>(self, PhantomData)),
            (false, _) => law.visit(Records::<MidOverlap, false>(self, PhantomData)),
        }
    }

    fn contact_records_with<N, D, T, C, A: LeverArms, const ROT: bool>(
        &self,
        law: &Composed<N, D, T, C>,
    ) -> Vec<ContactRecord>
    where
        N: NormalModel,
        D: DampingModel,
        T: TangentialModel,
        C: CohesionModel,
    {
        let kept = ContactStates::<StateOf<N, T>>::KEPT;
        let states = self.states_as::<StateOf<N, T>>();
        let p = &self.particles;
        let n = p.len();
        let bodies = Bodies {
            velocity: &p.velocity[..n],
            omega: &p.omega[..n],
            radius: &p.radius[..n],
            mass: &p.mass[..n],
            prescribed: &p.prescribed[..n],
        };
        let (dt, max_fraction) = (self.dt, self.limits.max_overlap_fraction);
        let law_reach = law.cohesion.reach();
        let image = self.neighbors.space.minimum_image();
        let mut out = Vec::new();
        for (k, &(i, j)) in self.neighbors.pairs.iter().enumerate() {
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
            let (g, arm_i, _) = pair_geometry::<A, ROT>(&bodies, i, j, d, dist, overlap);
            let pair = self.pair_table.get(p.material[i], p.material[j]);
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
        for (w, wall) in self.walls.iter().enumerate() {
            for i in 0..n {
                found.clear();
                wall.contacts(&p.position[i], p.radius[i], law_reach, &mut found);
                for contact in &found {
                    let ratio = contact.overlap / p.radius[i];
                    let (g, arm) = wall_geometry::<A, ROT>(p, i, contact, wall);
                    let pair = self.pair_table.get(p.material[i], wall.material);
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

    /// Power the prescribed bodies put into the particles at the current state, W.
    fn prescribed_power(&self) -> f64 {
        let p = &self.particles;
        let driven: f64 = (0..p.len())
            .filter(|&i| p.prescribed[i])
            .map(|i| -p.force[i].dot(&p.velocity[i]))
            .sum();
        driven + self.walls_power()
    }

    /// The walls' part of `prescribed_power`, W.
    fn walls_power(&self) -> f64 {
        self.walls
            .iter()
            .zip(&self.wall_force)
            .map(|(w, f)| -f.dot(&w.velocity))
            .sum()
    }

    /// Particle pairs closer than `beyond` to touching (overlap > −beyond):
    /// (neighbour-list index, i, j, overlap).
    fn touching_pairs(&self, beyond: f64) -> impl Iterator<Item = (usize, usize, usize, f64)> + '_ {
        self.neighbors
            .pairs
            .iter()
            .enumerate()
            .filter_map(move |(k, &(i, j))| {
                let (i, j) = (i as usize, j as usize);
                let overlap = self.overlap(i, j);
                (overlap > -beyond).then_some((k, i, j, overlap))
            })
    }

    /// Particle–boundary contacts closer than `beyond` to touching:
    /// (boundary, particle, facet, overlap).
    fn touching_walls(&self, beyond: f64) -> Vec<(usize, usize, u32, f64)> {
        let p = &self.particles;
        let mut out = Vec::new();
        let mut found = Vec::new();
        for (w, wall) in self.walls.iter().enumerate() {
            for i in 0..p.len() {
                found.clear();
                wall.contacts(&p.position[i], p.radius[i], beyond, &mut found);
                out.extend(found.iter().map(|c| (w, i, c.facet, c.overlap)));
            }
        }
        out
    }

    /// The state of the scene's laws, as the type `S` the force loop knows.
    fn states_as<S: crate::contact::model::ContactState>(&self) -> &ContactStates<S> {
        self.states
            .as_any()
            .downcast_ref::<ContactStates<S>>()
            .expect("the contact states were made for the scene's laws")
    }

    /// What the contacts keep between steps (read-only: for checkpoints, tests and
    /// diagnostics).
    pub fn contact_states(&self) -> &dyn StateStore {
        &*self.states
    }

    /// The tangential spring or force of the contact between particles `i` and `j`
    /// (either order) after the last force evaluation; `None` when the pair is not in
    /// the neighbour list or the law keeps no state. For tests and diagnostics that
    /// follow one contact.
    pub fn contact_tangential(&self, i: usize, j: usize) -> Option<Vec3> {
        let key = (i.min(j) as u32, i.max(j) as u32);
        let k = self.neighbors.pairs.binary_search(&key).ok()?;
        self.states.pair_tangential(k)
    }

    /// Energy stored in all contacts (pairs and walls) and in cohesion, J.
    pub fn stored_energy(&self) -> f64 {
        self.law.visit(StoredEnergy(self))
    }

    fn stored_energy_with<N, D, T, C>(&self, law: &Composed<N, D, T, C>) -> f64
    where
        N: NormalModel,
        D: DampingModel,
        T: TangentialModel,
        C: CohesionModel,
    {
        let p = &self.particles;
        let reach = law.cohesion.reach();
        let states = self.states_as::<StateOf<N, T>>();
        let pairs: f64 = self
            .touching_pairs(reach)
            .map(|(k, i, j, overlap)| {
                let pair = self.pair_table.get(p.material[i], p.material[j]);
                let r_eff = effective_radius(p.radius[i], p.radius[j]);
                law.stored_energy(overlap, r_eff, pair, &states.pair(k))
            })
            .sum();
        let walls: f64 = self
            .touching_walls(reach)
            .into_iter()
            .map(|(w, i, facet, overlap)| {
                let wall = &self.walls[w];
                let pair = self.pair_table.get(p.material[i], wall.material);
                let r_eff = wall.effective_radius(&p.position[i], p.radius[i]);
                law.stored_energy(overlap, r_eff, pair, &states.wall(w, i, facet))
            })
            .sum();
        pairs + walls
    }

    /// Potential energy of the free particles in the scene's gravity, −Σ m g·x (zero at
    /// the origin), J. Reported whether or not gravity acts yet (growth stage).
    pub fn gravitational_energy(&self) -> f64 {
        let p = &self.particles;
        self.gravity.map_or(0.0, |g| {
            (0..p.len())
                .filter(|&i| !p.prescribed[i])
                .map(|i| -p.mass[i] * g.dot(&p.position[i]))
                .sum()
        })
    }

    pub fn kinetic_energy(&self) -> f64 {
        self.particles.translational_kinetic_energy() + self.particles.rotational_kinetic_energy()
    }

    pub fn mechanical_energy(&self) -> f64 {
        self.kinetic_energy() + self.stored_energy()
    }

    /// Energy dissipated so far: E_mech(0) + W − E_mech. Negative means energy was created.
    pub fn dissipated_energy(&self) -> f64 {
        self.initial_mechanical_energy + self.external_work - self.mechanical_energy()
    }

    fn check_energy(&self) -> Result<()> {
        let gained = -self.dissipated_energy();
        let scale = self.initial_mechanical_energy.abs() + self.external_work_scale;
        if !(gained.is_finite() && scale.is_finite()) {
            return Err(self.unstable(format!(
                "the energy book is not finite (energy gained {gained:e} J, scale {scale:e} J): a quantity beyond the range of a double"
            )));
        }
        if scale > 0.0 && gained > self.limits.max_energy_growth * scale {
            let p = &self.particles;
            let fastest = (0..p.len())
                .max_by(|&a, &b| {
                    p.velocity[a]
                        .norm_squared()
                        .total_cmp(&p.velocity[b].norm_squared())
                })
                .unwrap_or(0);
            return Err(self.unstable(format!(
                "mechanical energy grew by {gained:.4e} J, {:.3e} of the energy scale {scale:.4e} J, without external work \
                 (fastest: particle {} at {:.4e} m/s); the time step is likely too large",
                gained / scale,
                p.id[fastest],
                p.velocity[fastest].norm()
            )));
        }
        Ok(())
    }

    /// Number of particle–particle and particle–wall contacts at the current positions.
    pub fn contact_count(&self) -> usize {
        self.touching_pairs(0.0).count() + self.touching_walls(0.0).len()
    }

    /// Overlap of two particles (negative when apart), m.
    pub fn overlap(&self, i: usize, j: usize) -> f64 {
        let p = &self.particles;
        let d = self
            .neighbors
            .space
            .displacement(&p.position[i], &p.position[j]);
        p.radius[i] + p.radius[j] - d.norm()
    }

    /// Critical time step estimate, Rojek eqs 26–29 without the safety factor α.
    ///
    /// k_i is the largest of: the sum of the particle's current normal contact
    /// stiffnesses (for laws with memory, the current branch's, or the unloading
    /// branch's where that is stiffer: `NormalLaw::time_step_stiffness`, Rojek §3.4); the impact stiffness against a much larger body of any material
    /// (R* = R_i, m* = m_i: walls, and an upper bound on any finite partner); and the
    /// sum of the tangential stiffnesses of its contacts (or the Cundall–Strack k_s) —
    /// times (1 + m R²/I) when rotation is on, because the tangential force then also
    /// drives the spin of the contact point. The sum, not the largest: in a dense bed
    /// neighbours spin against each other through all their contacts at once, and
    /// with the largest alone a 12-contact Mindlin lattice was stable only to
    /// α = 0.60 (`tamp study stable-alpha`, docs/accuracy-cost.md). Viscous
    /// Haff–Werner friction adds the explicit limit Δt < 2m/(n_c γ_s (1 + m R²/I)),
    /// n_c the particle's contacts (at least 1), for the same reason.
    /// Returns `None` when a nonlinear law has neither a characteristic velocity nor
    /// any current contact to take a stiffness from.
    pub fn critical_time_step(&self, characteristic_velocity: Option<f64>) -> Option<f64> {
        self.law.visit(CriticalStep(self, characteristic_velocity))
    }

    fn critical_time_step_with<N, D, T, C>(
        &self,
        law: &Composed<N, D, T, C>,
        characteristic_velocity: Option<f64>,
    ) -> Option<f64>
    where
        N: NormalModel,
        D: DampingModel,
        T: TangentialModel,
        C: CohesionModel,
    {
        let p = &self.particles;
        let states = self.states_as::<StateOf<N, T>>();
        let mut met = vec![ContactsMet::default(); p.len()];
        for (k, i, j, overlap) in self.touching_pairs(0.0) {
            let pair = self.pair_table.get(p.material[i], p.material[j]);
            let r_eff = effective_radius(p.radius[i], p.radius[j]);
            let (k_n, k_t) = law.stiffness(overlap, r_eff, pair, &states.pair(k));
            for b in [i, j] {
                met[b].add(k_n, k_t);
            }
        }
        for (w, i, facet, overlap) in self.touching_walls(0.0) {
            let wall = &self.walls[w];
            let pair = self.pair_table.get(p.material[i], wall.material);
            let r_eff = wall.effective_radius(&p.position[i], p.radius[i]);
            let (k_n, k_t) = law.stiffness(overlap, r_eff, pair, &states.wall(w, i, facet));
            met[i].add(k_n, k_t);
        }
        // Each body: (mass, radius at full size, moment of inertia, material, the
        // contacts it meets). Particles still to be poured count with the smallest
        // radius their source can draw, the lightest they can be, and no contact.
        let mut bodies: Vec<(f64, f64, f64, usize, ContactsMet)> = (0..p.len())
            .map(|i| {
                let r = self.final_radius(i);
                (p.mass[i], r, p.inertia[i], p.material[i], met[i])
            })
            .collect();
        for src in self.sources.iter().filter(|s| s.remaining > 0) {
            let r = src.radius.min_radius();
            if r > 0.0 {
                let m = self.materials[src.material].particle_density() * 4.0 / 3.0
                    * std::f64::consts::PI
                    * r.powi(3);
                bodies.push((
                    m,
                    r,
                    self.inertia_scale * 0.4 * m * r * r,
                    src.material,
                    ContactsMet::default(),
                ));
            }
        }
        let mut best: Option<f64> = None;
        for (mass, radius, inertia, material, met) in bodies {
            let impact =
                if !law.normal.stiffness_depends_on_speed() || characteristic_velocity.is_some() {
                    (0..self.materials.len())
                        .map(|b| {
                            let pair = self.pair_table.get(material, b);
                            let v = characteristic_velocity.unwrap_or(0.0);
                            law.normal.impact_stiffness(mass, v, radius, pair)
                        })
                        .fold(0.0, f64::max)
                } else {
                    0.0
                };
            let lever = if self.rotation {
                1.0 + mass * radius.powi(2) / inertia
            } else {
                1.0
            };
            let mut k = met.normal.max(impact);
            if k <= 0.0 {
                // No normal stiffness known: the estimate is undefined for this body.
                continue;
            }
            if T::ACTIVE {
                // A fixed spring (k_s), or LIGGGHTS hooke's k_t = k_n, is known
                // before any contact.
                k = k.max(law.tangential.stiffness_before_contact(impact) * lever);
            }
            k = k.max(met.tangential * lever);
            // Viscous friction: the dashpots of all its contacts act on the particle together.
            let viscous = law
                .tangential
                .viscous_coefficient()
                .map(|damping| 2.0 * mass / (damping * lever * met.count.max(1) as f64));
            let xi = if D::ACTIVE {
                law.damping.ratio(mass, k)
            } else {
                0.0
            };
            let elastic = critical_time_step(k, mass, xi);
            let dt = viscous.map_or(elastic, |v| v.min(elastic));
            best = Some(best.map_or(dt, |b: f64| b.min(dt)));
        }
        best
    }
}

/// What one particle's contacts add up to for the critical time step: Σ k_n, Σ k_t
/// (summed, because neighbours act on a particle through all its contacts at once)
/// and how many there are.
#[derive(Clone, Copy, Debug, Default)]
struct ContactsMet {
    normal: f64,
    tangential: f64,
    count: usize,
}

impl ContactsMet {
    fn add(&mut self, k_n: f64, k_t: f64) {
        self.normal += k_n;
        self.tangential += k_t;
        self.count += 1;
    }
}
