//! 3D ballistic deposition by steepest descent (Visscher & Bolsterli 1972, Nature
//! 239:504; the 2D form is the packing generator of Redanz & Fleck 2001 §2.2).
//!
//! Spheres are dropped one at a time at a uniformly random (x, y) in the footprint
//! and move quasi-statically, without inertia, along the path of steepest descent
//! of their height z over the free space left by the floor and the spheres already
//! placed. With centre p, radius a, and contacts i (centre cᵢ, contact distance
//! dᵢ = a + rᵢ, unit normal nᵢ = (p − cᵢ)/dᵢ), the direction of motion is gravity
//! g = −ẑ projected onto the tangent cone {v : v·nᵢ ≥ 0}:
//!
//!   v = g + Σ_{i∈B} μᵢ nᵢ,   v·nᵢ = 0 and μᵢ > 0 for i ∈ B,   v·nᵢ ≥ 0 for i ∉ B,
//!
//! the KKT conditions of min |v − g|² on the cone; μᵢ is the contact force in units
//! of the weight. The sphere rests when v = 0 has a solution with three contacts:
//! ẑ = Σ μᵢ nᵢ, μᵢ ≥ 0, i.e. the vertical through p passes inside (or on the edge
//! of) the triangle of the three contact points. Otherwise B is the smallest subset
//! of the current contacts (size ≤ 2) meeting the conditions, and its size says
//! what the sphere does:
//!
//! * |B| = 0: free fall, p(t) = p − t ẑ, until it first meets a sphere
//!   (t = p_z − c_z − √(d² − h²), h the horizontal distance) or the floor.
//! * |B| = 1: rolls on sphere j down the great circle in the vertical plane through
//!   cⱼ and p: p(φ) = cⱼ + dⱼ (cos φ e₁ + sin φ e₂), until the equator (n_z = 0,
//!   where μⱼ = n_z reaches 0 and it falls off), a new contact, or the floor.
//! * |B| = 2: rolls in the groove of spheres j, k: the circle of points at dⱼ from
//!   cⱼ and d_k from c_k, centre m = cⱼ + α û, α = (dⱼ² − d_k² + |c_k − cⱼ|²)/(2|c_k − cⱼ|),
//!   radius ρ = √(dⱼ² − α²), until one contact force vanishes
//!   (μⱼ ∝ nⱼ_z − (nⱼ·n_k) n_k_z, which is affine in cos φ, sin φ since nⱼ·n_k is
//!   fixed on the circle), a new contact, or the floor. No stable two-sphere rest
//!   exists: at the circle's lowest point both normals point down along the
//!   in-plane direction, so μⱼ, μ_k > 0 cannot hold there, and the top of the
//!   circle is a maximum.
//!
//! On the top of a sphere or of a groove circle v = 0 on one or two supports, an
//! unstable equilibrium (reached only by coincidence); the sphere leaves it along
//! any tangent no other contact blocks.
//!
//! Touching the floor ends the descent (g is normal to it, so there is no descent
//! direction left; any sphere contacts at that moment are incidental supports).
//!
//! Every event along a path is a root of c₀ + a cos φ + b sin φ (sphere contact:
//! |p(φ) − c|² = d²; floor: p_z(φ) = floor + a; release: μ = 0), solved in closed
//! form, so positions are exact contact geometry rather than small time steps.
//! The entering root of c₀ + R cos(φ − ψ) = 0 is φ = ψ + arccos(−c₀/R) (mod 2π).
//!
//! A cell grid (cell width ≥ the largest contact distance) makes each query O(1);
//! the free-fall search walks z layers down from the fall height and stops once no
//! lower layer can hold a higher contact, so a deposit of N spheres costs O(N).
//!
//! Along periodic x or y (from `Space`) spheres re-enter through the opposite side.
//! Along an open axis nothing confines them: they may roll beyond the footprint,
//! forming a heap on an unbounded floor.

use super::distribution::each_positive_finite;
use super::grid::CellGrid;
use crate::particles::Vec3;
use crate::progress::Progress;
use crate::space::Space;
use rand::RngExt;
use rand_chacha::ChaCha8Rng;

