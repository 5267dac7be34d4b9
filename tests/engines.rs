//! `tamp verify --engine`: a case measures only what an engine recorded, so tamp behind
//! the adapter contract must get the in-process engine's verdict on every case that runs
//! on every engine, and whatever an adapter writes is untrusted input: a missing,
//! truncated, non-finite, duplicated or mis-scaled output is an error or a failure
//! naming what is wrong, never a pass.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("tamp-engines-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// `tamp verify` with `args`, the report and JSON in `dir`; the JSON's cases.
fn verify(dir: &Path, args: &[&str]) -> (Output, Vec<serde_json::Value>) {
    let json = dir.join("v.json");
    let out = Command::new(env!("CARGO_BIN_EXE_tamp"))
        .arg("verify")
        .args(args)
        .arg("--report")
        .arg(dir.join("report"))
        .arg("--json")
        .arg(&json)
        .env("TAMP", env!("CARGO_BIN_EXE_tamp"))
        .current_dir(root())
        .output()
        .unwrap();
    let text = std::fs::read_to_string(&json)
        .unwrap_or_else(|e| panic!("no JSON ({e}): {}", String::from_utf8_lossy(&out.stderr)));
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    (out, v["cases"].as_array().unwrap().clone())
}

/// Run too long for a test: from 8 min to 80 s in-process, and as long again through
/// the adapter on the 2-core machine (their runs through `tamp_run.sh` are in
/// docs/engines.md).
const TOO_LONG: [&str; 4] = [
    "binary_packing_ratio10_quick",
    "nial_die_compaction_small",
    "liggghts_die_compaction_small",
    "lammps_die_compaction_small",
];

/// The quick cases whose files do not say `tamp_only`, but those `TOO_LONG` for a test.
fn cases_for_every_engine() -> Vec<String> {
    let mut names = Vec::new();
    for entry in std::fs::read_dir(root().join("verification")).unwrap() {
        let path = entry.unwrap().path();
        let file = path.to_string_lossy().to_string();
        if !file.ends_with(".json") || file.ends_with(".scene.json") {
            continue;
        }
        let case: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap();
        let name = case["name"].as_str().unwrap();
        if case["tier"] == "quick" && case.get("tamp_only").is_none() && !TOO_LONG.contains(&name) {
            names.push(name.to_string());
        }
    }
    names.sort();
    names
}

#[test]
fn tamp_behind_the_adapter_contract_gets_the_in_process_verdict_on_every_case() {
    let names = cases_for_every_engine();
    assert!(names.len() >= 5, "{names:?}");
    let dir = scratch("tamp-run");
    let mut args = vec![
        "--engine",
        "tamp",
        "--engine",
        "command:examples/adapters/tamp_run.sh",
    ];
    for n in &names {
        args.extend(["--case", n]);
    }
    let (out, cases) = verify(&dir, &args);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(cases.len(), 2 * names.len());
    for n in &names {
        let on = |engine: &str| {
            cases
                .iter()
                .find(|c| {
                    c["name"] == n.as_str() && c["engine"].as_str().unwrap().starts_with(engine)
                })
                .unwrap_or_else(|| panic!("{n} did not run on {engine}"))
        };
        let (inside, adapter) = (on("tamp"), on("command:"));
        // A known deviation is the law's, so the adapter must report it too.
        assert!(
            matches!(inside["status"].as_str(), Some("pass" | "known_deviation")),
            "{n}: {inside}"
        );
        assert_eq!(adapter["status"], inside["status"], "{n}: {adapter}");
        // The same quantities, equal to round-off (the adapter's clock is step·Δt).
        for (a, b) in adapter["quantities"]
            .as_array()
            .unwrap()
            .iter()
            .zip(inside["quantities"].as_array().unwrap())
        {
            assert_eq!(a["name"], b["name"]);
            let (x, y) = (a["value"].as_f64().unwrap(), b["value"].as_f64().unwrap());
            assert!(
                (x - y).abs() <= 1e-12 * y.abs().max(1e-300),
                "{n} {}: {x} vs {y}",
                a["name"]
            );
        }
    }
}

