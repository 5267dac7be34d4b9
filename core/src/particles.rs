//! Particle state as structure-of-arrays: each property is one contiguous vector,
//! so the integrator and the contact loop stream through memory.

use nalgebra::Vector3;
use serde::{Deserialize, Serialize};

/// A Cartesian 3-vector of `f64`: positions (m), velocities (m/s), forces (N) and the
/// like.
pub type Vec3 = Vector3<f64>;

/// How a particle moves: by Newton–Euler, or at a prescribed velocity
/// (displacement-controlled loading, Rojek 2016 §4). A prescribed particle still
/// receives contact forces; they are its reaction and are recorded as external work.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub enum Motion {
    /// Moves under its forces and torques.
    Free,
    /// Moves at this constant velocity, m/s, whatever the forces.
    Prescribed(Vec3),
}

/// Every particle of a simulation, a spherical rigid body each; element `k` of each
/// vector belongs to the particle at index `k`. SI units throughout.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
pub struct Particles {
    /// Centre position x, m.
    pub position: Vec<Vec3>,
    /// Translational velocity v of the centre, m/s.
    pub velocity: Vec<Vec3>,
    /// Angular velocity ω, rad/s.
    pub omega: Vec<Vec3>,
    /// Total force on the particle in the current step, N.
    pub force: Vec<Vec3>,
    /// Total torque about the centre in the current step, N·m.
    pub torque: Vec<Vec3>,
    /// Radius R, m.
    pub radius: Vec<f64>,
    /// Mass m = ρ (4/3) π R³, kg.
    pub mass: Vec<f64>,
    /// Moment of inertia, already multiplied by the scene's rotational-inertia scale.
    pub inertia: Vec<f64>,
    /// Index of the particle's material in the scene's material list.
    pub material: Vec<usize>,
    /// Whether the particle moves at its prescribed velocity (`Motion::Prescribed`,
    /// held in `velocity`) rather than by Newton–Euler: one flag, so the per-particle
    /// passes and the contact loop read a byte, not the 32-byte `Motion`.
    pub prescribed: Vec<bool>,
    /// The particle's id in every output (1-based, in the order the scene creates
    /// particles). It equals the index + 1 unless the scene asks for the particles to
    /// be renumbered for locality (`broad_phase.sort`), which moves the arrays but
    /// never the ids.
    pub id: Vec<u64>,
}

impl Particles {
    /// Number of particles.
    pub fn len(&self) -> usize {
        self.position.len()
    }

    /// Whether there are no particles.
    pub fn is_empty(&self) -> bool {
        self.position.is_empty()
    }

    /// The largest radius, m (0 with no particles).
    pub fn largest_radius(&self) -> f64 {
        self.radius.iter().copied().fold(0.0, f64::max)
    }

    /// Append a solid sphere of `radius` (m) and `density` (kg/m³); its mass and moment
    /// of inertia (2/5 m R², times `inertia_scale`) follow from them. A prescribed
    /// `motion` replaces `velocity`. The new particle takes the next free id.
    #[allow(clippy::too_many_arguments)]
    pub fn push(
        &mut self,
        position: Vec3,
        velocity: Vec3,
        omega: Vec3,
        radius: f64,
        density: f64,
        material: usize,
        inertia_scale: f64,
        motion: Motion,
    ) {
        let mass = density * 4.0 / 3.0 * std::f64::consts::PI * radius.powi(3);
        self.position.push(position);
        self.velocity.push(match motion {
            Motion::Prescribed(v) => v,
            Motion::Free => velocity,
        });
        self.omega.push(omega);
        self.force.push(Vec3::zeros());
        self.torque.push(Vec3::zeros());
        self.radius.push(radius);
        self.mass.push(mass);
        // Solid sphere: I = 2/5 m R²; Rojek 2016 §3.4 scales it (factor 10) to relax
        // the rotational stability limit.
        self.inertia
            .push(inertia_scale * 0.4 * mass * radius * radius);
        self.material.push(material);
        self.prescribed
            .push(matches!(motion, Motion::Prescribed(_)));
        // Ids of renumbered particles are a permutation of 1..=len, so the next free
        // one is still len + 1.
        self.id.push(self.id.len() as u64 + 1);
    }

