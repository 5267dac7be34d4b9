//! LAMMPS's tableting example under MDR, in tamp and in LAMMPS 22 Jul 2025:
//! `examples/granular/in.tableting.200` as a tamp scene (its 200 spheres in a 4 mm die,
//! adhesive MDR particles in non-adhesive walls, LAMMPS's linear history and rolling
//! sds, gravity, the punches' staged sine strokes), run here and, as the deck `tamp
//! export-lammps` writes from the same scene, by LAMMPS
//! (reference_data/lammps/lammps_mdr_tableting, `regenerate.sh`).
//!
//! Two hundred spheres pressed to a relative density near 0.9 are chaotic: the two runs
//! are equal to round-off for the first thousand steps, then part as any one-ulp change
//! of the initial positions makes either code part from itself, and are different
//! samples of the same press from about step 7000. The case therefore compares the
//! press's macroscopic record, each code's from its own run: the upper punch's force at
//! full stroke and at release, the force on the floor under the powder (the lower punch
//! and the die's lower end, one plane) at full stroke, the die wall's axial (friction)
//! force at full stroke, and the particles' mean apparent radius at the end, the
//! plastic flow MDR has spread. Each tolerance is three times the combined
//! standard deviation of the value over runs of both codes with every initial x moved by
//! a few ulps (docs/models/mdr.md). The recorded deck must be the one tamp exports from
//! the scene now (the same lines but comments).

use crate::compare::read_walls;
use crate::error::{Result, TampError};
use crate::verify::recording::RecordSpec;
use crate::verify::{CaseContext, Measured};
use serde::Deserialize;

/// The z force on a wall (its index) at a step, in one code's record, N.
type WallForce<'a> = &'a dyn Fn(u64, usize) -> Result<f64>;

/// The case file's parameters.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct Parameters {
    /// The step at which the upper punch is deepest.
    full_stroke_step: u64,
    /// A step of the upper punch's withdrawal.
    release_step: u64,
}

/// One row of `final.csv`: a particle at LAMMPS's last step.
#[derive(Debug, Deserialize)]
struct FinalRow {
    #[allow(dead_code)]
    id: u64,
    radius: f64,
}

pub fn run(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let p: Parameters = ctx.parameters()?;
    let scene = ctx.scene()?;
    let recorded = ctx.reference_data_dir().join("lammps").join(&ctx.spec.name);

    // The record is of this scene's deck as tamp exports it now.
    super::recorded_deck::check(ctx, &scene, &recorded)?;

    let wall = |name: &str| {
        scene
            .walls
            .iter()
            .position(|w| w.name.as_deref() == Some(name))
            .ok_or_else(|| TampError::Other(format!("the scene has no wall '{name}'")))
    };
    let (upper, lower, die, floor) = (
        wall("upper_punch")?,
        wall("lower_punch")?,
        wall("die")?,
        wall("die_bottom")?,
    );
    let ours = ctx.record(
        "tableting",
        &scene,
        RecordSpec::every(scene.output.trajectory_every, false).with_walls(),
    )?;
    let theirs = read_walls(&recorded.join("walls.csv"))?;
    // The z force on wall `w` at `step`, in each code's record (the force the particles
    // exert on the wall).
    let our_fz = |step: u64, w: usize| {
        ours.frames
            .iter()
            .find(|f| f.step == step)
            .map(|f| f.walls[w].force.z)
            .ok_or_else(|| TampError::Other(format!("tamp recorded no step {step}")))
    };
    let their_fz = |step: u64, w: usize| {
        theirs
            .get(&(step, w as u64 + 1))
            .map(|row| row.force.z)
            .ok_or_else(|| {
                TampError::Other(format!(
                    "{}: no row for step {step} and wall {}",
                    recorded.join("walls.csv").display(),
                    w + 1
                ))
            })
    };
    let (full, release) = (p.full_stroke_step, p.release_step);
    // The press's record in one code: the upper punch at full stroke, the floor (the
    // lower punch and the die's lower end) at full stroke, the die wall at full stroke,
    // the upper punch at release.
    let record = |fz: WallForce| -> Result<[f64; 4]> {
        Ok([
            fz(full, upper)?,
            fz(full, lower)? + fz(full, floor)?,
            fz(full, die)?,
            fz(release, upper)?,
        ])
    };
    let (mine, peer) = (record(&our_fz)?, record(&their_fz)?);

    let path = recorded.join("final.csv");
    let bad = |what: String| TampError::Other(format!("{}: {what}", path.display()));
    let rows: Vec<FinalRow> = crate::verify::read_csv(&path)?;
    let last = ours
        .frames
        .last()
        .ok_or_else(|| TampError::Other("tamp recorded no frame".into()))?;
    if rows.len() != last.bodies.len() {
        return Err(bad(format!(
            "{} particles, tamp's run has {}",
            rows.len(),
            last.bodies.len()
        )));
    }
    let mean = |r: &mut dyn Iterator<Item = f64>| {
        let (sum, n) = r.fold((0.0, 0.0), |(s, n), x| (s + x, n + 1.0));
        sum / n
    };
    let our_radius = mean(&mut last.bodies.iter().map(|b| b.radius));
    let their_radius = mean(&mut rows.iter().map(|r| r.radius));

    let names = [
        "upper_punch_force_full_stroke",
        "floor_force_full_stroke",
        "die_friction_full_stroke",
        "upper_punch_force_release",
    ];
    let mut out: Vec<Measured> = names
        .iter()
        .zip(mine.iter().zip(&peer))
        .map(|(name, (&ours, &theirs))| Measured::new(name, ours, theirs))
        .collect();
    out.push(Measured::new(
        "mean_apparent_radius_end",
        our_radius,
        their_radius,
    ));
    Ok(out)
}
