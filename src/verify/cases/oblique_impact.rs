//! Oblique impacts with friction and spin: a sphere hits a plane wall of its own
//! material at incidence angles θ from the normal (Chung & Ooi 2011, test 6 style), or
//! two equal spheres meet obliquely, once for each contact law the case file lists.
//! The laws are those a peer runs (LIGGGHTS's `tangential history`, LAMMPS's
//! `mindlin` variants and `linear_history`), so the same scenes run on every engine
//! that can express them. The references hold whatever the tangential law is:
//!
//! - Angular impulse about the contact point. The friction impulse J_t acts at the
//!   lever ℓ below the centre, so m Δv_t = J_t and I Δω = ℓ J_t; for a solid sphere
//!   (I = 2/5 m R²) ωR = (5/2)(ℓ/R) Δv_t at every angle, sticking or sliding. The
//!   case takes Σ ωR / ((5/2) Σ Δv_t) over the angles. With ℓ = R (LAMMPS's wall) it
//!   is 1 to round-off. With ℓ = R − δ/2 (tamp's and LIGGGHTS's) it departs from 1
//!   by at most (δ_max/2R) · Σ μ (1 + e) v_n / Σ Δv_t, the shortfall of the lever
//!   times the largest friction impulse over the net one (at small angles the
//!   friction reverses during the contact and the net impulse is small).
//! - Gross sliding (rigid-body impulse theory; Maw, Barber & Fawcett 1976; Brach
//!   1991): while the contact point slips the friction is μ F_n, so
//!   Δv_t = μ (1 + e) v_n with e the normal restitution of the same run. The slip
//!   lasts the whole contact when v_t > (7/2) μ (1 + e) v_n; the case judges only the
//!   angles 5 % beyond that bound. A dashpot that pulls at the end of the contact
//!   (F_n < 0) while the law caps the friction at μ |F_n| adds friction the normal
//!   impulse does not count: the damped runs of the peers' laws exceed the bound
//!   (docs/lammps.md §2).
//! - Energy: the slip velocity at the contact point can at most reverse, so a sphere
//!   that starts without spin loses between 0 and (4/7) v_t of its tangential velocity
//!   (ℓ = R). The sum over the angles of the tangential velocity lost must lie in that
//!   interval; it is a weak bound, and the quantity that carries every angle's rebound
//!   into an engine's agreement with tamp.
//! - Two spheres: the pair's angular momentum about its centre of mass (orbital plus
//!   spin) is conserved when the two lever arms add up to the centre distance.
//!
//! A plane that moves at a constant velocity W (its `motion`) gives the same impacts in
//! its own frame (Galilean invariance): each sphere starts at v + W, and every velocity
//! is measured relative to the wall, so the same references hold, and a code that left
//! the wall's velocity out of the relative velocity of the contact (normal or
//! tangential) would fail them.
//!
//! Velocities and spins are read from the first and the last recorded frame, once the
//! spheres have separated (no force acts after that).

use crate::error::{Result, TampError};
use crate::particles::Vec3;
use crate::plot::{Panel, Series, write_svg};
use crate::scene::Scene;
use crate::scene::schema::{ContactSpec, ParticleSpec};
use crate::scene::walls::{MotionSpec, ShapeSpec};
use crate::verify::{CaseContext, Measured, measure};
use serde::Deserialize;
use std::fmt::Write as _;

