//! Cold uniaxial die compaction of NiAl powder (Rojek et al. 2016 §5), end to end:
//! fill, flatten and press (`process::die_compaction`), then the density–pressure
//! curves.
//!
//! `nial_die_compaction_small` (quick, `nial_die_compaction_small.rs`): ≈ 300
//! particles of the derived size distribution (reference_data/nial/README.md) in a die
//! scaled to keep the paper's H₀/D, pressed on any engine; it shares this file's
//! records, curves and plots.
//!
//! `nial_die_compaction` (full): the paper's specimen (1751 particles, 58 µm die,
//! 54 µm RVE), filled and flattened once, then pressed under Hertz–Mindlin–
//! Deresiewicz and under Storåkers with Rojek's three Hollomon pairs, all
//! frictionless between particles, and friction sweeps μ = 0.01, 0.02, 0.05 for
//! Hertz and Storåkers m = 0.2 (Figs 17–20). The pressings are independent and run
//! on as many threads as the machine has (each one single-threaded and
//! deterministic, so the results do not depend on the thread count).
//!
//! The full case runs for most of an hour, so it keeps its work in the runner's
//! store (`verify::store`, `<report>/nial_die_compaction_runs/`): the specimen,
//! each finished pressing, and a restart checkpoint of each pressing under way. A
//! `tamp verify` that is killed goes on from there when run again; a change of code
//! or scene starts the work afresh.

use crate::contact::mdr::{Mdr, MdrDamping, damping::MdrDampingForm};
use crate::contact::normal::{NormalLaw, Storakers};
use crate::contact::tangential::{TangentialLaw, storakers};
use crate::error::{Result, TampError};
use crate::plot::{Panel, Series, write_svg};
use crate::process::die_compaction::{self, PressRecord, PressState, Pressing, Specimen};
use crate::process::die_compaction_file::DieCompactionFile;
use crate::process::press_cycle::{self, Cycle, EjectSpec, UnloadSpec};
use crate::scene::schema::HollomonSpec;
use crate::verify::store::{Store, key_of};
use crate::verify::{CaseContext, Measured};
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// Rojek 2016 Table 1: the mean relative bulk density of the poured powder.
const POURED_DENSITY: f64 = 0.650;
/// Records below this fraction of the final pressure are left out of the force
/// balance: there the bed is still being set in motion and the balance is judged
/// against a pressure near zero.
const BALANCE_FROM: f64 = 0.1;

/// The normal law of one pressing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Law {
    /// The scene's Hertz–Mindlin–Deresiewicz.
    Hertz,
    /// Storåkers with Hollomon m and σ₀ (Pa).
    Storakers(f64, f64),
    /// MDR (`MDR`): Zunker & Kamrin's law for compaction to high density.
    Mdr,
}

/// A contact law of one pressing.
#[derive(Clone, Copy, Debug)]
pub(super) struct Model {
    pub(super) label: &'static str,
    pub(super) law: Law,
    /// Friction between particles (the die wall keeps the scene's 0.02).
    pub(super) friction: f64,
}

impl Model {
    /// Whether the pressing goes on through the press cycle (`CYCLE_UNLOAD`,
    /// `CYCLE_EJECT`): the frictionless pairwise ones do.
    fn cycle(&self) -> bool {
        self.friction == 0.0 && self.law != Law::Mdr
    }
}

pub(super) const HERTZ: Model = Model {
    label: "hertz",
    law: Law::Hertz,
    friction: 0.0,
};

/// MDR with NiAl's E and ν, the yield stress of the Storåkers m = 0 pair (800 MPa, a
/// perfectly plastic solid, which is what MDR models), no adhesion, the bulk response
/// below a free-surface fraction of 0.5 (Zunker & Kamrin's value, LAMMPS's example),
/// and the dashpot `damping mdr 1` with η = 1.8 = 2ξ for the Hertz pressing's ξ = 0.9:
/// the law of reference_data/lammps/nial_die_compaction_mdr.
#[allow(clippy::approx_constant)] // NiAl's ν, not 1/π
const MDR: Mdr = Mdr {
    youngs_modulus: 1.83e11,
    poisson_ratio: 0.318,
    yield_stress: 800e6,
    surface_energy: 0.0,
    wall_surface_energy: None,
    bulk_trigger: 0.5,
    damping: MdrDamping {
        coefficient: 1.8,
        form: MdrDampingForm::Stiffness,
    },
};

