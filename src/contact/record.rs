//! What one contact did at one step, kept only when an output asks for it
//! (`output.contacts_every`): the force loop pushes a record per contact at such a
//! step and no other, so the contact network written is the one the step integrated.

use crate::particles::Vec3;

/// The other body of a contact.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Partner {
    Particle(usize),
    Wall(usize),
}

/// One contact seen from particle `i`. The force on `i` is
/// `normal * normal_force + tangential_force`; a partner particle gets the opposite.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactRecord {
    pub i: usize,
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
