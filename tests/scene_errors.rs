//! Bad scenes exit with code 2 and a message naming the JSON path and the rule.

use serde_json::{Value, json};
use std::process::Command;

fn base() -> Value {
    serde_json::from_str(include_str!("scenes/base.json")).unwrap()
}

/// Run `tamp run --quiet` on `text`; return (exit code, stderr).
fn run_text(text: &str) -> (i32, String) {
    run_with(text, &["--quiet"])
}

/// `run_text` without `--quiet`: what the run says of how it chose its step.
fn run_text_loud(text: &str) -> (i32, String) {
    run_with(text, &[])
}

fn run_with(text: &str, extra: &[&str]) -> (i32, String) {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("scene.json");
    std::fs::write(&scene, text).unwrap();
    let out_dir = dir.path().join("out");
    let out = Command::new(env!("CARGO_BIN_EXE_tamp"))
        .args([
            "run",
            scene.to_str().unwrap(),
            "--out",
            out_dir.to_str().unwrap(),
        ])
        .args(extra)
        .output()
        .unwrap();
    if out.status.code() == Some(2) {
        assert!(
            !out_dir.exists(),
            "exit 2 left {} behind",
            out_dir.display()
        );
    }
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stderr).to_string(),
    )
}

fn expect_input_error(scene: Value, needles: &[&str]) {
    let (code, stderr) = run_text(&scene.to_string());
    assert_eq!(code, 2, "stderr: {stderr}");
    for n in needles {
        assert!(stderr.contains(n), "expected '{n}' in: {stderr}");
    }
    assert!(!stderr.contains("panicked"), "{stderr}");
}

#[test]
fn unknown_field_is_named() {
    let mut s = base();
    s["particles"][1]["colour"] = json!("red");
    expect_input_error(s, &["error: particles[1].colour: unknown field `colour`"]);
}

#[test]
fn missing_field_is_named() {
    let mut s = base();
    s["particles"][1].as_object_mut().unwrap().remove("radius");
    expect_input_error(s, &["particles[1]", "missing field `radius`"]);
}

#[test]
fn negative_radius_is_named() {
    let mut s = base();
    s["particles"][1]["radius"] = json!(-1e-6);
    expect_input_error(s, &["particles[1].radius: must be > 0", "-1e-6"]);
}

#[test]
fn poisson_ratio_of_one_half_is_rejected() {
    let mut s = base();
    s["materials"][0]["poisson_ratio"] = json!(0.5);
    expect_input_error(
        s,
        &["materials[0].poisson_ratio: must be > -1 and < 0.5, got 0.5"],
    );
}

#[test]
fn overlapping_initial_particles_are_rejected() {
    let mut s = base();
    s["particles"][1]["position"] = json!([0.0, 0.0, 0.0035]);
    expect_input_error(
        s,
        &[
            "particles[1].position: overlaps particles[0]",
            "initial_overlap_tolerance",
        ],
    );
}

#[test]
fn zero_length_wall_normal_is_rejected() {
    let mut s = base();
    s["walls"][0]["shape"]["normal"] = json!([0, 0, 0]);
    expect_input_error(
        s,
        &["walls[0].shape.normal: must have non-zero finite length"],
    );
}

#[test]
fn malformed_json_is_reported() {
    let (code, stderr) = run_text("{\"materials\": [");
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains("malformed JSON"), "{stderr}");
}

#[test]
fn unknown_material_and_law_are_named() {
    let mut s = base();
    s["particles"][0]["material"] = json!("steel");
    expect_input_error(s, &["particles[0].material: unknown material 'steel'"]);
    let mut s = base();
    s["contact"]["normal"]["law"] = json!("hooke");
    expect_input_error(s, &["contact.normal", "unknown variant `hooke`"]);
}

#[test]
fn hertz_without_characteristic_velocity_or_fixed_step_is_rejected() {
    // Nothing moves (no gravity, no velocity), so no characteristic velocity is implied.
    let mut s = base();
    s["time_step"] = json!({"alpha": 0.2});
    s.as_object_mut().unwrap().remove("gravity");
    expect_input_error(s, &["time_step.characteristic_velocity: is required"]);
}

#[test]
fn accuracy_is_checked_and_exclusive() {
    let mut s = base();
    s["time_step"] = json!({"accuracy": 0.5});
    expect_input_error(s, &["time_step.accuracy: must be in (0, 0.1]"]);
    let mut s = base();
    s["time_step"] = json!({"accuracy": 1e-3, "fixed": 1e-9});
    expect_input_error(
        s,
        &["time_step.accuracy: cannot be combined with time_step.fixed"],
    );
}

#[test]
fn accuracy_refuses_a_walton_braun_unloading_stiffer_than_calibrated() {
    let mut s = base();
    s["contact"] = json!({"normal": {"law": "walton_braun", "loading_stiffness": 1e5,
                                     "unloading_stiffness": 2e6}});
    s["time_step"] = json!({"accuracy": 1e-3});
    expect_input_error(
        s,
        &[
            "time_step.accuracy",
            "unloading_stiffness is 20.000 times the loading_stiffness, above 10",
        ],
    );
    // Without a stated step the default accuracy gives way to alpha = 0.2.
    let mut s = base();
    s["contact"] = json!({"normal": {"law": "walton_braun", "loading_stiffness": 1e5,
                                     "unloading_stiffness": 2e6}});
    s["time_step"] = json!({});
    let built = tamp::scene::build(&tamp::scene::parse(&s.to_string()).unwrap());
    assert!(built.is_ok(), "{:?}", built.err());
}

/// A law without an error model is refused with exit 2 naming `time_step.accuracy` and
/// the law (`hysteretic`; `thornton` with the `liggghts` unloading, whose first-order
/// increments converge to another closed form); Thornton's own unloading is modelled up
/// to 30 times the yield velocity (glass 1 mm pair at p_y = 1 MPa: v_y = 1.5 cm/s).
#[test]
fn accuracy_refuses_laws_without_an_error_model() {
    for (normal, named) in [
        (
            json!({"law": "hysteretic", "stiffness": 1e5, "hysteresis": 0.5}),
            "(hysteretic) has no error model",
        ),
        (
            json!({"law": "thornton", "yield_pressure": 1e7, "unloading": "liggghts"}),
            "(thornton) has no error model",
        ),
        (
            json!({"law": "thornton", "yield_pressure": 1e6}),
            "times its yield velocity, above 30",
        ),
    ] {
        let mut s = base();
        s["contact"] = json!({ "normal": normal });
        s["time_step"] = json!({"accuracy": 1e-3, "characteristic_velocity": 1.0});
        expect_input_error(s, &["time_step.accuracy", named]);
    }
}

