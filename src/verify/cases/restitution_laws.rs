//! Head-on collisions of two equal spheres for the normal laws whose restitution
//! has a closed form independent of speed: Walton–Braun (Zhong 2009 eq 16,
//! e = √(k₁/k₂)) and the hysteretic law (Zhong eqs 17–18, e = √((1 − γ)/(1 + γ)),
//! derived in docs/models/hysteretic.md). One function per case, sharing the probe.

use super::probe::binary_collision;
use crate::error::{Result, TampError};
use crate::scene::{self, schema::NormalSpec};
use crate::verify::{CaseContext, Measured};

pub fn walton_braun(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let scene = ctx.scene()?;
    let NormalSpec::WaltonBraun {
        loading_stiffness,
        unloading_stiffness,
    } = scene.contact.normal
    else {
        return Err(TampError::Other("the scene must use walton_braun".into()));
    };
    let mut sim = scene::build(&scene)?.sim;
    let c = binary_collision(&mut sim, 0, 1, 10_000_000)?;
    Ok(vec![Measured::new(
        "restitution",
        c.restitution,
        (loading_stiffness / unloading_stiffness).sqrt(),
    )])
}

pub fn hysteretic(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let scene = ctx.scene()?;
    let NormalSpec::Hysteretic { hysteresis, .. } = scene.contact.normal else {
        return Err(TampError::Other("the scene must use hysteretic".into()));
    };
    let mut sim = scene::build(&scene)?.sim;
    let c = binary_collision(&mut sim, 0, 1, 10_000_000)?;
    Ok(vec![Measured::new(
        "restitution",
        c.restitution,
        ((1.0 - hysteresis) / (1.0 + hysteresis)).sqrt(),
    )])
}