/// The frictionless pressings go on through the press cycle as
/// `nial_die_compaction_small_cycle` does: the upper punch withdrawn at 0.05 m/s (the
/// unloading of `die_press_cycle`, below the pressing's own mean punch speed) and the
/// compact pushed out at up to 1 m/s.
const CYCLE_UNLOAD: UnloadSpec = UnloadSpec {
    speed: 0.05,
    record_interval: 2e-7,
};
const CYCLE_EJECT: EjectSpec = EjectSpec {
    speed: 1.0,
    records: 40,
    ramp_time: None,
};

/// Rojek §5: the three Hollomon pairs (m, σ₀).
pub(super) const STORAKERS: [(f64, f64, &str); 3] = [
    (0.0, 800e6, "storakers_m0"),
    (0.1, 1375e6, "storakers_m0.1"),
    (0.2, 2363e6, "storakers_m0.2"),
];

const FRICTIONS: [(f64, &str, &str); 3] = [
    (0.01, "hertz_mu0.01", "storakers_m0.2_mu0.01"),
    (0.02, "hertz_mu0.02", "storakers_m0.2_mu0.02"),
    (0.05, "hertz_mu0.05", "storakers_m0.2_mu0.05"),
];

/// MDR's overlap limit: a small particle pressed between two large ones flattens into
/// a disc, its overlap with each approaching its radius, which the law follows (the
/// displaced volume, the bulk response); the run stops only once one is pushed
/// nearly through the other.
const MDR_MAX_OVERLAP: f64 = 0.95;

/// MDR's pressing and those of Figs 17–20, longest first (MDR, Storåkers, then Hertz with
/// friction, then frictionless Hertz; their times are in reference_data/nial/README.md), so that
/// the threads that share them finish close together; a run cut short keeps each
/// pressing's checkpoint.
fn full_models() -> Vec<Model> {
    let storakers = |k: usize, friction: f64, label: &'static str| Model {
        label,
        law: Law::Storakers(STORAKERS[k].0, STORAKERS[k].1),
        friction,
    };
    let hertz = |friction: f64, label: &'static str| Model {
        label,
        law: Law::Hertz,
        friction,
    };
    let (mu, h, s) = (
        FRICTIONS.map(|f| f.0),
        FRICTIONS.map(|f| f.1),
        FRICTIONS.map(|f| f.2),
    );
    vec![
        Model {
            label: "mdr",
            law: Law::Mdr,
            friction: 0.0,
        },
        storakers(2, 0.0, STORAKERS[2].2),
        storakers(1, 0.0, STORAKERS[1].2),
        storakers(2, mu[1], s[1]),
        storakers(2, mu[2], s[2]),
        storakers(0, 0.0, STORAKERS[0].2),
        storakers(2, mu[0], s[0]),
        hertz(mu[0], h[0]),
        hertz(mu[1], h[1]),
        hertz(mu[2], h[2]),
        HERTZ,
    ]
}

/// The case scene with a model's normal law, Hollomon constants and friction. The
/// Storåkers runs take Rojek's tangential law (eq 21, k_t = β k_n) with β = 1, the
/// middle of the 0.5–5 Olsson & Larsson suggest, since §5 does not state it. MDR
/// keeps the Mindlin–Deresiewicz friction (only the walls have any) and brings its
/// own dashpot.
pub(super) fn with_model(scene: &DieCompactionFile, model: &Model) -> Result<DieCompactionFile> {
    let mut s = scene.clone();
    let tangential = s.scene.contact.tangential.as_mut().ok_or_else(|| {
        TampError::Other("the NiAl scene must have a tangential law (wall friction)".into())
    })?;
    tangential.friction = model.friction;
    if model.law == Law::Mdr {
        s.scene.contact.normal = NormalLaw::Mdr(MDR);
        s.scene.contact.damping = None;
        s.scene.stability.max_overlap_fraction = MDR_MAX_OVERLAP;
    }
    if let Law::Storakers(m, sigma0) = model.law {
        s.scene.contact.normal = NormalLaw::Storakers(Storakers {
            min_with_hertz: false,
        });
        tangential.law = TangentialLaw::Storakers(storakers::Storakers { beta: 1.0 });
        for material in &mut s.scene.materials {
            material.hollomon = Some(HollomonSpec {
                exponent: m,
                strength: Some(sigma0),
                yield_stress: None,
            });
        }
    }
    s.validate()?;
    Ok(s)
}

