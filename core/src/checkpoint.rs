//! Restart checkpoints: the dynamic state of a `Simulation` on disk, so that a long
//! run that is killed can go on from its last checkpoint and end exactly — bit for
//! bit — as the uninterrupted run would have.
//!
//! `SimState` holds what the step loop changes: the particle arrays (force and torque
//! included: the next step's first half-kick uses the last step's forces, which are
//! stored rather than re-evaluated), Δt, step and time, the neighbour list's pairs,
//! reference positions and radii and build count, the contact states (per pair and per
//! touched wall facet, in the shape of the scene's laws), the force on each wall, each wall's displacement and velocity, the
//! energy book (W, its scale, the last prescribed power that the trapezoidal work rule
//! averages with, E_mech(0)), the running maximum overlap, the growth stage's target
//! radii, and each pouring source's next event, count left, pending radius and random
//! generator.
//!
//! Everything else is rebuilt by `scene::build` from the same scene file: materials,
//! pair table, contact law, wall shapes and motion laws, gravity, growth stage,
//! stability limits, the neighbour list's detector, skin and space, and each source's
//! region, size law and schedule. The build is deterministic (the seed fixes every
//! random draw), so what it rebuilds is what the interrupted run had. A checkpoint is
//! therefore valid only for its scene: the file carries the scene's SHA-256, tamp's
//! version and the checkpoint format, and any other is refused.
//!
//! Why the restored run is bit-exact:
//! - every double is written as the shortest decimal that reads back to it (serde_json
//!   formats with ryu) and read with serde_json's `float_roundtrip` parser, which
//!   rounds correctly; the default, faster parser can be one ulp off;
//! - nothing is recomputed on restore, so no rounding can differ (the one cache a
//!   contact state holds, Storåkers' C, K and δ_res, is not stored: it is derived
//!   again from the stored δ_max by the same expressions);
//! - the neighbour list keeps its reference state, so it is rebuilt at the same steps,
//!   and its sorted pairs sum the contact forces in the same order;
//! - a source's ChaCha generator is stored as its abstract state (seed, stream, word
//!   position), which continues the same stream of draws.
//!
//! JSON has no infinities or NaN; a run stops as unstable before one reaches the state.

use crate::error::{Result, TampError};
use crate::particles::{Particles, Vec3};
use crate::simulation::Simulation;
use rand_chacha::ChaCha8Rng;
use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};
use std::path::Path;

/// The layout of `SimState` this tamp writes and reads. Format 2 stores the contact
/// states typed by the scene's laws (`contact_states`) and the `prescribed` flags;
/// files without the field are format 1 (tamp before the typed contact states).
/// Format 3 adds each particle's id, which `broad_phase.sort` separates from its index.
pub const CHECKPOINT_FORMAT: u32 = 3;

/// A checkpoint file: a state and the scene and tamp version it belongs to.
#[derive(Serialize, Deserialize)]
pub struct Checkpoint<T> {
    /// Layout of the stored state, `CHECKPOINT_FORMAT` when written.
    pub checkpoint_format: u32,
    /// tamp version that wrote the file.
    pub tamp_version: String,
    /// The commit that wrote it: a different commit of the same version is accepted,
    /// but may step differently, so the reader can warn.
    pub git_commit: String,
    /// SHA-256 of the scene file the run was built from, hex.
    pub scene_sha256: String,
    /// The stored state.
    pub state: T,
}

impl<T> Checkpoint<T> {
    /// A checkpoint of `state` for the scene whose SHA-256 is `scene_sha256`, stamped
    /// with this tamp's version, commit and format.
    pub fn new(scene_sha256: &str, state: T) -> Self {
        Checkpoint {
            checkpoint_format: CHECKPOINT_FORMAT,
            tamp_version: crate::VERSION.to_string(),
            git_commit: crate::GIT_COMMIT.to_string(),
            scene_sha256: scene_sha256.to_string(),
            state,
        }
    }

