//! Cross-checks against LAMMPS 22 Jul 2025 (update 4): a sphere hits a flat wall of its
//! own material obliquely (incidence θ from the normal, 5° to 85°), `pair granular` /
//! `fix wall/gran granular` with each of LAMMPS's history-dependent tangential models
//! against the tamp law that reproduces it. Both codes take LAMMPS's lever arms
//! (`contact.lever_arm` = `lammps`); tamp starts from the incident velocity components
//! recorded by LAMMPS (the same doubles) and runs the same number of steps.
//!
//! - `lammps_oblique_wall_impact_mindlin` (`mindlin`): `hertz/material` with `mindlin`,
//!   `mindlin/force`, `mindlin_rescale`, `mindlin_rescale/force` and `damping
//!   coeff_restitution` e = 0.9 against `lammps_mindlin` with `liggghts_restitution`
//!   e = 0.9, and `mindlin/force` undamped against `mindlin_no_slip` (equal when the
//!   normal force never pulls); each of the four again with the tangential dashpot
//!   x_γ,t = 0.5 against `lammps_mindlin` with that `x_gamma_t`;
//!   `reference_data/lammps/run_oblique_wall_mindlin.sh`.
//! - `lammps_oblique_wall_impact_linear` (`linear`): `hooke` and `hertz/material` with
//!   `linear_history` and `linear_nohistory` and `damping coeff_restitution` e = 0.9,
//!   `velocity`, `mass_velocity` or `viscoelastic` against `lammps_linear_history` /
//!   `lammps_linear_nohistory` with `linear` / `hertz` and `liggghts_restitution` /
//!   `constant` / `mass_velocity` / `viscoelastic`;
//!   `reference_data/lammps/run_oblique_wall_linear.sh`.
//!
//! - `lammps_cylinder_wall_impact` (`cylinder`): the sphere hits the inside of a cylinder
//!   (R_c = 2.5 R, axis along y through z = R_c, the wall's lowest line under the
//!   sphere; `region cylinder` + `fix wall/gran/region`, ends closed by planes), sliding
//!   around the circumference, `mindlin` and `mindlin/force` with `coeff_restitution`
//!   e = 0.9, against the scene's `"curvature": "mean"` cylinder; also the number of
//!   steps in contact, and (in the table only) tamp's default `flat` cylinder's,
//!   longer by about (R*/R)^{1/5} (Hertz: t_c ∝ R*^{−1/5}).
//!   `reference_data/lammps/run_cylinder_wall.sh`.
//!
//! Each quantity is the largest relative deviation over the runs,
//! |tamp − LAMMPS| / |LAMMPS|, of the rebound tangential velocity, the rebound spin ω·R
//! and the rebound normal velocity; the per-run table goes to
//! `<report>/<case>.csv`.

use super::liggghts_inputs::Mismatches;
use super::liggghts_oblique_wall_impact::rebound_and_contact_steps;
use crate::contact::damping::{Constant, Damping, LiggghtsRestitution, MassVelocity, Viscoelastic};
use crate::contact::lever_arm::LeverArm;
use crate::contact::normal::{Hertz, Linear, NormalLaw};
use crate::contact::tangential::lammps_linear_history::LammpsLinearHistory;
use crate::contact::tangential::lammps_linear_nohistory::LammpsLinearNohistory;
use crate::contact::tangential::lammps_mindlin::{LammpsMindlin, Variant};
use crate::contact::tangential::{MindlinNoSlip, TangentialLaw};
use crate::error::{Result, TampError};
use crate::scene::Scene;
use crate::scene::walls::{Curvature, MotionSpec, ShapeSpec};
use crate::verify::{CaseContext, Measured};
use serde::Deserialize;
use std::fmt::Write as _;

/// One LAMMPS run at one angle, as `run_oblique_wall_mindlin.sh` writes it.
#[derive(Debug, Deserialize)]
struct MindlinRow {
    tangential: String,
    damping: String,
    restitution_in: f64,
    /// x_γ,t of the tangential model; absent (the cylinder's file) is 0.
    #[serde(default)]
    x_gamma_t: f64,
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
    /// The cylinder's radius R_c (`run_cylinder_wall.sh`); absent for the plane.
    #[serde(default)]
    cylinder_radius: Option<f64>,
    vx: f64,
    vz: f64,
    omega_y: f64,
    /// Steps with a wall contact (`run_cylinder_wall.sh`).
    #[serde(default)]
    contact_steps: Option<u64>,
}

