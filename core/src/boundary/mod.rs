//! Boundaries: rigid bodies of given shape that particles collide with (Zhong 2009
//! §3: simple shapes, z = f(x, y) surfaces, convex polygon sets), each with its own
//! material and motion.
//!
//! A boundary is its shape in a rest frame plus a translation u(t). A contact is
//! found by asking the shape about the particle centre moved into the rest frame,
//! x − u; the contact point moves with the boundary's velocity. A boundary counts as
//! infinitely massive, m* = m_i, and by default as flat in the contact law, R* = R_i (a
//! curved boundary too: the radius of a die or funnel is many particle radii). A
//! cylinder may opt in to its curvature (`WallCurvature::Mean`,
//! `Boundary::effective_radius`).

pub mod motion;
pub mod pose;
pub mod shape;

pub use motion::{BoundaryMotion, PressureLoad, Servo};
pub use pose::WallPose;
use shape::{Shape, ShapeContact};

use crate::particles::Vec3;

/// How a boundary's curvature enters the contact's effective radius.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum WallCurvature {
    /// R* = R_i, as against a plane (the default of every wall).
    Flat,
    /// A cylinder of radius `radius` about the axis through `origin` along the unit
    /// vector `axis` (rest frame), entering the contact as the sphere of its mean
    /// curvature: `Boundary::effective_radius`.
    Mean {
        /// Point on the cylinder's axis, m (rest frame).
        origin: Vec3,
        /// Unit vector along the cylinder's axis.
        axis: Vec3,
        /// Cylinder radius R_c, m.
        radius: f64,
    },
}

/// A wall: a rigid body of given shape, material and prescribed or controlled
/// translation, that the particles collide with.
#[derive(Clone, Debug)]
pub struct Boundary {
    /// Name given in the scene, used in reports and error messages.
    pub name: String,
    /// Geometry in the rest frame.
    pub shape: Shape,
    /// Index of the wall's material in the scene's material list (selects the pair
    /// parameters of its contacts).
    pub material: usize,
    /// How the wall translates over time.
    pub motion: BoundaryMotion,
    /// Whether the contact's R* sees the wall as flat or as a curved cylinder.
    pub curvature: WallCurvature,
}

impl Boundary {
    /// A wall flat in the contact law.
    pub fn new(name: String, shape: Shape, material: usize, motion: BoundaryMotion) -> Self {
        Boundary {
            name,
            shape,
            material,
            motion,
            curvature: WallCurvature::Flat,
        }
    }

    /// The wall's pose at t = 0: where its motion puts it, moving at its prescribed
    /// velocity if it has one.
    pub fn initial_pose(&self) -> WallPose {
        WallPose {
            displacement: self.motion.displacement_at(0.0).unwrap_or_else(Vec3::zeros),
            velocity: match self.motion {
                BoundaryMotion::Velocity(v) => v,
                _ => Vec3::zeros(),
            },
        }
    }

    /// The effective radius R* of a contact of a sphere of radius R centred at `centre`
    /// with this boundary: the one place a wall contact's R* is formed (forces,
    /// records, stored energy, the time-step stiffness).
    ///
    /// `Flat`: R* = R. `Mean`: the cylinder of radius R_c enters as a sphere of its
    /// mean curvature (1/R_c + 0)/2, of radius r_w = −2R_c seen from inside (concave)
    /// and +2R_c from outside (convex), and R* = R r_w/(R + r_w) as for two spheres
    /// (Johnson 1985 §4.2 with one radius signed): inside R* = 2R R_c/(2R_c − R) > R.
    /// This is LAMMPS's rule (22 Jul 2025): fix_wall_gran.cpp `post_force` sets
    /// `rwall = (delxy < cylradius) ? -2*cylradius : 2*cylradius` for `zcylinder`,
    /// region_cylinder.cpp `surface_interior` sets the contact radius −2R_c for the
    /// curved face, and granular_model.cpp `check_contact` forms
    /// Reff = radi·radj/(radi + radj) for both wall kinds. Inside is where the centre's
    /// distance from the axis is below R_c (every contact with the wall, rim ones
    /// included, takes the wall's r_w).
    #[inline(always)]
    pub fn effective_radius(&self, pose: &WallPose, centre: &Vec3, radius: f64) -> f64 {
        match &self.curvature {
            WallCurvature::Flat => radius,
            WallCurvature::Mean {
                origin,
                axis,
                radius: r_c,
            } => {
                let x = centre - pose.displacement - origin;
                let rho = (x - axis * x.dot(axis)).norm();
                let r_w = if rho < *r_c { -2.0 * r_c } else { 2.0 * r_c };
                radius * r_w / (radius + r_w)
            }
        }
    }

    /// Contacts of a sphere with this boundary at `pose`, appended to `out`.
    #[inline(always)]
    pub fn contacts(
        &self,
        pose: &WallPose,
        centre: &Vec3,
        radius: f64,
        reach: f64,
        out: &mut Vec<ShapeContact>,
    ) {
        self.shape
            .contacts(&(centre - pose.displacement), radius, reach, out);
    }

    /// Largest overlap of a sphere with any part of the boundary, −∞ when it touches
    /// none. For set-up checks (insertion, initial overlaps), not the force loop.
    pub fn deepest_overlap(&self, pose: &WallPose, centre: &Vec3, radius: f64) -> f64 {
        let mut found = Vec::new();
        self.contacts(pose, centre, radius, 0.0, &mut found);
        found
            .iter()
            .map(|c| c.overlap)
            .fold(f64::NEG_INFINITY, f64::max)
    }

    /// Whether a sphere touches none of `walls` at their `poses`: where insertion may
    /// put it.
    pub fn clear_of_all(
        walls: &[Boundary],
        poses: &[WallPose],
        centre: &Vec3,
        radius: f64,
    ) -> bool {
        walls
            .iter()
            .zip(poses)
            .all(|(w, pose)| w.deepest_overlap(pose, centre, radius) <= 0.0)
    }

    /// Move `pose` over the step [t, t + dt]; `force_on_boundary` is the force the particles
    /// exerted at t (what a servo or a pressed punch reacts to). Fails when a displacement expression
    /// stops being finite (the other motions cannot).
    pub fn advance(
        &self,
        pose: &mut WallPose,
        t: f64,
        dt: f64,
        force_on_boundary: &Vec3,
    ) -> Result<(), String> {
        match &self.motion {
            BoundaryMotion::Fixed => pose.velocity = Vec3::zeros(),
            BoundaryMotion::Velocity(v) => pose.velocity = *v,
            BoundaryMotion::Displacement(_) => {
                let next = self
                    .motion
                    .displacement_at(t + dt)
                    .expect("displacement motion");
                if !next.iter().all(|c| c.is_finite()) {
                    return Err(format!(
                        "wall '{}' has a non-finite displacement {next:?} at t = {:e} s (check its motion expressions)",
                        self.name,
                        t + dt
                    ));
                }
                pose.velocity = if dt > 0.0 {
                    (next - pose.displacement) / dt
                } else {
                    Vec3::zeros()
                };
                pose.displacement = next;
                return Ok(());
            }
            BoundaryMotion::Servo(s) => pose.velocity = s.velocity(force_on_boundary),
            BoundaryMotion::Pressed(p) => {
                pose.velocity = p.velocity(t, dt, &pose.velocity, force_on_boundary)
            }
        }
        pose.displacement += pose.velocity * dt;
        Ok(())
    }
}
