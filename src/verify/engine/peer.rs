//! The peer engines, `liggghts` and `lammps`: the resolved scene exported as a deck
//! (`tamp export-liggghts`, `tamp export-lammps`), the peer run on it now, serially, and
//! its dump read as the recording. An exporter's refusal means the peer cannot
//! express the scene.

use super::resolved::Resolved;
use super::{Refusal, failed, tail};
use crate::error::TampError;
pub use crate::verify::crosscheck::Peer;
use crate::verify::recording::Recording;
use std::path::Path;
use std::process::Command;

/// Export `resolved` into the empty `dir` as `peer`'s deck and return the deck's
/// SHA-256 (`peer_record::deck_sha256`); the exporter's refusal means the peer cannot
/// express the scene.
pub fn export(peer: Peer, resolved: &Resolved, dir: &Path) -> Result<String, Refusal> {
    let every = Some(resolved.spec.trajectory_every);
    let sha = &resolved.sha256;
    let exported = match peer {
        Peer::Liggghts => crate::liggghts::export::export(&resolved.scene, sha, dir, every),
        Peer::Lammps => crate::lammps::export::export(&resolved.scene, sha, dir, every),
    };
    exported.map_err(|refusal| match refusal {
        e @ (TampError::Input { .. } | TampError::InputMany(_)) => {
            Refusal::NotExpressible(e.to_string().replace('\n', "; "))
        }
        e => Refusal::Failed(e),
    })?;
    if resolved.spec.walls {
        let every = resolved.spec.trajectory_every;
        match peer {
            Peer::Liggghts => {
                return Err(Refusal::NotExpressible(
                    "output.walls: the LIGGGHTS deck records no wall displacements and forces"
                        .into(),
                ));
            }
            // The LAMMPS deck prints walls.csv every `every` steps (fix print).
            Peer::Lammps if !resolved.steps.is_multiple_of(every) => {
                return Err(Refusal::NotExpressible(format!(
                    "output.walls: the LAMMPS deck prints walls.csv every {every} steps, and the run's last step {} is not one of them",
                    resolved.steps
                )));
            }
            Peer::Lammps => {}
        }
    }
    Ok(super::peer_record::deck_sha256(dir)?)
}

/// Export `resolved` into the empty `dir`, run `peer` on it and read its dump; also
/// the SHA-256 of the deck and of the dump, by which a recorded run is checked.
pub fn record(
    peer: Peer,
    resolved: &Resolved,
    dir: &Path,
) -> Result<(Recording, String, String), Refusal> {
    let deck_sha256 = export(peer, resolved, dir)?;
    peer.check_installed()?;
    crate::output::write_atomic(&dir.join("scene.json"), resolved.json.as_bytes())?;
    let (mut command, log, dump, last) = match peer {
        Peer::Liggghts => {
            let mut c = Command::new("liggghts");
            c.args(["-in", "in.tamp", "-log", "log.liggghts"]);
            (c, "log.liggghts", "dump.liggghts", "final.liggghts")
        }
        Peer::Lammps => {
            let mut c = Command::new(crate::verify::crosscheck::lammps_executable());
            c.args([
                "-in",
                "in.tamp",
                "-log",
                "log.lammps",
                "-screen",
                "none",
                "-nocite",
            ]);
            (c, "log.lammps", "dump.lammps", "final.lammps")
        }
    };
    let output = command
        .current_dir(dir)
        .output()
        .map_err(|e| failed(format!("{}: cannot start: {e}", peer.name())))?;
    crate::output::write_atomic(&dir.join("screen.txt"), &output.stdout)?;
    let log_text = std::fs::read_to_string(dir.join(log)).unwrap_or_default();
    if !output.status.success() || !dir.join(dump).is_file() {
        return Err(failed(format!(
            "{} failed on {} ({}): {}",
            peer.name(),
            dir.join("in.tamp").display(),
            output.status,
            tail(
                &format!("{log_text}\n{}", String::from_utf8_lossy(&output.stderr)),
                3
            )
        )));
    }
    // The dump holds every `every`-th step; the final state is the last step's frame
    // when the step count is not a multiple of it.
    let mut rows = crate::compare::dump_trajectory(&dir.join(dump))?;
    if dir.join(last).is_file() {
        for (key, state) in crate::compare::dump_trajectory(&dir.join(last))? {
            rows.entry(key).or_insert(state);
        }
    }
    let bytes = std::fs::read(dir.join(dump))
        .map_err(|e| TampError::io(format!("reading {}", dir.join(dump).display()), e))?;
    let mut recording = resolved.recording(&dir.join(dump), &rows)?;
    if resolved.spec.walls {
        let walls = dir.join("walls.csv");
        recording.attach_walls(
            &walls.display().to_string(),
            &crate::compare::read_walls(&walls)?,
            resolved.scene.walls.len(),
        )?;
    }
    Ok((recording, deck_sha256, crate::scene::sha256_hex(&bytes)))
}
