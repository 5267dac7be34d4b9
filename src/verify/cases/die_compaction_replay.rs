//! The NiAl die compaction pressed in a peer code along the stroke tamp pressed
//! (`process::die_replay`): the 300-particle specimen of `nial_die_compaction_small`
//! in LIGGGHTS-PUBLIC 3.8.0 (`liggghts_die_compaction_small`,
//! `liggghts::die_compaction`) and LAMMPS 22 Jul 2025 (`lammps_die_compaction_small`,
//! `lammps::die_compaction`), and the paper's 1751-particle specimen of
//! `nial_die_compaction` in LIGGGHTS, frictionless and with μ = 0.05 between
//! particles (`liggghts_die_compaction`, full tier, one pressing per entry of its
//! `parameters.pressings`). One comparison, two peers: each case's scene holds the
//! law its peer can express.
//!
//! For each seed recorded in `reference_data/<peer>/<case>/results.csv`, tamp
//! fills and flattens the specimen (the scene's preparation, the one the export
//! carried to the peer: its H₀ must equal the recorded one, else the recording is
//! stale), and the case's engine replays the recorded stroke on it: the resolved
//! press stage with the punch's `displacement` motion, recorded at every record
//! interval with the walls. Everything compared is measured from those frames; the
//! peer replayed the same stroke from the same specimen. Both codes then move the
//! punch through the same heights, so what the comparison tests is the force each
//! needs to get there, and what that force does to the bed:
//! - at the punch pressures 10, 25 and 50 MPa, each code's own (interpolated
//!   between records along its punch-pressure curve; beyond the last record,
//!   extrapolated from the last two), the specimen and RVE densities and, at
//!   50 MPa, ΔH/H₀;
//! - at the last record (the same height in both), the punch and floor pressures
//!   (force over the die's cross-section).
//!
//! Each quantity is the engine's value against the peer's, averaged over the seeds.
//! The report gets both curves (`<case>_curves.csv`). The replays are independent,
//! so they run one per core, and on the tamp engine they are kept in the runner's
//! store (`verify::store`): a full-tier run that is killed does not press again what
//! it finished.
//!
//! The live cross-check runs the peer on the recorded deck (`seed<S>/in.tamp`,
//! `particles.data`, `stroke.json`) rather than exporting it again, since the
//! export presses in tamp once more; so this case checks that the recorded deck is
//! still what tamp would export: the scene file's sha256 in its header, the
//! specimen's H₀, and its stroke equal to the one results.csv holds and tamp
//! replays. A change of tamp's pressing alone (not of the scene, fill or law) would
//! give another stroke but not a wrong comparison: both codes replay the recorded
//! one.

use super::nial_die_compaction_small::Walls;
use crate::error::{Result, TampError};
use crate::particles::Vec3;
use crate::plot::{Panel, Series, write_svg};
use crate::process::die_compaction::densities_in;
use crate::process::die_compaction_file::DieCompactionFile;
use crate::process::die_replay::{self, ReplayRecord, Stroke};
use crate::verify::recording::{RecordSpec, Recording};
use crate::verify::store::Store;
use crate::verify::{CaseContext, Measured};
use serde::Deserialize;
use std::f64::consts::PI;
use std::fmt::Write as _;
use std::path::Path;

/// One record of the peer's replay (regenerate.sh joins the thermo output of the
/// deck and `import-liggghts-dump --die-stroke`'s die.csv).
#[derive(Debug, Deserialize)]
pub(super) struct Row {
    /// The pressing's label, in a case that presses more than one (absent: the
    /// case's one pressing).
    #[serde(default)]
    pub(super) pressing: String,
    pub(super) seed: u64,
    pub(super) record: usize,
    pub(super) time: f64,
    pub(super) height: f64,
    pub(super) h0: f64,
    pub(super) dt: f64,
    pub(super) steps_per_record: u64,
    pub(super) tamp_pressure: f64,
    pub(super) punch_pressure: f64,
    pub(super) floor_pressure: f64,
    pub(super) density_specimen: f64,
    pub(super) density_rve: f64,
}

