//! 2D ballistic deposition of circular cylinders (discs of unit depth) by steepest
//! descent into a box with a floor and two side walls: the packing generator of
//! Redanz & Fleck 2001 §2.2 (Fig 3), after Visscher & Bolsterli 1972 (Nature
//! 239:504). `ballistic.rs` is the 3D form; this file is the same algorithm in the
//! plane, plus side walls.
//!
//! The box is [0, W] × [0, ∞), x horizontal and y up (x₁, x₂ of `CylinderPacking`).
//! Discs are dropped one at a time from above the pile, at a uniformly random
//! centre abscissa x ∈ [a, W − a] (a is the disc's radius). They move
//! quasi-statically, without inertia, along the path of steepest descent of their
//! height through the space left by the floor y = 0, the walls x = 0 and x = W and
//! the discs already placed. With centre p and contacts i, each either a disc
//! (centre cᵢ, contact distance dᵢ = a + rᵢ, unit normal nᵢ = (p − cᵢ)/dᵢ) or a wall
//! (nᵢ = +x̂ on the left, −x̂ on the right), the direction of motion is gravity
//! g = −ŷ projected onto the tangent cone {v : v·nᵢ ≥ 0}:
//!
//!   v = g + Σ_{i∈B} μᵢ nᵢ,   v·nᵢ = 0 and μᵢ > 0 for i ∈ B,   v·nᵢ ≥ 0 for i ∉ B,
//!
//! with μᵢ the contact force in units of the weight. In the plane two independent
//! normals span every direction, so two loaded contacts mean v = 0, a rest:
//!
//! * Rest: ŷ = μⱼ nⱼ + μ_k n_k with μⱼ, μ_k ≥ 0 for some two contacts, where
//!   Δ = nⱼx n_ky − n_kx nⱼy, μⱼ = −n_kx/Δ, μ_k = nⱼx/Δ (Cramer's rule): the two
//!   contact points straddle the vertical through p (the edge counts). A disc
//!   against a wall rests on the wall and one disc when the wall blocks its roll:
//!   μⱼ = 1/nⱼy and μ_wall = |nⱼx|/nⱼy, both positive when the disc rolls towards
//!   the wall. A disc also rests once it touches the floor: g is normal to it.
//! * |B| = 0: free fall, p(t) = p − t ŷ, until it meets a disc
//!   (t = p_y − c_y − √(d² − h²), h = |p_x − c_x| < d) or the floor (p_y = a). The
//!   walls are parallel to the path.
//! * |B| = 1: rolls on disc j (μⱼ = nⱼy > 0) down the circle of radius dⱼ about cⱼ,
//!   p(φ) = cⱼ + dⱼ (cos φ e₁ + sin φ e₂), e₁ = nⱼ at the start and e₂ ⊥ e₁ pointing
//!   downhill, until the equator φ_end = atan2(e₁y, −e₂y) (where nⱼy = μⱼ = 0: it
//!   falls off and drops), the floor, a wall, or another disc. A wall carries no
//!   weight (μ = n_y = 0): it only blocks.
//!
//! On the top of a disc (nⱼ = ŷ, v = 0 on one support) the balance is unstable: the
//! disc leaves along +x̂, or −x̂ if a contact blocks that (reached only by
//! coincidence).
//!
//! Every event along an arc is a root of c₀ + α cos φ + β sin φ, normalised so that
//! the derivative at φ = 0 is the rate of approach per unit path length:
//!
//!   disc k:  (|q|² + dⱼ² − d_k² + 2dⱼ q·(cos φ e₁ + sin φ e₂)) / (2dⱼd_k),  q = cⱼ − c_k
//!   floor:   (cⱼy − a)/dⱼ + cos φ e₁y + sin φ e₂y
//!   walls:   (cⱼx − a)/dⱼ + cos φ e₁x + sin φ e₂x,  (W − a − cⱼx)/dⱼ − cos φ e₁x − sin φ e₂x
//!
//! and is solved in closed form by `ballistic::first_entry` (the entering root
//! φ = ψ + arccos(−c₀/√(α² + β²)), ψ = atan2(β, α)), so positions are exact contact
//! geometry, never small time steps. The tolerances (1e-9 for a force or an
//! approach rate, 1e-12 rad for simultaneous events) are the 3D generator's.
//!
//! A cell grid of width 2 r_max (the 3D generator's `CellGrid`, with the disc's y as
//! its z) makes each query O(1); the free-fall search walks rows down from the top
//! and stops once no lower row can hold a higher contact, so a deposit is O(N).
//!
//! **Filling a box** (`BoxFill`): the paper fills a W × W box until it is full
//! without saying when a disc counts as inside. With `Lid::Top` a disc whose
//! resting top y + a would exceed the box height H is discarded (not placed: later
//! discs may still reach holes below), so every kept disc lies in the box;
//! `Lid::Centre` is the other reading, a disc is kept when its centre rests at or
//! below H. Filling stops after K consecutive discards. A hole still open then is
//! reached only from drop abscissae in some window w, missed K times in a row with
//! probability (1 − w/W)^K: after K = 1000 misses a window of 0.5 % of W remains
//! open with probability below e⁻⁵. At W = 80R the density is the same to 2e-4 for
//! K = 100, 1000 and 10 000 (docs/generation.md); the verification case uses 1000.

