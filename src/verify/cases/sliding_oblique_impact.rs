//! A steel sphere hits a plane wall obliquely, fast enough along the wall that it
//! slides throughout the contact (Zhong 2009 models VI–X, Rojek eqs 11–14 and 21).
//! While sliding, the friction impulse is μ times the normal impulse, so rigid-body
//! impulse theory (e.g. Brach 1991; Maw, Barber & Fawcett 1976) gives
//!   Δv_t = μ (1 + e) v_n,   ω R = (5/2) Δv_t  (solid sphere, I = 2/5 m R²)
//! with e the normal restitution measured in the same run. Gross sliding holds
//! throughout when v_t > (1 + 5/2) μ (1 + e) v_n (the slip speed v_t − ωR stays
//! positive); the scene uses v_t = 5 v_n, μ = 0.3. The velocities and the spin are
//! read from the first and last recorded frames, once the sphere has left the wall
//! (no force acts on it after that, so the last frame holds its rebound exactly).

use crate::contact::tangential::{
    Coulomb, CundallStrack, HaffWerner, MindlinDeresiewicz, MindlinNoSlip, TangentialLaw,
    storakers, walton_braun,
};
use crate::error::{Result, TampError};
use crate::particles::Vec3;
use crate::scene::{schema::FrictionSpec, walls::ShapeSpec};
use crate::verify::{CaseContext, Measured};

/// Each law with its own parameter where it has one (stiffness about half the
/// normal Hertz stiffness at peak; γ_s large enough to stay on the Coulomb cap).
const LAWS: [TangentialLaw; 7] = [
    TangentialLaw::MindlinDeresiewicz(MindlinDeresiewicz {}),
    TangentialLaw::Coulomb(Coulomb {}),
    TangentialLaw::HaffWerner(HaffWerner { damping: 100.0 }),
    TangentialLaw::CundallStrack(CundallStrack { stiffness: 2e6 }),
    TangentialLaw::WaltonBraun(walton_braun::WaltonBraun { stiffness: 2e6 }),
    TangentialLaw::MindlinNoSlip(MindlinNoSlip {}),
    TangentialLaw::Storakers(storakers::Storakers { beta: 1.0 }),
];

pub fn run(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let base = ctx.scene()?;
    let friction = base
        .contact
        .tangential
        .as_ref()
        .map(|t| t.friction)
        .ok_or_else(|| TampError::Other("the scene must name a tangential law".into()))?;
    let Some(ShapeSpec::Plane { point, normal }) = base.walls.first().map(|w| &w.shape) else {
        return Err(TampError::Other(
            "the scene's first wall must be a plane".into(),
        ));
    };
    let (point, normal) = (Vec3::from(*point), Vec3::from(*normal).normalize());
    let mut out = Vec::new();
    for law in LAWS {
        let mut s = base.clone();
        s.contact.tangential = Some(FrictionSpec {
            law,
            friction,
            friction_pairs: Vec::new(),
        });
        let (first, last) = ctx.first_and_last(law.name(), &s)?;
        let (b0, b1) = (&first.bodies[0], &last.bodies[0]);
        let (v0, v1, radius) = (b0.velocity, b1.velocity, b0.radius);
        let gap = (b1.position - point).dot(&normal) - b1.radius;
        if gap <= 0.0 || v1.dot(&normal) <= 0.0 {
            return Err(TampError::Other(format!(
                "{}: the sphere did not leave the wall by step {}",
                law.name(),
                last.step
            )));
        }
        let restitution = v1.z / -v0.z;
        let impulse_dv = friction * (1.0 + restitution) * -v0.z;
        out.push(Measured::new(
            &format!("tangential_velocity_error_{}", law.name()),
            v0.x - v1.x,
            impulse_dv,
        ));
        out.push(Measured::new(
            &format!("spin_error_{}", law.name()),
            b1.omega.y * radius,
            2.5 * impulse_dv,
        ));
    }
    Ok(out)
}