/// A contact force (in units of the weight) must exceed this to count as pressing;
/// a contact whose normal makes the motion direction approach it at a rate below
/// this (dimensionless, per unit path length) is treated as tangential, not
/// entering. The same threshold serves both so the active-set choice and the path
/// event search agree on which contacts are leaving.
pub(super) const TOL: f64 = 1e-9;

/// Angles (rad) within this of the start of a path count as "now".
pub(super) const ANGLE_TOL: f64 = 1e-9;

/// Events closer than this (rad) to the first one happen together.
pub(super) const SIMULTANEOUS: f64 = 1e-12;

/// A sphere needing more path segments than this is stuck in a numerical cycle;
/// typical counts are below 20.
const MAX_SEGMENTS: usize = 10_000;

/// Deposit spheres of the given radii, in order, onto the plane z = `floor`.
/// Drop points are uniform in `footprint` = ([x_lo, y_lo], [x_hi, y_hi]). Returns
/// the centres in deposition order, wrapped into the periodic box.
pub fn deposit(
    radii: &[f64],
    footprint: ([f64; 2], [f64; 2]),
    floor: f64,
    space: &Space,
    rng: &mut ChaCha8Rng,
) -> Result<Vec<Vec3>, String> {
    check_footprint(footprint, space)?;
    let (lo, hi) = footprint;
    let mut draw = |k: usize| {
        if hi[k] > lo[k] {
            rng.random_range(lo[k]..hi[k])
        } else {
            lo[k]
        }
    };
    let drops: Vec<[f64; 2]> = radii.iter().map(|_| [draw(0), draw(1)]).collect();
    deposit_at(radii, &drops, floor, space)
}

/// Deposit sphere i at the given drop point (x, y), for i in order: the
/// deterministic core of `deposit`, for reproducing or constructing a deposit.
pub fn deposit_at(
    radii: &[f64],
    drops: &[[f64; 2]],
    floor: f64,
    space: &Space,
) -> Result<Vec<Vec3>, String> {
    if drops.len() != radii.len() {
        return Err(format!(
            "need one drop point per radius (got {} and {})",
            drops.len(),
            radii.len()
        ));
    }
    let r_max = check_inputs(radii, floor, space)?;
    let mut pile = Pile {
        space: *space,
        floor,
        r_max,
        grid: CellGrid::new(space, 2.0 * r_max, floor),
        centres: Vec::with_capacity(radii.len()),
        radii: Vec::with_capacity(radii.len()),
        top_z: floor,
        scratch: Vec::new(),
    };
    let mut progress = Progress::new("deposit", radii.len() as u64, false);
    for (i, (&a, xy)) in radii.iter().zip(drops).enumerate() {
        // Start above every placed sphere so the fall meets the pile from above.
        let start = Vec3::new(xy[0], xy[1], pile.top_z + a + 2.0 * r_max);
        let p = pile
            .descend(start, a)
            .map_err(|e| format!("sphere {i} (radius {a}): {e}"))?;
        pile.place(p, a);
        if i % 1024 == 0 {
            progress.set(i as u64);
        }
    }
    progress.finish();
    Ok(pile.centres)
}

fn check_footprint(footprint: ([f64; 2], [f64; 2]), space: &Space) -> Result<(), String> {
    let (lo, hi) = footprint;
    for (k, axis) in ["x", "y"].iter().enumerate() {
        if !(lo[k].is_finite() && hi[k].is_finite() && hi[k] >= lo[k]) {
            return Err(format!(
                "footprint {axis} range must be finite with lo <= hi (got {} .. {})",
                lo[k], hi[k]
            ));
        }
        if let Some((start, length)) = space.periodic[k] {
            let slack = 1e-12 * length.abs().max(1.0);
            if lo[k] < start - slack || hi[k] > start + length + slack {
                return Err(format!(
                    "footprint {axis} range {} .. {} must lie inside the periodic interval {} .. {}",
                    lo[k],
                    hi[k],
                    start,
                    start + length
                ));
            }
        }
    }
    Ok(())
}

