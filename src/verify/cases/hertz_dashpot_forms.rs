//! Two steel spheres meet head-on under Hertz beside each of the dashpots LAMMPS offers
//! besides `coeff_restitution` (`hertz_damped_collision` runs that one), as LAMMPS
//! 22 Jul 2025 evaluates them (contact/damping/tsuji.rs, viscous.rs):
//!
//!   `tsuji`          η = d(e) √(m* F_n/δ) = d(e) √(m* K) δ^{1/4}   (Marshall's fit d(e))
//!   `mass_velocity`  η = η_n0 m*
//!   `viscoelastic`   η = η_n0 m* √(R* δ)
//!
//! None of the three impacts has a closed form, so the reference is the equation of
//! motion m* δ'' = −K δ^{3/2} − η(δ) δ' made dimensionless (δ_s = (m* v²/K)^{2/5}) and
//! solved by classical Runge–Kutta (`accuracy::damped_hertz`, converged far below these
//! tolerances): restitution, contact duration and largest overlap, for each dashpot of
//! the case file's parameters. Tsuji's fit is not the damping that rebounds at e (at
//! e = 0.5 it rebounds at 0.616); the reference takes the fit's coefficient as LAMMPS
//! does, so it checks the dashpot, not the fit.

use super::two_body::{Pair, collision_quantities};
use crate::accuracy::damped_hertz::{Dashpot, critical_fraction_c, unit_impact};
use crate::contact::damping::Damping;
use crate::contact::normal::NormalLaw;
use crate::error::{Result, TampError};
use crate::verify::recording::RecordSpec;
use crate::verify::{CaseContext, Measured, measure};
use serde::Deserialize;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Parameters {
    dashpots: Vec<Labelled>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Labelled {
    /// The run's name in the quantities (`restitution_<label>`).
    label: String,
    /// Replaces the scene's `contact.damping`.
    damping: Damping,
}

pub fn run(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let base = ctx.scene()?;
    if !matches!(base.contact.normal, NormalLaw::Hertz(_)) {
        return Err(TampError::Other("the scene must use hertz".into()));
    }
    let mut out = Vec::new();
    for run in ctx.parameters::<Parameters>()?.dashpots {
        let mut s = base.clone();
        s.contact.damping = Some(run.damping.into());
        let pair = Pair::of(&s)?;
        let (v, delta_s) = (pair.approach, pair.hertz_overlap_scale()?);
        let (dashpot, c) = match run.damping {
            Damping::Tsuji(t) => (
                Dashpot::CriticalFraction,
                critical_fraction_c(t.with(&s.contact.normal).map_err(TampError::Other)?.xi),
            ),
            Damping::MassVelocity(m) => (Dashpot::Constant, m.eta_n0 * delta_s / v),
            Damping::Viscoelastic(d) => (
                Dashpot::Viscoelastic,
                d.eta_n0 * (pair.r_eff * delta_s).sqrt() * delta_s / v,
            ),
            other => {
                return Err(TampError::Other(format!(
                    "{}: the case runs the dashpots tsuji, mass_velocity and viscoelastic, not {}",
                    run.label,
                    other.name()
                )));
            }
        };
        let unit = unit_impact(dashpot, c).ok_or_else(|| {
            TampError::Other(format!("{}: the reference impact does not end", run.label))
        })?;
        let rec = ctx.record(&run.label, &s, RecordSpec::EVERY_STEP)?;
        let collision = measure::two_body(&rec, 0, 1)?;
        out.extend(collision_quantities(
            &format!("_{}", run.label),
            &collision,
            unit.restitution,
            unit.duration * delta_s / v,
            unit.max_overlap * delta_s,
        ));
    }
    Ok(out)
}
