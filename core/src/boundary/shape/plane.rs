//! Infinite one-sided plane. A sphere on the side the unit normal n points to
//! touches it when its centre is closer than its radius:
//!   d = (x − p)·n,  δ = R − d,  contact normal = n.
//! A sphere behind the plane (d < 0) still gets δ = R − d > R, so deep penetration
//! is reported as such (and stopped by the stability limit) rather than missed.

use super::ShapeContact;
use crate::particles::Vec3;

/// An infinite one-sided plane through a point, facing the particles.
#[derive(Clone, Debug)]
pub struct Plane {
    /// A point of the plane, m.
    pub point: Vec3,
    /// Unit normal, pointing towards the particles.
    pub normal: Vec3,
}

impl Plane {
    /// Signed distance of a point from the plane, positive on the normal's side.
    #[inline]
    pub fn distance(&self, x: &Vec3) -> f64 {
        (x - self.point).dot(&self.normal)
    }

    /// Append the contact of a sphere with the plane (facet 0) when δ > −`reach`.
    #[inline(always)]
    pub fn contacts(&self, centre: &Vec3, radius: f64, reach: f64, out: &mut Vec<ShapeContact>) {
        let overlap = radius - self.distance(centre);
        if overlap > -reach {
            out.push(ShapeContact {
                normal: self.normal,
                overlap,
                facet: 0,
            });
        }
    }
}