fn check_inputs(radii: &[f64], floor: f64, space: &Space) -> Result<f64, String> {
    each_positive_finite("radii", radii)?;
    if !floor.is_finite() {
        return Err(format!("floor must be finite (got {floor})"));
    }
    if space.periodic[2].is_some() {
        return Err("z must not be periodic: spheres fall along −z onto the floor".into());
    }
    let r_max = radii.iter().copied().fold(0.0, f64::max);
    for (k, axis) in ["x", "y"].iter().enumerate() {
        // A path can meet spheres up to 2 contact distances (4 r_max) from the
        // sphere it rolls on; nearest images are unique only below L/2.
        if let Some((_, length)) = space.periodic[k]
            && length <= 8.0 * r_max
        {
            return Err(format!(
                "periodic {axis} length {length} must exceed 8 × the largest radius ({})",
                8.0 * r_max
            ));
        }
    }
    Ok(r_max)
}

struct Pile {
    space: Space,
    floor: f64,
    r_max: f64,
    grid: CellGrid,
    centres: Vec<Vec3>,
    radii: Vec<f64>,
    /// Highest centre placed (the floor before the first).
    top_z: f64,
    scratch: Vec<usize>,
}

/// A contact with a placed sphere, seen from the moving sphere: the image of its
/// centre nearest to the moving centre, and the contact distance.
#[derive(Clone, Copy)]
struct Contact {
    id: usize,
    centre: Vec3,
    reach: f64,
}

enum Outcome {
    Continue(Vec3, Vec<usize>),
    Rest(Vec3),
}

/// The path p(φ) = centre + radius (cos φ e₁ + sin φ e₂), φ ∈ [0, end].
struct Arc {
    centre: Vec3,
    radius: f64,
    e1: Vec3,
    e2: Vec3,
    end: f64,
}

impl Arc {
    fn at(&self, phi: f64) -> Vec3 {
        self.centre + (self.e1 * phi.cos() + self.e2 * phi.sin()) * self.radius
    }
}

/// First φ in [0, end] where c₀ + a cos φ + b sin φ turns negative, or None.
/// The function must be normalised so that its derivative is a dimensionless rate
/// (compared with TOL) at the start of the path.
pub(super) fn first_entry(c0: f64, a: f64, b: f64, end: f64) -> Option<f64> {
    let r2 = a * a + b * b;
    if r2 == 0.0 || (c0 >= 0.0 && c0 * c0 >= r2) {
        return None; // f = c₀ + R cos(φ − ψ) never drops below zero
    }
    // hypot would guard against overflow, which these O(1) coefficients cannot
    // reach, at several times the cost in this innermost call.
    let r = r2.sqrt();
    if c0 <= -r {
        // Negative all along: already inside. Only reachable through rounding in a
        // contact we are leaving; treat as no event.
        return None;
    }
    let psi = b.atan2(a);
    let beta = (-c0 / r).acos();
    let two_pi = 2.0 * std::f64::consts::PI;
    let mut phi = (psi + beta).rem_euclid(two_pi);
    if phi > two_pi - ANGLE_TOL {
        phi -= two_pi;
    }
    if phi <= ANGLE_TOL {
        // Touching now: an event only if the path heads inside (f'(0) = b).
        return (b < -TOL).then_some(0.0);
    }
    (phi <= end).then_some(phi)
}

impl Pile {
    fn place(&mut self, mut p: Vec3, a: f64) {
        self.space.wrap(&mut p);
        let id = self.centres.len();
        self.grid.insert(&p, id);
        self.top_z = self.top_z.max(p[2]);
        self.centres.push(p);
        self.radii.push(a);
    }

    fn contact(&self, p: &Vec3, id: usize, a: f64) -> Contact {
        Contact {
            id,
            centre: p - self.space.displacement(p, &self.centres[id]),
            reach: a + self.radii[id],
        }
    }