    /// The stored state, if it was written by this tamp version for the scene whose
    /// SHA-256 is `scene_sha256`; `file` names the checkpoint in the error.
    pub fn into_state(self, scene_sha256: &str, file: &Path) -> Result<T> {
        if self.scene_sha256 != scene_sha256 {
            return Err(TampError::input(
                file.display().to_string(),
                format!(
                    "was written for the scene with sha256 {}, but this scene has sha256 {scene_sha256}; a checkpoint resumes only the scene file it was made from",
                    self.scene_sha256
                ),
            ));
        }
        if self.tamp_version != crate::VERSION {
            return Err(TampError::input(
                file.display().to_string(),
                format!(
                    "was written by tamp {}, this is tamp {}; another version may step differently",
                    self.tamp_version,
                    crate::VERSION
                ),
            ));
        }
        Ok(self.state)
    }
}

/// Write a checkpoint to `path` atomically: a reader, or a run resumed after a kill,
/// sees the previous checkpoint or this one, never half of one.
pub fn write_checkpoint(path: &Path, checkpoint: &impl Serialize) -> Result<()> {
    let json = serde_json::to_vec(checkpoint)
        .map_err(|e| TampError::Other(format!("serialising {}: {e}", path.display())))?;
    crate::output::write_atomic(path, &json)
}

/// `--resume` needs checkpoints to resume from: refuse it (bad input) when the scene's
/// `output.checkpoint_every` is 0.
pub fn require_checkpoints_for_resume(resume: bool, checkpoint_every: u64) -> Result<()> {
    if resume && checkpoint_every == 0 {
        return Err(TampError::input(
            "output.checkpoint_every",
            "must be > 0 with --resume: a run that writes no checkpoint has nothing to resume from",
        ));
    }
    Ok(())
}

/// Read a checkpoint written by `write_checkpoint`. A file that does not parse is bad
/// input (exit 2); the error names the JSON path where it stopped.
pub fn read_checkpoint<T: DeserializeOwned>(path: &Path) -> Result<T> {
    let bytes = std::fs::read(path)
        .map_err(|e| TampError::io(format!("reading checkpoint {}", path.display()), e))?;
    // The format first, so that an older layout is named as such rather than as a
    // missing field somewhere inside it.
    #[derive(Deserialize)]
    struct Format {
        #[serde(default = "format_one")]
        checkpoint_format: u32,
    }
    fn format_one() -> u32 {
        1
    }
    if let Ok(Format { checkpoint_format }) = serde_json::from_slice::<Format>(&bytes)
        && checkpoint_format != CHECKPOINT_FORMAT
    {
        return Err(TampError::input(
            path.display().to_string(),
            format!(
                "is checkpoint format {checkpoint_format}; this tamp reads format {CHECKPOINT_FORMAT} only (it stores each contact's state in the shape of the scene's laws, and each particle's id): run the scene again from the start"
            ),
        ));
    }
    let de = &mut serde_json::Deserializer::from_slice(&bytes);
    serde_path_to_error::deserialize(de).map_err(|e| {
        let at = match e.path().to_string() {
            top if top == "." => String::new(),
            inner => format!(" (at {inner})"),
        };
        TampError::input(
            path.display().to_string(),
            format!("is not a readable tamp checkpoint{at}: {}", e.inner()),
        )
    })
}

/// The dynamic state of a `Simulation` (see the module documentation).
#[derive(Serialize, Deserialize)]
pub struct SimState {
    particles: Particles,
    dt: f64,
    step: u64,
    time: f64,
    neighbors: NeighborState,
    /// The per-pair and per-facet contact states, in the shape of the scene's laws
    /// (`contact::states::ContactStates`).
    contact_states: serde_json::Value,
    wall_force: Vec<Vec3>,
    walls: Vec<WallState>,
    external_work: f64,
    external_work_scale: f64,
    external_power: f64,
    initial_mechanical_energy: f64,
    max_overlap_ratio: f64,
    target_radius: Vec<f64>,
    sources: Vec<SourceState>,
}

