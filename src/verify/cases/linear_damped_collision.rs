//! Two steel spheres meet head-on under a linear spring k_n with the constant dashpot
//! γ_n = ξ · 2√(m* k_n), ξ set from a restitution e by LIGGGHTS's relation for `model
//! hooke`, ξ = |ln e|/√(ln²e + π²) (`liggghts_restitution`; LAMMPS `hooke` with
//! `damping coeff_restitution`). The scene's k_n is the one LIGGGHTS's `model hooke`
//! derives from E*, R*, m* and its characteristic velocity (`hooke_stiffness`), so the
//! scene is LIGGGHTS's hooke contact as well as tamp's linear one. A linear
//! spring–dashpot has closed forms (Zhong 2009 eqs 7–9): restitution, contact duration
//! and largest overlap, for each e of the case file's parameters, measured from the
//! recorded trajectory.

use super::two_body::{Pair, collision_quantities, each_restitution};
use crate::contact::normal::linear::LinearCollision;
use crate::contact::normal::{Linear, NormalLaw};
use crate::error::{Result, TampError};
use crate::verify::recording::RecordSpec;
use crate::verify::{CaseContext, Measured, measure};

pub fn run(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let base = ctx.scene()?;
    let NormalLaw::Linear(Linear { stiffness }) = base.contact.normal else {
        return Err(TampError::Other("the scene must use linear".into()));
    };
    let mut out = Vec::new();
    for (e, s) in each_restitution(ctx, &base)? {
        let pair = Pair::of(&s)?;
        let ln_e = e.ln();
        let xi = ln_e.abs() / (ln_e * ln_e + std::f64::consts::PI.powi(2)).sqrt();
        let gamma_n = xi * 2.0 * (pair.m_eff * stiffness).sqrt();
        let exact = LinearCollision::new(stiffness, pair.m_eff, gamma_n);
        let rec = ctx.record(&format!("collision_e{e}"), &s, RecordSpec::EVERY_STEP)?;
        let c = measure::two_body(&rec, 0, 1)?;
        out.extend(collision_quantities(
            &format!("_e{e}"),
            &c,
            exact.restitution(),
            exact.contact_duration(),
            exact.max_overlap(pair.approach),
        ));
    }
    Ok(out)
}