    fn descend(&mut self, start: Vec3, a: f64) -> Result<Vec3, String> {
        let mut p = start;
        let mut touching: Vec<usize> = Vec::new();
        for _ in 0..MAX_SEGMENTS {
            let contacts: Vec<Contact> =
                touching.iter().map(|&id| self.contact(&p, id, a)).collect();
            let Some((active, v)) = descent_direction(&p, &contacts)? else {
                return Ok(p);
            };
            let outcome = match active[..] {
                [] => self.fall(p, a),
                [j] => self.roll(p, a, contacts[j], v),
                [j, k] => self.groove(p, a, contacts[j], contacts[k], v),
                _ => unreachable!("at most two contacts support a moving sphere"),
            };
            match outcome {
                Outcome::Rest(q) => return Ok(q),
                Outcome::Continue(q, t) => {
                    p = q;
                    self.space.wrap(&mut p);
                    touching = t;
                }
            }
        }
        Err(format!(
            "no rest after {MAX_SEGMENTS} path segments (numerical cycle) near {p:?}"
        ))
    }

    /// Vertical fall: the highest contact below p, searched layer by layer downward.
    fn fall(&mut self, p: Vec3, a: f64) -> Outcome {
        let floor_z = self.floor + a;
        let reach_max = a + self.r_max;
        let mut best = floor_z;
        let mut hits: Vec<(usize, f64)> = Vec::new();
        // Centres lie at or below top_z: layers above its own are empty.
        let mut layer = self.grid.layer_of(p[2].min(self.top_z));
        let mut ids = std::mem::take(&mut self.scratch);
        while layer >= 0 {
            // Centres in this layer lie below its top edge, so no contact from here
            // or below can be higher than top edge + largest contact distance.
            if self.grid.layer_bottom(layer + 1) + reach_max < best {
                break;
            }
            self.grid.column_layer(&p, reach_max, layer, &mut ids);
            for &id in &ids {
                let c = self.contact(&p, id, a);
                let h2 = (p[0] - c.centre[0]).powi(2) + (p[1] - c.centre[1]).powi(2);
                let s2 = c.reach * c.reach - h2;
                if s2 <= 0.0 {
                    continue;
                }
                let s = s2.sqrt();
                // s/d = n_z at the meeting point: the approach rate; a grazing
                // touch at the equator is no contact.
                if s <= TOL * c.reach {
                    continue;
                }
                let z_hit = c.centre[2] + s;
                // Met above p only by rounding, when already touching: count it
                // as met now (the same 1e-9, relative to the contact distance).
                if z_hit > p[2] + ANGLE_TOL * c.reach {
                    continue;
                }
                hits.push((id, z_hit));
                best = best.max(z_hit);
            }
            layer -= 1;
        }
        self.scratch = ids;
        let tie = SIMULTANEOUS * a;
        let q = Vec3::new(p[0], p[1], best.min(p[2]));
        if best - floor_z <= tie {
            return Outcome::Rest(Vec3::new(p[0], p[1], floor_z));
        }
        let mut touching: Vec<usize> = hits
            .iter()
            .filter(|(_, z)| *z >= best - tie)
            .map(|(id, _)| *id)
            .collect();
        touching.sort_unstable();
        touching.dedup();
        Outcome::Continue(q, touching)
    }

    /// Rolling on `support` in the direction `v`.
    fn roll(&mut self, p: Vec3, a: f64, support: Contact, v: Vec3) -> Outcome {
        let e1 = (p - support.centre).normalize();
        // v ⊥ e₁ already, up to rounding, except when leaving the top along an
        // arbitrary horizontal; the projection keeps the arc on the sphere.
        let e2 = (v - e1 * v.dot(&e1)).normalize();
        let end = e1[2].atan2(-e2[2]).max(0.0);
        let arc = Arc {
            centre: support.centre,
            radius: support.reach,
            e1,
            e2,
            end,
        };
        self.follow(&arc, a, &[support.id], None)
    }

