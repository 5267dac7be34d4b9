//! The `tamp` command line: parse arguments, call the library, map errors to the
//! exit codes of the contract (0 ok; 1 a verification or comparison failed, or a file
//! could not be read or written; 2 bad input; 3 unstable).

use clap::{Parser, Subcommand};
use std::path::PathBuf;
use std::process::ExitCode;
use tamp::verify::{self, Tier};

#[derive(Parser)]
#[command(
    name = "tamp",
    version,
    about = "Verification-first DEM for powder packing and die compaction",
    after_help = "Exit codes: 0 ok; 1 a verification or comparison failed, or a file could not be read or written (the message names it); 2 bad input (the message names the field and the rule); 3 the run became unstable (the message names the particle or contact and the step); 130/143 `tamp run` stopped by SIGINT/SIGTERM after a whole step (a checkpoint is written when output.checkpoint_every is set)."
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Run a scene file (or a die-compaction file) and write its results to DIR.
    #[command(after_help = RUN_HELP)]
    Run {
        /// The scene, a JSON file (fields: docs/scene-format.md; examples:
        /// verification/*.scene.json); `-` reads it from standard input.
        scene: PathBuf,
        /// Output directory, created if needed. The run first deletes what an earlier
        /// run left there under its own file names.
        #[arg(long, value_name = "DIR")]
        out: PathBuf,
        /// No progress bar or log lines on stderr.
        #[arg(long)]
        quiet: bool,
        /// Go on from DIR/checkpoint.json if there is one (scene field
        /// output.checkpoint_every); start from step 0 otherwise.
        #[arg(long)]
        resume: bool,
    },
    /// Run verification cases and write the report (REPORT/verification.md, .html and .json).
    Verify {
        /// quick: about 10 min on 2 cores with cases side by side (CI). full: the papers' scale, many hours
        /// (the NiAl die compaction alone about 55 min, each full 2D compaction about
        /// 105 min); it includes the quick cases, and an interrupted NiAl case goes on
        /// from REPORT/nial_die_compaction_runs/.
        #[arg(long, value_enum, default_value_t = Tier::Quick)]
        tier: Tier,
        /// Only these cases (repeatable).
        #[arg(long = "case")]
        cases: Vec<String>,
        /// All the tier's cases but these (repeatable; not with --case).
        #[arg(long = "skip-case", value_name = "CASE", conflicts_with = "cases")]
        skip: Vec<String>,
        /// Also write the JSON result to this file (default: REPORT/verification.json).
        #[arg(long)]
        json: Option<PathBuf>,
        /// Directory of the report, its plots and its CSVs.
        #[arg(long, default_value = "report")]
        report: PathBuf,
        /// Cases run side by side (default: one per core). Results do not depend on
        /// it; the wall times in the report do (cores are shared), so time with 1.
        #[arg(long)]
        jobs: Option<usize>,
        /// The engine the cases run on (repeatable; default tamp): tamp, liggghts,
        /// lammps, or command:PROG, an adapter run as `PROG SCENE_JSON OUT_DIR`
        /// (docs/engines.md). Each case runs once per engine.
        #[arg(long = "engine", value_name = "ENGINE")]
        engines: Vec<verify::engine::Engine>,
        /// Run the peer engines (liggghts, lammps) now, and check each run against its
        /// record in reference_data/<peer>/engine/ (byte for byte, else every value to
        /// 1e-9). Without it a peer engine gives its recorded values, and needs no peer.
        #[arg(long)]
        live: bool,
        /// With --live: write the peer runs' records instead of checking them.
        #[arg(long, requires = "live")]
        record: bool,
    },
    /// Write a LIGGGHTS 3.8 deck (in.tamp, particles.data, meshes) for SCENE into DIR.
    ExportLiggghts {
        /// The scene to translate; what LIGGGHTS cannot express is listed, exit 2.
        scene: PathBuf,
        /// Directory of the deck.
        #[arg(long, value_name = "DIR")]
        out: PathBuf,
        /// Steps between frames of dump.liggghts (default: the scene's
        /// trajectory_every, else its series_every, else about 100 frames); the final
        /// state always goes to final.liggghts.
        #[arg(long)]
        dump_every: Option<u64>,
        /// Replace the scene's seed (a new random placement, the same scene otherwise).
        #[arg(long)]
        seed: Option<u64>,
    },
    /// Write a LAMMPS deck (in.tamp, particles.data) for SCENE into DIR, for LAMMPS's
    /// pair_style granular (22 Jul 2025; .ci/install-lammps).
    ExportLammps {
        /// The scene to translate; what LAMMPS cannot express is listed, exit 2.
        scene: PathBuf,
        /// Directory of the deck.
        #[arg(long, value_name = "DIR")]
        out: PathBuf,
        /// Steps between frames of dump.lammps (default: the scene's trajectory_every,
        /// else its series_every, else about 100 frames); the final state always goes
        /// to final.lammps.
        #[arg(long)]
        dump_every: Option<u64>,
        /// Replace the scene's seed (a new random placement, the same scene otherwise).
        #[arg(long)]
        seed: Option<u64>,
    },
    /// Convert a LIGGGHTS dump to trajectory.csv and measure its last frame
    /// (quantities.csv) in DIR.
    ImportLiggghtsDump {
        /// A `dump custom` file of LIGGGHTS or LAMMPS (id, radius, x y z, vx vy vz,
        /// omegax omegay omegaz; atoms in any order, from any number of ranks).
        file: PathBuf,
        /// Directory of trajectory.csv and quantities.csv.
        #[arg(long, value_name = "DIR")]
        out: PathBuf,
        /// Height of the floor under the bed, m (default: the lowest sphere bottom).
        #[arg(long)]
        floor: Option<f64>,
        /// Gravity along −z, m/s²: adds floor_force_over_weight (needs mass and fz).
        #[arg(long)]
        gravity: Option<f64>,
        /// Average floor_force_over_weight over the frames from this step on
        /// (default: the last frame only).
        #[arg(long)]
        average_from: Option<u64>,
        /// The stroke.json of a die-compaction export: also write die.csv, the
        /// specimen and RVE densities of every record's frame.
        #[arg(long, value_name = "FILE")]
        die_stroke: Option<PathBuf>,
    },
    /// Compare run A with the reference run B (layout: docs/compare.md); exit 1
    /// beyond tolerance.
    Compare {
        /// The run to check: a directory with quantities.csv and/or trajectory.csv.
        a: PathBuf,
        /// The reference run, in the same layout.
        b: PathBuf,
        /// CSV `item,tolerance,kind` overriding the defaults.
        #[arg(long)]
        tolerances: Option<PathBuf>,
    },
    /// Run the LIGGGHTS cross-check cases against the recorded LIGGGHTS results, or
    /// against LIGGGHTS run now (--live).
    Crosscheck {
        /// Run the peers now (LIGGGHTS: `apt-get install liggghts`; LAMMPS:
        /// .ci/install-lammps) and require their results to equal the recorded ones.
        #[arg(long)]
        live: bool,
        /// Which cross-check cases: quick (seconds) or full.
        #[arg(long, value_enum, default_value_t = Tier::Quick)]
        tier: Tier,
        /// Only this peer's cases (repeatable; default: LIGGGHTS and LAMMPS).
        #[arg(long = "peer", value_enum)]
        peers: Vec<tamp::verify::crosscheck::Peer>,
        /// Only these cases (repeatable; a named case runs whatever its tier).
        #[arg(long = "case")]
        cases: Vec<String>,
        /// Directory of the cross-check report.
        #[arg(long, default_value = "report")]
        report: PathBuf,
    },
    /// Numerical studies. Each writes into the directory given by --out (default
    /// `study/`); only an explicit `--out docs` rewrites the repository's
    /// docs/accuracy-cost.md.
    Study {
        #[command(subcommand)]
        study: Study,
    },
}