/// A clamped dashpot (`contact.damping.limit`) ends the contact at another restitution
/// than the calibrated one: an accuracy is refused naming the clamp, and a damping block
/// with a limit that is not a boolean is refused at its path.
#[test]
fn accuracy_refuses_a_clamped_dashpot_and_the_limit_is_a_boolean() {
    let mut s = base();
    s["contact"]["damping"]["limit"] = json!(true);
    s["time_step"] = json!({"accuracy": 1e-3, "characteristic_velocity": 1.0});
    expect_input_error(
        s,
        &[
            "time_step.accuracy",
            "limited to no pull) has no error model",
        ],
    );
    let mut s = base();
    s["contact"]["damping"]["limit"] = json!("yes");
    expect_input_error(s, &["contact.damping.limit"]);
}

/// The laws calibrated since (docs/accuracy-cost.md) are refused beyond their
/// calibration: Kuwabara–Kono rebounding below e = 0.1 (A = 0.1 ms on the base scene's
/// soft glass: c ≈ 5, e ≈ 0.07), Hertz with a constant γ_n so strong that the
/// bodies never part (γ_n = 1 N·s/m: c ≈ 6, overdamped above about 1.05), Storåkers with
/// `min_with_hertz` above 10 v* (NiAl 1 mm at 1000 m/s: v* ≈ 14 m/s for a pair), and
/// pure Storåkers, whose unloading returns more than its loading took.
#[test]
fn accuracy_refuses_the_new_laws_beyond_their_calibration() {
    // NiAl, Rojek Table 2 (clippy mistakes ν = 0.318 for 1/π).
    #[allow(clippy::approx_constant)]
    let nial = json!([{"name": "glass", "density": 5910, "youngs_modulus": 183e9,
                       "poisson_ratio": 0.318,
                       "hollomon": {"exponent": 0.2, "yield_stress": 800e6}}]);
    for (contact, materials, v, named) in [
        (
            json!({"normal": {"law": "kuwabara_kono", "dissipation_time": 1e-4}}),
            None,
            1.0,
            "below 0.1, the strongest damping the error model is calibrated for",
        ),
        (
            json!({"normal": {"law": "hertz"}, "damping": {"kind": "constant", "gamma_n": 1.0}}),
            None,
            1.0,
            "from rebounding (overdamped",
        ),
        (
            json!({"normal": {"law": "storakers", "min_with_hertz": true}}),
            Some(nial.clone()),
            1000.0,
            "times the speed at which its loading leaves Hertz's curve, above 10",
        ),
        (
            json!({"normal": {"law": "storakers"}}),
            Some(nial.clone()),
            1.0,
            "the storakers law without min_with_hertz has no error model",
        ),
    ] {
        let mut s = base();
        s["contact"] = contact;
        if let Some(m) = materials {
            s["materials"] = m;
        }
        s["time_step"] = json!({"accuracy": 1e-3, "characteristic_velocity": v});
        expect_input_error(s, &["time_step.accuracy", named]);
    }
}

/// LAMMPS's mass-scaled dashpots: a negative η_n0 is named by its path; `viscoelastic`
/// has no error model (its c_n grows as √δ without Kuwabara–Kono's clamp), while
/// `mass_velocity`, a constant γ_n = η_n0 m* per impact, has the constant dashpot's.
#[test]
fn mass_scaled_dashpots_are_checked() {
    let mut s = base();
    s["contact"] =
        json!({"normal": {"law": "hertz"}, "damping": {"kind": "viscoelastic", "eta_n0": -1.0}});
    expect_input_error(s, &["contact.damping.eta_n0", "must be >= 0"]);
    let mut s = base();
    s["contact"] =
        json!({"normal": {"law": "hertz"}, "damping": {"kind": "viscoelastic", "eta_n0": 1e8}});
    s["time_step"] = json!({"accuracy": 1e-3, "characteristic_velocity": 1.0});
    expect_input_error(s, &["time_step.accuracy", "has no error model"]);
    let mut s = base();
    s["contact"] =
        json!({"normal": {"law": "hertz"}, "damping": {"kind": "mass_velocity", "eta_n0": 10.0}});
    s["time_step"] = json!({"accuracy": 1e-3, "characteristic_velocity": 1.0});
    s["run"] = json!({"steps": 1});
    let (code, stderr) = run_text(&s.to_string());
    assert_eq!(code, 0, "{stderr}");
}

#[test]
fn hertz_accuracy_without_characteristic_velocity_states_its_step() {
    let mut s = base();
    s["time_step"] = json!({"accuracy": 1e-4});
    s["contact"].as_object_mut().unwrap().remove("damping");
    let (code, stderr) = run_text_loud(&s.to_string());
    assert_eq!(code, 0, "{stderr}");
    for said in [
        "accuracy 1e-4",
        "steps per contact",
        "predicted cost",
        "characteristic velocity",
    ] {
        assert!(stderr.contains(said), "{said}: {stderr}");
    }
}

/// `--quiet` keeps its promise: how the step was chosen is not printed.
#[test]
fn quiet_runs_print_nothing_on_stderr() {
    let mut s = base();
    s["time_step"] = json!({"accuracy": 1e-4});
    s["contact"].as_object_mut().unwrap().remove("damping");
    s["run"] = json!({"steps": 10});
    let (code, stderr) = run_text(&s.to_string());
    assert_eq!((code, stderr.as_str()), (0, ""));
}

/// The implied velocity names particles by their scene id (1-based, trajectory.csv's),
/// not by their 0-based place in memory.
#[test]
fn implied_velocity_names_particles_by_scene_id() {
    let mut s = base();
    s["time_step"] = json!({"accuracy": 1e-2});
    s.as_object_mut().unwrap().remove("gravity");
    s["particles"][1]["velocity"] = json!([0, 0, -1]);
    s["run"] = json!({"steps": 1});
    let (code, stderr) = run_text_loud(&s.to_string());
    assert_eq!(code, 0, "{stderr}");
    assert!(
        stderr.contains("the relative speed of particles 1 and 2"),
        "{stderr}"
    );
}

