//! Elastic Hertz spheres in a closed box of six plane walls, no damping, no friction,
//! no gravity: mechanical energy is conserved by the continuous system, so every
//! change is integration error. Velocity Verlet is second order, so the worst energy
//! excursion over a run should scale as Δt². The trajectories are chaotic, so each
//! step size samples different collisions: the order is the least-squares slope over
//! four halvings rather than one ratio (docs/verification-notes.md).
//!
//! Measured from recorded frames, at the same instants in the four runs (every
//! `SAMPLE_STEPS` steps of the scene's own step): the kinetic energy Σ ½ m v² + ½ I ω²
//! of solid spheres of the scene's density, plus the Hertz energy stored in every
//! overlap, U = 8/15 E* √R* δ^{5/2}, between two spheres (R* = R_i R_j/(R_i + R_j)) and
//! between a sphere and a wall plane (R* = R_i), with δ from positions and radii and E*
//! from the scene's material.

use crate::contact::normal::hertz::hertz_energy;
use crate::error::{Result, TampError};
use crate::particles::Vec3;
use crate::scene::schema::{RunSpec, TimeStepSpec};
use crate::scene::walls::{MotionSpec, ShapeSpec};
use crate::scene::{self, Scene};
use crate::verify::measure::kinetic_energy;
use crate::verify::recording::{Frame, RecordSpec, Recording};
use crate::verify::{CaseContext, Measured};

/// Steps of the scene's own step between two energy samples: 400 samples per run.
const SAMPLE_STEPS: f64 = 250.0;

/// What the energy of a frame needs from the scene: one material, fixed planes.
struct Energy {
    density: f64,
    /// E* of every contact, sphere–sphere and sphere–wall alike.
    modulus: f64,
    /// A point of each wall plane and its unit normal towards the spheres.
    planes: Vec<(Vec3, Vec3)>,
}

impl Energy {
    fn of(scene: &Scene) -> Result<Energy> {
        let material = super::one_material::of(scene)?;
        let planes = scene
            .walls
            .iter()
            .map(|w| match (&w.shape, &w.motion) {
                (ShapeSpec::Plane { point, normal }, MotionSpec::Fixed) => {
                    Ok((Vec3::from(*point), Vec3::from(*normal).normalize()))
                }
                _ => Err(TampError::Other(format!(
                    "walls '{}': the walls must be fixed planes",
                    w.name.as_deref().unwrap_or("unnamed")
                ))),
            })
            .collect::<Result<_>>()?;
        Ok(Energy {
            density: material.density,
            modulus: material.effective_modulus,
            planes,
        })
    }

    /// Kinetic plus stored energy, and whether any contact is open.
    fn mechanical(&self, f: &Frame) -> (f64, bool) {
        let mut stored = 0.0;
        let mut touching = false;
        for (i, a) in f.bodies.iter().enumerate() {
            for b in &f.bodies[i + 1..] {
                let overlap = a.radius + b.radius - (a.position - b.position).norm();
                if overlap > 0.0 {
                    let r_eff = a.radius * b.radius / (a.radius + b.radius);
                    stored += hertz_energy(overlap, r_eff, self.modulus);
                    touching = true;
                }
            }
            for (point, normal) in &self.planes {
                let overlap = a.radius - (a.position - point).dot(normal);
                if overlap > 0.0 {
                    stored += hertz_energy(overlap, a.radius, self.modulus);
                    touching = true;
                }
            }
        }
        (kinetic_energy(f, self.density) + stored, touching)
    }
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

/// The worst sampled excursion |E(t) − E(0)|/E(0) at the scene's step, and the order
/// fitted over four halvings (2, 1, 1/2, 1/4 times the step) of the same duration,
/// `run.steps` of the scene's step. `record` runs a scene on an engine and returns what
/// it recorded (its first argument labels the run).
pub(crate) fn drift_and_order(
    scene: &Scene,
    record: impl Fn(&str, &Scene, RecordSpec) -> Result<Recording>,
) -> Result<(f64, f64)> {
    let steps = scene
        .run
        .steps
        .ok_or_else(|| TampError::Other("scene must give run.steps".into()))?;
    let energy = Energy::of(scene)?;
    let dt = scene::build(scene)?.sim.dt();
    let mut points = Vec::new();
    let mut drift = 0.0;
    for (label, factor) in [
        ("dt_x2", 2.0),
        ("dt_x1", 1.0),
        ("dt_x0.5", 0.5),
        ("dt_x0.25", 0.25),
    ] {
        let mut s = scene.clone();
        s.time_step = TimeStepSpec {
            fixed: Some(factor * dt),
            ..TimeStepSpec::default()
        };
        s.run = RunSpec {
            steps: Some((steps as f64 / factor).round() as u64),
            ..RunSpec::default()
        };
        let every = (SAMPLE_STEPS / factor).round() as u64;
        let rec = record(label, &s, RecordSpec::every(every, false))?;
        let Some(first) = rec.frames.first() else {
            return Err(TampError::Other(format!(
                "{label}: the recording has no frames"
            )));
        };
        let (e0, _) = energy.mechanical(first);
        let (mut worst, mut touched) = (0.0f64, false);
        for f in &rec.frames[1..] {
            let (e, touching) = energy.mechanical(f);
            worst = worst.max((e - e0).abs() / e0);
            touched |= touching;
        }
        if !touched {
            return Err(TampError::Other(format!(
                "{label}: no contact was open at any sampled step: the case would test nothing"
            )));
        }
        if factor == 1.0 {
            drift = worst;
        }
        points.push(((factor * dt).ln(), worst.ln()));
    }
    Ok((drift, slope(&points)))
}

pub fn run(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let (drift, order) =
        drift_and_order(&ctx.scene()?, |label, s, spec| ctx.record(label, s, spec))?;
    Ok(vec![
        Measured::new("energy_drift", drift, 0.0),
        // At least second order: the lower bound is what the case guards; the upper one
        // only catches a measurement gone wrong (see the case file).
        Measured::between("energy_drift_order", order, 1.5, 3.0),
    ])
}
