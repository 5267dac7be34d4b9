//! The quasi-static incremental stiffness solution of Redanz & Fleck (2001) §2.3–2.4:
//! a network of cylinders (nodes with two displacements and a rotation) joined by
//! rigid-plastic contact springs, driven by a prescribed macroscopic strain and kept
//! in static equilibrium at every increment.
//!
//! **Kinematics (eqs 1, 5).** For a contact between cylinders i and j with unit
//! normal n from i to j and tangent t = ẑ × n, the generalised displacement
//! D = (xᵢ, yᵢ, θᵢ, xⱼ, yⱼ, θⱼ) gives
//!
//!   u̇_N = b_N·Ḋ,  b_N = ( n, 0, −n, 0),           (approach, eq 1)
//!   u̇_T = b_T·Ḋ,  b_T = ( t, dᵢ, −t, dⱼ),          (slip of i on j, eq 5)
//!
//! with dᵢ the distance from centre i to the plane of contact.
//!
//! **Forces (eqs 2, 4, 6–9).** F_N from `contact::normal::plastic_cylinder` (eq 2 with
//! elastic unloading, §3.4); F_T = k_T A_c u_T while it sticks (eq 6), capped at
//! μF_N (eq 7) and at τ_y A with τ_y = σ_y/√3 and A = F_N/(3σ_y), which is A_c on
//! loading (eq 2) and shrinks with F_N on unloading (see `evaluate`). The generalised
//! force the contact needs from outside, the force that balances it at the nodes, is
//!
//!   f = F_N b_N + F_T b_T,
//!
//! which contains eqs 4, 8 and the moments of eq 9, M = −d F_T (the contact's own
//! action on the nodes is −f).
//!
//! **Equilibrium (eqs 10–12).** Σ_contacts f = F^applied at every node. Nodes on which
//! eqs 14–15 prescribe the displacement take any applied force; free nodes take none.
//! Each increment ΔE of macroscopic strain moves the prescribed nodes by ΔE·x, then
//!
//! 1. *predicts* the free nodes by the paper's incremental stiffness solution, one
//!    forward Euler step of eq 12, K_ff Ḋ_f = −K_fp Ḋ_p with K = Σ_contacts
//!    (k_N b_N b_Nᵀ + k_T b_T b_Tᵀ) from the committed contacts, solved by a sparse
//!    Cholesky factorisation (`nalgebra-sparse`); a sliding contact adds no
//!    tangential stiffness and a small `regularisation` makes K positive definite
//!    where cylinders are free to move;
//! 2. *corrects* with FIRE relaxation (`Network::relax`) until the free nodes are in
//!    static equilibrium with the forces evaluated from the total overlaps and slips,
//!    so the curve does not drift with the increment size.
//!
//! Why both: the paper's forward Euler alone accumulates the out-of-balance force of
//! every contact that opens, forms or starts to slide, and Newton iteration on K
//! alone cannot cross the rearrangement of a loose deposit (K is singular there: a
//! frictionless deposit with Z ≈ 3.9 < 4 is a mechanism; Levenberg–Marquardt found no
//! equilibrium at the first increment). FIRE alone converges but several times more
//! slowly than with the predictor (docs/verification-notes.md has both measurements). Equilibrium is declared when the mean unbalanced
//! force on the free cylinders is below `tolerance` × the mean contact force
//! (Yade's `unbalancedForce`); docs/verification-notes.md gives what the tolerance
//! costs and changes.
//!
//! **Macroscopic stress (eq 13).** Σ_ij = (1/V) Σ_p F^applied_{p,i} x_{p,j}, summed over
//! the prescribed nodes (free nodes carry no applied force), V the current box area.

use super::affine_yield::Sym2;
use super::packing::{CylinderPacking, Vec2, touching_pairs};
use crate::contact::normal::plastic_cylinder;
use crate::error::{Result, TampError};
use nalgebra::DVector;
use nalgebra_sparse::{CooMatrix, CscMatrix, factorization::CscCholesky};
use serde::Serialize;
use std::collections::BTreeMap;

/// The inter-particle friction law (§2.1.2).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub enum Friction {
    /// μ = 0: contacts carry no shear force.
    Frictionless,
    /// Coulomb coefficient μ, with the shear traction also capped at τ_y.
    Coulomb(f64),
    /// μ = ∞: only the τ_y cap limits the shear force.
    Sticking,
}

/// Which cylinders follow the macroscopic strain (§2.4).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum Constraint {
    /// The peripheral layer only ("die compaction" in the paper's words).
    Die,
    /// Every cylinder (affine motion).
    Affine,
}

/// The parameters of a network solve: the contact laws' constants (σ_y, friction,
/// unloading and tangential stiffness), which cylinders are prescribed, and the
/// tolerances of the FIRE corrector and the sparse predictor.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct NetworkSettings {
    /// σ_y.
    pub yield_stress: f64,
    /// The inter-particle friction law (§2.1.2).
    pub friction: Friction,
    /// Whether interior cylinders may rotate (peripheral ones never do).
    pub rotation: bool,
    /// Which cylinders follow the macroscopic strain (§2.4).
    pub constraint: Constraint,
    /// Unloading/reloading stiffness over loading stiffness (10³ in §3.4).
    pub unloading_factor: f64,
    /// k_T of eq 6: shear traction per unit slip (stress/length).
    pub tangential_stiffness: f64,
    /// The loading tangent is evaluated at no less than this overlap (it is infinite
    /// at first touch).
    pub stiffness_floor_overlap: f64,
    /// Static equilibrium: the mean unbalanced force on the free cylinders over the
    /// mean contact force (Yade's `unbalancedForce`) is at most this.
    pub tolerance: f64,
    /// The mean contact force used in `tolerance` is at least this, so a network that
    /// has unloaded completely (all forces → 0 while it rearranges) still converges;
    /// below it the tolerance is absolute. The floor sits a few per cent below the mean
    /// contact force at D = 0.85, high enough that the nearly unloaded first increments
    /// of a tall frictionless deposit converge (docs/verification-notes.md gives the
    /// iteration counts that chose it).
    pub force_floor: f64,
    /// FIRE iterations allowed in one increment.
    pub max_iterations: usize,
    /// What happens when they run out: false, the increment fails; true, it is
    /// committed out of balance, says so in its report (`converged`), and the next
    /// increment starts from there. For a loose deposit whose collapse at near-zero
    /// stress does not settle (W = 80R, docs/verification-notes.md); a caller that
    /// sets it must check the increments it draws conclusions from.
    pub carry_over: bool,
    /// Largest move of a cylinder in one iteration (or in the predictor step).
    pub max_step: f64,
    /// Pairs within this gap are candidates for contact (`CandidatePairs`).
    pub skin: f64,
    /// The predictor solves (K + λ(diag K + σ_y)) Δ = −r with this λ: it makes K
    /// positive definite where cylinders are free to move.
    pub regularisation: f64,
}

