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
use rand_chacha::ChaCha8Rng;

/// A pouring source: a box region into which batches of spheres are inserted at
/// regular intervals during the run, with their random generator and what is left to
/// pour.
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
    /// Interval between insertion events, s.
    pub every: f64,
    /// Most spheres inserted per event.
    pub per_event: usize,
    /// Centre draws allowed per sphere and event before it waits for the next event.
    pub max_attempts: usize,
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
    /// Whether an insertion event falls due at time t, s (and particles remain to pour).
    pub fn is_due(&self, t: f64) -> bool {
        self.remaining > 0 && t >= self.next
    }
}
