//! The press cycle after the peak: what a powder engineer does once the compact is
//! pressed, and what decides whether it survives: release the upper punch, push the
//! compact out of the die with the lower punch, and let it rest. Each stage is
//! optional and continues the pressing's own run, so every contact keeps its state
//! (the tangential springs at the die wall among them) from the peak on:
//!
//! 1. **Unload** (`unload`): the upper punch, released from its load, withdraws at
//!    `speed` until the particles no longer push on it. The compact's height is then
//!    H_r, the punch's face, and the axial springback is (H_r − H_p)/H_p against the
//!    height H_p at the peak. What the die wall still holds is the residual radial
//!    pressure, F_r/(π D H_r).
//! 2. **Eject** (`eject`): the upper punch is taken away; the lower punch (the die's
//!    floor) rises through the fixed die, its speed ramped linearly up to `speed` over
//!    `ramp_time`, until its face reaches the die's mouth, so the compact's bottom
//!    clears it. The die is filled to its brim: its mouth is the flattened specimen's
//!    top H₀. The ejection force is the particles'
//!    push on the lower punch, averaged over blocks of 100 steps (a single step's push
//!    carries single collisions); its work is ∫ F du over the punch's rise u, summed
//!    step by step. Once the compact slides, its force balance is F = μ_w F_r + M g +
//!    M a, with μ_w the die wall's friction, F_r the radial force on it and a the
//!    punch's acceleration on its speed ramp.
//! 3. **Relax** (`relax`): the free compact stands on the lower punch for `duration`.
//!
//! The radial springback is √(⟨ρ²⟩/⟨ρ²⟩_p) − 1, with ⟨ρ²⟩ the mean squared distance
//! of the particles' centres from the die's axis at the end and ⟨ρ²⟩_p at the peak:
//! the compact's radius of gyration about the axis, which a few particles thrown off
//! a cohesionless compact move little, where its envelope would follow them. While the
//! compact is pressed, the die wall's radial force gives Janssen's ratio of radial to
//! axial stress, K = σ_r/σ̄_z with σ_r = F_r/(π D H) and σ̄_z = (p_upper + p_lower)/2;
//! with the wall's friction fully mobilised, a slice dz of the compact loses
//! μ_w K σ_z π D dz of its axial force to the wall, so the axial stress decays down the
//! compact as exp(−4 μ_w K z/D) and the pressure transmission ratio is
//! p_lower/p_upper = exp(−4 μ_w K H/D) (Janssen's silo balance, 1895).
//!
//! Every record of the cycle (the pressing's included) gives both punches' pushes,
//! the die wall's axial friction and radial force, the radial force per height band
//! of the compact, the compact's height and density and the lower punch's rise.

use super::die_compaction::{Pressing, Specimen, densities_in, top_of_bed};
use super::die_compaction_file::DieCompactionFile;
use crate::boundary::BoundaryMotion;
use crate::contact::record::Partner;
use crate::error::{Errors, Result, TampError};
use crate::particles::Vec3;
use crate::progress::Progress;
use crate::simulation::Simulation;
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;
use std::fmt::Write as _;

/// The unload stage: the upper punch withdrawn at a constant speed.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct UnloadSpec {
    /// Speed at which the upper punch withdraws, m/s.
    pub speed: f64,
    /// Punch travel between records, m.
    pub record_interval: f64,
}

/// The eject stage: the lower punch pushing the compact out through the fixed die.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct EjectSpec {
    /// Speed at which the lower punch rises, m/s.
    pub speed: f64,
    /// Records at equal steps of the lower punch's rise.
    #[serde(default = "default_eject_records")]
    pub records: usize,
    /// Time over which the lower punch's speed rises linearly from zero, s (default:
    /// a tenth of the time the stroke takes at `speed`). A punch started at full speed
    /// strikes the compact, and a compact without cohesion flies apart.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ramp_time: Option<f64>,
}

impl EjectSpec {
    /// The speed ramp for a stroke of `stroke` m, s.
    pub fn ramp(&self, stroke: f64) -> f64 {
        self.ramp_time.unwrap_or(0.1 * stroke / self.speed)
    }

