//! A run's model: everything a scene fixes and the step only reads — materials and
//! their pair table, the contact laws, gravity, rotation, the walls' shapes and motion
//! laws, the pouring sources, a growth stage, how pairs are found, and the
//! safeguards. It is built once from the scene (`scene::build`) and never written by
//! the step, so a checkpoint need not store it: the scene file rebuilds it.

use super::StabilityLimits;
use crate::boundary::Boundary;
use crate::contact::ContactLaw;
use crate::contact::states::StateStore;
use crate::detect::Detection;
use crate::generate::pour::Source;
use crate::growth::Growth;
use crate::material::{Material, PairTable};
use crate::particles::Vec3;

use super::VelocityChange;
use super::contacts::NewStates;

/// What a scene fixes for its run (see the module documentation).
#[derive(Clone, Debug)]
pub struct Model {
    /// The scene's materials; particles and walls refer to them by index.
    pub materials: Vec<Material>,
    /// Contact parameters of each pair of materials (E*, G*, friction coefficient, …).
    pub pair_table: PairTable,
    /// The scene's contact law: its normal, damping, tangential and cohesion models and
    /// lever arm.
    pub law: ContactLaw,
    /// Gravitational acceleration g, m/s²; `None` without gravity.
    pub gravity: Option<Vec3>,
    /// Whether spins are integrated (torques act); off, particles only translate.
    pub rotation: bool,
    /// Moment-of-inertia scale of new particles (`rotation.inertia_scale`).
    pub inertia_scale: f64,
    /// Which radius the moments of inertia take where radii change
    /// (`rotation.inertia_radius`).
    pub inertia_radius: crate::particles::InertiaRadius,
    /// Boundaries (walls, containers, meshes): shape, material and motion law. Where
    /// each one is lives in the state (`State::walls`).
    pub walls: Vec<Boundary>,
    /// Pouring sources (particles entering during the run): region, sizes and
    /// schedule. How far each has got lives in the state (`State::sources`).
    pub sources: Vec<Source>,
    /// Growth stage (Zhong 2009 §6.1): radii grow to `State::target_radius`, gravity off.
    pub growth: Option<Growth>,
    /// How candidate pairs are found: detector, skin, reach and domain.
    pub detection: Detection,
    /// The safeguards that stop an unstable run.
    pub limits: StabilityLimits,
    /// Prescribed velocities that change during the run, by step (`velocity_changes`).
    pub velocity_changes: Vec<VelocityChange>,
}

impl Model {
    /// An empty store of the contact states the model's laws keep, for `particles`
    /// particles.
    pub(crate) fn new_contact_states(&self, particles: usize) -> Box<dyn StateStore> {
        self.law.visit(NewStates {
            particles,
            boundaries: self.walls.len(),
        })
    }
}