#[derive(Serialize, Deserialize)]
struct NeighborState {
    pairs: Vec<(u32, u32)>,
    reference_position: Vec<Vec3>,
    reference_radius: Vec<f64>,
    builds: u64,
}

/// Where a wall is and how fast it moves; its motion law comes from the scene.
#[derive(Serialize, Deserialize)]
struct WallState {
    displacement: Vec3,
    velocity: Vec3,
}

#[derive(Serialize, Deserialize)]
struct SourceState {
    next: f64,
    remaining: usize,
    pending_radius: Option<f64>,
    rng: ChaCha8Rng,
}

impl SimState {
    /// The dynamic state of `sim` at the end of its last step, copied.
    pub fn capture(sim: &Simulation) -> SimState {
        let n = &sim.neighbors;
        SimState {
            particles: sim.particles.clone(),
            dt: sim.dt,
            step: sim.step,
            time: sim.time,
            neighbors: NeighborState {
                pairs: n.pairs.clone(),
                reference_position: n.reference_position.clone(),
                reference_radius: n.reference_radius.clone(),
                builds: n.builds,
            },
            contact_states: sim.states.to_json(),
            wall_force: sim.wall_force.clone(),
            walls: sim
                .walls
                .iter()
                .map(|w| WallState {
                    displacement: w.displacement,
                    velocity: w.velocity,
                })
                .collect(),
            external_work: sim.external_work,
            external_work_scale: sim.external_work_scale,
            external_power: sim.external_power,
            initial_mechanical_energy: sim.initial_mechanical_energy,
            max_overlap_ratio: sim.max_overlap_ratio,
            target_radius: sim.target_radius.clone(),
            sources: sim
                .sources
                .iter()
                .map(|s| SourceState {
                    next: s.next,
                    remaining: s.remaining,
                    pending_radius: s.pending_radius,
                    rng: s.rng.clone(),
                })
                .collect(),
        }
    }

    /// Put this state into `sim`, a simulation built from the same scene. Refuses
    /// (exit 2) a state that cannot belong to that scene.
    pub fn restore(self, sim: &mut Simulation) -> Result<()> {
        self.check_fits(sim)?;
        let mut states = sim.states.clone();
        states.load_json(self.contact_states).map_err(|e| {
            TampError::input(
                "checkpoint.contact_states",
                format!("does not hold the states of the scene's contact laws: {e}"),
            )
        })?;
        if !states.fits(
            self.neighbors.pairs.len(),
            self.particles.len(),
            sim.walls.len(),
        ) {
            let rule = if states.is_kept() {
                "lacks a state for each contact, which the scene's contact laws keep"
            } else {
                "holds contact states, but the scene's contact laws keep none"
            };
            return Err(TampError::input("checkpoint.contact_states", rule));
        }
        sim.states = states;
        let n = self.neighbors;
        sim.neighbors.pairs = n.pairs;
        sim.neighbors.reference_position = n.reference_position;
        sim.neighbors.reference_radius = n.reference_radius;
        sim.neighbors.builds = n.builds;
        for (wall, saved) in sim.walls.iter_mut().zip(self.walls) {
            wall.displacement = saved.displacement;
            wall.velocity = saved.velocity;
        }
        for (source, saved) in sim.sources.iter_mut().zip(self.sources) {
            source.next = saved.next;
            source.remaining = saved.remaining;
            source.pending_radius = saved.pending_radius;
            source.rng = saved.rng;
        }
        sim.particles = self.particles;
        sim.dt = self.dt;
        sim.step = self.step;
        sim.time = self.time;
        sim.wall_force = self.wall_force;
        sim.external_work = self.external_work;
        sim.external_work_scale = self.external_work_scale;
        sim.external_power = self.external_power;
        sim.initial_mechanical_energy = self.initial_mechanical_energy;
        sim.max_overlap_ratio = self.max_overlap_ratio;
        sim.target_radius = self.target_radius;
        sim.refresh_smallest_radius();
        Ok(())
    }

