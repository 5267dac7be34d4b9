//! Two steel spheres meet head-on under Hertz with the dashpot ξ · 2√(m* k_n) (Tsuji et
//! al. 1992's form), ξ set from a restitution e by LIGGGHTS's relation
//! ξ = −√(5/6) ln e/√(ln²e + π²) (`liggghts_restitution`; LIGGGHTS `model hertz`,
//! LAMMPS `damping coeff_restitution`). The damped Hertz impact has no closed form, so
//! the reference is its equation of motion m* δ'' = −K δ^{3/2} − η(δ) δ', made
//! dimensionless with δ_s = (m* v²/K)^{2/5} and solved by classical Runge–Kutta
//! (`accuracy::damped_hertz`, converged far below these tolerances): restitution,
//! contact duration and largest overlap, for each e of the case file's parameters.
//! Measured from the recorded trajectory, so every engine with this dashpot is held
//! to the same equation.

use super::two_body::{Pair, collision_quantities, each_restitution};
use crate::accuracy::damped_hertz::{Dashpot, critical_fraction_c, unit_impact};
use crate::contact::damping::liggghts::LiggghtsModel;
use crate::contact::normal::NormalLaw;
use crate::error::{Result, TampError};
use crate::verify::recording::RecordSpec;
use crate::verify::{CaseContext, Measured, measure};

pub fn run(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let base = ctx.scene()?;
    if !matches!(base.contact.normal, NormalLaw::Hertz(_)) {
        return Err(TampError::Other("the scene must use hertz".into()));
    }
    let mut out = Vec::new();
    for (e, s) in each_restitution(ctx, &base)? {
        let pair = Pair::of(&s)?;
        let (v, delta_s) = (pair.approach, pair.hertz_overlap_scale()?);
        let xi = LiggghtsModel::Hertz.critical_fraction(e);
        let unit =
            unit_impact(Dashpot::CriticalFraction, critical_fraction_c(xi)).ok_or_else(|| {
                TampError::Other(format!("e = {e}: the reference impact does not end"))
            })?;
        let rec = ctx.record(&format!("collision_e{e}"), &s, RecordSpec::EVERY_STEP)?;
        let c = measure::two_body(&rec, 0, 1)?;
        out.extend(collision_quantities(
            &format!("_e{e}"),
            &c,
            unit.restitution,
            unit.duration * delta_s / v,
            unit.max_overlap * delta_s,
        ));
    }
    Ok(out)
}
