//! The force loop: every contact's geometry, law and force, pairs then walls, for the
//! scene's laws as types, so a scene pays only for the laws it names; spins enter
//! through a branch on a value fixed for the run (`Spins`).

use super::Simulation;
use super::contact_pass::{ContactPass, Spins};
use super::mdr_pass::MdrStep;
use super::narrow_phase::NarrowPhase;
use crate::boundary::{Boundary, WallPose, shape::ShapeContact};
use crate::contact::lever_arm::Arms;
use crate::contact::mdr::contact::MdrForce;
use crate::contact::model::{Composed, NormalModel, StateOf, TangentialModel};
use crate::contact::states::ContactStates;
use crate::contact::{ContactForce, ContactGeometry};
use crate::error::Result;
use crate::material::PairProperties;
use crate::material::{effective_mass, effective_radius};
use crate::particles::{Particles, Vec3};

/// Effective mass of a pair; a prescribed particle moves whatever the force, so it
/// counts as infinitely heavy, like a wall.
#[inline(always)]
pub(super) fn contact_mass(mass: &[f64], prescribed: &[bool], i: usize, j: usize) -> f64 {
    match (prescribed[i], prescribed[j]) {
        (false, true) => mass[i],
        (true, false) => mass[j],
        _ => effective_mass(mass[i], mass[j]),
    }
}

/// Set every particle's force to its weight, zero plus m g for a free particle (the
/// same sum as zeroing the force and calling `add_weights`) and zero for a
/// prescribed one, in one pass.
pub(super) fn set_weights(p: &mut Particles, g: Vec3) {
    let n = p.len();
    let (force, mass, prescribed) = (&mut p.force[..n], &p.mass[..n], &p.prescribed[..n]);
    for ((f, &m), &fixed) in force.iter_mut().zip(mass).zip(prescribed) {
        *f = if fixed {
            Vec3::zeros()
        } else {
            Vec3::zeros() + g * m
        };
    }
}

/// Add the weight m g of every free particle to its force.
pub(super) fn add_weights(p: &mut Particles, g: Vec3) {
    for i in 0..p.len() {
        if !p.prescribed[i] {
            p.force[i] += g * p.mass[i];
        }
    }
}

/// What pair and wall contacts share once their geometry is known: the overlap
/// limit, the scene's laws (with MDR's normal force `given`, which needs the
/// contact's particles), and a finite force. Returns the force on particle i and its
/// parts; the error says what went wrong, for the caller to place.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub(super) fn resolve<N, T>(
    law: &Composed<N, T>,
    g: &ContactGeometry,
    ratio: f64,
    max_fraction: f64,
    pair: &PairProperties,
    state: &mut StateOf<N, T>,
    dt: f64,
    given: Option<MdrForce>,
    relative_spin: Vec3,
) -> std::result::Result<(Vec3, ContactForce), String>
where
    N: NormalModel,
    T: TangentialModel,
{
    let overlap = g.overlap;
    if ratio > max_fraction {
        return Err(format!(
            "overlap {overlap:.4e} m is {ratio:.3e} of the smaller radius (limit {max_fraction})"
        ));
    }
    let f = law.evaluate_given(g, pair, state, dt, given, relative_spin);
    let total = g.normal * f.normal + f.tangential;
    if !total.iter().all(|c| c.is_finite()) {
        return Err(format!(
            "non-finite contact force at overlap {overlap:.4e} m"
        ));
    }
    Ok((total, f))
}

/// Give this step's contacts of one particle with one wall (`found`) the states of
/// the same facets last step; a facet touched anew starts fresh.
#[inline(always)]
pub(super) fn carry_facet_states<S: Copy + Default>(
    states: &mut Vec<(u32, S)>,
    found: &[ShapeContact],
) {
    let same =
        states.len() == found.len() && states.iter().zip(found).all(|((f, _), c)| *f == c.facet);
    if !same {
        let previous = std::mem::take(states);
        states.extend(
            found
                .iter()
                .map(|c| (c.facet, carried_state(&previous, c.facet))),
        );
    }
}

/// The state facet `facet` had last step among one particle's contacts with one wall,
/// or a fresh one.
#[inline(always)]
pub(super) fn carried_state<S: Copy + Default>(previous: &[(u32, S)], facet: u32) -> S {
    let kept = previous.iter().find(|(f, _)| *f == facet);
    kept.map_or_else(S::default, |(_, s)| *s)
}

/// The particle arrays a contact's geometry reads, as slices of one length.
pub(super) struct Bodies<'a> {
    pub(super) position: &'a [Vec3],
    pub(super) velocity: &'a [Vec3],
    pub(super) omega: &'a [Vec3],
    pub(super) radius: &'a [f64],
    pub(super) mass: &'a [f64],
    pub(super) prescribed: &'a [bool],
}

impl<'a> Bodies<'a> {
    /// The arrays of `p`, as slices of its length.
    pub(super) fn of(p: &'a Particles) -> Self {
        let n = p.len();
        Bodies {
            position: &p.position[..n],
            velocity: &p.velocity[..n],
            omega: &p.omega[..n],
            radius: &p.radius[..n],
            mass: &p.mass[..n],
            prescribed: &p.prescribed[..n],
        }
    }
}