use super::ballistic::{ANGLE_TOL, SIMULTANEOUS, TOL, first_entry};
use super::distribution::{SizeDistribution, each_positive_finite};
use super::grid::CellGrid;
use crate::particles::Vec3;
use crate::quasistatic::{CylinderPacking, Vec2};
use crate::space::Space;
use rand::RngExt;
use rand_chacha::ChaCha8Rng;

/// A disc needing more path segments than this is stuck in a numerical cycle;
/// typical counts are below 10.
const MAX_SEGMENTS: usize = 10_000;

/// Which discs count as inside the box of height H (see the module header).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Lid {
    /// Kept when its top rests at or below H: every disc lies inside the box.
    Top,
    /// Kept when its centre rests at or below H: discs may stand out by up to r.
    Centre,
}

/// A box [0, `width`] × [0, `height`] to fill with discs of radii drawn from `law`
/// until `patience` consecutive discs rest outside the box by the `lid` rule (each
/// of them is discarded).
#[derive(Clone, Debug)]
pub struct BoxFill {
    /// Box width W, m.
    pub width: f64,
    /// Fill height H, m (the lid).
    pub height: f64,
    /// Size law of the disc radii.
    pub law: SizeDistribution,
    /// Which discs count as inside the box of height H.
    pub lid: Lid,
    /// Consecutive discs resting above the lid after which filling stops.
    pub patience: usize,
}

impl BoxFill {
    /// Per disc the radius is drawn first, then the drop abscissa, uniform in
    /// [a, width − a]. Returns the kept discs in deposition order.
    pub fn fill(&self, rng: &mut ChaCha8Rng) -> Result<CylinderPacking, String> {
        let BoxFill {
            width,
            height,
            ref law,
            lid,
            patience,
        } = *self;
        law.validate()?;
        let r_max = law.max_radius();
        if !r_max.is_finite() {
            return Err("the radius law must have a finite largest radius".into());
        }
        check_box(width, r_max)?;
        if !(height.is_finite() && height > 0.0) {
            return Err(format!("height must be positive and finite (got {height})"));
        }
        if patience == 0 {
            return Err("patience must be at least 1".into());
        }
        let mut pile = Pile::new(width, r_max);
        let mut misses = 0;
        while misses < patience {
            let a = law.sample(rng);
            let x = if width - a > a {
                rng.random_range(a..width - a)
            } else {
                a
            };
            let p = pile
                .descend(x, a)
                .map_err(|e| format!("disc {} (radius {a}): {e}", pile.radii.len()))?;
            let kept_below = match lid {
                Lid::Top => p.y + a,
                Lid::Centre => p.y,
            };
            if kept_below <= height {
                pile.place(p, a);
                misses = 0;
            } else {
                misses += 1;
            }
        }
        Ok(CylinderPacking {
            width,
            height,
            centres: pile.centres,
            radii: pile.radii,
        })
    }
}

