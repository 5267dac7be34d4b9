//! A surface of revolution: a polyline profile in the meridian half-plane, turned
//! about an axis through `origin` with unit direction a. Cylinders, cone frustums
//! and funnels (an outlet tube joined to a cone) are profiles of one or two segments.
//!
//! Meridian coordinates of a point x: with x' = x − origin,
//!   h = x'·a (along the axis),  ρ = |x' − h a| (from the axis),  u = (x' − h a)/ρ.
//! The profile point (ρ_p, h_p) sweeps the circle origin + h_p a + ρ_p (cos φ e1 +
//! sin φ e2), and |x − that point|² = ρ² + ρ_p² − 2 ρ ρ_p cos(φ − φ_x) + (h − h_p)²
//! is smallest at φ = φ_x. So the 3D distance from x to the surface equals the 2D
//! distance from (ρ, h) to the polyline, the closest point is origin + h_p a + ρ_p u,
//! and the contact normal is n = n_ρ u + n_h a with (n_ρ, n_h) the 2D unit vector
//! from the closest profile point to (ρ, h). End points of the polyline are rims.
//!
//! The shell is thin and two-sided: δ = r − distance on either side.
//!
//! Several contacts: every segment offers its closest point (facet = segment index);
//! the shared rule of `super::push_distinct` keeps the distinct ones, processing
//! points interior to a segment before segment end points, and dropping a point
//! that lies on a segment already kept. Seen from the side where the knee is
//! concave (a funnel's outside, where the cone meets the tube) a sphere can have an
//! interior foot on both segments: two contacts. Seen from the convex side both
//! segments offer the shared vertex, or one offers an interior foot and the other
//! the vertex lying on it: one contact.
//!
//! Degenerate positions, chosen deterministically: a centre on the axis (ρ = 0,
//! every meridian equally close) uses the fixed radial direction e1 = a × e_k, e_k
//! the coordinate axis least aligned with a; a centre exactly on the surface uses
//! the segment's left normal (−Δh, Δρ)/|Δ| (towards the axis for a profile drawn
//! in the +h direction). A sphere wider than a tube and centred on its axis really
//! touches the whole ring, whose radial forces cancel; one contact along e1 does not
//! model that.

use super::{Candidate, ShapeContact, perpendicular, push_distinct, within_reach};
use crate::error::{Result, TampError};
use crate::particles::Vec3;

/// A thin two-sided surface of revolution: a polyline profile (ρ, h) turned about an
/// axis.
#[derive(Clone, Debug)]
pub struct Revolved {
    origin: Vec3,
    axis: Vec3,
    profile: Vec<(f64, f64)>,
    /// e1: the radial direction used for a centre on the axis.
    radial0: Vec3,
    /// Largest extent of the profile, the scale of tolerances.
    scale: f64,
    /// The profile's bounding box in the meridian plane: ρ_min, ρ_max, h_min, h_max.
    bounds: [f64; 4],
}

/// 2D closest point of the segment p → q to c: (point, parameter t in [0, 1]).
#[inline]
fn closest_on_segment(p: (f64, f64), q: (f64, f64), c: (f64, f64)) -> ((f64, f64), f64) {
    let e = (q.0 - p.0, q.1 - p.1);
    let len2 = e.0 * e.0 + e.1 * e.1;
    let t = (((c.0 - p.0) * e.0 + (c.1 - p.1) * e.1) / len2).clamp(0.0, 1.0);
    ((p.0 + t * e.0, p.1 + t * e.1), t)
}

