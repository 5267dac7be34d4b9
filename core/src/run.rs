//! `tamp run SCENE --out DIR [--resume]`: build the scene, step it, write the outputs.
//! With `output.checkpoint_every`, the run also writes `DIR/checkpoint.json` on the
//! way; `--resume` goes on from it, and the outputs are then the ones the
//! uninterrupted run writes, byte for byte (see `checkpoint`).

use crate::checkpoint::{self, Checkpoint};
use crate::contact::record::ContactRecord;
use crate::error::{Result, TampError};
use crate::output::{
    self, Provenance,
    series::Series,
    summary::{RunEnd, Summary},
};
use crate::progress::Progress;
use crate::scene;
use crate::simulation::{Simulation, State};
use crate::until::Until;
use serde::{Deserialize, Serialize};
use std::borrow::Cow;
use std::fmt::Write;
use std::path::Path;

/// What a resumed run needs: the simulation's state, and, to write the same files as
/// an uninterrupted run, everything the outputs have accumulated so far. Borrowed
/// when written, so a checkpoint copies neither the state nor the trajectory text.
#[derive(Serialize, Deserialize)]
struct RunState<'a> {
    sim: Cow<'a, State>,
    series_rows: Cow<'a, [Vec<f64>]>,
    trajectory: Cow<'a, str>,
    /// walls.csv so far (empty without `output.walls`).
    #[serde(default, skip_serializing_if = "str::is_empty")]
    walls: Cow<'a, str>,
    vtk_frames: usize,
    /// `run.until`'s unbroken stretch below its thresholds (absent without `until`,
    /// so the checkpoints of other scenes are unchanged).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    settled_since: Option<f64>,
}

/// Append one trajectory.csv row per particle at the current step; `forces` adds the
/// force and torque columns.
fn record_trajectory(sim: &Simulation, out: &mut String, forces: bool) {
    let p = &sim.state.particles;
    for i in 0..p.len() {
        crate::output::run_files::trajectory_row(
            out,
            sim.state.step,
            p.id[i],
            p.radius[i],
            &p.position[i],
            &p.velocity[i],
            &p.omega[i],
        );
        if forces {
            let (f, t) = (p.force[i], p.torque[i]);
            out.pop(); // the row's newline
            let _ = writeln!(
                out,
                ",{:e},{:e},{:e},{:e},{:e},{:e}",
                f.x, f.y, f.z, t.x, t.y, t.z
            );
        }
    }
}

/// Append one walls.csv row per wall at the current step.
fn record_walls(sim: &Simulation, out: &mut String) {
    for (k, (pose, force)) in sim
        .state
        .walls
        .iter()
        .zip(&sim.state.wall_force)
        .enumerate()
    {
        crate::output::run_files::walls_row(out, sim.state.step, k + 1, &pose.displacement, force);
    }
}

fn write_frame(vtk_dir: &Path, index: usize, sim: &Simulation, forces: bool) -> Result<()> {
    let path = vtk_dir.join(format!("frame_{index:06}.vtk"));
    output::write_atomic(&path, output::vtk::to_ascii(sim, forces)?.as_bytes())
}

/// The contact network of the step just taken, as CSV and VTK lines, numbered by
/// step / contacts_every (so a resumed run rewrites the same names).
fn write_contacts(
    dir: &Path,
    every: u64,
    sim: &Simulation,
    records: &[ContactRecord],
) -> Result<()> {
    let name = format!("contacts_{:06}", sim.state.step / every);
    let csv = output::contacts::to_csv(sim, records);
    output::write_atomic(&dir.join(format!("{name}.csv")), csv.as_bytes())?;
    let vtk = output::contacts::to_vtk(sim, records)?;
    output::write_atomic(&dir.join(format!("{name}.vtk")), vtk.as_bytes())
}

/// The files a run writes in its `--out` (VTK frames aside, `vtk/`).
const OUTPUTS: &[&str] = &[
    "summary.json",
    "series.csv",
    "quantities.csv",
    "trajectory.csv",
    "walls.csv",
    CHECKPOINT,
];
const CHECKPOINT: &str = "checkpoint.json";

