//! The recorded runs of a peer engine: what LIGGGHTS or LAMMPS measured in a case,
//! kept in `reference_data/<peer>/engine/<case>.json`, so that `tamp verify --engine
//! liggghts` gives the peer's verdicts on a machine without the peer.
//!
//! A record holds, per run of the case, the SHA-256 of the deck the peer ran (its
//! files without their comment lines, which carry tamp's provenance) and of the dump
//! it wrote, and per quantity the value the case measured from that dump.
//!
//! - Recorded (the default): each run's deck is exported now and must be the recorded
//!   one (else the record is stale and the case an `error` saying how to re-record);
//!   the case measures tamp's in-process run of the same scene for its quantity list
//!   and references, and each value is replaced by the recorded peer value.
//! - `--live`: the peer runs now; a fresh dump equal to the recorded one byte for byte
//!   needs no more, otherwise every value must equal the recorded one to
//!   `DRIFT_TOLERANCE` (another machine's libm), or the case is an `error` (drift).
//! - `--live --record`: the peer runs now and its record is written.

use super::peer::Peer;
use crate::error::{Result, TampError};
use crate::verify::crosscheck::DRIFT_TOLERANCE;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// How the peer engines get their runs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum PeerRuns {
    /// From `reference_data/<peer>/engine/`.
    #[default]
    Recorded,
    /// Run now, and checked against the record.
    Live,
    /// Run now, and the record written.
    Record,
}

/// One run of a case on a peer.
#[derive(Clone, Debug, PartialEq, Eq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct PeerRun {
    /// The run's label in the case (`ctx.record`).
    pub label: String,
    /// SHA-256 of the exported deck without comment lines.
    pub deck_sha256: String,
    /// SHA-256 of the peer's dump.
    pub dump_sha256: String,
}

/// What a peer measured in one case.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct PeerRecord {
    pub case: String,
    pub engine: String,
    /// tamp's version and commit when the record was written.
    pub tamp_version: String,
    pub git_commit: String,
    pub runs: Vec<PeerRun>,
    /// Each quantity's value as the case measured it from the peer's dumps.
    pub quantities: BTreeMap<String, f64>,
}

/// `reference_data/<peer>/engine/<case>.json`.
pub fn path(reference_data: &Path, peer: Peer, case: &str) -> PathBuf {
    reference_data
        .join(peer.name())
        .join("engine")
        .join(format!("{case}.json"))
}

/// The record at `path`, if there is one.
pub fn load(path: &Path) -> Result<Option<PeerRecord>> {
    if !path.is_file() {
        return Ok(None);
    }
    let text = std::fs::read_to_string(path)
        .map_err(|e| TampError::io(format!("reading {}", path.display()), e))?;
    let record: PeerRecord = serde_json::from_str(&text)
        .map_err(|e| TampError::input(path.display().to_string(), e.to_string()))?;
    if let Some((name, _)) = record.quantities.iter().find(|(_, v)| !v.is_finite()) {
        return Err(TampError::input(
            path.display().to_string(),
            format!("quantities.{name} is not finite"),
        ));
    }
    Ok(Some(record))
}

/// Write `record` to `path` (under a temporary name, then renamed).
pub fn save(path: &Path, record: &PeerRecord) -> Result<()> {
    if let Some(dir) = path.parent() {
        crate::output::create_dir(dir)?;
    }
    let text = serde_json::to_string_pretty(record).expect("a record serialises") + "\n";
    crate::output::write_atomic(path, text.as_bytes())
}

/// SHA-256 of the deck an exporter wrote into `dir` (with its subdirectories, such as
/// `meshes/`): every file in path order, as its relative path and its lines that are
/// not comments (`#`), a data file without its title line. Those carry tamp's
/// provenance (version, commit, scene hash), so an unchanged deck keeps its hash.
pub fn deck_sha256(dir: &Path) -> Result<String> {
    let mut files = Vec::new();
    collect_files(dir, &mut files)?;
    files.sort();
    let mut text = String::new();
    for file in files {
        let content = std::fs::read_to_string(&file)
            .map_err(|e| TampError::io(format!("reading {}", file.display()), e))?;
        let relative = file.strip_prefix(dir).unwrap_or(&file);
        text.push_str(&relative.to_string_lossy());
        text.push('\n');
        let title = usize::from(file.extension().is_some_and(|e| e == "data"));
        for line in content
            .lines()
            .skip(title)
            .filter(|l| !l.trim_start().starts_with('#'))
        {
            text.push_str(line);
            text.push('\n');
        }
    }
    Ok(crate::scene::sha256_hex(text.as_bytes()))
}