impl Revolved {
    /// A profile of (ρ, h) points, ρ ≥ 0, consecutive points distinct. `axis` need
    /// not be unit length; it is normalised.
    pub fn new(origin: Vec3, axis: Vec3, profile: Vec<(f64, f64)>) -> Result<Self> {
        if !origin.iter().chain(axis.iter()).all(|v| v.is_finite()) {
            return Err(TampError::input(
                "origin",
                "origin and axis must be finite numbers",
            ));
        }
        let length = axis.norm();
        if length == 0.0 {
            return Err(TampError::input("axis", "the axis must not be zero"));
        }
        let axis = axis / length;
        if profile.len() < 2 {
            return Err(TampError::input(
                "profile",
                "a profile needs at least two (radius, height) points",
            ));
        }
        for (k, &(rho, h)) in profile.iter().enumerate() {
            if !(rho.is_finite() && h.is_finite()) {
                return Err(TampError::input(
                    format!("profile[{k}]"),
                    format!("profile point {k} must be finite numbers"),
                ));
            }
            if rho < 0.0 {
                return Err(TampError::input(
                    format!("profile[{k}]"),
                    format!("profile point {k} has a negative radius ({rho})"),
                ));
            }
        }
        let scale = profile
            .iter()
            .map(|&(rho, h)| rho.abs().max(h.abs()))
            .fold(0.0, f64::max);
        for (k, w) in profile.windows(2).enumerate() {
            let d = (w[1].0 - w[0].0).hypot(w[1].1 - w[0].1);
            if d <= 1e-12 * scale {
                return Err(TampError::input(
                    format!("profile[{}]", k + 1),
                    format!("profile point {} repeats point {k}", k + 1),
                ));
            }
        }
        let fold = |pick: fn(&(f64, f64)) -> f64, start: f64, f: fn(f64, f64) -> f64| {
            profile.iter().map(pick).fold(start, f)
        };
        let bounds = [
            fold(|p| p.0, f64::INFINITY, f64::min),
            fold(|p| p.0, f64::NEG_INFINITY, f64::max),
            fold(|p| p.1, f64::INFINITY, f64::min),
            fold(|p| p.1, f64::NEG_INFINITY, f64::max),
        ];
        Ok(Revolved {
            origin,
            axis,
            profile,
            radial0: perpendicular(&axis),
            scale,
            bounds,
        })
    }

    /// Open cylinder of the given radius between axial coordinates h0 and h1.
    pub fn cylinder(origin: Vec3, axis: Vec3, radius: f64, h0: f64, h1: f64) -> Result<Self> {
        if radius.is_nan() || radius <= 0.0 {
            return Err(TampError::input(
                "radius",
                format!("a cylinder radius must be positive (got {radius})"),
            ));
        }
        Self::new(origin, axis, vec![(radius, h0), (radius, h1)])
    }

    /// Open cone frustum from radius r0 at h0 to radius r1 at h1 (a radius of zero
    /// gives the apex).
    pub fn cone(
        origin: Vec3,
        axis: Vec3,
        (r0, h0): (f64, f64),
        (r1, h1): (f64, f64),
    ) -> Result<Self> {
        Self::new(origin, axis, vec![(r0, h0), (r1, h1)])
    }

    /// Funnel: an outlet tube of `outlet_radius` from `outlet_h0` to `outlet_h1`,
    /// continued by a cone from there to `top_radius` at `top_h`. Segment 0 is the
    /// tube, segment 1 the cone.
    pub fn funnel(
        origin: Vec3,
        axis: Vec3,
        outlet_radius: f64,
        outlet_h0: f64,
        outlet_h1: f64,
        top_radius: f64,
        top_h: f64,
    ) -> Result<Self> {
        if outlet_radius.is_nan() || outlet_radius <= 0.0 {
            return Err(TampError::input(
                "outlet_radius",
                format!("the outlet radius must be positive (got {outlet_radius})"),
            ));
        }
        Self::new(
            origin,
            axis,
            vec![
                (outlet_radius, outlet_h0),
                (outlet_radius, outlet_h1),
                (top_radius, top_h),
            ],
        )
    }

    /// Point of the axis where h = 0, m.
    pub fn origin(&self) -> Vec3 {
        self.origin
    }

    /// Unit axis.
    pub fn axis(&self) -> Vec3 {
        self.axis
    }

    /// The profile's (ρ, h) points: distance from the axis and height along it, m.
    pub fn profile(&self) -> &[(f64, f64)] {
        &self.profile
    }

    /// Meridian coordinates (ρ, h) of x and its radial unit vector.
    #[inline]
    fn meridian(&self, x: &Vec3) -> (f64, f64, Vec3) {
        let rel = x - self.origin;
        let h = rel.dot(&self.axis);
        let radial = rel - self.axis * h;
        // Near the axis the subtraction leaves an axial residue of order ε|x'|,
        // large relative to ρ; a second projection makes u perpendicular to a, so
        // the contact normal n_ρ u + n_h a stays unit length.
        let radial = radial - self.axis * radial.dot(&self.axis);
        let rho = radial.norm();
        // Below this the radial direction is rounding noise; the ring is symmetric.
        if rho > 1e-12 * self.scale {
            (rho, h, radial / rho)
        } else {
            (rho, h, self.radial0)
        }
    }

