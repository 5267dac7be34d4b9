//! Rules a scene must satisfy before anything is built. All violations are
//! collected, each as `json.path: rule, got value`.

use super::die_compaction::DieCompactionSpec;
use super::schema::*;
use crate::contact::model::{Needs, Roles};
pub(super) use crate::error::Errors;
use crate::error::{Result, TampError};
use std::collections::HashSet;

pub const SERIES_COLUMNS: &[&str] = &[
    "kinetic_energy",
    "rotational_energy",
    "stored_energy",
    "gravitational_energy",
    "external_work",
    "dissipated_energy",
    "contact_count",
    "max_overlap_ratio",
    "wall_forces",
];

/// What a law needs of the materials and the scene (`Needs`), asked of every
/// material; `by` names the law in the message.
fn require(e: &mut Errors, scene: &Scene, needs: Needs, by: &str) {
    if let Some(what_for) = needs.elastic {
        for (k, m) in scene.materials.iter().enumerate() {
            for (field, given) in [
                ("youngs_modulus", m.youngs_modulus.is_some()),
                ("poisson_ratio", m.poisson_ratio.is_some()),
            ] {
                if !given && !m.rigid {
                    e.push(
                        format!("materials[{k}].{field}"),
                        format!("is required by {by}{what_for}"),
                    );
                }
            }
        }
    }
    if needs.hollomon {
        let particle_materials: HashSet<&str> = scene
            .particles
            .iter()
            .map(|p| p.material.as_str())
            .chain(scene.insert.iter().map(|i| i.material.as_str()))
            .chain(scene.deposit.iter().map(|d| d.material.as_str()))
            .collect();
        for (k, m) in scene.materials.iter().enumerate() {
            if m.hollomon.is_none() && particle_materials.contains(m.name.as_str()) {
                e.push(
                    format!("materials[{k}].hollomon"),
                    format!("is required by {by} for every particle material"),
                );
            }
        }
        let exponents: Vec<(usize, f64)> = scene
            .materials
            .iter()
            .enumerate()
            .filter_map(|(k, m)| m.hollomon.as_ref().map(|h| (k, h.exponent)))
            .collect();
        if let Some(&(first, m0)) = exponents.first() {
            for &(k, m) in &exponents[1..] {
                if m != m0 {
                    e.push(
                        format!("materials[{k}].hollomon.exponent"),
                        format!("must equal materials[{first}].hollomon.exponent ({m0}): Rojek eq 18 mixes one exponent, got {m}"),
                    );
                }
            }
        }
    }
    if let Some(rule) = needs.rotation
        && scene.rotation.is_none()
    {
        e.push("rotation", rule);
    }
}

pub fn validate(scene: &Scene) -> Result<()> {
    match &scene.die_compaction {
        Some(dc) => validate_die_compaction(scene, dc),
        None => validate_plain(scene),
    }
}

/// A die-compaction scene owns its particles, walls and stage durations; its
/// contact blocks are checked by validating the stage scenes they make, with the
/// paths of the fill law's errors put back where the user wrote them.
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
        let mut probe = scene.clone();
        probe.die_compaction = None;
        probe.particles = vec![ParticleSpec {
            position: [0.0; 3],
            radius: dc.particles.radius.distribution().max_radius(),
            material: dc.particles.material.clone(),
            velocity: None,
            omega: None,
            prescribed_velocity: None,
        }];
        probe.run.duration = Some(1.0);
        if let Err(err) = validate_plain(&probe) {
            e.0.extend(err.into_list());
        }
        probe.contact = dc.fill.contact.clone();
        if let Err(err) = validate_plain(&probe) {
            e.0.extend(err.into_list().into_iter().filter_map(|err| match err {
                TampError::Input { path, rule } if path.starts_with("contact") => Some(
                    TampError::input(format!("die_compaction.fill.{path}"), rule),
                ),
                _ => None,
            }));
        }
    }
    e.finish()
}