/// The study's pressing of `model`: the law, and the press cycle for the models
/// that go through it.
fn study_pressing(scene: &DieCompactionFile, model: &Model) -> Result<DieCompactionFile> {
    let mut s = with_model(scene, model)?;
    if model.cycle() {
        s.die_compaction.unload = Some(CYCLE_UNLOAD);
        s.die_compaction.eject = Some(CYCLE_EJECT);
        s.validate()?;
    }
    Ok(s)
}

/// Steps between restart checkpoints of a pressing (a 1751-particle pressing takes
/// 2–5 million steps; a checkpoint is a few MB of JSON).
const CHECKPOINT_EVERY: u64 = 200_000;

/// A finished pressing, with its press cycle when it has one, and the wall time it
/// took (over all sessions it ran in).
#[derive(Serialize, Deserialize)]
pub(super) struct Done {
    pub(super) pressing: Pressing,
    #[serde(default)]
    cycle: Option<Cycle>,
    wall_s: f64,
}

/// Press one specimen in each of the labelled scenes, one per core at a time, reusing
/// and checkpointing work in `store` under each label.
pub(super) fn press_all(
    ctx: &CaseContext,
    specimen: &Specimen,
    pressings: &[(&str, DieCompactionFile)],
    store: &Store,
) -> Result<Vec<Done>> {
    let press_one = |(label, s): &(&str, DieCompactionFile)| -> Result<Done> {
        let key = key_of(s);
        let done_file = format!("{label}.done.json");
        if let Some(done) = store.load::<Done>(&done_file, &key) {
            eprintln!("{}: pressing '{label}' reused", ctx.spec.name);
            return Ok(done);
        }
        let checkpoint_file = format!("{label}.checkpoint.json");
        let resume: Option<(PressState, f64)> = store.load(&checkpoint_file, &key);
        let (resume, earlier_wall) = match resume {
            Some((state, wall)) => {
                eprintln!(
                    "{}: pressing '{label}' resumed at step {}",
                    ctx.spec.name, state.pressing.steps
                );
                (Some(state), wall)
            }
            None => (None, 0.0),
        };
        let started = std::time::Instant::now();
        let mut save = |state: &PressState| {
            let wall = earlier_wall + started.elapsed().as_secs_f64();
            store.save(&checkpoint_file, &key, &(state, wall))
        };
        let (pressing, sim) =
            die_compaction::press(s, specimen, false, resume, CHECKPOINT_EVERY, &mut save)?;
        // An interrupted cycle starts again from the checkpoint at the peak.
        let cycle = match s.die_compaction.unload {
            Some(_) => {
                let fixed = die_compaction::press_scene(s, specimen)?.time_step.fixed;
                Some(press_cycle::run(s, specimen, &pressing, sim, fixed, false)?)
            }
            None => None,
        };
        let done = Done {
            pressing,
            cycle,
            wall_s: earlier_wall + started.elapsed().as_secs_f64(),
        };
        store.save(&done_file, &key, &done)?;
        eprintln!(
            "{}: pressing '{label}' done, {:.0} s",
            ctx.spec.name, done.wall_s
        );
        Ok(done)
    };
    ctx.map(pressings, press_one)
        .into_iter()
        .zip(pressings)
        .map(|(r, (label, _))| r.map_err(|e| TampError::Other(format!("pressing '{label}': {e}"))))
        .collect()
}

/// The study's specimen, filled and flattened once per scene and kept in the store.
pub(super) fn stored_specimen(store: &Store, scene: &DieCompactionFile) -> Result<Specimen> {
    store.cached("specimen.json", &key_of(scene), || {
        die_compaction::prepare(scene, false)
    })
}

/// The particles' volume: with every particle inside the die, the exact solid volume
/// of the specimen is this less the caps pressed through the walls.
pub(super) fn solid_volume(specimen: &Specimen) -> f64 {
    specimen
        .particles
        .iter()
        .map(|p| 4.0 / 3.0 * PI * p.radius.powi(3))
        .sum()
}

/// Volume conservation: the specimen's relative density at a record, from its solid
/// volume and the die's volume at the record's height.
pub(super) fn solid_balance(specimen: &Specimen, die_diameter: f64, r: &PressRecord) -> f64 {
    let die_area = PI * (0.5 * die_diameter).powi(2);
    (solid_volume(specimen) - r.wall_lens_volume) / (die_area * r.height)
}

