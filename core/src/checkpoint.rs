//! Restart checkpoints: a run's `State` on disk beside the hash of the scene it
//! belongs to, so that a long run that is killed can go on from its last checkpoint
//! and end exactly — bit for bit — as the uninterrupted run would have.
//!
//! The state is everything the step changes (`simulation::state`); everything else is
//! the run's `Model`, which `scene::build` rebuilds from the same scene file:
//! materials, pair table, contact law, wall shapes and motion laws, gravity, growth
//! stage, stability limits, detection, and each source's region, size law and
//! schedule. The build is deterministic (the seed fixes every random draw), so what it
//! rebuilds is what the interrupted run had. A checkpoint is therefore valid only for
//! its scene: the file carries the scene's SHA-256, tamp's version and the checkpoint
//! format, and any other is refused. `Simulation::resume` puts the state back.

use crate::error::{Result, TampError};
use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};
use std::path::Path;

/// The layout of `simulation::State` this tamp writes and reads. Format 2 stores the
/// contact states typed by the scene's laws (`contact_states`) and the `prescribed`
/// flags; files without the field are format 1 (tamp before the typed contact
/// states). Format 3 adds each particle's id, which `broad_phase.sort` separates from
/// its index. Format 4 is the `State` of the model/state split: the energy book as
/// one object, the walls' poses, the contact states as `contacts`.
pub const CHECKPOINT_FORMAT: u32 = 4;

/// A checkpoint file: a state and the scene and tamp version it belongs to.
#[derive(Serialize, Deserialize)]
pub struct Checkpoint<T> {
    /// Layout of the stored state, `CHECKPOINT_FORMAT` when written.
    pub checkpoint_format: u32,
    /// tamp version that wrote the file.
    pub tamp_version: String,
    /// The commit that wrote it: a different commit of the same version is accepted,
    /// but may step differently, so the reader can warn.
    pub git_commit: String,
    /// SHA-256 of the scene file the run was built from, hex.
    pub scene_sha256: String,
    /// The stored state.
    pub state: T,
}

impl<T> Checkpoint<T> {
    /// A checkpoint of `state` for the scene whose SHA-256 is `scene_sha256`, stamped
    /// with this tamp's version, commit and format.
    pub fn new(scene_sha256: &str, state: T) -> Self {
        Checkpoint {
            checkpoint_format: CHECKPOINT_FORMAT,
            tamp_version: crate::VERSION.to_string(),
            git_commit: crate::GIT_COMMIT.to_string(),
            scene_sha256: scene_sha256.to_string(),
            state,
        }
    }

    /// The stored state, if it was written by this tamp version for the scene whose
    /// SHA-256 is `scene_sha256`; `file` names the checkpoint in the error.
    pub fn into_state(self, scene_sha256: &str, file: &Path) -> Result<T> {
        if self.scene_sha256 != scene_sha256 {
            return Err(TampError::input(
                file.display().to_string(),
                format!(
                    "was written for the scene with sha256 {}, but this scene has sha256 {scene_sha256}; a checkpoint resumes only the scene file it was made from",
                    self.scene_sha256
                ),
            ));
        }
        if self.tamp_version != crate::VERSION {
            return Err(TampError::input(
                file.display().to_string(),
                format!(
                    "was written by tamp {}, this is tamp {}; another version may step differently",
                    self.tamp_version,
                    crate::VERSION
                ),
            ));
        }
        Ok(self.state)
    }
}

/// Write a checkpoint to `path` atomically: a reader, or a run resumed after a kill,
/// sees the previous checkpoint or this one, never half of one.
pub fn write_checkpoint(path: &Path, checkpoint: &impl Serialize) -> Result<()> {
    let json = serde_json::to_vec(checkpoint)
        .map_err(|e| TampError::Other(format!("serialising {}: {e}", path.display())))?;
    crate::output::write_atomic(path, &json)
}

/// `--resume` needs checkpoints to resume from: refuse it (bad input) when the scene's
/// `output.checkpoint_every` is 0.
pub fn require_checkpoints_for_resume(resume: bool, checkpoint_every: u64) -> Result<()> {
    if resume && checkpoint_every == 0 {
        return Err(TampError::input(
            "output.checkpoint_every",
            "must be > 0 with --resume: a run that writes no checkpoint has nothing to resume from",
        ));
    }
    Ok(())
}

/// Read a checkpoint written by `write_checkpoint`. A file that does not parse is bad
/// input (exit 2); the error names the JSON path where it stopped.
pub fn read_checkpoint<T: DeserializeOwned>(path: &Path) -> Result<T> {
    let bytes = std::fs::read(path)
        .map_err(|e| TampError::io(format!("reading checkpoint {}", path.display()), e))?;
    // The format first, so that an older layout is named as such rather than as a
    // missing field somewhere inside it.
    #[derive(Deserialize)]
    struct Format {
        #[serde(default = "format_one")]
        checkpoint_format: u32,
    }
    fn format_one() -> u32 {
        1
    }
    if let Ok(Format { checkpoint_format }) = serde_json::from_slice::<Format>(&bytes)
        && checkpoint_format != CHECKPOINT_FORMAT
    {
        return Err(TampError::input(
            path.display().to_string(),
            format!(
                "is checkpoint format {checkpoint_format}; this tamp reads format {CHECKPOINT_FORMAT} only (the state of the model/state split, with each contact's state in the shape of the scene's laws and each particle's id): run the scene again from the start"
            ),
        ));
    }
    let de = &mut serde_json::Deserializer::from_slice(&bytes);
    serde_path_to_error::deserialize(de).map_err(|e| {
        let at = match e.path().to_string() {
            top if top == "." => String::new(),
            inner => format!(" (at {inner})"),
        };
        TampError::input(
            path.display().to_string(),
            format!("is not a readable tamp checkpoint{at}: {}", e.inner()),
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};

    #[test]
    fn random_doubles_round_trip_through_json() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(1);
        let mut values: Vec<f64> = (0..200_000)
            .map(|_| f64::from_bits(rng.next_u64()))
            .filter(|x| x.is_finite())
            .collect();
        values.extend([
            -0.0,
            0.1 + 0.2,
            f64::MIN_POSITIVE,
            f64::MIN_POSITIVE / 3.0,
            f64::from_bits(1),
            f64::MAX,
            -f64::MAX,
        ]);
        let back: Vec<f64> =
            serde_json::from_str(&serde_json::to_string(&values).unwrap()).unwrap();
        for (a, b) in values.iter().zip(&back) {
            assert_eq!(a.to_bits(), b.to_bits(), "{a:e} came back as {b:e}");
        }
    }

    #[test]
    fn a_checkpoint_of_an_older_format_is_refused_naming_the_format() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("old.json");
        // Format 1 had no `checkpoint_format` field.
        std::fs::write(
            &path,
            r#"{"tamp_version": "0.1.0", "git_commit": "e4fb2aa", "scene_sha256": "x", "state": {}}"#,
        )
        .unwrap();
        let err = read_checkpoint::<Checkpoint<crate::simulation::State>>(&path)
            .err()
            .expect("refused");
        assert_eq!(err.exit_code(), 2);
        assert!(
            err.to_string()
                .contains("is checkpoint format 1; this tamp reads format 4"),
            "{err}"
        );
    }
}