impl NetworkSettings {
    /// The paper's settings for cylinders of radius ~R with yield stress σ_y.
    pub fn redanz_fleck(
        yield_stress: f64,
        radius: f64,
        friction: Friction,
        rotation: bool,
        constraint: Constraint,
    ) -> Self {
        NetworkSettings {
            yield_stress,
            friction,
            rotation,
            constraint,
            unloading_factor: 1e3,
            tangential_stiffness: 1e3 * yield_stress / radius,
            stiffness_floor_overlap: 1e-6 * radius,
            tolerance: 1e-2,
            force_floor: 1e-2 * yield_stress * radius,
            max_iterations: 1_000_000,
            carry_over: false,
            max_step: 0.05 * radius,
            skin: 0.2 * radius,
            regularisation: 1e-8,
        }
    }

    /// `tolerance` and `max_iterations` for a box `height` tall: the tolerance as set
    /// (10⁻² from `redanz_fleck`) holds at height 20R and shrinks as 20R / height in
    /// taller boxes; the cap is 200 000 (3× the most a W = 20R increment takes) times
    /// height / 20R. Tolerance: eq 13's stress and the stress from
    /// the contact forces differ by the moment of the unbalanced forces about the box
    /// centre, at most about tolerance × (free cylinders / contacts) × (height / R):
    /// 0.05 at 20R, and 0.34 at 80R with the same tolerance. The unbalanced forces
    /// share a sign (FIRE stops while the interior still lags the boundary), so the
    /// gap approaches the bound (docs/verification-notes.md); the tolerance shrinks as
    /// R / height to cancel the height factor (0.085 at 80R, where more cylinders
    /// are free). Iterations: FIRE's slowest modes span the box, and their period in
    /// iterations grows with its height (docs/verification-notes.md).
    pub fn scaled_to_box(mut self, height: f64, radius: f64) -> Self {
        let taller = (height / (20.0 * radius)).max(1.0);
        self.tolerance /= taller;
        self.max_iterations = (200_000.0 * taller).round() as usize;
        self
    }
}

/// What a contact remembers between increments.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct ContactHistory {
    max_overlap: f64,
    /// F_T in the contact frame (positive opposes positive slip u_T of i on j).
    tangential_force: f64,
}

/// A force-carrying contact, as `Network::contact_forces` reports it.
#[derive(Clone, Copy, Debug)]
pub struct ContactForce {
    /// n, from i to j.
    pub normal: Vec2,
    /// l = xⱼ − xᵢ.
    pub branch: Vec2,
    /// F_N.
    pub normal_force: f64,
    /// The largest overlap u_N the contact has reached: where its loading branch
    /// (eq 2) resumes.
    pub max_overlap: f64,
    /// R₁R₂/(R₁ + R₂).
    pub effective_radius: f64,
}

/// A contact evaluated at trial positions.
#[derive(Clone, Copy, Debug)]
struct ContactState {
    i: usize,
    j: usize,
    normal: Vec2,
    d_i: f64,
    d_j: f64,
    normal_force: f64,
    normal_stiffness: f64,
    tangential_force: f64,
    tangential_stiffness: f64,
    max_overlap: f64,
    /// The stiffest normal branch this contact can take this increment, FIRE's
    /// inertia (`Network::inertia`).
    inertia_stiffness: f64,
    /// The same for the tangential spring: k_T A_c whether it sticks or slides.
    inertia_tangential: f64,
    sliding: bool,
}

impl ContactState {
    /// b_N, b_T of eqs 1 and 5 and the free-DOF numbers of (xᵢ, yᵢ, θᵢ, xⱼ, yⱼ, θⱼ)
    /// (`usize::MAX` where prescribed).
    fn rows(&self, dof: &[[usize; 3]]) -> ([f64; 6], [f64; 6], [usize; 6]) {
        let (n, t) = (self.normal, tangent(self.normal));
        let (a, b) = (dof[self.i], dof[self.j]);
        (
            [n.x, n.y, 0.0, -n.x, -n.y, 0.0],
            [t.x, t.y, self.d_i, -t.x, -t.y, self.d_j],
            [a[0], a[1], a[2], b[0], b[1], b[2]],
        )
    }
}

struct Trial {
    contacts: Vec<ContactState>,
    residual: DVector<f64>,
    worst_node: usize,
    /// Mean over free nodes of the unbalanced force (moments as rim forces).
    mean_unbalanced: f64,
    scale: f64,
}

/// Convergence record of one increment.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct IncrementReport {
    /// FIRE iterations the corrector took.
    pub iterations: usize,
    /// Mean unbalanced force on the free nodes over the mean contact force.
    pub residual: f64,
    /// Whether the residual reached the tolerance (see `carry_over`).
    pub converged: bool,
    /// How far the contacts' relative motion strayed from affine motion (§3.3).
    pub deviation: AffineDeviation,
}