    /// Rolling in the groove of `j` and `k` in the direction `v`.
    fn groove(&mut self, p: Vec3, a: f64, j: Contact, k: Contact, v: Vec3) -> Outcome {
        let axis = k.centre - j.centre;
        let gap = axis.norm();
        let u = axis / gap;
        let along = (j.reach * j.reach - k.reach * k.reach + gap * gap) / (2.0 * gap);
        let m = j.centre + u * along;
        let radius = (j.reach * j.reach - along * along).max(0.0).sqrt();
        let off = p - m;
        let e1 = (off - u * off.dot(&u)).normalize();
        let mut e2 = u.cross(&e1);
        if e2.dot(&v) < 0.0 {
            e2 = -e2;
        }
        // Lowest point of the circle: φ = atan2(e₂z, e₁z) + π.
        let end = (e2[2].atan2(e1[2]) + std::f64::consts::PI).clamp(0.0, std::f64::consts::PI);
        let arc = Arc {
            centre: m,
            radius,
            e1,
            e2,
            end,
        };
        // μⱼ ∝ nⱼ_z − c n_k_z with c = nⱼ·n_k fixed on the circle; at point φ,
        // n_z = (m_z − c_z + ρ (cos φ e₁z + sin φ e₂z)) / d.
        let nj = (p - j.centre) / j.reach;
        let nk = (p - k.centre) / k.reach;
        let c = nj.dot(&nk);
        let release = |s: &Contact, o: &Contact| {
            let c0 = (m[2] - s.centre[2]) / s.reach - c * (m[2] - o.centre[2]) / o.reach;
            let w = radius * (1.0 / s.reach - c / o.reach);
            (c0, w * e1[2], w * e2[2])
        };
        let releases = [release(&j, &k), release(&k, &j)];
        self.follow(&arc, a, &[j.id, k.id], Some(releases))
    }

    /// Move along `arc` to its first event: a new sphere contact, the floor, a
    /// vanishing contact force, or the end of the arc.
    fn follow(
        &mut self,
        arc: &Arc,
        a: f64,
        supports: &[usize],
        releases: Option<[(f64, f64, f64); 2]>,
    ) -> Outcome {
        let mut first = arc.end;
        let floor_z = self.floor + a;
        // Normalised by the arc radius so that f'(0) = e₂z, a unit rate.
        let floor_phi = first_entry(
            (arc.centre[2] - floor_z) / arc.radius,
            arc.e1[2],
            arc.e2[2],
            arc.end,
        );
        if let Some(phi) = floor_phi {
            first = first.min(phi);
        }
        for (c0, ca, cb) in releases.into_iter().flatten() {
            if let Some(phi) = first_entry(c0, ca, cb, arc.end) {
                first = first.min(phi);
            }
        }
        let mut new_contacts: Vec<(usize, f64)> = Vec::new();
        let mut ids = std::mem::take(&mut self.scratch);
        self.grid
            .near(&arc.centre, arc.radius + a + self.r_max, &mut ids);
        for &id in &ids {
            if supports.contains(&id) {
                continue;
            }
            let c = self.contact(&arc.centre, id, a);
            let q = arc.centre - c.centre;
            let rr = arc.radius;
            if q.norm_squared() > (rr + c.reach) * (rr + c.reach) {
                continue; // out of reach from anywhere on the circle
            }
            // (|q + ρ r̂(φ)|² − d²) / (2ρd), so that f'(0) = n·e₂ is the approach rate.
            let scale = 2.0 * rr * c.reach;
            let c0 = (q.norm_squared() + rr * rr - c.reach * c.reach) / scale;
            let ca = 2.0 * rr * q.dot(&arc.e1) / scale;
            let cb = 2.0 * rr * q.dot(&arc.e2) / scale;
            if let Some(phi) = first_entry(c0, ca, cb, arc.end) {
                new_contacts.push((id, phi));
                first = first.min(phi);
            }
        }
        self.scratch = ids;

        let p = arc.at(first);
        if floor_phi.is_some_and(|phi| phi <= first + SIMULTANEOUS) {
            return Outcome::Rest(Vec3::new(p[0], p[1], floor_z));
        }
        // Supports stay listed even when their force vanished here: they still
        // touch, and the next active-set choice decides whether they are left.
        let mut touching: Vec<usize> = supports.to_vec();
        touching.extend(
            new_contacts
                .iter()
                .filter(|(_, phi)| *phi <= first + SIMULTANEOUS)
                .map(|(id, _)| *id),
        );
        touching.sort_unstable();
        touching.dedup();
        Outcome::Continue(p, touching)
    }
}

