//! Scratch the step keeps between steps only to avoid allocating again, and what it
//! derives from the state once rather than at every step. Nothing here is part of a
//! run's state: a restored run rebuilds it.

use crate::boundary::shape::ShapeContact;
use crate::particles::Vec3;

/// The step's scratch (see the module documentation).
#[derive(Clone, Debug)]
pub(super) struct Workspace {
    /// The contacts of one particle with one boundary.
    pub(super) found: Vec<ShapeContact>,
    /// The neighbour-list pairs within reach of the law at this step, with their
    /// separation: (index in the list, x_i − x_j).
    pub(super) near: Vec<(u32, Vec3)>,
    /// Whether a step's drift is done and its count not yet taken (see `unstable`).
    pub(super) stepping: bool,
    /// The smallest final radius of the particles present (`refresh_smallest_radius`).
    pub(super) smallest_radius: f64,
}

impl Default for Workspace {
    fn default() -> Self {
        Workspace {
            found: Vec::new(),
            near: Vec::new(),
            stepping: false,
            smallest_radius: f64::INFINITY,
        }
    }
}
