//! Cross-check against LIGGGHTS 3.8.0: a sphere hits a flat wall of its own material
//! obliquely (Chung & Ooi 2011, test 6 style: constant speed, incidence angle θ from the
//! wall normal swept from 5° to 85°), Hertz with `liggghts_restitution` damping and the
//! `liggghts_history` tangential law. LIGGGHTS side: `fix wall/gran model hertz
//! tangential history primitive type 1 zplane 0.0`, one run per angle, reduced to the
//! rebound velocity and spin in `reference_data/liggghts/liggghts_oblique_wall_impact/
//! results.csv` (`reference_data/liggghts/run_oblique_wall_impact.sh`). tamp starts from
//! the incident velocity components recorded there (the same doubles) and runs the same
//! number of steps.
//!
//! Each quantity is the largest relative deviation over the angles, |tamp − LIGGGHTS| /
//! |LIGGGHTS|, of the rebound tangential velocity, the rebound spin ω·R and the rebound
//! normal velocity. The per-angle table goes to `<report>/liggghts_oblique_wall_impact.csv`
//! and a plot to `.svg`, beside the rigid-body (Coulomb, no tangential compliance)
//! prediction: gross sliding v_t' = v_t − μ(1 + e)v_n, ωR = (5/2)μ(1 + e)v_n while
//! v_t/v_n ≥ (7/2)μ(1 + e), else rolling at the end, v_t' = ωR = (5/7)v_t.

use super::liggghts_inputs::Mismatches;
use crate::contact::damping::{Damping, LiggghtsRestitution};
use crate::error::{Result, TampError};
use crate::plot::{Panel, Series, write_svg};
use crate::scene::{self, Scene};
use crate::verify::{CaseContext, Measured};
use serde::Deserialize;
use std::fmt::Write as _;

