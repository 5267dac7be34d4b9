//! The press cycle replayed: pressing, unloading and ejection as prescribed wall
//! displacements, so that a peer code can take a specimen through the cycle tamp took
//! it through and the two codes' wall forces can be compared record by record.
//!
//! tamp's own cycle (`press_cycle`) is load-controlled where a peer has no such
//! control: the punch presses under a pressure ramp and is withdrawn until the
//! particles stop pushing on it. The replay fixes both to what tamp's run did, in
//! steps of the pressing's fixed Δt (`die_replay::Stroke`):
//! - press, steps 0 … N_p: the punch face through the recorded heights (the stroke);
//! - unload, steps N_p … N_e = N_p + N_u: the punch rises at the unloading speed v_u
//!   for the N_u steps tamp took to release the compact (rounded up to a record);
//! - eject, steps after N_e: the punch is taken far above the die in one step, and the
//!   lower punch (the floor) rises by u(t') = v (min(t', T_r)² / (2 T_r) +
//!   max(t' − T_r, 0)) with t' = t − N_e Δt, capped at the die's mouth H₀: the linear
//!   speed ramp of `press_cycle`'s ejection.
//!
//! Every position is a function of the step alone, so the same motion is written once
//! for tamp (`displacement` motions, whose chord over a step is the wall's velocity,
//! `boundary::advance`) and once for LAMMPS (region `move` variables, the same chord,
//! `lammps::die_compaction`). The die is the cylinder from the floor's rest level to
//! the mouth H₀.
//!
//! A replay records every K steps (`record_steps`, dividing the stroke's steps per
//! record, so that the peak is a record, and every stage's length): the walls' axial
//! forces, the lower punch's push averaged over the K steps before the record (the
//! single collisions on the punch averaged out, as `press_cycle` does), the die
//! wall's radial force, and the compact's spread ⟨ρ²⟩ and top. `quantities` measures
//! the cycle from those records alone, the same function for both codes.

use super::die_compaction::{Pressing, Specimen, top_of_bed};
use super::die_compaction_file::DieCompactionFile;
use super::die_replay::{self, Stroke};
use super::press_cycle::{Cycle, DieWall, Stage, mean_square_radius};
use crate::error::{Result, TampError};
use crate::scene::walls::MotionSpec;
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// The walls of the press stage, in the order `die_compaction::press_scene` gives them.
const DIE: usize = 0;
const FLOOR: usize = 1;
const PUNCH: usize = 2;

/// The longest record interval of a replay, in steps.
const MOST_STEPS_PER_RECORD: u64 = 400;

/// How far above the mouth the punch is taken for the ejection, in units of H₀:
/// above the ejected compact, which no stage lets grow past twice the specimen.
const PUNCH_AWAY: f64 = 2.0;

/// The whole cycle as prescribed displacements at a fixed step.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CycleStroke {
    /// The pressing's stroke (its `dt` is the replay's step).
    pub press: Stroke,
    /// The punch's rise per step while unloading, m.
    pub unload_rise_per_step: f64,
    /// Steps of the unloading, N_u.
    pub unload_steps: u64,
    /// The lower punch's final speed, m/s.
    pub eject_speed: f64,
    /// The time over which it is reached, T_r, s.
    pub eject_ramp: f64,
    /// Steps of the ejection.
    pub eject_steps: u64,
    /// Steps between records, K.
    pub record_steps: u64,
}

