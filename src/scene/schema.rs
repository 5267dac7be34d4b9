//! The scene file schema (JSON). Every field, unit and default is documented in
//! docs/scene-format.md; unknown fields are rejected.

pub use super::die_compaction::DieCompactionSpec;
pub use super::walls::WallSpec;
use crate::contact::ContactLaw;
use crate::contact::damping::Damping;
use crate::contact::lever_arm::LeverArm;
use crate::contact::normal::NormalLaw;
use crate::contact::tangential::TangentialLaw;
use crate::contact::van_der_waals::Cohesion;
use crate::generate::distribution::SizeDistribution;
use crate::simulation::StabilityLimits;
use crate::until::UntilSpec;
use serde::{Deserialize, Serialize};

#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Scene {
    #[serde(default)]
    pub name: String,
    /// Seed of every random choice the scene makes (insertion positions, velocities).
    #[serde(default)]
    pub seed: u64,
    pub materials: Vec<MaterialSpec>,
    pub contact: ContactSpec,
    #[serde(default)]
    pub particles: Vec<ParticleSpec>,
    #[serde(default)]
    pub insert: Vec<InsertSpec>,
    #[serde(default)]
    pub deposit: Vec<DepositSpec>,
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
    pub time_step: TimeStepSpec,
    /// Required unless `die_compaction` sets the stages.
    #[serde(default)]
    pub run: RunSpec,
    #[serde(default)]
    pub broad_phase: BroadPhaseSpec,
    #[serde(default)]
    pub stability: StabilitySpec,
    #[serde(default)]
    pub output: OutputSpec,
    /// The die compaction of Rojek 2016 §5 as a sequence of stages (fill, flatten,
    /// press); absent for an ordinary run.
    #[serde(default)]
    pub die_compaction: Option<DieCompactionSpec>,
    /// Directory of the scene file, for relative paths (STL meshes); not a JSON field.
    #[serde(skip)]
    pub base_dir: std::path::PathBuf,
}

#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct MaterialSpec {
    pub name: String,
    /// kg/m³; required unless `rigid`.
    #[serde(default)]
    pub density: Option<f64>,
    /// A wall material that does not deform: no density or elastic constants, and a
    /// zero compliance term in E* and G* (docs/scene-format.md). Walls only.
    #[serde(default)]
    pub rigid: bool,
    /// Pa; required by elastic laws (hertz) unless `rigid`.
    #[serde(default)]
    pub youngs_modulus: Option<f64>,
    #[serde(default)]
    pub poisson_ratio: Option<f64>,
    /// Hollomon hardening σ = σ0 ε^m (Rojek eq 15); required by the Storåkers law.
    #[serde(default)]
    pub hollomon: Option<HollomonSpec>,
}

/// Give `exponent` and exactly one of `strength` (σ0, Pa) or `yield_stress` (σ_Y,
/// Pa: the curve then passes through (σ_Y/E, σ_Y), as in Rojek §4).
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct HollomonSpec {
    pub exponent: f64,
    #[serde(default)]
    pub strength: Option<f64>,
    #[serde(default)]
    pub yield_stress: Option<f64>,
}

/// The contact law, one block per role. Each law's parameters and rules are in its
/// own file under `contact/`; the scene holds the law types themselves.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct ContactSpec {
    pub normal: NormalLaw,
    #[serde(default)]
    pub damping: Option<Damping>,
    #[serde(default)]
    pub tangential: Option<FrictionSpec>,
    #[serde(default)]
    pub cohesion: Option<Cohesion>,
    /// Where a contact acts on spinning spheres: `mid_overlap` (default) or `lammps`
    /// (contact/lever_arm.rs).
    #[serde(default)]
    pub lever_arm: LeverArm,
}

impl ContactSpec {
    /// The law the force loop runs (friction coefficients go to the pair table).
    pub fn law(&self) -> ContactLaw {
        ContactLaw {
            lever_arm: self.lever_arm,
            ..ContactLaw::new(
                self.normal,
                self.damping,
                self.tangential.as_ref().map(|t| t.law),
                self.cohesion,
            )
        }
    }
}

/// Friction: the tangential law (its `law` tag and parameters, inline) plus μ and
/// per-pair overrides. Unknown fields are refused by the law's own type.
#[derive(Clone, Debug, Deserialize, Serialize)]
pub struct FrictionSpec {
    #[serde(flatten)]
    pub law: TangentialLaw,
    pub friction: f64,
    /// Per-material-pair friction overrides.
    #[serde(default)]
    pub friction_pairs: Vec<FrictionPair>,
}

