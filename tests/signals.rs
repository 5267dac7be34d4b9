//! SIGINT and SIGTERM used to kill a run at once, with no message and the work since
//! the last checkpoint lost. Now the run finishes its step, writes a checkpoint when
//! checkpoints are on, says how to go on, and exits with 128 + the signal; the resumed
//! run writes what an uninterrupted one writes.

mod common;

use serde_json::{Value, json};
use std::path::Path;
use std::process::{Command, Output, Stdio};
use std::time::Duration;

/// The two spheres of tests/scenes/base.json, run long enough (millions of steps)
/// to be signalled while stepping.
fn scene(dir: &Path, checkpoint_every: u64) -> std::path::PathBuf {
    let mut s = common::base();
    s["run"] = json!({"duration": 40.0});
    s["output"] = json!({"checkpoint_every": checkpoint_every});
    let path = dir.join("scene.json");
    std::fs::write(&path, s.to_string()).unwrap();
    path
}

fn tamp(args: &[&str]) -> Command {
    let mut c = common::tamp();
    c.args(args).arg("--quiet");
    c
}

/// Send `signal` (`-INT`, `-TERM`, `-KILL`) with the shell's built-in `kill`, which
/// every machine with `sh` has.
fn send(signal: &str, pid: u32) -> std::process::ExitStatus {
    Command::new("sh")
        .args(["-c", &format!("kill {signal} {pid}")])
        .status()
        .unwrap()
}

/// Start `tamp run`, send `signal` once it is stepping, and wait for it.
fn signalled(scene: &Path, out: &Path, signal: &str) -> Output {
    let child = tamp(&[
        "run",
        scene.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ])
    .stdout(Stdio::piped())
    .stderr(Stdio::piped())
    .spawn()
    .unwrap();
    std::thread::sleep(Duration::from_millis(500));
    let kill = send(signal, child.id());
    assert!(kill.success());
    child.wait_with_output().unwrap()
}

#[test]
fn sigint_checkpoints_and_the_resumed_run_equals_an_uninterrupted_one() {
    let dir = tempfile::tempdir().unwrap();
    let scene = scene(dir.path(), 200_000);
    let out = dir.path().join("out");
    let stopped = signalled(&scene, &out, "-INT");
    let stderr = String::from_utf8_lossy(&stopped.stderr);
    assert_eq!(stopped.status.code(), Some(130), "{stderr}");
    assert!(stderr.contains("stopped by SIGINT after step"), "{stderr}");
    assert!(stderr.contains("--resume"), "{stderr}");
    assert!(out.join("checkpoint.json").exists());
    assert!(
        !out.join("summary.json").exists(),
        "an unfinished run writes no summary"
    );

    let resumed = tamp(&[
        "run",
        scene.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--resume",
    ])
    .output()
    .unwrap();
    assert!(resumed.status.success(), "{resumed:?}");
    let whole = dir.path().join("whole");
    let uninterrupted = tamp(&[
        "run",
        scene.to_str().unwrap(),
        "--out",
        whole.to_str().unwrap(),
    ])
    .output()
    .unwrap();
    assert!(uninterrupted.status.success());
    for file in ["summary.json", "series.csv", "quantities.csv"] {
        assert_eq!(
            std::fs::read(out.join(file)).unwrap(),
            std::fs::read(whole.join(file)).unwrap(),
            "{file} of the resumed run differs from the uninterrupted run's"
        );
    }
}

#[test]
fn sigterm_without_checkpoints_says_nothing_was_saved() {
    let dir = tempfile::tempdir().unwrap();
    let scene = scene(dir.path(), 0);
    let out = dir.path().join("out");
    let stopped = signalled(&scene, &out, "-TERM");
    let stderr = String::from_utf8_lossy(&stopped.stderr);
    assert_eq!(stopped.status.code(), Some(143), "{stderr}");
    assert!(stderr.contains("stopped by SIGTERM after step"), "{stderr}");
    assert!(stderr.contains("nothing was saved"), "{stderr}");
    let left: Vec<_> = std::fs::read_dir(&out).unwrap().collect();
    assert!(left.is_empty(), "no output may appear: {left:?}");
}

/// SIGKILL cannot be handled: what it must never leave is a file cut short under
/// its final name. Killed at several moments while checkpoints are written every
/// few milliseconds, every checkpoint.json present parses whole.
#[test]
fn a_killed_run_leaves_no_file_cut_short_under_its_final_name() {
    let dir = tempfile::tempdir().unwrap();
    let scene = scene(dir.path(), 2_000);
    for (k, delay) in [150u64, 230, 310, 390, 470].into_iter().enumerate() {
        let out = dir.path().join(format!("out{k}"));
        let child = tamp(&[
            "run",
            scene.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ])
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
        std::thread::sleep(Duration::from_millis(delay));
        send("-KILL", child.id());
        let _ = child.wait_with_output().unwrap();
        for entry in std::fs::read_dir(&out).unwrap() {
            let name = entry.unwrap().file_name().to_string_lossy().to_string();
            if name.starts_with('.') {
                continue; // a temporary name, never taken for a result
            }
            assert_eq!(
                name, "checkpoint.json",
                "only checkpoints are written on the way"
            );
            let text = std::fs::read_to_string(out.join(&name)).unwrap();
            serde_json::from_str::<Value>(&text)
                .unwrap_or_else(|e| panic!("{name} after a kill at {delay} ms: {e}"));
        }
    }
}
