//! What an engine recorded of one run, the only thing a case measures: the frames of
//! the trajectory (the layout of docs/compare.md) at the steps the case asked for.
//!
//! A recording from another program is untrusted input. It is accepted only when every
//! frame the case needs is there with every particle, each value finite; anything else
//! is an error naming the file, the row or step, and the column, never a silent gap.

use crate::compare::State;
use crate::error::{Result, TampError};
use crate::particles::Vec3;
use std::collections::BTreeMap;

/// What a case needs an engine to record of one run: the scene's `output` block as
/// the resolved scene hands it to an engine.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
pub struct RecordSpec {
    /// Steps between frames; the first (step 0) and the last step are always recorded.
    pub trajectory_every: u64,
    /// Whether each frame holds the particles' total forces and torques.
    pub forces: bool,
    /// From this step to the last, every step is recorded too.
    pub every_step_from: Option<u64>,
    /// Whether each frame holds the walls' displacements and forces (walls.csv).
    pub walls: bool,
}

impl RecordSpec {
    /// Every step, no forces: what a collision measurement needs.
    pub const EVERY_STEP: RecordSpec = RecordSpec {
        trajectory_every: 1,
        forces: false,
        every_step_from: None,
        walls: false,
    };

    /// Every `k` steps (and the last).
    pub fn every(k: u64, forces: bool) -> RecordSpec {
        RecordSpec {
            trajectory_every: k,
            forces,
            every_step_from: None,
            walls: false,
        }
    }

    /// The same frames, each with the walls' displacements and forces.
    pub fn with_walls(self) -> RecordSpec {
        RecordSpec {
            walls: true,
            ..self
        }
    }

    /// Every `k` steps, and every step from `from` on: a run that crosses a value
    /// near its end, found between consecutive steps there.
    pub fn sparse_then_every_step(k: u64, from: u64, forces: bool) -> RecordSpec {
        RecordSpec {
            trajectory_every: k,
            forces,
            every_step_from: Some(from),
            walls: false,
        }
    }

    /// Whether step `step` of a run of `steps` steps is recorded.
    pub fn records(&self, step: u64, steps: u64) -> bool {
        step.is_multiple_of(self.trajectory_every.max(1))
            || step == steps
            || self.every_step_from.is_some_and(|from| step >= from)
    }

    /// The steps a run of `steps` steps must record: 0, k, 2k, …, every step from
    /// `every_step_from`, and `steps`.
    pub fn required_steps(&self, steps: u64) -> impl Iterator<Item = u64> {
        let spec = *self;
        (0..=steps).filter(move |&s| spec.records(s, steps))
    }
}

/// One particle in one frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Body {
    pub radius: f64,
    pub position: Vec3,
    pub velocity: Vec3,
    pub omega: Vec3,
    /// The total force on the particle, when the case asked for forces.
    pub force: Option<Vec3>,
}

/// One wall in one frame.
pub type WallState = crate::compare::WallRow;

/// The particles after one step, in the order of the resolved scene (id = index + 1),
/// and the walls in the scene's order when the case asked for them.
#[derive(Clone, Debug, PartialEq)]
pub struct Frame {
    pub step: u64,
    /// Simulated time, s: the engine's own clock in-process, step · Δt from files.
    pub time: f64,
    pub bodies: Vec<Body>,
    pub walls: Vec<WallState>,
}

/// The frames of one run, by increasing step.
#[derive(Clone, Debug, PartialEq)]
pub struct Recording {
    /// The time step the run was resolved with, s.
    pub dt: f64,
    pub frames: Vec<Frame>,
}

impl Recording {
    /// The frames, when they are consecutive steps (step k + 1 after step k), else an
    /// error naming the first gap: a measurement that interpolates between steps must
    /// not bridge a gap silently.
    pub fn consecutive(&self, what: &str) -> Result<&[Frame]> {
        for w in self.frames.windows(2) {
            if w[1].step != w[0].step + 1 {
                return Err(TampError::Other(format!(
                    "{what} needs every step, and the recording jumps from step {} to {}",
                    w[0].step, w[1].step
                )));
            }
        }
        Ok(&self.frames)
    }

    /// A recording read from the layout's rows, keyed by (step, id), from the file
    /// `file`: checks that every step `spec` asks of a run of `steps` steps is there
    /// with the ids 1..=`particles`, velocities, and forces when asked for. Other
    /// steps are left out.
    pub fn from_rows(
        file: &str,
        rows: &BTreeMap<(u64, u64), State>,
        particles: usize,
        dt: f64,
        steps: u64,
        spec: RecordSpec,
    ) -> Result<Recording> {
        let bad = |rule: String| TampError::input(file.to_string(), rule);
        let n = particles as u64;
        if let Some((step, id)) = rows.keys().find(|(s, i)| *s > steps || *i == 0 || *i > n) {
            return Err(bad(match step > &steps {
                true => format!("has step {step}, beyond the run's last step {steps}"),
                false => format!(
                    "step {step} has particle id {id}, and the scene has ids 1 to {particles}"
                ),
            }));
        }
        let mut frames = Vec::new();
        for step in spec.required_steps(steps) {
            if rows.range((step, 0)..=(step, u64::MAX)).next().is_none() {
                let dense = spec
                    .every_step_from
                    .map_or(String::new(), |from| format!(", every step from {from}"));
                return Err(bad(format!(
                    "has no rows for step {step} (the case needs steps 0, {}, {}, …{dense} and the last, {steps})",
                    spec.trajectory_every,
                    2 * spec.trajectory_every
                )));
            }
            let mut bodies = Vec::with_capacity(particles);
            for id in 1..=n {
                let Some(s) = rows.get(&(step, id)) else {
                    return Err(bad(format!(
                        "step {step} has no row for particle id {id} (ids are 1 to {particles}, the order of the scene's particles)"
                    )));
                };
                let need = |v: Option<Vec3>, columns: &str| {
                    v.ok_or_else(|| bad(format!("needs the columns {columns}")))
                };
                let force = match spec.forces {
                    true => Some(need(s.force, "fx, fy, fz (the case asks for forces)")?),
                    false => None,
                };
                bodies.push(Body {
                    radius: s.radius,
                    position: s.position,
                    velocity: need(s.velocity, "vx, vy, vz")?,
                    omega: s.omega.unwrap_or_else(Vec3::zeros),
                    force,
                });
            }
            frames.push(Frame {
                step,
                time: step as f64 * dt,
                bodies,
                walls: Vec::new(),
            });
        }
        Ok(Recording { dt, frames })
    }

