//! Two equal spheres, linear spring–dashpot (Zhong 2009 model I, Table 1 values),
//! head-on: restitution, contact duration and maximum overlap against the damped
//! oscillator's closed forms (Zhong eqs 7–9), once with the scene's γ_n (e ≈ 0.5)
//! and once with γ_n = 0, measured from the recorded trajectories.

use super::two_body::{Pair, collision_quantities};
use crate::contact::damping::{Constant, Damping};
use crate::contact::normal::linear::LinearCollision;
use crate::contact::normal::{Linear, NormalLaw};
use crate::error::Result;
use crate::verify::recording::RecordSpec;
use crate::verify::{CaseContext, Measured, measure};

pub fn run(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let base = ctx.scene()?;
    let NormalLaw::Linear(Linear { stiffness }) = base.contact.normal else {
        return Err(crate::TampError::Other(
            "linear_restitution needs the linear law".into(),
        ));
    };
    let gamma = match base.contact.dashpot() {
        Some(Damping::Constant(Constant { gamma_n })) => gamma_n,
        _ => {
            return Err(crate::TampError::Other(
                "linear_restitution needs constant damping".into(),
            ));
        }
    };
    let mut out = Vec::new();
    for (suffix, gamma_n) in [("", gamma), ("_undamped", 0.0)] {
        let mut s = base.clone();
        s.contact.damping =
            (gamma_n > 0.0).then_some(Damping::Constant(Constant { gamma_n }).into());
        let pair = Pair::of(&s)?;
        let exact = LinearCollision::new(stiffness, pair.m_eff, gamma_n);
        let label = format!("collision{suffix}");
        let rec = ctx.record(&label, &s, RecordSpec::EVERY_STEP)?;
        let c = measure::two_body(&rec, 0, 1)?;
        out.extend(collision_quantities(
            suffix,
            &c,
            exact.restitution(),
            exact.contact_duration(),
            exact.max_overlap(pair.approach),
        ));
    }
    Ok(out)
}
