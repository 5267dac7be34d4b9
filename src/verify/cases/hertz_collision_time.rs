//! Two elastic Hertz NiAl spheres (Rojek 2016 Table 2, R = 10 µm) meet head-on at
//! 0.2 m/s: contact duration (Zhong 2009 eq 13 with the exact constant), maximum
//! overlap (energy balance) and restitution 1, measured from the recorded trajectory.

use crate::contact::normal::hertz::{hertz_contact_duration, hertz_max_overlap};
use crate::error::Result;
use crate::verify::recording::RecordSpec;
use crate::verify::{CaseContext, Measured, measure};

pub fn run(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let scene = ctx.scene()?;
    let pair = super::two_body::Pair::of(&scene)?;
    let e_eff = pair.effective_modulus()?;
    let rec = ctx.record("collision", &scene, RecordSpec::EVERY_STEP)?;
    let c = measure::two_body(&rec, 0, 1)?;
    Ok(vec![
        Measured::new(
            "contact_duration",
            c.duration,
            hertz_contact_duration(pair.m_eff, pair.approach, pair.r_eff, e_eff),
        ),
        Measured::new(
            "max_overlap",
            c.max_overlap,
            hertz_max_overlap(pair.m_eff, pair.approach, pair.r_eff, e_eff),
        ),
        Measured::new("restitution", c.restitution, 1.0),
    ])
}