/// Run hertz_collision_time on an adapter whose body is `script` (sh, with $1 the
/// scene and $2 the output directory); its one case.
fn adapter_case(name: &str, script: &str) -> (Output, serde_json::Value) {
    let dir = scratch(name);
    let path = dir.join("adapter.sh");
    std::fs::write(&path, format!("#!/bin/sh\n{script}\n")).unwrap();
    let mut perms = std::fs::metadata(&path).unwrap().permissions();
    std::os::unix::fs::PermissionsExt::set_mode(&mut perms, 0o755);
    std::fs::set_permissions(&path, perms).unwrap();
    let engine = format!("command:{}", path.display());
    let (out, cases) = verify(
        &dir,
        &["--case", "hertz_collision_time", "--engine", &engine],
    );
    (out, cases[0].clone())
}

const RUN: &str = "\"$TAMP\" run \"$1\" --out \"$2\" --quiet || exit 1";

#[test]
fn an_adapter_s_output_is_untrusted_input() {
    let t = "\"$2/trajectory.csv\"";
    let bad_outputs = [
        (
            "nothing",
            "exit 0".to_string(),
            "trajectory.csv: was not written",
        ),
        (
            "truncated",
            format!("{RUN}\nhead -n 201 {t} > \"$2/t\" && mv \"$2/t\" {t}"),
            "has no rows for step",
        ),
        (
            "nan",
            format!("{RUN}\nsed -i '150s/^\\([0-9]*,[0-9]*\\),[^,]*,/\\1,NaN,/' {t}"),
            "row 150, column 'radius': 'NaN' is not a finite number",
        ),
        (
            "duplicated",
            format!("{RUN}\nsed -i '100p' {t}"),
            "were given before",
        ),
        (
            "missing-particle",
            format!("{RUN}\nsed -i '41d' {t}"),
            "has no row for particle id",
        ),
        (
            "no-velocities",
            format!("{RUN}\ncut -d, -f1-6 {t} > \"$2/t\" && mv \"$2/t\" {t}"),
            "needs the columns vx, vy, vz",
        ),
        (
            "crash",
            "echo 'segmentation fault in the force loop' >&2; exit 139".to_string(),
            "exited with code 139",
        ),
    ];
    for (name, script, expected) in bad_outputs {
        let (out, case) = adapter_case(name, &script);
        assert_eq!(case["status"], "error", "{name}: {case}");
        let error = case["error"].as_str().unwrap();
        assert!(error.contains(expected), "{name}: {error}");
        assert_eq!(out.status.code(), Some(1), "{name}");
    }
    // Millimetres for metres: the spheres never meet, and the case says so.
    let (_, case) = adapter_case(
        "millimetres",
        &format!(
            "{RUN}\nawk -F, 'BEGIN{{OFS=\",\"}} NR>1{{$4*=1e3;$5*=1e3;$6*=1e3}} {{print}}' {t} > \"$2/t\" && mv \"$2/t\" {t}"
        ),
    );
    assert_ne!(case["status"], "pass", "{case}");
    // A feature the adapter lacks: not expressible, with its reason; not a failure.
    let (out, case) = adapter_case(
        "feature",
        "echo 'contact.normal.law: this adapter has no hertz' >&2; exit 4",
    );
    assert_eq!(case["status"], "not_expressible", "{case}");
    assert!(
        case["error"]
            .as_str()
            .unwrap()
            .contains("this adapter has no hertz")
    );
    assert_eq!(out.status.code(), Some(0));
}

#[test]
fn a_case_for_tamp_alone_is_not_expressible_elsewhere_and_names_why() {
    let dir = scratch("tamp-only");
    let (out, cases) = verify(
        &dir,
        &[
            "--case",
            "hollomon_constants",
            "--engine",
            "command:examples/adapters/tamp_run.sh",
        ],
    );
    assert_eq!(out.status.code(), Some(0));
    assert_eq!(cases[0]["status"], "not_expressible");
    assert_eq!(cases[0]["engine"], "command:examples/adapters/tamp_run.sh");
    assert!(
        cases[0]["error"]
            .as_str()
            .unwrap()
            .starts_with("runs on tamp only: a calculation")
    );
}

