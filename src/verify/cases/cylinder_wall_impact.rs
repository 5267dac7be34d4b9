//! A sphere inside a cylinder of its own material: first head-on against the wall's
//! lowest line (elastic Hertz, frictionless), then obliquely with friction and damping,
//! once per contact law the case file lists.
//!
//! - Head-on. The contact is Hertz's with the effective radius the scene's `curvature`
//!   gives the concave wall: R* = R for `flat`, and for `mean` (the wall taken as the
//!   sphere of its mean curvature, radius 2R_c, concave) 1/R* = 1/R − 1/(2R_c), i.e.
//!   R* = 2R R_c/(2R_c − R); m* = m and 1/E* = 2(1 − ν²)/E. Contact duration and
//!   largest overlap are the closed forms of that contact (Johnson 1985 §11.4; the
//!   constant of `hertz.rs`), the restitution is 1. The references are computed here
//!   from the scene's inputs, so an engine that takes another effective radius for the
//!   curved wall fails the duration by (R*/R_other)^{1/5}.
//! - Oblique. One sphere per incidence angle θ from the normal, side by side along the
//!   axis, each at the head-on sphere's speed, sliding around the circumference. A fixed
//!   wall does no work and the laws are passive, so the kinetic energy (translational
//!   and rotational, summed over the spheres) after the impacts lies between 0 and its
//!   value before. A bound, not an estimate: it carries every rebound into an engine's
//!   agreement with tamp.
//!
//! A cylinder that slides along its axis at a constant velocity W (its `motion`) gives
//! the same impacts in its own frame (Galilean invariance): each sphere starts at its
//! velocity plus W and every velocity is measured relative to the wall, so the same
//! references hold. A code that left the wall's velocity out of a contact's relative
//! velocity would see an extra slip W along the axis and other rebounds.
//!
//! Everything is read from recorded frames: the head-on run at every step (the collision
//! measurement of `measure::cylinder_inside`), the oblique runs at their first and last
//! step, once every sphere has left the wall.

use super::oblique_impact::Parameters;
use crate::contact::normal::hertz::{hertz_contact_duration, hertz_max_overlap};
use crate::error::{Result, TampError};
use crate::measure::region::ball_volume;
use crate::particles::Vec3;
use crate::scene::walls::{Curvature, MotionSpec, ShapeSpec};
use crate::verify::recording::{Frame, RecordSpec};
use crate::verify::{CaseContext, Measured, measure};

/// The cylinder's axis point, unit axis, radius, curvature rule and velocity.
struct Cylinder {
    origin: Vec3,
    axis: Vec3,
    radius: f64,
    curvature: Curvature,
    velocity: Vec3,
}

pub fn run(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let p: Parameters = ctx.parameters()?;
    if p.angles_deg.is_empty() {
        return Err(TampError::Other("parameters.angles_deg: no angle".into()));
    }
    let base = ctx.scene()?;
    let needed = || {
        TampError::Other(
            "the scene must hold one sphere moving head-on towards walls[0], a cylinder of the sphere's material".into(),
        )
    };
    let (Some(wall), [sphere]) = (base.walls.first(), base.particles.as_slice()) else {
        return Err(needed());
    };
    let cylinder = match (&wall.shape, &wall.motion) {
        (
            &ShapeSpec::Cylinder {
                origin,
                axis,
                radius,
                curvature,
                ..
            },
            motion,
        ) => {
            let axis = Vec3::from(axis).normalize();
            let velocity = match motion {
                MotionSpec::Fixed => Vec3::zeros(),
                MotionSpec::Velocity { velocity } => Vec3::from(*velocity),
                _ => return Err(needed()),
            };
            // Sliding along its own axis, the wall keeps its place around the spheres.
            if (velocity - axis * velocity.dot(&axis)).norm() > 1e-12 * velocity.norm() {
                return Err(TampError::Other(
                    "walls[0] may move only along its own axis".into(),
                ));
            }
            Cylinder {
                origin: Vec3::from(origin),
                axis,
                radius,
                curvature,
                velocity,
            }
        }
        _ => return Err(needed()),
    };
    let super::one_material::OneMaterial {
        density,
        effective_modulus: e_star,
    } = super::one_material::of(&base)?;
    let r = sphere.radius;
    let r_eff = match cylinder.curvature {
        Curvature::Flat => r,
        Curvature::Mean => 2.0 * r * cylinder.radius / (2.0 * cylinder.radius - r),
    };
    let mass = density * ball_volume(r);
    // The head-on velocity relative to the wall (the radial approach, which the
    // collision measurement reads, is the same in the lab: W runs along the axis).
    let velocity = Vec3::from(sphere.velocity.unwrap_or([0.0; 3]));
    let speed = velocity.norm();
    let mut head_on = base.clone();
    head_on.particles[0].velocity = Some((velocity + cylinder.velocity).into());

    let rec = ctx.record("head_on", &head_on, RecordSpec::EVERY_STEP)?;
    let c = measure::cylinder_inside(&rec, 0, cylinder.origin, cylinder.axis, cylinder.radius)?;
    let mut out = vec![
        Measured::new(
            "contact_duration",
            c.duration,
            hertz_contact_duration(mass, speed, r_eff, e_star),
        ),
        Measured::new(
            "max_overlap",
            c.max_overlap,
            hertz_max_overlap(mass, speed, r_eff, e_star),
        ),
        Measured::new("restitution", c.restitution, 1.0),
    ];

    // The head-on direction is the wall's inward normal n; the tangent t runs around the
    // circumference, perpendicular to n and to the axis.
    let n = -velocity / speed;
    let t = cylinder.axis.cross(&n);
    for law in &p.laws {
        let mut s = base.clone();
        s.contact = law.contact.clone();
        s.particles = p.spheres_at_angles(sphere, cylinder.axis, n, t, cylinder.velocity);
        let (first, last) = ctx.first_and_last(&law.label, &s)?;
        for (k, b) in last.bodies.iter().enumerate() {
            let d = b.position - cylinder.origin;
            let from_axis = (d - cylinder.axis * d.dot(&cylinder.axis)).norm();
            if b.radius - (cylinder.radius - from_axis) >= 0.0 {
                return Err(TampError::Other(format!(
                    "{} at {}°: the sphere still touches the wall at step {}",
                    law.label, p.angles_deg[k], last.step
                )));
            }
        }
        let in_wall_frame = |f: &Frame| {
            let mut f = f.clone();
            f.bodies
                .iter_mut()
                .for_each(|b| b.velocity -= cylinder.velocity);
            measure::kinetic_energy(&f, density)
        };
        let ratio = in_wall_frame(&last) / in_wall_frame(&first);
        out.push(Measured::between(
            &format!("kinetic_energy_ratio_{}", law.label),
            ratio,
            0.0,
            1.0,
        ));
    }
    Ok(out)
}
