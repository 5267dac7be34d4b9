//! The NiAl study pressed on to high density: the 1751-particle specimen of
//! `nial_die_compaction` (its Hertz fill and flatten) pressed 0 → 600 MPa in 1e-4 s
//! under MDR (Zunker & Kamrin 2024, the law made for compaction to high relative
//! density), past relative density 0.85, with Hertz–Mindlin–Deresiewicz and
//! Storåkers m = 0 pressed beside it at the same rate of pressure.
//!
//! MDR's pressing is the case's scene, with the options LAMMPS's `pair granular mdr`
//! expresses (`lammps_linear_history` at the walls, LAMMPS's lever arms, the apparent
//! radius's moment of inertia, the die's mean curvature), so that LAMMPS replays its
//! punch stroke on the same specimen (reference_data/lammps/nial_die_compaction_dense,
//! recorded by `die_replay.sh` as the small die's replays are). Compared:
//! - with LAMMPS, the specimen density at the punch pressures 100, 300 and 600 MPa,
//!   each code's own (the particles' push on the punch, interpolated between records),
//!   and the punch pressure at which each code's specimen reaches relative density
//!   0.85;
//! - the solid balance at 600 MPa: the density against the particles' material
//!   volume less the caps pressed through the walls, over the die's volume below the
//!   punch (as `nial_die_compaction` does at 50 MPa);
//! - the pairwise laws against MDR at 300 MPa of applied pressure: each must leave the
//!   specimen less dense than MDR does.
//!
//! The pairwise pressings ramp at MDR's rate and stop at `pairwise_pressure` (300 MPa),
//! so they follow the first half of MDR's path in time. Pressed to 600 MPa, Storåkers
//! m = 0 stops where a contact's overlap reaches half the smaller radius (the scene's
//! `stability.max_overlap_fraction`; on the 300-particle specimen at 444 MPa).

use super::die_compaction_replay::{
    Row, at_pressure, recorded_deck_is_current, seed_rows, stroke_of,
};
use super::nial_die_compaction::{
    HERTZ, Law, Model, STORAKERS, at, mpa, poured_point, press_all, solid_balance, stored_specimen,
    with_model, write_curves_csv,
};
use crate::error::{Result, TampError};
use crate::plot::{Panel, Series, write_svg};
use crate::process::die_compaction::{self, PressRecord};
use crate::process::die_compaction_file::DieCompactionFile;
use crate::process::die_replay::ReplayRecord;
use crate::verify::{CaseContext, Measured};
use serde::Deserialize;

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct Parameters {
    /// The die-compaction file whose laws the pairwise pressings take (`nial_die_compaction`'s).
    pairwise_scene: String,
    /// Where the pairwise pressings stop, Pa.
    pairwise_pressure: f64,
}

/// The punch pressures at which the codes' densities are compared, Pa.
const PRESSURES: [f64; 3] = [100e6, 300e6, 600e6];

/// The relative density whose pressure the codes are compared at.
const TARGET_DENSITY: f64 = 0.85;

pub fn full(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let parameters: Parameters = ctx.parameters()?;
    let scene = ctx.die_compaction()?;
    let dc = &scene.die_compaction;
    let store = ctx.store()?;
    let specimen = stored_specimen(&store, &scene)?;

    let pairwise = pairwise_scene(ctx, &scene, &parameters)?;
    let storakers_m0 = Model {
        label: STORAKERS[0].2,
        law: Law::Storakers(STORAKERS[0].0, STORAKERS[0].1),
        ..HERTZ
    };
    let pressings = [
        ("mdr", scene.clone()),
        (HERTZ.label, with_model(&pairwise, &HERTZ)?),
        (storakers_m0.label, with_model(&pairwise, &storakers_m0)?),
    ];
    let done = press_all(ctx, &specimen, &pressings, &store)?;
    let labels: Vec<&str> = pressings.iter().map(|(l, _)| *l).collect();
    let pressed: Vec<_> = done.into_iter().map(|d| d.pressing).collect();
    write_curves_csv(ctx, &labels, &pressed)?;
    // LAMMPS's replay of the stroke tamp pressed, recorded for this specimen and scene
    // (read after the pressings, which the store keeps should the recording be stale).
    let rows: Vec<Row> = ctx.peer_results("lammps")?;
    let rows = seed_rows(rows.iter(), scene.scene.seed)?;
    let stroke = stroke_of(&rows);
    let decks = ctx
        .reference_data_dir()
        .join("lammps")
        .join(&ctx.spec.name)
        .join(format!("seed{}", scene.scene.seed));
    let sha = crate::scene::read_input(&ctx.scene_path()?)?.sha256;
    recorded_deck_is_current(&decks, &sha, &stroke)?;
    if (stroke.h0 - specimen.h0).abs() > 1e-12 * specimen.h0 {
        return Err(TampError::Other(format!(
            "results.csv was recorded for a specimen of H0 = {:e} m; tamp now fills one of {:e} m: re-record (regenerate.sh)",
            stroke.h0, specimen.h0
        )));
    }
    let lammps: Vec<ReplayRecord> = rows.iter().map(|r| r.record()).collect();

    let (mdr, hertz, storakers) = (&pressed[0], &pressed[1], &pressed[2]);
    let tamp: Vec<ReplayRecord> = mdr.records.iter().map(replay_record).collect();
    write_plot(ctx, &labels, &pressed, &lammps)?;

    let last = mdr.records.last().expect("records");
    let mut measured = vec![Measured::new(
        "density_specimen_600mpa_solid_balance",
        at(mdr, dc.press.pressure, |r| r.density_specimen)?,
        solid_balance(&specimen, dc.die_diameter, last),
    )];
    for p in PRESSURES {
        measured.push(Measured::new(
            &format!("density_specimen_{}mpa", p / 1e6),
            at_pressure(&tamp, p, |r| r.density_specimen),
            at_pressure(&lammps, p, |r| r.density_specimen),
        ));
    }
    measured.push(Measured::new(
        "pressure_at_density_0.85",
        pressure_at_density(&tamp, TARGET_DENSITY)?,
        pressure_at_density(&lammps, TARGET_DENSITY)?,
    ));
    let p = parameters.pairwise_pressure;
    let mdr_at = at(mdr, p, |r| r.density_specimen)?;
    for (label, pairwise) in [("hertz", hertz), ("storakers_m0", storakers)] {
        measured.push(Measured::new(
            &format!("density_specimen_{}mpa_{label}_minus_mdr", p / 1e6),
            at(pairwise, p, |r| r.density_specimen)? - mdr_at,
            0.0,
        ));
    }
    Ok(measured)
}

