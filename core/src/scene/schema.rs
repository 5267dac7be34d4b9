//! The scene file (JSON): its top level, and every type below it re-exported from
//! the topic file that holds the type with its rules and its build (materials.rs,
//! contact.rs, particles.rs, walls.rs, physics.rs, run.rs), so that
//! `scene::schema` names the whole tree. Every field, unit and default is documented
//! in docs/scene-format.md; unknown fields are rejected.

pub use super::contact::{ContactSpec, FrictionPair, FrictionSpec};
pub use super::materials::{HollomonSpec, MaterialSpec};
pub use super::particles::{
    BoxRegion, DepositSpec, InsertSpec, ParticleSpec, RadiusSpec, ScheduleSpec, UniformRadius,
    VelocityChangeSpec,
};
pub use super::physics::{GrowthSpec, PeriodicSpec, RotationSpec};
pub use super::run::{
    BroadPhaseSpec, DEFAULT_ALPHA, DetectorSpec, OutputSpec, RunSpec, StabilitySpec, TimeStepSpec,
};
pub use super::walls::WallSpec;
use serde::{Deserialize, Serialize};

/// The origin of a resolved scene.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct ResolvedFrom {
    /// The original scene's `name`.
    pub name: String,
    /// SHA-256 of the original scene file's bytes, hex.
    pub sha256: String,
}

/// A scene: what to simulate, and how.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Scene {
    /// A title, copied to the outputs.
    #[serde(default)]
    pub name: String,
    /// Seed of every random choice the scene makes (insertion positions, velocities).
    #[serde(default)]
    pub seed: u64,
    /// The materials particles and walls are made of.
    pub materials: Vec<MaterialSpec>,
    /// The contact law.
    pub contact: ContactSpec,
    /// Particles given one by one.
    #[serde(default)]
    pub particles: Vec<ParticleSpec>,
    /// Particles inserted at random into boxes.
    #[serde(default)]
    pub insert: Vec<InsertSpec>,
    /// Particles deposited ballistically onto a floor.
    #[serde(default)]
    pub deposit: Vec<DepositSpec>,
    /// The boundaries.
    #[serde(default)]
    pub walls: Vec<WallSpec>,
    /// Gravitational acceleration, m/s²; absent means no gravity.
    #[serde(default)]
    pub gravity: Option<[f64; 3]>,
    /// Periodic axes, each `[lo, hi]`; absent axes are open.
    #[serde(default)]
    pub periodic: Option<PeriodicSpec>,
    /// Growth stage of Zhong 2009 §6.1 (radii grow, gravity off); absent means none.
    #[serde(default)]
    pub growth: Option<GrowthSpec>,
    /// Absent means particles do not rotate.
    #[serde(default)]
    pub rotation: Option<RotationSpec>,
    /// How the time step is chosen.
    pub time_step: TimeStepSpec,
    /// How long the run lasts.
    #[serde(default)]
    pub run: RunSpec,
    /// Contact detection.
    #[serde(default)]
    pub broad_phase: BroadPhaseSpec,
    /// The limits that stop a run going wrong (exit 3).
    #[serde(default)]
    pub stability: StabilitySpec,
    /// The files a run writes.
    #[serde(default)]
    pub output: OutputSpec,
    /// The scene this one was resolved from (every particle placed, the step and the
    /// step count fixed: what `tamp verify --engine` hands an engine), for provenance
    /// only; absent in a scene written by hand.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub resolved_from: Option<ResolvedFrom>,
    /// Directory of the scene file, for relative paths (STL meshes); not a JSON field.
    #[serde(skip)]
    pub base_dir: std::path::PathBuf,
}