pub(super) fn at(pressing: &Pressing, p: f64, column: fn(&PressRecord) -> f64) -> Result<f64> {
    pressing
        .at_pressure(p, column)
        .or_else(|| {
            let last = pressing.records.last()?;
            (last.pressure == p).then(|| column(last))
        })
        .ok_or_else(|| TampError::Other(format!("no record brackets {p:e} Pa")))
}

/// Largest fall of a column between consecutive records (0 when it never falls).
pub(super) fn largest_drop(pressing: &Pressing, column: fn(&PressRecord) -> f64) -> f64 {
    pressing
        .records
        .windows(2)
        .map(|w| column(&w[0]) - column(&w[1]))
        .fold(0.0, f64::max)
}

/// Largest |a − b| over the records past the start of the ramp, as a fraction of
/// the final pressure.
pub(super) fn largest_imbalance(pressing: &Pressing, gap: fn(&PressRecord) -> f64) -> f64 {
    let p_max = pressing.records.last().map_or(1.0, |r| r.pressure);
    pressing
        .records
        .iter()
        .filter(|r| r.pressure >= BALANCE_FROM * p_max)
        .map(|r| gap(r).abs() / p_max)
        .fold(0.0, f64::max)
}

pub(super) fn mpa(points: &[PressRecord], column: fn(&PressRecord) -> f64) -> Vec<(f64, f64)> {
    points
        .iter()
        .map(|r| (r.pressure / 1e6, column(r)))
        .collect()
}

pub(super) fn poured_point() -> Series {
    Series::points(
        "experiment: poured density, Rojek Table 1 (the curve of Fig 5 is not available)",
        vec![(0.0, POURED_DENSITY)],
    )
}

pub(super) fn write_curves_csv(
    ctx: &CaseContext,
    labels: &[&str],
    pressings: &[Pressing],
) -> Result<()> {
    let mut csv = String::from(
        "model,pressure_pa,punch_reaction_pa,floor_reaction_pa,die_friction_pa,height_m,height_reduction,density_specimen,density_rve,contact_count\n",
    );
    for (label, p) in labels.iter().zip(pressings) {
        for r in &p.records {
            csv.push_str(&format!(
                "{label},{:e},{:e},{:e},{:e},{:e},{:e},{:e},{:e},{}\n",
                r.pressure,
                r.punch_reaction,
                r.floor_reaction,
                r.die_friction,
                r.height,
                r.height_reduction,
                r.density_specimen,
                r.density_rve,
                r.contact_count
            ));
        }
    }
    crate::output::write_atomic(
        &ctx.report_dir.join(format!("{}_curves.csv", ctx.spec.name)),
        csv.as_bytes(),
    )
}