impl Row {
    /// The row as a record of the replay.
    pub(super) fn record(&self) -> ReplayRecord {
        ReplayRecord {
            time: self.time,
            height: self.height,
            punch_pressure: self.punch_pressure,
            floor_pressure: self.floor_pressure,
            density_specimen: self.density_specimen,
            density_rve: self.density_rve,
        }
    }
}

/// The rows of one seed in the order of their records, which must run 0, 1, 2, … with
/// none missing.
pub(super) fn seed_rows<'a>(
    rows: impl Iterator<Item = &'a Row>,
    seed: u64,
) -> Result<Vec<&'a Row>> {
    let mut mine: Vec<&Row> = rows.filter(|r| r.seed == seed).collect();
    mine.sort_by_key(|r| r.record);
    if mine.len() < 3 || mine.iter().enumerate().any(|(k, r)| r.record != k) {
        return Err(TampError::Other(format!(
            "results.csv: seed {seed} needs records 0, 1, 2, … in full"
        )));
    }
    Ok(mine)
}

/// The radius of each body's material (docs/measures.md): the radius it starts the
/// replay with, which MDR's apparent radius outgrows as the bed is pressed and a
/// pairwise law keeps.
pub(super) fn material_radii(rec: &Recording) -> Result<Vec<f64>> {
    match rec.frames.first() {
        Some(f) if f.step == 0 => Ok(f.bodies.iter().map(|b| b.radius).collect()),
        _ => Err(TampError::Other(
            "the recording has no frame at step 0 to take the material's radii from".into(),
        )),
    }
}

/// The punch pressures the densities are compared at, Pa.
const PRESSURES: [f64; 3] = [10e6, 25e6, 50e6];

/// `column` where the punch pressure first reaches p, linear between records;
/// beyond the last record, extrapolated from the last two.
pub(super) fn at_pressure(
    records: &[ReplayRecord],
    p: f64,
    column: fn(&ReplayRecord) -> f64,
) -> f64 {
    let between = |a: &ReplayRecord, b: &ReplayRecord| {
        let s = (p - a.punch_pressure) / (b.punch_pressure - a.punch_pressure);
        column(a) + s * (column(b) - column(a))
    };
    records
        .windows(2)
        .find(|w| w[0].punch_pressure <= p && p <= w[1].punch_pressure)
        .map(|w| between(&w[0], &w[1]))
        .unwrap_or_else(|| {
            let n = records.len();
            between(&records[n - 2], &records[n - 1])
        })
}

/// The seven compared quantities of one code's replay, by name.
fn quantities(records: &[ReplayRecord], h0: f64) -> Vec<(String, f64)> {
    let mut out = Vec::new();
    for p in PRESSURES {
        let mpa = p / 1e6;
        out.push((
            format!("density_specimen_{mpa}mpa"),
            at_pressure(records, p, |r| r.density_specimen),
        ));
        out.push((
            format!("density_rve_{mpa}mpa"),
            at_pressure(records, p, |r| r.density_rve),
        ));
    }
    let h50 = at_pressure(records, PRESSURES[2], |r| r.height);
    out.push(("height_reduction_50mpa".into(), (h0 - h50) / h0));
    let last = records.last().expect("a replay has records");
    out.push(("punch_pressure_last_record".into(), last.punch_pressure));
    out.push(("floor_pressure_last_record".into(), last.floor_pressure));
    out
}

pub fn liggghts(ctx: &CaseContext) -> Result<Vec<Measured>> {
    compare(ctx, "liggghts")
}

pub fn lammps(ctx: &CaseContext) -> Result<Vec<Measured>> {
    compare(ctx, "lammps")
}

/// A pressing of a case that presses more than one law (`parameters.pressings`):
/// the label its rows in results.csv, its decks (`<label>/seed<S>/`) and its
/// quantities (`<quantity>_<label>`) carry, and its die-compaction file.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct PressingSpec {
    label: String,
    scene: String,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct Parameters {
    pressings: Vec<PressingSpec>,
    /// Draw LAMMPS's mdr pressing of the same specimen in the plot (`mdr_curve`).
    #[serde(default)]
    mdr_curve: bool,
}