#[derive(Subcommand)]
enum Study {
    /// Rerun verification cases with the time step scaled (and each broad phase for
    /// large beds): error against the case's reference, wall time, observed order.
    AccuracyCost {
        /// Only these cases (repeatable; default: every quick case).
        #[arg(long = "case")]
        cases: Vec<String>,
        /// Time-step multipliers of the sweep.
        #[arg(long, value_delimiter = ',', default_value = "8,4,2,1,0.5,0.25")]
        scales: Vec<f64>,
        /// Directory of accuracy-cost.md, accuracy-cost/<case>.csv and img/.
        #[arg(long, default_value = "study")]
        out: PathBuf,
        /// Repeat each run until this much wall time has passed, s.
        #[arg(long, default_value_t = 0.2)]
        min_wall: f64,
    },
    /// Single head-on impacts of each law with an impact closed form over a range of
    /// Δt/t_c: the error model of time_step.accuracy (docs/accuracy-cost.md).
    AccuracyCalibration {
        /// Directory of accuracy-cost.md (its calibration section) and accuracy-cost/accuracy_calibration.csv.
        #[arg(long, default_value = "study")]
        out: PathBuf,
    },
    /// Bisect the largest stable α of each contact law in a loaded FCC lattice.
    StableAlpha {
        /// Directory of accuracy-cost.md (its stable-α section) and accuracy-cost/stable_alpha.csv.
        #[arg(long, default_value = "study")]
        out: PathBuf,
    },
    /// Press one die-compaction specimen with slower ramps and smaller α: density at
    /// 50 MPa and wall time (docs/accuracy-cost.md).
    DieCompaction {
        /// The die-compaction scene (default: the quick NiAl case's).
        #[arg(long)]
        scene: Option<PathBuf>,
        /// Directory of accuracy-cost.md (its die-compaction section) and accuracy-cost/die_compaction.csv.
        #[arg(long, default_value = "study")]
        out: PathBuf,
    },
    /// Fill one die-compaction scene as a settled column and through the funnel, for
    /// several seeds: specimen and RVE densities after flattening
    /// (docs/paper-discrepancies.md §21).
    DieFilling {
        /// The die-compaction scene (default: the quick NiAl case's).
        #[arg(long)]
        scene: Option<PathBuf>,
        #[arg(long, value_delimiter = ',', default_value = "1,2,3")]
        seeds: Vec<u64>,
        /// Fillings to run: settled_column, funnel.
        #[arg(long, value_delimiter = ',', default_value = "settled_column,funnel")]
        methods: Vec<String>,
        /// Narrow the scene's log-normal size law to this σ of ln r, keeping its mean
        /// volume and bounds.
        #[arg(long)]
        sigma: Option<f64>,
        /// Directory of die-filling/<scene>.csv.
        #[arg(long, default_value = "study")]
        out: PathBuf,
    },
    /// 2D ballistic deposition at the paper's box, 20 seeds: solid fraction, contacts
    /// and coordination by lid rule and patience, the interior and strips, and the
    /// width dependence (docs/generation.md; the ballistic_deposition_2d tolerances).
    #[command(name = "deposition-2d")]
    Deposition2d {
        /// Directory of deposition-2d/{survey,interior,width}.csv.
        #[arg(long, default_value = "study")]
        out: PathBuf,
    },
    /// 3D ballistic deposition of equal spheres: bulk solid fraction and coordination
    /// over seeds (docs/generation.md), then the stress run of wide and bimodal size
    /// laws (exit 1 on any failure, overlap or unsupported sphere).
    #[command(name = "deposition-3d")]
    Deposition3d {
        /// Directory of deposition-3d/{seeds,survey,stress}.csv.
        #[arg(long, default_value = "study")]
        out: PathBuf,
    },
    /// The energy_conservation_elastic case's drift and order with seeds 7-11: the
    /// spread its tolerances rest on (docs/verification-notes.md).
    EnergyOrder {
        /// Directory of energy-order.csv.
        #[arg(long, default_value = "study")]
        out: PathBuf,
    },
}

