//! `tamp import-liggghts-dump FILE --out DIR`: a LIGGGHTS dump in tamp's run layout
//! (docs/compare.md), with tamp's own measures of its last frame, so that a bed
//! LIGGGHTS settled is measured exactly as tamp measures its own:
//!
//! - `trajectory.csv`: every frame of the dump;
//! - `quantities.csv` (last frame): `particles`, `coordination_number` (overlapping
//!   pairs per particle, `measure::coordination` with its defaults, nearest images
//!   through periodic faces), `max_overlap_ratio_last_frame` (tamp's `max_overlap_ratio`
//!   is over the whole run), `bed_height` and
//!   `packing_fraction` (the bulk fraction below the Gibbs surface of a bed on the
//!   floor `z = floor`, by default the lowest sphere bottom; `measure::bed`; only
//!   for a box periodic in x and y),
//!   `mean_speed`, and with `--gravity g` `floor_force_over_weight` (of the last
//!   frame, or averaged over the frames from step `--average-from` on).

use super::dump;
use crate::error::Result;
use crate::measure::bed::bulk_packing_fraction;
use crate::measure::coordination::{CoordinationOptions, coordination};
use crate::output::run_files::{TRAJECTORY_HEADER, quantities_csv, trajectory_row};
use crate::particles::Vec3;
use crate::space::Space;
use std::path::Path;

/// tamp's measures of one frame, by name (see the module comment).
pub fn measures(frame: &dump::Frame, floor: Option<f64>) -> Result<Vec<(String, f64)>> {
    let lateral = frame.periodic[0] && frame.periodic[1];
    state_measures(
        &frame.position,
        &frame.radius,
        &frame.velocity,
        &frame.space(),
        lateral,
        floor,
    )
}

/// The measures of a set of spheres, whichever code produced them: LIGGGHTS frames
/// here, tamp's own state in the cross-check cases. `bed_height` and
/// `packing_fraction` only when `lateral_periodic` (x and y).
pub fn state_measures(
    position: &[Vec3],
    radius: &[f64],
    velocity: &[Vec3],
    space: &Space,
    lateral_periodic: bool,
    floor: Option<f64>,
) -> Result<Vec<(String, f64)>> {
    let n = position.len();
    let pairs = crate::detect::cells::candidate_pairs_in(position, radius, 0.0, space);
    let mut max_overlap_ratio: f64 = 0.0;
    for &(i, j) in &pairs {
        let (i, j) = (i as usize, j as usize);
        let d = space.displacement(&position[i], &position[j]).norm();
        let overlap = radius[i] + radius[j] - d;
        max_overlap_ratio = max_overlap_ratio.max(overlap / radius[i].min(radius[j]));
    }
    let z = coordination(
        position,
        radius,
        space,
        &pairs,
        &CoordinationOptions::default(),
    )?;
    let mut out = vec![
        ("particles".to_string(), n as f64),
        ("coordination_number".to_string(), z.mean),
        (
            "max_overlap_ratio_last_frame".to_string(),
            max_overlap_ratio,
        ),
        (
            "mean_speed".to_string(),
            velocity.iter().map(|v| v.norm()).sum::<f64>() / n.max(1) as f64,
        ),
    ];
    if lateral_periodic {
        // The box's lower bound is no floor: a shrink-wrapped box starts below it.
        let lowest = position
            .iter()
            .zip(radius)
            .map(|(x, r)| x.z - r)
            .fold(f64::INFINITY, f64::min);
        let floor = floor.unwrap_or(lowest);
        let bed = bulk_packing_fraction(position, radius, space, 2, floor)?;
        out.push(("bed_height".to_string(), bed.height));
        out.push(("packing_fraction".to_string(), bed.bulk_fraction));
    }
    Ok(out)
}

/// (force of the floor on the bed)/(weight) from a frame's total forces: the dumped
/// f includes gravity and the walls, and the pair forces cancel in the sum, so the
/// floor carries Σf_z + Σm g. Needs the `mass` and `fz` columns.
fn floor_force_over_weight(frame: &dump::Frame, gravity: f64) -> f64 {
    let weight: f64 = frame.mass.iter().sum::<f64>() * gravity;
    let net: f64 = frame.force.iter().map(|f| f.z).sum();
    (net + weight) / weight
}

