//! One MDR contact: a pair as two rigid-flat sides, or a particle and a wall as one.
//!
//! Pair: the flat splits the overlap (`flat.rs`), each side is evaluated with its
//! own particle (`side.rs`), and the normal force is w (F₀ + F₁)/2, w the screening
//! weight (`penalty.rs`). Side 0 is the particle of the larger id, as LAMMPS orders
//! sides by atom tag, so that the history belongs to the same particle whichever
//! comes first in the neighbour list.
//!
//! Wall: one side at the full overlap, its force magnified by
//! 1 + e^{10.7 δ₀/R₀ − 10} (LAMMPS's "wall force magnifier", which makes a wall stiffer
//! than the mid-plane of a pair as δ₀ approaches R₀; 1.00005 at first touch).
//!
//! The damping scale √(2 m* E* a_d) is computed with the force and kept in the
//! contact for the dashpot (`damping.rs`).

use super::flat::Flat;
use super::parameters::{Mdr, Moduli};
use super::particle::MdrParticles;
use super::penalty;
use super::side::{self, SideHistory};
use crate::particles::Vec3;

/// What one MDR contact remembers between steps.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct MdrContact {
    /// The two sides (a wall contact uses side 0).
    pub sides: [SideHistory; 2],
    /// Screening penalty p of this step.
    pub penalty: f64,
    /// Largest pair overlap δ_max so far, m.
    pub max_overlap: f64,
    /// √(2 m* E* a_d) of the last force evaluation (0 without a contact radius), kg/s.
    pub damping_scale: f64,
}

/// The particle indices of a pair's side 0 (the larger id) and side 1.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PairSides(pub [usize; 2]);

impl PairSides {
    /// Order particles `i` and `j` (with ids `id_i`, `id_j`) as LAMMPS does.
    pub fn of(i: usize, j: usize, id_i: u64, id_j: u64) -> Self {
        if id_i > id_j {
            PairSides([i, j])
        } else {
            PairSides([j, i])
        }
    }
}

/// A particle's contact with a wall.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct WallSide(pub usize);

/// The normal force of one contact: the elastic–plastic (and bulk) part and the
/// dashpot's coefficient.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct MdrForce {
    /// Normal force without the dashpot, N (> 0 repulsive).
    pub force: f64,
    /// The dashpot's coefficient η_eff, N·s/m; the dashpot force is η_eff dδ/dt.
    pub damping: f64,
}

impl MdrContact {
    /// The pair contact at overlap `delta` along `normal` between the particles of
    /// `sides`, with effective mass `effective_mass`; advances the history and, when
    /// `update`, the particles' sums.
    #[allow(clippy::too_many_arguments)]
    pub fn pair(
        &mut self,
        law: &Mdr,
        moduli: &Moduli,
        delta: f64,
        sides: PairSides,
        particles: &mut MdrParticles,
        normal: Vec3,
        effective_mass: f64,
        update: bool,
    ) -> MdrForce {
        if delta >= self.max_overlap {
            self.max_overlap = delta;
        }
        let overlaps = self.side_overlaps(self.max_overlap, delta, sides, particles);
        let weight = penalty::weight(self.penalty);
        let mut forces = [0.0; 2];
        let mut damping_radius = 0.0;
        for (s, force) in forces.iter_mut().enumerate() {
            let (i, side_delta) = overlaps[s];
            let out = side::evaluate(
                law,
                moduli,
                &mut self.sides[s],
                side_delta,
                i,
                particles,
                weight,
                normal,
                update,
            );
            *force = out.force;
            damping_radius += out.damping_radius;
        }
        let scale = (effective_mass * 2.0 * moduli.plane_strain * damping_radius).sqrt();
        self.finish(
            law,
            weight * (forces[0] + forces[1]) * 0.5,
            scale,
            damping_radius,
            update,
        )
    }

    /// The wall contact of particle `side` at overlap `delta` along `normal`, with
    /// the particle's mass `mass`.
    #[allow(clippy::too_many_arguments)]
    pub fn wall(
        &mut self,
        law: &Mdr,
        moduli: &Moduli,
        delta: f64,
        side: WallSide,
        particles: &mut MdrParticles,
        normal: Vec3,
        mass: f64,
        update: bool,
    ) -> MdrForce {
        if delta >= self.max_overlap {
            self.max_overlap = delta;
        }
        let weight = penalty::weight(self.penalty);
        let i = side.0;
        let out = side::evaluate(
            law,
            moduli,
            &mut self.sides[0],
            delta,
            i,
            particles,
            weight,
            normal,
            update,
        );
        let damping_radius = out.damping_radius / 2.0;
        let scale = (mass * 2.0 * (0.5 * moduli.plane_strain) * damping_radius).sqrt();
        let magnifier =
            (10.7 * self.sides[0].displacement / particles.initial_radius[i] - 10.0).exp() + 1.0;
        self.finish(
            law,
            weight * out.force * magnifier,
            scale,
            damping_radius,
            update,
        )
    }

    /// The elastic energy the pair holds (`side::stored_energy`): the two sides' in
    /// series carry one force w(F₀ + F₁)/2 ≈ wF over the sum of their overlaps, so
    /// w (E₀ + E₁).
    /// `delta` is the pair's overlap, which the flat splits between the sides as
    /// `pair` does.
    pub fn pair_energy(
        &self,
        law: &Mdr,
        moduli: &Moduli,
        delta: f64,
        sides: PairSides,
        particles: &MdrParticles,
    ) -> f64 {
        let overlaps = self.side_overlaps(self.max_overlap.max(delta), delta, sides, particles);
        let w = penalty::weight(self.penalty);
        w * (0..2)
            .map(|s| {
                let (i, side_delta) = overlaps[s];
                side::stored_energy(law, moduli, &self.sides[s], side_delta, i, particles)
            })
            .sum::<f64>()
    }

    /// Each side's particle and its share of the pair overlap `delta`, the flat placed
    /// by the largest pair overlap `max_overlap` and the sides' plastic sets.
    fn side_overlaps(
        &self,
        max_overlap: f64,
        delta: f64,
        sides: PairSides,
        particles: &MdrParticles,
    ) -> [(usize, f64); 2] {
        let flat = Flat {
            max_overlap,
            plastic: [self.sides[0].plastic_overlap, self.sides[1].plastic_overlap],
        };
        [0, 1].map(|s| {
            let (i, j) = (sides.0[s], sides.0[1 - s]);
            let r = &particles.radius;
            (i, flat.force_side(delta, r[i], r[j], flat.plastic[s]))
        })
    }

    /// The elastic energy the wall contact holds: its side's, times the weight and the
    /// force magnifier of the present displacement.
    pub fn wall_energy(
        &self,
        law: &Mdr,
        moduli: &Moduli,
        delta: f64,
        side: WallSide,
        particles: &MdrParticles,
    ) -> f64 {
        let i = side.0;
        let magnifier =
            (10.7 * self.sides[0].displacement / particles.initial_radius[i] - 10.0).exp() + 1.0;
        penalty::weight(self.penalty)
            * magnifier
            * side::stored_energy(law, moduli, &self.sides[0], delta, i, particles)
    }

    fn finish(
        &mut self,
        law: &Mdr,
        force: f64,
        scale: f64,
        damping_radius: f64,
        update: bool,
    ) -> MdrForce {
        if update {
            self.damping_scale = if damping_radius <= 0.0 { 0.0 } else { scale };
        }
        MdrForce {
            force,
            damping: law.damping.coefficient(self.damping_scale),
        }
    }
}

impl crate::contact::model::ContactState for MdrContact {}