#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct FrictionPair {
    pub materials: [String; 2],
    pub friction: f64,
}

#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct ParticleSpec {
    /// m
    pub position: [f64; 3],
    /// m
    pub radius: f64,
    pub material: String,
    #[serde(default)]
    pub velocity: Option<[f64; 3]>,
    #[serde(default)]
    pub omega: Option<[f64; 3]>,
    /// When set, the particle moves at this velocity whatever the forces (m/s).
    #[serde(default)]
    pub prescribed_velocity: Option<[f64; 3]>,
}

#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct InsertSpec {
    pub count: usize,
    pub radius: RadiusSpec,
    pub material: String,
    /// Axis-aligned box the particles must lie inside (whole spheres), m.
    pub region: BoxRegion,
    /// Speed of each particle in a uniformly random direction, m/s.
    #[serde(default)]
    pub speed: f64,
    /// Magnitude of each particle's spin in a random direction, rad/s.
    #[serde(default)]
    pub spin: f64,
    #[serde(default = "default_attempts")]
    pub max_attempts: usize,
    /// Absent: all particles are placed at t = 0.
    #[serde(default)]
    pub schedule: Option<ScheduleSpec>,
}

fn default_attempts() -> usize {
    100_000
}

#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(untagged)]
pub enum RadiusSpec {
    Fixed(f64),
    Uniform(UniformRadius),
    /// Any `generate::distribution::SizeDistribution`, tagged by `law`.
    Law(SizeDistribution),
}

impl RadiusSpec {
    pub fn distribution(&self) -> SizeDistribution {
        match self {
            RadiusSpec::Fixed(radius) => SizeDistribution::Mono { radius: *radius },
            RadiusSpec::Uniform(UniformRadius { min, max }) => SizeDistribution::Uniform {
                min: *min,
                max: *max,
            },
            RadiusSpec::Law(law) => law.clone(),
        }
    }
}

/// Pouring: instead of all at t = 0, insert `per_event` particles every `every`
/// seconds from `start` on, until `count` are in.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct ScheduleSpec {
    #[serde(default)]
    pub start: f64,
    pub every: f64,
    pub per_event: usize,
}

/// 3D ballistic deposition (steepest descent) of `count` spheres dropped over a
/// rectangular footprint onto the plane z = `floor`.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct DepositSpec {
    pub count: usize,
    pub radius: RadiusSpec,
    pub material: String,
    /// [x, y] corners of the footprint, m.
    pub footprint: [[f64; 2]; 2],
    pub floor: f64,
}

/// Radii uniformly distributed in [min, max], m.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct UniformRadius {
    pub min: f64,
    pub max: f64,
}

#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct BoxRegion {
    pub lower: [f64; 3],
    pub upper: [f64; 3],
}

#[derive(Clone, Debug, Default, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct PeriodicSpec {
    #[serde(default)]
    pub x: Option<[f64; 2]>,
    #[serde(default)]
    pub y: Option<[f64; 2]>,
    #[serde(default)]
    pub z: Option<[f64; 2]>,
}

impl PeriodicSpec {
    pub fn axes(&self) -> [Option<[f64; 2]>; 3] {
        [self.x, self.y, self.z]
    }
}

#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct GrowthSpec {
    /// Time over which radii grow to their targets, s.
    pub duration: f64,
    /// Starting radius as a fraction of the target, in [0, 1).
    #[serde(default)]
    pub initial_fraction: f64,
}

#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct RotationSpec {
    /// Multiplies every moment of inertia (Rojek 2016 §3.4 uses 10).
    #[serde(default = "one")]
    pub inertia_scale: f64,
}

fn one() -> f64 {
    1.0
}

#[derive(Clone, Debug, Default, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct TimeStepSpec {
    /// Safety factor α of Rojek eq 26 (`alpha()`: 0.2 when absent).
    #[serde(default)]
    pub alpha: Option<f64>,
    /// The relative error of the impact quantities asked for (src/accuracy/).
    #[serde(default)]
    pub accuracy: Option<f64>,
    /// Impact speed that sets the stiffness of nonlinear laws before contacts exist, m/s.
    #[serde(default)]
    pub characteristic_velocity: Option<f64>,
    /// A fixed step (s) that overrides α·Δt_cr; a warning is printed when it exceeds it.
    #[serde(default)]
    pub fixed: Option<f64>,
}

