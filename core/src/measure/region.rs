//! Measurement regions and the exact volume of a sphere (centre c, radius r) inside
//! each of them.
//!
//! * Slab `lo ≤ x_k ≤ hi`: difference of two spherical caps. The part of the ball
//!   below the plane x_k = c_k + t is
//!   `V_<(t) = π (r + t)² (2r − t) / 3` for −r ≤ t ≤ 0 and `4/3 π r³ − V_<(−t)` for t > 0,
//!   so `V = V_<(hi − c_k) − V_<(lo − c_k)`.
//! * Sphere (centre C, radius R, d = |c − C|): the lens
//!   `V = π (r + R − d)² (d² + 2d(r + R) − 3(r − R)²) / (12 d)` for |r − R| < d < r + R,
//!   `4/3 π min(r, R)³` when one ball contains the other, 0 when apart.
//! * Box: `V = ∫ A(ρ(t)) dt` over one axis t, with `ρ(t) = √(r² − t²)` the radius of
//!   the ball's section and `A` the exact area of (disc ∩ rectangle), itself in closed
//!   form: `A = ∫ len([y₁, y₂] ∩ [−h(x), h(x)]) dx` with `h = √(ρ² − x²)`, which on each
//!   x-piece between the points where h crosses |y₁|, |y₂| is a constant times a length
//!   or a difference of the antiderivative `G(x) = ½ (x h(x) + ρ² asin(x/ρ))`.
//! * Cylinder (any axis â, base centre b, radius R, height H): the problem is
//!   rotationally symmetric about â, so only the axial coordinate t_c = (c − b)·â and
//!   the distance e of c from the axis matter.
//!   `V = ∫₀^H L(ρ(t − t_c), R, e) dt` with `L` the lens area of two discs (radii ρ, R,
//!   centres e apart): `L = s(ρ, h_ρ) + s(R, h_R)` with the segment heights
//!   `h_ρ = (ρ + R − e)(R + e − ρ)/(2e)`, `h_R = (ρ + R − e)(ρ + e − R)/(2e)` and the
//!   segment area `s(a, h) = a² (θ − sin θ cos θ)`, θ its half-angle.
//!
//! The two integrals are evaluated by Gauss–Legendre quadrature on sub-intervals split
//! at every t where the integrand changes form — where ρ(t) equals a distance from the
//! section centre to a side line (|x_i|, |y_j|) or to a corner (√(x_i² + y_j²)) for the
//! box; |R − e| or R + e for the cylinder. Between those points the integrand is an
//! analytic function of ρ², hence of t, but at the split points it behaves like
//! (t − t_k)^{n/2}, which would limit plain Gauss–Legendre to algebraic convergence.
//! Each piece [u, v] is therefore mapped by `t = u + (v − u)(1 − cos πs)/2`, s ∈ [0, 1],
//! under which √(t − u) and √(v − t) become analytic in s. Singularities that lie close
//! to a piece without being its ends (a neighbouring kink, the poles t = ±r where the
//! pieces' formulas branch at ρ = 0, the lens formula's branch point at t = ±i√((R+e)² − r²))
//! are handled by grading each piece geometrically towards its ends
//! (`integrate_split`). With 24 nodes per sub-piece the box agrees across its three
//! integration axes, and the cylinder with a 48-node rule, to better than 1e-15 of the
//! ball's volume (tests below). Where the result is a sliver, formulas are arranged so
//! that the sliver keeps its own digits (angles by atan2 from exact half chords,
//! θ − sinθcosθ by its series). The box takes the closed forms whenever the ball
//! crosses faces of only one axis (caps), and the cylinder when the ball lies radially
//! inside (caps along the axis).

use crate::particles::Vec3;
use std::f64::consts::PI;
use std::sync::OnceLock;

/// A region of space in which a packing is measured. Boxes and slabs are aligned with
/// the coordinate axes; the cylinder's axis may point anywhere. All are closed sets.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Region {
    /// Axis-aligned box [lower, upper].
    Box {
        /// Lower corner, m.
        lower: Vec3,
        /// Upper corner, m.
        upper: Vec3,
    },
    /// `lo ≤ x[axis] ≤ hi`, unbounded along the other two axes (infinite volume; see
    /// `packing::packing_fraction` for its use in laterally periodic beds).
    Slab {
        /// Axis normal to the slab (0 = x, 1 = y, 2 = z).
        axis: usize,
        /// Lower bound along `axis`, m.
        lo: f64,
        /// Upper bound along `axis`, m.
        hi: f64,
    },
    /// `base` is the centre of the bottom disc; `axis` is normalised on use.
    Cylinder {
        /// Centre of the bottom disc, m.
        base: Vec3,
        /// Direction of the cylinder's axis, from the base towards the top.
        axis: Vec3,
        /// Cylinder radius R, m.
        radius: f64,
        /// Height H along the axis, m.
        height: f64,
    },
    /// Ball of centre C and radius R.
    Sphere {
        /// Centre C, m.
        centre: Vec3,
        /// Radius R, m.
        radius: f64,
    },
}

