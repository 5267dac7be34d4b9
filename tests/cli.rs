//! The CLI contract: `tamp run` outputs and provenance, exit 3 on instability, VTK
//! frames that parse back, `tamp verify` exit codes.

mod common;

use serde_json::{Value, json};

use common::{base, scene_in_tempdir};

fn tamp(args: &[&str]) -> std::process::Output {
    common::tamp().args(args).output().unwrap()
}

/// `tamp COMMAND SCENE --out OUT` with `scene` written to a temporary directory: the exit
/// code, stderr, OUT, and the directory (kept alive while OUT is read).
fn on_scene(
    command: &str,
    scene: &Value,
) -> (Option<i32>, String, std::path::PathBuf, tempfile::TempDir) {
    let (dir, path, out) = scene_in_tempdir(scene);
    let o = tamp(&[
        command,
        path.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    let stderr = String::from_utf8_lossy(&o.stderr).into_owned();
    (o.status.code(), stderr, out, dir)
}

#[test]
fn run_writes_summary_series_and_vtk_with_provenance() {
    let (_dir, scene, out) = scene_in_tempdir(&base());
    let o = tamp(&[
        "run",
        scene.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));

    let summary: Value =
        serde_json::from_slice(&std::fs::read(out.join("summary.json")).unwrap()).unwrap();
    let prov = &summary["provenance"];
    assert_eq!(prov["tamp_version"], env!("CARGO_PKG_VERSION"));
    assert!(prov["git_commit"].as_str().unwrap().len() >= 7);
    let sha = tamp::scene::sha256_hex(&std::fs::read(&scene).unwrap());
    assert_eq!(prov["scene_sha256"], sha);
    assert!(prov["dt"].as_f64().unwrap() > 0.0);
    // The spheres come to rest on the floor: the floor carries their weight.
    let weight = 2.0 * 2500.0 * 4.0 / 3.0 * std::f64::consts::PI * 1e-9 * 9.81;
    let fz = summary["wall_forces"][0]["force"][2].as_f64().unwrap();
    assert!(
        (fz + weight).abs() < 0.05 * weight,
        "floor force {fz}, weight {weight}"
    );

    let series = std::fs::read_to_string(out.join("series.csv")).unwrap();
    assert!(
        series
            .lines()
            .next()
            .unwrap()
            .starts_with("step,time,kinetic_energy")
    );
    assert!(series.lines().count() > 100);

    let frames: Vec<_> = std::fs::read_dir(out.join("vtk"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    assert!(frames.len() >= 2);
    for f in frames {
        let vtk = vtkio::Vtk::import(&f)
            .unwrap_or_else(|e| panic!("{} does not parse: {e}", f.display()));
        let vtkio::model::DataSet::PolyData { pieces, .. } = vtk.data else {
            panic!("not polydata")
        };
        let vtkio::model::Piece::Inline(piece) = &pieces[0] else {
            panic!("not inline")
        };
        assert_eq!(piece.num_points(), 2);
        let names: Vec<String> = piece
            .data
            .point
            .iter()
            .map(|a| a.name().to_string())
            .collect();
        assert_eq!(names, ["id", "radius", "material", "velocity", "omega"]);
    }
    // No temporary files are left behind.
    assert!(
        std::fs::read_dir(&out).unwrap().all(|e| !e
            .unwrap()
            .file_name()
            .to_string_lossy()
            .ends_with(".tmp"))
    );
}

/// A scene piped on standard input (`-` or `/dev/stdin`) runs as from its file: one
/// read of the input serves the kind of document, the hash and the run.
#[test]
fn run_reads_the_scene_from_standard_input() {
    use std::io::Write;
    let (dir, scene, from_file) = scene_in_tempdir(&base());
    let o = tamp(&[
        "run",
        "--quiet",
        scene.to_str().unwrap(),
        "--out",
        from_file.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let bytes = std::fs::read(&scene).unwrap();
    for name in ["-", "/dev/stdin"] {
        let out = dir.path().join(format!("out_stdin{}", name.len()));
        let mut child = common::tamp()
            .args(["run", "--quiet", name, "--out", out.to_str().unwrap()])
            .stdin(std::process::Stdio::piped())
            .stderr(std::process::Stdio::piped())
            .spawn()
            .unwrap();
        child.stdin.take().unwrap().write_all(&bytes).unwrap();
        let o = child.wait_with_output().unwrap();
        assert!(
            o.status.success(),
            "{name}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        for file in ["series.csv", "summary.json"] {
            assert_eq!(
                std::fs::read(out.join(file)).unwrap(),
                std::fs::read(from_file.join(file)).unwrap(),
                "{name}: {file} differs from the run of the file"
            );
        }
    }
}

#[test]
fn ten_times_the_critical_step_stops_with_exit_3_and_a_diagnostic() {
    let mut s = base();
    s["contact"]["damping"] = Value::Null;
    s["particles"][0]["velocity"] = json!([0, 0, -1.0]);
    // Δt_cr for this scene is about 1.1e-5 s at 1 m/s (α = 1); ten times that:
    s["time_step"] = json!({"fixed": 1.1e-4, "characteristic_velocity": 1.0, "alpha": 1.0});
    let (_dir, scene, out) = scene_in_tempdir(&s);
    let o = tamp(&[
        "run",
        scene.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--quiet",
    ]);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(3), "{stderr}");
    assert!(stderr.contains("warning: time_step.fixed"), "{stderr}");
    assert!(stderr.contains("unstable at step"), "{stderr}");
    assert!(
        stderr.contains("contact 1-wall 'floor'")
            || stderr.contains("contact 1-2")
            || stderr.contains("particle 1 moved"),
        "{stderr}"
    );
    assert!(
        !out.join("summary.json").exists(),
        "an unstable run must not write a summary"
    );
}

/// A run shorter than `stability.check_every` used to end without any energy
/// check, so a step just past the stability limit of a linear spring
/// (ω Δt ≈ 2.07 > 2) created energy and exited 0. The check now also runs after
/// the last step.
#[test]
fn energy_created_before_the_first_periodic_check_stops_the_run() {
    let s = json!({
        "name": "two spheres on a spring stepped just past its limit",
        "materials": [{"name": "glass", "density": 2500}],
        "contact": {"normal": {"law": "linear", "stiffness": 1000}},
        "particles": [
            {"position": [0, 0, 0], "radius": 0.001, "material": "glass", "velocity": [0.01, 0, 0]},
            {"position": [0.0021, 0, 0], "radius": 0.001, "material": "glass", "velocity": [-0.01, 0, 0]}
        ],
        "time_step": {"fixed": 1.5e-4},
        "run": {"steps": 90},
        "stability": {"check_every": 100}
    });
    let (code, stderr, out, _dir) = on_scene("run", &s);
    assert_eq!(code, Some(3), "{stderr}");
    assert!(
        stderr.contains("unstable at step 90") && stderr.contains("mechanical energy grew"),
        "{stderr}"
    );
    assert!(!out.join("summary.json").exists());
}

#[test]
fn verify_rejects_unknown_case_with_exit_2() {
    let o = tamp(&["verify", "--case", "no_such_case"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--case: unknown case 'no_such_case'"));
    let o = tamp(&["verify", "--skip-case", "no_such_case"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        String::from_utf8_lossy(&o.stderr).contains("--skip-case: unknown case 'no_such_case'")
    );
}

#[test]
fn verify_writes_report_and_contract_json() {
    let dir = tempfile::tempdir().unwrap();
    let report = dir.path().join("report");
    let o = tamp(&[
        "verify",
        "--case",
        "hertz_yield_onset",
        "--report",
        report.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let j: Value =
        serde_json::from_slice(&std::fs::read(report.join("verification.json")).unwrap()).unwrap();
    let case = &j["cases"][0];
    assert_eq!(case["name"], "hertz_yield_onset");
    assert_eq!(case["status"], "pass");
    for key in [
        "name",
        "value",
        "reference",
        "tolerance",
        "tolerance_kind",
        "unit",
        "source",
    ] {
        assert!(!case["quantities"][0][key].is_null(), "missing {key}");
    }
    let md = std::fs::read_to_string(report.join("verification.md")).unwrap();
    assert!(md.contains("| hertz_yield_onset | F_Y_table2 |"));
}

/// Every checked-in scene and die-compaction file parses as its kind.
#[test]
fn every_verification_scene_parses() {
    for entry in std::fs::read_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/verification")).unwrap() {
        let path = entry.unwrap().path();
        if path.to_string_lossy().ends_with(".scene.json") {
            tamp::document::load(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        }
    }
}

#[test]
fn export_liggghts_refuses_what_liggghts_cannot_express_naming_every_field() {
    let mut scene = base();
    scene["contact"]["normal"] =
        json!({"law": "walton_braun", "loading_stiffness": 1e3, "unloading_stiffness": 2e3});
    scene["contact"]["cohesion"] =
        json!({"law": "van_der_waals", "hamaker": 1e-19, "min_separation": 4e-10, "cutoff": 1e-6});
    scene["growth"] = json!({"duration": 0.01, "initial_fraction": 0.5});
    scene["materials"]
        .as_array_mut()
        .unwrap()
        .push(json!({"name": "die", "rigid": true}));
    scene["walls"][0]["material"] = json!("die");
    let (code, err, out, _dir) = on_scene("export-liggghts", &scene);
    assert_eq!(code, Some(2), "{err}");
    for field in [
        "contact.normal.law",
        "contact.tangential.law",
        "contact.cohesion",
        "growth",
        "materials[1].rigid",
    ] {
        assert!(
            err.contains(&format!("{field}: cannot export to LIGGGHTS 3.8")),
            "{field}: {err}"
        );
    }
    assert!(
        !out.join("in.tamp").exists(),
        "a refused export writes nothing"
    );
}

/// LIGGGHTS's cylinders take R* = R: a "mean" cylinder would export as another contact.
#[test]
fn export_liggghts_refuses_a_mean_curvature_cylinder() {
    let scene: serde_json::Value = serde_json::from_str(include_str!(
        "../verification/cylinder_wall_impact_lammps.scene.json"
    ))
    .unwrap();
    let (code, err, out, _dir) = on_scene("export-liggghts", &scene);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("walls[0].shape.curvature: cannot export to LIGGGHTS 3.8"),
        "{err}"
    );
    assert!(
        !out.join("in.tamp").exists(),
        "a refused export writes nothing"
    );
}

#[test]
fn export_liggghts_writes_a_deck_with_the_same_particles() {
    let mut scene = base();
    scene["contact"] = json!({"normal": {"law": "hertz"},
        "damping": {"kind": "liggghts_restitution", "restitution": 0.5}});
    let (_dir, path, out) = scene_in_tempdir(&scene);
    let o = tamp(&[
        "export-liggghts",
        path.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let deck = std::fs::read_to_string(out.join("in.tamp")).unwrap();
    for line in [
        "read_data    particles.data",
        "pair_style   gran model hertz tangential history",
        "coefficientRestitution peratomtypepair 1 5e-1",
        "fix          integr all nve/sphere",
        "write_dump   all custom final.liggghts",
    ] {
        assert!(deck.contains(line), "missing '{line}' in\n{deck}");
    }
    let data = std::fs::read_to_string(out.join("particles.data")).unwrap();
    let n = scene["particles"].as_array().map_or(0, Vec::len);
    assert!(data.contains(&format!("\n{n} atoms\n")), "{data}");
}

#[test]
fn each_exporter_refuses_the_other_peers_lever_arms_naming_the_field() {
    // The oblique wall scene with friction and spins: LIGGGHTS's lever arm is R − δ/2
    // ("mid_overlap"), LAMMPS's the full radius ("lammps"), contact/lever_arm.rs.
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/verification/oblique_wall_impact_liggghts.scene.json"
    );
    let mut scene: Value = serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    for (command, arms, peer) in [
        ("export-liggghts", "lammps", "LIGGGHTS 3.8"),
        ("export-lammps", "mid_overlap", "LAMMPS"),
    ] {
        scene["contact"]["lever_arm"] = json!(arms);
        let (code, err, out, _dir) = on_scene(command, &scene);
        assert_eq!(code, Some(2), "{command}: {err}");
        assert!(
            err.contains(&format!("contact.lever_arm: cannot export to {peer}")),
            "{command}: {err}"
        );
        assert!(!out.join("in.tamp").exists());
    }
}

#[test]
fn compare_exits_1_beyond_tolerance_and_0_within() {
    let dir = tempfile::tempdir().unwrap();
    let write = |name: &str, text: &str| {
        let p = dir.path().join(name);
        std::fs::write(&p, text).unwrap();
        p
    };
    let a = write("a.csv", "quantity,value\npacking_fraction,0.640\n");
    let b = write("b.csv", "quantity,value\npacking_fraction,0.637\n");
    let tol = write(
        "tol.csv",
        "item,tolerance,kind\npacking_fraction,0.005,absolute\n",
    );
    let (a, b, tol) = (
        a.to_str().unwrap(),
        b.to_str().unwrap(),
        tol.to_str().unwrap(),
    );
    assert_eq!(tamp(&["compare", a, b]).status.code(), Some(1));
    let o = tamp(&["compare", a, b, "--tolerances", tol]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stdout)
    );
    let bad = write("bad.csv", "quantity,value\npacking_fraction,lots\n");
    let o = tamp(&["compare", bad.to_str().unwrap(), b]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("'lots' is not a number"));
}

/// `tamp study accuracy-cost` on one cheap case: a CSV row per quantity and step, the
/// case's own step passing as in `tamp verify`, the step scale changing Δt by that
/// factor, and a page with the case's section and plot; a bad scale list is exit 2.
#[test]
fn study_accuracy_cost_sweeps_one_case_and_writes_the_page() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().to_str().unwrap();
    let bad = tamp(&[
        "study",
        "accuracy-cost",
        "--case",
        "hertz_collision_time",
        "--scales",
        "0,1",
        "--out",
        out,
    ]);
    assert_eq!(bad.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&bad.stderr).contains("--scales"));

    let o = tamp(&[
        "study",
        "accuracy-cost",
        "--case",
        "hertz_collision_time",
        "--scales",
        "2,1,0.5",
        "--min-wall",
        "0",
        "--out",
        out,
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let mut reader =
        csv::Reader::from_path(dir.path().join("accuracy-cost/hertz_collision_time.csv")).unwrap();
    let rows: Vec<csv::StringRecord> = reader.records().map(|r| r.unwrap()).collect();
    let header = reader.headers().unwrap().clone();
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    let at = |scale: f64| -> Vec<&csv::StringRecord> {
        rows.iter()
            .filter(|r| r[col("step_scale")].parse::<f64>().unwrap() == scale)
            .collect()
    };
    assert!(!at(1.0).is_empty());
    assert!(at(1.0).iter().all(|r| &r[col("status")] == "pass"));
    let dt = |scale: f64| at(scale)[0][col("dt")].parse::<f64>().unwrap();
    assert!((dt(2.0) / dt(1.0) - 2.0).abs() < 1e-12);
    assert!((dt(0.5) / dt(1.0) - 0.5).abs() < 1e-12);
    assert_eq!(at(2.0).len(), at(1.0).len());
    let page = std::fs::read_to_string(dir.path().join("accuracy-cost.md")).unwrap();
    assert!(page.contains("### hertz_collision_time"));
    assert!(
        dir.path()
            .join("img/accuracy-cost/hertz_collision_time.svg")
            .exists()
    );
}

/// A run that fails in a directory holding an earlier run's outputs leaves none of them
/// behind to be taken for its own, and a scene file inside `--out` named like an output
/// is refused (exit 2), never overwritten.
#[test]
fn a_failed_run_leaves_no_earlier_outputs_and_never_overwrites_its_scene() {
    let (_dir, scene, out) = scene_in_tempdir(&base());
    let run = |scene: &std::path::Path| {
        tamp(&[
            "run",
            scene.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
            "--quiet",
        ])
    };
    assert_eq!(run(&scene).status.code(), Some(0));
    for name in ["summary.json", "series.csv", "quantities.csv"] {
        assert!(out.join(name).exists(), "{name}");
    }
    // The same directory, now for a run that goes unstable (ten times Δt_cr).
    let mut unstable = base();
    unstable["contact"]["damping"] = Value::Null;
    unstable["particles"][0]["velocity"] = json!([0, 0, -1.0]);
    unstable["time_step"] = json!({"fixed": 1.1e-4, "characteristic_velocity": 1.0, "alpha": 1.0});
    let unstable_path = scene.with_file_name("unstable.json");
    std::fs::write(&unstable_path, unstable.to_string()).unwrap();
    assert_eq!(run(&unstable_path).status.code(), Some(3));
    for name in [
        "summary.json",
        "series.csv",
        "quantities.csv",
        "trajectory.csv",
    ] {
        assert!(
            !out.join(name).exists(),
            "{name} of the earlier run survived"
        );
    }
    // A scene inside --out under an output's name.
    let inside = out.join("summary.json");
    std::fs::write(&inside, base().to_string()).unwrap();
    let o = run(&inside);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("--out") && stderr.contains("summary.json"),
        "{stderr}"
    );
    assert_eq!(
        std::fs::read_to_string(&inside).unwrap(),
        base().to_string()
    );
}

/// Help a user can act on. `run --help` names the files it writes and the exit codes;
/// `verify --help` gives the tiers' real durations; the studies write where the user
/// says, `docs/` only when named.
#[test]
fn help_texts_name_files_exit_codes_durations_and_where_studies_write() {
    let text = |args: &[&str]| String::from_utf8(tamp(args).stdout).unwrap();
    let run = text(&["run", "--help"]);
    for needle in [
        "summary.json",
        "series.csv",
        "quantities.csv",
        "trajectory.csv",
        "checkpoint.json",
        "one row per pressure record",
        "Exit codes",
        "130/143",
        "<SCENE>  The scene",
        "--out <DIR>",
    ] {
        assert!(run.contains(needle), "run --help lacks '{needle}':\n{run}");
    }
    let verify = text(&["verify", "--help"]);
    assert!(verify.contains("about 10 min on 2 cores"), "{verify}");
    assert!(!verify.contains("seconds)"), "{verify}");
    let study = text(&["study", "--help"]);
    assert!(study.contains("only an explicit `--out docs`"), "{study}");
    for sub in ["accuracy-cost", "stable-alpha", "die-compaction"] {
        let help = text(&["study", sub, "--help"]);
        assert!(help.contains("[default: study]"), "{sub}: {help}");
    }
}

/// The README is a front door of about one screen before its documentation list, and
/// every file its commands name exists.
#[test]
fn readme_front_door_is_one_screen_and_names_existing_files() {
    let readme = include_str!("../README.md");
    let front = readme
        .split("## Documentation")
        .next()
        .expect("README has a documentation list");
    assert!(
        front.lines().count() <= 50,
        "{} lines before the documentation list",
        front.lines().count()
    );
    for needle in [
        "cargo install --path .",
        "cargo run --release -- verify",
        "cargo test --release",
    ] {
        assert!(front.contains(needle), "README lacks `{needle}`");
    }
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let named: Vec<&str> = front
        .split(|c: char| c.is_whitespace() || c == '`' || c == '(' || c == ')')
        .filter(|w| w.ends_with(".scene.json") || w.starts_with(".ci/"))
        .collect();
    assert!(named.len() >= 3, "{named:?}");
    for path in named {
        assert!(
            root.join(path).exists(),
            "README names {path}, which does not exist"
        );
    }
}

/// A lone particle stores no energy and feels no contact: the zeros its run writes
/// have no sign (summary.json once said `"stored_energy": -0.0`).
#[test]
fn outputs_write_no_negative_zero() {
    let mut scene = common::base();
    scene["particles"] =
        serde_json::json!([{"position": [0, 0, 0.5], "radius": 0.001, "material": "glass"}]);
    scene["run"] = serde_json::json!({"steps": 10});
    scene["output"] = serde_json::json!({"trajectory_every": 1});
    let (_dir, path, out) = common::scene_in_tempdir(&scene);
    let run = common::run(&path, &out, &[]);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    for file in [
        "summary.json",
        "series.csv",
        "quantities.csv",
        "trajectory.csv",
    ] {
        let text = std::fs::read_to_string(out.join(file)).unwrap();
        for (k, line) in text.lines().enumerate() {
            for field in line.split([',', ' ', ':']) {
                let field = field.trim();
                assert!(
                    !(field.starts_with("-0") && field.parse::<f64>() == Ok(0.0)),
                    "{file} line {}: {line}",
                    k + 1
                );
            }
        }
    }
}
