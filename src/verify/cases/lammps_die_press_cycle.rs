//! `lammps_die_press_cycle`: the whole press cycle of a small compact in tamp and in
//! LAMMPS 22 Jul 2025, along the same prescribed wall motion (`process::cycle_replay`).
//!
//! tamp fills, flattens, presses and unloads the specimen of the case's scene under
//! its own load control, and `tamp export-lammps` writes what it did as a deck:
//! the recorded stroke to the peak, the punch rising at the unloading speed for as
//! many steps as tamp took to release the compact, then the punch taken away and the
//! lower punch pushing the compact out of the die. LAMMPS ran that deck
//! (`reference_data/lammps/lammps_die_press_cycle/`); tamp replays the same motion
//! from the same specimen here. Both are measured from their records by one function
//! (`cycle_replay::quantities`): the pressure transmission ratio and Janssen's K at
//! the peak, the work returned to the withdrawing punch, the die's residual radial
//! force at release, the peak ejection force and the work of ejection, and the
//! ejected compact's height and radial springback.
//!
//! The case also checks that the recorded deck is the one tamp would export now:
//! the scene's sha256 in its header, the specimen's H₀ and the cycle in `cycle.json`
//! (which tamp replays). The report gets both codes' records and a plot of the
//! cycle with LAMMPS's `mdr` cycle of the same specimen beside them
//! (`mdr/results.csv` in the recorded directory).

use crate::error::{Result, TampError};
use crate::plot::{Panel, Series, write_svg};
use crate::process::cycle_replay::{self, CycleReplayRecord, CycleStroke};
use crate::verify::store::key_of;
use crate::verify::{CaseContext, Measured};
use serde::Deserialize;
use std::fmt::Write as _;
use std::path::Path;

/// One record of LAMMPS's run (`rows.py` from the deck's thermo output).
#[derive(Debug, Deserialize)]
struct Row {
    seed: u64,
    step: u64,
    punch_face: f64,
    floor_rise: f64,
    punch_force: f64,
    floor_force: f64,
    floor_force_mean: f64,
    die_axial_force: f64,
    die_radial_force: f64,
    mean_square_radius: f64,
    top: f64,
}

impl Row {
    fn record(&self) -> CycleReplayRecord {
        CycleReplayRecord {
            step: self.step,
            punch_face: self.punch_face,
            floor_rise: self.floor_rise,
            punch_force: self.punch_force,
            floor_force: self.floor_force,
            floor_force_mean: self.floor_force_mean,
            die_axial_force: self.die_axial_force,
            die_radial_force: self.die_radial_force,
            mean_square_radius: self.mean_square_radius,
            top: self.top,
        }
    }
}

/// One record of LAMMPS's `mdr` cycle of the same specimen (`mdr/results.csv`).
#[derive(Debug, Deserialize)]
struct MdrRow {
    punch_face: f64,
    floor_rise: f64,
    punch_force: f64,
    floor_force_mean: f64,
}

/// `<case>_round_off.csv`: each quantity in tamp, LAMMPS and tamp from every initial
/// x moved by one ulp, with the two differences from tamp's value.
fn write_chaos(
    ctx: &CaseContext,
    ours: &[(String, f64)],
    peer: &[(String, f64)],
    nudged: &[(String, f64)],
) -> Result<()> {
    let mut csv = String::from(
        "quantity,tamp,lammps,tamp_one_ulp,relative_difference_lammps,relative_difference_one_ulp\n",
    );
    for (((name, a), (_, b)), (_, c)) in ours.iter().zip(peer).zip(nudged) {
        let _ = writeln!(
            csv,
            "{name},{a:e},{b:e},{c:e},{:e},{:e}",
            (b - a) / a.abs(),
            (c - a) / a.abs()
        );
    }
    crate::output::create_dir(&ctx.report_dir)?;
    crate::output::write_atomic(
        &ctx.report_dir
            .join(format!("{}_round_off.csv", ctx.spec.name)),
        csv.as_bytes(),
    )
}

/// `cycle.json` of a recorded deck.
#[derive(Debug, Deserialize)]
struct Recorded {
    cycle: CycleStroke,
}

