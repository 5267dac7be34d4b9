//! `nial_die_compaction_small`: the die compaction of Rojek et al. 2016 §5 at 300
//! particles, pressed on any engine. What must hold of any die compaction, whatever
//! the packing:
//! - the specimen density never falls while the pressure rises (the RVE density may:
//!   its sphere follows the specimen's centre down, and in a 28 µm RVE one particle
//!   of up to 18 µm entering or leaving moves it by 4e-3, which seed 1 shows);
//! - the punch carries the applied pressure, and the floor and die wall carry what
//!   the punch transmits (Newton's third law through the bed, up to the bed's and
//!   punch's inertia);
//! - no particle centre leaves the die;
//! - the settled density does not depend on the gravity scale used to fill.
//!
//! The fill and flatten are the scene's preparation, made by tamp for every engine as
//! a deposition is (`die_specimen`): the engine is given the flattened specimen, the
//! die, the floor and the pressure-loaded punch of mass `press.punch_mass` as a
//! resolved scene at the fixed step `press.time_step`, and records ten frames per
//! record interval with the walls' displacements and forces. Everything below is
//! measured from those frames: the punch height from its displacement, the densities
//! from the particles' positions and radii at that height, the pressures from the
//! walls' forces, containment at every frame.

use super::nial_die_compaction::{
    largest_drop, largest_imbalance, mpa, poured_point, write_curves_csv,
};
use crate::error::{Result, TampError};
use crate::particles::Vec3;
use crate::plot::{Panel, Series, write_svg};
use crate::process::die_compaction::{self, PressRecord, Pressing, densities_in, wall_lens_volume};
use crate::process::die_compaction_file::DieCompactionFile;
use crate::verify::recording::{Frame, RecordSpec, Recording};
use crate::verify::{CaseContext, Measured};
use std::f64::consts::PI;

/// Frames per record interval: the records, and containment between them.
const FRAMES_PER_RECORD: u64 = 10;

/// The press stage's walls, by the names `die_compaction::press_scene` gives them.
pub(super) struct Walls {
    pub die: usize,
    pub floor: usize,
    pub punch: usize,
}

impl Walls {
    pub(super) fn of(scene: &crate::scene::Scene) -> Result<Walls> {
        let find = |name: &str| {
            scene
                .walls
                .iter()
                .position(|w| w.name.as_deref() == Some(name))
                .ok_or_else(|| TampError::Other(format!("the press stage has no wall '{name}'")))
        };
        Ok(Walls {
            die: find("die")?,
            floor: find("floor")?,
            punch: find("punch")?,
        })
    }
}

/// The press stage, as measured from the recorded frames: a record at every
/// `per_record`-th step, and the particles found outside the die at any frame.
fn pressing(
    file: &DieCompactionFile,
    h0: f64,
    walls: &Walls,
    rec: &Recording,
    per_record: u64,
) -> Result<Pressing> {
    let dc = &file.die_compaction;
    let area = PI * (0.5 * dc.die_diameter).powi(2);
    let die_radius = 0.5 * dc.die_diameter;
    let height = |f: &Frame| h0 + f.walls[walls.punch].displacement.z;
    let mut records = Vec::with_capacity(dc.press.records + 1);
    let mut escaped = Vec::new();
    let radii = super::die_compaction_replay::material_radii(rec)?;
    for f in &rec.frames {
        let h = height(f);
        for (i, b) in f.bodies.iter().enumerate() {
            let x = b.position;
            if (x.x.hypot(x.y) > die_radius || x.z < 0.0 || x.z > h) && !escaped.contains(&i) {
                escaped.push(i);
            }
        }
        if !f.step.is_multiple_of(per_record) {
            continue;
        }
        let positions: Vec<Vec3> = f.bodies.iter().map(|b| b.position).collect();
        let (density_specimen, density_rve) =
            densities_in(&positions, &radii, dc.die_diameter, dc.rve_diameter, h)?;
        let force = |k: usize| f.walls[k].force.z / area;
        // The file's clock, step · Δt, on every engine: tamp's own sums the steps and
        // differs from it by round-off, which would be all the engines differ by.
        let time = f.step as f64 * rec.dt;
        records.push(PressRecord {
            time,
            pressure: dc.press.pressure * (time / dc.press.ramp_time).min(1.0),
            punch_reaction: force(walls.punch),
            floor_reaction: -force(walls.floor),
            die_friction: -force(walls.die),
            height: h,
            height_reduction: (h0 - h) / h0,
            density_specimen,
            density_rve,
            wall_lens_volume: wall_lens_volume(&positions, &radii, die_radius, h),
            contact_count: contacts(f, die_radius, h).len(),
            dt: rec.dt,
            step: f.step,
        });
    }
    if records.len() != dc.press.records + 1 {
        return Err(TampError::Other(format!(
            "the recording holds {} records of the {} the press makes",
            records.len(),
            dc.press.records + 1
        )));
    }
    Ok(Pressing {
        records,
        steps: rec.frames.last().map_or(0, |f| f.step),
        escaped,
        die_wall: Vec::new(),
    })
}