/// `floor_force_over_weight` averaged over the frames from step `from` on (None when
/// there are none): a settling bed rings, and one frame samples a force that
/// fluctuates by a few per cent.
pub fn mean_floor_force_over_weight(
    frames: &[dump::Frame],
    gravity: f64,
    from: u64,
) -> Option<f64> {
    let window: Vec<f64> = frames
        .iter()
        .filter(|f| f.step >= from)
        .map(|f| floor_force_over_weight(f, gravity))
        .collect();
    (!window.is_empty()).then(|| window.iter().sum::<f64>() / window.len() as f64)
}

pub fn run_cli(
    file: &Path,
    out_dir: &Path,
    floor: Option<f64>,
    gravity: Option<f64>,
    average_from: Option<u64>,
    die_stroke: Option<&Path>,
) -> Result<Vec<(String, f64)>> {
    let frames = dump::read(file)?;
    if let Some(path) = die_stroke {
        crate::output::create_dir(out_dir)?;
        let csv = die_densities(&frames, path)?;
        crate::output::write_atomic(&out_dir.join("die.csv"), csv.as_bytes())?;
    }
    let mut trajectory = format!("{TRAJECTORY_HEADER}\n");
    for f in &frames {
        for k in 0..f.id.len() {
            trajectory_row(
                &mut trajectory,
                f.step,
                f.id[k],
                f.radius[k],
                &f.position[k],
                &f.velocity[k],
                &f.omega[k],
            );
        }
    }
    let last = frames
        .last()
        .expect("dump::read returns at least one frame");
    let mut quantities = measures(last, floor)?;
    if let Some(g) = gravity {
        if last.mass.iter().any(|&m| m <= 0.0) {
            return Err(crate::error::TampError::input(
                "--gravity",
                "needs a dump with a positive 'mass' column for every atom",
            ));
        }
        let from = average_from.unwrap_or(last.step);
        let mean = mean_floor_force_over_weight(&frames, g, from).ok_or_else(|| {
            crate::error::TampError::input(
                "--average-from",
                format!(
                    "no frame at or after step {from}; the last is step {}",
                    last.step
                ),
            )
        })?;
        quantities.push(("floor_force_over_weight".to_string(), mean));
    }
    crate::output::create_dir(out_dir)?;
    crate::output::write_atomic(&out_dir.join("trajectory.csv"), trajectory.as_bytes())?;
    crate::output::write_atomic(
        &out_dir.join("quantities.csv"),
        quantities_csv(&quantities).as_bytes(),
    )?;
    Ok(quantities)
}

/// `die.csv` of a replayed pressing (`liggghts::die_compaction`): for the frame of
/// every record, the punch height of the stroke and tamp's specimen and RVE
/// densities of LIGGGHTS's particles at that height.
fn die_densities(frames: &[dump::Frame], path: &Path) -> Result<String> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| crate::error::TampError::io(format!("reading {}", path.display()), e))?;
    let die: super::die_compaction::DieStroke = serde_json::from_str(&text)
        .map_err(|e| crate::error::TampError::input(path.display().to_string(), e.to_string()))?;
    let s = &die.stroke;
    if frames.len() != s.heights.len() + 1 {
        return Err(crate::error::TampError::input(
            "--die-stroke",
            format!(
                "the dump has {} frames; the stroke needs one per record, {}",
                frames.len(),
                s.heights.len() + 1
            ),
        ));
    }
    let mut csv = String::from("record,step,height,density_specimen,density_rve\n");
    for (k, f) in frames.iter().enumerate() {
        if f.step != k as u64 * s.steps_per_record {
            return Err(crate::error::TampError::input(
                "--die-stroke",
                format!(
                    "frame {k} is step {}, not record {k}'s step {}",
                    f.step,
                    k as u64 * s.steps_per_record
                ),
            ));
        }
        let height = if k == 0 { s.h0 } else { s.heights[k - 1] };
        let material: Vec<f64>;
        let radii = match &die.material_radius {
            None => &f.radius,
            Some(by_id) => {
                material =
                    f.id.iter()
                        .map(|id| {
                            by_id.get(id).copied().ok_or_else(|| {
                                crate::error::TampError::input(
                                    "--die-stroke",
                                    format!("material_radius has no atom {id}"),
                                )
                            })
                        })
                        .collect::<Result<_>>()?;
                &material
            }
        };
        let (specimen, rve) = crate::process::die_compaction::densities_in(
            &f.position,
            radii,
            die.die_diameter,
            die.rve_diameter,
            height,
        )?;
        csv.push_str(&format!("{k},{},{height:e},{specimen:e},{rve:e}\n", f.step));
    }
    Ok(csv)
}