/// The geometry of the pair contact i–j at separation d = x_i − x_j (nearest image,
/// |d| = `dist` > 0, overlap δ = R_i + R_j − |d|), and the lever arms of i and j in
/// the scene's convention; spins enter the contact velocity if they are on.
#[inline(always)]
pub(super) fn pair_geometry(
    b: &Bodies,
    spins: Spins,
    i: usize,
    j: usize,
    d: Vec3,
    dist: f64,
    overlap: f64,
) -> (ContactGeometry, Arms, Arms) {
    let normal = d / dist;
    let (arm_i, arm_j) = (
        spins.arms.pair(b.radius[i], overlap),
        spins.arms.pair(b.radius[j], overlap),
    );
    let mut relative_velocity = b.velocity[i] - b.velocity[j];
    if spins.on {
        relative_velocity -=
            b.omega[i].cross(&normal) * arm_i.velocity + b.omega[j].cross(&normal) * arm_j.velocity;
    }
    let g = ContactGeometry {
        normal,
        overlap,
        effective_radius: effective_radius(b.radius[i], b.radius[j]),
        effective_mass: contact_mass(b.mass, b.prescribed, i, j),
        relative_velocity,
    };
    (g, arm_i, arm_j)
}

/// The geometry of particle i's contact `c` with `wall` at `pose`, and i's lever arms
/// in the scene's convention.
#[inline(always)]
pub(super) fn wall_geometry(
    b: &Bodies,
    spins: Spins,
    i: usize,
    c: &ShapeContact,
    wall: &Boundary,
    pose: &WallPose,
) -> (ContactGeometry, Arms) {
    let (overlap, normal) = (c.overlap, c.normal);
    let arm = spins.arms.wall(b.radius[i], overlap);
    let mut relative_velocity = b.velocity[i] - pose.velocity;
    if spins.on {
        relative_velocity -= b.omega[i].cross(&normal) * arm.velocity;
    }
    let g = ContactGeometry {
        normal,
        overlap,
        effective_radius: wall.effective_radius(pose, &b.position[i], b.radius[i]),
        effective_mass: b.mass[i],
        relative_velocity,
    };
    (g, arm)
}

/// `Simulation::compute_forces` as a pass specialised to the scene.
pub(super) struct ForceLoop<'a>(pub(super) &'a mut Simulation);

impl ContactPass for ForceLoop<'_> {
    type Output = Result<()>;
    fn run<N, T>(self, law: &Composed<N, T>, spins: Spins) -> Result<()>
    where
        N: NormalModel,
        T: TangentialModel,
    {
        self.0.compute_forces_with(law, spins)
    }
}