/// One LIGGGHTS run, as `oblique_wall_impact_extract.py` writes it (`final_gap` is for
/// people and is not read).
#[derive(Debug, Deserialize)]
struct Row {
    angle_deg: f64,
    tangential_speed: f64,
    normal_speed: f64,
    restitution_in: f64,
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

/// Differences between the scene and the inputs LIGGGHTS ran with.
fn mismatches(scene: &Scene, row: &Row) -> Mismatches {
    let mut out = Mismatches::default();
    out.check_material_and_step(
        scene,
        row.density,
        row.youngs_modulus,
        row.poisson_ratio,
        row.time_step,
    );
    out.check_history_runs(scene);
    match &scene.contact.damping {
        Some(Damping::LiggghtsRestitution(LiggghtsRestitution { restitution })) => out.check(
            "contact.damping.restitution",
            *restitution,
            row.restitution_in,
        ),
        _ => out
            .0
            .push("contact.damping: LIGGGHTS derives it from a restitution".into()),
    }
    if let Some(t) = &scene.contact.tangential {
        out.check("contact.tangential.friction", t.friction, row.friction);
    }
    out.check_sphere_on_floor(scene, row.radius, row.initial_gap);
    // The recorded speeds must be the angle's components (they are what both codes use).
    let angle = row.tangential_speed.atan2(row.normal_speed).to_degrees();
    out.check("incidence angle (deg)", angle, row.angle_deg);
    out
}

/// One angle: the rebound of both codes.
struct Rebound {
    angle: f64,
    v_t: f64,
    v_n: f64,
    /// (tamp, LIGGGHTS) tangential velocity, ω R, normal velocity.
    tangential: (f64, f64),
    spin: (f64, f64),
    normal: (f64, f64),
}

fn deviation((tamp, liggghts): (f64, f64)) -> f64 {
    (tamp - liggghts).abs() / liggghts.abs()
}

/// Rigid-body rebound (v_t', ωR) for Coulomb friction without tangential compliance.
fn rigid_body(v_t: f64, v_n: f64, mu: f64, e: f64) -> (f64, f64) {
    if v_t >= 3.5 * mu * (1.0 + e) * v_n {
        let dv = mu * (1.0 + e) * v_n;
        (v_t - dv, 2.5 * dv)
    } else {
        (5.0 / 7.0 * v_t, 5.0 / 7.0 * v_t)
    }
}

/// The sphere of `scene` launched at (v_t, 0, −v_n) and run `steps` steps: its rebound
/// (v_x, v_z, ω_y R), refused if it still touches the wall (`run` names the run).
pub(super) fn rebound(
    scene: &Scene,
    v: [f64; 2],
    steps: u64,
    run: &str,
) -> Result<(f64, f64, f64)> {
    rebound_and_contact_steps(scene, v, steps, run).map(|(vx, vz, w, _)| (vx, vz, w))
}

/// `rebound`, and the number of steps after which the sphere touches a wall (the
/// contact's duration in steps).
pub(super) fn rebound_and_contact_steps(
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

pub fn run(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let base = ctx.scene()?;
    let rows: Vec<Row> = ctx.liggghts_results()?;
    let mut rebounds = Vec::new();
    for row in &rows {
        mismatches(&base, row).refuse_any(&format!("{}°", row.angle_deg))?;
        let (vx, vz, omega_r) = rebound(
            &base,
            [row.tangential_speed, row.normal_speed],
            row.steps,
            &format!("{}°", row.angle_deg),
        )?;
        rebounds.push(Rebound {
            angle: row.angle_deg,
            v_t: row.tangential_speed,
            v_n: row.normal_speed,
            tangential: (vx, row.vx),
            spin: (omega_r, row.omega_y * row.radius),
            normal: (vz, row.vz),
        });
    }
    let (mu, e) = (rows[0].friction, rows[0].restitution_in);
    write_table(ctx, &rebounds, mu, e)?;
    let max = |f: fn(&Rebound) -> (f64, f64)| {
        rebounds.iter().map(|b| deviation(f(b))).fold(0.0, f64::max)
    };
    Ok(vec![
        Measured::new(
            "max_tangential_velocity_deviation",
            max(|b| b.tangential),
            0.0,
        ),
        Measured::new("max_angular_velocity_deviation", max(|b| b.spin), 0.0),
        Measured::new("max_normal_velocity_deviation", max(|b| b.normal), 0.0),
    ])
}

fn write_table(ctx: &CaseContext, rebounds: &[Rebound], mu: f64, e: f64) -> Result<()> {
    let name = &ctx.spec.name;
    let mut csv = String::from(
        "angle_deg,tangential_speed,normal_speed,liggghts_vt,tamp_vt,deviation_vt,liggghts_omega_r,tamp_omega_r,deviation_omega_r,liggghts_vn,tamp_vn,deviation_vn,rigid_body_vt,rigid_body_omega_r\n",
    );
    for b in rebounds {
        let (rigid_vt, rigid_wr) = rigid_body(b.v_t, b.v_n, mu, e);
        let _ = writeln!(
            csv,
            "{},{:.17e},{:.17e},{:.17e},{:.17e},{:e},{:.17e},{:.17e},{:e},{:.17e},{:.17e},{:e},{:e},{:e}",
            b.angle,
            b.v_t,
            b.v_n,
            b.tangential.1,
            b.tangential.0,
            deviation(b.tangential),
            b.spin.1,
            b.spin.0,
            deviation(b.spin),
            b.normal.1,
            b.normal.0,
            deviation(b.normal),
            rigid_vt,
            rigid_wr
        );
    }
    crate::output::create_dir(&ctx.report_dir)?;
    crate::output::write_atomic(&ctx.report_dir.join(format!("{name}.csv")), csv.as_bytes())?;
    let curve = |f: &dyn Fn(&Rebound) -> f64| -> Vec<(f64, f64)> {
        rebounds.iter().map(|b| (b.angle, f(b))).collect()
    };
    let rigid = |k: usize| {
        curve(&|b: &Rebound| {
            let r = rigid_body(b.v_t, b.v_n, mu, e);
            [r.0, r.1][k] / b.v_t
        })
    };
    let tangential = [
        Series::points(
            "LIGGGHTS 3.8.0",
            curve(&|b: &Rebound| b.tangential.1 / b.v_t),
        ),
        Series::line("tamp", curve(&|b: &Rebound| b.tangential.0 / b.v_t)),
        Series::line("rigid body (Coulomb)", rigid(0)),
    ];
    let spin = [
        Series::points("LIGGGHTS 3.8.0", curve(&|b: &Rebound| b.spin.1 / b.v_t)),
        Series::line("tamp", curve(&|b: &Rebound| b.spin.0 / b.v_t)),
        Series::line("rigid body (Coulomb)", rigid(1)),
    ];
    write_svg(
        &ctx.report_dir.join(format!("{name}.svg")),
        &[
            Panel {
                title: "Rebound tangential velocity",
                x_label: "incidence angle from the normal (deg)",
                y_label: "v_t' / v_t",
                log_y: false,
                log_x: false,
                series: &tangential,
            },
            Panel {
                title: "Rebound spin",
                x_label: "incidence angle from the normal (deg)",
                y_label: "omega R / v_t",
                log_y: false,
                log_x: false,
                series: &spin,
            },
        ],
    )
}
