//! The narrow phase: from the neighbour list and the walls to the contacts within a
//! reach of touching. Every pass over the contacts starts here (the force loop, the
//! contact records, the stored energy, the critical step, the contact count), so all
//! of them see the same contacts in the same order: pairs in the list's order, then
//! each wall's contacts particle by particle.

use crate::boundary::shape::ShapeContact;
use crate::boundary::{Boundary, WallPose};
use crate::particles::Vec3;
use crate::space::MinimumImage;

/// What the narrow phase reads: the particles' centres and radii, the neighbour
/// list, and the nearest-image rule of the domain.
#[derive(Clone, Copy)]
pub(super) struct NarrowPhase<'a> {
    pub(super) image: MinimumImage,
    pub(super) pairs: &'a [(u32, u32)],
    pub(super) position: &'a [Vec3],
    pub(super) radius: &'a [f64],
}

impl NarrowPhase<'_> {
    /// The pairs of the list whose surfaces are closer than `reach` (|d| < R_i + R_j +
    /// reach), with their separation d = x_i − x_j, into `near` in the list's order;
    /// `apart(k)` for every other pair. Most pairs of a Verlet list are apart, and this
    /// test is all they cost.
    #[inline(always)]
    pub(super) fn pairs_within(
        &self,
        reach: f64,
        near: &mut Vec<(u32, Vec3)>,
        mut apart: impl FnMut(usize),
    ) {
        let (position, radius) = (self.position, self.radius);
        near.clear();
        for (k, &(i, j)) in self.pairs.iter().enumerate() {
            let (i, j) = (i as usize, j as usize);
            let d = self.image.displacement(&position[i], &position[j]);
            let sum = radius[i] + radius[j];
            if d.norm_squared() >= (sum + reach).powi(2) {
                apart(k);
            } else {
                near.push((k as u32, d));
            }
        }
    }

    /// Pair `k` of the list as (i, j).
    #[inline(always)]
    pub(super) fn pair(&self, k: u32) -> (usize, usize) {
        let (i, j) = self.pairs[k as usize];
        (i as usize, j as usize)
    }

    /// Each particle's contacts with each wall closer than `reach` to touching: `each`
    /// gets the wall's index, the wall, its pose, the particle and its contacts (one
    /// per facet touched), wall by wall and particle by particle; it stops the walk
    /// with its first error.
    #[inline(always)]
    pub(super) fn wall_contacts<E>(
        &self,
        walls: &[Boundary],
        poses: &[WallPose],
        reach: f64,
        found: &mut Vec<ShapeContact>,
        mut each: impl FnMut(usize, &Boundary, &WallPose, usize, &[ShapeContact]) -> Result<(), E>,
    ) -> Result<(), E> {
        for (w, (wall, pose)) in walls.iter().zip(poses).enumerate() {
            for i in 0..self.position.len() {
                found.clear();
                wall.contacts(pose, &self.position[i], self.radius[i], reach, found);
                each(w, wall, pose, i, found)?;
            }
        }
        Ok(())
    }
}
