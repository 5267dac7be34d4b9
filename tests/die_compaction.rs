//! The die-compaction process through `tamp run`: a run killed during pressing and
//! resumed from its checkpoint writes the same files as the uninterrupted run, and a
//! die-compaction scene with a broken rule is refused with exit 2 naming the field.

mod common;

use std::path::{Path, PathBuf};
use std::process::Stdio;
use std::time::{Duration, Instant};

/// 60 particles in a 16 µm die: fill, flatten, press to 50 MPa, checkpoint every
/// 5000 steps (about 7 checkpoints in the press stage).
fn scene() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/tiny_die_compaction.scene.json")
}

use common::tamp;

fn fresh(dir: &Path) {
    let _ = std::fs::remove_dir_all(dir);
}

/// The tiny die through the press cycle: unloaded, ejected and relaxed.
fn cycle_scene() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/tiny_die_cycle.scene.json")
}

#[test]
fn killed_compaction_resumes_to_identical_outputs() {
    resumes_to_identical_outputs(&scene(), "plain");
}

/// A cycle killed during its pressing and resumed writes the same files as the
/// uninterrupted run, cycle.svg among them; its records come stage by stage, in order,
/// and every number in them is finite.
#[test]
fn killed_cycle_resumes_to_identical_outputs() {
    let a = resumes_to_identical_outputs(&cycle_scene(), "cycle");
    let series = std::fs::read_to_string(a.join("series.csv")).unwrap();
    let mut stages: Vec<&str> = series
        .lines()
        .skip(1)
        .map(|l| &l[..l.find(',').unwrap()])
        .collect();
    stages.dedup();
    assert_eq!(stages, ["press", "unload", "eject", "relax"], "{series}");
    for line in series.lines().skip(1) {
        for value in line.split(',').skip(1) {
            let v: f64 = value.parse().unwrap();
            assert!(v.is_finite(), "{line}");
        }
    }
    let quantities = std::fs::read_to_string(a.join("quantities.csv")).unwrap();
    for q in [
        "axial_springback,",
        "residual_radial_pressure,",
        "peak_ejection_force,",
        "ejection_work,",
        "radial_springback,",
    ] {
        assert!(quantities.contains(q), "{quantities}");
    }
    fresh(a.parent().unwrap());
}

/// Run `scene` once whole (into `<base>/a`, returned) and once killed at its first
/// pressing checkpoint and resumed (`<base>/b`): the same files, byte for byte.
fn resumes_to_identical_outputs(scene: &Path, label: &str) -> PathBuf {
    let base = std::env::temp_dir().join(format!("tamp_die_resume_{label}_{}", std::process::id()));
    let (a, b) = (base.join("a"), base.join("b"));
    fresh(&base);
    let status = tamp()
        .args(["run", "--quiet", "--out"])
        .arg(&a)
        .arg(scene)
        .status()
        .unwrap();
    assert!(status.success());

    // Kill B as soon as the press stage has written its first checkpoint.
    let mut child = tamp()
        .args(["run", "--quiet", "--out"])
        .arg(&b)
        .arg(scene)
        .stdout(Stdio::null())
        .spawn()
        .unwrap();
    let started = Instant::now();
    while !b.join("checkpoint.json").exists() {
        assert!(
            started.elapsed() < Duration::from_secs(60),
            "no checkpoint written"
        );
        std::thread::sleep(Duration::from_millis(2));
    }
    child.kill().unwrap();
    child.wait().unwrap();
    assert!(
        !b.join("series.csv").exists(),
        "the run finished before it was killed: the test proves nothing"
    );

    let out = tamp()
        .args(["run", "--quiet", "--resume", "--out"])
        .arg(&b)
        .arg(scene)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("resuming the pressing from step"),
        "{stderr}"
    );
    for file in [
        "series.csv",
        "quantities.csv",
        "summary.json",
        "specimen.json",
        "press.scene.json",
    ]
    .into_iter()
    .chain((label == "cycle").then_some("cycle.svg"))
    {
        let (x, y) = (
            std::fs::read(a.join(file)).unwrap(),
            std::fs::read(b.join(file)).unwrap(),
        );
        assert!(x == y, "{file} differs after resuming");
    }
    // One layout for every run: `scene_name` in summary.json, and quantities.csv and
    // series.csv that `tamp compare` reads like a plain run's.
    let summary: serde_json::Value =
        serde_json::from_slice(&std::fs::read(a.join("summary.json")).unwrap()).unwrap();
    assert!(summary["scene_name"].is_string(), "{summary}");
    let quantities = std::fs::read_to_string(a.join("quantities.csv")).unwrap();
    assert!(quantities.starts_with("quantity,value\n"), "{quantities}");
    assert!(quantities.contains("final_density_rve,"), "{quantities}");
    let compared = tamp().arg("compare").arg(&a).arg(&b).output().unwrap();
    assert!(
        compared.status.success(),
        "{}",
        String::from_utf8_lossy(&compared.stdout)
    );
    if label == "plain" {
        fresh(&base);
    }
    a
}

