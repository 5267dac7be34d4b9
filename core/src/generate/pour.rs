//! Pouring: particles enter the running simulation in batches, as a hopper or the
//! insertion of LIGGGHTS' `fix insert/rate/region` feeds a container. Every `every`
//! seconds from `start`, up to `per_event` spheres are placed by random sequential
//! insertion in the region, clear of the particles already there; a sphere that
//! finds no room waits for the next event (the region is still full of the last
//! batch), so pouring never overlaps particles and never fails for lack of room.
//!
//! A poured particle brings its kinetic energy into the system; the energy book
//! counts it as external work.

use super::distribution::SizeDistribution;
use super::rsi::InsertionBox;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};

/// A pouring source: a box region into which batches of spheres are inserted at
/// regular intervals during the run. What it has poured so far is its `SourceState`.
#[derive(Clone, Debug)]
pub struct Source {
    /// Box that must contain each inserted sphere whole.
    pub region: InsertionBox,
    /// Size law of the poured radii.
    pub radius: SizeDistribution,
    /// Index of the poured particles' material in the scene's material list.
    pub material: usize,
    /// Speed in a random direction and spin about a random axis at entry.
    pub speed: f64,
    /// Angular speed at entry, rad/s.
    pub spin: f64,
    /// Time of the first event, s.
    pub start: f64,
    /// Interval between insertion events, s.
    pub every: f64,
    /// Most spheres inserted per event.
    pub per_event: usize,
    /// Centre draws allowed per sphere and event before it waits for the next event.
    pub max_attempts: usize,
    /// Particles to pour in all.
    pub count: usize,
    /// Seed of the source's random generator.
    pub seed: u64,
}

/// How far a source has got: its next event, what is left to pour, and its random
/// generator, stored as its abstract state so a checkpoint continues the same draws.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct SourceState {
    /// Time of the next event, s.
    pub next: f64,
    /// Particles still to pour.
    pub remaining: usize,
    /// Radius of the next particle, drawn once so a sphere that waits keeps its size.
    pub pending_radius: Option<f64>,
    /// Random generator of this source's sizes, positions, entry velocities and spins.
    pub rng: ChaCha8Rng,
}

impl Source {
    /// The source before its first event.
    pub fn initial_state(&self) -> SourceState {
        SourceState {
            next: self.start,
            remaining: self.count,
            pending_radius: None,
            rng: ChaCha8Rng::seed_from_u64(self.seed),
        }
    }
}

impl SourceState {
    /// Whether an insertion event falls due at time t, s (and particles remain to pour).
    pub fn is_due(&self, t: f64) -> bool {
        self.remaining > 0 && t >= self.next
    }
}