    /// The time after the start at which the lower punch has risen by `u`, s.
    pub fn time_to_rise(&self, u: f64, ramp: f64) -> f64 {
        let over_ramp = 0.5 * self.speed * ramp;
        if u <= over_ramp {
            (2.0 * u * ramp / self.speed).sqrt()
        } else {
            ramp + (u - over_ramp) / self.speed
        }
    }
}

/// The relax stage: the ejected compact left standing on the lower punch.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct RelaxSpec {
    /// How long the compact stands, s.
    pub duration: f64,
    /// Records at equal time intervals.
    #[serde(default = "default_relax_records")]
    pub records: usize,
}

fn default_eject_records() -> usize {
    50
}

fn default_relax_records() -> usize {
    10
}

/// The rules of the cycle's stages, at their paths in `die_compaction`.
pub(super) fn validate(file: &super::die_compaction_file::DieCompactionSpec, e: &mut Errors) {
    let at = |f: &str| format!("die_compaction.{f}");
    if let Some(u) = &file.unload {
        e.positive(at("unload.speed"), u.speed);
        e.positive(at("unload.record_interval"), u.record_interval);
    }
    if let Some(x) = &file.eject {
        e.positive(at("eject.speed"), x.speed);
        if let Some(t) = x.ramp_time {
            e.non_negative(at("eject.ramp_time"), t);
        }
        if x.records == 0 {
            e.push(at("eject.records"), "must be >= 1, got 0");
        }
        if file.unload.is_none() {
            e.push(
                at("eject"),
                "needs die_compaction.unload: the upper punch is withdrawn before the compact is pushed out",
            );
        }
    }
    if let Some(r) = &file.relax {
        e.positive(at("relax.duration"), r.duration);
        if r.records == 0 {
            e.push(at("relax.records"), "must be >= 1, got 0");
        }
        if file.eject.is_none() {
            e.push(
                at("relax"),
                "needs die_compaction.eject: only an ejected compact stands free",
            );
        }
    }
    if let Some(n) = file.die_bands {
        if n == 0 {
            e.push(at("die_bands"), "must be >= 1, got 0");
        }
        if file.unload.is_none() {
            e.push(
                at("die_bands"),
                "is measured in a press cycle only: give die_compaction.unload, or leave die_bands out",
            );
        }
    }
}

/// The walls of the press stage, in the order `die_compaction::press_scene` gives them.
pub(super) const DIE: usize = 0;
pub(super) const FLOOR: usize = 1;
pub(super) const PUNCH: usize = 2;

/// The die wall's radial push at one record.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct DieWall {
    /// Σ of the radial components of the particles' forces on the die wall, N.
    pub radial_force: f64,
    /// The radial force on each height band of the compact (floor to top, `die_bands`
    /// equal bands), as a pressure on the band's share of the wall, 2π R H/n, Pa.
    pub band_pressure: Vec<f64>,
}

impl DieWall {
    /// The contacts of wall `die` (the die's cylinder) at the present state, the
    /// compact of `height` standing on the floor at `floor_level`.
    pub fn of(
        sim: &Simulation,
        die: usize,
        die_radius: f64,
        floor_level: f64,
        height: f64,
        bands: usize,
    ) -> DieWall {
        let mut band_force = vec![0.0; bands];
        let mut radial_force = 0.0;
        for c in sim.contact_records() {
            if c.partner != Partner::Wall(die) {
                continue;
            }
            let rho = c.point.x.hypot(c.point.y);
            if rho == 0.0 {
                continue;
            }
            let outward = Vec3::new(c.point.x / rho, c.point.y / rho, 0.0);
            // The force on the wall is the opposite of the force on the particle.
            let on_wall = -(c.normal * c.normal_force + c.tangential_force);
            let radial = on_wall.dot(&outward);
            radial_force += radial;
            let k = ((c.point.z - floor_level) / height * bands as f64).floor();
            band_force[(k.max(0.0) as usize).min(bands - 1)] += radial;
        }
        let band_area = 2.0 * PI * die_radius * height / bands as f64;
        DieWall {
            radial_force,
            band_pressure: band_force.iter().map(|f| f / band_area).collect(),
        }
    }
}