/// The projection of g = −ẑ onto the tangent cone at p: `None` when it vanishes
/// (a rest), else the smallest active subset B of `contacts` satisfying its KKT
/// conditions and the unit direction of motion. Indices in B refer to `contacts`.
fn descent_direction(p: &Vec3, contacts: &[Contact]) -> Result<Option<(Vec<usize>, Vec3)>, String> {
    let g = -Vec3::z();
    let normals: Vec<Vec3> = contacts.iter().map(|c| (p - c.centre) / c.reach).collect();
    let n = contacts.len();
    // Rest: ẑ in the closed cone of three normals, i.e. the vertical through p
    // inside or on the triangle of contact points. Accepting the edge (μ ≥ −TOL)
    // settles the marginal case where one support carries no load; the strict
    // search below would stall there, balanced on the other two.
    for subset in subsets(n, 3) {
        if let Some(mu) = solve_forces(&normals, &subset)
            && mu.iter().all(|m| *m >= -TOL)
        {
            return Ok(None);
        }
    }
    for size in 0..=n.min(2) {
        for subset in subsets(n, size) {
            let Some(mu) = solve_forces(&normals, &subset) else {
                continue;
            };
            if mu.iter().any(|m| *m <= TOL) {
                continue;
            }
            let mut v = g;
            for (m, &i) in mu.iter().zip(&subset) {
                v += normals[i] * *m;
            }
            let others: Vec<&Vec3> = (0..n)
                .filter(|i| !subset.contains(i))
                .map(|i| &normals[i])
                .collect();
            let speed = v.norm();
            let direction = if speed > TOL {
                v / speed
            } else {
                // Balanced on the top of a sphere or of a groove circle: an
                // unstable equilibrium; leave it along any tangent that no other
                // contact blocks.
                let tangents = match subset.as_slice() {
                    [_] => vec![Vec3::x(), -Vec3::x(), Vec3::y(), -Vec3::y()],
                    [i, j] => {
                        let t = normals[*i].cross(&normals[*j]).normalize();
                        vec![t, -t]
                    }
                    _ => unreachable!("free fall always moves"),
                };
                match tangents
                    .into_iter()
                    .find(|t| others.iter().all(|m| t.dot(m) >= -TOL))
                {
                    Some(t) => t,
                    None => continue,
                }
            };
            // The same rate threshold as the event search, so a contact accepted
            // here as leaving is not reported there as entering at φ = 0.
            if others.iter().all(|m| direction.dot(m) >= -TOL) {
                return Ok(Some((subset, direction)));
            }
        }
    }
    Err(format!(
        "no consistent set of supporting contacts among {:?} at {p:?}",
        contacts.iter().map(|c| c.id).collect::<Vec<_>>()
    ))
}

/// Contact forces μ with (Σ μᵢ nᵢ − ẑ)·n_l = 0 for l in the subset: G μ = n_z.
fn solve_forces(normals: &[Vec3], subset: &[usize]) -> Option<Vec<f64>> {
    let k = subset.len();
    if k == 0 {
        return Some(Vec::new());
    }
    let mut gram = nalgebra::DMatrix::<f64>::zeros(k, k);
    let mut rhs = nalgebra::DVector::<f64>::zeros(k);
    for (r, &i) in subset.iter().enumerate() {
        rhs[r] = normals[i][2];
        for (s, &j) in subset.iter().enumerate() {
            gram[(r, s)] = normals[i].dot(&normals[j]);
        }
    }
    // Nearly parallel normals (det → 0) leave the forces undetermined.
    if gram.determinant().abs() < 1e-12 {
        return None;
    }
    gram.lu().solve(&rhs).map(|x| x.iter().copied().collect())
}

