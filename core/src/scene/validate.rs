//! Rules a scene must satisfy before anything is built. All violations are
//! collected, each as `json.path: rule, got value`; each topic's rules live in its
//! file (materials.rs, contact.rs, particles.rs, walls.rs, physics.rs, run.rs), and
//! this one runs them in order.

use super::contact::LawContext;
use super::schema::*;
use super::{contact, materials, particles, physics, run, walls};
pub(super) use crate::error::Errors;
use crate::error::Result;

/// Every rule of the scene; all violations are listed together (exit 2): each topic's
/// rules, in the order of the file's blocks (the Hollomon blocks after the contact law,
/// whose needs name them first).
pub fn validate(scene: &Scene) -> Result<()> {
    let mut e = Errors(Vec::new());
    let names = materials::validate(&scene.materials, &mut e);
    contact::validate(
        &scene.contact,
        "contact",
        &LawContext::of(scene, &names),
        &mut e,
    );
    materials::validate_hardening(&scene.materials, &mut e);
    particles::validate(scene, &names, &mut e);
    walls::validate(&scene.walls, &|name| names.known(name), &mut e);
    physics::validate(scene, &mut e);
    run::validate(scene, &mut e);
    e.finish()
}