/// The stage a record belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Stage {
    /// Under the rising load, up to the peak.
    Press,
    /// The upper punch withdrawing.
    Unload,
    /// The lower punch pushing the compact out.
    Eject,
    /// The free compact standing on the lower punch.
    Relax,
}

impl Stage {
    fn name(self) -> &'static str {
        match self {
            Stage::Press => "press",
            Stage::Unload => "unload",
            Stage::Eject => "eject",
            Stage::Relax => "relax",
        }
    }
}

/// One record of the cycle.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct CycleRecord {
    /// The stage the record was taken in.
    pub stage: Stage,
    /// Simulated time since the pressing began, s.
    pub time: f64,
    /// Steps since the pressing began.
    pub step: u64,
    /// The particles' push on the upper punch over the die's cross-section, Pa.
    pub upper_punch: f64,
    /// The particles' push on the lower punch (the floor) over the die's cross-section, Pa.
    pub lower_punch: f64,
    /// The particles' axial force on the die wall over the die's cross-section, Pa:
    /// positive when the powder drags the wall down (pressing), negative when the wall
    /// holds the compact back (ejection).
    pub die_friction: f64,
    /// The die wall's radial force, N.
    pub die_radial_force: f64,
    /// The radial force over the wall the compact touches, π D min(H, mouth − floor), Pa.
    pub die_radial_pressure: f64,
    /// The radial pressure per height band (`DieWall::band_pressure`), Pa.
    pub band_pressure: Vec<f64>,
    /// The compact's height above the lower punch: the upper punch's face while it
    /// touches, then the top of the highest particle, m.
    pub height: f64,
    /// Solid fraction of the die's cylinder over the lower punch up to `height`.
    pub density_specimen: f64,
    /// How far the lower punch has risen, m.
    pub ejection: f64,
    /// Number of particle–particle and particle–wall contacts.
    pub contact_count: usize,
}

/// `series.csv` of a cycle: one row per record, the bands last but one.
pub fn series_csv(records: &[CycleRecord]) -> String {
    let bands = records.first().map_or(0, |r| r.band_pressure.len());
    let mut s = String::from(
        "stage,time,step,upper_punch,lower_punch,die_friction,die_radial_force,die_radial_pressure",
    );
    for k in 1..=bands {
        let _ = write!(s, ",die_band_{k}");
    }
    s.push_str(",height,density_specimen,ejection,contact_count\n");
    for r in records {
        let _ = write!(
            s,
            "{},{},{},{},{},{},{},{}",
            r.stage.name(),
            r.time,
            r.step,
            r.upper_punch,
            r.lower_punch,
            r.die_friction,
            r.die_radial_force,
            r.die_radial_pressure
        );
        for p in &r.band_pressure {
            let _ = write!(s, ",{p}");
        }
        let _ = writeln!(
            s,
            ",{},{},{},{}",
            r.height, r.density_specimen, r.ejection, r.contact_count
        );
    }
    s
}

/// The records of several cycles in one table, each row led by its run's `label` in
/// a first column named `column` (the runs share their die's height bands).
pub fn labelled_series_csv(column: &str, runs: &[(&str, &Cycle)]) -> String {
    let mut out = String::new();
    for (k, (label, c)) in runs.iter().enumerate() {
        for (j, line) in series_csv(&c.records).lines().enumerate() {
            match (k, j) {
                (0, 0) => out.push_str(&format!("{column},{line}\n")),
                (_, 0) => {}
                _ => out.push_str(&format!("{label},{line}\n")),
            }
        }
    }
    out
}