/// A contact found from a frame's geometry: its two ends (centre to centre, or centre
/// to the contact point on a wall), the point, and the Hertz force up to the factor
/// 4/3 E* the scene's one material gives every contact, √R* δ^{3/2}.
struct GeometricContact {
    ends: [Vec3; 2],
    point: Vec3,
    force: f64,
}

/// The overlapping pairs and the particles pressed into the floor (z = 0), the punch
/// face (z = height) and the die wall (radius R; the wall's R* taken as the particle's,
/// the flat die of the fill).
fn contacts(f: &Frame, die_radius: f64, height: f64) -> Vec<GeometricContact> {
    let hertz = |r_eff: f64, delta: f64| r_eff.sqrt() * delta.powf(1.5);
    let mut out = Vec::new();
    let b = &f.bodies;
    for i in 0..b.len() {
        for j in i + 1..b.len() {
            let d = b[j].position - b[i].position;
            let delta = b[i].radius + b[j].radius - d.norm();
            if delta > 0.0 {
                let r_eff = b[i].radius * b[j].radius / (b[i].radius + b[j].radius);
                out.push(GeometricContact {
                    ends: [b[i].position, b[j].position],
                    point: b[i].position + d * (b[i].radius - 0.5 * delta) / d.norm(),
                    force: hertz(r_eff, delta),
                });
            }
        }
        let (x, r) = (b[i].position, b[i].radius);
        let rho = x.x.hypot(x.y);
        let outward = match rho > 0.0 {
            true => Vec3::new(x.x / rho, x.y / rho, 0.0),
            false => Vec3::x(),
        };
        for (delta, touch) in [
            (r - x.z, Vec3::new(x.x, x.y, 0.0)),
            (x.z + r - height, Vec3::new(x.x, x.y, height)),
            (rho + r - die_radius, outward * die_radius + Vec3::z() * x.z),
        ] {
            if delta > 0.0 {
                out.push(GeometricContact {
                    ends: [x, touch],
                    point: touch,
                    force: hertz(r, delta),
                });
            }
        }
    }
    out
}

/// The force chains at the full pressure (Zhong 2009 §5 lists them among a DEM
/// system's views): the contacts of the last frame whose contact point lies in a slab
/// through the die's axis, |y| < the specimen's mean particle radius, drawn to scale in
/// the x–z plane, each line 1–8 px wide in proportion to its Hertz force.
fn write_force_chains(
    ctx: &CaseContext,
    die_radius: f64,
    last: &Frame,
    record: &PressRecord,
) -> Result<()> {
    let n = last.bodies.len().max(1) as f64;
    let half_width = last.bodies.iter().map(|b| b.radius).sum::<f64>() / n;
    let all = contacts(last, die_radius, record.height);
    let slice: Vec<_> = all
        .iter()
        .filter(|c| c.point.y.abs() < half_width)
        .collect();
    let largest = slice.iter().map(|c| c.force).fold(0.0, f64::max);
    let um = 1e6;
    let segments: Vec<([(f64, f64); 2], u32)> = slice
        .iter()
        .map(|c| {
            let width = 1.0 + 7.0 * c.force / largest.max(f64::MIN_POSITIVE);
            let [a, b] = c.ends;
            (
                [(a.x * um, a.z * um), (b.x * um, b.z * um)],
                width.round() as u32,
            )
        })
        .collect();
    crate::plot::write_segments_svg(
        &ctx.report_dir
            .join(format!("{}_force_chains.svg", ctx.spec.name)),
        &format!(
            "Force chains at {:.0} MPa: {} contacts with |y| < {:.2} µm (of {}), x–z in µm, width by the Hertz force of the overlap",
            record.pressure / 1e6,
            slice.len(),
            half_width * um,
            all.len(),
        ),
        (-die_radius * um, die_radius * um, 0.0, record.height * um),
        &segments,
    )
}