const RUN_HELP: &str = "Files written to DIR (each under a temporary name, then renamed):
  summary.json      final quantities with provenance (version, commit, scene sha256, dt, steps)
  series.csv        the quantities of output.series every output.series_every steps
  quantities.csv    the summary's quantities as name,value rows (for `tamp compare`)
  trajectory.csv    with output.trajectory_every: one row per particle per record
  vtk/frame_*.vtk   with output.vtk_every: particles for ParaView
  checkpoint.json   with output.checkpoint_every: the state to --resume from
A die-compaction file writes the same summary.json, series.csv (one row per pressure record) and
quantities.csv, and specimen.json and press.scene.json.

Exit codes: 0 finished; 1 a file could not be read or written; 2 bad input (the field and
the rule are named; nothing is run); 3 the run became unstable (the particle or contact and
the step are named; no summary is written); 130/143 stopped by SIGINT/SIGTERM after a whole
step (a checkpoint is written when output.checkpoint_every is set).";

fn main() -> ExitCode {
    let cli = Cli::parse();
    if let Command::Run { quiet, .. } = cli.command {
        tamp::progress::set_quiet(quiet);
        if let Err(e) = tamp::interrupt::install() {
            eprintln!("warning: SIGINT and SIGTERM will end the run at once: {e}");
        }
    }
    let result = match cli.command {
        Command::Run {
            scene,
            out,
            quiet,
            resume,
        } => run(&scene, &out, quiet, resume),
        Command::Verify {
            tier,
            cases,
            json,
            report,
            jobs,
            engines,
            live,
            record,
            skip,
        } => verify::run_cli(
            tier,
            &cases,
            &skip,
            &engines,
            match (live, record) {
                (_, true) => verify::engine::peer_record::PeerRuns::Record,
                (true, false) => verify::engine::peer_record::PeerRuns::Live,
                (false, false) => verify::engine::peer_record::PeerRuns::Recorded,
            },
            json.as_deref(),
            &report,
            jobs.unwrap_or_else(verify::default_jobs),
        ),
        Command::ExportLammps {
            scene,
            out,
            dump_every,
            seed,
        } => tamp::peer_deck::export_file(
            &scene,
            &out,
            (dump_every, seed),
            tamp::lammps::export::export,
            tamp::lammps::die_compaction::export_pressing,
        )
        .map(|x| exported(&x, &out, "lmp")),
        Command::ExportLiggghts {
            scene,
            out,
            dump_every,
            seed,
        } => tamp::peer_deck::export_file(
            &scene,
            &out,
            (dump_every, seed),
            tamp::liggghts::export::export,
            tamp::liggghts::die_compaction::export_pressing,
        )
        .map(|x| exported(&x, &out, "liggghts")),
        Command::ImportLiggghtsDump {
            file,
            out,
            floor,
            gravity,
            average_from,
            die_stroke,
        } => tamp::liggghts::import::run_cli(
            &file,
            &out,
            floor,
            gravity,
            average_from,
            die_stroke.as_deref(),
        )
        .map(|q| {
            for (name, value) in q {
                println!("{name} = {value:e}");
            }
            println!("wrote {}/trajectory.csv and quantities.csv", out.display());
            0
        }),
        Command::Compare { a, b, tolerances } => {
            tamp::compare::run_cli(&a, &b, tolerances.as_deref())
        }
        Command::Crosscheck {
            live,
            tier,
            peers,
            cases,
            report,
        } => tamp::verify::crosscheck::run_cli(live, tier, &peers, &cases, &report),
        Command::Study {
            study:
                Study::AccuracyCost {
                    cases,
                    mut scales,
                    out,
                    min_wall,
                },
        } => {
            scales.sort_by(|a, b| b.total_cmp(a));
            tamp::study::accuracy_cost::run(&tamp::study::accuracy_cost::Options {
                cases,
                scales,
                out,
                min_wall_s: min_wall,
            })
        }
        Command::Study {
            study: Study::AccuracyCalibration { out },
        } => tamp::study::accuracy_calibration::run(&out),
        Command::Study {
            study: Study::StableAlpha { out },
        } => tamp::study::stable_alpha::run(&out),
        Command::Study {
            study: Study::Deposition2d { out },
        } => tamp::study::deposition_2d::run(&out),
        Command::Study {
            study: Study::Deposition3d { out },
        } => tamp::study::deposition_3d::run(&out),
        Command::Study {
            study: Study::EnergyOrder { out },
        } => tamp::study::energy_order::run(&out),
        Command::Study {
            study: Study::DieCompaction { scene, out },
        } => {
            let scene = scene.unwrap_or_else(|| {
                tamp::verify::verification_dir().join("nial_die_compaction_small.scene.json")
            });
            tamp::study::die_compaction::run(&scene, &out)
        }
        Command::Study {
            study:
                Study::DieFilling {
                    scene,
                    seeds,
                    methods,
                    sigma,
                    out,
                },
        } => (|| {
            let scene = scene.unwrap_or_else(|| {
                tamp::verify::verification_dir().join("nial_die_compaction_small.scene.json")
            });
            let methods = methods
                .iter()
                .map(|m| {
                    serde_json::from_value(serde_json::Value::String(m.clone())).map_err(|_| {
                        tamp::error::TampError::input(
                            "--methods",
                            format!("'{m}' is not a filling: settled_column or funnel"),
                        )
                    })
                })
                .collect::<tamp::error::Result<Vec<_>>>()?;
            tamp::study::die_filling::run(&tamp::study::die_filling::Options {
                scene,
                seeds,
                methods,
                sigma,
                out,
            })
        })(),
    };
    match result {
        Ok(code) => ExitCode::from(code),
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(e.exit_code() as u8)
        }
    }
}

