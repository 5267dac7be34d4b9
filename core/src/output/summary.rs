//! summary.json: provenance plus the final quantities of a run.

use super::Provenance;
use crate::simulation::Simulation;
use serde::Serialize;

#[derive(Debug, Serialize)]
pub struct Summary {
    pub provenance: Provenance,
    pub scene_name: String,
    pub particles: usize,
    pub time: f64,
    pub steps: u64,
    pub kinetic_energy: f64,
    pub rotational_energy: f64,
    pub stored_energy: f64,
    pub external_work: f64,
    pub dissipated_energy: f64,
    pub contact_count: usize,
    pub max_overlap_ratio: f64,
    pub neighbor_list_builds: u64,
    pub wall_forces: Vec<WallForce>,
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
    pub criterion: &'static str,
    pub time: f64,
    pub step: u64,
    pub kinetic_energy_per_particle: f64,
    pub max_speed: f64,
}

#[derive(Debug, Serialize)]
pub struct WallForce {
    pub wall: String,
    pub force: [f64; 3],
}

impl Summary {
    pub fn new(
        sim: &Simulation,
        provenance: Provenance,
        scene_name: &str,
        warnings: Vec<String>,
    ) -> Self {
        Summary {
            provenance,
            scene_name: scene_name.to_string(),
            particles: sim.particles.len(),
            time: sim.time,
            steps: sim.step,
            kinetic_energy: sim.particles.translational_kinetic_energy(),
            rotational_energy: sim.particles.rotational_kinetic_energy(),
            stored_energy: sim.stored_energy(),
            external_work: sim.external_work,
            dissipated_energy: sim.dissipated_energy(),
            contact_count: sim.contact_count(),
            max_overlap_ratio: sim.max_overlap_ratio,
            neighbor_list_builds: sim.neighbors.builds,
            wall_forces: sim
                .walls
                .iter()
                .zip(&sim.wall_force)
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
