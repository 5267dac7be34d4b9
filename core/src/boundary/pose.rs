//! Where a wall is and how fast it moves: the part of a wall that changes as a run
//! steps. The wall's shape, material and motion law (`Boundary`) belong to the run's
//! model; its pose belongs to the run's state and is what a checkpoint stores.

use crate::particles::Vec3;
use serde::{Deserialize, Serialize};

/// A wall's translation from its rest frame and its velocity.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct WallPose {
    /// Translation u from the rest frame, m.
    pub displacement: Vec3,
    /// Velocity during the current step, m/s.
    pub velocity: Vec3,
}