/// Deposit disc i at drop abscissa `drops[i]` (its centre's x), for i in order, into
/// a box of the given width without a lid: the deterministic core of `BoxFill::fill`,
/// for reproducing or constructing a deposit. Returns the centres.
pub fn deposit_at(radii: &[f64], drops: &[f64], width: f64) -> Result<Vec<Vec2>, String> {
    if drops.len() != radii.len() {
        return Err(format!(
            "need one drop abscissa per radius (got {} and {})",
            drops.len(),
            radii.len()
        ));
    }
    each_positive_finite("radii", radii)?;
    let r_max = radii.iter().copied().fold(0.0, f64::max);
    check_box(width, r_max)?;
    let mut pile = Pile::new(width, r_max);
    for (i, (&a, &x)) in radii.iter().zip(drops).enumerate() {
        if !(x >= a && x <= width - a) {
            return Err(format!(
                "drops[{i}] = {x} must lie in [{a}, {}] (the disc inside the walls)",
                width - a
            ));
        }
        let p = pile
            .descend(x, a)
            .map_err(|e| format!("disc {i} (radius {a}): {e}"))?;
        pile.place(p, a);
    }
    Ok(pile.centres)
}

/// Contacts of the discs with the floor y = 0 and the side walls x = 0, x = width
/// (gap below `gap_tolerance`): (floor, walls). The lid y = height is not a
/// boundary of the deposit and is not counted.
pub fn boundary_contacts(packing: &CylinderPacking, gap_tolerance: f64) -> (usize, usize) {
    let mut floor = 0;
    let mut walls = 0;
    for (c, r) in packing.centres.iter().zip(&packing.radii) {
        if c.y - r <= gap_tolerance {
            floor += 1;
        }
        if c.x - r <= gap_tolerance {
            walls += 1;
        }
        if packing.width - c.x - r <= gap_tolerance {
            walls += 1;
        }
    }
    (floor, walls)
}

fn check_box(width: f64, r_max: f64) -> Result<(), String> {
    if !(width.is_finite() && width > 2.0 * r_max) {
        return Err(format!(
            "width must be finite and exceed the largest diameter {} (got {width})",
            2.0 * r_max
        ));
    }
    Ok(())
}

/// What a disc touches, seen from the moving disc.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Support {
    Disc(usize),
    LeftWall,
    RightWall,
}

enum Outcome {
    Continue(Vec2, Vec<Support>),
    Rest(Vec2),
}

/// The path p(φ) = centre + radius (cos φ e₁ + sin φ e₂), φ ∈ [0, end], rolling on
/// disc `support`.
struct Arc {
    support: usize,
    centre: Vec2,
    radius: f64,
    e1: Vec2,
    e2: Vec2,
    end: f64,
}

impl Arc {
    fn at(&self, phi: f64) -> Vec2 {
        self.centre + (self.e1 * phi.cos() + self.e2 * phi.sin()) * self.radius
    }
}

/// The grid's key for a disc centre: its height is the grid's z.
fn key(p: &Vec2) -> Vec3 {
    Vec3::new(p.x, 0.0, p.y)
}

struct Pile {
    width: f64,
    r_max: f64,
    grid: CellGrid,
    centres: Vec<Vec2>,
    radii: Vec<f64>,
    /// Highest centre placed (the floor before the first).
    top_y: f64,
    scratch: Vec<usize>,
}

impl Pile {
    fn new(width: f64, r_max: f64) -> Self {
        Pile {
            width,
            r_max,
            grid: CellGrid::new(&Space::open(), 2.0 * r_max, 0.0),
            centres: Vec::new(),
            radii: Vec::new(),
            top_y: 0.0,
            scratch: Vec::new(),
        }
    }

    fn place(&mut self, p: Vec2, a: f64) {
        let id = self.centres.len();
        self.grid.insert(&key(&p), id);
        self.top_y = self.top_y.max(p.y);
        self.centres.push(p);
        self.radii.push(a);
    }

    fn normal(&self, p: &Vec2, support: Support, a: f64) -> Vec2 {
        match support {
            Support::Disc(id) => (p - self.centres[id]) / (a + self.radii[id]),
            Support::LeftWall => Vec2::x(),
            Support::RightWall => -Vec2::x(),
        }
    }