/// A punch under a pressure ramp implies a speed (accuracy/velocity.rs): here the
/// mean speed that closes the bed's 4.5 mm within the 10 ms ramp, 0.45 m/s, which is
/// above its free-flight speed across the 1.5 mm gap, 0.171 m/s.
#[test]
fn a_pressed_punch_implies_its_speed() {
    let mut s = base();
    s["time_step"] = json!({"accuracy": 1e-3});
    s.as_object_mut().unwrap().remove("gravity");
    s["walls"].as_array_mut().unwrap().push(json!({
        "name": "punch", "material": "glass",
        "shape": {"kind": "plane", "point": [0, 0, 0.007], "normal": [0, 0, -1]},
        "motion": {"kind": "pressure", "direction": [0, 0, -1], "pressure": 1e3, "area": 1e-5,
                   "ramp_time": 0.01, "mass": 1e-3}
    }));
    s["run"] = json!({"steps": 1});
    let (code, stderr) = run_text_loud(&s.to_string());
    assert_eq!(code, 0, "{stderr}");
    assert!(
        stderr.contains("characteristic velocity 4.5000e-1 m/s: the mean speed at which punch 'punch' would close the bed's height 4.500e-3 m"),
        "{stderr}"
    );
}

#[test]
fn several_errors_are_all_listed() {
    let mut s = base();
    s["particles"][0]["radius"] = json!(0);
    s["materials"][0]["density"] = json!(-1);
    expect_input_error(s, &["particles[0].radius", "materials[0].density"]);
}

#[test]
fn spin_without_rotation_is_rejected() {
    let mut s = base();
    s.as_object_mut().unwrap().remove("rotation");
    s["particles"][0]["omega"] = json!([0, 0, 10]);
    expect_input_error(s, &["particles[0].omega: needs \"rotation\""]);
}

#[test]
fn uniform_radius_rejects_unknown_keys_and_narrow_regions_work() {
    let mut s = base();
    s["insert"] = json!([{"count": 1, "radius": {"min": 1e-3, "max": 1e-3, "typo": 1}, "material": "glass",
                          "region": {"lower": [0.01, 0, 0], "upper": [0.012, 0.002, 0.002]}}]);
    let (code, stderr) = run_text(&s.to_string());
    assert_eq!(code, 2, "{stderr}");
    // A region exactly one diameter wide holds exactly one sphere: no panic.
    s["insert"][0]["radius"] = json!({"min": 1e-3, "max": 1e-3});
    s["run"] = json!({"steps": 10});
    let (code, stderr) = run_text(&s.to_string());
    assert_eq!(code, 0, "{stderr}");
}

#[test]
fn duplicate_wall_names_are_rejected() {
    let mut s = base();
    let w = s["walls"][0].clone();
    s["walls"].as_array_mut().unwrap().push(w);
    expect_input_error(s, &["walls[1].name: must be unique"]);
}

#[test]
fn particle_inside_a_wall_is_rejected() {
    let mut s = base();
    s["particles"][0]["position"] = json!([0.0, 0.0, 0.0005]);
    expect_input_error(s, &["particles[0].position: penetrates walls[0] ('floor')"]);
}

#[test]
fn prescribed_particle_cannot_also_have_velocity_or_spin() {
    let mut s = base();
    s["particles"][0]["prescribed_velocity"] = json!([0, 0, 0]);
    s["particles"][0]["omega"] = json!([0, 0, 1]);
    expect_input_error(s, &["particles[0].prescribed_velocity: cannot be combined"]);
}

#[test]
fn duplicate_friction_pairs_are_rejected() {
    let mut s = base();
    s["contact"]["tangential"]["friction_pairs"] = json!([{"materials": ["glass", "glass"], "friction": 0.1}, {"materials": ["glass", "glass"], "friction": 0.2}]);
    expect_input_error(
        s,
        &["contact.tangential.friction_pairs[1].materials: the pair"],
    );
}

#[test]
fn storakers_without_hollomon_constants_is_named() {
    let mut s = base();
    s["contact"]["normal"] = json!({"law": "storakers"});
    expect_input_error(
        s,
        &["materials[0].hollomon: is required by contact.normal.law 'storakers'"],
    );
}

#[test]
fn hollomon_needs_exactly_one_constant() {
    let mut s = base();
    s["materials"][0]["hollomon"] = json!({"exponent": 0.1, "strength": 1e9, "yield_stress": 8e8});
    expect_input_error(s, &["materials[0].hollomon: give exactly one of"]);
}

#[test]
fn damping_with_a_self_dissipating_law_is_refused() {
    let mut s = base();
    s["contact"]["normal"] = json!({"law": "kuwabara_kono", "dissipation_time": 1e-6});
    expect_input_error(
        s,
        &["contact.damping: must be absent with contact.normal.law 'kuwabara_kono'"],
    );
}

#[test]
fn liggghts_restitution_follows_liggghts_rule() {
    for bad in [0.05, 0.0, 1.0000001, -0.5] {
        let mut s = base();
        s["contact"]["damping"] = json!({"kind": "liggghts_restitution", "restitution": bad});
        expect_input_error(
            s,
            &[&format!(
                "contact.damping.restitution: must be > 0.05 and <= 1 (LIGGGHTS's own rule), got {bad}"
            )],
        );
    }
    let mut s = base();
    s["contact"]["damping"] = json!({"kind": "liggghts_restitution", "xi": 0.5});
    expect_input_error(s, &["contact.damping", "unknown field `xi`"]);
}

#[test]
fn liggghts_restitution_is_refused_for_laws_liggghts_lacks() {
    let mut s = base();
    s["contact"]["normal"] =
        json!({"law": "walton_braun", "loading_stiffness": 1e3, "unloading_stiffness": 2e3});
    s["contact"]["damping"] = json!({"kind": "liggghts_restitution", "restitution": 0.5});
    expect_input_error(
        s,
        &[
            "contact.damping.restitution: has no LIGGGHTS definition with contact.normal.law 'walton_braun'",
        ],
    );
    let mut s = base();
    s["contact"]["normal"] = json!({"law": "storakers"});
    s["materials"][0]["hollomon"] = json!({"strength": 1e9, "exponent": 0.3});
    s["contact"]["damping"] = json!({"kind": "liggghts_restitution", "restitution": 0.5});
    expect_input_error(
        s,
        &[
            "contact.damping.restitution: has no LIGGGHTS definition with contact.normal.law 'storakers'",
        ],
    );
}

