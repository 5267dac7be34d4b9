//! Closest point of a triangle (a, b, c) to a point p, and which feature holds it.
//!
//! The plane of the triangle is split into seven Voronoi regions: three vertex
//! regions, three edge regions and the face (Ericson, Real-Time Collision Detection
//! §5.1.5). With ab = b − a, ac = c − a and the dot products
//!   d1 = ab·(p − a), d2 = ac·(p − a), d3 = ab·(p − b), d4 = ac·(p − b),
//!   d5 = ab·(p − c), d6 = ac·(p − c),
//! p is in the region of
//!   a        when d1 ≤ 0 and d2 ≤ 0,
//!   b        when d3 ≥ 0 and d4 ≤ d3,
//!   c        when d6 ≥ 0 and d5 ≤ d6,
//!   edge ab  when vc = d1 d4 − d3 d2 ≤ 0, d1 ≥ 0, d3 ≤ 0   (point a + ab d1/(d1 − d3)),
//!   edge ca  when vb = d5 d2 − d1 d6 ≤ 0, d2 ≥ 0, d6 ≤ 0   (point a + ac d2/(d2 − d6)),
//!   edge bc  when va = d3 d6 − d5 d4 ≤ 0, d4 − d3 ≥ 0, d5 − d6 ≥ 0,
//!   the face otherwise, with barycentric weights (va, vb, vc)/(va + vb + vc).
//! The denominators are |ab|², |ac|², |bc|² and twice the squared area, never zero
//! for a non-degenerate triangle. A projection exactly on an edge is classed as the
//! edge, so the face class means strictly inside.

use crate::particles::Vec3;

/// The part of a triangle a closest point lies on. Edges are numbered by their
/// first vertex: 0 = ab, 1 = bc, 2 = ca.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Feature {
    /// Strictly inside the triangle.
    Face,
    /// On edge k (0 = ab, 1 = bc, 2 = ca).
    Edge(u8),
    /// At vertex k (0 = a, 1 = b, 2 = c).
    Vertex(u8),
}

impl Feature {
    /// Processing order of the deduplication rule (faces, then edges, then vertices).
    #[inline]
    pub fn rank(self) -> u8 {
        match self {
            Feature::Face => 0,
            Feature::Edge(_) => 1,
            Feature::Vertex(_) => 2,
        }
    }
}

/// A non-degenerate triangle with its unit normal and length scale.
#[derive(Clone, Debug, PartialEq)]
pub struct Triangle {
    /// Corners a, b, c, m.
    pub vertices: [Vec3; 3],
    /// Unit normal, (b − a) × (c − a) normalised.
    pub normal: Vec3,
    /// Longest edge, the length scale of tolerances.
    pub size: f64,
}

impl Triangle {
    /// None when a coordinate is not finite or the triangle has no area (its
    /// vertices are collinear to within 1e-12 of its longest edge squared).
    pub fn new(vertices: [Vec3; 3]) -> Option<Self> {
        if !vertices.iter().all(|v| v.iter().all(|c| c.is_finite())) {
            return None;
        }
        let [a, b, c] = vertices;
        let size = (b - a).norm().max((c - b).norm()).max((a - c).norm());
        let n = (b - a).cross(&(c - a));
        let twice_area = n.norm();
        if size == 0.0 || twice_area <= 1e-12 * size * size {
            return None;
        }
        Some(Triangle {
            vertices,
            normal: n / twice_area,
            size,
        })
    }

    /// Componentwise bounds of the three vertices.
    pub fn bounds(&self) -> (Vec3, Vec3) {
        let [a, b, c] = &self.vertices;
        (a.inf(b).inf(c), a.sup(b).sup(c))
    }

    /// The point of the triangle closest to p, and the feature it lies on.
    pub fn closest_point(&self, p: &Vec3) -> (Vec3, Feature) {
        let [a, b, c] = &self.vertices;
        let ab = b - a;
        let ac = c - a;

        let ap = p - a;
        let d1 = ab.dot(&ap);
        let d2 = ac.dot(&ap);
        if d1 <= 0.0 && d2 <= 0.0 {
            return (*a, Feature::Vertex(0));
        }

        let bp = p - b;
        let d3 = ab.dot(&bp);
        let d4 = ac.dot(&bp);
        if d3 >= 0.0 && d4 <= d3 {
            return (*b, Feature::Vertex(1));
        }

        let vc = d1 * d4 - d3 * d2;
        if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
            let v = d1 / (d1 - d3);
            return (a + ab * v, Feature::Edge(0));
        }