impl Region {
    /// A rule the region breaks (empty box, zero radius, …), if any.
    pub fn defect(&self) -> Option<String> {
        let finite = |v: &Vec3| v.iter().all(|x| x.is_finite());
        match self {
            Region::Box { lower, upper } => {
                if !finite(lower) || !finite(upper) {
                    Some("box corners must be finite".into())
                } else if (0..3).any(|k| upper[k] <= lower[k]) {
                    Some(format!(
                        "box upper {upper:?} must exceed lower {lower:?} on every axis"
                    ))
                } else {
                    None
                }
            }
            Region::Slab { axis, lo, hi } => {
                if *axis > 2 {
                    Some(format!("slab axis must be 0, 1 or 2, got {axis}"))
                } else if !(lo.is_finite() && hi.is_finite() && hi > lo) {
                    Some(format!("slab needs finite lo < hi, got [{lo}, {hi}]"))
                } else {
                    None
                }
            }
            Region::Cylinder {
                base,
                axis,
                radius,
                height,
            } => {
                if !finite(base) || !finite(axis) || axis.norm() == 0.0 {
                    Some("cylinder needs a finite base and a non-zero axis".into())
                } else if !(radius.is_finite() && *radius > 0.0) {
                    Some(format!("cylinder radius must be positive, got {radius}"))
                } else if !(height.is_finite() && *height > 0.0) {
                    Some(format!("cylinder height must be positive, got {height}"))
                } else {
                    None
                }
            }
            Region::Sphere { centre, radius } => {
                if !finite(centre) {
                    Some("sphere centre must be finite".into())
                } else if !(radius.is_finite() && *radius > 0.0) {
                    Some(format!("sphere radius must be positive, got {radius}"))
                } else {
                    None
                }
            }
        }
    }

    /// Volume of the region (infinite for a slab).
    pub fn volume(&self) -> f64 {
        match *self {
            Region::Box { lower, upper } => (upper - lower).product(),
            Region::Slab { .. } => f64::INFINITY,
            Region::Cylinder { radius, height, .. } => PI * radius * radius * height,
            Region::Sphere { radius, .. } => ball_volume(radius),
        }
    }

    /// Whether a point lies in the region (boundary included).
    pub fn contains_point(&self, p: &Vec3) -> bool {
        match *self {
            Region::Box { lower, upper } => (0..3).all(|k| lower[k] <= p[k] && p[k] <= upper[k]),
            Region::Slab { axis, lo, hi } => lo <= p[axis] && p[axis] <= hi,
            Region::Cylinder {
                base,
                axis,
                radius,
                height,
            } => {
                let a = axis.normalize();
                let d = p - base;
                let t = d.dot(&a);
                (0.0..=height).contains(&t) && (d - a * t).norm_squared() <= radius * radius
            }
            Region::Sphere { centre, radius } => (p - centre).norm_squared() <= radius * radius,
        }
    }

    /// Axis-aligned bounding box `(lower, upper)`; infinite along a slab's free axes.
    pub fn bounding_box(&self) -> (Vec3, Vec3) {
        match *self {
            Region::Box { lower, upper } => (lower, upper),
            Region::Slab { axis, lo, hi } => {
                let mut l = Vec3::repeat(f64::NEG_INFINITY);
                let mut u = Vec3::repeat(f64::INFINITY);
                l[axis] = lo;
                u[axis] = hi;
                (l, u)
            }
            Region::Cylinder {
                base,
                axis,
                radius,
                height,
            } => {
                let a = axis.normalize();
                let top = base + a * height;
                // A disc of radius R with unit normal â spans R √(1 − â_k²) along axis k.
                let half = a.map(|ak| radius * (1.0 - ak * ak).max(0.0).sqrt());
                (base.inf(&top) - half, base.sup(&top) + half)
            }
            Region::Sphere { centre, radius } => {
                (centre.add_scalar(-radius), centre.add_scalar(radius))
            }
        }
    }

    /// Exact volume of the ball (centre `c`, radius `r`) inside the region.
    pub fn intersection_volume(&self, c: &Vec3, r: f64) -> f64 {
        if r <= 0.0 {
            return 0.0;
        }
        match *self {
            Region::Box { lower, upper } => ball_box(c, r, &lower, &upper),
            Region::Slab { axis, lo, hi } => ball_slab(r, lo - c[axis], hi - c[axis]),
            Region::Cylinder {
                base,
                axis,
                radius,
                height,
            } => ball_cylinder(c, r, &base, &axis, radius, height, gauss_legendre()),
            Region::Sphere { centre, radius } => ball_ball(r, radius, (c - centre).norm()),
        }
    }
}

/// Volume 4/3 π r³ of a ball of radius r.
pub fn ball_volume(r: f64) -> f64 {
    4.0 / 3.0 * PI * r * r * r
}