pub fn full(ctx: &CaseContext) -> Result<Vec<Measured>> {
    let scene = ctx.die_compaction()?;
    let dc = &scene.die_compaction;
    // Not quiet: this case runs for most of an hour, and its log says how far it got.
    let store = ctx.store()?;
    let specimen = stored_specimen(&store, &scene)?;
    eprintln!(
        "nial_die_compaction: specimen H0 = {:e} m, density {:.4}, RVE {:.4}",
        specimen.h0, specimen.density_specimen, specimen.density_rve
    );
    let models = full_models();
    let (mut pressings, mut walls, mut cycled) = (Vec::new(), Vec::new(), Vec::new());
    let scenes = models
        .iter()
        .map(|m| Ok((m.label, study_pressing(&scene, m)?)))
        .collect::<Result<Vec<_>>>()?;
    for d in press_all(ctx, &specimen, &scenes, &store)? {
        pressings.push(d.pressing);
        walls.push(d.wall_s);
        cycled.push(d.cycle);
    }
    let cycles: Vec<(&str, &Cycle)> = models
        .iter()
        .zip(&cycled)
        .filter_map(|(m, c)| c.as_ref().map(|c| (m.label, c)))
        .collect();
    write_cycles(ctx, &cycles)?;
    let mut timing = String::from("model,steps,wall_s\n");
    for ((m, p), w) in models.iter().zip(&pressings).zip(&walls) {
        timing.push_str(&format!("{},{},{w:.1}\n", m.label, p.steps));
    }
    crate::output::write_atomic(
        &ctx.report_dir
            .join(format!("{}_wall_times.csv", ctx.spec.name)),
        timing.as_bytes(),
    )?;
    let labels: Vec<&str> = models.iter().map(|m| m.label).collect();
    write_curves_csv(ctx, &labels, &pressings)?;
    let find = |label: &str| -> &Pressing {
        &pressings[labels
            .iter()
            .position(|l| *l == label)
            .expect("model listed")]
    };
    let p_max = dc.press.pressure;
    let hertz = find("hertz");
    let last = hertz.records.last().expect("records");

    // Plots: density against pressure (all frictionless models), ΔH/H₀, friction sweeps.
    let name = &ctx.spec.name;
    let frictionless = [
        "hertz",
        "storakers_m0",
        "storakers_m0.1",
        "storakers_m0.2",
        "mdr",
    ];
    let mut density = Vec::new();
    let mut height = Vec::new();
    for label in frictionless {
        let p = find(label);
        density.push(Series::line(
            &format!("{label}, specimen"),
            mpa(&p.records, |r| r.density_specimen),
        ));
        density.push(Series::line(
            &format!("{label}, RVE"),
            mpa(&p.records, |r| r.density_rve),
        ));
        height.push(Series::line(label, mpa(&p.records, |r| r.height_reduction)));
    }
    // LAMMPS's mdr law on the same specimen: a comparison of models (mdr_curve).
    let mdr = super::mdr_curve::load(&crate::verify::reference_data_beside(&ctx.dir))?;
    density.push(super::mdr_curve::density(&mdr));
    height.push(super::mdr_curve::height_reduction(&mdr));
    density.push(poured_point());
    write_svg(
        &ctx.report_dir.join(format!("{name}_density.svg")),
        &[Panel {
            title: "NiAl die compaction: relative density vs pressure, μ = 0 (Rojek Fig 18)",
            x_label: "pressure (MPa)",
            y_label: "relative density",
            log_x: false,
            log_y: false,
            series: &density,
        }],
    )?;
    write_svg(
        &ctx.report_dir.join(format!("{name}_height.svg")),
        &[Panel {
            title: "NiAl die compaction: ΔH/H0 vs pressure, μ = 0 (Rojek Fig 17)",
            x_label: "pressure (MPa)",
            y_label: "ΔH / H0",
            log_x: false,
            log_y: false,
            series: &height,
        }],
    )?;
    for (base, title) in [
        ("hertz", "Hertz–Mindlin–Deresiewicz (Rojek Fig 19)"),
        ("storakers_m0.2", "Storåkers m = 0.2 (Rojek Fig 20)"),
    ] {
        let mut sweep = vec![Series::line(
            "μ = 0",
            mpa(&find(base).records, |r| r.density_rve),
        )];
        for (mu, _, _) in FRICTIONS {
            sweep.push(Series::line(
                &format!("μ = {mu}"),
                mpa(&find(&format!("{base}_mu{mu}")).records, |r| r.density_rve),
            ));
        }
        sweep.push(poured_point());
        write_svg(
            &ctx.report_dir.join(format!("{name}_friction_{base}.svg")),
            &[Panel {
                title: &format!("RVE density vs pressure with friction: {title}"),
                x_label: "pressure (MPa)",
                y_label: "relative density (RVE)",
                log_x: false,
                log_y: false,
                series: &sweep,
            }],
        )?;
    }

    let solid = solid_volume(&specimen);
    let rve0 = specimen.density_rve;
    let first = hertz.records.first().expect("records");
    let ten = 10e6;
    let mut measured = vec![
        Measured::new("initial_density_specimen", specimen.density_specimen, 0.62),
        Measured::new("initial_density_rve", rve0, 0.66),
        Measured::new(
            "density_specimen_at_50MPa_hertz",
            at(hertz, p_max, |r| r.density_specimen)?,
            solid_balance(&specimen, dc.die_diameter, last),
        ),
        Measured::new(
            "height_reduction_at_50MPa_hertz",
            last.height_reduction,
            1.0 - first.density_specimen * (solid - last.wall_lens_volume)
                / (last.density_specimen * (solid - first.wall_lens_volume)),
        ),
        // The core cannot end looser than it began, nor densify more than the
        // specimen as a whole: it starts densest (near random close packing), so the
        // loose wall and top layers take more of the strain (measured: the core
        // takes 43 % of the uniform share under Hertz).
        Measured::between(
            "density_rve_at_50MPa_hertz",
            at(hertz, p_max, |r| r.density_rve)?,
            rve0,
            rve0 * specimen.h0 / last.height,
        ),
        Measured::new(
            "density_rve_at_50MPa_storakers_m0.2",
            at(find("storakers_m0.2"), p_max, |r| r.density_rve)?,
            at(hertz, p_max, |r| r.density_rve)?,
        ),
        Measured::new(
            "density_rve_at_10MPa_mu0.05_minus_mu0",
            at(find("hertz_mu0.05"), ten, |r| r.density_rve)? - at(hertz, ten, |r| r.density_rve)?,
            0.0,
        ),
    ];
    // MDR: the solid balance with the material's balls (State::material_radius), and
    // LAMMPS's mdr on the same specimen.
    let mdr_pressing = find("mdr");
    let mdr_last = mdr_pressing.records.last().expect("records");
    let mdr_density = at(mdr_pressing, p_max, |r| r.density_specimen)?;
    measured.extend([
        Measured::new(
            "density_specimen_at_50MPa_mdr",
            mdr_density,
            solid_balance(&specimen, dc.die_diameter, mdr_last),
        ),
        Measured::new(
            "density_specimen_at_50MPa_mdr_minus_lammps",
            mdr_density - super::mdr_curve::density_at(&mdr, p_max)?,
            0.0,
        ),
    ]);
    for (label, c) in &cycles {
        let missing = || TampError::Other(format!("the {label} cycle did not unload"));
        measured.push(Measured::new(
            &format!("unloading_work_{label}"),
            c.summary.unloading_work.ok_or_else(missing)?,
            c.summary.returned_by_book().ok_or_else(missing)?,
        ));
    }
    Ok(measured)
}

