//! `tamp crosscheck [--live] [--tier quick|full] [--peer P] [--case C]`: the peer-code
//! cross-check cases, the verification cases named `liggghts_*` (LIGGGHTS 3.8) and
//! `lammps_*` (LAMMPS 22 Jul 2025, `.ci/install-lammps`), and any other case that keeps
//! a peer's run of it in `reference_data/<peer>/<case>/regenerate.sh` (a study that
//! also compares against a peer, such as `nial_die_compaction_dense`).
//!
//! Without `--live` they run against the results recorded in
//! `reference_data/<peer>/<case>/`, exactly as `tamp verify` runs them. With
//! `--live`, the peer is run now: each case directory holds `regenerate.sh OUTDIR`,
//! which exports or uses the deck, runs the peer and writes `results.csv` to OUTDIR.
//! The scripts run side by side, as many at a time as `tamp verify` runs cases (each
//! peer run is serial). Two checks follow, so that the recorded data cannot drift
//! from what the peer really does:
//! 1. every CSV file recorded for the case (`results.csv`, `trajectory.csv`) comes
//!    out of the fresh run equal to the recorded one (every number to 1e-9
//!    relative: the same deck on the same LIGGGHTS version is deterministic, and
//!    1e-9 only leaves room for another machine's libm);
//! 2. the case passes against the fresh results. A case whose fresh files equal the
//!    recorded ones byte for byte is not run again: against the same bytes it gives
//!    what `tamp verify` (or `tamp crosscheck` without `--live`) gives against the
//!    recorded ones. This matters for the die compactions, whose tamp side presses
//!    for minutes and which CI would otherwise run twice.

use crate::error::{Result, TampError};
use crate::verify::{self, Tier};
use std::path::{Path, PathBuf};
use std::process::Command;

/// Numbers in the fresh and the recorded results must agree to this (relative).
pub const DRIFT_TOLERANCE: f64 = 1e-9;

fn reference_root() -> PathBuf {
    verify::verification_dir()
        .parent()
        .map(Path::to_path_buf)
        .unwrap_or_default()
        .join("reference_data")
}

/// Whether an executable `name` is on PATH.
pub fn on_path(name: &str) -> bool {
    std::env::var_os("PATH")
        .is_some_and(|paths| std::env::split_paths(&paths).any(|dir| dir.join(name).is_file()))
}

/// The largest relative difference between the numeric cells of two CSV files with
/// the same header and rows, or why they cannot be compared.
pub fn csv_drift(fresh: &Path, recorded: &Path) -> Result<f64> {
    let read = |p: &Path| -> Result<Vec<Vec<String>>> {
        let mut r = csv::Reader::from_path(p)
            .map_err(|e| TampError::Other(format!("{}: {e}", p.display())))?;
        let mut rows = vec![
            r.headers()
                .map_err(|e| TampError::Other(e.to_string()))?
                .iter()
                .map(String::from)
                .collect(),
        ];
        for rec in r.records() {
            let rec = rec.map_err(|e| TampError::Other(format!("{}: {e}", p.display())))?;
            rows.push(rec.iter().map(String::from).collect());
        }
        Ok(rows)
    };
    let (a, b) = (read(fresh)?, read(recorded)?);
    if a.len() != b.len() || a[0] != b[0] {
        return Err(TampError::Other(format!(
            "{} and {} differ in header or row count",
            fresh.display(),
            recorded.display()
        )));
    }
    let mut worst: f64 = 0.0;
    for (ra, rb) in a.iter().zip(&b).skip(1) {
        for (x, y) in ra.iter().zip(rb) {
            match (x.parse::<f64>(), y.parse::<f64>()) {
                (Ok(u), Ok(v)) if u != v => {
                    worst = worst.max((u - v).abs() / v.abs().max(f64::MIN_POSITIVE));
                }
                (Ok(_), Ok(_)) => {}
                _ if x == y => {}
                _ => {
                    return Err(TampError::Other(format!(
                        "{}: '{x}' where the recorded results have '{y}'",
                        fresh.display()
                    )));
                }
            }
        }
    }
    Ok(worst)
}

/// The CSV files recorded for a case (results.csv, trajectory.csv, ...), sorted.
fn recorded_csv_files(dir: &Path) -> Result<Vec<std::ffi::OsString>> {
    let mut files: Vec<std::ffi::OsString> = std::fs::read_dir(dir)
        .map_err(|e| TampError::io(format!("reading {}", dir.display()), e))?
        .filter_map(|e| e.ok())
        .map(|e| e.file_name())
        .filter(|n| n.to_string_lossy().ends_with(".csv"))
        .collect();
    files.sort();
    Ok(files)
}

