//! The inside of an axis-aligned box [lower, upper] as a container. Each of its six
//! faces is a finite rectangle that pushes inward; facet k is the face
//!   k = 0: x = lower.x, 1: x = upper.x, 2: y = lower.y, 3: y = upper.y,
//!   4: z = lower.z, 5: z = upper.z,
//! with inward unit normal n_k = +e_a for the lower face of axis a, −e_a for the
//! upper one. A face can be left out (`faces[k] = false`): a die has no lid.
//!
//! For a face on axis a and a sphere centre x, let q be the closest point of the
//! face rectangle (x with its a-coordinate set to the face's and the other two
//! clamped to [lower, upper]).
//! - If no clamping was needed (x lies over the rectangle), the face acts as a
//!   one-sided plane: d = (x − q)·n_k, signed, so a centre behind the face (escaped
//!   through it) has δ = r − d > r and is reported as a deep penetration, exactly
//!   as `Plane` does.
//! - Otherwise x is beyond an edge of the face and d = |x − q| with normal
//!   (x − q)/d: the rim of an open box is a rounded knife edge, so a particle
//!   spilling over the top of a die wall meets the rim rather than the wall's
//!   infinite extension.
//!
//! A sphere in a corner touches up to three faces. Where two present faces meet,
//! a centre outside both clamps both to the same edge point; the shared rule of
//! `super::push_distinct` keeps one of them.

use super::{Candidate, ShapeContact, push_distinct, within_reach};
use crate::error::{Result, TampError};
use crate::particles::Vec3;

/// The inside of an axis-aligned box as a container; each present face pushes
/// inward.
#[derive(Clone, Debug)]
pub struct BoxShape {
    /// Lower corner, m.
    pub lower: Vec3,
    /// Upper corner, m.
    pub upper: Vec3,
    /// Which faces exist, in facet order (−x, +x, −y, +y, −z, +z).
    pub faces: [bool; 6],
}

impl BoxShape {
    /// A closed box. Errors unless every coordinate is finite and lower < upper.
    pub fn new(lower: Vec3, upper: Vec3) -> Result<Self> {
        Self::with_faces(lower, upper, [true; 6])
    }

    /// A box with only the faces marked true, in facet order (−x, +x, −y, +y, −z, +z).
    pub fn with_faces(lower: Vec3, upper: Vec3, faces: [bool; 6]) -> Result<Self> {
        if !(lower.iter().chain(upper.iter()).all(|v| v.is_finite())) {
            return Err(TampError::input(
                "box",
                "the box corners must be finite numbers",
            ));
        }
        for (a, name) in ["x", "y", "z"].iter().enumerate() {
            if lower[a] >= upper[a] {
                return Err(TampError::input(
                    "box",
                    format!(
                        "lower {name} ({}) must be below upper {name} ({})",
                        lower[a], upper[a]
                    ),
                ));
            }
        }
        if !faces.iter().any(|&f| f) {
            return Err(TampError::input("box", "a box needs at least one face"));
        }
        Ok(BoxShape {
            lower,
            upper,
            faces,
        })
    }

    /// A closed box without its +z face (a die or an open container).
    pub fn open_top(lower: Vec3, upper: Vec3) -> Result<Self> {
        Self::with_faces(lower, upper, [true, true, true, true, true, false])
    }

    /// The rectangle of face k: its axis, the coordinate of its plane and its
    /// inward normal.
    #[inline]
    fn face(&self, k: usize) -> (usize, f64, Vec3) {
        let a = k / 2;
        let mut n = Vec3::zeros();
        if k.is_multiple_of(2) {
            n[a] = 1.0;
            (a, self.lower[a], n)
        } else {
            n[a] = -1.0;
            (a, self.upper[a], n)
        }
    }

