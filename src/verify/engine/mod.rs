//! Engines: whatever turns a scene into recorded outputs (docs/engines.md).
//!
//! - `tamp`, in-process: the scene is built and stepped here and its frames kept in
//!   memory, no files in between;
//! - `liggghts`, `lammps`: the resolved scene is exported as a deck (the exporters of
//!   `tamp export-liggghts` and `tamp export-lammps`), the peer runs it now, and its
//!   dump is read as the layout of docs/compare.md; or, without `--live`, the peer's
//!   recorded values stand in for the run (`peer_record`);
//! - `command:PROG`: any program, run as `PROG SCENE_JSON OUT_DIR` on the resolved
//!   scene, writing `OUT_DIR/trajectory.csv`.
//!
//! A case measures only what the engine recorded, so its verdict means the same on
//! every engine. What an external engine writes is untrusted input (`recording`).

pub mod command;
pub mod peer;
pub mod peer_record;
pub mod resolved;
pub mod tamp;

use super::recording::{RecordSpec, Recording};
use crate::error::TampError;
use crate::scene::Scene;
use std::fmt;
use std::path::Path;
use std::str::FromStr;

/// The exit code by which an adapter says that the scene uses a feature it lacks (its
/// reason on stderr): the case is then `not_expressible` on that engine, not an error.
pub const NOT_EXPRESSIBLE_EXIT: i32 = 4;

/// One engine of `tamp verify --engine`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Engine {
    /// tamp itself, in-process.
    Tamp,
    /// LIGGGHTS 3.8 (`liggghts` on PATH) on the exported deck: run now with `--live`,
    /// else its recorded values.
    Liggghts,
    /// LAMMPS 22 Jul 2025 (`.ci/install-lammps`, or `$LMP`) on the exported deck: run
    /// now with `--live`, else its recorded values.
    Lammps,
    /// An adapter: the program and its leading arguments, split on white space.
    Command(String),
}

impl FromStr for Engine {
    type Err = String;

    fn from_str(s: &str) -> std::result::Result<Self, String> {
        match s {
            "tamp" => Ok(Engine::Tamp),
            "liggghts" => Ok(Engine::Liggghts),
            "lammps" => Ok(Engine::Lammps),
            _ => match s.strip_prefix("command:") {
                Some(prog) if !prog.trim().is_empty() => {
                    Ok(Engine::Command(prog.trim().to_string()))
                }
                _ => Err(format!(
                    "'{s}' is not an engine: give tamp, liggghts, lammps or command:PROG (PROG is run as `PROG SCENE_JSON OUT_DIR`, docs/engines.md)"
                )),
            },
        }
    }
}

impl fmt::Display for Engine {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Engine::Tamp => f.write_str("tamp"),
            Engine::Liggghts => f.write_str("liggghts"),
            Engine::Lammps => f.write_str("lammps"),
            Engine::Command(prog) => write!(f, "command:{prog}"),
        }
    }
}

impl Engine {
    /// The peer code this engine runs, if it is one.
    pub fn peer(&self) -> Option<peer::Peer> {
        match self {
            Engine::Liggghts => Some(peer::Peer::Liggghts),
            Engine::Lammps => Some(peer::Peer::Lammps),
            _ => None,
        }
    }

    /// A file-name-safe name for the engine's run directories.
    pub fn slug(&self) -> String {
        safe_chars(&self.to_string(), '-', '_')
    }
}

/// `text` with every character other than an ASCII letter, a digit or `keep` replaced
/// by `replacement`: names for files and anchors.
pub fn safe_chars(text: &str, keep: char, replacement: char) -> String {
    text.chars()
        .map(|c| match c.is_ascii_alphanumeric() || c == keep {
            true => c,
            false => replacement,
        })
        .collect()
}

/// Why an engine gave no recording.
#[derive(Debug)]
pub enum Refusal {
    /// The engine cannot express the scene (an exporter's refusal, an adapter's exit
    /// code 4): the reason.
    NotExpressible(String),
    /// The engine failed, or what it wrote is unusable.
    Failed(TampError),
}

impl From<TampError> for Refusal {
    fn from(e: TampError) -> Self {
        Refusal::Failed(e)
    }
}

