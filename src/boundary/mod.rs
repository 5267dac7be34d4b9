//! Boundaries: rigid bodies of given shape that particles collide with (Zhong 2009
//! §3: simple shapes, z = f(x, y) surfaces, convex polygon sets), each with its own
//! material and motion.
//!
//! A boundary is its shape in a rest frame plus a translation u(t). A contact is
//! found by asking the shape about the particle centre moved into the rest frame,
//! x − u; the contact point moves with the boundary's velocity. A boundary counts as
//! infinitely massive with an infinite radius of curvature where flat, so
//! R* = R_i and m* = m_i in the contact law (a curved boundary is treated the same:
//! the radius of a die or funnel is many particle radii).

pub mod motion;
pub mod shape;

pub use motion::{BoundaryMotion, PressureLoad, Servo};
use shape::{Shape, ShapeContact};

use crate::particles::Vec3;

#[derive(Clone, Debug)]
pub struct Boundary {
    pub name: String,
    pub shape: Shape,
    pub material: usize,
    pub motion: BoundaryMotion,
    /// Translation from the rest frame, m.
    pub displacement: Vec3,
    /// Velocity during the current step, m/s.
    pub velocity: Vec3,
}

impl Boundary {
    pub fn new(name: String, shape: Shape, material: usize, motion: BoundaryMotion) -> Self {
        let mut b = Boundary {
            name,
            shape,
            material,
            motion,
            displacement: Vec3::zeros(),
            velocity: Vec3::zeros(),
        };
        if let Some(u0) = b.motion.displacement_at(0.0) {
            b.displacement = u0;
        }
        if let BoundaryMotion::Velocity(v) = b.motion {
            b.velocity = v;
        }
        b
    }

    /// Contacts of a sphere with this boundary, appended to `out`.
    #[inline(always)]
    pub fn contacts(&self, centre: &Vec3, radius: f64, reach: f64, out: &mut Vec<ShapeContact>) {
        self.shape
            .contacts(&(centre - self.displacement), radius, reach, out);
    }

    /// Largest overlap of a sphere with any part of the boundary, −∞ when it touches
    /// none. For set-up checks (insertion, initial overlaps), not the force loop.
    pub fn deepest_overlap(&self, centre: &Vec3, radius: f64) -> f64 {
        let mut found = Vec::new();
        self.contacts(centre, radius, 0.0, &mut found);
        found
            .iter()
            .map(|c| c.overlap)
            .fold(f64::NEG_INFINITY, f64::max)
    }

    /// Whether a sphere touches none of `walls`: where insertion may put it.
    pub fn clear_of_all(walls: &[Boundary], centre: &Vec3, radius: f64) -> bool {
        walls
            .iter()
            .all(|w| w.deepest_overlap(centre, radius) <= 0.0)
    }

    /// Move over the step [t, t + dt]; `force_on_boundary` is the force the particles
    /// exerted at t (what a servo or a pressed punch reacts to). Fails when a displacement expression
    /// stops being finite (the other motions cannot).
    pub fn advance(&mut self, t: f64, dt: f64, force_on_boundary: &Vec3) -> Result<(), String> {
        match &self.motion {
            BoundaryMotion::Fixed => self.velocity = Vec3::zeros(),
            BoundaryMotion::Velocity(v) => self.velocity = *v,
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
                self.velocity = if dt > 0.0 {
                    (next - self.displacement) / dt
                } else {
                    Vec3::zeros()
                };
                self.displacement = next;
                return Ok(());
            }
            BoundaryMotion::Servo(s) => self.velocity = s.velocity(force_on_boundary),
            BoundaryMotion::Pressed(p) => {
                self.velocity = p.velocity(t, dt, &self.velocity, force_on_boundary)
            }
        }
        self.displacement += self.velocity * dt;
        Ok(())
    }
}
