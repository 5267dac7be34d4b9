//! Elastic Hertz spheres in a closed box of six plane walls, no damping, no friction,
//! no gravity: mechanical energy is conserved by the continuous system, so every
//! change is integration error. Velocity Verlet is second order, so the worst energy
//! excursion over a run should scale as Δt². The trajectories are chaotic, so each
//! step size samples different collisions: the order is the least-squares slope over
//! four halvings rather than one ratio (docs/verification-notes.md).

use crate::error::{Result, TampError};
use crate::scene::{self, Scene};
use crate::verify::{CaseContext, Measured};

/// Largest |E(t) − E(0)| / E(0) over `duration`, sampled every step, and the contacts seen.
fn worst_excursion(scene: &Scene, dt: f64, duration: f64) -> Result<(f64, usize)> {
    let mut built = scene::build(scene)?;
    built.sim.set_time_step(dt)?;
    let sim = &mut built.sim;
    let e0 = sim.mechanical_energy();
    let (mut worst, mut contacts) = (0.0f64, 0usize);
    for _ in 0..(duration / dt).round() as u64 {
        sim.step()?;
        worst = worst.max((sim.mechanical_energy() - e0).abs() / e0);
        contacts += sim.contact_count();
    }
    Ok((worst, contacts))
}

fn slope(points: &[(f64, f64)]) -> f64 {
    let n = points.len() as f64;
    let (sx, sy) = points
        .iter()
        .fold((0.0, 0.0), |a, p| (a.0 + p.0, a.1 + p.1));
    let (sxx, sxy) = points
        .iter()
        .fold((0.0, 0.0), |a, p| (a.0 + p.0 * p.0, a.1 + p.0 * p.1));
    (n * sxy - sx * sy) / (n * sxx - sx * sx)
}

/// The worst excursion at the scene's step and the order fitted over four halvings
/// (2, 1, 1/2, 1/4 times the step) of the same duration, `run.steps` of the scene's step.
pub(crate) fn drift_and_order(scene: &Scene) -> Result<(f64, f64)> {
    let steps = scene
        .run
        .steps
        .ok_or_else(|| TampError::Other("scene must give run.steps".into()))?;
    let dt = scene::build(scene)?.sim.dt();
    let duration = dt * steps as f64;
    let mut points = Vec::new();
    let mut drift = 0.0;
    for factor in [2.0, 1.0, 0.5, 0.25] {
        let (worst, contacts) = worst_excursion(scene, factor * dt, duration)?;
        if contacts == 0 {
            return Err(TampError::Other(
                "no contact occurred: the case would test nothing".into(),
            ));
        }
        if factor == 1.0 {
            drift = worst;
        }
        points.push(((factor * dt).ln(), worst.ln()));
    }
    Ok((drift, slope(&points)))
}

pub fn run(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let (drift, order) = drift_and_order(&ctx.scene()?)?;
    Ok(vec![
        Measured::new("energy_drift", drift, 0.0),
        Measured::new("energy_drift_order", order, 2.0),
    ])
}
