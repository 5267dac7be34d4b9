//! `tamp run SCENE --out DIR`: build the scene, step it, write the outputs.

use crate::error::Result;
use crate::output::{self, Provenance, series::Series, summary::Summary};
use crate::scene;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::io::IsTerminal;
use std::path::Path;
use std::time::{Duration, Instant};

pub fn run_scene(scene_path: &Path, out_dir: &Path, quiet: bool) -> Result<Summary> {
    let (scene, sha) = scene::load(scene_path)?;
    let built = scene::build(&scene)?;
    for w in &built.warnings {
        eprintln!("warning: {w}");
    }
    let mut sim = built.sim;
    output::create_dir(out_dir)?;
    let every = match scene.output.series_every {
        0 => (built.steps / 1000).max(1),
        n => n,
    };
    let mut series = Series::new(&scene.output.series, &sim);
    series.record(&sim);
    let vtk_dir = out_dir.join("vtk");
    if scene.output.vtk_every > 0 {
        output::create_dir(&vtk_dir)?;
        output::vtk::remove_frames(&vtk_dir)?;
    }
    let trajectory_every = scene.output.trajectory_every;
    let mut trajectory = String::new();
    let record_trajectory = |sim: &crate::simulation::Simulation, out: &mut String| {
        let p = &sim.particles;
        for i in 0..p.len() {
            crate::compare::trajectory_row(
                out,
                sim.step,
                i as u64 + 1,
                p.radius[i],
                &p.position[i],
                &p.velocity[i],
                &p.omega[i],
            );
        }
    };
    if trajectory_every > 0 {
        trajectory.push_str(crate::compare::TRAJECTORY_HEADER);
        trajectory.push('\n');
        record_trajectory(&sim, &mut trajectory);
    }
    let mut frames = 0usize;
    let mut write_frame = |sim: &crate::simulation::Simulation| -> Result<()> {
        let path = vtk_dir.join(format!("frame_{frames:06}.vtk"));
        frames += 1;
        output::write_atomic(&path, output::vtk::to_ascii(sim)?.as_bytes())
    };
    if scene.output.vtk_every > 0 {
        write_frame(&sim)?;
    }

    // The bar appears only for runs longer than a second on an interactive terminal.
    let bar = ProgressBar::with_draw_target(Some(built.steps), ProgressDrawTarget::hidden());
    bar.set_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} steps  {elapsed} elapsed, ETA {eta}")
            .expect("static template"),
    );
    let show_bar = !quiet && std::io::stderr().is_terminal();
    let started = Instant::now();
    let mut shown = false;
    for _ in 0..built.steps {
        sim.step()?;
        if sim.step % every == 0 {
            series.record(&sim);
        }
        if trajectory_every > 0 && (sim.step % trajectory_every == 0 || sim.step == built.steps) {
            record_trajectory(&sim, &mut trajectory);
        }
        if scene.output.vtk_every > 0 && sim.step % scene.output.vtk_every == 0 {
            write_frame(&sim)?;
        }
        if sim.step % 256 == 0 {
            if show_bar && !shown && started.elapsed() > Duration::from_secs(1) {
                bar.set_draw_target(ProgressDrawTarget::stderr());
                shown = true;
            }
            bar.set_position(sim.step);
        }
    }
    bar.finish_and_clear();
    if sim.step % every != 0 {
        series.record(&sim);
    }
    let provenance = Provenance::new(sha, scene.seed, sim.dt, built.dt_estimate, built.steps);
    let summary = Summary::new(&sim, provenance, &scene.name, built.warnings);
    output::write_atomic(&out_dir.join("series.csv"), &series.to_csv()?)?;
    let json = serde_json::to_vec_pretty(&summary).expect("summary serialises");
    output::write_atomic(&out_dir.join("summary.json"), &json)?;
    output::write_atomic(
        &out_dir.join("quantities.csv"),
        crate::compare::quantities_csv(&summary.quantities()).as_bytes(),
    )?;
    if trajectory_every > 0 {
        output::write_atomic(&out_dir.join("trajectory.csv"), trajectory.as_bytes())?;
    }
    Ok(summary)
}