#[test]
fn liggghts_restitution_builds_the_critical_fraction_of_its_law() {
    use tamp::contact::damping::{CriticalFraction, Damping};
    let sqrt_ln2_pi2 = |e: f64| (e.ln().powi(2) + std::f64::consts::PI.powi(2)).sqrt();
    for (normal, e, xi) in [
        (
            json!({"law": "hertz"}),
            0.5,
            (5.0f64 / 6.0).sqrt() * 0.5f64.ln().abs() / sqrt_ln2_pi2(0.5),
        ),
        (
            json!({"law": "linear", "stiffness": 1e3}),
            0.9,
            0.9f64.ln().abs() / sqrt_ln2_pi2(0.9),
        ),
        (json!({"law": "hertz"}), 1.0, 0.0),
    ] {
        let mut s = base();
        s["contact"]["normal"] = normal;
        s["contact"]["damping"] = json!({"kind": "liggghts_restitution", "restitution": e});
        let scene = tamp::scene::parse(&s.to_string()).unwrap();
        let built = tamp::scene::build(&scene).unwrap();
        let law = built.sim.model().law;
        let Some(Damping::LiggghtsRestitution(restitution)) = law.damping else {
            panic!("expected liggghts_restitution, got {:?}", law.damping);
        };
        let CriticalFraction { xi: got } = restitution.with(&law.normal).unwrap();
        assert!((got - xi).abs() <= 1e-15, "e = {e}: xi {got} vs {xi}");
    }
}

#[test]
fn walton_braun_unloading_must_be_stiffer() {
    let mut s = base();
    s["contact"]["normal"] =
        json!({"law": "walton_braun", "loading_stiffness": 2e3, "unloading_stiffness": 1e3});
    expect_input_error(
        s,
        &["contact.normal.unloading_stiffness: must be >= loading_stiffness"],
    );
}

#[test]
fn tangential_parameters_must_match_the_law() {
    let mut s = base();
    s["contact"]["tangential"] = json!({"law": "coulomb", "friction": 0.3, "stiffness": 1e3});
    expect_input_error(
        s,
        &["contact.tangential.stiffness: unknown field `stiffness`"],
    );
    let mut s = base();
    s["contact"]["tangential"] = json!({"law": "haff_werner", "friction": 0.3});
    expect_input_error(s, &["contact.tangential.damping: missing field `damping`"]);
    let mut s = base();
    s["contact"]["tangential"] = json!({"law": "haff_werner", "friction": 0.3, "damping": -1});
    expect_input_error(s, &["contact.tangential.damping: must be > 0 and finite"]);
    let mut s = base();
    s["contact"]["tangential"] =
        json!({"law": "lammps_linear_history", "friction": 0.3, "stiffness": 0, "x_gamma_t": -0.5});
    expect_input_error(
        s,
        &[
            "contact.tangential.stiffness: must be > 0 and finite",
            "contact.tangential.x_gamma_t: must be >= 0 and finite",
        ],
    );
    let mut s = base();
    s["contact"]["tangential"] = json!({"law": "lammps_linear_nohistory", "friction": 0.3, "stiffness": 1e3, "x_gamma_t": 1});
    expect_input_error(
        s,
        &["contact.tangential.stiffness: unknown field `stiffness`"],
    );
    let mut s = base();
    s["contact"]["tangential"] =
        json!({"law": "lammps_mindlin", "variant": "mindlin", "friction": 0.3, "x_gamma_t": -0.5});
    expect_input_error(
        s.clone(),
        &["contact.tangential.x_gamma_t: must be >= 0 and finite, got -5e-1"],
    );
    // JSON has no infinity: a number too large for f64 is refused where it stands.
    let (code, stderr) = run_text(&s.to_string().replace("-0.5", "1e999"));
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.contains("contact.tangential.x_gamma_t: malformed JSON: number out of range"),
        "{stderr}"
    );
}

#[test]
fn cohesion_cutoff_must_exceed_min_separation() {
    let mut s = base();
    s["contact"]["cohesion"] =
        json!({"law": "van_der_waals", "hamaker": 1e-19, "min_separation": 4e-10, "cutoff": 1e-10});
    expect_input_error(s, &["contact.cohesion.cutoff: must be > min_separation"]);
}

#[test]
fn boundary_shapes_and_motions_are_checked() {
    let mut s = base();
    s["walls"].as_array_mut().unwrap().push(json!({
        "name": "hopper", "material": "glass",
        "shape": {"kind": "funnel", "origin": [0, 0, 0.1], "axis": [0, 0, 1], "outlet_radius": 0.01,
                  "outlet_bottom": 0, "outlet_top": 0.01, "top_radius": 0.005, "top": 0.02},
        "motion": {"kind": "displacement", "x": "0.0", "y": "0.0", "z": "0.001 * math::sin(t"}
    }));
    s["walls"].as_array_mut().unwrap().push(json!({
        "name": "lid", "material": "glass",
        "shape": {"kind": "box", "lower": [0, 0, 0], "upper": [1, 1, 1], "open": ["top"]},
        "motion": {"kind": "servo", "direction": [0, 0, -1], "pressure": 1e5, "gain": 1e-3, "max_speed": 0.1}
    }));
    expect_input_error(
        s,
        &[
            "walls[1].shape.top_radius: must exceed outlet_radius",
            "walls[1].motion.z: cannot parse expression",
            "walls[2].shape.open[0]: unknown face 'top'",
            "walls[2].motion: give either 'force' (N) or both 'pressure' (Pa) and 'area'",
        ],
    );
}

#[test]
fn missing_stl_file_is_an_input_error() {
    let mut s = base();
    s["walls"][0]["shape"] = json!({"kind": "mesh", "stl": "no/such/file.stl"});
    expect_input_error(s, &["walls[0].shape", "no/such/file.stl"]);
}