/// How far the relative motion at the contacts strayed from affine motion in one
/// increment (Redanz & Fleck 2001 §3.3, Figs 7–8), over the contacts that carried
/// force at its start: with u̇_N, u̇_T the network's relative normal approach and
/// slip (eqs 1, 5) and u̇_N^A = −n·ΔE·l, u̇_T^A = −t·ΔE·l their affine values
/// (l = xⱼ − xᵢ, no rotation),
///
///   normal = ⟨|u̇_N − u̇_N^A|⟩ / ⟨|u̇_N^A|⟩,  tangential = ⟨|u̇_T − u̇_T^A|⟩ / ⟨|u̇_N^A|⟩,
///   affine_tangential = ⟨|u̇_T^A|⟩ / ⟨|u̇_N^A|⟩.
///
/// The paper normalises by ⟨u̇_N^A⟩ for the tangential measure; for the normal one
/// its words ("each normalised by u_N^A") would divide contact by contact, which
/// diverges for contacts normal to a closed die's compression (u̇_N^A = 0), so the
/// same ratio of ensemble means is used.
#[derive(Clone, Copy, Debug, Default, Serialize)]
pub struct AffineDeviation {
    /// ⟨|u̇_N − u̇_N^A|⟩ / ⟨|u̇_N^A|⟩: the normal approach's departure from affine motion.
    pub normal: f64,
    /// ⟨|u̇_T − u̇_T^A|⟩ / ⟨|u̇_N^A|⟩: the slip's departure from affine motion.
    pub tangential: f64,
    /// ⟨|u̇_T^A|⟩ / ⟨|u̇_N^A|⟩: the slip affine motion alone would give.
    pub affine_tangential: f64,
}

/// The contact network of Redanz & Fleck (2001) §2.3–2.4: cylinders with two
/// displacements and a rotation each, their contacts' loading histories, and the box
/// the macroscopic strain deforms.
#[derive(Clone)]
pub struct Network {
    /// Cylinder radii.
    pub radii: Vec<f64>,
    /// Cylinder centres in the current box.
    pub centres: Vec<Vec2>,
    /// Rotation θ of each cylinder since the start, rad.
    pub rotations: Vec<f64>,
    /// Peripheral layer: prescribed in both modes, never rotates.
    pub peripheral: Vec<bool>,
    /// Current box [0, width] × [0, height] (deformed with the macroscopic strain).
    pub width: f64,
    /// Current box width along x₁.
    pub height: f64,
    /// Current box height along x₂.
    pub settings: NetworkSettings,
    history: BTreeMap<(usize, usize), ContactHistory>,
    /// Contacts at the last committed state.
    contacts: Vec<ContactState>,
    solid_area: f64,
}

impl Network {
    /// The network of `packing` at rest: no rotations, the peripheral layer marked, and
    /// the contacts of the pairs already touching, with no loading history.
    pub fn new(packing: &CylinderPacking, settings: NetworkSettings) -> Self {
        let peripheral = peripheral_layer(packing);
        let mut net = Network {
            radii: packing.radii.clone(),
            centres: packing.centres.clone(),
            rotations: vec![0.0; packing.len()],
            peripheral,
            width: packing.width,
            height: packing.height,
            settings,
            history: BTreeMap::new(),
            contacts: Vec::new(),
            solid_area: packing.solid_area(),
        };
        let pairs = touching_pairs(&net.centres, &net.radii, 0.0);
        let histories = vec![ContactHistory::default(); pairs.len()];
        net.contacts = net.evaluate(&net.centres, &net.rotations, &pairs, &histories);
        net
    }

    /// Number of cylinders.
    pub fn len(&self) -> usize {
        self.radii.len()
    }

    /// Whether the network has no cylinders.
    pub fn is_empty(&self) -> bool {
        self.radii.is_empty()
    }

    /// Current box area, per unit depth.
    pub fn area(&self) -> f64 {
        self.width * self.height
    }

    /// Relative density D: cylinder area over box area.
    pub fn density(&self) -> f64 {
        self.solid_area / self.area()
    }

    /// Z: twice the contacts carrying force over the number of cylinders.
    pub fn coordination(&self) -> f64 {
        let n = self
            .contacts
            .iter()
            .filter(|c| c.normal_force > 0.0)
            .count();
        2.0 * n as f64 / self.len() as f64
    }

    /// Whether node p's translation is prescribed.
    fn prescribed(&self, p: usize) -> bool {
        self.settings.constraint == Constraint::Affine || self.peripheral[p]
    }

    fn rotation_free(&self, p: usize) -> bool {
        self.settings.rotation
            && self.settings.friction != Friction::Frictionless
            && !self.peripheral[p]
    }

    /// The generalised forces f = F_N b_N + F_T b_T summed per node: (fx, fy, m).
    fn nodal_forces(&self, contacts: &[ContactState]) -> Vec<[f64; 3]> {
        let mut f = vec![[0.0; 3]; self.len()];
        for c in contacts {
            let t = tangent(c.normal);
            let v = c.normal * c.normal_force + t * c.tangential_force;
            f[c.i][0] += v.x;
            f[c.i][1] += v.y;
            f[c.i][2] += c.d_i * c.tangential_force;
            f[c.j][0] -= v.x;
            f[c.j][1] -= v.y;
            f[c.j][2] += c.d_j * c.tangential_force;
        }
        f
    }

    /// Eq 13 over the prescribed nodes.
    pub fn stress(&self) -> Sym2 {
        let f = self.nodal_forces(&self.contacts);
        let mut s = Sym2::new(0.0, 0.0, 0.0);
        for (p, (fp, x)) in f.iter().zip(&self.centres).enumerate() {
            if !self.prescribed(p) {
                continue;
            }
            s.xx += fp[0] * x.x;
            s.yy += fp[1] * x.y;
            s.xy += 0.5 * (fp[0] * x.y + fp[1] * x.x);
        }
        let v = self.area();
        Sym2::new(s.xx / v, s.yy / v, s.xy / v)
    }