impl CycleStroke {
    /// The replay of tamp's cycle of `file`: `pressing` its pressing, `cycle` what
    /// followed, `h0` the specimen's height.
    pub fn of(
        file: &DieCompactionFile,
        pressing: &Pressing,
        cycle: &Cycle,
        h0: f64,
    ) -> Result<CycleStroke> {
        let dc = &file.die_compaction;
        let (Some(unload), Some(eject)) = (&dc.unload, &dc.eject) else {
            return Err(TampError::Other(
                "a cycle replay needs die_compaction.unload and eject".into(),
            ));
        };
        let press = Stroke::of(pressing, h0)?;
        let dt = press.dt;
        let k = (1..=MOST_STEPS_PER_RECORD.min(press.steps_per_record))
            .rev()
            .find(|k| press.steps_per_record.is_multiple_of(*k))
            .unwrap_or(1);
        let whole = |steps: f64| (steps / k as f64).ceil() as u64 * k;
        let peak = pressing
            .records
            .last()
            .ok_or_else(|| TampError::Other("the pressing made no records".into()))?
            .time;
        let released = cycle
            .records
            .iter()
            .rfind(|r| r.stage == Stage::Unload)
            .ok_or_else(|| TampError::Other("the cycle has no unloading".into()))?
            .time;
        let ramp = eject.ramp(h0);
        Ok(CycleStroke {
            unload_rise_per_step: unload.speed * dt,
            unload_steps: whole((released - peak) / dt),
            eject_speed: eject.speed,
            eject_ramp: ramp,
            eject_steps: whole(eject.time_to_rise(h0, ramp) / dt),
            record_steps: k,
            press,
        })
    }

    /// Steps of the pressing, N_p.
    pub fn press_steps(&self) -> u64 {
        self.press.steps_per_record * self.press.heights.len() as u64
    }

    /// The step the ejection starts at, N_e.
    pub fn unload_end(&self) -> u64 {
        self.press_steps() + self.unload_steps
    }

    /// Steps of the whole replay.
    pub fn steps(&self) -> u64 {
        self.unload_end() + self.eject_steps
    }

    /// The punch's jump at the start of the ejection, m.
    pub fn punch_away(&self) -> f64 {
        PUNCH_AWAY * self.press.h0
    }

    /// The punch face's displacement from H₀ as an expression of t: the stroke, the
    /// unloading's constant rise, and the jump away over the ejection's first step
    /// (0 until N_e and 1 from N_e + 1 with half a step to spare either side, since
    /// t is the running sum of the steps and may stray from k Δt by a few ulps).
    pub fn punch_expression(&self) -> String {
        let dt = self.press.dt;
        let (tp, tu) = (
            self.press_steps() as f64 * dt,
            self.unload_steps as f64 * dt,
        );
        format!(
            "{} + {:e} * min(max(t - {tp:e}, 0.0), {tu:e}) + {:e} * min(max(2.0 * (t - {:e}) / {dt:e} - 0.5, 0.0), 1.0)",
            self.press.displacement(),
            self.unload_rise_per_step / dt,
            self.punch_away(),
            tp + tu,
        )
    }

    /// The lower punch's rise as an expression of t: the ramped ejection, capped at
    /// the mouth.
    pub fn floor_expression(&self) -> String {
        let te = self.unload_end() as f64 * self.press.dt;
        let (v, tr, h0) = (self.eject_speed, self.eject_ramp, self.press.h0);
        let ramped = match tr > 0.0 {
            true => format!("min(max(t - {te:e}, 0.0), {tr:e})^2 / {:e}", 2.0 * tr),
            false => "0.0".into(),
        };
        format!(
            "min({v:e} * ({ramped} + max(t - {:e}, 0.0)), {h0:e})",
            te + tr
        )
    }
}

/// One record of a replayed cycle. Forces are the particles' on the walls, N.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CycleReplayRecord {
    /// The step the record was taken after.
    pub step: u64,
    /// The upper punch's face, m.
    pub punch_face: f64,
    /// The lower punch's rise, m.
    pub floor_rise: f64,
    /// The push on the upper punch, upwards.
    pub punch_force: f64,
    /// The push on the lower punch, downwards.
    pub floor_force: f64,
    /// `floor_force` averaged over the K steps that end at this record (0 at step 0).
    pub floor_force_mean: f64,
    /// The particles' drag on the die along z (upwards positive).
    pub die_axial_force: f64,
    /// The sum of the radial components of their push on the die, outwards.
    pub die_radial_force: f64,
    /// ⟨ρ²⟩, the particles' mean squared distance from the axis, m².
    pub mean_square_radius: f64,
    /// The highest particle's top, m.
    pub top: f64,
}

