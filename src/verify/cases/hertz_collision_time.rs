//! Two elastic Hertz NiAl spheres (Rojek 2016 Table 2, R = 10 µm) meet head-on at
//! 0.2 m/s: contact duration (Zhong 2009 eq 13 with the exact constant), maximum
//! overlap (energy balance) and restitution 1.

use crate::collision::binary_collision;
use crate::contact::normal::hertz::{hertz_contact_duration, hertz_max_overlap};
use crate::error::Result;
use crate::material::{effective_mass, effective_radius};
use crate::scene;
use crate::verify::{CaseContext, Measured};

pub fn run(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let mut sim = scene::build(&ctx.scene()?)?.sim;
    let p = &sim.state.particles;
    let m_eff = effective_mass(p.mass[0], p.mass[1]);
    let r_eff = effective_radius(p.radius[0], p.radius[1]);
    let e_eff = sim
        .model
        .pair_table
        .get(p.material[0], p.material[1])
        .effective_modulus
        .expect("hertz scene has E and nu");
    let v = -(p.velocity[0] - p.velocity[1]).dot(&(p.position[0] - p.position[1]).normalize());
    let c = binary_collision(&mut sim, 0, 1, 10_000_000)?;
    Ok(vec![
        Measured::new(
            "contact_duration",
            c.duration,
            hertz_contact_duration(m_eff, v, r_eff, e_eff),
        ),
        Measured::new(
            "max_overlap",
            c.max_overlap,
            hertz_max_overlap(m_eff, v, r_eff, e_eff),
        ),
        Measured::new("restitution", c.restitution, 1.0),
    ])
}
