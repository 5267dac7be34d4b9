//! The energy book: mechanical energy (kinetic and stored in contacts), the work of
//! gravity and prescribed bodies, and the check that a run does not create energy.

use super::Simulation;
use crate::contact::mdr::{PairSides, WallSide};
use crate::contact::model::{Composed, LawVisitor, NormalModel, StateOf, TangentialModel};
use crate::error::Result;
use serde::{Deserialize, Serialize};

/// The energy book's running sums (see the module documentation of `simulation`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct EnergyBook {
    /// Work done on the particles by gravity and prescribed bodies since the start, J.
    pub external_work: f64,
    /// Σ |work| of the steps, J: the scale an energy gain is judged against.
    pub external_work_scale: f64,
    /// Power of the prescribed bodies at the end of the last step, W, which the
    /// trapezoidal work rule averages with the next step's.
    pub external_power: f64,
    /// Mechanical energy when the book was opened, J.
    pub initial_mechanical_energy: f64,
}

/// `Simulation::stored_energy` for the scene's laws as types.
pub(super) struct StoredEnergy<'a>(&'a Simulation);

impl LawVisitor for StoredEnergy<'_> {
    type Output = f64;
    fn visit<N: NormalModel, T: TangentialModel>(self, law: Composed<N, T>) -> f64 {
        self.0.stored_energy_with(&law)
    }
}

impl Simulation {
    /// Make the present state the reference of the energy book (W = 0, D = 0).
    pub(super) fn restart_energy_book(&mut self) {
        self.state.energy = EnergyBook {
            external_work: 0.0,
            external_work_scale: 0.0,
            external_power: self.prescribed_power(),
            initial_mechanical_energy: self.mechanical_energy(),
        };
    }

    /// Power the prescribed bodies put into the particles at the current state, W.
    pub(super) fn prescribed_power(&self) -> f64 {
        let p = &self.state.particles;
        let driven: f64 = (0..p.len())
            .filter(|&i| p.prescribed[i])
            .map(|i| -p.force[i].dot(&p.velocity[i]))
            .sum();
        driven + self.walls_power()
    }

    /// The walls' part of `prescribed_power`, W.
    pub(super) fn walls_power(&self) -> f64 {
        self.state
            .walls
            .iter()
            .zip(&self.state.wall_force)
            .map(|(w, f)| -f.dot(&w.velocity))
            .sum()
    }

    /// Energy stored in all contacts (pairs and walls) and in cohesion, J.
    pub fn stored_energy(&self) -> f64 {
        self.model.law.visit(StoredEnergy(self))
    }

    pub(super) fn stored_energy_with<N, T>(&self, law: &Composed<N, T>) -> f64
    where
        N: NormalModel,
        T: TangentialModel,
    {
        let reach = law.reach();
        let states = self.states_as::<StateOf<N, T>>();
        // MDR's contacts hold energy by their particles' state too (`MdrContact`).
        let mdr = law
            .normal
            .mdr()
            .zip(self.state.mdr.as_ref())
            .map(|(m, particles)| (m, m.moduli(), particles));
        let id = &self.state.particles.id;
        let pairs: f64 = self
            .touching_pairs(reach)
            .map(|(k, i, j, overlap)| {
                let (pair, r_eff) = self.pair_of(i, j);
                let mut state = states.pair(k);
                let held = match &mdr {
                    Some((m, moduli, particles)) => {
                        N::mdr_contact(&mut state.normal).map_or(0.0, |c| {
                            let sides = PairSides::of(i, j, id[i], id[j]);
                            c.pair_energy(m, moduli, overlap, sides, particles)
                        })
                    }
                    None => 0.0,
                };
                law.stored_energy(overlap, r_eff, pair, &state) + held
            })
            .sum();
        let walls: f64 = self
            .touching_walls(reach)
            .into_iter()
            .map(|(w, i, facet, overlap)| {
                let (pair, r_eff) = self.wall_pair_of(w, i);
                let mut state = states.wall(w, i, facet);
                let held = match &mdr {
                    Some((m, moduli, particles)) => N::mdr_contact(&mut state.normal)
                        .map_or(0.0, |c| {
                            c.wall_energy(&m.at_wall(), moduli, overlap, WallSide(i), particles)
                        }),
                    None => 0.0,
                };
                law.stored_energy(overlap, r_eff, pair, &state) + held
            })
            .sum();
        pairs + walls
    }

    /// Potential energy of the free particles in the scene's gravity, −Σ m g·x (zero at
    /// the origin), J. Reported whether or not gravity acts yet (growth stage).
    pub fn gravitational_energy(&self) -> f64 {
        let p = &self.state.particles;
        self.model.gravity.map_or(0.0, |g| {
            (0..p.len())
                .filter(|&i| !p.prescribed[i])
                .map(|i| -p.mass[i] * g.dot(&p.position[i]))
                .sum()
        })
    }

    /// Kinetic energy of translation and spin of all particles, Σ ½ m v² + ½ I ω², J.
    pub fn kinetic_energy(&self) -> f64 {
        self.state.particles.translational_kinetic_energy()
            + self.state.particles.rotational_kinetic_energy()
    }

    /// Mechanical energy E_mech: kinetic energy plus the energy stored in the contacts'
    /// springs, J.
    pub fn mechanical_energy(&self) -> f64 {
        self.kinetic_energy() + self.stored_energy()
    }

    /// Energy dissipated so far: E_mech(0) + W − E_mech. Negative means energy was created.
    pub fn dissipated_energy(&self) -> f64 {
        self.state.energy.initial_mechanical_energy + self.state.energy.external_work
            - self.mechanical_energy()
    }

    pub(super) fn check_energy(&self) -> Result<()> {
        let gained = -self.dissipated_energy();
        let book = &self.state.energy;
        let scale = book.initial_mechanical_energy.abs() + book.external_work_scale;
        if !(gained.is_finite() && scale.is_finite()) {
            return Err(self.unstable(format!(
                "the energy book is not finite (energy gained {gained:e} J, scale {scale:e} J): a quantity beyond the range of a double"
            )));
        }
        if scale > 0.0 && gained > self.model.limits.max_energy_growth * scale {
            let p = &self.state.particles;
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
}
