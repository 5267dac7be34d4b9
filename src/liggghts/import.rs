//! `tamp import-liggghts-dump FILE --out DIR`: a LIGGGHTS dump in tamp's run layout
//! (docs/compare.md), with tamp's own measures of its last frame, so that a bed
//! LIGGGHTS settled is measured exactly as tamp measures its own:
//!
//! - `trajectory.csv`: every frame of the dump;
//! - `quantities.csv` (last frame): `particles`, `coordination_number` (overlapping
//!   pairs per particle, `measure::coordination` with its defaults, nearest images
//!   through periodic faces), `max_overlap_ratio`, `bed_height` and
//!   `packing_fraction` (the bulk fraction below the Gibbs surface of a bed on the
//!   floor `z = floor`, `measure::bed`; only for a box periodic in x and y),
//!   `mean_speed`.

use super::dump;
use crate::compare::{TRAJECTORY_HEADER, quantities_csv, trajectory_row};
use crate::error::Result;
use crate::measure::bed::bulk_packing_fraction;
use crate::measure::coordination::{CoordinationOptions, coordination};
use std::path::Path;

/// tamp's measures of one frame, by name (see the module comment).
pub fn measures(frame: &dump::Frame, floor: Option<f64>) -> Result<Vec<(String, f64)>> {
    let space = frame.space();
    let n = frame.id.len();
    let pairs: Vec<(u32, u32)> =
        crate::detect::cells::candidate_pairs_in(&frame.position, &frame.radius, 0.0, &space);
    let mut max_overlap_ratio: f64 = 0.0;
    for &(i, j) in &pairs {
        let (i, j) = (i as usize, j as usize);
        let d = space
            .displacement(&frame.position[i], &frame.position[j])
            .norm();
        let overlap = frame.radius[i] + frame.radius[j] - d;
        max_overlap_ratio = max_overlap_ratio.max(overlap / frame.radius[i].min(frame.radius[j]));
    }
    let z = coordination(
        &frame.position,
        &frame.radius,
        &space,
        &pairs,
        &CoordinationOptions::default(),
    )?;
    let mut out = vec![
        ("particles".to_string(), n as f64),
        ("coordination_number".to_string(), z.mean),
        ("max_overlap_ratio".to_string(), max_overlap_ratio),
        (
            "mean_speed".to_string(),
            frame.velocity.iter().map(|v| v.norm()).sum::<f64>() / n.max(1) as f64,
        ),
    ];
    if frame.periodic[0] && frame.periodic[1] {
        let floor = floor.unwrap_or(frame.bounds[2][0]);
        let bed = bulk_packing_fraction(&frame.position, &frame.radius, &space, 2, floor)?;
        out.push(("bed_height".to_string(), bed.height));
        out.push(("packing_fraction".to_string(), bed.bulk_fraction));
    }
    Ok(out)
}

pub fn run_cli(file: &Path, out_dir: &Path, floor: Option<f64>) -> Result<Vec<(String, f64)>> {
    let frames = dump::read(file)?;
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
    let quantities = measures(last, floor)?;
    crate::output::create_dir(out_dir)?;
    crate::output::write_atomic(&out_dir.join("trajectory.csv"), trajectory.as_bytes())?;
    crate::output::write_atomic(
        &out_dir.join("quantities.csv"),
        quantities_csv(&quantities).as_bytes(),
    )?;
    Ok(quantities)
}
