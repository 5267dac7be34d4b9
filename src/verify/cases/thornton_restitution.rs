//! Head-on impacts of two equal spheres under Thornton's elastic–perfectly-plastic
//! law at v/v_y = 1.5, 3, 10 and 30, in the unloading form the scene names: the
//! restitution against Thornton's (1997) closed form for `thornton_1997`
//! (`thornton_restitution`), and against the closed form of LIGGGHTS's shifted-Hertz
//! unloading for `liggghts` (`thornton_liggghts_restitution`; both derived in
//! contact/normal/thornton.rs and docs/models/thornton.md). The scene gives the
//! spheres, the material, p_y and the form; the case sets the speeds from the yield
//! velocity v_y, and measures each impact from its recorded trajectory.

use super::two_body::{Pair, with_steps};
use crate::contact::normal::NormalLaw;
use crate::contact::normal::thornton::{
    Unloading, liggghts_restitution, thornton_1997_restitution, yield_velocity,
};
use crate::error::{Result, TampError};
use crate::verify::recording::RecordSpec;
use crate::verify::{CaseContext, Measured, measure};

/// A plastic impact lasts longer than an elastic one (the loading is softer past
/// yield); four Hertz durations leave room.
const CONTACTS: f64 = 4.0;

/// e(v/v_y) of one unloading form.
type ClosedForm = fn(f64) -> f64;

/// v/v_y of the impacts, and their labels in the quantity names.
const SPEEDS: [(f64, &str); 4] = [(1.5, "1_5"), (3.0, "3"), (10.0, "10"), (30.0, "30")];

pub fn run(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let base = ctx.scene()?;
    let NormalLaw::Thornton(law) = base.contact.normal else {
        return Err(TampError::Other("the scene must use thornton".into()));
    };
    let pair = Pair::of(&base)?;
    let v_y = yield_velocity(
        law.yield_pressure,
        pair.effective_modulus()?,
        pair.r_eff,
        pair.m_eff,
    );
    let (form, closed_form): (&str, ClosedForm) = match law.unloading {
        Unloading::Thornton1997 => ("thornton_1997", thornton_1997_restitution),
        Unloading::Liggghts => ("liggghts", liggghts_restitution),
    };
    let mut out = Vec::new();
    for (ratio, label) in SPEEDS {
        let mut s = base.clone();
        let v = ratio * v_y;
        s.particles[0].velocity = Some([0.5 * v, 0.0, 0.0]);
        s.particles[1].velocity = Some([-0.5 * v, 0.0, 0.0]);
        let s = with_steps(&s, Pair::of(&s)?.steps_through_collision(CONTACTS)?);
        let rec = ctx.record(&format!("V{label}"), &s, RecordSpec::EVERY_STEP)?;
        let c = measure::two_body(&rec, 0, 1)?;
        out.push(Measured::new(
            &format!("restitution_{form}_V{label}"),
            c.restitution,
            closed_form(ratio),
        ));
    }
    Ok(out)
}