pub fn run(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let rows: Vec<Row> = ctx.peer_results("lammps")?;
    let mut file = ctx.die_compaction()?;
    let seed = rows
        .first()
        .map(|r| r.seed)
        .ok_or_else(|| TampError::Other("results.csv has no rows".into()))?;
    if rows.iter().any(|r| r.seed != seed) {
        return Err(TampError::Other(
            "results.csv: the comparison takes one seed's records".into(),
        ));
    }
    file.scene.seed = seed;
    let theirs: Vec<CycleReplayRecord> = rows.iter().map(Row::record).collect();
    let recorded = ctx.reference_data_dir().join("lammps").join(&ctx.spec.name);
    let scene_path = ctx.dir.join(ctx.spec.scene.as_deref().unwrap_or_default());
    let sha = crate::scene::read_input(&scene_path)?.sha256;
    let cycle = recorded_cycle(&recorded.join(format!("seed{seed}")), &sha)?;
    let store = ctx.store()?;
    // The replay, and the same from every initial x moved by one ulp: what tamp gives
    // against itself is the size round-off grows to in this scene, the floor under any
    // agreement of two codes that round differently.
    let runs = ctx.map(&[false, true], |&nudged| {
        let name = match nudged {
            false => format!("seed{seed}.cycle_replay.json"),
            true => format!("seed{seed}.cycle_replay_ulp.json"),
        };
        store.cached(&name, &key_of(&(&file, &cycle, nudged)), || {
            let mut specimen = super::die_specimen::prepare(&file)?;
            if specimen.h0 != cycle.press.h0 {
                return Err(TampError::Other(format!(
                    "the recorded deck was exported for a specimen of H0 = {:e} m; tamp now fills one of {:e} m: re-record (regenerate.sh)",
                    cycle.press.h0, specimen.h0
                )));
            }
            if nudged {
                for p in &mut specimen.particles {
                    p.position[0] = p.position[0].next_up();
                }
            }
            cycle_replay::replay(&file, &specimen, &cycle)
        })
    });
    let [mine, nudged]: [Result<Vec<CycleReplayRecord>>; 2] =
        runs.try_into().expect("one run per entry");
    let (mine, nudged) = (mine?, nudged?);
    let radius = 0.5 * file.die_compaction.die_diameter;
    let ours = cycle_replay::quantities(&mine, &cycle, radius)?;
    let peer = cycle_replay::quantities(&theirs, &cycle, radius)?;
    let floor = cycle_replay::quantities(&nudged, &cycle, radius)?;
    write_chaos(ctx, &ours, &peer, &floor)?;
    let mdr = read_mdr(&recorded.join("mdr").join("results.csv"))?;
    write_report(ctx, &cycle, &[("tamp", &mine), ("LAMMPS", &theirs)], &mdr)?;
    let mut out: Vec<Measured> = ours
        .into_iter()
        .zip(peer)
        .map(|((name, a), (_, b))| Measured::new(&name, a, b))
        .collect();
    out.push(Measured::new(
        "wall_motion_difference",
        motion_difference(&mine, &theirs)?,
        0.0,
    ));
    Ok(out)
}

/// The largest difference between the two codes' punch faces and lower punch rises
/// over their records (m): that the deck's step-indexed variables move LAMMPS's
/// regions where tamp's displacement expressions move its walls, record by record.
fn motion_difference(a: &[CycleReplayRecord], b: &[CycleReplayRecord]) -> Result<f64> {
    if a.len() != b.len() || a.iter().zip(b).any(|(x, y)| x.step != y.step) {
        return Err(TampError::Other(format!(
            "the codes recorded different steps ({} and {} records)",
            a.len(),
            b.len()
        )));
    }
    Ok(a.iter()
        .zip(b)
        .map(|(x, y)| {
            (x.punch_face - y.punch_face)
                .abs()
                .max((x.floor_rise - y.floor_rise).abs())
        })
        .fold(0.0, f64::max))
}

/// The cycle a recorded deck replays, when the deck is the one tamp would export
/// from this scene (its sha256 in the deck's header).
fn recorded_cycle(dir: &Path, sha: &str) -> Result<CycleStroke> {
    let read = |name: &str| {
        let path = dir.join(name);
        std::fs::read_to_string(&path)
            .map_err(|e| TampError::io(format!("reading {}", path.display()), e))
    };
    let deck = read("in.tamp")?;
    if super::die_compaction_replay::deck_scene_sha(&deck) != Some(sha) {
        return Err(TampError::Other(format!(
            "{}: in.tamp was exported from another version of the scene (now sha256 {sha}): the recorded deck is stale, re-record (regenerate.sh)",
            dir.display()
        )));
    }
    let recorded: Recorded = serde_json::from_str(&read("cycle.json")?)
        .map_err(|e| TampError::Other(format!("{}/cycle.json: {e}", dir.display())))?;
    Ok(recorded.cycle)
}