    /// Whether every point of the surface is farther than `distance` from `centre`:
    /// the distance to the profile's bounding box in the meridian plane is a lower
    /// bound of the distance to each segment. A die tests every particle every step
    /// and touches few, so this test comes before the meridian's projections and
    /// uses squares; its margins (1e-9 of the larger of the profile's and the
    /// centre's extent on distances, 1e-12 of the centre's squared extent on ρ², both
    /// far above their rounding) keep any sphere the exact test could find in contact.
    fn beyond(&self, centre: &Vec3, distance: f64) -> bool {
        let [rho_min, rho_max, h_min, h_max] = self.bounds;
        let rel = centre - self.origin;
        let r2 = rel.norm_squared();
        let slack = 1e-9 * self.scale.max(r2.sqrt());
        let d = distance + slack;
        let h = rel.dot(&self.axis);
        if h < h_min - d || h > h_max + d {
            return true;
        }
        // ρ² by difference loses up to a few ε·|x|² to cancellation: 1e-12·|x|² covers it.
        let (rho2, cancel) = (r2 - h * h, 1e-12 * r2);
        let inner = rho_min - d;
        let outer = rho_max + d;
        (inner > 0.0 && rho2 + cancel < inner * inner) || rho2 - cancel > outer * outer
    }

    fn lies_on(&self, segment: u32, p: &Vec3) -> bool {
        let (rho, h, _) = self.meridian(p);
        let i = segment as usize;
        let ((sr, sh), _) = closest_on_segment(self.profile[i], self.profile[i + 1], (rho, h));
        (rho - sr).hypot(h - sh) <= 1e-9 * self.scale
    }

    /// Append the contacts of a sphere with the surface, one per distinct touching point
    /// (facet = profile segment index).
    pub fn contacts(&self, centre: &Vec3, radius: f64, reach: f64, out: &mut Vec<ShapeContact>) {
        if !self.beyond(centre, radius + reach) {
            self.meridian_contacts(centre, radius, reach, out);
        }
    }