/// Fill, flatten, press and take `file` through its cycle in tamp, and the replay of
/// that cycle: what a peer's deck is written from.
pub fn cycle_for_replay(file: &DieCompactionFile) -> Result<(Specimen, CycleStroke)> {
    let specimen = super::die_compaction::prepare(file, false)?;
    let fixed = super::die_compaction::press_scene(file, &specimen)?
        .time_step
        .fixed;
    let (pressing, sim) =
        super::die_compaction::press(file, &specimen, false, None, 0, &mut |_| Ok(()))?;
    let cycle = super::press_cycle::run(file, &specimen, &pressing, sim, fixed, false)?;
    let stroke = CycleStroke::of(file, &pressing, &cycle, specimen.h0)?;
    Ok((specimen, stroke))
}

/// tamp's replay of `cycle` on `specimen`, under `file`'s law with the solid sphere's
/// inertia (what `fix nve/sphere` integrates), recorded every K steps.
pub fn replay(
    file: &DieCompactionFile,
    specimen: &Specimen,
    cycle: &CycleStroke,
) -> Result<Vec<CycleReplayRecord>> {
    let solid = die_replay::solid_sphere_scene(file);
    let mut scene = die_replay::replay_scene(&solid, specimen, &cycle.press)?;
    let z = |e: String| MotionSpec::Displacement {
        x: "0.0".into(),
        y: "0.0".into(),
        z: e,
    };
    scene.walls[PUNCH].motion = z(cycle.punch_expression());
    scene.walls[FLOOR].motion = z(cycle.floor_expression());
    scene.run.duration = None;
    scene.run.steps = Some(cycle.steps());
    crate::scene::validate::validate(&scene)?;
    let mut sim = crate::scene::build(&scene)?.sim;
    let radius = 0.5 * file.die_compaction.die_diameter;
    let h0 = specimen.h0;
    let k = cycle.record_steps;
    let record = |sim: &crate::simulation::Simulation, mean: f64| {
        let s = sim.state();
        CycleReplayRecord {
            step: s.step,
            punch_face: h0 + s.walls[PUNCH].displacement.z,
            floor_rise: s.walls[FLOOR].displacement.z,
            punch_force: s.wall_force[PUNCH].z,
            floor_force: -s.wall_force[FLOOR].z,
            floor_force_mean: mean,
            die_axial_force: s.wall_force[DIE].z,
            die_radial_force: DieWall::of(sim, DIE, radius, 0.0, h0, 1).radial_force,
            mean_square_radius: mean_square_radius(sim),
            top: top_of_bed(sim),
        }
    };
    let mut out = vec![record(&sim, 0.0)];
    let mut block = 0.0;
    while sim.state().step < cycle.steps() {
        sim.step()?;
        block -= sim.state().wall_force[FLOOR].z;
        if sim.state().step.is_multiple_of(k) {
            out.push(record(&sim, block / k as f64));
            block = 0.0;
        }
        if let Some(signal) = crate::interrupt::received() {
            return Err(TampError::Interrupted {
                signal,
                step: sim.state().step,
                time: sim.state().time,
                next: "a replay is not checkpointed: it starts again".into(),
            });
        }
    }
    Ok(out)
}