/// What the cycle measures, each stage's when it ran.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
pub struct CycleSummary {
    /// Compact height at the peak (the upper punch's face), m.
    pub peak_height: f64,
    /// p_lower/p_upper at the peak.
    pub transmission_ratio: f64,
    /// Janssen's K = σ_r/σ̄_z at the peak.
    pub radial_to_axial_ratio: f64,
    /// Height at which the particles stopped pushing on the withdrawing upper punch, m.
    pub released_height: Option<f64>,
    /// (H_r − H_p)/H_p.
    pub axial_springback: Option<f64>,
    /// Work the particles did on the withdrawing upper punch until released, J.
    pub unloading_work: Option<f64>,
    /// Energy stored in the contacts at the peak and at release, J.
    pub stored_energy: Option<[f64; 2]>,
    /// Kinetic energy of the particles at the peak and at release, J.
    pub kinetic_energy: Option<[f64; 2]>,
    /// What the energy book counts as dissipated during the unloading, J.
    pub unloading_dissipation: Option<f64>,
    /// The die wall's radial force once the upper punch is released, N.
    pub residual_radial_force: Option<f64>,
    /// That force over the wall the compact touches, π D H_r, Pa.
    pub residual_radial_pressure: Option<f64>,
    /// Largest push of the particles on the lower punch while it ejects, each push
    /// averaged over a block of 100 steps, N.
    pub peak_ejection_force: Option<f64>,
    /// The lower punch's rise at the end of that block, m.
    pub peak_ejection_at: Option<f64>,
    /// The die wall's radial force at the end of that block, N.
    pub radial_force_at_peak_ejection: Option<f64>,
    /// Work the lower punch did on the compact over the ejection, J.
    pub ejection_work: Option<f64>,
    /// Compact height above the lower punch at the end, m.
    pub ejected_height: Option<f64>,
    /// √(⟨ρ²⟩/⟨ρ²⟩_p) − 1 at the end.
    pub radial_springback: Option<f64>,
}

impl CycleSummary {
    /// What the compact gives back to the withdrawing punch by the energy book: the
    /// energy its contacts stored at the peak less what they still store at release,
    /// with the change of the particles' kinetic energy, less what the book counts as
    /// dissipated while unloading (dashpots, friction, plastic flow). None without an
    /// unloading.
    pub fn returned_by_book(&self) -> Option<f64> {
        let (stored, kinetic) = (self.stored_energy?, self.kinetic_energy?);
        Some(stored[0] - stored[1] + kinetic[0] - kinetic[1] - self.unloading_dissipation?)
    }

    /// The summary by name, as `quantities.csv` lists it; stages that did not run are
    /// left out.
    pub fn quantities(&self) -> Vec<(String, f64)> {
        let fixed = [
            ("peak_height", Some(self.peak_height)),
            ("transmission_ratio", Some(self.transmission_ratio)),
            ("radial_to_axial_ratio", Some(self.radial_to_axial_ratio)),
            ("released_height", self.released_height),
            ("axial_springback", self.axial_springback),
            ("unloading_work", self.unloading_work),
            ("stored_energy_at_peak", self.stored_energy.map(|e| e[0])),
            ("stored_energy_released", self.stored_energy.map(|e| e[1])),
            ("kinetic_energy_at_peak", self.kinetic_energy.map(|e| e[0])),
            ("kinetic_energy_released", self.kinetic_energy.map(|e| e[1])),
            ("unloading_dissipation", self.unloading_dissipation),
            ("residual_radial_force", self.residual_radial_force),
            ("residual_radial_pressure", self.residual_radial_pressure),
            ("peak_ejection_force", self.peak_ejection_force),
            ("peak_ejection_at", self.peak_ejection_at),
            (
                "radial_force_at_peak_ejection",
                self.radial_force_at_peak_ejection,
            ),
            ("ejection_work", self.ejection_work),
            ("ejected_height", self.ejected_height),
            ("radial_springback", self.radial_springback),
        ];
        fixed
            .into_iter()
            .filter_map(|(name, v)| v.map(|v| (name.to_string(), v)))
            .collect()
    }
}

/// The whole cycle: its records and what they measure.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Cycle {
    /// The records, the pressing's first.
    pub records: Vec<CycleRecord>,
    /// What they measure.
    pub summary: CycleSummary,
}

/// The die's dimensions and how the cycle steps.
struct Die<'a> {
    file: &'a DieCompactionFile,
    radius: f64,
    area: f64,
    /// The die's mouth, H₀, which is also where the upper punch's face rests.
    mouth: f64,
    bands: usize,
    /// The pressing's fixed step, or none where it is re-estimated.
    fixed: Option<f64>,
    /// The step at the peak, the largest a re-estimated step may take in the cycle.
    peak_step: f64,
    alpha: f64,
}