/// A peer code: its cases are recorded in `reference_data/<name>/`, and most are named `<name>_*`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Peer {
    Liggghts,
    Lammps,
}

impl Peer {
    pub const ALL: [Peer; 2] = [Peer::Liggghts, Peer::Lammps];

    pub fn name(self) -> &'static str {
        match self {
            Peer::Liggghts => "liggghts",
            Peer::Lammps => "lammps",
        }
    }

    /// Whether the peer can run here, or how to install it.
    pub fn check_installed(self) -> Result<()> {
        match self {
            Peer::Liggghts if on_path("liggghts") => Ok(()),
            Peer::Liggghts => Err(TampError::input(
                "--live",
                "needs the LIGGGHTS executable 'liggghts' on PATH (apt-get install -y liggghts)",
            )),
            Peer::Lammps if lammps_executable().is_file() => Ok(()),
            Peer::Lammps => Err(TampError::input(
                "--live",
                format!(
                    "needs LAMMPS 22 Jul 2025 at {} (.ci/install-lammps) or in $LMP",
                    lammps_executable().display()
                ),
            )),
        }
    }
}

/// `$LMP`, else `.peers/bin/lmp` of the checkout (`.ci/install-lammps`); the
/// `regenerate.sh` scripts of the LAMMPS cases take the same one.
pub fn lammps_executable() -> PathBuf {
    match std::env::var_os("LMP") {
        Some(p) => PathBuf::from(p),
        None => reference_root().join("..").join(".peers/bin/lmp"),
    }
}

/// The peer a case cross-checks, of `peers`: the one it is named for, or the one whose
/// run of it is kept in `recorded_root/<peer>/<case>/regenerate.sh`.
fn peer_of(name: &str, peers: &[Peer], recorded_root: &Path) -> Option<Peer> {
    peers.iter().copied().find(|p| {
        name.starts_with(&format!("{}_", p.name()))
            || recorded_root
                .join(p.name())
                .join(name)
                .join("regenerate.sh")
                .is_file()
    })
}

