//! Cross-check against LAMMPS 22 Jul 2025 (update 4): a sphere hits a flat wall of its
//! own material obliquely (incidence θ from the normal, 5° to 85°), `pair granular` /
//! `fix wall/gran granular` with `hertz/material` and each of LAMMPS's Mindlin tangential
//! models against the tamp law that reproduces it: `mindlin`, `mindlin/force`,
//! `mindlin_rescale`, `mindlin_rescale/force` with `damping coeff_restitution` e = 0.9
//! against `lammps_mindlin` with `liggghts_restitution` e = 0.9, and `mindlin/force`
//! undamped against `mindlin_no_slip` (equal when the normal force never pulls). Both
//! codes take LAMMPS's lever arms (`contact.lever_arm` = `lammps`). LAMMPS side:
//! `reference_data/lammps/lammps_oblique_wall_impact_mindlin/results.csv`, one row per
//! model and angle (`reference_data/lammps/run_oblique_wall_mindlin.sh`); tamp starts
//! from the incident velocity components recorded there (the same doubles) and runs the
//! same number of steps.
//!
//! Each quantity is the largest relative deviation over the models and angles,
//! |tamp − LAMMPS| / |LAMMPS|, of the rebound tangential velocity, the rebound spin ω·R
//! and the rebound normal velocity; the per-run table goes to
//! `<report>/lammps_oblique_wall_impact_mindlin.csv`.

use super::liggghts_inputs::Mismatches;
use super::liggghts_oblique_wall_impact::rebound;
use crate::contact::damping::{Damping, LiggghtsRestitution};
use crate::contact::lever_arm::LeverArm;
use crate::contact::tangential::lammps_mindlin::{LammpsMindlin, Variant};
use crate::contact::tangential::{MindlinNoSlip, TangentialLaw};
use crate::error::{Result, TampError};
use crate::scene::Scene;
use crate::verify::{CaseContext, Measured};
use serde::Deserialize;
use std::fmt::Write as _;

/// One LAMMPS run at one angle, as `run_oblique_wall_mindlin.sh` writes it.
#[derive(Debug, Deserialize)]
struct Row {
    tangential: String,
    damping: String,
    restitution_in: f64,
    angle_deg: f64,
    tangential_speed: f64,
    normal_speed: f64,
    friction: f64,
    time_step: f64,
    steps: u64,
    youngs_modulus: f64,
    poisson_ratio: f64,
    density: f64,
    radius: f64,
    initial_gap: f64,
    vx: f64,
    vz: f64,
    omega_y: f64,
}

/// tamp's tangential law and damping for a LAMMPS tangential and damping model.
fn tamp_laws(row: &Row) -> Result<(TangentialLaw, Option<Damping>)> {
    let variant = Variant::ALL
        .into_iter()
        .find(|v| v.keyword() == row.tangential);
    match (variant, row.damping.as_str()) {
        (Some(Variant::MindlinForce), "velocity") if row.restitution_in == 0.0 => {
            Ok((TangentialLaw::MindlinNoSlip(MindlinNoSlip {}), None))
        }
        (Some(variant), "coeff_restitution") => Ok((
            TangentialLaw::LammpsMindlin(LammpsMindlin { variant }),
            Some(Damping::LiggghtsRestitution(LiggghtsRestitution {
                restitution: row.restitution_in,
            })),
        )),
        _ => Err(TampError::Other(format!(
            "results.csv: LAMMPS tangential '{}' with damping '{}' has no tamp law in this case",
            row.tangential, row.damping
        ))),
    }
}

/// Differences between the scene and the inputs LAMMPS ran with.
fn mismatches(scene: &Scene, row: &Row) -> Mismatches {
    let mut out = Mismatches::default();
    out.check_material_and_step(
        scene,
        row.density,
        row.youngs_modulus,
        row.poisson_ratio,
        row.time_step,
    );
    out.check_spins_without_gravity(scene);
    out.check_sphere_on_floor(scene, row.radius, row.initial_gap);
    match &scene.contact.tangential {
        Some(t) if t.friction_pairs.is_empty() => {
            out.check("contact.tangential.friction", t.friction, row.friction)
        }
        _ => out
            .0
            .push("contact.tangential: LAMMPS ran one friction coefficient".into()),
    }
    if scene.contact.lever_arm != LeverArm::Lammps {
        out.0
            .push("contact.lever_arm: LAMMPS's lever arms are 'lammps'".into());
    }
    let angle = row.tangential_speed.atan2(row.normal_speed).to_degrees();
    out.check("incidence angle (deg)", angle, row.angle_deg);
    out
}

fn deviation(tamp: f64, lammps: f64) -> f64 {
    (tamp - lammps).abs() / lammps.abs()
}

pub fn run(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let base = ctx.scene()?;
    let rows: Vec<Row> = ctx.peer_results("lammps")?;
    let mut worst = [0.0_f64; 3];
    let mut table = String::from(
        "tangential,damping,angle_deg,tamp_law,lammps_vt,tamp_vt,deviation_vt,lammps_omega_r,tamp_omega_r,deviation_omega_r,lammps_vn,tamp_vn,deviation_vn\n",
    );
    for row in &rows {
        let run = format!("{} {} {}°", row.tangential, row.damping, row.angle_deg);
        mismatches(&base, row).refuse_any(&run)?;
        let (law, damping) = tamp_laws(row)?;
        let mut s = base.clone();
        if let Some(t) = s.contact.tangential.as_mut() {
            t.law = law;
        }
        s.contact.damping = damping;
        let (vx, vz, omega_r) = rebound(
            &s,
            [row.tangential_speed, row.normal_speed],
            row.steps,
            &run,
        )?;
        let pairs = [
            (vx, row.vx),
            (omega_r, row.omega_y * row.radius),
            (vz, row.vz),
        ];
        let _ = write!(
            table,
            "{},{},{},{}",
            row.tangential,
            row.damping,
            row.angle_deg,
            law.name()
        );
        for (k, (tamp, lammps)) in pairs.into_iter().enumerate() {
            let d = deviation(tamp, lammps);
            worst[k] = worst[k].max(d);
            let _ = write!(table, ",{lammps:.17e},{tamp:.17e},{d:e}");
        }
        table.push('\n');
    }
    crate::output::create_dir(&ctx.report_dir)?;
    crate::output::write_atomic(
        &ctx.report_dir.join(format!("{}.csv", ctx.spec.name)),
        table.as_bytes(),
    )?;
    Ok(vec![
        Measured::new("max_tangential_velocity_deviation", worst[0], 0.0),
        Measured::new("max_angular_velocity_deviation", worst[1], 0.0),
        Measured::new("max_normal_velocity_deviation", worst[2], 0.0),
    ])
}
