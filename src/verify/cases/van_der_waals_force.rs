//! Van der Waals attraction (Zhong 2009 eq 28): two steel spheres R = 1 µm held at
//! three surface gaps inside the cut-off, force against A R*/(6 h²); the broad-phase
//! skin is made negligible so the pair is found only through the cohesion reach.
//! Then two touching spheres, free, with cohesion, Hertz repulsion and damping and
//! no other load: they must stay in contact at every step and settle where the
//! Hertz force balances the saturated attraction,
//!   4/3 E* √R* δ_eq^{3/2} = A R*/(6 h_min²).
//! The held spheres' force is read from the first recorded frame (the forces of the
//! placed particles, before any step); the free pair from a frame at every step.

use super::two_body::{Pair, with_steps};
use crate::contact::normal::hertz::hertz_overlap_at_force;
use crate::contact::van_der_waals::{Cohesion, VanDerWaals};
use crate::error::{Result, TampError};
use crate::verify::recording::RecordSpec;
use crate::verify::{CaseContext, Measured, measure};

const GAPS: [(&str, f64); 3] = [("1nm", 1e-9), ("10nm", 1e-8), ("50nm", 5e-8)];

pub fn run(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let base = ctx.scene()?;
    let Some(Cohesion::VanDerWaals(VanDerWaals {
        hamaker,
        min_separation,
        ..
    })) = base.contact.cohesion
    else {
        return Err(TampError::Other("the scene must enable cohesion".into()));
    };
    let radius = base.particles[0].radius;
    let r_eff = 0.5 * radius;
    let mut out = Vec::new();
    for (name, gap) in GAPS {
        let mut s = base.clone();
        for (p, sign) in s.particles.iter_mut().zip([-1.0, 1.0]) {
            p.position = [sign * (radius + 0.5 * gap), 0.0, 0.0];
            p.velocity = None;
            p.prescribed_velocity = Some([0.0; 3]);
        }
        s.broad_phase.skin_fraction = 1e-6;
        let rec = ctx.record(name, &with_steps(&s, 1), RecordSpec::every(1, true))?;
        let held = rec.frames[0].bodies[0].force.unwrap_or_default();
        out.push(Measured::new(
            &format!("force_at_separation_{name}"),
            held.x,
            hamaker * r_eff / (6.0 * gap * gap),
        ));
    }

    let rec = ctx.record("free_pair", &base, RecordSpec::EVERY_STEP)?;
    let apart = rec.frames[1..]
        .iter()
        .filter(|f| measure::overlap(f, 0, 1) <= 0.0)
        .count();
    let last = rec
        .frames
        .last()
        .ok_or_else(|| TampError::Other("an empty recording".into()))?;
    let e_star = Pair::of(&base)?.effective_modulus()?;
    let pull = hamaker * r_eff / (6.0 * min_separation * min_separation);
    out.push(Measured::new("steps_apart", apart as f64, 0.0));
    out.push(Measured::new(
        "equilibrium_overlap",
        measure::overlap(last, 0, 1),
        hertz_overlap_at_force(pull, r_eff, e_star),
    ));
    Ok(out)
}