/// Part of a ball of radius r (centred at 0) with coordinate below t.
fn cap_below(r: f64, t: f64) -> f64 {
    if t <= -r {
        0.0
    } else if t >= r {
        ball_volume(r)
    } else if t <= 0.0 {
        PI * (r + t) * (r + t) * (2.0 * r - t) / 3.0
    } else {
        // The smaller cap carries no cancellation; take the complement of it.
        ball_volume(r) - PI * (r - t) * (r - t) * (2.0 * r + t) / 3.0
    }
}

/// Ball of radius r at 0 between the planes at lo and hi (relative to its centre).
fn ball_slab(r: f64, lo: f64, hi: f64) -> f64 {
    if hi <= lo {
        return 0.0;
    }
    (cap_below(r, hi) - cap_below(r, lo)).max(0.0)
}

/// Lens of two balls with radii r, big_r and centres d apart.
fn ball_ball(r: f64, big_r: f64, d: f64) -> f64 {
    if d >= r + big_r {
        0.0
    } else if d <= (r - big_r).abs() {
        ball_volume(r.min(big_r))
    } else {
        let s = r + big_r - d;
        PI * s * s * (d * d + 2.0 * d * (r + big_r) - 3.0 * (r - big_r) * (r - big_r)) / (12.0 * d)
    }
}

fn ball_box(c: &Vec3, r: f64, lower: &Vec3, upper: &Vec3) -> f64 {
    let lo = lower - c;
    let hi = upper - c;
    if (0..3).any(|k| lo[k] >= r || hi[k] <= -r || hi[k] <= lo[k]) {
        return 0.0;
    }
    let cut: Vec<usize> = (0..3).filter(|&k| lo[k] > -r || hi[k] < r).collect();
    match cut.len() {
        0 => ball_volume(r),
        1 => ball_slab(r, lo[cut[0]], hi[cut[0]]),
        // Integrating along an uncut axis (if any) keeps the section's limits at ±r.
        _ => {
            let along = (0..3).find(|k| !cut.contains(k)).unwrap_or(2);
            ball_box_along(r, &lo, &hi, along, gauss_legendre())
        }
    }
}

/// ∫ A(ρ(t)) dt along axis `along`, bounds relative to the ball's centre.
fn ball_box_along(r: f64, lo: &Vec3, hi: &Vec3, along: usize, rule: &[(f64, f64)]) -> f64 {
    let (p, q) = match along {
        0 => (1, 2),
        1 => (0, 2),
        _ => (0, 1),
    };
    let t0 = lo[along].max(-r);
    let t1 = hi[along].min(r);
    if t1 <= t0 {
        return 0.0;
    }
    let sides = [lo[p], hi[p], lo[q], hi[q]];
    let mut kinks: Vec<f64> = sides.iter().map(|d| d.abs()).collect();
    for x in [lo[p], hi[p]] {
        for y in [lo[q], hi[q]] {
            kinks.push(x.hypot(y));
        }
    }
    // The section's poles ρ = 0 are branch points of the pieces' formulas (acos(d/ρ))
    // even where they are not kinks, so the grading must see them.
    let mut breaks = vec![(-r, 0.0), (r, 0.0)];
    for d in kinks {
        if d < r {
            let t = ((r - d) * (r + d)).sqrt();
            breaks.extend([(-t, 0.0), (t, 0.0)]);
        }
    }
    integrate_split(
        |t| {
            disc_rect_area(
                ((r - t) * (r + t)).max(0.0).sqrt(),
                lo[p],
                hi[p],
                lo[q],
                hi[q],
            )
        },
        t0,
        t1,
        &breaks,
        rule,
    )
}

/// Exact area of the disc of radius ρ at the origin inside [x1, x2] × [y1, y2].
pub(crate) fn disc_rect_area(rho: f64, x1: f64, x2: f64, y1: f64, y2: f64) -> f64 {
    if rho <= 0.0 || y2 <= -rho || y1 >= rho {
        return 0.0;
    }
    // Each abscissa travels with its half chord c = √(ρ² − x²), known exactly where x
    // comes from a y side (c = |y|): the angle is then atan2(x, c), which keeps its
    // digits where asin(x/ρ) near ±1 would lose half of them.
    let half_chord = |x: f64| ((rho - x) * (rho + x)).max(0.0).sqrt();
    let xa = if x1 > -rho {
        (x1, half_chord(x1))
    } else {
        (-rho, 0.0)
    };
    let xb = if x2 < rho {
        (x2, half_chord(x2))
    } else {
        (rho, 0.0)
    };
    if xb.0 <= xa.0 {
        return 0.0;
    }
    let rho2 = rho * rho;
    // Area under the upper semicircle from 0 to x.
    let g = |(x, c): (f64, f64)| 0.5 * (x * c + rho2 * x.atan2(c));
    let mut pts = [(0.0f64, 0.0f64); 6];
    pts[0] = xa;
    let mut n = 1;
    for y in [y1, y2] {
        if y.abs() < rho {
            let s = half_chord(y);
            for x in [-s, s] {
                if xa.0 < x && x < xb.0 {
                    pts[n] = (x, y.abs());
                    n += 1;
                }
            }
        }
    }
    pts[n] = xb;
    n += 1;
    let pts = &mut pts[..n];
    pts.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut area = 0.0;
    for w in pts.windows(2) {
        let (u, v) = (w[0].0, w[1].0);
        if v <= u {
            continue;
        }
        // The form of the integrand is fixed on the piece; read it at the middle.
        let h = half_chord(0.5 * (u + v));
        if y2.min(h) <= y1.max(-h) {
            continue;
        }
        let arc = g(w[1]) - g(w[0]);
        let top = if y2 < h { y2 * (v - u) } else { arc };
        let bottom = if y1 > -h { y1 * (v - u) } else { -arc };
        area += top - bottom;
    }
    area.max(0.0)
}

