//! Head-on collisions of two equal spheres for the normal laws whose restitution
//! has a closed form independent of speed: Walton–Braun (Zhong 2009 eq 16,
//! e = √(k₁/k₂)) and the hysteretic law (Zhong eqs 17–18, e = √((1 − γ)/(1 + γ)),
//! derived in docs/models/hysteretic.md). One function per case, sharing the
//! measurement of the recorded collision.

use crate::contact::normal::{Hysteretic, NormalLaw, WaltonBraun};
use crate::error::{Result, TampError};
use crate::verify::recording::RecordSpec;
use crate::verify::{CaseContext, Measured, measure};

pub fn walton_braun(ctx: &CaseContext) -> Result<Vec<Measured>> {
    restitution_against(ctx, "walton_braun", |law| match *law {
        NormalLaw::WaltonBraun(WaltonBraun {
            loading_stiffness,
            unloading_stiffness,
        }) => Some((loading_stiffness / unloading_stiffness).sqrt()),
        _ => None,
    })
}

pub fn hysteretic(ctx: &CaseContext) -> Result<Vec<Measured>> {
    restitution_against(ctx, "hysteretic", |law| match *law {
        NormalLaw::Hysteretic(Hysteretic { hysteresis, .. }) => {
            Some(((1.0 - hysteresis) / (1.0 + hysteresis)).sqrt())
        }
        _ => None,
    })
}

/// The recorded restitution against the law's closed form (`None`: the scene uses
/// another law than the case is about).
fn restitution_against(
    ctx: &CaseContext,
    law: &str,
    closed_form: fn(&NormalLaw) -> Option<f64>,
) -> Result<Vec<Measured>> {
    let scene = ctx.scene()?;
    let expected = closed_form(&scene.contact.normal)
        .ok_or_else(|| TampError::Other(format!("the scene must use {law}")))?;
    let rec = ctx.record("collision", &scene, RecordSpec::EVERY_STEP)?;
    let c = measure::two_body(&rec, 0, 1)?;
    Ok(vec![Measured::new("restitution", c.restitution, expected)])
}
