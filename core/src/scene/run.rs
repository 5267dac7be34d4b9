//! How a scene runs: the `time_step` (α of Rojek eq 26, an accuracy, or a fixed
//! step), the `run` length and its early end, the `broad_phase` contact detection, the
//! `stability` limits that stop a run going wrong, and the `output` files.
//!
//! ```json
//! "time_step": {"alpha": 0.2, "characteristic_velocity": 1.0},
//! "run": {"duration": 0.5, "until": {"kinetic_energy_per_particle": 1e-12}},
//! "output": {"trajectory_every": 1000}
//! ```

use super::schema::Scene;
use crate::detect::Detector;
use crate::error::Errors;
use crate::simulation::StabilityLimits;
use crate::until::UntilSpec;
use serde::{Deserialize, Serialize};

/// The columns `output.series` may name, in the order of `series.csv`.
pub const SERIES_COLUMNS: &[&str] = &[
    "kinetic_energy",
    "rotational_energy",
    "stored_energy",
    "gravitational_energy",
    "external_work",
    "dissipated_energy",
    "contact_count",
    "max_overlap_ratio",
    "wall_forces",
];

/// How the time step is chosen (docs/scene-format.md, "Time step").
#[derive(Clone, Debug, Default, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct TimeStepSpec {
    /// Safety factor α of Rojek eq 26 (`alpha()`: 0.2 when absent).
    #[serde(default)]
    pub alpha: Option<f64>,
    /// The relative error of the impact quantities asked for (core/src/accuracy/).
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

pub use crate::timestep::DEFAULT_ALPHA;

/// How long the run lasts.
#[derive(Clone, Debug, Default, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct RunSpec {
    /// Simulated time, s (exclusive with `steps`).
    #[serde(default)]
    pub duration: Option<f64>,
    /// Number of steps (exclusive with `duration`).
    #[serde(default)]
    pub steps: Option<u64>,
    /// End the run earlier, once the particles have settled; `duration` or `steps`
    /// stays its maximum (docs/scene-format.md).
    #[serde(default)]
    pub until: Option<UntilSpec>,
    /// The longest run the scene may ask for, s of predicted wall time; absent:
    /// `DEFAULT_MAX_WALL_TIME` (docs/scene-format.md, "Run length").
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_wall_time: Option<f64>,
}

/// A run predicted to take longer than this (30 days) is refused unless the scene
/// raises `run.max_wall_time`: it is almost certainly a mistake of units.
pub const DEFAULT_MAX_WALL_TIME: f64 = 30.0 * 86_400.0;

/// The largest step count whose times t = n·Δt are all exact multiples: beyond 2^53
/// a double cannot hold every integer, so steps would share a time.
pub const MAX_STEPS: f64 = 9_007_199_254_740_992.0;

/// Contact detection: which detector, and its Verlet skin.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct BroadPhaseSpec {
    /// The detector.
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

impl DetectorSpec {
    /// The detector the neighbour list runs.
    pub fn detector(self) -> Detector {
        match self {
            DetectorSpec::Brute => Detector::Brute,
            DetectorSpec::Cells => Detector::Cells,
            DetectorSpec::Multigrid => Detector::Multigrid,
        }
    }
}

fn default_detector() -> DetectorSpec {
    DetectorSpec::Cells
}

fn default_skin() -> f64 {
    0.2
}

/// The contact detectors (core/src/detect/).
#[derive(Clone, Copy, Debug, Deserialize, Serialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum DetectorSpec {
    /// Every pair tested: the reference the others are checked against.
    Brute,
    /// One cell grid sized by the largest particle.
    Cells,
    /// One grid per size class, for wide size distributions.
    Multigrid,
}