    /// The same stress from the contacts, −(1/V) Σ_c f_c ⊗ l_c with l_c = xⱼ − xᵢ:
    /// equal to eq 13 when the free nodes are in equilibrium (a check, not a second
    /// definition).
    pub fn stress_from_contacts(&self) -> Sym2 {
        let mut s = Sym2::new(0.0, 0.0, 0.0);
        for c in &self.contacts {
            let l = self.centres[c.j] - self.centres[c.i];
            let f = c.normal * c.normal_force + tangent(c.normal) * c.tangential_force;
            s.xx -= f.x * l.x;
            s.yy -= f.y * l.y;
            s.xy -= 0.5 * (f.x * l.y + f.y * l.x);
        }
        let v = self.area();
        Sym2::new(s.xx / v, s.yy / v, s.xy / v)
    }

    /// Contact forces, stiffnesses and histories at trial positions and rotations,
    /// from the committed histories (`histories[k]` that of `pairs[k]`, looked up once
    /// per candidate list rather than once per FIRE iteration).
    fn evaluate(
        &self,
        centres: &[Vec2],
        rotations: &[f64],
        pairs: &[(usize, usize)],
        histories: &[ContactHistory],
    ) -> Vec<ContactState> {
        let s = &self.settings;
        let mut out = Vec::with_capacity(pairs.len());
        for (&(i, j), &h) in pairs.iter().zip(histories) {
            let (ri, rj) = (self.radii[i], self.radii[j]);
            let l = centres[j] - centres[i];
            // Most candidates are apart: skip the square root where that is certain
            // (the margin covers rounding; the exact test follows).
            let squared = l.norm_squared();
            if squared > (ri + rj) * (ri + rj) * (1.0 + 1e-12) {
                continue;
            }
            let dist = l.norm();
            if dist >= ri + rj {
                continue;
            }
            let normal = l / dist;
            let overlap = ri + rj - dist;
            let r_star = ri * rj / (ri + rj);
            // Distances from the centres to the chord of the two circles.
            let d_i = (dist * dist + ri * ri - rj * rj) / (2.0 * dist);
            let d_j = dist - d_i;
            let n = plastic_cylinder::response(
                overlap,
                h.max_overlap,
                r_star,
                s.yield_stress,
                s.unloading_factor,
                s.stiffness_floor_overlap,
            );
            let width = plastic_cylinder::contact_width(n.max_overlap, r_star);
            let (mut tangential_force, mut tangential_stiffness, mut sliding) = (0.0, 0.0, false);
            let mut inertia_tangential = 0.0;
            if s.friction != Friction::Frictionless && n.force > 0.0 {
                // Slip of i on j since the committed state (eq 5, secant normal).
                let committed = (self.centres[i], self.centres[j]);
                let t = tangent(normal);
                let slip = ((centres[i] - committed.0) - (centres[j] - committed.1)).dot(&t)
                    + d_i * (rotations[i] - self.rotations[i])
                    + d_j * (rotations[j] - self.rotations[j]);
                let k = s.tangential_stiffness * width;
                inertia_tangential = k;
                let trial = h.tangential_force + k * slip;
                // τ_y over the area that carries F_N at the mean pressure 3σ_y of eq 2:
                // on loading that is A_c itself (the paper's effective friction
                // coefficient 1/(3√3), §3.1); on unloading it shrinks with F_N, so the
                // cap vanishes as the contact opens instead of jumping from τ_y A_c to
                // zero (that jump kept a sticking contact flickering: FIRE cycled
                // without converging).
                let shear_cap = n.force / 3.0 / 3f64.sqrt();
                let cap = match s.friction {
                    Friction::Coulomb(mu) => (mu * n.force).min(shear_cap),
                    _ => shear_cap,
                };
                if trial.abs() > cap {
                    tangential_force = cap * trial.signum();
                    sliding = true;
                } else {
                    tangential_force = trial;
                    tangential_stiffness = k;
                }
            }
            // On the loading branch K uses the secant F/u = 2 dF/du: Newton with the
            // tangent of a √u law overshoots to separation whenever it starts from more
            // than 4× the equilibrium overlap, the secant never does.
            let normal_stiffness = if overlap >= h.max_overlap {
                n.force / overlap.max(s.stiffness_floor_overlap)
            } else {
                n.stiffness
            };
            // The unloading stiffness at u_max (§3.4): `response` has it as its
            // stiffness on the unloading branch, and the loading tangent it returns on
            // the loading branch is the same expression at u_max = u_N.
            let unloading = if overlap >= h.max_overlap {
                s.unloading_factor * n.stiffness
            } else if n.force > 0.0 {
                n.stiffness
            } else {
                s.unloading_factor
                    * plastic_cylinder::loading_stiffness(
                        n.max_overlap.max(s.stiffness_floor_overlap),
                        r_star,
                        s.yield_stress,
                    )
            };
            out.push(ContactState {
                i,
                j,
                normal,
                d_i,
                d_j,
                normal_force: n.force,
                normal_stiffness,
                inertia_stiffness: normal_stiffness.max(unloading),
                inertia_tangential,
                tangential_force,
                tangential_stiffness,
                max_overlap: n.max_overlap,
                sliding,
            });
        }
        out
    }

    /// One increment of macroscopic strain (eqs 14–15).
    pub fn increment(&mut self, de: Sym2) -> Result<IncrementReport> {
        let affine = |x: Vec2| Vec2::new(de.xx * x.x + de.xy * x.y, de.xy * x.x + de.yy * x.y);
        let mut centres: Vec<Vec2> = self.centres.iter().map(|&x| x + affine(x)).collect();
        let mut rotations = self.rotations.clone();
        let (dof, count) = self.free_dofs();
        let mut report = IncrementReport {
            iterations: 0,
            residual: 0.0,
            converged: false,
            deviation: AffineDeviation::default(),
        };
        let mut pairs =
            CandidatePairs::new(&centres, &self.radii, self.settings.skin, &self.history);
        if count > 0 {
            self.predict(&mut centres, &mut rotations, &dof, count)?;
        }
        let trial = self.relax(
            &mut centres,
            &mut rotations,
            &dof,
            count,
            &mut pairs,
            &mut report,
        )?;
        report.deviation = self.affine_deviation(&centres, &rotations, de);
        self.commit(centres, rotations, trial.contacts, de);
        Ok(report)
    }