    /// The rest position of a disc of radius `a` dropped at abscissa `x` (not placed).
    fn descend(&mut self, x: f64, a: f64) -> Result<Vec2, String> {
        // Start above every placed disc so the fall meets the pile from above.
        let mut p = Vec2::new(x, self.top_y + a + 2.0 * self.r_max);
        let mut touching: Vec<Support> = Vec::new();
        for _ in 0..MAX_SEGMENTS {
            let normals: Vec<Vec2> = touching.iter().map(|s| self.normal(&p, *s, a)).collect();
            let Some((active, v)) = descent_direction(&p, &normals)? else {
                return Ok(p);
            };
            let outcome = match active {
                None => self.fall(p, a),
                Some(j) => match touching[j] {
                    Support::Disc(id) => self.roll(p, a, id, v),
                    _ => unreachable!("a wall carries no weight"),
                },
            };
            match outcome {
                Outcome::Rest(q) => return Ok(q),
                Outcome::Continue(q, t) => {
                    p = q;
                    touching = t;
                }
            }
        }
        Err(format!(
            "no rest after {MAX_SEGMENTS} path segments (numerical cycle) near {p:?}"
        ))
    }

    /// Vertical fall: the highest contact below p, searched row by row downward.
    fn fall(&mut self, p: Vec2, a: f64) -> Outcome {
        let floor_y = a;
        let reach_max = a + self.r_max;
        let mut best = floor_y;
        let mut hits: Vec<(usize, f64)> = Vec::new();
        // Centres lie at or below top_y: rows above its own are empty.
        let mut row = self.grid.layer_of(p.y.min(self.top_y));
        let mut ids = std::mem::take(&mut self.scratch);
        while row >= 0 {
            // Centres in this row lie below its top edge, so no contact from here or
            // below can be higher than that edge + the largest contact distance.
            if self.grid.layer_bottom(row + 1) + reach_max < best {
                break;
            }
            self.grid.column_layer(&key(&p), reach_max, row, &mut ids);
            for &id in &ids {
                let c = self.centres[id];
                let reach = a + self.radii[id];
                let s2 = reach * reach - (p.x - c.x).powi(2);
                if s2 <= 0.0 {
                    continue;
                }
                let s = s2.sqrt();
                // s/d = n_y at the meeting point, the approach rate: a grazing touch
                // at the equator is no contact.
                if s <= TOL * reach {
                    continue;
                }
                let y_hit = c.y + s;
                // Met above p only by rounding, when already touching: count it as
                // met now (the same 1e-9, relative to the contact distance).
                if y_hit > p.y + ANGLE_TOL * reach {
                    continue;
                }
                hits.push((id, y_hit));
                best = best.max(y_hit);
            }
            row -= 1;
        }
        self.scratch = ids;
        let tie = SIMULTANEOUS * a;
        if best - floor_y <= tie {
            return Outcome::Rest(Vec2::new(p.x, floor_y));
        }
        let mut touching: Vec<usize> = hits
            .iter()
            .filter(|(_, y)| *y >= best - tie)
            .map(|(id, _)| *id)
            .collect();
        touching.sort_unstable();
        touching.dedup();
        Outcome::Continue(
            Vec2::new(p.x, best.min(p.y)),
            touching.into_iter().map(Support::Disc).collect(),
        )
    }

    /// Rolling on disc `support` in the direction `v`.
    fn roll(&mut self, p: Vec2, a: f64, support: usize, v: Vec2) -> Outcome {
        let centre = self.centres[support];
        let e1 = (p - centre).normalize();
        let mut e2 = Vec2::new(e1.y, -e1.x);
        if e2.dot(&v) < 0.0 {
            e2 = -e2;
        }
        let arc = Arc {
            support,
            centre,
            radius: a + self.radii[support],
            e1,
            e2,
            end: e1.y.atan2(-e2.y).max(0.0),
        };
        self.follow(&arc, a)
    }

