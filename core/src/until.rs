//! `run.until`: end a run once its particles have settled, instead of at a guessed
//! time (Zhong 2009 §5: the system monitors the run and ends it).
//!
//! Settled means: no particle is still to be poured, radii have stopped growing, and
//! the kinetic energy per particle (translation + spin, J) — and, when given, the
//! largest particle speed (m/s) — have stayed below their thresholds at every step
//! for `held_for` seconds without a break. The run's `duration` (or `steps`) remains
//! its maximum length. The check is one pass over the particles after a step, made
//! only when the scene asks for it; the force loop does not know about it.

use crate::simulation::Simulation;
use serde::{Deserialize, Serialize};

/// The settling criterion as written in `run.until`: thresholds on kinetic energy
/// per particle and largest speed, and how long they must hold.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct UntilSpec {
    /// J: (translational + rotational kinetic energy) / particles must stay below this.
    pub kinetic_energy_per_particle: f64,
    /// m/s: when given, the largest particle speed must stay below this too.
    #[serde(default)]
    pub max_speed: Option<f64>,
    /// s: how long both must hold without a break.
    pub held_for: f64,
}

/// What the criterion last saw, for summary.json and the message on stderr.
#[derive(Clone, Copy, Debug, Default, Serialize)]
pub struct Reading {
    /// Kinetic energy per particle (translation + spin), J.
    pub kinetic_energy_per_particle: f64,
    /// Largest particle speed, m/s.
    pub max_speed: f64,
}

/// The watcher of one run: when the criterion started to hold, if it holds now.
#[derive(Clone, Debug)]
pub struct Until {
    /// The criterion's thresholds.
    pub spec: UntilSpec,
    /// Simulated time of the first step of the current unbroken stretch below the
    /// thresholds (kept in checkpoints, so a resumed run stops where the whole one does).
    pub held_since: Option<f64>,
    /// What the last check saw.
    pub last: Reading,
}

impl Until {
    /// A watcher that has not yet seen the criterion hold.
    pub fn new(spec: UntilSpec) -> Self {
        Until {
            spec,
            held_since: None,
            last: Reading::default(),
        }
    }

    /// After a step: whether the particles have now been settled for `held_for`.
    pub fn settled(&mut self, sim: &Simulation) -> bool {
        self.last = reading(sim);
        let below = self.last.kinetic_energy_per_particle < self.spec.kinetic_energy_per_particle
            && self.spec.max_speed.is_none_or(|v| self.last.max_speed < v);
        let filling = sim.is_growing() || sim.state.still_to_pour() > 0;
        if !below || filling {
            self.held_since = None;
            return false;
        }
        let since = *self.held_since.get_or_insert(sim.state.time);
        sim.state.time - since >= self.spec.held_for
    }
}

/// Kinetic energy per particle and largest speed; zero without particles.
pub fn reading(sim: &Simulation) -> Reading {
    let p = &sim.state.particles;
    let n = p.len();
    Reading {
        kinetic_energy_per_particle: if n == 0 {
            0.0
        } else {
            sim.kinetic_energy() / n as f64
        },
        max_speed: p.velocity.iter().map(|v| v.norm()).fold(0.0, f64::max),
    }
}