    /// §3.3's measures for the step from the committed state to `centres`.
    fn affine_deviation(&self, centres: &[Vec2], rotations: &[f64], de: Sym2) -> AffineDeviation {
        let strain = |l: Vec2| Vec2::new(de.xx * l.x + de.xy * l.y, de.xy * l.x + de.yy * l.y);
        let (mut normal, mut tangential, mut affine_normal, mut affine_tangential) =
            (0.0, 0.0, 0.0, 0.0);
        for c in self.contacts.iter().filter(|c| c.normal_force > 0.0) {
            let (n, t) = (c.normal, tangent(c.normal));
            let l = self.centres[c.j] - self.centres[c.i];
            let relative = (centres[c.i] - self.centres[c.i]) - (centres[c.j] - self.centres[c.j]);
            let u_n = n.dot(&relative);
            let u_t = t.dot(&relative)
                + c.d_i * (rotations[c.i] - self.rotations[c.i])
                + c.d_j * (rotations[c.j] - self.rotations[c.j]);
            let (u_n_a, u_t_a) = (-n.dot(&strain(l)), -t.dot(&strain(l)));
            normal += (u_n - u_n_a).abs();
            tangential += (u_t - u_t_a).abs();
            affine_normal += u_n_a.abs();
            affine_tangential += u_t_a.abs();
        }
        if affine_normal == 0.0 {
            return AffineDeviation::default();
        }
        AffineDeviation {
            normal: normal / affine_normal,
            tangential: tangential / affine_normal,
            affine_tangential: affine_tangential / affine_normal,
        }
    }

    /// Free DOFs (x, y, θ per node, `usize::MAX` where prescribed), numbered bottom to
    /// top so K is banded, and their count.
    fn free_dofs(&self) -> (Vec<[usize; 3]>, usize) {
        let n = self.len();
        let mut order: Vec<usize> = (0..n).collect();
        order.sort_by(|&a, &b| {
            self.centres[a]
                .y
                .total_cmp(&self.centres[b].y)
                .then(self.centres[a].x.total_cmp(&self.centres[b].x))
        });
        let mut dof = vec![[usize::MAX; 3]; n];
        let mut count = 0;
        for &p in &order {
            if !self.prescribed(p) {
                dof[p][0] = count;
                dof[p][1] = count + 1;
                count += 2;
            }
            if self.rotation_free(p) {
                dof[p][2] = count;
                count += 1;
            }
        }
        (dof, count)
    }

    /// The incremental stiffness solution of eqs 11–12, the paper's forward Euler
    /// step, as the predictor: with K assembled from the committed contacts, the free
    /// DOFs move by Δ_f = −K_ff⁻¹ K_fp Δ_p for the prescribed motion Δ_p. Where K_ff
    /// is singular (rattlers, floppy frictionless clusters) the `regularisation` picks
    /// the smallest step; a step longer than `max_step` is scaled back, since the
    /// network it was linearised on would no longer hold.
    fn predict(
        &self,
        centres: &mut [Vec2],
        rotations: &mut [f64],
        dof: &[[usize; 3]],
        count: usize,
    ) -> Result<()> {
        // Δ of every DOF: the affine motion where prescribed, zero where free.
        let motion = |p: usize, a: usize| -> f64 {
            if dof[p][a] != usize::MAX || a == 2 {
                0.0
            } else {
                let d = centres[p] - self.centres[p];
                if a == 0 { d.x } else { d.y }
            }
        };
        let mut rhs = DVector::zeros(count);
        for c in &self.contacts {
            let (bn, bt, idx) = c.rows(dof);
            let nodes = [(c.i, 0), (c.i, 1), (c.i, 2), (c.j, 0), (c.j, 1), (c.j, 2)];
            for a in 0..6 {
                if idx[a] == usize::MAX {
                    continue;
                }
                for b in 0..6 {
                    let (p, comp) = nodes[b];
                    let m = motion(p, comp);
                    if m != 0.0 {
                        rhs[idx[a]] += (c.normal_stiffness * bn[a] * bn[b]
                            + c.tangential_stiffness * bt[a] * bt[b])
                            * m;
                    }
                }
            }
        }
        let step = self.solve(&self.contacts, dof, count, &rhs)?;
        let longest = self.longest_move(dof, step.as_slice());
        if !longest.is_finite() {
            return Err(TampError::Other(
                "quasi-static increment: the stiffness solve gave a non-finite step".into(),
            ));
        }
        let scale = (self.settings.max_step / longest).min(1.0);
        for p in 0..self.len() {
            if dof[p][0] != usize::MAX {
                centres[p] = self.centres[p] - Vec2::new(step[dof[p][0]], step[dof[p][1]]) * scale;
            }
            if dof[p][2] != usize::MAX {
                rotations[p] = self.rotations[p] - step[dof[p][2]] * scale;
            }
        }
        Ok(())
    }

