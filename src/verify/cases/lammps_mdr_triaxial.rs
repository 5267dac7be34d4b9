//! Twelve spheres pressed by six walls under MDR, in tamp and in LAMMPS 22 Jul 2025:
//! LAMMPS's `examples/granular/in.triaxial.compaction.12` as a tamp scene, run here
//! and, as the deck `tamp export-lammps` writes from the same scene, by LAMMPS
//! (reference_data/lammps/lammps_mdr_triaxial, `regenerate.sh`).
//!
//! Both runs record every particle (apparent radius, position, velocity) and every wall
//! (displacement, the force the particles exert on it) at the same steps; the case
//! compares them frame by frame: the largest difference in position over the radius,
//! in apparent radius, in velocity over the walls' speed, in wall force over the
//! largest wall force of the run, in wall displacement over the walls' travel and in
//! free-surface fraction ψ (`fix granular/mdr`'s, from the deck's `mdr.lammps`), and
//! the last frame's force on the lower z wall. The recorded deck must be the one
//! tamp exports from the scene now (the same lines but comments), so the record
//! cannot belong to another scene or another exporter.

use crate::compare::{read_trajectory, read_walls};
use crate::error::{Result, TampError};
use crate::verify::recording::RecordSpec;
use crate::verify::{CaseContext, Measured};
use serde::Deserialize;

/// The wall whose last force is reported: the plane z = −1.5 m moving up
/// (`walls[5]`, `plane_xy_neg`, LAMMPS's example prints its force).
const LOWER_Z_WALL: usize = 5;

pub fn run(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let scene = ctx.scene()?;
    let recorded = ctx.reference_data_dir().join("lammps").join(&ctx.spec.name);

    // The record is of this scene's deck as tamp exports it now.
    super::recorded_deck::check(ctx, &scene, &recorded)?;

    let theirs = read_trajectory(&recorded.join("trajectory.csv"))?;
    let their_walls = read_walls(&recorded.join("walls.csv"))?;
    let every = scene.output.trajectory_every;
    let ours = ctx.record(
        "triaxial",
        &scene,
        RecordSpec::every(every, false).with_walls(),
    )?;

    let speed = scene
        .walls
        .iter()
        .map(|w| match &w.motion {
            crate::scene::walls::MotionSpec::Velocity { velocity } => {
                velocity.iter().fold(0.0_f64, |m, v| m.max(v.abs()))
            }
            _ => 0.0,
        })
        .fold(0.0_f64, f64::max);
    let last = ours.frames.last().map_or(0, |f| f.step);
    let travel = speed * last as f64 * ours.dt;
    let peak_force = their_walls
        .values()
        .map(|w| w.force.norm())
        .fold(0.0_f64, f64::max);

    let (mut position, mut radius, mut velocity) = (0.0_f64, 0.0_f64, 0.0_f64);
    let (mut force, mut displacement) = (0.0_f64, 0.0_f64);
    let mut frames = 0;
    for frame in &ours.frames {
        for (k, body) in frame.bodies.iter().enumerate() {
            let id = k as u64 + 1;
            let Some(them) = theirs.get(&(frame.step, id)) else {
                return Err(TampError::Other(format!(
                    "{}: no row for step {} and particle {id}, which tamp recorded",
                    recorded.join("trajectory.csv").display(),
                    frame.step
                )));
            };
            position = position.max((body.position - them.position).norm() / them.radius);
            radius = radius.max((body.radius - them.radius).abs() / them.radius);
            let v = them.velocity.ok_or_else(|| {
                TampError::Other(format!(
                    "{}: no velocities",
                    recorded.join("trajectory.csv").display()
                ))
            })?;
            velocity = velocity.max((body.velocity - v).norm() / speed);
        }
        for (k, wall) in frame.walls.iter().enumerate() {
            let Some(them) = their_walls.get(&(frame.step, k as u64 + 1)) else {
                return Err(TampError::Other(format!(
                    "{}: no row for step {} and wall {}, which tamp recorded",
                    recorded.join("walls.csv").display(),
                    frame.step,
                    k + 1
                )));
            };
            force = force.max((wall.force - them.force).norm() / peak_force);
            displacement =
                displacement.max((wall.displacement - them.displacement).norm() / travel);
        }
        frames += 1;
    }
    if frames * scene.walls.len() != their_walls.len() {
        return Err(TampError::Other(format!(
            "{}: {} rows, tamp recorded {frames} frames of {} walls",
            recorded.join("walls.csv").display(),
            their_walls.len(),
            scene.walls.len()
        )));
    }
    let free_surface = free_surface_difference(&scene, &recorded.join("free_surface.csv"))?;
    let lower = |f: &crate::verify::recording::Frame| f.walls[LOWER_Z_WALL].force.z;
    let our_last = ours.frames.last().map(lower).unwrap_or_default();
    let their_last = their_walls
        .get(&(last, LOWER_Z_WALL as u64 + 1))
        .map_or(f64::NAN, |w| w.force.z);

    Ok(vec![
        Measured::new("position_difference", position, 0.0),
        Measured::new("radius_difference", radius, 0.0),
        Measured::new("velocity_difference", velocity, 0.0),
        Measured::new("wall_force_difference", force, 0.0),
        Measured::new("wall_displacement_difference", displacement, 0.0),
        Measured::new("free_surface_difference", free_surface, 0.0),
        Measured::new("lower_wall_force", our_last, their_last),
    ])
}

/// One row of LAMMPS's free-surface fractions (`free_surface.csv`).
#[derive(Debug, Deserialize)]
struct FreeSurface {
    step: u64,
    id: u64,
    free_surface: f64,
}

/// The largest difference between LAMMPS's free-surface fraction ψ of each particle at
/// each recorded step and tamp's (`MdrParticles::free_surface`, from a run of the
/// scene stepped here: an engine's recording carries no MDR state).
fn free_surface_difference(scene: &crate::scene::Scene, path: &std::path::Path) -> Result<f64> {
    let bad = |what: String| TampError::Other(format!("{}: {what}", path.display()));
    let mut rows: Vec<FreeSurface> = crate::verify::read_csv(path)?;
    rows.sort_by_key(|r| (r.step, r.id));
    let mut sim = crate::scene::build(scene)?.sim;
    let mut largest = 0.0_f64;
    for row in &rows {
        while sim.state().step < row.step {
            sim.step()?;
        }
        if sim.state().step != row.step {
            return Err(bad(format!("step {} is past the run's last", row.step)));
        }
        let p = &sim.state().particles;
        let i = (0..p.len())
            .find(|&i| p.id[i] == row.id)
            .ok_or_else(|| bad(format!("no particle {} in the scene", row.id)))?;
        let ours = sim
            .state()
            .mdr
            .as_ref()
            .map_or(f64::NAN, |m| m.free_surface[i]);
        largest = largest.max((ours - row.free_surface).abs());
    }
    if rows.is_empty() {
        return Err(bad("no rows".into()));
    }
    Ok(largest)
}