impl TimeStepSpec {
    /// The safety factor α: the scene's, or the default 0.2.
    pub fn alpha(&self) -> f64 {
        self.alpha.unwrap_or(DEFAULT_ALPHA)
    }

    /// Whether the scene states how its step is chosen (α, a fixed step or an
    /// accuracy); a scene that does not gets `accuracy::step::DEFAULT_ACCURACY`.
    pub fn stated(&self) -> bool {
        self.alpha.is_some() || self.fixed.is_some() || self.accuracy.is_some()
    }
}

pub const DEFAULT_ALPHA: f64 = 0.2;

#[derive(Clone, Debug, Default, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct RunSpec {
    /// Simulated time, s (exclusive with `steps`).
    #[serde(default)]
    pub duration: Option<f64>,
    #[serde(default)]
    pub steps: Option<u64>,
    /// End the run earlier, once the particles have settled; `duration` or `steps`
    /// stays its maximum (docs/scene-format.md).
    #[serde(default)]
    pub until: Option<UntilSpec>,
}

#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct BroadPhaseSpec {
    #[serde(default = "default_detector")]
    pub kind: DetectorSpec,
    /// Verlet skin as a fraction of the smallest radius.
    #[serde(default = "default_skin")]
    pub skin_fraction: f64,
    /// Renumber the particles by the cell they lie in once they are all placed, for
    /// memory locality (as LAMMPS `atom_modify sort`). Off by default: it changes the
    /// order in which contact forces are summed, so a chaotic run's results change at
    /// round-off and then beyond.
    #[serde(default)]
    pub sort: bool,
}

impl Default for BroadPhaseSpec {
    fn default() -> Self {
        BroadPhaseSpec {
            kind: default_detector(),
            skin_fraction: default_skin(),
            sort: false,
        }
    }
}

fn default_detector() -> DetectorSpec {
    DetectorSpec::Cells
}

fn default_skin() -> f64 {
    0.2
}

#[derive(Clone, Copy, Debug, Deserialize, Serialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum DetectorSpec {
    Brute,
    Cells,
    Multigrid,
}

#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct StabilitySpec {
    #[serde(default = "default_max_overlap")]
    pub max_overlap_fraction: f64,
    #[serde(default = "default_energy_growth")]
    pub max_energy_growth: f64,
    #[serde(default = "default_check_every")]
    pub check_every: u64,
    /// Largest move of a particle in one step, as a fraction of the smallest radius.
    #[serde(default = "default_max_step_fraction")]
    pub max_step_fraction: f64,
    /// Largest overlap allowed between initial particles, as a fraction of the smaller radius.
    #[serde(default = "default_initial_overlap")]
    pub initial_overlap_tolerance: f64,
}

impl Default for StabilitySpec {
    fn default() -> Self {
        StabilitySpec {
            max_overlap_fraction: default_max_overlap(),
            max_energy_growth: default_energy_growth(),
            check_every: default_check_every(),
            max_step_fraction: default_max_step_fraction(),
            initial_overlap_tolerance: default_initial_overlap(),
        }
    }
}

fn default_max_step_fraction() -> f64 {
    StabilityLimits::default().max_step_fraction
}

fn default_max_overlap() -> f64 {
    0.5
}
fn default_energy_growth() -> f64 {
    0.5
}
fn default_check_every() -> u64 {
    100
}
fn default_initial_overlap() -> f64 {
    1e-6
}

#[derive(Clone, Debug, Default, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct OutputSpec {
    /// Steps between rows of series.csv; 0 chooses about 1000 rows.
    #[serde(default)]
    pub series_every: u64,
    /// Columns of series.csv; empty means all (see docs/scene-format.md).
    #[serde(default)]
    pub series: Vec<String>,
    /// Steps between VTK frames; 0 writes none.
    #[serde(default)]
    pub vtk_every: u64,
    /// Steps between rows of trajectory.csv (every particle; docs/compare.md); 0
    /// writes none. The last step is always written when this is set.
    #[serde(default)]
    pub trajectory_every: u64,
    /// Steps between restart checkpoints (`checkpoint.json`); 0 writes none.
    #[serde(default)]
    pub checkpoint_every: u64,
    /// Each particle's force and torque: columns of trajectory.csv, point data of
    /// VTK frames.
    #[serde(default)]
    pub forces: bool,
    /// Steps between contact-network files (`contacts/contacts_NNNNNN.csv` and
    /// `.vtk`: pairs and wall contacts with point, normal, forces, overlap); 0 writes none.
    #[serde(default)]
    pub contacts_every: u64,
}