/// The mean of the particles' squared distances from the die's axis, ⟨ρ²⟩, m²: the
/// compact's spread, whose growth after the peak is its radial springback.
pub(super) fn mean_square_radius(sim: &Simulation) -> f64 {
    let p = &sim.state().particles;
    let sum: f64 = p.position.iter().map(|x| x.x * x.x + x.y * x.y).sum();
    sum / p.len().max(1) as f64
}

impl Die<'_> {
    fn floor_level(sim: &Simulation) -> f64 {
        sim.state().walls[FLOOR].displacement.z
    }

    /// The upper punch's face, m.
    fn punch_face(&self, sim: &Simulation) -> f64 {
        self.mouth + sim.state().walls[PUNCH].displacement.z
    }

    fn record(&self, sim: &Simulation, stage: Stage) -> Result<CycleRecord> {
        let floor = Self::floor_level(sim);
        let height = match stage {
            Stage::Press | Stage::Unload => self.punch_face(sim),
            Stage::Eject | Stage::Relax => top_of_bed(sim),
        } - floor;
        let wall = DieWall::of(sim, DIE, self.radius, floor, height, self.bands);
        let p = &sim.state().particles;
        let above_floor: Vec<Vec3> = p.position.iter().map(|x| x - Vec3::z() * floor).collect();
        let (density, _) = densities_in(
            &above_floor,
            sim.state().material_radius(),
            2.0 * self.radius,
            self.file.die_compaction.rve_diameter,
            height,
        )?;
        let force = &sim.state().wall_force;
        let in_die = height.min(self.mouth - floor).max(0.0);
        Ok(CycleRecord {
            stage,
            time: sim.state().time,
            step: sim.state().step,
            upper_punch: force[PUNCH].z / self.area,
            lower_punch: -force[FLOOR].z / self.area,
            die_friction: -force[DIE].z / self.area,
            die_radial_force: wall.radial_force,
            die_radial_pressure: if in_die > 0.0 {
                wall.radial_force / (2.0 * PI * self.radius * in_die)
            } else {
                0.0
            },
            band_pressure: wall.band_pressure,
            height,
            density_specimen: density,
            ejection: floor,
            contact_count: sim.contact_count(),
        })
    }

    /// One step of the cycle, landing on `due` when it is nearer than a step, the step
    /// fixed or re-estimated as in the pressing.
    fn step(&self, sim: &mut Simulation, due: f64) -> Result<()> {
        let dt = match self.fixed {
            Some(dt) => dt,
            None => {
                let every = self.file.die_compaction.press.dt_every;
                // Never above the step at the peak, the stiffest the compact gets: once
                // released, its contacts soften and part, and a step grown on the few
                // left would meet the next collision too coarse.
                if sim.state().step.is_multiple_of(every)
                    && let Some(dt_cr) = sim.critical_time_step(None)
                {
                    sim.set_time_step((self.alpha * dt_cr).min(self.peak_step))?;
                }
                sim.dt()
            }
        };
        sim.set_time_step(dt.min(due - sim.state().time).max(1e-12 * dt))?;
        sim.step()?;
        sim.set_time_step(dt)?;
        if let Some(signal) = crate::interrupt::received() {
            return Err(TampError::Interrupted {
                signal,
                step: sim.state().step,
                time: sim.state().time,
                next: "the cycle after the peak is not checkpointed: a run resumed from the pressing's checkpoint (output.checkpoint_every) starts it again at the peak".into(),
            });
        }
        Ok(())
    }
}

