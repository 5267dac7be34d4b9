//! A collision measured as it happens: `binary_collision` and `plane_collision` step
//! the simulation they are given until the bodies have touched and separated; the
//! measurement itself never changes the state.

use crate::error::{Result, TampError};
use crate::particles::Vec3;
use crate::simulation::Simulation;

/// What one binary collision between particles `i` and `j` looked like.
#[derive(Clone, Copy, Debug)]
pub struct Collision {
    /// From first touch to separation, each interpolated linearly between steps, s.
    pub duration: f64,
    /// Largest overlap, refined by a parabola through the three samples around the peak, m.
    pub max_overlap: f64,
    /// Largest sampled overlap (after each step, no refinement), m: LIGGGHTS dumps
    /// are reduced the same way.
    pub max_sampled_overlap: f64,
    /// Largest contact force on the first body, refined like the overlap, N (the
    /// probed bodies must feel no other force: no gravity, no third body).
    pub max_force: f64,
    /// Normal relative speed after / before.
    pub restitution: f64,
}

/// Step `sim` until `i` and `j` have touched and separated (at most `max_steps`).
pub fn binary_collision(
    sim: &mut Simulation,
    i: usize,
    j: usize,
    max_steps: u64,
) -> Result<Collision> {
    let n = (sim.state.particles.position[i] - sim.state.particles.position[j]).normalize();
    collision(
        sim,
        max_steps,
        &format!("particles {i} and {j}"),
        |s| s.overlap(i, j),
        |s| -(s.state.particles.velocity[i] - s.state.particles.velocity[j]).dot(&n),
        |s| s.state.particles.force[i].norm(),
    )
}

/// Step `sim` until particle `i` has touched and left the fixed plane through `point`
/// with unit `normal` (at most `max_steps`); the overlap is R_i − (x_i − point)·n.
pub fn plane_collision(
    sim: &mut Simulation,
    i: usize,
    point: Vec3,
    normal: Vec3,
    max_steps: u64,
) -> Result<Collision> {
    collision(
        sim,
        max_steps,
        &format!("particle {i} and the plane"),
        |s| s.state.particles.radius[i] - (s.state.particles.position[i] - point).dot(&normal),
        |s| -s.state.particles.velocity[i].dot(&normal),
        |s| s.state.particles.force[i].norm(),
    )
}

/// One collision seen through its overlap and normal approach speed.
fn collision(
    sim: &mut Simulation,
    max_steps: u64,
    bodies: &str,
    overlap: impl Fn(&Simulation) -> f64,
    approach: impl Fn(&Simulation) -> f64,
    force: impl Fn(&Simulation) -> f64,
) -> Result<Collision> {
    let mut watch = CollisionWatch::new(overlap(sim), approach(sim));
    let dt = sim.state.dt;
    for _ in 0..max_steps {
        sim.step()?;
        if watch.observe(sim.state.time, dt, overlap(sim), || force(sim)) {
            break;
        }
    }
    watch.finish(approach(sim)).ok_or_else(|| {
        TampError::Other(format!(
            "{bodies} did not complete a collision in {max_steps} steps"
        ))
    })
}

/// The measurement of one collision from the states after consecutive steps, whether
/// they come from a simulation as it steps (`binary_collision`) or from a recorded
/// trajectory: the same arithmetic either way.
#[derive(Clone, Debug)]
pub struct CollisionWatch {
    v_before: f64,
    prev: f64,
    start: Option<f64>,
    end: Option<f64>,
    samples: Vec<f64>,
    forces: Vec<f64>,
}

impl CollisionWatch {
    /// Before the first step: the overlap (negative: a gap) and the normal approach speed.
    pub fn new(overlap: f64, approach: f64) -> Self {
        CollisionWatch {
            v_before: approach,
            prev: overlap,
            start: None,
            end: None,
            samples: Vec::new(),
            forces: Vec::new(),
        }
    }

    /// The state after one more step of `dt`, at `time`: its overlap, and the force on
    /// the first body (asked for only while in contact). True once the bodies have
    /// separated, after which nothing more is taken.
    pub fn observe(&mut self, time: f64, dt: f64, now: f64, force: impl FnOnce() -> f64) -> bool {
        if self.end.is_some() {
            return true;
        }
        let prev = self.prev;
        if self.start.is_none() && prev <= 0.0 && now > 0.0 {
            self.start = Some(time - dt + dt * (-prev) / (now - prev));
        }
        if self.start.is_some() {
            self.samples.push(now);
            self.forces.push(force());
        }
        if self.start.is_some() && prev > 0.0 && now <= 0.0 {
            self.end = Some(time - dt + dt * prev / (prev - now));
            return true;
        }
        self.prev = now;
        false
    }

    /// The collision, given the normal approach speed at the step of separation; `None`
    /// when the bodies have not touched and separated.
    pub fn finish(&self, approach: f64) -> Option<Collision> {
        let (Some(start), Some(end)) = (self.start, self.end) else {
            return None;
        };
        let (k, max_overlap) = refined_peak(&self.samples);
        // The last sample is after separation (no force): it stays out of the peak.
        let forces = &self.forces[..self.forces.len().saturating_sub(1).max(1)];
        let (_, max_force) = refined_peak(forces);
        Some(Collision {
            duration: end - start,
            max_overlap,
            max_sampled_overlap: self.samples[k],
            max_force,
            restitution: -approach / self.v_before,
        })
    }
}

/// The largest sample and its index; the value is refined by the parabola through it
/// and its two neighbours when it is an interior maximum.
fn refined_peak(samples: &[f64]) -> (usize, f64) {
    let k = samples
        .iter()
        .enumerate()
        .max_by(|a, b| a.1.total_cmp(b.1))
        .map(|(k, _)| k)
        .unwrap_or(0);
    let peak = if k > 0 && k + 1 < samples.len() {
        let (a, b, c) = (samples[k - 1], samples[k], samples[k + 1]);
        let curvature = a - 2.0 * b + c;
        if curvature < 0.0 {
            b - 0.125 * (a - c).powi(2) / curvature
        } else {
            b
        }
    } else {
        samples[k]
    };
    (k, peak)
}
