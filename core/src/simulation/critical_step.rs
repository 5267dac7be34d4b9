//! The critical time step of the current state (Rojek et al. 2016 eqs 26–29 without
//! the safety factor α).

use super::Simulation;
use super::force_loop::contact_mass;
use crate::contact::model::{Composed, LawVisitor, NormalModel, StateOf, TangentialModel};
use crate::timestep::{critical_time_step, critical_time_step_with_dashpot};

/// `Simulation::critical_time_step` for the scene's laws as types.
pub(super) struct CriticalStep<'a>(&'a Simulation, Option<f64>);

impl LawVisitor for CriticalStep<'_> {
    type Output = Option<f64>;
    fn visit<N: NormalModel, T: TangentialModel>(self, law: Composed<N, T>) -> Option<f64> {
        self.0.critical_time_step_with(&law, self.1)
    }
}

impl Simulation {
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
    /// n_c the particle's contacts (at least 1), for the same reason. LAMMPS's tangential
    /// dashpots (x_γ,t > 0 in the `lammps_*` laws) add the tangential mode as its own
    /// system: stiffness L Σk_t, dashpot L Σ x_γ,t c_n (c_n each contact's normal
    /// dashpot; for no contact the impact's), Rojek eq 28 with its own damping ratio.
    /// Returns `None` when a nonlinear law has neither a characteristic velocity nor
    /// any current contact to take a stiffness from.
    pub fn critical_time_step(&self, characteristic_velocity: Option<f64>) -> Option<f64> {
        self.model
            .law
            .visit(CriticalStep(self, characteristic_velocity))
    }

    pub(super) fn critical_time_step_with<N, T>(
        &self,
        law: &Composed<N, T>,
        characteristic_velocity: Option<f64>,
    ) -> Option<f64>
    where
        N: NormalModel,
        T: TangentialModel,
    {
        let p = &self.state.particles;
        let states = self.states_as::<StateOf<N, T>>();
        // LAMMPS's tangential dashpot x_γ,t c_n, c_n the contact's normal dashpot.
        let x_gamma_t = if law.damping.is_some() && T::ACTIVE {
            law.tangential.dashpot_over_normal()
        } else {
            0.0
        };
        let dashpot = |effective_mass: f64, k_n: f64, contact_radius: f64| match law.damping {
            Some(d) if x_gamma_t > 0.0 => {
                x_gamma_t * d.coefficient(effective_mass, k_n, || contact_radius)
            }
            _ => 0.0,
        };
        let mut met = vec![ContactsMet::default(); p.len()];
        for (k, i, j, overlap) in self.touching_pairs(0.0) {
            let (pair, r_eff) = self.pair_of(i, j);
            let (k_n, k_t) = law.stiffness(overlap, r_eff, pair, &states.pair(k));
            let a = (overlap * r_eff).sqrt();
            let c_t = dashpot(contact_mass(&p.mass, &p.prescribed, i, j), k_n, a);
            for b in [i, j] {
                met[b].add(k_n, k_t, c_t);
            }
        }
        for (w, i, facet, overlap) in self.touching_walls(0.0) {
            let (pair, r_eff) = self.wall_pair_of(w, i);
            let (k_n, k_t) = law.stiffness(overlap, r_eff, pair, &states.wall(w, i, facet));
            let a = (overlap * r_eff).sqrt();
            met[i].add(k_n, k_t, dashpot(p.mass[i], k_n, a));
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
        for src in self.pouring_sources() {
            let r = src.radius.min_radius();
            if r > 0.0 {
                let m = self.model.materials[src.material].particle_density() * 4.0 / 3.0
                    * std::f64::consts::PI
                    * r.powi(3);
                bodies.push((
                    m,
                    r,
                    self.model.inertia_scale * 0.4 * m * r * r,
                    src.material,
                    ContactsMet::default(),
                ));
            }
        }
        let mut best: Option<f64> = None;
        for (mass, radius, inertia, material, met) in bodies {
            let impact =
                if !law.normal.stiffness_depends_on_speed() || characteristic_velocity.is_some() {
                    (0..self.model.materials.len())
                        .map(|b| {
                            let pair = self.model.pair_table.get(material, b);
                            let v = characteristic_velocity.unwrap_or(0.0);
                            law.normal.impact_stiffness(mass, v, radius, pair)
                        })
                        .fold(0.0, f64::max)
                } else {
                    0.0
                };
            let lever = if self.model.rotation {
                1.0 + mass * radius.powi(2) / inertia
            } else {
                1.0
            };
            let mut k = met.normal.max(impact);
            if k <= 0.0 {
                // No normal stiffness known: the estimate is undefined for this body.
                continue;
            }
            let k_t = if T::ACTIVE {
                // A fixed spring (k_s), or LIGGGHTS hooke's k_t = k_n, is known
                // before any contact.
                law.tangential
                    .stiffness_before_contact(impact)
                    .max(met.tangential)
            } else {
                0.0
            };
            k = k.max(k_t * lever);
            // Viscous friction: the dashpots of all its contacts act on the particle together.
            let viscous = law
                .tangential
                .viscous_coefficient()
                .map(|damping| 2.0 * mass / (damping * lever * met.count.max(1) as f64));
            // The body's radius bounds the contact radius (damping/viscous.rs).
            let xi = law.damping.map_or(0.0, |d| d.ratio(mass, k, radius));
            let elastic = critical_time_step(k, mass, xi);
            let mut dt = viscous.map_or(elastic, |v| v.min(elastic));
            if x_gamma_t > 0.0 {
                // The tangential mode with its own dashpot (the normal damping ratio
                // above is the normal mode's): the dashpots of all its contacts, or of an
                // impact against a wall, times the lever factor like the springs.
                let c_t = met.tangential_dashpot.max(dashpot(mass, impact, radius));
                dt = dt.min(critical_time_step_with_dashpot(
                    k_t * lever,
                    mass,
                    c_t * lever,
                ));
            }
            best = Some(best.map_or(dt, |b: f64| b.min(dt)));
        }
        best
    }
}

/// What one particle's contacts add up to for the critical time step: Σ k_n, Σ k_t,
/// Σ γ_t of LAMMPS's tangential dashpots (summed, because neighbours act on a particle
/// through all its contacts at once) and how many there are.
#[derive(Clone, Copy, Debug, Default)]
struct ContactsMet {
    normal: f64,
    tangential: f64,
    tangential_dashpot: f64,
    count: usize,
}

impl ContactsMet {
    fn add(&mut self, k_n: f64, k_t: f64, c_t: f64) {
        self.normal += k_n;
        self.tangential += k_t;
        self.tangential_dashpot += c_t;
        self.count += 1;
    }
}