    /// The shape of the state against the scene's simulation: walls and sources, the
    /// particle count (those built plus those poured since), and histories kept
    /// exactly when the scene's contact law keeps them. A mismatch here would
    /// otherwise surface as an index out of bounds in the middle of the run.
    fn check_fits(&self, sim: &Simulation) -> Result<()> {
        let refuse =
            |field: &str, rule: String| Err(TampError::input(format!("checkpoint.{field}"), rule));
        let walls = sim.walls.len();
        if self.walls.len() != walls || self.wall_force.len() != walls {
            return refuse(
                "walls",
                format!("has {} walls, the scene {walls}", self.walls.len()),
            );
        }
        if self.sources.len() != sim.sources.len() {
            return refuse(
                "sources",
                format!(
                    "has {} pouring sources, the scene {}",
                    self.sources.len(),
                    sim.sources.len()
                ),
            );
        }
        let mut poured = 0;
        for (k, (saved, built)) in self.sources.iter().zip(&sim.sources).enumerate() {
            if saved.remaining > built.remaining {
                return refuse(
                    &format!("sources[{k}].remaining"),
                    format!(
                        "{} particles still to pour, more than the {} of the scene",
                        saved.remaining, built.remaining
                    ),
                );
            }
            poured += built.remaining - saved.remaining;
        }
        let p = &self.particles;
        let n = p.len();
        if n != sim.particles.len() + poured {
            return refuse(
                "particles",
                format!(
                    "holds {n} particles, but the scene builds {} and its sources have poured {poured} since",
                    sim.particles.len()
                ),
            );
        }
        let lengths = [
            p.velocity.len(),
            p.omega.len(),
            p.force.len(),
            p.torque.len(),
            p.radius.len(),
            p.mass.len(),
            p.inertia.len(),
            p.material.len(),
            p.prescribed.len(),
            p.id.len(),
        ];
        if lengths.iter().any(|&l| l != n) {
            return refuse(
                "particles",
                format!("its arrays must all hold {n} entries, got {lengths:?}"),
            );
        }
        let nb = &self.neighbors;
        if nb.reference_position.len() != nb.reference_radius.len() {
            return refuse(
                "neighbors",
                "reference positions and radii differ in number".to_string(),
            );
        }
        if self.target_radius.len() != sim.target_radius.len() {
            return refuse(
                "target_radius",
                format!(
                    "has {} target radii, the scene's growth stage {}",
                    self.target_radius.len(),
                    sim.target_radius.len()
                ),
            );
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};

    #[test]
    fn random_doubles_round_trip_through_json() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(1);
        let mut values: Vec<f64> = (0..200_000)
            .map(|_| f64::from_bits(rng.next_u64()))
            .filter(|x| x.is_finite())
            .collect();
        values.extend([
            -0.0,
            0.1 + 0.2,
            f64::MIN_POSITIVE,
            f64::MIN_POSITIVE / 3.0,
            f64::from_bits(1),
            f64::MAX,
            -f64::MAX,
        ]);
        let back: Vec<f64> =
            serde_json::from_str(&serde_json::to_string(&values).unwrap()).unwrap();
        for (a, b) in values.iter().zip(&back) {
            assert_eq!(a.to_bits(), b.to_bits(), "{a:e} came back as {b:e}");
        }
    }

    #[test]
    fn a_checkpoint_of_an_older_format_is_refused_naming_the_format() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("old.json");
        // Format 1 had no `checkpoint_format` field.
        std::fs::write(
            &path,
            r#"{"tamp_version": "0.1.0", "git_commit": "e4fb2aa", "scene_sha256": "x", "state": {}}"#,
        )
        .unwrap();
        let err = read_checkpoint::<Checkpoint<SimState>>(&path)
            .err()
            .expect("refused");
        assert_eq!(err.exit_code(), 2);
        assert!(
            err.to_string()
                .contains("is checkpoint format 1; this tamp reads format 3"),
            "{err}"
        );
    }
}
