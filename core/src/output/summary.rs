//! summary.json: provenance plus the final quantities of a run.

use super::Provenance;
use crate::simulation::Simulation;
use serde::Serialize;

/// summary.json of one run: its provenance and the quantities at the last step,
/// including the energy balance (kinetic, stored, external work, dissipated).
#[derive(Debug, Serialize)]
pub struct Summary {
    /// Where the result came from.
    pub provenance: Provenance,
    /// The scene's `name`.
    pub scene_name: String,
    /// Number of particles at the end of the run.
    pub particles: usize,
    /// Simulated time at the end, s.
    pub time: f64,
    /// Steps taken since t = 0.
    pub steps: u64,
    /// Translational kinetic energy Σ ½ m v², J.
    pub kinetic_energy: f64,
    /// Rotational kinetic energy Σ ½ I ω², J.
    pub rotational_energy: f64,
    /// Energy stored in all contacts (pairs and walls) and in cohesion, J.
    pub stored_energy: f64,
    /// Work W done on the particles by gravity and prescribed bodies since the start, J.
    pub external_work: f64,
    /// Energy dissipated so far, E_mech(0) + W − E_mech, J; negative means energy was
    /// created.
    pub dissipated_energy: f64,
    /// Number of particle–particle and particle–wall contacts at the end.
    pub contact_count: usize,
    /// Largest overlap δ over the smaller radius seen during the run.
    pub max_overlap_ratio: f64,
    /// How many times the Verlet neighbour list was built.
    pub neighbor_list_builds: u64,
    /// Force the particles exert on each wall at the last step, in wall order.
    pub wall_forces: Vec<WallForce>,
    /// Warnings of the scene build, as printed on stderr.
    pub warnings: Vec<String>,
    /// Which criterion ended the run; present only when the scene gives `run.until`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ended_by: Option<RunEnd>,
}

/// How a run with `run.until` ended: `criterion` is `run.until` when the particles
/// settled, or `run.duration` / `run.steps` when the maximum came first; the reading
/// is the criterion's at the last step.
#[derive(Debug, Serialize)]
pub struct RunEnd {
    /// `run.until` when the particles settled, else `run.duration` or `run.steps`.
    pub criterion: &'static str,
    /// Simulated time at the end, s.
    pub time: f64,
    /// Step at the end.
    pub step: u64,
    /// Kinetic energy per particle (translation + spin) at the last step, J.
    pub kinetic_energy_per_particle: f64,
    /// Largest particle speed at the last step, m/s.
    pub max_speed: f64,
}

/// The force the particles exert on one wall, N.
#[derive(Debug, Serialize)]
pub struct WallForce {
    /// The wall's name (`walls[k].name`, or `wall<k>`).
    pub wall: String,
    /// Force components along x, y and z, N.
    pub force: [f64; 3],
}

impl Summary {
    /// The summary of `sim` as it stands; `ended_by` is left for the run to fill in.
    pub fn new(
        sim: &Simulation,
        provenance: Provenance,
        scene_name: &str,
        warnings: Vec<String>,
    ) -> Self {
        Summary {
            provenance,
            scene_name: scene_name.to_string(),
            particles: sim.state.particles.len(),
            time: sim.state.time,
            steps: sim.state.step,
            kinetic_energy: sim.state.particles.translational_kinetic_energy(),
            rotational_energy: sim.state.particles.rotational_kinetic_energy(),
            stored_energy: sim.stored_energy(),
            external_work: sim.state.energy.external_work,
            dissipated_energy: sim.dissipated_energy(),
            contact_count: sim.contact_count(),
            max_overlap_ratio: sim.state.max_overlap_ratio,
            neighbor_list_builds: sim.state.neighbors.builds,
            wall_forces: sim
                .model
                .walls
                .iter()
                .zip(&sim.state.wall_force)
                .map(|(w, f)| WallForce {
                    wall: w.name.clone(),
                    force: [f.x, f.y, f.z],
                })
                .collect(),
            warnings,
            ended_by: None,
        }
    }

    /// The scalar results as `quantities.csv` rows (docs/compare.md).
    pub fn quantities(&self) -> Vec<(String, f64)> {
        let mut q: Vec<(String, f64)> = [
            ("particles", self.particles as f64),
            ("time", self.time),
            ("steps", self.steps as f64),
            ("kinetic_energy", self.kinetic_energy),
            ("rotational_energy", self.rotational_energy),
            ("stored_energy", self.stored_energy),
            ("external_work", self.external_work),
            ("dissipated_energy", self.dissipated_energy),
            ("contact_count", self.contact_count as f64),
            ("max_overlap_ratio", self.max_overlap_ratio),
        ]
        .into_iter()
        .map(|(k, v)| (k.to_string(), v))
        .collect();
        for w in &self.wall_forces {
            for (axis, f) in ["x", "y", "z"].iter().zip(w.force) {
                q.push((format!("wall_force_{}_{axis}", w.wall), f));
            }
        }
        q
    }
}
