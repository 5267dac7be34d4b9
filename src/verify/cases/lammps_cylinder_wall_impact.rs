//! Cross-check against LAMMPS 22 Jul 2025 (update 4): a sphere hits the inside of a
//! cylinder obliquely (incidence θ from the normal, 5° to 85°; R_c = 2.5 R, axis along y
//! through z = R_c, the wall's lowest line under the sphere; `region cylinder` + `fix
//! wall/gran/region`, ends closed by planes), sliding around the circumference, `mindlin`
//! and `mindlin/force` with `coeff_restitution` e = 0.9, against the scene's
//! `"curvature": "mean"` cylinder with `lammps_mindlin` and LAMMPS's lever arms
//! (`contact.lever_arm` = `lammps`). tamp starts from the incident velocity components
//! recorded by LAMMPS (the same doubles) and runs the same number of steps
//! (`reference_data/lammps/run_cylinder_wall.sh`). Also the number of steps in contact,
//! and (in the table only) tamp's default `flat` cylinder's, longer by about
//! (R*/R)^{1/5} (Hertz: t_c ∝ R*^{−1/5}).
//!
//! Each quantity is the largest relative deviation over the runs,
//! |tamp − LAMMPS| / |LAMMPS|, of the rebound tangential velocity, the rebound spin ω·R
//! and the rebound normal velocity; the per-run table goes to `<report>/<case>.csv`.

use super::liggghts_inputs::Mismatches;
use crate::contact::damping::{Damping, LiggghtsRestitution};
use crate::contact::lever_arm::LeverArm;
use crate::contact::tangential::TangentialLaw;
use crate::contact::tangential::lammps_mindlin::{LammpsMindlin, Variant};
use crate::error::{Result, TampError};
use crate::scene::walls::{Curvature, MotionSpec, ShapeSpec};
use crate::scene::{self, Scene};
use crate::verify::{CaseContext, Measured};
use serde::Deserialize;
use std::fmt::Write as _;

/// One LAMMPS run at one angle, as `run_cylinder_wall.sh` writes it.
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
    /// The cylinder's radius R_c.
    cylinder_radius: f64,
    vx: f64,
    vz: f64,
    omega_y: f64,
    /// Steps with a wall contact.
    contact_steps: u64,
}

impl Row {
    fn label(&self) -> String {
        format!("{} {} {}°", self.tangential, self.damping, self.angle_deg)
    }

    /// tamp's tangential law and damping for the row's LAMMPS Mindlin model and damping.
    fn tamp_laws(&self) -> Result<(TangentialLaw, Damping)> {
        let variant = Variant::ALL
            .into_iter()
            .find(|v| v.keyword() == self.tangential);
        match (variant, self.damping.as_str()) {
            (Some(variant), "coeff_restitution") => Ok((
                TangentialLaw::LammpsMindlin(LammpsMindlin {
                    variant,
                    x_gamma_t: 0.0,
                }),
                Damping::LiggghtsRestitution(LiggghtsRestitution {
                    restitution: self.restitution_in,
                }),
            )),
            _ => Err(TampError::Other(format!(
                "results.csv: LAMMPS tangential '{}' with damping '{}' has no tamp law in this case",
                self.tangential, self.damping
            ))),
        }
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
    check_sphere_in_cylinder(&mut out, scene, row);
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
/// material of radius R_c with `"curvature": "mean"`, axis along y through (0, ·, R_c)
/// (its lowest line through the origin), and nothing else but planes normal to y
/// (the closed ends, out of the sphere's reach).
fn check_sphere_in_cylinder(out: &mut Mismatches, scene: &Scene, row: &Row) {
    let r_c = row.cylinder_radius;
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

/// `lammps_cylinder_wall_impact`: every run in tamp against its LAMMPS rebound.
pub fn cylinder(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let rows: Vec<Row> = ctx.peer_results("lammps")?;
    let base = ctx.scene()?;
    let mut worst = [0.0_f64; 3];
    let mut worst_steps = 0_u64;
    let mut table = String::from(
        "tangential,damping,angle_deg,tamp_law,lammps_vt,tamp_vt,deviation_vt,lammps_omega_r,tamp_omega_r,deviation_omega_r,lammps_vn,tamp_vn,deviation_vn,lammps_contact_steps,tamp_contact_steps,flat_contact_steps,flat_over_lammps,flat_deviation_vt,flat_deviation_omega_r,flat_deviation_vn\n",
    );
    for row in &rows {
        let label = row.label();
        mismatches(&base, row).refuse_any(&label)?;
        let (tangential, damping) = row.tamp_laws()?;
        let mut s = base.clone();
        if let Some(t) = s.contact.tangential.as_mut() {
            t.law = tangential;
        }
        s.contact.damping = Some(damping);
        let v = [row.tangential_speed, row.normal_speed];
        let (vx, vz, omega_r, steps) = rebound_and_contact_steps(&s, v, row.steps, &label)?;
        let lammps = [row.vx, row.omega_y * row.radius, row.vz];
        let _ = write!(
            table,
            "{},{},{},{}",
            row.tangential,
            row.damping,
            row.angle_deg,
            tangential.name()
        );
        for (k, (tamp, lammps)) in [vx, omega_r, vz].into_iter().zip(lammps).enumerate() {
            let d = deviation(tamp, lammps);
            worst[k] = worst[k].max(d);
            let _ = write!(table, ",{lammps:.17e},{tamp:.17e},{d:e}");
        }
        worst_steps = worst_steps.max(steps.abs_diff(row.contact_steps));
        // tamp's default flat cylinder against the same LAMMPS run.
        for w in &mut s.walls {
            if let ShapeSpec::Cylinder { curvature, .. } = &mut w.shape {
                *curvature = Curvature::Flat;
            }
        }
        let (fx, fz, fw, flat_steps) = rebound_and_contact_steps(&s, v, row.steps, &label)?;
        let _ = writeln!(
            table,
            ",{},{steps},{flat_steps},{:.6},{:e},{:e},{:e}",
            row.contact_steps,
            flat_steps as f64 / row.contact_steps as f64,
            deviation(fx, lammps[0]),
            deviation(fw, lammps[1]),
            deviation(fz, lammps[2])
        );
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
        Measured::new("max_contact_steps_difference", worst_steps as f64, 0.0),
    ])
}

/// `rebound`, and the number of steps after which the sphere touches a wall (the
/// contact's duration in steps).
fn rebound_and_contact_steps(
    scene: &Scene,
    [v_t, v_n]: [f64; 2],
    steps: u64,
    run: &str,
) -> Result<(f64, f64, f64, u64)> {
    let mut s = scene.clone();
    s.particles[0].velocity = Some([v_t, 0.0, -v_n]);
    let mut sim = scene::build(&s)?.sim;
    let mut touching = 0;
    for _ in 0..steps {
        sim.step()?;
        touching += u64::from(sim.contact_count() != 0);
    }
    if sim.contact_count() != 0 {
        return Err(TampError::Other(format!(
            "{run}: the sphere still touches the wall after {steps} steps"
        )));
    }
    let p = &sim.state.particles;
    Ok((
        p.velocity[0].x,
        p.velocity[0].z,
        p.omega[0].y * p.radius[0],
        touching,
    ))
}