/// The error of a run stopped by a signal after a whole step: what was kept and the
/// command that goes on from it.
pub fn interrupted(
    signal: i32,
    sim: &Simulation,
    scene_path: &Path,
    out_dir: &Path,
    checkpoint_every: u64,
) -> TampError {
    let next = if checkpoint_every > 0 {
        format!(
            "checkpoint written to {}; go on with `tamp run {} --out {} --resume`",
            out_dir.join(CHECKPOINT).display(),
            scene_path.display(),
            out_dir.display()
        )
    } else {
        "nothing was saved (output.checkpoint_every is 0) and no output was written; set it to make runs resumable".to_string()
    };
    TampError::Interrupted {
        signal,
        step: sim.state.step,
        time: sim.state.time,
        next,
    }
}

/// Run `scene` (read from `scene_path`, whose bytes hash to `sha`) into `out_dir`.
pub fn run_scene(
    scene: &scene::Scene,
    sha: &str,
    scene_path: &Path,
    out_dir: &Path,
    quiet: bool,
    resume: bool,
) -> Result<Summary> {
    let checkpoint_every = scene.output.checkpoint_every;
    crate::checkpoint::require_checkpoints_for_resume(resume, checkpoint_every)?;
    let built = scene::build(scene)?;
    for w in &built.warnings {
        eprintln!("warning: {w}");
    }
    // How the step was chosen is information, not a warning: `--quiet` keeps it off.
    if !quiet {
        for n in &built.notes {
            eprintln!("{n}");
        }
    }
    let mut sim = built.sim;
    let keep: &[&str] = if resume { &[CHECKPOINT] } else { &[] };
    output::claim_dir(out_dir, scene_path, OUTPUTS, keep)?;
    let every = match scene.output.series_every {
        0 => (built.steps / 1000).max(1),
        n => n,
    };
    let trajectory_every = scene.output.trajectory_every;
    let dense_from = scene.output.trajectory_every_step_from;
    let vtk_every = scene.output.vtk_every;
    let vtk_dir = out_dir.join("vtk");
    if vtk_every > 0 {
        output::create_dir(&vtk_dir)?;
    }
    let forces = scene.output.forces;
    let contacts_every = scene.output.contacts_every;
    let contacts_dir = out_dir.join("contacts");
    if contacts_every > 0 {
        output::create_dir(&contacts_dir)?;
    }
    let checkpoint_path = out_dir.join(CHECKPOINT);
    let mut series = Series::new(&scene.output.series, &sim);
    let mut trajectory = String::new();
    let record_wall_rows = scene.output.walls;
    let mut walls = String::new();
    let mut frames = 0usize;
    let mut until = scene.run.until.clone().map(Until::new);
    if resume && checkpoint_path.exists() {
        let saved: Checkpoint<RunState> = checkpoint::read_checkpoint(&checkpoint_path)?;
        if saved.git_commit != crate::GIT_COMMIT {
            eprintln!(
                "warning: {} was written by tamp commit {}, this is {}; if the step changed between them, the resumed run differs from an uninterrupted one",
                checkpoint_path.display(),
                saved.git_commit,
                crate::GIT_COMMIT
            );
        }
        let state = saved.into_state(sha, &checkpoint_path)?;
        sim.resume(state.sim.into_owned())?;
        series.rows = state.series_rows.into_owned();
        trajectory = state.trajectory.into_owned();
        walls = state.walls.into_owned();
        frames = state.vtk_frames;
        if let Some(u) = &mut until {
            u.held_since = state.settled_since;
        }
        eprintln!(
            "resuming from step {} of {} ({})",
            sim.state.step,
            built.steps,
            checkpoint_path.display()
        );
    } else {
        if resume {
            eprintln!(
                "no checkpoint in {}: starting from step 0",
                out_dir.display()
            );
        }
        series.record(&sim)?;
        if trajectory_every > 0 {
            trajectory.push_str(crate::output::run_files::TRAJECTORY_HEADER);
            if forces {
                trajectory.push_str(crate::output::run_files::TRAJECTORY_FORCE_COLUMNS);
            }
            trajectory.push('\n');
            record_trajectory(&sim, &mut trajectory, forces);
        }
        if record_wall_rows {
            walls.push_str(crate::output::run_files::WALLS_HEADER);
            walls.push('\n');
            record_walls(&sim, &mut walls);
        }
        if vtk_every > 0 {
            // Frames of an earlier run must not mix with this one's. A resumed run
            // keeps them: they are its own, and it rewrites those past the checkpoint.
            output::vtk::remove_frames(&vtk_dir)?;
            write_frame(&vtk_dir, frames, &sim, forces)?;
            frames += 1;
        }
        if contacts_every > 0 {
            // Likewise the contact files (a resumed run rewrites those past the checkpoint).
            output::vtk::remove_numbered(&contacts_dir, "contacts_", &[".csv", ".vtk"])?;
        }
    }

    let mut progress = Progress::new("steps", built.steps, quiet);
    progress.set(sim.state.step);
    let mut settled = false;
    while sim.state.step < built.steps && !settled {
        if contacts_every > 0 && (sim.state.step + 1) % contacts_every == 0 {
            let records = sim.step_recording_contacts()?;
            write_contacts(&contacts_dir, contacts_every, &sim, &records)?;
        } else {
            sim.step()?;
        }
        if let Some(u) = &mut until {
            settled = u.settled(&sim);
        }
        let last = settled || sim.state.step == built.steps;
        if sim.state.step % every == 0 {
            series.record(&sim)?;
        }
        let dense = dense_from.is_some_and(|from| sim.state.step >= from);
        if trajectory_every > 0 && (sim.state.step % trajectory_every == 0 || last || dense) {
            record_trajectory(&sim, &mut trajectory, forces);
            if record_wall_rows {
                record_walls(&sim, &mut walls);
            }
        }
        if vtk_every > 0 && sim.state.step % vtk_every == 0 {
            write_frame(&vtk_dir, frames, &sim, forces)?;
            frames += 1;
        }
        let signal = crate::interrupt::received();
        if checkpoint_every > 0 && (sim.state.step % checkpoint_every == 0 || signal.is_some()) {
            let state = RunState {
                sim: Cow::Borrowed(&sim.state),
                series_rows: Cow::Borrowed(&series.rows),
                trajectory: Cow::Borrowed(&trajectory),
                walls: Cow::Borrowed(&walls),
                vtk_frames: frames,
                settled_since: until.as_ref().and_then(|u| u.held_since),
            };
            checkpoint::write_checkpoint(&checkpoint_path, &Checkpoint::new(sha, state))?;
        }
        if let Some(signal) = signal {
            progress.finish();
            return Err(interrupted(
                signal,
                &sim,
                scene_path,
                out_dir,
                checkpoint_every,
            ));
        }
        if sim.state.step % 256 == 0 {
            progress.set(sim.state.step);
        }
    }
    progress.finish();
    sim.check_energy_at_end()?;
    if sim.state.step % every != 0 {
        series.record(&sim)?;
    }
    let provenance = Provenance::new(
        sha.to_string(),
        scene.seed,
        sim.state.dt,
        built.dt_estimate,
        built.steps,
    );
    let mut summary = Summary::new(&sim, provenance, &scene.name, built.warnings);
    if let Some(u) = &until {
        let criterion = match (settled, scene.run.steps) {
            (true, _) => "run.until",
            (false, Some(_)) => "run.steps",
            (false, None) => "run.duration",
        };
        let r = crate::until::reading(&sim);
        eprintln!(
            "{criterion} ended the run at t = {:e} s (step {}): kinetic energy per particle {:e} J (run.until: below {:e} J{} for {:e} s), largest speed {:e} m/s",
            sim.state.time,
            sim.state.step,
            r.kinetic_energy_per_particle,
            u.spec.kinetic_energy_per_particle,
            u.spec
                .max_speed
                .map_or(String::new(), |v| format!(" and speeds below {v:e} m/s")),
            u.spec.held_for,
            r.max_speed
        );
        summary.ended_by = Some(RunEnd {
            criterion,
            time: sim.state.time,
            step: sim.state.step,
            kinetic_energy_per_particle: r.kinetic_energy_per_particle,
            max_speed: r.max_speed,
        });
    }
    if let Some((name, value)) = summary
        .quantities()
        .into_iter()
        .find(|(_, v)| !v.is_finite())
    {
        return Err(TampError::Unstable {
            step: sim.state.step,
            time: sim.state.time,
            what: format!(
                "the summary's {name} is {value} (a quantity beyond the range of a double)"
            ),
        });
    }
    output::write_atomic(&out_dir.join("series.csv"), &series.to_csv()?)?;
    let json = output::json_bytes(&summary);
    output::write_atomic(&out_dir.join("summary.json"), &json)?;
    output::write_atomic(
        &out_dir.join("quantities.csv"),
        crate::output::run_files::quantities_csv(&summary.quantities()).as_bytes(),
    )?;
    if trajectory_every > 0 {
        output::write_atomic(&out_dir.join("trajectory.csv"), trajectory.as_bytes())?;
    }
    if record_wall_rows {
        output::write_atomic(&out_dir.join("walls.csv"), walls.as_bytes())?;
    }
    Ok(summary)
}
