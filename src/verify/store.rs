//! The verification runner's store of finished and interrupted work: a case that
//! runs for long (the NiAl study, the full-tier peer pressings) keeps each run's
//! result, and a restart checkpoint of a run under way, in
//! `<report>/<case>_runs/`, so that a `tamp verify` that is killed goes on from
//! there when run again.
//!
//! A saved file is used only when it was written for the same input (the SHA-256 of
//! the input as serialised, usually the scene as run) by a build of the same code
//! (`SOURCE_TREE`: the git objects of `core/`, `src/` and `Cargo.lock`). A build
//! with uncommitted changes neither reuses nor trusts anything, since its code has
//! no name; a change of code or input starts the work afresh. Nothing from a store
//! reaches a report without passing those checks, so an earlier run cannot be
//! mistaken for this one.

use crate::checkpoint::{self, Checkpoint};
use crate::error::Result;
use serde::{Serialize, de::DeserializeOwned};
use std::path::PathBuf;

/// A case's saved work (`CaseContext::store`).
pub struct Store {
    pub(crate) dir: PathBuf,
}

/// The key of work on `input`: its SHA-256 as serialised and the code that ran it.
pub fn key_of<T: Serialize>(input: &T) -> String {
    let sha = crate::scene::sha256_hex(&serde_json::to_vec(input).expect("input serialises"));
    format!("{sha}:{}", crate::SOURCE_TREE)
}

impl Store {
    /// What `name` holds, if it was saved under `key` by this tamp version; anything
    /// else is left to be recomputed.
    pub fn load<T: DeserializeOwned>(&self, name: &str, key: &str) -> Option<T> {
        if crate::SOURCE_TREE.ends_with("-dirty") {
            return None;
        }
        let path = self.dir.join(name);
        let saved: Checkpoint<T> = checkpoint::read_checkpoint(&path).ok()?;
        saved.into_state(key, &path).ok()
    }

    /// Save `state` as `name` under `key` (written under a temporary name and renamed).
    pub fn save<T: Serialize>(&self, name: &str, key: &str, state: &T) -> Result<()> {
        checkpoint::write_checkpoint(&self.dir.join(name), &Checkpoint::new(key, state))
    }

    /// The result saved as `name` for `key`, or `run`'s, which is then saved.
    pub fn cached<T: Serialize + DeserializeOwned>(
        &self,
        name: &str,
        key: &str,
        run: impl FnOnce() -> Result<T>,
    ) -> Result<T> {
        if let Some(done) = self.load(name, key) {
            return Ok(done);
        }
        let done = run()?;
        self.save(name, key, &done)?;
        Ok(done)
    }
}