    /// Reorder every array so that the particle at index `k` is the one that was at
    /// `order[k]`; `order` must be a permutation of `0..len`.
    pub fn permute(&mut self, order: &[usize]) {
        fn apply<T: Copy>(v: &mut Vec<T>, order: &[usize]) {
            *v = order.iter().map(|&k| v[k]).collect();
        }
        debug_assert_eq!(order.len(), self.len());
        apply(&mut self.position, order);
        apply(&mut self.velocity, order);
        apply(&mut self.omega, order);
        apply(&mut self.force, order);
        apply(&mut self.torque, order);
        apply(&mut self.radius, order);
        apply(&mut self.mass, order);
        apply(&mut self.inertia, order);
        apply(&mut self.material, order);
        apply(&mut self.prescribed, order);
        apply(&mut self.id, order);
    }

    /// Room for `additional` more particles, or an error instead of the abort an
    /// infallible allocation makes when memory runs out.
    pub fn try_reserve(
        &mut self,
        additional: usize,
    ) -> Result<(), std::collections::TryReserveError> {
        self.position.try_reserve_exact(additional)?;
        self.velocity.try_reserve_exact(additional)?;
        self.omega.try_reserve_exact(additional)?;
        self.force.try_reserve_exact(additional)?;
        self.torque.try_reserve_exact(additional)?;
        self.radius.try_reserve_exact(additional)?;
        self.mass.try_reserve_exact(additional)?;
        self.inertia.try_reserve_exact(additional)?;
        self.material.try_reserve_exact(additional)?;
        self.prescribed.try_reserve_exact(additional)?;
        self.id.try_reserve_exact(additional)
    }

    /// From now on particle `i` moves at velocity `v` whatever the force.
    pub fn prescribe(&mut self, i: usize, v: Vec3) {
        self.prescribed[i] = true;
        self.velocity[i] = v;
    }

    /// Translational kinetic energy Σ ½ m v², J.
    pub fn translational_kinetic_energy(&self) -> f64 {
        self.mass
            .iter()
            .zip(&self.velocity)
            .map(|(m, v)| 0.5 * m * v.norm_squared())
            .sum()
    }

    /// Rotational kinetic energy Σ ½ I ω², J, with the scaled moment of inertia that the
    /// dynamics uses.
    pub fn rotational_kinetic_energy(&self) -> f64 {
        self.inertia
            .iter()
            .zip(&self.omega)
            .map(|(i, w)| 0.5 * i * w.norm_squared())
            .sum()
    }

    /// Total linear momentum Σ m v, kg·m/s.
    pub fn linear_momentum(&self) -> Vec3 {
        self.mass
            .iter()
            .zip(&self.velocity)
            .map(|(m, v)| v * *m)
            .sum()
    }

    /// Orbital plus spin angular momentum about the origin.
    pub fn angular_momentum(&self) -> Vec3 {
        (0..self.len())
            .map(|i| {
                self.position[i].cross(&self.velocity[i]) * self.mass[i]
                    + self.omega[i] * self.inertia[i]
            })
            .sum()
    }
}

/// The radius a particle's moment of inertia takes where its radius changes during the
/// run (MDR's apparent radius; a growth stage's particles have their final size's
/// inertia throughout).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum InertiaRadius {
    /// The radius the particle starts with: its mass keeps the distribution it has,
    /// and contacts' torques conserve angular momentum.
    #[default]
    Initial,
    /// The radius of the step, as LAMMPS's `fix nve/sphere` takes it: a particle's
    /// spin is kept while its moment of inertia changes, so angular momentum is not
    /// conserved where radii change.
    Current,
}

impl InertiaRadius {
    /// The default: the radius the particle starts with.
    pub fn is_initial(&self) -> bool {
        *self == InertiaRadius::Initial
    }
}