#[test]
fn periodic_period_must_exceed_the_interaction_range() {
    let mut s = base();
    s["periodic"] = json!({"x": [-0.0015, 0.0015]});
    expect_input_error(s, &["periodic.x: the period"]);
}

#[test]
fn initial_overlap_through_a_periodic_face_is_found() {
    let mut s = base();
    s["periodic"] = json!({"x": [-0.01, 0.01]});
    s["particles"] = json!([
        {"position": [-0.0095, 0, 0.002], "radius": 0.001, "material": "glass"},
        {"position": [0.0095, 0, 0.002], "radius": 0.001, "material": "glass"}
    ]);
    expect_input_error(s, &["particles[1].position: overlaps particles[0]"]);
}

#[test]
fn deposited_spheres_that_hit_an_explicit_one_are_named() {
    let mut s = base();
    s["particles"] = json!([{"position": [0, 0, 0.001], "radius": 0.001, "material": "glass"}]);
    s["deposit"] = json!([{"count": 30, "radius": 0.001, "material": "glass",
                           "footprint": [[-0.002, -0.002], [0.002, 0.002]], "floor": 0.0}]);
    expect_input_error(s, &["deposit (particle", "overlaps particles[0]"]);
}

#[test]
fn liggghts_history_needs_liggghts_normal_law_damping_and_rotation() {
    let history = json!({"law": "liggghts_history", "friction": 0.3});
    let mut s = base();
    s["contact"]["tangential"] = history.clone();
    s["contact"]["normal"] = json!({"law": "storakers"});
    s["materials"][0]["hollomon"] = json!({"strength": 1e9, "exponent": 0.3});
    s["contact"].as_object_mut().unwrap().remove("damping");
    expect_input_error(
        s,
        &[
            "contact.tangential.law: 'liggghts_history' needs contact.normal.law 'hertz' (model hertz) or 'linear' (model hooke)",
            "got 'storakers'",
        ],
    );
    let mut s = base();
    s["contact"]["tangential"] = history.clone();
    expect_input_error(
        s,
        &[
            "contact.damping: must be absent or of kind 'liggghts_restitution' with contact.tangential.law 'liggghts_history'",
            "got kind 'critical_fraction'",
        ],
    );
    let mut s = base();
    s["contact"]["tangential"] = history.clone();
    s["contact"]["damping"] = json!({"kind": "liggghts_restitution", "restitution": 0.5});
    s.as_object_mut().unwrap().remove("rotation");
    expect_input_error(
        s,
        &["rotation: is required by contact.tangential.law 'liggghts_history'"],
    );
    let mut s = base();
    s["contact"]["tangential"] =
        json!({"law": "liggghts_history", "friction": 0.3, "stiffness": 1e3});
    s["contact"]["damping"] = json!({"kind": "liggghts_restitution", "restitution": 0.5});
    expect_input_error(
        s,
        &["contact.tangential.stiffness: unknown field `stiffness`"],
    );
}

#[test]
fn liggghts_history_takes_its_model_and_damping_from_the_scene() {
    use tamp::contact::damping::{Damping, liggghts::LiggghtsModel};
    use tamp::contact::tangential::{LiggghtsHistory, TangentialLaw};
    for (normal, damping, model) in [
        (
            json!({"law": "hertz"}),
            Some(json!({"kind": "liggghts_restitution", "restitution": 0.5})),
            LiggghtsModel::Hertz,
        ),
        (
            json!({"law": "linear", "stiffness": 1e3}),
            Some(json!({"kind": "liggghts_restitution", "restitution": 0.9})),
            LiggghtsModel::Hooke,
        ),
        (json!({"law": "hertz"}), None, LiggghtsModel::Hertz),
    ] {
        let mut s = base();
        s["contact"]["normal"] = normal;
        s["contact"]["tangential"] = json!({"law": "liggghts_history", "friction": 0.3});
        match damping {
            Some(d) => s["contact"]["damping"] = d,
            None => {
                s["contact"].as_object_mut().unwrap().remove("damping");
            }
        }
        let scene = tamp::scene::parse(&s.to_string()).unwrap();
        let law = tamp::scene::build(&scene).unwrap().sim.model().law;
        // γ_t uses the normal damping's ξ; no damping means e = 1, ξ = 0.
        let xi = match law.damping {
            Some(Damping::LiggghtsRestitution(r)) => r.with(&law.normal).unwrap().xi,
            None => 0.0,
            other => panic!("unexpected damping {other:?}"),
        };
        assert_eq!(
            law.tangential,
            Some(TangentialLaw::LiggghtsHistory(LiggghtsHistory {
                model,
                xi
            }))
        );
    }
}

/// Data after the scene's JSON is an error naming where it starts, not silently dropped
/// (two documents, a word after the brace, and a die-compaction file, which must not be
/// taken for a plain scene either).
#[test]
fn trailing_data_after_the_scene_is_named() {
    let text = base().to_string();
    for tail in [" {\"name\": \"second\"}", "\nrun", " ]"] {
        let (code, stderr) = run_text(&format!("{text}{tail}"));
        assert_eq!(code, 2, "{tail:?}: {stderr}");
        assert!(
            stderr.contains("scene: trailing data after the scene's JSON at line"),
            "{tail:?}: {stderr}"
        );
    }
    let die: Value = serde_json::from_str(include_str!(
        "../verification/nial_die_compaction_small.scene.json"
    ))
    .unwrap();
    let (code, stderr) = run_text(&format!("{die} junk"));
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains("trailing data"), "{stderr}");
}

/// A byte-order mark is named, and a syntax error names the scene rather than the
/// path `?`.
#[test]
fn byte_order_mark_and_syntax_errors_are_named() {
    let (code, stderr) = run_text(&format!("\u{feff}{}", base()));
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains("byte-order mark"), "{stderr}");
    let (code, stderr) = run_text("{\"name\": \"x\",,}");
    assert_eq!(code, 2, "{stderr}");
    assert!(!stderr.contains("?:"), "{stderr}");
    assert!(stderr.contains("scene: malformed JSON"), "{stderr}");
}