pub fn run(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let scene = ctx.die_compaction()?;
    let dc = &scene.die_compaction;
    let (_, per_record) = dc.press.fixed_step().ok_or_else(|| {
        TampError::input(
            format!(
                "verification/{}.scene.json: die_compaction.press.time_step",
                ctx.spec.name
            ),
            "required: an engine runs the press at a fixed step",
        )
    })?;
    if !per_record.is_multiple_of(FRAMES_PER_RECORD) {
        return Err(TampError::input(
            format!(
                "verification/{}.scene.json: die_compaction.press.time_step",
                ctx.spec.name
            ),
            format!(
                "gives {per_record} steps per record, and the case records {FRAMES_PER_RECORD} frames per record: choose a step that makes them a multiple of {FRAMES_PER_RECORD}"
            ),
        ));
    }
    let specimen = super::die_specimen::prepare(&scene)?;
    let press = die_compaction::press_scene(&scene, &specimen)?;
    let walls = Walls::of(&press)?;
    let spec = RecordSpec::every(per_record / FRAMES_PER_RECORD, false).with_walls();
    let rec = ctx.record("press", &press, spec)?;
    let pressing = pressing(&scene, specimen.h0, &walls, &rec, per_record)?;

    // The same fill under ten times the gravity: the settled density must not move
    // beyond the packing's own randomness. A property of the preparation, which tamp
    // makes for every engine.
    let mut stronger = scene.clone();
    stronger.die_compaction.fill.gravity_scale *= 10.0;
    let specimen_stronger = die_compaction::prepare(&stronger, true)?;

    write_curves_csv(ctx, &["hertz"], std::slice::from_ref(&pressing))?;
    let (last_frame, last_record) = rec
        .frames
        .last()
        .zip(pressing.records.last())
        .ok_or_else(|| TampError::Other("a pressing without records".into()))?;
    write_force_chains(ctx, 0.5 * dc.die_diameter, last_frame, last_record)?;
    write_svg(
        &ctx.report_dir.join(format!("{}.svg", ctx.spec.name)),
        &[Panel {
            title: "NiAl die compaction, 300 particles, Hertz, frictionless",
            x_label: "pressure (MPa)",
            y_label: "relative density",
            log_x: false,
            log_y: false,
            series: &[
                Series::line("specimen", mpa(&pressing.records, |r| r.density_specimen)),
                Series::line("RVE", mpa(&pressing.records, |r| r.density_rve)),
                poured_point(),
            ],
        }],
    )?;
    Ok(vec![
        Measured::new(
            "largest_density_drop_specimen",
            largest_drop(&pressing, |r| r.density_specimen),
            0.0,
        ),
        Measured::new(
            "punch_reaction_minus_applied",
            largest_imbalance(&pressing, |r| r.punch_reaction - r.pressure),
            0.0,
        ),
        Measured::new(
            "floor_and_die_minus_punch",
            largest_imbalance(&pressing, |r| {
                r.floor_reaction + r.die_friction - r.punch_reaction
            }),
            0.0,
        ),
        Measured::new("particles_left_die", pressing.escaped.len() as f64, 0.0),
        Measured::new(
            "settled_density_change_gravity_x10",
            specimen_stronger.density_specimen - specimen.density_specimen,
            0.0,
        ),
    ])
}