/// tamp's replay of each recorded stroke against `peer`'s, for each pressing of
/// the case (one, the case's scene, unless its parameters list several).
fn compare(ctx: &CaseContext, peer: &str) -> Result<Vec<Measured>> {
    let rows: Vec<Row> = ctx.peer_results(peer)?;
    let parameters = match ctx.spec.parameters {
        None => Parameters {
            pressings: vec![PressingSpec {
                label: String::new(),
                scene: ctx.spec.scene.clone().unwrap_or_default(),
            }],
            mdr_curve: false,
        },
        Some(_) => ctx.parameters::<Parameters>()?,
    };
    let pressings = parameters.pressings;
    let recorded = ctx.reference_data_dir().join(peer).join(&ctx.spec.name);
    let mut runs = Vec::new();
    for pressing in &pressings {
        let decks = match pressing.label.as_str() {
            "" => recorded.clone(),
            label => recorded.join(label),
        };
        let mine: Vec<&Row> = rows
            .iter()
            .filter(|r| r.pressing == pressing.label)
            .collect();
        if mine.is_empty() {
            return Err(TampError::Other(format!(
                "results.csv: no rows of pressing '{}'",
                pressing.label
            )));
        }
        runs.extend(recorded_runs(ctx, pressing, &mine, &decks)?);
    }
    // The replays are independent: one per core, each kept in the case's store.
    let store = ctx.store()?;
    let replays = ctx
        .map(&runs, |run| replay(ctx, &store, run))
        .into_iter()
        .collect::<Result<Vec<_>>>()?;

    let engine = ctx.engine.to_string();
    let mut curves = String::from(
        "code,pressing,seed,record,time,height,punch_pressure,floor_pressure,density_specimen,density_rve\n",
    );
    for (run, tamp) in runs.iter().zip(&replays) {
        for (code, records) in [(engine.as_str(), tamp), (peer, &run.theirs)] {
            for (k, r) in records.iter().enumerate() {
                let _ = writeln!(
                    curves,
                    "{code},{},{},{k},{:e},{:e},{:e},{:e},{:e},{:e}",
                    run.label,
                    run.seed,
                    r.time,
                    r.height,
                    r.punch_pressure,
                    r.floor_pressure,
                    r.density_specimen,
                    r.density_rve
                );
            }
        }
    }
    let mut measured = Vec::new();
    let mut panels_series = Vec::new();
    for pressing in &pressings {
        let label = pressing.label.as_str();
        let of_pressing: Vec<(&RecordedRun, &Vec<ReplayRecord>)> = runs
            .iter()
            .zip(&replays)
            .filter(|(run, _)| run.label == label)
            .collect();
        let tag = |code: &str| match label {
            "" => code.to_string(),
            label => format!("{code}, {label}"),
        };
        let (first, tamp) = of_pressing[0];
        panels_series.push((tag(&engine), tamp.clone()));
        panels_series.push((tag(peer), first.theirs.clone()));
        // Each quantity is the mean over the seeds of each code's value.
        let n = of_pressing.len() as f64;
        let mut sums: Vec<(String, f64, f64)> = Vec::new();
        for (run, tamp) in &of_pressing {
            let (t, l) = (
                quantities(tamp, run.stroke.h0),
                quantities(&run.theirs, run.stroke.h0),
            );
            if sums.is_empty() {
                sums = t.iter().map(|(name, _)| (name.clone(), 0.0, 0.0)).collect();
            }
            for (k, ((_, a), (_, b))) in t.iter().zip(&l).enumerate() {
                sums[k].1 += a;
                sums[k].2 += b;
            }
        }
        for (name, a, b) in sums {
            let name = match label {
                "" => name,
                label => format!("{name}_{label}"),
            };
            measured.push(Measured::new(&name, a / n, b / n));
        }
    }
    crate::output::create_dir(&ctx.report_dir)?;
    crate::output::write_atomic(
        &ctx.report_dir.join(format!("{}_curves.csv", ctx.spec.name)),
        curves.as_bytes(),
    )?;
    let mdr = match parameters.mdr_curve {
        true => {
            let recorded = crate::verify::reference_data_beside(&ctx.dir);
            Some(super::mdr_curve::density(&super::mdr_curve::load(
                &recorded,
            )?))
        }
        false => None,
    };
    write_plot(ctx, &panels_series, mdr)?;
    Ok(measured)
}