    /// Move along `arc` to its first event: a new disc contact, a wall, the floor,
    /// or the equator of the supporting disc (the end of the arc).
    fn follow(&mut self, arc: &Arc, a: f64) -> Outcome {
        let (c, d, e1, e2) = (arc.centre, arc.radius, arc.e1, arc.e2);
        let floor_phi = first_entry((c.y - a) / d, e1.y, e2.y, arc.end);
        let walls = [
            (
                Support::LeftWall,
                first_entry((c.x - a) / d, e1.x, e2.x, arc.end),
            ),
            (
                Support::RightWall,
                first_entry((self.width - a - c.x) / d, -e1.x, -e2.x, arc.end),
            ),
        ];
        let mut first = arc.end;
        for phi in std::iter::once(floor_phi)
            .chain(walls.iter().map(|w| w.1))
            .flatten()
        {
            first = first.min(phi);
        }
        let mut new_contacts: Vec<(usize, f64)> = Vec::new();
        let mut ids = std::mem::take(&mut self.scratch);
        self.grid.near(&key(&c), d + a + self.r_max, &mut ids);
        for &id in &ids {
            if id == arc.support {
                continue;
            }
            let reach = a + self.radii[id];
            let q = c - self.centres[id];
            if q.norm_squared() > (d + reach) * (d + reach) {
                continue; // out of reach from anywhere on the circle
            }
            // (|q + d ê(φ)|² − reach²) / (2 d reach): f'(0) = n·e₂, the approach rate.
            let scale = 2.0 * d * reach;
            let c0 = (q.norm_squared() + d * d - reach * reach) / scale;
            let ca = 2.0 * d * q.dot(&e1) / scale;
            let cb = 2.0 * d * q.dot(&e2) / scale;
            if let Some(phi) = first_entry(c0, ca, cb, arc.end) {
                new_contacts.push((id, phi));
                first = first.min(phi);
            }
        }
        self.scratch = ids;

        let p = arc.at(first);
        let now = |phi: &Option<f64>| phi.is_some_and(|phi| phi <= first + SIMULTANEOUS);
        if now(&floor_phi) {
            return Outcome::Rest(Vec2::new(p.x, a));
        }
        // The support stays listed even at the equator, where its force vanished:
        // it still touches, and the next active-set choice lets it go.
        let mut touching = vec![Support::Disc(arc.support)];
        let mut met: Vec<usize> = new_contacts
            .iter()
            .filter(|(_, phi)| *phi <= first + SIMULTANEOUS)
            .map(|(id, _)| *id)
            .collect();
        met.sort_unstable();
        met.dedup();
        touching.extend(met.into_iter().map(Support::Disc));
        touching.extend(walls.iter().filter(|w| now(&w.1)).map(|w| w.0));
        Outcome::Continue(p, touching)
    }
}

