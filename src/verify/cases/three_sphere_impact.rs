//! A chain of off-centre impacts between three spheres in 3D: a small spinning sphere
//! strikes a resting one, which strikes a third. Normal, damping, tangential and torque
//! terms all act, every contact opens and closes once, and nothing outside the three
//! spheres acts on them, so whatever the contact law:
//!
//! - linear momentum Σ m v is conserved (each contact force acts equally and oppositely);
//! - angular momentum about the origin Σ (m x × v + I ω) is conserved, when the two
//!   lever arms of each contact add up to the centre distance (tamp's and LIGGGHTS's
//!   contact point mid-overlap, LAMMPS's R − δ/2); with `gran/hooke/history`'s full
//!   radii (`"lever_arm": "full_radius"`) each contact adds at most μ δ_max ∫|F_n| dt,
//!   a bound the case file derives from the scene's inputs;
//! - the kinetic energy (translational and rotational) after the last contact lies
//!   between 0 and its initial value (passive contacts).
//!
//! Measured from the first and last recorded frames; masses and moments of inertia are
//! those of solid spheres of the scene's density. Each conserved quantity is given as
//! the projection ratio Q_end · Q_0 / |Q_0|², so it is 1 to round-off and an engine's
//! value can be held to tamp's (the case file's `agreement`); the kinetic energy ratio
//! depends on every step of the three impacts, which makes the agreement on it a check
//! of the whole trajectory.

use crate::error::{Result, TampError};
use crate::verify::measure::{angular_momentum, kinetic_energy, linear_momentum, overlap};
use crate::verify::{CaseContext, Measured};

pub fn run(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let scene = ctx.scene()?;
    if scene.particles.len() != 3 || !scene.walls.is_empty() {
        return Err(TampError::Other(
            "the scene must hold three spheres and no wall".into(),
        ));
    }
    let density = scene
        .materials
        .iter()
        .map(|m| m.density)
        .reduce(|a, b| if a == b { a } else { None })
        .flatten()
        .ok_or_else(|| {
            TampError::Other("the scene's spheres must share one material density".into())
        })?;
    let (first, last) = ctx.first_and_last("impact", &scene)?;
    for (i, j) in [(0, 1), (0, 2), (1, 2)] {
        if overlap(&last, i, j) >= 0.0 {
            return Err(TampError::Other(format!(
                "spheres {i} and {j} still touch at step {}: the kinetic energy is not the whole energy yet",
                last.step
            )));
        }
    }
    // A sphere that never moved would leave its impacts untested.
    if let Some(i) = (0..3).find(|&i| first.bodies[i].velocity == last.bodies[i].velocity) {
        return Err(TampError::Other(format!(
            "sphere {i}'s velocity did not change between the first and the last frame: the chain of impacts did not happen"
        )));
    }
    let ratio =
        |q0: crate::particles::Vec3, q1: crate::particles::Vec3| q1.dot(&q0) / q0.norm_squared();
    let p = ratio(
        linear_momentum(&first, density),
        linear_momentum(&last, density),
    );
    let l = ratio(
        angular_momentum(&first, density),
        angular_momentum(&last, density),
    );
    let energy = kinetic_energy(&last, density) / kinetic_energy(&first, density);
    Ok(vec![
        Measured::new("linear_momentum_ratio", p, 1.0),
        Measured::new("angular_momentum_ratio", l, 1.0),
        Measured::between("kinetic_energy_ratio", energy, 0.0, 1.0),
    ])
}
