//! Boundary geometry, in the boundary's own (rest) frame. A shape answers one
//! question: which parts of it does a sphere of centre x and radius r touch, or
//! come within `reach` of (cohesion acts across a gap)?
//!
//! Contract of `Shape::contacts` (every kind keeps it; tests in each file check it):
//! - It appends one `ShapeContact` per touching part and never clears `out`.
//! - `normal` is a unit vector from the surface towards the sphere centre, so a
//!   positive normal force pushes the particle away from the surface.
//! - `overlap` = r − (distance from the centre to the surface); contacts are
//!   reported only when `overlap > −reach`.
//! - `facet` identifies the part (a box face, a mesh triangle) so tangential
//!   history can follow a contact from step to step; single-surface shapes use 0.
//! - The same touching point is never reported twice (a sphere on the shared edge
//!   of two coplanar triangles gets one contact).

pub mod plane;

pub use plane::Plane;

use crate::particles::Vec3;

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShapeContact {
    pub normal: Vec3,
    pub overlap: f64,
    pub facet: u32,
}

#[derive(Clone, Debug)]
pub enum Shape {
    Plane(Plane),
}

impl Shape {
    #[inline]
    pub fn contacts(&self, centre: &Vec3, radius: f64, reach: f64, out: &mut Vec<ShapeContact>) {
        match self {
            Shape::Plane(s) => s.contacts(centre, radius, reach, out),
        }
    }
}