/// Record one run of `scene` on `engine`. An external engine works under `dir`,
/// emptied first so that nothing of an earlier run is read as this one's; tamp needs
/// no files. A peer's run also gives what its record keeps (`peer_record::PeerRun`,
/// labelled `label`).
pub fn record(
    engine: &Engine,
    label: &str,
    scene: &Scene,
    spec: RecordSpec,
    dir: &Path,
) -> std::result::Result<(Recording, Option<peer_record::PeerRun>), Refusal> {
    if *engine == Engine::Tamp {
        return Ok((tamp::record(scene, spec)?, None));
    }
    let resolved = fresh_resolved(scene, spec, dir)?;
    match (engine, engine.peer()) {
        (_, Some(p)) => {
            let (recording, deck_sha256, dump_sha256) = peer::record(p, &resolved, dir)?;
            let run = peer_record::PeerRun {
                label: label.to_string(),
                deck_sha256,
                dump_sha256,
            };
            Ok((recording, Some(run)))
        }
        (Engine::Command(prog), None) => Ok((command::record(prog, &resolved, dir)?, None)),
        (Engine::Tamp | Engine::Liggghts | Engine::Lammps, None) => {
            unreachable!("tamp is recorded in-process and the peers have a peer")
        }
    }
}

/// The SHA-256 of the deck `peer` would run for `scene`, exported into `dir` (emptied
/// first), without running it: what a recorded run is checked against.
pub fn peer_deck(
    peer: peer::Peer,
    scene: &Scene,
    spec: RecordSpec,
    dir: &Path,
) -> std::result::Result<String, Refusal> {
    let resolved = fresh_resolved(scene, spec, dir)?;
    let deck = peer::export(peer, &resolved, dir)?;
    crate::output::write_atomic(&dir.join("scene.json"), resolved.json.as_bytes())?;
    Ok(deck)
}

/// `scene` resolved, with `dir` emptied for its run.
fn fresh_resolved(
    scene: &Scene,
    spec: RecordSpec,
    dir: &Path,
) -> std::result::Result<resolved::Resolved, Refusal> {
    if dir.exists() {
        std::fs::remove_dir_all(dir)
            .map_err(|e| TampError::io(format!("emptying {}", dir.display()), e))?;
    }
    crate::output::create_dir(dir)?;
    resolved::resolve(scene, spec)
}

/// Read an engine's trajectory, written as the layout of docs/compare.md, for the
/// resolved run.
pub fn read_recording(
    path: &Path,
    resolved: &resolved::Resolved,
) -> std::result::Result<Recording, Refusal> {
    if !path.is_file() {
        return Err(Refusal::Failed(TampError::input(
            path.display().to_string(),
            "was not written (the engine must write trajectory.csv, docs/engines.md)",
        )));
    }
    let rows = crate::compare::read_trajectory(path)?;
    let mut recording = resolved.recording(path, &rows)?;
    if resolved.spec.walls {
        let walls = path.with_file_name("walls.csv");
        if !walls.is_file() {
            return Err(Refusal::Failed(TampError::input(
                walls.display().to_string(),
                "was not written (the case records the walls: the scene sets output.walls, docs/engines.md)",
            )));
        }
        let rows = crate::compare::read_walls(&walls)?;
        recording.attach_walls(
            &walls.display().to_string(),
            &rows,
            resolved.scene.walls.len(),
        )?;
    }
    Ok(recording)
}

/// The last lines of a program's output, for a message.
pub fn tail(text: &str, lines: usize) -> String {
    let all: Vec<&str> = text.lines().filter(|l| !l.trim().is_empty()).collect();
    all[all.len().saturating_sub(lines)..].join(" | ")
}

/// An engine's failure, as a refusal.
pub fn failed(e: impl Into<String>) -> Refusal {
    Refusal::Failed(TampError::Other(e.into()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn engines_are_named_as_on_the_command_line() {
        for name in ["tamp", "liggghts", "lammps", "command:python3 adapter.py"] {
            assert_eq!(name.parse::<Engine>().unwrap().to_string(), name);
        }
        for bad in ["", "gromacs", "command:", "command:  "] {
            let e = bad.parse::<Engine>().unwrap_err();
            assert!(e.contains("command:PROG"), "{e}");
        }
        assert_eq!(
            "command:./a b".parse::<Engine>().unwrap().slug(),
            "command___a_b"
        );
    }
}
