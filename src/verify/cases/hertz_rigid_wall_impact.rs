//! An elastic Hertz NiAl sphere (Rojek 2016 Table 2, R = 10 µm) hits a plane made of
//! a `"rigid": true` material head-on at 0.1 m/s. Against a rigid body the wall's
//! compliance term vanishes, so E* = E/(1 − ν²) of the sphere alone, R* = R and
//! m* = m: contact duration (Zhong 2009 eq 13 with the exact constant), maximum
//! overlap (energy balance) and restitution 1. The references take E and ν from the
//! scene's particle material, not from tamp's pair table, so a wrong mixing rule
//! (a finite wall term) fails the case.

use crate::contact::normal::hertz::{hertz_contact_duration, hertz_max_overlap};
use crate::error::{Result, TampError};
use crate::particles::Vec3;
use crate::scene;
use crate::verify::recording::RecordSpec;
use crate::verify::{CaseContext, Measured, measure};

pub fn run(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let s = ctx.scene()?;
    let particle = &s.materials[0];
    let (Some(e), Some(nu)) = (particle.youngs_modulus, particle.poisson_ratio) else {
        return Err(TampError::Other(
            "the scene's first material must be the sphere's, with E and ν".into(),
        ));
    };
    if !s.materials.get(1).is_some_and(|m| m.rigid) {
        return Err(TampError::Other(
            "the scene's second material must be the rigid wall's".into(),
        ));
    }
    let e_star = e / (1.0 - nu * nu);
    let sim = scene::build(&s)?.sim;
    let p = &sim.state().particles;
    let (m, r) = (p.mass[0], p.radius[0]);
    let mixed = sim
        .model()
        .pair_table
        .get(p.material[0], sim.model().walls[0].material)
        .effective_modulus
        .ok_or_else(|| TampError::Other("no E* for the sphere and the rigid wall".into()))?;
    let normal = Vec3::new(0.0, 0.0, 1.0);
    let v = -p.velocity[0].dot(&normal);
    let rec = ctx.record("impact", &s, RecordSpec::EVERY_STEP)?;
    let c = measure::plane(&rec, 0, Vec3::zeros(), normal)?;
    Ok(vec![
        Measured::new("effective_modulus", mixed, e_star),
        Measured::new(
            "contact_duration",
            c.duration,
            hertz_contact_duration(m, v, r, e_star),
        ),
        Measured::new(
            "max_overlap",
            c.max_overlap,
            hertz_max_overlap(m, v, r, e_star),
        ),
        Measured::new("restitution", c.restitution, 1.0),
    ])
}