/// `pairwise_scene` pressed at the rate of the case's ramp up to `pairwise_pressure`:
/// the same pressure at every time the two share, and records at the same pressures.
fn pairwise_scene(
    ctx: &CaseContext,
    scene: &DieCompactionFile,
    parameters: &Parameters,
) -> Result<DieCompactionFile> {
    let mut pairwise = ctx.die_compaction_at(&ctx.dir.join(&parameters.pairwise_scene))?;
    let mut press = scene.die_compaction.press.clone();
    let fraction = parameters.pairwise_pressure / press.pressure;
    let records = press.records as f64 * fraction;
    if !(fraction > 0.0 && fraction <= 1.0) || records.fract() != 0.0 {
        return Err(TampError::input(
            format!(
                "verification/{}.json: parameters.pairwise_pressure",
                ctx.spec.name
            ),
            "must be a fraction of the scene's press.pressure that falls on one of its records",
        ));
    }
    press.pressure = parameters.pairwise_pressure;
    press.ramp_time *= fraction;
    press.records = records as usize;
    pairwise.die_compaction.press = press;
    pairwise.validate()?;
    Ok(pairwise)
}

/// A record of tamp's pressing as the replays record theirs.
fn replay_record(r: &PressRecord) -> ReplayRecord {
    ReplayRecord {
        time: r.time,
        height: r.height,
        punch_pressure: r.punch_reaction,
        floor_pressure: r.floor_reaction,
        density_specimen: r.density_specimen,
        density_rve: r.density_rve,
    }
}

/// The punch pressure at which the specimen density first reaches `density`, linear
/// between the two records that bracket it.
fn pressure_at_density(records: &[ReplayRecord], density: f64) -> Result<f64> {
    records
        .windows(2)
        .find_map(|w| {
            let (a, b) = (&w[0], &w[1]);
            (a.density_specimen < density && density <= b.density_specimen).then(|| {
                let s = (density - a.density_specimen) / (b.density_specimen - a.density_specimen);
                a.punch_pressure + s * (b.punch_pressure - a.punch_pressure)
            })
        })
        .ok_or_else(|| TampError::Other(format!("the specimen never reaches density {density}")))
}

/// `<case>_density.svg`: specimen density against pressure, tamp's three laws against
/// the applied pressure, MDR in both codes against the punch's.
fn write_plot(
    ctx: &CaseContext,
    labels: &[&str],
    pressed: &[die_compaction::Pressing],
    lammps: &[ReplayRecord],
) -> Result<()> {
    let mut series: Vec<Series> = labels
        .iter()
        .zip(pressed)
        .map(|(label, p)| {
            Series::line(
                &format!("tamp {label}, applied pressure"),
                mpa(&p.records, |r| r.density_specimen),
            )
        })
        .collect();
    let punch = |name: &str, records: Vec<ReplayRecord>| {
        let points = records
            .iter()
            .map(|r| (r.punch_pressure / 1e6, r.density_specimen));
        Series::line(name, points.collect())
    };
    series.push(punch(
        "tamp mdr, punch pressure",
        pressed[0].records.iter().map(replay_record).collect(),
    ));
    series.push(punch(
        "LAMMPS mdr replaying tamp's stroke, punch pressure",
        lammps.to_vec(),
    ));
    series.push(poured_point());
    write_svg(
        &ctx.report_dir
            .join(format!("{}_density.svg", ctx.spec.name)),
        &[Panel {
            title: "NiAl die compaction to 600 MPa: specimen density vs pressure, μ = 0",
            x_label: "pressure (MPa)",
            y_label: "relative density (specimen)",
            log_x: false,
            log_y: false,
            series: &series,
        }],
    )
}
