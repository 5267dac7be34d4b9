//! Infinite plane wall. A particle on the side the unit normal points to touches
//! the wall when its centre is closer than its radius:
//!   d = (x − p)·n,  δ = R − d > 0,  contact normal = n (from the wall to the particle).
//! The wall is rigid with infinite mass and radius, so R* = R and m* = m.
//! The plane translates with a constant velocity (zero when fixed).

use crate::particles::Vec3;

#[derive(Clone, Debug)]
pub struct PlaneWall {
    pub name: String,
    pub point: Vec3,
    pub normal: Vec3,
    pub material: usize,
    pub velocity: Vec3,
}

impl PlaneWall {
    /// Signed distance of a point from the plane, positive on the normal's side.
    #[inline]
    pub fn distance(&self, x: &Vec3) -> f64 {
        (x - self.point).dot(&self.normal)
    }

    pub fn advance(&mut self, dt: f64) {
        self.point += self.velocity * dt;
    }
}