    /// Give each frame its walls from the rows of `file` keyed by (step, wall): every
    /// frame needs a row for each of the walls 1..=`walls`, and no row may name another
    /// step or wall. Steps between frames are allowed and left out.
    pub fn attach_walls(
        &mut self,
        file: &str,
        rows: &BTreeMap<(u64, u64), WallState>,
        walls: usize,
    ) -> Result<()> {
        let bad = |rule: String| TampError::input(file.to_string(), rule);
        let n = walls as u64;
        if let Some((step, wall)) = rows.keys().find(|(_, w)| *w == 0 || *w > n) {
            return Err(bad(format!(
                "step {step} has wall {wall}, and the scene has walls 1 to {walls}"
            )));
        }
        for frame in &mut self.frames {
            frame.walls = (1..=n)
                .map(|wall| {
                    rows.get(&(frame.step, wall)).copied().ok_or_else(|| {
                        bad(format!(
                            "has no row for step {} and wall {wall} (a row for each wall 1 to {walls} at every step of trajectory.csv)",
                            frame.step
                        ))
                    })
                })
                .collect::<Result<_>>()?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn state(x: f64) -> State {
        State {
            radius: 1.0,
            position: Vec3::new(x, 0.0, 0.0),
            velocity: Some(Vec3::zeros()),
            omega: None,
            force: None,
        }
    }

    #[test]
    fn the_steps_a_run_must_record_include_the_first_and_the_last() {
        let every3 = RecordSpec::every(3, false);
        assert_eq!(every3.required_steps(7).collect::<Vec<_>>(), [0, 3, 6, 7]);
        assert_eq!(every3.required_steps(6).collect::<Vec<_>>(), [0, 3, 6]);
        let window = RecordSpec::sparse_then_every_step(4, 9, false);
        assert_eq!(
            window.required_steps(12).collect::<Vec<_>>(),
            [0, 4, 8, 9, 10, 11, 12]
        );
    }

    #[test]
    fn a_missing_step_or_particle_is_named_and_never_skipped() {
        let mut rows = BTreeMap::new();
        for step in 0..=2 {
            rows.insert((step, 1), state(step as f64));
            rows.insert((step, 2), state(5.0));
        }
        let spec = RecordSpec::EVERY_STEP;
        let ok = Recording::from_rows("t.csv", &rows, 2, 0.5, 2, spec).unwrap();
        assert_eq!(ok.frames.len(), 3);
        assert_eq!(ok.frames[2].time, 1.0);
        let short = Recording::from_rows("t.csv", &rows, 2, 0.5, 3, spec).unwrap_err();
        assert!(
            short.to_string().contains("t.csv: has no rows for step 3"),
            "{short}"
        );
        rows.remove(&(1, 2));
        let hole = Recording::from_rows("t.csv", &rows, 2, 0.5, 2, spec).unwrap_err();
        assert!(
            hole.to_string()
                .contains("step 1 has no row for particle id 2"),
            "{hole}"
        );
        rows.insert((1, 2), state(5.0));
        rows.insert((1, 3), state(9.0));
        let stranger = Recording::from_rows("t.csv", &rows, 2, 0.5, 2, spec).unwrap_err();
        assert!(stranger.to_string().contains("particle id 3"), "{stranger}");
    }

    #[test]
    fn every_frame_needs_every_wall_and_no_other() {
        let rows: BTreeMap<_, _> = [((0, 1), state(0.0)), ((2, 1), state(0.0))]
            .into_iter()
            .collect();
        let spec = RecordSpec::every(2, false).with_walls();
        let mut rec = Recording::from_rows("t.csv", &rows, 1, 1.0, 2, spec).unwrap();
        let wall = WallState {
            displacement: Vec3::new(0.0, 0.0, -1.0),
            force: Vec3::new(0.0, 0.0, 2.0),
        };
        let mut walls: BTreeMap<_, _> = [((0, 1), wall), ((1, 1), wall), ((2, 1), wall)]
            .into_iter()
            .collect();
        rec.attach_walls("w.csv", &walls, 1).unwrap();
        assert_eq!(rec.frames[1].walls, [wall]);
        let e = rec.attach_walls("w.csv", &walls, 2).unwrap_err();
        assert!(
            e.to_string()
                .contains("w.csv: has no row for step 0 and wall 2"),
            "{e}"
        );
        walls.insert((2, 3), wall);
        let e = rec.attach_walls("w.csv", &walls, 2).unwrap_err();
        assert!(e.to_string().contains("step 2 has wall 3"), "{e}");
    }

    #[test]
    fn forces_are_required_only_when_asked_for() {
        let rows: BTreeMap<_, _> = [((0, 1), state(0.0))].into_iter().collect();
        let spec = RecordSpec::every(1, true);
        let e = Recording::from_rows("t.csv", &rows, 1, 1.0, 0, spec).unwrap_err();
        assert!(e.to_string().contains("fx, fy, fz"), "{e}");
    }
}
