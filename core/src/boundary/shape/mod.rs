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
//!
//! The kinds (Zhong 2009 §3): an infinite plane, the inside of a box, surfaces of
//! revolution of a polyline (cylinder, cone, funnel), and triangle meshes (convex
//! polygon sets, STL files, height fields z = f(x, y)).
//!
//! Shapes made of several parts share one rule for "the same touching point"
//! (`push_distinct`): candidates whose closest point is interior to their part
//! come first, then those on a part's edge, then those on a corner; a candidate
//! is dropped when its closest point lies on a part already accepted for this
//! sphere. What remains is one contact per local minimum of the distance over the
//! whole surface: a ridge or a flat seam gives one contact, a valley or an inside
//! corner one per face.

pub mod box_shape;
pub mod mesh;
pub mod plane;
pub mod revolved;
pub mod triangle;

pub use box_shape::BoxShape;
pub use mesh::Mesh;
pub use plane::Plane;
pub use revolved::Revolved;
pub use triangle::{Feature, Triangle};

use crate::particles::Vec3;

/// One touching part of a shape, as the module's contract defines it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShapeContact {
    /// Unit normal from the surface towards the sphere centre.
    pub normal: Vec3,
    /// Overlap δ = r − (centre-to-surface distance), m; negative across a gap.
    pub overlap: f64,
    /// Which part of the shape is touched (box face, mesh triangle, profile segment); 0
    /// for single-surface shapes.
    pub facet: u32,
}

/// A wall's geometry in its rest frame, one of the kinds of Zhong 2009 §3.
#[derive(Clone, Debug)]
pub enum Shape {
    /// Infinite one-sided plane.
    Plane(Plane),
    /// Inside of an axis-aligned box, some faces possibly open.
    Box(BoxShape),
    /// Thin two-sided surface of revolution of a polyline (cylinder, cone, funnel).
    Revolved(Revolved),
    /// Two-sided triangle mesh (polygon sets, STL files, height fields).
    Mesh(Mesh),
}

impl Shape {
    /// Append the contacts of a sphere of centre `centre` (rest frame) and radius
    /// `radius` with this shape, those within `reach` of it included, as the module's
    /// contract states.
    // `always`: every sphere asks every wall every step; as a call the plane's few
    // instructions paid for the call and for reloading the centre.
    #[inline(always)]
    pub fn contacts(&self, centre: &Vec3, radius: f64, reach: f64, out: &mut Vec<ShapeContact>) {
        match self {
            Shape::Plane(s) => s.contacts(centre, radius, reach, out),
            Shape::Box(s) => s.contacts(centre, radius, reach, out),
            Shape::Revolved(s) => s.contacts(centre, radius, reach, out),
            Shape::Mesh(s) => s.contacts(centre, radius, reach, out),
        }
    }
}

/// One part's closest point to a sphere centre, before deduplication.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Candidate {
    /// 0: interior of the part, 1: on an edge, 2: on a corner (see `Feature::rank`).
    pub rank: u8,
    /// Centre-to-surface distance (signed for one-sided parts, so it may be < 0).
    pub distance: f64,
    pub facet: u32,
    pub point: Vec3,
    pub normal: Vec3,
}

/// Append the candidates that are distinct touching points, in the order of the
/// module rule. `lies_on(facet, point)` says whether a point lies on that part.
/// The order is total (rank, distance, facet), so the result does not depend on
/// the order in which the candidates were found. The common cases cost nothing
/// extra: no candidate appends nothing, and a lone one is appended as it is
/// (sorting one element and checking it against no kept contact are no-ops).
pub(crate) fn push_distinct(
    candidates: &mut [Candidate],
    radius: f64,
    lies_on: impl Fn(u32, &Vec3) -> bool,
    out: &mut Vec<ShapeContact>,
) {
    candidates.sort_unstable_by(|a, b| {
        a.rank
            .cmp(&b.rank)
            .then(a.distance.total_cmp(&b.distance))
            .then(a.facet.cmp(&b.facet))
    });
    let start = out.len();
    for c in candidates.iter() {
        if out[start..]
            .iter()
            .any(|kept| lies_on(kept.facet, &c.point))
        {
            continue;
        }
        out.push(ShapeContact {
            normal: c.normal,
            overlap: radius - c.distance,
            facet: c.facet,
        });
    }
}

/// The contract's reporting rule, false for a NaN overlap (as in `Plane`).
#[inline]
pub(crate) fn within_reach(overlap: f64, reach: f64) -> bool {
    overlap > -reach
}

/// A unit vector perpendicular to the unit vector `a`, the same for the same `a`:
/// `a` crossed with the coordinate axis it is least aligned with.
pub(crate) fn perpendicular(a: &Vec3) -> Vec3 {
    let k = (0..3)
        .min_by(|&i, &j| a[i].abs().total_cmp(&a[j].abs()))
        .unwrap_or(0);
    let mut e = Vec3::zeros();
    e[k] = 1.0;
    a.cross(&e).normalize()
}