/// Inputs that pass the per-field rules but make a derived quantity leave the range of
/// a double are exit 2 naming the field: a density whose particle masses overflow, a
/// gravity whose speeds over the run overflow the energies, and a Young's modulus whose
/// critical step is not finite (given a characteristic velocity, the message must not
/// ask for one).
#[test]
fn inputs_whose_derived_quantities_overflow_are_named() {
    let mut s = base();
    s["materials"][0]["density"] = json!(1e308);
    expect_input_error(s, &["materials[0].density:", "mass"]);
    let mut s = base();
    s["gravity"] = json!([0, 0, -1e200]);
    expect_input_error(s, &["gravity:", "range of a double"]);
    let mut s = base();
    s["materials"][0]["youngs_modulus"] = json!(1e308);
    let (code, stderr) = run_text(&s.to_string());
    assert_eq!(code, 2, "{stderr}");
    assert!(
        !stderr.contains("characteristic_velocity: is required"),
        "{stderr}"
    );
    assert!(stderr.contains("youngs_modulus"), "{stderr}");
}

/// Sizes that cannot fit in memory used to abort the process (SIGABRT, "memory
/// allocation of … bytes failed"). They are refused before anything is allocated,
/// naming the field, the estimate and the memory available.
#[test]
fn scenes_too_large_for_memory_are_refused_before_allocating() {
    let needles = |field: &'static str| [field, "GiB of memory", "this process can still use"];
    let mut s = base();
    s["insert"] = json!([{"count": 1_000_000_000u64, "radius": 0.001, "material": "glass",
        "region": {"lower": [-10, -10, 0.01], "upper": [10, 10, 20]}}]);
    expect_input_error(s, &needles("insert[0].count"));

    let mut s = base();
    s["walls"] = json!([{"material": "glass", "shape": {"kind": "height_field",
        "x_range": [-1, 1], "y_range": [-1, 1], "expression": "0.0", "cells": [100000, 100000]}}]);
    expect_input_error(s, &needles("walls[0].shape.cells"));

    let mut s: Value = serde_json::from_str(include_str!(
        "../verification/nial_die_compaction_small.scene.json"
    ))
    .unwrap();
    s["die_compaction"]["particles"]["count"] = json!(1_000_000_000u64);
    expect_input_error(s, &needles("die_compaction.particles.count"));

    let mut s = base();
    s["output"] = json!({"trajectory_every": 1});
    s["run"] = json!({"steps": 1_000_000_000_000u64});
    expect_input_error(s, &needles("output.trajectory_every"));
}

/// Rows at every step from a step on are rows of trajectory.csv, which must be written.
#[test]
fn every_step_rows_need_a_trajectory() {
    let mut s = base();
    s["output"] = json!({"trajectory_every_step_from": 5});
    expect_input_error(
        s,
        &[
            "output.trajectory_every_step_from",
            "output.trajectory_every >= 1",
        ],
    );
}

/// walls.csv is written at the steps of trajectory.csv, of the scene's walls.
#[test]
fn wall_rows_need_a_trajectory_and_walls() {
    let mut s = base();
    s["output"] = json!({"walls": true});
    expect_input_error(s.clone(), &["output.walls", "output.trajectory_every >= 1"]);
    s["output"] = json!({"walls": true, "trajectory_every": 10});
    s["walls"] = json!([]);
    expect_input_error(s, &["output.walls", "no walls to record"]);
}

/// A rigid wall material: no density or elastic constants (a value given would never
/// be used, so it is refused), and never a particle's material.
#[test]
fn rigid_material_rules_are_named() {
    let mut s = base();
    s["materials"]
        .as_array_mut()
        .unwrap()
        .push(json!({"name": "die", "rigid": true, "density": 7800, "youngs_modulus": 2e11}));
    s["walls"][0]["material"] = json!("die");
    s["particles"][1]["material"] = json!("die");
    s["materials"][0].as_object_mut().unwrap().remove("density");
    expect_input_error(
        s,
        &[
            "materials[1].density: must be absent for a rigid material",
            "materials[1].youngs_modulus: must be absent for a rigid material",
            "particles[1].material: 'die' is rigid: only walls may be made of a rigid material",
            "materials[0].density: is required (kg/m³) unless the material is \"rigid\": true",
        ],
    );
}

#[test]
fn a_rigid_wall_material_runs_without_constants() {
    let mut s = base();
    s["materials"]
        .as_array_mut()
        .unwrap()
        .push(json!({"name": "die", "rigid": true}));
    s["walls"][0]["material"] = json!("die");
    s["run"]["duration"] = json!(0.01);
    let (code, stderr) = run_text(&s.to_string());
    assert_eq!(code, 0, "stderr: {stderr}");
}

#[test]
fn a_die_compaction_of_rigid_particles_is_named() {
    let mut die: Value = serde_json::from_str(include_str!(
        "../verification/nial_die_compaction_small.scene.json"
    ))
    .unwrap();
    die["materials"][0] = json!({"name": "NiAl", "rigid": true});
    expect_input_error(
        die,
        &[
            "die_compaction.particles.material: 'NiAl' is rigid: only walls may be made of a rigid material",
        ],
    );
}

/// A die-compaction file is a process document whose stages set the particles, walls
/// and run; giving them is refused naming each, and a `tamp run` of
/// the file tells it from a scene by its `die_compaction` block alone.
#[test]
fn a_die_compaction_file_names_the_blocks_its_stages_set() {
    let mut die: Value = serde_json::from_str(include_str!(
        "../verification/nial_die_compaction_small.scene.json"
    ))
    .unwrap();
    die["walls"] = json!([{"shape": {"kind": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}, "material": "die"}]);
    die["run"] = json!({"steps": 10});
    die["growth"] = json!({"duration": 1e-6});
    expect_input_error(
        die,
        &[
            "walls: must be left out of a die_compaction scene: its stages set it",
            "growth: must be left out of a die_compaction scene: its stages set it",
            "run: must be left out of a die_compaction scene: its stages set it",
        ],
    );
}