    /// FIRE (Bitzek et al. 2006, PRL 97 170201) on the free DOFs, each DOF's inertia
    /// the diagonal of K: damped pseudo-dynamics that carries a loose network through
    /// rearrangement (mechanisms, contacts opening and forming) to static equilibrium,
    /// for any friction law (sliding forces need no potential).
    fn relax(
        &self,
        centres: &mut [Vec2],
        rotations: &mut [f64],
        dof: &[[usize; 3]],
        count: usize,
        pairs: &mut CandidatePairs,
        report: &mut IncrementReport,
    ) -> Result<Trial> {
        // FIRE's constants as published; DT_MAX = 1 is the stability limit of the
        // inertia below (Gershgorin: the largest eigenvalue of M⁻¹K is below 2.5).
        const DT_MAX: f64 = 1.0;
        const ALPHA_START: f64 = 0.1;
        const N_DELAY: usize = 5;
        let n = self.len();
        pairs.refresh(centres, &self.radii, &self.history);
        let mut trial = self.trial(centres, rotations, dof, count, pairs);
        let mut velocity = vec![0.0; count];
        let (mut dt, mut alpha, mut positive) = (0.1f64, ALPHA_START, 0usize);
        loop {
            report.residual = trial.mean_unbalanced / trial.scale;
            if !report.residual.is_finite() {
                return Err(TampError::Other(format!(
                    "quasi-static increment: non-finite force on cylinder {} at iteration {} \
                     (density {:.5})",
                    trial.worst_node,
                    report.iterations,
                    self.density()
                )));
            }
            if count == 0 || report.residual <= self.settings.tolerance {
                report.converged = true;
                return Ok(trial);
            }
            if report.iterations >= self.settings.max_iterations && self.settings.carry_over {
                report.converged = false;
                return Ok(trial);
            }
            if report.iterations >= self.settings.max_iterations {
                return Err(TampError::Other(format!(
                    "quasi-static increment: no static equilibrium after {} iterations at \
                     density {:.5}: the mean unbalanced force is {:.3e} × the mean contact \
                     force; the largest is on cylinder {} (centre {:?})",
                    report.iterations,
                    self.density(),
                    report.residual,
                    trial.worst_node,
                    centres.get(trial.worst_node).map(|c| (c.x, c.y)),
                )));
            }
            report.iterations += 1;
            let mass = self.inertia(&trial.contacts, dof, count);
            // The force on a node is minus what the contacts need from outside.
            let force: Vec<f64> = trial.residual.iter().map(|r| -r).collect();
            let power: f64 = force.iter().zip(&velocity).map(|(f, v)| f * v).sum();
            if power > 0.0 {
                positive += 1;
                if positive > N_DELAY {
                    dt = (dt * 1.1).min(DT_MAX);
                    alpha *= 0.99;
                }
            } else {
                positive = 0;
                dt *= 0.5;
                alpha = ALPHA_START;
                velocity.iter_mut().for_each(|v| *v = 0.0);
            }
            for d in 0..count {
                velocity[d] += dt * force[d] / mass[d];
            }
            // Turn the velocity towards the force, in mass-weighted norms.
            let v_norm = velocity
                .iter()
                .zip(&mass)
                .map(|(v, m)| m * v * v)
                .sum::<f64>()
                .sqrt();
            let f_norm = force
                .iter()
                .zip(&mass)
                .map(|(f, m)| f * f / m)
                .sum::<f64>()
                .sqrt();
            if f_norm > 0.0 {
                for d in 0..count {
                    velocity[d] =
                        (1.0 - alpha) * velocity[d] + alpha * v_norm / f_norm * force[d] / mass[d];
                }
            }
            // No cylinder moves more than max_step in one iteration, so none can pass
            // through a neighbour.
            let longest = self.longest_move(dof, &velocity) * dt;
            let scale = dt * (self.settings.max_step / longest).min(1.0);
            for p in 0..n {
                if dof[p][0] != usize::MAX {
                    centres[p] += Vec2::new(velocity[dof[p][0]], velocity[dof[p][1]]) * scale;
                }
                if dof[p][2] != usize::MAX {
                    rotations[p] += velocity[dof[p][2]] * scale;
                }
            }
            pairs.refresh(centres, &self.radii, &self.history);
            trial = self.trial(centres, rotations, dof, count, pairs);
        }
    }

    /// FIRE's inertia per free DOF: the diagonal of K with each contact at the stiffest
    /// branch it can take this increment: normally the unloading stiffness once it has
    /// been loaded, tangentially k_T A_c even while it slides. A loading contact that
    /// turns back is 10³ times stiffer; an inertia taken from the loading branch lets
    /// it overshoot (a released affine network gained energy, 0.142 → 0.202 σ_y R²,
    /// before this rule). A sliding contact that sticks again is the same jump: with
    /// its inertia from the sliding branch (zero), a cylinder whose contacts all slide
    /// spun on the σ_y R² floor alone, and FIRE needed 14× (μ = 0.1) and 4.6×
    /// (sticking) more iterations over 30 increments of the W = 20R deposit.
    fn inertia(&self, contacts: &[ContactState], dof: &[[usize; 3]], count: usize) -> Vec<f64> {
        self.diagonal(contacts, dof, count, |c| {
            (c.inertia_stiffness, c.inertia_tangential)
        })
    }

    /// The diagonal of K over the free DOFs with normal stiffness `k_n(contact)`, plus
    /// σ_y (σ_y R² for rotations) so a node with no contact still has a finite entry.
    fn diagonal(
        &self,
        contacts: &[ContactState],
        dof: &[[usize; 3]],
        count: usize,
        k: impl Fn(&ContactState) -> (f64, f64),
    ) -> Vec<f64> {
        let mut diagonal = vec![0.0; count];
        for c in contacts {
            let (bn, bt, idx) = c.rows(dof);
            let (kn, kt) = k(c);
            for a in 0..6 {
                if idx[a] != usize::MAX {
                    diagonal[idx[a]] += kn * bn[a] * bn[a] + kt * bt[a] * bt[a];
                }
            }
        }
        for (node, r) in dof.iter().zip(&self.radii) {
            for (a, &d) in node.iter().enumerate() {
                if d != usize::MAX {
                    diagonal[d] += self.settings.yield_stress * if a == 2 { r * r } else { 1.0 };
                }
            }
        }
        diagonal
    }

    /// The longest move of a cylinder under the DOF vector `step` (rotations as arc
    /// length at the rim).
    fn longest_move(&self, dof: &[[usize; 3]], step: &[f64]) -> f64 {
        // The squared translations pick the candidates; `hypot` (dearer) runs only on
        // those within rounding of the longest, so the result is the same as taking
        // `hypot` of every node.
        let squared = |p: usize| {
            let (x, y) = (step[dof[p][0]], step[dof[p][1]]);
            x * x + y * y
        };
        let translated = |p: usize| dof[p][0] != usize::MAX;
        let longest_squared = (0..self.len())
            .filter(|&p| translated(p))
            .map(squared)
            .fold(0.0, f64::max);
        let threshold = longest_squared * (1.0 - 1e-9);
        let mut longest = 0.0f64;
        for p in 0..self.len() {
            if translated(p) && (squared(p) >= threshold || squared(p).is_nan()) {
                longest = longest.max(step[dof[p][0]].hypot(step[dof[p][1]]));
            }
            if dof[p][2] != usize::MAX {
                longest = longest.max((step[dof[p][2]] * self.radii[p]).abs());
            }
        }
        longest
    }

