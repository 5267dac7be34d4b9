//! Cross-check against LAMMPS 22 Jul 2025 (`lammps_moving_wall`), trajectory by
//! trajectory: soft spheres among walls that move (a plane, a cylinder sliding along its
//! axis), with the normal, damping, tangential and torque terms of sphere and wall
//! contacts all acting.
//!
//! The deck is the one `tamp export-liggghts` / `tamp export-lammps` writes for this
//! case's scene (`reference_data/<peer>/run_exported.sh`); the peer's dump, converted to
//! tamp's run layout, is `reference_data/<peer>/<case>/trajectory.csv`. The case refuses
//! to compare when the recorded deck was exported from another version of the scene
//! (the scene's SHA-256 is in the deck's header). Deviations are measured as
//! `tamp compare` measures them (docs/compare.md): position in units of the particle
//! radius, velocity and spin against the particle's largest value over the run.

use crate::compare::{self, Run};
use crate::error::{Result, TampError};
use crate::scene;
use crate::verify::{CaseContext, Measured};
use std::collections::BTreeMap;

pub fn run(ctx: &CaseContext) -> Result<Vec<Measured>> {
    // The peer is the case name's prefix (LAMMPS's dump is converted by
    // `import-liggghts-dump`, reference_data/lammps/run_exported.sh).
    let peer = ctx.spec.name.split('_').next().unwrap_or_default();
    let recorded = ctx.reference_data_dir().join(peer).join(&ctx.spec.name);
    let scene_file = ctx
        .spec
        .scene
        .as_ref()
        .ok_or_else(|| TampError::Other(format!("case {} names no scene", ctx.spec.name)))?;
    let (scene, sha) = scene::load(&ctx.dir.join(scene_file))?;
    let deck_path = recorded.join("deck").join("in.tamp");
    let deck = std::fs::read_to_string(&deck_path)
        .map_err(|e| TampError::io(format!("reading {}", deck_path.display()), e))?;
    if !deck.contains(&format!("sha256 {sha}")) {
        return Err(TampError::Other(format!(
            "{} was exported from another version of {scene_file} (sha256 {sha}): re-record with regenerate.sh",
            deck_path.display()
        )));
    }
    let reference = compare::load(&recorded.join("trajectory.csv"))?;

    let every = scene.output.trajectory_every.max(1);
    let built = scene::build(&scene)?;
    let mut sim = built.sim;
    let mut mine = Run::default();
    mine.record(&sim);
    for _ in 0..built.steps {
        sim.step()?;
        if sim.state.step % every == 0 || sim.state.step == built.steps {
            mine.record(&sim);
        }
    }
    if mine.trajectory.len() != reference.trajectory.len() {
        return Err(TampError::Other(format!(
            "tamp recorded {} (step, particle) rows, {peer} {}: the runs do not cover the same steps",
            mine.trajectory.len(),
            reference.trajectory.len()
        )));
    }
    let comparison = compare::compare(&mine, &reference, &BTreeMap::new());
    crate::output::create_dir(&ctx.report_dir)?;
    crate::output::write_atomic(
        &ctx.report_dir.join(format!("{}.txt", ctx.spec.name)),
        comparison.report().as_bytes(),
    )?;
    let worst = |item: &str| {
        comparison
            .deviations
            .iter()
            .find(|d| d.name == item)
            .map(|d| d.deviation)
            .ok_or_else(|| TampError::Other(format!("no {item} in the recorded trajectory")))
    };
    Ok(vec![
        Measured::new("max_position_deviation", worst("position")?, 0.0),
        Measured::new("max_velocity_deviation", worst("velocity")?, 0.0),
        Measured::new("max_angular_velocity_deviation", worst("omega")?, 0.0),
    ])
}