/// The scene members of a die-compaction file meet the scene's reader: an unknown one
/// is refused by name, at its line in the file as written, wherever it stands beside
/// `die_compaction` (here after it, the member blanked out for that reader).
#[test]
fn a_die_compaction_file_refuses_an_unknown_member_at_its_line() {
    let mut die: Value = serde_json::from_str(include_str!(
        "../verification/nial_die_compaction_small.scene.json"
    ))
    .unwrap();
    die["zeta"] = json!(1);
    // serde_json's map is ordered by key: `zeta` is written after `die_compaction`.
    let text = serde_json::to_string_pretty(&die).unwrap();
    let line = 1 + text.lines().position(|l| l.contains("\"zeta\"")).unwrap();
    assert!(
        line > 1 + text
            .lines()
            .position(|l| l.contains("\"die_compaction\""))
            .unwrap()
    );
    let (code, stderr) = run_text(&text);
    assert_eq!(code, 2, "stderr: {stderr}");
    assert!(
        stderr.contains("error: zeta: unknown field `zeta`")
            && stderr.contains(&format!("at line {line} ")),
        "{stderr}"
    );
}

#[test]
fn a_bad_die_curvature_is_named() {
    let mut die: Value = serde_json::from_str(include_str!(
        "../verification/nial_die_compaction_small.scene.json"
    ))
    .unwrap();
    die["die_compaction"]["die_curvature"] = json!("round");
    expect_input_error(
        die,
        &["die_compaction.die_curvature", "unknown variant `round`"],
    );
}

/// The press cycle's stages come in order (unload, eject, relax), each naming what it
/// needs, and every number is checked at its path.
#[test]
fn press_cycle_stages_are_checked_at_their_paths() {
    let base: Value =
        serde_json::from_str(include_str!("../verification/die_press_cycle.scene.json")).unwrap();
    let mut die = base.clone();
    die["die_compaction"]
        .as_object_mut()
        .unwrap()
        .remove("unload");
    die["die_compaction"]["relax"] = json!({"duration": 1e-6});
    die["die_compaction"]["die_bands"] = json!(0);
    expect_input_error(
        die,
        &[
            "die_compaction.eject: needs die_compaction.unload: the upper punch is withdrawn before the compact is pushed out",
            "die_compaction.die_bands: must be >= 1, got 0",
            "die_compaction.die_bands: is measured in a press cycle only",
        ],
    );
    let mut die = base.clone();
    die["die_compaction"]["unload"]["speed"] = json!(-0.05);
    die["die_compaction"]["eject"]["records"] = json!(0);
    die["die_compaction"]["eject"]["ramp_time"] = json!(-1.0);
    expect_input_error(
        die,
        &[
            "die_compaction.unload.speed: must be > 0 and finite, got -5e-2",
            "die_compaction.eject.records: must be >= 1, got 0",
            "die_compaction.eject.ramp_time",
        ],
    );
    let mut die = base;
    die["die_compaction"]["unload"]["rate"] = json!(1.0);
    expect_input_error(die, &["die_compaction.unload", "unknown field `rate`"]);
}

#[test]
fn bad_contact_outputs_are_named() {
    for (field, value, rule) in [
        ("contacts_every", json!(-1), "invalid value: integer `-1`"),
        (
            "contacts_every",
            json!(2.5),
            "invalid type: floating point `2.5`",
        ),
        ("forces", json!("yes"), "invalid type: string \"yes\""),
    ] {
        let mut s = base();
        s["output"] = json!({ field: value });
        expect_input_error(s, &[&format!("output.{field}"), rule]);
    }
}

/// The funnel filling's dimensions are refused with exit 2 naming the path and the
/// rule: an outlet that cannot pass the largest particle (18.5 µm) or does not fit in
/// the die, a cone no wider than the die (it could not rest in the die's mouth), a flat
/// or inverted cone, non-positive lengths, a funnel block without the funnel method,
/// and an unknown method or field.
#[test]
fn bad_funnel_fillings_are_named() {
    let die = || -> Value {
        let mut s: Value = serde_json::from_str(include_str!(
            "../verification/nial_die_compaction_small.scene.json"
        ))
        .unwrap();
        s["die_compaction"]["fill"]["method"] = json!("funnel");
        s
    };
    let funnel = |field: &str, value: Value| {
        let mut s = die();
        s["die_compaction"]["fill"]["funnel"] = json!({ field: value });
        s
    };
    let at = |f: &str| format!("die_compaction.fill.funnel.{f}: ");
    for (field, value, rule) in [
        (
            "outlet_diameter",
            json!(10e-6),
            "must exceed the largest particle diameter",
        ),
        ("outlet_diameter", json!(40e-6), "be smaller than the die"),
        ("top_diameter", json!(30e-6), "must exceed the die diameter"),
        ("cone_angle", json!(180), "must be in (0, 180) degrees"),
        ("cone_angle", json!(0), "must be in (0, 180) degrees"),
        ("outlet_length", json!(0), "must be > 0 and finite"),
        ("outlet_height", json!(-1e-6), "must be > 0 and finite"),
    ] {
        expect_input_error(funnel(field, value), &[&at(field), rule]);
    }
    let mut s = die();
    s["die_compaction"]["fill"]["method"] = json!("settled_column");
    s["die_compaction"]["fill"]["funnel"] = json!({});
    expect_input_error(
        s,
        &["die_compaction.fill.funnel: applies only to fill.method \"funnel\""],
    );
    let mut s = die();
    s["die_compaction"]["fill"]["method"] = json!("hopper");
    expect_input_error(
        s,
        &["die_compaction.fill.method", "unknown variant `hopper`"],
    );
    expect_input_error(
        funnel("outlet_radius", json!(1e-5)),
        &[
            "die_compaction.fill.funnel",
            "unknown field `outlet_radius`",
        ],
    );
}

#[test]
fn velocity_changes_need_a_prescribed_particle() {
    let mut s = base();
    s["particles"][0]["prescribed_velocity_changes"] =
        json!([{"time": 1e-6, "velocity": [0, 0, 0]}]);
    expect_input_error(
        s,
        &["particles[0].prescribed_velocity_changes: needs prescribed_velocity"],
    );
}

/// The base scene with its first particle prescribed at rest.
fn prescribed_base() -> Value {
    let mut s = base();
    s["particles"][0]["prescribed_velocity"] = json!([0, 0, 0]);
    s
}

#[test]
fn velocity_changes_come_in_time_order() {
    let mut s = prescribed_base();
    s["particles"][0]["prescribed_velocity_changes"] = json!([
        {"time": 2e-6, "velocity": [0, 0, 0]},
        {"time": 1e-6, "velocity": [0, 0, 0]}
    ]);
    expect_input_error(
        s,
        &["particles[0].prescribed_velocity_changes[1].time: must be finite and later than 2e-6 s"],
    );
}