        let cp = p - c;
        let d5 = ab.dot(&cp);
        let d6 = ac.dot(&cp);
        if d6 >= 0.0 && d5 <= d6 {
            return (*c, Feature::Vertex(2));
        }

        let vb = d5 * d2 - d1 * d6;
        if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
            let w = d2 / (d2 - d6);
            return (a + ac * w, Feature::Edge(2));
        }

        let va = d3 * d6 - d5 * d4;
        if va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0 {
            let w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
            return (b + (c - b) * w, Feature::Edge(1));
        }

        let denom = 1.0 / (va + vb + vc);
        let v = vb * denom;
        let w = vc * denom;
        (a + ab * v + ac * w, Feature::Face)
    }

    /// Whether p lies on the triangle, to 1e-9 of its size.
    pub fn contains(&self, p: &Vec3) -> bool {
        let (q, _) = self.closest_point(p);
        (p - q).norm() <= 1e-9 * self.size
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn tri() -> Triangle {
        Triangle::new([
            Vec3::new(0.0, 0.0, 0.0),
            Vec3::new(2.0, 0.0, 0.0),
            Vec3::new(0.0, 2.0, 0.0),
        ])
        .unwrap()
    }

    #[test]
    fn every_region() {
        let t = tri();
        let cases = [
            (
                Vec3::new(0.5, 0.5, 3.0),
                Vec3::new(0.5, 0.5, 0.0),
                Feature::Face,
            ),
            (
                Vec3::new(-1.0, -1.0, 1.0),
                Vec3::zeros(),
                Feature::Vertex(0),
            ),
            (
                Vec3::new(3.0, -0.5, 0.0),
                Vec3::new(2.0, 0.0, 0.0),
                Feature::Vertex(1),
            ),
            (
                Vec3::new(-0.1, 2.5, 0.0),
                Vec3::new(0.0, 2.0, 0.0),
                Feature::Vertex(2),
            ),
            (
                Vec3::new(1.0, -1.0, 1.0),
                Vec3::new(1.0, 0.0, 0.0),
                Feature::Edge(0),
            ),
            (
                Vec3::new(2.0, 2.0, -1.0),
                Vec3::new(1.0, 1.0, 0.0),
                Feature::Edge(1),
            ),
            (
                Vec3::new(-3.0, 1.5, 0.0),
                Vec3::new(0.0, 1.5, 0.0),
                Feature::Edge(2),
            ),
            // Projection exactly on an edge belongs to the edge.
            (
                Vec3::new(1.0, 0.0, 0.7),
                Vec3::new(1.0, 0.0, 0.0),
                Feature::Edge(0),
            ),
        ];
        for (p, q, f) in cases {
            let (got, feature) = t.closest_point(&p);
            assert!((got - q).norm() < 1e-15, "{p:?}: {got:?} vs {q:?}");
            assert_eq!(feature, f, "{p:?}");
        }
        assert_eq!(t.normal, Vec3::z());
        assert_eq!(t.size, 8f64.sqrt());
    }

    #[test]
    fn degenerate_triangles_are_refused() {
        let z = Vec3::zeros();
        assert!(Triangle::new([z, z, z]).is_none());
        let collinear = [z, Vec3::new(1.0, 1.0, 1.0), Vec3::new(2.0, 2.0, 2.0)];
        assert!(Triangle::new(collinear).is_none());
        assert!(Triangle::new([z, Vec3::x(), Vec3::new(f64::NAN, 0.0, 0.0)]).is_none());
    }

    fn coord() -> impl Strategy<Value = f64> {
        -2.0..2.0f64
    }
    fn point() -> impl Strategy<Value = Vec3> {
        (coord(), coord(), coord()).prop_map(|(x, y, z)| Vec3::new(x, y, z))
    }

    proptest! {
        /// The closest point is no farther than any point of a dense barycentric
        /// sample of the triangle, and lies on the triangle.
        #[test]
        fn closest_point_beats_sampling(a in point(), b in point(), c in point(), p in point()) {
            let Some(t) = Triangle::new([a, b, c]) else { return Ok(()); };
            let (q, _) = t.closest_point(&p);
            let d = (p - q).norm();
            prop_assert!(t.contains(&q));
            let n = 40;
            for i in 0..=n {
                for j in 0..=(n - i) {
                    let (u, v) = (i as f64 / n as f64, j as f64 / n as f64);
                    let s = a + (b - a) * u + (c - a) * v;
                    prop_assert!(d <= (p - s).norm() + 1e-12);
                }
            }
        }
    }
}