/// `tamp run`: the input is read and parsed once; a `die_compaction` block makes it the
/// die-compaction process, anything else is a scene run as it stands.
fn run(
    scene_path: &std::path::Path,
    out: &std::path::Path,
    quiet: bool,
    resume: bool,
) -> tamp::error::Result<u8> {
    // Refused input leaves no output directory this run made: an empty directory
    // could be taken for a run's result.
    let fresh = !out.exists();
    let result = run_document(scene_path, out, quiet, resume);
    if fresh
        && let Err(tamp::error::TampError::Input { .. } | tamp::error::TampError::InputMany(_)) =
            &result
    {
        let _ = std::fs::remove_dir(out);
    }
    result
}

fn run_document(
    scene_path: &std::path::Path,
    out: &std::path::Path,
    quiet: bool,
    resume: bool,
) -> tamp::error::Result<u8> {
    use tamp::document::Document;
    match tamp::document::load(scene_path)? {
        (Document::DieCompaction(file), sha) => {
            let s = tamp::process::die_compaction_run::run_scene(
                &file, &sha, scene_path, out, quiet, resume,
            )?;
            println!(
                "die compaction of {} particles: H0 = {:e} m, initial density {:e} (RVE {:e}); at {:e} Pa density {:e} (RVE {:e}); wrote {}",
                s.particles,
                s.h0,
                s.initial_density_specimen,
                s.initial_density_rve,
                s.last.pressure,
                s.last.density_specimen,
                s.last.density_rve,
                out.display()
            );
            if let Some(cycle) = &s.cycle {
                for (name, value) in cycle.summary.quantities() {
                    println!("  {name} = {value:e}");
                }
                write_cycle_plot(&cycle.records, file.die_compaction.die_diameter, out)?;
            }
        }
        (Document::Scene(scene), sha) => {
            let s = tamp::run::run_scene(&scene, &sha, scene_path, out, quiet, resume)?;
            println!(
                "ran {} steps of {:e} s ({} particles); wrote {}",
                s.steps,
                s.provenance.dt,
                s.particles,
                out.display()
            );
        }
    }
    Ok(0)
}

