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
use crate::contact::damping::liggghts::LiggghtsModel;
use crate::contact::{
    ContactGeometry, ContactLaw, history::ContactHistory, normal::NormalLaw,
    tangential::TangentialLaw,
};
use crate::detect::NeighborList;
use crate::error::{Result, TampError};
use crate::generate::pour::Source;
use crate::generate::rsi;
use crate::growth::Growth;
use crate::integrate;
use crate::material::{Material, PairTable, effective_mass, effective_radius};
use crate::particles::{Motion, Particles, Vec3};
use crate::timestep::critical_time_step;

/// Effective mass of a pair; a prescribed particle moves whatever the force, so it
/// counts as infinitely heavy, like a wall.
#[inline]
fn contact_mass(p: &Particles, i: usize, j: usize) -> f64 {
    match (p.motion[i], p.motion[j]) {
        (Motion::Free, Motion::Prescribed(_)) => p.mass[i],
        (Motion::Prescribed(_), Motion::Free) => p.mass[j],
        _ => effective_mass(p.mass[i], p.mass[j]),
    }
}

/// Add the weight m g of every free particle to its force.
fn add_weights(p: &mut Particles, g: Vec3) {
    for i in 0..p.len() {
        if p.motion[i] == Motion::Free {
            p.force[i] += g * p.mass[i];
        }
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
}

impl Default for StabilityLimits {
    fn default() -> Self {
        StabilityLimits {
            max_overlap_fraction: 0.5,
            max_energy_growth: 0.5,
            check_every: 100,
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
    /// History of particle–boundary contacts, `[boundary][particle]` → (facet, history)
    /// for each facet touched; empty when the law keeps none.
    pub(crate) wall_history: Vec<Vec<Vec<(u32, ContactHistory)>>>,
    /// Scratch list of the contacts of one particle with one boundary.
    scratch: Vec<ShapeContact>,
    /// Scratch copy of one particle's facet histories from the previous step.
    scratch_history: Vec<(u32, ContactHistory)>,
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
        let n = particles.len();
        let wall_history = if law.has_history() {
            vec![vec![Vec::new(); n]; walls.len()]
        } else {
            Vec::new()
        };
        neighbors.rebuild(&particles.position, &particles.radius);
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
            wall_history,
            scratch: Vec::new(),
            scratch_history: Vec::new(),
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
        Ok(sim)
    }

    pub fn step(&mut self) -> Result<()> {
        let dt = self.dt;
        integrate::kick(&mut self.particles, 0.5 * dt);
        if self.rotation {
            integrate::kick_spin(&mut self.particles, 0.5 * dt);
        }
        let growing = self.is_growing();
        let gravity = self.active_gravity();
        let gravity_work = integrate::drift(&mut self.particles, dt, gravity.as_ref());
        if let Some(growth) = self.growth.filter(|_| growing) {
            let f = growth.fraction(self.time + dt);
            for (r, target) in self.particles.radius.iter_mut().zip(&self.target_radius) {
                *r = target * f;
            }
        }
        let space = self.neighbors.space;
        if space.is_periodic() {
            self.particles
                .position
                .iter_mut()
                .for_each(|x| space.wrap(x));
        }
        for (wall, force) in self.walls.iter_mut().zip(&self.wall_force) {
            if let Err(what) = wall.advance(self.time, dt, force) {
                return Err(self.unstable(what));
            }
        }
        self.neighbors
            .update(&self.particles.position, &self.particles.radius);
        self.compute_forces()?;
        integrate::kick(&mut self.particles, 0.5 * dt);
        if self.rotation {
            integrate::kick_spin(&mut self.particles, 0.5 * dt);
        }
        self.step += 1;
        self.time += dt;
        if growing && !self.is_growing() {
            self.restart_energy_book();
        }
        if self.sources.iter().any(|s| s.is_due(self.time)) {
            self.pour()?;
        }
        if let Some(i) = integrate::first_non_finite(&self.particles) {
            return Err(self.unstable(format!(
                "particle {i} has a non-finite position, velocity or spin"
            )));
        }
        // Trapezoidal work of prescribed bodies, exact for gravity.
        let power = self.prescribed_power();
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
        // The forces of `new` included the weights, which wait for the end of growth:
        // take them off again instead of evaluating every contact a second time.
        if let Some(g) = self.gravity.filter(|_| self.is_growing()) {
            add_weights(&mut self.particles, -g);
        }
        self.restart_energy_book();
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
            for _ in 0..src.per_event.min(src.remaining) {
                let r = *src
                    .pending_radius
                    .get_or_insert_with(|| src.radius.sample(&mut src.rng));
                let walls = &self.walls;
                let clear = |x: &Vec3, r: f64| Boundary::clear_of_all(walls, x, r);
                let p = &self.particles;
                let Some(x) = rsi::place(
                    r,
                    &src.region,
                    &p.position,
                    &p.radius,
                    &clear,
                    &self.neighbors.space,
                    1.0,
                    &mut src.rng,
                    src.max_attempts,
                ) else {
                    break; // no room now: this sphere waits for the next event
                };
                src.pending_radius = None;
                src.remaining -= 1;
                let velocity = crate::generate::random_unit(&mut src.rng) * src.speed;
                let omega = crate::generate::random_unit(&mut src.rng) * src.spin;
                let density = self.materials[src.material].density;
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
                for h in &mut self.wall_history {
                    h.push(Vec::new());
                }
                let brought = 0.5 * self.particles.mass[i] * velocity.norm_squared()
                    + 0.5 * self.particles.inertia[i] * omega.norm_squared();
                self.external_work += brought;
                self.external_work_scale += brought;
            }
        }
        self.sources = sources;
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
        Ok(())
    }

    fn unstable(&self, what: String) -> TampError {
        TampError::Unstable {
            step: self.step,
            time: self.time,
            what,
        }
    }

    fn compute_forces(&mut self) -> Result<()> {
        match (self.rotation, self.law.has_history()) {
            (false, false) => self.compute_forces_with::<false, false>(),
            (false, true) => self.compute_forces_with::<false, true>(),
            (true, false) => self.compute_forces_with::<true, false>(),
            (true, true) => self.compute_forces_with::<true, true>(),
        }
    }

    /// Contact, wall and body forces at the current positions. `ROT`: spins enter
    /// contact velocities and torques are accumulated. `HIST`: contacts carry
    /// history (a tangential state or the normal law's δ_max).
    fn compute_forces_with<const ROT: bool, const HIST: bool>(&mut self) -> Result<()> {
        let gravity = self.active_gravity();
        let p = &mut self.particles;
        let n = p.len();
        p.force.iter_mut().for_each(|f| *f = Vec3::zeros());
        if ROT {
            p.torque.iter_mut().for_each(|t| *t = Vec3::zeros());
        }
        if let Some(g) = gravity {
            add_weights(p, g);
        }
        let dt = self.dt;
        let max_fraction = self.limits.max_overlap_fraction;
        let mut worst = self.max_overlap_ratio;
        let torques = ROT && self.law.tangential.is_some();
        let law_reach = self.law.reach();
        let space = self.neighbors.space;

        for (k, &(i, j)) in self.neighbors.pairs.iter().enumerate() {
            let (i, j) = (i as usize, j as usize);
            let d = space.displacement(&p.position[i], &p.position[j]);
            let reach = p.radius[i] + p.radius[j];
            let dist2 = d.norm_squared();
            if dist2 >= (reach + law_reach).powi(2) {
                if HIST {
                    self.neighbors.history[k] = ContactHistory::default();
                }
                continue;
            }
            let dist = dist2.sqrt();
            let overlap = reach - dist;
            let ratio = overlap / p.radius[i].min(p.radius[j]);
            worst = worst.max(ratio);
            if dist == 0.0 {
                // The build refuses coincident centres, and a pair driven together
                // meets the overlap limit first unless it is at least (R_i + R_j)/R_min ≥ 2.
                return Err(self.unstable(format!(
                    "contact {i}-{j}: the centres coincide (overlap {overlap:.4e} m), so the contact normal is undefined"
                )));
            }
            if ratio > max_fraction {
                return Err(self.unstable(format!(
                    "contact {i}-{j}: overlap {overlap:.4e} m is {ratio:.3} of the smaller radius (limit {max_fraction})"
                )));
            }
            let normal = d / dist;
            // Contact point in the middle of the overlap: the two lever arms add up to
            // the centre distance, so contact torques conserve angular momentum.
            let lever_i = p.radius[i] - 0.5 * overlap;
            let lever_j = p.radius[j] - 0.5 * overlap;
            let mut relative_velocity = p.velocity[i] - p.velocity[j];
            if ROT {
                relative_velocity -=
                    p.omega[i].cross(&normal) * lever_i + p.omega[j].cross(&normal) * lever_j;
            }
            let g = ContactGeometry {
                normal,
                overlap,
                effective_radius: effective_radius(p.radius[i], p.radius[j]),
                effective_mass: contact_mass(p, i, j),
                relative_velocity,
            };
            let pair = self.pair_table.get(p.material[i], p.material[j]);
            let history = if HIST {
                Some(&mut self.neighbors.history[k])
            } else {
                None
            };
            let f = self.law.evaluate(&g, pair, history, dt);
            let total = normal * f.normal + f.tangential;
            if !total.iter().all(|c| c.is_finite()) {
                return Err(self.unstable(format!(
                    "contact {i}-{j}: non-finite contact force at overlap {overlap:.4e} m"
                )));
            }
            p.force[i] += total;
            p.force[j] -= total;
            if torques {
                let t = -normal.cross(&f.tangential);
                p.torque[i] += t * lever_i;
                p.torque[j] += t * lever_j;
            }
        }

        let mut found = std::mem::take(&mut self.scratch);
        let mut previous = std::mem::take(&mut self.scratch_history);
        for (w, wall) in self.walls.iter().enumerate() {
            let mut on_wall = Vec3::zeros();
            for i in 0..n {
                found.clear();
                wall.contacts(&p.position[i], p.radius[i], law_reach, &mut found);
                if found.is_empty() {
                    if HIST {
                        self.wall_history[w][i].clear();
                    }
                    continue;
                }
                // Histories of the facets touched last step, carried to this step's
                // contacts; both buffers keep their capacity, so the walls' loop allocates
                // nothing of its own (revolved and mesh shapes still gather their
                // candidate parts in a fresh Vec for each sphere that touches them).
                if HIST {
                    previous.clear();
                    previous.extend_from_slice(&self.wall_history[w][i]);
                    self.wall_history[w][i].clear();
                }
                for c in &found {
                    let overlap = c.overlap;
                    let ratio = overlap / p.radius[i];
                    worst = worst.max(ratio);
                    if ratio > max_fraction {
                        return Err(self.unstable(format!(
                            "contact {i}-wall '{}' (facet {}): overlap {overlap:.4e} m is {ratio:.3} of the radius (limit {max_fraction})",
                            wall.name, c.facet
                        )));
                    }
                    let normal = c.normal;
                    let lever = p.radius[i] - 0.5 * overlap;
                    let mut relative_velocity = p.velocity[i] - wall.velocity;
                    if ROT {
                        relative_velocity -= p.omega[i].cross(&normal) * lever;
                    }
                    let g = ContactGeometry {
                        normal,
                        overlap,
                        effective_radius: p.radius[i],
                        effective_mass: p.mass[i],
                        relative_velocity,
                    };
                    let pair = self.pair_table.get(p.material[i], wall.material);
                    // `previous` is only filled when contacts have history.
                    let mut history = previous
                        .iter()
                        .find(|(f, _)| *f == c.facet)
                        .map_or_else(ContactHistory::default, |(_, h)| *h);
                    let f = self
                        .law
                        .evaluate(&g, pair, HIST.then_some(&mut history), dt);
                    if HIST {
                        self.wall_history[w][i].push((c.facet, history));
                    }
                    let total = normal * f.normal + f.tangential;
                    if !total.iter().all(|c| c.is_finite()) {
                        return Err(self.unstable(format!(
                            "contact {i}-wall '{}' (facet {}): non-finite contact force",
                            wall.name, c.facet
                        )));
                    }
                    p.force[i] += total;
                    on_wall -= total;
                    if torques {
                        p.torque[i] += -normal.cross(&f.tangential) * lever;
                    }
                }
            }
            self.wall_force[w] = on_wall;
        }
        self.scratch = found;
        self.scratch_history = previous;
        self.max_overlap_ratio = worst;
        Ok(())
    }

    /// Power the prescribed bodies put into the particles at the current state, W.
    fn prescribed_power(&self) -> f64 {
        let p = &self.particles;
        let driven: f64 = (0..p.len())
            .filter(|&i| p.motion[i] != Motion::Free)
            .map(|i| -p.force[i].dot(&p.velocity[i]))
            .sum();
        let walls: f64 = self
            .walls
            .iter()
            .zip(&self.wall_force)
            .map(|(w, f)| -f.dot(&w.velocity))
            .sum();
        driven + walls
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

    fn pair_history(&self, k: usize) -> Option<&ContactHistory> {
        self.neighbors.history.get(k)
    }

    /// The stored state of the contact between particles `i` and `j` (either order)
    /// after the last force evaluation; `None` when the pair is not in the neighbour
    /// list or the law keeps no history. Read-only: for tests and diagnostics that
    /// follow one contact's tangential state.
    pub fn contact_history(&self, i: usize, j: usize) -> Option<&ContactHistory> {
        let key = (i.min(j) as u32, i.max(j) as u32);
        let k = self.neighbors.pairs.binary_search(&key).ok()?;
        self.pair_history(k)
    }

    fn wall_contact_history(&self, w: usize, i: usize, facet: u32) -> Option<&ContactHistory> {
        self.wall_history
            .get(w)
            .and_then(|h| h.get(i))
            .and_then(|list| list.iter().find(|(f, _)| *f == facet).map(|(_, h)| h))
    }

    /// Energy stored in all contacts (pairs and walls) and in cohesion, J.
    pub fn stored_energy(&self) -> f64 {
        let p = &self.particles;
        let reach = self.law.reach();
        let pairs: f64 = self
            .touching_pairs(reach)
            .map(|(k, i, j, overlap)| {
                let pair = self.pair_table.get(p.material[i], p.material[j]);
                let r_eff = effective_radius(p.radius[i], p.radius[j]);
                self.law
                    .stored_energy(overlap, r_eff, pair, self.pair_history(k))
            })
            .sum();
        let walls: f64 = self
            .touching_walls(reach)
            .into_iter()
            .map(|(w, i, facet, overlap)| {
                let pair = self.pair_table.get(p.material[i], self.walls[w].material);
                let history = self.wall_contact_history(w, i, facet);
                self.law.stored_energy(overlap, p.radius[i], pair, history)
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
                .filter(|&i| p.motion[i] == Motion::Free)
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
                "mechanical energy grew by {gained:.4e} J, {:.3} of the energy scale {scale:.4e} J, without external work \
                 (fastest: particle {fastest} at {:.4e} m/s); the time step is likely too large",
                gained / scale,
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
        let p = &self.particles;
        let mut met = vec![ContactsMet::default(); p.len()];
        for (k, i, j, overlap) in self.touching_pairs(0.0) {
            let pair = self.pair_table.get(p.material[i], p.material[j]);
            let r_eff = effective_radius(p.radius[i], p.radius[j]);
            let (k_n, k_t) = self
                .law
                .stiffness(overlap, r_eff, pair, self.pair_history(k));
            for b in [i, j] {
                met[b].add(k_n, k_t);
            }
        }
        for (w, i, facet, overlap) in self.touching_walls(0.0) {
            let pair = self.pair_table.get(p.material[i], self.walls[w].material);
            let history = self.wall_contact_history(w, i, facet);
            let (k_n, k_t) = self.law.stiffness(overlap, p.radius[i], pair, history);
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
                let m = self.materials[src.material].density * 4.0 / 3.0
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
            let impact = match (&self.law.normal, characteristic_velocity) {
                (NormalLaw::Linear { .. }, _)
                | (NormalLaw::Hysteretic { .. }, _)
                | (NormalLaw::WaltonBraun { .. }, _)
                | (_, Some(_)) => (0..self.materials.len())
                    .map(|b| {
                        let pair = self.pair_table.get(material, b);
                        let v = characteristic_velocity.unwrap_or(0.0);
                        self.law.normal.impact_stiffness(mass, v, radius, pair)
                    })
                    .fold(0.0, f64::max),
                (_, None) => 0.0,
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
            if let Some(
                TangentialLaw::CundallStrack { stiffness }
                | TangentialLaw::WaltonBraun { stiffness },
            ) = self.law.tangential
            {
                k = k.max(stiffness * lever);
            }
            if let Some(TangentialLaw::LiggghtsHistory {
                model: LiggghtsModel::Hooke,
                ..
            }) = self.law.tangential
            {
                // k_t = k_n of the linear law, known before any contact.
                k = k.max(impact * lever);
            }
            k = k.max(met.tangential * lever);
            let viscous = match self.law.tangential {
                Some(TangentialLaw::HaffWerner { damping }) if damping > 0.0 => {
                    // The dashpots of all its contacts act on the particle together.
                    Some(2.0 * mass / (damping * lever * met.count.max(1) as f64))
                }
                _ => None,
            };
            let xi = self.law.damping.map(|d| d.ratio(mass, k)).unwrap_or(0.0);
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
