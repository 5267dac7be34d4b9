//! Cross-check against a peer code on a many-body scene, statistically: 2000 spheres
//! placed at random in a laterally periodic column fall onto a floor and settle
//! (hertz, restitution damping, friction, rotation). Two cases share this code:
//! `liggghts_settled_packing` (LIGGGHTS 3.8.0, tangential history) and
//! `lammps_settled_packing` (LAMMPS 22 Jul 2025, `pair granular` mindlin with
//! LAMMPS's lever arms, tamp's `lammps_mindlin`). For each seed both codes start from
//! the same particles (tamp places them; the deck `tamp export-liggghts --seed S` or
//! `tamp export-lammps --seed S` writes carries them to the peer), but a pile of
//! 2000 colliding spheres is chaotic: round-off differences between the codes grow
//! until the two beds are different random packings. So the beds are compared
//! through their statistics, the mean over seeds of each measure, and the
//! difference of the means is judged against the seed-to-seed spread of each code.
//!
//! Measures (the same code on both beds, `liggghts::import::state_measures`):
//! `packing_fraction`, the bulk fraction below the bed's Gibbs surface
//! (`measure::bed`); `coordination_number`, overlapping pairs per particle;
//! `bottom_wall_force_over_weight`, the floor's force on the bed over its weight,
//! averaged over the last 0.1 s (every `FORCE_EVERY` steps from `FORCE_FROM` on, the
//! frames regenerate.sh has the peer dump; peer: from the dumped total forces,
//! `import::mean_floor_force_over_weight`). The bed still rings at 0.5 s: one frame
//! samples a force that fluctuates by ±2.6 % (standard deviation over those frames).
//! The peer's values are `reference_data/<peer>/<case>/results.csv`, one row per
//! seed, written by its `regenerate.sh`. The report gets every seed's values and
//! each code's mean and standard deviation.

use crate::error::{Result, TampError};
use crate::liggghts::import::state_measures;
use crate::measure::sample::mean_sd;
use crate::scene;
use crate::verify::{CaseContext, Measured};
use serde::Deserialize;
use std::fmt::Write as _;

#[derive(Debug, Deserialize)]
struct Row {
    seed: u64,
    packing_fraction: f64,
    coordination_number: f64,
    bottom_wall_force_over_weight: f64,
}

/// The floor force is averaged over steps FORCE_FROM, FORCE_FROM + FORCE_EVERY, …, the
/// last step (t = 0.4–0.5 s at dt = 5 µs; regenerate.sh passes the same numbers).
const FORCE_FROM: u64 = 80_000;
const FORCE_EVERY: u64 = 500;

const MEASURES: [&str; 3] = [
    "packing_fraction",
    "coordination_number",
    "bottom_wall_force_over_weight",
];

/// tamp's three measures of the scene run with `seed`.
fn tamp_measures(base: &scene::Scene, seed: u64) -> Result<[f64; 3]> {
    let mut scene = base.clone();
    scene.seed = seed;
    let built = scene::build(&scene)?;
    let mut sim = built.sim;
    let floor = sim
        .model()
        .walls
        .iter()
        .position(|w| w.name == "floor")
        .ok_or_else(|| TampError::Other("the scene has no wall named 'floor'".into()))?;
    let mut floor_force = Vec::new();
    sim.run_with(built.steps, |s| {
        if s.state().step >= FORCE_FROM && s.state().step % FORCE_EVERY == 0 {
            // wall_force is the force on the wall; the floor pushes the bed the other way.
            floor_force.push(-s.state().wall_force[floor].z);
        }
    })?;
    let p = &sim.state().particles;
    let q = state_measures(
        &p.position,
        &p.radius,
        &p.velocity,
        &sim.model().detection.space,
        true,
        Some(0.0),
    )?;
    let get = |name: &str| q.iter().find(|(n, _)| n == name).map(|(_, v)| *v);
    let g = sim.model().gravity.map_or(0.0, |g| g.norm());
    let weight: f64 = p.mass.iter().sum::<f64>() * g;
    Ok([
        get("packing_fraction").expect("a laterally periodic bed"),
        get("coordination_number").expect("always measured"),
        floor_force.iter().sum::<f64>() / floor_force.len().max(1) as f64 / weight,
    ])
}

/// `liggghts_settled_packing`.
pub fn liggghts(ctx: &CaseContext) -> Result<Vec<Measured>> {
    against(ctx, "liggghts")
}

/// `lammps_settled_packing`.
pub fn lammps(ctx: &CaseContext) -> Result<Vec<Measured>> {
    against(ctx, "lammps")
}

/// The case against the seeds `peer` (`liggghts` or `lammps`) recorded.
fn against(ctx: &CaseContext, peer: &str) -> Result<Vec<Measured>> {
    let rows: Vec<Row> = ctx.peer_results(peer)?;
    if rows.len() < 2 {
        return Err(TampError::Other(
            "results.csv: needs at least two seeds to state a spread".into(),
        ));
    }
    let base = ctx.scene()?;
    let mut tamp_values: Vec<[f64; 3]> = Vec::new();
    for row in &rows {
        tamp_values.push(tamp_measures(&base, row.seed)?);
    }
    let peer_values: Vec<[f64; 3]> = rows
        .iter()
        .map(|r| {
            [
                r.packing_fraction,
                r.coordination_number,
                r.bottom_wall_force_over_weight,
            ]
        })
        .collect();

    let mut csv = String::from("measure,code,seed,value\n");
    let mut summary = format!("measure,tamp_mean,tamp_sd,{peer}_mean,{peer}_sd\n");
    let mut out = Vec::new();
    for (k, name) in MEASURES.iter().enumerate() {
        let t: Vec<f64> = tamp_values.iter().map(|v| v[k]).collect();
        let l: Vec<f64> = peer_values.iter().map(|v| v[k]).collect();
        for (row, (a, b)) in rows.iter().zip(t.iter().zip(&l)) {
            let _ = writeln!(csv, "{name},tamp,{},{a:e}", row.seed);
            let _ = writeln!(csv, "{name},{peer},{},{b:e}", row.seed);
        }
        let ((tm, ts), (lm, ls)) = (mean_sd(&t), mean_sd(&l));
        let _ = writeln!(summary, "{name},{tm:e},{ts:e},{lm:e},{ls:e}");
        out.push(Measured::new(name, tm, lm));
    }
    crate::output::create_dir(&ctx.report_dir)?;
    let name = &ctx.spec.name;
    crate::output::write_atomic(
        &ctx.report_dir.join(format!("{name}_seeds.csv")),
        csv.as_bytes(),
    )?;
    crate::output::write_atomic(
        &ctx.report_dir.join(format!("{name}_spread.csv")),
        summary.as_bytes(),
    )?;
    Ok(out)
}