/// The funnel pour (Rojek Fig 13a) loses no particle and leaves every one whole inside
/// the die after settling and flattening: the count is conserved, and each sphere lies
/// inside the die's cylinder (radius R), above the floor and below H₀, up to the
/// overlap a wall contact may press it in by. That overlap is bounded by the Hertz
/// overlap under the bed's whole weight on one contact, F = M g′:
/// δ = (3F/(4E*√r))^(2/3) ≈ 7e-9 m for the 60 particles at g′ = 9.81e6 m/s² (r = 2 µm,
/// E* = 1.0e11 Pa); 2e-8 m is about three times that. The settled column of the same
/// seed is the other filling; the two must be different beds (the funnel is really used).
#[test]
fn a_funnel_pour_fills_the_die_with_every_particle() {
    use tamp::process::die_compaction_file::{DieCompactionFile, FillMethod};
    let (mut scene, _) = DieCompactionFile::load(&scene()).unwrap();
    let column = tamp::process::die_compaction::prepare(&scene, true).unwrap();
    let dc = &mut scene.die_compaction;
    dc.fill.method = FillMethod::Funnel;
    let (count, die_radius) = (dc.particles.count, 0.5 * dc.die_diameter);
    scene.validate().unwrap();
    let poured = tamp::process::die_compaction::prepare(&scene, true).unwrap();
    assert!(poured.fill_at_rest, "the poured bed did not come to rest");
    assert_eq!(poured.particles.len(), count);
    let tol = 2e-8;
    for (i, p) in poured.particles.iter().enumerate() {
        let [x, y, z] = p.position;
        let r = p.radius;
        assert!(
            x.hypot(y) + r <= die_radius + tol,
            "particle {i} outside the die wall: {p:?}"
        );
        assert!(z - r >= -tol, "particle {i} below the floor: {p:?}");
        assert!(
            z + r <= poured.h0 + tol,
            "particle {i} above H0 {}: {p:?}",
            poured.h0
        );
    }
    assert_ne!(
        column.particles[0].position, poured.particles[0].position,
        "the funnel pour made the settled column's bed"
    );
}

#[test]
fn broken_die_compaction_rules_exit_2_naming_the_field() {
    let text = std::fs::read_to_string(scene()).unwrap();
    let mut value: serde_json::Value = serde_json::from_str(&text).unwrap();
    value["die_compaction"]["rve_diameter"] = serde_json::json!(20e-6);
    value["run"] = serde_json::json!({"duration": 1.0});
    let dir = std::env::temp_dir().join(format!("tamp_die_bad_{}", std::process::id()));
    fresh(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("bad.scene.json");
    std::fs::write(&path, value.to_string()).unwrap();
    let out = tamp()
        .args(["run", "--out"])
        .arg(dir.join("out"))
        .arg(&path)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("die_compaction.rve_diameter"), "{stderr}");
    assert!(stderr.contains("run: must be left out"), "{stderr}");
    assert!(!dir.join("out").join("series.csv").exists());
    fresh(&dir);
}

/// A die-compaction file piped on standard input is recognised as one from the single
/// read of the input: its broken rule is reported as a die-compaction rule.
#[test]
fn a_die_compaction_file_on_standard_input_is_read_as_one() {
    use std::io::Write;
    let text = std::fs::read_to_string(scene()).unwrap();
    let mut value: serde_json::Value = serde_json::from_str(&text).unwrap();
    value["die_compaction"]["rve_diameter"] = serde_json::json!(20e-6);
    let dir = std::env::temp_dir().join(format!("tamp_die_stdin_{}", std::process::id()));
    fresh(&dir);
    let mut child = tamp()
        .args(["run", "-", "--out"])
        .arg(dir.join("out"))
        .stdin(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    child
        .stdin
        .take()
        .unwrap()
        .write_all(value.to_string().as_bytes())
        .unwrap();
    let out = child.wait_with_output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("die_compaction.rve_diameter"), "{stderr}");
    fresh(&dir);
}