pub fn run_cli(
    live: bool,
    tier: Tier,
    peers: &[Peer],
    cases: &[String],
    report_dir: &Path,
) -> Result<u8> {
    let peers = if peers.is_empty() {
        &Peer::ALL[..]
    } else {
        peers
    };
    let specs = verify::load_specs(&verify::verification_dir())?;
    let recorded_root = reference_root();
    let peer_of = |name: &str| peer_of(name, peers, &recorded_root);
    let names: Vec<String> = specs
        .iter()
        .filter(|s| {
            peer_of(&s.name).is_some()
                && (cases.is_empty() || cases.contains(&s.name))
                && (tier == Tier::Full || s.tier == Tier::Quick || cases.contains(&s.name))
        })
        .map(|s| s.name.clone())
        .collect();
    if let Some(unknown) = cases.iter().find(|c| !names.contains(c)) {
        return Err(TampError::input(
            "--case",
            format!("'{unknown}' is not a cross-check case of the peers asked for"),
        ));
    }
    if !live {
        return verify::run_cases(
            tier,
            &names,
            &[],
            verify::engine::peer_record::PeerRuns::Recorded,
            None,
            report_dir,
            None,
            verify::default_jobs(),
        );
    }
    for peer in peers {
        if names.iter().any(|n| peer_of(n) == Some(*peer)) {
            peer.check_installed()?;
        }
    }
    let live_root = std::path::absolute(report_dir.join("liggghts_live"))
        .map_err(|e| TampError::io("resolving the report directory", e))?;
    let tamp =
        std::env::current_exe().map_err(|e| TampError::io("locating the tamp executable", e))?;
    let runs: Vec<(String, &str, PathBuf, PathBuf)> = names
        .iter()
        .map(|name| {
            let peer = peer_of(name).expect("names are filtered by peer").name();
            let recorded = recorded_root.join(peer).join(name);
            let out = live_root.join(peer).join(name);
            (name.clone(), peer, recorded, out)
        })
        .collect();
    for (_, _, recorded, out) in &runs {
        let script = recorded.join("regenerate.sh");
        if !script.is_file() {
            return Err(TampError::Other(format!(
                "{}: missing; every cross-check case needs one",
                script.display()
            )));
        }
        crate::output::create_dir(out)?;
    }
    // Each script's output goes to its own log, so that runs side by side stay readable.
    let next = std::sync::atomic::AtomicUsize::new(0);
    let outcomes: Vec<std::sync::Mutex<Option<Result<()>>>> =
        runs.iter().map(|_| std::sync::Mutex::new(None)).collect();
    std::thread::scope(|scope| {
        for _ in 0..verify::default_jobs().min(runs.len()) {
            scope.spawn(|| {
                loop {
                    let k = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                    let Some((name, peer, recorded, out)) = runs.get(k) else {
                        break;
                    };
                    eprintln!(
                        "{name}: running {peer} ({}/regenerate.sh)",
                        recorded.display()
                    );
                    let outcome = run_script(recorded, out, &tamp);
                    *outcomes[k].lock().expect("no run panics holding it") = Some(outcome);
                }
            });
        }
    });
    let mut drifted = 0;
    let mut to_check = Vec::new();
    for ((name, peer, recorded, out), outcome) in runs.iter().zip(outcomes) {
        outcome
            .into_inner()
            .expect("no run panics holding it")
            .expect("every run is taken")?;
        let mut drift: f64 = 0.0;
        let mut identical = true;
        for file in recorded_csv_files(recorded)? {
            let (fresh, kept) = (out.join(&file), recorded.join(&file));
            drift = drift.max(csv_drift(&fresh, &kept)?);
            identical &= std::fs::read(&fresh).ok() == std::fs::read(&kept).ok();
        }
        let verdict = if drift <= DRIFT_TOLERANCE {
            "same"
        } else {
            drifted += 1;
            "DRIFTED"
        };
        eprintln!(
            "{name}: fresh {peer} results vs recorded: largest relative difference {drift:e} ({verdict}, tolerance {DRIFT_TOLERANCE:e})"
        );
        if identical {
            eprintln!(
                "{name}: the fresh files are the recorded ones byte for byte, so the case's verdict is tamp verify's; not run again"
            );
        } else {
            to_check.push(name.clone());
        }
    }
    let code = if to_check.is_empty() {
        0
    } else {
        verify::run_cases(
            tier,
            &to_check,
            &[],
            verify::engine::peer_record::PeerRuns::Recorded,
            None,
            report_dir,
            Some(&live_root),
            verify::default_jobs(),
        )?
    };
    if drifted > 0 {
        eprintln!(
            "{drifted} case(s) drifted from the recorded peer results: re-record them (regenerate.sh) and say why"
        );
        return Ok(1);
    }
    Ok(code)
}

/// Runs `recorded/regenerate.sh out` (the peer's run of one case) with its output in
/// `out/regenerate.log`.
fn run_script(recorded: &Path, out: &Path, tamp: &Path) -> Result<()> {
    let script = recorded.join("regenerate.sh");
    let log_path = out.join("regenerate.log");
    let log = std::fs::File::create(&log_path)
        .map_err(|e| TampError::io(format!("creating {}", log_path.display()), e))?;
    let log_err = log
        .try_clone()
        .map_err(|e| TampError::io(format!("opening {}", log_path.display()), e))?;
    let status = Command::new("bash")
        .arg(&script)
        .arg(out)
        .env("TAMP", tamp)
        .env("LMP", lammps_executable())
        .current_dir(recorded)
        .stdout(log)
        .stderr(log_err)
        .status()
        .map_err(|e| TampError::io(format!("running {}", script.display()), e))?;
    if status.success() {
        Ok(())
    } else {
        Err(TampError::Other(format!(
            "{} failed ({status}); its output is in {}, the peer's logs beside it",
            script.display(),
            log_path.display()
        )))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_study_with_a_peer_run_is_a_cross_check_case() {
        let root = reference_root();
        let of = |name| peer_of(name, &Peer::ALL, &root);
        assert_eq!(of("lammps_mdr_triaxial"), Some(Peer::Lammps));
        assert_eq!(of("liggghts_die_compaction_small"), Some(Peer::Liggghts));
        assert_eq!(of("nial_die_compaction_dense"), Some(Peer::Lammps));
        assert_eq!(of("nial_die_compaction"), None);
        assert_eq!(
            peer_of("nial_die_compaction_dense", &[Peer::Liggghts], &root),
            None
        );
    }
}
