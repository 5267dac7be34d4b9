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
        self.model.growth = Some(growth);
        self.state.target_radius = target_radius;
        self.refresh_smallest_radius();
        // The forces of `new` included the weights, which wait for the end of growth:
        // take them off again instead of evaluating every contact a second time.
        if let Some(g) = self.model.gravity.filter(|_| self.is_growing()) {
            add_weights(&mut self.state.particles, -g);
        }
        self.restart_energy_book();
    }

    /// Keep `smallest_radius` the smallest final radius present, after particles or
    /// their final radii change (build, growth, pouring).
    pub(crate) fn refresh_smallest_radius(&mut self) {
        self.work.smallest_radius = (0..self.state.particles.len())
            .map(|i| self.final_radius(i))
            .fold(f64::INFINITY, f64::min);
    }

    /// The smallest final radius of the particles present, m (∞ with none).
    pub fn smallest_radius(&self) -> f64 {
        self.work.smallest_radius
    }

    /// Radius particle i has at the end of any growth stage.
    pub(super) fn final_radius(&self, i: usize) -> f64 {
        if self.model.growth.is_some() {
            self.state.target_radius[i]
        } else {
            self.state.particles.radius[i]
        }
    }

    /// Whether a growth stage is under way at the current time.
    pub fn is_growing(&self) -> bool {
        self.model
            .growth
            .is_some_and(|g| g.is_growing(self.state.time))
    }

    /// Gravity as it acts now: absent during a growth stage.
    pub fn active_gravity(&self) -> Option<Vec3> {
        if self.is_growing() {
            None
        } else {
            self.model.gravity
        }
    }
}