impl Simulation {
    /// Contact, wall and body forces at the current positions, for the scene's laws
    /// as types. With `spins` on, spins enter contact velocities and torques are
    /// accumulated, with the lever arms of the scene's convention.
    pub(super) fn compute_forces_with<N, T>(
        &mut self,
        law: &Composed<N, T>,
        spins: Spins,
    ) -> Result<()>
    where
        N: NormalModel,
        T: TangentialModel,
    {
        let mdr = law.normal.mdr();
        if let Some(m) = mdr {
            self.mdr_begin_step::<N, T>(m);
        }
        let update = self.work.stepping;
        let kept = ContactStates::<StateOf<N, T>>::KEPT;
        let gravity = self.active_gravity();
        let p = &mut self.state.particles;
        let n = p.len();
        // Forces start from the weights (or zero), torques from zero, in one pass.
        match gravity {
            Some(g) => set_weights(p, g),
            None => p.force.iter_mut().for_each(|f| *f = Vec3::zeros()),
        }
        if spins.on {
            p.torque.iter_mut().for_each(|t| *t = Vec3::zeros());
        }
        let dt = self.state.dt;
        let max_fraction = self.model.limits.max_overlap_fraction;
        let mut worst = self.state.max_overlap_ratio;
        let torques = spins.on && T::ACTIVE;
        let law_reach = law.reach();
        let mut mdr_step = MdrStep::of(mdr, self.state.mdr.as_mut(), update);
        let states = self.state.contacts.typed_mut::<StateOf<N, T>>();
        let mut fresh = StateOf::<N, T>::default();

        // The particle arrays as slices of one length n, so that one bounds check
        // per index covers them all, and none of them is re-read through `self`.
        let Particles {
            id,
            position,
            velocity,
            omega,
            force,
            torque,
            radius,
            mass,
            material,
            prescribed,
            ..
        } = p;
        let bodies = Bodies {
            position: &position[..n],
            velocity: &velocity[..n],
            omega: &omega[..n],
            radius: &radius[..n],
            mass: &mass[..n],
            prescribed: &prescribed[..n],
        };
        let (id, material) = (&id[..n], &material[..n]);
        let (force, torque) = (&mut force[..n], &mut torque[..]);
        let narrow = NarrowPhase {
            image: self.model.detection.space.minimum_image(),
            pairs: &self.state.neighbors.pairs[..],
            position: bodies.position,
            radius: bodies.radius,
        };
        let pair_states: &mut [StateOf<N, T>] = if kept {
            &mut states.pairs[..narrow.pairs.len()]
        } else {
            &mut []
        };

        // The pairs within reach of their law, with their separation; the state of
        // every other pair is reset (it is apart). Then those pairs, in the list's
        // order (so forces are summed in the same order as by one loop over the list).
        let mut near = std::mem::take(&mut self.work.near);
        narrow.pairs_within(law_reach, &mut near, |k| {
            if kept {
                pair_states[k] = Default::default();
            }
        });
        let radius = bodies.radius;
        let pairs = near.iter().try_for_each(|&(k, d)| {
            let (i, j) = narrow.pair(k);
            let reach = radius[i] + radius[j];
            let dist2 = d.norm_squared();
            let dist = dist2.sqrt();
            let overlap = reach - dist;
            let ratio = overlap / radius[i].min(radius[j]);
            worst = worst.max(ratio);
            let name = || format!("contact {}-{}", id[i], id[j]);
            if dist == 0.0 {
                // The build refuses coincident centres, and a pair driven together
                // meets the overlap limit first unless it is at least (R_i + R_j)/R_min ≥ 2.
                return Err(format!(
                    "{}: the centres coincide (overlap {overlap:.4e} m), so the contact normal is undefined",
                    name()
                ));
            }
            let (g, arm_i, arm_j) = pair_geometry(&bodies, spins, i, j, d, dist, overlap);
            let normal = g.normal;
            let pair = self.model.pair_table.get(material[i], material[j]);
            let state = if kept {
                &mut pair_states[k as usize]
            } else {
                &mut fresh
            };
            let given = mdr_step
                .as_mut()
                .and_then(|m| m.pair::<N>(&mut state.normal, overlap, (i, j), id, &g));
            let spin = if T::ROLLS {
                bodies.omega[i] - bodies.omega[j]
            } else {
                Vec3::zeros()
            };
            let (total, f) = resolve(law, &g, ratio, max_fraction, pair, state, dt, given, spin)
                .map_err(|what| format!("{}: {what}", name()))?;
            force[i] += total;
            force[j] -= total;
            if torques {
                let t = -normal.cross(&f.tangential);
                let (mut t_i, mut t_j) = (t * arm_i.torque, t * arm_j.torque);
                if T::ROLLS {
                    // Summed per contact before it joins the particle's torque, as
                    // LAMMPS does, so that both codes round alike.
                    let rolling = normal.cross(&f.rolling) * g.effective_radius;
                    t_i += rolling;
                    t_j -= rolling;
                }
                torque[i] += t_i;
                torque[j] += t_j;
            }
            Ok(())
        });
        self.work.near = near;

        let mut found = std::mem::take(&mut self.work.found);
        let wall_force = &mut self.state.wall_force;
        let walls = pairs.and_then(|()| {
            wall_force.iter_mut().for_each(|f| *f = Vec3::zeros());
            let (walls, poses) = (&self.model.walls[..], &self.state.walls[..]);
            narrow.wall_contacts(
                walls,
                poses,
                law_reach,
                &mut found,
                |w, wall, pose, i, found| {
                    if kept {
                        // The states of the facets touched last step, carried to this
                        // step's contacts by facet.
                        carry_facet_states(&mut states.walls[w][i], found);
                    }
                    for (c, contact) in found.iter().enumerate() {
                        let (facet, normal) = (contact.facet, contact.normal);
                        let ratio = contact.overlap / radius[i];
                        worst = worst.max(ratio);
                        let (g, arm) = wall_geometry(&bodies, spins, i, contact, wall, pose);
                        let pair = self.model.pair_table.get(material[i], wall.material);
                        let state = if kept {
                            &mut states.walls[w][i][c].1
                        } else {
                            &mut fresh
                        };
                        let given = mdr_step
                            .as_mut()
                            .and_then(|m| m.wall::<N>(&mut state.normal, contact.overlap, i, &g));
                        let spin = if T::ROLLS {
                            bodies.omega[i]
                        } else {
                            Vec3::zeros()
                        };
                        let (total, f) =
                            resolve(law, &g, ratio, max_fraction, pair, state, dt, given, spin)
                                .map_err(|what| {
                                    format!(
                                        "contact {}-wall '{}' (facet {facet}): {what}",
                                        id[i], wall.name
                                    )
                                })?;
                        force[i] += total;
                        wall_force[w] -= total;
                        if torques {
                            let mut t = -normal.cross(&f.tangential) * arm.torque;
                            if T::ROLLS {
                                t += normal.cross(&f.rolling) * g.effective_radius;
                            }
                            torque[i] += t;
                        }
                    }
                    Ok(())
                },
            )
        });
        self.work.found = found;
        walls.map_err(|what| self.unstable(what))?;
        self.state.max_overlap_ratio = worst;
        Ok(())
    }
}
