//! Accuracy against cost for die compaction: one flattened specimen (the
//! quick NiAl scene, 300 particles) pressed with the pressure ramp slowed (1e-4,
//! 3e-4, 1e-3 s at α = 0.4) and with the step shortened (α = 0.4, 0.2, 0.1 at the
//! paper's 1e-4 s ramp). Each pressing's specimen-density curve is compared with the
//! most accurate setting of its axis (the slowest ramp: closest to quasi-static; the
//! smallest α: smallest integration error) by the largest difference over the
//! common record pressures. The two axes are swept separately: their corner (1e-3 s
//! at α = 0.1) would cost as much as all the others together.
//!
//! Writes `<out>/accuracy-cost/die_compaction.csv`; the page (`page.rs`) shows it.

use crate::error::Result;
use crate::process::die_compaction::{self, Pressing};
use crate::process::die_compaction_file::DieCompactionFile;
use serde::{Deserialize, Serialize};
use std::fmt::Write;
use std::path::Path;
use std::time::Instant;

/// Settings (ramp time s, α) and the axis each belongs to.
const SETTINGS: [(f64, f64, &str); 5] = [
    (1e-4, 0.4, "both"),
    (3e-4, 0.4, "ramp"),
    (1e-3, 0.4, "ramp"),
    (1e-4, 0.2, "alpha"),
    (1e-4, 0.1, "alpha"),
];

/// The curves must stay this close to the most accurate one.
pub const WITHIN: f64 = 0.005;

#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct DieRow {
    pub ramp_time: f64,
    pub alpha: f64,
    pub steps: u64,
    pub wall_s: f64,
    pub density_specimen_50mpa: f64,
    pub density_rve_50mpa: f64,
    /// Largest |φ − φ_ref| of the specimen density over the records, against the
    /// most accurate setting of the same axis (ramp or α).
    pub curve_deviation_ramp_axis: Option<f64>,
    pub curve_deviation_alpha_axis: Option<f64>,
    pub commit: String,
}

fn deviation(a: &Pressing, b: &Pressing) -> f64 {
    a.records
        .iter()
        .zip(&b.records)
        .map(|(x, y)| (x.density_specimen - y.density_specimen).abs())
        .fold(0.0, f64::max)
}

pub fn run(scene_path: &Path, out: &Path) -> Result<u8> {
    let (scene, _) = DieCompactionFile::load(scene_path)?;
    let specimen = die_compaction::prepare(&scene, false)?;
    let mut runs = Vec::new();
    for (ramp, alpha, axis) in SETTINGS {
        let mut s = scene.clone();
        s.scene.time_step.alpha = Some(alpha);
        s.die_compaction.press.ramp_time = ramp;
        let started = Instant::now();
        let pressing = die_compaction::press(&s, &specimen, false, None, 0, &mut |_| Ok(()))?.0;
        let wall_s = started.elapsed().as_secs_f64();
        eprintln!("ramp {ramp:e} s, alpha {alpha}: {wall_s:.1} s");
        runs.push((ramp, alpha, axis, wall_s, pressing));
    }
    let slowest = &runs[2].4;
    let finest = &runs[4].4;
    let rows: Vec<DieRow> = runs
        .iter()
        .map(|(ramp, alpha, axis, wall_s, p)| {
            let last = p.records.last().expect("records");
            DieRow {
                ramp_time: *ramp,
                alpha: *alpha,
                steps: p.steps,
                wall_s: *wall_s,
                density_specimen_50mpa: last.density_specimen,
                density_rve_50mpa: last.density_rve,
                curve_deviation_ramp_axis: matches!(*axis, "ramp" | "both")
                    .then(|| deviation(p, slowest)),
                curve_deviation_alpha_axis: matches!(*axis, "alpha" | "both")
                    .then(|| deviation(p, finest)),
                commit: crate::GIT_COMMIT.to_string(),
            }
        })
        .collect();
    let dir = out.join("accuracy-cost");
    crate::output::create_dir(&dir)?;
    super::write_csv(&dir.join("die_compaction.csv"), &rows)?;
    super::page::write(out)?;
    Ok(0)
}

fn cell(x: Option<f64>) -> String {
    x.map_or("—".into(), |v| format!("{v:.4}"))
}

/// The page's section: the table and the recommendation.
pub fn section(rows: &[DieRow]) -> String {
    let mut s = String::from(
        "## Die compaction: pressure ramp and time step\n\n\
         The quick NiAl specimen (`nial_die_compaction_small`, 300 particles, flattened once) \
         pressed to 50 MPa by `tamp study die-compaction --out docs`. Deviation: the largest \
         difference of the specimen-density curve from the most accurate setting of the same \
         axis (slowest ramp at α = 0.4; smallest α at the 1e-4 s ramp), over the 25 record \
         pressures.\n\n\
         | ramp time (s) | α | steps | wall time (s) | φ specimen at 50 MPa | φ RVE at 50 MPa | deviation, ramp axis | deviation, α axis |\n\
         |---|---|---|---|---|---|---|---|\n",
    );
    for r in rows {
        let _ = writeln!(
            s,
            "| {:e} | {} | {} | {:.1} | {:.4} | {:.4} | {} | {} |",
            r.ramp_time,
            r.alpha,
            r.steps,
            r.wall_s,
            r.density_specimen_50mpa,
            r.density_rve_50mpa,
            cell(r.curve_deviation_ramp_axis),
            cell(r.curve_deviation_alpha_axis)
        );
    }
    // A ramp is good enough when, at α = 0.4, its curve stays within WITHIN of the
    // slowest ramp's; an α when, at the 1e-4 s ramp, its curve stays within WITHIN of
    // the smallest α's. A setting qualifies when both its ramp and its α do; the cost
    // is the number of steps (wall times depend on what else the machine runs).
    let ramp_ok = |ramp: f64| {
        rows.iter().any(|r| {
            r.ramp_time == ramp && r.curve_deviation_ramp_axis.is_some_and(|d| d <= WITHIN)
        })
    };
    let alpha_ok = |alpha: f64| {
        rows.iter()
            .any(|r| r.alpha == alpha && r.curve_deviation_alpha_axis.is_some_and(|d| d <= WITHIN))
    };
    let cheapest = rows
        .iter()
        .filter(|r| ramp_ok(r.ramp_time) && alpha_ok(r.alpha))
        .min_by_key(|r| r.steps);
    let _ = writeln!(
        s,
        "\n{}\n",
        match cheapest {
            Some(r) => format!(
                "Recommended: ramp {:e} s at α = {} ({} steps), the cheapest measured setting whose ramp and α each keep the curve within {WITHIN} of the most accurate one on their axis.",
                r.ramp_time, r.alpha, r.steps
            ),
            None => format!("No setting stays within {WITHIN} of the most accurate one."),
        }
    );
    s.push_str(
        "The deviations on the α axis do not shrink with α (α = 0.4 is closer to α = 0.1 \
         than α = 0.2 is): at this size they are not integration error but the path \
         dependence of rearrangement, which any change of the step sends down another \
         sequence of particle slips. They measure how well one 300-particle pressing \
         determines the curve (a few 1e-3), and the ramp axis shows the same size plus a \
         systematic part: a faster ramp ends denser (less time to relax at each load). \
         Wall times were taken while other runs shared the machine; compare the steps.\n\n",
    );
    s
}
