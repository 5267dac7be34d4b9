//! Everything a run writes. Files are written to a temporary name in the target
//! directory and renamed, so a reader never sees a half-written file and an
//! interrupted run never clobbers a previous result.

pub mod contacts;
pub mod data_file;
pub mod run_files;
pub mod series;
pub mod summary;
pub mod vtk;

use crate::error::{Result, TampError};
use serde::Serialize;
use std::path::Path;

/// A number as the text outputs write it: `{:e}`, the shortest form that reads back to
/// the same double, and a zero without a sign (−0 is rounding's, not the physics', and
/// readers in other languages disagree on it).
#[derive(Clone, Copy, Debug)]
pub struct Sci(pub f64);

impl std::fmt::Display for Sci {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        // x + 0 is x for every double but −0, which it turns into +0.
        write!(f, "{:e}", self.0 + 0.0)
    }
}

/// `value` as indented JSON, each zero without a sign (`Sci`).
pub fn json_bytes<T: Serialize>(value: &T) -> Vec<u8> {
    fn unsigned_zeros(v: &mut serde_json::Value) {
        match v {
            serde_json::Value::Number(n) if n.as_f64() == Some(0.0) && n.is_f64() => {
                *n = serde_json::Number::from_f64(0.0).expect("finite");
            }
            serde_json::Value::Array(items) => items.iter_mut().for_each(unsigned_zeros),
            serde_json::Value::Object(map) => map.values_mut().for_each(unsigned_zeros),
            _ => {}
        }
    }
    let mut v = serde_json::to_value(value).expect("outputs serialise");
    unsigned_zeros(&mut v);
    serde_json::to_vec_pretty(&v).expect("a JSON value serialises")
}

/// Write `bytes` to `path` through a temporary file in the same directory and a rename,
/// so `path` holds either its old content or all of the new.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<()> {
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().to_string())
        .unwrap_or_default();
    let tmp = path.with_file_name(format!(".{name}.tmp"));
    std::fs::write(&tmp, bytes)
        .map_err(|e| TampError::io(format!("writing {}", tmp.display()), e))?;
    std::fs::rename(&tmp, path).map_err(|e| {
        TampError::io(
            format!("renaming {} to {}", tmp.display(), path.display()),
            e,
        )
    })
}

/// Make `out_dir` this run's: create it, refuse (exit 2) if one of the run's output
/// names would overwrite its `input`, and delete what an earlier run left under
/// those names, except `keep` (a resumed run's checkpoint). A run that then fails
/// leaves nothing that could be taken for its own result.
pub fn claim_dir(out_dir: &Path, input: &Path, outputs: &[&str], keep: &[&str]) -> Result<()> {
    create_dir(out_dir)?;
    let input = std::fs::canonicalize(input).ok();
    for name in outputs {
        let path = out_dir.join(name);
        if input.is_some() && std::fs::canonicalize(&path).ok() == input {
            return Err(TampError::input(
                "--out",
                format!(
                    "{} holds the scene file under the output name '{name}', which this run writes; choose another --out or move the scene",
                    out_dir.display()
                ),
            ));
        }
    }
    for name in outputs.iter().filter(|name| !keep.contains(name)) {
        let path = out_dir.join(name);
        if path.exists() {
            std::fs::remove_file(&path)
                .map_err(|e| TampError::io(format!("removing {}", path.display()), e))?;
        }
    }
    Ok(())
}

/// Create `dir` and its missing parents; an existing directory is kept as it is.
pub fn create_dir(dir: &Path) -> Result<()> {
    std::fs::create_dir_all(dir)
        .map_err(|e| TampError::io(format!("creating {}", dir.display()), e))
}

/// Where a result came from: enough to reproduce it.
#[derive(Clone, Debug, Serialize)]
pub struct Provenance {
    /// Version of tamp that made the result (the crate version).
    pub tamp_version: String,
    /// Commit of the build ([`GIT_COMMIT`](crate::GIT_COMMIT); `-dirty` with uncommitted
    /// changes).
    pub git_commit: String,
    /// SHA-256 of the scene file's bytes, in hex.
    pub scene_sha256: String,
    /// The scene's `seed`, from which the particle generators' random draws follow.
    pub seed: u64,
    /// Time step Δt used (a die compaction's: the pressing's last), s.
    pub dt: f64,
    /// α · Δt_cr (Rojek eqs 26–29) when the run could estimate it, s.
    pub dt_estimate: Option<f64>,
    /// Steps the run lasts (its maximum, with `run.until`; a die compaction's: the
    /// pressing's).
    pub steps: u64,
}

impl Provenance {
    /// Provenance of this build of tamp for a run of the scene hashing to `scene_sha256`.
    pub fn new(
        scene_sha256: String,
        seed: u64,
        dt: f64,
        dt_estimate: Option<f64>,
        steps: u64,
    ) -> Self {
        Provenance {
            tamp_version: crate::VERSION.to_string(),
            git_commit: crate::GIT_COMMIT.to_string(),
            scene_sha256,
            seed,
            dt,
            dt_estimate,
            steps,
        }
    }
}