#[test]
fn velocity_changes_need_a_step_each() {
    let mut s = prescribed_base();
    s["time_step"] = json!({"fixed": 1e-6});
    s["particles"][0]["prescribed_velocity_changes"] = json!([
        {"time": 1e-6, "velocity": [0, 0, 0]},
        {"time": 1.2e-6, "velocity": [0, 0, 0]}
    ]);
    expect_input_error(
        s,
        &[
            "particles[0].prescribed_velocity_changes[1].time: 1.2e-6 s is step 1",
            "a step of its own after step 1",
        ],
    );
}

/// `text` with the JSON number `number` at its first occurrence replaced by `literal`
/// (Python's `json.dump` writes `NaN` and `Infinity` for non-finite floats).
fn with_literal(scene: &Value, number: &str, literal: &str) -> String {
    let text = serde_json::to_string_pretty(scene).unwrap();
    assert!(text.contains(number), "{number} not in the scene");
    text.replacen(number, literal, 1)
}

fn expect_text_error(text: &str, needles: &[&str]) {
    let (code, stderr) = run_text(text);
    assert_eq!(code, 2, "stderr: {stderr}");
    for n in needles {
        assert!(stderr.contains(n), "expected '{n}' in: {stderr}");
    }
}

#[test]
fn a_non_finite_literal_is_named_by_its_full_path_in_every_block() {
    let mut s = base();
    s["contact"]["damping"]["xi"] = json!(0.123456);
    s["walls"][0]["shape"]["normal"] = json!([0, 0, 0.987654]);
    s["run"]["duration"] = json!(0.345678);
    s["time_step"]["alpha"] = json!(0.234567);
    for (number, literal, path) in [
        ("0.001", "NaN", "particles[0].radius: malformed JSON"),
        ("2500", "Infinity", "materials[0].density: malformed JSON"),
        ("0.234567", "NaN", "time_step.alpha: malformed JSON"),
        ("0.123456", "NaN", "contact.damping.xi: malformed JSON"),
        (
            "0.987654",
            "-Infinity",
            "walls[0].shape.normal[2]: malformed JSON",
        ),
        ("0.345678", "NaN", "run.duration: malformed JSON"),
    ] {
        expect_text_error(&with_literal(&s, number, literal), &[path, "line"]);
    }
}

#[test]
fn a_value_inside_a_tagged_or_flattened_block_is_named_by_its_full_path() {
    let mut s = base();
    s["contact"]["tangential"]["law"] = json!("mindlin");
    expect_input_error(s, &["contact.tangential.law: unknown variant `mindlin`"]);
    let mut s = base();
    s["contact"]["damping"]["xi"] = json!("high");
    expect_input_error(
        s,
        &["contact.damping.xi: invalid type: string \"high\", expected f64"],
    );
    let mut s = base();
    s["contact"]["tangential"]["stiffness"] = json!(true);
    expect_input_error(s, &["contact.tangential.stiffness: invalid type: boolean"]);
    let mut s = base();
    s["walls"][0]["shape"]["point"] = json!([0, "x", 0]);
    expect_input_error(s, &["walls[0].shape.point[1]: invalid type: string \"x\""]);
    let mut s = base();
    s["contact"]["damping"]
        .as_object_mut()
        .unwrap()
        .remove("xi");
    expect_input_error(s, &["contact.damping.xi: missing field `xi`"]);
    let mut s = base();
    s["insert"] = json!([{"count": 2, "material": "glass", "radius": {"min": "small", "max": 1e-3},
                          "region": {"lower": [0, 0, 0], "upper": [0.01, 0.01, 0.01]}}]);
    expect_input_error(s, &["insert[0].radius.min: invalid type: string \"small\""]);
}

#[test]
fn runs_too_long_to_finish_are_refused_naming_what_set_their_length() {
    let mut s = base();
    s["run"] = json!({"duration": 1e308});
    expect_input_error(s, &["run.duration: 1e308 s at a step of", "more than 2^53"]);
    let mut s = base();
    s["run"] = json!({"steps": 1_000_000_000_000_000_000u64});
    expect_input_error(s, &["run.steps: the run is 1e18 steps, more than 2^53"]);
    let mut s = base();
    s["time_step"] = json!({"fixed": 5e-324});
    expect_input_error(s, &["run.duration:", "(time_step.fixed)", "more than 2^53"]);
    // 1e15 steps of two particles: about 1.4e8 s predicted, beyond 30 days.
    let mut s = base();
    s["run"] = json!({"steps": 1_000_000_000_000_000u64});
    expect_input_error(
        s,
        &[
            "run.steps: the run is 1e15 steps of 2 particles, predicted to take",
            "run.max_wall_time = 2.592e6 s",
        ],
    );
}

#[test]
fn a_user_who_means_a_long_run_raises_its_wall_time_limit() {
    let mut s = base();
    s["run"] = json!({"steps": 1_000_000_000_000_000u64, "max_wall_time": 1e9});
    let text = s.to_string();
    let scene = tamp::scene::parse(&text).unwrap();
    assert!(tamp::scene::build(&scene).is_ok());
    s["run"]["max_wall_time"] = json!(-1);
    expect_input_error(s, &["run.max_wall_time: must be > 0"]);
}

/// A rolling resistance needs spins and a tangential law with one spring to join, and
/// its own parameters in range; each rule is named at its path.
#[test]
fn rolling_resistance_rules_are_named() {
    let mut s = base();
    s["contact"]["rolling"] =
        json!({"law": "sds", "stiffness": 0.0, "damping": -1.0, "friction": 0.2});
    s.as_object_mut().unwrap().remove("rotation");
    expect_input_error(
        s.clone(),
        &[
            "contact.rolling.stiffness: must be > 0",
            "contact.rolling.damping: must be >= 0",
            "contact.rolling: needs \"rotation\"",
        ],
    );
    s["contact"]["tangential"] = json!({"law": "coulomb", "friction": 0.3});
    expect_input_error(
        s,
        &["contact.rolling.law: 'sds' needs contact.tangential with a law that keeps one spring"],
    );
}