fn read_mdr(path: &Path) -> Result<Vec<MdrRow>> {
    csv::Reader::from_path(path)
        .and_then(|mut r| r.deserialize().collect::<std::result::Result<Vec<_>, _>>())
        .map_err(|e| TampError::Other(format!("{}: {e}", path.display())))
}

/// `<case>_records.csv` (both codes' records) and `<case>_cycle.svg`: the upper
/// punch's push against its face through pressing and unloading, and the lower
/// punch's mean push against its rise through the ejection, with the mdr cycle.
fn write_report(
    ctx: &CaseContext,
    cycle: &CycleStroke,
    codes: &[(&str, &Vec<CycleReplayRecord>)],
    mdr: &[MdrRow],
) -> Result<()> {
    let mut csv = String::from(
        "code,step,punch_face,floor_rise,punch_force,floor_force,floor_force_mean,die_axial_force,die_radial_force,mean_square_radius,top\n",
    );
    for (code, records) in codes {
        for r in records.iter() {
            let _ = writeln!(
                csv,
                "{code},{},{:e},{:e},{:e},{:e},{:e},{:e},{:e},{:e},{:e}",
                r.step,
                r.punch_face,
                r.floor_rise,
                r.punch_force,
                r.floor_force,
                r.floor_force_mean,
                r.die_axial_force,
                r.die_radial_force,
                r.mean_square_radius,
                r.top
            );
        }
    }
    crate::output::create_dir(&ctx.report_dir)?;
    crate::output::write_atomic(
        &ctx.report_dir
            .join(format!("{}_records.csv", ctx.spec.name)),
        csv.as_bytes(),
    )?;
    let um = 1e6;
    let mut press = Vec::new();
    let mut eject = Vec::new();
    for (code, records) in codes {
        let to_release = records.iter().filter(|r| r.step <= cycle.unload_end());
        press.push(Series::line(
            &format!("{code}, Hertz"),
            to_release
                .map(|r| (r.punch_face * um, r.punch_force))
                .collect(),
        ));
        let ejecting = records.iter().filter(|r| r.step > cycle.unload_end());
        eject.push(Series::line(
            &format!("{code}, Hertz"),
            ejecting
                .map(|r| (r.floor_rise * um, r.floor_force_mean))
                .collect(),
        ));
    }
    press.push(Series::line(
        "LAMMPS, mdr",
        mdr.iter()
            .filter(|r| r.floor_rise == 0.0 && r.punch_force > 0.0)
            .map(|r| (r.punch_face * um, r.punch_force))
            .collect(),
    ));
    eject.push(Series::line(
        "LAMMPS, mdr",
        mdr.iter()
            .filter(|r| r.floor_rise > 0.0)
            .map(|r| (r.floor_rise * um, r.floor_force_mean))
            .collect(),
    ));
    write_svg(
        &ctx.report_dir.join(format!("{}_cycle.svg", ctx.spec.name)),
        &[
            Panel {
                title: "pressing and unloading",
                x_label: "upper punch face (um)",
                y_label: "push on the upper punch (N)",
                log_x: false,
                log_y: false,
                series: &press,
            },
            Panel {
                title: "ejection",
                x_label: "lower punch rise (um)",
                y_label: "push on the lower punch, mean over a record (N)",
                log_x: false,
                log_y: false,
                series: &eject,
            },
        ],
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Cheap staleness check of the recorded deck (no fill, no replay): the scene's
    /// hash in its header, and its cycle the one results.csv was run along (the last
    /// record at the cycle's last step, the first at the specimen's H₀).
    #[test]
    fn the_recorded_deck_is_the_scenes_and_its_records_the_cycles() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR"));
        let recorded = root.join("reference_data/lammps/lammps_die_press_cycle");
        let scene = root.join("verification/lammps_die_press_cycle.scene.json");
        let sha = crate::scene::read_input(&scene).unwrap().sha256;
        let cycle = recorded_cycle(&recorded.join("seed1"), &sha).unwrap();
        assert!(recorded_cycle(&recorded.join("seed1"), &sha[..8]).is_err());
        let rows: Vec<Row> = csv::Reader::from_path(recorded.join("results.csv"))
            .unwrap()
            .deserialize()
            .collect::<std::result::Result<_, _>>()
            .unwrap();
        assert_eq!(rows[0].punch_face, cycle.press.h0);
        assert_eq!(rows.last().unwrap().step, cycle.steps());
        assert_eq!(rows.len() as u64, cycle.steps() / cycle.record_steps + 1);
    }
}
