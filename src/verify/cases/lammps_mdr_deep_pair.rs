//! An MDR pair pressed until one side's share of the overlap passes the cap a side may
//! have, then held still, in tamp and in LAMMPS 22 Jul 2025
//! (reference_data/lammps/lammps_mdr_deep_pair, `in.deep`).
//!
//! A 1 µm sphere is pressed by a 3 µm one to a pair overlap of 1.3 µm. At the
//! intersection plane the small sphere's cap height would be
//! δ_max (2R − δ_max)/(2(r + R − δ_max)) = 1.13 r, so its side passes 0.75 r (where a
//! version of LAMMPS's source caps the force's split) and 0.95 r (where LAMMPS 22 Jul
//! 2025 caps both of its splits). With the bulk trigger at 0.99 the bulk response acts,
//! so a difference between the force's split and the mean surface displacement's would
//! enter the force through the bulk displacement (`contact::mdr::flat`).
//!
//! Checked: the force on the small sphere at every recorded step against LAMMPS's, and,
//! once both stand still, that the force does not change, in tamp's run and in
//! LAMMPS's record: a pair that does not move has no surface displacement increment.

use crate::error::{Result, TampError};
use crate::verify::recording::RecordSpec;
use crate::verify::{CaseContext, Measured};
use serde::Deserialize;

/// The case file's parameters.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct Parameters {
    /// The last step of the pressing; the spheres stand still after it.
    press_steps: u64,
}

/// One row of `results.csv`, LAMMPS's thermo output every 10 steps.
#[derive(Debug, Deserialize)]
struct Row {
    step: u64,
    force_x_1: f64,
}

/// Largest |F − F_ref|/|F_ref| over `forces` (step, force), F_ref the first force
/// after `press_steps`.
fn hold_drift(forces: &[(u64, f64)], press_steps: u64) -> Result<f64> {
    let mut held = forces.iter().filter(|(step, _)| *step > press_steps);
    let (_, first) = held.next().ok_or_else(|| {
        TampError::Other(format!(
            "lammps_mdr_deep_pair: no record after step {press_steps}"
        ))
    })?;
    Ok(held.fold(0.0, |m: f64, (_, f)| m.max((f - first).abs() / first.abs())))
}

pub fn run(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let p: Parameters = ctx.parameters()?;
    let rows: Vec<Row> = ctx.peer_results("lammps")?;
    let scene = ctx.scene()?;
    let rec = ctx.record("pair", &scene, RecordSpec::every(10, true))?;
    let bad = |what: String| TampError::Other(format!("lammps_mdr_deep_pair: {what}"));

    let peak = rows.iter().fold(0.0, |m: f64, r| m.max(r.force_x_1.abs()));
    let mut tamp = Vec::with_capacity(rows.len());
    let mut difference = 0.0f64;
    for r in &rows {
        let frame = rec
            .frames
            .iter()
            .find(|f| f.step == r.step)
            .ok_or_else(|| bad(format!("tamp's run has no frame at step {}", r.step)))?;
        let force = frame.bodies[0]
            .force
            .ok_or_else(|| bad("tamp's run recorded no forces".into()))?[0];
        difference = difference.max((force - r.force_x_1).abs() / peak);
        tamp.push((r.step, force));
    }
    let lammps: Vec<(u64, f64)> = rows.iter().map(|r| (r.step, r.force_x_1)).collect();
    Ok(vec![
        Measured::new("force_difference", difference, 0.0),
        Measured::new("hold_force_drift", hold_drift(&tamp, p.press_steps)?, 0.0),
        Measured::new(
            "hold_force_drift_lammps",
            hold_drift(&lammps, p.press_steps)?,
            0.0,
        ),
    ])
}
