//! A free cloud of colliding spheres with friction, damping and rotation, no walls
//! and no gravity. Contact forces come in equal and opposite pairs, and the contact
//! point sits mid-overlap so the two lever arms add up to the centre distance: linear
//! and angular (orbital + spin) momentum are conserved to round-off.

use crate::error::{Result, TampError};
use crate::scene;
use crate::verify::{CaseContext, Measured};

pub fn run(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let scene = ctx.scene()?;
    let built = scene::build(&scene)?;
    let mut sim = built.sim;
    let p = &sim.state.particles;
    let p0 = p.linear_momentum();
    let l0 = p.angular_momentum();
    // Scales: the sums of magnitudes, so the errors are relative to the momentum in play.
    let p_scale: f64 = (0..p.len()).map(|i| p.mass[i] * p.velocity[i].norm()).sum();
    let l_scale: f64 = (0..p.len())
        .map(|i| {
            p.mass[i] * p.position[i].cross(&p.velocity[i]).norm()
                + p.inertia[i] * p.omega[i].norm()
        })
        .sum();
    let mut contacts = 0;
    let mut sliding_torque = 0.0f64;
    sim.run_with(built.steps, |s| {
        contacts += s.contact_count();
        sliding_torque = sliding_torque.max(
            s.state
                .particles
                .torque
                .iter()
                .map(|t| t.norm())
                .fold(0.0, f64::max),
        );
    })?;
    if contacts == 0 || sliding_torque == 0.0 {
        return Err(TampError::Other(
            "no frictional contact occurred: the case would test nothing".into(),
        ));
    }
    let p = &sim.state.particles;
    Ok(vec![
        Measured::new(
            "linear_momentum_error",
            (p.linear_momentum() - p0).norm() / p_scale,
            0.0,
        ),
        Measured::new(
            "angular_momentum_error",
            (p.angular_momentum() - l0).norm() / l_scale,
            0.0,
        ),
    ])
}