/// One seed of one pressing as the peer recorded it: what tamp replays.
struct RecordedRun {
    label: String,
    seed: u64,
    /// The die-compaction file with the seed set.
    scene: DieCompactionFile,
    stroke: Stroke,
    theirs: Vec<ReplayRecord>,
}

/// The recorded runs of one pressing, seeds in the order of results.csv, each
/// checked to be complete and its deck current.
fn recorded_runs(
    ctx: &CaseContext,
    pressing: &PressingSpec,
    rows: &[&Row],
    decks: &Path,
) -> Result<Vec<RecordedRun>> {
    let scene_path = ctx.dir.join(&pressing.scene);
    let base = ctx.die_compaction_at(&scene_path)?;
    let sha = crate::scene::read_input(&scene_path)?.sha256;
    let mut seeds: Vec<u64> = rows.iter().map(|r| r.seed).collect();
    seeds.dedup();
    let mut out = Vec::new();
    for seed in seeds {
        let mine = seed_rows(rows.iter().copied(), seed)?;
        let stroke = stroke_of(&mine);
        recorded_deck_is_current(&decks.join(format!("seed{seed}")), &sha, &stroke)?;
        let mut scene = base.clone();
        scene.scene.seed = seed;
        let theirs: Vec<ReplayRecord> = mine.iter().map(|r| r.record()).collect();
        out.push(RecordedRun {
            label: pressing.label.clone(),
            seed,
            scene,
            stroke,
            theirs,
        });
    }
    Ok(out)
}

/// The engine's replay of a recorded run: tamp fills and flattens the specimen (the
/// one the export carried to the peer: its H₀ must equal the recorded one, else the
/// recording is stale), and the engine moves the punch through the recorded heights
/// at the stroke's fixed step, recording the particles and walls at every record.
fn replay(ctx: &CaseContext, store: &Store, run: &RecordedRun) -> Result<Vec<ReplayRecord>> {
    let label = match run.label.as_str() {
        "" => format!("seed{}", run.seed),
        label => format!("{label}_seed{}", run.seed),
    };
    let per_record = run.stroke.steps_per_record;
    let spec = RecordSpec::every(per_record, false).with_walls();
    let dc = &run.scene.die_compaction;
    let scene = || {
        let specimen = super::die_specimen::prepare(&run.scene)?;
        let recorded = run.stroke.h0;
        if (specimen.h0 - recorded).abs() > 1e-12 * recorded {
            return Err(TampError::Other(format!(
                "results.csv: seed {} was recorded for a specimen of H0 = {recorded:e} m; tamp now fills one of {:e} m: re-record (regenerate.sh)",
                run.seed, specimen.h0
            )));
        }
        let solid = die_replay::solid_sphere_scene(&run.scene);
        let mut scene = die_replay::replay_scene(&solid, &specimen, &run.stroke)?;
        scene.run.duration = None;
        scene.run.steps = Some(per_record * run.stroke.heights.len() as u64);
        let walls = Walls::of(&scene)?;
        Ok((scene, (specimen.h0, walls)))
    };
    let measure = |rec: &Recording, (h0, walls): &(f64, Walls)| {
        let area = PI * (0.5 * dc.die_diameter).powi(2);
        let radii = material_radii(rec)?;
        rec.frames
            .iter()
            .map(|f| {
                let height = h0 + f.walls[walls.punch].displacement.z;
                let positions: Vec<Vec3> = f.bodies.iter().map(|b| b.position).collect();
                let (density_specimen, density_rve) =
                    densities_in(&positions, &radii, dc.die_diameter, dc.rve_diameter, height)?;
                Ok(ReplayRecord {
                    time: f.step as f64 * rec.dt,
                    height,
                    punch_pressure: f.walls[walls.punch].force.z / area,
                    floor_pressure: -f.walls[walls.floor].force.z / area,
                    density_specimen,
                    density_rve,
                })
            })
            .collect()
    };
    // The replay is made from the die-compaction file and the stroke alone.
    let key = (&run.scene, &run.stroke);
    ctx.record_and_keep(
        store,
        (&format!("{label}.replay.json"), &key),
        (&label, spec),
        scene,
        measure,
    )
}

