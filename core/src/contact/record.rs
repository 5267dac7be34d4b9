//! What one contact did at one step, made only when an output asks for it
//! (`output.contacts_every`, the die-compaction force chains): a read-only pass just
//! before the step's force loop evaluates each contact with the same geometry and law
//! code on a copy of its stored state (`Simulation::step_recording_contacts`), so the
//! forces recorded are the ones the step applies and the force loop records nothing.

use crate::particles::Vec3;

/// The other body of a contact.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Partner {
    /// Another particle, by index.
    Particle(usize),
    /// A wall, by its index among the simulation's walls.
    Wall(usize),
}

/// One contact seen from particle `i`. The force on `i` is
/// `normal * normal_force + tangential_force`; a partner particle gets the opposite.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactRecord {
    /// Index of the particle the contact is seen from.
    pub i: usize,
    /// The other body.
    pub partner: Partner,
    /// Centre of particle i, m.
    pub centre: Vec3,
    /// The partner's end of the contact's line: its centre (the nearest periodic image)
    /// for a particle, the contact point for a wall, m.
    pub other_end: Vec3,
    /// Contact point, in the middle of the overlap (tamp's lever-arm rule), m.
    pub point: Vec3,
    /// Unit normal from the partner towards i.
    pub normal: Vec3,
    /// Normal force on i along `normal`, N (> 0 pushes i away; cohesion can make it < 0).
    pub normal_force: f64,
    /// Tangential force on i, N.
    pub tangential_force: Vec3,
    /// δ = R_i + R_j − |x_i − x_j| (or the wall's), m.
    pub overlap: f64,
}
