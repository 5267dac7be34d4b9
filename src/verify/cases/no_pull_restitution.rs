//! Head-on impacts with the normal force kept from pulling (`contact.damping.limit`;
//! LAMMPS's `limit_damping`, LIGGGHTS's `limitForce on`): the contact force ends where
//! spring plus dashpot reach zero, before the overlap does, and the spheres coast apart
//! through the rest of it. Measured from the recorded trajectories (restitution at
//! separation, duration from the overlap's zero crossings):
//! - `linear_no_pull_restitution`: the linear spring with a constant dashpot, one
//!   impact per γ_n of the case file, against the clamped oscillator's closed forms
//!   (`LinearCollision::no_pull_restitution`, Schwager & Pöschel 2007), on both sides of
//!   β = ω₀/√2 where the force's zero moves from the second quarter of the damped
//!   period into the first;
//! - `hertz_no_pull_restitution`: Hertz with the dashpot ξ · 2√(m* k_n), ξ from each
//!   restitution e of the case file by LIGGGHTS's relation, against the clamped
//!   equation of motion solved by Runge–Kutta (`damped_hertz::unit_impact_no_pull`);
//!   the clamp makes the rebound faster than e.

use super::two_body::{Pair, each_hertz_impact};
use crate::accuracy::damped_hertz::unit_impact_no_pull;
use crate::collision::Collision;
use crate::contact::damping::{Constant, Damping};
use crate::contact::normal::linear::LinearCollision;
use crate::contact::normal::{Linear, NormalLaw};
use crate::error::{Result, TampError};
use crate::scene::Scene;
use crate::scene::contact::DampingSpec;
use crate::verify::recording::RecordSpec;
use crate::verify::{CaseContext, Measured, measure};

/// The case file's `parameters` of the linear case: one impact per γ_n, N s/m.
#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct Gammas {
    gammas: Vec<f64>,
}

/// The scene's dashpot clamped at zero, as the case requires.
fn clamped(scene: &Scene) -> Result<()> {
    match scene.contact.damping {
        Some(DampingSpec { limit: true, .. }) => Ok(()),
        _ => Err(TampError::Other(
            "the scene must clamp its dashpot (contact.damping.limit)".into(),
        )),
    }
}

/// The two quantities of one impact, named with `suffix`.
fn quantities(suffix: &str, c: &Collision, e: f64, duration: f64) -> [Measured; 2] {
    [
        Measured::new(&format!("restitution{suffix}"), c.restitution, e),
        Measured::new(&format!("contact_duration{suffix}"), c.duration, duration),
    ]
}

pub fn linear(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let base = ctx.scene()?;
    clamped(&base)?;
    let NormalLaw::Linear(Linear { stiffness }) = base.contact.normal else {
        return Err(TampError::Other("the scene must use the linear law".into()));
    };
    let mut out = Vec::new();
    for gamma_n in ctx.parameters::<Gammas>()?.gammas {
        let mut s = base.clone();
        s.contact.damping = Some(DampingSpec {
            kind: Damping::Constant(Constant { gamma_n }),
            limit: true,
        });
        let pair = Pair::of(&s)?;
        let exact = LinearCollision::new(stiffness, pair.m_eff, gamma_n);
        if exact.beta >= exact.omega0 {
            return Err(TampError::Other(format!(
                "gamma_n = {gamma_n}: overdamped (beta >= omega0), outside the closed form"
            )));
        }
        let rec = ctx.record(&format!("gamma{gamma_n}"), &s, RecordSpec::EVERY_STEP)?;
        let c = measure::two_body(&rec, 0, 1)?;
        out.extend(quantities(
            &format!("_g{gamma_n}"),
            &c,
            exact.no_pull_restitution(),
            exact.no_pull_contact_duration(),
        ));
    }
    Ok(out)
}

pub fn hertz(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let base = ctx.scene()?;
    clamped(&base)?;
    Ok(each_hertz_impact(ctx, &base, unit_impact_no_pull)?
        .iter()
        .flat_map(|i| {
            quantities(
                &format!("_e{}", i.e),
                &i.measured,
                i.restitution,
                i.duration,
            )
        })
        .collect())
}