/// `<case>_density_pressure.svg`: the specimen and RVE densities against the punch
/// pressure, each code's replay of the first seed of each pressing, and `also` in
/// the specimen panel.
fn write_plot(
    ctx: &CaseContext,
    replays: &[(String, Vec<ReplayRecord>)],
    also: Option<Series>,
) -> Result<()> {
    let series = |column: fn(&ReplayRecord) -> f64| -> Vec<Series> {
        replays
            .iter()
            .map(|(name, records)| {
                let points = records.iter().map(|r| (r.punch_pressure / 1e6, column(r)));
                Series::line(name, points.collect())
            })
            .collect()
    };
    let (mut specimen, rve) = (series(|r| r.density_specimen), series(|r| r.density_rve));
    specimen.extend(also);
    let panel = |title, series| Panel {
        title,
        x_label: "punch pressure (MPa)",
        y_label: "relative density",
        log_x: false,
        log_y: false,
        series,
    };
    write_svg(
        &ctx.report_dir
            .join(format!("{}_density_pressure.svg", ctx.spec.name)),
        &[panel("specimen", &specimen), panel("RVE", &rve)],
    )
}

/// The stroke of one seed's rows (records 0, 1, 2, … in order).
pub(super) fn stroke_of(rows: &[&Row]) -> Stroke {
    Stroke {
        h0: rows[0].h0,
        interval: rows[1].time - rows[0].time,
        steps_per_record: rows[0].steps_per_record,
        dt: rows[0].dt,
        heights: rows[1..].iter().map(|r| r.height).collect(),
        pressures: rows[1..].iter().map(|r| r.tamp_pressure).collect(),
    }
}

/// The deck the peer ran for a seed (`dir` = `seed<S>/`: `in.tamp`, `stroke.json`,
/// recorded beside results.csv and run as it is by the live cross-check) must be the one
/// tamp would export now: written from this scene file (its sha256 in the deck's
/// header) and along the stroke results.csv holds and tamp replays. The specimen's
/// H₀ is checked by the caller.
pub(super) fn recorded_deck_is_current(dir: &Path, sha: &str, stroke: &Stroke) -> Result<()> {
    let read = |file: &str| {
        let path = dir.join(file);
        std::fs::read_to_string(&path)
            .map_err(|e| TampError::io(format!("reading {}", path.display()), e))
    };
    let stale = |what: String| {
        TampError::Other(format!(
            "{}: {what}: the recorded deck is stale, re-record (regenerate.sh)",
            dir.display()
        ))
    };
    let deck = read("in.tamp")?;
    if deck_scene_sha(&deck) != Some(sha) {
        return Err(stale(format!(
            "in.tamp was exported from another version of the scene (now sha256 {sha})"
        )));
    }
    let ran: crate::liggghts::die_compaction::DieStroke =
        serde_json::from_str(&read("stroke.json")?)
            .map_err(|e| stale(format!("stroke.json: {e}")))?;
    let ran = ran.stroke;
    // die_replay_rows.py copies stroke.json's numbers into results.csv with
    // Python's repr, which reads back to the same double: equal to the bit.
    if ran.steps_per_record != stroke.steps_per_record
        || ran.dt != stroke.dt
        || ran.h0 != stroke.h0
        || ran.heights != stroke.heights
    {
        return Err(stale(
            "stroke.json differs from the stroke in results.csv".into(),
        ));
    }
    Ok(())
}