/// The case file's `parameters` of the impacts of a sphere on a wall at several
/// angles, once per contact law (this module's and `cylinder_wall_impact`'s).
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct Parameters {
    /// Incidence angles from the wall's normal, degrees (wall impacts only).
    #[serde(default)]
    pub angles_deg: Vec<f64>,
    /// Each contact law in turn, one scene each.
    pub laws: Vec<Law>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct Law {
    /// The law's name in the quantities (`spin_ratio_<label>`, …).
    pub label: String,
    /// Replaces the scene's `contact`.
    pub contact: ContactSpec,
}

impl Parameters {
    /// The scene's `sphere` once per angle, side by side 4R apart along `along`, each
    /// moving at its own speed towards the wall whose unit normal `n` points at it, at its
    /// angle from −n, its tangential part along `t`; plus the wall's velocity `w`.
    pub fn spheres_at_angles(
        &self,
        sphere: &ParticleSpec,
        along: Vec3,
        n: Vec3,
        t: Vec3,
        w: Vec3,
    ) -> Vec<ParticleSpec> {
        let speed = Vec3::from(sphere.velocity.unwrap_or([0.0; 3])).norm();
        self.angles_deg
            .iter()
            .enumerate()
            .map(|(k, angle)| {
                let (sin, cos) = angle.to_radians().sin_cos();
                let mut each = sphere.clone();
                let shift = along * (4.0 * sphere.radius * k as f64);
                each.position = (Vec3::from(sphere.position) + shift).into();
                each.velocity = Some((speed * (sin * t - cos * n) + w).into());
                each
            })
            .collect()
    }
}

/// The wall impacts: the scene's one sphere above its one plane, repeated side by side
/// along the wall (far enough apart never to touch), one per angle, each at the
/// scene's speed relative to the wall.
pub fn wall(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let p: Parameters = ctx.parameters()?;
    let base = ctx.scene()?;
    let (sphere, wall_velocity) = match (base.walls.as_slice(), base.particles.as_slice()) {
        ([w], [s])
            if matches!(w.shape, ShapeSpec::Plane { point, normal }
            if point == [0.0; 3] && normal == [0.0, 0.0, 1.0]) =>
        {
            match w.motion {
                MotionSpec::Fixed => (s, Vec3::zeros()),
                MotionSpec::Velocity { velocity } => (s, Vec3::from(velocity)),
                _ => return Err(plane_needed()),
            }
        }
        _ => return Err(plane_needed()),
    };
    let mut out = Vec::new();
    let mut table = String::from(
        "law,angle_deg,tangential_speed,normal_speed,restitution,rebound_vt,omega_r,spin_ratio,sliding,sliding_ratio\n",
    );
    let mut plotted = Vec::new();
    for law in &p.laws {
        let mut s = base.clone();
        s.contact = law.contact.clone();
        s.particles = p.spheres_at_angles(
            sphere,
            Vec3::new(0.0, 1.0, 0.0),
            Vec3::new(0.0, 0.0, 1.0),
            Vec3::new(1.0, 0.0, 0.0),
            wall_velocity,
        );
        let (first, last) = ctx.first_and_last(&law.label, &s)?;
        let mu = friction(&s)?;
        let mut sliding_ratio: Option<f64> = None;
        let (mut lost, mut lost_most, mut spin) = (0.0, 0.0, 0.0);
        let mut curve = Vec::new();
        for (k, angle) in p.angles_deg.iter().enumerate() {
            let (b0, b1) = (&first.bodies[k], &last.bodies[k]);
            // In the wall's frame: positions from the wall's height now, velocities less W.
            let height = b1.position.z - wall_velocity.z * last.time;
            let (u0, u1) = (b0.velocity - wall_velocity, b1.velocity - wall_velocity);
            if height - b1.radius <= 0.0 || u1.z <= 0.0 {
                return Err(TampError::Other(format!(
                    "{} at {angle}°: the sphere has not left the wall by step {}",
                    law.label, last.step
                )));
            }
            let (v_t, v_n) = (u0.x, -u0.z);
            let e = u1.z / v_n;
            let dv_t = v_t - u1.x;
            let omega_r = b1.omega.y * b1.radius;
            let ratio = omega_r / (2.5 * dv_t);
            spin += omega_r;
            lost += dv_t;
            lost_most += 4.0 / 7.0 * v_t;
            let sliding = v_t > 1.05 * 3.5 * mu * (1.0 + e) * v_n;
            let slide = dv_t / (mu * (1.0 + e) * v_n);
            if sliding {
                sliding_ratio = Some(farther_from_one(sliding_ratio, slide));
            }
            curve.push((*angle, u1.x / v_t));
            let _ = writeln!(
                table,
                "{},{angle},{v_t:.17e},{v_n:.17e},{e:.17e},{:.17e},{omega_r:.17e},{ratio:.17e},{sliding},{slide:.17e}",
                law.label, u1.x
            );
        }
        out.push(Measured::new(
            &format!("spin_ratio_{}", law.label),
            spin / (2.5 * lost),
            1.0,
        ));
        // A law whose friction need not reach μ F_n (a viscous one, LAMMPS's
        // linear_nohistory) has no sliding bound: its file does not ask for one.
        let sliding = format!("sliding_ratio_{}", law.label);
        if ctx.spec.asks_for(&sliding) {
            let ratio = sliding_ratio.ok_or_else(|| {
                TampError::Other(format!(
                    "{}: no angle slides throughout the contact (v_t > 1.05 (7/2) mu (1 + e) v_n)",
                    law.label
                ))
            })?;
            out.push(Measured::new(&sliding, ratio, 1.0));
        }
        out.push(Measured::between(
            &format!("tangential_velocity_lost_{}", law.label),
            lost,
            0.0,
            lost_most,
        ));
        plotted.push(Series::line(&law.label, curve));
    }
    write_table_and_plot(ctx, &table, plotted)?;
    Ok(out)
}

/// The pair impacts: the scene's two spheres, once per law.
pub fn pair(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let p: Parameters = ctx.parameters()?;
    let base = ctx.scene()?;
    if base.particles.len() != 2 || !base.walls.is_empty() {
        return Err(TampError::Other(
            "the scene must hold two spheres and no wall".into(),
        ));
    }
    let mut out = Vec::new();
    let mut table = String::from("law,angular_momentum_ratio,vx,vy,omega_z\n");
    for law in &p.laws {
        let mut s = base.clone();
        s.contact = law.contact.clone();
        let (first, last) = ctx.first_and_last(&law.label, &s)?;
        let (b0, b1) = (&last.bodies[0], &last.bodies[1]);
        if (b1.position - b0.position).norm() <= b0.radius + b1.radius {
            return Err(TampError::Other(format!(
                "{}: the spheres still touch at step {}",
                law.label, last.step
            )));
        }
        let density = s.materials.first().and_then(|m| m.density).ok_or_else(|| {
            TampError::Other("the scene's first material must have a density".into())
        })?;
        let l0 = measure::angular_momentum(&first, density);
        let l1 = measure::angular_momentum(&last, density);
        let ratio = l1.dot(&l0) / l0.norm_squared();
        let (v0, v1) = (first.bodies[0].velocity, b0.velocity);
        let _ = writeln!(
            table,
            "{},{ratio:.17e},{:.17e},{:.17e},{:.17e}",
            law.label, v1.x, v1.y, b0.omega.z
        );
        out.push(Measured::new(
            &format!("angular_momentum_ratio_{}", law.label),
            ratio,
            1.0,
        ));
        out.push(Measured::between(
            &format!("tangential_velocity_lost_{}", law.label),
            v0.y - v1.y,
            0.0,
            4.0 / 7.0 * v0.y,
        ));
    }
    write_table_and_plot(ctx, &table, Vec::new())?;
    Ok(out)
}

fn plane_needed() -> TampError {
    TampError::Other(
        "the scene must hold one sphere and one plane wall through the origin with normal (0, 0, 1), fixed or moving at a constant velocity".into(),
    )
}

fn friction(s: &Scene) -> Result<f64> {
    s.contact
        .tangential
        .as_ref()
        .map(|t| t.friction)
        .ok_or_else(|| TampError::Other("each law must name a tangential law".into()))
}

/// Of a running extreme and a new ratio, the one farther from 1.
fn farther_from_one(so_far: Option<f64>, ratio: f64) -> f64 {
    match so_far {
        Some(r) if (r - 1.0).abs() >= (ratio - 1.0).abs() => r,
        _ => ratio,
    }
}

fn write_table_and_plot(ctx: &CaseContext, table: &str, curves: Vec<Series>) -> Result<()> {
    let name = &ctx.spec.name;
    crate::output::create_dir(&ctx.report_dir)?;
    crate::output::write_atomic(
        &ctx.report_dir.join(format!("{name}.csv")),
        table.as_bytes(),
    )?;
    if curves.is_empty() {
        return Ok(());
    }
    write_svg(
        &ctx.report_dir.join(format!("{name}.svg")),
        &[Panel {
            title: "Rebound tangential velocity",
            x_label: "incidence angle from the normal (deg)",
            y_label: "v_t' / v_t",
            log_y: false,
            log_x: false,
            series: &curves,
        }],
    )
}