fn ball_cylinder(
    c: &Vec3,
    r: f64,
    base: &Vec3,
    axis: &Vec3,
    big_r: f64,
    height: f64,
    rule: &[(f64, f64)],
) -> f64 {
    let a = axis.normalize();
    let d = c - base;
    let tc = d.dot(&a);
    let e = (d - a * tc).norm();
    if e >= big_r + r {
        return 0.0;
    }
    if e + r <= big_r {
        return ball_slab(r, -tc, height - tc);
    }
    let t0 = (-tc).max(-r);
    let t1 = (height - tc).min(r);
    if t1 <= t0 {
        return 0.0;
    }
    let mut breaks = vec![(-r, 0.0), (r, 0.0)];
    for rho in [(big_r - e).abs(), big_r + e] {
        let t = ((r - rho) * (r + rho)).abs().sqrt();
        if rho < r {
            breaks.extend([(-t, 0.0), (t, 0.0)]);
        } else {
            // The lens formula still branches at ρ = R + e when that exceeds r: at
            // t = ±i √(ρ² − r²), close to the real axis when ρ is just above r.
            breaks.push((0.0, t));
        }
    }
    integrate_split(
        |t| disc_disc_area(((r - t) * (r + t)).max(0.0).sqrt(), big_r, e),
        t0,
        t1,
        &breaks,
        rule,
    )
}

/// Area common to two discs of radii a and b whose centres are d apart.
pub(crate) fn disc_disc_area(a: f64, b: f64, d: f64) -> f64 {
    if a <= 0.0 || b <= 0.0 || d >= a + b {
        0.0
    } else if d <= (a - b).abs() {
        PI * a.min(b).powi(2)
    } else {
        // Heights of the two segments cut off by the common chord, written as products
        // so that a thin lens of a small disc with a huge one (a die wall seen by a
        // particle) keeps its relative accuracy.
        let gap = a + b - d;
        let ha = gap * (b + d - a) / (2.0 * d);
        let hb = gap * (a + d - b) / (2.0 * d);
        segment(a, ha) + segment(b, hb)
    }
}

/// Area of a segment of height h (0 ≤ h ≤ 2a) of a disc of radius a:
/// a² (θ − sin θ cos θ) with θ the half-angle of the chord.
fn segment(a: f64, h: f64) -> f64 {
    let h = h.clamp(0.0, 2.0 * a);
    let half_chord = (h * (2.0 * a - h)).sqrt();
    let theta = half_chord.atan2(a - h);
    let u = 2.0 * theta;
    if u < 0.5 {
        // u − sin u by its series: the direct difference loses all digits when the
        // segment is a sliver of a large disc.
        let u2 = u * u;
        let mut term = u * u2 / 6.0;
        let mut sum = term;
        for k in (5..=17).step_by(2) {
            term *= -u2 / ((k - 1) * k) as f64;
            sum += term;
        }
        0.5 * a * a * sum
    } else {
        0.5 * a * a * (u - u.sin())
    }
}

/// Nodes per piece: enough for ~1e-16 relative on the smoothed pieces (tests compare
/// with 48 nodes).
const NODES: usize = 24;

fn gauss_legendre() -> &'static [(f64, f64)] {
    static TABLE: OnceLock<Vec<(f64, f64)>> = OnceLock::new();
    TABLE.get_or_init(|| crate::quadrature::legendre_rule(NODES))
}

