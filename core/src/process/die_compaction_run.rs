//! `tamp run` of a die-compaction scene: the three stages, then the records.
//!
//! Writes the layout of every `tamp run` (docs/compare.md), each file atomically:
//! - `series.csv`: one row per record along the pressure ramp (`PressRecord`), or, with
//!   a press cycle, one per record of every stage (`press_cycle::series_csv`);
//! - `cycle.svg`: with a press cycle, its curves (written by `tamp run` itself);
//! - `quantities.csv`: the summary's numbers as `quantity,value` rows;
//! - `press.scene.json`: the press stage as an ordinary scene (the flattened
//!   specimen as explicit particles, the pressure-loaded punch), to rerun the
//!   pressing alone or with another contact law;
//! - `summary.json`: provenance, `scene_name`, the specimen (H₀, both initial
//!   densities, the fill) and the last record;
//! - `specimen.json`: the flattened specimen, written when flattening ends;
//! - `checkpoint.json`: the pressing's state every `output.checkpoint_every` steps.
//!
//! With `--resume`, a run goes on from `checkpoint.json` (or, when the pressing had
//! not reached its first checkpoint, from `specimen.json`) and writes the same files
//! as the uninterrupted run, byte for byte (`tests/die_compaction.rs`). Filling and
//! flattening are not checkpointed inside: they are the short stages.

use super::die_compaction::{self, PressRecord, PressState, Specimen};
use super::press_cycle::{self, CycleRecord, CycleSummary};
use crate::checkpoint::{self, Checkpoint};
use crate::error::{Result, TampError};
use crate::output::{self, Provenance};
use serde::Serialize;
use std::path::Path;

/// summary.json of a die-compaction run: the flattened specimen and the last record of
/// the pressing.
#[derive(Debug, Serialize)]
pub struct CompactionSummary {
    /// Where the result came from (Δt and steps are the pressing's).
    pub provenance: Provenance,
    /// The scene's `name`.
    pub scene_name: String,
    /// Number of particles in the die.
    pub particles: usize,
    /// Height H₀ of the flattened specimen (top of the highest particle), m.
    pub h0: f64,
    /// Solid fraction of the die cylinder of height H₀ before pressing.
    pub initial_density_specimen: f64,
    /// Solid fraction of the RVE sphere before pressing.
    pub initial_density_rve: f64,
    /// Simulated settling time of the fill, s.
    pub fill_time: f64,
    /// Whether the bed came to rest before `fill.max_duration`.
    pub fill_at_rest: bool,
    /// Steps the pressing took.
    pub press_steps: u64,
    /// The record at the full pressure.
    pub last: PressRecord,
    /// The press cycle after the peak, when the file asks for one.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cycle: Option<CycleOutcome>,
}

/// What the press cycle after the peak measured, in summary.json.
#[derive(Debug, Serialize)]
pub struct CycleOutcome {
    /// Steps since the pressing began, at the cycle's last record.
    pub steps: u64,
    /// The cycle's measures (`press_cycle::CycleSummary`).
    #[serde(flatten)]
    pub summary: CycleSummary,
    /// The records, which series.csv holds; not in summary.json.
    #[serde(skip)]
    pub records: Vec<CycleRecord>,
}

