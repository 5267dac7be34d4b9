//! A free cloud of colliding spheres with friction, damping and rotation, no walls
//! and no gravity. Contact forces come in equal and opposite pairs, and the contact
//! point sits mid-overlap so the two lever arms add up to the centre distance: linear
//! and angular (orbital + spin) momentum are conserved to round-off. Measured from the
//! first and last recorded frames; masses and moments of inertia are the scene's
//! inputs (densities, radii, `rotation.inertia_scale`).

use crate::error::{Result, TampError};
use crate::particles::Vec3;
use crate::scene;
use crate::verify::recording::Frame;
use crate::verify::{CaseContext, Measured};

pub fn run(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let scene = ctx.scene()?;
    let built = scene::build(&scene)?;
    let p = &built.sim.state().particles;
    let (mass, inertia) = (p.mass.clone(), p.inertia.clone());
    let (first, last) = ctx.first_and_last("cloud", &scene)?;
    let (first, last) = (&first, &last);
    let linear = |f: &Frame| -> Vec3 {
        f.bodies
            .iter()
            .zip(&mass)
            .map(|(b, m)| b.velocity * *m)
            .sum()
    };
    let angular = |f: &Frame| -> Vec3 {
        f.bodies
            .iter()
            .enumerate()
            .map(|(i, b)| b.position.cross(&b.velocity) * mass[i] + b.omega * inertia[i])
            .sum()
    };
    // Scales: the sums of magnitudes, so the errors are relative to the momentum in play.
    let b0 = &first.bodies;
    let p_scale: f64 = (0..b0.len()).map(|i| mass[i] * b0[i].velocity.norm()).sum();
    let l_scale: f64 = (0..b0.len())
        .map(|i| {
            mass[i] * b0[i].position.cross(&b0[i].velocity).norm() + inertia[i] * b0[i].omega.norm()
        })
        .sum();
    // Only a frictional contact changes a spin: without one the case would test nothing.
    let spun = first
        .bodies
        .iter()
        .zip(&last.bodies)
        .any(|(a, b)| a.omega != b.omega);
    if !spun {
        return Err(TampError::Other(
            "no spin changed between the first and the last frame: no frictional contact occurred, and the case would test nothing".into(),
        ));
    }
    Ok(vec![
        Measured::new(
            "linear_momentum_error",
            (linear(last) - linear(first)).norm() / p_scale,
            0.0,
        ),
        Measured::new(
            "angular_momentum_error",
            (angular(last) - angular(first)).norm() / l_scale,
            0.0,
        ),
    ])
}