#[test]
fn an_unknown_engine_is_refused_naming_the_choices() {
    let out = Command::new(env!("CARGO_BIN_EXE_tamp"))
        .args(["verify", "--engine", "gromacs"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("tamp, liggghts, lammps or command:PROG"),
        "{err}"
    );
}

/// Without `--live` a peer engine gives the values recorded in
/// `reference_data/<peer>/engine/`, with no peer installed; a record whose deck is not
/// the one the case exports now is an error naming the command that re-records it; an
/// engine farther from tamp than the case file's `agreement` fails.
#[test]
fn a_peer_engine_without_the_peer_gives_its_recorded_values_and_keeps_its_promises() {
    let case = "hertz_collision_time";
    let record_path = root().join(format!("reference_data/liggghts/engine/{case}.json"));
    let record: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&record_path).unwrap()).unwrap();

    let dir = scratch("recorded");
    let json = dir.join("v.json");
    let run = |verification: &Path| {
        let _ = std::fs::remove_file(&json);
        Command::new(env!("CARGO_BIN_EXE_tamp"))
            .args(["verify", "--engine", "liggghts", "--case", case, "--report"])
            .arg(dir.join("report"))
            .arg("--json")
            .arg(&json)
            .env("PATH", "/nonexistent")
            .env("TAMP_VERIFICATION_DIR", verification)
            .current_dir(root())
            .output()
            .unwrap()
    };
    let cases = |out: &Output| -> Vec<serde_json::Value> {
        let text = std::fs::read_to_string(&json)
            .unwrap_or_else(|e| panic!("no JSON ({e}): {}", String::from_utf8_lossy(&out.stderr)));
        serde_json::from_str::<serde_json::Value>(&text).unwrap()["cases"]
            .as_array()
            .unwrap()
            .clone()
    };
    let out = run(&root().join("verification"));
    let c = &cases(&out)[0];
    assert_eq!(c["status"], "pass", "{c}");
    for q in c["quantities"].as_array().unwrap() {
        let name = q["name"].as_str().unwrap();
        assert_eq!(q["value"], record["quantities"][name], "{name}");
    }

    // The same case beside a record of another deck.
    let copy = dir.join("copy");
    std::fs::create_dir_all(copy.join("verification")).unwrap();
    for file in [format!("{case}.json"), format!("{case}.scene.json")] {
        std::fs::copy(
            root().join("verification").join(&file),
            copy.join("verification").join(&file),
        )
        .unwrap();
    }
    let mut stale = record.clone();
    stale["runs"][0]["deck_sha256"] = serde_json::json!("0".repeat(64));
    let stale_path = copy.join(format!("reference_data/liggghts/engine/{case}.json"));
    std::fs::create_dir_all(stale_path.parent().unwrap()).unwrap();
    std::fs::write(&stale_path, stale.to_string()).unwrap();
    let out = run(&copy.join("verification"));
    let c = &cases(&out)[0];
    assert_eq!(c["status"], "error", "{c}");
    let error = c["error"].as_str().unwrap();
    assert!(
        error.contains("is stale") && error.contains("--live --record --case hertz_collision_time"),
        "{error}"
    );

    // The record as it is, and a case file that promises exact agreement with tamp:
    // the peer's values differ from tamp's through the clock alone, and that fails.
    std::fs::write(&stale_path, record.to_string()).unwrap();
    let case_path = copy.join(format!("verification/{case}.json"));
    let mut strict: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&case_path).unwrap()).unwrap();
    for a in strict["agreement"].as_array_mut().unwrap() {
        a["relative"] = serde_json::json!(0.0);
    }
    std::fs::write(&case_path, strict.to_string()).unwrap();
    let out = run(&copy.join("verification"));
    let c = &cases(&out)[0];
    assert_eq!(c["status"], "fail", "{c}");
    let error = c["error"].as_str().unwrap();
    assert!(error.contains("liggghts departs from tamp"), "{error}");
}