/// `<case>_cycle.csv` (each cycle's quantities, one row per law),
/// `<case>_cycle_series.csv` (their records) and `<case>_cycle.svg`: the upper
/// punch's pressure against the specimen's density through pressing and unloading,
/// and the lower punch's push against its rise through the ejection.
fn write_cycles(ctx: &CaseContext, cycles: &[(&str, &Cycle)]) -> Result<()> {
    let name = &ctx.spec.name;
    let mut table = String::new();
    for (k, (label, c)) in cycles.iter().enumerate() {
        let q = c.summary.quantities();
        if k == 0 {
            let names: Vec<&str> = q.iter().map(|(n, _)| n.as_str()).collect();
            table.push_str(&format!("model,{}\n", names.join(",")));
        }
        let values: Vec<String> = q.iter().map(|(_, v)| format!("{v:e}")).collect();
        table.push_str(&format!("{label},{}\n", values.join(",")));
    }
    crate::output::write_atomic(
        &ctx.report_dir.join(format!("{name}_cycle.csv")),
        table.as_bytes(),
    )?;
    crate::output::write_atomic(
        &ctx.report_dir.join(format!("{name}_cycle_series.csv")),
        press_cycle::labelled_series_csv("model", cycles).as_bytes(),
    )?;
    let loading: Vec<Series> = cycles
        .iter()
        .map(|(label, c)| {
            let points = c
                .records
                .iter()
                .filter(|r| {
                    matches!(
                        r.stage,
                        press_cycle::Stage::Press | press_cycle::Stage::Unload
                    )
                })
                .map(|r| (r.density_specimen, r.upper_punch / 1e6));
            Series::line(label, points.collect())
        })
        .collect();
    let ejection: Vec<Series> = cycles
        .iter()
        .map(|(label, c)| {
            let points = c
                .records
                .iter()
                .filter(|r| r.stage == press_cycle::Stage::Eject)
                .map(|r| (r.ejection * 1e6, r.lower_punch / 1e6));
            Series::line(label, points.collect())
        })
        .collect();
    write_svg(
        &ctx.report_dir.join(format!("{name}_cycle.svg")),
        &[
            Panel {
                title: "NiAl press cycle: pressing and unloading, μ = 0",
                x_label: "relative density (specimen)",
                y_label: "upper punch pressure (MPa)",
                log_x: false,
                log_y: false,
                series: &loading,
            },
            Panel {
                title: "NiAl press cycle: ejection",
                x_label: "lower punch rise (µm)",
                y_label: "lower punch pressure (MPa)",
                log_x: false,
                log_y: false,
                series: &ejection,
            },
        ],
    )
}