/// One LAMMPS run at one angle, as `run_oblique_wall_linear.sh` writes it: the normal
/// model with k_n (0 for `hertz/material`), the damping model with its damp slot, the
/// tangential model with k_t (0 for `linear_nohistory`) and x_γ,t.
#[derive(Debug, Deserialize)]
struct LinearRow {
    normal: String,
    normal_stiffness: f64,
    damping: String,
    damp: f64,
    tangential: String,
    tangential_stiffness: f64,
    x_gamma_t: f64,
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

/// One LAMMPS run, whichever case recorded it: tamp's laws for it, what LAMMPS ran
/// with, and its rebound.
struct Run {
    /// "<models> <angle>°", for the table and messages.
    label: String,
    /// LAMMPS's models, the first columns of the table.
    models: String,
    /// `None`: the scene's own normal law.
    normal: Option<NormalLaw>,
    tangential: TangentialLaw,
    damping: Option<Damping>,
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
    cylinder_radius: Option<f64>,
    vx: f64,
    vz: f64,
    omega_y: f64,
    contact_steps: Option<u64>,
}

impl MindlinRow {
    fn run(self) -> Result<Run> {
        let (tangential, damping) = tamp_laws(&self)?;
        Ok(Run {
            label: format!(
                "{} x_gamma_t {} {} {}°",
                self.tangential, self.x_gamma_t, self.damping, self.angle_deg
            ),
            models: format!("{},{},{}", self.tangential, self.x_gamma_t, self.damping),
            normal: None,
            tangential,
            damping,
            angle_deg: self.angle_deg,
            tangential_speed: self.tangential_speed,
            normal_speed: self.normal_speed,
            friction: self.friction,
            time_step: self.time_step,
            steps: self.steps,
            youngs_modulus: self.youngs_modulus,
            poisson_ratio: self.poisson_ratio,
            density: self.density,
            radius: self.radius,
            initial_gap: self.initial_gap,
            cylinder_radius: self.cylinder_radius,
            vx: self.vx,
            vz: self.vz,
            omega_y: self.omega_y,
            contact_steps: self.contact_steps,
        })
    }
}

impl LinearRow {
    /// `hooke k` is `linear` k, `hertz/material` `hertz`; `coeff_restitution` e is
    /// `liggghts_restitution` e, `velocity` η `constant` γ_n = η, `mass_velocity` and
    /// `viscoelastic` η_n0 the kinds of their names; `linear_history k_t x`
    /// and `linear_nohistory x` are the laws of their names.
    fn run(self) -> Result<Run> {
        let unknown = |what: &str, name: &str| {
            TampError::Other(format!(
                "results.csv: LAMMPS {what} '{name}' has no tamp law in this case"
            ))
        };
        let normal = match self.normal.as_str() {
            "hooke" => NormalLaw::Linear(Linear {
                stiffness: self.normal_stiffness,
            }),
            "hertz/material" => NormalLaw::Hertz(Hertz {}),
            other => return Err(unknown("normal model", other)),
        };
        let damping = match self.damping.as_str() {
            "coeff_restitution" => Damping::LiggghtsRestitution(LiggghtsRestitution {
                restitution: self.damp,
            }),
            "velocity" => Damping::Constant(Constant { gamma_n: self.damp }),
            "mass_velocity" => Damping::MassVelocity(MassVelocity { eta_n0: self.damp }),
            "viscoelastic" => Damping::Viscoelastic(Viscoelastic { eta_n0: self.damp }),
            other => return Err(unknown("damping model", other)),
        };
        let tangential = match self.tangential.as_str() {
            "linear_history" => TangentialLaw::LammpsLinearHistory(LammpsLinearHistory {
                stiffness: self.tangential_stiffness,
                x_gamma_t: self.x_gamma_t,
            }),
            "linear_nohistory" => TangentialLaw::LammpsLinearNohistory(LammpsLinearNohistory {
                x_gamma_t: self.x_gamma_t,
            }),
            other => return Err(unknown("tangential model", other)),
        };
        let models = format!("{} {},{}", self.normal, self.tangential, self.damping);
        Ok(Run {
            label: format!(
                "{} {} {} {}°",
                self.normal, self.tangential, self.damping, self.angle_deg
            ),
            models,
            normal: Some(normal),
            tangential,
            damping: Some(damping),
            angle_deg: self.angle_deg,
            tangential_speed: self.tangential_speed,
            normal_speed: self.normal_speed,
            friction: self.friction,
            time_step: self.time_step,
            steps: self.steps,
            youngs_modulus: self.youngs_modulus,
            poisson_ratio: self.poisson_ratio,
            density: self.density,
            radius: self.radius,
            initial_gap: self.initial_gap,
            cylinder_radius: None,
            vx: self.vx,
            vz: self.vz,
            omega_y: self.omega_y,
            contact_steps: None,
        })
    }
}

/// tamp's tangential law and damping for a LAMMPS Mindlin model (with its x_γ,t) and
/// damping.
fn tamp_laws(row: &MindlinRow) -> Result<(TangentialLaw, Option<Damping>)> {
    let variant = Variant::ALL
        .into_iter()
        .find(|v| v.keyword() == row.tangential);
    match (variant, row.damping.as_str()) {
        (Some(Variant::MindlinForce), "velocity")
            if row.restitution_in == 0.0 && row.x_gamma_t == 0.0 =>
        {
            Ok((TangentialLaw::MindlinNoSlip(MindlinNoSlip {}), None))
        }
        (Some(variant), "coeff_restitution") => Ok((
            TangentialLaw::LammpsMindlin(LammpsMindlin {
                variant,
                x_gamma_t: row.x_gamma_t,
            }),
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
fn mismatches(scene: &Scene, row: &Run) -> Mismatches {
    let mut out = Mismatches::default();
    out.check_material_and_step(
        scene,
        row.density,
        row.youngs_modulus,
        row.poisson_ratio,
        row.time_step,
    );
    out.check_spins_without_gravity(scene);
    match row.cylinder_radius {
        None => out.check_sphere_on_floor(scene, row.radius, row.initial_gap),
        Some(r_c) => check_sphere_in_cylinder(&mut out, scene, row, r_c),
    }
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

/// The scene is the one sphere above the origin, inside a fixed cylinder of its own
/// material of radius `r_c` with `"curvature": "mean"`, axis along y through (0, ·, r_c)
/// (its lowest line through the origin), and nothing else but planes normal to y
/// (the closed ends, out of the sphere's reach).
fn check_sphere_in_cylinder(out: &mut Mismatches, scene: &Scene, row: &Run, r_c: f64) {
    let Some(p) = out.check_sphere_above_origin(scene, row.radius, row.initial_gap) else {
        return;
    };
    let cylinders: Vec<_> = scene
        .walls
        .iter()
        .filter(|w| matches!(w.shape, ShapeSpec::Cylinder { .. }))
        .collect();
    let cylinder_ok = matches!(cylinders.as_slice(), [w] if w.material == p.material
        && matches!(w.motion, MotionSpec::Fixed)
        && matches!(&w.shape, ShapeSpec::Cylinder { origin, axis, radius, curvature, .. }
            if *origin == [0.0, 0.0, r_c] && *axis == [0.0, 1.0, 0.0] && *radius == r_c
                && *curvature == Curvature::Mean));
    let others_ok = scene.walls.iter().all(|w| match &w.shape {
        ShapeSpec::Cylinder { .. } => true,
        ShapeSpec::Plane { normal, .. } => normal[0] == 0.0 && normal[2] == 0.0,
        _ => false,
    });
    if !(cylinder_ok && others_ok) {
        out.0.push(format!(
            "walls: the peer ran one fixed cylinder of the sphere's material, radius {r_c:e}, axis y through (0, 0, {r_c:e}), curvature 'mean', its ends closed by planes normal to y"
        ));
    }
}

fn deviation(tamp: f64, lammps: f64) -> f64 {
    (tamp - lammps).abs() / lammps.abs()
}

/// `lammps_oblique_wall_impact_mindlin`.
pub fn mindlin(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let rows: Vec<MindlinRow> = ctx.peer_results("lammps")?;
    let runs = rows
        .into_iter()
        .map(MindlinRow::run)
        .collect::<Result<Vec<_>>>()?;
    compare(ctx, &runs, "tangential,x_gamma_t,damping")
}

/// `lammps_cylinder_wall_impact`.
pub fn cylinder(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let rows: Vec<MindlinRow> = ctx.peer_results("lammps")?;
    let runs = rows
        .into_iter()
        .map(MindlinRow::run)
        .collect::<Result<Vec<_>>>()?;
    if runs
        .iter()
        .any(|r| r.cylinder_radius.is_none() || r.contact_steps.is_none())
    {
        return Err(TampError::Other(
            "results.csv: every run needs cylinder_radius and contact_steps".into(),
        ));
    }
    compare(ctx, &runs, "tangential,x_gamma_t,damping")
}

/// `lammps_oblique_wall_impact_linear`.
pub fn linear(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let rows: Vec<LinearRow> = ctx.peer_results("lammps")?;
    let runs = rows
        .into_iter()
        .map(LinearRow::run)
        .collect::<Result<Vec<_>>>()?;
    compare(ctx, &runs, "models,damping")
}

/// Every run in tamp against its LAMMPS rebound; `columns` names the `models` columns
/// of the table.
fn compare(ctx: &CaseContext, runs: &[Run], columns: &str) -> Result<Vec<Measured>> {
    let base = ctx.scene()?;
    let mut worst = [0.0_f64; 3];
    let mut worst_steps = 0_u64;
    let mut table = format!(
        "{columns},angle_deg,tamp_law,lammps_vt,tamp_vt,deviation_vt,lammps_omega_r,tamp_omega_r,deviation_omega_r,lammps_vn,tamp_vn,deviation_vn",
    );
    let counted = runs.iter().all(|r| r.contact_steps.is_some());
    if counted {
        table.push_str(",lammps_contact_steps,tamp_contact_steps,flat_contact_steps,flat_over_lammps,flat_deviation_vt,flat_deviation_omega_r,flat_deviation_vn");
    }
    table.push('\n');
    for row in runs {
        mismatches(&base, row).refuse_any(&row.label)?;
        let mut s = base.clone();
        if let Some(normal) = row.normal {
            s.contact.normal = normal;
        }
        if let Some(t) = s.contact.tangential.as_mut() {
            t.law = row.tangential;
        }
        s.contact.damping = row.damping;
        let v = [row.tangential_speed, row.normal_speed];
        let (vx, vz, omega_r, steps) = rebound_and_contact_steps(&s, v, row.steps, &row.label)?;
        let lammps = [row.vx, row.omega_y * row.radius, row.vz];
        let _ = write!(
            table,
            "{},{},{}",
            row.models,
            row.angle_deg,
            row.tangential.name()
        );
        for (k, (tamp, lammps)) in [vx, omega_r, vz].into_iter().zip(lammps).enumerate() {
            let d = deviation(tamp, lammps);
            worst[k] = worst[k].max(d);
            let _ = write!(table, ",{lammps:.17e},{tamp:.17e},{d:e}");
        }
        if let Some(lammps_steps) = row.contact_steps {
            worst_steps = worst_steps.max(steps.abs_diff(lammps_steps));
            // tamp's default flat cylinder against the same LAMMPS run.
            for w in &mut s.walls {
                if let ShapeSpec::Cylinder { curvature, .. } = &mut w.shape {
                    *curvature = Curvature::Flat;
                }
            }
            let (fx, fz, fw, flat_steps) = rebound_and_contact_steps(&s, v, row.steps, &row.label)?;
            let _ = write!(
                table,
                ",{lammps_steps},{steps},{flat_steps},{:.6},{:e},{:e},{:e}",
                flat_steps as f64 / lammps_steps as f64,
                deviation(fx, lammps[0]),
                deviation(fw, lammps[1]),
                deviation(fz, lammps[2])
            );
        }
        table.push('\n');
    }
    crate::output::create_dir(&ctx.report_dir)?;
    crate::output::write_atomic(
        &ctx.report_dir.join(format!("{}.csv", ctx.spec.name)),
        table.as_bytes(),
    )?;
    let mut out = vec![
        Measured::new("max_tangential_velocity_deviation", worst[0], 0.0),
        Measured::new("max_angular_velocity_deviation", worst[1], 0.0),
        Measured::new("max_normal_velocity_deviation", worst[2], 0.0),
    ];
    if counted {
        out.push(Measured::new(
            "max_contact_steps_difference",
            worst_steps as f64,
            0.0,
        ));
    }
    Ok(out)
}