/// The projection of g = −ŷ onto the tangent cone at p: `None` when it vanishes (a
/// rest), else the loaded contact (an index into `normals`, `None` in free fall) and
/// the unit direction of motion.
fn descent_direction(p: &Vec2, normals: &[Vec2]) -> Result<Option<(Option<usize>, Vec2)>, String> {
    // Rest: ŷ in the closed cone of two normals. Accepting the edge (μ ≥ −TOL)
    // settles the marginal case where one support carries no load.
    for (j, nj) in normals.iter().enumerate() {
        for nk in &normals[j + 1..] {
            let det = nj.x * nk.y - nk.x * nj.y;
            // Parallel normals (opposite contacts at the same height) leave the
            // forces undetermined and hold no weight.
            if det.abs() < 1e-12 {
                continue;
            }
            let (mu_j, mu_k) = (-nk.x / det, nj.x / det);
            if mu_j >= -TOL && mu_k >= -TOL {
                return Ok(None);
            }
        }
    }
    let g = -Vec2::y();
    // The same rate threshold as the event search, so a contact accepted here as
    // leaving is not reported there as entering at φ = 0.
    let free = |dir: &Vec2, skip: Option<usize>| {
        normals
            .iter()
            .enumerate()
            .all(|(i, m)| Some(i) == skip || dir.dot(m) >= -TOL)
    };
    if free(&g, None) {
        return Ok(Some((None, g)));
    }
    for (j, nj) in normals.iter().enumerate() {
        let mu = nj.y;
        if mu <= TOL {
            continue;
        }
        let v = g + nj * mu;
        let speed = v.norm();
        let directions = if speed > TOL {
            vec![v / speed]
        } else {
            // Balanced on the top of a disc: leave along a free horizontal.
            vec![Vec2::x(), -Vec2::x()]
        };
        if let Some(dir) = directions.into_iter().find(|d| free(d, Some(j))) {
            return Ok(Some((Some(j), dir)));
        }
    }
    Err(format!(
        "no consistent supporting contact among normals {normals:?} at {p:?}"
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;

    fn close(a: &Vec2, b: &Vec2, tol: f64) -> bool {
        (a - b).norm() < tol
    }

    #[test]
    fn lone_disc_falls_to_the_floor() {
        let p = deposit_at(&[0.3], &[1.0], 4.0).unwrap();
        assert_eq!(p[0], Vec2::new(1.0, 0.3));
    }

    #[test]
    fn rests_in_the_groove_of_two_floor_discs() {
        // Unit discs on the floor at x = 1 and 3.5 (gap 0.5). A unit disc dropped at
        // x = 2.9 lands on the right one, rolls left into the groove and rests where
        // it touches both: x = 2.25, y = 1 + √(2² − 1.25²).
        let p = deposit_at(&[1.0; 3], &[1.0, 3.5, 2.9], 10.0).unwrap();
        let expect = Vec2::new(2.25, 1.0 + (4.0f64 - 1.5625).sqrt());
        assert!(close(&p[2], &expect, 1e-12), "{:?}", p[2]);
    }

    #[test]
    fn small_disc_rolls_off_at_the_equator_and_drops() {
        // r = 0.5 dropped at 5.2 on a unit disc at (5, 1): rolls right on the circle
        // of radius 1.5 to its equator (6.5, 1), leaves it and falls to the floor.
        let p = deposit_at(&[1.0, 0.5], &[5.0, 5.2], 10.0).unwrap();
        assert!(close(&p[1], &Vec2::new(6.5, 0.5), 1e-12), "{:?}", p[1]);
    }

    #[test]
    fn large_disc_rolling_off_a_small_one_meets_the_floor_first() {
        // r = 1 on r = 0.5 at (5, 0.5): the circle of radius 1.5 reaches y = 1 where
        // sin θ = 1/3, at x = 5 + 1.5 cos θ = 5 + √2.
        let p = deposit_at(&[0.5, 1.0], &[5.0, 4.8], 10.0).unwrap();
        assert!(
            close(&p[1], &Vec2::new(5.0 - 2f64.sqrt(), 1.0), 1e-12),
            "{:?}",
            p[1]
        );
    }

    #[test]
    fn wall_blocks_the_roll() {
        // A unit disc on the floor at x = 1.5 leaves a gap of 0.5 to the left wall.
        // A unit disc dropped at 1.2 rolls left until it meets the wall at x = 1:
        // y = 1 + √(2² − 0.5²); it rests on the wall and the disc.
        let p = deposit_at(&[1.0, 1.0], &[1.5, 1.2], 10.0).unwrap();
        let expect = Vec2::new(1.0, 1.0 + 3.75f64.sqrt());
        assert!(close(&p[1], &expect, 1e-12), "{:?}", p[1]);
        // The mirror image at the right wall.
        let p = deposit_at(&[1.0, 1.0], &[8.5, 8.8], 10.0).unwrap();
        assert!(close(&p[1], &Vec2::new(9.0, expect.y), 1e-12), "{:?}", p[1]);
    }

    #[test]
    fn rolls_from_one_disc_onto_a_lower_one() {
        // A unit disc at (2, 1) on the floor and a small one (r = 0.5) at (4.5, 0.5)
        // beside it, out of touch. A unit disc dropped at 2.4 rolls right on the first, meets
        // the small one before the equator, and rests on both (they straddle it).
        let p = deposit_at(&[1.0, 0.5, 1.0], &[2.0, 4.5, 2.4], 10.0).unwrap();
        let (c1, c2) = (Vec2::new(2.0, 1.0), Vec2::new(4.5, 0.5));
        assert!(((p[2] - c1).norm() - 2.0).abs() < 1e-12);
        assert!(((p[2] - c2).norm() - 1.5).abs() < 1e-12);
        assert!(p[2].x > c1.x && p[2].x < c2.x, "{:?}", p[2]);
    }

    /// Overlaps (discs and walls) beyond 1e-9 of the contact distance, and discs off
    /// the floor that no two earlier contacts (discs or walls) hold.
    fn check_packing(p: &CylinderPacking) {
        let tol = 1e-9;
        let n = p.len();
        for i in 0..n {
            let (c, r) = (p.centres[i], p.radii[i]);
            assert!(
                c.x - r > -tol * r && p.width - c.x - r > -tol * r,
                "disc {i} in a wall"
            );
            assert!(c.y - r > -tol * r, "disc {i} in the floor");
            if c.y - r <= tol * r {
                continue;
            }
            let mut normals = Vec::new();
            for j in 0..n {
                if j == i {
                    continue;
                }
                let d = r + p.radii[j];
                let gap = (c - p.centres[j]).norm() - d;
                assert!(gap > -tol * d, "discs {i} and {j} overlap by {gap}");
                if j < i && gap <= tol * d {
                    normals.push((c - p.centres[j]) / d);
                }
            }
            if c.x - r <= tol * r {
                normals.push(Vec2::x());
            }
            if p.width - c.x - r <= tol * r {
                normals.push(-Vec2::x());
            }
            assert_eq!(
                descent_direction(&c, &normals).unwrap(),
                None,
                "disc {i} at {c:?} is not at rest on its earlier contacts"
            );
        }
    }

    fn poly() -> SizeDistribution {
        SizeDistribution::Uniform { min: 0.9, max: 1.1 }
    }

    fn fill_box(
        width: f64,
        height: f64,
        law: &SizeDistribution,
        patience: usize,
        rng: &mut ChaCha8Rng,
    ) -> Result<CylinderPacking, String> {
        let fill = BoxFill {
            width,
            height,
            law: law.clone(),
            lid: Lid::Top,
            patience,
        };
        fill.fill(rng)
    }

    #[test]
    fn filled_boxes_are_overlap_free_stable_and_full() {
        for (law, seed) in [(SizeDistribution::Mono { radius: 1.0 }, 3), (poly(), 4)] {
            let mut rng = ChaCha8Rng::seed_from_u64(seed);
            let p = fill_box(30.0, 30.0, &law, 200, &mut rng).unwrap();
            check_packing(&p);
            assert!(p.centres.iter().zip(&p.radii).all(|(c, r)| c.y + r <= 30.0));
            assert!(p.density() > 0.7, "{}", p.density());
        }
    }

    #[test]
    fn same_seed_same_packing() {
        let fill = |seed| {
            let mut rng = ChaCha8Rng::seed_from_u64(seed);
            fill_box(20.0, 20.0, &poly(), 100, &mut rng).unwrap()
        };
        assert_eq!(fill(7), fill(7));
        assert_ne!(fill(7), fill(8));
    }

    #[test]
    fn full_size_deposit_is_fast_and_overlap_free() {
        // The paper's box, W = 80R: ~1650 discs in well under a second.
        let started = std::time::Instant::now();
        let mut rng = ChaCha8Rng::seed_from_u64(1);
        let p = fill_box(80.0, 80.0, &poly(), 1000, &mut rng).unwrap();
        let elapsed = started.elapsed().as_secs_f64();
        assert!(p.len() > 1500, "{}", p.len());
        // Overlaps through the packing's own pair search (a negative gap is a pair).
        let pairs = p.touching_pairs(1e-9);
        for (i, j) in pairs {
            let gap = (p.centres[i] - p.centres[j]).norm() - p.radii[i] - p.radii[j];
            assert!(gap > -1e-9, "{i} {j} {gap}");
        }
        assert!(elapsed < 5.0, "{elapsed} s");
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(24))]
        #[test]
        fn random_small_boxes_are_overlap_free_and_stable(
            seed in 0u64..1_000_000,
            width in 6.0f64..20.0,
            spread in 0.0f64..0.5,
        ) {
            let law = SizeDistribution::Uniform { min: 1.0 - spread, max: 1.0 + spread };
            let mut rng = ChaCha8Rng::seed_from_u64(seed);
            let p = fill_box(width, 15.0, &law, 50, &mut rng).unwrap();
            check_packing(&p);
        }
    }

    #[test]
    fn rejects_bad_inputs() {
        let mut rng = ChaCha8Rng::seed_from_u64(0);
        let err = fill_box(1.5, 10.0, &poly(), 10, &mut rng).unwrap_err();
        assert!(err.contains("largest diameter"), "{err}");
        let err = fill_box(10.0, 10.0, &poly(), 0, &mut rng).unwrap_err();
        assert!(err.contains("patience"), "{err}");
        let err = deposit_at(&[1.0], &[0.5], 10.0).unwrap_err();
        assert!(err.contains("inside the walls"), "{err}");
        let err = deposit_at(&[1.0, -1.0], &[2.0, 3.0], 10.0).unwrap_err();
        assert!(err.contains("radii[1]"), "{err}");
    }
}