/// Run the die-compaction file `scene` (read from `scene_path`, whose bytes hash to
/// `sha`) into `out_dir`.
pub fn run_scene(
    file: &super::die_compaction_file::DieCompactionFile,
    sha: &str,
    scene_path: &Path,
    out_dir: &Path,
    quiet: bool,
    resume: bool,
) -> Result<CompactionSummary> {
    let every = file.scene.output.checkpoint_every;
    crate::checkpoint::require_checkpoints_for_resume(resume, every)?;
    // The specimen and the checkpoint are what a resumed run starts from.
    let keep: &[&str] = if resume {
        &["specimen.json", "checkpoint.json"]
    } else {
        &[]
    };
    output::claim_dir(
        out_dir,
        scene_path,
        &[
            "specimen.json",
            "checkpoint.json",
            "press.scene.json",
            "series.csv",
            "quantities.csv",
            "summary.json",
            "cycle.svg",
        ],
        keep,
    )?;
    let specimen_path = out_dir.join("specimen.json");
    let checkpoint_path = out_dir.join("checkpoint.json");
    let specimen: Specimen = if resume && specimen_path.exists() {
        let saved: Checkpoint<Specimen> = checkpoint::read_checkpoint(&specimen_path)?;
        eprintln!(
            "resuming from the flattened specimen in {}",
            specimen_path.display()
        );
        saved.into_state(sha, &specimen_path)?
    } else {
        let specimen = die_compaction::prepare(file, quiet)?;
        if every > 0 {
            checkpoint::write_checkpoint(&specimen_path, &Checkpoint::new(sha, &specimen))?;
        }
        specimen
    };
    let press_scene = die_compaction::press_scene(file, &specimen)?;
    let json = serde_json::to_vec_pretty(&press_scene).expect("scene serialises");
    output::write_atomic(&out_dir.join("press.scene.json"), &json)?;
    let state: Option<PressState> = if resume && checkpoint_path.exists() {
        let saved: Checkpoint<PressState> = checkpoint::read_checkpoint(&checkpoint_path)?;
        let state = saved.into_state(sha, &checkpoint_path)?;
        eprintln!(
            "resuming the pressing from step {} ({})",
            state.pressing.steps,
            checkpoint_path.display()
        );
        Some(state)
    } else {
        None
    };
    let mut write = |state: &PressState| {
        checkpoint::write_checkpoint(&checkpoint_path, &Checkpoint::new(sha, state))
    };
    let (pressing, sim) = die_compaction::press(file, &specimen, quiet, state, every, &mut write)
        .map_err(|e| match e {
        TampError::Interrupted {
            signal,
            step,
            time,
            next,
        } if every > 0 => TampError::Interrupted {
            signal,
            step,
            time,
            next: format!(
                "{next}; go on with `tamp run {} --out {} --resume`",
                scene_path.display(),
                out_dir.display()
            ),
        },
        other => other,
    })?;
    let cycle = match file.die_compaction.unload {
        Some(_) => Some(press_cycle::run(
            file,
            &specimen,
            &pressing,
            sim,
            press_scene.time_step.fixed,
            quiet,
        )?),
        None => None,
    };
    let series = match &cycle {
        Some(cycle) => press_cycle::series_csv(&cycle.records).into_bytes(),
        None => {
            let mut csv = csv::Writer::from_writer(Vec::new());
            for r in &pressing.records {
                csv.serialize(r)
                    .map_err(|e| TampError::Other(format!("series.csv: {e}")))?;
            }
            csv.into_inner()
                .map_err(|e| TampError::Other(format!("series.csv: {e}")))?
        }
    };
    output::write_atomic(&out_dir.join("series.csv"), &series)?;
    let last = pressing
        .records
        .last()
        .expect("at least two records")
        .clone();
    let summary = CompactionSummary {
        provenance: Provenance::new(
            sha.to_string(),
            file.scene.seed,
            last.dt,
            None,
            pressing.steps,
        ),
        scene_name: file.scene.name.clone(),
        particles: specimen.particles.len(),
        h0: specimen.h0,
        initial_density_specimen: specimen.density_specimen,
        initial_density_rve: specimen.density_rve,
        fill_time: specimen.fill_time,
        fill_at_rest: specimen.fill_at_rest,
        press_steps: pressing.steps,
        last,
        cycle: cycle.map(|c| CycleOutcome {
            steps: c.records.last().map_or(pressing.steps, |r| r.step),
            summary: c.summary,
            records: c.records,
        }),
    };
    let json = crate::output::json_bytes(&summary);
    output::write_atomic(&out_dir.join("summary.json"), &json)?;
    output::write_atomic(
        &out_dir.join("quantities.csv"),
        crate::output::run_files::quantities_csv(&summary.quantities()).as_bytes(),
    )?;
    Ok(summary)
}

impl CompactionSummary {
    /// The numbers of the summary by name, as `quantities.csv` lists them for
    /// `tamp compare`: the specimen's, then the last record's as `final_*`.
    pub fn quantities(&self) -> Vec<(String, f64)> {
        let l = &self.last;
        [
            ("particles", self.particles as f64),
            ("h0", self.h0),
            ("initial_density_specimen", self.initial_density_specimen),
            ("initial_density_rve", self.initial_density_rve),
            ("fill_time", self.fill_time),
            ("press_steps", self.press_steps as f64),
            ("final_pressure", l.pressure),
            ("final_punch_reaction", l.punch_reaction),
            ("final_floor_reaction", l.floor_reaction),
            ("final_die_friction", l.die_friction),
            ("final_height", l.height),
            ("final_height_reduction", l.height_reduction),
            ("final_density_specimen", l.density_specimen),
            ("final_density_rve", l.density_rve),
            ("final_contact_count", l.contact_count as f64),
        ]
        .into_iter()
        .map(|(name, value)| (name.to_string(), value))
        .chain(self.cycle.iter().flat_map(|c| c.summary.quantities()))
        .collect()
    }
}