    /// `contacts` segment by segment in the meridian plane.
    fn meridian_contacts(
        &self,
        centre: &Vec3,
        radius: f64,
        reach: f64,
        out: &mut Vec<ShapeContact>,
    ) {
        let (rho, h, u) = self.meridian(centre);
        let mut candidates: Vec<Candidate> = Vec::new();
        for (i, w) in self.profile.windows(2).enumerate() {
            let ((sr, sh), t) = closest_on_segment(w[0], w[1], (rho, h));
            let (vr, vh) = (rho - sr, h - sh);
            let distance = vr.hypot(vh);
            if !within_reach(radius - distance, reach) {
                continue;
            }
            let (nr, nh) = if distance > 0.0 {
                (vr / distance, vh / distance)
            } else {
                let (er, eh) = (w[1].0 - w[0].0, w[1].1 - w[0].1);
                let len = er.hypot(eh);
                (-eh / len, er / len)
            };
            candidates.push(Candidate {
                rank: if t > 0.0 && t < 1.0 { 0 } else { 1 },
                distance,
                facet: i as u32,
                point: self.origin + self.axis * sh + u * sr,
                normal: u * nr + self.axis * nh,
            });
        }
        push_distinct(&mut candidates, radius, |s, p| self.lies_on(s, p), out);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    fn query(s: &Revolved, x: Vec3, r: f64) -> Vec<ShapeContact> {
        let mut out = Vec::new();
        s.contacts(&x, r, 0.0, &mut out);
        for c in &out {
            assert!((c.normal.norm() - 1.0).abs() < 1e-14);
        }
        out
    }

    /// Smallest distance from x to samples of the surface (brute force, independent
    /// of the meridian reduction): per segment, a coarse (t, φ) grid, then a fine
    /// grid over the four coarse cells around its best point.
    fn sampled_distance(s: &Revolved, x: &Vec3) -> f64 {
        let e1 = perpendicular(&s.axis);
        let e2 = s.axis.cross(&e1);
        let at = |w: &[(f64, f64)], t: f64, phi: f64| {
            let rho = w[0].0 + t * (w[1].0 - w[0].0);
            let h = w[0].1 + t * (w[1].1 - w[0].1);
            let p = s.origin + s.axis * h + (e1 * phi.cos() + e2 * phi.sin()) * rho;
            (x - p).norm()
        };
        let (nt, nphi) = (100, 200);
        let (dt, dphi) = (1.0 / nt as f64, 2.0 * PI / nphi as f64);
        let mut best = f64::INFINITY;
        for w in s.profile.windows(2) {
            let mut coarse = (f64::INFINITY, 0.0, 0.0);
            for j in 0..=nt {
                for k in 0..nphi {
                    let (t, phi) = (j as f64 * dt, k as f64 * dphi);
                    let d = at(w, t, phi);
                    if d < coarse.0 {
                        coarse = (d, t, phi);
                    }
                }
            }
            let n = 200;
            for j in 0..=n {
                let t = (coarse.1 + (2.0 * j as f64 / n as f64 - 1.0) * 2.0 * dt).clamp(0.0, 1.0);
                for k in 0..=n {
                    let phi = coarse.2 + (2.0 * k as f64 / n as f64 - 1.0) * 2.0 * dphi;
                    best = best.min(at(w, t, phi));
                }
            }
        }
        best
    }

    #[test]
    fn cylinder_inside_outside_rim_and_axis() {
        let axis = Vec3::new(0.0, 0.0, 1.0);
        let c = Revolved::cylinder(Vec3::new(1.0, 2.0, 3.0), axis, 1.0, 0.0, 2.0).unwrap();
        // Inside, 0.2 from the wall along +x.
        let out = query(&c, Vec3::new(1.8, 2.0, 4.0), 0.3);
        assert_eq!(out.len(), 1);
        assert!((out[0].overlap - 0.1).abs() < 1e-14);
        assert!((out[0].normal - Vec3::new(-1.0, 0.0, 0.0)).norm() < 1e-14);
        // Outside (the shell is two-sided), along the diagonal.
        let d = Vec3::new(1.0, 1.0, 0.0).normalize();
        let out = query(&c, Vec3::new(1.0, 2.0, 4.0) + d * 1.2, 0.3);
        assert_eq!(out.len(), 1);
        assert!((out[0].overlap - 0.1).abs() < 1e-14);
        assert!((out[0].normal - d).norm() < 1e-14);
        // Above the top rim (h = 2), diagonally out: distance √(0.1² + 0.1²).
        let out = query(&c, Vec3::new(2.1, 2.0, 5.1), 0.3);
        assert_eq!(out.len(), 1);
        assert!((out[0].overlap - (0.3 - 0.02f64.sqrt())).abs() < 1e-14);
        let n = Vec3::new(1.0, 0.0, 1.0).normalize();
        assert!((out[0].normal - n).norm() < 1e-14);
        // Beyond reach: nothing, and reach brings it back as a gap.
        assert!(query(&c, Vec3::new(1.0, 2.0, 4.0), 0.9).is_empty());
        let mut out = Vec::new();
        c.contacts(&Vec3::new(1.0, 2.0, 4.0), 0.9, 0.15, &mut out);
        assert_eq!(out.len(), 1);
        assert!((out[0].overlap + 0.1).abs() < 1e-14);
    }

    #[test]
    fn centre_exactly_on_the_axis() {
        let axis = Vec3::new(1.0, 1.0, 1.0);
        let c = Revolved::cylinder(Vec3::zeros(), axis, 0.5, -1.0, 1.0).unwrap();
        let out = query(&c, Vec3::new(0.2, 0.2, 0.2), 0.6);
        assert_eq!(out.len(), 1);
        assert!((out[0].overlap - 0.1).abs() < 1e-14);
        // Radial (perpendicular to the axis), pointing from the wall to the axis,
        // and the same every time.
        assert!(out[0].normal.dot(&c.axis()).abs() < 1e-14);
        assert_eq!(
            query(&c, Vec3::new(0.2, 0.2, 0.2), 0.6)[0].normal,
            out[0].normal
        );
        // A disc-bottomed cup: the centre above the disc's centre is pushed along
        // the axis.
        let cup = Revolved::new(
            Vec3::zeros(),
            Vec3::z(),
            vec![(0.0, 0.0), (1.0, 0.0), (1.0, 1.0)],
        )
        .unwrap();
        let out = query(&cup, Vec3::new(0.0, 0.0, 0.25), 0.3);
        assert_eq!(out.len(), 1);
        assert!((out[0].overlap - 0.05).abs() < 1e-14);
        assert!((out[0].normal - Vec3::z()).norm() < 1e-14);
    }

    #[test]
    fn near_the_axis_far_from_the_origin_the_normal_stays_unit() {
        // ρ ≪ h: the radial part of x' is a small difference of large numbers.
        let axis = Vec3::new(0.3, 0.1, 1.0);
        let f = Revolved::cylinder(Vec3::new(0.1, 0.2, -0.3), axis, 0.4, 0.0, 1e3).unwrap();
        let e1 = f.axis().cross(&Vec3::x()).normalize();
        for (rho, h) in [(3.4e-3, 1.9), (1e-6, 500.0), (2e-9, 999.0)] {
            let x = f.origin() + f.axis() * h + e1 * rho;
            let out = query(&f, x, 0.5);
            assert_eq!(out.len(), 1);
            assert!((out[0].overlap - (0.1 + rho)).abs() < 1e-12);
            assert!(out[0].normal.dot(&f.axis()).abs() < 1e-14);
        }
    }

    #[test]
    fn cone_matches_sampled_distance() {
        let origin = Vec3::new(0.3, -0.2, 0.1);
        let axis = Vec3::new(0.2, -0.4, 1.0);
        let cone = Revolved::cone(origin, axis, (0.2, 0.0), (1.0, 1.5)).unwrap();
        let points = [
            Vec3::new(0.5, 0.1, 0.8),
            Vec3::new(-0.4, 0.6, 1.2),
            Vec3::new(0.3, -0.2, 0.1),
            Vec3::new(1.4, -0.9, 1.9),
            Vec3::new(0.2, 0.2, -0.3),
        ];
        for x in points {
            let out = query(&cone, x, 5.0);
            assert_eq!(out.len(), 1, "{x:?}");
            let exact = 5.0 - out[0].overlap;
            let sampled = sampled_distance(&cone, &x);
            // The sample can only be farther; its spacing bounds by how much.
            assert!(exact <= sampled + 1e-12, "{x:?}: {exact} vs {sampled}");
            assert!(sampled - exact < 2e-5, "{x:?}: {exact} vs {sampled}");
        }
    }

    fn funnel() -> Revolved {
        // Tube of radius 0.5 for h in [0, 1], cone out to radius 1.5 at h = 2.
        Revolved::funnel(Vec3::zeros(), Vec3::z(), 0.5, 0.0, 1.0, 1.5, 2.0).unwrap()
    }

    #[test]
    fn funnel_outside_knee_is_concave_two_contacts() {
        let f = funnel();
        // (ρ, h) = (0.8, 0.9): 0.3 from the tube, 0.4/√2 from the cone, both feet
        // inside their segments.
        let out = query(&f, Vec3::new(0.0, 0.8, 0.9), 0.35);
        assert_eq!(out.len(), 2);
        let (tube, cone) = if out[0].facet == 0 {
            (out[0], out[1])
        } else {
            (out[1], out[0])
        };
        assert_eq!((tube.facet, cone.facet), (0, 1));
        assert!((tube.overlap - 0.05).abs() < 1e-14);
        assert!((cone.overlap - (0.35 - 0.4 / 2f64.sqrt())).abs() < 1e-14);
        assert!((tube.normal - Vec3::y()).norm() < 1e-14);
        assert!((cone.normal - Vec3::new(0.0, 1.0, -1.0).normalize()).norm() < 1e-14);
        let sampled = sampled_distance(&f, &Vec3::new(0.0, 0.8, 0.9));
        assert!((sampled - 0.4 / 2f64.sqrt()).abs() < 2e-5);
    }

    #[test]
    fn funnel_inside_knee_is_convex_one_contact() {
        let f = funnel();
        // Both segments offer the knee vertex (0.5, 1): one contact.
        let x = Vec3::new(0.3, 0.0, 1.2);
        let out = query(&f, x, 0.35);
        assert_eq!(out.len(), 1);
        assert!((out[0].overlap - (0.35 - 0.08f64.sqrt())).abs() < 1e-14);
        assert!((out[0].normal - Vec3::new(-1.0, 0.0, 1.0).normalize()).norm() < 1e-14);
        // On the cone's side: the cone's interior foot wins, the tube's end point
        // (the knee, which lies on the cone) is dropped.
        let x = Vec3::new(0.6, 0.0, 1.3);
        let out = query(&f, x, 0.35);
        assert_eq!(out.len(), 1);
        assert_eq!(out[0].facet, 1);
        assert!((out[0].overlap - (0.35 - 0.2 / 2f64.sqrt())).abs() < 1e-14);
        assert!((sampled_distance(&f, &x) - 0.2 / 2f64.sqrt()).abs() < 2e-5);
    }

    #[test]
    fn rejects_bad_profiles() {
        let z = Vec3::z();
        assert!(Revolved::cylinder(Vec3::zeros(), z, 0.0, 0.0, 1.0).is_err());
        assert!(Revolved::cylinder(Vec3::zeros(), z, 1.0, 1.0, 1.0).is_err());
        assert!(Revolved::cylinder(Vec3::zeros(), Vec3::zeros(), 1.0, 0.0, 1.0).is_err());
        let e = Revolved::new(Vec3::zeros(), z, vec![(1.0, 0.0), (-0.5, 1.0)])
            .unwrap_err()
            .to_string();
        assert!(e.contains("negative radius"), "{e}");
        assert!(Revolved::new(Vec3::zeros(), z, vec![(1.0, 0.0)]).is_err());
    }

    /// A funnel with a tilted axis and the point at (ρ, φ, h) of its own frame.
    fn tilted_funnel(rho: f64, phi: f64, h: f64) -> (Revolved, Vec3) {
        let axis = Vec3::new(0.3, 0.1, 1.0).normalize();
        let origin = Vec3::new(0.1, 0.2, -0.3);
        let f = Revolved::funnel(origin, axis, 0.4, 0.0, 1.0, 1.6, 2.0).unwrap();
        let e1 = axis.cross(&Vec3::x()).normalize();
        let e2 = axis.cross(&e1);
        (
            f,
            origin + axis * h + (e1 * phi.cos() + e2 * phi.sin()) * rho,
        )
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]

        /// The bounding-box test before the meridian leaves out no contact: with it
        /// and without, a tilted funnel gives the same contacts, for spheres whose
        /// radius plus reach falls just short of, at, or just past the distance.
        #[test]
        fn the_early_test_keeps_every_contact(
            rho in 0.0..3.0f64, phi in 0.0..2.0 * PI, h in -1.5..3.5f64,
            radius in 0.05..0.6f64, reach in 0.0..0.1f64, nudge in -1e-9..1e-9f64,
        ) {
            let (f, centre) = tilted_funnel(rho, phi, h);
            let mut all = Vec::new();
            f.meridian_contacts(&centre, 100.0, 0.0, &mut all);
            let distance = all.iter().map(|c| 100.0 - c.overlap).fold(f64::INFINITY, f64::min);
            for r in [radius, (distance - reach + nudge).max(1e-3)] {
                let (mut with, mut without) = (Vec::new(), Vec::new());
                f.contacts(&centre, r, reach, &mut with);
                f.meridian_contacts(&centre, r, reach, &mut without);
                proptest::prop_assert_eq!(with.len(), without.len());
            }
        }

        /// The deepest contact of a tilted funnel is at the sampled distance, and
        /// every contact's touching point x − d n lies on the profile.
        #[test]
        fn funnel_distance_against_samples(
            rho in 0.0..2.0f64, phi in 0.0..2.0 * PI, h in -0.5..2.5f64,
        ) {
            let (f, centre) = tilted_funnel(rho, phi, h);
            let r = 10.0;
            let out = query(&f, centre, r);
            proptest::prop_assert!(!out.is_empty());
            let exact = out.iter().map(|c| r - c.overlap).fold(f64::INFINITY, f64::min);
            let sampled = sampled_distance(&f, &centre);
            proptest::prop_assert!(exact <= sampled + 1e-12, "{} > {}", exact, sampled);
            proptest::prop_assert!(sampled - exact < 1e-4, "{} vs {}", exact, sampled);
            for c in &out {
                let q = centre - c.normal * (r - c.overlap);
                let seg = c.facet as usize;
                let (qr, qh, _) = f.meridian(&q);
                let ((sr, sh), _) = closest_on_segment(f.profile[seg], f.profile[seg + 1], (qr, qh));
                proptest::prop_assert!((qr - sr).hypot(qh - sh) < 1e-12, "{:?}", (qr, qh));
            }
        }
    }
}