/// ∫_a^b f, split at the real parts of the singular points inside (a, b), each
/// piece with the endpoint-smoothing map described in the module comment.
///
/// `singular` lists the points (t, y) where the integrand's pieces have a branch
/// point at t ± iy: the kinks (y = 0) and, for the cylinder, a branch point of the
/// lens formula off the real axis. A singularity close to a piece but not at its end
/// (a short neighbouring piece, a kink just beyond a face that limits the integral,
/// or one just off the axis) slows Gauss–Legendre to a crawl, which the map does not
/// cure. So each piece is further split geometrically (ratio 1/4) towards an end
/// until the sub-piece at that end is no longer than the distance from the end to
/// the nearest other singularity: every sub-piece then sees all singularities at
/// least its own length away.
fn integrate_split(
    f: impl Fn(f64) -> f64,
    a: f64,
    b: f64,
    singular: &[(f64, f64)],
    rule: &[(f64, f64)],
) -> f64 {
    const GRADE: f64 = 0.25;
    const MAX_LEVELS: usize = 30;
    let mut pts: Vec<f64> = singular
        .iter()
        .map(|s| s.0)
        .filter(|&t| a < t && t < b)
        .collect();
    pts.extend([a, b]);
    pts.sort_by(f64::total_cmp);
    pts.dedup();
    let nearest_other = |t: f64| {
        singular
            .iter()
            .map(|&(k, y)| (k - t).hypot(y))
            .filter(|&d| d > 0.0)
            .fold(f64::INFINITY, f64::min)
    };
    let mut total = 0.0;
    let mut sub = Vec::with_capacity(2 * MAX_LEVELS + 2);
    for w in pts.windows(2) {
        let (u, v) = (w[0], w[1]);
        let len = v - u;
        sub.clear();
        sub.extend([u, v]);
        for (end, towards) in [(u, 1.0), (v, -1.0)] {
            let gap = nearest_other(end);
            let mut h = len * GRADE;
            for _ in 0..MAX_LEVELS {
                if h <= gap {
                    break;
                }
                sub.push(end + towards * h);
                h *= GRADE;
            }
        }
        sub.sort_by(f64::total_cmp);
        for p in sub.windows(2) {
            let (u, v) = (p[0], p[1]);
            let len = v - u;
            let mut piece = 0.0;
            for &(s, weight) in rule {
                let t = u + len * 0.5 * (1.0 - (PI * s).cos());
                piece += weight * f(t) * (PI * s).sin();
            }
            total += piece * len * 0.5 * PI;
        }
    }
    total
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rel(a: f64, b: f64) -> f64 {
        (a - b).abs() / b.abs().max(1e-300)
    }

    fn unit_box() -> Region {
        Region::Box {
            lower: Vec3::new(0.0, 0.0, 0.0),
            upper: Vec3::new(1.0, 2.0, 3.0),
        }
    }

    #[test]
    fn gauss_legendre_integrates_polynomials_exactly() {
        for n in [NODES, 48] {
            let table = crate::quadrature::legendre_rule(n);
            let sum: f64 = table.iter().map(|(_, w)| w).sum();
            assert!((sum - 1.0).abs() < 1e-14);
            // Degree 2n − 1 is the highest degree integrated exactly.
            let m: f64 = table
                .iter()
                .map(|(x, w)| w * x.powi(2 * n as i32 - 1))
                .sum();
            assert!(rel(m, 1.0 / (2 * n) as f64) < 1e-13, "{n}: {m}");
        }
    }

    #[test]
    fn disc_rectangle_special_cases() {
        let rho: f64 = 0.7;
        let disc = PI * rho * rho;
        assert!(rel(disc_rect_area(rho, -1.0, 1.0, -1.0, 1.0), disc) < 1e-15);
        assert!(rel(disc_rect_area(rho, 0.0, 1.0, -1.0, 1.0), disc / 2.0) < 1e-15);
        assert!(rel(disc_rect_area(rho, 0.0, 1.0, 0.0, 1.0), disc / 4.0) < 1e-15);
        assert!(rel(disc_rect_area(rho, -1.0, 0.0, 0.0, 1.0), disc / 4.0) < 1e-15);
        assert_eq!(disc_rect_area(rho, 0.5, 1.0, 0.5, 1.0), 0.0);
        // Half-plane: a circular segment.
        let x = 0.3;
        let seg = rho * rho * (x / rho).acos() - x * (rho * rho - x * x).sqrt();
        assert!(rel(disc_rect_area(rho, x, 5.0, -5.0, 5.0), seg) < 1e-14);
        // Small rectangle well inside: its own area.
        assert!(rel(disc_rect_area(rho, -0.1, 0.2, 0.0, 0.3), 0.09) < 1e-14);
        // Symmetry of the quadrant piece under swapping x and y.
        let q1 = disc_rect_area(rho, 0.2, 1.0, -0.35, 1.0);
        let q2 = disc_rect_area(rho, -0.35, 1.0, 0.2, 1.0);
        assert!(rel(q1, q2) < 1e-14);
    }

    /// `region ∩ ball(c, r)` has volume `want` to relative `tol`.
    fn check(region: &Region, c: Vec3, r: f64, want: f64, tol: f64) {
        let got = region.intersection_volume(&c, r);
        assert!(
            rel(got, want) < tol,
            "{region:?}, ball at {c:?} r {r}: {got} vs {want}"
        );
    }

    #[test]
    fn closed_form_special_cases() {
        let r = 0.25;
        let full = ball_volume(r);
        let b = unit_box();
        check(&b, Vec3::new(0.5, 1.0, 1.5), r, full, 1e-15);
        // Centred on a face, an edge and a corner.
        check(&b, Vec3::new(0.0, 1.0, 1.5), r, full / 2.0, 1e-14);
        check(&b, Vec3::new(0.0, 2.0, 1.5), r, full / 4.0, 1e-13);
        check(&b, Vec3::new(1.0, 2.0, 3.0), r, full / 8.0, 1e-13);
        check(&b, Vec3::new(0.0, 0.0, 0.0), r, full / 8.0, 1e-13);
        // A ball swallowing the box.
        check(&b, Vec3::new(0.5, 1.0, 1.5), 10.0, 6.0, 1e-14);
        // Ball just outside a corner, its bounding box touching the box.
        assert_eq!(b.intersection_volume(&Vec3::repeat(-0.2), r), 0.0);

        let slab = Region::Slab {
            axis: 1,
            lo: 0.0,
            hi: 1.0,
        };
        check(&slab, Vec3::new(5.0, 0.0, 7.0), r, full / 2.0, 1e-15);
        check(
            &slab,
            Vec3::new(5.0, 0.5, 7.0),
            10.0,
            PI * (100.0 - 1.0 / 12.0),
            1e-14,
        );

        let s = Region::Sphere {
            centre: Vec3::zeros(),
            radius: 1.0,
        };
        check(&s, Vec3::new(0.1, 0.2, 0.0), r, full, 1e-15);
        check(&s, Vec3::new(0.1, 0.2, 0.0), 3.0, ball_volume(1.0), 1e-15);
        // Equal balls one radius apart: lens = 5/12 π r³.
        let s1 = Region::Sphere {
            centre: Vec3::zeros(),
            radius: r,
        };
        check(
            &s1,
            Vec3::new(0.0, 0.0, r),
            r,
            5.0 / 12.0 * PI * r.powi(3),
            1e-14,
        );

        let cyl = Region::Cylinder {
            base: Vec3::new(0.0, 0.0, 0.0),
            axis: Vec3::new(0.0, 0.0, 2.0),
            radius: 1.0,
            height: 2.0,
        };
        check(&cyl, Vec3::new(0.2, 0.0, 1.0), r, full, 1e-15);
        check(&cyl, Vec3::new(0.2, 0.0, 0.0), r, full / 2.0, 1e-15);
        check(&cyl, Vec3::new(0.0, 0.0, 1.0), 10.0, 2.0 * PI, 1e-14);
        // Coaxial ball larger than the radius, cylinder taller than the ball: the ball
        // minus a napkin ring, 4/3 π (r³ − (r² − R²)^{3/2}).
        let big = 1.5;
        let napkin = ball_volume(big) - 4.0 / 3.0 * PI * (big * big - 1.0f64).powf(1.5);
        let tall = Region::Cylinder {
            base: Vec3::new(0.0, 0.0, -5.0),
            axis: Vec3::z(),
            radius: 1.0,
            height: 10.0,
        };
        check(&tall, Vec3::zeros(), big, napkin, 1e-14);
        // Large cylinder radius: the lateral wall is locally a plane, the base a plane;
        // centred on the rim of the base the ball is cut to ≈ 1/4.
        let wide = Region::Cylinder {
            base: Vec3::zeros(),
            axis: Vec3::z(),
            radius: 1e4,
            height: 1.0,
        };
        let q = wide.intersection_volume(&Vec3::new(1e4, 0.0, 0.0), r);
        // The wall bends inward by y²/2R, so the deficit is of order r/R = 2.5e-5.
        let deficit = 1.0 - q / (full / 4.0);
        assert!(deficit > 0.0 && deficit < 1e-4, "{deficit}");
    }

    /// A sliver of a small disc cut by a huge one: in the limit it is the segment cut
    /// by a straight chord, a²(θ − sinθcosθ) with cos θ = 1 − h/a.
    #[test]
    fn thin_lens_with_a_huge_disc_keeps_its_digits() {
        let (a, b, h) = (1.0f64, 1e6f64, 1e-3f64);
        let lens = disc_disc_area(a, b, a + b - h);
        let theta = (1.0 - h).acos();
        let chord_segment = theta - theta.sin() * theta.cos();
        // The huge disc's own sliver and its curvature change the area by O(h a/b).
        assert!(rel(lens, chord_segment) < 1e-5, "{lens} {chord_segment}");
    }

    /// The box integral taken along each of the three axes is three different
    /// quadratures (different sections, different split points): over 20 000 random
    /// boxes they must agree to 1e-14 of the ball's volume (measured: 3e-16), as must
    /// the caps when only one axis is cut. Boxes reach past the centre and past the
    /// poles so that faces fall near the centre, near each other and near ±r.
    #[test]
    fn box_quadrature_is_exact_along_every_axis() {
        use rand::{RngExt, SeedableRng};
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(7);
        let rule = gauss_legendre();
        let full = ball_volume(1.0);
        let mut worst = 0.0f64;
        for _ in 0..20_000 {
            let mut v3 = |a: f64, b: f64| {
                Vec3::new(
                    rng.random_range(a..b),
                    rng.random_range(a..b),
                    rng.random_range(a..b),
                )
            };
            let lo = v3(-1.2, 0.5);
            let hi = lo + v3(0.01, 1.5);
            let v: Vec<f64> = (0..3)
                .map(|k| ball_box_along(1.0, &lo, &hi, k, rule))
                .collect();
            let spread = v.iter().fold(f64::MIN, |m, &x| m.max(x))
                - v.iter().fold(f64::MAX, |m, &x| m.min(x));
            worst = worst.max(spread / full);
        }
        assert!(worst < 1e-14, "worst spread {worst:e} of the ball volume");
        let lo = Vec3::new(-0.37, -5.0, -5.0);
        let hi = Vec3::new(0.81, 5.0, 5.0);
        let caps = ball_slab(1.0, -0.37, 0.81);
        for k in [1, 2] {
            assert!(rel(ball_box_along(1.0, &lo, &hi, k, rule), caps) < 1e-14);
        }
    }

    /// The cylinder has one quadrature only, so it is checked for convergence: 24
    /// nodes per piece against 48 over 20 000 random placements, to 1e-14 of the
    /// ball's volume (measured: 7e-16). Radii and offsets put R + e near r, where the
    /// lens formula's off-axis branch point sits close to the interval.
    #[test]
    fn cylinder_quadrature_is_converged() {
        use rand::{RngExt, SeedableRng};
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(8);
        let fine = crate::quadrature::legendre_rule(48);
        let full = ball_volume(1.0);
        let mut worst = 0.0f64;
        for _ in 0..20_000 {
            let big_r = rng.random_range(0.05..3.0);
            let c = Vec3::new(
                rng.random_range(0.0..big_r + 1.0),
                0.0,
                rng.random_range(-1.0..2.0),
            );
            let h = rng.random_range(0.05..2.0);
            let (o, z) = (Vec3::zeros(), Vec3::z());
            let v24 = ball_cylinder(&c, 1.0, &o, &z, big_r, h, gauss_legendre());
            let v48 = ball_cylinder(&c, 1.0, &o, &z, big_r, h, &fine);
            worst = worst.max((v24 - v48).abs() / full);
        }
        assert!(
            worst < 1e-14,
            "worst difference {worst:e} of the ball volume"
        );
    }

    /// An axis along z and the same configuration rotated: same volume.
    #[test]
    fn cylinder_volume_is_independent_of_axis_direction() {
        let r = 0.4;
        let (e, tc) = (0.83, 0.15);
        let z = Region::Cylinder {
            base: Vec3::zeros(),
            axis: Vec3::z(),
            radius: 1.0,
            height: 1.3,
        };
        let vz = z.intersection_volume(&Vec3::new(e, 0.0, tc), r);
        let a = Vec3::new(1.0, -2.0, 0.5).normalize();
        let perp = a.cross(&Vec3::x()).normalize();
        let base = Vec3::new(0.3, 0.1, -0.2);
        let tilted = Region::Cylinder {
            base,
            axis: a * 3.0,
            radius: 1.0,
            height: 1.3,
        };
        let vt = tilted.intersection_volume(&(base + a * tc + perp * e), r);
        assert!(rel(vz, vt) < 1e-13, "{vz} {vt}");
    }

    /// Moving a ball across each region's boundary in small steps: no jump larger
    /// than the volume swept by the step allows.
    #[test]
    fn volume_is_continuous() {
        let r = 0.3;
        let regions = [
            unit_box(),
            Region::Cylinder {
                base: Vec3::zeros(),
                axis: Vec3::new(0.0, 1.0, 1.0),
                radius: 0.5,
                height: 1.0,
            },
            Region::Sphere {
                centre: Vec3::new(0.5, 0.5, 0.5),
                radius: 0.4,
            },
        ];
        let dir = Vec3::new(1.0, 0.7, 0.4).normalize();
        let step = 1e-4;
        for region in regions {
            let mut prev = region.intersection_volume(&(dir * -1.0), r);
            for i in 1..=30000 {
                let c = dir * (-1.0 + i as f64 * step);
                let v = region.intersection_volume(&c, r);
                // |dV| ≤ cross-section area × step ≤ π r² step.
                assert!(
                    (v - prev).abs() <= PI * r * r * step * 1.0001,
                    "{region:?} at {c:?}"
                );
                prev = v;
            }
        }
    }

    #[test]
    fn bounding_box_contains_sampled_points() {
        let cyl = Region::Cylinder {
            base: Vec3::new(1.0, 2.0, 3.0),
            axis: Vec3::new(0.3, -0.5, 0.8),
            radius: 0.7,
            height: 2.0,
        };
        let (lo, hi) = cyl.bounding_box();
        let a = Vec3::new(0.3, -0.5, 0.8).normalize();
        let u = a.cross(&Vec3::x()).normalize();
        let w = a.cross(&u);
        for i in 0..360 {
            let th = i as f64 * PI / 180.0;
            for t in [0.0, 2.0] {
                let rim = u * th.cos() + w * th.sin();
                let p = Vec3::new(1.0, 2.0, 3.0) + a * t + rim * 0.7;
                let inward = a * (1.0 - t) * 1e-9 - rim * 1e-9;
                assert!(cyl.contains_point(&(p + inward)));
                assert!(!cyl.contains_point(&(p - inward)));
                assert!((0..3).all(|k| lo[k] - 1e-12 <= p[k] && p[k] <= hi[k] + 1e-12));
            }
        }
    }

    /// Monte Carlo check of every region type: random regions, random balls that cut
    /// their boundary, N points uniform in the ball. The fraction inside (by
    /// `contains_point`) estimates V/V_ball with standard error √(p(1 − p)/N), p the
    /// exact fraction. Each case must agree within 5 standard errors (a false alarm
    /// has probability ~6e-7 per case), and the z-scores of all cases together must
    /// look like standard normal draws (RMS within 0.75–1.25, mean within 4/√n ≈ 0.28),
    /// which catches a bias far smaller than 5 SE in any one case.
    #[test]
    fn monte_carlo_agrees_with_exact_volumes() {
        use rand::{RngExt, SeedableRng};
        use rand_chacha::ChaCha8Rng;

        const CASES: usize = 50;
        const POINTS: usize = 100_000;
        let mut rng = ChaCha8Rng::seed_from_u64(20160405);
        let mut all_z = Vec::new();
        for kind in 0..4 {
            let mut zs = Vec::new();
            while zs.len() < CASES {
                let mut v3 = |lo: f64, hi: f64| {
                    Vec3::new(
                        rng.random_range(lo..hi),
                        rng.random_range(lo..hi),
                        rng.random_range(lo..hi),
                    )
                };
                let region = match kind {
                    0 => {
                        let lower = v3(-1.0, 0.0);
                        Region::Box {
                            lower,
                            upper: lower + v3(0.2, 2.0),
                        }
                    }
                    1 => {
                        let lo = v3(-1.0, 0.0)[0];
                        let shape = v3(0.0, 3.0);
                        Region::Slab {
                            axis: shape[0] as usize,
                            lo,
                            hi: lo + 0.1 + shape[1] / 2.0,
                        }
                    }
                    2 => {
                        let mut axis = v3(-1.0, 1.0);
                        let shape = v3(0.2, 1.5);
                        // One case in three along a coordinate axis, where the
                        // bounding box and the caps shortcut take other paths.
                        if shape[2] < 0.6 {
                            axis = Vec3::zeros();
                            axis[(shape[0] * 2.0) as usize % 3] = 1.0;
                        }
                        Region::Cylinder {
                            base: v3(-0.5, 0.5),
                            axis,
                            radius: shape[0],
                            height: shape[1] * 1.3,
                        }
                    }
                    _ => Region::Sphere {
                        centre: v3(-0.5, 0.5),
                        radius: v3(0.1, 1.5)[0],
                    },
                };
                let r = rng.random_range(0.1..1.0);
                let (lo, hi) = region.bounding_box();
                let lo = lo.map(|x| x.max(-3.0)).add_scalar(-r);
                let hi = hi.map(|x| x.min(3.0)).add_scalar(r);
                let c = Vec3::new(
                    rng.random_range(lo[0]..hi[0]),
                    rng.random_range(lo[1]..hi[1]),
                    rng.random_range(lo[2]..hi[2]),
                );
                let exact = region.intersection_volume(&c, r);
                let p = exact / ball_volume(r);
                if !(0.005..0.995).contains(&p) {
                    continue;
                }
                let mut inside = 0usize;
                let mut drawn = 0usize;
                while drawn < POINTS {
                    let d = Vec3::new(
                        rng.random_range(-1.0..1.0),
                        rng.random_range(-1.0..1.0),
                        rng.random_range(-1.0..1.0),
                    );
                    if d.norm_squared() > 1.0 {
                        continue;
                    }
                    drawn += 1;
                    inside += region.contains_point(&(c + d * r)) as usize;
                }
                let estimate = inside as f64 / POINTS as f64;
                let se = (p * (1.0 - p) / POINTS as f64).sqrt();
                let z = (estimate - p) / se;
                assert!(
                    z.abs() < 5.0,
                    "{region:?}, ball at {c:?} r {r}: exact fraction {p}, MC {estimate}, z = {z}"
                );
                zs.push(z);
            }
            let max = zs.iter().fold(0.0f64, |m, z| m.max(z.abs()));
            let rms = (zs.iter().map(|z| z * z).sum::<f64>() / zs.len() as f64).sqrt();
            let mean = zs.iter().sum::<f64>() / zs.len() as f64;
            println!(
                "region kind {kind}: {CASES} cases, max |z| {max:.2}, RMS z {rms:.2}, mean z {mean:+.2}"
            );
            all_z.extend(zs);
        }
        let n = all_z.len() as f64;
        let rms = (all_z.iter().map(|z| z * z).sum::<f64>() / n).sqrt();
        let mean = all_z.iter().sum::<f64>() / n;
        println!("all: {n} cases, RMS z {rms:.3}, mean z {mean:+.3}");
        assert!((0.75..1.25).contains(&rms), "RMS z {rms}");
        assert!(mean.abs() < 4.0 / n.sqrt(), "mean z {mean}");
    }
}