/// Go on from the peak (`die_compaction::press`) through the file's stages.
pub fn run(
    file: &DieCompactionFile,
    specimen: &Specimen,
    pressing: &Pressing,
    mut sim: Simulation,
    fixed_step: Option<f64>,
    quiet: bool,
) -> Result<Cycle> {
    let dc = &file.die_compaction;
    let die = Die {
        file,
        radius: 0.5 * dc.die_diameter,
        area: PI * (0.5 * dc.die_diameter).powi(2),
        mouth: specimen.h0,
        bands: dc.die_bands().unwrap_or(1),
        fixed: fixed_step,
        peak_step: sim.dt(),
        alpha: file.scene.time_step.alpha(),
    };
    let mut records: Vec<CycleRecord> = pressing
        .records
        .iter()
        .zip(&pressing.die_wall)
        .map(|(r, w)| CycleRecord {
            stage: Stage::Press,
            time: r.time,
            step: r.step,
            upper_punch: r.punch_reaction,
            lower_punch: r.floor_reaction,
            die_friction: r.die_friction,
            die_radial_force: w.radial_force,
            die_radial_pressure: w.radial_force / (2.0 * PI * die.radius * r.height),
            band_pressure: w.band_pressure.clone(),
            height: r.height,
            density_specimen: r.density_specimen,
            ejection: 0.0,
            contact_count: r.contact_count,
        })
        .collect();
    let peak = records
        .last()
        .cloned()
        .ok_or_else(|| TampError::Other("the pressing made no records".into()))?;
    if !(peak.upper_punch > 0.0 && peak.lower_punch + peak.upper_punch > 0.0) {
        return Err(TampError::Other(format!(
            "the upper punch carries no load at the peak (step {}, {:e} Pa): the cycle's ratios would be undefined",
            peak.step, peak.upper_punch
        )));
    }
    let peak_spread = mean_square_radius(&sim);
    let mean_axial = 0.5 * (peak.upper_punch + peak.lower_punch);
    let mut summary = CycleSummary {
        peak_height: peak.height,
        transmission_ratio: peak.lower_punch / peak.upper_punch,
        radial_to_axial_ratio: peak.die_radial_pressure / mean_axial,
        ..Default::default()
    };

    if let Some(unload) = &dc.unload {
        unload_stage(&die, &mut sim, unload, &mut records, &mut summary, quiet)?;
    }
    if let Some(eject) = &dc.eject {
        eject_stage(&die, &mut sim, eject, &mut records, &mut summary, quiet)?;
    }
    if let Some(relax) = &dc.relax {
        let start = sim.state().time;
        let mut progress = Progress::new("relax", relax.records as u64, quiet);
        for k in 1..=relax.records {
            let due = start + relax.duration * k as f64 / relax.records as f64;
            while sim.state().time < due * (1.0 - 1e-12) {
                die.step(&mut sim, due)?;
            }
            records.push(die.record(&sim, Stage::Relax)?);
            progress.set(k as u64);
        }
        progress.finish();
    }
    if dc.eject.is_some() {
        let last = records.last().expect("the ejection recorded");
        summary.ejected_height = Some(last.height);
        summary.radial_springback = Some((mean_square_radius(&sim) / peak_spread).sqrt() - 1.0);
    }
    sim.check_energy_at_end()?;
    Ok(Cycle { records, summary })
}

/// Withdraw the upper punch until the particles no longer push on it.
fn unload_stage(
    die: &Die,
    sim: &mut Simulation,
    unload: &UnloadSpec,
    records: &mut Vec<CycleRecord>,
    summary: &mut CycleSummary,
    quiet: bool,
) -> Result<()> {
    sim.set_wall_motion(PUNCH, BoundaryMotion::Velocity(Vec3::z() * unload.speed));
    let interval = unload.record_interval / unload.speed;
    let start = sim.state().time;
    let (stored, kinetic, dissipated) = (
        sim.stored_energy(),
        sim.kinetic_energy(),
        sim.dissipated_energy(),
    );
    let mut work = 0.0;
    let mut k = 1u64;
    loop {
        let due = start + interval * k as f64;
        let (face, push) = (die.punch_face(sim), sim.state().wall_force[PUNCH].z);
        die.step(sim, due)?;
        work += 0.5 * (push + sim.state().wall_force[PUNCH].z) * (die.punch_face(sim) - face);
        let released = sim.state().wall_force[PUNCH].z <= 0.0;
        if released {
            summary.unloading_work = Some(work);
            summary.stored_energy = Some([stored, sim.stored_energy()]);
            summary.kinetic_energy = Some([kinetic, sim.kinetic_energy()]);
            summary.unloading_dissipation = Some(sim.dissipated_energy() - dissipated);
            let r = die.record(sim, Stage::Unload)?;
            summary.released_height = Some(r.height);
            summary.axial_springback = Some((r.height - summary.peak_height) / summary.peak_height);
            summary.residual_radial_force = Some(r.die_radial_force);
            summary.residual_radial_pressure = Some(r.die_radial_pressure);
            records.push(r);
            break;
        }
        if sim.state().time >= due * (1.0 - 1e-12) {
            records.push(die.record(sim, Stage::Unload)?);
            k += 1;
        }
        if die.punch_face(sim) >= die.mouth {
            return Err(TampError::input(
                "die_compaction.unload",
                format!(
                    "the compact still pushes on the upper punch at the die's mouth ({:e} m, step {}): it springs back out of the die",
                    die.mouth,
                    sim.state().step
                ),
            ));
        }
    }
    if !quiet {
        eprintln!(
            "unload: released at H = {:e} m after {} records",
            summary.released_height.unwrap_or(f64::NAN),
            k
        );
    }
    Ok(())
}