    /// Contacts, residual and its largest entry at trial positions.
    fn trial(
        &self,
        centres: &[Vec2],
        rotations: &[f64],
        dof: &[[usize; 3]],
        count: usize,
        pairs: &CandidatePairs,
    ) -> Trial {
        let contacts = self.evaluate(centres, rotations, &pairs.pairs, &pairs.histories);
        let forces = self.nodal_forces(&contacts);
        let live = contacts
            .iter()
            .filter(|c| c.normal_force > 0.0)
            .count()
            .max(1);
        let mean_force = contacts.iter().map(|c| c.normal_force).sum::<f64>() / live as f64;
        let mut residual = DVector::zeros(count);
        let (mut worst, mut worst_node) = (0.0f64, usize::MAX);
        let (mut unbalanced, mut free) = (0.0, 0usize);
        for p in 0..self.len() {
            if dof[p].iter().all(|&d| d == usize::MAX) {
                continue;
            }
            // Moments count as forces at the cylinder's rim.
            let mut node = 0.0;
            for a in 0..3 {
                if dof[p][a] != usize::MAX {
                    residual[dof[p][a]] = forces[p][a];
                    let r = if a == 2 {
                        forces[p][a] / self.radii[p]
                    } else {
                        forces[p][a]
                    };
                    node += r * r;
                }
            }
            let node = node.sqrt();
            unbalanced += node;
            free += 1;
            if node > worst || node.is_nan() {
                worst = node;
                worst_node = p;
            }
        }
        Trial {
            contacts,
            residual,
            worst_node,
            mean_unbalanced: unbalanced / free.max(1) as f64,
            scale: mean_force.max(self.settings.force_floor),
        }
    }

    /// Assemble K_ff (plus the regularisation) and solve K Δ = r.
    fn solve(
        &self,
        contacts: &[ContactState],
        dof: &[[usize; 3]],
        count: usize,
        residual: &DVector<f64>,
    ) -> Result<DVector<f64>> {
        let lambda = self.settings.regularisation;
        let mut coo = CooMatrix::new(count, count);
        // Marquardt's scaling: λ times the diagonal of K (with σ_y so a node with no
        // stiffness still has a finite, small step).
        for (d, k) in self
            .diagonal(contacts, dof, count, |c| {
                (c.normal_stiffness, c.tangential_stiffness)
            })
            .into_iter()
            .enumerate()
        {
            coo.push(d, d, lambda * k);
        }
        for c in contacts {
            let (bn, bt, idx) = c.rows(dof);
            for a in 0..6 {
                if idx[a] == usize::MAX {
                    continue;
                }
                for b in 0..6 {
                    if idx[b] == usize::MAX {
                        continue;
                    }
                    let k =
                        c.normal_stiffness * bn[a] * bn[b] + c.tangential_stiffness * bt[a] * bt[b];
                    if k != 0.0 {
                        coo.push(idx[a], idx[b], k);
                    }
                }
            }
        }
        let csc = CscMatrix::from(&coo);
        let chol = CscCholesky::factor(&csc).map_err(|e| {
            TampError::Other(format!(
                "quasi-static stiffness is not positive definite ({e:?})"
            ))
        })?;
        Ok(chol.solve(residual).column(0).into_owned())
    }

    fn commit(
        &mut self,
        centres: Vec<Vec2>,
        rotations: Vec<f64>,
        contacts: Vec<ContactState>,
        de: Sym2,
    ) {
        // Contacts that separated keep their plastic history (they may touch again).
        for c in &contacts {
            self.history.insert(
                (c.i, c.j),
                ContactHistory {
                    max_overlap: c.max_overlap,
                    tangential_force: c.tangential_force,
                },
            );
        }
        let live: std::collections::BTreeSet<(usize, usize)> =
            contacts.iter().map(|c| (c.i, c.j)).collect();
        for (key, h) in self.history.iter_mut() {
            if !live.contains(key) {
                h.tangential_force = 0.0;
            }
        }
        self.centres = centres;
        self.rotations = rotations;
        self.contacts = contacts;
        self.width *= 1.0 + de.xx;
        self.height *= 1.0 + de.yy;
    }

    /// Every force-carrying contact.
    pub fn contact_forces(&self) -> Vec<ContactForce> {
        self.contacts
            .iter()
            .filter(|c| c.normal_force > 0.0)
            .map(|c| {
                let (ri, rj) = (self.radii[c.i], self.radii[c.j]);
                ContactForce {
                    normal: c.normal,
                    branch: self.centres[c.j] - self.centres[c.i],
                    normal_force: c.normal_force,
                    max_overlap: c.max_overlap,
                    effective_radius: ri * rj / (ri + rj),
                }
            })
            .collect()
    }

    /// Fraction of force-carrying contacts that slide.
    pub fn sliding_fraction(&self) -> f64 {
        let live: Vec<_> = self
            .contacts
            .iter()
            .filter(|c| c.normal_force > 0.0)
            .collect();
        live.iter().filter(|c| c.sliding).count() as f64 / live.len().max(1) as f64
    }
}

fn tangent(n: Vec2) -> Vec2 {
    Vec2::new(-n.y, n.x)
}

/// Pairs that may touch, kept for as long as no cylinder has moved more than half
/// the skin since they were found (a Verlet list): FIRE re-evaluates the contacts
/// thousands of times per increment and the grid search would dominate.
struct CandidatePairs {
    skin: f64,
    anchor: Vec<Vec2>,
    pairs: Vec<(usize, usize)>,
    /// The committed history of each pair (default where it has none).
    histories: Vec<ContactHistory>,
}