fn validate_plain(scene: &Scene) -> Result<()> {
    let mut e = Errors(Vec::new());
    if scene.materials.is_empty() {
        e.push("materials", "must list at least one material");
    }
    let mut names = HashSet::new();
    for (k, m) in scene.materials.iter().enumerate() {
        if !names.insert(m.name.as_str()) {
            e.push(
                format!("materials[{k}].name"),
                format!("must be unique, '{}' is repeated", m.name),
            );
        }
        if m.rigid {
            // Refused rather than ignored: a value given but never used would mislead.
            for (field, given) in [
                ("density", m.density.is_some()),
                ("youngs_modulus", m.youngs_modulus.is_some()),
                ("poisson_ratio", m.poisson_ratio.is_some()),
                ("hollomon", m.hollomon.is_some()),
            ] {
                if given {
                    e.push(
                        format!("materials[{k}].{field}"),
                        "must be absent for a rigid material: it does not deform or move, so the value would never be used",
                    );
                }
            }
        } else {
            match m.density {
                Some(d) => e.positive(format!("materials[{k}].density"), d),
                None => e.push(
                    format!("materials[{k}].density"),
                    "is required (kg/m³) unless the material is \"rigid\": true",
                ),
            }
        }
        if let Some(y) = m.youngs_modulus {
            e.positive(format!("materials[{k}].youngs_modulus"), y);
        }
        if let Some(nu) = m.poisson_ratio
            && !(nu > -1.0 && nu < 0.5)
        {
            e.push(
                format!("materials[{k}].poisson_ratio"),
                format!("must be > -1 and < 0.5, got {nu}"),
            );
        }
    }
    let known = |name: &str| names.contains(name);
    let rigid: HashSet<&str> = scene
        .materials
        .iter()
        .filter(|m| m.rigid)
        .map(|m| m.name.as_str())
        .collect();
    // What a particle's material must be: known, and not rigid (a rigid body has no
    // mass to integrate).
    let particle_material = |e: &mut Errors, path: String, name: &str| {
        if !known(name) {
            e.push(path, format!("unknown material '{name}'"));
        } else if rigid.contains(name) {
            e.push(
                path,
                format!("'{name}' is rigid: only walls may be made of a rigid material"),
            );
        }
    };

    let contact = &scene.contact;
    let roles = Roles {
        normal: &contact.normal,
        damping: contact.damping.as_ref(),
    };
    let normal = &contact.normal;
    contact.normal.check("contact.normal", &mut e);
    require(
        &mut e,
        scene,
        normal.needs(),
        &format!("contact.normal.law '{}'", normal.name()),
    );
    if let Some(damping) = &contact.damping {
        damping.check("contact.damping", roles, &mut e);
        if normal.has_own_dissipation() {
            e.push(
                "contact.damping",
                format!(
                    "must be absent with contact.normal.law '{}', which dissipates by itself",
                    normal.name()
                ),
            );
        }
    }
    if let Some(t) = &contact.tangential {
        t.law.check("contact.tangential", roles, &mut e);
        require(
            &mut e,
            scene,
            t.law.needs(),
            &format!("contact.tangential.law '{}'", t.law.name()),
        );
        e.non_negative("contact.tangential.friction", t.friction);
        // A pair is unordered: its key is its two names sorted.
        let mut listed = HashSet::new();
        for (k, fp) in t.friction_pairs.iter().enumerate() {
            let mut key = fp.materials.clone();
            key.sort();
            if !listed.insert(key.clone()) {
                e.push(
                    format!("contact.tangential.friction_pairs[{k}].materials"),
                    format!("the pair {key:?} is listed twice"),
                );
            }
            e.non_negative(
                format!("contact.tangential.friction_pairs[{k}].friction"),
                fp.friction,
            );
            for (s, name) in fp.materials.iter().enumerate() {
                if !known(name) {
                    e.push(
                        format!("contact.tangential.friction_pairs[{k}].materials[{s}]"),
                        format!("unknown material '{name}'"),
                    );
                }
            }
        }
    }
    if let Some(cohesion) = &contact.cohesion {
        cohesion.check("contact.cohesion", &mut e);
    }

    for (k, m) in scene.materials.iter().enumerate() {
        let Some(h) = &m.hollomon else { continue };
        let path = format!("materials[{k}].hollomon");
        if !(h.exponent >= 0.0 && h.exponent < 1.0) {
            e.push(
                format!("{path}.exponent"),
                format!("must be in [0, 1), got {}", h.exponent),
            );
        }
        match (h.strength, h.yield_stress) {
            (Some(s), None) => e.positive(format!("{path}.strength"), s),
            (None, Some(y)) => {
                e.positive(format!("{path}.yield_stress"), y);
                if m.youngs_modulus.is_none() {
                    e.push(
                        format!("materials[{k}].youngs_modulus"),
                        "is required by hollomon.yield_stress (the curve passes through (σ_Y/E, σ_Y))",
                    );
                }
            }
            _ => e.push(
                path,
                "give exactly one of 'strength' (σ0, Pa) or 'yield_stress' (σ_Y, Pa)",
            ),
        }
    }
    for (k, p) in scene.particles.iter().enumerate() {
        e.finite3(format!("particles[{k}].position"), &p.position);
        e.positive(format!("particles[{k}].radius"), p.radius);
        particle_material(&mut e, format!("particles[{k}].material"), &p.material);
        if p.prescribed_velocity.is_some() && (p.velocity.is_some() || p.omega.is_some()) {
            e.push(
                format!("particles[{k}].prescribed_velocity"),
                "cannot be combined with velocity or omega: a prescribed particle moves at exactly this velocity and does not spin",
            );
        }
        if p.omega.is_some() && scene.rotation.is_none() {
            e.push(
                format!("particles[{k}].omega"),
                "needs \"rotation\" in the scene: without it spins never change",
            );
        }
        for (field, v) in [
            ("velocity", &p.velocity),
            ("omega", &p.omega),
            ("prescribed_velocity", &p.prescribed_velocity),
        ] {
            if let Some(v) = v {
                e.finite3(format!("particles[{k}].{field}"), v);
            }
        }
    }
    for (k, ins) in scene.insert.iter().enumerate() {
        let path = format!("insert[{k}]");
        particle_material(&mut e, format!("{path}.material"), &ins.material);
        let r_max = match ins.radius {
            RadiusSpec::Fixed(r) => {
                e.positive(format!("{path}.radius"), r);
                r
            }
            RadiusSpec::Uniform(UniformRadius { min, max }) => {
                e.positive(format!("{path}.radius.min"), min);
                if !(max >= min && max.is_finite()) {
                    e.push(
                        format!("{path}.radius.max"),
                        format!("must be >= radius.min ({min:e}), got {max:e}"),
                    );
                }
                max
            }
            RadiusSpec::Law(_) => radius_law_max(&mut e, &format!("{path}.radius"), &ins.radius),
        };
        if let Some(sch) = &ins.schedule {
            e.non_negative(format!("{path}.schedule.start"), sch.start);
            e.positive(format!("{path}.schedule.every"), sch.every);
            if sch.per_event == 0 {
                e.push(format!("{path}.schedule.per_event"), "must be >= 1, got 0");
            }
            if scene.growth.is_some() {
                e.push(
                    format!("{path}.schedule"),
                    "cannot be combined with growth: poured particles would arrive during or after the growth stage at full size",
                );
            }
        }
        e.finite3(format!("{path}.region.lower"), &ins.region.lower);
        e.finite3(format!("{path}.region.upper"), &ins.region.upper);
        for a in 0..3 {
            if ins.region.upper[a] - ins.region.lower[a] < 2.0 * r_max {
                e.push(
                    format!("{path}.region.upper[{a}]"),
                    format!("the region must be at least one particle diameter ({:e} m) wide along every axis", 2.0 * r_max),
                );
                break;
            }
        }
        e.non_negative(format!("{path}.speed"), ins.speed);
        e.non_negative(format!("{path}.spin"), ins.spin);
        if ins.spin > 0.0 && scene.rotation.is_none() {
            e.push(
                format!("{path}.spin"),
                "needs \"rotation\" in the scene: without it spins never change",
            );
        }
        if ins.max_attempts == 0 {
            e.push(format!("{path}.max_attempts"), "must be >= 1, got 0");
        }
    }
    for (k, dep) in scene.deposit.iter().enumerate() {
        let path = format!("deposit[{k}]");
        particle_material(&mut e, format!("{path}.material"), &dep.material);
        radius_law_max(&mut e, &format!("{path}.radius"), &dep.radius);
        let [lo, hi] = dep.footprint;
        if !(lo.iter().chain(&hi).all(|c| c.is_finite()) && hi[0] > lo[0] && hi[1] > lo[1]) {
            e.push(
                format!("{path}.footprint"),
                format!(
                    "must be [[x_lo, y_lo], [x_hi, y_hi]] with hi > lo, finite, got {:?}",
                    dep.footprint
                ),
            );
        }
        if !dep.floor.is_finite() {
            e.push(format!("{path}.floor"), "must be finite");
        }
    }
    if scene.particles.is_empty()
        && scene.insert.iter().all(|i| i.count == 0)
        && scene.deposit.iter().all(|d| d.count == 0)
    {
        e.push(
            "particles",
            "the scene must contain at least one particle (particles or insert)",
        );
    }
    super::walls::validate(&scene.walls, &known, &mut e);
    if let Some(g) = &scene.gravity {
        e.finite3("gravity", g);
    }
    if let Some(per) = &scene.periodic {
        for (a, axis) in per.axes().iter().enumerate() {
            let name = ["x", "y", "z"][a];
            if let Some([lo, hi]) = axis
                && !(lo.is_finite() && hi.is_finite() && hi > lo)
            {
                e.push(
                    format!("periodic.{name}"),
                    format!("must be [lo, hi] with hi > lo, finite, got [{lo:e}, {hi:e}]"),
                );
            }
        }
        if per.axes().iter().all(Option::is_none) {
            e.push("periodic", "must name at least one axis (x, y or z)");
        }
    }
    if let Some(g) = &scene.growth {
        e.positive("growth.duration", g.duration);
        if !(g.initial_fraction >= 0.0 && g.initial_fraction < 1.0) {
            e.push(
                "growth.initial_fraction",
                format!("must be in [0, 1), got {}", g.initial_fraction),
            );
        }
    }
    if let Some(r) = &scene.rotation {
        e.positive("rotation.inertia_scale", r.inertia_scale);
    }
    let ts = &scene.time_step;
    if let Some(alpha) = ts.alpha
        && !(alpha > 0.0 && alpha <= 1.0)
    {
        e.push("time_step.alpha", format!("must be in (0, 1], got {alpha}"));
    }
    if let Some(a) = ts.accuracy {
        if !(a > 0.0 && a <= 0.1) {
            e.push(
                "time_step.accuracy",
                format!("must be in (0, 0.1] (a relative error; the error model is calibrated from 1e-1 down), got {a}"),
            );
        }
        for (field, given) in [("alpha", ts.alpha.is_some()), ("fixed", ts.fixed.is_some())] {
            if given {
                e.push(
                    "time_step.accuracy",
                    format!("cannot be combined with time_step.{field}: the accuracy chooses the step; give one of them"),
                );
            }
        }
    }
    if let Some(v) = ts.characteristic_velocity {
        e.positive("time_step.characteristic_velocity", v);
    }
    if let Some(dt) = ts.fixed {
        e.positive("time_step.fixed", dt);
    }
    match (scene.run.duration, scene.run.steps) {
        (Some(d), None) => e.positive("run.duration", d),
        (None, Some(_)) => {}
        _ => e.push("run", "give exactly one of 'duration' (s) or 'steps'"),
    }
    if let Some(u) = &scene.run.until {
        e.positive(
            "run.until.kinetic_energy_per_particle",
            u.kinetic_energy_per_particle,
        );
        if let Some(v) = u.max_speed {
            e.positive("run.until.max_speed", v);
        }
        e.non_negative("run.until.held_for", u.held_for);
    }
    e.positive("broad_phase.skin_fraction", scene.broad_phase.skin_fraction);
    e.positive(
        "stability.max_overlap_fraction",
        scene.stability.max_overlap_fraction,
    );
    e.positive(
        "stability.max_energy_growth",
        scene.stability.max_energy_growth,
    );
    e.positive(
        "stability.max_step_fraction",
        scene.stability.max_step_fraction,
    );
    e.non_negative(
        "stability.initial_overlap_tolerance",
        scene.stability.initial_overlap_tolerance,
    );
    if scene.stability.check_every == 0 {
        e.push(
            "stability.check_every",
            "must be >= 1, got 0 (it would switch the energy check off)",
        );
    }
    for (k, c) in scene.output.series.iter().enumerate() {
        if !SERIES_COLUMNS.contains(&c.as_str()) {
            e.push(
                format!("output.series[{k}]"),
                format!("unknown column '{c}', expected one of {SERIES_COLUMNS:?}"),
            );
        }
    }
    e.finish()
}

/// Check a radius given as a distribution; returns its largest radius (0 when invalid).
fn radius_law_max(e: &mut Errors, path: &str, radius: &RadiusSpec) -> f64 {
    let d = radius.distribution();
    if let Err(rule) = d.validate() {
        e.push(path, rule);
        return 0.0;
    }
    let r_max = d.max_radius();
    if !r_max.is_finite() {
        e.push(
            format!("{path}.max"),
            "is required: placing particles needs a largest radius",
        );
        return 0.0;
    }
    r_max
}
