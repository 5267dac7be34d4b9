//! `run.until` ends a run once its particles have settled, and says so: a bed that
//! settles stops before its maximum duration, one that cannot settle in time runs to
//! it, and a scene without `until` writes the summary it always did.

mod common;

use serde_json::{Value, json};

use common::base;

/// Run `scene`; return (exit code, stderr, summary.json).
fn run(scene: &Value) -> (i32, String, Value) {
    let (_dir, path, out) = common::scene_in_tempdir(scene);
    let o = common::run(&path, &out, &[]);
    let stderr = String::from_utf8_lossy(&o.stderr).to_string();
    let summary = std::fs::read_to_string(out.join("summary.json"))
        .map(|s| serde_json::from_str(&s).unwrap())
        .unwrap_or(Value::Null);
    (o.status.code().unwrap_or(-1), stderr, summary)
}

/// A damped sphere dropped 1 mm straight onto a floor (0.3 s at most) comes to rest
/// long before. (Two spheres would not: the upper one rolls off the lower one and
/// keeps rolling, which nothing in the scene dissipates.)
fn settling() -> Value {
    let mut s = base();
    s["particles"].as_array_mut().unwrap().truncate(1);
    s["run"] = json!({"duration": 0.3,
        "until": {"kinetic_energy_per_particle": 1e-10, "max_speed": 1e-3, "held_for": 0.01}});
    s
}

#[test]
fn a_settling_bed_ends_by_the_criterion_before_its_maximum() {
    let (code, stderr, summary) = run(&settling());
    assert_eq!(code, 0, "{stderr}");
    let end = &summary["ended_by"];
    assert_eq!(end["criterion"], "run.until", "{summary}");
    let time = summary["time"].as_f64().unwrap();
    assert!(time > 0.01 && time < 0.25, "t = {time}");
    assert_eq!(end["time"].as_f64(), Some(time));
    assert!(end["kinetic_energy_per_particle"].as_f64().unwrap() < 1e-10);
    assert!(end["max_speed"].as_f64().unwrap() < 1e-3);
    assert!(
        stderr.contains("run.until ended the run at t = "),
        "{stderr}"
    );
    // The steps run are the ones summary.json reports, fewer than the maximum.
    let steps = summary["steps"].as_u64().unwrap();
    assert!(steps < summary["provenance"]["steps"].as_u64().unwrap());
    assert_eq!(end["step"].as_u64(), Some(steps));
}

#[test]
fn a_bed_still_falling_runs_to_its_maximum() {
    let mut s = settling();
    s["run"]["duration"] = json!(0.005);
    let (code, stderr, summary) = run(&s);
    assert_eq!(code, 0, "{stderr}");
    assert_eq!(
        summary["ended_by"]["criterion"], "run.duration",
        "{summary}"
    );
    assert_eq!(summary["steps"], summary["provenance"]["steps"]);
    assert!(stderr.contains("run.duration ended the run"), "{stderr}");
}

#[test]
fn a_scene_without_until_reports_no_criterion() {
    let mut s = base();
    s["run"]["duration"] = json!(0.005);
    let (code, stderr, summary) = run(&s);
    assert_eq!(code, 0, "{stderr}");
    assert!(summary.get("ended_by").is_none(), "{summary}");
    assert!(!stderr.contains("ended the run"), "{stderr}");
}

#[test]
fn until_rules_are_named() {
    let mut s = settling();
    s["run"]["until"] =
        json!({"kinetic_energy_per_particle": 0, "max_speed": -1, "held_for": -0.1});
    let (code, stderr, _) = run(&s);
    assert_eq!(code, 2, "{stderr}");
    for path in [
        "run.until.kinetic_energy_per_particle: must be > 0",
        "run.until.max_speed: must be > 0",
        "run.until.held_for: must be >= 0",
    ] {
        assert!(stderr.contains(path), "{path}: {stderr}");
    }
}
