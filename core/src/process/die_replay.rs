//! The press stage replayed: the punch follows a recorded stroke instead of a load,
//! so that a peer code without tamp's pressure-loaded punch can press the same
//! specimen along the same path and the two codes' punch forces can be compared.
//!
//! The stroke is the punch face height H_k of a pressing (`die_compaction::press`)
//! at its records t_k = k t_ramp / n, and the punch moves between records at the
//! constant speed (H_k − H_{k−1}) / (t_k − t_{k−1}): piecewise linear in time, exact
//! at every record. The step is fixed, Δt = (t_k − t_{k−1}) / N with N the least
//! integer that makes Δt no larger than the smallest step the pressing took (its
//! stiffest bed), so that a record falls on a step in both codes and the same
//! motion is written once for LIGGGHTS (`fix move/mesh linear/variable`, one `run N`
//! per record) and once for tamp (a `displacement` motion whose chord over a step is
//! the segment's speed, `boundary::motion`).
//!
//! A replay is measured from its recorded frames as a pressing is: the particles'
//! force on punch and floor over the die's cross-section, and the specimen and RVE
//! densities at the punch height (`die_compaction::densities_in`).

use super::die_compaction::{self, Pressing, Specimen};
use super::die_compaction_file::DieCompactionFile;
use crate::error::{Result, TampError};
use crate::scene::Scene;
use crate::scene::walls::MotionSpec;
use serde::{Deserialize, Serialize};

/// Index of the punch among the press stage's walls (die, floor, punch).
const PUNCH: usize = 2;

/// A recorded punch stroke: the heights at equal record intervals.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Stroke {
    /// Height of the punch face before the stroke (the specimen's H₀), m.
    pub h0: f64,
    /// Time between records, s.
    pub interval: f64,
    /// Steps per record interval.
    pub steps_per_record: u64,
    /// The fixed time step, `interval / steps_per_record`, s.
    pub dt: f64,
    /// Punch face height at records 1, 2, …, n, m.
    pub heights: Vec<f64>,
    /// The pressure the recorded pressing applied at those records, Pa.
    pub pressures: Vec<f64>,
}

impl Stroke {
    /// The stroke of a pressing, with the step set by the smallest one it took.
    pub fn of(pressing: &Pressing, h0: f64) -> Result<Stroke> {
        let r = &pressing.records;
        if r.len() < 2 {
            return Err(TampError::Other(
                "a stroke needs a pressing with at least two records".into(),
            ));
        }
        let interval = r[1].time - r[0].time;
        let smallest = r[1..].iter().map(|x| x.dt).fold(f64::INFINITY, f64::min);
        let steps_per_record = (interval / smallest).ceil() as u64;
        Ok(Stroke {
            h0,
            interval,
            steps_per_record,
            dt: interval / steps_per_record as f64,
            heights: r[1..].iter().map(|x| x.height).collect(),
            pressures: r[1..].iter().map(|x| x.pressure).collect(),
        })
    }

    /// Speed of the punch face along z during record interval k (0-based), m/s.
    pub fn speed(&self, k: usize) -> f64 {
        let before = if k == 0 { self.h0 } else { self.heights[k - 1] };
        (self.heights[k] - before) / self.interval
    }

    /// The displacement of the punch as an expression of t: Σ_k v_k clamp(t − t_k, 0, T).
    pub fn displacement(&self) -> String {
        let terms: Vec<String> = (0..self.heights.len())
            .map(|k| {
                format!(
                    "{:e} * min(max(t - {:e}, 0.0), {:e})",
                    self.speed(k),
                    k as f64 * self.interval,
                    self.interval
                )
            })
            .collect();
        terms.join(" + ")
    }
}

/// What a peer's replay of the pressing cannot carry: the press cycle after the peak,
/// which it would leave out without a word.
pub fn cycle_refusals(file: &DieCompactionFile) -> Vec<(String, String)> {
    match file.die_compaction.unload {
        Some(_) => vec![(
            "die_compaction.unload".into(),
            "the replay deck presses along tamp's stroke up to the peak; the press cycle after it (unload, eject, relax) is not exported: leave die_compaction.unload, eject and relax out to export the pressing".into(),
        )],
        None => Vec::new(),
    }
}