/// The limits beyond which a run stops with exit 3 (docs/scene-format.md).
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct StabilitySpec {
    /// Largest overlap allowed, as a fraction of the smaller radius (the particle's,
    /// against a wall).
    #[serde(default = "default_max_overlap")]
    pub max_overlap_fraction: f64,
    /// The energy gain allowed, as a fraction of the energy scale
    /// (docs/scene-format.md, "Exit codes").
    #[serde(default = "default_energy_growth")]
    pub max_energy_growth: f64,
    /// Steps between energy checks.
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

impl StabilitySpec {
    /// The limits the simulation checks as it runs.
    pub fn limits(&self) -> StabilityLimits {
        StabilityLimits {
            max_overlap_fraction: self.max_overlap_fraction,
            max_energy_growth: self.max_energy_growth,
            check_every: self.check_every,
            max_step_fraction: self.max_step_fraction,
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

/// What a run writes besides `summary.json` and `quantities.csv`.
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
    /// From this step to the last, trajectory.csv has a row at every step as well:
    /// a measurement that interpolates between steps near the end of a run (where a
    /// force or an overlap crosses a value) needs them there and nowhere else.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub trajectory_every_step_from: Option<u64>,
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
    /// walls.csv beside trajectory.csv, at the same steps: each wall's displacement from
    /// where the scene puts it and the force the particles exert on it.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub walls: bool,
}

/// The rules of `time_step`, `run`, `broad_phase`, `stability` and `output`.
pub fn validate(scene: &Scene, e: &mut Errors) {
    validate_time_step(&scene.time_step, e);
    validate_length(&scene.run, e);
    validate_detection_limits_and_output(scene, e);
}

/// α in (0, 1], an accuracy in (0, 0.1] and alone, a positive speed and step.
pub fn validate_time_step(ts: &TimeStepSpec, e: &mut Errors) {
    if let Some(alpha) = ts.alpha
        && !(alpha > 0.0 && alpha <= 1.0)
    {
        e.push("time_step.alpha", format!("must be in (0, 1], got {alpha}"));
    }
    if let Some(a) = ts.accuracy {
        if !(a > 0.0 && a <= 0.1) {
            e.push(
                "time_step.accuracy",
                format!("must be in (0, 0.1] (a relative error; the error model is calibrated from 1e-1 down), got {a}"),
            );
        }
        for (field, given) in [("alpha", ts.alpha.is_some()), ("fixed", ts.fixed.is_some())] {
            if given {
                e.push(
                    "time_step.accuracy",
                    format!("cannot be combined with time_step.{field}: the accuracy chooses the step; give one of them"),
                );
            }
        }
    }
    if let Some(v) = ts.characteristic_velocity {
        e.positive("time_step.characteristic_velocity", v);
    }
    if let Some(dt) = ts.fixed {
        e.positive("time_step.fixed", dt);
    }
}

/// Exactly one of a duration or a number of steps, and an early end in range.
pub fn validate_length(run: &RunSpec, e: &mut Errors) {
    match (run.duration, run.steps) {
        (Some(d), None) => e.positive("run.duration", d),
        (None, Some(_)) => {}
        _ => e.push("run", "give exactly one of 'duration' (s) or 'steps'"),
    }
    if let Some(u) = &run.until {
        e.positive(
            "run.until.kinetic_energy_per_particle",
            u.kinetic_energy_per_particle,
        );
        if let Some(v) = u.max_speed {
            e.positive("run.until.max_speed", v);
        }
        e.non_negative("run.until.held_for", u.held_for);
    }
    if let Some(w) = run.max_wall_time {
        e.positive("run.max_wall_time", w);
    }
}

/// The skin, the stability limits and the series columns.
pub fn validate_detection_limits_and_output(scene: &Scene, e: &mut Errors) {
    e.positive("broad_phase.skin_fraction", scene.broad_phase.skin_fraction);
    e.positive(
        "stability.max_overlap_fraction",
        scene.stability.max_overlap_fraction,
    );
    e.positive(
        "stability.max_energy_growth",
        scene.stability.max_energy_growth,
    );
    e.positive(
        "stability.max_step_fraction",
        scene.stability.max_step_fraction,
    );
    e.non_negative(
        "stability.initial_overlap_tolerance",
        scene.stability.initial_overlap_tolerance,
    );
    if scene.stability.check_every == 0 {
        e.push(
            "stability.check_every",
            "must be >= 1, got 0 (it would switch the energy check off)",
        );
    }
    if scene.output.trajectory_every_step_from.is_some() && scene.output.trajectory_every == 0 {
        e.push(
            "output.trajectory_every_step_from",
            "needs output.trajectory_every >= 1 (it adds rows to trajectory.csv)",
        );
    }
    if scene.output.walls && scene.output.trajectory_every == 0 {
        e.push(
            "output.walls",
            "needs output.trajectory_every >= 1 (walls.csv is written at the steps of trajectory.csv)",
        );
    }
    if scene.output.walls && scene.walls.is_empty() {
        e.push("output.walls", "the scene has no walls to record");
    }
    for (k, c) in scene.output.series.iter().enumerate() {
        if !SERIES_COLUMNS.contains(&c.as_str()) {
            e.push(
                format!("output.series[{k}]"),
                format!("unknown column '{c}', expected one of {SERIES_COLUMNS:?}"),
            );
        }
    }
}