/// All `size`-element subsets of 0..n in lexicographic order.
fn subsets(n: usize, size: usize) -> Vec<Vec<usize>> {
    let mut out = Vec::new();
    let mut current = Vec::with_capacity(size);
    fn rec(
        start: usize,
        n: usize,
        size: usize,
        current: &mut Vec<usize>,
        out: &mut Vec<Vec<usize>>,
    ) {
        if current.len() == size {
            out.push(current.clone());
            return;
        }
        for i in start..n {
            current.push(i);
            rec(i + 1, n, size, current, out);
            current.pop();
        }
    }
    rec(0, n, size, &mut current, &mut out);
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::generate::measure::{contact_pairs, unsupported};
    use rand::SeedableRng;

    fn close(a: &Vec3, b: &Vec3, tol: f64) -> bool {
        (a - b).norm() < tol
    }

    #[test]
    fn entering_root_of_the_event_function() {
        // f = 0.5 + cos φ: crosses zero downward at φ = 2π/3.
        let phi = first_entry(0.5, 1.0, 0.0, 3.0).unwrap();
        assert!((phi - 2.0 * std::f64::consts::PI / 3.0).abs() < 1e-15);
        assert_eq!(first_entry(0.5, 1.0, 0.0, 2.0), None);
        // Touching now: an event only when heading inside.
        assert_eq!(first_entry(-1.0, 1.0, -0.5, 1.0), Some(0.0));
        // Touching and leaving: the next entry, where cos φ + ½ sin φ = 1 again.
        let back = first_entry(-1.0, 1.0, 0.5, 1.0).unwrap();
        assert!((back - 2.0 * 0.5f64.atan()).abs() < 1e-15);
        assert_eq!(first_entry(-1.0, 1.0, 0.5, 0.9), None);
        assert_eq!(first_entry(2.0, 1.0, 1.0, 6.0), None);
    }

    #[test]
    fn lone_sphere_falls_to_the_floor() {
        let p = deposit_at(&[0.3], &[[1.0, 2.0]], -1.0, &Space::open()).unwrap();
        assert_eq!(p[0], Vec3::new(1.0, 2.0, -0.7));
    }

    #[test]
    fn rolls_off_a_larger_sphere_and_drops() {
        // Lands on the big sphere, rolls down the great circle toward +x+y, leaves
        // it at the equator (height 1) and falls to the floor at distance 1.5.
        let drops = [[0.0, 0.0], [0.1, 0.1]];
        let p = deposit_at(&[1.0, 0.5], &drops, 0.0, &Space::open()).unwrap();
        let s = 1.5 / 2f64.sqrt();
        assert!(close(&p[1], &Vec3::new(s, s, 0.5), 1e-12), "{:?}", p[1]);
    }

    #[test]
    fn rolls_along_the_groove_of_two_spheres() {
        // Two touching unit spheres on the floor at x = ±1. A unit sphere dropped at
        // (0.1, 0.3) lands on the right one, rolls into the groove, and descends the
        // groove circle (centre (0,0,1), radius √3) to the floor at (0, √3, 1).
        let drops = [[-1.0, 0.0], [1.0, 0.0], [0.1, 0.3]];
        let p = deposit_at(&[1.0; 3], &drops, 0.0, &Space::open()).unwrap();
        assert!(
            close(&p[2], &Vec3::new(0.0, 3f64.sqrt(), 1.0), 1e-12),
            "{:?}",
            p[2]
        );
    }

    #[test]
    fn settles_in_the_pocket_of_three() {
        // Three touching unit spheres on the floor; a fourth dropped off-centre rolls
        // into the tetrahedral pocket above their centroid, height 1 + 2√(2/3).
        let s3 = 3f64.sqrt();
        let mut drops = vec![[0.0, 0.0], [2.0, 0.0], [1.0, s3]];
        let centroid = [1.0, s3 / 3.0];
        drops.push([centroid[0] + 0.2, centroid[1] + 0.05]);
        let p = deposit_at(&[1.0; 4], &drops, 0.0, &Space::open()).unwrap();
        let expect = Vec3::new(centroid[0], centroid[1], 1.0 + 2.0 * (2.0f64 / 3.0).sqrt());
        assert!(close(&p[3], &expect, 1e-12), "{:?}", p[3]);
    }

    fn periodic(l: f64) -> Space {
        Space {
            periodic: [Some((0.0, l)), Some((0.0, l)), None],
        }
    }

    /// No overlap beyond 1e-9 of the contact distance, and every sphere supported
    /// when it was placed.
    fn check_packing(p: &[Vec3], radii: &[f64], space: &Space, floor: f64) {
        let pairs = contact_pairs(p, radii, space, 1e-9);
        let worst = pairs.iter().map(|c| c.2).fold(0.0, f64::min);
        assert!(worst > -1e-9, "overlap {worst}");
        let loose = unsupported(p, radii, space, floor, 1e-9);
        assert!(loose.is_empty(), "unsupported spheres {loose:?}");
    }

    #[test]
    fn monodisperse_deposit_is_overlap_free_and_stable() {
        let space = periodic(8.0);
        let radii = vec![0.5; 1500];
        let mut rng = ChaCha8Rng::seed_from_u64(1);
        let p = deposit(&radii, ([0.0, 0.0], [8.0, 8.0]), 0.0, &space, &mut rng).unwrap();
        check_packing(&p, &radii, &space, 0.0);
        let mut again = ChaCha8Rng::seed_from_u64(1);
        let q = deposit(&radii, ([0.0, 0.0], [8.0, 8.0]), 0.0, &space, &mut again).unwrap();
        assert_eq!(p, q, "same seed, same packing");
    }

    #[test]
    fn polydisperse_deposits_are_overlap_free_and_stable() {
        use crate::generate::distribution::SizeDistribution;
        let space = periodic(12.0);
        let laws = [
            SizeDistribution::Uniform { min: 0.3, max: 0.7 },
            SizeDistribution::LogNormal {
                median: 0.4,
                sigma: 0.35,
                min: Some(0.15),
                max: Some(1.0),
            },
            SizeDistribution::Discrete {
                radii: vec![0.25, 0.75],
                number_fractions: vec![0.8, 0.2],
            },
        ];
        for (s, law) in laws.iter().enumerate() {
            let mut rng = ChaCha8Rng::seed_from_u64(40 + s as u64);
            let radii: Vec<f64> = (0..1500).map(|_| law.sample(&mut rng)).collect();
            let p = deposit(&radii, ([0.0, 0.0], [12.0, 12.0]), 0.0, &space, &mut rng).unwrap();
            check_packing(&p, &radii, &space, 0.0);
        }
    }

    #[test]
    fn open_heap_stays_overlap_free() {
        // No periodicity: drops inside a small square build a cone on the floor.
        let radii = vec![0.5; 600];
        let mut rng = ChaCha8Rng::seed_from_u64(9);
        let p = deposit(
            &radii,
            ([0.0, 0.0], [2.0, 2.0]),
            0.0,
            &Space::open(),
            &mut rng,
        )
        .unwrap();
        check_packing(&p, &radii, &Space::open(), 0.0);
        assert!(
            p.iter().any(|x| x[0] < -1.0 || x[0] > 3.0),
            "the heap spreads"
        );
    }

    #[test]
    fn rejects_bad_inputs() {
        let space = periodic(4.0);
        let mut rng = ChaCha8Rng::seed_from_u64(0);
        let fp = ([0.0, 0.0], [4.0, 4.0]);
        let err = deposit(&[0.5, 0.6], fp, 0.0, &space, &mut rng).unwrap_err();
        assert!(err.contains("must exceed 8"), "{err}");
        let err = deposit(&[0.2, -1.0], fp, 0.0, &space, &mut rng).unwrap_err();
        assert!(err.contains("radii[1]"), "{err}");
        let err = deposit(&[0.2], ([0.0, 0.0], [5.0, 4.0]), 0.0, &space, &mut rng).unwrap_err();
        assert!(err.contains("inside the periodic interval"), "{err}");
    }
}
