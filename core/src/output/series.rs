//! series.csv: one row every `series_every` steps with the requested columns.

use crate::error::{Result, TampError};
use crate::simulation::Simulation;

/// The rows of series.csv: the chosen columns of a run's quantities, sampled every
/// `series_every` steps and kept in memory until the run writes them.
pub struct Series {
    columns: Vec<String>,
    header: Vec<String>,
    /// Recorded rows; a restart checkpoint carries them so a resumed run writes them all.
    pub(crate) rows: Vec<Vec<f64>>,
}

impl Series {
    /// `requested` empty means every column.
    pub fn new(requested: &[String], sim: &Simulation) -> Self {
        let columns: Vec<String> = if requested.is_empty() {
            crate::scene::run::SERIES_COLUMNS
                .iter()
                .map(|s| s.to_string())
                .collect()
        } else {
            requested.to_vec()
        };
        let mut header = vec!["step".to_string(), "time".to_string()];
        for c in &columns {
            if c == "wall_forces" {
                for w in &sim.model.walls {
                    for a in ["x", "y", "z"] {
                        header.push(format!("wall_force_{}_{a}", w.name));
                    }
                }
            } else {
                header.push(c.clone());
            }
        }
        Series {
            columns,
            header,
            rows: Vec::new(),
        }
    }

    /// Append the row of the current state. A value that is not finite (an energy
    /// that overflowed while every position stayed finite) ends the run: exit 3,
    /// naming the column and the step, so no series holds NaN or inf.
    pub fn record(&mut self, sim: &Simulation) -> Result<()> {
        let mut row = vec![sim.state.step as f64, sim.state.time];
        for c in &self.columns {
            match c.as_str() {
                "kinetic_energy" => row.push(sim.state.particles.translational_kinetic_energy()),
                "rotational_energy" => row.push(sim.state.particles.rotational_kinetic_energy()),
                "stored_energy" => row.push(sim.stored_energy()),
                "gravitational_energy" => row.push(sim.gravitational_energy()),
                "external_work" => row.push(sim.state.energy.external_work),
                "dissipated_energy" => row.push(sim.dissipated_energy()),
                "contact_count" => row.push(sim.contact_count() as f64),
                "max_overlap_ratio" => row.push(sim.state.max_overlap_ratio),
                "wall_forces" => sim
                    .state
                    .wall_force
                    .iter()
                    .for_each(|f| row.extend([f.x, f.y, f.z])),
                other => unreachable!("column '{other}' passed validation"),
            }
        }
        if let Some(k) = row.iter().position(|v| !v.is_finite()) {
            return Err(TampError::Unstable {
                step: sim.state.step,
                time: sim.state.time,
                what: format!(
                    "{} is {} (a quantity beyond the range of a double)",
                    self.header[k], row[k]
                ),
            });
        }
        self.rows.push(row);
        Ok(())
    }

    /// series.csv as bytes: the header, then one row per sample in `{:e}` notation, which
    /// reads back to the same double.
    pub fn to_csv(&self) -> Result<Vec<u8>> {
        let mut w = csv::Writer::from_writer(Vec::new());
        let err = |e: csv::Error| TampError::Other(format!("writing series.csv: {e}"));
        w.write_record(&self.header).map_err(err)?;
        for row in &self.rows {
            w.write_record(row.iter().map(|v| super::Sci(*v).to_string()))
                .map_err(err)?;
        }
        w.into_inner()
            .map_err(|e| TampError::Other(format!("writing series.csv: {e}")))
    }
}
