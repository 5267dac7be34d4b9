//! What the integration tests share: the `tamp` binary, the two-sphere scene of
//! `tests/scenes/base.json`, a scene built in memory, a scene written to a temporary
//! directory.

// Each test file is its own crate and uses a subset of these.
#![allow(dead_code)]

use serde_json::Value;
use std::path::PathBuf;
use std::process::Command;

/// The `tamp` executable of this build.
pub fn tamp() -> Command {
    Command::new(env!("CARGO_BIN_EXE_tamp"))
}

/// Two spheres settling on a floor: the smallest scene that exercises a whole run.
pub fn base() -> Value {
    serde_json::from_str(include_str!("../scenes/base.json")).unwrap()
}

/// Parse and build `scene`, panicking with tamp's own message if either refuses it.
pub fn built(scene: &Value) -> tamp::scene::BuiltScene {
    let parsed = tamp::scene::parse(&scene.to_string()).unwrap_or_else(|e| panic!("{e}"));
    tamp::scene::build(&parsed).unwrap_or_else(|e| panic!("{e}"))
}

/// Write `scene` into a fresh temporary directory; return the directory (removed when
/// dropped), the scene's path and an output path inside it.
pub fn scene_in_tempdir(scene: &Value) -> (tempfile::TempDir, PathBuf, PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("scene.json");
    std::fs::write(&path, scene.to_string()).unwrap();
    let out = dir.path().join("out");
    (dir, path, out)
}

/// `tamp run SCENE --out OUT --quiet` and its extra arguments.
pub fn run(scene: &std::path::Path, out: &std::path::Path, extra: &[&str]) -> std::process::Output {
    tamp()
        .args([
            "run",
            scene.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
            "--quiet",
        ])
        .args(extra)
        .output()
        .unwrap()
}