    /// Whether a point lies on the rectangle of face k, to a tolerance relative to
    /// the box size.
    fn lies_on(&self, k: usize, p: &Vec3) -> bool {
        let tol = 1e-9 * (self.upper - self.lower).amax();
        let (a, plane, _) = self.face(k);
        (p[a] - plane).abs() <= tol
            && (0..3)
                .filter(|&b| b != a)
                .all(|b| p[b] >= self.lower[b] - tol && p[b] <= self.upper[b] + tol)
    }

    /// Append the contacts of a sphere with the present faces and their rims, one per
    /// distinct touching point (facet = face number).
    pub fn contacts(&self, centre: &Vec3, radius: f64, reach: f64, out: &mut Vec<ShapeContact>) {
        // At most one candidate per face, so they fit on the stack.
        let mut candidates = [Candidate::default(); 6];
        let mut count = 0;
        for k in (0..6).filter(|&k| self.faces[k]) {
            let (a, plane, n) = self.face(k);
            let mut q = *centre;
            q[a] = plane;
            let mut clamped = false;
            for b in (0..3).filter(|&b| b != a) {
                let c = q[b].clamp(self.lower[b], self.upper[b]);
                clamped |= c != q[b];
                q[b] = c;
            }
            let (distance, normal, rank) = if clamped {
                let v = centre - q;
                let d = v.norm();
                // A centre exactly on the rim has no direction of its own; the
                // face's inward normal is the continuous choice from inside.
                let normal = if d > 0.0 { v / d } else { n };
                (d, normal, 1)
            } else {
                ((centre - q).dot(&n), n, 0)
            };
            if within_reach(radius - distance, reach) {
                candidates[count] = Candidate {
                    rank,
                    distance,
                    facet: k as u32,
                    point: q,
                    normal,
                };
                count += 1;
            }
        }
        push_distinct(
            &mut candidates[..count],
            radius,
            |k, p| self.lies_on(k as usize, p),
            out,
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit_box() -> BoxShape {
        BoxShape::new(Vec3::new(0.0, 0.0, 0.0), Vec3::new(1.0, 2.0, 3.0)).unwrap()
    }

    fn query(b: &BoxShape, x: Vec3, r: f64, reach: f64) -> Vec<ShapeContact> {
        let mut out = Vec::new();
        b.contacts(&x, r, reach, &mut out);
        for c in &out {
            assert!((c.normal.norm() - 1.0).abs() < 1e-14);
        }
        out
    }

    #[test]
    fn sphere_near_one_face() {
        let b = unit_box();
        let out = query(&b, Vec3::new(0.5, 1.0, 0.08), 0.1, 0.0);
        assert_eq!(out.len(), 1);
        assert_eq!(out[0].facet, 4);
        assert!((out[0].overlap - 0.02).abs() < 1e-15);
        assert_eq!(out[0].normal, Vec3::new(0.0, 0.0, 1.0));
        // The +x face pushes towards −x.
        let out = query(&b, Vec3::new(0.95, 1.0, 1.5), 0.1, 0.0);
        assert_eq!(out.len(), 1);
        assert_eq!(out[0].facet, 1);
        assert!((out[0].overlap - 0.05).abs() < 1e-14);
        assert_eq!(out[0].normal, Vec3::new(-1.0, 0.0, 0.0));
    }

    #[test]
    fn corner_touches_three_faces_and_keeps_the_out_vector() {
        let b = unit_box();
        let mut out = vec![ShapeContact {
            normal: Vec3::x(),
            overlap: 9.0,
            facet: 77,
        }];
        b.contacts(&Vec3::new(0.05, 1.96, 2.97), 0.1, 0.0, &mut out);
        assert_eq!(out.len(), 4);
        assert_eq!(out[0].facet, 77);
        let mut got: Vec<(u32, f64)> = out[1..].iter().map(|c| (c.facet, c.overlap)).collect();
        got.sort_by_key(|g| g.0);
        let want = [(0, 0.05), (3, 0.06), (5, 0.07)];
        for (g, w) in got.iter().zip(want) {
            assert_eq!(g.0, w.0);
            assert!((g.1 - w.1).abs() < 1e-14, "{g:?} vs {w:?}");
        }
    }

    #[test]
    fn reach_reports_gaps_and_nothing_beyond() {
        let b = unit_box();
        let out = query(&b, Vec3::new(0.5, 1.0, 0.15), 0.1, 0.06);
        assert_eq!(out.len(), 1);
        assert!((out[0].overlap + 0.05).abs() < 1e-14);
        assert!(query(&b, Vec3::new(0.5, 1.0, 0.17), 0.1, 0.06).is_empty());
        assert!(query(&b, Vec3::new(0.5, 1.0, 1.5), 0.1, 0.0).is_empty());
    }

    #[test]
    fn escaped_centre_is_a_deep_penetration() {
        let b = unit_box();
        let out = query(&b, Vec3::new(0.5, 1.0, -0.2), 0.1, 0.0);
        assert_eq!(out.len(), 1);
        assert_eq!(out[0].facet, 4);
        assert!((out[0].overlap - 0.3).abs() < 1e-15);
    }

    #[test]
    fn open_top_rim_is_a_rounded_edge() {
        let b = BoxShape::open_top(Vec3::zeros(), Vec3::new(1.0, 1.0, 1.0)).unwrap();
        // Above the open top, inside the footprint, far from the walls: nothing.
        assert!(query(&b, Vec3::new(0.5, 0.5, 1.5), 0.1, 0.0).is_empty());
        // Resting on the +x rim from outside and above: distance to the rim line.
        let x = Vec3::new(1.03, 0.5, 1.04);
        let out = query(&b, x, 0.1, 0.0);
        assert_eq!(out.len(), 1);
        assert_eq!(out[0].facet, 1);
        assert!((out[0].overlap - 0.05).abs() < 1e-14);
        assert!((out[0].normal - Vec3::new(0.6, 0.0, 0.8)).norm() < 1e-14);
        // Just above the corner post, exactly over the vertical edge: the +x and +y
        // rims give the same point, reported once.
        let out = query(&b, Vec3::new(1.0, 1.0, 1.05), 0.1, 0.0);
        assert_eq!(out.len(), 1);
        assert!((out[0].overlap - 0.05).abs() < 1e-14);
        assert!((out[0].normal - Vec3::z()).norm() < 1e-14);
        // Over the corner but inside both walls: two distinct rim points.
        let out = query(&b, Vec3::new(0.97, 0.96, 1.02), 0.1, 0.0);
        assert_eq!(out.len(), 2);
        assert_eq!((out[0].facet, out[1].facet), (1, 3));
        assert!((out[0].overlap - (0.1 - 0.0013f64.sqrt())).abs() < 1e-14);
        assert!((out[1].overlap - (0.1 - 0.002f64.sqrt())).abs() < 1e-14);
    }

    #[test]
    fn outside_a_closed_edge_reports_one_point() {
        let b = unit_box();
        // Outside both the +x and +z faces, diagonally beyond their shared edge.
        let out = query(&b, Vec3::new(1.03, 1.0, 3.04), 0.1, 0.0);
        assert_eq!(out.len(), 1);
        assert!((out[0].overlap - 0.05).abs() < 1e-14);
    }

    #[test]
    fn rejects_bad_corners() {
        assert!(BoxShape::new(Vec3::zeros(), Vec3::new(1.0, 0.0, 1.0)).is_err());
        assert!(BoxShape::new(Vec3::zeros(), Vec3::new(1.0, f64::NAN, 1.0)).is_err());
        let e = BoxShape::new(Vec3::new(0.0, 2.0, 0.0), Vec3::new(1.0, 1.0, 1.0))
            .unwrap_err()
            .to_string();
        assert!(e.contains("lower y"), "{e}");
        assert!(BoxShape::with_faces(Vec3::zeros(), Vec3::repeat(1.0), [false; 6]).is_err());
    }
}