/// The scene's sha256 that an exported deck's header names. The header names the
/// whole hash: it is read as a token, so that a prefix of the right hash does not match.
pub(super) fn deck_scene_sha(deck: &str) -> Option<&str> {
    deck.split("sha256 ").nth(1).map(|rest| {
        rest.split(|c: char| !c.is_ascii_hexdigit())
            .next()
            .unwrap_or_default()
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn recorded_rows(recorded: &Path) -> Vec<Row> {
        csv::Reader::from_path(recorded.join("results.csv"))
            .unwrap()
            .deserialize()
            .collect::<std::result::Result<_, _>>()
            .unwrap()
    }

    /// Cheap staleness check of the small cases' recorded decks (no fill, no replay):
    /// what the case checks before it presses, so a scene edit fails `cargo test` too.
    #[test]
    fn the_recorded_decks_are_the_scenes_and_strokes_of_results_csv() {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
        for peer in ["liggghts", "lammps"] {
            let case = format!("{peer}_die_compaction_small");
            let recorded = root.join("reference_data").join(peer).join(&case);
            let rows = recorded_rows(&recorded);
            let seed1: Vec<&Row> = rows.iter().filter(|r| r.seed == 1).collect();
            let scene = root.join("verification").join(format!("{case}.scene.json"));
            let sha = crate::scene::read_input(&scene).unwrap().sha256;
            let stroke = stroke_of(&seed1);
            recorded_deck_is_current(&recorded.join("seed1"), &sha, &stroke).unwrap();
            let mut moved = stroke.clone();
            moved.heights[7] *= 1.0 + 1e-15;
            assert!(recorded_deck_is_current(&recorded.join("seed1"), &sha, &moved).is_err());
            // A prefix of the right hash is another hash (the LAMMPS scene's starts "0").
            assert!(recorded_deck_is_current(&recorded.join("seed1"), &sha[..1], &stroke).is_err());
            assert!(recorded_deck_is_current(&recorded.join("seed1"), "0", &stroke).is_err());
        }
    }

    /// The same for the full case's six decks (two pressings, seeds 1–3), each
    /// against the scene its pressing names in the case's parameters: the full tier
    /// runs rarely, so a scene edit that makes them stale shows here first.
    #[test]
    fn the_full_case_decks_are_current() {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
        let case = "liggghts_die_compaction";
        let spec: serde_json::Value = serde_json::from_str(
            &std::fs::read_to_string(root.join("verification").join(format!("{case}.json")))
                .unwrap(),
        )
        .unwrap();
        let parameters: Parameters = serde_json::from_value(spec["parameters"].clone()).unwrap();
        let recorded = root.join("reference_data/liggghts").join(case);
        let rows = recorded_rows(&recorded);
        let mut decks = 0;
        for pressing in &parameters.pressings {
            let scene = root.join("verification").join(&pressing.scene);
            let sha = crate::scene::read_input(&scene).unwrap().sha256;
            for seed in 1..=3 {
                let mut mine: Vec<&Row> = rows
                    .iter()
                    .filter(|r| r.pressing == pressing.label && r.seed == seed)
                    .collect();
                mine.sort_by_key(|r| r.record);
                let dir = recorded.join(&pressing.label).join(format!("seed{seed}"));
                recorded_deck_is_current(&dir, &sha, &stroke_of(&mine)).unwrap();
                decks += 1;
            }
        }
        assert_eq!(decks, 6);
    }

    /// The plot draws the codes' curves and, when asked, the mdr pressing beside them
    /// in the specimen panel (what the full case's parameters ask for).
    #[test]
    fn the_plot_draws_the_mdr_curve_when_asked() {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
        let spec: crate::verify::CaseSpec = serde_json::from_str(
            r#"{"name": "plot_test", "tier": "quick", "description": "", "quantities": []}"#,
        )
        .unwrap();
        let report = std::env::temp_dir().join(format!("tamp-plot-test-{}", std::process::id()));
        crate::output::create_dir(&report).unwrap();
        let ctx = CaseContext::new(
            &spec,
            &root.join("verification"),
            &report,
            None,
            Default::default(),
            crate::verify::engine::Engine::Tamp,
        );
        let record = |p: f64, d: f64| ReplayRecord {
            time: 0.0,
            height: 1.0,
            punch_pressure: p,
            floor_pressure: p,
            density_specimen: d,
            density_rve: d,
        };
        let tamp = vec![record(0.0, 0.62), record(50e6, 0.66)];
        let mdr = super::super::mdr_curve::density(
            &super::super::mdr_curve::load(&root.join("reference_data")).unwrap(),
        );
        let name = mdr.name.clone();
        write_plot(&ctx, &[("tamp".into(), tamp)], Some(mdr)).unwrap();
        let svg = std::fs::read_to_string(report.join("plot_test_density_pressure.svg")).unwrap();
        std::fs::remove_dir_all(&report).unwrap();
        assert!(svg.contains("tamp") && svg.contains(&name), "{svg}");
    }
}
