//! The adapter engine, `command:PROG`: any program that runs a resolved scene.
//!
//! In the run directory tamp writes `scene.json` (the resolved scene) and, where the
//! exporters can express it, the same scene as decks in `liggghts/` and `lammps/`, so
//! an adapter may start from a deck instead. It then runs `PROG scene.json out` there
//! (PROG split on white space into the program and its leading arguments; a relative
//! program path is taken from where `tamp verify` runs) and reads `out/trajectory.csv`.
//! Exit 0 is a run, exit 4 a scene the adapter cannot express (its reason on stderr),
//! anything else a failure; stdout and stderr are kept beside, in `stdout.txt` and
//! `stderr.txt`.

use super::resolved::Resolved;
use super::{NOT_EXPRESSIBLE_EXIT, Refusal, failed, read_recording, tail};
use crate::error::TampError;
use crate::verify::recording::Recording;
use std::path::{Path, PathBuf};
use std::process::Command;

/// Run the adapter `prog` on `resolved` in `dir` and read what it recorded.
pub fn record(prog: &str, resolved: &Resolved, dir: &Path) -> Result<Recording, Refusal> {
    let scene_path = dir.join("scene.json");
    crate::output::write_atomic(&scene_path, resolved.json.as_bytes())?;
    write_decks(resolved, dir);
    let out = dir.join("out");
    crate::output::create_dir(&out)?;
    let mut words = prog.split_whitespace();
    let program = words
        .next()
        .ok_or_else(|| failed("command: no program named"))?;
    // A relative path names a file from where `tamp verify` runs, not from `dir`.
    let program = match Path::new(program) {
        p if p.components().count() > 1 && p.is_relative() => {
            std::path::absolute(p).map_err(|e| TampError::io(format!("resolving {program}"), e))?
        }
        p => PathBuf::from(p),
    };
    let output = Command::new(&program)
        .args(words)
        .arg("scene.json")
        .arg("out")
        .current_dir(dir)
        .output()
        .map_err(|e| {
            failed(format!(
                "command:{prog}: cannot start {}: {e}",
                program.display()
            ))
        })?;
    let stderr = String::from_utf8_lossy(&output.stderr);
    crate::output::write_atomic(&dir.join("stdout.txt"), &output.stdout)?;
    crate::output::write_atomic(&dir.join("stderr.txt"), &output.stderr)?;
    match output.status.code() {
        Some(0) => read_recording(&out.join("trajectory.csv"), resolved),
        Some(NOT_EXPRESSIBLE_EXIT) => Err(Refusal::NotExpressible(tail(&stderr, 3))),
        code => Err(failed(format!(
            "command:{prog} exited with {} on {}: {}",
            code.map_or("a signal".to_string(), |c| format!("code {c}")),
            scene_path.display(),
            tail(&stderr, 3)
        ))),
    }
}

/// The exported decks beside the resolved scene, where the exporters can express it
/// (a refusal only means no deck: the adapter may not need one).
fn write_decks(resolved: &Resolved, dir: &Path) {
    let every = Some(resolved.spec.trajectory_every);
    let sha = &resolved.sha256;
    let _ = crate::liggghts::export::export(&resolved.scene, sha, &dir.join("liggghts"), every);
    let _ = crate::lammps::export::export(&resolved.scene, sha, &dir.join("lammps"), every);
}