/// A die-compaction scene pressed in tamp, ready to be replayed by a peer code: the
/// flattened specimen, the stroke tamp pressed, and the press stage replaying it
/// under `solid`'s law (what the peer can express).
pub struct Pressed {
    /// The flattened specimen both codes press.
    pub specimen: Specimen,
    /// The punch stroke of tamp's pressing.
    pub stroke: Stroke,
    /// The press stage with the punch following the stroke, under the peer's law.
    pub replay: Scene,
}

/// Fill, flatten and press `file` in tamp (its own law and inertia), and set up the
/// replay of the recorded stroke under `solid`.
pub fn press_for_replay(file: &DieCompactionFile, solid: &DieCompactionFile) -> Result<Pressed> {
    let specimen = die_compaction::prepare(file, false)?;
    let pressing = die_compaction::press(file, &specimen, false, None, 0, &mut |_| Ok(()))?.0;
    let stroke = Stroke::of(&pressing, specimen.h0)?;
    let replay = replay_scene(solid, &specimen, &stroke)?;
    Ok(Pressed {
        specimen,
        stroke,
        replay,
    })
}

/// The file whose pressing a peer with `fix nve/sphere` (LIGGGHTS, LAMMPS) can
/// replay: `file` with the moment of inertia of a solid sphere, the only one that
/// integrator has. tamp's fill, flatten and pressed stroke keep the file's own
/// factor; both replays use this one.
pub fn solid_sphere_scene(file: &DieCompactionFile) -> DieCompactionFile {
    let mut s = file.clone();
    if let Some(r) = s.scene.rotation.as_mut() {
        r.inertia_scale = 1.0;
    }
    s
}

/// One record of a replay.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct ReplayRecord {
    /// Simulated time since the replay began, s.
    pub time: f64,
    /// Punch face height, m.
    pub height: f64,
    /// The particles' force on the punch along the pressing direction, over the die's
    /// cross-section, Pa.
    pub punch_pressure: f64,
    /// The particles' push on the floor over the die's cross-section, Pa.
    pub floor_pressure: f64,
    /// Solid fraction of the die cylinder up to the punch height H.
    pub density_specimen: f64,
    /// Solid fraction of the RVE sphere centred on the axis at H/2.
    pub density_rve: f64,
}

/// The press stage with the punch following `stroke` at its fixed step.
pub fn replay_scene(
    file: &DieCompactionFile,
    specimen: &Specimen,
    stroke: &Stroke,
) -> Result<Scene> {
    let mut s = die_compaction::press_scene(file, specimen)?;
    s.walls[PUNCH].motion = MotionSpec::Displacement {
        x: "0.0".into(),
        y: "0.0".into(),
        z: stroke.displacement(),
    };
    s.time_step.fixed = Some(stroke.dt);
    s.run.duration = Some(stroke.interval * stroke.heights.len() as f64);
    s.run.steps = None;
    crate::scene::validate::validate(&s)?;
    Ok(s)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::expression::Expression;

    #[test]
    fn the_displacement_passes_through_every_recorded_height() {
        let stroke = Stroke {
            h0: 6.0e-5,
            interval: 4e-6,
            steps_per_record: 100,
            dt: 4e-8,
            heights: vec![5.9e-5, 5.85e-5, 5.83e-5, 5.829e-5],
            pressures: vec![1e6, 2e6, 3e6, 4e6],
        };
        let u = Expression::parse(&stroke.displacement(), &["t"]).unwrap();
        for (k, h) in stroke.heights.iter().enumerate() {
            let t = (k + 1) as f64 * stroke.interval;
            let at = stroke.h0 + u.eval(&[t]).unwrap();
            assert!((at - h).abs() < 1e-15 * h, "record {k}: {at:e} vs {h:e}");
            // Halfway through a segment the punch is halfway between its ends.
            let before = if k == 0 {
                stroke.h0
            } else {
                stroke.heights[k - 1]
            };
            let mid = stroke.h0 + u.eval(&[t - 0.5 * stroke.interval]).unwrap();
            assert!((mid - 0.5 * (before + h)).abs() < 1e-15 * h);
        }
    }
}
