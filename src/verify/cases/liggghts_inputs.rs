//! The inputs a recorded LIGGGHTS (or LAMMPS) run was made with, checked against the case's
//! scene before any number is compared: a case refuses to compare when the two
//! differ (a scene edited without re-recording, or a results file from another deck).

use crate::contact::tangential::TangentialLaw;
use crate::error::{Result, TampError};
use crate::scene::Scene;
use crate::scene::walls::{MotionSpec, ShapeSpec};

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

    /// A head-on pair of equal spheres (`particles[0]`, `particles[1]`): radius,
    /// initial gap and speed of approach along the line of centres.
    pub fn check_head_on_pair(
        &mut self,
        scene: &Scene,
        radius: f64,
        initial_gap: f64,
        relative_speed: f64,
    ) {
        let [a, b] = [&scene.particles[0], &scene.particles[1]];
        self.check("radius of particles[0]", a.radius, radius);
        self.check("radius of particles[1]", b.radius, radius);
        let d: f64 = (0..3)
            .map(|k| (b.position[k] - a.position[k]).powi(2))
            .sum::<f64>()
            .sqrt();
        self.check("initial gap", d - a.radius - b.radius, initial_gap);
        let (va, vb) = (
            a.velocity.unwrap_or([0.0; 3]),
            b.velocity.unwrap_or([0.0; 3]),
        );
        let approach: f64 = (0..3)
            .map(|k| (va[k] - vb[k]) * (b.position[k] - a.position[k]) / d)
            .sum();
        self.check("relative speed", approach, relative_speed);
    }

    /// What the runs with friction share: LIGGGHTS's tangential history with one
    /// friction coefficient, solid-sphere spins, no gravity.
    pub fn check_history_runs(&mut self, scene: &Scene) {
        if !scene.contact.tangential.as_ref().is_some_and(|t| {
            matches!(t.law, TangentialLaw::LiggghtsHistory(_)) && t.friction_pairs.is_empty()
        }) {
            self.0.push(
                "contact.tangential: LIGGGHTS ran tangential history, the scene needs law 'liggghts_history' with one friction".into(),
            );
        }
        self.check_spins_without_gravity(scene);
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

    /// One sphere of `radius` at (0, 0, radius + initial_gap) above one fixed plane
    /// z = 0 (normal +z) of its own material.
    pub fn check_sphere_on_floor(&mut self, scene: &Scene, radius: f64, initial_gap: f64) {
        let Some(p) = self.check_sphere_above_origin(scene, radius, initial_gap) else {
            return;
        };
        let plane_ok = matches!(scene.walls.as_slice(), [w] if w.material == p.material
            && matches!(w.motion, MotionSpec::Fixed)
            && matches!(&w.shape, ShapeSpec::Plane { point, normal }
                if *point == [0.0; 3] && *normal == [0.0, 0.0, 1.0]));
        if !plane_ok {
            self.0.push(
                "walls: the peer ran one fixed plane z = 0 (normal +z) of the sphere's material"
                    .into(),
            );
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
