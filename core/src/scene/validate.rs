//! Rules a scene must satisfy before anything is built. All violations are
//! collected, each as `json.path: rule, got value`; each topic's rules live in its
//! file (materials.rs, contact.rs, particles.rs, walls.rs, physics.rs, run.rs), and
//! this one runs them in order.

use super::contact::LawContext;
use super::die_compaction::DieCompactionSpec;
use super::schema::*;
use super::{contact, materials, particles, physics, run, walls};
pub(super) use crate::error::Errors;
use crate::error::Result;
use std::collections::HashSet;

/// Every rule of the scene; all violations are listed together (exit 2).
pub fn validate(scene: &Scene) -> Result<()> {
    match &scene.die_compaction {
        Some(dc) => validate_die_compaction(scene, dc),
        None => validate_plain(scene),
    }
}

/// A die-compaction scene owns its particles, walls and stage durations; the rest
/// is checked by the topics' own rules, the fill stage's contact block at its path.
fn validate_die_compaction(scene: &Scene, dc: &DieCompactionSpec) -> Result<()> {
    let mut e = Errors(Vec::new());
    let owned = [
        ("particles", !scene.particles.is_empty()),
        ("insert", !scene.insert.is_empty()),
        ("deposit", !scene.deposit.is_empty()),
        ("walls", !scene.walls.is_empty()),
        ("periodic", scene.periodic.is_some()),
        ("growth", scene.growth.is_some()),
        (
            "run",
            scene.run.duration.is_some() || scene.run.steps.is_some() || scene.run.until.is_some(),
        ),
    ];
    for (field, given) in owned {
        if given {
            e.push(
                field,
                "must be left out of a die_compaction scene: its stages set it",
            );
        }
    }
    if scene.gravity.is_none() {
        e.push(
            "gravity",
            "is required by die_compaction: the die is filled by settling under it",
        );
    }
    if scene.time_step.accuracy.is_some() {
        e.push(
            "time_step.accuracy",
            "is not available in a die_compaction scene (its press stage re-estimates the step from the contacts with time_step.alpha); give time_step.alpha",
        );
    }
    let names: HashSet<&str> = scene.materials.iter().map(|m| m.name.as_str()).collect();
    dc.validate(&|name| names.contains(name), &mut e);
    if let Some(m) = scene
        .materials
        .iter()
        .find(|m| m.rigid && m.name == dc.particles.material)
    {
        e.push(
            "die_compaction.particles.material",
            format!(
                "'{}' is rigid: only walls may be made of a rigid material",
                m.name
            ),
        );
    }
    if e.0.is_empty() {
        // The topics the stages share with an ordinary scene, the particles being the
        // specimen's and the run's length the stages'.
        let names = materials::validate(&scene.materials, &mut e);
        let ctx = LawContext {
            particle_materials: [dc.particles.material.as_str()].into(),
            rotation: scene.rotation.is_some(),
            materials: &scene.materials,
            names: &names,
        };
        contact::validate(&scene.contact, "contact", &ctx, &mut e);
        materials::validate_hardening(&scene.materials, &mut e);
        physics::validate(scene, &mut e);
        run::validate_time_step(&scene.time_step, &mut e);
        run::validate_detection_limits_and_output(scene, &mut e);
        contact::validate(
            &dc.fill.contact,
            "die_compaction.fill.contact",
            &ctx,
            &mut e,
        );
    }
    e.finish()
}

/// An ordinary scene: each topic's rules, in the order of the file's blocks (the
/// Hollomon blocks after the contact law, whose needs name them first).
fn validate_plain(scene: &Scene) -> Result<()> {
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