/// What a replayed cycle measures, from its records alone (`die_radius` R, the
/// specimen's `h0`), by name: at the peak (step N_p) the transmission ratio
/// F_lower/F_upper and Janssen's K = (F_r / 2πR H) / (½(F_upper + F_lower) / πR²); the
/// work the compact returns to the withdrawing punch, ∫F dH over the unloading
/// (trapezoids between records); the die's residual radial force at the release
/// (step N_e); the largest K-step mean push of the lower punch during the ejection
/// and its work Σ F̄ Δu; and after it the compact's height (top less the lower
/// punch) and radial springback √(⟨ρ²⟩/⟨ρ²⟩_peak) − 1.
pub fn quantities(
    records: &[CycleReplayRecord],
    cycle: &CycleStroke,
    die_radius: f64,
) -> Result<Vec<(String, f64)>> {
    let at = |step: u64| {
        records
            .iter()
            .find(|r| r.step == step)
            .ok_or_else(|| TampError::Other(format!("the replay has no record at step {step}")))
    };
    let (peak, released) = (at(cycle.press_steps())?, at(cycle.unload_end())?);
    let last = at(cycle.steps())?;
    let area = PI * die_radius * die_radius;
    let radial_pressure = peak.die_radial_force / (2.0 * PI * die_radius * peak.punch_face);
    let axial = 0.5 * (peak.punch_force + peak.floor_force) / area;
    let stage = |from: u64, to: u64| {
        records
            .windows(2)
            .filter(move |w| w[0].step >= from && w[1].step <= to)
    };
    let unloading_work: f64 = stage(peak.step, released.step)
        .map(|w| 0.5 * (w[0].punch_force + w[1].punch_force) * (w[1].punch_face - w[0].punch_face))
        .sum();
    let ejection: Vec<&[CycleReplayRecord]> = stage(released.step, last.step).collect();
    let peak_ejection = ejection
        .iter()
        .map(|w| w[1].floor_force_mean)
        .fold(0.0, f64::max);
    let ejection_work: f64 = ejection
        .iter()
        .map(|w| w[1].floor_force_mean * (w[1].floor_rise - w[0].floor_rise))
        .sum();
    Ok(vec![
        (
            "transmission_ratio".into(),
            peak.floor_force / peak.punch_force,
        ),
        ("radial_to_axial_ratio".into(), radial_pressure / axial),
        ("unloading_work".into(), unloading_work),
        ("residual_radial_force".into(), released.die_radial_force),
        ("peak_ejection_force".into(), peak_ejection),
        ("ejection_work".into(), ejection_work),
        ("ejected_height".into(), last.top - last.floor_rise),
        (
            "radial_springback".into(),
            (last.mean_square_radius / peak.mean_square_radius).sqrt() - 1.0,
        ),
    ])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::expression::Expression;

    fn cycle() -> CycleStroke {
        CycleStroke {
            press: Stroke {
                h0: 3e-5,
                interval: 4e-8,
                steps_per_record: 400,
                dt: 1e-10,
                heights: vec![2.99e-5, 2.98e-5],
                pressures: vec![1e6, 2e6],
            },
            unload_rise_per_step: 5e-12,
            unload_steps: 800,
            eject_speed: 0.5,
            eject_ramp: 2e-8,
            eject_steps: 600_400,
            record_steps: 400,
        }
    }

    /// The expressions tamp moves the walls by are the motion the docs describe:
    /// the recorded heights, the unloading rise, the jump, the ramped ejection.
    #[test]
    fn the_walls_follow_the_three_stages() {
        let c = cycle();
        let punch = Expression::parse(&c.punch_expression(), &["t"]).unwrap();
        let floor = Expression::parse(&c.floor_expression(), &["t"]).unwrap();
        let dt = c.press.dt;
        let at = |e: &Expression, s: u64| e.eval(&[s as f64 * dt]).unwrap();
        let h = |s| c.press.h0 + at(&punch, s);
        assert!((h(400) - 2.99e-5).abs() < 1e-18);
        assert!((h(800) - 2.98e-5).abs() < 1e-18);
        assert!((h(1600) - (2.98e-5 + 800.0 * 5e-12)).abs() < 1e-18);
        assert!((h(1601) - (2.98e-5 + 4e-9 + c.punch_away())).abs() < 1e-18);
        assert_eq!(at(&floor, 1600), 0.0);
        // Halfway up the ramp: v t'^2 / (2 T_r); past it: v (t' - T_r / 2).
        assert!((at(&floor, 1700) - 0.5 * 1e-8 * 1e-8 / 4e-8).abs() < 1e-20);
        assert!((at(&floor, 1600 + 10_000) - 0.5 * (1e-6 - 1e-8)).abs() < 1e-18);
        assert_eq!(at(&floor, c.steps()), c.press.h0);
    }
}