impl CandidatePairs {
    fn new(
        centres: &[Vec2],
        radii: &[f64],
        skin: f64,
        history: &BTreeMap<(usize, usize), ContactHistory>,
    ) -> Self {
        let pairs = touching_pairs(centres, radii, skin);
        let histories = pairs
            .iter()
            .map(|key| history.get(key).copied().unwrap_or_default())
            .collect();
        CandidatePairs {
            skin,
            anchor: centres.to_vec(),
            pairs,
            histories,
        }
    }

    fn refresh(
        &mut self,
        centres: &[Vec2],
        radii: &[f64],
        history: &BTreeMap<(usize, usize), ContactHistory>,
    ) {
        let moved = centres
            .iter()
            .zip(&self.anchor)
            .map(|(a, b)| (a - b).norm())
            .fold(0.0, f64::max);
        if moved > 0.5 * self.skin {
            *self = CandidatePairs::new(centres, radii, self.skin, history);
        }
    }
}

/// The peripheral layer of a deposited packing (§2.4, Fig 3): cylinders within half
/// a radius of a side wall or the floor, and the top surface, the cylinders no other
/// cylinder shadows from above.
pub fn peripheral_layer(packing: &CylinderPacking) -> Vec<bool> {
    let n = packing.len();
    (0..n)
        .map(|p| {
            let (c, r) = (packing.centres[p], packing.radii[p]);
            let near_wall =
                c.x - r < 0.5 * r || packing.width - (c.x + r) < 0.5 * r || c.y - r < 0.5 * r;
            let shadowed = (0..n).any(|q| {
                q != p
                    && packing.centres[q].y > c.y
                    && (packing.centres[q].x - c.x).abs() < r + packing.radii[q]
            });
            near_wall || !shadowed
        })
        .collect()
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use approx::assert_relative_eq;

    /// Five unit cylinders in a horizontal row, the two ends prescribed.
    pub(crate) fn chain(friction: Friction) -> Network {
        let packing = CylinderPacking {
            width: 10.0,
            height: 2.0,
            centres: (0..5)
                .map(|k| Vec2::new(1.0 + 2.0 * k as f64, 1.0))
                .collect(),
            radii: vec![1.0; 5],
        };
        let mut settings = NetworkSettings::redanz_fleck(1.0, 1.0, friction, true, Constraint::Die);
        // A five-node chain has no rearrangement to wait for: hold it to near round-off.
        settings.tolerance = 1e-10;
        let mut net = Network::new(&packing, settings);
        net.peripheral = vec![true, false, false, false, true];
        net
    }

    #[test]
    fn box_scaling_keeps_the_equilibrium_gap_bound_and_leaves_the_20r_box_alone() {
        let settings = |height: f64| {
            NetworkSettings::redanz_fleck(1.0, 1.0, Friction::Sticking, true, Constraint::Die)
                .scaled_to_box(height, 1.0)
        };
        // The quick cases' box keeps the settings their recorded values were measured with.
        assert_eq!(settings(20.0).tolerance, 1e-2);
        assert_eq!(settings(20.0).max_iterations, 200_000);
        // tolerance × height / R, the gap bound's factor, is the same in the paper's box.
        assert_relative_eq!(
            settings(80.0).tolerance * 80.0,
            1e-2 * 20.0,
            max_relative = 1e-15
        );
        assert_eq!(settings(80.0).max_iterations, 800_000);
        // A smaller box is not held looser than the 20R one.
        assert_eq!(settings(10.0).tolerance, 1e-2);
    }

    #[test]
    fn a_compressed_chain_shares_the_shortening_equally_and_eq_13_matches_the_contacts() {
        let mut net = chain(Friction::Frictionless);
        for _ in 0..10 {
            net.increment(Sym2::new(-1e-3, 0.0, 0.0)).unwrap();
        }
        let dist = net.centres[4].x - net.centres[0].x;
        let overlap = (8.0 - dist) / 4.0;
        for k in 0..4 {
            let gap = net.centres[k + 1].x - net.centres[k].x;
            assert_relative_eq!(2.0 - gap, overlap, max_relative = 1e-5);
        }
        let force = plastic_cylinder::loading_force(overlap, 0.5, 1.0);
        let s = net.stress();
        assert_relative_eq!(s.xx, -force * dist / net.area(), max_relative = 1e-5);
        let c = net.stress_from_contacts();
        assert_relative_eq!(s.xx, c.xx, max_relative = 1e-5);
        assert_eq!(net.coordination(), 2.0 * 4.0 / 5.0);
    }

    #[test]
    fn an_increment_out_of_iterations_fails_or_is_carried_over_and_recovered() {
        let mut net = chain(Friction::Frictionless);
        net.settings.max_iterations = 1;
        assert!(net.clone().increment(Sym2::new(-1e-3, 0.0, 0.0)).is_err());
        net.settings.carry_over = true;
        let report = net.increment(Sym2::new(-1e-3, 0.0, 0.0)).unwrap();
        assert!(!report.converged && report.residual > net.settings.tolerance);
        // The next increment starts from the unbalanced state and restores equilibrium.
        net.settings.max_iterations = 1_000_000;
        let report = net.increment(Sym2::new(-1e-3, 0.0, 0.0)).unwrap();
        assert!(report.converged);
        let (s, c) = (net.stress(), net.stress_from_contacts());
        assert_relative_eq!(s.xx, c.xx, max_relative = 1e-5);
    }

    #[test]
    fn a_sticking_chain_under_shear_rolls_instead_of_sliding() {
        // Shearing the row vertically (Ė₁₂) with free interior rotations: the interior
        // cylinders roll so that the contacts stick with no net moment.
        let mut net = chain(Friction::Sticking);
        net.increment(Sym2::new(-2e-3, 0.0, 0.0)).unwrap();
        net.increment(Sym2::new(0.0, 0.0, 1e-4)).unwrap();
        for p in 1..4 {
            assert!(net.rotations[p].is_finite());
        }
        let s = net.stress();
        let c = net.stress_from_contacts();
        assert_relative_eq!(s.xy, c.xy, max_relative = 1e-4, epsilon = 1e-12);
    }
}