/// `cycle.svg` of a press cycle: the upper punch's pressure against the density
/// through pressing and unloading, and the ejection force against the lower punch's rise.
fn write_cycle_plot(
    records: &[tamp::process::press_cycle::CycleRecord],
    die_diameter: f64,
    out: &std::path::Path,
) -> tamp::error::Result<()> {
    use tamp::plot::{Panel, Series, write_svg};
    use tamp::process::press_cycle::Stage;
    let area = std::f64::consts::PI * 0.25 * die_diameter * die_diameter;
    let stage = |s: Stage, f: &dyn Fn(&tamp::process::press_cycle::CycleRecord) -> (f64, f64)| {
        records
            .iter()
            .filter(|r| r.stage == s)
            .map(f)
            .collect::<Vec<_>>()
    };
    let pressure =
        |r: &tamp::process::press_cycle::CycleRecord| (r.density_specimen, r.upper_punch / 1e6);
    let compaction = [
        Series::line("pressing", stage(Stage::Press, &pressure)),
        Series::line("unloading", stage(Stage::Unload, &pressure)),
    ];
    let ejection = [Series::line(
        "lower punch",
        stage(Stage::Eject, &|r| (r.ejection * 1e6, r.lower_punch * area)),
    )];
    let mut panels = vec![Panel {
        title: "Pressure and density through the cycle",
        x_label: "specimen density",
        y_label: "upper punch pressure (MPa)",
        log_x: false,
        log_y: false,
        series: &compaction,
    }];
    if !ejection[0].points.is_empty() {
        panels.push(Panel {
            title: "Ejection",
            x_label: "lower punch rise (um)",
            y_label: "ejection force (N)",
            log_x: false,
            log_y: false,
            series: &ejection,
        });
    }
    write_svg(&out.join("cycle.svg"), &panels)
}

/// What `export-lammps` and `export-liggghts` print of a deck written to `out`: the
/// differences it cannot avoid (stderr), then what it holds and how `peer` runs it.
fn exported(x: &tamp::peer_deck::Exported, out: &std::path::Path, peer: &str) -> u8 {
    for note in &x.notes {
        eprintln!("note: {note}");
    }
    println!(
        "exported {} particles, {} steps of {:e} s to {} ({}); run: cd {} && {peer} -in in.tamp",
        x.particles,
        x.steps,
        x.dt,
        out.display(),
        x.files.join(", "),
        out.display()
    );
    0
}