/// Steps over which the lower punch's push is averaged into the ejection force.
const EJECTION_BLOCK: u64 = 100;

/// Take the upper punch away and push the compact out with the lower punch.
fn eject_stage(
    die: &Die,
    sim: &mut Simulation,
    eject: &EjectSpec,
    records: &mut Vec<CycleRecord>,
    summary: &mut CycleSummary,
    quiet: bool,
) -> Result<()> {
    // Far above anything the compact reaches: its bottom rises to the mouth, and no
    // compact is taller than the specimen it was pressed from.
    sim.place_wall(PUNCH, Vec3::z() * (2.0 * die.mouth));
    sim.set_wall_motion(PUNCH, BoundaryMotion::Fixed);
    records.push(die.record(sim, Stage::Eject)?);
    let (start, ramp) = (sim.state().time, eject.ramp(die.mouth));
    let (mut peak, mut peak_at, mut radial_at_peak) = (0.0f64, 0.0, 0.0);
    let (mut block_sum, mut block_steps) = (0.0, 0u64);
    let mut work = 0.0;
    let mut progress = Progress::new("eject", eject.records as u64, quiet);
    for k in 1..=eject.records {
        let rise = die.mouth * k as f64 / eject.records as f64;
        let due = start + eject.time_to_rise(rise, ramp);
        while sim.state().time < due * (1.0 - 1e-12) {
            // The speed over the step is the ramp's at the step's middle, so the rise
            // is the ramp's exactly where it is linear in time.
            let middle = sim.state().time - start + 0.5 * sim.dt().min(due - sim.state().time);
            let speed = eject.speed
                * if ramp > 0.0 {
                    (middle / ramp).min(1.0)
                } else {
                    1.0
                };
            sim.set_wall_motion(FLOOR, BoundaryMotion::Velocity(Vec3::z() * speed));
            let before = Die::floor_level(sim);
            let push_before = -sim.state().wall_force[FLOOR].z;
            die.step(sim, due)?;
            let push = -sim.state().wall_force[FLOOR].z;
            let rise = Die::floor_level(sim) - before;
            work += 0.5 * (push_before + push) * rise;
            // The push of one step carries the single collisions of the particles on
            // the punch (a few per cent of it); the ejection force is its mean over
            // blocks of EJECTION_BLOCK steps, and the radial force is measured at the
            // end of the block with the largest mean.
            block_sum += push;
            block_steps += 1;
            if block_steps == EJECTION_BLOCK {
                let mean = block_sum / block_steps as f64;
                (block_sum, block_steps) = (0.0, 0);
                if mean > peak {
                    peak = mean;
                    let floor = Die::floor_level(sim);
                    peak_at = floor;
                    let height = top_of_bed(sim) - floor;
                    radial_at_peak =
                        DieWall::of(sim, DIE, die.radius, floor, height, 1).radial_force;
                }
            }
        }
        records.push(die.record(sim, Stage::Eject)?);
        progress.set(k as u64);
    }
    progress.finish();
    sim.set_wall_motion(FLOOR, BoundaryMotion::Fixed);
    summary.peak_ejection_force = Some(peak);
    summary.peak_ejection_at = Some(peak_at);
    summary.radial_force_at_peak_ejection = Some(radial_at_peak);
    summary.ejection_work = Some(work);
    Ok(())
}