fn collect_files(dir: &Path, out: &mut Vec<PathBuf>) -> Result<()> {
    for entry in std::fs::read_dir(dir)
        .map_err(|e| TampError::io(format!("listing {}", dir.display()), e))?
    {
        let path = entry
            .map_err(|e| TampError::io(format!("listing {}", dir.display()), e))?
            .path();
        if path.is_dir() {
            collect_files(&path, out)?;
        } else {
            out.push(path);
        }
    }
    Ok(())
}

impl PeerRecord {
    /// A stale or missing run is an error naming the command that re-records it.
    pub fn check_run(&self, label: &str, deck_sha256: &str, path: &Path) -> Result<()> {
        let again = format!(
            "re-record it with `tamp verify --engine {} --live --record --case {}` (the peer installed)",
            self.engine, self.case
        );
        match self.runs.iter().find(|r| r.label == label) {
            None => Err(TampError::Other(format!(
                "{}: has no run '{label}'; {again}",
                path.display()
            ))),
            Some(r) if r.deck_sha256 != deck_sha256 => Err(TampError::Other(format!(
                "{}: run '{label}' is stale: it was recorded on a deck with SHA-256 {}, and the case exports one with {deck_sha256} now; {again}",
                path.display(),
                r.deck_sha256
            ))),
            Some(_) => Ok(()),
        }
    }

    /// Differences between a fresh live run and this record: none when every dump is
    /// the recorded one byte for byte, else every value that differs from the recorded
    /// one by more than `DRIFT_TOLERANCE` (relative).
    pub fn drift(&self, runs: &[PeerRun], quantities: &BTreeMap<String, f64>) -> Vec<String> {
        if runs == self.runs.as_slice() {
            return Vec::new();
        }
        let mut out = Vec::new();
        for (name, &now) in quantities {
            match self.quantities.get(name) {
                None => out.push(format!("{name}: not in the record")),
                Some(&was) => {
                    let scale = was.abs().max(f64::MIN_POSITIVE);
                    if (now - was).abs() > DRIFT_TOLERANCE * scale {
                        out.push(format!("{name}: recorded {was:e}, now {now:e}"));
                    }
                }
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run(dump: &str) -> PeerRun {
        PeerRun {
            label: "collision".into(),
            deck_sha256: "d".into(),
            dump_sha256: dump.into(),
        }
    }

    fn record(value: f64) -> PeerRecord {
        PeerRecord {
            case: "c".into(),
            engine: "liggghts".into(),
            tamp_version: "0".into(),
            git_commit: "x".into(),
            runs: vec![run("a")],
            quantities: [("restitution".to_string(), value)].into_iter().collect(),
        }
    }

    /// The same dumps need nothing more; other dumps must give the recorded values to
    /// 1e-9, and a value beyond that is named with both numbers.
    #[test]
    fn drift_is_measured_only_when_the_dumps_differ() {
        let kept = record(0.5);
        let now = |v: f64| [("restitution".to_string(), v)].into_iter().collect();
        assert!(kept.drift(&[run("a")], &now(0.7)).is_empty());
        assert!(
            kept.drift(&[run("b")], &now(0.5 * (1.0 + 1e-10)))
                .is_empty()
        );
        let drift = kept.drift(&[run("b")], &now(0.5 * (1.0 + 1e-6)));
        assert_eq!(drift.len(), 1);
        assert!(drift[0].contains("recorded 5e-1"), "{drift:?}");
    }

    /// A run the record does not hold, or one of another deck, is refused.
    #[test]
    fn a_missing_or_stale_run_is_refused() {
        let kept = record(0.5);
        let p = Path::new("r.json");
        assert!(kept.check_run("collision", "d", p).is_ok());
        let stale = kept.check_run("collision", "e", p).unwrap_err().to_string();
        assert!(stale.contains("is stale"), "{stale}");
        let missing = kept.check_run("other", "d", p).unwrap_err().to_string();
        assert!(missing.contains("has no run 'other'"), "{missing}");
    }
}
