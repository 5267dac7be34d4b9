//! The inputs a recorded LIGGGHTS (or LAMMPS) run was made with, checked against the case's
//! scene before any number is compared: a case refuses to compare when the two
//! differ (a scene edited without re-recording, or a results file from another deck).

use crate::error::{Result, TampError};
use crate::scene::Scene;

/// Collects "what: scene …, peer run …" for inputs that differ by more than 1e-12.
#[derive(Default)]
pub(super) struct Mismatches(pub Vec<String>);

impl Mismatches {
    pub fn check(&mut self, what: &str, tamp: f64, liggghts: f64) {
        // Written so that a NaN on either side is a mismatch.
        let close = (tamp - liggghts).abs() <= 1e-12 * liggghts.abs();
        if !close {
            self.0
                .push(format!("{what}: scene {tamp:e}, peer run {liggghts:e}"));
        }
    }

    /// Refuse to compare when any input differs; `run` names the LIGGGHTS run.
    pub fn refuse_any(self, run: &str) -> Result<()> {
        if self.0.is_empty() {
            return Ok(());
        }
        Err(TampError::Other(format!(
            "the scene is not the one the peer code ran ({run}): {}",
            self.0.join("; ")
        )))
    }

    /// The material and the time step, which every recorded row carries.
    pub fn check_material_and_step(
        &mut self,
        scene: &Scene,
        density: f64,
        youngs_modulus: f64,
        poisson_ratio: f64,
        time_step: f64,
    ) {
        let m = &scene.materials[0];
        self.check("density", m.density.unwrap_or(f64::NAN), density);
        self.check(
            "youngs_modulus",
            m.youngs_modulus.unwrap_or(f64::NAN),
            youngs_modulus,
        );
        self.check(
            "poisson_ratio",
            m.poisson_ratio.unwrap_or(f64::NAN),
            poisson_ratio,
        );
        self.check(
            "time_step",
            scene.time_step.fixed.unwrap_or(f64::NAN),
            time_step,
        );
    }

    /// Solid-sphere spins (both peers' fix nve/sphere) and no gravity.
    pub fn check_spins_without_gravity(&mut self, scene: &Scene) {
        if scene.rotation.as_ref().map(|r| r.inertia_scale) != Some(1.0) {
            self.0.push(
                "rotation: the peer integrates spins with I = 0.4 m R^2 (inertia_scale 1)".into(),
            );
        }
        if scene.gravity.is_some() {
            self.0.push("gravity: the peer ran without gravity".into());
        }
    }

    /// The scene's one sphere, checked to be the peer's: radius `radius`, centre at
    /// (0, 0, radius + initial_gap) above the wall's point at the origin.
    pub fn check_sphere_above_origin<'s>(
        &mut self,
        scene: &'s Scene,
        radius: f64,
        initial_gap: f64,
    ) -> Option<&'s crate::scene::schema::ParticleSpec> {
        let [p] = scene.particles.as_slice() else {
            self.0.push("particles: the peer ran one sphere".into());
            return None;
        };
        self.check("particles[0].radius", p.radius, radius);
        self.check("particles[0].position.x", p.position[0], 0.0);
        self.check("particles[0].position.y", p.position[1], 0.0);
        self.check(
            "particles[0].position.z",
            p.position[2],
            radius + initial_gap,
        );
        Some(p)
    }
}
