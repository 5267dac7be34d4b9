//! The growth stage (Zhong 2009 §6.1): radii grow to their final size with gravity
//! off; what the step needs to know about it.

use super::Simulation;
use super::force_loop::add_weights;
use crate::growth::Growth;
use crate::particles::Vec3;

impl Simulation {
    /// Attach a growth stage to a simulation built with its particles at the starting
    /// size; `target_radius` are the final radii.
    pub fn set_growth(&mut self, growth: Growth, target_radius: Vec<f64>) {
        self.growth = Some(growth);
        self.target_radius = target_radius;
        self.refresh_smallest_radius();
        // The forces of `new` included the weights, which wait for the end of growth:
        // take them off again instead of evaluating every contact a second time.
        if let Some(g) = self.gravity.filter(|_| self.is_growing()) {
            add_weights(&mut self.particles, -g);
        }
        self.restart_energy_book();
    }

    /// Keep `smallest_radius` the smallest final radius present, after particles or
    /// their final radii change (build, growth, pouring).
    pub(crate) fn refresh_smallest_radius(&mut self) {
        self.smallest_radius = (0..self.particles.len())
            .map(|i| self.final_radius(i))
            .fold(f64::INFINITY, f64::min);
    }

    /// The smallest final radius of the particles present, m (∞ with none).
    pub fn smallest_radius(&self) -> f64 {
        self.smallest_radius
    }

    /// Radius particle i has at the end of any growth stage.
    pub(super) fn final_radius(&self, i: usize) -> f64 {
        if self.growth.is_some() {
            self.target_radius[i]
        } else {
            self.particles.radius[i]
        }
    }

    /// Whether a growth stage is under way at the current time.
    pub fn is_growing(&self) -> bool {
        self.growth.is_some_and(|g| g.is_growing(self.time))
    }

    /// Gravity as it acts now: absent during a growth stage.
    pub fn active_gravity(&self) -> Option<Vec3> {
        if self.is_growing() {
            None
        } else {
            self.gravity
        }
    }
}
