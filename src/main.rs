//! The `tamp` command line: parse arguments, call the library, map errors to the
//! exit codes of the contract (0 ok, 1 verification failure, 2 bad input, 3 unstable).

use clap::{Parser, Subcommand};
use std::path::PathBuf;
use std::process::ExitCode;
use tamp::verify::{self, Tier};

#[derive(Parser)]
#[command(
    name = "tamp",
    version,
    about = "Verification-first DEM for powder packing and die compaction"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Run a scene file and write summary.json and series.csv to DIR.
    Run {
        scene: PathBuf,
        #[arg(long)]
        out: PathBuf,
        /// No progress bar.
        #[arg(long)]
        quiet: bool,
    },
    /// Run verification cases and write the report.
    Verify {
        /// quick (CI, seconds) or full (paper scale); `full` includes the quick cases.
        #[arg(long, value_enum, default_value_t = Tier::Quick)]
        tier: Tier,
        /// Only these cases (repeatable).
        #[arg(long = "case")]
        cases: Vec<String>,
        /// Also write the JSON result to this file (default: REPORT/verification.json).
        #[arg(long)]
        json: Option<PathBuf>,
        /// Directory of the report.
        #[arg(long, default_value = "report")]
        report: PathBuf,
    },
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Run { scene, out, quiet } => tamp::run::run_scene(&scene, &out, quiet).map(|s| {
            println!(
                "ran {} steps of {:e} s ({} particles); wrote {}",
                s.steps,
                s.provenance.dt,
                s.particles,
                out.display()
            );
            0
        }),
        Command::Verify {
            tier,
            cases,
            json,
            report,
        } => verify::run_cli(tier, &cases, json.as_deref(), &report),
    };
    match result {
        Ok(code) => ExitCode::from(code),
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(e.exit_code() as u8)
        }
    }
}
